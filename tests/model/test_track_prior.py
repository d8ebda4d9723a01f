"""The incoming fit's spin prior (``fit_arc(spin_prior=...)``, ``BounceFit.spin_prior``,
``predict_bounce(spin_prior=...)``)."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.model.track import find_bounce, spin_axes
from spinimpact.model.track_arc import SPIN_COMPONENTS, fit_arc

from .track_cases import shot


@pytest.fixture(scope="module")
def incoming():
    """A 0.4 s incoming flight with 100 rad/s of backspin and 60 rad/s of gyrospin."""
    track, truth = shot(np.random.default_rng(11), before=0.4, after=0.05,
                        spin=[60.0, 0.0, 100.0])  # fmt: skip
    return track.select(slice(0, find_bounce(track)["index"])), truth


@pytest.mark.parametrize(
    ("prior", "error", "message"),
    [
        ((0.0, 1.0), TypeError, "spin_prior must be a dict"),
        ({"backspin": (0.0, 1.0)}, ValueError, "unknown component 'backspin'"),
        ({"gyrospin": 1.0}, TypeError, r"spin_prior\['gyrospin'\] must be \(mean, sd\)"),
        ({"gyrospin": (0.0, 0.0)}, ValueError, "an sd > 0"),
        ({"gyrospin": (np.nan, 1.0)}, ValueError, "a finite mean"),
    ],
)
def test_a_bad_prior_is_refused_naming_it(incoming, prior, error, message):
    with pytest.raises(error, match=message):
        fit_arc(incoming[0], sigma=0.0015, spin_prior=prior)


def test_the_prior_holds_a_loose_component_and_barely_moves_a_determined_one(incoming):
    track, truth = incoming
    free = fit_arc(track, sigma=0.0015)
    held = fit_arc(track, sigma=0.0015, spin_prior={"gyrospin": (-5.0, 0.5)})
    assert free.spin_components["gyrospin"][2] != "determined"
    gyro = held.spin_components["gyrospin"][0]
    assert abs(gyro + 5.0) < 1.5  # the samples hardly pull it off the prior's mean
    top_free, top_se = free.spin_components["topspin"][:2]
    assert abs(held.spin_components["topspin"][0] - top_free) < 0.5 * top_se
    # the words and standard errors of spin_components are the samples' alone
    for name in SPIN_COMPONENTS:
        assert held.spin_components[name][2] == free.spin_components[name][2]

    # the covariance is the posterior's: the gyrospin g(v, w) = axis(v) . w, the quantity the
    # prior is on, has a linearized standard error of at most the prior's sd
    def g(x):
        return spin_axes(x[3:6], track.up)[2] @ x[6:9]

    x = held.state[:9]
    grad = np.array([(g(x + h * np.eye(9)[j]) - g(x - h * np.eye(9)[j])) / (2 * h)
                     for j, h in enumerate([1e-6] * 6 + [1e-3] * 3)])  # fmt: skip
    se = float(np.sqrt(grad @ held.covariance[:9, :9] @ grad))
    assert se <= 0.5


def test_a_wide_prior_changes_nothing_that_matters(incoming):
    track, _ = incoming
    free = fit_arc(track, sigma=0.0015)
    wide = fit_arc(track, sigma=0.0015, spin_prior={"gyrospin": (0.0, 1e9)})
    np.testing.assert_allclose(wide.position, free.position, atol=1e-6)
    np.testing.assert_allclose(wide.velocity, free.velocity, atol=1e-5)
