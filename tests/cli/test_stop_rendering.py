"""A stop (SIGTERM, SIGINT) reaches a command while it renders a picture: the animation
checks for it between frames and the map renders before its file is opened, so either
stops within about a second (rendering an animation takes 20 to 46 s, a map at 600 dpi
about 8 s). The signal is sent once the command is rendering: run on a terminal, the command
shows its progress line and has since used a second of processor time. The old output
stays, no temporary file is left."""

import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

pytestmark = [
    pytest.mark.slow,
    pytest.mark.alone,  # times the stop: no other test may load the cores meanwhile
    pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals"),
]

OLD = b"old output the user keeps\n"
#: Seconds a stop may take once signalled (rendering one frame, or a piece of one, and
#: removing the temporary file), with room for a loaded machine.
STOP_WITHIN = 2.5


def cpu_seconds(pid: int) -> float:
    """Processor time process ``pid`` has used, s (Linux /proc)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def stop_while_drawing(folder: Path, name: str, args: list[str], signum: int, marker: str):
    """Run ``spinimpact ARGS`` with a terminal as stderr, writing ``folder/name`` over old
    data; send ``signum`` a second of processor time after its progress line (``marker``)
    shows:
    (exit status, stderr, seconds from the signal to the end)."""
    (folder / name).write_bytes(OLD)
    main, terminal = os.openpty()
    seen = bytearray()

    def drain() -> None:  # read the terminal all along: a full one would block the writer
        try:
            while chunk := os.read(main, 4096):
                seen.extend(chunk)
        except OSError:  # the terminal closed with the process
            pass

    reader = threading.Thread(target=drain, daemon=True)
    with subprocess.Popen([sys.executable, "-m", "spinimpact", *args], cwd=folder,
                          stdout=subprocess.DEVNULL, stderr=terminal) as proc:  # fmt: skip
        os.close(terminal)
        reader.start()
        deadline = time.monotonic() + 120
        while marker.encode() not in seen:
            assert proc.poll() is None, bytes(seen)
            assert time.monotonic() < deadline
            time.sleep(0.01)
        start = cpu_seconds(proc.pid)
        while cpu_seconds(proc.pid) < start + 1.0:
            assert proc.poll() is None, bytes(seen)
            time.sleep(0.01)
        sent = time.monotonic()
        proc.send_signal(signum)
        status = proc.wait(timeout=60)
        took = time.monotonic() - sent
    reader.join(timeout=10)
    os.close(main)
    return status, bytes(seen).decode(errors="replace"), took


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads Linux /proc")
def test_a_map_at_600_dpi_stops_within_a_second_or_two(tmp_path):
    args = ["map", "--output", "map.png", "--dpi", "600"]
    status, err, took = stop_while_drawing(tmp_path, "map.png", args, signal.SIGTERM, "drawing")
    assert status == 143, err
    assert took < STOP_WITHIN, f"stopped {took:.1f} s after the signal"
    assert (tmp_path / "map.png").read_bytes() == OLD
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.png"]


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads Linux /proc")
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_an_animation_stops_between_frames(tmp_path, signum):
    args = ["flight", "--animate", "ball.gif", "--fps", "60", "--json"]
    status, err, took = stop_while_drawing(tmp_path, "ball.gif", args, signum, "animating")
    assert status == 128 + signum, err
    assert took < STOP_WITHIN, f"stopped {took:.1f} s after the signal"
    assert "no output was changed" in err and "Traceback" not in err
    assert (tmp_path / "ball.gif").read_bytes() == OLD
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ball.gif"]
