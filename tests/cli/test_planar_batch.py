"""``spinimpact batch`` on files of planar bodies and pendulums and ``spinimpact sweep
--planar``: the files and numbers they write, bad input as one line with exit status 2."""

import csv
import math
import signal
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.cli import main
from spinimpact.io.problem_sweep import ProblemSweep
from spinimpact.io.sweep import parse_axis, run_sweep

ROD = ["mass", "inertia", "rx", "ry", "vx", "vy", "omega", "law"]


def shell(*args):
    cmd = [sys.executable, "-m", "spinimpact", *map(str, args)]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=120)


@pytest.fixture
def run_main(capsys):
    """Run ``spinimpact ARGS`` in this process: (exit status, stdout, stderr)."""
    previous = signal.getsignal(signal.SIGTERM)  # main installs its own handler

    def call(*args):
        try:
            main([*map(str, args)])
            status = 0
        except SystemExit as exit_:
            status = exit_.code
        out = capsys.readouterr()
        return status, out.out, out.err

    yield call
    signal.signal(signal.SIGTERM, previous)


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        csv.writer(f).writerows([header, *rows])
    return path


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.mark.slow
def test_batch_of_rods_from_the_shell(tmp_path):
    rows = [[1, 0.08, -0.35, -0.35, 1, -1, 0, "newton"], [2, 0.1, 0.2, -0.3, 0, -2, 3, ""]]
    src = write_csv(tmp_path / "rods.csv", ROD, rows)
    out = tmp_path / "out.csv"
    result = shell("batch", src, "--output", out, "--mu", 0.4, "--kappa", 0.7, "--law", "energetic")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"wrote 2 rows to {out}"
    got = read_csv(out)
    for row, line in zip(rows, got, strict=True):
        law = row[7] or "energetic"
        imp = solve_planar(PlanarBody(*row[:4]), *row[4:7], mu=0.4, kappa=0.7, law=law)
        assert (float(line["mu"]), float(line["kappa"])) == (0.4, 0.7)
        assert line["regime"] == imp.regime
        for name in ("after_vx", "after_vy", "after_omega", "dissipated_fraction", "tau1"):
            assert float(line[name]) == float(imp.columns()[name]), name
        assert line["creates_energy"] == ("true" if imp.creates_energy else "false")
    bad = shell("batch", src, "--output", out, "--radius", 0.2)
    assert bad.returncode == 2 and bad.stdout == ""
    assert bad.stderr.strip().splitlines() == [
        f"spinimpact: error: --radius describes the paper's bodies, but the columns of {src} "
        "describe free planar bodies: their mass and geometry come from the file"
    ]


def test_batch_of_pendulums_with_skipped_rows(run_main, tmp_path):
    header = ["mass", "inertia", "gx", "gy", "px", "py", "omega", "mu"]
    rows = [[1, 0.1, 0.25, -0.4, 0.5, -0.8, -2, 0.1], [1, 0.1, 0.25, -0.4, 0.5, -0.8, 2, 0.1],
            [1, 0.1, 0.25, -0.4, 0.5, -0.8, -3, 0.9]]  # fmt: skip
    src = write_csv(tmp_path / "p.csv", header, rows)
    status, out, err = run_main("batch", src, "--output", tmp_path / "o.csv", "--on-error", "skip")
    assert (status, err) == (0, "") and "(1 with errors" in out
    got = read_csv(tmp_path / "o.csv")
    assert got[1]["error"] == (
        "row 2 (line 3), columns omega, px: the contact point must approach the surface, "
        "but its normal velocity omega*px is 1.0 m/s"
    )
    for i in (0, 2):
        imp = solve_pendulum(Pendulum(*rows[i][:6]), rows[i][6], mu=rows[i][7], kappa=0.8)
        assert got[i]["regime"] == imp.regime and got[i]["law"] == "poisson"
        assert float(got[i]["before_vx"]) == float(imp.before.vx)
        assert float(got[i]["after_omega"]) == float(imp.after.omega)
    assert {got[0]["regime"], got[2]["regime"]} == {"reverse-compression", "locked"}


@pytest.mark.parametrize(
    ("header", "row", "needle"),
    [
        (ROD, [1, 0.1, 0.2, -0.3, 1, -1, 0, "hooke"], "row 1 (line 2), column law: must be one"),
        (ROD[:-1] + ["px"], [1, 0.1, 0.2, -0.3, 1, -1, 0, 1], "do not go together"),
        (["mass", "inertia", "vx", "vy", "omega"], [1, 1, 1, -1, 0], "'inertia' describes"),
    ],
)
def test_batch_errors_are_one_line_exit_2(run_main, tmp_path, header, row, needle):
    src = write_csv(tmp_path / "in.csv", header, [row])
    status, out, err = run_main("batch", src, "--output", tmp_path / "o.csv")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert err.startswith("spinimpact: error: ") and needle in err
    assert not (tmp_path / "o.csv").exists()


