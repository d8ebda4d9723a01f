"""What the 3D solvers refuse before solving: a body that cannot be a sphere (its radius
of gyration above a thin spherical shell's sqrt(2/3) R, the largest any sphere has), and a
grazing impact whose normal approach speed is below the smallest speed ``solve`` accepts
(1e-50 m/s; closer to zero the impulses divide by it and come out infinite or NaN).

The planar solver keeps accepting rings and spools: a disk, ring or spool in plane motion
is not a sphere, and its gyration may exceed the contact radius.
"""

import math
import warnings

import numpy as np
import pytest

from spinimpact import Body, solve, solve_pair, solve_sphere
from spinimpact.model.compliance import Walton
from spinimpact.model.presets import Ball

BALL = Body.solid_sphere(mass=1.0, radius=0.1)
SHELL = math.sqrt(2.0 / 3.0)


def _pair(b1, b2, velocity1=(0.0, 0.0, -1.0), **kw):
    return solve_pair(b1, b2, velocity1=velocity1, spin1=[0, 0, 0], velocity2=[0, 0, 0],
                      spin2=[0, 0, 0], normal=[0, 0, 1], mu=0.1, kappa=0.9, **kw)  # fmt: skip


NOT_SPHERES = {
    "ring preset": Body.ring(mass=1.0, radius=0.1),
    "solid disk preset": Body.solid_disk(mass=1.0, radius=0.1),  # rho = 0.707 R: < 0.816 R
    "gyration 1 m, radius 0.1 m": Body(mass=1.0, radius=0.1, gyration=1.0),
    "array, second too large": Body(mass=1.0, radius=0.1, gyration=[0.05, 0.09]),
}


@pytest.mark.parametrize("name", ["ring preset", "gyration 1 m, radius 0.1 m",
                                  "array, second too large"])  # fmt: skip
@pytest.mark.parametrize("velocity", [[1.0, -1.0, 0.0], [[1.0, -1.0, 0.0]]],
                         ids=["one impact", "array"])  # fmt: skip
def test_solve_sphere_refuses_a_gyration_above_a_thin_shells(name, velocity):
    body = NOT_SPHERES[name]
    with pytest.raises(ValueError, match=r"gyration must be <= sqrt\(2/3\) \* radius") as err:
        solve_sphere(body, velocity, [0, 0, 0], mu=0.2, kappa=0.5)
    text = str(err.value)
    bad = float(np.max(body.gyration))
    assert repr(bad) in text and "0.0816497" in text  # the value and the bound, in metres
    if np.ndim(body.gyration):
        assert "first offending index 1" in text


def test_the_tangential_laws_refuse_it_too():
    with pytest.raises(ValueError, match=r"gyration must be <= sqrt\(2/3\)"):
        solve_sphere(NOT_SPHERES["ring preset"], [1.0, -1.0, 0.0], [0, 0, 0], mu=0.2,
                     kappa=0.5, tangential=Walton(0.5))  # fmt: skip


def test_the_message_says_a_preset_is_not_a_sphere():
    with pytest.raises(ValueError, match="'ring'"):
        solve_sphere(NOT_SPHERES["ring preset"], [1.0, -1.0, 0.0], [0, 0, 0], mu=0.2, kappa=0.5)


@pytest.mark.parametrize("velocity1", [[0.0, 0.0, -1.0], [[0.0, 0.0, -1.0]]],
                         ids=["one impact", "array"])  # fmt: skip
def test_solve_pair_names_the_ball_that_is_not_a_sphere(velocity1):
    ring = NOT_SPHERES["ring preset"]
    with pytest.raises(ValueError, match=r"ball2's gyration must be <= sqrt\(2/3\)"):
        _pair(BALL, ring, velocity1=velocity1)
    with pytest.raises(ValueError, match=r"ball1's gyration must be <= sqrt\(2/3\)"):
        _pair(ring, BALL, velocity1=velocity1)


def test_ball_refuses_a_gyration_above_a_thin_shells():
    with pytest.raises(ValueError, match=r"gyration must be <= sqrt\(2/3\) \* radius.*0\.05"):
        Ball("odd", mass=0.1, radius=0.05, gyration=0.05, drag_coefficient=0.5)


@pytest.mark.parametrize("body", [
    Body.spherical_shell(mass=1.0, radius=0.1),
    Body(mass=1.0, radius=0.1, gyration=0.1 * SHELL),  # sqrt(2/3) R rounds either way
    Body(mass=1.0, radius=0.3, gyration=0.3 * SHELL),
    Body(mass=1.0, radius=0.1, gyration=[0.01, 0.05, 0.1 * SHELL]),
])  # fmt: skip
def test_a_thin_shell_and_anything_more_compact_is_a_sphere(body):
    imp = solve_sphere(body, [1.0, -1.0, 0.0], [0, 0, 0], mu=0.2, kappa=0.5)
    assert np.all(np.isfinite(imp.tau1))
    assert np.all(np.isfinite(_pair(body, body).tau1))
    g = float(np.max(body.gyration))
    Ball("shell", mass=1.0, radius=float(np.max(body.radius)), gyration=g, drag_coefficient=0.5)


@pytest.mark.parametrize("body", [Body.ring(mass=1.0, radius=0.1),
                                  Body(mass=0.2, radius=0.01, gyration=0.03)],
                         ids=["ring", "spool"])  # fmt: skip
def test_the_planar_solver_still_accepts_rings_and_spools(body):
    imp = solve(body, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5)
    assert np.isfinite(imp.tau1)


GRAZING = [-1e-300, -1e-51, -0.0, 1e-300]


@pytest.mark.parametrize("vy", GRAZING)
@pytest.mark.parametrize("array", [False, True], ids=["one impact", "array"])
def test_solve_sphere_refuses_a_grazing_impact_as_solve_refuses_vy(vy, array):
    """No ZeroDivisionError, and no NaN with a RuntimeWarning: a ValueError in solve's
    words for |vy| < 1e-50 ("must be <= -1e-50")."""
    v = [1.0, vy, 0.0]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match=r"normal velocity must be (<= -1e-50|< 0)"):
            solve_sphere(BALL, [v] if array else v, [0, 0, 10], mu=0.2, kappa=0.8)
        with pytest.raises(ValueError, match=r"normal velocity must be (<= -1e-50|< 0)"):
            _pair(BALL, BALL, velocity1=[[0.0, 1.0, vy]] if array else [0.0, 1.0, vy])
    with pytest.raises(ValueError, match=r"vy must be (<= -1e-50|< 0)"):
        solve(BALL, 1.0, vy, 10.0, mu=0.2, kappa=0.8)


def test_grazing_message_names_the_speed_and_the_smallest_accepted():
    with pytest.raises(ValueError) as err:
        solve_sphere(BALL, [1.0, -1e-300, 0.0], [0, 0, 10], mu=0.2, kappa=0.8)
    assert "<= -1e-50" in str(err.value) and "-1e-300" in str(err.value)


def test_the_smallest_accepted_approach_speed_is_solved():
    for v in ([1.0, -1e-50, 0.0], [[1.0, -1e-50, 0.0]]):
        imp = solve_sphere(BALL, v, [0, 0, 10], mu=0.2, kappa=0.8)
        assert np.all(np.isfinite(imp.energetic_restitution))
