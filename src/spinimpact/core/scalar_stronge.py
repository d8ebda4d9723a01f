r"""Stronge's lumped tangential compliance for one contact, on floats: the one formulation.

The physics and its closed forms are those of :mod:`spinimpact.core.stronge` (read its
docstring: the dimensionless time ``t`` of each normal phase, the stick phases harmonic at
``c Omega``, the slip phases in closed form). This module holds the computation itself,
written once, for one contact: :func:`stronge_contact` follows the impact phase by phase
(slip to its closed-form end; stick one window of ``16`` samples at a time, the first
sample where the spring's force leaves the friction cone, or a dip between two samples
that may reach it, then Newton's method kept inside the bracket). The array kernel
:func:`spinimpact.core.stronge.stronge_restitution` runs this very function over its rows
(compiled by Numba where installed, else a Python loop), and
:mod:`spinimpact.core.law` registers it for users' ``numba.njit`` code, so both give the
same bits. Written in the subset of Python that Numba compiles; a division whose divisor
may vanish goes through :func:`~spinimpact.core.scalar_planar._divide` (IEEE's ``inf`` or
NaN, never an exception), and no ``math.hypot`` (Python's and the C library's differ in
the last bit). Nothing is validated.

References
----------
.. [1] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000 (ch. 5, 8).
.. [2] N. Maw, J. R. Barber and J. N. Fawcett, "The role of elastic tangential compliance
   in oblique impact", Journal of Lubrication Technology 103 (1981) 74-80.
"""

from __future__ import annotations

import math

from .scalar import sign
from .scalar_planar import _divide, _maximum, _minimum

__all__ = ["stronge_contact"]

_HALF_PI = 0.5 * math.pi
#: Samples per stick window, and the sample step in units of 1/(c Omega).
_SAMPLES, _STEP = 16, 0.2
#: Most phases (stick, slip or stick windows) before giving up: far above what any
#: admissible input needs (about (pi/2) c Omega / (_SAMPLES _STEP) windows a phase).
_MAX_ROUNDS = 200_000


def _n(t, comp):
    """The normal force's shape in the phase: ``sin t`` in compression, ``cos t`` after."""
    return math.sin(t) if comp else math.cos(t)


def _clip01(x):
    """``x`` clipped to ``[0, 1]`` (NaN stays NaN)."""
    if x != x:
        return x
    return _minimum(_maximum(x, 0.0), 1.0)


def _stick(t, ta, ua, xa, c, r, zeta, omega):
    """``(u, x)`` at ``t`` of a stick phase that began at ``ta`` with ``(ua, xa)``."""
    w = c * omega
    ph = w * (t - ta)
    cs, sn = math.cos(ph), math.sin(ph)
    return ua * cs - _divide(c * zeta * xa, w) * sn, xa * cs + _divide(c * r * ua, w) * sn


def _cone(n, dn, u, x, sgn, cr, mu):
    """``h = mu n - sgn x + tol`` (the room left in the friction cone on side ``sgn``, to
    rounding) and ``h'``, from the stick phase's ``(u, x)`` and ``mu n``, ``mu n'``."""
    return n - sgn * x + 1e-12 * mu, dn - sgn * cr * u


def _h(t, slope, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift):
    """During a stick phase, :func:`_cone` at ``t``; with ``slope``, ``-h'`` and ``-h''``
    instead (a dip of ``h`` is least where ``h' = 0``)."""
    u, x = _stick(t, ta, ua, xa, c, r, zeta, omega)
    h, dh = _cone(mu * math.sin(t + shift), mu * math.cos(t + shift), u, x, sgn, c * r, mu)
    if slope:
        cw = c * omega
        return -dh, -(-mu * math.sin(t + shift) + sgn * (cw * cw) * x)
    return h, dh


def _root(a, b, slope, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift):
    """Where :func:`_h` crosses from ``>= 0`` at ``a`` to ``< 0`` at ``b``: Newton's steps
    kept inside the bracket, bisection where a step would leave it, to rounding."""
    t = 0.5 * (a + b)
    for _ in range(100):
        value, rate = _h(t, slope, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift)
        if value < 0.0:
            b = t
        else:
            a = t
        newton = t - _divide(value, rate)
        step = newton if (newton > a and newton < b) else 0.5 * (a + b)
        done = abs(step - t) <= 1e-15 * _maximum(abs(t), 1.0)
        t = step
        if done:
            break
    return t


