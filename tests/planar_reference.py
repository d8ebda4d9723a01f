"""Independent numerical route for a planar body striking a fixed plane at one point.

Direct integration in the normal impulse ``tau`` of the impulse-momentum equations of a
free rigid body (mass ``m``, moment of inertia ``J`` about its centre of mass) touching the
plane ``y = 0`` at the offset ``r = (rx, ry)`` from its centre of mass:

* ``m dvx = s dtau``, ``m dvy = dtau``, ``J domega = (rx - ry s) dtau``, where ``s = df/dtau``
  is the friction ratio;
* the contact point moves with ``u = vx - omega ry`` (slip), ``v = vy + omega rx`` (normal);
* Coulomb: while ``u != 0``, ``s = -mu sign(u)``. At ``u = 0`` the ratio ``s*`` that keeps
  ``du/dtau = 0`` is found from the body's equations; the contact sticks if
  ``|s*| <= mu``, otherwise it slips in the one direction ``e`` for which ``s = -mu e``
  makes ``e du/dtau > 0`` (the only choice consistent with Coulomb's law);
* compression ends at the event ``v = 0`` (``tau_c``); the impact ends at the event of the
  chosen law: Newton ``v = -kappa v(0)``, Poisson ``tau = (1 + kappa) tau_c``, Stronge
  ``int_{tau_c}^{tau} v dtau = -kappa^2 int_0^{tau_c} v dtau``.

Nothing here uses the collision matrix ``W`` or any closed form: the rates of ``u`` and
``v`` are whatever the body's velocity updates make them. The contact velocity is advanced
with those rates from ``(u(0), v(0))`` rather than recomputed as ``vx - omega ry`` (which
loses digits to cancellation when the body moves much faster than its contact point); the
body's velocities are the impulse-momentum balance for the accumulated impulse ``(f, tau)``.

The integration is vectorized over many impacts. Each impact advances in steps no longer
than the impulse that changes its contact velocity by ``1/resolution`` of its incidence
speed ``|u(0)| + |v(0)|``; every event (slip stops, compression ends, the law's end
condition) shortens the step to land on it, and the event's value (``u = 0``, ``v = 0``) is
set exactly. Between events the right-hand side is constant, so the velocities are advanced
exactly, the works (trapezoid rule on linear integrands) are exact, and the end condition of
Stronge's law (a quadratic in the step) is solved exactly; the result differs from the
closed forms only by rounding accumulated over the steps. The kinetic energy is computed
from the body's velocities (not from the works), and its minimum along the path is located
inside the step where ``dT/dtau`` changes sign.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Regime names, in the order of :data:`spinimpact.core.planar.PLANAR_REGIMES` (kept here
#: so that the reference classifies by its own events; the tests check the two agree).
REGIMES = (
    "frictionless",
    "no-slip",
    "stick-compression",
    "stick-restitution",
    "slip",
    "reverse-compression",
    "reverse-restitution",
    "slip-from-rest",
)

NEWTON, POISSON, STRONGE = 0, 1, 2


@dataclass
class PlanarReference:
    """What the integration found, one entry per impact (arrays of one shape)."""

    regime: np.ndarray  # code into REGIMES, from the sequence of events
    tau_slip: np.ndarray  # impulse at which the slip first stopped; 0 if u(0) = 0; inf if not
    tau_compression: np.ndarray
    tau_end: np.ndarray
    ratio_first: np.ndarray  # friction ratio s in the first phase
    ratio_second: np.ndarray  # s after the slip stopped (nan if it did not within the impact)
    friction_impulse: np.ndarray  # f at tau_end
    slip_after: np.ndarray  # u at tau_end
    normal_after: np.ndarray  # v at tau_end
    vx: np.ndarray  # body velocities at tau_end
    vy: np.ndarray
    omega: np.ndarray
    work_compression_normal: np.ndarray  # int v dtau over [0, tau_c]
    work_compression_friction: np.ndarray  # int u s dtau over [0, tau_c]
    work_restitution_normal: np.ndarray  # over [tau_c, tau_end]
    work_restitution_friction: np.ndarray
    energy_change: np.ndarray  # T(tau_end) - T(0), from the body's velocities
    energy_min: np.ndarray  # min over [0, tau_end] of T(tau) - T(0)
    tau_min: np.ndarray  # where that minimum is
    steps: int  # vectorized iterations used


def _kinetic(m, J, vx, vy, om):
    return 0.5 * m * (vx * vx + vy * vy) + 0.5 * J * om * om


def integrate(mass, inertia, rx, ry, vx, vy, omega, mu, kappa, law, until=np.inf, resolution=32):
    """Integrate many impacts at once; every input broadcasts to one shape.

    ``law`` is 0 (Newton), 1 (Poisson) or 2 (Stronge). The incidence must approach the
    plane: ``vy + omega rx < 0``. With a finite ``until`` the integration stops at the
    normal impulse ``min(until, tau_f)`` instead (``tau_end`` says where it stopped), which
    gives the state and the works part-way through the impact.
    """
    arrays = np.broadcast_arrays(mass, inertia, rx, ry, vx, vy, omega, mu, kappa, law, until)
    m, J, rx, ry, vx, vy, om, mu, kappa = (np.array(a, dtype=float).ravel() for a in arrays[:9])
    law = np.array(arrays[9], dtype=int).ravel()
    until = np.array(arrays[10], dtype=float).ravel()
    shape = arrays[0].shape
    n = m.size

    def contact(vx, vy, om):
        return vx - om * ry, vy + om * rx

    def body_rates(s):
        """Rates of (vx, vy, omega) per unit normal impulse at friction ratio s."""
        return s / m, 1.0 / m, (rx - ry * s) / J

    def contact_rates(s):
        dvx, dvy, dom = body_rates(s)
        return dvx - dom * ry, dvy + dom * rx

    u0, v0 = contact(vx, vy, om)
    u, v = u0.copy(), v0.copy()  # advanced with their own rates: no cancellation in vx - om ry
    if np.any(v0 >= 0):
        raise ValueError("every incidence must approach the plane (v(0) < 0)")
    scale = np.abs(u0) + np.abs(v0)
    t0 = _kinetic(m, J, vx, vy, om)
    vx0, vy0, om0 = vx, vy, om

    def body(f, tau):
        """Body velocities after the contact impulse (f, tau): momentum and angular momentum
        about the centre of mass (the integrated form, so no rounding builds up in them)."""
        return vx0 + f / m, vy0 + tau / m, om0 + (rx * tau - ry * f) / J

    # Coulomb's decision at u = 0. The slip rate is affine in s: du/dtau = A s + B.
    B = contact_rates(np.zeros(n))[0]
    A = contact_rates(np.ones(n))[0] - B
    s_hold = -B / A
    holds = np.abs(s_hold) <= mu
    pos = contact_rates(-mu)[0] > 0  # slipping forward with s = -mu keeps u > 0
    neg = contact_rates(mu)[0] < 0
    assert not np.any(~holds & (pos == neg)), "Coulomb's law must pick one direction"
    direction_from_rest = np.where(pos, 1.0, -1.0)

    frictionless = mu == 0
    at_rest = (u0 == 0) & ~frictionless
    stuck = at_rest & holds
    direction = np.where(at_rest, direction_from_rest, np.sign(u0))  # used while slipping
    first_phase = ~at_rest  # the slip-stop event can only happen in the first phase

    def ratio_now():
        s = np.where(stuck, s_hold, -mu * direction)
        return np.where(frictionless, 0.0, s)

    ratio_first = ratio_now()
    ratio_second = np.full(n, np.nan)
    tau = np.zeros(n)
    tau_slip = np.where(at_rest, 0.0, np.inf)
    reversed_ = np.zeros(n, dtype=bool)
    tau_c = np.full(n, np.nan)
    tau_f = np.full(n, np.nan)
    compressing = np.ones(n, dtype=bool)
    done = np.zeros(n, dtype=bool)
    f = np.zeros(n)
    wcn, wct, wrn, wrt = (np.zeros(n) for _ in range(4))
    e_min = np.zeros(n)
    tau_min = np.zeros(n)
    target_v = -kappa * v0
    steps = 0
    inf = np.full(n, np.inf)

    while not done.all():
        steps += 1
        if steps > 100_000:
            raise RuntimeError("reference integration did not finish")
        s = ratio_now()
        du, dv = contact_rates(s)
        du = np.where(stuck, 0.0, du)  # s_hold makes it 0 up to rounding; a stuck contact stays
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            h = scale / resolution / np.maximum(np.abs(du), np.abs(dv))
            # slip stops: u linear, reaches 0 if moving towards it (first phase only)
            slipping = first_phase & ~frictionless
            d_u = np.where(slipping & (direction * du < 0), -u / du, inf)
            d_u = np.where(slipping & (direction * u <= 0), 0.0, d_u)  # at 0 by rounding
            d_v = np.where(compressing & (dv > 0), -v / dv, inf)
            d_v = np.where(compressing & (v >= 0), 0.0, d_v)
            # the law's end condition, once compression is over
            newton = np.maximum((target_v - v) / dv, 0.0)
            poisson = np.maximum((1.0 + kappa) * tau_c - tau, 0.0)
            rest = np.maximum(-(kappa**2) * wcn - wrn, 0.0)  # normal work still to do
            stronge = 2.0 * rest / (v + np.sqrt(v * v + 2.0 * dv * rest))
            stronge = np.where(rest == 0, 0.0, stronge)
        d_end = np.select([law == NEWTON, law == POISSON], [newton, poisson], stronge)
        d_end = np.minimum(np.where(compressing, inf, d_end), until - tau)
        length = np.minimum(np.minimum(h, d_u), np.minimum(d_v, d_end))
        length = np.where(done, 0.0, length)
        hit_u = ~done & (length == d_u)
        hit_v = ~done & (length == d_v)
        hit_end = ~done & (length == d_end)

        # advance the body exactly (constant rates on the step)
        u1, v1 = u + du * length, v + dv * length
        u1, v1 = np.where(hit_u, 0.0, u1), np.where(hit_v, 0.0, v1)  # land on the events
        wn = 0.5 * length * (v + v1)
        wt = 0.5 * length * s * (u + u1)
        wcn += np.where(compressing, wn, 0.0)
        wct += np.where(compressing, wt, 0.0)
        wrn += np.where(compressing, 0.0, wn)
        wrt += np.where(compressing, 0.0, wt)

        # energy minimum: dT/dtau = v + s u is linear on the step
        g0, g1 = v + s * u, v1 + s * u1
        with np.errstate(divide="ignore", invalid="ignore"):
            theta = np.where((g0 < 0) & (g1 > 0), g0 / (g0 - g1), 1.0)
        inner = theta * length
        e_in = _kinetic(m, J, *body(f + s * inner, tau + inner)) - t0
        better = ~done & (e_in < e_min)
        e_min = np.where(better, e_in, e_min)
        tau_min = np.where(better, tau + inner, tau_min)

        u, v = np.where(done, u, u1), np.where(done, v, v1)
        f = f + s * length
        tau = tau + length

        # events
        tau_c = np.where(hit_v, tau, tau_c)
        compressing &= ~hit_v
        if hit_u.any():
            tau_slip = np.where(hit_u, tau, tau_slip)
            first_phase &= ~hit_u
            stuck |= hit_u & holds
            reversed_ |= hit_u & ~holds
            direction = np.where(hit_u & ~holds, direction_from_rest, direction)
            ratio_second = np.where(hit_u, ratio_now(), ratio_second)
        tau_f = np.where(hit_end, tau, tau_f)
        done |= hit_end

    vx, vy, om = body(f, tau)
    t1 = _kinetic(m, J, vx, vy, om) - t0
    e_min = np.minimum(e_min, t1)

    slipped_stop = ~at_rest & np.isfinite(tau_slip)
    in_comp = tau_slip <= tau_c
    regime = np.select(
        [
            frictionless,
            at_rest & holds,
            at_rest,
            slipped_stop & ~reversed_ & in_comp,
            slipped_stop & ~reversed_,
            slipped_stop & reversed_ & in_comp,
            slipped_stop & reversed_,
        ],
        [0, 1, 7, 2, 3, 5, 6],
        4,
    ).astype(np.int8)
    out = [
        regime,
        tau_slip,
        tau_c,
        tau_f,
        ratio_first,
        ratio_second,
        f,
        u,
        v,
        vx,
        vy,
        om,
        wcn,
        wct,
        wrn,
        wrt,
        t1,
        e_min,
        tau_min,
    ]
    return PlanarReference(*(a.reshape(shape) for a in out), steps=steps)


def random_planar_cases(n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` random bodies and incidences, an eighth of them aimed at each regime.

    Bodies: mass over two decades, radius of gyration ``rho`` over 1.5 decades, the contact
    at distance ``|r|`` in ``[rho/5, 5 rho]`` from the centre of mass, below it at any angle,
    with a fifth of the offsets within a milliradian of vertical (``W_tn`` nearly 0, one in
    fifty exactly vertical) or of horizontal. Incidences approach at ``|v(0)|`` over two
    decades, with a random spin; ``u(0) = 0`` exactly for the regimes that start at rest.
    ``mu`` is 0 (frictionless target), log-uniform in ``[0.01, 3]`` or up to 30; ``kappa``
    uniform with its ends 0 and 1 each one case in twenty.

    The aim uses the phase rates of the module notes (``W`` from the body's equations, the
    first-phase rates and ``tau_s``); it only spreads the sample over the regimes, the tests
    never take it as the answer.
    """
    rng = np.random.default_rng(seed)
    target = np.arange(n) % 8
    m = 10 ** rng.uniform(-1, 1, n)
    rho = 10 ** rng.uniform(-1.5, 0, n)
    J = m * rho**2
    dist = rho * 10 ** rng.uniform(-0.7, 0.7, n)
    angle = rng.uniform(-np.pi, 0, n)
    pick = rng.random(n)
    vertical, horizontal = pick < 0.1, (pick >= 0.1) & (pick < 0.2)
    angle[vertical] = -np.pi / 2 + rng.normal(0, 1e-3, n)[vertical]
    angle[pick < 0.02] = -np.pi / 2
    angle[horizontal] = rng.choice([0.0, -np.pi], n)[horizontal] - np.abs(
        rng.normal(0, 1e-3, n)[horizontal]
    )
    rx, ry = dist * np.cos(angle), dist * np.sin(angle)
    rx[pick < 0.02] = 0.0  # exactly vertical: the paper's body
    a = 1 / m + ry**2 / J
    b = -rx * ry / J
    d = 1 / m + rx**2 / J
    cone = np.abs(b) / a  # the friction the stuck contact needs

    mu = 10 ** rng.uniform(-2, np.log10(3), n)
    mu[rng.random(n) < 0.1] *= 10
    kappa = rng.uniform(0, 1, n)
    kappa[rng.random(n) < 0.05] = 0.0
    kappa[rng.random(n) < 0.05] = 1.0
    vn = -(10 ** rng.uniform(-1, 1, n))
    lam = rng.uniform(0.02, 0.98, n)
    sigma = rng.choice([-1.0, 1.0], n)
    free = np.abs(vn) * 10 ** rng.uniform(-3, 2, n)  # |u(0)| when the target leaves it free

    stick = np.isin(target, (1, 2, 3))
    mu[stick] = np.maximum(mu, cone * rng.uniform(1.01, 3, n))[stick]
    reverse = np.isin(target, (5, 6, 7))
    mu[reverse] = (cone * rng.uniform(0.02, 0.98, n))[reverse]
    sigma[reverse] = -np.sign(b[reverse])  # slides against sign(b): the slip stops
    sigma[reverse & (b == 0)] = 1.0
    mu[target == 0] = 0.0
    kappa[np.isin(target, (3, 6)) & (kappa == 0)] = 0.5  # leaves a restitution interval
    r1 = d - mu * sigma * b  # normal rate while the first slip lasts
    stops = a * mu - sigma * b  # rate at which |u| falls in the first phase
    tau_c1 = np.abs(vn) / np.where(r1 > 0, r1, 1.0)  # tau_c if the slip outlasts it
    ts = np.select(
        [np.isin(target, (2, 5)), np.isin(target, (3, 6)), target == 4],
        [lam * tau_c1, tau_c1 * (1 + lam * kappa), tau_c1 * (1 + kappa) * (1.05 + lam)],
        np.nan,
    )
    slip = np.where(np.isnan(ts) | (r1 <= 0) | (stops <= 0), free, stops * ts) * sigma
    slip[np.isin(target, (1, 7))] = 0.0
    slip[(target == 0) & (rng.random(n) < 0.2)] = 0.0
    omega = rng.normal(0, 3, n) * np.abs(vn) / dist
    vx = slip + omega * ry  # so that u = vx - omega ry = slip (exactly 0 where slip = 0)
    vy = vn - omega * rx
    u0, v0 = vx - omega * ry, vy + omega * rx
    return dict(
        mass=m,
        inertia=J,
        rx=rx,
        ry=ry,
        vx=vx,
        vy=vy,
        omega=omega,
        slip=u0,
        vn=v0,
        mu=mu,
        kappa=kappa,
        target=target,
    )
