"""One contact of any rigid body in 3D: Keller's method in the normal impulse, on floats.

The contact frame has axes ``t1, t2, n``: ``n`` is the surface's normal, pointing into the
body, and the contact point's velocity relative to the surface is ``v = (v1, v2, vn)``
with ``vn < 0`` at the start. The contact impulse ``p = (p1, p2, pn)`` changes it
linearly, ``dv = W dp``, where ``W`` is the 3 x 3 collision matrix (symmetric, positive
definite; :func:`spinimpact.core.rigid3d.body_matrix` builds it for a body, and two bodies
touching add theirs). Friction is Coulomb's, and the normal impulse ``pn`` (Keller 1986)
is the independent variable: it grows monotonically while the normal force acts, so the
shape of the force in time never matters.

Sliding (``|v_t| > 0``, ``s = v_t/|v_t|``)
    ``dp_t/dpn = -mu s`` and ``dv/dpn = W (-mu s, 1)``. Unless ``W_tn`` and ``W_tt s`` keep
    ``s`` an eigen-direction, the slip direction turns. With ``g(s) = W_tn - mu W_tt s``
    (the tangential block ``W_tt`` and the coupling ``W_tn``), the slip speed changes at
    ``d|v_t|/dpn = s . g(s)`` and the direction turns at ``s_perp . g(s) / |v_t|``. This
    phase is integrated numerically in ``tau = int dpn / |v_t|`` (Dormand and Prince's
    8(5,3) pair, a local error below ``rtol`` times the speed scale per step:
    :mod:`spinimpact.core.rigid_slide`) until the slip stops, the impact ends or the
    direction has settled on one that ``W`` keeps; everything else is closed form.
Stop
    When the slip vanishes, the contact sticks if the friction cone holds the impulse
    ratio that keeps ``v_t = 0``: ``c = W_tt^-1 W_tn`` and ``|c| <= mu``. It then sticks
    to the end (``W`` is constant), with ``dp_t/dpn = -c`` and
    ``dvn/dpn = W_nn - W_nt c > 0`` (a Schur complement of ``W``).
Re-slide
    Otherwise it slides again along a direction ``s`` with ``g(s) = lambda s`` and
    ``lambda > 0`` (the slip grows along ``s`` and never turns again). Writing
    ``M = W_tt^-1``, ``c = (mu I + lambda M) s``, so ``s = (mu I + lambda M)^-1 c`` with
    ``|s| = 1``. In ``M``'s eigenbasis ``|s|^2 = sum c_i^2 / (mu + lambda m_i)^2``, which
    falls strictly from ``|c|^2/mu^2`` at ``lambda = 0`` to 0: a root ``lambda > 0`` exists,
    and is unique, exactly when ``|c| > mu``, that is exactly when the contact cannot
    stick. So after a stop the contact either sticks or re-slides along one direction;
    never both, never a choice. The same rule starts an impact with no initial slip.

The impact's end (``law``: 0 Newton, 1 Poisson, 2 Stronge; ``kappa`` the coefficient):
compression ends at the first ``pn = p_c`` where ``vn = 0``; Newton's law ends at the
first ``pn >= p_c`` where ``vn = -kappa vn(0)``, Poisson's at ``pn = (1 + kappa) p_c``,
Stronge's where the normal force's work in restitution is ``kappa^2`` times that of
compression. The energy the impact takes from the bodies is
``-p . (v_before + v_after) / 2`` exactly (rigid bodies). The normal works are
integrated; friction's work is the impulse's work less the normal work in a sliding phase
whose direction turns, and integrated in closed form in the others
(``tests/model/test_rigid.py`` checks their sum against the kinetic energy lost).

The functions take and return floats (plain Python when called from Python; registered
with Numba so that compiled code calls them too). Nothing is validated here.
"""

from __future__ import annotations

import math

import numpy as np

from .rigid_slide import _MAX_STEPS, _N, _STOP, _slide

__all__ = ["LAW_CODES", "SEQUENCES", "reslide_direction", "rigid_impact"]

#: The restitution laws by code.
LAW_CODES = ("newton", "poisson", "energetic")

#: The sequences of phases by code (``rigid_impact``'s ``sequence``).
SEQUENCES = ("slide", "slide-stick", "slide-reslide", "stick")


def _stick_ratio(w):
    """``c = W_tt^-1 W_tn``: the tangential impulse per normal impulse that keeps the slip
    zero."""
    det = w[0] * w[3] - w[1] * w[1]
    c1 = (w[3] * w[2] - w[1] * w[4]) / det
    c2 = (w[0] * w[4] - w[1] * w[2]) / det
    return c1, c2


