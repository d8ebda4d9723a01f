"""The explorer's server side: one update, the map's click, the comparison, the downloads."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from spinimpact.explore import app, views
from spinimpact.explore import settings as st


@pytest.mark.parametrize("kind", list(st.PROBLEMS))
def test_one_update_draws_every_view_and_the_report(kind):
    out = app.update({"problem": kind})
    assert out["errors"] == {}
    for name in ("bounce", "process", "map"):
        assert out["figures"][name]["layout"]["title"]["text"]
    assert out["figures"]["bounce"]["data"], "the body is drawn"
    assert {t.key for t in out["tables"]} >= {"result"}
    data = json.loads(json.dumps(out["data"]))  # plain JSON, nothing lost
    assert data["result"] == out["data"]["result"]
    assert data["command"] == out["setting"].command


def test_a_bad_field_returns_its_message_and_nothing_else():
    out = app.update({"problem": "sphere", "kappa": "2"})
    assert set(out) == {"errors"} and "kappa" in out["errors"]


def test_the_process_is_the_results_own_history():
    s = st.evaluate({"problem": "paper"}).setting
    line = views.process(s)["data"][0]
    h = s.result.history(201)
    assert line["x"] == h.tau.tolist() and line["y"] == h.slip.tolist()


@pytest.mark.parametrize(("kind", "point"), [("paper", (1.5, -0.7)), ("sphere", (0.4, 1.2))])
def test_a_click_on_the_map_moves_the_incidence_there(kind, point):
    values = st.defaults(kind)
    moved = app.clicked(values, *point)
    s = st.evaluate(moved).setting
    # the page keeps six significant digits of the click
    np.testing.assert_allclose(views.map_point(s), point, rtol=1e-5, atol=1e-5)


def test_a_click_the_inputs_cannot_reach_changes_nothing():
    assert app.clicked(st.defaults("paper"), -1.0, 0.0) is None  # the speed's angle is in [0, 90]
    assert app.clicked(st.defaults("sphere"), -1.0, 0.0) is None  # behind the heading
    assert app.clicked(st.defaults("planar"), 1.0, 0.0) is None  # no map for a planar body


def test_the_comparison_and_the_csv_hold_both_settings():
    one = app.update({"problem": "paper", "mu": "0.1"})["data"]
    two = app.update({"problem": "paper", "mu": "0.3"})["data"]
    table = app.compare_table(one, two)
    rows = {r[0]: r for r in table.rows}
    assert rows["regime"][1:3] == (one["result"]["regime"], two["result"]["regime"])
    diff = float(rows["after_vx (m/s)"][3])
    assert math.isclose(diff, two["result"]["after_vx"] - one["result"]["after_vx"], rel_tol=1e-5)
    read = list(csv.DictReader(io.StringIO(app.to_csv(two, one))))
    assert [r["setting"] for r in read] == ["pinned", "current"]
    assert float(read[1]["after_vx"]) == two["result"]["after_vx"]  # repr: full precision


@pytest.mark.parametrize(
    ("zeta", "mu", "kappa"), [(3.5, 0.2, 0.8), (2.0, 0.7, 0.3), (1.5, 0.05, 0)]
)
def test_the_map_is_the_librarys_map_on_its_half_plane(zeta, mu, kappa):
    from spinimpact import Body
    from spinimpact.viz.maps import map_fields

    a, b, regime = views._regimes(zeta, mu, kappa)
    # map_fields on 241 points a side: its a >= 0 half on the page's grid, every third row
    whole_a, whole_b, fields = map_fields(
        Body.from_zeta(mass=1.0, radius=1.0, zeta=zeta), mu=mu, kappa=kappa, extent=3.0, n=241
    )
    np.testing.assert_allclose(whole_a[120:], a, atol=1e-12)
    np.testing.assert_allclose(whole_b[::3], b, atol=1e-12)
    np.testing.assert_array_equal(fields["regime"][::3, 120:], regime)
