"""Figures of planar impacts (spinimpact.viz.planar): Routh's diagram for coupled contacts,
the three restitution laws side by side, and the map over the body's angle and the slip
ratio; and the planar report's tables."""

import dataclasses
import math

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.core.planar import LAWS, PLANAR_REGIMES
from spinimpact.viz import planar as viz
from spinimpact.viz.report import planar_tables
from spinimpact.viz.tables import number

from tests.viz.layout import ATTACHED, legend_gaps, stacked_markers
from tests.viz.test_figure_text import _problems

matplotlib = pytest.importorskip("matplotlib")

ROD = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))


def rod_factory(angle):
    return PlanarBody.rod(mass=1.0, length=1.0, angle=angle)


def labelled(ax, needle):
    """The lines of ``ax`` whose legend label contains ``needle``."""
    return [ln for ln in ax.get_lines() if needle in ln.get_label()]


@pytest.fixture(scope="module")
def reverse():
    imp = solve_planar(ROD, 1.0, -1.0, 0.0, mu=0.3, kappa=0.8, law="poisson")
    assert imp.regime == "reverse-restitution"
    return imp


def test_routh_diagram_draws_path_lines_cone_and_breakpoints(reverse, tmp_path):
    fig = viz.plot_routh_planar(reverse)
    (ax,) = fig.get_axes()
    assert "$\\tau$" in ax.get_xlabel() and "$f$" in ax.get_ylabel()
    (path,) = labelled(ax, "impulse path")
    tau, f = path.get_data()
    # the path ends at (tau1, f1) of the result (the last point of history(): exact)
    assert tau[-1] == float(reverse.tau1) and f[-1] == float(reverse.tangential_impulse)
    # the two lines of Routh's diagram: v = 0 and u = 0 for the impulses on them
    w = ROD.collision_matrix
    a, b, d = float(w.tt), float(w.tn), float(w.nn)
    u0, v0 = float(reverse.slip_before), float(reverse.normal_velocity_before)
    (compression,) = labelled(ax, "compression line")
    (sticking,) = labelled(ax, "sticking line")
    for line, (nt, nf, c) in ((compression, (d, b, -v0)), (sticking, (b, a, -u0))):
        for x, y in (line.get_xy1(), line.get_xy2()):
            assert nt * x + nf * y == pytest.approx(c, rel=1e-12)  # rounding of one foot
    # the cone f = +- mu tau
    for line in labelled(ax, "friction cone"):
        x, y = line.get_data()
        np.testing.assert_allclose(np.abs(y), 0.3 * x, rtol=1e-15)
    # breakpoints: tau0 lies on the compression line, tau* on the sticking line
    t0, ts = float(reverse.tau0), float(reverse.tau_star)
    (m0,) = labelled(ax, "end of compression")
    (ms,) = labelled(ax, "slip stops")
    (m1,) = labelled(ax, "$f_1")
    assert "and reverses" in ms.get_label()  # one marker where the slip stops and reverses
    assert m0.get_xdata()[0] == t0 and ms.get_xdata()[0] == ts
    assert d * t0 + b * m0.get_ydata()[0] == pytest.approx(-v0, rel=1e-12)
    assert b * ts + a * ms.get_ydata()[0] == pytest.approx(-u0, abs=1e-12)
    assert m1.get_xdata()[0] == float(reverse.tau1)
    assert reverse.regime in fig.get_suptitle()
    target = tmp_path / "routh.png"
    fig.savefig(target, dpi=40)
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_routh_diagram_marks_no_reversal_when_the_contact_sticks():
    imp = solve_planar(ROD, 0.2, -1.0, 0.0, mu=0.8, kappa=0.5, law="newton")
    assert imp.regime.startswith("stick")
    ax = viz.plot_routh_planar(imp).get_axes()[0]
    assert labelled(ax, "reverses") == []
    assert "rank one" not in labelled(ax, "sticking line")[0].get_label()


