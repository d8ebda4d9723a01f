"""A planar body or a pendulum whose contact point approaches slower than 1e-50 m/s is
refused as ``solve`` refuses ``|vy| < 1e-50`` (its impulses divide by the approach speed:
the one-impact path solved it silently, the array path returned NaN with a warning)."""

import warnings

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar

ROD = PlanarBody.rod(mass=1.0, length=1.0, angle=0.5)
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=0.5)


@pytest.mark.parametrize("array", [False, True], ids=["one impact", "array"])
def test_a_grazing_planar_body_is_refused(array):
    vy = np.array([-1e-300]) if array else -1e-300
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match=r"normal velocity must be <= -1e-50.*got"):
            solve_planar(ROD, 0.0, vy, 0.0, mu=0.2, kappa=0.5)
        with pytest.raises(ValueError, match=r"normal velocity must be <= -1e-50.*got"):
            solve_pendulum(PENDULUM, np.array([-1e-300]) if array else -1e-300, mu=0.2, kappa=0.5)


def test_the_slowest_accepted_approach_is_solved():
    imp = solve_planar(ROD, 0.0, -1e-49, 0.0, mu=0.2, kappa=0.5)
    assert np.isfinite(imp.tau1)
