"""pooltool's sphere impact laws beside spinimpact's exact ones, on random cases.

Run from the repository root:

    .venv/bin/python -m benchmarks.pooltool_compare [--n 100000] [--seed 1]

pooltool (PyPI ``pooltool-billiards``, a billiards simulator) resolves three of the impacts
spinimpact solves with closed forms. This script writes their equations as plain vectorized
functions (``peer_*`` below, from pooltool 0.6.0's modules named in each docstring and the
papers they cite), solves the same random cases with ``solve_sphere`` / ``solve_pair``, and
prints how far apart the answers are. If pooltool itself is importable, the transcriptions are
also checked against pooltool's own functions (``--pooltool-cases``); its 0.6.0 wheel pins a
development build of panda3d that PyPI does not carry, so it is not a dependency here.

Every figure is a difference over a speed scale, ``|v| + R|omega|`` summed over the balls, or
an angle in degrees; nothing is timed. docs/sphere3d.md quotes the output.
"""

from __future__ import annotations

import argparse
import importlib.util

import numpy as np

from spinimpact import Body, Surface, solve_pair, solve_sphere

UP = np.array([0.0, 1.0, 0.0])  # spinimpact's vertical; the table is the plane y = 0

#: Pool balls (kg, m), pooltool's defaults.
BALL_MASS, BALL_RADIUS = 0.170097, 0.028575


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def _unit_or_zero(a):
    size = np.sqrt(_dot(a, a))
    safe = np.where(size > 0, size, 1.0)
    return np.where(size[..., None] > 0, a / safe[..., None], 0.0), size


# --- pooltool's equations ---------------------------------------------------------------


def peer_sphere_plane(v, w, normal, radius, mu, e):
    """pooltool's impulse law for a solid sphere striking a half-space.

    pooltool 0.6.0, ``pooltool/physics/resolve/sphere_half_space_collision.py``
    (``resolve_sphere_half_space_collision``; its ball-cushion model
    ``impulse_frictional_inelastic`` calls it with the cushion's normal). With ``n`` the
    outward normal and ``v_n = v . n < 0``: the centre's normal velocity changes by
    ``(1 + e)|v_n|``; the tangential velocity of the contact point ``c_t`` is opposed by
    ``min(mu (1 + e)|v_n|, (2/7)|c_t|)`` (sliding, or the change that stops the slip,
    whichever is smaller); the spin changes by ``-(5/(2R)) n x dv_t`` (a solid sphere,
    ``J = 2 m R^2 / 5``).
    """
    radius = np.asarray(radius)[..., None]
    vn = _dot(v, normal)[..., None]
    dvn = -(1.0 + np.asarray(e)[..., None]) * vn
    slip = v - vn * normal + np.cross(w, -radius * normal)
    direction, speed = _unit_or_zero(slip)
    size = np.minimum(mu * dvn[..., 0], 2.0 / 7.0 * speed)
    dvt = -size[..., None] * direction
    return v + dvn * normal + dvt, w - 2.5 / radius * np.cross(normal, dvt)


