"""Every text of every figure is typeset with mathtext, and none sits on a curve, a mark
line or another text (issue 10, item 21), checked on the drawn figures' geometry."""

import re

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.viz import plots

matplotlib = pytest.importorskip("matplotlib")
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.text import Text  # noqa: E402
from matplotlib.transforms import Bbox  # noqa: E402

DISK = Body.solid_disk(mass=1.0, radius=0.1)
SPHERE = Body.solid_sphere(mass=1.0, radius=0.1)

#: (body, vx, vy, omega, mu, kappa): the regimes, both slip directions, and the layouts
#: that put a label on a line before (Fig. 4a's tau1, sticking diagrams, the
#: frictionless tau0, an energy minimum at rebound, marks close together).
CASES = {
    "default": (SPHERE, 3.0, -4.0, 10.0, 0.2, 0.8),
    "frictionless": (SPHERE, 3.0, -4.0, 10.0, 0.0, 0.8),
    "head-on": (SPHERE, 0.0, -4.0, 0.0, 0.2, 0.8),
    "stick-compression, backward": (DISK, -0.5, -1.0, 2.0, 0.25, 0.6),
    "tau* near tau0": (DISK, 0.745, -1.0, 0.0, 0.25, 0.6),
    "tau* near tau1": (DISK, 1.19, -1.0, 0.0, 0.25, 0.6),
    "kappa 0": (DISK, 0.3, -1.0, 0.0, 0.25, 0.0),
    "three marks together": (DISK, 0.752, -1.0, 0.0, 0.25, 0.01),
    "minimum at rebound": (DISK, 3.0, -1.0, 0.0, 0.05, 0.1),
    "slip, u < 0": (Body.ring(mass=2.0, radius=0.3), -4.0, -1.0, -5.0, 0.3, 0.9),
    "spool": (Body(mass=0.2, radius=0.01, gyration=0.03), 1.0, -2.0, 30.0, 0.4, 0.5),
}

_MATH = re.compile(r"(?<!\\)\$.*?(?<!\\)\$")
_UNTYPESET = re.compile(
    r"[\u0300-\u036f\u0370-\u03ff\u2070-\u209f√≤≥]"  # Greek, combining, sub/superscripts
    r"|\b(tau|zeta|kappa|omega|mu|rho|Delta|sqrt)\b|[_^]"
    r"|(?<![A-Za-z])(u|v|vx|vy|E)[-+](?![A-Za-z])"
)


def _figures(name):
    body, vx, vy, omega, mu, kappa = CASES[name]
    imp = solve(body, vx, vy, omega, mu=mu, kappa=kappa)
    return plots.impact_figures(imp)


def _drawn(fig):
    FigureCanvasAgg(fig)
    fig.set_dpi(40)  # the layout in inches does not depend on it; drawing is faster
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def _texts(fig):
    """The texts a reader sees: tick labels only of the ticks drawn (Matplotlib keeps
    labels of ticks outside the view, never drawn)."""
    ticks, drawn = set(), []
    for ax in _axes(fig):
        for axis in (ax.xaxis, ax.yaxis):
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                ticks |= {id(tick.label1), id(tick.label2)}
            for tick in axis._update_ticks():  # the ticks inside the view
                drawn += [t for t in (tick.label1, tick.label2) if t.get_visible()]
    others = [t for t in fig.findobj(Text) if id(t) not in ticks and t.get_visible()]
    return [t for t in others + drawn if t.get_text().strip() and t.figure is not None]


def _axes(fig):
    """Every axes (colour bars included), with the child axes (the marks' top axes)."""
    out = []
    for ax in fig.get_axes():
        out += [ax, *ax.child_axes]
    return out


def _crossing(box, line, renderer):
    """Whether ``line`` (clipped to its axes) passes through ``box``, in pixels."""
    inside = Bbox.intersection(box, line.axes.bbox)
    if inside is None or inside.width <= 0 or inside.height <= 0:
        return False
    path = line.get_transform().transform_path(line.get_path())
    if line.get_linestyle() in ("None", "", " "):  # markers only: their centres
        x, y = path.vertices.T
        return bool(
            np.any((x >= inside.x0) & (x <= inside.x1) & (y >= inside.y0) & (y <= inside.y1))
        )
    return path.intersects_bbox(inside, filled=False)


