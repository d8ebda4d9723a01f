"""spinimpact solve with a tangential compliance law: the numbers of the library, one-line
errors with exit status 2 for a law without its parameter or a parameter without its law."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, Stronge, Walton, solve
from spinimpact.cli import main

from tests.cli.test_errors import _keep_sigterm  # noqa: F401 (an autouse fixture)

BALL = Body.solid_sphere(mass=1.0, radius=0.1)


def run_main(capsys, *args):
    """Run the command in this process; (exit status, stdout, stderr); 0 when it returns."""
    try:
        main([str(a) for a in args])
        status = 0
    except SystemExit as exit_:
        status = exit_.code or 0
    out = capsys.readouterr()
    return status, out.out, out.err


@pytest.mark.parametrize(
    "args, law",
    [
        (["--tangential", "walton", "--beta0", "0.35"], Walton(0.35)),
        (["--tangential", "stronge", "--poisson-ratio", "0.23"], Stronge(poisson_ratio=0.23)),
        (["--tangential", "stronge", "--stiffness-ratio", "3"], Stronge(stiffness_ratio=3.0)),
    ],
)
def test_solve_json_is_the_library_result(capsys, args, law):
    status, out, err = run_main(capsys, "solve", "--vx", "1.5", "--omega", "-3", *args, "--json")
    assert status == 0 and err == ""
    data = json.loads(out)
    imp = solve(BALL, 1.5, -4.0, -3.0, mu=0.2, kappa=0.8, tangential=law)
    assert data["law"] == law.to_dict()
    assert data["regime"] == str(imp.regime)
    assert data["after"]["omega"] == pytest.approx(float(imp.after.omega), rel=1e-15)
    assert data["tangential_restitution"] == pytest.approx(float(imp.tangential_restitution))


@pytest.mark.slow
def test_solve_prints_a_report_in_a_subprocess():
    proc = subprocess.run(
        [sys.executable, "-m", "spinimpact", "solve", "--vx", "1", "--omega", "0",
         "--tangential", "stronge", "--poisson-ratio", "0.23"],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    imp = solve(BALL, 1.0, -4.0, 0.0, mu=0.2, kappa=0.8, tangential=Stronge(poisson_ratio=0.23))
    assert "Stronge(poisson_ratio=0.23)" in proc.stdout
    assert str(imp.regime) in proc.stdout
    assert f"{float(imp.tangential_restitution):.6g}" in proc.stdout


def test_rigid_is_the_default_and_todays_report(capsys):
    a = run_main(capsys, "solve", "--json")
    b = run_main(capsys, "solve", "--tangential", "rigid", "--json")
    assert a == b and "tau_star" in json.loads(a[1])


@pytest.mark.parametrize(
    "args, needle",
    [
        (["--tangential", "walton"], "--tangential walton needs --beta0"),
        (["--tangential", "walton", "--beta0", "1.5"], "beta0 must be in [-1, 1], got 1.5"),
        (["--beta0", "0.2"], "--beta0 applies to --tangential walton only"),
        (["--tangential", "walton", "--beta0", "0.2", "--poisson-ratio", "0.3"],
         "--poisson-ratio applies to --tangential stronge and mindlin-deresiewicz only"),
        (["--tangential", "stronge"], "needs exactly one of --poisson-ratio and --stiffness-ratio"),
        (["--tangential", "stronge", "--poisson-ratio", "0.3", "--stiffness-ratio", "1"],
         "needs exactly one of"),
        (["--tangential", "stronge", "--poisson-ratio", "0.7"], "poisson_ratio must be in"),
        (["--tangential", "stronge", "--stiffness-ratio", "-1"], "stiffness_ratio must be in"),
        (["--tangential", "bouncy"], "--tangential"),
        (["--tangential", "mindlin-deresiewicz"],
         "--tangential mindlin-deresiewicz needs exactly one of --poisson-ratio and "
         "--stiffness-ratio"),
        (["--tangential", "mindlin-deresiewicz", "--poisson-ratio", "0.6"],
         "poisson_ratio must be in"),
        (["--tangential", "mindlin-deresiewicz", "--poisson-ratio", "0.3", "--kappa", "0"],
         "kappa must be > 0 under MindlinDeresiewicz"),
    ],
)  # fmt: skip
def test_bad_options_are_one_line_and_exit_2(capsys, args, needle):
    status, out, err = run_main(capsys, "solve", *args)
    assert status == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert needle in lines[0]


@pytest.mark.slow
def test_sweep_with_a_law_writes_the_library_numbers(tmp_path):
    out = tmp_path / "sweep.csv"
    proc = subprocess.run(
        [sys.executable, "-m", "spinimpact", "sweep", "--vx", "0:5:11", "--omega", "0",
         "--tangential", "walton", "--beta0", "0.3", "--output", str(out),
         "--fields", "after_vx,tangential_restitution,regime"],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert "slip-reversal" in proc.stdout
    import csv

    with out.open() as f:
        rows = list(csv.DictReader(f))
    vx = np.array([float(r["vx"]) for r in rows])
    imp = solve(BALL, vx, -4.0, 0.0, mu=0.2, kappa=0.8, tangential=Walton(0.3))
    np.testing.assert_allclose([float(r["after_vx"]) for r in rows], imp.after.vx, rtol=1e-15)
    assert [r["regime"] for r in rows] == [str(x) for x in imp.regime]


@pytest.mark.parametrize(
    "args, needle",
    [
        (["--planar", "rod", "--tangential", "walton", "--beta0", "0.2"],
         "--tangential walton does not apply to --planar sweeps"),
        (["--tangential", "stronge"], "needs exactly one of --poisson-ratio and --stiffness-ratio"),
        (["--tangential", "walton", "--beta0", "0.2", "--fields", "tau_star"],
         "fields must be among"),
    ],
)  # fmt: skip
def test_sweep_bad_options_are_one_line(capsys, args, needle):
    status, out, err = run_main(capsys, "sweep", "--vx", "0:1:3", "--omega", "0", *args)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and needle in err


def test_mindlin_deresiewicz_on_the_command_line(capsys):
    """The law's report is solve(..., tangential=MindlinDeresiewicz(...))'s numbers."""
    from spinimpact import Body, MindlinDeresiewicz, solve

    status, out, _ = run_main(capsys, "solve", "--body", "solid-sphere", "--mass", "1",
                              "--radius", "0.1", "--vx", "0.5", "--vy", "-1", "--omega", "0",
                              "--mu", "0.3", "--kappa", "1", "--tangential",
                              "mindlin-deresiewicz", "--poisson-ratio", "0.23")  # fmt: skip
    assert status == 0
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 0.5, -1.0, 0.0, mu=0.3, kappa=1.0,
                tangential=MindlinDeresiewicz(poisson_ratio=0.23))  # fmt: skip
    assert "MindlinDeresiewicz(poisson_ratio=0.23)" in out and "slip-reversal" in out
    assert f"{float(imp.tangential_restitution):.6g}" in out
