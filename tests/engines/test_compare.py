"""spinimpact.engines.bounce: PyBullet, MuJoCo and Drake set up to bounce the impact solve() solves.

What is tested is the set-up (axes, spin sign, inertia, friction and restitution
as each engine defines them, the error measure), through cases where an engine
must agree with the exact answer, not the engines' accuracy in general, which
is what the benchmark measures.
"""

import json
import sys

import numpy as np
import pytest

import spinimpact
from spinimpact import Body
from spinimpact import engines as E

from .bodies import BODIES, SPHERE, needs


def test_unknown_engine():
    with pytest.raises(
        ValueError, match="engine must be one of pybullet, mujoco, drake; got 'ode'"
    ):
        E.bounce("ode", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(ValueError, match="engine"):
        E.available("ode")
    with pytest.raises(TypeError, match="engine must be one of pybullet, mujoco, drake; got 3"):
        E.bounce(3, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(TypeError, match="engine"):
        E.available(None)


@pytest.mark.parametrize("name", E.ENGINES)
def test_a_missing_engine_names_the_extra(name, monkeypatch):
    """Without the engine, bounce() raises ImportError naming the [engines] extra
    (spinimpact._validation.require), after checking the inputs."""
    monkeypatch.setitem(sys.modules, E.common.MODULES[name], None)  # import of it now fails
    assert not E.available(name)
    extra = r"needs .* not installed: pip install 'spinimpact\[engines\]'"
    with pytest.raises(ImportError, match=extra) as err:
        E.bounce(name, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5)
    assert type(err.value) is ImportError and name in str(err.value)
    with pytest.raises(ValueError, match="vy must be < 0"):  # inputs are checked first
        E.bounce(name, SPHERE, 1.0, 1.0, 0.0, mu=0.3, kappa=0.5)


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


def test_wrong_types_are_type_errors(engine):
    with pytest.raises(TypeError, match="vx must be a real number"):
        E.bounce(engine, SPHERE, "1", -1.0, 0.0, mu=0.3, kappa=0.5)
    with pytest.raises(TypeError, match="phase must be a real number"):
        E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, phase=None)
    key = {"pybullet": "hz", "mujoco": "timestep", "drake": "time_step"}[engine]
    with pytest.raises(TypeError, match=f"{key} must be a finite"):
        E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **{key: "fast"})


#: Settings per engine for the checks below: the engines' defaults of bounce().
CHECK_SETTINGS = {"pybullet": {}, "mujoco": {}, "drake": {}}
#: MuJoCo clamps a friction coefficient to at least 1e-5.
FRICTIONLESS_RTOL = {"pybullet": 1e-9, "mujoco": 1e-4, "drake": 1e-9}


def test_frictionless_keeps_tangential_velocity_and_spin(engine):
    """mu = 0: no tangential impulse, whatever the spin."""
    vx, omega = np.array([1.0, -2.0, 3.0]), np.array([30.0, -50.0, 10.0])
    run = E.bounce(engine, SPHERE, vx, -2.0, omega, mu=0.0, kappa=0.7, **CHECK_SETTINGS[engine])
    np.testing.assert_allclose(run.vx, vx, rtol=FRICTIONLESS_RTOL[engine])
    np.testing.assert_allclose(run.omega, omega, rtol=FRICTIONLESS_RTOL[engine])
    assert np.all(run.vy > 0)  # it bounced


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
    # Drake: its point contact acts half the penetration below the surface (measured 1.2e-3)
    assert change.max() < {"pybullet": 1e-9, "mujoco": 3e-3, "drake": 2e-3}[engine]
    # and the impact did act: friction changed the spin by far more than that
    assert np.all(np.abs(run.omega - omega) * r / run.scale > 0.1)


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
    assert run.batch_size == 288


