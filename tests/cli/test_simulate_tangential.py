"""spinimpact simulate --tangential mindlin: output, figure, one-line errors."""

import pytest

from spinimpact.cli import main

from .test_errors import assert_one_line, run_main

KHARAZ = (
    "simulate",
    "--body",
    "solid-sphere",
    "--mass",
    "2.618e-4",
    "--radius",
    "0.0025",
    "--vx",
    "1.334",
    "--vy",
    "-3.665",
    "--omega",
    "0",
    "--mu",
    "0.092",
    "--kappa",
    "0.98",
    "--youngs-modulus",
    "3.8e11",
    "--poisson-ratio",
    "0.23",
)


@pytest.mark.slow
def test_mindlin_rows_and_plot(capsys, tmp_path):
    png = tmp_path / "t.png"
    main([*KHARAZ, "--tangential", "mindlin", "--plot", str(png)])
    out = capsys.readouterr().out
    assert "k_t/k_n = 0.870056" in out and "2 stick/slip switches" in out
    row = next(x for x in out.splitlines() if x.startswith("vx+ (m/s)")).split()
    assert float(row[2]) == pytest.approx(0.8290, abs=1e-3)  # compliant
    assert float(row[3]) == pytest.approx(5 / 7 * 1.334, abs=1e-6)  # rigid: sticks
    assert png.stat().st_size > 0


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("--stiffness-ratio", "2"), "--stiffness-ratio needs --tangential mindlin"),
        (("--spring", "total"), "--spring needs --tangential mindlin"),
        (("--contact", "linear", "--tangential", "mindlin"), "needs --stiffness-ratio"),
        (("--tangential", "mindlin", "--stiffness-ratio", "-1"), "stiffness_ratio must be in"),
        (("--tangential", "mindlin", "--poisson-ratio", "0.6"), "poisson_ratio must be in"),
    ],
)
def test_bad_options_are_one_line_errors(capsys, args, needle):
    assert_one_line(*run_main(capsys, "simulate", *args), needle)


def test_spring_rule_reaches_the_law(capsys):
    main(
        [*KHARAZ, "--tangential", "mindlin", "--spring", "total", "--vx", "0.136", "--vy", "-3.898"]
    )
    row = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("vx+ (m/s)"))
    assert float(row.split()[2]) / 0.136 > 0.99  # the total rule at 2 degrees: e_t near 1


def test_duration_in_microseconds_and_rigid_beta_exact(capsys):
    """A 6 µs contact reads in µs, and the rigid law's beta of a sticking impact is 0
    (not the 1e-17 its rounded velocities give); a sliding one keeps -u+/u-."""
    import re

    main([*KHARAZ, "--tangential", "mindlin"])
    out = capsys.readouterr().out
    duration = re.search(r"contact duration ([\d.]+) µs,", out)
    assert duration is not None and 5 < float(duration.group(1)) < 7  # Hertz: 6.2 µs
    beta = next(x for x in out.splitlines() if x.startswith("beta = -u+/u-")).split()
    assert beta[-1] == "0" and float(beta[-2]) > 0.3
    main([*KHARAZ, "--tangential", "mindlin", "--mu", "0.01"])  # slides throughout
    beta = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("beta = -u+/u-"))
    expected = -(1 - 3.5 * 0.01 * (1 + 0.98) * 3.665 / 1.334)  # u+ = u- - zeta mu (1+k)|vy|
    assert float(beta.split()[-1]) == pytest.approx(expected, rel=1e-3)
