"""The explorer's views of one setting, as Plotly figure specifications (plain dicts).

Each function takes a checked :class:`~spinimpact.explore.settings.Setting` and draws what
the library computed: the bounce (:func:`bounce`), the impact process over the normal
impulse from the result's own ``history()`` (:func:`process`, with Routh's diagram of the
friction impulse for a planar body), the map of regimes from
the library's solver over the incidence plane (:func:`regime_map`, cached by body and
surface)
and the ball's flight from :func:`spinimpact.flight` (:func:`flight_view`). No formula of
the theory is evaluated here. The dicts are what ``dcc.Graph`` takes, so drawing costs no
Plotly import.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np

__all__ = [
    "bounce",
    "process",
    "regime_map",
    "map_key",
    "map_point",
    "flight_view",
    "MAP_POINTS",
    "MAP_ROWS",
]

#: Grid points per axis of the regime map (about the width of its panel in pixels / 3).
MAP_POINTS = 121
#: Rows of the regime map (its panel is about half as tall as wide).
MAP_ROWS = 81
_EXTENT = 3.0
_BEFORE, _AFTER, _SPIN = "#1f77b4", "#d62728", "#2ca02c"
_FONT = {"family": "DejaVu Sans, sans-serif", "size": 12}


def _layout(title: str, **extra: Any) -> dict[str, Any]:
    return {
        "title": {"text": title, "x": 0.02, "font": {"size": 14}},
        "font": _FONT,
        "margin": {"l": 55, "r": 15, "t": 55, "b": 45},
        "autosize": True,
        "legend": {"orientation": "h", "y": -0.25},
        **extra,
    }


def _vectors(s: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Centre velocity and spin vector before and after (m/s, rad/s), in 3D."""
    r = s.result
    b, a = (r.before1, r.after1) if s.problem == "pair" else (r.before, r.after)
    if s.problem in ("sphere", "pair"):
        return tuple(np.array([float(x.vx), float(x.vy), float(x.vz)]) for x in (b, a)) + tuple(
            np.array([float(x.wx), float(x.wy), float(x.wz)]) for x in (b, a)
        )  # type: ignore[return-value]
    v = [np.array([float(x.vx), float(x.vy), 0.0]) for x in (b, a)]
    w = [np.array([0.0, 0.0, float(x.omega)]) for x in (b, a)]
    return v[0], v[1], w[0], w[1]


def _arrow(
    start: tuple,
    end: tuple,
    colour: str,
    text: str,
    xref: str,
    yref: str,
    dash: bool = False,
    label_at_start: bool = False,
    shift: int = 0,
    down: bool = False,
) -> list[dict]:
    """An arrow from ``start`` to ``end`` and its label beyond its free end, away from it
    (``down``: the vertical axis points down the screen)."""
    arrow = {
        "x": end[0],
        "y": end[1],
        "ax": start[0],
        "ay": start[1],
        "xref": xref,
        "yref": yref,
        "axref": xref,
        "ayref": yref,
        "showarrow": True,
        "arrowhead": 3,
        "arrowwidth": 1.5 if dash else 2.5,
        "arrowcolor": colour,
        "text": "",
        "standoff": 0,
    }
    at, other = (start, end) if label_at_start else (end, start)
    dx, dy = at[0] - other[0], at[1] - other[1]
    size = math.hypot(dx, dy) or 1.0
    ux, uy = dx / size, (-dy if down else dy) / size
    label = {
        "x": at[0],
        "y": at[1],
        "xref": xref,
        "yref": yref,
        "showarrow": False,
        "text": text,
        "font": {"color": colour, "size": 11},
        "yshift": shift,
        "xanchor": "left" if ux > 0.3 else "right" if ux < -0.3 else "center",
        "yanchor": "bottom" if uy > 0.3 else "top" if uy < -0.3 else "middle",
    }
    if abs(ux) < 0.5:  # a mostly vertical arrow: its label beside its head, off the shafts
        label.update(xanchor="left", yanchor="middle", xshift=6)
    return [arrow, label]


