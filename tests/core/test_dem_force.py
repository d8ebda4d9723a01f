"""The DEM contact force against the impulse-space laws it time-steps, and the DEM loop.

Each tangential model of :mod:`spinimpact.core.dem_force` has an independent solution of the
same impact: the event-located integration of :func:`spinimpact.dynamics.simulate` with the
same spring rule (history, incremental, total, scaled) and :func:`spinimpact.core.mdr.mdr_slip`
for micro-slip. The DEM loop's rebound must converge to it as the step shrinks.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from spinimpact import Body, dem
from spinimpact.core import dem_force, dem_loop
from spinimpact.core.mdr import mdr_slip
from spinimpact.dynamics import HertzContact, Mindlin, simulate

E, NU, RHO, R, VN, MU = 7.0e10, 0.33, 2700.0, 0.1, 0.2, 0.4
SPRINGS = {"history": "history", "incremental": "incremental", "total": "total",
           "scaled": "scaled"}  # fmt: skip


def _force(model, cells=4096, **options):
    return dem.ContactForce.sphere_on_wall(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                           density=RHO, mu=MU, model=model, cells=cells,
                                           **options)  # fmt: skip


def _reference(model, omega):
    force = _force(model)
    if model == "micro-slip":
        ratio = 4.0 * force.shear_modulus / force.modulus
        slip, _ = mdr_slip(R * omega, -VN, 3.5, MU, 1.0, ratio, springs=1024, steps=8192)
        return float(slip)
    body = Body.solid_sphere(mass=force.mass, radius=R)
    law = Mindlin(poisson_ratio=NU, spring=SPRINGS[model])
    sim = simulate(body, 0.0, -VN, omega, mu=MU, contact=HertzContact(E, NU, R),
                   tangential=law, rtol=1e-12)  # fmt: skip
    return float(sim.after.vx + R * sim.after.omega)


@pytest.mark.parametrize("model", list(dem.MODELS))
def test_converges_to_the_impulse_space_law(model):
    """Backspin u-/vn = 1 (the contact sticks, slips and reverses): the slip after the
    impact approaches the independent solution by more than 181 times over five halvings of
    the step (an order of at least 1.5), to within 1e-6 of vn."""
    omega = VN / R
    ref = _reference(model, omega)
    force = _force(model)
    ball = Body.solid_sphere(mass=force.mass, radius=R)
    errors = []
    for steps in (100, 3200):
        run = dem.wall_impact(force, ball, 0.0, -VN, omega, dt=force.time_scale(VN) / steps)
        errors.append(abs(float(run.vx) + R * float(run.omega) - ref) / VN)
    assert errors[1] < 1e-6
    assert errors[0] / errors[1] > 2.0**7.5


def test_damped_micro_slip_converges_to_the_impulse_space_law():
    """With Hunt-Crossley damping (e = 0.5) and the friction limit on the whole normal
    force, as :func:`spinimpact.core.mdr.mdr_slip` takes it: the slip after the impact
    converges at second order too (the loop extrapolates the rates to the new step;
    measured 1,090 times over five halvings), and the restitution is 0.5 to 1e-6."""
    omega = VN / R
    force = _force("micro-slip", restitution=0.5, damping="hunt-crossley", speed=VN,
                   friction_limit="total")  # fmt: skip
    ratio = 4.0 * force.shear_modulus / force.modulus
    ref = float(mdr_slip(R * omega, -VN, 3.5, MU, 0.5, ratio, springs=2048, steps=16384)[0])
    ball = Body.solid_sphere(mass=force.mass, radius=R)
    errors = []
    for steps in (100, 3200):
        run = dem.wall_impact(force, ball, 0.0, -VN, omega, dt=force.time_scale(VN) / steps)
        errors.append(abs(float(run.vx) + R * float(run.omega) - ref) / VN)
    assert float(run.vy) / VN == pytest.approx(0.5, abs=1e-6)
    assert errors[1] < 1e-6
    assert errors[0] / errors[1] > 2.0**7.5


def test_few_cells_keep_the_history():
    """64 cells (merged as the contact grows over 2,000 steps) give the rebound of 65,536
    within 1e-3 of the incident slip, at stick (chi = 10) and at reversal (chi = 1.5)."""
    ball = Body.solid_sphere(mass=_force("micro-slip").mass, radius=R)
    for chi in (1.5, 10.0):
        u0 = 3.5 * MU * 2.0 * VN / chi
        out = []
        for cells in (64, 1 << 16):
            force = _force("micro-slip", cells=cells)
            run = dem.wall_impact(force, ball, 0.0, -VN, u0 / R,
                                  dt=force.time_scale(VN) / 4000)  # fmt: skip
            out.append(float(run.vx) + R * float(run.omega))
        assert abs(out[0] - out[1]) < 1e-3 * u0


def test_compiled_loop_equals_the_python_loop():
    """The Numba-compiled loop and the plain Python functions give the same rebound to
    rounding (Numba may contract differently; 1e-12 of the speed)."""
    from spinimpact.core import dem_law

    force = _force("micro-slip", cells=64, restitution=0.5, friction_limit="total",
                   tangential_damping=0.2)  # fmt: skip
    ball = Body.solid_sphere(mass=force.mass, radius=R)
    args = (float(ball.mass), R, float(ball.mass) * R * R * 0.4, 0.0, -VN, 2.0,
            force.time_scale(VN) / 300, 10_000, dem_loop.empty_trace())  # fmt: skip
    a = dem_law.wall_impact(force.parameters(), force.new_state(), *args)
    b = dem_loop.wall_impact(force.parameters(), force.new_state(), *args)
    assert a[3] == b[3]
    np.testing.assert_allclose(a[:3], b[:3], rtol=0, atol=1e-12)


def test_two_spheres_are_the_reduced_sphere_on_a_wall():
    """Two equal spheres meeting head-on with equal spins: the spheres' changes are
    symmetric (to rounding), and the relative motion is that of the reduced body (half the
    mass and radius, same zeta) on a wall with the pair's force, to 2e-3 (speed: 1e-4; the pair's
    contact normal turns a little as the centres move sideways; the wall's does not)."""
    ball = Body.solid_sphere(mass=4.0 / 3.0 * math.pi * R**3 * RHO, radius=R)
    pair = dem.ContactForce.two_spheres(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                        density=RHO, mu=MU)  # fmt: skip
    dt = pair.time_scale(2 * VN) / 1000
    run = dem.pair_impact(pair, (ball, ball), ((0.0, VN, 1.0), (0.0, -VN, 1.0)), dt=dt)
    vx, vy, omega = (np.asarray(x) for x in (run.vx, run.vy, run.omega))
    assert vx[0] == -vx[1] and vy[0] == -vy[1] and omega[0] == omega[1]
    # the reduced body: half the mass and, as the force's, half the radius (zeta stays 7/2);
    # its spin 4 gives the pair's incident slip R (omega_1 + omega_2) = 2 R
    reduced = Body.solid_sphere(mass=float(ball.mass) / 2, radius=R / 2)
    wall = dem.wall_impact(pair, reduced, 0.0, -2 * VN, 4.0, dt=dt)
    assert 4 * omega[0] == pytest.approx(float(wall.omega), rel=2e-3)
    # the tangent t = (-n_y, n_x) is -x here: the relative slide along t is vx_2 - vx_1
    assert vx[1] - vx[0] == pytest.approx(float(wall.vx), rel=2e-3)
    assert math.hypot(vx[0] - vx[1], vy[1] - vy[0]) == pytest.approx(
        math.hypot(float(wall.vx), float(wall.vy)), rel=1e-4
    )
    assert run.steps == wall.steps


