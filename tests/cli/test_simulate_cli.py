"""``spinimpact simulate`` as a user meets it (issue 10, items 11 and 20): its default
compares with ``solve``'s default, the Hertz law stays Hertz when calibrated, a bad
restitution is named by the option typed, a bad plot name fails before any output,
and ``--help`` gives the defaults."""

import re
import subprocess
import sys

import pytest

from spinimpact.dynamics import HertzContact


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", "simulate", *args],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip


def _row(stdout, label):
    """The (simulated, rigid) numbers of a row of the comparison table."""
    line = next(x for x in stdout.splitlines() if x.strip().startswith(label))
    return [
        float(x) for x in re.findall(r"[-+]?\d+(?:\.\d*)?(?:e[-+]?\d+)?", line.split("│", 1)[1])
    ]


@pytest.mark.slow
def test_default_compares_with_solves_default():
    """The issue: simulate's default was elastic Hertz (vy+ = 4 m/s) where solve's default
    kappa = 0.8 gives 3.2; now the default calibrates the law to kappa = 0.8."""
    out = _run()
    assert out.returncode == 0, out.stderr
    simulated, rigid, _ = _row(out.stdout, "vy+ (m/s)")
    assert simulated == pytest.approx(3.2, abs=1e-6) and rigid == pytest.approx(3.2, abs=1e-6)
    assert _row(out.stdout, "Newton restitution")[:2] == pytest.approx([0.8, 0.8], abs=1e-6)
    assert "the default of --kappa, as solve's" in out.stdout


@pytest.mark.slow
def test_calibrated_hertz_stays_hertz_and_says_so():
    """--contact hertz with --kappa 0.8 once ran a HuntCrossleyContact silently."""
    out = _run("--contact", "hertz", "--kappa", "0.8")
    assert out.returncode == 0, out.stderr
    assert "HertzContact(youngs_modulus=2e+09, poisson_ratio=0.35, radius=0.1, alpha=" in out.stdout
    assert "HuntCrossleyContact" not in out.stdout
    assert "hertz contact law, its Hunt-Crossley damping alpha calibrated to give kappa = 0.8 " \
        "at |vy| = 4 m/s (--kappa)" in out.stdout  # fmt: skip
    elastic = _run("--kappa", "1")
    assert elastic.returncode == 0, elastic.stderr
    assert "elastic: no damping for kappa = 1" in elastic.stdout and "alpha=0)" in elastic.stdout
    assert _row(elastic.stdout, "Newton restitution")[:2] == [1.0, 1.0]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--kappa", "1.2"], "--kappa must be in (0, 1], got 1.2"),
        (["--contact", "linear", "--kappa", "0"], "--kappa must be in (0, 1], got 0.0"),
        (["--alpha", "0.1", "--kappa", "0.5"], "give either --alpha or --kappa, not both"),
        (["--plot", "sim.txt"], "--plot must end in .png, .svg or .pdf, got 'sim.txt'"),
    ],
)
@pytest.mark.slow
def test_bad_options_are_named_as_typed_before_any_output(args, message, tmp_path):
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "simulate", *args],
        capture_output=True, text=True, timeout=120, cwd=tmp_path,
    )  # fmt: skip
    assert out.returncode == 2
    assert out.stderr.strip() == f"spinimpact: error: {message}" or message in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
    assert out.stdout == ""  # nothing printed before the error (the plot name included)
    assert list(tmp_path.iterdir()) == []


def test_help_gives_the_law_defaults():
    out = _run("--help")
    text = " ".join(out.stdout.split())
    assert "N/m for linear (default 1e6)" in text and "(default 1e8)" in text
    assert "Young's modulus E, Pa. Hertz; default 2e9." in text
    assert "Hertz; default 0.35." in text
    assert "Here in (0, 1]" in text and "Default 0.8, as solve" in text


@pytest.mark.slow
def test_damping_given_means_no_calibration():
    out = _run("--contact", "hunt-crossley", "--alpha", "0.1")
    assert out.returncode == 0, out.stderr
    assert "alpha=0.1)" in out.stdout and "calibrated" not in out.stdout
    assert _row(out.stdout, "Newton restitution")[0] < 0.8


def test_hertz_calibration_in_python():
    law = HertzContact.calibrated(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02,
                                  kappa=0.6, mass=0.05, speed=3.0)  # fmt: skip
    assert type(law) is HertzContact and law.youngs_modulus == 2e9 and law.radius == 0.02
    assert law.restitution(0.05, 3.0, rtol=1e-11) == pytest.approx(0.6, abs=1e-9)
    with pytest.raises(ValueError, match=r"kappa must be in .0, 1\], got 1.2"):
        HertzContact.calibrated(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02,
                                kappa=1.2, mass=0.05, speed=3.0)  # fmt: skip
