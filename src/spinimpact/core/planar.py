"""Keller's method for a general planar contact: the collision matrix with coupling.

A planar body touching the surface at an offset ``r = (rx, ry)`` from its centre of
mass has the collision matrix (:func:`~spinimpact.core.impulse.planar_collision_matrix`)

.. math::

    W = \\begin{pmatrix} a & b \\\\ b & d \\end{pmatrix}
      = \\begin{pmatrix} 1/m + r_y^2/J & -r_x r_y/J \\\\ -r_x r_y/J & 1/m + r_x^2/J
        \\end{pmatrix},

and the contact velocity ``c = (u, v)`` (slip ``u``, normal velocity ``v < 0``) changes
with the contact impulse ``p = (f, tau)`` as ``dc = W dp``. With the force ratio
``s = df/dtau`` (Coulomb: ``s = -mu sign(u)`` while slipping),

.. math::

    \\frac{du}{d\\tau} = a s + b, \\qquad \\frac{dv}{d\\tau} = b s + d .

When ``b != 0`` the two directions couple. The process has at most two phases:

1. **initial slip** in the direction ``sigma = sign(u^-)`` (``s_1 = -mu sigma``). The slip
   decays when ``sigma b < a mu`` and stops at ``tau_s = |u^-| / (a mu - sigma b)``;
   otherwise it never stops (``tau_s = inf``).
2. once ``u = 0``: **stick** if the friction needed to hold it, ``s = -b/a``, lies inside
   the cone (``|b| <= a mu``), with ``dv/dtau = (a d - b^2)/a``; otherwise the slip
   **reverses** to ``sign(b)`` (``s_2 = -mu sign(b)``, ``dv/dtau = d - mu |b|``).

For a positive-definite ``W`` (a free body) the normal velocity always grows in the
last phase, so compression ends, at ``tau_c`` where ``v = 0``; in the first phase it may
fall (``b s_1 + d < 0``), which the paper's bodies (``b = 0``) never do. Three laws end
the impact at ``tau_f``:

* **Newton** (kinematic): ``v(tau_f) = -kappa v^-``;
* **Poisson** (kinetic): ``tau_f = (1 + kappa) tau_c``;
* **Stronge** (energetic): the work of the normal impulse in restitution is
  ``-kappa^2`` times that in compression, ``int_{tau_c}^{tau_f} v dtau =
  -kappa^2 int_0^{tau_c} v dtau``.

With ``b = 0`` the first phase never lowers ``v``, the phases in ``v`` are one line, and
the three laws coincide: the paper's case (:mod:`spinimpact.core.impulse`).

All functions are pure array kernels (any array-API library), broadcasting over their
arguments; they do not validate (the model layer does).

References
----------
.. [1] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000, ch. 5.
.. [3] Y. Wang and M. T. Mason, "Two-dimensional rigid-body collisions with friction",
   Journal of Applied Mechanics 59 (1992) 635-642.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from ._xp import arrays, quiet
from .impulse import CollisionMatrix

__all__ = [
    "LAWS",
    "PLANAR_REGIMES",
    "PlanarProcess",
    "PlanarState",
    "planar_process",
    "planar_state_at",
    "planar_work",
    "planar_min_energy_impulse",
    "planar_contact_velocity",
    "planar_apply_impulse",
    "pendulum_collision_matrix",
    "pendulum_contact_velocity",
    "pendulum_apply_impulse",
]

#: Restitution laws, indexed by the ``law`` codes of :func:`planar_process`.
LAWS = ("newton", "poisson", "energetic")

#: Regime names, indexed by the codes of :attr:`PlanarProcess.regime`. The first five
#: are the paper's (:data:`~spinimpact.core.impulse.REGIMES`), with the same meaning.
PLANAR_REGIMES = (
    "frictionless",  # mu = 0
    "no-slip",  # u^- = 0 and the contact stays stuck
    "stick-compression",  # slip stops at tau_s <= tau_c, then stick
    "stick-restitution",  # tau_c < tau_s <= tau_f, then stick
    "slip",  # one slip direction throughout (tau_s > tau_f)
    "reverse-compression",  # slip stops at tau_s <= tau_c and reverses
    "reverse-restitution",  # tau_c < tau_s <= tau_f, slip reverses
    "slip-from-rest",  # u^- = 0 but the cone cannot hold it: slips in direction sign(b)
    "locked",  # singular W: stuck and stopped against the support (a pendulum), no rebound
    "jam",  # singular W: slip never stops and v never rises; no finite impulse (NaN)
)

#: ``r_2 / W_nn`` at or below which the stuck phase cannot raise the normal velocity:
#: ``a d - b^2`` vanishes for a pendulum and is rounding-size there.
_SINGULAR = 1e-12


class PlanarProcess(NamedTuple):
    """The impact process in the normal impulse, from :func:`planar_process`."""

    regime: Any  #: code into :data:`PLANAR_REGIMES` (int8)
    tau_slip: Any  #: ``tau_s``: slip stops (``0`` if ``u^- = 0``, ``inf`` if never), N s
    tau_compression: Any  #: ``tau_c``: normal velocity vanishes, N s
    tau_end: Any  #: ``tau_f``: the impact ends under the chosen law, N s
    ratio_first: Any  #: force ratio ``F/N`` before ``tau_s``
    ratio_second: Any  #: force ratio ``F/N`` after ``tau_s`` (stick or reversed slip)
    friction_impulse: Any  #: ``f(tau_f)``, N s
    slip_after: Any  #: ``u^+``, m/s
    normal_after: Any  #: ``v^+``, m/s


class PlanarState(NamedTuple):
    """Contact-point quantities at normal impulse ``tau`` (:func:`planar_state_at`)."""

    friction_impulse: Any  #: ``f(tau)``, N s
    slip: Any  #: ``u(tau)``, m/s
    normal: Any  #: ``v(tau)``, m/s
    force_ratio: Any  #: ``F/N`` just after ``tau``


def _safe(xp, ok, x):
    """``x`` where ``ok``, else 1: a divisor for a branch that ``where`` discards."""
    return xp.where(ok, x, 1.0)


def _phases(slip, vn, a, b, d, mu):
    """Rates of both phases and the impulse ``tau_s`` at which the first one ends."""
    xp, (slip, vn, a, b, d, mu) = arrays(slip, vn, a, b, d, mu)
    sigma = xp.sign(slip)
    s1 = -mu * sigma
    k1 = a * s1 + b  # du/dtau in the first phase
    r1 = b * s1 + d  # dv/dtau in the first phase
    decays = (slip != 0) & (sigma * b < a * mu)
    gap = a * mu - sigma * b
    with quiet(xp, over="ignore"):  # a vanishing decay rate: tau_s overflows to inf, rightly
        tau_s = xp.where(decays, xp.abs(slip) / _safe(xp, decays, gap), xp.inf)
    tau_s = xp.where(slip == 0, 0.0, tau_s)
    stick = xp.abs(b) <= a * mu
    sb = xp.sign(b)
    moves = a > 0  # a = 0: the contact cannot move along the surface (b = 0 then too)
    s2 = xp.where(stick, -b / _safe(xp, moves, a), -mu * sb)
    k2 = xp.where(stick, 0.0, b - a * mu * sb)
    r2 = xp.where(stick, xp.where(moves, (a * d - b * b) / _safe(xp, moves, a), d),
                  d - mu * xp.abs(b))  # fmt: skip
    return xp, (slip, vn, mu, s1, k1, r1, tau_s, stick, s2, k2, r2)


def _first_reaches(xp, v0, r1, finite, ts, target):
    """Whether ``v`` reaches ``target`` (>= v0) within the first phase (``ts`` is
    ``tau_s`` where ``finite``)."""
    return (r1 > 0) & (~finite | (target - v0 <= r1 * ts))


def planar_process(slip, vn, w_tt, w_tn, w_nn, mu, kappa, law):
    """The impact process of a planar contact: impulses at every breakpoint and the rebound.

    Parameters
    ----------
    slip : array_like
        Tangential velocity of the contact point before the impact, ``u^-``, m/s.
    vn : array_like
        Normal velocity of the contact point before the impact, ``v^- < 0``, m/s.
    w_tt, w_tn, w_nn : array_like
        Entries ``a, b, d`` of the collision matrix ``W``, 1/kg (``a, d > 0``,
        ``a d - b^2 > 0``).
    mu : array_like
        Coulomb friction coefficient, ``>= 0``.
    kappa : array_like
        Coefficient of restitution of the chosen law, in ``[0, 1]``.
    law : array_like of int
        ``0`` Newton, ``1`` Poisson, ``2`` Stronge (energetic); :data:`LAWS`.

    Returns
    -------
    PlanarProcess
        Regime code, ``tau_s``, ``tau_c``, ``tau_f``, the force ratios of both phases,
        the friction impulse and the contact velocity after the impact.

    Notes
    -----
    The normal velocity is piecewise linear: ``v = v^- + r_1 tau`` before ``tau_s`` and
    ``v_s + r_2 (tau - tau_s)`` after, with ``r_1 = d - mu sigma b`` and ``r_2`` of the
    module notes; each law's ``tau_f`` solves a linear (Newton, Poisson) or quadratic
    (Stronge) equation on the piece where the impact ends.
    """
    xp, (u0, v0, mu, s1, k1, r1, tau_s, stick, s2, k2, r2) = _phases(slip, vn, w_tt, w_tn, w_nn, mu)
    xp, (kappa, law) = arrays(kappa, law)
    finite = tau_s != xp.inf
    ts = xp.where(finite, tau_s, 0.0)  # finite stand-in where the first phase never ends
    with quiet(xp, over="ignore"):  # a huge tau_s: only branches that where() discards
        v1 = v0 + r1 * ts  # v at tau_s
    # Rank one (a pendulum): u and v are proportional and vanish together, at tau_s.
    _, (a, b, d) = arrays(w_tt, w_tn, w_nn)
    together = finite & (a * d - b * b <= _SINGULAR * a * d)
    v1 = xp.where(together, 0.0, v1)
    with quiet(xp, divide="ignore", invalid="ignore", over="ignore"):
        # compression: in the first phase, or in the second
        ends1 = _first_reaches(xp, v0, r1, finite, ts, 0.0 * v0) & ~together
        tau_c = xp.where(ends1, -v0 / _safe(xp, ends1, r1), ts - v1 / _safe(xp, ~ends1, r2))
        # Newton: v(tau_f) = -kappa v^-
        target = -kappa * v0
        n1 = _first_reaches(xp, v0, r1, finite, ts, target)
        newton = xp.where(
            n1, (target - v0) / _safe(xp, n1, r1), ts + (target - v1) / _safe(xp, ~n1, r2)
        )
        poisson = (1.0 + kappa) * tau_c
        # Stronge: restitution work of v equals kappa^2 times the compression work
        wc = xp.where(ends1, v0 * tau_c / 2.0, (v0 + v1) * ts / 2.0 + v1 * (tau_c - ts) / 2.0)
        wt = -kappa * kappa * wc
        room = xp.where(finite & ends1, r1 * (ts - tau_c) ** 2 / 2.0, xp.inf)  # first phase
        in_first = ends1 & (wt <= room)
        e1 = tau_c + xp.sqrt(2.0 * wt / _safe(xp, in_first, r1))
        rest = xp.where(ends1, wt - xp.where(in_first, 0.0, room), wt)
        vs = xp.where(ends1, r1 * (ts - tau_c), 0.0)  # v entering the second phase
        start = xp.where(ends1, ts, tau_c)
        root = xp.sqrt(vs * vs + 2.0 * r2 * rest)
        e2 = start + 2.0 * rest / _safe(xp, (vs + root) > 0, vs + root)
        energetic = xp.where(in_first, e1, e2)
    tau_f = xp.where(law == 0, newton, xp.where(law == 1, poisson, energetic))
    # A singular W (a pendulum on its pivot): u and v are proportional, so they vanish
    # together at tau_s; once stuck the normal velocity cannot rise, and the body stops
    # against its support. Compression ends there; Newton's and
    # Stronge's laws can do no restitution, and Poisson's extra impulse lies in the null
    # space of W (the pivot takes it): no velocity changes after tau_s.
    _, (w_nn,) = arrays(w_nn)
    locked = stick & (r2 <= _SINGULAR * w_nn) & finite
    tau_c = xp.where(locked, ts, tau_c)
    tau_f = xp.where(locked, xp.where(law == 1, (1.0 + kappa) * ts, ts), tau_f)
    # Jam: the slip never stops and friction keeps the normal velocity from rising; no
    # finite impulse ends the impact (only possible for a singular W).
    jam = ~finite & (r1 <= 0)
    tau_c = xp.where(jam, xp.nan, tau_c)
    tau_f = xp.where(jam, xp.nan, tau_f)

    f = s1 * xp.minimum(tau_f, tau_s) + s2 * xp.where(tau_f > tau_s, tau_f - ts, 0.0)
    state = planar_state_at(tau_f, u0, v0, w_tt, w_tn, w_nn, mu, tau_s)

    code = xp.where(tau_s > tau_f, 4, xp.where(stick, 3, 6))  # slip / stops in restitution
    early = tau_s <= tau_c
    code = xp.where((code != 4) & early, code - 1, code)
    code = xp.where(u0 == 0, xp.where(stick, 1, 7), code)
    code = xp.where(mu == 0, 0, code)
    code = xp.where(locked, 8, xp.where(jam, 9, code))
    return PlanarProcess(
        xp.astype(code, xp.int8), tau_s, tau_c, tau_f, s1, s2, f + 0.0, state.slip, state.normal
    )


def planar_state_at(tau, slip, vn, w_tt, w_tn, w_nn, mu, tau_slip):
    """Friction impulse, slip, normal velocity and force ratio at normal impulse ``tau``.

    ``tau_slip`` is :attr:`PlanarProcess.tau_slip` of the same contact. Piecewise
    linear: ``u = u^- + (a s_1 + b) tau`` before ``tau_s``, then ``0`` (stick) or
    ``(a s_2 + b)(tau - tau_s)`` (reversed slip); ``v`` likewise with ``b s + d``.
    """
    xp, (u0, v0, mu, s1, k1, r1, _, _, s2, k2, r2) = _phases(slip, vn, w_tt, w_tn, w_nn, mu)
    xp, (tau, tau_slip) = arrays(tau, tau_slip)
    finite = tau_slip != xp.inf
    ts = xp.where(finite, tau_slip, 0.0)
    before = tau < tau_slip
    late = xp.where(before, 0.0, tau - ts)
    early = xp.minimum(tau, tau_slip)
    with quiet(xp, over="ignore", invalid="ignore"):  # a huge tau_s in discarded branches
        f = s1 * early + s2 * late
        u = xp.where(before, u0 + k1 * tau, k2 * late)
        v = xp.where(before, v0 + r1 * tau, v0 + r1 * ts + r2 * late)
    return PlanarState(f + 0.0, u + 0.0, v + 0.0, xp.where(before, s1, s2) + 0.0)


def planar_work(lo, hi, slip, vn, w_tt, w_tn, w_nn, mu, tau_slip):
    """Works of the normal and friction impulses between normal impulses ``lo <= hi``, J.

    Returns ``(W^n, W^t) = (int v dtau, int u s dtau)`` over ``[lo, hi]``: exact for the
    piecewise-linear velocities (the trapezoid rule on each piece, split at ``tau_s``).
    ``W^t <= 0`` always; ``W^n + W^t`` is the change of kinetic energy.
    """
    xp, (lo, hi, tau_slip) = arrays(lo, hi, tau_slip)
    finite = tau_slip != xp.inf
    ts = xp.where(finite, tau_slip, 0.0)
    cut = xp.where(finite, ts, xp.maximum(hi, lo))  # where the pieces meet
    pieces = ((lo, xp.minimum(hi, cut)), (xp.maximum(lo, cut), hi))
    normal = 0.0
    tangential = 0.0
    for k, (x0, x1) in enumerate(pieces):
        x1 = xp.maximum(x0, x1)
        # evaluate each piece from its own side of tau_s, so the jump of s is respected
        probe = (x0 + x1) / 2.0
        side = probe < tau_slip if k == 0 else probe >= tau_slip
        a = planar_state_at(x0, slip, vn, w_tt, w_tn, w_nn, mu, tau_slip)
        b = planar_state_at(x1, slip, vn, w_tt, w_tn, w_nn, mu, tau_slip)
        ratio = planar_state_at(probe, slip, vn, w_tt, w_tn, w_nn, mu, tau_slip).force_ratio
        h = xp.where(side, x1 - x0, 0.0)
        normal = normal + h * (a.normal + b.normal) / 2.0
        tangential = tangential + h * ratio * (a.slip + b.slip) / 2.0
    return normal, tangential


def planar_min_energy_impulse(slip, vn, w_tt, w_tn, w_nn, mu, tau_slip, tau_end):
    """Normal impulse ``tau_m`` at which the kinetic energy is smallest, N s.

    ``dE/dtau = v + u s`` is continuous (``u = 0`` where ``s`` jumps) and, on each
    phase, grows at ``(s, 1) W (s, 1)^T > 0``: ``E`` is convex in ``tau``. Its minimum
    is where ``v + u s`` vanishes, on the first phase if that root comes before
    ``tau_s``, else on the second; capped at ``tau_f`` (the energy may still fall when
    the impact ends).
    """
    xp, (u0, v0, mu, s1, k1, r1, _, _, s2, k2, r2) = _phases(slip, vn, w_tt, w_tn, w_nn, mu)
    xp, (tau_slip, tau_end) = arrays(tau_slip, tau_end)
    finite = tau_slip != xp.inf
    ts = xp.where(finite, tau_slip, 0.0)
    grow1 = r1 + k1 * s1  # = (s1, 1) W (s1, 1)^T
    root1 = -(v0 + u0 * s1) / grow1
    v1 = v0 + r1 * ts
    grow2 = r2 + k2 * s2
    with quiet(xp, divide="ignore", invalid="ignore"):
        root2 = ts - v1 / _safe(xp, grow2 > 0, grow2)
    tau_m = xp.where(root1 <= tau_slip, root1, root2)
    return xp.minimum(xp.maximum(tau_m, 0.0), tau_end)


def planar_contact_velocity(vx, vy, omega, rx, ry):
    """Velocity ``(u, v)`` of the contact point at offset ``(rx, ry)`` from the centre of
    mass: ``u = vx - omega ry``, ``v = vy + omega rx`` (``c = v_G + omega e_z x r``), m/s."""
    return vx - omega * ry, vy + omega * rx


def planar_apply_impulse(vx, vy, omega, mass, inertia, rx, ry, friction, normal):
    """Body velocities after a contact impulse ``(f, tau)`` at offset ``(rx, ry)``.

    ``vx + f/m``, ``vy + tau/m``, ``omega + (rx tau - ry f)/J`` (momentum and angular
    momentum about the centre of mass).
    """
    return (
        vx + friction / mass,
        vy + normal / mass,
        omega + (rx * normal - ry * friction) / inertia,
    )


def pendulum_collision_matrix(inertia_pivot, px, py):
    """Collision matrix of a rigid pendulum on a fixed frictionless pivot, 1/kg.

    ``p = (px, py)`` is the contact point relative to the pivot, m, and
    ``inertia_pivot`` the moment of inertia about the pivot, kg m^2. The only motion is
    the rotation ``omega`` about the pivot, so the contact moves with
    ``c = omega e_z x p = (-omega py, omega px)`` and an impulse ``(f, tau)`` changes
    ``omega`` by ``(px tau - py f)/J_O``:
    ``W = [[py^2, -px py], [-px py, px^2]] / J_O``, of rank one.
    """
    return CollisionMatrix(py * py / inertia_pivot, -px * py / inertia_pivot,
                           px * px / inertia_pivot)  # fmt: skip


def pendulum_contact_velocity(omega, px, py):
    """Contact-point velocity ``(u, v) = (-omega py, omega px)`` of a pendulum, m/s."""
    return -omega * py, omega * px


def pendulum_apply_impulse(omega, inertia_pivot, px, py, friction, normal):
    """Spin of a pendulum after a contact impulse ``(f, tau)``:
    ``omega + (px tau - py f)/J_O``, rad/s (angular momentum about the pivot)."""
    return omega + (px * normal - py * friction) / inertia_pivot