def _crossing(lo, g, dip, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift):
    """Between the samples ``lo`` and ``g`` where ``h`` of side ``sgn`` went below zero, or
    dipped towards it: ``(root, real)``, where it crosses zero, and whether it does (a dip
    may stay above zero)."""
    b, real = g, True
    if dip:  # the least value of the dip, where h' changes sign
        b = _root(lo, g, True, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift)
        real = _h(b, False, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift)[0] < 0.0
    return _root(lo, b, False, sgn, ta, ua, xa, c, r, zeta, omega, mu, shift), real


def _stick_end(ta, ua, xa, c, r, zeta, mu, omega, comp, amp):
    """The first ``t`` after ``ta``, within one window of samples, where ``|x|`` exceeds
    ``mu n`` by more than rounding (``inf`` if none), and how far the window was checked."""
    w = c * omega
    cr = c * r
    step = _minimum(_divide(_STEP, w), _HALF_PI / _SAMPLES)
    shift = 0.0 if comp else _HALF_PI  # n = sin(t + shift), n' = cos(t + shift)
    checked = _minimum(ta + step * _SAMPLES, _HALF_PI)
    end = math.inf
    curvature = mu + (w * w) * amp  # |h''| <= mu + (c Omega)^2 amp while stuck
    n0, dn0 = mu * math.sin(ta + shift), mu * math.cos(ta + shift)
    # h = mu n - sgn x + tol on both sides, sgn = +1 and -1: stick needs both >= 0; each
    # side is scanned to its first sample that fails, the samples shared
    hp, dhp = _cone(n0, dn0, ua, xa, 1.0, cr, mu)
    hm, dhm = _cone(n0, dn0, ua, xa, -1.0, cr, mu)
    live_p = live_m = True
    lo = ta
    for k in range(1, _SAMPLES + 1):
        g = _minimum(ta + step * k, _HALF_PI)
        u, x = _stick(g, ta, ua, xa, c, r, zeta, omega)
        n, dn = mu * math.sin(g + shift), mu * math.cos(g + shift)
        bound = curvature * ((g - lo) * (g - lo)) / 8.0
        for sgn in (1.0, -1.0):
            if not (live_p if sgn > 0.0 else live_m):
                continue
            h0, dh0 = (hp, dhp) if sgn > 0.0 else (hm, dhm)
            hv, dh = _cone(n, dn, u, x, sgn, cr, mu)
            # a dip below zero between two samples: h falls, then rises, and its curvature
            # does not keep it above zero on the interval
            dip = hv >= 0.0 and dh0 < 0.0 and dh > 0.0 and _minimum(hv, h0) < bound
            if hv < 0.0 or dip:
                root, real = _crossing(lo, g, dip, sgn, ta, ua, xa, c, r, zeta, omega, mu,
                                       shift)  # fmt: skip
                # a dip that stays above zero: checked up to its interval's end, go on there
                checked = _minimum(checked, root if real else g)
                if real:
                    end = _minimum(end, root)
                if sgn > 0.0:
                    live_p = False
                else:
                    live_m = False
            elif sgn > 0.0:
                hp, dhp = hv, dh
            else:
                hm, dhm = hv, dh
        if not (live_p or live_m):
            break
        lo = g
    return (end if end <= checked else math.inf), checked


def _slip_phase(t, u, sigma, c, r, zeta, mu, comp):
    """A slip phase in direction ``sigma`` from ``(t, u)`` to its closed-form end: the new
    ``(t, u, x)`` and whether it ends stuck (the contact point's velocity vanished)."""
    end = _HALF_PI
    if comp:  # cos t = (zeta mu cos t_a - sigma u_a)/(mu (zeta - 1/r))
        a = sigma * u - zeta * mu * math.cos(t)
        hit = a < 0.0 and mu > 0.0
        if hit:
            b = mu * (zeta - _divide(1.0, r))
            end = _maximum(math.acos(_clip01(-a / b if b != 0.0 else -a)), t)
    else:  # sin t = (sigma u_a + kappa zeta mu sin t_a)/(mu (kappa zeta - 1/(kappa r)))
        a = sigma * u + c * zeta * mu * math.sin(t)
        b = -mu * (c * zeta - _divide(1.0, c * r))
        hit = a + b < 0.0 and mu > 0.0
        if hit:
            end = _maximum(math.asin(_clip01(-a / b if b != 0.0 else -a)), t)
    du = math.cos(t) - math.cos(end) if comp else c * (math.sin(end) - math.sin(t))
    return end, u - zeta * mu * sigma * du, sigma * mu * _n(end, comp), hit


