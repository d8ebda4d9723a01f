"""Kernels of spinimpact.core.compliance against independent routes: Walton's law from the
seam's definitions, Mindlin's ratio from the contact moduli, the normalized angles."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.core import compliance as cc
from spinimpact.core import impulse

RNG = np.random.default_rng(2024)


def _cases(n=5000):
    slip = RNG.normal(0, 3, n)
    slip[::17] = 0.0
    vy = -(10 ** RNG.uniform(-1, 1, n))
    zeta = RNG.choice([1.05, 2.0, 2.5, 3.0, 3.5, 5.0], n)
    mu = RNG.uniform(0, 1.2, n)
    mu[::23] = 0.0
    kappa = RNG.uniform(0, 1, n)
    return slip, vy, zeta, mu, kappa


def test_sliding_restitution_is_the_seam_sliding_throughout():
    slip, vy, zeta, mu, kappa = _cases()
    moving = slip != 0
    # Coulomb over the whole impulse tau_1, then dc_t = W_tt df: an independent route
    tau1 = impulse.total_impulse(1.0, vy, kappa)
    slip_after = slip - zeta * mu * np.sign(slip) * tau1  # mass 1: W_tt = zeta
    beta = cc.sliding_restitution(slip, vy, zeta, mu, kappa)
    np.testing.assert_allclose(beta[moving], -slip_after[moving] / slip[moving], rtol=1e-12,
                               atol=1e-12)  # fmt: skip
    assert np.all(np.isinf(beta[~moving]))
    # beta_slide >= 0 exactly where the rigid law sticks
    stick = impulse.sticks(slip, vy, zeta, mu, kappa)
    near = np.abs(beta) < 1e-12
    assert np.array_equal((beta >= 0)[~near], stick[~near])


def test_walton_is_min_of_beta0_and_the_sliding_value():
    slip, vy, zeta, mu, kappa = _cases()
    beta0 = RNG.uniform(-1, 1, slip.size)
    beta = cc.walton_restitution(slip, vy, zeta, mu, kappa, beta0)
    slide = cc.sliding_restitution(slip, vy, zeta, mu, kappa)
    moving = slip != 0
    np.testing.assert_array_equal(beta[moving], np.minimum(beta0, slide)[moving])
    assert np.all(np.isnan(beta[~moving]))
    after, stuck = cc.walton_slip(slip, vy, zeta, mu, kappa, beta0)
    np.testing.assert_allclose(after[moving], -beta[moving] * slip[moving], rtol=1e-12,
                               atol=1e-12 * np.abs(slip).max())  # fmt: skip
    assert np.all(after[~moving] == 0)
    far = np.abs(slide - beta0) > 1e-9
    np.testing.assert_array_equal(stuck[moving & far], (beta0 <= slide)[moving & far])


def test_walton_beta0_zero_is_the_rigid_rebound_slip_bit_for_bit():
    slip, vy, zeta, mu, kappa = _cases()
    after, stuck = cc.walton_slip(slip, vy, zeta, mu, kappa, 0.0)
    np.testing.assert_array_equal(after, impulse.rebound_slip(slip, vy, zeta, mu, kappa))
    np.testing.assert_array_equal(stuck, impulse.sticks(slip, vy, zeta, mu, kappa))
    f1 = cc.tangential_impulse_of(2.0, zeta, slip, after)
    np.testing.assert_allclose(f1, impulse.tangential_impulse(2.0, slip, vy, zeta, mu, kappa),
                               rtol=1e-12, atol=1e-13 * np.abs(slip).max())  # fmt: skip


def test_regime_codes():
    code = cc.compliant_regime_code(
        np.array([1.0, 0.0, 1.0, 1.0, 1.0]),
        np.array([1.0, 0.0, 0.0, -0.3, 0.4]),
        np.array([0.0, 0.5, 0.5, 0.5, 0.5]),
        np.array([False, True, True, True, False]),
    )
    names = np.asarray(cc.COMPLIANT_REGIMES)[code]
    assert names.tolist() == ["frictionless", "no-slip", "stick", "slip-reversal", "slip"]


@pytest.mark.parametrize("nu", [0.0, 0.23, 0.3, 0.33, 0.5])
def test_mindlin_ratio_from_the_contact_moduli(nu):
    E = 3.8e11
    G = E / (2 * (1 + nu))
    # one body rigid: E* = E/(1-nu^2), G* = G/(2-nu); k_n = 2 E* a, k_t = 8 G* a
    assert cc.mindlin_stiffness_ratio(nu) == pytest.approx(
        8 * G / (2 - nu) / (2 * E / (1 - nu**2)), rel=1e-14
    )
    # two bodies of one material: E*, G* halve, the ratio stays
    assert cc.mindlin_stiffness_ratio(nu) == pytest.approx(
        8 * G / (2 * (2 - nu)) / (2 * E / (2 * (1 - nu**2))), rel=1e-14
    )


def test_maw_angles_of_the_rigid_law_follow_the_simple_theory():
    # MBF's chi = zeta (1 - nu)/(2 - nu); sliding throughout: psi2 = (psi1 - 2 chi (1+k))/k
    zeta, nu, mu = 3.0, 0.28, 0.3
    chi = zeta * (1 - nu) / (2 - nu)
    assert chi == pytest.approx(1.2558, abs=1e-4)  # their disk cut from a sphere
    kappa = np.array([1.0, 0.8, 0.5])
    vy = -2.0
    slip = 5.0 * np.ones(3)
    after = impulse.rebound_slip(slip, vy, zeta, mu, kappa)
    a = cc.maw_angles(slip, vy, after, -kappa * vy, mu, nu)
    np.testing.assert_allclose(a.recoil, (a.incidence - 2 * chi * (1 + kappa)) / kappa,
                               rtol=1e-12)  # fmt: skip
    assert a.recoil[0] == pytest.approx(a.incidence[0] - 4 * chi)
    stuck = cc.maw_angles(0.2, vy, 0.0, -0.8 * vy, mu, nu)
    assert float(stuck.recoil) == 0.0
    assert np.isnan(cc.maw_angles(1.0, -1.0, 0.3, 0.0, mu, nu).recoil)


def test_walton_kernels_run_on_another_array_library():
    xp = pytest.importorskip("array_api_strict")
    slip, vy, zeta, mu, kappa = (xp.asarray(x) for x in _cases(50))
    beta = cc.walton_restitution(slip, vy, zeta, mu, kappa, 0.3)
    ref = cc.walton_restitution(*(np.asarray(x) for x in (slip, vy, zeta, mu, kappa)), 0.3)
    np.testing.assert_array_equal(np.asarray(beta), ref)
