"""Report tables and figure of a sphere's 3D impact (:func:`~spinimpact.solve_sphere`) or of
two spheres colliding (:func:`~spinimpact.solve_pair`).

:func:`sphere_tables` builds the report's tables once, as plain
:class:`~spinimpact.viz.tables.Table` data, for the terminal (``spinimpact sphere`` and
``pair``: ASCII labels) and the HTML page (:mod:`spinimpact.viz.sphere_html`: typeset
labels); angles are in degrees there, the results hold radians. :func:`plot_sphere` draws
the side view ``(x, y)`` and the top view ``(x, z)`` with the velocity and spin arrows.
Spin after (:class:`~spinimpact.SphereImpact`): topspin about ``n x e_t`` (negative:
backspin), side spin about the normal ``n`` (positive: counter-clockwise seen from the
normal's side, "from above"), gyrospin about the direction of travel ``e_t``. Nothing here
computes physics: every number is a field of the result.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from ..model.pair import PairImpact
from ..model.sphere3d import SphereImpact
from ._labels import notation
from .tables import Table, number

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["RPM", "sphere_tables", "headline", "plot_sphere"]

#: rad/s in one revolution per minute.
RPM = 2 * math.pi / 60
#: Typeset forms of this module's labels (the shared ones are in ``viz._labels``).
_TYPESET = {
    "wx (rad/s)": "ωx (rad/s)", "wy (rad/s)": "ωy (rad/s)", "wz (rad/s)": "ωz (rad/s)",
    "slip speed |c_t| (m/s)": "slip speed |cₜ| (m/s)", "mu_hat = |F|/tau1": "μ̂ = |F|/τ₁",
    "contact normal velocity c_n (m/s)": "contact normal velocity cₙ (m/s)",
    "rebound speed |v+|": "rebound speed |v⁺|", "total spin |w+|": "total spin |ω⁺|",
}  # fmt: skip


def _labeller(typeset: bool) -> Callable[[str], str]:
    shared = notation(typeset)
    return (lambda s: _TYPESET.get(s, shared(s))) if typeset else shared


def _vec(x: Any, unit: str = "") -> str:
    """A 3-vector as ``(x, y, z) unit``, each component by :func:`number`."""
    return f"({', '.join(number(p) for p in np.asarray(x, float).reshape(3))}) {unit}".rstrip()


def _deg(x: Any) -> str:
    value = float(x)
    return number(value) if math.isnan(value) else f"{math.degrees(value) + 0.0:.6g}°"


def _norm(x: Any) -> float:
    return float(np.linalg.norm(np.asarray(x, float)))


def _leaves(imp: SphereImpact | PairImpact) -> str:
    """Whether the contact leaves without slip (grips) or still slipping (skids)."""
    if bool(imp.grips):
        return "grips (leaves rolling, no slip)"
    return f"skids (leaves sliding at {number(_norm(imp.slip_after.array), 'm/s')})"


def _spin_rows(imp: SphereImpact) -> tuple[tuple[str, ...], ...]:
    """Topspin or backspin, side spin, gyrospin and the total after, in rpm and rad/s."""
    top, side, gyro = (float(x) for x in (imp.topspin, imp.sidespin, imp.gyrospin))
    top_label = "topspin / backspin" if math.isnan(top) else ("backspin", "topspin")[top >= 0]
    rows = ((top_label, abs(top)),
            (f"side spin, {('clockwise', 'counter-clockwise')[side >= 0]}", abs(side)),
            ("gyrospin, about the travel", gyro),
            ("total spin |w+|", _norm(imp.after.spin)))  # fmt: skip
    return tuple((k, number(v / RPM), number(v)) for k, v in rows)


def _table(label: Callable[[str], str], key: str, title: str, columns: tuple, rows: tuple) -> Table:
    return Table(key, title, tuple(map(label, columns)), tuple((label(r[0]), *r[1:]) for r in rows))


def _body_rows(body: Any, label: Callable[[str], str], ball: int = 0) -> list[tuple[str, str]]:
    rows = [("body", str(body.name)), ("mass m", number(body.mass, "kg")),
            ("radius R", number(body.radius, "m")),
            ("radius of gyration rho", number(body.gyration, "m")),
            ("zeta = 1 + R^2/rho^2", number(body.zeta))]  # fmt: skip
    return [(label(k) + f", ball {ball}" * (ball > 0), v) for k, v in rows]


def _common(imp: SphereImpact | PairImpact, label: Callable[[str], str], frame: str) -> list:
    """The impulses, energy, works and coefficients tables (the same for both kinds)."""
    n, e0 = number, float(imp.kinetic_energy_before)
    wn = (imp.work_compression_normal, imp.work_restitution_normal)
    wt = (imp.work_compression_tangential, imp.work_restitution_tangential)
    energies = (("kinetic energy before, E-", e0),
                ("kinetic energy after, E+", imp.kinetic_energy_after),
                ("dissipated, E- - E+", imp.dissipated_energy))  # fmt: skip
    phases = zip(("compression", "restitution", "whole impact"), (*wn, sum(wn)), (*wt, sum(wt)),
                 strict=True)  # fmt: skip
    tables = (
        ("impulses", "Impulses", ("impulse", "N s"), (
            ("end of compression, tau0", n(imp.tau0)), ("end of slip, tau*", n(imp.tau_star)),
            ("end of impact, tau1", n(imp.tau1)),
            ("friction impulse |F|", n(_norm(imp.friction_impulse.array))),
            ("friction impulse F (N s)", _vec(imp.friction_impulse.array)),
            ("mu_hat = |F|/tau1", n(imp.impulse_ratio)))),
        ("energy", "Energy budget", ("energy", "J", "of E-"), (
            *((k, n(v), f"{float(v) / e0:.2%}" if e0 else "") for k, v in energies),
            (f"dissipated, share in the {frame}", "", f"{float(imp.dissipated_fraction):.2%}"))),
        ("works", "Works of the contact forces",
         ("phase", "normal (J)", "friction (J)", "total (J)"),
         tuple((p, n(x), n(y), n(x + y)) for p, x, y in phases)),
        ("coefficients", "Coefficients", ("coefficient", "value"), (
            ("Newton restitution -v+/v-", n(imp.newton_restitution)),
            ("Poisson restitution (tau1-tau0)/tau0", n(imp.poisson_restitution)),
            ("energetic restitution sqrt(-Wr^n/Wc^n)", n(imp.energetic_restitution)))),
    )  # fmt: skip
    return [_table(label, *t) for t in tables]


def sphere_tables(imp: SphereImpact | PairImpact, *, typeset: bool = False) -> tuple[Table, ...]:
    """The tables of a sphere's (or a pair's) report, in the order a report shows them.

    Parameters
    ----------
    imp : SphereImpact or PairImpact
        One impact (shape ``()``).
    typeset : bool, optional
        Unicode labels (``ω``, ``τ₁``, ``μ̂``) instead of ASCII; the values are the same.

    Returns
    -------
    tuple of Table
        Keys ``outcome`` (regime; rebound speed, m/s, and angle, degrees, or a pair's angle
        between the paths and speeds; grips or skids), ``spin`` (a sphere's topspin or
        backspin, side spin, gyrospin and total after, rpm and rad/s) or ``contact`` (a
        pair's relative contact velocity), ``inputs``, ``motion`` (velocity and spin
        components before and after), ``impulses``, ``energy``, ``works``, ``coefficients``.

    Raises
    ------
    TypeError
        For anything but a :class:`~spinimpact.SphereImpact` or :class:`~spinimpact.PairImpact`.
    ValueError
        For more than one impact.
    """
    _single(imp)
    label, n = _labeller(typeset), number
    slip = (_norm(s.array) for s in (imp.slip_before, imp.slip_after))
    contact = (("slip speed |c_t| (m/s)", *map(n, slip)),
               ("contact normal velocity c_n (m/s)", n(imp.normal_velocity_before),
                n(imp.normal_velocity_after)))  # fmt: skip
    if isinstance(imp, PairImpact):
        outcome = (("regime", str(imp.regime)),
                   ("angle between the paths after", _deg(imp.angle_between_paths)),
                   ("speed of ball 1 after", n(_norm(imp.after1.velocity), "m/s")),
                   ("speed of ball 2 after", n(_norm(imp.after2.velocity), "m/s")),
                   ("contact", _leaves(imp)))  # fmt: skip
        inputs = (*_body_rows(imp.ball1, label, 1), *_body_rows(imp.ball2, label, 2),
                  ("normal n, from ball 2 to ball 1", _vec(imp.normal.array)))  # fmt: skip
        states = {"ball 1 before": imp.before1, "ball 1 after": imp.after1,
                  "ball 2 before": imp.before2, "ball 2 after": imp.after2}  # fmt: skip
        extra = _table(label, "contact", "Contact, ball 1 relative to ball 2",
                       ("", "before", "after"), contact)  # fmt: skip
        frame, contact = "centre-of-mass frame", ()
    else:
        outcome = (("regime", str(imp.regime)),
                   ("rebound speed |v+|", n(imp.rebound_speed, "m/s")),
                   ("rebound angle above the surface", _deg(imp.rebound_angle)),
                   ("contact", _leaves(imp)))  # fmt: skip
        inputs = (*_body_rows(imp.body, label), ("surface normal n", _vec(imp.normal.array)),
                  ("surface velocity", _vec(imp.surface_velocity.array, "m/s")))  # fmt: skip
        states = {"before": imp.before, "after": imp.after}
        extra = _table(label, "spin", "Spin after the impact", ("component", "rpm", "rad/s"),
                       _spin_rows(imp))  # fmt: skip
        frame = "surface frame"
    inputs += (("friction mu", n(imp.mu)), ("restitution kappa", n(imp.kappa)))
    motion = tuple(
        (f"{k} ({'m/s' if k[0] == 'v' else 'rad/s'})", *(n(getattr(s, k)) for s in states.values()))
        for k in ("vx", "vy", "vz", "wx", "wy", "wz")
    ) + contact  # fmt: skip
    return (
        _table(label, "outcome", "Outcome", ("", "value"), outcome),
        extra,
        _table(label, "inputs", "Inputs", ("input", "value"), inputs),
        _table(label, "motion", "Velocity and spin", ("", *states), motion),
        *_common(imp, label, frame),
    )


def headline(imp: SphereImpact | PairImpact) -> str:
    """One sentence: how the ball leaves (or how the two balls part)."""
    _single(imp)
    if isinstance(imp, PairImpact):
        return f"The paths part at {_deg(imp.angle_between_paths)}; the contact {_leaves(imp)}"
    top, size = float(imp.topspin), _norm(imp.after.spin)
    spin = f", with {number(abs(top) / RPM, 'rpm')} of {('backspin', 'topspin')[top >= 0]}"
    spin = spin if abs(top) > 1e-9 * size else ""  # none, or none defined (NaN)
    return (f"The ball leaves at {number(imp.rebound_speed, 'm/s')}, {_deg(imp.rebound_angle)} "
            f"above the surface{spin}; it {_leaves(imp)}")  # fmt: skip


def _single(imp: Any) -> None:
    if not isinstance(imp, SphereImpact | PairImpact):
        raise TypeError(f"expected a SphereImpact or PairImpact, got {type(imp).__name__}")
    if imp.shape != ():
        raise ValueError(f"a report describes one impact; this result has shape {imp.shape}")


# -- the figure ---------------------------------------------------------------------

#: (colour, line width) of each arrow: before wide and light under after narrow and dark.
_STYLE = {("velocity", "before"): ("#8fb8de", 3.2), ("velocity", "after"): ("#1f4e9a", 1.6),
          ("spin", "before"): ("#f1b07a", 3.2), ("spin", "after"): ("#b5470f", 1.6)}  # fmt: skip
_WHEN, _DASH, _GROUND, _MOVING = ("before", "after"), (0, (4, 1.5)), "#6b5b45", "#2e8b57"
_SYMBOL = {("velocity", "before"): "$v^-$", ("velocity", "after"): "$v^+$",
           ("spin", "before"): r"$\omega^-$", ("spin", "after"): r"$\omega^+$"}  # fmt: skip
#: name, title, the axis drawn up the page, the axis toward the reader, and the sign of a
#: positive turn about it in the axes' data coordinates (the top view's z runs down).
_VIEWS = (("side", "side view, looking along -z", 1, 2, 1.0),
          ("top", "top view, seen from above", 2, 1, -1.0))  # fmt: skip


def _balls(imp: SphereImpact | PairImpact) -> list[dict[str, Any]]:
    """Each ball's name, centre (the contact point at the origin), radius and states."""
    n = imp.normal.array
    if isinstance(imp, SphereImpact):
        r = float(imp.body.radius)
        return [{"name": "ball", "centre": r * n, "radius": r, "before": imp.before,
                 "after": imp.after, "fill": "#e6e6e6"}]  # fmt: skip
    pairs = ((imp.ball1, 1, imp.before1, imp.after1), (imp.ball2, -1, imp.before2, imp.after2))
    return [{"name": f"ball{k}", "centre": side * float(b.radius) * n, "radius": float(b.radius),
             "before": s0, "after": s1, "fill": ("#e6e6e6", "#f3e3c3")[k - 1]}
            for k, (b, side, s0, s1) in enumerate(pairs, 1)]  # fmt: skip


