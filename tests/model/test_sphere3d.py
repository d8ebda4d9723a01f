"""solve_sphere() and solve_pair(): the reductions the theory promises, conservation laws,
and bad input. (The independent integration of the 3D equations is tests/core/test_sphere3d.py.)"""

import re

import numpy as np
import pytest

from spinimpact import Body, Surface, solve, solve_pair, solve_sphere

from tests.cases import SPHERE_ZETAS, random_cases


def test_impacts_in_a_vertical_plane_are_the_2d_solve():
    c = random_cases(20_000, seed=51, zetas=SPHERE_ZETAS)
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])
    z = np.zeros_like(c["vx"])
    s = solve_sphere(body, np.stack([c["vx"], c["vy"], z], -1), np.stack([z, z, c["omega"]], -1),
                     mu=c["mu"], kappa=c["kappa"])  # fmt: skip
    assert np.array_equal(s.regime, imp.regime)
    speed = np.abs(c["vx"]) + np.abs(c["vy"]) + c["radius"] * np.abs(c["omega"])
    # the same closed forms through 3D vectors: agreement to a few roundings
    assert np.max(np.abs(s.after.vx - imp.after.vx) / speed) < 1e-15
    assert np.max(np.abs(s.after.vy - imp.after.vy) / speed) < 1e-15
    assert np.max(c["radius"] * np.abs(s.after.wz - imp.after.omega) / speed) < 1e-15
    assert not np.any(s.after.vz) and not np.any(s.after.wx) and not np.any(s.after.wy)
    for name in ("dissipated_energy", "work_restitution_tangential", "tau1", "tau_star"):
        np.testing.assert_array_equal(getattr(s, name), getattr(imp, name))
    np.testing.assert_array_equal(s.grips, imp.outcome.rolling)


def _random_3d(n, seed):
    rng = np.random.default_rng(seed)
    v = rng.normal(size=(n, 3)) * 3
    v[:, 1] = -np.abs(v[:, 1]) - 0.1
    w = rng.normal(size=(n, 3)) * 40
    return v, w, rng.uniform(0, 1.2, n), rng.uniform(0, 1, n)


def test_spin_about_the_normal_is_unchanged_and_slip_keeps_its_direction():
    v, w, mu, kappa = _random_3d(5000, 52)
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    s = solve_sphere(ball, v, w, mu=mu, kappa=kappa)
    np.testing.assert_array_equal(s.after.wy, s.before.wy)
    before, after = s.slip_before.array, s.slip_after.array
    cross = np.cross(before, after)
    assert np.max(np.abs(cross)) < 1e-12 * np.max(np.abs(before)) ** 2
    assert np.all(np.sum(before * after, -1) >= 0)  # never reversed
    assert np.all(s.dissipated_energy >= 0)
    ek = s.kinetic_energy_before - s.kinetic_energy_after
    np.testing.assert_allclose(ek, s.dissipated_energy, atol=1e-12 * np.max(ek))


def test_a_moving_tilted_surface_is_the_fixed_surface_in_its_frame():
    """A racket moving at V with normal n: in its frame (and axes) the ball meets a fixed
    plane; back in the ground frame the velocities differ by V."""
    v, w, mu, kappa = _random_3d(2000, 53)
    theta = 0.4
    rot = np.array([[np.cos(theta), -np.sin(theta), 0], [np.sin(theta), np.cos(theta), 0],
                    [0, 0, 1]])  # fmt: skip
    vel = np.array([3.0, -1.0, 2.0])
    surf = Surface(normal=rot @ [0, 1, 0], velocity=vel)
    ball = Body.solid_sphere(mass=0.046, radius=0.0214)
    moving = solve_sphere(ball, v @ rot.T + vel, w @ rot.T, mu=mu, kappa=kappa, surface=surf)
    fixed = solve_sphere(ball, v, w, mu=mu, kappa=kappa)
    np.testing.assert_allclose(moving.after.velocity, fixed.after.velocity @ rot.T + vel,
                               atol=1e-12)  # fmt: skip
    np.testing.assert_allclose(moving.after.spin, fixed.after.spin @ rot.T, atol=1e-10)
    np.testing.assert_allclose(moving.dissipated_energy, fixed.dissipated_energy, rtol=1e-12)
    assert np.array_equal(moving.regime, fixed.regime)


