"""spinimpact.engines.restitution: the setting that gives a head-on restitution e, and the e
that settings give across speeds."""

import json

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.engines import restitution_curve, restitution_settings

from .bodies import PYBULLET_EXACT, needs

BALL = Body.solid_sphere(mass=0.06, radius=0.033)


@pytest.mark.slow
@pytest.mark.parametrize("engine, dt", [("pybullet", 1 / 240), ("mujoco", 0.002)])
def test_settings_give_the_target_e_at_the_target_speed(engine, dt):
    """The setting solved for reproduces e at the speed it was solved at: the root is found
    to 1e-12 in the setting, so the mean rebound ratio is e within the stated TOLERANCE."""
    needs(engine)
    for e in (0.5, 0.8):
        settings = restitution_settings(engine, e, 2.0, dt, BALL)
        assert settings["timestep"] == dt
        curve = restitution_curve(engine, settings, BALL, [2.0, 6.0])
        assert curve.restitution[0] == pytest.approx(e, abs=1e-6)
        assert curve.low[0] < curve.high[0]  # the phase within a step matters at 2 m/s
    assert json.loads(json.dumps(curve.to_dict()))["speed"] == [2.0, 6.0]


@pytest.mark.slow
def test_pybullet_exact_contact_settings_bounce_with_e_at_every_speed():
    """With no contact margin, position correction or restitution threshold and a zero slop,
    Bullet's restitution is e itself, at every speed and phase (to rounding)."""
    needs("pybullet")
    exact = {**PYBULLET_EXACT, "contact_slop": 0.0}
    settings = restitution_settings("pybullet", 0.7, 2.0, 1 / 240, BALL, **exact)
    assert settings["restitution"] == pytest.approx(0.7, abs=1e-9)
    curve = restitution_curve("pybullet", settings, BALL, [0.5, 1.0, 10.0])
    np.testing.assert_allclose([curve.low, curve.high], 0.7, atol=1e-9)


@pytest.mark.slow
def test_pybullet_defaults_bounce_low_at_low_speed():
    """At PyBullet's default contact parameters the e set at 2 m/s is not the e at 0.5 m/s."""
    needs("pybullet")
    settings = restitution_settings("pybullet", 0.7, 2.0, 1 / 240, BALL)
    curve = restitution_curve("pybullet", settings, BALL, [0.5, 2.0])
    assert curve.restitution[0] < 0.7 - 0.05


def test_mujoco_dampratio_is_solved_with_the_time_constant_held():
    needs("mujoco")
    settings = restitution_settings("mujoco", 0.75, 2.0, 0.002, BALL, solref=(0.01, 1.0))
    assert settings["solref"][0] == 0.01 and 0 < settings["solref"][1] < 1
    with pytest.raises(ValueError, match="e = 0.0 cannot be reached by mujoco"):
        restitution_settings("mujoco", 0.0, 2.0, 0.002, BALL)


@pytest.mark.parametrize(
    "args, kwargs, error, message",
    [
        (("mujoco", 1.5, 2.0, 0.002, BALL), {}, ValueError, "e must be"),
        (("mujoco", "0.5", 2.0, 0.002, BALL), {}, TypeError, "e must be"),
        (("mujoco", 0.5, -2.0, 0.002, BALL), {}, ValueError, r"speed must be > 0 \(m/s\)"),
        (("mujoco", 0.5, 2.0, 0.002, BALL), {"timestep": 0.001}, ValueError, "time step is dt"),
        (("mujoco", 0.5, 0.0, 0.002, BALL), {}, ValueError, "speed must be > 0"),
        (("mujoco", 0.5, 2.0, -1.0, BALL), {}, ValueError, "dt must be a finite number > 0"),
        (("mujoco", 0.5, 2.0, 0.002, "ball"), {}, TypeError, "body must be a spinimpact.Body"),
        (("ode", 0.5, 2.0, 0.002, BALL), {}, ValueError, "engine must be one of"),
        (("mujoco", 0.5, 2.0, 0.002, BALL), {"stiffness": 1.0}, ValueError, "stiffness"),
        (("mujoco", 0.5, 2.0, 0.002, BALL), {"solref": 0.1}, TypeError, "solref must be 2"),
        (("mujoco", 0.5, 2.0, 0.002, BALL), {"cone": "round"}, ValueError, "cone must be"),
        (("pybullet", 0.5, 2.0, 0.002, BALL), {"contact_erp": -1}, ValueError, "contact_erp"),
    ],
)
def test_bad_input_is_named(args, kwargs, error, message):
    with pytest.raises(error, match=message):
        restitution_settings(*args, **kwargs)


def test_curve_refuses_bad_speeds_and_settings():
    with pytest.raises(ValueError, match="speed must be > 0"):
        restitution_curve("pybullet", {}, BALL, [1.0, 0.0])
    with pytest.raises(ValueError, match="speed must hold at least one speed"):
        restitution_curve("mujoco", {}, BALL, [])
    with pytest.raises(TypeError, match="settings must be a mapping"):
        restitution_curve("mujoco", None, BALL, 2.0)