def test_routh_diagram_of_a_pendulum_has_one_line():
    imp = solve_pendulum(PENDULUM, -2.0, mu=0.2, kappa=0.8)
    ax = viz.plot_routh_planar(imp).get_axes()[0]
    assert "rank one" in labelled(ax, "sticking line")[0].get_label()
    x, y = labelled(ax, "impulse path")[0].get_data()
    assert (x[-1], y[-1]) == (float(imp.tau1), float(imp.tangential_impulse))


def test_routh_diagram_refuses_arrays_and_unended_impacts(reverse):
    many = solve_planar(ROD, [1.0, 2.0], -1.0, 0.0, mu=0.3, kappa=0.8)
    with pytest.raises(ValueError, match="one impact"):
        viz.plot_routh_planar(many)
    with pytest.raises(ValueError, match="no finite impulse"):
        viz.plot_routh_planar(dataclasses.replace(reverse, tau1=np.float64("nan")))
    with pytest.raises(TypeError, match="PlanarImpact"):
        viz.plot_routh_planar("rod")


def test_laws_figure_marks_each_law_end_and_tabulates_it():
    fig = viz.plot_laws(ROD, 1.0, -1.0, 0.0, 0.3, 0.8)
    imps = {law: solve_planar(ROD, 1.0, -1.0, 0.0, mu=0.3, kappa=0.8, law=law) for law in LAWS}
    vax, eax = fig.get_axes()[:2]
    assert "$v$" in vax.get_ylabel() and "$E$" in eax.get_ylabel()
    for law, imp in imps.items():
        name = viz.LAW_NAMES[law]
        (mv,) = labelled(vax, name)
        (me,) = labelled(eax, name)
        assert mv.get_xdata()[0] == me.get_xdata()[0] == float(imp.tau1)
        assert mv.get_ydata()[0] == float(imp.normal_velocity_after)
        assert me.get_ydata()[0] == float(imp.kinetic_energy_after)
    # Newton's coefficient is kappa under Newton's law, Poisson's under Poisson's ...
    table = fig.get_axes()[-1].tables[0]
    cells = {c.get_text().get_text() for c in table.get_celld().values()}
    for law, imp in imps.items():
        assert viz.LAW_NAMES[law] in cells
        assert number(imp.tau1) in cells and number(imp.energetic_restitution) in cells
    # ... and the three differ when the impulses couple
    assert len({round(float(i.tau1), 12) for i in imps.values()}) == 3


def test_laws_figure_of_a_pendulum():
    fig = viz.plot_laws(PENDULUM, None, None, -2.0, 0.2, 0.8)
    imp = solve_pendulum(PENDULUM, -2.0, mu=0.2, kappa=0.8, law="energetic")
    (mark,) = labelled(fig.get_axes()[0], viz.LAW_NAMES["energetic"])
    assert mark.get_xdata()[0] == float(imp.tau1)
    with pytest.raises(ValueError, match="vx=None"):
        viz.plot_laws(PENDULUM, 1.0, -1.0, -2.0, 0.2, 0.8)


