"""fit() refuses what it cannot answer: rebounds no impact can give, data whose scatter is
zero (no standard deviation can be estimated from them), starting values outside a
parameter's range; and it keeps every evaluation inside solve's domain."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import BALLS, Body, solve
from spinimpact.model.fit import fit
from spinimpact.model.fit_data import MeasuredBounces
from spinimpact.model.fit_models import MU_INFINITY

BALL = Body.solid_sphere(mass=0.058, radius=0.033)
SIGMAS = {"sigma_after_vx": 0.05, "sigma_after_vy": 0.05, "sigma_after_omega": 3.0}


def eight(after_vy, **sigmas):
    """Eight bounces at 5 m/s normal speed, vx from 1 to 8 m/s, with a given after_vy."""
    vx = np.arange(1.0, 9.0)
    return MeasuredBounces(vx, np.full(8, -5.0), np.zeros(8), after_vx=0.7 * vx,
                           after_vy=after_vy, **sigmas)  # fmt: skip


@pytest.mark.parametrize("sigmas", [{}, SIGMAS])
def test_a_rebound_into_the_surface_is_refused_naming_the_rows(sigmas):
    after_vy = np.full(8, 3.0)
    after_vy[[2, 5]] = [-3.0, -0.5]
    with pytest.raises(ValueError) as err:
        fit(eight(after_vy, **sigmas), BALL)
    text = str(err.value)
    assert "after_vy" in text and "into the surface" in text
    assert "index 2" in text and "-3" in text and "index 5" in text and "-0.5" in text
    assert "index 0" not in text


@pytest.mark.parametrize("sigmas", [{}, SIGMAS])
def test_a_rebound_faster_than_the_impact_is_refused(sigmas):
    with pytest.raises(ValueError) as err:
        fit(eight(np.full(8, 8.0), **sigmas), BALL)
    text = str(err.value)
    assert "faster than the impact" in text and "index 0" in text and "8" in text
    assert "and 3 more" in text  # eight bad rows: the first five named, the count of the rest


def test_noise_may_cross_the_bounds_within_its_sigmas():
    """A rebound measured 3 sigmas above the impact speed, or 3 sigmas into the surface,
    is noise about kappa = 1 or kappa = 0, not an impossible bounce: it is fitted."""
    after_vy = np.array([5.15, 5.0, 4.95, 5.1, 4.9, 5.0, 5.05, 4.98])
    res = fit(eight(after_vy, **SIGMAS), BALL)
    assert res["kappa"].high == 1.0
    near_zero = np.array([-0.15, 0.0, 0.05, 0.1, -0.1, 0.02, 0.0, 0.03])
    assert fit(eight(near_zero, **SIGMAS), BALL)["kappa"].low == 0.0


def test_without_sigmas_a_few_percent_is_noise_and_more_is_refused():
    after_vy = np.array([5.2, 5.0, 4.95, 5.1, 4.9, 5.0, 5.05, 4.98])  # 4 % above at most
    assert fit(eight(after_vy), BALL)["kappa"].high == 1.0
    after_vy[3] = 5.5  # 10 % above the impact speed
    with pytest.raises(ValueError, match=r"after_vy = 5.5 m/s at index 3"):
        fit(eight(after_vy), BALL)


def exact(n, vx, **sigmas):
    vy, om = np.full(n, -4.0), np.zeros(n)
    after = solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after
    return MeasuredBounces(vx, vy, om, after.vx, after.vy, after.omega, **sigmas)


@pytest.mark.parametrize(
    "data",
    [exact(12, np.full(12, 2.0)), exact(1, np.array([2.0])), exact(12, np.linspace(1, 8, 12))],
    ids=["twelve identical rows", "one bounce", "noise-free rows"],
)
def test_data_without_scatter_and_without_sigmas_are_refused(data):
    """One standard deviation estimated from the scatter is 0 (to rounding): no interval
    can be given, so none is; and no RuntimeWarning escapes (pytest turns it into an
    error)."""
    with pytest.raises(ValueError, match="no scatter") as err:
        fit(data, BALL)
    assert "sigma_after_vx" in str(err.value)


def test_the_same_rows_with_sigmas_are_fitted():
    res = fit(exact(12, np.full(12, 2.0), **SIGMAS), BALL)
    assert res["kappa"].estimate == pytest.approx(0.7, abs=1e-9)
    assert res["kappa"].high - res["kappa"].low > 0.01
    assert np.isfinite(res.aic) and np.isfinite(res.bic)


def sticking(seed):
    """Twelve bounces at 6 to 31 degrees from the normal: every one sticks, so the data
    only bound mu from below."""
    rng = np.random.default_rng(seed)
    vy = -rng.uniform(2, 6, 12)
    vx = np.linspace(0.1, 0.6, 12) * -vy
    om = rng.normal(0, 20, 12)
    after = solve(BALL, vx, vy, om, mu=0.5, kappa=0.7).after
    noise = rng.normal(0, 0.05, (3, 12)) * np.array([[1.0], [1.0], [40.0]])
    return MeasuredBounces(vx, vy, om, after.vx + noise[0], after.vy + noise[1],
                           after.omega + noise[2])  # fmt: skip


@pytest.mark.parametrize("seed", [0, 2])
@pytest.mark.slow
def test_mu_stays_in_solves_domain_when_every_bounce_sticks(seed):
    """The optimizer used to step past mu = 1e6 (solve's bound), and the fit failed with
    solve's "mu must be <= 1e6"; now mu is bounded there, and the data's lower bound on
    mu is reported as one-sided."""
    res = fit(sticking(seed), BALL, model="stronge")
    assert res["mu"].estimate <= MU_INFINITY
    assert res["mu"].one_sided and res["mu"].high == np.inf and res["mu"].low > 0.0
    assert "only bound mu" in res.identifiability


@pytest.mark.parametrize(
    "start, needle",
    [
        ({"mu": -1.0}, "start['mu'] must be in [0, 1e+06], got -1.0"),
        ({"kappa": 1.5}, "start['kappa'] must be in [0, 1], got 1.5"),
    ],
)
def test_a_start_outside_the_parameters_range_is_refused(start, needle):
    data = eight(np.full(8, 3.0))
    with pytest.raises(ValueError) as err:
        fit(data, BALL, start=start)
    assert needle in str(err.value)


def test_a_ball_is_a_body_and_the_result_names_the_body():
    tennis = BALLS["tennis"]
    vx = np.linspace(1.0, 16.0, 12)  # the last four slide
    vy, om = np.full(12, -4.0), np.zeros(12)
    after = solve(tennis.body, vx, vy, om, mu=0.6, kappa=0.75).after
    data = MeasuredBounces(vx, vy, om, after.vx, after.vy, after.omega, **SIGMAS)
    res = fit(data, tennis)
    assert res["mu"].estimate == pytest.approx(0.6, rel=1e-6)
    zeta = pytest.approx(1 + (tennis.radius / tennis.gyration) ** 2)
    assert res.body == {"name": "tennis", "radius": tennis.radius,
                        "gyration": tennis.gyration, "zeta": zeta}  # fmt: skip
    assert res.to_dict()["body"]["name"] == "tennis"
    assert "tennis" in repr(res)
