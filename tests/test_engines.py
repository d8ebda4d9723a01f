"""spinimpact.engines: PyBullet and MuJoCo set up to bounce the impact solve() solves.

What is tested is the set-up (axes, spin sign, inertia, friction and restitution
as each engine defines them, the error measure), through cases where an engine
must agree with the exact answer, not the engines' accuracy in general, which
is what the benchmark measures.
"""

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact import engines as E


@pytest.fixture(params=E.ENGINES)
def engine(request):
    if not E.available(request.param):
        pytest.skip(f"{request.param} is not installed (the [engines] extra)")
    return request.param


SPHERE = Body.solid_sphere(mass=1.0, radius=0.1)


def test_standard_cases_grid():
    c = E.standard_cases(phases=4)
    assert set(c) == {"vx", "vy", "omega", "mu", "kappa", "phase"}
    assert all(v.shape == (144 * 4,) for v in c.values())
    assert sorted(set(c["phase"])) == [0.125, 0.375, 0.625, 0.875]
    assert set(np.round(0.1 * c["omega"], 12)) == {-3.0, 0.0, 2.0}
    # every regime occurs for the solid sphere
    regimes = set(
        np.asarray(
            solve(
                SPHERE, **{k: c[k] for k in ("vx", "vy", "omega")}, mu=c["mu"], kappa=c["kappa"]
            ).regime
        ).astype(str)
    )
    assert regimes == {"slip", "stick-compression", "stick-restitution", "no-slip"}


@pytest.mark.parametrize("bad", [0, -1, 2.5, True])
def test_standard_cases_rejects_bad_phases(bad):
    with pytest.raises(ValueError, match="phases"):
        E.standard_cases(phases=bad)


def test_unknown_engine():
    with pytest.raises(ValueError, match="engine must be one of pybullet, mujoco; got 'ode'"):
        E.bounce("ode", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match="engine"):
        E.available("ode")


def test_bad_inputs_are_named(engine):
    with pytest.raises(ValueError, match="vy must be < 0"):
        E.bounce(engine, SPHERE, 1.0, 1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match=r"phase must be in \[0, 1\), got 1.0"):
        E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, phase=1.0)
    with pytest.raises(ValueError, match="kappa must be in"):
        E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=1.5)
    with pytest.raises(ValueError, match="unknown .* setting"):
        E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, warp_speed=9)
    arrays = Body(mass=[1.0, 2.0], radius=0.1, gyration=0.05)
    with pytest.raises(ValueError, match="body.mass must be a single number"):
        E.bounce(engine, arrays, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)


#: Settings per engine for the checks below: a stiffer MuJoCo contact (1 ms) so the
#: sphere's penetration, which shortens the friction force's lever arm, stays small.
CHECK_SETTINGS = {"pybullet": {}, "mujoco": {"contact_time": 1e-3, "timestep": 2e-5}}
#: MuJoCo clamps a friction coefficient to at least 1e-5.
FRICTIONLESS_RTOL = {"pybullet": 1e-9, "mujoco": 1e-4}


def test_frictionless_keeps_tangential_velocity_and_spin(engine):
    """mu = 0: no tangential impulse, whatever the spin."""
    vx, omega = np.array([1.0, -2.0, 3.0]), np.array([30.0, -50.0, 10.0])
    run = E.bounce(engine, SPHERE, vx, -2.0, omega, mu=0.0, kappa=0.7, **CHECK_SETTINGS[engine])
    np.testing.assert_allclose(run.vx, vx, rtol=FRICTIONLESS_RTOL[engine])
    np.testing.assert_allclose(run.omega, omega, rtol=FRICTIONLESS_RTOL[engine])
    assert np.all(run.vy > 0)  # it bounced


BODIES = [
    SPHERE,
    Body.solid_disk(mass=2.0, radius=0.05),
    Body.spherical_shell(mass=0.5, radius=0.2),
]


@pytest.mark.parametrize("body", BODIES, ids=lambda b: b.name)
def test_angular_momentum_about_the_contact_point_is_kept(engine, body):
    """Whatever an engine's friction law, its contact forces act at the contact point,
    so I omega - m R vx is unchanged by the impact (the invariant behind eq. 4.9).
    With ample friction and spin either way this checks the axes, the sign of the
    spin and the inertia given to the engine: a wrong one breaks the balance."""
    rim = np.array([-3.0, 5.0, 1.0, 0.0])
    vx = np.array([1.0, -2.0, 3.0, 2.0])
    omega = rim / body.radius
    run = E.bounce(engine, body, vx, -2.0, omega, mu=2.0, kappa=0.7, **CHECK_SETTINGS[engine])
    m, r, inertia = body.mass, body.radius, body.inertia
    before = inertia * omega - m * r * vx
    after = inertia * run.omega - m * r * run.vx
    change = np.abs(after - before) / (m * r * run.scale)
    assert change.max() < {"pybullet": 1e-9, "mujoco": 3e-3}[engine]
    # and the impact did act: friction changed the spin by far more than that
    assert np.all(np.abs(run.omega - omega) * r / run.scale > 0.1)


