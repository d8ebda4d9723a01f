r"""The per-contact law of a general planar contact on plain numbers (``W_tn != 0``).

The scalar counterpart of :mod:`spinimpact.core.planar` (Keller's method with the coupled
collision matrix ``W = [[a, b], [b, d]]``: slip that stops, sticks or reverses; Newton's,
Poisson's and Stronge's restitution). Each function performs the array kernels' IEEE
operations in their order on the branch that ``where`` would select, so the results equal
:func:`spinimpact.solve_planar`'s and :func:`spinimpact.solve_pendulum`'s bit for bit
(NaN where they give NaN; ``tests/core/test_law.py``). A division whose divisor may vanish
goes through :func:`_divide`, which gives IEEE's ``inf`` or NaN as NumPy does, so the law
raises nothing in Python or in Numba's default error model. Registered for compiled
callers by :mod:`spinimpact.core.law`. Nothing is validated.

Arguments: ``slip`` and ``vn`` (``< 0``), the contact point's velocity before the impact
(m/s); ``a, b, d`` the entries ``W_tt, W_tn, W_nn`` (1/kg); ``mu >= 0``; ``kappa`` in
``[0, 1]``; ``law`` ``0`` Newton, ``1`` Poisson, ``2`` Stronge
(:data:`~spinimpact.core.planar.LAWS`).

References
----------
.. [1] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.
.. [2] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000, ch. 5.
"""

from __future__ import annotations

import math

from .scalar import sign

__all__ = [
    "planar_phases",
    "planar_process",
    "planar_state_at",
    "planar_work",
    "planar_min_energy_impulse",
    "planar_rebound",
]

_SINGULAR = 1e-12  # as core.planar: a d - b^2 this small (relative) is a rank-one W


def _divide(x, y):
    """``x / y`` in IEEE arithmetic: ``+-inf`` or NaN for ``y = 0``, as NumPy gives."""
    if y != 0.0:
        return x / y
    if x != x or x == 0.0:
        return math.nan
    return math.copysign(math.inf, x) * math.copysign(1.0, y)


def _sqrt(x):
    return math.sqrt(x) if x >= 0.0 else math.nan  # NaN for x < 0 or NaN, as numpy.sqrt


def _minimum(x, y):
    """``numpy.minimum``: NaN if either is NaN, else the smaller (``y`` when equal)."""
    if x != x:
        return x
    if y != y:
        return y
    return x if x < y else y


def _maximum(x, y):
    if x != x:
        return x
    if y != y:
        return y
    return x if x > y else y


def planar_phases(slip, a, b, d, mu):
    """Force ratios and rates of both phases, and the impulse ``tau_s`` ending the first.

    Returns
    -------
    tuple
        ``(s1, k1, r1, tau_s, stick, s2, k2, r2)``: the first phase's force ratio and rates
        ``du/dtau``, ``dv/dtau``; ``tau_s`` (``0`` without slip, ``inf`` if the slip never
        stops); whether the cone holds the contact once stuck; the second phase's.
    """
    sigma = sign(slip)
    s1 = -mu * sigma
    k1 = a * s1 + b
    r1 = b * s1 + d
    if slip == 0.0:
        tau_s = 0.0
    elif sigma * b < a * mu:
        tau_s = abs(slip) / (a * mu - sigma * b)
    else:
        tau_s = math.inf
    stick = abs(b) <= a * mu
    if stick:
        s2 = -b / a if a > 0.0 else -b / 1.0
        k2 = 0.0
        r2 = (a * d - b * b) / a if a > 0.0 else d
    else:
        s2 = -mu * sign(b)
        k2 = b - a * mu * sign(b)
        r2 = d - mu * abs(b)
    return s1, k1, r1, tau_s, stick, s2, k2, r2


def planar_state_at(tau, slip, vn, a, b, d, mu, tau_slip):
    """``(f, u, v, F/N)`` at normal impulse ``tau``, as
    :func:`spinimpact.core.planar.planar_state_at`."""
    s1, k1, r1, _, _, s2, k2, r2 = planar_phases(slip, a, b, d, mu)
    return _state(tau, slip, vn, tau_slip, s1, k1, r1, s2, k2, r2)