def test_a_run_is_a_result(engine):
    """Shape, indexing, plain values for JSON and flat columns, as every result."""
    vx, omega = np.array([[1.0, -2.0], [3.0, 0.5]]), np.array([10.0, -20.0])
    run = E.bounce(engine, SPHERE, vx, -2.0, omega, mu=0.3, kappa=0.6)
    assert run.shape == (2, 2) and len(run) == 2
    one = run[1, 0]
    assert one.shape == () and one.vx == run.vx[1, 0] and one.phase == 0.5
    assert one.exact.after.vy == run.exact.after.vy[1, 0]
    assert one.error == run.error[1, 0]
    assert one.seconds_per_impact == run.seconds_per_impact == run.seconds / 4
    d = json.loads(json.dumps(run.to_dict()))  # plain values throughout
    assert d["engine"] == engine and d["vy"] == run.vy.tolist()
    assert d["exact"]["after"]["vx"] == run.exact.after.vx.tolist()
    assert d["settings"].keys() == run.settings.keys()
    if engine == "mujoco":
        assert d["settings"]["damping"] == run.settings["damping"].tolist()
    cols = run.columns()
    assert tuple(cols) == E.EngineRun.column_names()
    np.testing.assert_array_equal(cols["exact_after_omega"], run.exact.after.omega)
    np.testing.assert_array_equal(cols["omega"], run.omega)


@pytest.mark.parametrize("label, engine, settings", E.CONFIGURATIONS, ids=lambda x: str(x))
def test_documented_configurations_run(label, engine, settings):
    needs(engine)
    run = E.bounce(engine, SPHERE, [1.0, -2.0], -2.0, [10.0, 0.0], mu=0.3, kappa=0.6, **settings)
    assert np.all(np.isfinite(run.error)) and np.all(run.vy > 0), label
    assert {k: run.settings[k] for k in settings} == settings


@pytest.mark.parametrize("label, engine, settings", E.CONFIGURATIONS, ids=lambda x: str(x))
def test_sliding_impacts_have_friction_impulse_mu_times_normal(label, engine, settings):
    """In an impact that slides throughout, |change of vx| = mu * change of vy in
    every set-up: the friction coefficient reaches the engine as mu (not combined
    with the plane's into something else)."""
    needs(engine)
    if engine == "drake" and settings.get("contact") == "default":
        pytest.skip(
            "Drake's default contact breaks the proportion (|dvx| was 13 mu dvy at mu 0.05): "
            "its lagged approximation bounds friction by the previous step's normal force, "
            "which includes a large default dissipation"
        )
    mu = np.array([0.05, 0.1, 0.2])
    run = E.bounce(engine, SPHERE, 3.0, -1.0, 0.0, mu=mu, kappa=0.5, **settings)
    assert set(np.asarray(run.exact.regime).astype(str)) == {"slip"}
    # Drake's lagged approximation, for the same reason: measured 8.0e-4
    lagged = engine == "drake" and settings.get("approximation", "lagged") == "lagged"
    rtol = 1e-3 if lagged else 1e-6
    np.testing.assert_allclose(np.abs(run.vx - 3.0) / (run.vy + 1.0), mu, rtol=rtol)


def test_numpy_number_settings_are_accepted(engine):
    key = {"pybullet": "hz", "mujoco": "timestep", "drake": "time_step"}[engine]
    value = {"pybullet": np.int64(240), "mujoco": np.float32(2e-5), "drake": np.float32(2e-5)}[
        engine
    ]
    run = E.bounce(engine, SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **{key: value})
    assert run.settings[key] == float(value)


def test_more_bad_inputs(engine):
    with pytest.raises(TypeError, match="body must be a spinimpact.Body"):
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


def test_a_ball_is_taken_as_its_body():
    needs("pybullet")
    ball = spinimpact.BALLS["table-tennis"]
    for call in (
        lambda b: E.bounce("pybullet", b, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5).vx,
        lambda b: E.restitution_settings("pybullet", 0.5, 2.0, 1 / 240, b),
    ):
        assert np.array_equal(call(ball), call(ball.body))
