"""The independent 3D rigid-body reference (:mod:`tests.rigid_reference`) checked on its own.

Before the reference can judge the production solver it has to be right. Here it is
compared with closed forms derived by hand (not from the package):

* a uniform sphere touching under its centre (``W_tn = 0``, isotropic ``W_tt``: the slip
  keeps its direction), sliding throughout and sliding then sticking;
* a uniform rod touching at its end, moving in a vertical plane (Keller's/Routh's 2D
  analysis: slide then stick, slide then reverse), whose out-of-plane components must stay
  zero;

and with identities every solution obeys: the work of the impulse integrated along the
path equals ``v(0).p + p.W.p/2`` and the final contact velocity equals ``v(0) + W p``;
Stronge's law never creates energy; a rotation of the tangential axes rotates the answer;
a re-slide direction exists exactly when sticking is not allowed, and is unique.

Tolerances. The reference integrates with ``rtol = 1e-12``; its answers differ from a run
at ``rtol = 1e-13`` by at most about 1e-11 of the scales (measured on 300 random impacts:
9e-12 for the impulse over ``|v(0)| / max eig W``). Closed forms are compared at 1e-10
relative (a tenfold margin), the path identities at 1e-10 of the scales.
"""

import math

import numpy as np
import pytest

from tests.rigid_reference import (
    LAWS,
    collision_matrix,
    example,
    near_boundary,
    random_cases,
    reference_impact,
    reslide_direction_by_lambda,
    reslide_directions,
)

TOL = 1e-10  # relative; the reference is good to about 1e-11 (module docstring)


def _scales(w, v):
    """Velocity, impulse and energy scales of one impact: ``|v|``, ``|v|/w``, ``|v|^2/w``."""
    speed = float(np.linalg.norm(v))
    wmax = float(np.linalg.eigvalsh(w)[-1])
    return speed, speed / wmax, speed * speed / wmax


# ----------------------------------------------------------------------------------- sphere


def _sphere(mass=2.0, radius=0.11):
    """A uniform solid sphere touching a plane below its centre, in a tilted frame."""
    inertia = 0.4 * mass * radius**2
    rot = np.linalg.qr(np.array([[1.0, 2.0, 0.5], [0.3, -1.0, 2.0], [1.5, 0.2, -0.7]]))[0]
    n = rot[:, 2]
    frame = np.column_stack([rot[:, 0], rot[:, 1], n])
    if np.linalg.det(frame) < 0:
        frame[:, 1] *= -1
    w = collision_matrix(mass, inertia * np.eye(3), -radius * n, frame)
    return w, mass, inertia, radius


def test_sphere_collision_matrix():
    """``W = diag(1/m + R^2/J, 1/m + R^2/J, 1/m)`` for a sphere touched below its centre."""
    w, m, j, r = _sphere()
    alpha = 1 / m + r**2 / j
    np.testing.assert_allclose(w, np.diag([alpha, alpha, 1 / m]), rtol=0, atol=1e-13 * alpha)


@pytest.mark.parametrize("law", LAWS)
def test_sphere_slides_throughout(law):
    """Slip speed ``s0 > mu alpha p_end``: the slip never stops.

    With ``alpha = 1/m + R^2/J``, ``beta = 1/m``: ``p_c = -v_n0 / beta`` and the impact ends at
    ``p_end = (1 + kappa) p_c`` under all three laws (``v_n`` is linear in ``p_n``). Then
    ``p_t = -mu p_end d0``, ``v_t = v_t0 - mu alpha p_end d0``, ``v_n = -kappa v_n0``; the
    tangential work is ``-mu (s0 p_end - mu alpha p_end^2 / 2)`` and the normal works
    ``-v_n0^2 / (2 beta)`` and ``kappa^2 v_n0^2 / (2 beta)``.
    """
    w, m, j, r = _sphere()
    alpha, beta = 1 / m + r**2 / j, 1 / m
    v0 = np.array([3.0, -1.6, -1.7])
    mu, kappa = 0.3, 0.6
    s0 = math.hypot(v0[0], v0[1])
    d0 = v0[:2] / s0
    p_end = (1 + kappa) * -v0[2] / beta
    assert s0 > mu * alpha * p_end  # the branch this test is about
    ref = reference_impact(w, v0, mu, kappa, law)
    _, pscale, escale = _scales(w, v0)
    assert ref.sequence == ("slide",)
    np.testing.assert_allclose(ref.impulse, [*(-mu * p_end * d0), p_end], rtol=0, atol=TOL * pscale)
    after = [*(v0[:2] - mu * alpha * p_end * d0), -kappa * v0[2]]
    np.testing.assert_allclose(ref.velocity, after, rtol=0, atol=TOL * np.linalg.norm(v0))
    np.testing.assert_allclose(ref.compression_impulse, p_end / (1 + kappa), rtol=TOL)
    works = [
        -(v0[2] ** 2) / (2 * beta),
        kappa**2 * v0[2] ** 2 / (2 * beta),
        -mu * (s0 * p_end - mu * alpha * p_end**2 / 2),
    ]
    got = [ref.work_normal_compression, ref.work_normal_restitution, ref.work_tangential]
    np.testing.assert_allclose(got, works, rtol=0, atol=TOL * escale)
    assert ref.slip_turn == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("law", LAWS)