def _problems(fig):
    renderer = _drawn(fig)
    texts = _texts(fig)
    boxes = [t.get_window_extent(renderer).shrunk(0.96, 0.9) for t in texts]
    for ax in _axes(fig):
        legend = ax.get_legend()
        if legend is not None:
            texts.append(legend)
            boxes.append(legend.get_window_extent(renderer))
    lines = [ln for ax in _axes(fig) for ln in ax.get_lines() if ln.get_visible()]
    out = []
    for text, box in zip(texts, boxes, strict=True):
        for line in lines:
            if _crossing(box, line, renderer):
                out.append(f"{_name(text)!r} on line {line.get_label()!r}")
    legend_texts = {
        id(t)
        for ax in _axes(fig)
        if ax.get_legend()
        for t in (*ax.get_legend().texts, ax.get_legend().get_title())
    }
    for i, (a, box_a) in enumerate(zip(texts, boxes, strict=True)):
        for b, box_b in zip(texts[i + 1 :], boxes[i + 1 :], strict=True):
            inside_legend = {id(a), id(b)} & legend_texts or "Legend" in type(a).__name__
            if not inside_legend and box_a.overlaps(box_b):
                out.append(f"{_name(a)!r} on {_name(b)!r}")
    return out


def _name(artist):
    return artist.get_text() if isinstance(artist, Text) else type(artist).__name__


def _untypeset(fig):
    found = []
    for t in _texts(fig):
        plain = _MATH.sub("", t.get_text()).replace(r"\$", "")
        if _UNTYPESET.search(plain):
            found.append(t.get_text())
    return found


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.slow
def test_impact_figures_have_no_text_on_a_line_or_a_text(name):
    for kind, fig in _figures(name).items():
        assert _problems(fig) == [], (name, kind)
        assert _untypeset(fig) == [], (name, kind)


@pytest.mark.parametrize("name", sorted(plots.PAPER_FIGURES))
@pytest.mark.slow
def test_paper_figures_are_typeset_and_clear(name):
    fig = plots.paper_figure(name)
    assert _problems(fig) == []
    assert _untypeset(fig) == []


@pytest.mark.parametrize(("mu", "kappa"), [(0.2, 0.8), (0.0, 0.5), (0.6, 0.0)])
@pytest.mark.slow
def test_maps_are_typeset_and_clear(mu, kappa):
    fig = plots.plot_map(Body.solid_sphere(mass=1.0, radius=0.1), mu=mu, kappa=kappa, n=24)
    assert _untypeset(fig) == []
    assert _problems(fig) == []


@pytest.mark.slow
def test_simulation_figure_is_typeset_and_clear():
    from spinimpact.dynamics import LinearContact, simulate

    sim = simulate(SPHERE, 3.0, -4.0, 10.0, mu=0.2, contact=LinearContact(1e6, 0.0))
    fig = plots.plot_simulation(sim)
    assert _untypeset(fig) == []
    assert _problems(fig) == []


@pytest.mark.slow
def test_the_checks_find_what_they_look_for():
    """The geometry check sees a label put on a curve, and the typesetting check sees
    ASCII and Unicode math (so a passing figure means something)."""
    fig = _figures("default")["routh"]
    ax = fig.get_axes()[0]
    line = [ln for ln in ax.get_lines() if ln.get_label() == r"$f(\tau)$"][0]
    x, y = line.get_data()
    ax.text(x[len(x) // 2], y[len(y) // 2], "on the line", ha="center", va="center")
    ax.set_ylabel("friction impulse f (N s), tau1, W_r^t, u- < 0")
    assert any("on the line" in p for p in _problems(fig))
    assert _untypeset(fig) == ["friction impulse f (N s), tau1, W_r^t, u- < 0"]
    ax.set_ylabel("τ₁ and μ̂")
    assert _untypeset(fig) == ["τ₁ and μ̂"]
