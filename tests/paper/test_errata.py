"""Each entry of docs/errata.md: the printed form fails, the corrected one holds.

Values are computed by the package *and* by hand from the definitions here.
"""

import numpy as np
import pytest

import spinimpact.core as core
from spinimpact import Body, solve, solve_particle

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