def peer_han2005(v, w, radius, mass, height, mu, e):
    """pooltool's ball-cushion model ``han_2005`` (Han 2005, eqs. 14-23).

    pooltool 0.6.0, ``pooltool/physics/resolve/ball_cushion/han_2005/model.py``. Axes of the
    rail: ``x`` towards the cushion (``v_x > 0``), ``y`` along it, ``z`` up; the ball (solid)
    rolls on the table (``v_z = 0``) and meets the cushion's nose at height ``h``, at the
    angle ``theta = arcsin(h/R - 1)`` above its centre. The contact impulse is Keller's for a
    sphere on the plane tangent to the nose (stick when the impulse that stops the slip is
    within the cone), and both the velocity and the spin change by it, except that the
    vertical velocity is left unchanged (the table is assumed to take the vertical impulse).
    """
    theta = np.arcsin(height / radius - 1.0)
    sin, cos = np.sin(theta), np.cos(theta)
    vx, vy, vz = v[..., 0], v[..., 1], v[..., 2]
    wx, wy, wz = w[..., 0], w[..., 1], w[..., 2]
    sx = vx * sin - vz * cos + radius * wy
    sy = -vy - radius * wz * cos + radius * wx * sin
    c = -vx * cos
    inertia = 0.4 * mass * radius**2
    a, b = 3.5 / mass, 1.0 / mass
    pz = -(1.0 + e) * c / b
    s0 = np.hypot(sx, sy)
    sticks = s0 / a <= mu * pz
    safe = np.where(s0 > 0, s0, 1.0)
    px = np.where(sticks, sx / a, mu * pz * sx / safe)
    py = np.where(sticks, sy / a, mu * pz * sy / safe)
    big_x, big_y, big_z = -px * sin - pz * cos, py, px * cos - pz * sin
    after_v = np.stack([vx + big_x / mass, vy + big_y / mass, vz], -1)
    k = radius / inertia
    after_w = np.stack(
        [wx - k * big_y * sin, wy + k * (big_x * sin - big_z * cos), wz + k * big_y * cos], -1
    )
    return after_v, after_w, sticks


def peer_ball_ball(v1, w1, v2, w2, normal, radius, mu, e, *, published=True, up=UP):
    """pooltool's ball-ball model ``frictional_inelastic`` (equal solid balls).

    pooltool 0.6.0, ``pooltool/physics/resolve/ball_ball/frictional_inelastic/__init__.py``
    (after Alciatore's technical proofs TP A-5, A-6, A-14). ``normal`` runs from ball 1's
    centre to ball 2's and lies in the table. The normal velocities follow Newton's law with
    ``e`` for equal masses. Ball 1's velocity changes along the contact point's relative
    tangential velocity ``c_t`` by ``-min(a, |c_t|/7)`` (ball 2's by the opposite; both spins
    by ``(5/(2R)) n x dv_1t``) with

    - ``a = mu e |v_rel,n|`` as published (``published=True``): ``mu`` times the relative
      normal speed *after* the impact;
    - ``a = mu (1 + e)|v_rel,n|/2`` with ``published=False``: ``mu`` times the normal impulse
      per unit mass, Coulomb's law over the whole impact.

    As published, each ball's vertical velocity is then set to zero (the table's part);
    ``published=False`` keeps it.
    """
    e_ = np.asarray(e)[..., None]
    vrel_n = _dot(v1 - v2, normal)[..., None]  # > 0: approaching
    dv1n = -0.5 * (1.0 + e_) * vrel_n
    slip = v1 - v2 + radius * np.cross(w1 + w2, normal)
    slip = slip - _dot(slip, normal)[..., None] * normal
    direction, speed = _unit_or_zero(slip)
    per_mass = e_[..., 0] if published else 0.5 * (1.0 + e_[..., 0])
    size = np.minimum(mu * per_mass * np.abs(vrel_n[..., 0]), speed / 7.0)
    dvt = -size[..., None] * direction
    after1 = v1 + dv1n * normal + dvt
    after2 = v2 - dv1n * normal - dvt
    dw = 2.5 / radius * np.cross(normal, dvt)
    if published:
        after1 = after1 - _dot(after1, up)[..., None] * up
        after2 = after2 - _dot(after2, up)[..., None] * up
    return after1, w1 + dw, after2, w2 + dw


# --- random cases -----------------------------------------------------------------------