def test_sweep_of_a_rod_prints_the_planar_regimes(run_main, tmp_path):
    args = ["--vx", "-2:2:41", "--vy", "-1", "--omega", "-1:1:11", "--mu", "0.4", "--kappa", "0.6"]
    status, out, err = run_main(
        "sweep", "--planar", "rod", "--length", 1, "--orientation-deg", 45, "--law", "newton",
        *args,
        "--histogram", "dissipated_fraction:0:1:4", "--output", tmp_path / "s",
        "--fields", "after_vx,regime,creates_energy",
    )  # fmt: skip
    assert (status, err) == (0, "")
    assert out.splitlines()[0] == "451 points (rod, newton law)"
    rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
    texts = dict(zip(args[::2], args[1::2], strict=True))
    axes = {n[2:]: parse_axis(n[2:], v) for n, v in texts.items()}
    sweep = ProblemSweep(problem="planar", body=rod, axes=axes, fixed={"law": "newton"})
    want = run_sweep(sweep, histogram=("dissipated_fraction", 0, 1, 4))
    for name, share in want.regime_fractions.items():
        assert f"  {name:20s} {share:.6f}" in out.splitlines()
    assert "reverse-compression" in out and "histogram of dissipated_fraction:" in out
    for count in want.histogram:
        assert f"  {count}" in out
    vx, omega = np.load(tmp_path / "s" / "vx.npy"), np.load(tmp_path / "s" / "omega.npy")
    imp = solve_planar(rod, vx, -1.0, omega, mu=0.4, kappa=0.6, law="newton")
    np.testing.assert_array_equal(np.load(tmp_path / "s" / "after_vx.npy"), imp.after.vx)
    np.testing.assert_array_equal(np.load(tmp_path / "s" / "creates_energy.npy"),
                                  imp.creates_energy)  # fmt: skip


def test_sweep_of_a_pendulum_and_of_a_custom_body(run_main):
    status, out, _ = run_main("sweep", "--planar", "pendulum", "--mu", "0:1:11")
    assert status == 0 and out.splitlines()[0] == "11 points (rod-pendulum, poisson law)"
    assert "  locked               0.454545" in out  # mu >= 0.6 holds the contact
    status, out, _ = run_main(
        "sweep", "--planar", "custom", "--inertia", 0.1, "--rx", 0.2, "--ry", -0.3,
        "--vx", "uniform:-1:1", "--samples", 500, "--mass", 2,
    )  # fmt: skip
    assert status == 0 and out.splitlines()[0] == "500 points (custom, poisson law)"


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--planar", "pendulum", "--vx", "1"], "--vx does not apply to --planar pendulum"),
        (["--length", "2"], "--length needs --planar"),
        (["--law", "newton"], "--law needs --planar"),
        (["--planar", "block", "--length", "2"], "--length does not apply to --planar block"),
        (["--planar", "rod", "--radius", "0.2"], "--radius does not apply to --planar rod"),
        (["--planar", "rod", "--body", "ring"], "either --body"),
        (["--planar", "custom", "--rx", "1"], "--planar custom needs --inertia, --rx and --ry"),
        (["--planar", "rod", "--omega", "-50:50:3"], "must approach the surface at every point"),
        (["--planar", "rod", "--orientation-deg", "200"], "--orientation-deg 200 is"),
        (["--planar", "rod", "--fields", "zeta"], "fields must be among after_vx"),
    ],
)
def test_sweep_errors_are_one_line_exit_2(run_main, args, needle):
    status, out, err = run_main("sweep", *args)
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert err.startswith("spinimpact: error: ") and needle in err


@pytest.mark.slow
def test_sweep_error_from_the_shell():
    result = shell("sweep", "--planar", "pendulum", "--omega", "-1:1:3")
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "omega*px reaches 0.5 m/s" in result.stderr


def test_help_names_the_planar_options(run_main):
    status, out, _ = run_main("sweep", "--help")
    assert status == 0 and "--planar [rod|block|eccentric-disk|pendulum|custom]" in out
    status, out, _ = run_main("batch", "--help")
    assert status == 0 and "mass, inertia, rx, ry" in out and "gx, gy, px, py" in out
