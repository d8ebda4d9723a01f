"""Figures: the Python API returns Matplotlib figures; `spinimpact figures` writes
the paper's figures as files of the expected size."""

import struct
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.viz.plots import (
    PAPER_FIGURES,
    incidence_grid,
    paper_figure,
    plot_energy,
    plot_history,
    plot_map,
    plot_routh,
)

from tests.viz.layout import ATTACHED, legend_gaps

matplotlib = pytest.importorskip("matplotlib")


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


@pytest.fixture(scope="module")
def impact():
    return solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.25, kappa=0.6)


def test_history_figure_draws_the_process(impact):
    fig = plot_history(impact)
    axes = fig.get_axes()
    assert len(axes) == 4
    h = impact.history(401)
    # the plotted curves are the history arrays, in the paper's panel order
    for ax, y in zip(axes, (h.force_ratio, h.vy, h.slip, h.omega), strict=True):
        line = ax.get_lines()[0]
        np.testing.assert_array_equal(line.get_ydata(), y)
        np.testing.assert_array_equal(line.get_xdata(), h.tau)
        # tau0, tau* and tau1 are marked
        marks = {
            round(float(x.get_xdata()[0]), 12)
            for x in ax.get_lines()[1:]
            if len(set(x.get_xdata())) == 1
        }
        assert {round(float(t), 12) for t in (h.tau0, h.tau_star, h.tau1)} <= marks
    assert "stick-restitution" in fig.get_suptitle()


def test_routh_and_energy_figures(impact):
    fig = plot_routh(impact)
    f = [ln for ln in fig.get_axes()[0].get_lines() if ln.get_label() == r"$f(\tau)$"][0]
    assert f.get_ydata()[-1] == pytest.approx(float(impact.tangential_impulse))
    fig = plot_energy(impact)
    ax, bars = fig.get_axes()
    x, y = ax.get_lines()[1].get_data()  # the marked minimum
    assert x[0] == pytest.approx(float(impact.tau_min_energy))
    assert y[0] == pytest.approx(float(impact.min_kinetic_energy))
    heights = sorted(round(p.get_height(), 12) for p in bars.patches)
    works = (
        impact.work_compression_normal,
        impact.work_restitution_normal,
        impact.work_compression_tangential,
        impact.work_restitution_tangential,
    )
    assert heights == sorted(round(float(w), 12) for w in works)


@pytest.mark.parametrize(
    ("name", "regime"),
    [
        ("fig2", "stick-restitution"),
        ("fig3", "slip"),
        ("fig4a", "stick-restitution"),
        ("fig4b", "slip"),
        ("fig5a", "stick-restitution"),
        ("fig5b", "stick-compression"),
        ("fig5c", "slip"),
    ],
)
def test_paper_figures_are_in_their_regimes(name, regime):
    fig = paper_figure(name)
    assert regime in fig.get_suptitle()
    if name.startswith("fig5"):
        case = {"fig5a": "Fig. 5a", "fig5b": "Fig. 5b", "fig5c": "Fig. 5c"}[name]
        assert case in fig.get_axes()[0].get_title()


@pytest.mark.parametrize("name", sorted(PAPER_FIGURES))
@pytest.mark.slow
def test_paper_figures_legends_sit_at_their_panels(name):
    """Figs. 5a-c once put the works' legend in the figure's corner, a quarter inch below
    the panel it explains."""
    gaps = legend_gaps(paper_figure(name))
    assert all(gap < ATTACHED for gap in gaps), gaps


def test_unknown_paper_figure():
    with pytest.raises(ValueError, match="figure must be one of"):
        paper_figure("fig9")


@pytest.mark.slow
def test_figures_command_writes_every_figure(tmp_path):
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "spinimpact",
            "figures",
            "--output-dir",
            str(tmp_path),
            "--dpi",
            "50",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    for name in PAPER_FIGURES:
        path = tmp_path / f"{name}.png"
        kind = PAPER_FIGURES[name][0]
        inches = {"history": (8, 6.4), "routh": (6, 4.4), "energy": (9, 4.2)}[kind]
        assert png_size(path) == (round(inches[0] * 50), round(inches[1] * 50))
        assert path.stat().st_size > 5000
    assert not list(tmp_path.glob(".*"))  # no temporary files left


