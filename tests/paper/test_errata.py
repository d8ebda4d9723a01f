"""Each entry of docs/errata.md: the printed form fails, the corrected one holds.

Values are computed by the package *and* by hand from the definitions here.
"""

from fractions import Fraction as Fr

import numpy as np
import pytest

import spinimpact.core as core
from spinimpact import Body, solve, solve_particle

from . import exact_tau as exact

DISK = Body.solid_disk(mass=1.0, radius=1.0)  # zeta = 3


def printed_7_10(mu, u_before, u_after):
    """Eq. (7.10) as printed: mu_hat = -mu |u-| / (u- - u+)."""
    return -mu * abs(u_before) / (u_before - u_after)


@pytest.mark.parametrize(
    ("mu", "regime", "mu_hat"),
    [
        # slip throughout: |u/v| = 1 > (1+kappa) zeta mu = 0.9, so mu_hat = -mu (eq. 7.9)
        (0.2, "slip", -0.2),
        # stick: |u/v| = 1 <= zeta mu = 1.5, so mu_hat = u-/((1+kappa) zeta v-) = -1/4.5 (eq. 7.8)
        (0.5, "stick-compression", -1 / 4.5),
    ],
)
def test_eq_7_10_printed_common_form_is_wrong(mu, regime, mu_hat):
    imp = solve(DISK, vx=1.0, vy=-1.0, omega=0.0, mu=mu, kappa=0.5)
    assert imp.regime == regime
    assert imp.impulse_ratio == pytest.approx(mu_hat, rel=1e-14)
    # definition (7.4): f1/tau1
    assert imp.tangential_impulse / imp.tau1 == pytest.approx(mu_hat, rel=1e-14)
    # the corrected common form: (u+ - u-) / ((1 + kappa) zeta |v-|)
    assert (imp.slip_after - imp.slip_before) / (1.5 * 3 * 1.0) == pytest.approx(mu_hat, rel=1e-14)
    # the printed form gives -0.2222 in slip and -0.5 in stick: the two cases swapped
    printed = printed_7_10(mu, float(imp.slip_before), float(imp.slip_after))
    assert abs(printed - mu_hat) > 0.02


def test_eq_6_14_second_line_restitution_work_turns_negative():
    """(6.14) claims W_r >= 0 for all |u/v| >= (1+kappa) zeta mu when zeta mu^2 <= 1."""
    zeta, mu, kappa = 3.0, 0.1, 0.5  # zeta mu^2 = 0.03 <= 1
    ratio = 10.0  # far beyond (1 + kappa) zeta mu = 0.45
    imp = solve(DISK, vx=ratio, vy=-1.0, omega=0.0, mu=mu, kappa=kappa)
    assert imp.regime == "slip"
    w_r = imp.work_restitution_normal + imp.work_restitution_tangential
    # by hand from (6.10): W_r = tau0|v|/2 [kappa^2 + kappa zeta mu^2 (2 + kappa) - 2 kappa mu r]
    by_hand = 0.5 * (kappa**2 + kappa * zeta * mu**2 * (2 + kappa) - 2 * kappa * mu * ratio)
    assert w_r == pytest.approx(by_hand, rel=1e-13)
    assert by_hand == pytest.approx(-0.35625)
    assert w_r < 0  # the printed claim W_r >= 0 fails
    # the corrected threshold (kappa + (2 + kappa) zeta mu^2) / (2 mu) = 2.875
    assert core.restitution_work_zero(zeta, mu, kappa) == pytest.approx(2.875, rel=1e-14)
    signs = [np.sign(float(core.restitution_work(r, zeta, mu, kappa))) for r in (2.8, 2.875, 2.95)]
    assert signs == [1.0, 0.0, -1.0]