def sphere_plane_cases(n, rng):
    """Solid spheres (0.05-0.5 kg, 2-5 cm) on planes of random orientation: velocity and spin
    components normal with standard deviations 3 m/s and 100 rad/s (the normal component made
    approaching), ``mu`` in [0, 1], ``e`` in [0, 1]."""
    normal = rng.normal(size=(n, 3))
    normal /= np.sqrt(_dot(normal, normal))[:, None]
    v = rng.normal(0, 3, (n, 3))
    vn = _dot(v, normal)[:, None]
    v = v - vn * normal - (np.abs(vn) + 0.05) * normal
    return dict(
        v=v,
        w=rng.normal(0, 100, (n, 3)),
        normal=normal,
        mass=rng.uniform(0.05, 0.5, n),
        radius=rng.uniform(0.02, 0.05, n),
        mu=rng.uniform(0, 1, n),
        e=rng.uniform(0, 1, n),
    )


def cushion_cases(n, rng):
    """A pool ball rolling or sliding into a cushion (rail axes): ``v_x`` 0.1-4 m/s towards it,
    ``v_y`` -3..3 m/s along it, ``v_z = 0``; spin components normal, 100 rad/s; nose height
    ``h/R`` in [1.05, 1.6]; ``mu`` in [0, 0.4], ``e`` in [0.5, 1]."""
    v = np.stack([rng.uniform(0.1, 4, n), rng.uniform(-3, 3, n), np.zeros(n)], -1)
    return dict(
        v=v,
        w=rng.normal(0, 100, (n, 3)),
        height=rng.uniform(1.05, 1.6, n) * BALL_RADIUS,
        mu=rng.uniform(0, 0.4, n),
        e=rng.uniform(0.5, 1, n),
    )


def ball_ball_cases(n, rng):
    """Two pool balls on the table (``y`` up): ball 1 at 0.1-5 m/s in a random direction, ball 2
    at rest in half the cases, else at 0-2 m/s; the line of centres horizontal at a cut angle
    uniform in [-85, 85] degrees from the relative velocity; spin components normal, 60 rad/s
    (``R omega`` 1.7 m/s); ``mu`` in [0.01, 0.15], ``e`` in [0.85, 0.98]."""

    def flat(speed):
        angle = rng.uniform(0, 2 * np.pi, n)
        return speed[:, None] * np.stack([np.cos(angle), np.zeros(n), np.sin(angle)], -1)

    v1 = flat(rng.uniform(0.1, 5, n))
    v2 = np.where(rng.random(n)[:, None] < 0.5, 0.0, flat(rng.uniform(0, 2, n)))
    rel = v1 - v2
    heading = np.arctan2(rel[:, 2], rel[:, 0]) + np.radians(rng.uniform(-85, 85, n))
    normal = np.stack([np.cos(heading), np.zeros(n), np.sin(heading)], -1)
    return dict(
        v1=v1,
        w1=rng.normal(0, 60, (n, 3)),
        v2=v2,
        w2=rng.normal(0, 60, (n, 3)),
        normal=normal,
        mu=rng.uniform(0.01, 0.15, n),
        e=rng.uniform(0.85, 0.98, n),
    )


# --- spinimpact on the same cases ---------------------------------------------------------


def ours_sphere_plane(c):
    ball = Body.solid_sphere(mass=c["mass"], radius=c["radius"])
    imp = solve_sphere(
        ball, c["v"], c["w"], mu=c["mu"], kappa=c["e"], surface=Surface(normal=c["normal"])
    )
    return imp.after.velocity, imp.after.spin, imp


def cushion_normal(height, radius=BALL_RADIUS):
    """Outward normal of the plane tangent to the cushion's nose, in rail axes."""
    theta = np.arcsin(height / radius - 1.0)
    return -np.stack([np.cos(theta), np.zeros_like(theta), np.sin(theta)], -1)


def ours_cushion(c):
    ball = Body.solid_sphere(mass=BALL_MASS, radius=BALL_RADIUS)
    imp = solve_sphere(
        ball,
        c["v"],
        c["w"],
        mu=c["mu"],
        kappa=c["e"],
        surface=Surface(normal=cushion_normal(c["height"])),
    )
    return imp.after.velocity, imp.after.spin, imp


