"""``spinimpact sweep`` run as a user runs it: in a subprocess, its files read back."""

import subprocess
import sys


def sweep(*args, timeout=120, **kwargs):
    """``spinimpact sweep ARGS`` in a fresh interpreter: the CompletedProcess."""
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", "sweep", *map(str, args)],
        capture_output=True,
        text=True,
        timeout=timeout,
        **kwargs,
    )


def assert_one_line_error(out, needle):
    assert out.returncode == 2, (out.stdout, out.stderr)
    assert out.stdout == ""
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert lines[0].startswith("spinimpact: error: ") and needle in lines[0], lines[0]


def test_the_same_seed_gives_the_same_sweep_whatever_the_chunk_size():
    args = ("--vx", "uniform:-5:5", "--omega", "uniform:-50:50", "--samples", 20_000)
    args += ("--seed", 11, "--histogram", "dissipated_fraction:0:1:7")
    runs = [sweep(*args, "--chunk-size", size) for size in (20_000, 4096, 777)]
    for out in runs:
        assert out.returncode == 0, out.stderr
    assert runs[1].stdout == runs[0].stdout == runs[2].stdout
    assert "20,000 points" in runs[0].stdout
    other_seed = sweep(*args[:-4], "--seed", 12, *args[-2:], "--chunk-size", 777)
    assert other_seed.returncode == 0 and other_seed.stdout != runs[0].stdout
    help_text = sweep("--help").stdout
    assert "depend on --chunk-size" not in help_text
