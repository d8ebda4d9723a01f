"""Any rigid body in 3D (``solve_rigid``, ``solve_contact``): against the sphere, planar and
pair solvers, the energy identities, the three laws' energy, the re-slide direction, and
the refusals. The comparison with an independent integration written from the theory
alone is ``tests/core/test_rigid3d_against_reference.py``."""

import math
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from spinimpact import (
    Body,
    PlanarBody,
    RigidBody,
    Surface,
    solve_contact,
    solve_pair,
    solve_planar,
    solve_rigid,
    solve_sphere,
)
from spinimpact.core import rigid3d
from spinimpact.core.scalar_rigid import reslide_direction

LAWS = ("poisson", "newton", "energetic")


def quaternions(rng, n):
    q = rng.normal(size=(n, 4))
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def approaching(rng, body, n, speed=3.0):
    """Velocities and spins of ``n`` impacts whose contact point approaches y = 0."""
    v = rng.normal(size=(n, 3)) * speed
    w = rng.normal(size=(n, 3)) * speed / 0.3
    contact = v + np.cross(w, body.offset)
    v[:, 1] -= np.maximum(contact[:, 1], 0) + 0.1 * speed  # the contact point moves down
    return v, w


def dice(rng, n):
    size = rng.uniform(0.2, 1.0, (n, 3))
    corner = rng.choice([-1.0, 1.0], (n, 3))
    return RigidBody.cuboid(rng.uniform(0.1, 2.0, n), size, corner, quaternions(rng, n))


@pytest.mark.parametrize("law", LAWS)
def test_a_sphere_equals_solve_sphere(law):
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    moment = ball.mass * ball.gyration**2
    body = RigidBody.principal(ball.mass, [moment] * 3, [0.0, -ball.radius, 0.0])
    rng = np.random.default_rng(3)
    v, w = approaching(rng, body, 500)
    a = solve_sphere(ball, v, w, mu=0.6, kappa=0.75)  # all three laws agree for a sphere
    b = solve_rigid(body, v, w, mu=0.6, kappa=0.75, law=law)
    after = np.stack([a.after.vx, a.after.vy, a.after.vz], -1)
    spin = np.stack([a.after.wx, a.after.wy, a.after.wz], -1)
    assert np.abs(after - b.velocity).max() <= 1e-12 * np.abs(v).max()
    assert np.abs(spin - b.spin).max() * ball.radius <= 1e-12 * np.abs(v).max()
    assert set(b.regime) == {"slide", "slide-stick"}


@pytest.mark.parametrize("law", LAWS)
def test_a_planar_rod_equals_solve_planar(law):
    rng = np.random.default_rng(4)
    n = 2000
    angle = rng.uniform(0.1, math.pi - 0.1, n)
    rods = PlanarBody.rod(mass=1.0, length=1.0, angle=angle)
    vx, vy, om = rng.normal(size=n), -rng.uniform(0.2, 2, n), rng.normal(size=n) * 3
    keep = vy + om * rods.rx < -0.05
    vx, vy, om, angle = vx[keep], vy[keep], om[keep], angle[keep]
    rods = PlanarBody.rod(mass=1.0, length=1.0, angle=angle)
    moments = np.stack([np.full(angle.size, 0.5), np.full(angle.size, 0.5),
                        np.full(angle.size, rods.inertia)], -1)  # fmt: skip
    body = RigidBody.principal(1.0, moments, np.stack([rods.rx, rods.ry, 0 * angle], -1))
    zero = np.zeros_like(vx)
    a = solve_planar(rods, vx, vy, om, mu=0.4, kappa=0.6, law=law)
    b = solve_rigid(body, np.stack([vx, vy, zero], -1), np.stack([zero, zero, om], -1),
                    mu=0.4, kappa=0.6, law=law)  # fmt: skip
    scale = np.abs(vy).max()
    assert np.abs(a.after.vx - b.velocity[:, 0]).max() <= 1e-12 * scale
    assert np.abs(a.after.vy - b.velocity[:, 1]).max() <= 1e-12 * scale
    assert np.abs(a.after.omega - b.spin[:, 2]).max() * 0.5 <= 1e-12 * scale
    assert np.all(b.velocity[:, 2] == 0)  # stays in its plane
    assert {"slide", "slide-stick", "slide-reslide"} <= set(b.regime)  # reversals included