def ours_ball_ball(c):
    ball = Body.solid_sphere(mass=BALL_MASS, radius=BALL_RADIUS)
    # spinimpact's normal runs from ball 2's centre to ball 1's
    imp = solve_pair(
        ball,
        ball,
        velocity1=c["v1"],
        spin1=c["w1"],
        velocity2=c["v2"],
        spin2=c["w2"],
        normal=-c["normal"],
        mu=c["mu"],
        kappa=c["e"],
    )
    return imp


def peer_cases_ball_ball(c, published=True):
    return peer_ball_ball(
        c["v1"],
        c["w1"],
        c["v2"],
        c["w2"],
        c["normal"],
        BALL_RADIUS,
        c["mu"],
        c["e"],
        published=published,
    )


# --- measures -----------------------------------------------------------------------------


def _norm(a):
    return np.sqrt(_dot(a, a))


def _summary(x):
    return f"median {np.median(x):.2e}, 99% {np.quantile(x, 0.99):.2e}, max {np.max(x):.2e}"


def _heading_deg(v):
    """Direction of travel in the table (degrees, about ``y``)."""
    return np.degrees(np.arctan2(v[..., 2], v[..., 0]))


def _flat(a):
    """The part of ``a`` in the table (its vertical component removed)."""
    return a - _dot(a, UP)[..., None] * UP


def _angle_diff(a, b):
    return np.abs((a - b + 180.0) % 360.0 - 180.0)


