"""Property tests (hypothesis): what must hold for every admissible impact."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import spinimpact.core as core
from spinimpact import Body, solve

speed = st.floats(0.05, 20.0)
signed = st.floats(-20.0, 20.0)
mus = st.one_of(st.just(0.0), st.floats(0.0, 2.0))
kappas = st.one_of(st.sampled_from([0.0, 1.0]), st.floats(0.0, 1.0))
zetas = st.one_of(st.sampled_from([2.0, 2.5, 3.0, 3.5]), st.floats(1.01, 10.0))


def _solve(vx, w, omega, mu, kappa, zeta, mass=1.3, radius=0.07):
    body = Body.from_zeta(mass=mass, radius=radius, zeta=zeta)
    return solve(body, vx, -w, omega, mu=mu, kappa=kappa)


@given(signed, speed, st.floats(-300, 300), mus, kappas, zetas)
def test_energy_never_increases(vx, w, omega, mu, kappa, zeta):
    imp = _solve(vx, w, omega, mu, kappa, zeta)
    e0 = float(imp.kinetic_energy_before)
    assert imp.dissipated_energy >= 0
    # rounding of E+ computed from the velocities: a few ulps of E-
    assert imp.kinetic_energy_after <= e0 * (1 + 1e-13)
    assert imp.min_kinetic_energy <= imp.kinetic_energy_after + 1e-13 * e0
    assert imp.min_kinetic_energy >= 0  # the energy of a state: never negative
    assert imp.work_compression_normal + imp.work_compression_tangential < 0  # W_c < 0 (sec. 6.1)
    assert imp.work_restitution_tangential <= 0
    assert imp.work_compression_tangential <= 0


@given(signed, speed, st.floats(-300, 300), mus, kappas, zetas)
@pytest.mark.slow
def test_impulse_ratio_bounded_by_mu(vx, w, omega, mu, kappa, zeta):
    imp = _solve(vx, w, omega, mu, kappa, zeta)
    assert abs(imp.impulse_ratio) <= mu * (1 + 1e-12)
    # the identity behind (7.8)-(7.9): mu_hat = (u+ - u-) / ((1 + kappa) zeta |v-|)
    expected = (imp.slip_after - imp.slip_before) / ((1 + kappa) * zeta * w)
    assert imp.impulse_ratio == pytest.approx(expected, rel=1e-9, abs=1e-12 * (1 + mu))


@given(signed, speed, st.floats(-300, 300), st.floats(0.01, 2.0), kappas, zetas)
def test_work_ratio_bounds(vx, w, omega, mu, kappa, zeta):
    imp = _solve(vx, w, omega, mu, kappa, zeta)
    ratio = imp.work_ratio_tangential
    if imp.slip_before == 0:
        assert np.isnan(ratio)
        return
    lower, upper = core.work_ratio_tangential_bounds(imp.incidence_ratio, zeta, mu, kappa)
    assert lower - 1e-12 <= ratio <= upper + 1e-12  # eqs. 6.15, 6.17, 6.19
    assert ratio <= kappa + 1e-12 and ratio <= 1  # W_r^t <= W_c^t in magnitude
    # the closed form (6.15/6.16/6.18) is the ratio of the two computed works
    if imp.work_compression_tangential < -1e-200:  # not underflowed
        works = imp.work_restitution_tangential / imp.work_compression_tangential
        assert ratio == pytest.approx(works, rel=1e-9, abs=1e-12)


@given(speed, mus, kappas, zetas, st.sampled_from([-1.0, 1.0]))
@pytest.mark.slow
def test_continuity_across_regime_boundaries(w, mu, kappa, zeta, sign):
    """Rebound, energy, works and mu_hat are continuous where the regime changes."""
    for boundary in (zeta * mu, (1 + kappa) * zeta * mu):
        slips = sign * w * boundary * (1 + np.array([-1e-9, 0.0, 1e-9]))
        imp = _solve(0.3, w, (slips - 0.3) / 0.07, mu, kappa, zeta)
        for field in (
            imp.after.vx,
            imp.after.omega * 0.07,
            imp.dissipated_energy,
            imp.work_restitution_tangential,
            imp.min_kinetic_energy,
            imp.tau_min_energy,
        ):
            jumps = np.abs(np.diff(field))
            scale = 1 + np.abs(field).max() + w**2
            assert jumps.max() <= 1e-7 * scale
        assert np.abs(np.diff(imp.impulse_ratio)).max() <= 1e-7 * (1 + mu)


@given(st.integers(1, 4), st.integers(1, 5))
def test_broadcasting_gives_the_broadcast_shape(n, k):
    vx = np.linspace(-3, 3, n)[:, None]
    omega = np.linspace(-40, 40, k)
    imp = solve(Body.ring(mass=1.0, radius=0.1), vx, -2.0, omega, mu=0.3, kappa=0.5)
    for value in (
        imp.after.vx,
        imp.regime,
        imp.tau_star,
        imp.work_ratio_tangential,
        imp.outcome.backward,
        imp.min_energy_case,
    ):
        assert np.shape(value) == (n, k)
    # each element equals the scalar solution
    one = solve(
        Body.ring(mass=1.0, radius=0.1), vx[n - 1, 0], -2.0, omega[k - 1], mu=0.3, kappa=0.5
    )
    assert imp[n - 1, k - 1].after.vx == one.after.vx
    assert imp[n - 1, k - 1].regime == one.regime


def test_scalar_inputs_give_scalars():
    imp = solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.2, kappa=0.5)
    assert np.shape(imp.after.vx) == ()
    assert isinstance(imp.regime, str)
    assert isinstance(float(imp.dissipated_energy), float)


def test_body_arrays_broadcast_with_velocities():
    body = Body(mass=[1.0, 2.0], radius=0.1, gyration=[0.05, 0.2])
    imp = solve(body, [[1.0], [2.0], [3.0]], -1.0, 0.0, mu=0.4, kappa=0.6)
    assert imp.shape == (3, 2)
    single = solve(Body(mass=2.0, radius=0.1, gyration=0.2), 3.0, -1.0, 0.0, mu=0.4, kappa=0.6)
    assert imp[2, 1].after.omega == single.after.omega
    assert imp[2, 1].body.mass == 2.0