def test_two_spheres_through_their_summed_matrix_equal_solve_pair():
    one = Body.solid_sphere(mass=0.17, radius=0.0286)
    two = Body.solid_sphere(mass=0.16, radius=0.0286)
    j1, j2 = one.mass * one.gyration**2, two.mass * two.gyration**2
    normal = np.array([0.0, 1.0, 0.0])  # from sphere 2's centre to sphere 1's
    b1 = RigidBody.principal(one.mass, [j1] * 3, -one.radius * normal)
    b2 = RigidBody.principal(two.mass, [j2] * 3, two.radius * normal)
    v1, w1 = np.array([0.3, -1.2, 0.4]), np.array([5.0, -20.0, 30.0])
    v2, w2 = np.array([-0.1, 0.5, 0.0]), np.array([0.0, 10.0, -5.0])
    relative = (v1 + np.cross(w1, b1.offset)) - (v2 + np.cross(w2, b2.offset))
    imp = solve_contact(b1.matrix() + b2.matrix(), relative, mu=0.3, kappa=0.9,
                        normal=normal)  # fmt: skip
    pair = solve_pair(one, two, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, mu=0.3,
                      kappa=0.9, normal=normal)  # fmt: skip
    after1 = v1 + imp.impulse.array / one.mass
    after2 = v2 - imp.impulse.array / two.mass
    assert np.allclose(after1, [pair.after1.vx, pair.after1.vy, pair.after1.vz], atol=1e-13)
    assert np.allclose(after2, [pair.after2.vx, pair.after2.vy, pair.after2.vz], atol=1e-13)
    assert np.all(np.isnan(imp.velocity))  # no body: the caller maps the impulse


def test_the_energy_identities_hold_on_random_dice():
    rng = np.random.default_rng(6)
    body = dice(rng, 3000)
    v, w = approaching(rng, body, 3000)
    for law in LAWS:
        imp = solve_rigid(body, v, w, mu=0.5, kappa=0.8, law=law)
        works = (
            imp.work_compression_normal
            + imp.work_restitution_normal
            + imp.work_compression_tangential
            + imp.work_restitution_tangential
        )
        scale = body.mass * np.sum(imp.contact_before.array**2, -1)
        assert np.abs(works + imp.dissipated_energy).max() <= 1e-9 * scale.max()

        # the kinetic energy of the body itself, before and after
        def energy(vel, spin):
            return 0.5 * body.mass * np.sum(vel**2, -1) + 0.5 * np.einsum(
                "ni,nij,nj->n", spin, body.inertia, spin)  # fmt: skip

        lost = energy(v, w) - energy(imp.velocity, imp.spin)
        assert np.abs(lost - imp.dissipated_energy).max() <= 1e-10 * scale.max()
        assert np.all(imp.work_compression_tangential <= 1e-12 * scale)
        assert np.all(imp.work_restitution_tangential <= 1e-12 * scale)
        # the contact velocity after is the body's, at the contact point
        point = imp.velocity + np.cross(imp.spin, body.offset)
        assert np.abs(point - imp.contact_after.array).max() <= 1e-11 * np.abs(v).max()