def report(n, seed, pooltool_cases):
    rng = np.random.default_rng(seed)
    print(f"pooltool's equations beside spinimpact, {n:,} random cases each (seed {seed})\n")

    c = sphere_plane_cases(n, rng)
    v, w, imp = ours_sphere_plane(c)
    pv, pw = peer_sphere_plane(c["v"], c["w"], c["normal"], c["radius"], c["mu"], c["e"])
    scale = _norm(c["v"]) + c["radius"] * _norm(c["w"])
    print("1. Sphere on a plane (pooltool's sphere-half-space law; solid spheres, any normal)")
    print(f"   velocity after:  {_summary(_norm(pv - v) / scale)}  (over |v| + R|w|)")
    print(f"   R * spin after:  {_summary(c['radius'] * _norm(pw - w) / scale)}")
    print(f"   regimes here: {np.mean(imp.grips):.1%} leave rolling (stick), the rest slip\n")

    c = cushion_cases(n, rng)
    v, w, imp = ours_cushion(c)
    pv, pw, sticks = peer_han2005(
        c["v"], c["w"], BALL_RADIUS, BALL_MASS, c["height"], c["mu"], c["e"]
    )
    scale = _norm(c["v"]) + BALL_RADIUS * _norm(c["w"])
    print("2. Ball on a cushion (pooltool's han_2005) against a sphere on the nose's plane")
    print(f"   horizontal velocity: {_summary(_norm((pv - v)[:, :2]) / scale)}")
    print(f"   R * spin:            {_summary(BALL_RADIUS * _norm(pw - w) / scale)}")
    print(f"   stick/slip decision: the same in {np.mean(sticks == imp.grips):.2%} of cases")
    up = np.abs(v[:, 2]) / scale
    down = np.mean(v[:, 2] < 0)
    print(f"   vertical velocity (ours; pooltool keeps 0): {_summary(up)}, {down:.1%} downward")
    lost = 0.5 * BALL_MASS * v[:, 2] ** 2 / imp.kinetic_energy_before
    print(f"   kinetic energy in that vertical motion: {_summary(lost)} of the incident\n")

    c = ball_ball_cases(n, rng)
    imp = ours_ball_ball(c)
    v1, v2 = imp.after1.velocity, imp.after2.velocity
    scale = _norm(c["v1"]) + _norm(c["v2"]) + BALL_RADIUS * (_norm(c["w1"]) + _norm(c["w2"]))
    print("3. Two pool balls (pooltool's frictional_inelastic) against solve_pair")
    variants = (
        ("Coulomb's impulse, vertical kept", False, c["e"]),
        ("as published", True, c["e"]),
        ("as published, e = 1 (ours with e = 1 too)", True, 1.0),
    )
    for name, published, e in variants:
        cases = dict(c, e=np.broadcast_to(e, c["mu"].shape))
        ref = imp if e is c["e"] else ours_ball_ball(cases)
        r1, r2 = ref.after1.velocity, ref.after2.velocity
        p1, q1, p2, q2 = peer_cases_ball_ball(cases, published)
        dv = np.maximum(_norm(_flat(p1) - _flat(r1)), _norm(_flat(p2) - _flat(r2))) / scale
        dw = (
            BALL_RADIUS
            * np.maximum(_norm(q1 - ref.after1.spin), _norm(q2 - ref.after2.spin))
            / scale
        )
        print(f"   {name}:")
        print(f"     velocities in the table: {_summary(dv)}")
        print(f"     R * spins:               {_summary(dw)}")
    p1, q1, p2, q2 = peer_cases_ball_ball(c, True)
    vrel_n = np.abs(_dot(c["v1"] - c["v2"], c["normal"]))
    slip = _norm(imp.slip_before.array)
    peer_sticks = slip / 7.0 <= c["mu"] * c["e"] * vrel_n
    print("   as published, in detail:")
    print(
        f"     stick or slip: the same in {np.mean(peer_sticks == imp.grips):.2%} of cases "
        f"(ours stick in {np.mean(imp.grips):.1%}, pooltool's in {np.mean(peer_sticks):.1%})"
    )
    both = ~peer_sticks & ~imp.grips
    ours = _norm(imp.friction_impulse.array) / BALL_MASS
    ratio = (c["mu"] * c["e"] * vrel_n / ours)[both]
    expect = (2 * c["e"] / (1 + c["e"]))[both]
    print(
        f"     friction impulse, pooltool's over ours where both slide: {ratio.min():.4f} to "
        f"{ratio.max():.4f}; |ratio - 2e/(1+e)| <= {np.max(np.abs(ratio - expect)):.1e}"
    )
    rest = _norm(c["v2"]) == 0
    throw = _angle_diff(_heading_deg(v2), _heading_deg(-imp.normal.array))[rest]
    diff = _angle_diff(_heading_deg(p2), _heading_deg(v2))[rest]
    print(f"     object ball at rest ({rest.sum():,} cases): throw (ours, deg) {_summary(throw)}")
    print(f"       direction, pooltool's minus ours (deg):      {_summary(diff)}")
    vertical = 0.5 * BALL_MASS * (_dot(v1, UP) ** 2 + _dot(v2, UP) ** 2)
    print(
        f"     vertical motion after (ours; pooltool sets it to 0): "
        f"{_summary(vertical / imp.kinetic_energy_before)} of the kinetic energy\n"
    )

    if pooltool_cases and importlib.util.find_spec("pooltool") is not None:
        check_against_pooltool(min(pooltool_cases, n), seed)
    elif pooltool_cases:
        print("pooltool is not installed: the transcriptions were not run against it.")


# --- pooltool itself, where installed -------------------------------------------------------

#: Ours (x along the table, y up, z = x cross y) to pooltool's (x, y in the table, z up).
TO_POOLTOOL = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def pooltool_sphere_plane(c):
    """pooltool's own ``resolve_sphere_half_space_collision``, one case at a time."""
    from pooltool.physics.resolve.sphere_half_space_collision import (
        resolve_sphere_half_space_collision,
    )

    out_v, out_w = np.empty_like(c["v"]), np.empty_like(c["w"])
    for i in range(len(c["v"])):
        rvw = np.array([np.zeros(3), c["v"][i], c["w"][i]])
        rvw = resolve_sphere_half_space_collision(
            c["normal"][i], rvw, c["radius"][i], c["mu"][i], c["e"][i]
        )
        out_v[i], out_w[i] = rvw[1], rvw[2]
    return out_v, out_w


