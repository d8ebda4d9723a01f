"""Tracks across a bounce: the joint fit through the exact law, the prediction from the
incoming samples alone, another bounce map in its place, and bad input."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.model.track import Air, as_track
from spinimpact.model.track_bounce import flights
from spinimpact.model.track_fit import fit_bounces
from spinimpact.model.track_predict import predict_bounce

from .track_cases import BALL, CONTACT_HEIGHT, shot

TRUE = {"mu": 0.2, "kappa": 0.88, "contact_height": CONTACT_HEIGHT}


@pytest.fixture(scope="module")
def two_shots():
    rng = np.random.default_rng(21)
    return [shot(rng, before=0.3, after=0.15, name=f"shot {i}") for i in range(2)]


@pytest.fixture(scope="module")
def fitted(two_shots):
    return fit_bounces([t for t, _ in two_shots], law="rigid", sigma=0.0015, intervals=False)


@pytest.mark.slow  # a joint fit of two shots: about 10 s
def test_the_shared_parameters_and_the_spin_after_are_recovered(fitted, two_shots):
    for name, truth in TRUE.items():
        z = (fitted[name] - truth) / fitted.standard_error[name]
        assert abs(z) < 4.0, (name, fitted[name], fitted.standard_error[name])
    for s, (_, truth) in zip(fitted.shots, two_shots, strict=True):
        assert abs(s.contact_time - truth["contact_time"]) < 1e-3
        # the law's spin after the bounce, from positions alone, within 15 % of the truth
        np.testing.assert_allclose(s.spin_after, truth["after_spin"],
                                   atol=0.15 * np.linalg.norm(truth["after_spin"]))  # fmt: skip
        assert s.rms_after < 3.5e-3
    assert fitted.names == ("mu", "kappa", "contact_height")
    assert np.isnan(fitted.interval_low["mu"])  # intervals not asked for


@pytest.mark.slow  # the joint fit of the fixture
def test_the_fits_spin_prior_is_its_determined_shots_median_and_spread(fitted, two_shots):
    values = {name: [s.spin_components_before[name][0] for s in fitted.shots
                     if s.spin_components_before[name][2] == "determined"]
              for name in ("topspin", "sidespin", "gyrospin")}  # fmt: skip
    prior = fitted.spin_prior(("topspin", "sidespin", "gyrospin"))
    for name, v in values.items():
        if not v:
            assert name not in prior
            continue
        mid = float(np.median(v))
        assert prior[name] == (mid, max(1.4826 * float(np.median(np.abs(np.subtract(v, mid)))),
                                        1.0))  # fmt: skip
    with pytest.raises(ValueError, match="unknown spin component 'spin'"):
        fitted.spin_prior(("spin",))
    # predict_bounce takes the fit's gyrospin prior by default
    track, truth = two_shots[0]
    incoming = track.select(track.time < truth["contact_time"])
    default = predict_bounce(incoming, fitted, horizon=0.05)
    given = predict_bounce(incoming, fitted, horizon=0.05, spin_prior=fitted.spin_prior())
    np.testing.assert_array_equal(default.position, given.position)
    none = predict_bounce(incoming, fitted, horizon=0.05, spin_prior=None)
    assert np.all(np.isfinite(none.position))
    with pytest.raises(ValueError, match="spin_prior must be a dict, 'fit' or None"):
        predict_bounce(incoming, fitted, spin_prior="data")


@pytest.mark.slow  # a joint fit: several seconds
def test_a_fixed_parameter_is_held(two_shots):
    tracks = [two_shots[0][0].select(two_shots[0][0].time > 0.15)]
    f = fit_bounces(tracks, law="rigid", sigma=0.0015, intervals=False,
                    fixed={"contact_height": CONTACT_HEIGHT, "kappa": 0.88})  # fmt: skip
    assert f.free == ("mu",)
    assert f["contact_height"] == CONTACT_HEIGHT
    assert "(fixed)" in f.summary()


def test_the_prediction_from_the_incoming_samples_holds_the_later_samples():
    """With the truth's own law and parameters, a 0.45 s incoming flight (its spin
    determined) predicts the later samples within the band (4 standard errors, outliers
    aside) and within 1 cm rms."""
    track, truth = shot(np.random.default_rng(8), before=0.45, after=0.15, spin=[0, 0, 100.0])
    incoming = track.select(track.time < truth["contact_time"])
    later = track.time > truth["contact_time"]
    p = predict_bounce(incoming, TRUE, times=track.time[later], sigma=0.0015)
    assert abs(p.contact_time - truth["contact_time"]) < 2e-3
    good = np.ones(track.time.size, dtype=bool)
    good[truth["outliers"]] = False
    good = good[later]
    err = p.position - track.position[later]
    assert np.sqrt(np.mean(np.sum(err[good] ** 2, axis=1))) < 0.01
    z = err[good] / np.hypot(p.standard_error[good], 0.0015)
    assert np.all(np.abs(z) < 4.0), np.abs(z).max()
    assert np.all(p.low < p.high)


def test_another_bounce_map_replaces_the_law():
    """A map that reverses the vertical velocity and keeps the rest: the ball leaves the
    contact with exactly that velocity."""
    air = Air(BALL)
    state = np.array([[0.0, 0.0, 1.0, 5.0, 0.0, -1.0, 0.0, 50.0, 0.0, 0.5]])
    shared = {"mu": np.zeros(1), "kappa": np.zeros(1), "contact_height": np.full(1, 0.76)}

    def mirror(v, w):
        return v * [1.0, 1.0, -1.0], w

    out = flights(np.zeros(1), state, shared, air, "rigid", np.zeros((1, 0)), np.zeros((1, 0)),
                  "z", rebound=mirror)  # fmt: skip
    np.testing.assert_allclose(out["velocity_after"], out["velocity_before"] * [1, 1, -1])
    assert out["contact_position"][0, 2] == pytest.approx(0.76, abs=1e-12)


def test_bad_input_is_refused_naming_the_track(two_shots):
    track, truth = two_shots[0]
    early = track.select(track.time < truth["contact_time"] - 0.05)
    with pytest.raises(ValueError, match="track shot 0: no bounce found"):
        fit_bounces([early])
    with pytest.raises(TypeError, match="tracks must be Track objects"):
        fit_bounces([(track.time, track.position)])
    with pytest.raises(ValueError, match="law must be one of rigid, walton, mindlin-deresiewicz"):
        fit_bounces([track], law="stronge")
    with pytest.raises(ValueError, match="fixed names an unknown parameter 'beta0'"):
        fit_bounces([track], fixed={"beta0": 0.1})
    with pytest.raises(ValueError, match="shared values missing: contact_height"):
        predict_bounce(early, {"mu": 0.2, "kappa": 0.9})
    flat = as_track(track.time, track.position * [1, 1, 0] + [0, 0, 2.0], name="high")
    with pytest.raises(ValueError, match="track high: the incoming flight does not reach"):
        predict_bounce(flat, {**TRUE, "contact_height": -50.0})


@pytest.mark.slow  # a joint fit of three shots: about 20 s
def test_micro_slip_bounces_are_fitted_through_the_table():
    from spinimpact import MindlinDeresiewicz

    nu = 0.25  # a thin shell: zeta r = 2.5 * 0.857 = 2.14, inside the table
    rng = np.random.default_rng(5)
    shots = [shot(rng, before=0.3, after=0.15, name=f"micro {i}",
                  tangential=MindlinDeresiewicz(poisson_ratio=nu)) for i in range(3)]  # fmt: skip
    f = fit_bounces([t for t, _ in shots], law="mindlin-deresiewicz", sigma=0.0015,
                    intervals=False)  # fmt: skip
    assert f.names == ("mu", "kappa", "contact_height", "poisson_ratio")
    for name, truth in TRUE.items() | {("poisson_ratio", nu)}:
        z = (f[name] - truth) / f.standard_error[name]
        assert abs(z) < 4.0, (name, f[name], f.standard_error[name])
    for s, (_, truth) in zip(f.shots, shots, strict=True):
        np.testing.assert_allclose(s.spin_after, truth["after_spin"],
                                   atol=0.15 * np.linalg.norm(truth["after_spin"]))  # fmt: skip
    # the prediction from the incoming samples flies the same law
    track, truth = shots[0]
    p = predict_bounce(track.select(track.time < truth["contact_time"] - 0.01), f)
    assert abs(p.contact_time - truth["contact_time"]) < 2e-3


@pytest.mark.parametrize(
    ("name", "value", "error"),
    [("poisson_ratio", float("nan"), ValueError), ("poisson_ratio", 0.7, ValueError),
     ("poisson_ratio", "abc", TypeError), ("kappa", 1.5, ValueError), ("mu", None, TypeError)],
)  # fmt: skip
def test_shared_values_given_as_numbers_are_checked(two_shots, name, value, error):
    track, _ = two_shots[0]
    values = {**TRUE, "poisson_ratio": 0.3, name: value}
    with pytest.raises(error, match=rf"shared\['{name}'\]"):
        predict_bounce(track, values, law="mindlin-deresiewicz")
