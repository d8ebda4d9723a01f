"""spinimpact.engines.mujoco: the calibrated soft contact and the spin's frame."""

import numpy as np
import pytest

from spinimpact import engines as E
from spinimpact.engines import mujoco as engine_mujoco

from .bodies import SPHERE, needs


@pytest.fixture(autouse=True)
def _mujoco():
    needs("mujoco")


def test_mujoco_calibrated_restitution():
    """The calibrated MuJoCo contact bounces head-on with the requested kappa at any
    speed (a linear spring-damper); MuJoCo's default contact has its own kappa."""
    kappa = np.array([0.3, 0.5, 0.8, 0.95])
    for vy in (-0.5, -4.0):
        run = E.bounce("mujoco", SPHERE, 0.0, vy, 0.0, mu=0.3, kappa=kappa)
        np.testing.assert_allclose(run.vy / -vy, kappa, atol=engine_mujoco._KAPPA_TOLERANCE)
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


def test_mujoco_spin_is_rotated_from_the_body_frame():
    import mujoco

    rng = np.random.default_rng(3)
    q = rng.normal(size=(50, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    v = rng.normal(size=(50, 3))
    got = engine_mujoco._rotate(q, v)
    for i in range(50):
        expected = np.zeros(3)
        mujoco.mju_rotVecQuat(expected, v[i], q[i])
        np.testing.assert_allclose(got[i], expected, rtol=0, atol=1e-14)


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"timestep": float("inf")}, ValueError, "timestep must be a finite time > 0"),
        ({"timestep": None}, TypeError, "timestep must be a finite time > 0"),
        ({"contact_time": 0.0}, ValueError, "contact_time must be a finite time > 0"),
        ({"contact_time": "1e-3"}, TypeError, "contact_time must be a finite time > 0"),
        ({"friction_time": float("inf")}, ValueError, "friction_time must be None or a finite"),
        ({"friction_time": "0.6"}, TypeError, "friction_time must be None or a finite"),
        ({"contact": 3}, TypeError, "contact must be 'calibrated' or 'default', got 3"),
        (
            {"contact": "default", "contact_time": 1e-3},
            ValueError,
            "contact_time applies only to contact='calibrated'",
        ),
    ],
)
def test_bad_settings_are_named(kwargs, error, message):
    with pytest.raises(error, match=message):
        E.bounce("mujoco", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **kwargs)
