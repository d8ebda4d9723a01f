"""Benchmark of the explorer's server: the time of one update of the page, every view.

Run with ``.venv/bin/python -m benchmarks.explore`` (from the repository root; needs the
``explore`` extra). Each update is the request a browser sends when an input changes
(``POST /_dash-update-component``), answered by the app's own Flask server in this process
(no network, no browser): the setting checked, the impact solved, the bounce, the impact
process, the regime map and the report's tables drawn, and the whole answer serialized to
JSON. The flight of a ball is the page's next request, timed on its own. Baseline, measured
in the same run: the bare solver call (``solve`` or ``solve_sphere``) for the same impact.

Two cases of the map: the same body, ``mu`` and ``kappa`` as the update before (the map is
cached and only its marker moves: the usual change of a speed, an angle or a spin), and a
new ``mu`` every update (the map solved again at the page's resolution,
:data:`spinimpact.explore.views.MAP_POINTS` points a side).
"""

from __future__ import annotations

import statistics
import time

from rich.console import Console
from rich.table import Table

from spinimpact.explore import settings as st


def _payload(app, values: dict[str, str], changed: str, drawn: object = None) -> dict:
    """The request a browser sends for the main update (the inputs' callback)."""
    deps = {d["output"]: d for d in app.server.test_client().get("/_dash-dependencies").json}
    out = next(k for k in deps if k.startswith("..url.search"))
    spec = deps[out]
    values = st.defaults(values.get("problem", "paper")) | values
    inputs = []
    for i in spec["inputs"]:
        name = i["id"].removeprefix("in-")
        value = {"url": st.to_query(values), "map": None}.get(i["id"], values.get(name))
        inputs.append({"id": i["id"], "property": i["property"], "value": value})
    outputs = [dict(zip(("id", "property"), o.split("."), strict=True))
               for o in out.strip(".").split("...")]  # fmt: skip
    state = [{"id": "map-key", "property": "data", "value": drawn}]
    return {"output": out, "outputs": outputs, "inputs": inputs, "state": state,
            "changedPropIds": [changed]}  # fmt: skip


def _flight_payload(data: dict) -> dict:
    return {"output": "flight.figure", "outputs": {"id": "flight", "property": "figure"},
            "inputs": [{"id": "current", "property": "data", "value": data}],
            "changedPropIds": ["current.data"]}  # fmt: skip


def _post(client, payload: dict) -> tuple[float, dict]:
    start = time.perf_counter()
    answer = client.post("/_dash-update-component", json=payload)
    elapsed = time.perf_counter() - start
    if answer.status_code != 200:
        raise RuntimeError(f"the update failed: {answer.status_code} {answer.data[:300]!r}")
    response = answer.json["response"]
    if "current" not in response and "flight" not in response:  # a message beside an input
        messages = [v["children"] for k, v in response.items() if k.startswith("err-")]
        raise RuntimeError(f"the setting was refused: {[m for m in messages if m]}")
    return elapsed, answer.json


def _median(times: list[float]) -> float:
    return statistics.median(times) * 1e3


def measure(values: dict[str, str], repeat: int, new_map: bool) -> tuple[float, float, dict]:
    """Median ms of one update (changing the speed, or ``mu`` when ``new_map``), the median
    ms of the bare solver call for the same impact, and the last answer."""
    from spinimpact.explore.app import create_app

    app = create_app()
    client = app.server.test_client()
    times, solver = [], []
    answer: dict = {}
    drawn = None
    _post(client, _payload(app, values, "in-speed.value"))  # imports and the first map
    for k in range(repeat):
        v = dict(values, speed=f"{5 + 0.01 * k:.6g}")
        if new_map:
            v["mu"] = f"{0.3 + 0.001 * k:.6g}"
        payload = _payload(app, v, "in-mu.value" if new_map else "in-speed.value", drawn)
        elapsed, answer = _post(client, payload)
        drawn = answer["response"].get("map-key", {}).get("data", drawn)
        times.append(elapsed)
        s = st.evaluate(v).setting
        start = time.perf_counter()
        _solve_again(s)
        solver.append(time.perf_counter() - start)
    return _median(times), _median(solver), answer


def _solve_again(s: st.Setting) -> None:
    """The bare solver call of a setting (the baseline)."""
    from spinimpact import solve, solve_sphere

    i = s.inputs
    if s.problem == "paper":
        solve(s.body, i["vx"], i["vy"], i["omega"], mu=i["mu"], kappa=i["kappa"],
              tangential=s.law)  # fmt: skip
    else:
        solve_sphere(s.body, [i["vx"], i["vy"], i["vz"]], [i["wx"], i["wy"], i["wz"]],
                     mu=i["mu"], kappa=i["kappa"], tangential=s.law)  # fmt: skip


def flight_time(values: dict[str, str], repeat: int) -> float:
    """Median ms of the flight's request (each update a new bounce, so nothing cached)."""
    from spinimpact.explore.app import create_app

    app = create_app()
    client = app.server.test_client()
    times = []
    for k in range(repeat + 1):
        v = dict(values, speed=f"{5 + 0.01 * k:.6g}")
        data = _post(client, _payload(app, v, "in-speed.value"))[1]["response"]["current"]["data"]
        elapsed, _ = _post(client, _flight_payload(data))
        times.append(elapsed)
    return _median(times[1:])


def main() -> None:
    console = Console()
    table = Table(title="spinimpact explore: server time of one update (median, ms)")
    for column in ("setting", "map", "update", "solver", "ratio"):
        table.add_column(column, justify="left" if column in ("setting", "map") else "right")
    cases = [
        ("paper: solid sphere, rigid", {"problem": "paper"}),
        ("sphere: tennis on hard, rigid", {"problem": "sphere"}),
    ]
    for name, values in cases:
        for new_map in (False, True):
            update, solver, _ = measure(values, 15, new_map)
            table.add_row(name, "new" if new_map else "cached",
                          f"{update:.1f}", f"{solver:.3f}", f"{update / solver:.0f}")  # fmt: skip
    laws = [("walton", {"beta0": "0.4"}), ("stronge", {"poisson_ratio": "0.3"}),
            ("mindlin-deresiewicz", {"poisson_ratio": "0.3"})]  # fmt: skip
    for law, extra in laws:
        for kind in ("paper", "sphere"):
            values = {"problem": kind, "tangential": law, **extra}
            update, solver, _ = measure(values, 5, False)
            table.add_row(f"{kind}: {law}", "none",
                          f"{update:.1f}", f"{solver:.3f}", f"{update / solver:.0f}")  # fmt: skip
    console.print(table)
    console.print("update: one change of an input, every view (bounce, process, map, tables) "
                  "and the answer's JSON; solver: the bare solve or solve_sphere call; map: "
                  "cached (only its marker moves), new (a new mu: solved again), none (drawn "
                  "for the rigid law only).")  # fmt: skip
    flight = flight_time({"problem": "sphere"}, 5)
    console.print(f"The flight after a tennis ball's bounce on hard (drawn by the page's next "
                  f"request, up to 8 bounces): {flight:.0f} ms (median of 5).")  # fmt: skip


if __name__ == "__main__":
    main()