def test_section_8_particle_example_inequality_direction():
    """mu = 0.5, kappa = 0.8: energy is created for |u/v| BELOW 0.25, not above."""
    assert core.particle_energy_threshold(0.5, 0.8) == pytest.approx(0.25, rel=1e-14)
    near_normal = solve_particle(vx=0.1, vy=-1.0, mu=0.5, kappa=0.8)  # about 5.7 degrees
    oblique = solve_particle(vx=1.0, vy=-1.0, mu=0.5, kappa=0.8)  # 45 degrees
    # (8.7) by hand: 1/2 (1.8) [-0.2 + 0.45 - 2 (0.5) r]
    assert near_normal.energy_change == pytest.approx(0.9 * 0.15, rel=1e-13)
    assert oblique.energy_change == pytest.approx(0.9 * -0.75, rel=1e-13)
    assert near_normal.creates_energy and not oblique.creates_energy
    # the printed sentence says the increase occurs "if u-/|v-| > 0.25": it does not
    assert np.degrees(np.arctan(0.25)) == pytest.approx(14.04, abs=0.01)


def test_section_8_minimum_energy_beyond_eq_8_5():
    """Past the right end of (8.5), eq. (8.4) would undercut the rebound energy."""
    zeta, mu, kappa, ratio = 3.0, 0.1, 0.5, 10.0
    upper = ((1 + kappa) * (1 + zeta * mu**2) - 1) / mu  # right side of (8.5): 5.45
    assert ratio > upper
    imp = solve(DISK, vx=ratio, vy=-1.0, omega=0.0, mu=mu, kappa=kappa)
    printed_8_4 = imp.kinetic_energy_before - 0.5 * (1 + mu * ratio) ** 2 / (1 + zeta * mu**2)
    assert printed_8_4 < imp.kinetic_energy_after - 0.05  # not attainable: E falls until tau1
    assert imp.min_energy_case == "at rebound"
    assert imp.tau_min_energy == imp.tau1
    assert imp.min_kinetic_energy == pytest.approx(imp.kinetic_energy_after, rel=1e-13)
    # E(tau) is still decreasing at tau1: dE/dtau = v + (F/N) u < 0 there
    h = imp.history(tau=[imp.tau1 * (1 - 1e-6), imp.tau1])
    assert h.kinetic_energy[1] < h.kinetic_energy[0]


# --- Errata 5-9: sentences that state a relation -------------------------------------------
#
# Each is checked three ways: by exact integration of (2.7) in tau with fractions
# (tests/paper/exact_tau.py, no closed form and no package code), by hand from the
# definitions, and against the package.

DISK_EXACT = {"m": 1, "radius": 1, "rho2": Fr(1, 2)}  # solid disk, zeta = 3


def test_exact_route_reproduces_the_package():
    """The fraction integrator is a trustworthy second route: it gives solve()'s numbers."""
    rng = np.random.default_rng(5)
    for _ in range(60):
        vx, rim = (Fr(int(x), 8) for x in rng.integers(-24, 25, 2))
        vy = -Fr(int(rng.integers(1, 25)), 8)
        mu, kappa = Fr(int(rng.integers(1, 21)), 20), Fr(int(rng.integers(0, 21)), 20)
        p = exact.integrate(**DISK_EXACT, vx=vx, vy=vy, rim=rim, mu=mu, kappa=kappa)
        imp = solve(DISK, float(vx), float(vy), float(rim), mu=float(mu), kappa=float(kappa))
        for ours, theirs in [
            (p.vx, imp.after.vx),
            (p.vy, imp.after.vy),
            (p.omega, imp.after.omega),
            (p.f1, imp.tangential_impulse),
            (p.work_compression_normal, imp.work_compression_normal),
            (p.work_restitution_normal, imp.work_restitution_normal),
            (p.work_compression_tangential, imp.work_compression_tangential),
            (p.work_restitution_tangential, imp.work_restitution_tangential),
            (p.min_energy, imp.min_kinetic_energy),
            (p.tau_min_energy, imp.tau_min_energy),
        ]:
            assert float(theirs) == pytest.approx(float(ours), rel=1e-12, abs=1e-12)


