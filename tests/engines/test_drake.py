"""spinimpact.engines.drake: Hunt-Crossley dissipation calibrated to kappa, the spin's
rebound beside the exact answer, and settings checked by name.

Skipped, with the reason, where Drake (``pip install drake``, the [engines] extra) is
not installed.
"""

import numpy as np
import pytest

from spinimpact import engines as E
from spinimpact.engines import drake as engine_drake

from .bodies import SPHERE, needs


@pytest.fixture(autouse=True)
def _drake():
    needs("drake")


def test_calibrated_head_on_restitution_is_kappa_at_any_speed():
    """A frictionless head-on bounce leaves at kappa |vy| to the calibration's tolerance
    (1e-5; measured 1.9e-6 at kappa 0.3): the dissipation calibrated at 1 m/s carries
    over to other speeds as d = c / |vy|, as a linear Hunt-Crossley spring predicts."""
    kappa = np.array([0.3, 0.5, 0.8, 0.9])
    for vy in (-0.5, -4.0):
        run = E.bounce("drake", SPHERE, 0.0, vy, 0.0, mu=0.0, kappa=kappa)
        np.testing.assert_allclose(run.vy / -vy, kappa, rtol=0, atol=engine_drake._KAPPA_TOLERANCE)
        np.testing.assert_array_equal(run.vx, 0.0)
    run = E.bounce("drake", SPHERE, 0.0, [-1.0, -2.0], 0.0, mu=0.3, kappa=0.5)
    d = run.settings["dissipation"]
    assert d.shape == (2,) and d[0] == pytest.approx(2.0 * d[1], rel=1e-12)  # d |vy| fixed
    assert run.settings["approximation"] == "lagged"
    assert run.settings["time_step"] == pytest.approx(run.settings["contact_time"] / 100)


def test_drakes_default_contact_ignores_kappa():
    """Drake's own point contact (its heuristic stiffness and dissipation, 1 ms steps)
    leaves at about 0.02 m/s whatever kappa: nearly no bounce."""
    run = E.bounce("drake", SPHERE, 0.0, -1.0, 0.0, mu=0.3, kappa=[0.3, 0.9], contact="default")
    assert np.ptp(run.vy) < 1e-9
    assert 0 < run.vy[0] < 0.05
    assert run.settings["time_step"] == 1e-3 and "dissipation" not in run.settings


def test_spinning_ball_rebounds_near_the_exact_answer():
    """Backspin and topspin, sticking and sliding (mu 0.3 and 0.05): the rebound's vx and
    rim speed R omega are within 1e-3 of the speed scale of the exact answer (measured:
    at most 8.9e-4, in the case that sticks during restitution), and vy within 2e-5
    (measured 8.7e-6). The rest is the compliant contact: its force acts at a point
    sunk half the penetration below the sphere's surface, and friction is regularized."""
    vx = np.tile([1.0, 1.0, -2.0, 3.0, 0.0], 2)
    rim = np.tile([-3.0, 2.0, 3.0, -1.0, 2.0], 2)
    mu = np.repeat([0.3, 0.05], 5)
    run = E.bounce("drake", SPHERE, vx, -2.0, rim / SPHERE.radius, mu=mu, kappa=0.5)
    regimes = set(np.asarray(run.exact.regime).astype(str))
    assert {"slip", "stick-compression", "stick-restitution"} <= regimes
    err = run.errors()
    assert err["vx"].max() < 1e-3 and err["omega"].max() < 1e-3
    assert err["vy"].max() < 2e-5
    # and friction did act: the spin changed by far more than the error
    assert np.all(np.abs(run.omega - rim / SPHERE.radius) * SPHERE.radius / run.scale > 0.05)


def test_scenes_of_any_size_give_the_same_rebounds():
    """The impacts are split into scenes of scene_size spheres; Drake solves each scene's
    contacts together, so the split changes a rebound only by the solver's tolerance
    (measured: 3.5e-6 of the speed scale)."""
    vx, omega = np.array([1.0, -2.0, 3.0, 0.0, 2.0]), np.array([-30.0, 20.0, 0.0, 20.0, 5.0])
    one = E.bounce("drake", SPHERE, vx, -2.0, omega, mu=0.3, kappa=0.5)
    split = E.bounce("drake", SPHERE, vx, -2.0, omega, mu=0.3, kappa=0.5, scene_size=2)
    assert split.settings["scene_size"] == 2 and one.settings["scene_size"] == 64
    for a, b in ((one.vx, split.vx), (one.vy, split.vy), (0.1 * one.omega, 0.1 * split.omega)):
        assert np.max(np.abs(a - b) / one.scale) < 1e-5


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        ({"time_step": float("inf")}, ValueError, "time_step must be a finite time > 0"),
        ({"time_step": "1e-5"}, TypeError, "time_step must be a finite time > 0"),
        ({"contact_time": 0.0}, ValueError, "contact_time must be a finite time > 0"),
        ({"contact_time": None}, TypeError, "contact_time must be a finite time > 0"),
        ({"approximation": "sap"}, ValueError, "approximation must be 'lagged' or 'similar'"),
        ({"approximation": 1}, TypeError, "approximation must be 'lagged' or 'similar'"),
        ({"contact": "hard"}, ValueError, "contact must be 'calibrated' or 'default'"),
        ({"scene_size": 0}, ValueError, "scene_size must be a whole number >= 1"),
        ({"scene_size": 8.0}, TypeError, "scene_size must be a whole number >= 1"),
        ({"stiffness": 1e6}, ValueError, "unknown drake setting"),
        (
            {"contact": "default", "contact_time": 1e-3},
            ValueError,
            "contact_time applies only to contact='calibrated'",
        ),
        (
            {"contact_time": 1e-4, "time_step": 1e-5},
            ValueError,
            "contact_time must span at least 20 time steps",
        ),
    ],
)
def test_bad_settings_are_named(kwargs, error, message):
    with pytest.raises(error, match=message):
        E.bounce("drake", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.5, **kwargs)


def test_unreachable_kappa_is_named():
    """The implicit steps lose energy even without dissipation (about 5 % of the rebound
    speed at 100 steps a contact), and a sphere damped too hard stays on the surface."""
    with pytest.raises(ValueError, match=r"kappa must be below 0\.9\d+ for a calibrated Drake"):
        E.bounce("drake", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=0.99)
    with pytest.raises(ValueError, match=r"kappa must be in \(0, 1\) for a calibrated Drake"):
        E.bounce("drake", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=1.0)
    with pytest.raises(ValueError, match="kappa = 0.0001 cannot be reached"):
        E.bounce("drake", SPHERE, 1.0, -1.0, 0.0, mu=0.3, kappa=1e-4)


def test_drake_has_no_searched_settings():
    """calibrate, restitution_settings and configure search PyBullet's and MuJoCo's own
    settings only: Drake is refused by name, not run as another engine."""
    with pytest.raises(ValueError, match="engine must be one of pybullet, mujoco; got 'drake'"):
        E.restitution_settings("drake", 0.5, 1.0, 1e-3, SPHERE)
    with pytest.raises(ValueError, match="engine must be one of pybullet, mujoco; got 'drake'"):
        E.configure.defaults("drake")