@pytest.mark.slow
def test_figures_command_svg_and_bad_output(tmp_path):
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "spinimpact",
            "figures",
            "--output-dir",
            str(tmp_path),
            "--format",
            "svg",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0
    assert (tmp_path / "fig3.svg").read_text().lstrip().startswith("<?xml")
    blocker = tmp_path / "file"
    blocker.write_text("x")
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "figures", "--output-dir", str(blocker)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 2 and len(out.stderr.strip().splitlines()) == 1


def test_incidence_grid_is_dimensionless_and_oriented():
    body = Body.solid_disk(mass=2.0, radius=0.05)
    a, b, imp = incidence_grid(body, mu=0.3, kappa=0.5, extent=2.0, n=21)
    assert imp.shape == (21, 21)
    # element [j, i] is the impact at vx/|vy| = a[i], R omega/|vy| = b[j]; any |vy| gives
    # the same dimensionless results
    i, j, vy = 3, 17, -4.0
    same = solve(body, a[i] * 4.0, vy, b[j] * 4.0 / 0.05, mu=0.3, kappa=0.5)
    assert imp[j, i].regime == same.regime
    loss = same.dissipated_energy / same.kinetic_energy_before
    assert imp[j, i].dissipated_energy / imp[j, i].kinetic_energy_before == pytest.approx(loss)
    assert imp[j, i].impulse_ratio == pytest.approx(same.impulse_ratio)
    with pytest.raises(ValueError, match="n must be an integer >= 2"):
        incidence_grid(body, mu=0.3, kappa=0.5, n=1)


def test_map_figure_panels():
    fig = plot_map(Body.ring(mass=1.0, radius=0.1), mu=0.3, kappa=0.5, n=40)
    titles = [ax.get_title() for ax in fig.get_axes()]
    for needle in ("regime", "rebound outcome", "energy lost", r"$\hat\mu", "$W_r^t/W_c^t$"):
        assert any(needle in t for t in titles), needle
    # every panel carries the four boundary lines |a + b| = zeta mu, (1 + kappa) zeta mu
    regime_ax = fig.get_axes()[0]
    assert len(regime_ax.get_lines()) == 4


@pytest.mark.slow  # renders a whole page or map (about a second)
def test_friction_work_panel_shows_no_line_where_the_ratio_is_undefined():
    """On the no-slip line ``u^- = 0`` friction does no work and ``W_r^t/W_c^t`` is 0/0;
    its limit from both sides is 0 (the contact sticks in compression). Drawn as
    missing, those pixels once showed a dotted white line along the panel's diagonal."""
    fig = plot_map(Body.solid_sphere(mass=1.0, radius=0.1), mu=0.2, kappa=0.8, n=41)
    (panel,) = [ax for ax in fig.get_axes() if "friction work" in ax.get_title()]
    (image,) = panel.get_images()
    data = image.get_array()
    missing = np.ma.getmaskarray(np.ma.masked_invalid(data))
    assert missing.any()  # the grid is symmetric: (a, -a) lies on the line u^- = 0
    colours = image.to_rgba(data)
    np.testing.assert_array_equal(
        colours[missing], np.broadcast_to(image.to_rgba(0.0), colours[missing].shape)
    )
    no_friction = plot_map(Body.solid_sphere(mass=1.0, radius=0.1), mu=0.0, kappa=0.8, n=8)
    (panel,) = [ax for ax in no_friction.get_axes() if "friction work" in ax.get_title()]
    assert "undefined" in panel.get_title()  # no friction: undefined everywhere, and said


@pytest.mark.slow
def test_map_command(tmp_path):
    target = tmp_path / "map.png"
    target.write_bytes(b"previous content")
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "spinimpact",
            "map",
            "--output",
            str(target),
            "--resolution",
            "60",
            "--dpi",
            "50",
            "--body",
            "ring",
            "--mu",
            "0.3",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    assert png_size(target) == (750, 460)  # 15 x 9.2 inches at 50 dpi
    bad = subprocess.run(
        [sys.executable, "-m", "spinimpact", "map", "--output", str(target), "--mu", "-1"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert bad.returncode == 2 and "mu must be >= 0" in bad.stderr
    assert png_size(target) == (750, 460)  # the earlier output is untouched
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.png"]
