"""fit() on a measurement: Kharaz, Gorham & Salman (2001), a 5 mm aluminium-oxide sphere
on a glass anvil at 3.9 m/s without spin (docs/references.md, "Kharaz et al. 2001").

The points (benchmarks/data/kharaz2001) are the public digitization of the paper's
figures used by the MFiX DEM test case DEM05 (via Di Renzo & Di Maio 2004, Figs. 6 and 8):
tangential restitution ``e_t = vx+/vx-`` of the centre and the magnitude of the spin after
impact, each over the incidence angle from the normal. Each point is one bounce with one
measured quantity: ``vx = 3.9 sin(theta)``, ``vy = -3.9 cos(theta)``, ``omega = 0``, and either
``after_vx = e_t vx`` or ``after_omega = -|omega|`` (a ball moving in +x spins clockwise
after friction acts). The literature's friction coefficient is 0.092 with normal
restitution 0.98 (Chung & Ooi 2011, Test 4), held fixed: without measured ``vy+`` the
sliding bounces depend on ``mu (1 + kappa)`` only.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from spinimpact import Body
from spinimpact.cli.fit import read_columns
from spinimpact.model.fit import fit
from spinimpact.model.fit_data import MeasuredBounces

DATA = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "kharaz2001"
E_T = np.column_stack(list(read_columns(str(DATA / "tangential_restitution.csv")).values()))
OMEGA = np.column_stack(list(read_columns(str(DATA / "omega.csv")).values()))
SPEED, RADIUS, MU = 3.9, 0.0025, 0.092
BALL = Body.solid_sphere(mass=4000.0 * 4.0 / 3.0 * np.pi * RADIUS**3, radius=RADIUS)


def kharaz(sigma_e_t=None) -> MeasuredBounces:
    """The measured bounces; with ``sigma_e_t``, only the e_t points, with that standard
    deviation of e_t (the digitization's reading error of about 1 % of an axis from 0 to 1)."""
    et, om = E_T, OMEGA
    if sigma_e_t is not None:
        om = om[:0]
    theta = np.radians(np.r_[et[:, 0], om[:, 0]])
    vx, vy = SPEED * np.sin(theta), -SPEED * np.cos(theta)
    n, k = theta.size, len(et)
    after_vx, after_omega = np.full(n, np.nan), np.full(n, np.nan)
    after_vx[:k] = et[:, 1] * vx[:k]
    after_omega[k:] = -om[:, 1]
    sig = {}
    if sigma_e_t is not None:
        sig = {"sigma_after_vx": sigma_e_t * vx, "sigma_after_vy": 1.0, "sigma_after_omega": 1.0}
    return MeasuredBounces(vx, vy, np.zeros(n), after_vx=after_vx, after_omega=after_omega, **sig)


def sliding_fit(data: MeasuredBounces):
    """Fit every bounce, keep those the fit says slid throughout, fit them alone."""
    everything = fit(data, BALL, fixed={"kappa": 0.98})
    slid = everything.sliding
    assert 0 < slid.sum() < len(data)
    return everything, fit(data.select(slid), BALL, fixed={"kappa": 0.98})


def test_sliding_bounces_recover_the_literature_friction():
    """Both kinds of point, one standard deviation (in m/s, spin as R omega) estimated
    from their scatter: the bounces at 39 degrees and above slide, and their mu interval
    holds 0.092."""
    everything, res = sliding_fit(kharaz())
    assert np.all(everything.incidence_angle_deg[everything.sliding] > 35.0)
    assert np.all(everything.incidence_angle_deg[~everything.sliding] < 35.0)
    assert res.n_sliding == 6 and res.n_sticking == 0
    mu = res["mu"]
    assert not mu.one_sided and mu.low < MU < mu.high
    assert mu.high - mu.low < 0.02  # an interval that says something


def test_sliding_bounces_with_the_digitization_error_recover_the_literature_friction():
    """The e_t points alone with sigma(e_t) = 0.01: a chi2 consistent with the reading
    error, and the interval holds 0.092."""
    _, res = sliding_fit(kharaz(sigma_e_t=0.01))
    assert res.n_sliding == 3
    mu = res["mu"]
    assert mu.low < MU < mu.high
    assert res.chi2 < 6.0  # chi2 with 2 degrees of freedom: 95 % quantile 5.99


def test_walton_fitted_to_every_point_finds_the_literature_values():
    """All 15 points, Walton's law (the compliance that makes a ball grip at low angles):
    mu holds 0.092, beta0 holds the 0.33 that DEM practice takes for these spheres
    (Foerster et al. 1994, as docs/validation.md uses it), and the AIC prefers it to the
    rigid law by far."""
    data = kharaz()
    walton = fit(data, BALL, model="walton", fixed={"kappa": 0.98})
    rigid = fit(data, BALL, fixed={"kappa": 0.98})
    assert walton["mu"].low < MU < walton["mu"].high
    assert walton["beta0"].low < 0.33 < walton["beta0"].high
    assert walton.aic < rigid.aic - 20