def test_map_is_one_vectorized_solve_and_labels_the_regimes_present(monkeypatch):
    calls = []

    def counting(body, vx, vy, omega, **kw):
        calls.append((np.shape(body.rx), np.shape(vx), kw["law"]))
        return solve_planar(body, vx, vy, omega, **kw)

    monkeypatch.setattr(viz, "solve_planar", counting)
    n = 24
    fig = viz.plot_planar_map(rod_factory, mu=0.8, kappa=0.9, n=n)
    assert calls == [((1, n), (n, 1), "newton")]  # the whole grid in one call
    rx, ex = fig.get_axes()[:2]
    codes = rx.get_images()[0].get_array()
    assert codes.shape == (n, n)
    angles = (np.arange(n) + 0.5) * math.pi / n
    ratio = np.linspace(-3.0, 3.0, n)
    grid = solve_planar(
        rod_factory(angles[None, :]), ratio[:, None], -1.0, 0.0, mu=0.8, kappa=0.9, law="newton"
    )
    present = [r for r in PLANAR_REGIMES if np.any(grid.regime == r)]
    assert [t.get_text() for t in rx.get_legend().get_texts()] == present
    # pixel [j, i] is the impact at angle i and slip ratio j
    i, j = 5, 17
    one = solve_planar(rod_factory(angles[i]), ratio[j], -1.0, 0.0, mu=0.8, kappa=0.9, law="newton")
    assert PLANAR_REGIMES[int(codes[j, i])] == one.regime
    gain = ex.get_images()[0].get_array()
    assert gain[j, i] == pytest.approx(-float(one.dissipated_fraction), rel=1e-12)
    assert grid.creates_energy.any() and "creates energy" in ex.get_title()
    assert "Newton creates energy" in ex.get_legend().get_texts()[0].get_text()
    assert "$u^-/|v^-|$" in rx.get_ylabel() and "degrees" in rx.get_xlabel()


def test_map_of_a_block_under_another_law(monkeypatch):
    calls = []

    def counting(body, vx, vy, omega, **kw):
        calls.append(kw["law"])
        assert np.shape(body.rx) == (1, 12)  # the preset accepted every default angle
        return solve_planar(body, vx, vy, omega, **kw)

    monkeypatch.setattr(viz, "solve_planar", counting)
    block = lambda a: PlanarBody.block(mass=1.0, width=0.2, height=0.1, angle=a)  # noqa: E731
    fig = viz.plot_planar_map(block, mu=0.3, kappa=0.7, law="poisson", n=12)
    assert calls == ["newton", "poisson"]
    assert "Poisson" in fig.get_axes()[0].get_title()
    assert "no energy" in fig.get_axes()[1].get_title()


def test_map_bad_input():
    with pytest.raises(TypeError, match="callable"):
        viz.plot_planar_map(ROD, mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match="n must be an integer >= 2"):
        viz.plot_planar_map(rod_factory, mu=0.3, kappa=0.5, n=1)
    custom = lambda a: PlanarBody(1.0, 0.1, 0.1 * np.cos(a), -0.2)  # noqa: E731
    with pytest.raises(ValueError, match="give the angles"):
        viz.plot_planar_map(custom, mu=0.3, kappa=0.5, n=4)


def test_planar_tables_hold_the_result(reverse):
    tables = {t.key: t for t in planar_tables(reverse)}
    assert list(tables) == ["inputs", "rebound", "impulses", "energy", "works", "coefficients"]
    assert ("end of impact, tau1", number(reverse.tau1)) in tables["impulses"].rows
    assert ("vx (m/s)", "1", number(reverse.after.vx)) in tables["rebound"].rows
    assert ("creates energy (E+ > E-)", "no") in tables["coefficients"].rows
    pend = planar_tables(solve_pendulum(PENDULUM, -2.0, mu=0.2, kappa=0.8))
    assert ("px", number(PENDULUM.px, "m")) in pend[0].rows