def test_newton_creates_energy_in_3d_where_poisson_and_stronge_do_not():
    # 20,000 dice on a corner (seed 5): Newton's law created energy in 201 of the 9,463
    # whose corner approached, by up to 2.18 J; neither other law did in any.
    rng = np.random.default_rng(5)
    body = dice(rng, 4000)
    v, w = approaching(rng, body, 4000)
    made = {law: solve_rigid(body, v, w, mu=0.5, kappa=0.9, law=law).creates_energy.sum()
            for law in LAWS}  # fmt: skip
    assert made["newton"] > 0
    assert made["energetic"] == 0


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**31), mu=st.floats(0.0, 2.0), kappa=st.floats(0.0, 1.0))
def test_stronges_energetic_law_never_creates_energy(seed, mu, kappa):
    rng = np.random.default_rng(seed)
    body = dice(rng, 50)
    v, w = approaching(rng, body, 50)
    imp = solve_rigid(body, v, w, mu=mu, kappa=kappa, law="energetic")
    scale = body.mass * np.sum(imp.contact_before.array**2, -1)
    assert np.all(imp.dissipated_energy >= -1e-10 * scale)
    # restitution's work is kappa^2 that of compression (the coefficient itself, a square
    # root of their ratio, cannot resolve kappa below about 1e-8)
    target = kappa**2 * -imp.work_compression_normal
    assert np.all(
        np.abs(imp.work_restitution_normal - target) <= 1e-10 * -imp.work_compression_normal
    )


def test_the_three_coefficients_are_each_laws_own():
    rng = np.random.default_rng(8)
    body = dice(rng, 500)
    v, w = approaching(rng, body, 500)
    newton = solve_rigid(body, v, w, mu=0.4, kappa=0.7, law="newton")
    poisson = solve_rigid(body, v, w, mu=0.4, kappa=0.7, law="poisson")
    energetic = solve_rigid(body, v, w, mu=0.4, kappa=0.7, law="energetic")
    assert np.allclose(newton.newton_restitution, 0.7, atol=1e-9)
    assert np.allclose(poisson.poisson_restitution, 0.7, atol=1e-9)
    assert np.allclose(energetic.energetic_restitution, 0.7, atol=1e-9)
    turned = poisson.regime != "slide"  # where the slip stopped, the laws differ
    assert np.abs(poisson.newton_restitution - 0.7).max() > 1e-3 or not turned.any()


def test_the_reslide_direction_is_the_one_direction_slip_grows_along():
    # Derived in core.scalar_rigid: it exists, and is unique, exactly when the contact
    # cannot stick. Checked here by a scan of every direction on random matrices.
    rng = np.random.default_rng(9)
    angles = np.linspace(0, 2 * np.pi, 20001)
    s = np.stack([np.cos(angles), np.sin(angles)], -1)
    found = {True: 0, False: 0}
    for _ in range(300):
        a = rng.normal(size=(3, 3))
        w = a @ a.T + 0.2 * np.eye(3)
        mu = rng.uniform(0, 1.5)
        six = np.array([w[0, 0], w[0, 1], w[0, 2], w[1, 1], w[1, 2], w[2, 2]])
        c = np.linalg.solve(w[:2, :2], w[:2, 2])
        g = w[:2, 2] - mu * s @ w[:2, :2]
        cross = s[:, 0] * g[:, 1] - s[:, 1] * g[:, 0]
        along = np.sum(s * g, -1)
        roots = np.flatnonzero(np.sign(cross[:-1]) != np.sign(cross[1:]))
        growing = [k for k in roots if along[k] > 0]
        s1, s2, lam = reslide_direction(six, mu)
        can_stick = np.hypot(*c) <= mu
        found[bool(can_stick)] += 1
        if can_stick:
            assert math.isnan(lam) and growing == []
        else:
            assert len(growing) == 1
            k = growing[0]
            assert abs(math.atan2(s2, s1) % (2 * np.pi) - angles[k]) < 1e-3
            g0 = w[:2, 2] - mu * w[:2, :2] @ [s1, s2]
            assert abs(g0[0] * s2 - g0[1] * s1) <= 1e-12 * np.abs(g0).max()
            assert lam > 0
    assert found[True] > 20 and found[False] > 20  # both kinds were met


