"""Independent numerical route for spheres in 3D: a sphere on a plane, and two spheres.

Direct integration in the normal impulse ``tau`` of the impulse-momentum equations of the
bodies themselves, as 3-vectors; nothing here uses a collision matrix, ``zeta`` or any
closed form of the package. One integrator serves both problems:

* body 1 (mass ``m_1``, moment of inertia ``J_1 = m_1 rho_1^2``, radius ``R_1``) touches at
  ``r_1 = -R_1 n`` from its centre, body 2 at ``r_2 = +R_2 n``; ``n`` is the unit normal from
  body 2 to body 1 (for a sphere on a plane: the plane's outward normal, and the plane is
  body 2 with ``1/m_2 = 1/J_2 = 0``, ``R_2 = 0``, centre velocity ``V_s`` and no spin);
* the contact point of 1 moves relative to that of 2 with
  ``c = (v_1 + w_1 x r_1) - (v_2 + w_2 x r_2)``, split into ``c_n = c.n`` and ``c_t``;
* an impulse ``dP = (n + s) dtau`` on body 1 (``-dP`` on body 2), with ``s = dF/dtau`` the
  tangential friction ratio (a vector in the tangent plane), changes
  ``v_1`` by ``dP/m_1``, ``w_1`` by ``(r_1 x dP)/J_1``, ``v_2`` by ``-dP/m_2``, ``w_2`` by
  ``(r_2 x (-dP))/J_2``; the rate of ``c`` is whatever these changes make it;
* Coulomb: while ``c_t != 0``, ``s = -mu c_t/|c_t|``, re-evaluated at every step from the
  current ``c_t`` (the integrator does not assume that the slip keeps its direction: it
  records how far the direction turned). When ``|c_t|`` reaches 0 (an event located inside
  the step), the ratio ``s*`` that keeps ``dc_t/dtau = 0`` is solved from the bodies'
  equations (a 2x2 system in a tangent basis); the contact sticks if ``|s*| <= mu``;
* compression ends at the event ``c_n = 0`` (``tau_0``); Poisson's law ends the impact at
  ``tau_1 = (1 + kappa) tau_0``;
* works: ``W^n = int c_n dtau``, ``W^t = int c . dF``, each over compression
  ``[0, tau_0]`` and restitution ``[tau_0, tau_1]``; the energy change is computed
  separately from the bodies' kinetic energies (in the frame moving with body 2's initial
  velocity: the plane's frame; for two spheres any frame gives the same change).

Each impact advances in steps no longer than the impulse that changes its contact velocity
by ``1/resolution`` of its incidence speed ``|c_n(0)| + |c_t(0)|``; the events shorten the
step to land on them, and the event's value (``c_n = 0``, ``c_t = 0``) is set exactly. On a
step the friction ratio is constant, so ``c`` is advanced exactly (linear in ``tau``) and the
works (trapezoids of linear integrands) are exact: where the slip keeps its direction, as
the physics says it does, the result differs from the exact answer by rounding only. The
contact velocity is advanced with its own rates from ``c(0)`` rather than recomputed from
the bodies' velocities (which loses digits when a body spins fast); the bodies' final
velocities are the impulse-momentum balance for the accumulated impulse ``P = tau_1 n + F``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

REGIMES = ("frictionless", "no-slip", "stick-compression", "stick-restitution", "slip")


@dataclass
class ContactReference:
    """What the integration found, one entry per impact (vectors with a last axis of 3)."""

    regime: np.ndarray  # names from REGIMES, by the sequence of events
    tau0: np.ndarray
    tau1: np.ndarray
    tau_slip: np.ndarray  # where the slip stopped: 0 if c_t(0) = 0; else inf if mu = 0;
    # extrapolated past tau_1 at the final slip rate when the slip outlasts the impact
    friction: np.ndarray  # F on body 1, (..., 3)
    normal_after: np.ndarray  # c_n at tau_1
    slip_after: np.ndarray  # c_t at tau_1, (..., 3)
    slip_before: np.ndarray  # c_t at 0, (..., 3)
    normal_before: np.ndarray
    velocity1: np.ndarray  # bodies after the impact, (..., 3)
    spin1: np.ndarray
    velocity2: np.ndarray
    spin2: np.ndarray
    work_compression_normal: np.ndarray
    work_compression_tangential: np.ndarray
    work_restitution_normal: np.ndarray
    work_restitution_tangential: np.ndarray
    energy_before: np.ndarray  # kinetic energy in body 2's initial frame
    energy_change: np.ndarray  # T(tau_1) - T(0) there, from the bodies' velocities
    slip_turn: np.ndarray  # largest |sin| of the angle between c_t(tau) and c_t(0)
    stick_holds: np.ndarray  # |s*| <= mu (Coulomb can hold a stopped contact)
    steps: int


def _dot(a, b):
    return np.sum(a * b, axis=-1)


def _norm(a):
    return np.sqrt(_dot(a, a))


def integrate(
    inv_mass1,
    inv_inertia1,
    radius1,
    velocity1,
    spin1,
    inv_mass2,
    inv_inertia2,
    radius2,
    velocity2,
    spin2,
    normal,
    mu,
    kappa,
    resolution=64,
):
    """Integrate many contacts at once. Scalars broadcast to a shape ``S``, vectors to
    ``S + (3,)``; ``normal`` must be a unit vector and the contact must approach
    (``c_n(0) < 0``). Inverse masses and inertias may be 0 (an immovable body 2)."""
    scal = [inv_mass1, inv_inertia1, radius1, inv_mass2, inv_inertia2, radius2, mu, kappa]
    vecs = [velocity1, spin1, velocity2, spin2, normal]
    scal = [np.asarray(a, dtype=float) for a in scal]
    vecs = [np.asarray(a, dtype=float) for a in vecs]
    shape = np.broadcast_shapes(*(a.shape for a in scal), *(a.shape[:-1] for a in vecs))
    im1, iJ1, R1, im2, iJ2, R2, mu, kappa = (np.broadcast_to(a, shape).ravel() for a in scal)
    v1_0, w1_0, v2_0, w2_0, n = (np.broadcast_to(a, shape + (3,)).reshape(-1, 3) for a in vecs)
    N = im1.size
    col = lambda a: a[:, None]  # noqa: E731  scalar per case -> column for vectors

    r1 = -col(R1) * n
    r2 = col(R2) * n

    def contact(v1, w1, v2, w2):
        return (v1 + np.cross(w1, r1)) - (v2 + np.cross(w2, r2))

    def body_changes(P):
        """Velocity and spin changes of both bodies for an impulse P on body 1."""
        return (
            col(im1) * P,
            col(iJ1) * np.cross(r1, P),
            -col(im2) * P,
            col(iJ2) * np.cross(r2, -P),
        )

    def contact_rate(g):
        """dc/dtau for an impulse direction g = n + s (per unit normal impulse)."""
        dv1, dw1, dv2, dw2 = body_changes(g)
        return (dv1 + np.cross(dw1, r1)) - (dv2 + np.cross(dw2, r2))

    # tangent basis: c_t and s are kept as two components along (e1, e2), so that they
    # stay exactly in the tangent plane whatever the rounding of the 3D vectors
    helper = np.where(col(np.abs(n[:, 0]) < 0.9), [[1.0, 0, 0]], [[0, 1.0, 0]])
    e1 = np.cross(n, helper)
    e1 /= col(_norm(e1))
    e2 = np.cross(n, e1)

    def split(c):
        """Normal component and tangential components (along e1, e2) of a 3-vector."""
        return _dot(c, n), np.stack([_dot(c, e1), _dot(c, e2)], -1)

    def tangent(t):
        return col(t[:, 0]) * e1 + col(t[:, 1]) * e2

    v_abs = _norm(v1_0) + _norm(v2_0) + R1 * _norm(w1_0) + R2 * _norm(w2_0)
    c0 = contact(v1_0, w1_0, v2_0, w2_0)
    cn, ct = split(c0)
    if np.any(cn >= 0):
        raise ValueError("every contact must approach (c_n(0) < 0)")
    # a slip below the rounding of c (a head-on impact on a tilted plane) is no slip
    ct = np.where(col(_norm(ct) <= 16 * np.finfo(float).eps * v_abs), 0.0, ct)
    cn_0, ct_0 = cn.copy(), ct.copy()
    scale = np.abs(cn) + _norm(ct)

    # Coulomb's decision at c_t = 0: dc_t/dtau = A s + b, A a 2x2 matrix in (e1, e2)
    b = split(contact_rate(n))[1]
    A = np.stack([split(contact_rate(n + e))[1] - b for e in (e1, e2)], -1)
    s_hold = np.linalg.solve(A, -b[..., None])[..., 0]
    holds = _norm(s_hold) <= mu

    frictionless = mu == 0
    at_rest = ~frictionless & (_norm(ct) == 0)
    stuck = at_rest.copy()
    tau = np.zeros(N)
    F = np.zeros((N, 2))
    tau0 = np.full(N, np.nan)
    tau1 = np.full(N, np.inf)
    tau_slip = np.where(_norm(ct) == 0, 0.0, np.inf)
    compressing = np.ones(N, dtype=bool)
    done = np.zeros(N, dtype=bool)
    wcn, wct, wrn, wrt = (np.zeros(N) for _ in range(4))
    turn = np.zeros(N)
    dir0 = ct_0 / col(np.where(_norm(ct_0) > 0, _norm(ct_0), 1.0))
    inf = np.full(N, np.inf)
    steps = 0

    def ratio():
        slip = _norm(ct)
        with np.errstate(invalid="ignore", divide="ignore"):
            sliding = -col(mu) * ct / col(slip)
        s = np.where(col(stuck), s_hold, sliding)
        return np.where(col(frictionless | (~stuck & (slip == 0))), 0.0, s)

    while not done.all():
        steps += 1
        if steps > 100_000:
            raise RuntimeError("reference integration did not finish")
        s = ratio()
        rate = contact_rate(n + tangent(s))
        rn, rt = split(rate)
        rt = np.where(col(stuck), 0.0, rt)  # s_hold makes it 0 to rounding; stuck stays stuck
        with np.errstate(divide="ignore", invalid="ignore"):
            h = scale / resolution / _norm(rate)
            slipping = ~frictionless & ~stuck
            toward = _dot(ct, rt)
            d_s = np.where(slipping & (toward < 0), -toward / _dot(rt, rt), inf)
            # the slip stops only if c_t passes through 0 (not merely nearest to it)
            miss = _norm(ct + col(np.where(np.isfinite(d_s), d_s, 0.0)) * rt)
            d_s = np.where(miss <= 1e-9 * _norm(ct), d_s, inf)
            d_c = np.where(compressing & (rn > 0), -cn / rn, inf)
            d_c = np.where(compressing & (cn >= 0), 0.0, d_c)
        d_e = np.where(compressing, inf, np.maximum(tau1 - tau, 0.0))
        length = np.minimum(np.minimum(h, d_s), np.minimum(d_c, d_e))
        length = np.where(done, 0.0, length)
        hit_s = ~done & (length == d_s)
        hit_c = ~done & (length == d_c)
        hit_e = ~done & (length == d_e)

        cn1 = np.where(hit_c, 0.0, cn + rn * length)
        ct1 = np.where(col(hit_s), 0.0, ct + rt * col(length))
        wn = 0.5 * length * (cn + cn1)
        wt = 0.5 * length * (_dot(ct, s) + _dot(ct1, s))
        wcn += np.where(compressing, wn, 0.0)
        wct += np.where(compressing, wt, 0.0)
        wrn += np.where(compressing, 0.0, wn)
        wrt += np.where(compressing, 0.0, wt)
        cn, ct = np.where(done, cn, cn1), np.where(col(done), ct, ct1)
        F = F + s * col(length)
        tau = tau + length
        nc = _norm(ct)
        with np.errstate(invalid="ignore", divide="ignore"):
            d = ct / col(nc)
            sin = np.abs(d[:, 0] * dir0[:, 1] - d[:, 1] * dir0[:, 0])
        turn = np.where(nc > 0, np.maximum(turn, sin), turn)

        tau0 = np.where(hit_c, tau, tau0)
        tau1 = np.where(hit_c, (1.0 + kappa) * tau, tau1)
        compressing &= ~hit_c
        tau_slip = np.where(hit_s, tau, tau_slip)
        stuck |= hit_s & holds
        tau = np.where(hit_e, tau1, tau)
        done |= hit_e

    ct_end = ct
    F = tangent(F)
    P = col(tau) * n + F
    dv1, dw1, dv2, dw2 = body_changes(P)
    v1, w1, v2, w2 = v1_0 + dv1, w1_0 + dw1, v2_0 + dv2, w2_0 + dw2

    def kinetic(v1, w1, v2, w2):
        """Kinetic energy of the bodies in the frame moving with v2_0."""
        with np.errstate(divide="ignore", invalid="ignore"):
            t = 0.5 * _dot(v1 - v2_0, v1 - v2_0) / im1 + 0.5 * _dot(w1, w1) / iJ1
            t2 = np.where(im2 > 0, 0.5 * _dot(v2 - v2_0, v2 - v2_0) / im2, 0.0)
            t2 = t2 + np.where(iJ2 > 0, 0.5 * _dot(w2, w2) / iJ2, 0.0)
        return t + t2

    t0 = kinetic(v1_0, w1_0, v2_0, w2_0)
    dT = kinetic(v1, w1, v2, w2) - t0

    # a slip that outlasts the impact would stop at tau_1 + |c_t| / (rate of |c_t|)
    sliding = ~frictionless & ~at_rest & ~np.isfinite(tau_slip)
    s = ratio()
    rate_t = split(contact_rate(n + tangent(s)))[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        fall = -_dot(rate_t, ct) / _norm(ct)
        tau_slip = np.where(sliding, tau1 + _norm(ct) / fall, tau_slip)

    regime_code = np.select(
        [frictionless, at_rest, tau_slip <= tau0, tau_slip <= tau1],
        [0, 1, 2, 3],
        4,
    )
    out = dict(
        regime=np.asarray(REGIMES)[regime_code],
        tau0=tau0,
        tau1=tau1,
        tau_slip=tau_slip,
        friction=F,
        normal_after=cn,
        slip_after=tangent(ct_end),
        slip_before=tangent(ct_0),
        normal_before=cn_0,
        velocity1=v1,
        spin1=w1,
        velocity2=v2,
        spin2=w2,
        work_compression_normal=wcn,
        work_compression_tangential=wct,
        work_restitution_normal=wrn,
        work_restitution_tangential=wrt,
        energy_before=t0,
        energy_change=dT,
        slip_turn=turn,
        stick_holds=holds | frictionless,
    )
    out = {k: v.reshape(shape + v.shape[1:]) for k, v in out.items()}
    return ContactReference(**out, steps=steps)


def sphere_on_plane(mass, radius, gyration, velocity, spin, normal, surface_velocity, mu, kappa,
                    **kw):  # fmt: skip
    """A sphere (body 1) on a rigid plane of infinite mass (body 2) with unit ``normal``
    moving at ``surface_velocity``."""
    mass, radius, gyration = (np.asarray(a, dtype=float) for a in (mass, radius, gyration))
    return integrate(
        1.0 / mass, 1.0 / (mass * gyration**2), radius, velocity, spin,
        0.0, 0.0, 0.0, surface_velocity, np.zeros(3), normal, mu, kappa, **kw,
    )  # fmt: skip


def sphere_pair(ball1, ball2, velocity1, spin1, velocity2, spin2, normal, mu, kappa, **kw):
    """Two spheres; ``ball1``, ``ball2`` are ``(mass, radius, gyration)`` tuples and
    ``normal`` the unit vector from ball 2's centre to ball 1's."""
    (m1, R1, g1), (m2, R2, g2) = (tuple(np.asarray(a, dtype=float) for a in b)
                                  for b in (ball1, ball2))  # fmt: skip
    return integrate(
        1.0 / m1, 1.0 / (m1 * g1**2), R1, velocity1, spin1,
        1.0 / m2, 1.0 / (m2 * g2**2), R2, velocity2, spin2, normal, mu, kappa, **kw,
    )  # fmt: skip


# ---------------------------------------------------------------------------------------
# random cases


def _unit(rng, n):
    u = rng.normal(size=(n, 3))
    return u / np.linalg.norm(u, axis=-1)[:, None]


def _tangent_direction(rng, nrm):
    t = rng.normal(size=nrm.shape)
    t -= np.sum(t * nrm, -1)[:, None] * nrm
    return t / np.linalg.norm(t, axis=-1)[:, None]


def _aim(rng, target, zeta, mu, kappa, cn):
    """|c_t| for each target regime from the scalar thresholds ``zeta mu`` and
    ``(1 + kappa) zeta mu`` (only to spread the sample; the tests never use it as the
    answer), at a random fraction inside the regime's interval, away from its ends."""
    n = target.size
    lo, hi = zeta * mu, (1 + kappa) * zeta * mu
    ratio = np.select(
        [target == 0, target == 1, target == 2, target == 3],
        [rng.uniform(0, 3, n), np.zeros(n), rng.uniform(0.02, 0.98, n) * lo,
         lo + rng.uniform(0.02, 0.98, n) * (hi - lo)],
        hi * (1.02 + rng.exponential(2.0, n)),
    )  # fmt: skip
    return ratio * np.abs(cn)