@pytest.mark.parametrize("body", BODIES, ids=lambda b: b.name)
def test_pybullet_sticking_impacts_leave_rolling_as_exact(body):
    """Bullet resolves friction as a hard constraint: with ample friction the sphere
    leaves rolling with exactly the exact tangential velocity and spin (the zeta rule,
    e.g. 5/7 for a sphere)."""
    if not E.available("pybullet"):
        pytest.skip("pybullet is not installed (the [engines] extra)")
    rim = np.array([-3.0, 5.0, 1.0, 0.0])
    vx = np.array([1.0, -2.0, 3.0, 2.0])
    run = E.bounce("pybullet", body, vx, -2.0, rim / body.radius, mu=2.0, kappa=0.7)
    assert set(np.asarray(run.exact.regime).astype(str)) == {"stick-compression"}
    np.testing.assert_allclose(run.vx, run.exact.after.vx, rtol=1e-9)
    np.testing.assert_allclose(run.omega, run.exact.after.omega, rtol=1e-9)


def test_mujoco_calibrated_restitution():
    """The calibrated MuJoCo contact bounces head-on with the requested kappa at any
    speed (a linear spring-damper); MuJoCo's default contact has its own kappa."""
    pytest.importorskip("mujoco", reason="mujoco is not installed (the [engines] extra)")
    kappa = np.array([0.3, 0.5, 0.8, 0.95])
    for vy in (-0.5, -4.0):
        run = E.bounce("mujoco", SPHERE, 0.0, vy, 0.0, mu=0.3, kappa=kappa)
        np.testing.assert_allclose(run.vy / -vy, kappa, atol=E._KAPPA_TOLERANCE)
        default = E.bounce("mujoco", SPHERE, 0.0, vy, 0.0, mu=0.3, kappa=kappa, contact="default")
        assert np.ptp(default.vy) < 1e-9 * abs(vy)  # kappa has no effect
        assert 0 < default.vy[0] / -vy < 0.3
    with pytest.raises(ValueError, match=r"kappa must be in \(0, 1\) for a calibrated"):
        E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=1.0)
    with pytest.raises(ValueError, match="contact must be 'calibrated' or 'default'"):
        E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=0.5, contact="hard")
    with pytest.raises(ValueError, match="contact_time must span at least 20 time steps"):
        E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=0.5, contact_time=1e-4)


def test_errors_and_summary_follow_their_definition(engine):
    c = E.standard_cases(phases=2)
    run = E.bounce(engine, SPHERE, **c)
    assert run.vx.shape == run.exact.after.vx.shape == (288,)
    scale = np.maximum.reduce([np.abs(c["vx"]), np.abs(c["vy"]), np.abs(0.1 * c["omega"])])
    np.testing.assert_array_equal(run.scale, scale)
    err = run.errors()
    np.testing.assert_allclose(err["vy"], np.abs(run.vy - run.exact.after.vy) / scale)
    np.testing.assert_allclose(
        err["omega"], 0.1 * np.abs(run.omega - run.exact.after.omega) / scale
    )
    np.testing.assert_array_equal(
        run.error, np.maximum(np.maximum(err["vx"], err["vy"]), err["omega"])
    )
    s = run.summary()
    assert s["worst"]["max"] == run.error.max()
    assert s["vx"]["median"] == np.median(err["vx"])
    assert run.steps >= 3 and run.seconds > 0
    assert run.seconds_per_impact == run.seconds / 288


@pytest.mark.parametrize("label, engine, settings", E.CONFIGURATIONS, ids=lambda x: str(x))
def test_documented_configurations_run(label, engine, settings):
    if not E.available(engine):
        pytest.skip(f"{engine} is not installed (the [engines] extra)")
    run = E.bounce(engine, SPHERE, [1.0, -2.0], -2.0, [10.0, 0.0], mu=0.3, kappa=0.6, **settings)
    assert np.all(np.isfinite(run.error)) and np.all(run.vy > 0), label
    assert {k: run.settings[k] for k in settings} == settings
