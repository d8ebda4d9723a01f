"""The Mindlin tangential spring in time (core.tangential): energy, events, limits."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from spinimpact import Body, solve
from spinimpact.core.contact import power_law_time_scale
from spinimpact.core.tangential import integrate_tangential, mindlin_stiffness_ratio

R = 0.0025
M = 4.0 / 3.0 * math.pi * R**3 * 4000.0
J = 0.4 * M * R**2
K_HERTZ = 4.0 / 3.0 * 3.8e11 / (1 - 0.23**2) * math.sqrt(R)


def _hertz(vx, vy, omega=0.0, mu=0.092, ratio=0.87, alpha=0.0, rtol=1e-10):
    ts = float(power_law_time_scale(M, abs(vy), K_HERTZ, 1.5))
    return integrate_tangential(
        M,
        R,
        J,
        mu,
        vx,
        vy,
        omega,
        stiffness=K_HERTZ,
        exponent=1.5,
        alpha=alpha,
        stiffness_ratio=ratio,
        time_scale=ts,
        rtol=rtol,
    )


def _cases(n=24, seed=7):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        angle = rng.uniform(0.5, 80.0)
        speed = rng.uniform(0.5, 5.0)
        yield (
            speed * math.sin(math.radians(angle)),
            -speed * math.cos(math.radians(angle)),
            rng.uniform(-800, 800),
            rng.uniform(0.05, 0.6),
            rng.uniform(0.3, 1.2),
            rng.choice([0.0, 0.02, 0.1]),
        )


@pytest.mark.slow
def test_energy_never_increases():
    """E = T + U_n + F^2/(2 k_t) is non-increasing (module docstring); sampled on the
    dense output, so a rise of the order of the tolerance times E0 would be noise: the
    bound is 1e-8 E0, and every run ends with less kinetic energy than it began with."""
    for vx, vy, omega, mu, ratio, alpha in _cases():
        run = _hertz(vx, vy, omega, mu, ratio, alpha)
        e = run.energy
        assert np.diff(e).max() <= 1e-8 * e[0], (vx, vy, omega, mu, ratio, alpha)
        t_end = 0.5 * M * (run.vx[-1] ** 2 + run.vy[-1] ** 2) + 0.5 * J * run.omega[-1] ** 2
        assert t_end <= e[0] * (1 + 1e-9)


def test_linear_spring_dashpot_energy_and_cap():
    for vx, vy, omega, mu, ratio, _ in _cases(12, seed=3):
        run = integrate_tangential(
            M,
            R,
            J,
            mu,
            vx,
            vy,
            omega,
            stiffness=1e7,
            exponent=1.0,
            damping=0.3,
            stiffness_ratio=ratio,
            time_scale=math.sqrt(M / 1e7),
        )
        assert np.diff(run.energy).max() <= 1e-8 * run.energy[0]
        excess = np.abs(run.tangential_force) - mu * run.normal_force
        assert excess.max() <= 1e-8 * mu * run.normal_force.max()


def test_switch_events_to_integrator_precision():
    """At a stick->slip switch |F| = mu N; at slip->stick the slip velocity is zero; and the
    switch times move by far less than the contact time when the tolerance is tightened."""
    vx, vy = 3.9 * math.sin(math.radians(20)), -3.9 * math.cos(math.radians(20))
    run = _hertz(vx, vy)
    fine = _hertz(vx, vy, rtol=1e-12)
    assert run.switches.size == fine.switches.size == 2
    assert np.abs(run.switches - fine.switches).max() < 1e-7 * run.t1
    for t in run.switches:
        i = int(np.flatnonzero(run.t == t)[0])
        assert abs(abs(run.tangential_force[i]) - 0.092 * run.normal_force[i]) <= (
            1e-9 * run.normal_force.max()
        )
    # the first switch ends the initial slip: the slip velocity, extrapolated from the
    # last two samples of the slip phase, reaches zero there (to the sampling's O(dt^2))
    i = int(np.flatnonzero(run.t == run.switches[0])[0])
    w1, w2, t1, t2 = run.slip[i - 2], run.slip[i - 1], run.t[i - 2], run.t[i - 1]
    at_switch = w2 + (w2 - w1) / (t2 - t1) * (run.t[i] - t2)
    assert abs(at_switch) < 1e-3 * abs(vx) < abs(w1) and run.stuck[i] and not run.stuck[i - 1]


def test_full_stick_linear_spring_is_a_harmonic_oscillator():
    """Closed form: a linear elastic normal spring (duration pi/w_n) and a tangential
    spring r k that sticks (large mu): u(t) = u- cos(w_t t), w_t/w_n = sqrt(zeta r). The cap
    mu N falls to zero at separation, so a slip phase may open in the last 1e-4 of the
    contact; it changes u+ by less than 1e-4 u-."""
    zeta = 3.5
    for ratio in (0.3, 0.87, 2.0):
        run = integrate_tangential(
            M,
            R,
            J,
            1e3,
            0.2,
            -3.0,
            0.0,
            stiffness=1e7,
            exponent=1.0,
            stiffness_ratio=ratio,
            time_scale=math.sqrt(M / 1e7),
            rtol=1e-12,
        )
        assert run.switches.size <= 1 and (run.switches > (1 - 1e-4) * run.t1).all()
        expected = 0.2 * math.cos(math.pi * math.sqrt(zeta * ratio))
        assert run.contact_velocity[-1] == pytest.approx(expected, abs=1e-4 * 0.2)
        assert run.t1 == pytest.approx(math.pi * math.sqrt(M / 1e7), rel=1e-9)


@pytest.mark.parametrize("angle", [5.0, 20.0, 45.0])
@pytest.mark.slow
def test_stiff_tangential_spring_converges_to_the_rigid_law(angle):
    vx, vy = 3.9 * math.sin(math.radians(angle)), -3.9 * math.cos(math.radians(angle))
    rigid = solve(Body.solid_sphere(mass=M, radius=R), vx, vy, 0.0, mu=0.092, kappa=1.0)
    errs = [abs(_hertz(vx, vy, ratio=r).vx[-1] - float(rigid.after.vx)) for r in (1e2, 1e4, 1e6)]
    assert errs[-1] < 1e-5 * abs(vx) + 1e-12
    if angle < 30:  # sticking impacts: the error shrinks with the stiffness
        assert errs[0] > errs[1] > errs[2]


def test_frictionless_contact_leaves_the_tangential_motion_alone():
    run = _hertz(1.0, -3.0, 50.0, mu=0.0)
    assert run.vx[-1] == 1.0 and run.omega[-1] == 50.0


def test_stiffness_ratio_from_the_definitions():
    """4 G*/E* with E*, G* of two materials (Johnson 1985, sec. 7.2), computed here from E
    and nu directly, against the kernel's closed forms."""
    for nu1, nu2, e1, e2 in (
        (0.23, 0.23, 3.8e11, 3.8e11),
        (0.23, 0.22, 3.8e11, 7.0e10),
        (0.33, 0.4, 7e10, 2.5e9),
    ):
        g1, g2 = e1 / (2 * (1 + nu1)), e2 / (2 * (1 + nu2))
        e_star = 1 / ((1 - nu1**2) / e1 + (1 - nu2**2) / e2)
        g_star = 1 / ((2 - nu1) / g1 + (2 - nu2) / g2)
        assert float(mindlin_stiffness_ratio(nu1, nu2, e1 / e2)) == pytest.approx(
            4 * g_star / e_star, rel=1e-13
        )
    assert float(mindlin_stiffness_ratio(0.3)) == pytest.approx(2 * 0.7 / 1.7, rel=1e-15)


