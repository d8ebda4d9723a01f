"""Kernels of spinimpact.core.compliance against independent routes: Walton's law from the
seam's definitions, Mindlin's ratio from the contact moduli, the normalized angles."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

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
    none = cc.compliant_regime_code(np.array([1.0, 0.0]), np.array([1.0, 0.0]),
                                    np.array([0.5, 0.5]), np.array([True, True]), True)  # fmt: skip
    assert np.asarray(cc.COMPLIANT_REGIMES)[none].tolist() == ["frictionless"] * 2


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


# -- Stronge's lumped-parameter compliance: the closed form against an integration in time --


def _stronge_cases():
    """(slip, vy, zeta, mu, kappa, ratio) over gross slip, stick then reversal, and many
    stick/slip changes (stiff tangential springs), kappa from 0 to 1."""
    rng = np.random.default_rng(7)
    out = []
    for k in range(120):
        zeta = float(rng.choice([1.05, 2.0, 2.5, 3.0, 3.5, 5.0]))
        mu = float(rng.uniform(0.05, 0.8))
        kappa = float(rng.choice([0.0, 0.3, 0.6, 0.8, 0.98, 1.0]))
        ratio = float(rng.choice([0.7, 0.87, 2.0, 8.0, 30.0, 150.0]))
        vy = -float(10 ** rng.uniform(-1, 1))
        psi = float(10 ** rng.uniform(-1.5, 1.3))  # r |u/v| / mu: < 1 starts stuck
        slip = (-1) ** k * psi * mu / ratio * abs(vy)
        out.append((slip, vy, zeta, mu, kappa, ratio))
    return out


#: Two impacts with a short slip phase inside a stick (found by a wide random search), which
#: an integration in long steps misses; and the 5 mm oxide sphere at r = 5 with spin.
HARD = [
    (0.0033948366943540842, -0.19907695457770933, 7.612923565731044, 0.01265206259078675,
     1.0, 4.198188436515437),
    (-0.3462797736698212, -0.033638784885628076, 5.170783142985348, 1.0193934568911345,
     0.1, 0.06797428490550407),
    (0.75, -3.665, 3.5, 0.092, 1.0, 5.0),
]  # fmt: skip
STRONGE = _stronge_cases() + HARD


@pytest.mark.slow
def test_stronge_closed_form_equals_the_integration_in_time():
    ref = pytest.importorskip("tests.compliance_reference")
    slip, vy, zeta, mu, kappa, ratio = (np.array(c) for c in zip(*STRONGE, strict=True))
    got = cc.stronge_restitution(slip, vy, zeta, mu, kappa, ratio)
    kinds = set()
    for i, case in enumerate(STRONGE):
        after, changes, rise = ref.integrate(*case)
        # integrator tolerance rtol 1e-12: the two routes agree to 1e-9 of |c_n^-|
        assert abs(got.slip_after[i] - after) <= 1e-9 * abs(case[1]), (case, after)
        assert got.transitions[i] == changes, case
        assert rise <= 1e-9 * 0.3 * case[0] ** 2 / case[2] + 1e-15, case  # energy never rises
        kinds.add("slip" if changes == 0 else "one" if changes == 1 else "many")
    assert kinds == {"slip", "one", "many"}
    assert got.transitions.max() >= 4  # several stick/slip changes in one impact
    assert np.any(got.restitution > 0) and np.any(got.restitution < 0)  # reversals and not


def test_stronge_sliding_throughout_is_the_sliding_rebound():
    slip, vy, zeta, mu, kappa = _cases(6000)
    ratio = RNG.uniform(0.5, 20, slip.size)
    got = cc.stronge_restitution(slip, vy, zeta, mu, kappa, ratio)
    slid = (got.transitions == 0) & ~got.stuck & (slip != 0)
    assert slid.sum() > 300
    # Coulomb over all of tau_1: beta_slide. The rigid law takes it only where it is <= 0;
    # the spring lets the contact point slide on a little past c_t = 0 as it unloads.
    sliding = slip - np.sign(slip) * (1 + kappa) * zeta * mu * np.abs(vy)
    np.testing.assert_allclose(got.slip_after[slid], sliding[slid], rtol=1e-12,
                               atol=1e-13 * np.abs(slip).max())  # fmt: skip
    rigid = impulse.rebound_slip(slip, vy, zeta, mu, kappa)
    past = slid & (rigid != sliding)
    assert past.any()  # reversed while sliding, by less than mu/(kappa r) |c_n^-| (the end)
    assert np.all((-np.sign(slip) * sliding <= mu / (kappa * ratio) * np.abs(vy) + 1e-12)[past])
    # energy: |beta| <= 1 everywhere (the spring ends relaxed, friction only dissipates)
    beta = got.restitution[slip != 0]
    assert np.all(np.abs(beta) <= 1 + 1e-12)
    assert np.all(np.isnan(got.restitution[slip == 0])) and np.all(got.slip_after[slip == 0] == 0)
    smooth = mu == 0
    np.testing.assert_allclose(got.slip_after[smooth], slip[smooth], rtol=1e-15)  # u0/v*v


@pytest.mark.slow
def test_stronge_rigid_limit_approaches_the_rigid_law():
    slip, vy, zeta, mu, kappa = (a[:40] for a in _cases())
    rigid = impulse.rebound_slip(slip, vy, zeta, mu, kappa)
    errors = []
    for ratio in (1e1, 1e3, 1e5):
        got = cc.stronge_restitution(slip, vy, zeta, mu, kappa, ratio)
        err = np.abs(got.slip_after - rigid) / np.abs(vy)
        errors.append(err.max())
        if ratio > 10:
            # what is left is the stuck spring's oscillation: its velocity amplitude is at
            # most mu |c_n^-| Omega/r = mu |c_n^-| sqrt(zeta/r) (docs/compliance.md)
            assert np.all(err <= mu * np.sqrt(zeta / ratio)), ratio
    assert errors[2] < errors[1] < errors[0] / 10, errors
    assert errors[2] < 1e-3, errors


def test_stronge_depends_on_the_normalized_angle_and_frequency_ratio_only():
    # scaling: u+/|v| depends on (psi1 = r u/(mu |v|), Omega^2 = zeta r, kappa) and mu/r
    slip, vy, zeta, mu, kappa = (a[:500] for a in _cases())
    ratio = RNG.uniform(0.6, 10, slip.size)
    a = cc.stronge_restitution(slip, vy, zeta, mu, kappa, ratio)
    b = cc.stronge_restitution(-3.0 * slip, 3.0 * vy, zeta, mu, kappa, ratio)  # mirror, scale
    np.testing.assert_allclose(b.slip_after, -3.0 * a.slip_after, rtol=1e-9,
                               atol=1e-11 * np.abs(vy).max())  # fmt: skip
    # the same psi1 = r u/(mu |v|) and Omega^2 = zeta r, and r/mu: the same u+
    c = cc.stronge_restitution(slip, vy, zeta / 2.0, 2.0 * mu, kappa, 2.0 * ratio)
    np.testing.assert_allclose(c.slip_after, a.slip_after, rtol=1e-9,
                               atol=1e-11 * np.abs(vy).max())  # fmt: skip


# -- properties (hypothesis) ---------------------------------------------------------------

finite = dict(allow_nan=False, allow_infinity=False)


@given(
    st.floats(-20, 20, **finite),
    st.floats(0.05, 10, **finite),
    st.floats(1.01, 8, **finite),
    st.floats(0, 1.5, **finite),
    st.floats(0, 1, **finite),
    st.floats(0.05, 50, **finite),
    st.floats(-1, 1, **finite),
)
@settings(max_examples=300, deadline=None)
@pytest.mark.slow
def test_energy_never_increases_and_the_laws_stay_in_their_bounds(
    slip, speed, zeta, mu, kappa, ratio, beta0
):
    vy = -speed
    for after in (
        cc.stronge_restitution(slip, vy, zeta, mu, kappa, ratio).slip_after,
        cc.walton_slip(slip, vy, zeta, mu, kappa, beta0)[0],
    ):
        assert abs(after) <= abs(slip) * (1 + 1e-12) + 1e-300  # |beta| <= 1: energy
        # the friction impulse never exceeds Coulomb's over the whole impact
        assert abs(after - slip) <= (1 + kappa) * zeta * mu * speed * (1 + 1e-12) + 1e-15