def _state(tau, slip, vn, tau_slip, s1, k1, r1, s2, k2, r2):
    """:func:`planar_state_at` given the phases' force ratios and rates."""
    ts = tau_slip if tau_slip != math.inf else 0.0
    before = tau < tau_slip
    late = 0.0 if before else tau - ts
    f = s1 * _minimum(tau, tau_slip) + s2 * late
    if before:
        return f + 0.0, slip + k1 * tau + 0.0, vn + r1 * tau + 0.0, s1 + 0.0
    return f + 0.0, k2 * late + 0.0, vn + r1 * ts + r2 * late + 0.0, s2 + 0.0


def _first_reaches(v0, r1, finite, ts, target):
    return r1 > 0.0 and (not finite or target - v0 <= r1 * ts)


def planar_process(slip, vn, a, b, d, mu, kappa, law):
    """The impact process, as :func:`spinimpact.core.planar.planar_process`.

    Returns
    -------
    tuple
        ``(regime, tau_s, tau_c, tau_f, s1, s2, f, u+, v+)``: the code into
        :data:`~spinimpact.core.planar.PLANAR_REGIMES`, the impulses (N s), the force
        ratios of both phases, the friction impulse (N s) and the contact velocity after.
    """
    s1, _, r1, tau_s, stick, s2, _, r2 = planar_phases(slip, a, b, d, mu)
    v0 = vn
    finite = tau_s != math.inf
    ts = tau_s if finite else 0.0
    together = finite and a * d - b * b <= _SINGULAR * a * d
    v1 = 0.0 if together else v0 + r1 * ts
    ends1 = _first_reaches(v0, r1, finite, ts, 0.0 * v0) and not together
    tau_c = -v0 / r1 if ends1 else ts - _divide(v1, r2)
    if law == 0:  # Newton: v(tau_f) = -kappa v^-
        target = -kappa * v0
        if _first_reaches(v0, r1, finite, ts, target):
            tau_f = (target - v0) / r1
        else:
            tau_f = ts + _divide(target - v1, r2)
    elif law == 1:  # Poisson
        tau_f = (1.0 + kappa) * tau_c
    else:  # Stronge: restitution work of v is kappa^2 times the compression work
        if ends1:
            wc = v0 * tau_c / 2.0
        else:
            wc = (v0 + v1) * ts / 2.0 + v1 * (tau_c - ts) / 2.0
        wt = -kappa * kappa * wc
        room = r1 * ((ts - tau_c) * (ts - tau_c)) / 2.0 if finite and ends1 else math.inf
        if ends1 and wt <= room:
            tau_f = tau_c + _sqrt(2.0 * wt / r1)
        else:
            rest = wt - room if ends1 else wt
            vs = r1 * (ts - tau_c) if ends1 else 0.0
            start = ts if ends1 else tau_c
            root = _sqrt(vs * vs + 2.0 * r2 * rest)
            den = vs + root
            tau_f = start + 2.0 * rest / (den if den > 0.0 else 1.0)
    locked = stick and r2 <= _SINGULAR * d and finite
    if locked:
        tau_c = ts
        tau_f = (1.0 + kappa) * ts if law == 1 else ts
    jam = not finite and r1 <= 0.0
    if jam:
        tau_c = math.nan
        tau_f = math.nan
    f = s1 * _minimum(tau_f, tau_s) + s2 * (tau_f - ts if tau_f > tau_s else 0.0)
    _, u1, vn1, _ = planar_state_at(tau_f, slip, vn, a, b, d, mu, tau_s)
    code = 4 if tau_s > tau_f else (3 if stick else 6)
    if code != 4 and tau_s <= tau_c:
        code -= 1
    if slip == 0.0:
        code = 1 if stick else 7
    if mu == 0.0:
        code = 0
    if locked:
        code = 8
    elif jam:
        code = 9
    return code, tau_s, tau_c, tau_f, s1, s2, f + 0.0, u1, vn1