def test_erratum_5_impulse_connection_after_eq_2_3():
    """Printed: zeta (uC+ - uC-) = R (omega+ - omega-). From (2.1) and (2.3), with
    J = m rho^2: R (omega+ - omega-) = (R^2/rho^2)(uC+ - uC-) = (zeta - 1)(uC+ - uC-);
    zeta (uC+ - uC-) is the change of the contact-point slip, u+ - u-."""
    p = exact.integrate(**DISK_EXACT, vx=1, vy=-1, rim=0, mu="0.5", kappa="0.5")
    zeta = 3
    d_uc, d_rim = p.vx - 1, 1 * (p.omega - 0)
    assert (d_uc, d_rim) == (Fr(-1, 3), Fr(-2, 3))
    assert zeta * d_uc != d_rim  # printed: -1 against -2/3
    assert (zeta - 1) * d_uc == d_rim  # corrected
    assert zeta * d_uc == (p.vx + p.omega) - 1  # = u+ - u-
    imp = solve(DISK, vx=1.0, vy=-1.0, omega=0.0, mu=0.5, kappa=0.5)
    d_uc, d_rim = imp.after.vx - 1.0, imp.after.omega * 1.0
    assert (zeta - 1) * d_uc == pytest.approx(d_rim, rel=1e-15)
    assert abs(zeta * d_uc - d_rim) == pytest.approx(1 / 3, rel=1e-15)
    # and for any body, regime and incidence: the printed form fails whenever f1 != 0
    rng = np.random.default_rng(6)
    for rho2 in (Fr(1, 2), Fr(2, 5), Fr(2, 3), Fr(1), Fr(9, 4)):  # disk ... spool
        z = 1 + 1 / rho2
        for _ in range(20):
            vx, rim = (Fr(int(x), 4) for x in rng.integers(-12, 13, 2))
            q = exact.integrate(1, 1, rho2, vx, -1, rim, mu="0.3", kappa="0.7")
            assert (z - 1) * (q.vx - vx) == q.omega - rim
            assert (z * (q.vx - vx) == q.omega - rim) == (q.f1 == 0)


def test_erratum_6_normal_works_after_eq_6_14():
    """Printed: "W_r^n is never greater than W_c^n". W_c^n = tau0 v-/2 < 0 and
    W_r^n = -kappa^2 W_c^n >= 0, so W_r^n > W_c^n whenever kappa > 0; the statement
    holds for the magnitudes, |W_r^n| = kappa^2 |W_c^n| <= |W_c^n|."""
    p = exact.integrate(**DISK_EXACT, vx=1, vy=-1, rim=0, mu="0.2", kappa="0.5")
    assert (p.work_compression_normal, p.work_restitution_normal) == (Fr(-1, 2), Fr(1, 8))
    assert not p.work_restitution_normal <= p.work_compression_normal  # printed
    assert abs(p.work_restitution_normal) == Fr(1, 4) * abs(p.work_compression_normal)
    imp = solve(DISK, vx=1.0, vy=-1.0, omega=0.0, mu=0.2, kappa=0.5)
    assert imp.work_restitution_normal - imp.work_compression_normal == pytest.approx(0.625)


