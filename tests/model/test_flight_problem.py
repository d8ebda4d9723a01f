"""The ball's flight as a registered problem: its rows are the flights ``flight()`` flies."""

from __future__ import annotations

import numpy as np
import pytest

import spinimpact
from spinimpact import flight, launch, problem
from spinimpact.io.batch import run_batch
from spinimpact.model.flight_problem import FlightSummary


def _same(a, b) -> bool:
    a, b = np.asarray(a), np.asarray(b)
    if a.dtype.kind == "f" or b.dtype.kind == "f":
        return np.array_equal(a.astype(float), b.astype(float), equal_nan=True)
    return np.array_equal(a.astype(str), b.astype(str))


def test_a_row_is_the_flight_flight_flies():
    got = problem("flight").solve(speed=50.0, elevation_deg=-6.0, launch_height=2.8,
                                  topspin_rpm=2000.0)  # fmt: skip
    want = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0)
    columns = want.columns()
    for name, column in got.columns().items():
        assert _same(column[0], columns[name]), name  # the same numbers, bit for bit


def test_side_spin_and_back_spin_are_the_named_axes_mixed():
    # topspin -1200 rpm (backspin) and sidespin 900 rpm: the spin vector launch() gives for
    # a spin of 1500 rpm about backspin:0.8+sidespin:0.6 (a 3-4-5 mix, of unit length)
    got = problem("flight").solve(ball="table-tennis", surface="table", speed=8.0,
                                  elevation_deg=10.0, heading_deg=30.0, launch_height=0.3,
                                  topspin_rpm=-1200.0, sidespin_rpm=900.0)  # fmt: skip
    _, spin = launch(8.0, 10.0, 30.0, 1500.0, "backspin:0.8+sidespin:0.6")
    launched = [got.columns()[f"launch_w{k}"][0] for k in "xyz"]
    np.testing.assert_allclose(launched, spin, rtol=1e-14, atol=1e-12)


def test_rows_of_several_balls_and_grounds_are_each_their_own_flight():
    rows = {
        "ball": np.array(["tennis", "golf", "tennis", "soccer"], dtype=object),
        "surface": np.array(["clay", "green", "hard", "grass"], dtype=object),
        "speed": np.array([30.0, 20.0, 25.0, 15.0]),
        "elevation_deg": np.array([5.0, 30.0, -3.0, 20.0]),
        "topspin_rpm": np.array([1500.0, -3000.0, 0.0, 200.0]),
    }
    got = problem("flight").solve(**rows)
    assert isinstance(got, FlightSummary) and got.shape == (4,)
    for i in range(4):
        one = flight(str(rows["ball"][i]), str(rows["surface"][i]), speed=rows["speed"][i],
                     angle=rows["elevation_deg"][i], spin_rpm=rows["topspin_rpm"][i])  # fmt: skip
        assert got.columns()["final_position_x"][i] == one.final_position.x
        assert got.columns()["bounce1_regime"][i] == str(one.bounces.regime[0])


def test_a_ball_that_never_bounces_has_no_first_bounce():
    got = problem("flight").solve(speed=0.0, elevation_deg=0.0, launch_height=0.0335,
                                  ball="tennis")  # fmt: skip
    columns = got.columns()
    assert columns["bounce_count"][0] == 0 and np.isnan(columns["bounce1_time"][0])
    assert columns["bounce1_regime"][0] == ""


def test_a_file_of_launches_is_batched_with_units(tmp_path):
    source = tmp_path / "serves.csv"
    source.write_text("speed,elevation_deg,launch_height,topspin_rpm\n"
                      "50,-6,2.8,2000\n45,-4,2.7,-500\n")  # fmt: skip
    out = tmp_path / "out.csv"
    summary = run_batch(source, out, defaults={}, fields=("final_position_x", "bounce1_regime"))
    assert summary.kind == "flight" and summary.rows == 2
    lines = out.read_text().splitlines()
    header = "speed,elevation_deg,launch_height,topspin_rpm,final_position_x,bounce1_regime"
    assert lines[0] == header
    first = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0)
    assert float(lines[1].split(",")[4]) == first.final_position.x
    units = (tmp_path / "out.units.json").read_text()
    assert '"final_position_x": "m"' in units and '"speed": "m/s"' in units


@pytest.mark.parametrize(
    ("given", "message"),
    [
        ({"speed": -1.0}, "speed must be >= 0"),
        ({"elevation_deg": 95.0}, r"elevation_deg must be in \[-90, 90\]"),
        ({"ball": "cricket"}, "ball must be one of tennis"),
    ],
)
def test_bad_launch_inputs_are_named(given, message):
    values = {"speed": 10.0, "elevation_deg": 5.0, **given}
    with pytest.raises(ValueError, match=message):
        problem("flight").solve(**values)


def test_the_problem_is_listed_with_its_units():
    declared = spinimpact.problem("flight")
    assert declared.unit("topspin_rpm") == "rpm" and declared.unit("elevation_deg") == "deg"
    assert declared.unit("final_time") == "s" and declared.unit("stop") is None