def test_tangential_damper_explains_chung_ooi_test6():
    """Chung & Ooi's Test 6 (e = 0.5, backspin): with a viscous tangential damper of the
    normal damping's ratio (as Kratos and LIGGGHTS add it) the contact point's reversal
    stays near the reference curve's (largest beta 0.119 at chi > 1, measured 0.143);
    without it every elastic model reverses strongly (measured 0.43 to 0.70)."""
    from benchmarks import dem_chung_ooi as bench

    chi = np.array([1.45, 1.74, 2.09, 3.0])
    damped = bench.test6_beta(bench.TEST6_MODELS[
        "scaled, viscous, limit mu N, tangential damper (Kratos-like)"], chi)  # fmt: skip
    assert 0.1 < damped.max() < 0.16
    for label in ("micro-slip, viscous, limit mu N_el", "scaled, viscous, limit mu N"):
        assert bench.test6_beta(bench.TEST6_MODELS[label], chi).max() > 0.35


def test_parameters_round_trip():
    """The parameter array holds what the ContactForce says."""
    force = _force("scaled", restitution=0.5, friction_limit="total", tangential_damping=0.1)
    p = force.parameters()
    assert p[dem_force.P_MODEL] == dem_force.SCALED
    assert p[dem_force.P_DAMPING] == dem_force.VISCOUS
    assert p[dem_force.P_NORMAL_COEF] == pytest.approx(dem.viscous_damping(0.5))
    assert p[dem_force.P_LIMIT_TOTAL] == 1.0 and p[dem_force.P_TANGENT_COEF] == 0.1
    assert force.new_state().size == dem_force.state_size(4096)


