"""Independent test suite for ``spinimpact``, derived straight from the paper.

V. A. Lubarda (2010), "On the frictional impact of a spinning disk against a
fixed surface" (Glasnik CANU 19).  Every expected value below is derived here
from the definitions only -- the impulse equations (2.1)-(2.7), Coulomb's law
F/N = -mu*sign(u) while the contact point slips and F = 0 once it sticks,
tau = normal impulse, v = v^- + tau/m, tau0 = m|v^-|, tau1 = (1+kappa)*tau0,
u = vx + R*omega, zeta = 1 + R^2/rho^2 -- and NOT from the implementation.

Derivation summary (used by the reference model ``ref`` below)
-------------------------------------------------------------
From (2.7): m dvx = (F/N) dtau, m dvy = dtau, J domega = R (F/N) dtau, J = m rho^2,
hence m du = zeta (F/N) dtau (4.1).  While slipping F/N = -mu s, s = sign(u^-),
so |u| = |u^-| - zeta mu tau/m and u reaches 0 at tau* = m|u^-|/(zeta mu) (4.3).
The slip ends at t_end = min(tau*, tau1); the tangential impulse is
f(tau) = -mu s min(tau, t_end) (7.2)/(7.3), f1 = f(tau1), and
    vx+ = vx^- + f1/m,  omega+ = omega^- + R f1/J,  vy+ = -kappa vy^-.
The frictional power (F/N) u = -mu |u| during slip, so its integral from 0 to t
(t <= t_end) is g(t) = -mu (|u^-| t - zeta mu t^2 / (2 m)).  The kinetic energy
obeys dE/dtau = v + (F/N) u (8.1); dE/dtau is continuous and non-decreasing,
so E(tau) is convex on [0, tau1] and its minimum is where dE/dtau = 0, or at
tau1 when dE/dtau < 0 throughout.

Printed formulas found to disagree with the definitions (tests below check the
DERIVED result and would fail on the printed one):
  * (6.14), second line: "W_r >= 0 for |u/v| >= (1+kappa) zeta mu when
    zeta mu^2 <= 1" is false; W_r(r) decreases linearly in r and becomes
    negative for r > [kappa + zeta mu^2 (2+kappa)]/(2 mu).
  * (7.10): mu_hat = -mu |u^-|/(u^- - u^+) is wrong in both regimes (in the
    stick regime it gives -mu sign(u^-)); the identity that follows from the
    impulse equations is mu_hat = (u^+ - u^-)/(zeta (1+kappa) |v^-|).
  * Worked example after (8.7): with mu = 0.5, kappa = 0.8 the particle model
    creates energy when u^-/|v^-| < 0.25 (incidence angle from the normal
    smaller than about 14 degrees), not "> 0.25" as printed.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import numpy.testing as npt
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import spinimpact.core as core
from spinimpact import (
    Body,
    ConstantRestitution,
    TabulatedRestitution,
    solve,
    solve_particle,
)

# Rounding-level tolerance: closed forms evaluated along different algebraic
# routes (e.g. vx - u/zeta versus vx + f1/m) agree to a few ulps of the largest
# term; 1e-12 relative leaves ~4 decades of headroom for cancellation.
RTOL = 1e-12

# friction coefficients: exactly 0 or a physically meaningful positive value
# (subnormal mu such as 1e-308 would only probe floating-point overflow of tau*)
MU = st.one_of(st.just(0.0), st.floats(1e-6, 1.5))

HYP = settings(
    max_examples=120,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
)

# (mass, radius, gyration) triples with known zeta; rho is given explicitly so
# the reference model never depends on the implementation's Body.
BODIES = {
    "disk": (2.0, 0.5, 0.5 / math.sqrt(2.0)),  # zeta = 3
    "ring": (1.0, 0.2, 0.2),  # zeta = 2
    "sphere": (0.45, 0.11, 0.11 * math.sqrt(0.4)),  # zeta = 7/2
    "shell": (0.06, 0.02, 0.02 * math.sqrt(2.0 / 3.0)),  # zeta = 5/2
    "custom": (2.0, 0.1, 0.05),  # zeta = 5
    "spool": (1.0, 0.1, 0.2),  # rho > R: zeta = 1.25
}


def make_body(name):
    m, R, rho = BODIES[name]
    return Body(mass=m, radius=R, gyration=rho)


# --------------------------------------------------------------------------
# Reference model, derived from the definitions (see module docstring)
# --------------------------------------------------------------------------
def ref(m, R, rho, vx, vy, omega, mu, kappa):
    vx, vy, omega, mu, kappa = np.broadcast_arrays(
        *(np.asarray(a, dtype=float) for a in (vx, vy, omega, mu, kappa))
    )
    zeta = 1.0 + R**2 / rho**2
    J = m * rho**2
    u = vx + R * omega
    s = np.sign(u)
    tau0 = m * np.abs(vy)
    tau1 = (1.0 + kappa) * tau0
    with np.errstate(divide="ignore", invalid="ignore"):
        tau_star = np.where(u == 0.0, 0.0, np.where(mu == 0.0, np.inf, m * np.abs(u) / (zeta * mu)))
    t_end = np.minimum(tau_star, tau1)  # end of the slip stage
    f1 = -mu * s * t_end
    vx_p = vx + f1 / m
    om_p = omega + R * f1 / J
    vy_p = vy + tau1 / m

    def energy(a, b, c):
        return 0.5 * m * (a**2 + b**2) + 0.5 * J * c**2

    def g(t):  # integral of (F/N) u over [0, t], t <= t_end
        return -mu * (np.abs(u) * t - zeta * mu * t**2 / (2.0 * m))

    wct = g(np.minimum(tau0, t_end))
    wrt = g(t_end) - wct
    wcn = -0.5 * m * vy**2
    wrn = 0.5 * kappa**2 * m * vy**2

    # minimum of the convex E(tau): zero of dE/dtau = v + (F/N) u
    slope_at_end = vy + t_end / m - mu * np.maximum(np.abs(u) - zeta * mu * t_end / m, 0.0)
    tau_m_slip = m * (np.abs(vy) + mu * np.abs(u)) / (1.0 + zeta * mu**2)
    tau_m = np.where(slope_at_end >= 0.0, tau_m_slip, np.where(t_end < tau1, tau0, tau1))
    f_m = -mu * s * np.minimum(tau_m, t_end)
    e_min = energy(vx + f_m / m, vy + tau_m / m, omega + R * f_m / J)

    regime = np.where(
        mu == 0.0,
        "frictionless",
        np.where(
            u == 0.0,
            "no-slip",
            np.where(
                tau_star <= tau0,
                "stick-compression",
                np.where(tau_star <= tau1, "stick-restitution", "slip"),
            ),
        ),
    )
    e_b = energy(vx, vy, omega)
    e_a = energy(vx_p, vy_p, om_p)
    return SimpleNamespace(
        zeta=zeta,
        J=J,
        u=u,
        s=s,
        tau0=tau0,
        tau1=tau1,
        tau_star=tau_star,
        t_end=t_end,
        f1=f1,
        vx=vx_p,
        vy=vy_p,
        omega=om_p,
        slip=vx_p + R * om_p,
        mu_hat=f1 / tau1,
        e_before=e_b,
        e_after=e_a,
        wcn=wcn,
        wrn=wrn,
        wct=wct,
        wrt=wrt,
        tau_m=tau_m,
        e_min=e_min,
        regime=regime,
    )


def ref_state(m, R, rho, vx, vy, omega, mu, kappa, tau):
    """Velocities, slip, force ratio, tangential impulse, E along tau (scalar impact)."""
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    J = m * rho**2
    tau = np.asarray(tau, dtype=float)
    f = -mu * r.s * np.minimum(tau, r.t_end)
    hvx = vx + f / m
    hvy = vy + tau / m
    hom = omega + R * f / J
    return SimpleNamespace(
        vx=hvx,
        vy=hvy,
        omega=hom,
        slip=hvx + R * hom,
        f=f,
        E=0.5 * m * (hvx**2 + hvy**2) + 0.5 * J * hom**2,
    )


def integrate_impulse(m, R, rho, vx, vy, omega, mu, kappa, n=64):
    """Direct step-by-step integration of (2.7) in tau with Coulomb friction.

    Independent of the closed forms above: friction ratio -mu*sign(u) while
    u != 0, the step is cut where u reaches zero, after which the contact sticks
    (F = 0).  Within a sub-step every velocity is linear in tau, so midpoint
    values integrate the powers exactly.
    """
    J = m * rho**2
    tau0 = m * abs(vy)
    tau1 = (1.0 + kappa) * tau0
    grid = np.concatenate([np.linspace(0.0, tau0, n + 1), np.linspace(tau0, tau1, n + 1)[1:]])
    stuck = (vx + R * omega) == 0.0 or mu == 0.0
    wcn = wct = wrn = wrt = 0.0
    for a, b in zip(grid[:-1], grid[1:], strict=True):
        t = a
        while t < b:
            u = vx + R * omega
            if not stuck:
                ratio = -mu * math.copysign(1.0, u)
                dudt = (1.0 / m + R * R / J) * ratio
                t_zero = t + abs(u) / abs(dudt)
                t_next = min(b, t_zero)
            else:
                ratio, dudt, t_zero, t_next = 0.0, 0.0, math.inf, b
            d = t_next - t
            wn = (vy + 0.5 * d / m) * d
            wt = ratio * (u + 0.5 * dudt * d) * d
            if b <= tau0:
                wcn, wct = wcn + wn, wct + wt
            else:
                wrn, wrt = wrn + wn, wrt + wt
            vx += ratio * d / m
            vy += d / m
            omega += R * ratio * d / J
            if t_next >= t_zero:
                stuck = True
            t = t_next
    return SimpleNamespace(vx=vx, vy=vy, omega=omega, wcn=wcn, wct=wct, wrn=wrn, wrt=wrt)


def ref_work_ratio(r, zeta, mu, kappa):
    """W_r^t / W_c^t from the integrals, per unit m|v^-|^2 (x = tau/tau0)."""
    zm = zeta * mu
    x_end = np.minimum(r / zm, 1.0 + kappa)  # slip end in units of tau0

    def G(x):  # integral of -mu (r - zm x) dx from 0 to x
        return -mu * (r * x - 0.5 * zm * x**2)

    wc = G(np.minimum(1.0, x_end))
    wr = G(x_end) - wc
    return wr / wc


def close(actual, expected, scale, rtol=RTOL):
    npt.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.max(scale))


# --------------------------------------------------------------------------
# Body presets
# --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "factory,zeta",
    [
        (Body.solid_disk, 3.0),
        (Body.ring, 2.0),
        (Body.solid_sphere, 3.5),
        (Body.spherical_shell, 2.5),
    ],
)
def test_presets_zeta_and_inertia(factory, zeta):
    b = factory(mass=1.7, radius=0.3)
    # zeta = 1 + R^2/rho^2 evaluated with a square root for rho: rounding only.
    npt.assert_allclose(b.zeta, zeta, rtol=RTOL)
    # J = m rho^2 with rho^2 = R^2/(zeta - 1): rounding only.
    npt.assert_allclose(b.inertia, 1.7 * 0.3**2 / (zeta - 1.0), rtol=RTOL)


def test_custom_body_and_spool():
    b = Body(mass=2.0, radius=0.1, gyration=0.05)
    npt.assert_allclose(b.zeta, 5.0, rtol=RTOL)  # 1 + 0.01/0.0025, rounding only
    npt.assert_allclose(b.inertia, 0.005, rtol=RTOL)
    spool = Body(mass=1.0, radius=0.1, gyration=0.2)  # rho > R is allowed
    npt.assert_allclose(spool.zeta, 1.25, rtol=RTOL)


# --------------------------------------------------------------------------
# 1. Rebound velocities: hand-worked cases (solid disk m=2, R=0.5, J=0.25,
#    zeta=3, mu=0.2, kappa=0.5, so zeta*mu = 0.6, (1+kappa)*zeta*mu = 0.9)
# --------------------------------------------------------------------------
HAND = [
    # name, (vx, vy, omega, mu), regime, (vx+, vy+, omega+), tau0, tau*, tau1, f1, E-, E+
    # |u/v| = 1/4 <= 0.6: stick before tau0. vx+ = 1 - 1/3, omega+ = -2*1/(3*0.5)
    (
        "stick-c",
        (1.0, -4.0, 0.0, 0.2),
        "stick-compression",
        (2 / 3, 2.0, -4 / 3),
        8.0,
        10 / 3,
        12.0,
        -2 / 3,
        17.0,
        14 / 3,
    ),
    # |u/v| = 2/3 in (0.6, 0.9]: stick during restitution, same rebound formula
    (
        "stick-r",
        (1.0, -1.5, 0.0, 0.2),
        "stick-restitution",
        (2 / 3, 0.75, -4 / 3),
        3.0,
        10 / 3,
        4.5,
        -2 / 3,
        3.25,
        0.5625 + 2 / 3,
    ),
    # u = 3 + 0.5*2 = 4, |u/v| = 4 > 0.9: slip; f1 = -mu*tau1 = -0.6
    ("slip", (3.0, -1.0, 2.0, 0.2), "slip", (2.7, 0.5, 0.8), 2.0, 40 / 3, 3.0, -0.6, 10.5, 7.62),
    # mu = 0: tangential state unchanged
    (
        "frictionless",
        (3.0, -1.0, 2.0, 0.0),
        "frictionless",
        (3.0, 0.5, 2.0),
        2.0,
        np.inf,
        3.0,
        0.0,
        10.5,
        9.75,
    ),
    # u = 1 + 0.5*(-2) = 0 exactly: rolling contact, no friction needed
    (
        "no-slip",
        (1.0, -2.0, -2.0, 0.2),
        "no-slip",
        (1.0, 1.0, -2.0),
        4.0,
        0.0,
        6.0,
        0.0,
        5.0 + 0.5,
        1.0 + 1.0 + 0.5,
    ),
    # mirror image of stick-c (u < 0)
    (
        "stick-c-neg",
        (-1.0, -4.0, 0.0, 0.2),
        "stick-compression",
        (-2 / 3, 2.0, 4 / 3),
        8.0,
        10 / 3,
        12.0,
        2 / 3,
        17.0,
        14 / 3,
    ),
]


@pytest.mark.parametrize("case", HAND, ids=[c[0] for c in HAND])
def test_hand_worked_rebound(case):
    _, (vx, vy, om, mu), regime, after, tau0, tstar, tau1, f1, eb, ea = case
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), vx, vy, om, mu=mu, kappa=0.5)
    assert str(imp.regime) == regime
    # hand values are exact rationals; only rounding separates them
    close(imp.after.vx, after[0], 10.0)
    close(imp.after.vy, after[1], 10.0)
    close(imp.after.omega, after[2], 10.0)
    close(imp.before.vx, vx, 10.0)
    close(imp.before.vy, vy, 10.0)
    close(imp.before.omega, om, 10.0)
    close(imp.tau0, tau0, 10.0)
    close(imp.tau1, tau1, 10.0)
    if np.isinf(tstar):
        assert np.isinf(imp.tau_star) and imp.tau_star > 0
    else:
        close(imp.tau_star, tstar, 10.0)
    close(imp.tangential_impulse, f1, 10.0)
    close(imp.kinetic_energy_before, eb, 20.0)
    close(imp.kinetic_energy_after, ea, 20.0)
    close(imp.dissipated_energy, eb - ea, 20.0)
    close(imp.slip_before, vx + 0.5 * om, 10.0)
    close(imp.slip_after, after[0] + 0.5 * after[2], 10.0)


def test_hand_worked_slip_matches_7_11():
    # (7.11): u+ = u^- (1 - (1+kappa) zeta mu / |u/v|) = 4 (1 - 0.9/4) = 3.1
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), 3.0, -1.0, 2.0, mu=0.2, kappa=0.5)
    close(imp.slip_after, 3.1, 10.0)


@pytest.mark.parametrize("name", list(BODIES))
def test_random_cases_against_reference(name):
    m, R, rho = BODIES[name]
    rng = np.random.default_rng(20100519)
    n = 3000
    vx = rng.uniform(-5, 5, n)
    vy = rng.uniform(-5, -0.05, n)
    omega = rng.uniform(-5, 5, n) / R
    mu = rng.uniform(0.01, 1.2, n)
    kappa = rng.uniform(0.0, 1.0, n)
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    # sanity of the test itself: all three friction regimes are sampled
    assert {"stick-compression", "stick-restitution", "slip"} <= set(r.regime.tolist())
    imp = solve(Body(mass=m, radius=R, gyration=rho), vx, vy, omega, mu=mu, kappa=kappa)
    scale = np.abs(vx) + np.abs(vy) + R * np.abs(omega)
    close(imp.after.vx, r.vx, scale)
    close(imp.after.vy, r.vy, scale)
    close(R * np.asarray(imp.after.omega), R * r.omega, scale)
    close(imp.slip_after, r.slip, scale)
    close(imp.tau0, r.tau0, m * scale)
    close(imp.tau1, r.tau1, m * scale)
    close(imp.tau_star, r.tau_star, m * scale / mu.min())
    close(imp.tangential_impulse, r.f1, m * scale)
    assert np.asarray(imp.regime).shape == (n,)
    assert np.asarray(imp.regime).tolist() == r.regime.tolist()


MIXED = dict(  # one element per regime, disk m=2 R=0.5
    vx=np.array([3.0, 1.0, 1.0, 1.0, 3.0]),
    vy=np.array([-1.0, -2.0, -4.0, -1.5, -1.0]),
    omega=np.array([2.0, -2.0, 0.0, 0.0, 2.0]),
    mu=np.array([0.0, 0.2, 0.2, 0.2, 0.2]),
)


def test_regime_array_of_strings():
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), kappa=0.5, **MIXED)
    assert np.asarray(imp.regime).tolist() == [
        "frictionless",
        "no-slip",
        "stick-compression",
        "stick-restitution",
        "slip",
    ]
    # frictionless: tau* = +inf; no-slip: tau* = 0
    assert np.isinf(np.asarray(imp.tau_star)[0])
    assert np.asarray(imp.tau_star)[1] == 0.0


@pytest.mark.parametrize("name", ["disk", "sphere", "spool"])
def test_direct_integration_of_2_7(name):
    """Rebound and phase works against a step-by-step integration of (2.7)."""
    m, R, rho = BODIES[name]
    zeta = 1 + R**2 / rho**2
    mu, kappa, vy = 0.3, 0.7, -2.0
    zm = zeta * mu
    body = Body(mass=m, radius=R, gyration=rho)
    for ratio in (0.0, 0.3 * zm, 1.3 * zm, 1.6 * zm, 3.0 * zm, 8.0 * zm):
        for sgn in (1.0, -1.0):
            vx = 0.4 * sgn * ratio * abs(vy)
            omega = (sgn * ratio * abs(vy) - vx) / R
            it = integrate_impulse(m, R, rho, vx, vy, omega, mu, kappa)
            imp = solve(body, vx, vy, omega, mu=mu, kappa=kappa)
            sc = abs(vx) + abs(vy) + R * abs(omega)
            # the integration accumulates ~130 steps of rounding: 1e-10
            close(imp.after.vx, it.vx, sc, 1e-10)
            close(imp.after.vy, it.vy, sc, 1e-10)
            close(R * imp.after.omega, R * it.omega, sc, 1e-10)
            esc = m * sc**2
            close(imp.work_compression_normal, it.wcn, esc, 1e-10)
            close(imp.work_restitution_normal, it.wrn, esc, 1e-10)
            close(imp.work_compression_tangential, it.wct, esc, 1e-10)
            close(imp.work_restitution_tangential, it.wrt, esc, 1e-10)


@HYP
@given(
    name=st.sampled_from(list(BODIES)),
    vx=st.floats(-10, 10),
    vy=st.floats(-10, -0.01),
    w=st.floats(-10, 10),
    mu=MU,
    kappa=st.floats(0, 1),
)
def test_property_rebound_matches_reference(name, vx, vy, w, mu, kappa):
    m, R, rho = BODIES[name]
    omega = w / R
    imp = solve(make_body(name), vx, vy, omega, mu=mu, kappa=kappa)
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    # the rebound is continuous in the data, so rounding near a regime
    # boundary cannot move it by more than rounding: 1e-11 of the speed scale
    sc = abs(vx) + abs(vy) + abs(w)
    close(imp.after.vx, r.vx, sc, 1e-11)
    close(imp.after.vy, r.vy, sc, 1e-11)
    close(R * imp.after.omega, R * r.omega, sc, 1e-11)


# --------------------------------------------------------------------------
# 2. Classic rolling rebound of a non-spinning body: vx+/vx- = 1 - 1/zeta
# --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "factory,expected",
    [
        (Body.solid_sphere, 5 / 7),
        (Body.solid_disk, 2 / 3),
        (Body.ring, 1 / 2),
        (Body.spherical_shell, 3 / 5),
    ],
)
@pytest.mark.parametrize("vx", [1.3, -0.7])
def test_classic_rolling_ratio(factory, expected, vx):
    body = factory(mass=0.3, radius=0.04)
    # |u/v| = |vx|/5 <= (1+kappa) zeta mu (>= 1.5*2*0.5): ends rolling
    imp = solve(body, vx, -5.0, 0.0, mu=0.5, kappa=0.5)
    assert str(imp.regime).startswith("stick")
    npt.assert_allclose(imp.after.vx / vx, expected, rtol=RTOL)  # rounding only
    # rolling without slip: omega+ = -vx+/R
    npt.assert_allclose(imp.after.omega, -imp.after.vx / 0.04, rtol=RTOL)
    npt.assert_allclose(imp.slip_after, 0.0, atol=RTOL * abs(vx))


# --------------------------------------------------------------------------
# 3. Energy dissipation (5.4), (5.6), (5.10) and energy never increases
# --------------------------------------------------------------------------
def _energy_of(imp, m, J, which):
    s = getattr(imp, which)
    return (
        0.5 * m * (np.asarray(s.vx) ** 2 + np.asarray(s.vy) ** 2)
        + 0.5 * J * np.asarray(s.omega) ** 2
    )


@pytest.mark.parametrize("name", ["disk", "ring", "custom", "spool"])
def test_dissipation_formulas(name):
    m, R, rho = BODIES[name]
    J = m * rho**2
    zeta = 1 + R**2 / rho**2
    rng = np.random.default_rng(7)
    n = 2000
    vx = rng.uniform(-4, 4, n)
    vy = rng.uniform(-4, -0.1, n)
    omega = rng.uniform(-4, 4, n) / R
    mu, kappa = 0.25, 0.6
    imp = solve(Body(mass=m, radius=R, gyration=rho), vx, vy, omega, mu=mu, kappa=kappa)
    eb, ea = _energy_of(imp, m, J, "before"), _energy_of(imp, m, J, "after")
    close(imp.kinetic_energy_before, eb, eb)
    close(imp.kinetic_energy_after, ea, eb)
    # dissipated energy from the velocities; 1e-11: difference of two energies
    close(imp.dissipated_energy, eb - ea, eb, 1e-11)
    r = np.abs((vx + R * omega) / vy)
    half = 0.5 * m * vy**2
    stick = r <= (1 + kappa) * zeta * mu
    assert stick.any() and (~stick).any()
    de_stick = half * (1 - kappa**2 + r**2 / zeta)  # (5.4)
    de_slip = half * (1 + kappa) * (1 - kappa + mu * (2 * r - (1 + kappa) * zeta * mu))  # (5.6)
    close(np.asarray(imp.dissipated_energy)[stick], de_stick[stick], eb, 1e-11)
    close(np.asarray(imp.dissipated_energy)[~stick], de_slip[~stick], eb, 1e-11)
    # (5.10): Delta E = -f1 (u- + u+)/2 - tau1 (v- + v+)/2
    de_510 = -0.5 * np.asarray(imp.tangential_impulse) * (
        np.asarray(imp.slip_before) + np.asarray(imp.slip_after)
    ) - 0.5 * np.asarray(imp.tau1) * (vy + np.asarray(imp.after.vy))
    close(imp.dissipated_energy, de_510, eb, 1e-11)


@HYP
@given(
    name=st.sampled_from(list(BODIES)),
    vx=st.floats(-10, 10),
    vy=st.floats(-10, -0.01),
    w=st.floats(-10, 10),
    mu=MU,
    kappa=st.floats(0, 1),
)
def test_property_energy_never_increases(name, vx, vy, w, mu, kappa):
    m, R, rho = BODIES[name]
    imp = solve(make_body(name), vx, vy, w / R, mu=mu, kappa=kappa)
    eb = float(imp.kinetic_energy_before)
    # >= 0 up to rounding of the energy scale
    assert float(imp.dissipated_energy) >= -1e-12 * eb
    assert float(imp.kinetic_energy_after) <= eb * (1 + 1e-12)
    # E^- + W_c + W_r = E^+ (section 6); 1e-11: sums of several energy terms
    w_tot = (
        imp.work_compression_normal
        + imp.work_compression_tangential
        + imp.work_restitution_normal
        + imp.work_restitution_tangential
    )
    close(-w_tot, imp.dissipated_energy, eb, 1e-11)
    # W_c < 0 always (6.1 and section 6.1)
    assert imp.work_compression_normal + imp.work_compression_tangential < 0


# --------------------------------------------------------------------------
# 4. Restitution coefficients (section 3): Newton = Poisson = Stronge = kappa
# --------------------------------------------------------------------------
@pytest.mark.parametrize("kappa", [0.0, 0.1, 0.5, 0.93, 1.0])
def test_three_restitution_coefficients_equal_kappa(kappa):
    body = Body.solid_disk(mass=2.0, radius=0.5)
    imp = solve(body, MIXED["vx"], MIXED["vy"], MIXED["omega"], mu=MIXED["mu"], kappa=kappa)
    # each is a ratio of rounded quantities: rounding only (atol for kappa = 0)
    for c in (imp.newton_restitution, imp.poisson_restitution, imp.energetic_restitution):
        npt.assert_allclose(c, kappa, rtol=1e-12, atol=1e-12)
    # Newton's kinematic definition from the velocities, Poisson's from impulses
    npt.assert_allclose(-imp.after.vy / imp.before.vy, kappa, rtol=1e-12, atol=1e-12)
    npt.assert_allclose(imp.tau1 / imp.tau0 - 1, kappa, rtol=1e-12, atol=1e-12)
    # Stronge: eta^2 = -W_r^n/W_c^n (6.5)
    npt.assert_allclose(
        -imp.work_restitution_normal / imp.work_compression_normal,
        kappa**2,
        rtol=1e-12,
        atol=1e-12,
    )


# --------------------------------------------------------------------------
# 5. Works by phase (section 6) and W_r^t / W_c^t (6.15)-(6.19)
# --------------------------------------------------------------------------
HAND_WORKS = [
    # (vx, vy, omega): Wc^t, Wr^t derived by hand from g(t) = -mu(|u|t - zeta mu t^2/(2m))
    ((1.0, -4.0, 0.0), -1 / 3, 0.0),  # stick before tau0: -mu tau* |u| /2
    ((1.0, -1.5, 0.0), -0.33, -1 / 300),  # g(3) = -0.33, g(10/3) = -1/3
    ((3.0, -1.0, 2.0), -1.48, -0.65),  # g(2) = -1.48, g(3) = -2.13
]


@pytest.mark.parametrize("case", HAND_WORKS)
def test_hand_worked_works(case):
    (vx, vy, om), wct, wrt = case
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), vx, vy, om, mu=0.2, kappa=0.5)
    close(imp.work_compression_normal, -0.5 * 2.0 * vy**2, 20.0)  # -m v^2/2
    close(imp.work_restitution_normal, 0.25 * 0.5 * 2.0 * vy**2, 20.0)  # kappa^2 m v^2/2
    close(imp.work_compression_tangential, wct, 20.0)
    close(imp.work_restitution_tangential, wrt, 20.0)


@pytest.mark.parametrize("name", ["disk", "shell", "custom"])
def test_works_random_against_reference(name):
    m, R, rho = BODIES[name]
    rng = np.random.default_rng(99)
    n = 2000
    vx = rng.uniform(-4, 4, n)
    vy = rng.uniform(-4, -0.1, n)
    omega = rng.uniform(-4, 4, n) / R
    mu = rng.uniform(0.05, 1.0, n)
    kappa = rng.uniform(0, 1, n)
    imp = solve(Body(mass=m, radius=R, gyration=rho), vx, vy, omega, mu=mu, kappa=kappa)
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    esc = r.e_before
    close(imp.work_compression_normal, r.wcn, esc)
    close(imp.work_restitution_normal, r.wrn, esc)
    close(imp.work_compression_tangential, r.wct, esc, 1e-11)
    close(imp.work_restitution_tangential, r.wrt, esc, 1e-11)
    # normalized form of W_c^n and W_r^n: -m v^2/2 and kappa^2 m v^2/2
    close(imp.work_compression_normal, -0.5 * m * vy**2, esc)
    close(imp.work_restitution_normal, 0.5 * kappa**2 * m * vy**2, esc)


@pytest.mark.parametrize("kappa,expected", [(1.0, 1 / 3), (0.5, 1 / 8), (0.1, 1 / 120)])
@pytest.mark.parametrize("zeta,mu", [(3.0, 0.2), (3.5, 0.45), (1.25, 1.0)])
def test_work_ratio_worked_values(kappa, expected, zeta, mu):
    # paper, after (6.17): at |u/v| = (1+kappa) zeta mu the ratio is kappa^2/(1+2kappa)
    ratio = (1 + kappa) * zeta * mu
    npt.assert_allclose(core.work_ratio_tangential(ratio, zeta, mu, kappa), expected, rtol=1e-12)
    npt.assert_allclose(ref_work_ratio(ratio, zeta, mu, kappa), expected, rtol=1e-12)


def test_work_ratio_piecewise_forms_and_bounds():
    zeta, mu = 3.0, 0.3
    zm = zeta * mu
    for kappa in (0.0, 0.2, 0.6, 1.0):
        r = np.concatenate(
            [
                np.linspace(1e-3, zm, 50),
                np.linspace(zm, (1 + kappa) * zm, 50),
                np.linspace((1 + kappa) * zm, 60 * zm, 50),
            ]
        )
        got = np.asarray(core.work_ratio_tangential(r, zeta, mu, kappa))
        assert got.shape == r.shape
        # against the integrals, rounding only
        npt.assert_allclose(got, ref_work_ratio(r, zeta, mu, kappa), rtol=1e-11, atol=1e-13)
        lo, mid, hi = got[:50], got[50:100], got[100:]
        npt.assert_allclose(lo, 0.0, atol=1e-13)  # (6.15)
        up = kappa**2 / (1 + 2 * kappa)
        assert np.all(mid >= -1e-13) and np.all(mid <= up + 1e-13)  # (6.17)
        assert np.all(hi >= up - 1e-13) and np.all(hi <= kappa + 1e-13)  # (6.19)
        # (6.16) and (6.18) printed forms agree with the integrals
        r2, r3 = r[50:100], r[100:]
        npt.assert_allclose(mid, r2**2 / (zm * (2 * r2 - zm)) - 1, rtol=1e-10, atol=1e-12)
        npt.assert_allclose(hi, kappa * (1 - (1 + kappa) * zm / (2 * r3 - zm)), rtol=1e-11)
        # W_r^t < W_c^t in magnitude for kappa < 1 (the paper's claim)
        if kappa < 1:
            assert np.all(got < 1)


@HYP
@given(
    name=st.sampled_from(list(BODIES)),
    vx=st.floats(-10, 10),
    vy=st.floats(-10, -0.01),
    w=st.floats(-10, 10),
    mu=st.floats(0.01, 1.5),
    kappa=st.floats(0, 1),
)
def test_property_solve_work_ratio_matches_core(name, vx, vy, w, mu, kappa):
    m, R, rho = BODIES[name]
    zeta = 1 + R**2 / rho**2
    imp = solve(make_body(name), vx, vy, w / R, mu=mu, kappa=kappa)
    wct = float(imp.work_compression_tangential)
    u = vx + w  # R*omega = w
    if abs(u) < 1e-6 * (abs(vx) + abs(w) + abs(vy)):
        return  # no slip: both works vanish, ratio undefined
    ratio = abs(u / vy)
    expected = ref_work_ratio(ratio, zeta, mu, kappa)
    got = float(imp.work_restitution_tangential) / wct
    # ratio of two works each accurate to rounding of E^-; wct can be small
    tol = 1e-10 * float(imp.kinetic_energy_before) / abs(wct)
    npt.assert_allclose(got, expected, rtol=0, atol=max(tol, 1e-12))
    npt.assert_allclose(
        core.work_ratio_tangential(ratio, zeta, mu, kappa), expected, rtol=1e-10, atol=1e-12
    )
    up = kappa**2 / (1 + 2 * kappa)
    zm = zeta * mu
    if ratio <= zm * (1 - 1e-9):
        assert abs(expected) < 1e-12
    elif ratio <= (1 + kappa) * zm:
        assert -1e-12 <= expected <= up + 1e-9
    else:
        assert up - 1e-9 <= expected <= kappa + 1e-12


def test_restitution_work_sign_6_12_6_13():
    # (6.12): W_r > 0 for |u/v| <= zeta mu (kappa > 0)
    body = Body.solid_disk(mass=1.0, radius=1.0)  # zeta = 3
    imp = solve(body, 0.5, -1.0, 0.0, mu=0.4, kappa=0.3)  # r = 0.5 <= 1.2
    assert imp.work_restitution_normal + imp.work_restitution_tangential > 0
    # (6.13) with zeta mu^2 = 3 >= 1: mu = 1, kappa = 0.5, zeta mu = 3, switch at
    # zeta mu + sqrt(zeta) kappa = 3.866, interval end (1+kappa) zeta mu = 4.5
    pos = solve(body, 3.5, -1.0, 0.0, mu=1.0, kappa=0.5)
    neg = solve(body, 4.2, -1.0, 0.0, mu=1.0, kappa=0.5)
    assert str(pos.regime) == str(neg.regime) == "stick-restitution"
    # derived: W_r / (m v^2/2) = kappa^2 - (r - zeta mu)^2 / zeta
    for imp, r in ((pos, 3.5), (neg, 4.2)):
        w_r = imp.work_restitution_normal + imp.work_restitution_tangential
        close(w_r, 0.5 * (0.25 - (r - 3.0) ** 2 / 3.0), 10.0)
    assert pos.work_restitution_normal + pos.work_restitution_tangential > 0
    assert neg.work_restitution_normal + neg.work_restitution_tangential < 0


def test_restitution_work_sign_6_14_print_is_wrong():
    """Eq. (6.14), second line, is wrong as printed.

    Printed: W_r >= 0 for every |u/v| >= (1+kappa) zeta mu when zeta mu^2 <= 1.
    Derived (slip throughout): W_r / (m v^2/2)
        = kappa^2 + kappa zeta mu^2 (2 + kappa - 2 |u/v| / (zeta mu)),
    which decreases in |u/v| and is negative for
        |u/v| > [kappa + zeta mu^2 (2 + kappa)] / (2 mu).
    Disk (zeta 3), mu = 0.2 (zeta mu^2 = 0.12 <= 1), kappa = 0.5, m = 2, v = -1,
    |u/v| = 5:  W_r = 0.25 + 0.06 (2.5 - 16.667) = -0.6  (hand: W_r^n = 0.25,
    W_r^t = g(3) - g(2) = -2.13 + 1.48 = -0.65 ... see HAND_WORKS for g).
    """
    body = Body.solid_disk(mass=2.0, radius=0.5)
    imp = solve(body, 5.0, -1.0, 0.0, mu=0.2, kappa=0.5)
    assert str(imp.regime) == "slip"
    w_r = imp.work_restitution_normal + imp.work_restitution_tangential
    close(w_r, -0.6, 10.0)  # exact rational, rounding only
    assert w_r < 0  # the printed (6.14) would claim W_r >= 0 here
    # derived sign switch at |u/v| = (0.5 + 0.12*2.5)/0.4 = 2.0
    for r, sign in ((1.5, 1), (2.5, -1)):
        imp = solve(body, r, -1.0, 0.0, mu=0.2, kappa=0.5)
        w_r = imp.work_restitution_normal + imp.work_restitution_tangential
        close(w_r, 0.25 + 0.06 * (2.5 - 2 * r / 0.6), 10.0)
        assert np.sign(w_r) == sign
    # first line of (6.14) (zeta mu^2 >= 1 -> W_r <= 0) holds: mu = 0.7
    for r in (3.0, 5.0, 20.0):  # (1+kappa) zeta mu = 3.15 with kappa = 0.5
        imp = solve(body, r + 0.2, -1.0, 0.0, mu=0.7, kappa=0.5)
        assert imp.work_restitution_normal + imp.work_restitution_tangential <= 0


# --------------------------------------------------------------------------
# 6. Tangential impact coefficient mu_hat (7.4)-(7.11)
# --------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["disk", "sphere", "ring", "spool"])
def test_mu_hat_forms(name):
    m, R, rho = BODIES[name]
    zeta = 1 + R**2 / rho**2
    rng = np.random.default_rng(3)
    n = 2000
    vx = rng.uniform(-3, 3, n)
    vy = rng.uniform(-3, -0.1, n)
    omega = rng.uniform(-3, 3, n) / R
    mu = rng.uniform(0.05, 1.0, n)
    kappa = rng.uniform(0, 1, n)
    imp = solve(Body(mass=m, radius=R, gyration=rho), vx, vy, omega, mu=mu, kappa=kappa)
    u = vx + R * omega
    r = np.abs(u / vy)
    mh = np.asarray(imp.impulse_ratio)
    # (7.4): mu_hat = f1/tau1; rounding only
    close(mh, np.asarray(imp.tangential_impulse) / np.asarray(imp.tau1), mu)
    stick = r <= (1 + kappa) * zeta * mu
    assert stick.any() and (~stick).any()
    # (7.8): mu_hat = u^-/((1+kappa) zeta v^-)  (stick),  (7.9): -mu sign(u^-)  (slip)
    close(mh[stick], (u / ((1 + kappa) * zeta * vy))[stick], mu)
    close(mh[~stick], (-mu * np.sign(u))[~stick], mu)
    # identity from the impulse equations: mu_hat = (u+ - u-)/(zeta (1+kappa)|v-|)
    ident = (np.asarray(imp.slip_after) - u) / (zeta * (1 + kappa) * np.abs(vy))
    close(mh, ident, mu, 1e-11)
    # (7.5): mu_hat = (vx+ - vx-)/(vy+ - vy-)
    close(mh, (np.asarray(imp.after.vx) - vx) / (np.asarray(imp.after.vy) - vy), mu, 1e-11)
    # bound -mu <= mu_hat <= mu
    assert np.all(np.abs(mh) <= mu * (1 + 1e-12))


def test_mu_hat_printed_7_10_is_wrong():
    """Eq. (7.10) as printed, mu_hat = -mu|u^-|/(u^- - u^+), disagrees with (7.4)."""
    body = Body.solid_disk(mass=2.0, radius=0.5)
    # stick case: mu_hat = f1/tau1 = (-2/3)/12 = -1/18; printed (7.10) gives -mu = -0.2
    imp = solve(body, 1.0, -4.0, 0.0, mu=0.2, kappa=0.5)
    close(imp.impulse_ratio, -1 / 18, 1.0)
    printed = -0.2 * abs(imp.slip_before) / (imp.slip_before - imp.slip_after)
    assert abs(printed - imp.impulse_ratio) > 0.1
    # slip case: mu_hat = -mu = -0.2; printed gives -0.2*4/0.9 = -0.889
    imp = solve(body, 3.0, -1.0, 2.0, mu=0.2, kappa=0.5)
    close(imp.impulse_ratio, -0.2, 1.0)
    printed = -0.2 * abs(imp.slip_before) / (imp.slip_before - imp.slip_after)
    assert abs(printed - imp.impulse_ratio) > 0.5


@HYP
@given(
    name=st.sampled_from(list(BODIES)),
    vx=st.floats(-10, 10),
    vy=st.floats(-10, -0.01),
    w=st.floats(-10, 10),
    mu=MU,
    kappa=st.floats(0, 1),
)
def test_property_mu_hat_bounded(name, vx, vy, w, mu, kappa):
    m, R, rho = BODIES[name]
    zeta = 1 + R**2 / rho**2
    imp = solve(make_body(name), vx, vy, w / R, mu=mu, kappa=kappa)
    assert abs(float(imp.impulse_ratio)) <= mu * (1 + 1e-12) + 1e-300
    ident = (float(imp.slip_after) - float(imp.slip_before)) / (zeta * (1 + kappa) * abs(vy))
    # slip velocities carry rounding of the speed scale, divided by |v|
    tol = 1e-11 * (abs(vx) + abs(w) + abs(vy)) / abs(vy)
    npt.assert_allclose(float(imp.impulse_ratio), ident, rtol=0, atol=tol)


# --------------------------------------------------------------------------
# 7. Minimum kinetic energy, Fig. 5, (8.2)-(8.6)
# --------------------------------------------------------------------------
def brute_min(m, R, rho, vx, vy, omega, mu, kappa, n=400_001):
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    tau = np.linspace(0.0, float(r.tau1), n)
    E = ref_state(m, R, rho, vx, vy, omega, mu, kappa, tau).E
    i = int(np.argmin(E))
    return E[i], tau[i], tau[1] - tau[0], r


MINCASES = [
    # disk m=2 R=0.5 mu=0.2 kappa=0.5, zeta mu = 0.6, (1+k) zeta mu = 0.9,
    # (8.5) upper end kappa/mu + (1+kappa) zeta mu = 3.4
    ("5b stick before tau0", (1.0, -4.0, 0.0), "b"),
    ("5a stick during restitution", (1.0, -1.5, 0.0), "a"),
    ("5c slip, tau_m < tau1", (2.0, -1.0, 0.0), "c"),
    ("slip beyond tau1", (3.0, -1.0, 2.0), "end"),
    ("no-slip", (1.0, -2.0, -2.0), "b"),
]


@pytest.mark.parametrize("case", MINCASES, ids=[c[0] for c in MINCASES])
def test_min_kinetic_energy_cases(case):
    _, (vx, vy, om), kind = case
    m, R, rho = 2.0, 0.5, 0.5 / math.sqrt(2)
    mu, kappa, zeta = 0.2, 0.5, 3.0
    imp = solve(Body.solid_disk(mass=m, radius=R), vx, vy, om, mu=mu, kappa=kappa)
    e_bf, t_bf, h, r = brute_min(m, R, rho, vx, vy, om, mu, kappa)
    eb = float(imp.kinetic_energy_before)
    # brute-force grid min exceeds the true min by <= E'' h^2/2 ~ 1e-11 E^-
    assert float(imp.min_kinetic_energy) <= e_bf + 1e-12 * eb
    npt.assert_allclose(imp.min_kinetic_energy, e_bf, rtol=0, atol=1e-9 * eb)
    # strictly convex E: grid argmin within one grid step (plus rounding ties)
    npt.assert_allclose(imp.tau_min_energy, t_bf, rtol=0, atol=2 * h)
    ratio = abs((vx + R * om) / vy)
    half = 0.5 * m * vy**2
    tau0, tau1 = m * abs(vy), (1 + kappa) * m * abs(vy)
    tau_m_82 = m * (abs(vy) + mu * abs(vx + R * om)) / (1 + zeta * mu**2)  # (8.2)
    e_84 = eb - half * (1 + mu * ratio) ** 2 / (1 + zeta * mu**2)  # (8.4)
    e_86 = eb - half * (1 + ratio**2 / zeta)  # (8.6)
    if kind == "b":  # Fig. 5b: tau_m = tau0, (8.6)
        close(imp.tau_min_energy, tau0, tau1)
        close(imp.min_kinetic_energy, e_86, eb)
    elif kind in ("a", "c"):  # Fig. 5a / 5c: tau0 < tau_m = (8.2) < min(tau*, tau1), (8.4)
        close(imp.tau_min_energy, tau_m_82, tau1)
        close(imp.min_kinetic_energy, e_84, eb)
        assert tau0 < float(imp.tau_min_energy) < min(float(imp.tau_star), tau1)
    else:
        # Slip continues to the end and the would-be tau_m (8.2) = 3.214 exceeds
        # tau1 = 3 (|u/v| = 4 > 3.4, outside (8.5)): E decreases throughout the
        # impact; the minimum is the rebound energy at tau1 and (8.4) is NOT
        # attained (it lies below the true minimum).
        assert tau_m_82 > tau1
        close(imp.tau_min_energy, tau1, tau1)
        close(imp.min_kinetic_energy, imp.kinetic_energy_after, eb)
        assert float(imp.min_kinetic_energy) > e_84 + 1e-3
    # hand values: case 5b (1,-4,0): E_m = 2/3; case 5a (1,-1.5,0): 0.669643;
    # case 5c (2,-1,0): tau_m = 2.5, E_m = 3.25; slip beyond: E_m = E+ = 7.62
    hand = {(1.0, -4.0, 0.0): 2 / 3, (2.0, -1.0, 0.0): 3.25, (3.0, -1.0, 2.0): 7.62}
    if (vx, vy, om) in hand:
        close(imp.min_kinetic_energy, hand[(vx, vy, om)], eb)


@pytest.mark.parametrize("name", ["disk", "sphere", "custom"])
def test_min_kinetic_energy_random_against_reference(name):
    m, R, rho = BODIES[name]
    rng = np.random.default_rng(11)
    n = 2000
    vx = rng.uniform(-4, 4, n)
    vy = rng.uniform(-4, -0.1, n)
    omega = rng.uniform(-4, 4, n) / R
    mu = rng.uniform(0.0, 1.0, n)
    kappa = rng.uniform(0, 1, n)
    imp = solve(Body(mass=m, radius=R, gyration=rho), vx, vy, omega, mu=mu, kappa=kappa)
    r = ref(m, R, rho, vx, vy, omega, mu, kappa)
    close(imp.min_kinetic_energy, r.e_min, r.e_before, 1e-11)
    close(imp.tau_min_energy, r.tau_m, r.tau1, 1e-11)
    # the minimum is never above the incidence, compression-end or rebound energy
    e_min = np.asarray(imp.min_kinetic_energy)
    assert np.all(e_min <= np.asarray(imp.kinetic_energy_after) + 1e-12 * r.e_before)
    # brute force on a coarse grid for a subset
    for i in range(0, n, 250):
        e_bf, t_bf, h, _ = brute_min(m, R, rho, vx[i], vy[i], omega[i], mu[i], kappa[i], 20_001)
        assert e_min[i] <= e_bf + 1e-12 * r.e_before[i]
        # coarse-grid min exceeds true min by <= E''h^2/2 <= ~1e-8 E^-
        npt.assert_allclose(e_min[i], e_bf, rtol=0, atol=1e-7 * r.e_before[i])


def test_frictionless_min_energy_and_mu_hat():
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), 3.0, -1.0, 2.0, mu=0.0, kappa=0.5)
    close(imp.tau_min_energy, 2.0, 3.0)  # tau0
    close(imp.min_kinetic_energy, 10.5 - 1.0, 10.5)  # E^- - m v^2/2
    assert float(imp.impulse_ratio) == 0.0
    assert float(imp.tangential_impulse) == 0.0


# --------------------------------------------------------------------------
# 8. Particle model (Whittaker, end of section 8, eq. 8.7)
# --------------------------------------------------------------------------
def test_particle_threshold_worked_example():
    # derived: E+ - E- <= 0  <=>  |u|/|v| >= [(1+kappa) mu^2 + kappa - 1]/(2 mu)
    # mu = 0.5, kappa = 0.8: (0.45 - 0.2)/1 = 0.25; atan(0.25) = 14.04 deg
    thr = core.particle_energy_threshold(0.5, 0.8)
    npt.assert_allclose(thr, 0.25, rtol=1e-12)
    assert abs(math.degrees(math.atan(thr)) - 14.0) < 0.1
    npt.assert_allclose(
        core.particle_energy_threshold(0.3, 0.9), (1.9 * 0.09 - 0.1) / 0.6, rtol=1e-12
    )


@pytest.mark.parametrize("ratio,sign", [(0.1, 1), (0.2, 1), (0.3, -1), (0.5, -1), (2.0, -1)])
@pytest.mark.parametrize("direction", [1.0, -1.0])
def test_particle_energy_direction(ratio, sign, direction):
    """Energy is CREATED for u/|v| < 0.25 (near-normal incidence).

    The paper's sentence after (8.7) says "energy increase would occur if
    u/|v| > 0.25, i.e. incidence angle greater than about 14 deg": the
    inequality is reversed there; (8.7) itself gives the opposite.
    """
    mu, kappa, m, vy = 0.5, 0.8, 1.3, -2.0
    vx = direction * ratio * abs(vy)
    p = solve_particle(vx, vy, mu=mu, kappa=kappa, mass=m)
    # Whittaker: f1 = -mu sign(u) tau1, tau1 = (1+kappa) m |v|
    vx_p = vx - mu * np.sign(vx) * (1 + kappa) * abs(vy)
    close(p.after.vx, vx_p, 5.0)
    close(p.after.vy, -kappa * vy, 5.0)
    de = 0.5 * m * (vx_p**2 + (kappa * vy) ** 2) - 0.5 * m * (vx**2 + vy**2)
    close(p.energy_change, de, 10.0)
    # (8.7) with u^- replaced by |u^-| for either direction
    e87 = 0.5 * m * vy**2 * (1 + kappa) * (kappa - 1 + (1 + kappa) * mu**2 - 2 * mu * ratio)
    close(p.energy_change, e87, 10.0)
    assert np.sign(float(p.energy_change)) == sign


def test_particle_broadcast():
    vx = np.array([0.1, 0.3, 1.0])
    p = solve_particle(vx, -1.0, mu=0.5, kappa=0.8, mass=1.0)
    assert np.shape(p.after.vx) == (3,)
    close(p.after.vx, vx - 0.9, 2.0)


# --------------------------------------------------------------------------
# 9. Broadcasting
# --------------------------------------------------------------------------
FIELDS = [
    "tau0",
    "tau_star",
    "tau1",
    "tangential_impulse",
    "impulse_ratio",
    "kinetic_energy_before",
    "kinetic_energy_after",
    "dissipated_energy",
    "work_compression_normal",
    "work_compression_tangential",
    "work_restitution_normal",
    "work_restitution_tangential",
    "min_kinetic_energy",
    "tau_min_energy",
    "newton_restitution",
    "poisson_restitution",
    "energetic_restitution",
    "slip_before",
    "slip_after",
]


def _all_fields(imp):
    out = {f: getattr(imp, f) for f in FIELDS}
    for part in ("before", "after"):
        for c in ("vx", "vy", "omega"):
            out[f"{part}.{c}"] = getattr(getattr(imp, part), c)
    for c in ("backward", "reversed_spin", "vertical", "spinning"):
        out[f"outcome.{c}"] = getattr(imp.outcome, c)
    out["regime"] = imp.regime
    return out


def test_broadcasting_shapes_and_values():
    body = Body.solid_sphere(mass=0.45, radius=0.11)
    vx = np.array([[-2.0], [0.5], [3.0]])  # (3, 1)
    omega = np.array([-30.0, -4.0, 0.0, 25.0])  # (4,)
    mu = np.array([0.1, 0.3, 0.0, 0.6])  # (4,)
    imp = solve(body, vx, -2.5, omega, mu=mu, kappa=0.7)
    fields = _all_fields(imp)
    for k, v in fields.items():
        assert np.shape(v) == (3, 4), k
    for i in range(3):
        for j in range(4):
            one = _all_fields(solve(body, vx[i, 0], -2.5, omega[j], mu=mu[j], kappa=0.7))
            for k, v in one.items():
                a, b = np.asarray(fields[k])[i, j], np.asarray(v)
                if k == "regime" or k.startswith("outcome"):
                    assert a == b, k
                else:
                    # same arithmetic, element by element: rounding only
                    npt.assert_allclose(a, b, rtol=1e-13, atol=1e-12, err_msg=k)


def test_scalar_inputs_give_scalar_fields():
    imp = solve(Body.solid_disk(mass=1.0, radius=0.2), 1.0, -2.0, 3.0, mu=0.3, kappa=0.6)
    for k, v in _all_fields(imp).items():
        assert np.shape(v) == (), k
    assert isinstance(imp.regime, str)


# --------------------------------------------------------------------------
# 10. history()
# --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "args",
    [
        (1.0, -1.5, 0.0, 0.2),  # stick during restitution
        (1.0, -4.0, 0.0, 0.2),  # stick during compression
        (-1.0, -1.5, 0.0, 0.2),  # u < 0
        (3.0, -1.0, 2.0, 0.2),  # slip throughout
        (2.0, -1.0, 0.0, 0.2),  # slip, interior energy minimum
        (3.0, -1.0, 2.0, 0.0),  # frictionless
    ],
)
def test_history(args):
    vx, vy, om, mu = args
    m, R, rho, kappa = 2.0, 0.5, 0.5 / math.sqrt(2), 0.5
    imp = solve(Body.solid_disk(mass=m, radius=R), vx, vy, om, mu=mu, kappa=kappa)
    h = imp.history(n=201)
    # The contract does not say "exactly n points"; an implementation may add
    # the breakpoints tau0 and tau* to the grid.  Require >= n, one common shape.
    npts = np.shape(h.tau)[0]
    assert npts >= 201
    for name in (
        "tau",
        "vx",
        "vy",
        "omega",
        "slip",
        "force_ratio",
        "tangential_impulse",
        "kinetic_energy",
    ):
        assert np.shape(getattr(h, name)) == (npts,), name
    tau = np.asarray(h.tau)
    tau1 = float(imp.tau1)
    assert tau[0] == 0.0
    close(tau[-1], tau1, tau1)
    assert np.all(np.diff(tau) >= 0)
    sc = 10.0
    # first point = incidence, last point = rebound (rounding only)
    for c in ("vx", "vy", "omega"):
        close(np.asarray(getattr(h, c))[0], getattr(imp.before, c), sc)
        close(np.asarray(getattr(h, c))[-1], getattr(imp.after, c), sc)
    close(np.asarray(h.slip)[-1], imp.slip_after, sc)
    close(np.asarray(h.tangential_impulse)[-1], imp.tangential_impulse, sc)
    close(np.asarray(h.kinetic_energy)[0], imp.kinetic_energy_before, 20.0)
    close(np.asarray(h.kinetic_energy)[-1], imp.kinetic_energy_after, 20.0)
    # whole curves against the derived state (3.1), (4.2), (4.7), (4.11), (4.12), (7.2)
    st_ = ref_state(m, R, rho, vx, vy, om, mu, kappa, tau)
    close(h.vx, st_.vx, sc)
    close(h.vy, st_.vy, sc)
    close(h.omega, st_.omega, sc)
    close(h.slip, st_.slip, sc)
    close(h.slip, np.asarray(h.vx) + R * np.asarray(h.omega), sc)
    close(h.tangential_impulse, st_.f, sc)
    close(h.kinetic_energy, st_.E, 20.0)
    # Coulomb law along the process: F/N = -mu sign(u^-) before tau*, 0 after
    ts = float(imp.tau_star)
    fr = np.asarray(h.force_ratio)
    u0 = vx + R * om
    before = tau < ts * (1 - 1e-9)
    after = tau > ts * (1 + 1e-9)
    # the force ratio is a constant, not a computed difference: 1e-14 rounding
    npt.assert_allclose(fr[before], -mu * np.sign(u0), rtol=1e-14, atol=0)
    npt.assert_allclose(fr[after], 0.0, rtol=0, atol=1e-14)
    npt.assert_allclose(np.asarray(h.slip)[after], 0.0, atol=RTOL * sc)
    # slip keeps the sign of u^- before tau* (unidirectional, no reversal)
    assert np.all(np.asarray(h.slip)[before] * np.sign(u0) > 0) or mu == 0.0
    # the sampled energy never drops below the reported minimum
    assert np.min(h.kinetic_energy) >= float(imp.min_kinetic_energy) - 1e-12 * 20.0


def test_history_fine_grid_reaches_minimum():
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), 2.0, -1.0, 0.0, mu=0.2, kappa=0.5)
    h = imp.history(n=30_001)
    # grid spacing 1e-4 in tau; E'' = (1+zeta mu^2)/m = 0.56: error <= 3e-9
    npt.assert_allclose(np.min(h.kinetic_energy), imp.min_kinetic_energy, atol=1e-8)
    npt.assert_allclose(np.asarray(h.tau)[np.argmin(h.kinetic_energy)], 2.5, atol=2e-4)


# --------------------------------------------------------------------------
# 11. Continuity across |u/v| = zeta mu, (1+kappa) zeta mu and the (8.5) end
# --------------------------------------------------------------------------
CONT_FIELDS = [
    "after.vx",
    "after.vy",
    "after.omega",
    "slip_after",
    "tangential_impulse",
    "impulse_ratio",
    "dissipated_energy",
    "kinetic_energy_after",
    "work_compression_tangential",
    "work_restitution_tangential",
    "min_kinetic_energy",
    "tau_min_energy",
    "tau_star",
]


@pytest.mark.parametrize("name", ["disk", "sphere", "spool"])
@pytest.mark.parametrize("boundary", ["zeta_mu", "one_plus_kappa", "eq_8_5"])
@pytest.mark.parametrize("sgn", [1.0, -1.0])
def test_continuity_across_boundaries(name, boundary, sgn):
    m, R, rho = BODIES[name]
    zeta = 1 + R**2 / rho**2
    mu, kappa, vy = 0.3, 0.6, -2.0
    zm = zeta * mu
    rb = {
        "zeta_mu": zm,
        "one_plus_kappa": (1 + kappa) * zm,
        "eq_8_5": kappa / mu + (1 + kappa) * zm,  # = [(1+k)(1+zeta mu^2)-1]/mu
    }[boundary]
    body = Body(mass=m, radius=R, gyration=rho)
    eps = 1e-9
    sides = []
    for f in (1 - eps, 1 + eps):
        u = sgn * rb * f * abs(vy)
        vx = 0.3 * u
        sides.append(solve(body, vx, vy, (u - vx) / R, mu=mu, kappa=kappa))
    lo, hi = sides
    expected_regimes = {
        "zeta_mu": ("stick-compression", "stick-restitution"),
        "one_plus_kappa": ("stick-restitution", "slip"),
        "eq_8_5": ("slip", "slip"),
    }[boundary]
    assert (str(lo.regime), str(hi.regime)) == expected_regimes
    for k in CONT_FIELDS:
        a = lo
        b = hi
        for part in k.split("."):
            a, b = getattr(a, part), getattr(b, part)
        scale = float(hi.kinetic_energy_before) + float(hi.tau1) + 10.0
        if k.endswith("omega"):
            scale /= R
        # the two sides differ in the data by a relative 2e-9; a continuous
        # field moves by O(1e-9 * scale); a jump would be O(scale)
        npt.assert_allclose(float(a), float(b), rtol=0, atol=1e-7 * scale, err_msg=k)
    if boundary == "eq_8_5":
        # the minimum reaches the end of the impact exactly at the (8.5) bound
        npt.assert_allclose(float(hi.tau_min_energy), float(hi.tau1), rtol=1e-7)


# --------------------------------------------------------------------------
# Outcomes (end of section 4)
# --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "args,expected",
    [
        # backspin: u = 1 + 0.5*6 = 4, r = 0.4, stick: vx+ = 1 - 4/3 = -1/3, omega+ = 2/3
        (
            (1.0, -10.0, 6.0, 0.2),
            dict(backward=True, reversed_spin=False, vertical=False, spinning=True),
        ),
        # topspin-like: vx = 2, omega = 1, u = 2.5, r = 0.5: vx+ = 7/6, omega+ = -7/3
        (
            (2.0, -5.0, 1.0, 0.2),
            dict(backward=False, reversed_spin=True, vertical=False, spinning=True),
        ),
        # slip with mu=0.25, kappa=0.5, vy=-2: vx+ = 0.75 - 0.25*3 = 0, omega+ = 6 - 3 = 3
        # (backward is not asserted: vx+ is 0 only up to rounding)
        ((0.75, -2.0, 6.0, 0.25), dict(reversed_spin=False, vertical=True, spinning=True)),
        # stick with vx = u/zeta: vx+ = 0 and omega+ = 0 (vertical, non-spinning);
        # backward / reversed_spin not asserted: both rebound values are 0 +- rounding
        ((1.0, -10.0, 4.0, 0.2), dict(vertical=True, spinning=False)),
        # vertical drop, no spin: nothing changes sign, no horizontal motion
        (
            (0.0, -3.0, 0.0, 0.2),
            dict(backward=False, reversed_spin=False, vertical=True, spinning=False),
        ),
    ],
)
def test_outcomes(args, expected):
    vx, vy, om, mu = args
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), vx, vy, om, mu=mu, kappa=0.5)
    for k, v in expected.items():
        assert bool(getattr(imp.outcome, k)) is v, k


def test_outcome_values_backspin():
    imp = solve(Body.solid_disk(mass=2.0, radius=0.5), 1.0, -10.0, 6.0, mu=0.2, kappa=0.5)
    close(imp.after.vx, -1 / 3, 10.0)
    close(imp.after.omega, 2 / 3, 10.0)


# --------------------------------------------------------------------------
# Velocity-dependent restitution kappa(|v^-|) (section 3)
# --------------------------------------------------------------------------
def test_tabulated_restitution():
    tab = TabulatedRestitution(speeds=[1, 2, 4], kappas=[0.9, 0.8, 0.6])
    npt.assert_allclose(tab(3.0), 0.7, rtol=1e-12)  # linear interpolation
    npt.assert_allclose(tab(1.5), 0.85, rtol=1e-12)
    body = Body.solid_disk(mass=2.0, radius=0.5)
    imp = solve(body, 1.0, -3.0, 0.0, mu=0.2, kappa=tab)
    close(imp.after.vy, 2.1, 10.0)
    close(imp.tau1, 1.7 * 6.0, 20.0)
    close(imp.newton_restitution, 0.7, 1.0)
    arr = solve(body, 1.0, np.array([-1.5, -3.0]), 0.0, mu=0.2, kappa=tab)
    close(arr.after.vy, [1.275, 2.1], 10.0)


def test_constant_and_callable_restitution():
    body = Body.solid_disk(mass=2.0, radius=0.5)
    ref_imp = solve(body, 3.0, -1.0, 2.0, mu=0.2, kappa=0.6)
    c = solve(body, 3.0, -1.0, 2.0, mu=0.2, kappa=ConstantRestitution(0.6))
    close(c.after.vx, ref_imp.after.vx, 10.0)
    close(c.after.vy, ref_imp.after.vy, 10.0)
    close(c.after.omega, ref_imp.after.omega, 10.0)
    # a plain callable of the impact speed |vy|: kappa = 0.9 - 0.1*2.5 = 0.65
    f = solve(body, 1.0, -2.5, 0.0, mu=0.2, kappa=lambda s: 0.9 - 0.1 * s)
    close(f.after.vy, 0.65 * 2.5, 10.0)


# --------------------------------------------------------------------------
# 12. Bad input -> ValueError naming the parameter
# --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "kwargs,name",
    [
        (dict(mass=0.0, radius=0.1, gyration=0.05), "mass"),
        (dict(mass=-1.0, radius=0.1, gyration=0.05), "mass"),
        (dict(mass=np.nan, radius=0.1, gyration=0.05), "mass"),
        (dict(mass=np.inf, radius=0.1, gyration=0.05), "mass"),
        (dict(mass=1.0, radius=0.0, gyration=0.05), "radius"),
        (dict(mass=1.0, radius=-0.1, gyration=0.05), "radius"),
        (dict(mass=1.0, radius=np.nan, gyration=0.05), "radius"),
        (dict(mass=1.0, radius=0.1, gyration=0.0), "gyration"),
        (dict(mass=1.0, radius=0.1, gyration=-0.05), "gyration"),
        (dict(mass=1.0, radius=0.1, gyration=np.inf), "gyration"),
    ],
)
def test_bad_body(kwargs, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        Body(**kwargs)


@pytest.mark.parametrize(
    "factory", [Body.solid_disk, Body.ring, Body.solid_sphere, Body.spherical_shell]
)
@pytest.mark.parametrize("mass,radius,name", [(-1.0, 0.1, "mass"), (1.0, 0.0, "radius")])
def test_bad_preset(factory, mass, radius, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        factory(mass=mass, radius=radius)


GOOD = dict(vx=1.0, vy=-2.0, omega=3.0, mu=0.3, kappa=0.6)


@pytest.mark.parametrize(
    "change,name",
    [
        (dict(mu=-0.1), "mu"),
        (dict(mu=np.nan), "mu"),
        (dict(mu=np.inf), "mu"),
        (dict(kappa=1.1), "kappa"),
        (dict(kappa=-0.1), "kappa"),
        (dict(kappa=np.nan), "kappa"),
        (dict(vy=0.0), "vy"),
        (dict(vy=1.0), "vy"),
        (dict(vy=np.nan), "vy"),
        (dict(vy=-np.inf), "vy"),
        (dict(vy=np.array([-1.0, 0.5])), "vy"),
        (dict(vx=np.nan), "vx"),
        (dict(vx=np.inf), "vx"),
        (dict(omega=np.nan), "omega"),
        (dict(omega=-np.inf), "omega"),
        (dict(mu=np.array([0.2, -0.2])), "mu"),
        (dict(kappa=np.array([0.2, 1.5])), "kappa"),
    ],
)
def test_bad_solve_inputs(change, name):
    args = {**GOOD, **change}
    body = Body.solid_disk(mass=1.0, radius=0.1)
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        solve(body, args["vx"], args["vy"], args["omega"], mu=args["mu"], kappa=args["kappa"])


@pytest.mark.parametrize(
    "change,name",
    [
        (dict(mu=-0.5), "mu"),
        (dict(kappa=2.0), "kappa"),
        (dict(vy=0.5), "vy"),
        (dict(mass=0.0), "mass"),
        (dict(vx=np.nan), "vx"),
    ],
)
def test_bad_particle_inputs(change, name):
    args = {**dict(vx=1.0, vy=-1.0, mu=0.5, kappa=0.8, mass=1.0), **change}
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        solve_particle(
            args["vx"], args["vy"], mu=args["mu"], kappa=args["kappa"], mass=args["mass"]
        )