def _arrow(ax: Any, path: Any, key: tuple, gid: str, dashed: bool, colour: str = "") -> None:
    """An arrow along ``path`` (points, shape (k, 2)) in the style of ``key``."""
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.path import Path

    ax.add_patch(FancyArrowPatch(
        path=Path(np.asarray(path)), arrowstyle="-|>", mutation_scale=8 + 3 * _STYLE[key][1],
        lw=_STYLE[key][1], color=colour or _STYLE[key][0], linestyle=_DASH if dashed else "-",
        shrinkA=0, shrinkB=0, gid=gid, zorder=4 if key[1] == "after" else 3))  # fmt: skip


def _draw_ball(ax: Any, ball: dict, view: tuple, scale: dict, wmax: float) -> list:
    """One ball in one view: its circle, its arrows and the turn of its spin about the axis
    toward the reader; returns the points the axes must show."""
    from matplotlib.patches import Circle

    name, _, up, toward, turn = view
    c, r = ball["centre"][[0, up]], ball["radius"]
    ax.add_patch(Circle(tuple(c), r, fc=ball["fill"], ec="#555555", lw=1, zorder=2))
    points = [c - r, c + r]
    for quantity, when in _STYLE:
        vector = getattr(ball[when], quantity)
        vec, gid = vector[[0, up]] * scale[quantity], f"{name}-{ball['name']}-{quantity}-{when}"
        if np.any(vec):
            tail = c - vec if (quantity, when) == ("velocity", "before") else c
            _arrow(ax, [tail, tail + vec], (quantity, when), gid, quantity == "spin")
            points += [tail, tail + vec]
        about = float(vector[toward]) if quantity == "spin" else 0.0
        if abs(about) > 0.02 * wmax:  # curved: the turn about the axis toward the reader
            a = np.linspace(0.25, 0.65 + 1.1 * abs(about) / wmax, 40) * np.pi * np.sign(about)
            rho = r * (0.8 if when == "before" else 0.62)
            arc = c + rho * np.stack([np.cos(a), turn * np.sin(a)], -1)
            _arrow(ax, arc, (quantity, when), f"{gid}-turn", dashed=False)
    return points


