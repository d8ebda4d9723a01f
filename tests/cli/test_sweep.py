"""``spinimpact sweep`` run as a user runs it: in a subprocess, its files read back."""

import csv
import re
import subprocess
import sys
from pathlib import Path

import pytest

from spinimpact import Body
from spinimpact.io.sweep import Sweep, parse_axis, run_sweep

from tests.limits import under_limits


def sweep(*args, timeout=120, gib=None, **kwargs):
    """``spinimpact sweep ARGS`` in a fresh interpreter (under an address-space limit of
    ``gib`` GiB, as ``ulimit -v``, if given): the CompletedProcess."""
    command = [sys.executable, "-m", "spinimpact", "sweep", *map(str, args)]
    return subprocess.run(
        command if gib is None else under_limits(command, RLIMIT_AS=int(gib * 2**30)),
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


@pytest.mark.slow
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


ROOT = Path(__file__).resolve().parents[2]


def readme_sweep_commands():
    """The README's two sweep commands, as its table prints them (``[...]`` optional parts
    left out; ``…`` stands for the options left at their defaults)."""
    row = next(line for line in (ROOT / "README.md").read_text().splitlines()
               if line.startswith("| `spinimpact sweep "))  # fmt: skip
    grid, random = re.findall(r"`([^`]*)`", row.split("|")[1])[:2]
    grid = re.sub(r"\s*\[[^\]]*\]", "", grid).split()[2:]  # after "spinimpact sweep"
    return grid, random.replace("…", "").split()


@pytest.mark.slow
def test_the_readme_sweep_commands_run_as_written():
    grid, random = readme_sweep_commands()
    assert random == ["--vx", "uniform:-5:5", "--samples", "100000000"]
    assert grid == ["--vx", "-5:5:1001", "--omega", "-50:50:1001"]
    out = sweep(*grid)
    assert out.returncode == 0, out.stderr
    assert "1,002,001 points" in out.stdout
    # The random command as written, up to the point where it would compute: every default
    # it leaves (--omega, --vy, --mu, --kappa, --chunk-size, the body) applied, the sweep
    # built and checked, its size estimated and accepted. Computing its 1e8 points takes
    # 5-10 s on the 2-core test machine (more under load), so it is not run whole here.
    out = sweep(*random, "--dry-run")
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("estimate: 100,000,000 points in 100 chunks: about ")
    # The same defaults computing: the same command with fewer samples gives the numbers
    # of a sweep with vx and omega uniform over the grid defaults' ranges.
    small = [*random[:-1], "200000"]
    out = sweep(*small, "--histogram", "after_omega:-60:60:6")
    assert out.returncode == 0, out.stderr
    axes = dict(vx="uniform:-5:5", vy="-4", omega="uniform:-50:50", mu="0.2", kappa="0.8")
    want = run_sweep(
        Sweep(Body.solid_sphere(mass=1.0, radius=0.1),
              {n: parse_axis(n, v) for n, v in axes.items()}, samples=200_000),
        histogram=("after_omega", -60, 60, 6),
    )  # fmt: skip
    for name, share in want.regime_fractions.items():
        assert f"  {name:18s} {share:.6f}" in out.stdout
    for count in want.histogram:
        assert f")  {count}\n" in out.stdout


@pytest.mark.slow
def test_random_defaults_follow_samples_and_typed_uniform_axes():
    out = sweep("--samples", 1000, "--dry-run")  # no axis typed: vx and omega random
    assert out.returncode == 0 and "1,000 points" in out.stdout, out.stderr
    out = sweep("--omega", "uniform:-5:5", "--samples", 1000, "--histogram", "vx:-5:5:2")
    assert_one_line_error(out, "histogram field must be among")  # the inputs are no field
    out = sweep("--vx", "-1:1:3", "--omega", "uniform:-5:5", "--samples", 10)
    assert_one_line_error(out, "either a grid or random samples, not both")
    out = sweep("--vx", "uniform:-1:1")
    assert_one_line_error(out, "samples must be a positive integer")


@pytest.mark.slow
def test_sweeps_too_long_or_too_large_are_refused_in_one_line():
    # 1e10 grid points of vx times the 201 of omega's default grid
    out = sweep("--vx", "-5:5:10000000000")
    assert_one_line_error(out, "2,010,000,000,000 points would take about")
    assert "--force" in out.stderr
    out = sweep("--vx", "uniform:-5:5", "--samples", 10**12, "--chunk-size", 10**12)
    assert_one_line_error(out, "a chunk of 1,000,000,000,000 points needs about")
    assert "TiB of memory" in out.stderr and "--force" in out.stderr


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc")
@pytest.mark.slow
def test_memory_is_checked_against_the_address_space_limit_and_never_a_traceback():
    # 1e8 points a chunk: about 6 GiB, more than the 3 GiB the child may map (where more is
    # available, the address-space limit alone refuses it)
    args = ("--vx", "uniform:-5:5", "--samples", 10**8, "--chunk-size", 10**8)
    out = sweep(*args, gib=3)
    assert_one_line_error(out, "a chunk of 100,000,000 points needs about")
    # --force runs it anyway: the allocation fails, and says so in one line
    out = sweep(*args[:-2], "--chunk-size", 10**12, "--force", gib=3)
    assert_one_line_error(out, "out of memory (Unable to allocate")
    assert "lower --chunk-size" in out.stderr and "Traceback" not in out.stderr
    out = sweep("--vx", "-5:5:10000000000", "--omega", "0", "--chunk-size", 10**10, "--force",
                gib=3)  # fmt: skip
    assert_one_line_error(out, "out of memory")


@pytest.mark.slow
def test_dry_run_estimates_the_output_and_writes_nothing(tmp_path):
    out = sweep("--vx", "-5:5:1001", "--omega", "-50:50:101", "--output", tmp_path / "d",
                "--dry-run")  # fmt: skip
    assert out.returncode == 0, out.stderr
    assert "101,101 points in 1 chunk: about" in out.stdout
    assert "6.27 MiB of output" in out.stdout  # 8 float64 columns and the int8 regime
    assert list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_help_says_how_files_name_the_regimes(tmp_path):
    text = " ".join(sweep("--help").stdout.split())
    assert "FILE.parquet or FILE.csv" in text and "metadata.json" in text
    assert "regime as names (a dictionary column in Parquet; in .npy, int8 indices" in text
    assert "--dry-run" in text and "--force" in text
    out = sweep("--vx", "-1:1:3", "--omega", "0", "--output", tmp_path / "x.txt")
    assert_one_line_error(out, "a sweep writes FILE.parquet, FILE.csv or a new directory")
    assert list(tmp_path.iterdir()) == []
    pytest.importorskip("pyarrow.csv", reason="the [parquet] extra is not installed")
    out = sweep("--vx", "-1:1:3", "--omega", "0", "--output", tmp_path / "x.csv")
    assert out.returncode == 0, out.stderr
    with open(tmp_path / "x.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["vx", "vy", "omega", "mu", "kappa", "after_vx", "after_vy", "after_omega",
                       "regime"]  # fmt: skip
    assert [float(r[0]) for r in rows[1:]] == [-1.0, 0.0, 1.0]
    assert [r[-1] for r in rows[1:]] == ["stick-compression", "no-slip", "stick-compression"]