def pooltool_han2005(c):
    """pooltool's own ``han2005``, one case at a time (rail axes = table axes)."""
    from pooltool.physics.resolve.ball_cushion.han_2005.model import han2005

    out_v, out_w = np.empty_like(c["v"]), np.empty_like(c["w"])
    for i in range(len(c["v"])):
        rvw = np.array([np.zeros(3), c["v"][i], c["w"][i]])
        rvw = han2005(
            rvw, np.array([1.0, 0.0]), BALL_RADIUS, BALL_MASS, c["height"][i], c["e"][i], c["mu"][i]
        )
        out_v[i], out_w[i] = rvw[1], rvw[2]
    return out_v, out_w


def pooltool_ball_ball(c):
    """pooltool's own ``frictional_inelastic`` kernel, one case at a time, in its axes."""
    from pooltool.physics.resolve.ball_ball.frictional_inelastic import _resolve_ball_ball

    m = TO_POOLTOOL
    out = [np.empty_like(c["v1"]) for _ in range(4)]
    for i in range(len(c["v1"])):
        n = m @ c["normal"][i]
        r1 = np.array([np.zeros(3), m @ c["v1"][i], m @ c["w1"][i]])
        r2 = np.array([2 * BALL_RADIUS * n, m @ c["v2"][i], m @ c["w2"][i]])
        a, b = _resolve_ball_ball(r1, r2, BALL_RADIUS, c["mu"][i], c["e"][i])
        for k, x in enumerate((a[1], a[2], b[1], b[2])):
            out[k][i] = m.T @ x
    return out


def check_against_pooltool(n, seed):
    from importlib.metadata import version

    rng = np.random.default_rng(seed + 1)
    print(
        f"Transcriptions against pooltool {version('pooltool-billiards')}'s own functions, "
        f"{n:,} cases each (largest difference over the speed scale):"
    )
    c = sphere_plane_cases(n, rng)
    pv, pw = pooltool_sphere_plane(c)
    tv, tw = peer_sphere_plane(c["v"], c["w"], c["normal"], c["radius"], c["mu"], c["e"])
    scale = _norm(c["v"]) + c["radius"] * _norm(c["w"])
    err = np.maximum(_norm(pv - tv), c["radius"] * _norm(pw - tw)) / scale
    print(f"   sphere-half-space: {err.max():.1e}")
    c = cushion_cases(n, rng)
    pv, pw = pooltool_han2005(c)
    tv, tw, _ = peer_han2005(c["v"], c["w"], BALL_RADIUS, BALL_MASS, c["height"], c["mu"], c["e"])
    scale = _norm(c["v"]) + BALL_RADIUS * _norm(c["w"])
    err = np.maximum(_norm(pv - tv), BALL_RADIUS * _norm(pw - tw)) / scale
    print(f"   han_2005:          {err.max():.1e}")
    c = ball_ball_cases(n, rng)
    got = pooltool_ball_ball(c)
    mine = peer_cases_ball_ball(c, True)
    scale = _norm(c["v1"]) + _norm(c["v2"]) + BALL_RADIUS * (_norm(c["w1"]) + _norm(c["w2"]))
    err = max(
        np.max(_norm(a - b) * (1 if k % 2 == 0 else BALL_RADIUS) / scale)
        for k, (a, b) in enumerate(zip(got, mine, strict=True))
    )
    print(f"   frictional_inelastic: {err:.1e}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="random cases per comparison")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument(
        "--pooltool-cases",
        type=int,
        default=2000,
        help="cases run through pooltool itself, where it is installed",
    )
    args = parser.parse_args(argv)
    report(args.n, args.seed, args.pooltool_cases)


if __name__ == "__main__":
    main()