def stronge_contact(slip, vy, zeta, mu, kappa, stiffness_ratio):
    r"""Slip after one impact under Stronge's lumped tangential compliance.

    Parameters
    ----------
    slip, vy : float
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float
        ``W_tt/W_nn``, friction (``>= 0``) and normal restitution (Stronge's energetic
        coefficient, in ``[0, 1]``).
    stiffness_ratio : float
        ``r = k_t/k_n > 0`` (Mindlin's ``2(1 - nu)/(2 - nu)`` from Poisson's ratio).

    Returns
    -------
    tuple
        ``(slip_after, stuck, transitions)``: ``c_t^+`` (m/s; ``0.0`` for ``c_t^- = 0``),
        whether the contact point stuck at any time, and the number of stick/slip changes;
        as :func:`spinimpact.core.stronge.stronge_restitution` gives them, bit for bit.

    Raises
    ------
    RuntimeError
        After ``200_000`` phases (not reached by admissible inputs).

    Notes
    -----
    Dimensionless: time ``omega_n t``, velocities in ``|c_n^-|``. It starts slipping if
    ``r |u^-| > mu`` (Maw et al.'s normalized incidence angle above 1); slip phases end in
    closed form, stick phases where ``|x| = mu n(t)``; the impact ends where the normal
    force does, ``n = 0`` (Stronge 2000, ch. 5).

    Examples
    --------
    >>> after, stuck, changes = stronge_contact(10.0, -1.0, 3.5, 0.5, 0.8, 0.8)
    >>> round(-after / 10.0, 12), stuck, changes  # slides throughout: beta_slide
    (-0.685, False, 0)
    """
    e, r = kappa, stiffness_ratio
    v = abs(vy)
    u = _divide(slip, v)
    omega = math.sqrt(zeta * r)
    t, x, comp = 0.0, 0.0, True
    active = u != 0.0  # no slip: it stays stuck at rest, u^+ = 0
    stick = active and r * abs(u) <= mu
    sigma = sign(u)
    stuck = stick
    changes = 0
    rounds = 0
    while active:
        rounds += 1
        if rounds > _MAX_ROUNDS:  # pragma: no cover - a safeguard
            raise RuntimeError("stronge_contact: too many stick/slip phases")
        c = 1.0 if comp else e
        if not stick:  # a slip phase, to its end in closed form
            t, u, x, stick = _slip_phase(t, u, sigma, c, r, zeta, mu, comp)
            stuck = stuck or stick
            changes += int(stick)
        if stick:  # a stick phase, one window of samples at a time
            q = _divide(c * r * u, c * omega)
            amp = math.sqrt(x * x + q * q)  # |x| <= amp while stuck
            # it holds while mu n >= amp: to the end of compression, or in restitution to
            # n = amp/mu (closed form); sample only where it may end
            if comp:
                safe = _HALF_PI if mu * _n(t, comp) >= amp else t
            else:
                safe = math.acos(_clip01(amp / (mu if mu > 0.0 else 1.0)))
            if safe > t:
                end, last = math.inf, safe
            else:
                end, last = _stick_end(t, u, x, c, r, zeta, mu, omega, comp, amp)
            leave = math.isfinite(end)
            t_new = end if leave else last
            u, x = _stick(t_new, t, u, x, c, r, zeta, omega)
            t = t_new
            if leave:
                sigma = sign(x)
                x = sigma * mu * _n(t, comp)
                changes += 1
            stick = not leave
        if t >= _HALF_PI:  # the end of a normal phase
            if not comp or e == 0.0:
                active = False
            else:
                comp, t = False, 0.0
    # the change of slip in units of |c_n^-|, back in m/s: mu = 0 leaves c_t^- as it was
    after = 0.0 if slip == 0.0 else slip + (u - _divide(slip, v)) * v
    return after + 0.0, stuck, changes
