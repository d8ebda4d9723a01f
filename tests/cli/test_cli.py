"""User-level tests: the installed ``spinimpact`` command run as a subprocess."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from spinimpact import Body, solve

EXE = Path(sys.executable).parent / "spinimpact"


def run(*args):
    cmd = [str(EXE), *args] if EXE.exists() else [sys.executable, "-m", "spinimpact", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=60)


@pytest.mark.slow
def test_default_report_shows_every_section():
    out = run("solve")
    assert out.returncode == 0, out.stderr
    text = out.stdout
    for needle in (
        "stick-restitution",
        "Rebound",
        "Energy budget",
        "Works of the contact forces",
        "mu_hat",
        "Outcome:",
        "Whittaker",
        "1.85714",  # vx+ = 3 - 4/3.5 for the default case
        "-18.5714",  # omega+ = -vx+/R
    ):
        assert needle in text, needle
    assert out.stderr == ""


@pytest.mark.slow
def test_json_equals_python_api():
    out = run(
        "solve",
        "--body",
        "solid-disk",
        "--mass",
        "2",
        "--radius",
        "0.05",
        "--vx",
        "1.5",
        "--vy",
        "-2",
        "--omega",
        "-80",
        "--mu",
        "0.1",
        "--kappa",
        "0.6",
        "--json",
    )
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    imp = solve(Body.solid_disk(mass=2, radius=0.05), 1.5, -2.0, -80.0, mu=0.1, kappa=0.6)
    assert data["regime"] == imp.regime == "slip"
    assert data["after"]["vx"] == float(imp.after.vx)
    assert data["after"]["omega"] == float(imp.after.omega)
    assert data["dissipated_energy"] == float(imp.dissipated_energy)
    assert data["impulse_ratio"] == float(imp.impulse_ratio)
    assert data["outcome"]["rolling"] is False
    assert data["body"]["zeta"] == 3.0


@pytest.mark.slow
def test_json_is_strict_when_values_are_infinite():
    out = run("solve", "--mu", "0", "--json")
    assert out.returncode == 0
    data = json.loads(out.stdout)  # would fail on the non-standard Infinity/NaN tokens
    assert data["tau_star"] is None and data["work_ratio_tangential"] is None
    assert data["regime"] == "frictionless"


@pytest.mark.slow
def test_custom_body_with_gyration_spool():
    out = run("solve", "--radius", "0.01", "--gyration", "0.03", "--json")
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout)["body"]["zeta"] == pytest.approx(1 + 1 / 9)


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--mass", "0"], "mass must be > 0"),
        (["--radius", "-1"], "radius must be > 0"),
        (["--gyration", "0"], "gyration must be > 0"),
        (["--mu", "-0.1"], "mu must be >= 0"),
        (["--kappa", "1.5"], "kappa must be in [0, 1]"),
        (["--vy", "0"], "vy must be < 0"),
        (["--vx", "nan"], "vx must be finite"),
        (["--omega", "inf"], "omega must be finite"),
        (["--mu", "abc"], "'--mu'"),
        (["--body", "cube"], "'--body'"),
        (["--body", "ring", "--gyration", "0.1"], "either --body or --gyration"),
        (["--no-such-option"], "no-such-option"),
    ],
)
@pytest.mark.slow
def test_bad_input_is_one_line_exit_2(args, needle):
    out = run("solve", *args)
    assert out.returncode == 2
    assert out.stdout == ""
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert lines[0].startswith("spinimpact: error:")
    assert needle in lines[0]
    assert "Traceback" not in out.stderr


@pytest.mark.slow
def test_help_and_version():
    out = run("solve", "--help")
    assert out.returncode == 0 and "--kappa" in out.stdout and "counter-clockwise" in out.stdout
    out = run("--version")
    assert out.returncode == 0 and "0.1.0" in out.stdout