@pytest.mark.parametrize(
    ("vx", "mu", "regime", "w_c", "w_r"),
    [
        # after (6.19): slip throughout, r = 1 >= (1 + kappa) zeta mu = 0.9
        ("1", "0.2", "slip", Fr(-7, 50), Fr(-1, 40)),
        # after (6.17): stick in restitution, zeta mu = 1.5 <= r = 2 <= 2.25
        ("2", "0.5", "stick-restitution", Fr(-5, 8), Fr(-1, 24)),
    ],
)
def test_erratum_7_tangential_works_after_eqs_6_17_and_6_19(vx, mu, regime, w_c, w_r):
    """Printed twice: "W_r^t < W_c^t". Friction never does positive work (F opposes u),
    so both works are <= 0 and the ratio (6.16)/(6.18) < 1 means W_r^t > W_c^t; the
    true statement is |W_r^t| < |W_c^t|, as the words ("smaller frictional work") say."""
    p = exact.integrate(**DISK_EXACT, vx=vx, vy=-1, rim=0, mu=mu, kappa="0.5")
    assert (p.work_compression_tangential, p.work_restitution_tangential) == (w_c, w_r)
    assert not p.work_restitution_tangential < p.work_compression_tangential  # printed
    assert abs(p.work_restitution_tangential) < abs(p.work_compression_tangential)
    # by hand: (6.9)/(6.11) tangential parts with tau0 |v-| / 2 = 1/2, zeta = 3
    r, m_u, k = Fr(vx), Fr(mu), Fr(1, 2)
    assert w_c == -Fr(1, 2) * m_u * (2 * r - 3 * m_u)
    if regime == "slip":
        assert w_r == -Fr(1, 2) * k * m_u * (2 * r - (2 + k) * 3 * m_u)
    else:
        assert w_r == -Fr(1, 2) * (r - 3 * m_u) ** 2 / 3
    imp = solve(DISK, vx=float(vx), vy=-1.0, omega=0.0, mu=float(mu), kappa=0.5)
    assert imp.regime == regime
    assert imp.work_ratio_tangential == pytest.approx(float(w_r / w_c), rel=1e-13)  # 5/28, 1/15
    assert imp.work_restitution_tangential > imp.work_compression_tangential


def test_erratum_8_which_bound_of_mu_hat_is_attained():
    """Printed after (7.9): the bounds are attained when |u-/v-| = (1 + kappa) zeta mu,
    "the lower bound if sign(u-) is negative, and the upper bound if sign(u-) is
    positive". By (7.9), mu_hat = -mu sign(u-): u- < 0 gives the upper bound +mu, u- > 0
    the lower bound -mu, and both hold for every |u-/v-| >= (1 + kappa) zeta mu."""
    mu, kappa = Fr(1, 5), Fr(1, 2)  # (1 + kappa) zeta mu = 0.9
    for vx, bound in ((-1, +mu), (-2, +mu), (1, -mu), (2, -mu)):
        p = exact.integrate(**DISK_EXACT, vx=vx, vy=-1, rim=0, mu=mu, kappa=kappa)
        mu_hat = p.f1 / p.tau1  # definition (7.4)
        assert mu_hat == bound
        printed = -mu if vx < 0 else +mu  # "lower if sign(u-) negative"
        assert mu_hat != printed
        imp = solve(DISK, vx=float(vx), vy=-1.0, omega=0.0, mu=0.2, kappa=0.5)
        assert imp.impulse_ratio == pytest.approx(float(bound), rel=1e-15)
    # attained at r = 1 and r = 2, not only at r = 0.9


def test_erratum_9_figure_5a_caption():
    """Printed (caption of Fig. 5a): the minimum lies in the sliding phase "if
    |u-/v-| > zeta mu, and in that case tau0 < tau_m < tau* < tau1". By (4.6) tau* < tau1
    only while |u-/v-| < (1 + kappa) zeta mu; beyond, slip lasts throughout (Fig. 5c)."""
    p = exact.integrate(**DISK_EXACT, vx=1, vy=-1, rim=0, mu="0.1", kappa="0.5")
    tau_star = Fr(1) / (3 * Fr(1, 10))  # m |u-| / (zeta mu), eq. (4.3): the slip never stops
    assert p.tau_star is None and tau_star == Fr(10, 3) > p.tau1 == Fr(3, 2)
    assert p.tau0 < p.tau_min_energy < p.tau1  # tau_m = 110/103 tau0: Fig. 5c, not 5a
    assert p.tau_min_energy == Fr(110, 103)
    imp = solve(DISK, vx=1.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5)
    assert imp.regime == "slip"
    assert imp.tau_star > imp.tau1  # the caption's tau* < tau1 fails
    assert imp.tau_min_energy == pytest.approx(110 / 103, rel=1e-14)
