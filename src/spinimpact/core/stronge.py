r"""Stronge's lumped-parameter tangential compliance, solved piecewise in closed form.

The contact is a massless point joined to the body by a normal and a tangential spring
(Stronge [1]_, ch. 5; Maw, Barber and Fawcett [2]_ for the stiffness ratio). On the seam
(``W_tn = 0``; ``W_nn = 1/m``, ``W_tt = zeta/m``):

* Normal spring, linear: stiffness ``k_n`` while loading, ``k_n/kappa^2`` while unloading
  from the largest compression (Stronge's model of the energetic coefficient: the
  restitution phase returns ``kappa^2`` of the stored energy). With ``W_tn = 0`` the normal
  motion is independent of friction and Newton's, Poisson's and Stronge's coefficients all
  equal ``kappa``; ``tau_1 = (1 + kappa) m |c_n^-|``, as in the rigid law.
* Tangential spring, linear, stiffness ``k_t = r k_n`` with ``r`` from Poisson's ratio
  (:func:`spinimpact.core.compliance.mindlin_stiffness_ratio`: Mindlin's initial
  tangential stiffness over Hertz's normal stiffness, both proportional to the contact
  radius). Its force on the body is ``F = -k_t xi`` (``xi``: the body's contact point less
  the contact point's position on the surface).
* Coulomb: the contact point sticks to the surface while ``|F| < mu N``; otherwise it slips
  with ``F = -mu N sign(w)``, ``w`` its velocity on the surface.

Dimensionless form. Time ``s = omega_n t`` with ``omega_n = sqrt(k_n W_nn)``; velocities in
units of ``|c_n^-|``, forces in ``omega_n m |c_n^-|``: ``u = c_t/|c_n^-|``, ``x = -F/(...)``.
In compression (``n = sin t``, ``t = s``) and restitution (``n = cos t``, ``s = pi/2 +
kappa t``), with ``c = 1`` or ``kappa`` the phase's time scale, ``t`` in ``[0, pi/2]``:

* stick: :math:`u' = -c\zeta x,\ x' = c r u`: harmonic at ``c Omega``,
  :math:`\Omega = \sqrt{\zeta r} = \omega_t/\omega_n`, the ratio of the tangential to the
  normal frequency; it lasts while ``|x| < mu n(t)`` (the first crossing is found by
  sampling at a fine fraction of the period, then Newton's method kept inside the
  bracket, vectorized);
* slip in direction ``sigma``: ``x = sigma mu n(t)``, :math:`u' = -c\zeta\mu\sigma n`, so
  ``u = u_a - zeta mu sigma (cos t_a - cos t)`` or ``u_a - kappa zeta mu sigma (sin t -
  sin t_a)``; the contact point's velocity :math:`w = u - \mu\sigma n'/(c r)` keeps the
  sign ``sigma`` until :math:`\sigma u - \mu n'/(c r)` vanishes, in closed form:
  :math:`\cos t = (\zeta\mu\cos t_a - \sigma u_a)/(\mu(\zeta - 1/r))` in compression and
  :math:`\sin t = (\sigma u_a + \kappa\zeta\mu\sin t_a)/(\mu(\kappa\zeta - 1/(\kappa r)))`
  in restitution.

The impact starts slipping if ``r |u^-| > mu`` (Maw et al.'s normalized incidence angle
above 1) and sticking otherwise. It ends with ``n = 0``, so ``x = 0``: no energy stays in
the spring, and ``u^2/zeta + x^2/r`` (the tangential kinetic plus spring energy) never
grows, so ``|beta| <= 1``. If it slides throughout, ``beta = beta_slide`` (Coulomb over
the whole ``tau_1``) exactly, also where the rigid law would have stuck: the unloading
spring lets the contact point slide on past ``c_t = 0`` by up to ``mu |c_n^-|/(kappa r)``.
As ``r -> inf`` (a rigid contact) the slip after tends to the rigid law's, the difference
bounded by the stuck spring's velocity amplitude ``mu |c_n^-| sqrt(zeta/r)``
(``docs/compliance.md``).

References
----------
.. [1] W. J. Stronge, Impact Mechanics, Cambridge University Press, 2000 (ch. 5, 8).
.. [2] N. Maw, J. R. Barber and J. N. Fawcett, "The role of elastic tangential compliance
   in oblique impact", Journal of Lubrication Technology 103 (1981) 74-80.
"""