def bounce(s: Any) -> dict[str, Any]:
    """Side view (x, y) and top view (x, z) of the bounce: the centre's velocity before
    (arriving) and after (leaving), and the spin vector before and after, to scale."""
    v0, v1, w0, w1 = _vectors(s)
    radius = float(getattr(s.body, "radius", 0.0) or 0.0)
    if s.problem == "pendulum":
        size = 0.5 * float(np.hypot(s.body.px, s.body.py))
    else:
        size = radius if radius > 0 else 0.5 * float(np.hypot(s.body.rx, s.body.ry))
    vmax = max(float(np.linalg.norm(v0)), float(np.linalg.norm(v1)), 1e-300)
    wmax = max(float(np.linalg.norm(w0)), float(np.linalg.norm(w1)), 1e-300)
    scale, wscale = 3 * size / vmax, 1.5 * size / wmax
    centre = np.array([0.0, size, 0.0])
    traces: list[dict[str, Any]] = []
    notes: list[dict[str, Any]] = []
    t = np.linspace(0, 2 * math.pi, 73)
    for k, (i, j, name) in enumerate(((0, 1, "side"), (0, 2, "top"))):
        xa, ya = ("x", "y") if k == 0 else ("x2", "y2")
        ground = [-4 * size, 4 * size]
        if k == 0:
            traces.append(
                {
                    "type": "scatter",
                    "x": ground,
                    "y": [0, 0],
                    "mode": "lines",
                    "line": {"color": "#888"},
                    "showlegend": False,
                    "hoverinfo": "skip",
                    "xaxis": xa,
                    "yaxis": ya,
                }
            )
        traces.append(
            {
                "type": "scatter",
                "x": list(centre[i] + size * np.cos(t)),
                "y": list(centre[j] + size * np.sin(t)),
                "mode": "lines",
                "fill": "toself",
                "fillcolor": "rgba(120,120,120,0.15)",
                "line": {"color": "#555"},
                "showlegend": False,
                "hoverinfo": "skip",
                "xaxis": xa,
                "yaxis": ya,
            }
        )
        c = (centre[i], centre[j])
        if s.problem == "pair":  # ball 2, at rest before, touching ball 1 along the normal
            n = np.array([s.inputs[f"normal_{x}"] for x in "xyz"])
            other = centre - 2 * size * n / np.linalg.norm(n)
            traces.append(
                dict(
                    traces[-1],
                    x=list(other[i] + size * np.cos(t)),
                    y=list(other[j] + size * np.sin(t)),
                )
            )
            a2 = s.result.after2
            d2 = np.array([float(a2.vx), float(a2.vy), float(a2.vz)]) * scale
            start2 = (other[i], other[j])
            end2 = (other[i] + d2[i], other[j] + d2[j])
            notes += _arrow(start2, end2, _AFTER, "ball 2 after", xa, ya, down=k == 1)
        for vec, colour, label, arriving in (
            (v0, _BEFORE, "v before", True),
            (v1, _AFTER, "v after", False),
        ):
            d = (vec[i] * scale, vec[j] * scale)
            start = (c[0] - d[0], c[1] - d[1]) if arriving else c
            end = c if arriving else (c[0] + d[0], c[1] + d[1])
            notes += _arrow(start, end, colour, label, xa, ya, label_at_start=arriving, down=k == 1)
        for vec, label, shift in ((w0, "ω before", 0), (w1, "ω after", -14)):
            d = (vec[i] * wscale, vec[j] * wscale)
            if math.hypot(*d) > 1e-9 * size:
                end = (c[0] + d[0], c[1] + d[1])
                notes += _arrow(c, end, _SPIN, label, xa, ya, dash=True, shift=shift, down=k == 1)
        del name
    lim = 4.5 * size
    axis = {"range": [-lim, lim], "zeroline": False}
    layout = _layout(
        "Bounce, seen from the side and from above:<br>velocity before (blue), after (red), "
        "spin ω (green)",
        annotations=notes,
        showlegend=False,
        xaxis={**axis, "domain": [0, 0.47], "title": {"text": "x (m)"}},
        yaxis={**axis, "scaleanchor": "x", "title": {"text": "y (m)"}},
        xaxis2={**axis, "domain": [0.53, 1], "title": {"text": "x (m)"}},
        # seen from above (+y): z points down the screen, headings turn counter-clockwise
        yaxis2={
            **axis,
            "range": [lim, -lim],
            "scaleanchor": "x2",
            "anchor": "x2",
            "title": {"text": "z (m)"},
        },
    )
    return {"data": traces, "layout": layout}


def _line(x: Any, y: Any, name: str, colour: str, **extra: Any) -> dict[str, Any]:
    return {
        "type": "scatter",
        "x": list(map(float, x)),
        "y": list(map(float, y)),
        "mode": "lines",
        "name": name,
        "line": {"color": colour},
        **extra,
    }