def reslide_direction(w, mu):
    """The direction ``(s1, s2)`` along which a stopped contact slides again, and its slip
    growth ``lambda = s . g(s) > 0`` per unit normal impulse; ``(nan, nan, nan)`` where the
    contact can stick (``|W_tt^-1 W_tn| <= mu``: no such direction exists).

    ``w`` holds ``W``'s six entries ``(W11, W12, W1n, W22, W2n, Wnn)``. The root of
    ``|(mu I + lambda M)^-1 c| = 1`` (module notes) is bracketed in
    ``(0, (|c| - mu) / m_min]`` and found by bisection to the last bit.
    """
    c1, c2 = _stick_ratio(w)
    size = math.hypot(c1, c2)
    if size <= mu:
        return math.nan, math.nan, math.nan
    det = w[0] * w[3] - w[1] * w[1]
    m11, m12, m22 = w[3] / det, -w[1] / det, w[0] / det  # M = W_tt^-1
    half = 0.5 * (m11 + m22)
    m_min = half - math.sqrt(0.25 * (m11 - m22) ** 2 + m12 * m12)
    lo, hi = 0.0, (size - mu) / m_min
    s1 = s2 = math.nan
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not lo < mid < hi:
            break
        a11, a12, a22 = mu + mid * m11, mid * m12, mu + mid * m22  # mu I + lambda M
        d = a11 * a22 - a12 * a12
        s1 = (a22 * c1 - a12 * c2) / d
        s2 = (a11 * c2 - a12 * c1) / d
        if s1 * s1 + s2 * s2 > 1.0:
            lo = mid
        else:
            hi = mid
    norm = math.hypot(s1, s2)
    s1 /= norm
    s2 /= norm
    g1 = w[2] - mu * (w[0] * s1 + w[1] * s2)
    g2 = w[4] - mu * (w[1] * s1 + w[3] * s2)
    return s1, s2, s1 * g1 + s2 * g2


def rigid_impact(w11, w12, w1n, w22, w2n, wnn, v1, v2, vn, mu, kappa, law, rtol, p_max):
    """One impact of a rigid body at one point contact, by Keller's method (module notes).

    Parameters
    ----------
    w11, w12, w1n, w22, w2n, wnn : float
        The collision matrix ``W`` in the contact frame (1/kg), symmetric positive definite.
    v1, v2, vn : float
        The contact point's velocity before the impact (m/s), ``vn < 0``.
    mu, kappa : float
        Friction coefficient and the law's restitution coefficient (``0 <= kappa <= 1``).
    law : int
        0 Newton, 1 Poisson, 2 Stronge's energetic law (:data:`LAW_CODES`).
    rtol : float
        The local error allowed per step of the sliding phase, a fraction of the speed
        scale (``1e-13`` keeps the rebound within ``1e-12`` of a run at ``1e-15``:
        ``tests/core/test_rigid3d.py``).
    p_max : float
        Stop at this normal impulse if the impact has not ended before (N s; ``inf`` for
        the whole impact): the state part-way, for the slip's history.

    Returns
    -------
    tuple
        ``(v1, v2, vn)`` after, the impulse ``(p1, p2, pn)``, the compression impulse
        ``p_c``, the normal works of compression and restitution, the tangential works of
        compression and restitution (J), the normal impulse at which the slip stopped
        (``nan`` if it did not), the sequence code (:data:`SEQUENCES`), the number of
        steps taken, and whether the impact ended (``False``: no separation, or the step
        limit).
    """
    w = np.empty(6)
    w[0], w[1], w[2], w[3], w[4], w[5] = w11, w12, w1n, w22, w2n, wnn
    y = np.zeros(7)  # v1, v2, vn, normal work, tangential work, p1, p2
    y[0], y[1], y[2] = v1, v2, vn
    scale = math.sqrt(v1 * v1 + v2 * v2 + vn * vn)
    # p, compressed, p_c, normal and tangential works at p_c, stop
    state = np.array([0.0, 0.0, math.nan, math.nan, math.nan, math.nan])
    k = np.empty((15, _N))
    z = np.empty(_N)
    out = np.empty(_N)
    c = np.empty(5)
    steps = 0
    ended = False
    first = -1  # the first phase: 0 slide, 1 stick
    second = -1  # the phase after a stop, if any
    settled = False
    for _ in range(5):  # at most: a slide, a settled slide, a stop, a closed-form phase
        rho = math.hypot(y[0], y[1])
        if rho > _STOP * scale:
            if first < 0:
                first = 0
            s1, s2 = y[0] / rho, y[1] / rho
            g1 = w[2] - mu * (w[0] * s1 + w[1] * s2)
            g2 = w[4] - mu * (w[1] * s1 + w[3] * s2)
            if not settled and abs(s1 * g2 - s2 * g1) > 1e-14 * (abs(g1) + abs(g2)):
                # the slip direction turns: integrate to the stop, the end, or until it
                # has settled on a direction W keeps (then the slide goes on along it)
                steps, ended, settled = _slide(w, mu, kappa, law, rtol, p_max, scale, y,
                                               state, k, z, out, c, steps, vn)  # fmt: skip
                if ended or state[0] >= p_max or steps >= _MAX_STEPS:
                    break
                continue
            settled = False
            r1, r2, lam, f1, f2 = s1, s2, s1 * g1 + s2 * g2, -mu * s1, -mu * s2
        else:  # stopped (or no slip at the start): stick, or slide along W's direction
            rho = 0.0
            c1, c2 = _stick_ratio(w)
            r1, r2, lam = reslide_direction(w, mu)
            phase = 1 if math.isnan(lam) else 0
            if first < 0:
                first = phase
            else:
                second = phase
            if phase == 1:
                r1, r2, lam, f1, f2 = 0.0, 0.0, 0.0, -c1, -c2
            else:
                f1, f2 = -mu * r1, -mu * r2
        ended, stopped = _linear(w, mu, kappa, law, p_max, y, state, r1, r2, rho, lam, f1, f2,
                                 vn)  # fmt: skip
        if not stopped:
            break
    sequence = 3 if first == 1 else (0 if second < 0 else (1 if second == 1 else 2))
    compressed = state[1] > 0.0
    wn_c = state[3] if compressed else y[3]
    wn_r = y[3] - state[3] if compressed else 0.0
    wt_c = state[5] if compressed else y[4]
    wt_r = y[4] - state[5] if compressed else 0.0
    return (y[0], y[1], y[2], y[5], y[6], state[0], state[2], wn_c, wn_r, wt_c, wt_r, state[4],
            sequence, steps, ended)  # fmt: skip