from __future__ import annotations

import functools
from typing import Any, NamedTuple

import numpy as np

__all__ = ["StrongeRebound", "stronge_restitution"]

_HALF_PI = 0.5 * np.pi
#: Samples per stick window, and the sample step in units of 1/(c Omega).
_SAMPLES, _STEP = 16, 0.2
#: Most phases (stick, slip or stick windows) before giving up: far above what any
#: admissible input needs (about (pi/2) c Omega / (_SAMPLES _STEP) windows a phase).
_MAX_ROUNDS = 200_000


class StrongeRebound(NamedTuple):
    """Result of :func:`stronge_restitution`."""

    slip_after: Any  #: c_t^+, m/s
    stuck: Any  #: whether the contact point stuck at any time
    transitions: Any  #: number of stick/slip changes during the impact
    restitution: Any  #: beta = -c_t^+/c_t^- (NaN for c_t^- = 0)


def _n(t, comp):
    return np.where(comp, np.sin(t), np.cos(t))


def _dn(t, comp):
    return np.where(comp, np.cos(t), -np.sin(t))


def _stick(t, ta, ua, xa, c, r, zeta, omega):
    """``(u, x)`` at ``t`` of a stick phase that began at ``ta`` with ``(ua, xa)``."""
    w = c * omega
    ph = w * (t - ta)
    cs, sn = np.cos(ph), np.sin(ph)
    return ua * cs - (c * zeta * xa / w) * sn, xa * cs + (c * r * ua / w) * sn


def _stick_end(ta, ua, xa, c, r, zeta, mu, omega, comp, amp):
    """The first ``t`` after ``ta``, within one window of samples, where ``|x|`` exceeds
    ``mu n`` by more than rounding (``inf`` if none), and how far the window was checked."""
    w = c * omega
    step = np.minimum(_STEP / w, _HALF_PI / _SAMPLES)
    grid = np.minimum(ta[:, None] + step[:, None] * np.arange(1, _SAMPLES + 1), _HALF_PI)
    lo = np.concatenate([ta[:, None], grid[:, :-1]], axis=1)
    shift = np.where(comp, 0.0, _HALF_PI)  # n = sin(t + shift), n' = cos(t + shift)
    col = [a[:, None] for a in (ta, ua, xa, c, r, zeta, omega, mu, 1e-12 * mu, shift)]
    end = np.full(ta.shape, np.inf)
    checked = grid[:, -1].copy()
    u, x = _stick(grid, *col[:7])  # shared by both signs
    n, dn = col[7] * np.sin(grid + col[9]), col[7] * np.cos(grid + col[9])
    n0, dn0 = col[7] * np.sin(col[0] + col[9]), col[7] * np.cos(col[0] + col[9])
    cr = col[3] * col[4]
    for sign in (1.0, -1.0):  # h = mu n - sign x + tol, smooth; stick needs both >= 0
        hv, dh = n - sign * x + col[8], dn - sign * cr * u
        h0, dh0 = n0 - sign * col[2] + col[8], dn0 - sign * cr * col[1]  # at t_a: (u_a, x_a)
        # a dip below zero between two samples: h falls, then rises, and |h''| <= mu +
        # (c Omega)^2 amp does not keep it above zero on the interval
        dip = (hv >= 0) & (np.concatenate([dh0, dh[:, :-1]], axis=1) < 0) & (dh > 0)
        bound = (col[7] + (col[3] * col[6]) ** 2 * amp[:, None]) * (grid - lo) ** 2 / 8
        dip &= np.minimum(hv, np.concatenate([h0, hv[:, :-1]], axis=1)) < bound
        hit = (hv < 0) | dip
        rows = np.flatnonzero(hit.any(axis=1))
        if not rows.size:
            continue
        first = np.argmax(hit[rows], axis=1)
        sub = [x[rows] for x in col]
        a, b = lo[rows, first], grid[rows, first]
        real = np.ones(rows.size, dtype=bool)
        d = np.flatnonzero(dip[rows, first])
        if d.size:  # the least value of a candidate dip, where h' changes sign
            dsub = [x[d] for x in sub]
            tmin = _root(a[d], b[d], functools.partial(_slope, col=dsub, sign=sign))
            real[d] = _h(tmin[:, None], dsub, sign)[0][:, 0] < 0
            b[d] = tmin
        root = _root(a, b, functools.partial(_h1, col=sub, sign=sign))
        # a dip that stays above zero: checked up to its interval's end, go on from there
        stop = np.where(real, root, grid[rows, first])
        checked[rows] = np.minimum(checked[rows], stop)
        end[rows] = np.where(real, np.minimum(end[rows], root), end[rows])
    end = np.where(end <= checked, end, np.inf)  # only an end before any unchecked stretch
    return end, checked


