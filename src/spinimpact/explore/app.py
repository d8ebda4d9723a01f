"""The explorer's page: a Dash app over :mod:`~spinimpact.explore.settings` and
:mod:`~spinimpact.explore.views`.

The inputs are text boxes and radio buttons whose text is the page's address
(``?problem=sphere&speed=20...``); every change re-solves and redraws all views in one
server call (:func:`update`), which the benchmark ``python -m benchmarks.explore`` times.
A field the library refuses shows the library's message beside it and leaves the last
good views. Every script and style sheet is served by the installed Dash packages
(``serve_locally``): the page needs no network.
"""

from __future__ import annotations

import csv
import io
import math
from typing import Any

import numpy as np

from ..viz.tables import Table, number
from . import settings as st
from . import views

__all__ = ["create_app", "update", "tables", "export", "compare_table", "clicked"]


def tables(s: st.Setting) -> tuple[Table, ...]:
    """The tables of the terminal report for this setting (:mod:`spinimpact.viz.tables`,
    :func:`spinimpact.viz.sphere.sphere_tables`, :func:`spinimpact.viz.report.planar_tables`),
    then every result column with its unit (:func:`spinimpact.viz.problems.result_tables`)."""
    from ..model.registry import problem
    from ..viz.problems import result_tables

    out: tuple[Table, ...] = ()
    if s.law is None:
        if s.problem == "paper":
            from ..viz.tables import impact_tables

            out = impact_tables(s.result, typeset=True)
        elif s.problem in ("sphere", "pair"):
            from ..viz.sphere import sphere_tables

            out = sphere_tables(s.result, typeset=True)
        else:
            from ..viz.report import planar_tables

            out = planar_tables(s.result)
    declared = problem(s.problem)
    if s.law is None:
        values = {k: v for k, v in s.inputs.items() if k in declared.names}
        return out + result_tables(declared, values, s.result)[1:]
    # under a tangential law the result has columns of its own: each with its unit
    rows = tuple(
        (name, _text(value), declared.unit(name) or "") for name, value in _columns(s).items()
    )
    return (Table("result", "Result", ("column", "value", "unit"), rows),)


def _columns(s: st.Setting) -> dict[str, Any]:
    """The result's columns for one impact, as plain Python values (full precision)."""
    out: dict[str, Any] = {}
    for name, value in s.result.columns().items():
        x = np.asarray(value).reshape(-1)[0]
        if isinstance(x, np.bool_ | bool):
            out[name] = bool(x)
        elif isinstance(x, np.str_ | str):
            out[name] = str(x)
        else:
            x = float(x)
            out[name] = x if math.isfinite(x) else str(x)  # "inf", "-inf", "nan"
    return out


def export(s: st.Setting) -> dict[str, Any]:
    """What the page shows, as data: the setting, the solver's inputs (SI), every result
    column and its unit, and the command line that computes the same impact."""
    from ..model.registry import problem

    declared = problem(s.problem)
    columns = _columns(s)
    return {
        "problem": s.problem,
        "settings": dict(s.values),
        "inputs": dict(s.inputs),
        "result": columns,
        "units": {k: declared.unit(k) or "" for k in columns},
        "command": s.command,
        "address": st.to_query(s.values),
    }


def to_csv(data: dict[str, Any], pinned: dict[str, Any] | None = None) -> str:
    """One row a setting (the pinned one first): its inputs, then its result columns."""
    rows = [("pinned", pinned), ("current", data)] if pinned else [("current", data)]
    names = ["setting", "problem"]
    for _, d in rows:
        names += [k for k in (*d["inputs"], *d["result"]) if k not in names]
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, names, lineterminator="\n")
    writer.writeheader()
    for which, d in rows:
        writer.writerow({"setting": which, "problem": d["problem"], **d["inputs"], **d["result"]})
    return buffer.getvalue()


def compare_table(pinned: dict[str, Any], current: dict[str, Any]) -> Table:
    """The result columns of a pinned setting beside the current one's, with differences."""
    rows = []
    for name, now in current["result"].items():
        was = pinned["result"].get(name)
        if isinstance(now, float) and isinstance(was, float):
            diff = number(now - was)
        else:
            diff = "" if now == was else "changed"
        unit = current["units"].get(name, "")
        rows.append((f"{name} ({unit})" if unit else name, _text(was), _text(now), diff))
    return Table(
        "compare",
        "Pinned and current",
        ("column", "pinned", "current", "current - pinned"),
        tuple(rows),
    )


def _text(x: Any) -> str:
    if x is None:
        return ""
    if isinstance(x, bool):
        return "yes" if x else "no"
    return number(x) if isinstance(x, float) else str(x)


def update(values: dict[str, str]) -> dict[str, Any]:
    """Everything one change of the inputs computes on the server: the setting and all
    views but the flight (drawn next, :func:`views.flight_view`).

    Returns
    -------
    dict
        ``errors`` (field -> message); when there is none, also ``setting``, ``figures``
        (bounce, process, map), ``tables`` and ``data`` (:func:`export`).
    """
    found = st.evaluate(values)
    if found.errors:
        return {"errors": found.errors}
    s = found.setting
    assert s is not None
    figures = {"bounce": views.bounce(s), "process": views.process(s), "map": views.regime_map(s)}
    return {"errors": {}, "setting": s, "figures": figures, "tables": tables(s), "data": export(s)}


def clicked(values: dict[str, str], x: float, y: float) -> dict[str, str] | None:
    """The setting whose incidence is the map's point ``(vx/|vy|, R omega/|vy|)``: the same
    normal speed, the speed, angle (and for a ball heading and topspin) moved there;
    ``None`` where the map point cannot be reached from these inputs."""
    from ..cli._common import SPEED_UNITS

    found = st.evaluate(values)
    s = found.setting
    if s is None or views.map_point(s) is None or not (math.isfinite(x) and math.isfinite(y)):
        return None
    out = dict(values)
    if s.problem == "paper":
        vn, radius = abs(float(s.inputs["vy"])), float(s.body.radius)
        if x < 0:
            return None
        out["spin"] = f"{y * vn / radius * 60 / (2 * math.pi):.6g}"
    else:
        vn, radius = abs(float(s.result.normal_velocity_before)), float(s.body.radius)
        if x < 0:  # the map is drawn along the ball's heading
            return None
        out["spin"] = f"{-y * vn / radius * 60 / (2 * math.pi):.6g}"
        out["spin_axis"] = "topspin"
    speed = vn * math.hypot(1.0, x) / SPEED_UNITS[values.get("speed_unit", "m/s")]
    out["speed"] = f"{speed:.6g}"
    out["angle"] = f"{math.degrees(math.atan2(1.0, x)):.6g}"
    return out


def create_app() -> Any:
    """The Dash app of the explorer (its Flask server is ``app.server``)."""
    from ._layout import build

    return build(update, clicked, tables, to_csv, compare_table)
