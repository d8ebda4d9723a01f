"""The explorer's Dash layout and callbacks (the only module that imports Dash).

One callback owns the inputs and the address (``sync``: the address fills the inputs on
load and after Back/Forward, an input or a click on the map writes the address), one
computes every view (``compute``), one draws the flight, and the buttons pin a setting
and download what is shown.
"""

from __future__ import annotations

import json
import threading
from typing import Any

from . import settings as st
from . import views

# The server answers requests on several threads, and the solvers' compiled kernels run on
# Numba's thread pool, whose default layer must not be entered from two threads at once:
# one solve at a time.
_SOLVING = threading.Lock()

_NAMES = tuple(st.FIELDS)
_CSS = """
body { font-family: DejaVu Sans, sans-serif; margin: 0; color: #222; }
header { padding: 8px 16px; background: #f3f3f3; border-bottom: 1px solid #ddd; }
header h1 { font-size: 20px; margin: 4px 0; }
.main { display: flex; flex-wrap: wrap; gap: 12px; padding: 8px 16px; }
.form { flex: 0 1 300px; min-width: 0; max-width: 100%; }
.views { flex: 1 1 600px; min-width: 0; max-width: 100%; }
.field { margin: 4px 0 8px; }
.field label.name { display: block; font-weight: bold; font-size: 13px; }
.field input[type=text] { width: 100%; box-sizing: border-box; padding: 3px; }
.field .radios label { margin-right: 8px; font-size: 13px; display: inline-block; }
.error { color: #b00020; font-size: 13px; overflow-wrap: anywhere; }
.graph { width: 100%; min-height: 360px; }
table.report { border-collapse: collapse; margin: 6px 0 12px; font-size: 13px; }
table.report td, table.report th { border-bottom: 1px solid #ddd; padding: 2px 8px;
  text-align: right; overflow-wrap: anywhere; }
table.report td:first-child, table.report th:first-child { text-align: left; }
.tables { overflow-x: auto; max-width: 100%; }
code.command { display: block; white-space: pre-wrap; overflow-wrap: anywhere;
  background: #f6f6f6; padding: 6px; font-size: 12px; }
button { margin: 4px 4px 4px 0; }
#status { min-height: 1.2em; color: #555; }
td.changed { background: #fff3cd; }
"""


def _control(f: st.Field, dcc: Any, html: Any) -> Any:
    if f.choices is not None:
        return dcc.RadioItems(
            id=f"in-{f.name}",
            options=[{"label": c, "value": c} for c in f.choices],
            value=f.default,
            className="radios",
            inline=True,
        )
    return dcc.Input(
        id=f"in-{f.name}", type="text", value=f.default, debounce=True, autoComplete="off"
    )


def _field(f: st.Field, dcc: Any, html: Any) -> Any:
    label = f"{f.label} ({f.unit})" if f.unit else f.label
    return html.Div(
        [
            html.Label(label, htmlFor=f"in-{f.name}", className="name"),
            _control(f, dcc, html),
            html.Div(id=f"err-{f.name}", className="error"),
        ],
        id=f"row-{f.name}",
        className="field",
    )


def _raw_table(t: Any, changed: bool = False) -> str:
    """A table as one HTML string: the page renders it as one element, not a component a cell."""
    from html import escape

    head = "".join(f"<th>{escape(c)}</th>" for c in t.columns)
    rows = []
    for row in t.rows:
        cells = [f"<td>{escape(x)}</td>" for x in row]
        if changed and row[-1] not in ("", "0"):
            cells[-1] = f'<td class="changed">{escape(row[-1])}</td>'
        rows.append("<tr>" + "".join(cells) + "</tr>")
    return (
        f'<h4>{escape(t.title)}</h4><table class="report" id="table-{t.key}"><thead><tr>'
        f"{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
    )