def plot_sphere(imp: SphereImpact | PairImpact) -> Figure:
    """Side view ``(x, y)`` and top view ``(x, z)`` of one impact with its arrows.

    Parameters
    ----------
    imp : SphereImpact or PairImpact
        One impact (shape ``()``).

    Returns
    -------
    matplotlib.figure.Figure
        Two axes at one equal scale; each ball touches the contact point at the origin (a
        sphere's centre at ``R n``, a pair's at ``R_1 n`` and ``-R_2 n``). Arrows project
        the 3D vectors: velocity before (arriving at the centre) and after (leaving it),
        spin vector before and after (dashed, right-handed); the spin about the axis toward
        the reader (``+z`` side, ``+y`` top) also curves its way round the centre. Velocity
        and spin have their own scales; the legend names the magnitudes. A sphere's surface
        is solid and shaded where a view sees it edge-on, else its dashed trace through the
        contact; a moving surface's velocity is a green arrow. The top view is seen from
        above, so ``z`` runs down the page. Arrow ``gid``:
        ``"{view}-{ball|ball1|ball2}-{velocity|spin}-{before|after}"`` (``-turn`` appended
        for a curved one), ``"{view}-surface-velocity"``.

    Raises
    ------
    TypeError, ValueError
        As :func:`sphere_tables`.
    """
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    _single(imp)
    balls = _balls(imp)
    surface = imp.surface_velocity.array if isinstance(imp, SphereImpact) else np.zeros(3)
    vmax = max(_norm(b[w].velocity) for b in balls for w in _WHEN)
    vmax, wmax = max(vmax, _norm(surface)), max(_norm(b[w].spin) for b in balls for w in _WHEN)
    rmax = max(b["radius"] for b in balls)
    scale = {"velocity": 2.4 * rmax / vmax if vmax else 0.0,
             "spin": 2.0 * rmax / wmax if wmax else 0.0}  # fmt: skip
    fig = Figure(figsize=(10.5, 6), layout="constrained")
    axes, boxes, extra = fig.subplots(1, 2), [], {}
    for ax, view in zip(axes, _VIEWS, strict=True):
        points = [np.zeros(2)] + [
            p for ball in balls for p in _draw_ball(ax, ball, view, scale, wmax)
        ]
        vs = surface[[0, view[2]]] * scale["velocity"]
        if np.any(vs):
            _arrow(ax, [np.zeros(2), vs], ("velocity", "after"), f"{view[0]}-surface-velocity",
                   dashed=False, colour=_MOVING)  # fmt: skip
            points.append(vs)
        ax.plot([0], [0], "o", color="k", ms=3, zorder=5)
        boxes.append((np.min(points, 0), np.max(points, 0)))
    low, high = min(b[0][0] for b in boxes), max(b[1][0] for b in boxes)
    tall = max(b[1][1] - b[0][1] for b in boxes)
    pad = 0.1 * max(high - low, tall, rmax)
    fig.set_size_inches(
        10.5, 1.9 + 4.5 * np.clip((tall + 2 * pad) / (high - low + 2 * pad), 0.5, 1.5)
    )
    for ax, view, (lo, hi) in zip(axes, _VIEWS, boxes, strict=True):
        mid = 0.5 * (lo[1] + hi[1])  # the same ranges in both views: the same scale
        ax.set(xlim=(low - pad, high + pad), ylim=(mid - tall / 2 - pad, mid + tall / 2 + pad))
        if isinstance(imp, SphereImpact):
            extra.update(_surface(ax, imp.normal.array, view))
        ax.set_aspect("equal", adjustable="box")
        if view[0] == "top":
            ax.invert_yaxis()
        ax.set(title=view[1], xlabel="x (m)", ylabel=("y (m)", "z (m)")[view[2] - 1])
        ax.grid(alpha=0.25)
    handles = [Line2D([], [], color=_STYLE[key][0], lw=_STYLE[key][1] + 0.4,
                      ls="-" if key[0] == "velocity" else _DASH, label=_legend(key, balls))
               for key in _STYLE]  # fmt: skip
    handles.append(Line2D([], [], ls="", marker="o", color="k", ms=3, label="contact point"))
    if np.any(surface):
        handles.append(Line2D([], [], color=_MOVING, lw=2,
                              label=f"surface velocity: {_norm(surface):.3g} m/s"))  # fmt: skip
    handles += [Line2D([], [], color=_GROUND, lw=1.2, ls=ls, label=k) for k, ls in extra.items()]
    columns = 4 - (len(balls) > 1)
    fig.legend(
        handles=handles, loc="outside lower center", ncols=columns, fontsize=9, frameon=False
    )
    fig.suptitle(_figure_title(imp), fontsize=11)
    return fig


