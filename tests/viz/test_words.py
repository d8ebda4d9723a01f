"""What the reports say: user text is shown as text (never Rich markup, HTML or mathtext),
and the words describe the impact that was solved (issue 10, items 13 and 23)."""

import io
import subprocess
import sys

import pytest
from rich.console import Console

from spinimpact import Body, solve, solve_particle
from spinimpact.viz.html import impact_report_html
from spinimpact.viz.report import print_report
from spinimpact.viz.tables import impact_tables, regime_summary

pytest.importorskip("matplotlib")

HOSTILE = ("[/bold]", "[link=http://evil.example]x[/link]", "[red]red", "<b>x</b> & $a_b$")


def _terminal(imp, particle=None):
    out = io.StringIO()
    console = Console(file=out, width=200, force_terminal=True, color_system="truecolor")
    print_report(imp, particle, console=console)
    return out.getvalue()


@pytest.mark.parametrize("name", HOSTILE)
@pytest.mark.slow
def test_body_names_are_text_in_every_report(name):
    body = Body(mass=1.0, radius=0.1, gyration=0.05, name=name)
    imp = solve(body, 3.0, -4.0, 10.0, mu=0.2, kappa=0.8)
    text = _terminal(imp, solve_particle(3.0, -4.0, mu=0.2, kappa=0.8))  # no MarkupError
    assert "\x1b]8;" not in text  # no terminal hyperlink
    assert f"Impact of a {name} body" in text
    page = impact_report_html(imp)
    assert name not in page or "<" not in name  # HTML special characters are escaped
    assert "&lt;b&gt;x&lt;/b&gt; &amp; $a_b$" in page if "<" in name else name in page


@pytest.mark.slow
def test_figure_titles_show_a_dollar_in_a_name_as_a_dollar(tmp_path):
    from spinimpact.viz.plots import plot_energy, plot_history, plot_routh

    body = Body(mass=1.0, radius=0.1, gyration=0.05, name="$5 ball_2 $x$")
    imp = solve(body, 3.0, -4.0, 10.0, mu=0.2, kappa=0.8)
    for plot in (plot_history, plot_routh, plot_energy):
        fig = plot(imp)
        assert r"\$5 ball_2 \$x\$" in fig.get_suptitle()
        fig.savefig(tmp_path / "f.png", dpi=30)  # mathtext would raise on an odd '$'


def test_head_on_bounce_without_spin_says_no_slip_before_or_after():
    """u^- = 0: nothing rolls; the contact point simply never slips."""
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 0.0, -4.0, 0.0, mu=0.2, kappa=0.8)
    assert imp.regime == "no-slip"
    text = _terminal(imp)
    assert "rolling" not in text, text
    assert "no slip before or after" in text
    assert "leaves without slip (u+ = 0): yes" in text
    assert "no slip before or after" in regime_summary(imp)
    energy = {t.key: t for t in impact_tables(imp)}["energy"]
    assert "Fig. 5b" not in energy.note and "end of compression" in energy.note


@pytest.mark.slow
def test_frictionless_title_and_summary():
    imp = solve(Body.ring(mass=1.0, radius=0.1), 0.5, -1.0, 3.0, mu=0.0, kappa=1.0)
    text = _terminal(imp)
    assert "rough" not in text and "on a smooth surface (mu = 0)" in text
    assert "stick" not in regime_summary(imp)
    page = impact_report_html(imp)
    assert "rough" not in page and "smooth surface (μ = 0)" in page
    rough = _terminal(solve(Body.ring(mass=1.0, radius=0.1), 0.5, -1.0, 3.0, mu=0.3, kappa=1.0))
    assert "on a rough surface" in rough


def _cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", *args], capture_output=True, text=True, timeout=60
    )


@pytest.mark.slow
def test_solve_help_cites_the_equations():
    from spinimpact import solve as api

    assert "eq" in api.__doc__ and "4.13" in api.__doc__
    out = _cli("solve", "--help")
    assert out.returncode == 0
    for needle in ("eqs.", "3.6", "4.13", "Lubarda"):
        assert needle in out.stdout, needle


@pytest.mark.parametrize("command", ["map", "figures"])
@pytest.mark.slow
def test_dpi_has_help_text(command):
    out = _cli(command, "--help")
    assert out.returncode == 0
    block = out.stdout[out.stdout.index("\n  --dpi") + 1 :].split("\n  -")[0]
    text = " ".join(block.split())
    assert "Image resolution, dots per inch." in text and "inchs" not in text, block


@pytest.mark.slow
def test_html_sets_the_scripts_of_its_symbols():
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 3.0, -4.0, 10.0, mu=0.2, kappa=0.8)
    page = impact_report_html(imp)
    assert "√(−W<sub>r</sub><sup>n</sup>/W<sub>c</sub><sup>n</sup>)" in page
    assert "E<sub>m</sub>" in page and "τ<sub>m</sub>" in page
    for raw in ("W_r", "W_c", "E_m", "τ_m", "^n", "^t"):
        assert raw not in page.split("<h2>Figures")[0], raw
    name = "my_ball^2"  # user text keeps its characters
    named = solve(
        Body(mass=1.0, radius=0.1, gyration=0.05, name=name), 3.0, -4.0, 1.0, mu=0.2, kappa=0.8
    )
    assert f"<td>{name}</td>" in impact_report_html(named)


def test_planar_report_says_smooth_without_friction():
    import math

    from spinimpact import PlanarBody, solve_planar
    from spinimpact.viz.report import print_planar_report

    rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
    for mu, words in ((0.0, "on a smooth surface (mu = 0)"), (0.3, "on a rough surface")):
        out = io.StringIO()
        imp = solve_planar(rod, 1.0, -1.0, 0.0, mu=mu, kappa=0.8, law="poisson")
        print_planar_report(imp, console=Console(file=out, width=200))
        assert words in out.getvalue()