def test_pair_conserves_momentum_and_each_balls_angular_momentum_about_the_contact():
    rng = np.random.default_rng(54)
    n = 3000
    r1, r2 = rng.uniform(0.01, 0.1, n), rng.uniform(0.01, 0.1, n)
    b1 = Body(mass=rng.uniform(0.1, 2, n), radius=r1, gyration=r1 * rng.uniform(0.05, 0.8, n))
    b2 = Body(mass=rng.uniform(0.1, 2, n), radius=r2, gyration=r2 * rng.uniform(0.05, 0.8, n))
    nrm = rng.normal(size=(n, 3))
    nrm /= np.linalg.norm(nrm, axis=-1)[:, None]
    v1, v2 = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
    v1 -= (np.sum((v1 - v2) * nrm, -1) + 0.5 + np.abs(rng.normal(size=n)))[:, None] * nrm
    w1, w2 = rng.normal(size=(n, 3)) * 30, rng.normal(size=(n, 3)) * 30
    imp = solve_pair(b1, b2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=nrm,
                     mu=rng.uniform(0, 1, n), kappa=rng.uniform(0, 1, n))  # fmt: skip
    m1, m2 = b1.mass[:, None], b2.mass[:, None]
    p0 = m1 * v1 + m2 * v2
    p1 = m1 * imp.after1.velocity + m2 * imp.after2.velocity
    np.testing.assert_allclose(p1, p0, atol=1e-12 * np.max(np.abs(p0)))
    balls = ((b1, imp.before1, imp.after1, -1), (b2, imp.before2, imp.after2, 1))
    for body, before, after, sign in balls:
        r = sign * body.radius[:, None] * nrm  # contact point from the centre
        j = body.inertia[:, None]

        def about_contact(state, r=r, j=j, body=body):
            # L = J w + m (centre - contact) x v
            return j * state.spin + body.mass[:, None] * np.cross(-r, state.velocity)

        l0, l1 = about_contact(before), about_contact(after)
        np.testing.assert_allclose(l1, l0, atol=1e-10 * np.max(np.abs(l0)))
    assert np.all(imp.dissipated_energy >= 0)
    ek = imp.kinetic_energy_before - imp.kinetic_energy_after
    np.testing.assert_allclose(
        ek, imp.dissipated_energy, atol=1e-12 * np.max(imp.kinetic_energy_before)
    )


def test_identical_balls_with_opposite_spins_meet_head_on():
    """A DEM benchmark: no relative slip at the contact, so the spins are kept and the
    velocities reverse (kappa = 1)."""
    b = Body.solid_sphere(mass=1.0, radius=0.1)
    imp = solve_pair(b, b, velocity1=[0, 0, -1.0], spin1=[5.0, 0, 0], velocity2=[0, 0, 1.0],
                     spin2=[-5.0, 0, 0], normal=[0, 0, 1], mu=0.3, kappa=1.0)  # fmt: skip
    np.testing.assert_allclose(imp.after1.velocity, [0, 0, 1.0], atol=1e-15)
    np.testing.assert_allclose(imp.after2.velocity, [0, 0, -1.0], atol=1e-15)
    np.testing.assert_array_equal(imp.after1.spin, [5.0, 0, 0])
    np.testing.assert_array_equal(imp.after2.spin, [-5.0, 0, 0])
    assert imp.regime == "no-slip"