def _legend(key: tuple[str, str], balls: list[dict[str, Any]]) -> str:
    quantity, when = key
    shown = ", ".join(f"{_norm(getattr(b[when], quantity)):.3g}" for b in balls)
    unit = "m/s" if quantity == "velocity" else "rad/s"
    return f"{_SYMBOL[key]} {quantity} {when}: {shown} {unit}" + " (balls 1, 2)" * (len(balls) > 1)


def _surface(ax: Any, normal: np.ndarray, view: tuple) -> dict[str, Any]:
    """The surface in one view: edge-on, a solid line with the material shaded behind it;
    otherwise its dashed trace through the contact point. Returns its legend entry."""
    from matplotlib.patches import Polygon

    n2 = normal[[0, view[2]]]
    if np.hypot(*n2) < 1e-9:  # the plane is the plane of the view: no line to draw
        return {}
    nn = n2 / np.hypot(*n2)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    far = 4 * max(x1 - x0, y1 - y0)
    a, b = far * np.array([nn[1], -nn[0]]), far * np.array([-nn[1], nn[0]])
    edge_on = abs(float(normal[view[3]])) < 1e-9
    if edge_on:
        ax.add_patch(Polygon([a, b, b - far * nn, a - far * nn], closed=True, fc="#eee9e0",
                             ec="#c9bfae", lw=0, zorder=1, hatch="//"))  # fmt: skip
    ls = "-" if edge_on else (0, (5, 3))
    ax.plot(*np.transpose([a, b]), color=_GROUND, lw=1.4 if edge_on else 1, ls=ls, zorder=1.5)
    ax.set(xlim=(x0, x1), ylim=(y0, y1))
    return {"surface, seen edge-on" if edge_on else "surface's trace through the contact": ls}


def _figure_title(imp: SphereImpact | PairImpact) -> str:
    """The suptitle; a body's name is shown as typed (a ``$`` never starts mathtext)."""
    if isinstance(imp, PairImpact):
        what = f"{imp.ball1.name} on {imp.ball2.name}, paths {_deg(imp.angle_between_paths)} apart"
    else:
        what = (f"{imp.body.name}: leaves at {number(imp.rebound_speed, 'm/s')}, "
                f"{_deg(imp.rebound_angle)} above the surface")  # fmt: skip
    mu, kappa = float(imp.mu), float(imp.kappa)
    return what.replace("$", r"\$") + rf"; $\mu = {mu:g}$, $\kappa = {kappa:g}$, {imp.regime}"