def _root(a, b, f):
    """Where ``f(t, rows)`` (the value and the derivative at ``t`` of those rows) crosses
    from ``>= 0`` at ``a`` to ``< 0`` at ``b``, per row: Newton's steps kept inside the
    bracket, bisection where a step would leave it, to rounding."""
    a, b = a.copy(), b.copy()
    t = 0.5 * (a + b)
    live = np.arange(t.size)
    for _ in range(100):
        value, slope = f(t[live], live)
        below = value < 0
        a[live] = np.where(below, a[live], t[live])
        b[live] = np.where(below, t[live], b[live])
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            newton = t[live] - value / slope
        inside = (newton > a[live]) & (newton < b[live])
        step = np.where(inside, newton, 0.5 * (a[live] + b[live]))
        done = np.abs(step - t[live]) <= 1e-15 * np.maximum(np.abs(t[live]), 1.0)
        t[live] = step
        live = live[~done]
        if not live.size:
            break
    return t


def _h1(t, rows, col, sign):
    """:func:`_h` at one ``t`` for each of ``rows``."""
    value, slope = _h(t[:, None], [x[rows] for x in col], sign)
    return value[:, 0], slope[:, 0]


def _slope(t, rows, col, sign):
    """``-h'`` and ``-h''`` of :func:`_h` for ``rows`` (a dip is least where ``h' = 0``)."""
    ta, ua, xa, c, r, zeta, omega, mu, tol, shift = (x[rows, 0] for x in col)
    u, x = _stick(t, ta, ua, xa, c, r, zeta, omega)
    dh = mu * np.cos(t + shift) - sign * c * r * u
    d2h = -mu * np.sin(t + shift) + sign * (c * omega) ** 2 * x
    return -dh, -d2h


def _h(t, col, sign):
    """``mu n - sign x + tol`` and its derivative in ``t`` during a stick phase."""
    ta, ua, xa, c, r, zeta, omega, mu, tol, shift = col
    u, x = _stick(t, ta, ua, xa, c, r, zeta, omega)
    return mu * np.sin(t + shift) - sign * x + tol, mu * np.cos(t + shift) - sign * c * r * u