def test_sphere_slides_then_sticks(law):
    """Slip speed ``s0 < mu alpha p_end``: it stops at ``p* = s0 / (mu alpha)`` and sticks.

    ``W_tn = 0``, so ``|W_tt^-1 W_tn| = 0 <= mu``: it stays stuck with ``dp_t = 0``; then
    ``p_t = -v_t0 / alpha``, ``v_t = 0``, and the normal part is as when sliding.
    """
    w, m, j, r = _sphere()
    alpha, beta = 1 / m + r**2 / j, 1 / m
    v0 = np.array([0.2, 0.35, -1.7])
    mu, kappa = 0.4, 0.45
    p_end = (1 + kappa) * -v0[2] / beta
    s0 = math.hypot(v0[0], v0[1])
    assert s0 < mu * alpha * p_end
    ref = reference_impact(w, v0, mu, kappa, law)
    _, pscale, escale = _scales(w, v0)
    assert ref.sequence == ("slide", "stick")
    np.testing.assert_allclose(ref.impulse, [*(-v0[:2] / alpha), p_end], rtol=0, atol=TOL * pscale)
    np.testing.assert_allclose(
        ref.velocity, [0, 0, -kappa * v0[2]], rtol=0, atol=TOL * np.linalg.norm(v0)
    )
    # tangential work: -mu int s dp over the slide, s falling linearly from s0 to 0
    p_stop = s0 / (mu * alpha)
    assert ref.work_tangential == pytest.approx(-mu * s0 * p_stop / 2, abs=TOL * escale)
    assert ref.margins.stick == pytest.approx(-mu, abs=1e-12)
    assert ref.margins.stop_to_end == pytest.approx((p_end - p_stop) / p_end, rel=TOL)


# -------------------------------------------------------------------------------------- rod


def _rod(theta_deg=30.0, mass=1.0, length=1.0):
    """A uniform rod in the x-y plane, ``theta_deg`` degrees above the surface y = 0,
    touching it at its lower end; contact frame ``(x, -z, y)``.

    Returns (W, the hand-derived 2D W)."""
    theta = math.radians(theta_deg)
    e = np.array([math.cos(theta), math.sin(theta), 0.0])
    j = mass * length**2 / 12
    inertia = j * (np.eye(3) - np.outer(e, e)) + (j / 100) * np.outer(e, e)
    r = -0.5 * length * e
    frame = np.column_stack([[1.0, 0, 0], [0, 0, -1.0], [0, 1.0, 0]])
    w = collision_matrix(mass, inertia, r, frame)
    # 2D: the contact velocity is v_cm + omega z x r, with m dv_cm = dp and J domega = r x dp
    rx, ry = r[0], r[1]
    w2 = np.array([[1 / mass + ry**2 / j, -rx * ry / j], [-rx * ry / j, 1 / mass + rx**2 / j]])
    return w, w2