def test_refused_inputs_name_what_is_wrong():
    """A step too coarse for the contact, spheres that are not the force's, a state that
    does not fit the parameters, NaN, and a displacement that is not two numbers."""
    force = _force("micro-slip", cells=32)
    ball = Body.solid_sphere(mass=force.mass, radius=R)
    with pytest.raises(ValueError, match="dt = .* tenth of the contact's duration"):
        dem.wall_impact(force, ball, 0.0, -VN, 0.0, dt=force.time_scale(VN) / 5)
    pair = dem.ContactForce.two_spheres(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                        density=RHO, mu=MU)  # fmt: skip
    dt = pair.time_scale(2 * VN) / 100
    small = Body.solid_sphere(mass=1.0, radius=R)
    with pytest.raises(ValueError, match="bodies must be the force's spheres"):
        dem.pair_impact(pair, (ball, small), ((0, VN, 0), (0, -VN, 0)), dt=dt)
    with pytest.raises(TypeError, match="bodies must be two Body"):
        dem.pair_impact(pair, (ball,), ((0, VN, 0), (0, -VN, 0)), dt=dt)
    with pytest.raises(TypeError, match="velocities must be"):
        dem.pair_impact(pair, (ball, ball), (0, VN, 0), dt=dt)
    with pytest.raises(ValueError, match=r"vy of sphere 2 \(0.1\)"):
        dem.pair_impact(pair, (ball, ball), ((0, 0.0, 0), (0, 0.1, 0)), dt=dt)
    with pytest.raises(ValueError, match="state must hold 101 floats"):
        force.step(np.zeros(11), 1e-6, 0.0, (0.0, 0.0))
    with pytest.raises(TypeError, match="state must be a 1-D float64"):
        force.step(np.zeros(101, dtype=np.float32), 1e-6, 0.0, (0.0, 0.0))
    with pytest.raises(TypeError, match="displacement must be two numbers"):
        force.step(force.new_state(), 1e-6, 0.0, 1e-7)
    with pytest.raises(ValueError, match="overlap must be finite"):
        force.step(force.new_state(), float("nan"), 0.0, (0.0, 0.0))
    # the compiled path refuses them too, without the model layer's checks
    with pytest.raises(ValueError, match="state is smaller"):
        dem.contact_force(np.zeros(11), force.parameters(), 1e-6, 0.0, 0.0, 0.0, 0.0, 0.0)
    with pytest.raises(ValueError, match="NaN"):
        dem.contact_force(force.new_state(), force.parameters(), float("nan"), 0.0, 0.0, 0.0,
                          0.0, 0.0)  # fmt: skip
    with pytest.raises(ValueError, match="restitution must be 1 with damping='none'"):
        dem.ContactForce.sphere_on_wall(youngs_modulus=E, poisson_ratio=NU, radius=R,
                                        density=RHO, mu=MU, restitution=0.5,
                                        damping="none")  # fmt: skip
    assert dem.viscous_damping(0.5) == dem.viscous_damping(np.float64(0.5))
    with pytest.raises(ValueError, match="single number"):
        dem.viscous_damping([0.5])