def planar_work(lo, hi, slip, vn, a, b, d, mu, tau_slip):
    """Works ``(W^n, W^t)`` of the normal and friction impulses over ``[lo, hi]``, J, as
    :func:`spinimpact.core.planar.planar_work` (the trapezoid rule on each piece)."""
    s1, k1, r1, _, _, s2, k2, r2 = planar_phases(slip, a, b, d, mu)  # once for every state
    finite = tau_slip != math.inf
    ts = tau_slip if finite else 0.0
    cut = ts if finite else _maximum(hi, lo)
    normal = 0.0
    tangential = 0.0
    for k in range(2):
        if k == 0:
            x0, x1 = lo, _minimum(hi, cut)
        else:
            x0, x1 = _maximum(lo, cut), hi
        x1 = _maximum(x0, x1)
        probe = (x0 + x1) / 2.0
        side = probe < tau_slip if k == 0 else probe >= tau_slip
        _, u_a, v_a, _ = _state(x0, slip, vn, tau_slip, s1, k1, r1, s2, k2, r2)
        _, u_b, v_b, _ = _state(x1, slip, vn, tau_slip, s1, k1, r1, s2, k2, r2)
        ratio = _state(probe, slip, vn, tau_slip, s1, k1, r1, s2, k2, r2)[3]
        h = x1 - x0 if side else 0.0
        normal = normal + h * (v_a + v_b) / 2.0
        tangential = tangential + h * ratio * (u_a + u_b) / 2.0
    return normal, tangential


def planar_min_energy_impulse(slip, vn, a, b, d, mu, tau_slip, tau_end):
    """Normal impulse of least kinetic energy, N s, as
    :func:`spinimpact.core.planar.planar_min_energy_impulse`."""
    s1, k1, r1, _, _, s2, k2, r2 = planar_phases(slip, a, b, d, mu)
    ts = tau_slip if tau_slip != math.inf else 0.0
    root1 = _divide(-(vn + slip * s1), r1 + k1 * s1)
    if root1 <= tau_slip:
        tau_m = root1
    else:
        grow2 = r2 + k2 * s2
        tau_m = ts - (vn + r1 * ts) / (grow2 if grow2 > 0.0 else 1.0)
    return _minimum(_maximum(tau_m, 0.0), tau_end)


def planar_rebound(vx, vy, omega, mass, inertia, rx, ry, mu, kappa, law):
    """Rebound of a free planar body touching the surface at ``(rx, ry)`` from its centre.

    Parameters
    ----------
    vx, vy, omega : float
        Velocity of the centre of mass (m/s) and spin (rad/s) before the impact; the
        contact point must approach the surface (``vy + omega rx < 0``).
    mass, inertia : float
        Mass (kg) and moment of inertia about the centre of mass (kg m^2).
    rx, ry : float
        The contact point relative to the centre of mass, m.
    mu, kappa : float
        Coulomb friction and the restitution coefficient of ``law``.
    law : int
        ``0`` Newton, ``1`` Poisson, ``2`` Stronge (energetic).

    Returns
    -------
    tuple of float
        ``(vx+, vy+, omega+, f, tau_f)``: as :func:`spinimpact.solve_planar`'s ``after``,
        its ``tangential_impulse`` and ``tau1``.

    Examples
    --------
    A rod of 1 kg and 0.5 m touching at 45 degrees, dropped without spin, with Poisson's
    restitution (``PlanarBody.rod(mass=1.0, length=0.5, angle=math.radians(45))``):

    >>> r = 0.25 * math.sqrt(0.5)
    >>> out = planar_rebound(0.0, -2.0, 0.0, 1.0, 0.5**2 / 12, -r, -r, 0.3, 0.8, 1)
    >>> [round(x, 6) for x in out]
    [0.526829, -0.243902, -10.430687, 0.526829, 1.756098]
    """
    a = 1.0 / mass + ry * ry / inertia
    b = -rx * ry / inertia
    d = 1.0 / mass + rx * rx / inertia
    slip, vn = vx - omega * ry, vy + omega * rx
    process = planar_process(slip, vn, a, b, d, mu, kappa, law)
    f, tau = process[6], process[3]
    return (
        vx + f / mass,
        vy + tau / mass,
        omega + (rx * tau - ry * f) / inertia,
        f,
        tau,
    )