def test_the_jacobian_matrix_of_a_free_body_is_its_body_matrix():
    rng = np.random.default_rng(10)
    body = dice(rng, 1)
    r = body.offset[0]
    mass_matrix = np.zeros((6, 6))
    mass_matrix[:3, :3] = body.mass[0] * np.eye(3)
    mass_matrix[3:, 3:] = body.inertia[0]
    cross = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
    jacobian = np.hstack([np.eye(3), -cross])  # v_point = v + w x r = v - [r]x w
    assert np.allclose(rigid3d.jacobian_matrix(mass_matrix, jacobian), body.matrix()[0],
                       rtol=1e-12, atol=1e-12)  # fmt: skip


def test_a_tilted_moving_surface_is_the_same_impact_rotated():
    rng = np.random.default_rng(11)
    body = dice(rng, 200)
    v, w = approaching(rng, body, 200)
    flat = solve_rigid(body, v, w, mu=0.5, kappa=0.6)
    # rotate the whole scene by R, and move it with the surface's velocity u
    q = quaternions(rng, 1)[0]
    turn = RigidBody.principal(1.0, [1, 1, 1], [0, 0, 0], q)  # only for its rotation
    from spinimpact.model.rigid import _rotation

    rot = _rotation(q)
    assert turn.inertia.shape == (3, 3)
    u = np.array([0.3, -0.2, 1.0])
    moved = RigidBody(body.mass, rot @ body.inertia @ rot.T, body.offset @ rot.T)
    tilted = solve_rigid(moved, v @ rot.T + u, w @ rot.T, mu=0.5, kappa=0.6,
                         surface=Surface(normal=rot @ [0, 1, 0], velocity=u))  # fmt: skip
    assert np.abs(tilted.velocity - (flat.velocity @ rot.T + u)).max() <= 1e-11
    assert np.abs(tilted.spin - flat.spin @ rot.T).max() <= 1e-10
    assert np.array_equal(tilted.regime, flat.regime)


def test_one_impact_without_numba_is_solved_and_many_are_refused(monkeypatch):
    rng = np.random.default_rng(12)
    body = dice(rng, 3)
    v, w = approaching(rng, body, 3)
    compiled = solve_rigid(body, v, w, mu=0.5, kappa=0.6)
    monkeypatch.setattr(rigid3d, "HAVE_NUMBA", False)
    for i in range(3):
        one = RigidBody(body.mass[i], body.inertia[i], body.offset[i])
        alone = solve_rigid(one, v[i], w[i], mu=0.5, kappa=0.6)
        assert np.allclose(alone.velocity, compiled.velocity[i], rtol=0, atol=1e-14)
    monkeypatch.setitem(sys.modules, "numba", None)  # as if it were not installed
    with pytest.raises(ImportError, match=r"spinimpact\[fast\]"):
        solve_rigid(body, v, w, mu=0.5, kappa=0.6)


def test_presets_are_the_textbook_bodies():
    die = RigidBody.cuboid(mass=6.0, size=[1.0, 2.0, 3.0])
    assert np.allclose(np.diag(die.inertia), [6.0 * 13 / 12, 6.0 * 10 / 12, 6.0 * 5 / 12])
    assert np.allclose(die.offset, [-0.5, -1.0, -1.5])
    coin = RigidBody.cylinder(mass=2.0, radius=0.5, height=0.1, rim_angle=math.pi / 2)
    assert np.allclose(np.diag(coin.inertia), [2 * (0.75 + 0.01) / 12] * 2 + [0.25])
    assert np.allclose(coin.offset, [0.0, 0.5, -0.05])
    rod = RigidBody.rod(mass=1.0, length=2.0)
    assert np.allclose(rod.offset, [-1.0, 0.0, 0.0])


