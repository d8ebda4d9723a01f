"""``spinimpact explore``: bad options, a missing extra, and a server that stops on Ctrl-C."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import urllib.request

import pytest


@pytest.mark.parametrize("port", ["abc", "-1", "70000", "8.5"])
def test_a_bad_port_is_one_line_naming_the_option_and_value(cli, port):
    status, out, err = cli("explore", "--port", port)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "--port" in lines[0] and repr(port) in lines[0], err


@pytest.mark.slow  # a fresh interpreter: about a second
def test_without_dash_the_command_names_the_extra():
    code = (
        "import sys; sys.modules['dash'] = None\n"  # an import of dash now fails
        "from spinimpact.cli import main; main(['explore', '--port', '0'])"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and "pip install 'spinimpact[explore]'" in lines[0], run.stderr


@pytest.mark.slow
def test_it_serves_on_localhost_and_stops_cleanly_on_ctrl_c():
    pytest.importorskip("dash", reason="needs the [explore] extra")
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(
        [sys.executable, "-m", "spinimpact", "explore", "--port", "0"],
        stderr=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
        env=env,
    )
    try:
        line = proc.stderr.readline()
        found = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        assert found, line
        with urllib.request.urlopen(found.group(0), timeout=30) as page:
            html = page.read().decode()
        assert "spinimpact explorer" in html
        assert "cdn" not in html.lower() and "https://" not in html  # nothing from the web
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 130, err
    assert "Traceback" not in err
