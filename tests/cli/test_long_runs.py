"""Long runs on the command line (spinimpact._long's rule): a run estimated to take more
than an hour is refused in one line naming its estimate and --force, before it runs; one
estimated over a minute says its estimate on stderr first. The estimates are measured on
the run itself (its first steps, rows or points), so the thresholds are lowered through
the environment of an in-process run where a test needs a long one."""

import subprocess
import sys

import pytest

from spinimpact import _long


def run(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "spinimpact", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout)  # fmt: skip


@pytest.mark.slow
def test_a_flight_with_a_step_of_a_tenth_of_a_microsecond_is_refused_in_one_line():
    out = run("flight", "--dt", "1e-7")
    assert out.returncode == 2, out.stderr
    lines = out.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in out.stderr
    assert lines[0].startswith("spinimpact: error: this flight (1 ball, dt = 1e-07 s) would take")
    assert lines[0].endswith("--force runs it anyway")
    assert out.stdout == ""


@pytest.mark.slow
def test_a_long_flight_says_its_estimate_first_and_force_runs_it(cli, monkeypatch):
    monkeypatch.setattr(_long, "ANNOUNCE_SECONDS", 0.0)
    monkeypatch.setattr(_long, "REFUSE_SECONDS", 0.01)
    status, out, err = cli("flight", "--dt", "1e-3", "--json")
    assert status == 2 and "--force runs it anyway" in err and out == ""
    status, out, err = cli("flight", "--dt", "1e-3", "--json", "--force")
    assert status == 0, err
    assert err.startswith("spinimpact: this flight (1 ball, dt = 0.001 s) will take about ")
    assert '"bounce_count"' in out


@pytest.mark.parametrize("seconds", [59.0, 61.0])
def test_the_rule_announces_over_a_minute_and_refuses_over_an_hour(seconds):
    e = _long.Estimate("this run", seconds, "its first 64 rows")
    assert e.announced == (seconds > 60) and not e.too_long
    assert not _long.Estimate("this run", 3601.0, "x").check(force=True)
    with pytest.raises(_long.TooLong, match=r"this run would take about 1 h here, over the "):
        _long.Estimate("this run", 3601.0, "x").check(force=False)
