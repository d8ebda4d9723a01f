"""spinimpact.engines.pybullet: Bullet's one-step impulse solve, set up to be exact."""

import numpy as np
import pytest

from spinimpact import Body
from spinimpact import engines as E

from .bodies import BODIES, PYBULLET_EXACT, SPHERE, needs


@pytest.fixture(autouse=True)
def _pybullet():
    needs("pybullet")


@pytest.mark.parametrize("body", BODIES, ids=lambda b: b.name)
def test_pybullet_sticking_impacts_leave_rolling_as_exact(body):
    """Bullet resolves friction as a hard constraint: with ample friction the sphere
    leaves rolling with exactly the exact tangential velocity and spin (the zeta rule,
    e.g. 5/7 for a sphere)."""
    rim = np.array([-3.0, 5.0, 1.0, 0.0])
    vx = np.array([1.0, -2.0, 3.0, 2.0])
    run = E.bounce("pybullet", body, vx, -2.0, rim / body.radius, mu=2.0, kappa=0.7)
    assert set(np.asarray(run.exact.regime).astype(str)) == {"stick-compression"}
    np.testing.assert_allclose(run.vx, run.exact.after.vx, rtol=1e-9)
    np.testing.assert_allclose(run.omega, run.exact.after.omega, rtol=1e-9)


@pytest.mark.slow
def test_pybullet_exact_contact_settings_give_the_exact_answer():
    """For a sphere (normal through the centre) Bullet's one-step impulse solve,
    Newton restitution and Coulomb friction with sticking, is the rigid-body answer,
    once nothing else acts: every rebound agrees with solve() to rounding. This
    checks restitution and friction as set (Bullet multiplies the plane's 1 by the
    sphere's kappa and mu), the axes, the spin sign and the inertia."""
    for body in BODIES[:3]:
        cases = E.standard_cases(phases=2)
        cases["omega"] = cases["omega"] * 0.1 / body.radius  # the same rim speeds
        run = E.bounce("pybullet", body, **cases, **PYBULLET_EXACT)
        assert run.error.max() < 1e-12, body.name
        high = E.bounce("pybullet", body, **cases, hz=1000.0, **PYBULLET_EXACT)
        assert high.error.max() < 1e-12, body.name


def test_pybullet_fast_spin_and_speed_are_not_clamped():
    """Bullet clamps body velocities to 100 m/s and rad/s unless told otherwise."""
    ball = Body.spherical_shell(mass=0.0027, radius=0.02)  # a table-tennis ball
    run = E.bounce("pybullet", ball, 5.0, -3.0, [0.0, 300.0, -600.0], mu=0.0, kappa=0.9)
    np.testing.assert_allclose(run.omega, [0.0, 300.0, -600.0], rtol=1e-12, atol=1e-12)
    fast = E.bounce("pybullet", SPHERE, 99.0, -200.0, 0.0, mu=10.0, kappa=0.8, **PYBULLET_EXACT)
    assert fast.error < 1e-12
    assert abs(fast.omega) > 100 and fast.vy > 100


def test_pybullet_ignores_contact_parameters_left_by_other_clients():
    """Bullet keeps the contact breaking threshold for the whole process."""
    import pybullet as pb

    cases = E.standard_cases(phases=2)
    before = E.bounce("pybullet", SPHERE, **cases)
    client = pb.connect(pb.DIRECT)
    try:
        pb.setPhysicsEngineParameter(contactBreakingThreshold=0.001, physicsClientId=client)
    finally:
        pb.disconnect(client)
    after = E.bounce("pybullet", SPHERE, **cases)
    np.testing.assert_array_equal(after.vy, before.vy)
    assert before.settings["contact_breaking_threshold"] == 0.02
    assert {k: before.settings[k] for k in E.PYBULLET_DEFAULTS} == E.PYBULLET_DEFAULTS


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"hz": float("inf")}, ValueError, "hz must be a finite rate > 0"),
        ({"hz": 0}, ValueError, "hz must be a finite rate > 0"),
        ({"hz": "240"}, TypeError, "hz must be a finite rate > 0"),
        ({"solver_iterations": 2.5}, TypeError, "solver_iterations must be a whole number"),
        ({"solver_iterations": 0}, ValueError, "solver_iterations must be a whole number >= 1"),
        ({"contact_erp": -1.0}, ValueError, "contact_erp must be a finite number >= 0"),
        ({"contact_erp": True}, TypeError, "contact_erp must be a finite number >= 0"),
        ({"contact_breaking_threshold": None}, TypeError, "contact_breaking_threshold must"),
    ],
)
def test_bad_settings_are_named(kwargs, error, message):
    with pytest.raises(error, match=message):
        E.bounce("pybullet", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **kwargs)