def process(s: Any) -> dict[str, Any]:
    """The impact process over the normal impulse ``tau`` (N s): the contact point's slip
    and normal velocity (m/s) from the result's ``history()``; for a planar body or a
    pendulum, Routh's diagram of the friction impulse beside it."""
    r = s.result
    if s.problem == "pair":
        return {
            "data": [],
            "layout": _layout(
                "Impact process: not drawn for two balls (spinimpact pair reports its impulses)"
            ),
        }
    if not hasattr(r, "history"):  # a tangential law: its own process is not sampled here
        return {
            "data": [],
            "layout": _layout(
                "Impact process: drawn for the rigid law (a tangential law's process is in "
                "time: spinimpact simulate)"
            ),
        }
    h = r.history(201)
    tau = h.tau
    if s.problem == "sphere":
        slip, normal = h.slip_speed, h.normal_velocity
        slip_name = "slip speed |c_t| (m/s)"
    elif s.problem == "paper":
        slip, normal = h.slip, h.vy
        slip_name = "slip u (m/s)"
    else:
        slip, normal = h.slip, h.normal_velocity
        slip_name = "slip c_t (m/s)"
    data = [
        _line(tau, slip, slip_name, _BEFORE),
        _line(tau, normal, "normal velocity (m/s)", _AFTER),
    ]
    marks = [(float(h.tau0), "τ₀"), (float(h.tau_star), "τ*"), (float(h.tau1), "τ₁")]
    shapes = [
        {
            "type": "line",
            "x0": x,
            "x1": x,
            "yref": "paper",
            "y0": 0,
            "y1": 1,
            "line": {"dash": "dot", "color": "#888", "width": 1},
        }
        for x, _ in marks
        if math.isfinite(x) and x <= float(h.tau1)
    ]
    notes = [
        {"x": x, "y": 1.0, "yref": "paper", "text": name, "showarrow": False, "yanchor": "bottom"}
        for x, name in marks
        if math.isfinite(x) and x <= float(h.tau1)
    ]
    layout = _layout(
        "Impact process over the normal impulse τ",
        shapes=shapes,
        annotations=notes,
        xaxis={"title": {"text": "τ (N s)"}, "domain": [0, 1]},
        yaxis={"title": {"text": "m/s"}},
    )
    if s.problem in ("planar", "pendulum"):
        data.append(
            _line(
                tau, h.tangential_impulse, "friction impulse f (N s)", _SPIN, xaxis="x2", yaxis="y2"
            )
        )
        layout["xaxis"]["domain"] = [0, 0.55]
        layout["xaxis2"] = {"domain": [0.67, 1], "title": {"text": "normal impulse τ (N s)"}}
        layout["yaxis2"] = {"anchor": "x2", "title": {"text": "friction impulse f (N s)"}}
        layout["title"]["text"] = "Impact process over τ,<br>and Routh's diagram (right)"
    return {"data": data, "layout": layout}