def build(update: Any, clicked: Any, tables: Any, to_csv: Any, compare_table: Any) -> Any:
    """The app: layout and callbacks around the functions of :mod:`.app`."""
    import dash
    from dash import Input, Output, Patch, State, ctx, dcc, html, no_update

    app = dash.Dash(__name__, title="spinimpact explorer", serve_locally=True, update_title=None)
    app.index_string = app.index_string.replace("{%css%}", "{%css%}<style>" + _CSS + "</style>")
    graph = {"displaylogo": False, "responsive": True}
    app.layout = html.Div(
        [
            dcc.Location(id="url", refresh=False),
            dcc.Store(id="current"),
            dcc.Store(id="map-key"),
            dcc.Store(id="pinned"),
            dcc.Download(id="download"),
            html.Header(
                [
                    html.H1("spinimpact explorer"),
                    html.Div(
                        "Exact frictional impact of a spinning body: change an input, every view "
                        "follows. SI units unless a unit is named; the address of this page "
                        "reproduces it."
                    ),
                ]
            ),
            html.Div(
                [
                    html.Div([_field(f, dcc, html) for f in st.FIELDS.values()], className="form"),
                    html.Div(
                        [
                            html.Div(id="status", children=""),
                            html.Div(
                                [
                                    html.Button("Pin this setting", id="pin"),
                                    html.Button("Unpin", id="unpin"),
                                    html.Button("Download JSON", id="get-json"),
                                    html.Button("Download CSV", id="get-csv"),
                                ]
                            ),
                            html.Div("The command line that computes it:"),
                            html.Code(id="command", className="command"),
                            dcc.Graph(
                                id="bounce",
                                className="graph",
                                config=graph,
                                style={"height": "380px"},
                            ),
                            dcc.Graph(
                                id="process",
                                className="graph",
                                config=graph,
                                style={"height": "380px"},
                            ),
                            dcc.Graph(
                                id="map", className="graph", config=graph, style={"height": "380px"}
                            ),
                            dcc.Graph(
                                id="flight",
                                className="graph",
                                config=graph,
                                style={"height": "380px"},
                            ),
                            html.Div(id="compare", className="tables"),
                            html.Div(id="tables", className="tables"),
                        ],
                        className="views",
                    ),
                ],
                className="main",
            ),
        ]
    )

    values_in = [Input(f"in-{n}", "value") for n in _NAMES]
    values_out = [Output(f"in-{n}", "value") for n in _NAMES]
    rows_out = [Output(f"row-{n}", "style") for n in _NAMES]

    errors_out = [Output(f"err-{n}", "children") for n in _NAMES]
    views_out = [Output(k, "figure") for k in ("bounce", "process", "map")]
    views_out += [Output("tables", "children"), Output("command", "children")]

    @app.callback(
        Output("url", "search"),
        *values_out,
        *rows_out,
        *errors_out,
        *views_out,
        Output("current", "data"),
        Output("map-key", "data"),
        Input("url", "search"),
        Input("map", "clickData"),
        *values_in,
        State("map-key", "data"),
        running=[(Output("status", "children"), "computing…", "")],
    )
    def step(search: str | None, click: Any, *given: str) -> Any:
        """One round trip a change: the address and the inputs agree, then every view."""
        *given, drawn = given
        values = dict(zip(_NAMES, given, strict=True))
        address: Any = None
        shown: Any = [no_update] * len(_NAMES)
        if ctx.triggered_id in (None, "url"):  # the address (first load, Back, a link)
            values = st.from_query(search or "")
            address, shown = no_update, [values[n] for n in _NAMES]
        elif ctx.triggered_id == "map":
            point = (click or {}).get("points", [{}])[0]
            with _SOLVING:
                moved = clicked(values, float(point.get("x", "nan")), float(point.get("y", "nan")))
            if moved is None:
                return [no_update] * (3 * len(_NAMES) + 8)
            values, shown = moved, [moved[n] for n in _NAMES]
        elif ctx.triggered_id == "in-problem":
            old = st.from_query(search or "").get("problem", "paper")
            for name, text in st.defaults(old).items():  # untouched defaults follow the problem
                if name != "problem" and values[name] == text:
                    values[name] = st.defaults(values["problem"])[name]
            shown = [values[n] for n in _NAMES]
        if address is None:
            address = st.to_query(values)
        with _SOLVING:
            out = update(values)
        errors = [out["errors"].get(n, "") for n in _NAMES]
        head = [address, *shown, *_styles(values), *errors]
        if out["errors"]:  # the last good views stay
            return [*head, *[no_update] * 7]
        f = out["figures"]
        key = views.map_key(out["setting"])
        if key is not None and key == drawn:  # the same colours: move the marker alone
            point = views.map_point(out["setting"])
            f["map"] = Patch()
            f["map"]["data"][1]["x"], f["map"]["data"][1]["y"] = [point[0]], [point[1]]
        body = dcc.Markdown(
            "\n".join(_raw_table(t) for t in out["tables"]), dangerously_allow_html=True
        )
        data = out["data"]
        return [*head, f["bounce"], f["process"], f["map"], body, data["command"], data, key]

    def _styles(values: dict[str, str]) -> list[dict[str, str]]:
        shown = set(st.relevant(values))
        return [{} if n in shown else {"display": "none"} for n in _NAMES]

    @app.callback(
        Output("flight", "figure"),
        Input("current", "data"),
        running=[(Output("status", "children"), "drawing the flight…", "")],
    )
    def flight(data: dict | None) -> Any:
        if not data:
            return no_update
        with _SOLVING:
            found = st.evaluate(data["settings"])
            return views.flight_view(found.setting) if found.setting else no_update

    @app.callback(
        Output("pinned", "data"),
        Input("pin", "n_clicks"),
        Input("unpin", "n_clicks"),
        State("current", "data"),
        prevent_initial_call=True,
    )
    def pin(_pin: Any, _unpin: Any, data: dict | None) -> Any:
        return data if ctx.triggered_id == "pin" else None

    @app.callback(Output("compare", "children"), Input("pinned", "data"), Input("current", "data"))
    def compare(pinned: dict | None, data: dict | None) -> Any:
        if not pinned or not data:
            return []
        return dcc.Markdown(
            _raw_table(compare_table(pinned, data), changed=True), dangerously_allow_html=True
        )

    @app.callback(
        Output("download", "data"),
        Input("get-json", "n_clicks"),
        Input("get-csv", "n_clicks"),
        State("current", "data"),
        State("pinned", "data"),
        prevent_initial_call=True,
    )
    def download(_json: Any, _csv: Any, data: dict | None, pinned: dict | None) -> Any:
        if not data:
            return no_update
        if ctx.triggered_id == "get-csv":
            return {"content": to_csv(data, pinned), "filename": "spinimpact-explore.csv"}
        content = dict(data, pinned=pinned) if pinned else data
        return {"content": json.dumps(content, indent=1), "filename": "spinimpact-explore.json"}

    return app