def test_a_ball_against_an_immovable_ball_is_the_ball_on_a_plane():
    v, w, mu, kappa = _random_3d(3000, 55)
    ball = Body.solid_sphere(mass=0.2, radius=0.03)
    wall = Body.solid_sphere(mass=1e40, radius=1.0)  # 1/m and R^2/J below rounding
    p = solve_pair(ball, wall, velocity1=v, spin1=w, velocity2=[0, 0, 0], spin2=[0, 0, 0],
                   normal=[0, 1, 0], mu=mu, kappa=kappa)  # fmt: skip
    s = solve_sphere(ball, v, w, mu=mu, kappa=kappa)
    assert np.array_equal(p.regime, s.regime)
    np.testing.assert_allclose(p.after1.velocity, s.after.velocity, atol=1e-13)
    np.testing.assert_allclose(p.after1.spin, s.after.spin, atol=1e-10)


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (lambda b: solve_sphere(b, [1, -1], [0, 0, 0], mu=0.1, kappa=0.5), ValueError,
         "velocity must be a 3-vector"),
        (lambda b: solve_sphere(b, [1, -1, 0], [0, 0, np.nan], mu=0.1, kappa=0.5), ValueError,
         "spin must be finite"),
        (lambda b: solve_sphere(b, [1, 1, 0], [0, 0, 0], mu=0.1, kappa=0.5), ValueError,
         "must be < 0 (the sphere must approach the surface)"),
        (lambda b: Surface(normal=[0, 0, 0]), ValueError, "the length of normal must be > 0"),
        (lambda b: solve_sphere("ball", [1, -1, 0], [0, 0, 0], mu=0.1, kappa=0.5), TypeError,
         "body must be a spinimpact.Body"),
        (lambda b: solve_pair(b, b, velocity1=[0, 0, -1], spin1=[0, 0, 0], velocity2=[0, 0, 0],
                              spin2=[0, 0, 0], centres=([0, 0, 0], [0, 0, -0.01]), mu=0.1,
                              kappa=0.5), ValueError, "the balls overlap"),
        (lambda b: solve_pair(b, b, velocity1=[0, 0, -1], spin1=[0, 0, 0], velocity2=[0, 0, 0],
                              spin2=[0, 0, 0], centres=([0, 0, 0], [0, 0, -1.0]), mu=0.1,
                              kappa=0.5), ValueError, "the balls do not touch"),
        (lambda b: solve_pair(b, b, velocity1=[0, 0, 1], spin1=[0, 0, 0], velocity2=[0, 0, 0],
                              spin2=[0, 0, 0], normal=[0, 0, 1], mu=0.1, kappa=0.5), ValueError,
         "the balls must approach each other"),
    ],
)  # fmt: skip
def test_bad_input_is_named(call, error, message):
    with pytest.raises(error, match=re.escape(message)):
        call(Body.solid_sphere(mass=0.1, radius=0.02))


def test_indexing_selects_the_body_of_each_impact():
    """SphereImpact[i] and PairImpact[i] index an array-valued body with the impacts (the
    Result base does it for every body field), so each selected impact carries the body it
    was solved with and equals that impact solved alone."""
    body = Body(mass=[1.0, 2.0], radius=0.1, gyration=[0.05, 0.07])
    v = [[[1.0, -1.0, 0.0]], [[2.0, -1.0, 0.5]], [[3.0, -2.0, 0.0]]]
    imp = solve_sphere(body, v, [0.0, 0.0, 10.0], mu=0.4, kappa=0.6)
    assert imp.shape == (3, 2)
    picked = imp[2, 1]
    assert picked.body.mass == 2.0 and picked.body.gyration == 0.07
    one = solve_sphere(Body(mass=2.0, radius=0.1, gyration=0.07), v[2][0], [0.0, 0.0, 10.0],
                       mu=0.4, kappa=0.6)  # fmt: skip
    assert picked.body.zeta == one.body.zeta
    np.testing.assert_array_equal(picked.after.velocity, one.after.velocity)
    assert list(imp[1].body.mass) == [1.0, 2.0]
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    pair = solve_pair(body, ball, velocity1=[[1.0, 0.0, 0.0]], spin1=[0.0, 0.0, 0.0],
                      velocity2=[-1.0, 0.0, 0.0], spin2=[0.0, 0.0, 0.0],
                      normal=[-1.0, 0.0, 0.0], mu=0.3, kappa=0.8)  # fmt: skip
    assert pair.shape == (2,) and pair[1].ball1.mass == 2.0 and pair[1].ball2 is ball