def _gyration(rng, radius):
    """Solid spheres, thin shells, thick shells, and heavy cores (``zeta = 6`` and ``12``).
    No sphere has its mass further out than a thin shell's (``rho > sqrt(2/3) R``, ``zeta <
    5/2``): the solvers refuse it (tests/model/test_sphere_inputs.py)."""
    n = radius.size
    zeta = rng.choice([3.5, 2.5, 6.0, 12.0], n)
    thick = rng.random(n) < 0.3
    zeta[thick] = rng.uniform(2.5, 3.5, n)[thick]
    return radius / np.sqrt(zeta - 1.0), zeta


def random_sphere_cases(n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` spheres on planes, a fifth aimed at each regime.

    Masses over three decades, radii over two, gyrations as :func:`_gyration`; ``mu`` in
    ``(0.01, 1.5]`` (0 for the frictionless fifth), ``kappa`` in ``[0, 1]`` with its ends;
    approach ``|c_n|`` over two decades, spins of random direction up to 30 ``|c_n|/R``.
    A third of the surfaces are the default ``y = 0`` at rest (``tilted`` false), a third
    tilted at random, a third tilted and moving (up to several m/s). The no-slip fifth is
    built on the default plane (or one moving along its normal) with ``c_t = 0`` exactly;
    one case in ten of the frictionless and no-slip targets is head-on (``v`` along ``-n``,
    spin about ``n``), also on tilted planes (there ``c_t`` is 0 to rounding only: flagged
    ``near_rest``). ``planar`` marks plane-motion cases (``v_z = w_x = w_y = 0`` on the
    default plane), one in ten of the stick and slip targets.
    """
    rng = np.random.default_rng(seed)
    target = np.arange(n) % 5
    mass = 10 ** rng.uniform(-2, 1, n)
    radius = 10 ** rng.uniform(-2.5, -0.5, n)
    gyration, zeta = _gyration(rng, radius)
    mu = rng.uniform(0.01, 1.5, n)
    mu[target == 0] = 0.0
    kappa = rng.uniform(0, 1, n)
    kappa[rng.random(n) < 0.05] = 0.0
    kappa[rng.random(n) < 0.05] = 1.0
    kappa[(target == 3) & (kappa == 0)] = 0.5

    kind = rng.integers(0, 3, n)  # 0: default plane, 1: tilted, 2: tilted and moving
    kind[target == 1] = 0
    planar = np.isin(target, (2, 3, 4)) & (rng.random(n) < 0.1)
    kind[planar] = 0
    head_on = np.isin(target, (0, 1)) & (rng.random(n) < 0.1)
    kind[head_on] = rng.integers(0, 3, n)[head_on]
    normal = np.tile([0.0, 1.0, 0.0], (n, 1))
    tilted = kind > 0
    normal[tilted] = _unit(rng, n)[tilted]
    surface_velocity = np.zeros((n, 3))
    moving = kind == 2
    surface_velocity[moving] = (rng.normal(size=(n, 3)) * 3)[moving]
    along = (target == 1) & (rng.random(n) < 0.3)  # default plane moving along its normal
    surface_velocity[along, 1] = rng.normal(size=n)[along]

    cn = -(10 ** rng.uniform(-1, 1, n))
    slip = _aim(rng, target, zeta, mu, kappa, cn)
    ct = slip[:, None] * _tangent_direction(rng, normal)
    spin_scale = np.abs(cn) / radius * 10 ** rng.uniform(-2, np.log10(30), n)
    spin = rng.normal(size=(n, 3)) * spin_scale[:, None]
    ct[planar, 1:] = 0.0
    ct[planar, 0] = slip[planar] * rng.choice([-1.0, 1.0], n)[planar]
    spin[planar, :2] = 0.0
    about_normal = rng.normal(size=n) * np.abs(cn) / radius
    spin[head_on] = (about_normal[:, None] * normal)[head_on]
    ct[head_on] = 0.0
    c = cn[:, None] * normal + ct
    velocity = c + surface_velocity - np.cross(spin, -radius[:, None] * normal)
    # no slip, exactly: on the default plane c_t = (vx + R wz - Vx, vz - R wx - Vz)
    rest = target == 1
    velocity[rest, 0] = -radius[rest] * spin[rest, 2]
    velocity[rest, 2] = radius[rest] * spin[rest, 0]
    velocity[head_on] = (cn[:, None] * normal + surface_velocity)[head_on]
    return dict(
        mass=mass, radius=radius, gyration=gyration, zeta=zeta, mu=mu, kappa=kappa,
        velocity=velocity, spin=spin, normal=normal, surface_velocity=surface_velocity,
        target=np.asarray(REGIMES)[target], tilted=tilted, moving=moving, planar=planar,
        head_on=head_on, near_rest=head_on & tilted,
    )  # fmt: skip


def random_pair_cases(n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` pairs of spheres, a fifth aimed at each regime (by the pair's ``zeta``, which
    is used only to aim).

    Each ball has its own mass (three decades), radius (two decades) and gyration; normals
    are random, except for the no-slip fifth, which is built with ``c_t = 0`` exactly on a
    coordinate axis (ball 2 moving along the normal only, without spin), and head-on cases
    (one in ten of the frictionless and no-slip targets) with velocities along the normal
    and spins about it on random normals (``c_t`` zero to rounding: ``near_rest``).
    """
    rng = np.random.default_rng(seed)
    target = np.arange(n) % 5
    m1, m2 = 10 ** rng.uniform(-2, 1, n), 10 ** rng.uniform(-2, 1, n)
    R1, R2 = 10 ** rng.uniform(-2.5, -0.5, n), 10 ** rng.uniform(-2.5, -0.5, n)
    (g1, _), (g2, _) = _gyration(rng, R1), _gyration(rng, R2)
    w_nn = 1 / m1 + 1 / m2
    zeta = (w_nn + R1**2 / (m1 * g1**2) + R2**2 / (m2 * g2**2)) / w_nn
    mu = rng.uniform(0.01, 1.5, n)
    mu[target == 0] = 0.0
    kappa = rng.uniform(0, 1, n)
    kappa[rng.random(n) < 0.05] = 0.0
    kappa[rng.random(n) < 0.05] = 1.0
    kappa[(target == 3) & (kappa == 0)] = 0.5
    normal = _unit(rng, n)
    rest = target == 1
    head_on = np.isin(target, (0, 1)) & (rng.random(n) < 0.1)
    axis = rng.integers(0, 3, n)
    axial = rest & ~head_on
    normal[axial] = np.eye(3)[axis[axial]] * rng.choice([-1.0, 1.0], n)[axial, None]

    cn = -(10 ** rng.uniform(-1, 1, n))
    slip = _aim(rng, target, zeta, mu, kappa, cn)
    ct = slip[:, None] * _tangent_direction(rng, normal)
    spin_scale = (np.abs(cn) * 10 ** rng.uniform(-2, np.log10(30), n))[:, None]
    w1 = rng.normal(size=(n, 3)) * spin_scale / R1[:, None]
    w2 = rng.normal(size=(n, 3)) * spin_scale / R2[:, None]
    v2 = rng.normal(size=(n, 3)) * np.abs(cn)[:, None] * 3
    # ball 2 moving along the normal only, not spinning: c_t = v1 + w1 x (-R1 n) tangential
    v2[axial] = (normal * rng.normal(size=n)[:, None])[axial]
    w2[axial] = 0.0
    for w, R in ((w1, R1), (w2, R2)):  # spins about the normal only
        w[head_on] = (normal * (rng.normal(size=n) * np.abs(cn) / R)[:, None])[head_on]
    v2[head_on] = (normal * rng.normal(size=n)[:, None])[head_on]
    ct[head_on | axial] = 0.0
    c = cn[:, None] * normal + ct
    v1 = c + v2 + np.cross(w2, R2[:, None] * normal) - np.cross(w1, -R1[:, None] * normal)
    # exact zero slip on an axis: the tangential components of v1 cancel w1 x (-R1 n)
    for k in range(3):
        on = axial & (axis == k)
        rot = np.cross(w1[on], -R1[on, None] * normal[on])
        for j in range(3):
            if j != k:
                v1[on, j] = -rot[:, j]
        v1[on, k] = (cn[on] * normal[on, k]) + v2[on, k]
    v1[head_on] = (cn[:, None] * normal + v2)[head_on]
    return dict(
        mass1=m1, radius1=R1, gyration1=g1, mass2=m2, radius2=R2, gyration2=g2, zeta=zeta,
        mu=mu, kappa=kappa, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=normal,
        target=np.asarray(REGIMES)[target], head_on=head_on, near_rest=head_on,
    )  # fmt: skip
