"""solve(..., tangential=MindlinDeresiewicz(...)) and solve_sphere with it: the fields by
their definitions, ratios only, energy, the 3D seam, parameters and errors."""

import numpy as np
import pytest

from spinimpact import Body, CompliantImpact, MindlinDeresiewicz, solve, solve_sphere
from spinimpact.core.mdr import mdr_slip

FAST = {"springs": 48, "steps": 384}


def test_the_law_on_the_seam():
    ball = Body.solid_sphere(mass=0.2, radius=0.03)
    law = MindlinDeresiewicz(poisson_ratio=0.3, **FAST)
    vx = np.linspace(-4.0, 4.0, 41)
    imp = solve(ball, vx, -2.0, 5.0, mu=0.25, kappa=0.8, tangential=law)
    assert isinstance(imp, CompliantImpact)
    slip = vx + 0.03 * 5.0
    expected, _ = mdr_slip(slip, -2.0, 3.5, 0.25, 0.8, law.stiffness_ratio, **FAST)
    np.testing.assert_array_equal(imp.slip_after, expected)
    np.testing.assert_allclose(imp.after.vy, 1.6, rtol=1e-15)
    assert (np.abs(imp.tangential_restitution) <= 1.0).all()  # energy never increases
    assert (imp.dissipated_energy >= -1e-12 * imp.kinetic_energy_before).all()
    assert set(imp.regime) == {"stick", "slip-reversal", "slip"}
    # the friction impulse never exceeds Coulomb's over the whole normal impulse
    assert (np.abs(imp.tangential_impulse) <= 0.25 * imp.tau1 * (1 + 1e-6)).all()


def test_the_rebound_depends_on_ratios_only():
    law = MindlinDeresiewicz(poisson_ratio=0.23, **FAST)
    ball = Body.solid_sphere(mass=0.01, radius=0.002)
    slow = solve(ball, 0.3, -1.0, 0.0, mu=0.1, kappa=0.9, tangential=law)
    fast = solve(Body.solid_sphere(mass=5.0, radius=0.2), 3.0, -10.0, 0.0, mu=0.1, kappa=0.9,
                 tangential=law)  # fmt: skip
    assert float(fast.tangential_restitution) == pytest.approx(
        float(slow.tangential_restitution), rel=1e-12
    )


def test_a_sphere_in_3d_takes_the_law_along_its_slip():
    law = MindlinDeresiewicz(poisson_ratio=0.23, **FAST)
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    sphere = solve_sphere(ball, [0.6, -2.0, 0.8], [0.0, 0.0, 0.0], mu=0.2, kappa=0.9,
                          tangential=law)  # fmt: skip
    flat = solve(ball, 1.0, -2.0, 0.0, mu=0.2, kappa=0.9, tangential=law)
    assert float(sphere.tangential_restitution) == pytest.approx(
        float(flat.tangential_restitution), rel=1e-9
    )


def test_parameters_and_errors():
    law = MindlinDeresiewicz(poisson_ratio=0.25)
    assert law.stiffness_ratio == pytest.approx(1.5 / 1.75, rel=1e-15)
    assert law.to_dict() == {"law": "mindlin-deresiewicz", "poisson_ratio": 0.25,
                             "stiffness_ratio": law.stiffness_ratio, "springs": 256,
                             "steps": 2048, "method": "table"}  # fmt: skip
    assert repr(law) == "MindlinDeresiewicz(poisson_ratio=0.25)"
    assert repr(MindlinDeresiewicz(stiffness_ratio=2.0, springs=8, steps=64)) == (
        "MindlinDeresiewicz(stiffness_ratio=2.0, springs=8, steps=64)"
    )
    for kwargs, error, message in [
        ({}, TypeError, "MindlinDeresiewicz takes one of poisson_ratio and stiffness_ratio"),
        ({"poisson_ratio": 0.7}, ValueError, r"poisson_ratio must be in \(-1, 0.5\], got 0.7"),
        ({"stiffness_ratio": 0.0}, ValueError, "stiffness_ratio must be in"),
        ({"poisson_ratio": 0.3, "springs": 0}, ValueError, "springs must be at least 1, got 0"),
        ({"poisson_ratio": 0.3, "steps": 4}, ValueError, "steps must be at least 8, got 4"),
        ({"poisson_ratio": 0.3, "springs": 2.5}, TypeError, "springs"),
    ]:
        with pytest.raises(error, match=message):
            MindlinDeresiewicz(**kwargs)
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    law = MindlinDeresiewicz(poisson_ratio=0.3, **FAST)
    with pytest.raises(ValueError, match=r"kappa must be > 0 under MindlinDeresiewicz.*got "
                       r"0.0 \(first offending index 1\)"):  # fmt: skip
        solve(ball, 1.0, -1.0, 0.0, mu=0.3, kappa=np.array([0.9, 0.0]), tangential=law)
    with pytest.raises(ValueError, match="kappa must be > 0 under MindlinDeresiewicz"):
        solve_sphere(ball, [1.0, -1.0, 0.0], [0.0, 0.0, 0.0], mu=0.3, kappa=0.0, tangential=law)


def test_limits_of_the_resolution_and_the_class_itself():
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    stiff = MindlinDeresiewicz(stiffness_ratio=1e5)  # a period is 1/340 of the contact
    with pytest.raises(ValueError, match=r"steps = 2048 do not resolve .* use steps >= 60"):
        solve(ball, 0.5, -1.0, 0.0, mu=0.3, kappa=1.0, tangential=stiff)
    with pytest.raises(ValueError, match="springs \\* steps must be at most 16777216"):
        MindlinDeresiewicz(poisson_ratio=0.2, steps=10**9)
    with pytest.raises(TypeError, match="an instance such as MindlinDeresiewicz"):
        solve(ball, 1.0, -3.0, 0.0, mu=0.1, kappa=0.9, tangential=MindlinDeresiewicz)