def _final_gain(run):
    kinetic = 0.5 * M * (run.vx[-1] ** 2 + run.vy[-1] ** 2) + 0.5 * J * run.omega[-1] ** 2
    return kinetic / run.energy[0] - 1.0


@pytest.mark.slow
def test_the_other_spring_rules_can_gain_energy():
    """Why "scaled" is the default (module docstring): on the same elastic impacts the
    plain incremental rule lets E rise while unloading, and the total-displacement rule
    even returns more kinetic energy than the ball brought (measured: up to 0.4 %)."""
    gains = {"scaled": [], "incremental": [], "total": []}
    finals = {"scaled": [], "incremental": [], "total": []}
    for vx, vy, omega, mu, ratio, _ in _cases():
        ts = float(power_law_time_scale(M, abs(vy), K_HERTZ, 1.5))
        for spring in gains:
            run = integrate_tangential(
                M,
                R,
                J,
                mu,
                vx,
                vy,
                omega,
                stiffness=K_HERTZ,
                exponent=1.5,
                stiffness_ratio=ratio,
                time_scale=ts,
                spring=spring,
            )
            gains[spring].append(np.diff(run.energy).max() / run.energy[0])
            finals[spring].append(_final_gain(run))
    assert max(gains["scaled"]) < 1e-8 and max(finals["scaled"]) < 0
    assert max(gains["incremental"]) > 1e-5
    assert max(finals["total"]) > 1e-3