def _linear(w, mu, kappa, law, p_max, y, state, r1, r2, rho, lam, f1, f2, vn0):
    """A phase with a fixed slip direction ``(r1, r2)``: the slip speed ``rho + lam d``,
    ``dp_t/dpn = (f1, f2)``, ``vn`` linear and the works quadratic in the impulse ``d``
    since its start. Advances ``y`` and ``state`` to the slip's stop, the law's end or
    ``p_max``, whichever comes first; returns ``(ended, stopped)``."""
    p_s, vn_s, wn_s = state[0], y[2], y[3]
    slope = w[5] + w[2] * f1 + w[4] * f2
    compressed = state[1] > 0.0
    p_c, wn_c, wt_c = state[2], state[3], state[5]
    p_end = math.inf
    if not compressed and slope > 0.0:
        p_c = p_s - vn_s / slope
        wn_c = wn_s - 0.5 * vn_s * vn_s / slope
        wt_c = y[4] - mu * (rho * (p_c - p_s) + 0.5 * lam * (p_c - p_s) ** 2)
        compressed = True
    if compressed and slope > 0.0:
        if law == 1:
            p_end = (1.0 + kappa) * p_c
        elif law == 0:
            p_end = max(p_c, p_s + (-kappa * vn0 - vn_s) / slope)
        else:
            target = -kappa * kappa * wn_c  # the restitution work still to come ...
            if p_c >= p_s:
                p_end = p_c + math.sqrt(2.0 * target / slope)
            else:  # ... less what was done before this phase (negative where vn fell
                # below zero again after compression: friction pressing the contact back)
                left = max(target - (wn_s - wn_c), 0.0)
                p_end = p_s + (-vn_s + math.sqrt(vn_s * vn_s + 2.0 * slope * left)) / slope
        p_end = max(p_end, p_s)
    p_stop = p_s + rho / -lam if (rho > 0.0 and lam < 0.0) else math.inf
    stopped = p_stop < p_end and p_stop <= p_max
    ended = not stopped and p_end <= p_max
    d = min(p_stop, p_end, p_max) - p_s
    if not math.isfinite(d):
        return False, False
    y[3] += vn_s * d + 0.5 * slope * d * d
    y[2] = vn_s + slope * d
    speed = 0.0 if stopped else rho + lam * d
    y[0] = speed * r1
    y[1] = speed * r2
    y[4] -= mu * (rho * d + 0.5 * lam * d * d)
    y[5] += f1 * d
    y[6] += f2 * d
    state[0] = p_s + d
    if compressed and p_c <= state[0]:
        state[1], state[2], state[3], state[5] = 1.0, p_c, wn_c, wt_c
    if stopped:
        state[4] = state[0]
    return ended, stopped
