"""One flight fitted to a camera track: input checks, the frame, the integrator, the fit,
outliers, the bounce finder and the identifiability words."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.core.flight import integrate_to_ground
from spinimpact.model.track import Air, as_track, find_bounce, fly_to, frame_rotation
from spinimpact.model.track_arc import IDENTIFIABILITY, fit_arc

from .track_cases import BALL, shot


def _parabola(n=40, span=0.3):
    t = np.linspace(0.0, span, n)
    return t, np.stack([5 * t, 0 * t, 1 + 2 * t - 9.80665 * t**2 / 2], 1)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (lambda t, p: (t, np.where(np.arange(len(t))[:, None] == 7, np.nan, p)),
         "track shot, row 7: time or position is NaN"),
        (lambda t, p: (np.r_[t[:5], t[4], t[6:]], p), "track shot, row 5: time does not increase"),
        (lambda t, p: (t[:4], p[:4]), "track shot: 4 sample"),
        (lambda t, p: (t, p[:, :2]), "track shot: time must have shape"),
    ],
)  # fmt: skip
def test_bad_tracks_are_refused_naming_the_track_and_the_row(change, message):
    t, p = change(*_parabola())
    with pytest.raises(ValueError, match=message):
        as_track(t, p, name="shot")


def test_a_track_of_text_is_a_type_error():
    t, p = _parabola()
    with pytest.raises(TypeError, match="track shot: time must be an array of real numbers"):
        as_track(t.astype(str), p, name="shot")
    with pytest.raises(TypeError, match="track must be a Track"):
        fit_arc((t, p))


def test_the_camera_frame_is_a_proper_rotation_to_the_package_frame():
    rot = frame_rotation("z")
    assert np.linalg.det(rot) == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_array_equal(rot @ [0, 0, 1], [0, 1, 0])  # z up becomes y up
    np.testing.assert_array_equal(rot.T @ rot, np.eye(3))
    with pytest.raises(ValueError, match="up must be 'z' or 'y'"):
        frame_rotation("x")


def test_fly_to_agrees_with_the_core_integrator_at_a_fine_step():
    """Positions read from fly_to's interpolant at uneven times equal those the core's
    integrator reaches with a 1 ms step, to 1e-7 m (the step error of 0.02 s is of order
    1e-8 m for a table-tennis ball at 6 m/s and 300 rad/s)."""
    aero = Air(BALL).aero(0.45)
    p0, v0, w0 = np.array([[0.0, 0.5, 0.0]]), np.array([[6.0, 1.0, 0.3]]), np.array(
        [[20.0, 40.0, 300.0]])  # fmt: skip
    targets = np.array([0.013, 0.05, 0.0571, 0.2, 0.33])
    got, _ = fly_to(np.zeros(1), p0, v0, w0, targets, aero)
    for k, t in enumerate(targets):
        seg = integrate_to_ground(np.zeros(1), p0, v0, w0, aero, radius=-10.0, t_stop=t,
                                  dt=1e-3)  # fmt: skip
        np.testing.assert_allclose(got[0, k], seg.position[0], atol=1e-7)


def test_a_parabola_is_recovered_within_its_errors():
    t, p = _parabola()
    rng = np.random.default_rng(3)
    f = fit_arc(as_track(t, p + rng.normal(0, 0.002, p.shape)), air_density=0.0,
                drag_coefficient=0.5, sigma=0.002)  # fmt: skip
    z = (f.velocity - [5.0, 0.0, 2.0]) / f.standard_error[3:6]
    assert np.all(np.abs(z) < 4.0), z
    assert f.outliers.sum() == 0
    assert f.standard_error.size == 9  # C_D held


def test_a_synthetic_flight_its_outliers_and_its_drag_are_recovered():
    """A 0.4 s flight with 100 rad/s of backspin: its topspin component is determined, the
    spin about its heading (which the Magnus force does not see) is not."""
    track, truth = shot(np.random.default_rng(11), before=0.4, after=0.05, spin=[0, 0, 100.0])
    split = find_bounce(track)["index"]
    f = fit_arc(track.select(slice(0, split)), sigma=0.0015)
    assert set(np.flatnonzero(f.outliers)) == {i for i in truth["outliers"] if i < split}
    z = (f.state[3:10] - np.r_[truth["velocity"], truth["spin"], 0.5]) / f.standard_error[3:10]
    assert np.all(np.abs(z) < 4.0), z
    assert f.rms < 3.5e-3  # 1.5 mm a coordinate: 2.6 mm in 3D
    assert f.spin_components["topspin"][2] == "determined"
    assert f.spin_components["gyrospin"][2] != "determined"
    assert {w for _, _, w in f.spin_components.values()} <= set(IDENTIFIABILITY)


def test_a_short_arc_leaves_the_spin_poorly_determined():
    short, _ = shot(np.random.default_rng(5), before=0.1, after=0.05, spin=[0.0, 0.0, 300.0])
    f = fit_arc(short.select(short.time < 0.08), sigma=0.0015)
    assert f.spin_components["topspin"][2] == "poorly determined"


def test_find_bounce_locates_the_contact_and_names_a_track_without_one():
    track, truth = shot(np.random.default_rng(2))
    b = find_bounce(track)
    assert abs(b["time"] - truth["contact_time"]) < 2e-3
    assert track.time[b["index"] - 1] <= b["time"] < track.time[b["index"]]
    with pytest.raises(
        ValueError, match=r"track synthetic: no bounce found \(lowest sample at row"
    ):
        find_bounce(track.select(track.time < truth["contact_time"] - 0.05))


def test_find_bounce_splits_the_shipped_tracks_as_their_own_rule_does():
    """On the 65 measured tracks, find_bounce finds a bounce exactly where the data's README
    rule confirmed one (``bounce`` or ``bounce_few_post``) and splits it at the same sample;
    it finds none in the tracks that end at or before the table."""
    import csv
    from pathlib import Path

    from spinimpact.io.tracks import read_tracks

    data = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "table_tennis_tracks"
    with open(data / "trajectories.csv", newline="") as f:
        rows = {f"{r['set']} {r['trajectory']}": r for r in csv.DictReader(f)}
    for track in read_tracks(data / "tracks.csv"):
        row = rows[track.name.split(" (")[0]]
        if row["bounce_status"] in ("bounce", "bounce_few_post"):
            assert find_bounce(track)["index"] == int(row["n_pre"]), track.name
        else:
            with pytest.raises(ValueError, match="no bounce found"):
                find_bounce(track)