def test_spring_rules_coincide_for_a_linear_normal_spring():
    runs = [
        integrate_tangential(
            M,
            R,
            J,
            0.3,
            0.4,
            -2.0,
            100.0,
            stiffness=1e7,
            exponent=1.0,
            stiffness_ratio=0.9,
            time_scale=math.sqrt(M / 1e7),
            spring=spring,
        )
        for spring in ("scaled", "incremental", "total")
    ]
    for run in runs[1:]:
        assert run.vx[-1] == runs[0].vx[-1] and run.omega[-1] == runs[0].omega[-1]
    with pytest.raises(ValueError, match="spring must be one of"):
        integrate_tangential(
            M,
            R,
            J,
            0.3,
            0.4,
            -2.0,
            0.0,
            stiffness=1e7,
            exponent=1.0,
            stiffness_ratio=0.9,
            time_scale=1e-5,
            spring="x",
        )


@settings(max_examples=40)
@given(
    st.floats(0.05, 5.0),
    st.floats(-5.0, 5.0),
    st.floats(-2000.0, 2000.0),
    st.floats(0.0, 1.0),
    st.floats(0.05, 5.0),
    st.sampled_from([0.0, 0.05, 0.3]),
)
@pytest.mark.slow
def test_energy_never_increases_property(speed, vx, omega, mu, ratio, alpha):
    """Hypothesis: any incidence, friction, stiffness ratio and Hunt-Crossley damping;
    E never rises above 1e-8 E0 on the samples and the rebound keeps the cap."""
    run = _hertz(vx, -speed, omega, mu, ratio, alpha)
    assert np.diff(run.energy).max() <= 1e-8 * run.energy[0]
    excess = np.abs(run.tangential_force) - mu * run.normal_force
    assert excess.max() <= 1e-8 * (mu * run.normal_force.max() + 1e-300)


def _history(vx, vy, omega, mu, ratio, alpha=0.0, spring="history"):
    ts = float(power_law_time_scale(M, abs(vy), K_HERTZ, 1.5))
    return integrate_tangential(M, R, J, mu, vx, vy, omega, stiffness=K_HERTZ, exponent=1.5,
                                alpha=alpha, stiffness_ratio=ratio, time_scale=ts,
                                spring=spring)  # fmt: skip


@pytest.mark.slow
def test_the_history_rule_keeps_its_field_energy_from_rising():
    """spring="history": E = T + U_n + the traction field's energy (loading history plus
    the punch beyond it; a sliding field's n F^2/((n + 1) k_t)) never rises, on the same
    random impacts as the other rules and with damping, through slip and re-stick."""
    rises, switched = [], 0
    for i, (vx, vy, omega, mu, ratio, _) in enumerate(_cases()):
        run = _history(vx, vy, omega, mu, ratio, alpha=0.05 * (i % 3))
        rises.append(np.diff(run.energy).max() / run.energy[0])
        switched += run.switches.size > 0
        assert _final_gain(run) < 0
    assert max(rises) < 1e-8 and switched >= 5


def test_the_history_rule_differs_only_while_the_contact_shrinks():
    """Up to the end of compression the stuck spring of every rule is dF/dt = -k_t u; the
    history rule then unloads only the force beyond the loading history's, so it keeps
    less of the stored strain than the scaled rule near normal incidence (e_t = vx+/vx-
    0.799 against 0.882 for nu = 0.23, sticking throughout)."""
    runs = {s: _history(0.01, -3.9, 0.0, 0.092, 0.870056, spring=s)
            for s in ("scaled", "history")}  # fmt: skip
    before = {s: np.interp(0.5 * r.t0, r.t, r.tangential_force) for s, r in runs.items()}
    assert before["history"] == pytest.approx(before["scaled"], rel=1e-7)
    e_t = {s: r.vx[-1] / 0.01 for s, r in runs.items()}
    assert e_t["history"] == pytest.approx(0.799, abs=1e-3)
    assert e_t["scaled"] == pytest.approx(0.882, abs=1e-3)


def test_the_history_rule_without_friction():
    """mu = 0: no tangential force at all, as with the other rules (it divided by mu)."""
    run = _history(3.0, -4.0, 10.0, 0.0, 0.87)
    assert run.vx[-1] == 3.0 and run.omega[-1] == 10.0
