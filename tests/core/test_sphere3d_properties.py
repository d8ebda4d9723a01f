"""Properties of solve_sphere() and solve_pair() on hypothesis-drawn impacts.

Deterministic examples (the ``repro`` profile of ``tests/conftest.py``). Impacts are drawn
component by component: masses, radii, gyrations from 0.2 radii to a thin shell's
``sqrt(2/3) R`` (the largest of any sphere), velocity and spin vectors, plane normals of
any direction and length, moving planes, ``mu`` up to 5 and ``kappa`` in ``[0, 1]`` with
its ends; the approach speed is set along the normal so that the contact approaches.

Tolerances: energies to ``64 eps m S^2`` and impulses to ``64 eps m S`` with ``S`` the sum
of the speeds the contact velocity is computed from (its rounding is ``eps S``); the
closed forms agree with the independent integration to 15 eps in these units
(``tests/core/test_sphere3d.py``), so 64 leaves a margin while a real energy gain or a
friction impulse outside the cone by a relative 1e-12 fails.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from spinimpact import Body, Surface, solve_pair, solve_sphere

#: Hypothesis solves a few hundred impacts a test: `make test` runs them.
pytestmark = pytest.mark.slow

EPS = np.finfo(float).eps
TOL = 64 * EPS


def _norm(a):
    """Length without underflow of the squares (friction impulses can be tiny)."""
    return np.hypot.reduce(np.asarray(a, dtype=float), axis=-1)


def _dot(a, b):
    return np.sum(a * b, axis=-1)


finite = dict(allow_nan=False, allow_infinity=False)
component = st.floats(-30, 30, **finite)
vector = st.tuples(component, component, component).map(np.array)
direction = (
    st.tuples(*(st.floats(-1, 1, **finite),) * 3)
    .map(np.array)
    .filter(lambda n: np.linalg.norm(n) > 0.1)
)
mass = st.floats(1e-2, 10, **finite)
radius = st.floats(1e-3, 0.3, **finite)
gyration_ratio = st.floats(0.2, np.sqrt(2 / 3), **finite)  # rho / R, up to a thin shell
mu = st.one_of(st.just(0.0), st.floats(1e-9, 5.0, **finite))  # no subnormal mu
kappa = st.one_of(st.sampled_from([0.0, 1.0]), st.floats(0.0, 1.0, **finite))
approach = st.floats(1e-2, 30, **finite)


@st.composite
def bodies(draw):
    R = draw(radius)
    return Body(mass=draw(mass), radius=R, gyration=R * draw(gyration_ratio))


def _approaching(v, w, n, R, V, speed):
    """``v`` moved along ``n`` so that the contact point of a sphere (radius ``R``, spin
    ``w``) approaches the plane (normal ``n``, velocity ``V``) at ``speed``."""
    c = v + np.cross(w, -R * n) - V
    return v - (np.dot(c, n) + speed) * n


@given(body=bodies(), v=vector, w=vector, n=direction, V=vector, s=approach, mu=mu, kappa=kappa)
def test_energy_never_increases_on_a_plane(body, v, w, n, V, s, mu, kappa):
    """In the plane's frame (a moving plane can give a ball energy in the ground frame, as
    a racket does)."""
    unit = n / np.linalg.norm(n)
    v = _approaching(v, w, unit, body.radius, V, s)
    imp = solve_sphere(body, v, w, mu=mu, kappa=kappa, surface=Surface(normal=n, velocity=V))
    m, J = body.mass, body.inertia

    def energy(v, w):
        return 0.5 * m * _dot(v - V, v - V) + 0.5 * J * _dot(w, w)

    S = np.linalg.norm(v) + np.linalg.norm(V) + max(body.radius, body.gyration) * np.linalg.norm(w)
    tol = TOL * m * S**2
    before, after = energy(v, w), energy(imp.after.velocity, imp.after.spin)
    assert after <= before + tol
    assert imp.dissipated_energy >= -tol
    assert abs(imp.dissipated_energy - (before - after)) <= tol
    assert imp.work_compression_tangential <= tol and imp.work_restitution_tangential <= tol


@st.composite
def pairs(draw):
    b1, b2 = draw(bodies()), draw(bodies())
    n = draw(direction)
    n = n / np.linalg.norm(n)
    v1, w1, v2, w2 = (draw(vector) for _ in range(4))
    c = (v1 + np.cross(w1, -b1.radius * n)) - (v2 + np.cross(w2, b2.radius * n))
    v1 = v1 - (np.dot(c, n) + draw(approach)) * n
    return b1, b2, n, v1, w1, v2, w2


@given(pair=pairs(), mu=mu, kappa=kappa)
def test_energy_never_increases_for_two_spheres(pair, mu, kappa):
    b1, b2, n, v1, w1, v2, w2 = pair
    imp = solve_pair(b1, b2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=n,
                     mu=mu, kappa=kappa)  # fmt: skip

    def energy(v1, w1, v2, w2):
        return 0.5 * (b1.mass * _dot(v1, v1) + b1.inertia * _dot(w1, w1)
                      + b2.mass * _dot(v2, v2) + b2.inertia * _dot(w2, w2))  # fmt: skip

    S = (np.linalg.norm(v1) + np.linalg.norm(v2) + max(b1.radius, b1.gyration) * np.linalg.norm(w1)
         + max(b2.radius, b2.gyration) * np.linalg.norm(w2))  # fmt: skip
    tol = TOL * (b1.mass + b2.mass) * S**2
    before = energy(v1, w1, v2, w2)
    after = energy(imp.after1.velocity, imp.after1.spin, imp.after2.velocity, imp.after2.spin)
    assert after <= before + tol
    assert imp.dissipated_energy >= -tol
    assert abs(imp.dissipated_energy - (before - after)) <= tol
    # momentum is conserved (the impulses are equal and opposite)
    p0 = b1.mass * v1 + b2.mass * v2
    p1 = b1.mass * imp.after1.velocity + b2.mass * imp.after2.velocity
    assert np.all(np.abs(p1 - p0) <= TOL * (b1.mass + b2.mass) * S)


@given(body=bodies(), v=vector, w=vector, n=direction, V=vector, s=approach, mu=mu, kappa=kappa)
def test_friction_stays_in_the_cone_on_a_plane(body, v, w, n, V, s, mu, kappa):
    unit = n / np.linalg.norm(n)
    v = _approaching(v, w, unit, body.radius, V, s)
    imp = solve_sphere(body, v, w, mu=mu, kappa=kappa, surface=Surface(normal=n, velocity=V))
    F = imp.friction_impulse.array
    S = np.linalg.norm(v) + np.linalg.norm(V) + body.radius * np.linalg.norm(w)
    assert _norm(F) <= mu * imp.tau1 * (1 + TOL)
    assert abs(np.dot(F, unit)) <= TOL * body.mass * S  # tangential
    assert imp.impulse_ratio <= mu * (1 + TOL)
    assert imp.tau1 >= imp.tau0 > 0


@given(pair=pairs(), mu=mu, kappa=kappa)
def test_friction_stays_in_the_cone_for_two_spheres(pair, mu, kappa):
    b1, b2, n, v1, w1, v2, w2 = pair
    imp = solve_pair(b1, b2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=n,
                     mu=mu, kappa=kappa)  # fmt: skip
    F = imp.friction_impulse.array
    assert _norm(F) <= mu * imp.tau1 * (1 + TOL)
    assert imp.impulse_ratio <= mu * (1 + TOL)
    assert imp.tau1 >= imp.tau0 > 0


# --- broadcasting ---------------------------------------------------------------------

shapes = st.tuples(st.integers(1, 3), st.integers(1, 4))


def _random_inputs(rng, shape_body, shape_vec, radius):
    m = 10 ** rng.uniform(-1, 1, shape_body)
    g = radius * rng.uniform(0.3, 0.8, shape_body)  # up to a thin shell
    v = rng.normal(size=shape_vec + (3,)) * 3
    w = rng.normal(size=shape_vec + (3,)) * 30
    return m, g, v, w


def _close(a, b, scale):
    np.testing.assert_allclose(a, b, rtol=0, atol=8 * EPS * scale)


@settings(max_examples=40)
@given(shape=shapes, seed=st.integers(0, 2**32 - 1), tilted=st.booleans())
def test_arrays_of_spheres_broadcast_like_numpy(shape, seed, tilted):
    """Bodies of shape ``(k, 1)``, vectors of shape ``(j, 3)``, a plane normal per row
    ``(k, 1, 3)`` or the default plane, ``mu`` per column: a result of shape ``(k, j)``
    whose every entry is the impact solved alone."""
    rng = np.random.default_rng(seed)
    k, j = shape
    R = 10 ** rng.uniform(-2, -1, (k, 1))
    m, g, v, w = _random_inputs(rng, (k, 1), (j,), R)
    n = rng.normal(size=(k, 1, 3)) if tilted else np.array([0.0, 1.0, 0.0])
    unit = n / np.linalg.norm(n, axis=-1, keepdims=True)
    V = rng.normal(size=(k, 1, 3)) if tilted else np.zeros(3)
    c = v + np.cross(w, -R[..., None] * unit) - V
    v = v - (_dot(c, unit) + rng.uniform(0.1, 3, (k, j)))[..., None] * unit  # (k, j, 3)
    mu_, kappa_ = rng.uniform(0, 1.5, j), rng.uniform(0, 1, (k, 1))
    body = Body(mass=m, radius=R, gyration=g)
    surface = Surface(normal=n, velocity=V)
    imp = solve_sphere(body, v, w, mu=mu_, kappa=kappa_, surface=surface)
    assert imp.shape == (k, j)
    assert imp.after.velocity.shape == (k, j, 3) and imp.friction_impulse.array.shape == (k, j, 3)
    assert np.shape(imp.regime) == (k, j) and np.shape(imp.dissipated_energy) == (k, j)
    for a in range(k):
        for b in range(j):
            plane = Surface(normal=np.broadcast_to(n, (k, 1, 3))[a, 0],
                            velocity=np.broadcast_to(V, (k, 1, 3))[a, 0])  # fmt: skip
            one = solve_sphere(Body(mass=m[a, 0], radius=R[a, 0], gyration=g[a, 0]), v[a, b],
                               w[b], mu=mu_[b], kappa=kappa_[a, 0], surface=plane)  # fmt: skip
            S = np.linalg.norm(v[a, b]) + np.linalg.norm(V) + R[a, 0] * np.linalg.norm(w[b])
            assert one.regime == imp.regime[a, b]
            _close(imp.after.velocity[a, b], one.after.velocity, S)
            _close(imp.after.spin[a, b] * R[a, 0], one.after.spin * R[a, 0], S)
            _close(imp.friction_impulse.array[a, b], one.friction_impulse.array, m[a, 0] * S)
            _close(imp.dissipated_energy[a, b], one.dissipated_energy, m[a, 0] * S**2)


@settings(max_examples=40)
@given(shape=shapes, seed=st.integers(0, 2**32 - 1))
def test_arrays_of_pairs_broadcast_like_numpy(shape, seed):
    """Ball 1 an array of shape ``(k, 1)``, ball 2 one ball, velocities ``(j, 3)``,
    normals ``(k, 1, 3)``: a result of shape ``(k, j)``, each entry the pair solved alone."""
    rng = np.random.default_rng(seed)
    k, j = shape
    R1 = 10 ** rng.uniform(-2, -1, (k, 1))
    m1, g1, v1, w1 = _random_inputs(rng, (k, 1), (j,), R1)
    b2 = Body.solid_sphere(mass=0.3, radius=0.04)
    v2, w2 = rng.normal(size=3), rng.normal(size=3) * 20
    n = rng.normal(size=(k, 1, 3))
    unit = n / np.linalg.norm(n, axis=-1, keepdims=True)
    c = (v1 + np.cross(w1, -R1[..., None] * unit)) - (v2 + np.cross(w2, 0.04 * unit))
    v1 = v1 - (_dot(c, unit) + rng.uniform(0.1, 3, (k, j)))[..., None] * unit
    b1 = Body(mass=m1, radius=R1, gyration=g1)
    mu_, kappa_ = rng.uniform(0, 1.5, (k, 1)), rng.uniform(0, 1, j)
    imp = solve_pair(b1, b2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=n,
                     mu=mu_, kappa=kappa_)  # fmt: skip
    assert imp.shape == (k, j)
    assert imp.after1.velocity.shape == (k, j, 3) and imp.after2.spin.shape == (k, j, 3)
    for a in range(k):
        for b in range(j):
            one = solve_pair(Body(mass=m1[a, 0], radius=R1[a, 0], gyration=g1[a, 0]), b2,
                             velocity1=v1[a, b], spin1=w1[b], velocity2=v2, spin2=w2,
                             normal=n[a, 0], mu=mu_[a, 0], kappa=kappa_[b])  # fmt: skip
            S = (np.linalg.norm(v1[a, b]) + np.linalg.norm(v2) + R1[a, 0] * np.linalg.norm(w1[b])
                 + 0.04 * np.linalg.norm(w2))  # fmt: skip
            assert one.regime == imp.regime[a, b]
            for name in ("after1", "after2"):
                _close(getattr(imp, name).velocity[a, b], getattr(one, name).velocity, S)
            _close(imp.after1.spin[a, b] * R1[a, 0], one.after1.spin * R1[a, 0], S)
            _close(imp.after2.spin[a, b] * 0.04, one.after2.spin * 0.04, S)
            _close(imp.friction_impulse.array[a, b], one.friction_impulse.array, m1[a, 0] * S)