def _keller_2d(w2, u0, v0, mu, kappa, law):
    """Keller's piecewise-linear 2D solution when the slip stops during compression.

    Slide 1 (``sigma = sign u0``): ``du/dp = W12 - mu sigma W11``, ``dv/dp = W22 - mu sigma
    W12``; stop at ``p1 = -u0 / (du/dp)``. Then stick if ``|W12| <= mu W11``
    (``dp_t/dp = -W12/W11``, ``dv/dp = W22 - W12^2/W11``), else slide the other way
    (``sigma' = sign W12``). Compression ends in phase 2 at ``p_c = p1 - v(p1) / r2v``; the
    end: Poisson ``(1 + kappa) p_c``; Newton ``p_c + kappa |v0| / r2v``; Stronge ``p_c +
    sqrt(2 kappa^2 (-W_c) / r2v)`` with ``W_c = v0 p1 + r1v p1^2 / 2 - v(p1)^2 / (2 r2v)``.
    Returns ``(p_t, p_n, u_end, v_end, sequence)``.
    """
    w11, w12, w22 = w2[0, 0], w2[0, 1], w2[1, 1]
    sigma = math.copysign(1.0, u0)
    r1u, r1v = w12 - mu * sigma * w11, w22 - mu * sigma * w12
    p1 = -u0 / r1u
    assert p1 > 0
    v1 = v0 + r1v * p1
    assert v1 < 0  # the slip stops during compression (the case derived here)
    if abs(w12) <= mu * w11:
        q2, r2u, r2v, seq = -w12 / w11, 0.0, w22 - w12**2 / w11, ("slide", "stick")
    else:
        s2 = math.copysign(1.0, w12)
        q2, r2u, r2v = -mu * s2, w12 - mu * s2 * w11, w22 - mu * s2 * w12
        seq = ("slide", "stick", "slide")
    pc = p1 - v1 / r2v
    wc = v0 * p1 + r1v * p1**2 / 2 - v1**2 / (2 * r2v)
    if law == "poisson":
        p_end = (1 + kappa) * pc
    elif law == "newton":
        p_end = pc + kappa * -v0 / r2v
    else:
        p_end = pc + math.sqrt(2 * kappa**2 * -wc / r2v)
    return (
        -mu * sigma * p1 + q2 * (p_end - p1),
        p_end,
        r2u * (p_end - p1),
        v1 + r2v * (p_end - p1),
        seq,
    )


def test_rod_collision_matrix_is_planar():
    """The rod's 3D ``W`` is its 2D ``W`` in the plane, decoupled from the normal to it."""
    w, w2 = _rod()
    np.testing.assert_allclose(w[np.ix_([0, 2], [0, 2])], w2, rtol=1e-14)
    np.testing.assert_allclose(w[1, [0, 2]], 0.0, atol=1e-15)


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize(("mu", "kind"), [(0.9, "stick"), (0.5, "reverse")])
def test_rod_against_keller_2d(law, mu, kind):
    """Rod at 30 degrees (``|W12/W11| = 0.742``): ``mu = 0.9`` sticks, ``mu = 0.5`` reverses.

    Incidence ``(u0, v0) = (0.3, -1)`` m/s, ``kappa = 0.7``; the 3D result must equal the
    hand-derived 2D one and keep its ``t2`` components at zero.
    """
    w, w2 = _rod()
    u0, v0, kappa = 0.3, -1.0, 0.7
    pt, pn, u_end, v_end, seq = _keller_2d(w2, u0, v0, mu, kappa, law)
    assert len(seq) == (2 if kind == "stick" else 3)
    ref = reference_impact(w, [u0, 0.0, v0], mu, kappa, law)
    speed, pscale, _ = _scales(w, [u0, 0.0, v0])
    assert ref.sequence == seq
    np.testing.assert_allclose(ref.impulse, [pt, 0.0, pn], rtol=0, atol=TOL * pscale)
    np.testing.assert_allclose(ref.velocity, [u_end, 0.0, v_end], rtol=0, atol=TOL * speed)
    # out of the plane: zero, but for the rounding of a re-slide angle found numerically
    assert abs(ref.impulse[1]) <= 1e-14 * pscale and abs(ref.velocity[1]) <= 1e-14 * speed
    if kind == "reverse":
        assert ref.reslide_directions == (1,)


# --------------------------------------------------------------------- identities and energy

CASES = random_cases(40, seed=11)


@pytest.mark.parametrize("law", LAWS)
def test_path_identities(law):
    """Along any path: work of the impulse ``= v(0).p + p.W.p/2``; ``v_after = v(0) + W p``."""
    for w, v, mu, kappa in zip(*CASES, strict=True):
        ref = reference_impact(w, v, mu, kappa, law)
        speed, _, escale = _scales(w, v)
        p = ref.impulse
        assert -ref.dissipated == pytest.approx(v @ p + p @ w @ p / 2, abs=TOL * escale)
        np.testing.assert_allclose(ref.velocity, v + w @ p, rtol=0, atol=TOL * speed)
        assert ref.work_tangential <= 0.0
        assert ref.work_normal_compression < 0.0
        assert ref.compression_impulse > 0.0


def test_stronge_never_creates_energy():
    """Stronge's law: the normal works sum to ``-(1 - kappa^2) (-W_c) <= 0`` and friction
    only removes energy, so ``dissipated >= 0`` (to ``1e-12`` of ``|v|^2 / max eig W``)."""
    for w, v, mu, kappa in zip(*CASES, strict=True):
        ref = reference_impact(w, v, mu, kappa, "stronge")
        assert ref.dissipated >= -1e-12 * _scales(w, v)[2]
        assert ref.work_normal_restitution == pytest.approx(
            -(kappa**2) * ref.work_normal_compression, rel=1e-9
        )


