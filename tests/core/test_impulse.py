"""The contact seam (spinimpact.core.impulse, spinimpact.core.works).

Checked two independent ways:

1. the paper's bodies through the generic planar collision matrix ``W`` and the
   generic impulse-momentum map (``dv = p/m``, ``domega = (r x p)/J``) give the
   rebound that ``solve`` computes;
2. for contacts that are *not* one of the paper's bodies (any ``1/W_nn`` and
   ``W_tt/W_nn``), the seam's impulses and works agree with a direct numerical
   integration of ``dc = W dp`` under Coulomb's law and Poisson's restitution.
"""

import numpy as np
import pytest

import spinimpact.core as core
from spinimpact import Body, solve
from spinimpact.core import impulse, works

from tests.cases import random_cases

EPS = np.finfo(float).eps


def test_paper_body_collision_matrix_is_diagonal_with_zeta():
    """r = (0, -R), J = m rho^2: W = diag(zeta/m, 1/m), so (1/W_nn, W_tt/W_nn) = (m, zeta)."""
    c = random_cases(5000, seed=21)
    inertia = c["mass"] * c["gyration"] ** 2
    w = core.planar_collision_matrix(c["mass"], inertia, 0.0, -c["radius"])
    assert np.all(w.tn == 0)
    params = core.contact_parameters(w.tt, w.nn)
    # a handful of roundings each (1/m, R^2/J, a division): 8 ulp
    np.testing.assert_allclose(params.mass, c["mass"], rtol=8 * EPS)
    np.testing.assert_allclose(params.zeta, c["zeta"], rtol=8 * EPS)


def test_generic_impulse_momentum_map_reproduces_solve():
    """Body velocities from the seam's contact impulse through W and r x p."""
    c = random_cases(20_000, seed=22)
    m, radius = c["mass"], c["radius"]
    inertia = m * c["gyration"] ** 2
    body = Body(mass=m, radius=radius, gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])

    rx, ry = 0.0, -radius
    ct = c["vx"] - c["omega"] * ry  # c = v + omega e_z x r
    cn = c["vy"] + c["omega"] * rx
    f = impulse.tangential_impulse(m, ct, cn, c["zeta"], c["mu"], c["kappa"])
    tau = impulse.total_impulse(m, cn, c["kappa"])
    vx = c["vx"] + f / m
    vy = c["vy"] + tau / m
    omega = c["omega"] + (rx * tau - ry * f) / inertia

    scale = np.abs(c["vx"]) + np.abs(c["vy"]) + radius * np.abs(c["omega"])
    # different but equivalent arithmetic: agreement to a few roundings of the scale
    assert np.max(np.abs(vx - imp.after.vx) / scale) < 1e-13
    assert np.max(np.abs(vy - imp.after.vy) / scale) < 1e-13
    assert np.max(np.abs(radius * (omega - imp.after.omega)) / scale) < 1e-13

    # and the contact velocity after, c+ = c- + W p, is (u+, -kappa vy)
    w = core.planar_collision_matrix(m, inertia, rx, ry)
    ct_after = ct + w.tt * f + w.tn * tau
    cn_after = cn + w.tn * f + w.nn * tau
    assert np.max(np.abs(ct_after - imp.slip_after) / scale) < 1e-12
    cn_rebound = impulse.rebound_normal_velocity(cn, c["kappa"])
    assert np.max(np.abs(cn_after - cn_rebound) / scale) < 1e-13


def _integrate_contact(ct, cn, w_tt, w_nn, mu, kappa, steps=20_000):
    """Midpoint integration of dc = W dp in the normal impulse, Coulomb friction with
    stick (friction stops once the slip would change sign), Poisson's end of impact.

    Written from the definitions only, for contacts given by W's entries (not a body).
    Returns the friction impulse, the total normal impulse and the friction work.
    """
    tau0 = -cn / w_nn
    tau1 = (1.0 + kappa) * tau0
    dtau = tau1 / steps
    slip = ct.copy()
    f = np.zeros_like(ct)
    work_t = np.zeros_like(ct)
    for _ in range(steps):
        ratio = -mu * np.sign(slip)  # F/N while slipping
        step_slip = w_tt * ratio * dtau
        # stick: the slip reaches zero inside this step; friction acts only until then
        stops = np.abs(step_slip) >= np.abs(slip)
        frac = np.where(stops, np.abs(slip) / np.where(step_slip != 0, np.abs(step_slip), 1), 1.0)
        df = ratio * dtau * frac
        work_t += df * (slip + 0.5 * w_tt * df)  # int u df over the (linear) piece
        slip = np.where(stops, 0.0, slip + step_slip)
        f += df
    return f, tau1, work_t


@pytest.mark.slow
def test_seam_against_direct_integration_for_general_contacts():
    """Contacts with arbitrary 1/W_nn and W_tt/W_nn (two balls, a 3D sphere...)."""
    rng = np.random.default_rng(23)
    n = 400
    w_nn = 10 ** rng.uniform(-1, 1, n)
    w_tt = w_nn * rng.uniform(1.05, 6.0, n)
    cn = -(10 ** rng.uniform(-1, 1, n))
    ct = rng.uniform(-4, 4, n) * np.abs(cn)
    mu = rng.uniform(0.0, 1.0, n)
    kappa = rng.uniform(0.0, 1.0, n)
    mass, zeta = core.contact_parameters(w_tt, w_nn)

    f_num, tau1_num, wt_num = _integrate_contact(ct, cn, w_tt, w_nn, mu, kappa)
    f = impulse.tangential_impulse(mass, ct, cn, zeta, mu, kappa)
    tau1 = impulse.total_impulse(mass, cn, kappa)
    pw = works.contact_phase_works(ct, cn, mass, zeta, mu, kappa)

    np.testing.assert_allclose(tau1, tau1_num, rtol=1e-12)
    # the step that holds the stick point is resolved exactly; rounding of 2e4 steps
    scale = tau1
    assert np.max(np.abs(f - f_num) / scale) < 1e-9
    energy = np.abs(cn) * tau1
    wt = pw.compression_tangential + pw.restitution_tangential
    assert np.max(np.abs(wt - wt_num) / energy) < 1e-6  # midpoint rule, O(dtau^2)

    # energy: the dissipated energy is minus the work of the contact impulse
    loss = works.contact_dissipated_energy(ct, cn, mass, zeta, mu, kappa)
    wn = pw.compression_normal + pw.restitution_normal
    np.testing.assert_allclose(loss, -(wn + wt), rtol=1e-10, atol=1e-14 * np.max(energy))


def test_core_results_are_named_tuples_that_unpack_as_before():
    ball = dict(mass=1.0, radius=0.1, zeta=3.5)
    r = core.rebound(2.0, -3.0, 5.0, ball["mass"], ball["radius"], ball["zeta"], 0.3, 0.7)
    vx, vy, omega, f1 = r
    assert (r.vx, r.vy, r.omega, r.tangential_impulse) == (vx, vy, omega, f1)
    w = core.phase_works(2.0, -3.0, 5.0, 1.0, 0.1, 3.5, 0.3, 0.7)
    assert w.compression_normal == w[0] and w.restitution_tangential == w[3]
    assert core.regime_thresholds(3.5, 0.3, 0.7).impact == pytest.approx(1.7 * 3.5 * 0.3)
    flags = core.rebound_outcomes(2.0, -3.0, 5.0, 0.1, 3.5, 0.3, 0.7)
    assert flags._fields == core.OUTCOMES
