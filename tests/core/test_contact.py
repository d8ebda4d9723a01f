"""The contact kernels of spinimpact.core.contact against closed forms and invariants.

``integrate_contact`` is the one integrator of the impact in time; both
``simulate`` and ``ContactLaw.normal_impact`` use it, so these tests check it
directly, without the model layer.
"""

import math

import numpy as np
import pytest

from spinimpact.core import contact as kc

MASS, RADIUS = 0.05, 0.02
INERTIA = 0.4 * MASS * RADIUS**2  # solid sphere


def _hunt_crossley(k, n, alpha):
    return lambda d, dd: kc.hunt_crossley_force(d, dd, k, n, alpha)


def _run(force, vx, vy, omega, mu, *, time_scale, rtol=1e-11, exponent=1.5):
    return kc.integrate_contact(force, MASS, RADIUS, INERTIA, mu, vx, vy, omega,
                                time_scale=time_scale, rtol=rtol, exponent=exponent)  # fmt: skip


def test_integrate_contact_returns_a_named_tuple_of_equal_length_series():
    force = _hunt_crossley(1e8, 1.5, 0.2)
    run = _run(force, 0.5, -3.0, 0.0, 0.3, time_scale=kc.power_law_time_scale(MASS, 3, 1e8, 1.5))
    assert isinstance(run, kc.ContactRun) and isinstance(run, tuple)
    assert run._fields[:2] == ("t", "compression")
    series = [f for f in run._fields if isinstance(getattr(run, f), np.ndarray)]
    assert len(series) == 12
    assert {getattr(run, f).shape for f in series} == {run.t.shape}
    assert run.stuck.dtype == bool and run.stuck[-1] and not run.stuck[1]
    # events in order, and the end of the contact is the last sample
    assert 0 < run.t_star < run.t1 and 0 < run.t0 < run.t1 and run.t[-1] == run.t1
    assert np.all(run.normal_force >= 0.0)
    assert np.all(run.friction_force[run.stuck] == 0.0) and np.all(run.slip[run.stuck] == 0.0)


def test_linear_invariants_hold_to_rounding():
    """Runge-Kutta preserves the linear invariants of eq. 2.4 exactly (up to rounding):
    ``m (vy - vy0) = tau`` and ``m (vx - vx0) = f``."""
    force = _hunt_crossley(1e8, 1.5, 0.2)
    run = _run(force, 2.0, -3.0, 60.0, 0.1, time_scale=kc.power_law_time_scale(MASS, 3, 1e8, 1.5))
    np.testing.assert_allclose(MASS * (run.vy + 3.0), run.tau, rtol=0, atol=1e-15)
    np.testing.assert_allclose(MASS * (run.vx - 2.0), run.tangential_impulse, rtol=0, atol=1e-15)
    # the three restitution coefficients coincide (W_tn = 0: section 3)
    assert run.poisson_restitution == pytest.approx(run.newton_restitution, abs=1e-9)
    assert run.energetic_restitution == pytest.approx(run.newton_restitution, abs=1e-9)
    assert run.compression_work == pytest.approx(-0.5 * MASS * 9.0, rel=1e-9)  # stops vy


@pytest.mark.parametrize("speed", [0.3, 3.0])
def test_elastic_hertz_drop_matches_hertz_closed_forms(speed):
    k = float(kc.hertz_stiffness(70e9, 0.3, RADIUS))
    scale = kc.power_law_time_scale(MASS, speed, k, 1.5)
    run = kc.integrate_normal_impact(_hunt_crossley(k, 1.5, 0.0), MASS, speed,
                                     time_scale=scale, rtol=1e-12, exponent=1.5)  # fmt: skip
    # elastic: kappa = 1; duration and compression from energy balance (Hertz 1882)
    assert run.newton_restitution == pytest.approx(1.0, abs=1e-9)
    assert run.t1 == pytest.approx(kc.hertz_duration(MASS, speed, k), rel=1e-9)
    assert run.max_compression == pytest.approx(kc.hertz_max_compression(MASS, speed, k), rel=1e-9)


def test_undamped_linear_spring_is_half_a_period():
    k = 1e6
    force = lambda d, dd: kc.linear_force(d, dd, k, 0.0)  # noqa: E731
    run = kc.integrate_normal_impact(force, MASS, 2.0, time_scale=math.sqrt(MASS / k), rtol=1e-12)
    # m x'' = -k x: contact lasts pi sqrt(m/k), largest compression v sqrt(m/k)
    assert run.t1 == pytest.approx(math.pi * math.sqrt(MASS / k), rel=1e-9)
    assert run.max_compression == pytest.approx(2.0 * math.sqrt(MASS / k), rel=1e-9)
    assert run.peak_force == pytest.approx(k * run.max_compression, rel=1e-4)  # sampled peak
    assert run.newton_restitution == pytest.approx(1.0, abs=1e-9)


def test_damped_linear_restitution_does_not_depend_on_speed():
    k, c = 1e6, 40.0
    force = lambda d, dd: kc.linear_force(d, dd, k, c)  # noqa: E731
    kappas = [
        kc.integrate_normal_impact(
            force, MASS, v, time_scale=MASS / c, rtol=1e-12
        ).newton_restitution
        for v in (0.1, 1.0, 10.0)
    ]
    assert 0.0 < kappas[0] < 0.99
    np.testing.assert_allclose(kappas, kappas[0], rtol=1e-9)


def test_hunt_crossley_restitution_depends_on_alpha_times_speed_only():
    """Scaling delta and t in ``m delta'' = -k delta^n (1 + 3/2 alpha delta')`` leaves
    ``alpha v`` as the only parameter of the restitution (Hunt & Crossley 1975)."""

    def kappa(k, alpha, mass, speed):
        run = kc.integrate_normal_impact(
            _hunt_crossley(k, 1.5, alpha), mass, speed,
            time_scale=kc.power_law_time_scale(mass, speed, k, 1.5), rtol=1e-12, exponent=1.5,
        )  # fmt: skip
        return run.newton_restitution

    reference = kappa(1e8, 0.2, 0.05, 1.0)
    assert 0.5 < reference < 0.95
    assert kappa(1e8, 0.1, 0.05, 2.0) == pytest.approx(reference, abs=1e-9)
    assert kappa(3e9, 0.2, 0.7, 1.0) == pytest.approx(reference, abs=1e-9)
    assert kappa(1e8, 0.2, 0.05, 2.0) < reference  # more dissipation at higher alpha v