def test_newton_creates_energy_in_3d():
    """Newton's law can create energy in 3D.

    The example ``energy-newton`` (``random_cases`` seed 7, index 1532: a single body,
    ``mu = 0.5948``, ``kappa = 0.9935``, incidence ``v0 = (0.005754, 0.027100, -0.117450)``
    m/s, ``W`` with diagonal ``(12.27, 8.837, 6.059)`` 1/kg) slides, its slip turning by
    191 degrees, and sticks. The reference gives, with the contact kinetic energy
    ``E0 = v0.W^-1.v0 / 2 = 1.1794e-3`` J: Newton ``dissipated = -1.2101e-4`` J (energy
    created: 10.3 % of ``E0``; normal works -1.1515e-3 J in compression, +1.3004e-3 J in
    restitution); Poisson ``+5.662e-5`` J; Stronge ``+4.270e-5`` J. On 3,000 random impacts
    (seed 7) Newton's law created energy in 14, Poisson's and Stronge's in none.
    """
    w, v, mu, kappa, _ = example("energy-newton")
    energy = 0.5 * v @ np.linalg.solve(w, v)
    assert energy == pytest.approx(1.1794154760982e-3, rel=1e-10)
    newton = reference_impact(w, v, mu, kappa, "newton")
    assert newton.dissipated == pytest.approx(-1.2101339222632e-4, rel=1e-8)
    assert newton.dissipated < -0.1 * energy
    for law in ("poisson", "stronge"):
        assert reference_impact(w, v, mu, kappa, law).dissipated > 0.03 * energy


@pytest.mark.parametrize("law", LAWS)
def test_tangential_rotation(law):
    """Turning ``(t1, t2)`` by ``psi`` about ``n`` turns the impulse and velocity with them."""
    psi = 0.7
    c, s = math.cos(psi), math.sin(psi)
    q = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])  # columns: new axes in old ones
    for w, v, mu, kappa in zip(*(x[:12] for x in CASES), strict=True):
        ref = reference_impact(w, v, mu, kappa, law)
        turned = reference_impact(q.T @ w @ q, q.T @ v, mu, kappa, law)
        speed, pscale, _ = _scales(w, v)
        np.testing.assert_allclose(turned.impulse, q.T @ ref.impulse, rtol=0, atol=TOL * pscale)
        np.testing.assert_allclose(turned.velocity, q.T @ ref.velocity, rtol=0, atol=TOL * speed)
        assert turned.sequence == ref.sequence


# ------------------------------------------------------------------------------- re-slide


def test_reslide_direction_exists_iff_stick_fails_and_is_unique():
    """For random contacts and ``mu``: the angle scan finds one re-slide direction when
    ``|W_tt^-1 W_tn| > mu``, none otherwise, and it agrees with the ``lambda`` equation."""
    ws, _, _, _ = random_cases(40, seed=5)
    rng = np.random.default_rng(3)
    for w in ws:
        ratio = float(np.hypot(*np.linalg.solve(w[:2, :2], w[:2, 2])))
        for mu in (0.0, 0.5 * ratio, 0.999 * ratio, 1.001 * ratio, rng.uniform(0, 1.5)):
            angles = reslide_directions(w, mu, n=720)
            e = reslide_direction_by_lambda(w, mu)
            if ratio > mu:
                assert len(angles) == 1
                assert abs(math.remainder(angles[0] - math.atan2(e[1], e[0]), 2 * math.pi)) < 1e-9
            else:
                assert angles == [] and e is None


# ------------------------------------------------------------------------------- examples


@pytest.mark.parametrize(
    "name", ["slide", "slide-stick", "slide-stick-slide", "stick-from-rest", "turn"]
)
def test_examples_have_their_sequences(name):
    """The seeded examples used against the production solver are what their names say."""
    w, v, mu, kappa, law = example(name)
    ref = reference_impact(w, v, mu, kappa, law)
    expected = {
        "slide": ("slide",),
        "slide-stick": ("slide", "stick"),
        "slide-stick-slide": ("slide", "stick", "slide"),
        "stick-from-rest": ("stick",),
    }.get(name)
    if expected is not None:
        assert ref.sequence == expected
    else:
        assert abs(ref.slip_turn) > math.pi / 2
    assert not near_boundary(ref)
