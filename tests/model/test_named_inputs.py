"""Errors name what the caller gave: a quantity derived from the inputs is refused in
terms of the inputs it comes from, and a callback that cannot be called is refused before
the run starts."""

import pytest

from spinimpact import Body, flight
from spinimpact.dynamics import LinearContact, simulate
from spinimpact.io.sweep import Sweep, parse_axis, run_sweep


def test_simulate_names_the_mass_and_size_behind_a_tiny_inertia():
    """It said "inertia must be >= 1e-50": no parameter of simulate is called inertia."""
    body = Body.solid_disk(mass=1e-50, radius=1e-49)
    with pytest.raises(ValueError) as err:
        simulate(body, 1.0, -1.0, 0.0, mu=0.3, contact=LinearContact(stiffness=1e5))
    text = str(err.value)
    assert "mass * gyration**2" in text and ">= 1e-50" in text
    assert "mass 1e-50" in text and "radius 1e-49" in text


@pytest.mark.parametrize("progress", [5, "bar", [1]])
def test_flight_refuses_a_progress_it_cannot_call(progress):
    """It failed after the first chunk with "'int' object is not callable"."""
    with pytest.raises(TypeError, match=r"progress must be a callable progress\(done, total\)"):
        flight("tennis", "hard", speed=20.0, angle=10.0, progress=progress)


def test_run_sweep_refuses_a_progress_it_cannot_call():
    axes = dict(vx="-2:2:5", vy="-1", omega="0", mu="0.5", kappa="0.8")
    sweep = Sweep(
        Body.solid_sphere(mass=1.0, radius=0.1), {k: parse_axis(k, v) for k, v in axes.items()}
    )
    with pytest.raises(
        TypeError, match=r"progress must be a callable progress\(done, total\), or None, got 5"
    ):
        run_sweep(sweep, progress=5)