def stronge_restitution(slip, vy, zeta, mu, kappa, stiffness_ratio):
    """The slip after an impact with Stronge's lumped tangential compliance.

    Parameters
    ----------
    slip, vy : float or array
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float or array
        ``W_tt/W_nn``, friction and normal restitution (here the energetic coefficient,
        equal to Newton's and Poisson's with ``W_tn = 0``).
    stiffness_ratio : float or array
        ``r = k_t/k_n > 0``, e.g. ``2(1-nu)/(2-nu)``.

    Returns
    -------
    StrongeRebound
        ``slip_after`` (m/s), ``stuck``, ``transitions`` and ``restitution`` (``beta``),
        of the broadcast shape. NumPy arrays (the phases are iterated with masks).

    Examples
    --------
    Sliding throughout it is the rigid law's sliding rebound; a small incidence angle
    sticks and reverses the slip:

    >>> r = stronge_restitution([10.0, 0.3], -1.0, 3.5, 0.5, 0.8, 0.8)
    >>> round(float(r.restitution[0]), 12), bool(r.stuck[1]), bool(r.restitution[1] > 0)
    (-0.685, True, True)
    """
    u0, vy, zeta, mu, kappa, r = (
        np.asarray(a, dtype=np.float64)
        for a in np.broadcast_arrays(slip, vy, zeta, mu, kappa, stiffness_ratio)
    )
    shape = u0.shape
    u0, vy, zeta, mu, e, r = (a.ravel() for a in (u0, vy, zeta, mu, kappa, r))
    v = np.abs(vy)
    u = u0 / v
    omega = np.sqrt(zeta * r)
    t = np.zeros(u.size)
    x = np.zeros(u.size)
    comp = np.ones(u.size, dtype=bool)
    active = u != 0  # no slip: it stays stuck at rest, u^+ = 0
    stick = active & (r * np.abs(u) <= mu)
    sigma = np.sign(u)
    stuck = stick.copy()
    changes = np.zeros(u.size, dtype=np.int64)
    # tiny mu or kappa (down to subnormal numbers) overflow 1/(c r) and -a/b harmlessly:
    # the quotients are clipped, and such a phase changes nothing
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        for _ in range(_MAX_ROUNDS):
            if not active.any():
                break
            c = np.where(comp, 1.0, e)
            # -- slip phases, to their end in closed form --------------------------------
            i = np.flatnonzero(active & ~stick)
            if i.size:
                ti, ui, si, mi, zi, ri, ci, pi = (
                    t[i],
                    u[i],
                    sigma[i],
                    mu[i],
                    zeta[i],
                    r[i],
                    c[i],
                    comp[i],
                )
                with np.errstate(divide="ignore", invalid="ignore"):
                    a_c = si * ui - zi * mi * np.cos(ti)
                    b_c = mi * (zi - 1.0 / ri)
                    a_r = si * ui + ci * zi * mi * np.sin(ti)
                    b_r = -mi * (ci * zi - 1.0 / (ci * ri))
                    hit = np.where(pi, a_c < 0, a_r + b_r < 0) & (mi > 0)
                    tc = np.arccos(np.clip(-a_c / np.where(b_c != 0, b_c, 1.0), 0.0, 1.0))
                    tr = np.arcsin(np.clip(-a_r / np.where(b_r != 0, b_r, 1.0), 0.0, 1.0))
                tend = np.where(hit, np.maximum(np.where(pi, tc, tr), ti), _HALF_PI)
                du = np.where(pi, np.cos(ti) - np.cos(tend), ci * (np.sin(tend) - np.sin(ti)))
                u[i] = ui - zi * mi * si * du
                t[i] = tend
                x[i] = si * mi * _n(tend, pi)
                s_i = hit.copy()
                stick[i] = s_i
                stuck[i] |= s_i
                changes[i] += s_i
            # -- stick phases, one window of samples at a time ---------------------------
            j = np.flatnonzero(active & stick)
            if j.size:
                tj, uj, xj, cj, mj, pj = t[j], u[j], x[j], c[j], mu[j], comp[j]
                amp = np.hypot(xj, cj * r[j] * uj / (cj * omega[j]))  # |x| <= amp while stuck
                # it holds while mu n >= amp: to the end of compression, or in restitution to
                # n = amp/mu (closed form); sample only where it may end
                level = np.arccos(np.clip(amp / np.where(mj > 0, mj, 1.0), 0.0, 1.0))
                safe = np.where(pj, np.where(mj * _n(tj, pj) >= amp, _HALF_PI, tj), level)
                skip = safe > tj
                end, last = _stick_end(tj, uj, xj, cj, r[j], zeta[j], mj, omega[j], pj, amp)
                end[skip], last[skip] = np.inf, safe[skip]
                tnew = np.where(np.isfinite(end), end, last)
                un, xn = _stick(tnew, tj, uj, xj, cj, r[j], zeta[j], omega[j])
                leave = np.isfinite(end)
                sg = np.where(leave, np.sign(xn), sigma[j])
                u[j], t[j], sigma[j] = un, tnew, sg
                x[j] = np.where(leave, sg * mu[j] * _n(tnew, comp[j]), xn)
                stick[j] = ~leave
                changes[j] += leave
            # -- the end of a normal phase ------------------------------------------------
            over = active & (t >= _HALF_PI)
            ends = over & (~comp | (e == 0))
            active &= ~ends
            go_on = over & comp & (e > 0)
            comp &= ~go_on
            t[go_on] = 0.0
        else:  # pragma: no cover - a safeguard, not reached by admissible inputs
            raise RuntimeError("stronge_restitution: too many stick/slip phases")
    # the change of slip in units of |c_n^-|, back in m/s: mu = 0 leaves c_t^- as it was
    after = np.where(u0 == 0, 0.0, u0 + (u - u0 / v) * v) + 0.0
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = np.where(u0 != 0, -after / np.where(u0 != 0, u0, 1.0), np.nan)
    return StrongeRebound(*(a.reshape(shape)[()] for a in (after, stuck, changes, beta)))