@functools.lru_cache(maxsize=32)
def _regimes(zeta: float, mu: float, kappa: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The regime (an index into :func:`~spinimpact.viz.maps.map_regimes`) on the half-plane
    ``a = vx/|vy|`` in ``[0, 3]`` (:data:`MAP_POINTS` columns, the page's own incidences)
    by ``b = R omega/|vy|`` in ``[-3, 3]`` (:data:`MAP_ROWS` rows), solved by
    :func:`spinimpact.solve` at ``vy = -1`` m/s for a body of this ``zeta`` with unit mass
    and radius (nothing else of a body changes a map, as
    :func:`~spinimpact.viz.maps.map_fields` explains; that function solves the whole plane,
    and ``a < 0`` mirrors ``a > 0``)."""
    from ..model.body import Body
    from ..model.impact import solve
    from ..viz.maps import map_regimes

    unit = Body.from_zeta(mass=1.0, radius=1.0, zeta=zeta)
    # the points of map_fields(n=241): its a >= 0 half, every third row
    a = np.linspace(-_EXTENT, _EXTENT, 2 * MAP_POINTS - 1)[MAP_POINTS - 1 :]
    b = np.linspace(-_EXTENT, _EXTENT, 3 * MAP_ROWS - 2)[::3]
    imp = solve(unit, a[None, :], -1.0, b[:, None], mu=mu, kappa=kappa)
    code = {name: i for i, name in enumerate(map_regimes(mu, kappa))} | {"no-slip": 0}
    names, inverse = np.unique(imp.regime, return_inverse=True)
    return a, b, np.array([code[str(x)] for x in names], np.int8)[inverse].reshape(imp.shape)


def map_point(s: Any) -> tuple[float, float] | None:
    """The incidence ``(vx/|vy|, R omega/|vy|)`` of a setting on the map (for a ball in 3D:
    along its heading, topspin counting as negative ``omega``), or ``None`` for bodies
    the map does not describe."""
    if s.problem not in ("paper", "sphere") or s.law is not None:
        return None
    r, b = s.result, s.result.before
    if s.problem == "paper":
        vn = abs(float(b.vy))
        return float(b.vx) / vn, float(s.body.radius) * float(b.omega) / vn
    vn = abs(float(r.normal_velocity_before))
    v = np.array([float(b.vx), 0.0, float(b.vz)])
    along = float(np.linalg.norm(v))
    e = v / along if along > 0 else np.array([1.0, 0.0, 0.0])
    slip = np.array([float(r.slip_before.x), 0.0, float(r.slip_before.z)])
    return along / vn, float(np.dot(slip, e) - along) / vn


def map_key(s: Any) -> str | None:
    """What the map's colours depend on (``zeta``, ``mu``, ``kappa``; ``None``: no map): two
    settings with the same key differ on the map by their marker alone."""
    if map_point(s) is None:
        return None
    return repr((float(s.body.zeta), float(s.result.mu), float(s.result.kappa)))


def regime_map(s: Any) -> dict[str, Any]:
    """The regimes over the incidence plane at this body's ``zeta``, ``mu`` and ``kappa``
    (:func:`_regimes`), with this setting's incidence marked."""
    from ..viz.maps import map_regimes

    point = map_point(s)
    if point is None:
        why = "the rigid law" if s.law is not None else "the paper's bodies and a ball"
        return {"data": [], "layout": _layout(f"Regime map: drawn for {why} only")}
    mu, kappa = float(s.result.mu), float(s.result.kappa)
    a, b, regime = _regimes(float(s.body.zeta), mu, kappa)
    names = map_regimes(mu, kappa)
    colours = ["#9ecae1", "#fdae6b", "#c7e9c0", "#dadaeb"]
    k = len(names)
    scale = [[(i + (j % 2)) / k, colours[i]] for i in range(k) for j in (0, 1)]
    heat = {
        "type": "heatmap",
        "x": a.tolist(),
        "y": b.tolist(),
        "z": regime.tolist(),
        "zmin": -0.5,
        "zmax": k - 0.5,
        "colorscale": scale,
        "showscale": True,
        "colorbar": {"tickvals": list(range(k)), "ticktext": list(names), "len": 0.9},
        "hovertemplate": "vx/|vy| %{x:.3g}<br>Rω/|vy| %{y:.3g}<extra></extra>",
    }
    x, y = point
    mark = {
        "type": "scatter",
        "x": [x],
        "y": [y],
        "mode": "markers",
        "name": "this impact",
        "marker": {"symbol": "x", "size": 12, "color": "black"},
        "cliponaxis": True,
    }
    title = f"Regimes at μ = {mu:.6g}, κ = {kappa:.6g}<br>(click to move there)"
    layout = _layout(
        title,
        showlegend=False,
        xaxis={"title": {"text": "vx/|vy|"}, "range": [0, _EXTENT]},
        yaxis={"title": {"text": "R ω/|vy|"}, "range": [-_EXTENT, _EXTENT]},
    )
    return {"data": [heat, mark], "layout": layout}


@functools.lru_cache(maxsize=16)
def _flight(ball: str, ground: str, mu: float, kappa: float, v: tuple, w: tuple) -> Any:
    from ..model.flight import flight
    from ..model.presets import BALLS, GROUNDS

    surface = GROUNDS[ground].replace(mu=mu, kappa=kappa)
    r = BALLS[ball].radius
    return flight(
        ball,
        surface,
        velocity=list(v),
        spin=list(w),
        position=(0.0, r, 0.0),
        path=True,
        max_bounces=8,
    )


def flight_view(s: Any) -> dict[str, Any]:
    """A ball's flight after this bounce (:func:`spinimpact.flight`: drag, lift, spin decay,
    each later bounce solved exactly): height over distance, and the path seen from above."""
    if s.problem != "sphere" or s.ball is None or s.law is not None:
        return {
            "data": [],
            "layout": _layout("Flight: drawn for a ball preset on a surface under the rigid law"),
        }
    a = s.result.after
    v = tuple(float(getattr(a, k)) for k in ("vx", "vy", "vz"))
    w = tuple(float(getattr(a, k)) for k in ("wx", "wy", "wz"))
    ground = s.ground or "hard"
    fl = _flight(s.ball, ground, float(s.result.mu), float(s.result.kappa), v, w)
    p = np.asarray(fl.path_position).reshape(-1, 3)
    p = p[np.isfinite(p).all(axis=1)]
    data = [
        _line(p[:, 0], p[:, 1], "height", _BEFORE),
        _line(p[:, 0], p[:, 2], "seen from above", _AFTER, xaxis="x2", yaxis="y2"),
    ]
    n = int(np.asarray(fl.bounce_count).reshape(-1)[0])
    layout = _layout(
        f"Flight after the bounce:<br>{n} more bounces on {ground}",
        showlegend=False,
        xaxis={"domain": [0, 0.47], "title": {"text": "x (m)"}},
        yaxis={"title": {"text": "y (m)"}},
        xaxis2={"domain": [0.53, 1], "title": {"text": "x (m)"}},
        yaxis2={
            "anchor": "x2",
            "autorange": "reversed",
            "title": {"text": "z (m)"},
        },
    )
    return {"data": data, "layout": layout}
