"""Equation tests: every closed form of the package against direct numerical
integration of the equations of motion (2.7) in tau (``tests/reference.py``),
over 12,000 random impacts spread evenly over the five regimes."""

import numpy as np
import pytest

from spinimpact import Body, solve

from tests.cases import REGIME_NAMES, random_cases
from tests.reference import integrate, integrate_ivp

N = 12_000


@pytest.fixture(scope="module")
def both():
    c = random_cases(N, seed=20261122)
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])
    ref = integrate(
        c["vx"], c["vy"], c["omega"], c["mass"], c["radius"], c["gyration"], c["mu"], c["kappa"]
    )
    return c, imp, ref


def _scale_v(c):
    """Velocity scale of each impact, for absolute tolerances near zero."""
    return np.abs(c["vx"]) + np.abs(c["vy"]) + np.abs(c["radius"] * c["omega"])


def _scale_e(c):
    return 0.5 * c["mass"] * _scale_v(c) ** 2


# The event-located integrator advances piecewise-constant right-hand sides
# exactly, so both routes differ only by accumulated rounding of ~50 steps:
# 1e-11 of the natural scale is ~100x the observed worst case and still
# 1e5x smaller than any modelling error would be.
RTOL = 1e-11


def test_all_regimes_are_covered(both):
    c, imp, _ = both
    assert (imp.regime == c["target"]).all()
    for name in REGIME_NAMES:
        assert (imp.regime == name).sum() >= N // 5 - 1


def test_rebound_velocities(both):
    c, imp, ref = both
    v = _scale_v(c)
    np.testing.assert_allclose(imp.after.vx, ref.vx, rtol=0, atol=RTOL * v.max())
    assert np.all(np.abs(imp.after.vx - ref.vx) <= RTOL * v)
    assert np.all(np.abs(imp.after.vy - ref.vy) <= RTOL * v)
    assert np.all(np.abs(c["radius"] * (imp.after.omega - ref.omega)) <= RTOL * v)


def test_impulses(both):
    c, imp, ref = both
    p = c["mass"] * _scale_v(c)
    assert np.all(np.abs(imp.tau0 - ref.tau0) <= RTOL * p)
    assert np.all(np.abs(imp.tau1 - ref.tau1) <= RTOL * p)
    assert np.all(np.abs(imp.tangential_impulse - ref.f1) <= RTOL * p)
    stuck = np.isfinite(ref.tau_stick)
    # The slip stops (event u = 0) exactly where tau_* <= tau_1 (eq. 4.6) ...
    closed_stick = imp.tau_star <= imp.tau1
    assert np.array_equal(stuck & (c["mu"] > 0), closed_stick & (c["mu"] > 0))
    # ... at tau_* = m|u-|/(zeta mu) (eq. 4.3).
    assert np.all(np.abs(imp.tau_star[stuck] - ref.tau_stick[stuck]) <= RTOL * p[stuck])


def test_dissipated_energy_and_works(both):
    c, imp, ref = both
    e = _scale_e(c)
    for mine, theirs in (
        (imp.work_compression_normal, ref.wcn),
        (imp.work_compression_tangential, ref.wct),
        (imp.work_restitution_normal, ref.wrn),
        (imp.work_restitution_tangential, ref.wrt),
        (imp.dissipated_energy, -(ref.wcn + ref.wct + ref.wrn + ref.wrt)),
    ):
        assert np.all(np.abs(mine - theirs) <= RTOL * e)
    # and the energy balance E- + W = E+ closes on the computed velocities (eq. 5.11)
    assert np.all(
        np.abs(imp.kinetic_energy_before - imp.kinetic_energy_after - imp.dissipated_energy)
        <= RTOL * e
    )


def test_impulse_ratio(both):
    c, imp, ref = both
    # mu_hat (closed forms 7.8/7.9) against its definition f1/tau1 (7.4) on the integrated process
    scale = np.maximum(c["mu"], _scale_v(c) / np.abs(c["vy"]))
    assert np.all(np.abs(imp.impulse_ratio - ref.f1 / ref.tau1) <= RTOL * scale)


def test_minimum_kinetic_energy(both):
    c, imp, ref = both
    e = _scale_e(c)
    assert np.all(np.abs(imp.min_kinetic_energy - ref.e_min) <= RTOL * e)
    # tau_m is only determined where E has a strict minimum; compare where E'' > 0 there.
    p = c["mass"] * _scale_v(c)
    strict = imp.min_energy_case != "at rebound"
    assert np.all(np.abs(imp.tau_min_energy - ref.tau_min)[strict] <= 1e-7 * p[strict])


def test_restitution_coefficients_from_the_process(both):
    c, imp, ref = both
    k = c["kappa"]
    np.testing.assert_allclose(imp.newton_restitution, -ref.vy / c["vy"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        imp.poisson_restitution, (ref.tau1 - ref.tau0) / ref.tau0, atol=1e-12
    )
    # sqrt of a ratio of two works that each carry ~1e-16 relative rounding:
    # near kappa = 0 the square root amplifies it to ~1e-8 absolute at worst.
    np.testing.assert_allclose(imp.energetic_restitution, np.sqrt(-ref.wrn / ref.wcn), atol=1e-7)
    # ... and all three equal kappa (section 3; eq. 6.5); Newton's and Poisson's to
    # rounding, Stronge's through the same square root as above.
    np.testing.assert_allclose(imp.newton_restitution, k, rtol=0, atol=1e-14)
    np.testing.assert_allclose(imp.poisson_restitution, k, rtol=0, atol=1e-14)
    np.testing.assert_allclose(imp.energetic_restitution, k, rtol=0, atol=1e-7)


@pytest.mark.parametrize("index", range(0, 300, 3))
def test_against_scipy_solve_ivp(both, index):
    """A generic adaptive ODE solver (RK45, rtol 1e-10) with event location."""
    c, imp, _ = both
    args = [c[k][index] for k in ("vx", "vy", "omega", "mass", "radius", "gyration", "mu", "kappa")]
    vx, vy, om, de = integrate_ivp(*args)
    v = _scale_v(c)[index]
    assert abs(imp.after.vx[index] - vx) <= 1e-8 * v
    assert abs(imp.after.vy[index] - vy) <= 1e-8 * v
    assert abs(c["radius"][index] * (imp.after.omega[index] - om)) <= 1e-8 * v
    assert abs(imp.dissipated_energy[index] - de) <= 1e-8 * _scale_e(c)[index]
