"""Coverage of fit()'s profile-likelihood intervals on synthetic data with known truth.

Each data set is 24 bounces of a solid sphere at one seeded set of incidences (half of
them slide, half stick at the true mu), their exact rebounds (spinimpact.solve) plus
Gaussian noise of known standard deviation. Over 200 data sets the nominal 95 % intervals
must cover the true value in 90-99 % of them (the binomial standard error at 200 sets
is 1.5 %, so 90-99 % is about three of them either side of 95 %).
"""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.model.fit import fit
from spinimpact.model.fit_data import MeasuredBounces

#: 200 fits a test: run by `make test` only.
pytestmark = pytest.mark.slow

BALL = Body.solid_sphere(mass=0.058, radius=0.033)
TRUE = {"mu": 0.35, "kappa": 0.75}
N_SETS = 200


def _incidences(n: int = 24) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(2026)
    vy = -rng.uniform(2.0, 6.0, n)
    ratio = np.linspace(0.3, 4.0, n)  # |u/vy|: sticks below (1+kappa) zeta mu = 2.14
    vx = ratio * -vy
    return vx, vy, np.zeros(n)


def _data_sets(sigmas: bool, seed: int):
    vx, vy, om = _incidences()
    exact = solve(BALL, vx, vy, om, **TRUE).after
    sd = np.array([0.05, 0.05, 3.0])  # m/s, m/s, rad/s
    rng = np.random.default_rng(seed)
    for _ in range(N_SETS):
        noisy = [x + rng.normal(0.0, s, x.shape) for x, s in zip(
            (exact.vx, exact.vy, exact.omega), sd, strict=True)]  # fmt: skip
        kw = dict(zip(("sigma_after_vx", "sigma_after_vy", "sigma_after_omega"), sd,
                      strict=True)) if sigmas else {}  # fmt: skip
        yield MeasuredBounces(vx, vy, om, *noisy, **kw)


@pytest.mark.parametrize("sigmas", [True, False], ids=["sigmas-given", "sigma-estimated"])
def test_95_percent_intervals_cover_the_truth_90_to_99_percent(sigmas):
    hits = {name: 0 for name in TRUE}
    for data in _data_sets(sigmas, seed=15 + sigmas):
        res = fit(data, BALL)
        assert res.n_sliding > 0 and res.n_sticking > 0
        for name, truth in TRUE.items():
            est = res[name]
            hits[name] += est.low <= truth <= est.high
    for name, count in hits.items():
        assert 0.90 * N_SETS <= count <= 0.99 * N_SETS, (name, count / N_SETS)


def test_one_sided_bounds_of_a_friction_the_data_only_bound_cover_the_truth():
    """Every bounce sticks and the true mu is just above the least value that stops the
    largest slip (the worst case for a lower bound): the one-sided 95 % bounds still
    cover it in 90-99 % of 200 data sets."""
    rng = np.random.default_rng(5)
    vy = -rng.uniform(2.0, 6.0, 24)
    vx = np.linspace(0.2, 2.0, 24) * -vy
    mu = float(np.max(vx / -vy)) / ((1 + TRUE["kappa"]) * 3.5) * 1.0001  # eq. 4.15
    exact = solve(BALL, vx, vy, 0.0, mu=mu, kappa=TRUE["kappa"]).after
    sd = np.array([0.05, 0.05, 3.0])
    covered = one_sided = 0
    for _ in range(N_SETS):
        noisy = [x + rng.normal(0.0, s, x.shape) for x, s in zip(
            (exact.vx, exact.vy, exact.omega), sd, strict=True)]  # fmt: skip
        res = fit(MeasuredBounces(vx, vy, np.zeros(24), *noisy, *sd), BALL)
        covered += res["mu"].low <= mu <= res["mu"].high
        one_sided += res["mu"].one_sided
    assert 0.90 * N_SETS <= covered <= 0.99 * N_SETS, covered / N_SETS
    assert one_sided >= 0.8 * N_SETS  # the data say "at least", not a value
