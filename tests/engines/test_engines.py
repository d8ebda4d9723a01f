"""spinimpact.engines: PyBullet and MuJoCo set up to bounce the impact solve() solves.

What is tested is the set-up (axes, spin sign, inertia, friction and restitution
as each engine defines them, the error measure), through cases where an engine
must agree with the exact answer, not the engines' accuracy in general, which
is what the benchmark measures.
"""

import numpy as np
import pytest

import spinimpact
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


#: Settings per engine for the checks below: the engines' defaults of bounce().
CHECK_SETTINGS = {"pybullet": {}, "mujoco": {}}
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
    Body.solid_sphere(mass=1e-5, radius=1e-3),  # a small fast ball: MuJoCo's contact scales
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
    run = E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=[0.3, 0.3, 0.6], kappa=[0.5, 0.8, 0.5])
    damping = run.settings["damping"]
    assert damping.shape == (3,) and damping[0] > damping[1] > 0  # less restitution, more damping
    assert run.settings["stiffness"] == pytest.approx((np.pi / run.settings["contact_time"]) ** 2)
    with pytest.raises(ValueError, match=r"kappa must be in \(0, 1\) for a calibrated"):
        E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=1.0)
    with pytest.raises(ValueError, match="contact must be 'calibrated' or 'default'"):
        E.bounce("mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=0.5, contact="hard")
    with pytest.raises(ValueError, match="contact_time must span at least 20 time steps"):
        E.bounce(
            "mujoco", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=0.5, contact_time=1e-4, timestep=1e-5
        )


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


#: PyBullet with no contact margin, position correction or restitution threshold.
PYBULLET_EXACT = {
    "contact_breaking_threshold": 0.0,
    "contact_erp": 0.0,
    "restitution_velocity_threshold": 0.0,
}


def test_pybullet_exact_contact_settings_give_the_exact_answer():
    """For a sphere (normal through the centre) Bullet's one-step impulse solve,
    Newton restitution and Coulomb friction with sticking, is the rigid-body answer,
    once nothing else acts: every rebound agrees with solve() to rounding. This
    checks restitution and friction as set (Bullet multiplies the plane's 1 by the
    sphere's kappa and mu), the axes, the spin sign and the inertia."""
    if not E.available("pybullet"):
        pytest.skip("pybullet is not installed (the [engines] extra)")
    for body in BODIES[:3]:
        cases = E.standard_cases(phases=2)
        cases["omega"] = cases["omega"] * 0.1 / body.radius  # the same rim speeds
        run = E.bounce("pybullet", body, **cases, **PYBULLET_EXACT)
        assert run.error.max() < 1e-12, body.name
        high = E.bounce("pybullet", body, **cases, hz=1000.0, **PYBULLET_EXACT)
        assert high.error.max() < 1e-12, body.name


def test_pybullet_fast_spin_and_speed_are_not_clamped():
    """Bullet clamps body velocities to 100 m/s and rad/s unless told otherwise."""
    if not E.available("pybullet"):
        pytest.skip("pybullet is not installed (the [engines] extra)")
    ball = Body.spherical_shell(mass=0.0027, radius=0.02)  # a table-tennis ball
    run = E.bounce("pybullet", ball, 5.0, -3.0, [0.0, 300.0, -600.0], mu=0.0, kappa=0.9)
    np.testing.assert_allclose(run.omega, [0.0, 300.0, -600.0], rtol=1e-12, atol=1e-12)
    fast = E.bounce("pybullet", SPHERE, 99.0, -200.0, 0.0, mu=10.0, kappa=0.8, **PYBULLET_EXACT)
    assert fast.error < 1e-12
    assert abs(fast.omega) > 100 and fast.vy > 100


def test_pybullet_ignores_contact_parameters_left_by_other_clients():
    """Bullet keeps the contact breaking threshold for the whole process."""
    if not E.available("pybullet"):
        pytest.skip("pybullet is not installed (the [engines] extra)")
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


@pytest.mark.parametrize("label, engine, settings", E.CONFIGURATIONS, ids=lambda x: str(x))
def test_sliding_impacts_have_friction_impulse_mu_times_normal(label, engine, settings):
    """In an impact that slides throughout, |change of vx| = mu * change of vy in
    every set-up: the friction coefficient reaches the engine as mu (not combined
    with the plane's into something else)."""
    if not E.available(engine):
        pytest.skip(f"{engine} is not installed (the [engines] extra)")
    mu = np.array([0.05, 0.1, 0.2])
    run = E.bounce(engine, SPHERE, 3.0, -1.0, 0.0, mu=mu, kappa=0.5, **settings)
    assert set(np.asarray(run.exact.regime).astype(str)) == {"slip"}
    np.testing.assert_allclose(np.abs(run.vx - 3.0) / (run.vy + 1.0), mu, rtol=1e-6)


def test_mujoco_spin_is_rotated_from_the_body_frame():
    mujoco = pytest.importorskip("mujoco", reason="mujoco is not installed (the [engines] extra)")
    rng = np.random.default_rng(3)
    q = rng.normal(size=(50, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    v = rng.normal(size=(50, 3))
    got = E._rotate(q, v)
    for i in range(50):
        expected = np.zeros(3)
        mujoco.mju_rotVecQuat(expected, v[i], q[i])
        np.testing.assert_allclose(got[i], expected, rtol=0, atol=1e-14)


@pytest.mark.parametrize(
    "engine_name, kwargs, message",
    [
        ("pybullet", {"hz": float("inf")}, "hz must be a finite rate > 0"),
        ("pybullet", {"hz": 0}, "hz must be a finite rate > 0"),
        ("pybullet", {"solver_iterations": 2.5}, "solver_iterations must be a whole number"),
        ("pybullet", {"contact_erp": -1.0}, "contact_erp must be a finite number >= 0"),
        ("mujoco", {"timestep": float("inf")}, "timestep must be a finite time > 0"),
        ("mujoco", {"contact_time": 0.0}, "contact_time must be a finite time > 0"),
        ("mujoco", {"friction_time": float("inf")}, "friction_time must be None or a finite"),
        (
            "mujoco",
            {"contact": "default", "contact_time": 1e-3},
            "contact_time applies only to contact='calibrated'",
        ),
    ],
)
def test_bad_settings_are_named(engine_name, kwargs, message):
    if not E.available(engine_name):
        pytest.skip(f"{engine_name} is not installed (the [engines] extra)")
    with pytest.raises(ValueError, match=message):
        E.bounce(engine_name, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **kwargs)


def test_numpy_number_settings_are_accepted(engine):
    key = {"pybullet": "hz", "mujoco": "timestep"}[engine]
    value = {"pybullet": np.int64(240), "mujoco": np.float32(2e-5)}[engine]
    run = E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **{key: value})
    assert run.settings[key] == float(value)


def test_more_bad_inputs(engine):
    with pytest.raises(ValueError, match="body must be a spinimpact.Body"):
        E.bounce(engine, "ball", 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match="the inputs hold no impact"):
        E.bounce(engine, SPHERE, [], -1.0, 0.0, mu=0.3, kappa=0.5)
    if engine == "pybullet":
        with pytest.raises(ValueError, match="mu must be <= 10 for PyBullet"):
            E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=12.0, kappa=0.5)
    else:
        with pytest.raises(ValueError, match="kappa = 0.0001 cannot be reached"):
            E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=1e-4)


def test_scalar_inputs_give_scalars(engine):
    run = E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    for value in (run.vx, run.vy, run.omega, run.phase, run.error):
        assert np.ndim(value) == 0
    assert isinstance(run.exact, spinimpact.Impact)