@pytest.mark.slow
def test_no_marker_hides_another():
    """Where tau_0, tau_* and tau_1 coincide (a pendulum's slip stops and reverses at the
    end of compression; kappa = 0 ends the impact there) one marker names them all; the
    pendulum's diagram once stacked three markers on one point, and the laws figure
    stacked the three laws' ends where they coincide."""
    pendulum = solve_pendulum(PENDULUM, -2.0, mu=0.3, kappa=0.8)
    assert pendulum.tau0 == pendulum.tau_star and pendulum.regime.startswith("reverse")
    impacts = {
        "pendulum": pendulum,
        "reverse": solve_planar(ROD, 1.0, -1.0, 0.0, mu=0.3, kappa=0.8, law="poisson"),
        "kappa 0": solve_planar(ROD, 0.2, -1.0, 0.0, mu=0.8, kappa=0.0, law="newton"),
    }
    for name, imp in impacts.items():
        ax = viz.plot_routh_planar(imp).get_axes()[0]
        assert stacked_markers(ax) == [], name
    (ax,) = viz.plot_routh_planar(pendulum).get_axes()
    (mark,) = labelled(ax, "end of compression")
    assert r"$\tau_0 = \tau_*" in mark.get_label() and "slip stops and reverses" in mark.get_label()
    assert mark.get_xdata()[0] == float(pendulum.tau0)
    upright = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(90))  # W_tn = 0
    for body, args in (
        (upright, (1.0, -1.0, 0.0)),
        (PENDULUM, (None, None, -2.0)),
        (ROD, (1.0, -1.0, 0.0)),
    ):
        fig = viz.plot_laws(body, *args, 0.3, 0.8)
        for ax in fig.get_axes()[:2]:
            assert stacked_markers(ax) == [], body.name
    fig = viz.plot_laws(upright, 1.0, -1.0, 0.0, 0.3, 0.8)
    (end,) = [ln for ln in fig.get_axes()[0].get_lines() if "tau_1" in ln.get_label()]
    assert end.get_label().startswith("all three laws")


@pytest.mark.parametrize(
    "body, args",
    [(ROD, (1.0, -1.0, 0.0)), (PENDULUM, (None, None, -2.0))],
    ids=["rod", "pendulum"],
)
@pytest.mark.slow
def test_laws_figure_legend_sits_beside_its_panels(body, args):
    """The legend once floated in a column of its own, 0.7 inch right of the panels."""
    fig = viz.plot_laws(body, *args, 0.3, 0.8)
    gaps = legend_gaps(fig)
    assert len(gaps) == 1 and gaps[0] < ATTACHED, gaps
    assert _problems(fig) == []


def _round_steps(ticks):
    """The steps between neighbouring ``ticks``, as (mantissa, ok) where ok says the
    step is 1, 2, 2.5 or 5 times a power of ten and every tick is a multiple of it."""
    ticks = np.sort(np.asarray(ticks, float))
    steps = np.diff(ticks)
    if not np.allclose(steps, steps[0], rtol=1e-9):
        return False
    power = 10.0 ** math.floor(math.log10(steps[0]))
    mantissa = steps[0] / power
    multiples = ticks / steps[0]
    return any(math.isclose(mantissa, m, rel_tol=1e-9) for m in (1, 2, 2.5, 5, 10)) and bool(
        np.allclose(multiples, np.round(multiples), atol=1e-9)
    )


@pytest.mark.parametrize("mu, kappa", [(0.8, 0.9), (0.3, 0.8), (0.5, 0.5), (0.1, 1.0)], ids=str)
def test_map_colour_bar_ticks_are_round_numbers(mu, kappa):
    """The energy bar once read 0.0820, 0.0410, -0.2172, -0.4344: ticks at equal fifths
    of each side. Each side of 0 now has round, evenly spaced ticks inside the bar."""
    fig = viz.plot_planar_map(rod_factory, mu=mu, kappa=kappa, n=40)
    (bar,) = [ax for ax in fig.get_axes() if "under Newton" in ax.get_ylabel()]
    ticks = np.asarray(bar.get_yticks(), float)
    low, high = bar.get_ylim()
    shown = ticks[(ticks >= low - 1e-12) & (ticks <= high + 1e-12)]
    assert 0.0 in shown and len(shown) >= 3
    below, above = shown[shown <= 0], shown[shown >= 0]
    for side in (below, above):
        if len(side) > 1:
            assert _round_steps(side), shown
    labels = [t.get_text() for t in bar.get_yticklabels() if t.get_text()]
    assert all(len(label.replace("\u2212", "-").lstrip("-")) <= 5 for label in labels), labels