@pytest.mark.parametrize(
    ("call", "error", "text"),
    [
        (lambda b: solve_rigid("die", [0, -1, 0], [0, 0, 0], mu=0.5, kappa=0.5), TypeError,
         "body must be a spinimpact.RigidBody"),
        (lambda b: solve_rigid(b, [0, -1, 0], [0, 0, 0], mu=0.5, kappa=0.5, law="stronge"),
         ValueError, "law must be one of poisson, newton, energetic"),
        (lambda b: solve_rigid(b, [0, 1, 0], [0, 0, 0], mu=0.5, kappa=0.5), ValueError,
         "must approach the surface"),
        (lambda b: solve_rigid(b, [0, -1, 0], [0, 0, 0], mu=-0.1, kappa=0.5), ValueError,
         "mu must be >= 0"),
        (lambda b: solve_rigid(b, [0, -1], [0, 0, 0], mu=0.5, kappa=0.5), ValueError,
         "velocity must be a 3-vector"),
        (lambda b: RigidBody.principal(1.0, [1, 1, 3], [0, -1, 0]), ValueError, "triangle"),
        (lambda b: RigidBody.principal(1.0, [1, 1, 1], [0, -1, 0], [1, 1, 0, 0]), ValueError,
         "unit quaternion"),
        (lambda b: RigidBody.principal(1.0, [1, 1, 1], [0, -1, 0], -np.eye(3)), ValueError,
         "not a reflection"),
        (lambda b: solve_contact(-np.eye(3), [0, -1, 0], mu=0.5, kappa=0.5), ValueError,
         "positive definite"),
    ],
)  # fmt: skip
def test_bad_input_is_named(call, error, text):
    body = RigidBody.cuboid(mass=1.0, size=[1.0, 1.0, 1.0])
    with pytest.raises(error, match=text):
        call(body)


def test_a_file_of_rigid_bodies_is_solved_as_solve_rigid_solves_them(tmp_path):
    from spinimpact.io.batch import run_batch

    rng = np.random.default_rng(13)
    body = dice(rng, 40)
    v, w = approaching(rng, body, 40)
    laws = np.array(LAWS)[rng.integers(0, 3, 40)]
    names = ["mass", "ixx", "iyy", "izz", "ixy", "ixz", "iyz", "rx", "ry", "rz",
             "vx", "vy", "vz", "wx", "wy", "wz", "law"]  # fmt: skip
    tensor = body.inertia
    columns = [body.mass, tensor[:, 0, 0], tensor[:, 1, 1], tensor[:, 2, 2], tensor[:, 0, 1],
               tensor[:, 0, 2], tensor[:, 1, 2], *body.offset.T, *v.T, *w.T]  # fmt: skip
    lines = [",".join(names)]
    lines += [",".join([*(repr(float(c[i])) for c in columns), laws[i]]) for i in range(40)]
    (tmp_path / "bodies.csv").write_text("\n".join(lines) + "\n")
    run_batch(tmp_path / "bodies.csv", tmp_path / "out.csv", defaults={}, chunk_size=16)
    out = np.genfromtxt(tmp_path / "out.csv", delimiter=",", names=True, dtype=None,
                        encoding="utf-8")  # fmt: skip
    for law in LAWS:
        rows = laws == law
        want = solve_rigid(
            RigidBody(body.mass[rows], tensor[rows], body.offset[rows]),
            v[rows],
            w[rows],
            mu=0.2,
            kappa=0.8,
            law=law,
        )  # the defaults
        assert np.array_equal(out["regime"][rows], want.regime)
        for k, c in enumerate("xyz"):  # the file holds the tensor's upper triangle: the
            # body's own tensor is symmetric only to rounding
            assert np.allclose(out[f"after_v{c}"][rows], want.velocity[:, k], rtol=1e-12,
                               atol=1e-12)  # fmt: skip


def test_an_impulse_changes_the_contact_points_velocity_by_the_body_matrix():
    # two routes: the body's own equations (apply_impulse) and the collision matrix
    rng = np.random.default_rng(14)
    body = dice(rng, 100)
    v, w, p = rng.normal(size=(3, 100, 3))
    v1, w1 = rigid3d.apply_impulse(body.mass, body.inertia, body.offset, v, w, p)
    change = (v1 + np.cross(w1, body.offset)) - (v + np.cross(w, body.offset))
    assert np.allclose(change, np.einsum("nij,nj->ni", body.matrix(), p), rtol=1e-12,
                       atol=1e-12)  # fmt: skip
