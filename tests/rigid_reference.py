"""Independent reference for the frictional impact of rigid bodies in 3D at one contact point.

What it computes
----------------
One impact at a time, by Keller's method: the normal impulse ``p_n`` (monotonically
increasing from 0) replaces time, and the contact velocity ``v = (v_t1, v_t2, v_n)`` (frame
``(t1, t2, n)``, ``n`` pointing into the body) changes with the contact impulse ``p`` as
``dv = W dp``, ``W`` the collision matrix of the contact (symmetric positive definite).
Write ``A = W_tt`` (the 2x2 tangential block), ``b = W_tn`` (the tangential-normal coupling)
and ``W_nn``. Coulomb's law, with ``s = |v_t|`` the slip speed and ``d = v_t / s`` the slip
direction:

* slide (``s > 0``): ``dp_t/dp_n = -mu d``, so ``dv_t/dp_n = a(d) = b - mu A d`` and
  ``dv_n/dp_n = W_nn - mu b.d``. The rate depends on the direction only, so the slip turns
  as ``d phi/dp_n = (d x a(d)) / s`` while ``ds/dp_n = d . a(d)``;
* where the slip vanishes (or is zero at the start): stick if ``|A^-1 b| <= mu``, with
  ``dp_t/dp_n = -A^-1 b``, ``v_t = 0`` and ``dv_n/dp_n = W_nn - b.A^-1 b`` (a Schur
  complement of ``W``: positive);
* otherwise re-slide along a unit direction ``e`` with ``a(e) = lambda e``, ``lambda > 0``.

The end of compression ``p_c`` is the first ``p_n > 0`` at which ``v_n`` reaches 0; the
impact ends under Poisson's law at ``(1 + kappa) p_c``, under Newton's at the first
``p_n >= p_c`` with ``v_n = -kappa v_n(0)``, under Stronge's at the first ``p_n > p_c``
with ``int_{p_c}^{p_n} v_n dp_n = -kappa^2 int_0^{p_c} v_n dp_n``.

Re-slide: a unique direction (derivation)
-----------------------------------------
``a(e) = lambda e`` is ``b = (lambda I + mu A) e``. For ``lambda > 0`` and ``mu >= 0`` the
matrix ``lambda I + mu A`` is positive definite, so ``e = (lambda I + mu A)^-1 b`` and the
condition ``|e| = 1`` reads ``h(lambda) = 1`` with ``h(lambda) = |(lambda I + mu A)^-1 b|``.
In the eigenbasis of ``A`` (eigenvalues ``alpha_i > 0``), ``h^2 = sum b_i^2 / (lambda + mu
alpha_i)^2``: strictly decreasing on ``lambda > 0`` when ``b != 0``, from
``h(0+) = |A^-1 b| / mu`` to 0. Hence a re-slide direction exists if and only if
``|A^-1 b| > mu``, which is exactly when sticking is not allowed, and it is then unique;
when sticking is allowed there is none. Stick and re-slide therefore never compete and
Coulomb's law decides the continuation uniquely (for ``mu = 0``: ``e = b / |b|``). The
derivation is this module's own (no published statement of it is relied on). The reference
does not assume it: it scans the angle of ``e`` (3600 points, the roots of ``e x a(e)``
refined by :func:`scipy.optimize.brentq`, kept where ``e . a(e) > 0``) and reports the
count. It found exactly one on each of 1,500 random contacts with ``mu`` drawn below
``|A^-1 b|`` (agreeing with the ``lambda`` equation to 2e-15 rad) and at every re-slide
met on 9,000 random impacts (21 re-slides); none where sticking is allowed.

The directions along which the slip *stops* are not unique. ``e x a(e) = (b2 cos - b1 sin)
- mu (A12 cos 2theta + (A22 - A11) sin 2theta / 2)`` is a trigonometric polynomial of
degree 2, so there are at most four invariant rays in all (re-slide and stopping rays
together): up to four stopping rays when sticking is allowed, up to three otherwise (on
1,500 random contacts with random ``mu``: one in 306, two in 585, three in 16, four in
593). The slip converges to one of them, often after turning a long way (by more than 90
degrees in 23 % of the random impacts above, by 191 degrees in one of the examples), and
sometimes only slowly: ``|phi - phi*|`` falls like ``s^k``, with ``k = (d/dphi (e x a)) /
(e . a)`` at the ray, which can be a few hundredths.

After a stick the contact stays stuck (the condition depends on ``W`` only), and a re-slide
runs along an invariant ray (the slip grows in the fixed direction ``e``), so the phases
are at most ``slide, stick, slide``; both late phases have constant rates and are advanced
exactly. A slip stop followed at once by a re-slide is recorded as a (momentary) "stick",
and an impact that starts with zero slip starts with "stick" (then "slide" if it
re-slides at once).

How it integrates
-----------------
Internally in units where ``|v(0)| = 1`` and the largest eigenvalue of ``W`` is 1. The first
slide is integrated with :func:`scipy.integrate.solve_ivp` (DOP853, ``rtol = 1e-12``,
``atol = 1e-15``) in two forms:

* in ``p_n``, on the state (slip speed ``s``, slip angle ``phi``, ``v_n``, ``p_t``, the
  normal and tangential works), while the slip is not small;
* once it has fallen below a switch value (20 % of the slip where the slide began) while
  shrinking, in ``u = ln(s_switch / s)``: ``dp_n/du = -s / (d . a)``, ``dphi/du = -(d x
  a) / (d . a)``, ``s`` known from ``u``. This form stays smooth up to the stop however fast
  the slip turns in ``p_n``. It ends when the slip angle has settled on its stopping ray
  (the error of finishing along the ray, ``mu |phi - phi*| (s / -(d . a)) / (1 + k)``, is
  below 1e-15 of the impulse scale) or when ``s`` is below 1e-17 of ``|v(0)|``; the rest
  is a straight line to zero slip with constant rates, advanced exactly. If ``d . a``
  rises above ``-gamma/2`` (the slip no longer shrinking) it returns to the ``p_n`` form.

The end of compression and the law's end are terminal events of both forms; the works are
states. The state at a terminal event is not read from the dense output, which near a
stopping ray (a stiff direction) was found off by 1e-8: the last step is integrated again
to the event, and the law's events are then placed by Newton steps on the event function.

Self-checks, in ``tests/core/test_rigid_reference.py``: the work of the impulse integrated
along the path equals ``v(0).p + p.W.p/2`` (path-independent for a symmetric ``W``) and
the final velocity equals ``v(0) + W p``, to 1e-10 of the scales (5e-13 measured);
closed forms for a sphere (the slip keeps its direction) and for a planar rod (Keller's
2D analysis) agree to 1e-10; rotating the tangential axes rotates the answer.

Precision: the answers move by at most 1.3e-12 of the velocity scale ``|v(0)|`` and of the
impulse scale ``|v(0)| / max eig W`` when ``rtol`` is tightened from 1e-12 to 1e-14 (300
random impacts per law). Speed: about 13 ms an impact on one core (median; a few ms for a
short slide, up to about 0.1 s for slips that turn slowly near a stopping ray).
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.spatial.transform import Rotation

LAWS = ("newton", "poisson", "stronge")

_ATOL = 1e-15  # in units |v(0)| = 1, max eig W = 1
_SWITCH = 0.2  # slip, as a fraction of the slip where the slide began, below which u is used
_STOPPED = 1e-17  # slip (units of |v(0)|) below which the rest is a straight line
_SETTLED = 1e-15  # error bound (scaled impulse) of finishing a slide on its stopping ray
_SCAN = 3600  # angles scanned for re-slide directions
_MAX_SEGMENTS = 400


class Margins(NamedTuple):
    """How close one impact came to another branch of the solution (nan: not applicable).

    Attributes
    ----------
    stick : float
        ``|W_tt^-1 W_tn| - mu`` where the slip stopped or started at zero (``<= 0``: stick;
        ``> 0``: re-slide); near 0 the two continuations meet.
    slip_min : float
        For a first slide that did not stop: the smallest slip speed along it over
        ``|v(0)|``; near 0 the slip nearly stopped.
    stop_to_end : float
        For a slide that stopped: ``(p_end - p_stop) / p_end`` (normal impulses); near 0 the
        impact nearly ended while sliding.
    """

    stick: float
    slip_min: float
    stop_to_end: float


class Reference(NamedTuple):
    """One impact, as found by :func:`reference_impact` (SI units of the inputs).

    Attributes
    ----------
    impulse : ndarray, shape (3,)
        Contact impulse ``(p_t1, p_t2, p_n)`` over the whole impact.
    velocity : ndarray, shape (3,)
        Contact velocity after the impact (integrated along the path).
    compression_impulse : float
        ``p_c``, the normal impulse at the end of compression.
    sequence : tuple of str
        Phases in order, from ``{"slide", "stick"}``.
    reslide_directions : tuple of int
        Re-slide directions found by the angle scan, one count per re-slide.
    work_normal_compression, work_normal_restitution : float
        ``int v_n dp_n`` over compression and over restitution.
    work_tangential : float
        ``int v_t . dp_t`` over the impact (never positive).
    dissipated : float
        Minus the total work of the impulse (the kinetic energy lost).
    margins : Margins
        Distances to the other branches, for counting cases near a boundary.
    slip_turn : float
        Angle (rad, counter-clockwise from t1 to t2) the slip direction turned during the
        first slide; 0 if there was none.
    ambiguous : bool
        True if a re-slide found more than one candidate direction (never seen).
    """

    impulse: np.ndarray
    velocity: np.ndarray
    compression_impulse: float
    sequence: tuple[str, ...]
    reslide_directions: tuple[int, ...]
    work_normal_compression: float
    work_normal_restitution: float
    work_tangential: float
    dissipated: float
    margins: Margins
    slip_turn: float
    ambiguous: bool


# --------------------------------------------------------------------------- collision matrix


def _cross_matrix(r: np.ndarray) -> np.ndarray:
    """``[r]x``, with ``[r]x y = r x y``."""
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def collision_matrix(mass: float, inertia, offset, frame) -> np.ndarray:
    """Collision matrix of one rigid body at a contact point, in the contact frame.

    Parameters
    ----------
    mass : float
        Mass of the body (kg).
    inertia : array_like, shape (3, 3)
        Inertia tensor about the centre of mass, world components (kg m^2).
    offset : array_like, shape (3,)
        Contact point minus centre of mass, world components (m).
    frame : array_like, shape (3, 3)
        Columns ``t1, t2, n`` (world components, orthonormal).

    Returns
    -------
    ndarray, shape (3, 3)
        ``W = R^T ((1/m) I - [r]x J^-1 [r]x) R`` with ``R = frame``: the change of the
        contact point's velocity per unit impulse applied there (``dv = W dp``).
    """
    r = np.asarray(offset, dtype=float)
    rx = _cross_matrix(r)
    world = np.eye(3) / mass - rx @ np.linalg.solve(np.asarray(inertia, dtype=float), rx)
    frame = np.asarray(frame, dtype=float)
    w = frame.T @ world @ frame
    return 0.5 * (w + w.T)


def pair_matrix(w1, w2) -> np.ndarray:
    """Collision matrix of two bodies touching at one point (``W1 + W2``, same frame).

    Parameters
    ----------
    w1, w2 : array_like, shape (3, 3)
        Each body's collision matrix at the contact, in the contact frame (body 2's
        computed with the frame as seen by body 1: the relative velocity is body 1's minus
        body 2's, and body 2 receives ``-p``).

    Returns
    -------
    ndarray, shape (3, 3)
    """
    return np.asarray(w1, dtype=float) + np.asarray(w2, dtype=float)


# ------------------------------------------------------------------------- the contact's rates


class _Rates:
    """Entries of the (scaled) collision matrix and the Coulomb rates built from them."""

    def __init__(self, w: np.ndarray, mu: float):
        self.a11, self.a12, self.a22 = float(w[0, 0]), float(w[0, 1]), float(w[1, 1])
        self.b1, self.b2, self.wnn = float(w[0, 2]), float(w[1, 2]), float(w[2, 2])
        self.mu = float(mu)
        self.w = w

    def slide(self, c: float, s: float):
        """``a(d)``, ``d . a``, ``d x a`` and ``dv_n/dp_n`` for the slip direction ``(c, s)``."""
        mu = self.mu
        a1 = self.b1 - mu * (self.a11 * c + self.a12 * s)
        a2 = self.b2 - mu * (self.a12 * c + self.a22 * s)
        return a1, a2, c * a1 + s * a2, c * a2 - s * a1, self.wnn - mu * (self.b1 * c + self.b2 * s)

    def turn_rate(self, phi: float) -> float:
        """``d/dphi (d x a(d))`` at the slip angle ``phi``."""
        c, s = math.cos(phi), math.sin(phi)
        mu = self.mu
        da1 = -mu * (-self.a11 * s + self.a12 * c)
        da2 = -mu * (-self.a12 * s + self.a22 * c)
        return -self.slide(c, s)[2] + c * da2 - s * da1

    def settled(self, phi: float, slip: float) -> float:
        """Error bound of finishing a shrinking slide as a straight line along the nearby
        stopping ray (scaled impulse units); inf if no attracting ray is near.

        Near a ray ``phi*`` where ``d x a = 0`` and ``d . a = g < 0``, the angle obeys
        ``d(phi - phi*)/du = -k (phi - phi*)``, ``k = f'/g`` (attracting if ``k > 0``), while
        ``ds/du = -s``; the impulse still to come is ``s / -g``. Replacing the true path by
        the ray changes the friction impulse by about ``mu |phi - phi*| (s / -g) / (1 + k)``.
        """
        _, _, g, f, _ = self.slide(math.cos(phi), math.sin(phi))
        fp = self.turn_rate(phi)
        if g >= 0.0 or fp == 0.0 or fp / g <= 0.0:
            return 0.0 if self.mu == 0.0 and g < 0.0 else math.inf
        return self.mu * abs(f / fp) * (slip / -g) / (1.0 + fp / g)

    def stopping_ray(self, phi: float) -> float:
        """The stopping ray that a shrinking slip at angle ``phi`` converges to.

        The slip angle moves as ``dphi/du = -(d x a) / (d . a)``, towards the next root of
        ``d x a`` in that sense (it may converge slowly: ``|phi - phi*|`` falls as ``s^k``
        with ``k`` as small as a few hundredths). Found by marching to a sign change of
        ``d x a``, then :func:`~scipy.optimize.brentq`.
        """

        def cross(x):
            return self.slide(math.cos(x), math.sin(x))[3]

        f0 = cross(phi)
        if f0 == 0.0:
            return phi
        for width in (1e-9, 1e-6):
            if cross(phi - width) * cross(phi + width) < 0.0:
                return brentq(cross, phi - width, phi + width, xtol=1e-16, rtol=1e-15)
        sense = -math.copysign(1.0, f0 / self.slide(math.cos(phi), math.sin(phi))[2])
        lo, step = phi, 1e-3
        while abs(lo - phi) < 2 * math.pi:
            hi = lo + sense * step
            if cross(hi) * f0 <= 0.0:
                return brentq(cross, min(lo, hi), max(lo, hi), xtol=1e-16, rtol=1e-15)
            lo, step = hi, min(2 * step, 0.05)
        return phi

    def stick_ratio(self) -> np.ndarray:
        """``dp_t/dp_n = -A^-1 b`` that keeps ``v_t = 0``."""
        a = np.array([[self.a11, self.a12], [self.a12, self.a22]])
        return -np.linalg.solve(a, np.array([self.b1, self.b2]))


def reslide_directions(w, mu: float, n: int = _SCAN) -> list[float]:
    """Angles ``theta`` (from t1 towards t2) of every re-slide direction of a contact.

    A re-slide direction ``e = (cos theta, sin theta)`` makes the slip grow along itself:
    ``a(e) = W_tn - mu W_tt e = lambda e`` with ``lambda > 0``.

    Parameters
    ----------
    w : array_like, shape (3, 3)
        Collision matrix (contact frame).
    mu : float
        Friction coefficient.
    n : int
        Angles scanned.

    Returns
    -------
    list of float
        The angles found: roots of ``e x a(e)`` (sign changes on the scan, refined by
        brentq) at which ``e . a(e) > 0``.
    """
    rates = _Rates(np.asarray(w, dtype=float), mu)

    def cross(theta):
        return rates.slide(math.cos(theta), math.sin(theta))[3]

    # an irrational shift keeps the grid off the special angles of symmetric inputs
    grid = 2 * math.pi * (np.arange(n + 1) + 0.5 / math.sqrt(2.0)) / n
    values = [cross(t) for t in grid]
    roots = []
    for k in range(n):
        lo, hi, flo, fhi = grid[k], grid[k + 1], values[k], values[k + 1]
        if flo == 0.0:
            theta = lo
        elif flo * fhi < 0.0:
            theta = brentq(cross, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
        else:
            continue
        if rates.slide(math.cos(theta), math.sin(theta))[2] > 0.0:
            roots.append(theta % (2 * math.pi))
    return roots


def reslide_direction_by_lambda(w, mu: float) -> np.ndarray | None:
    """The re-slide direction from ``|(lambda I + mu W_tt)^-1 W_tn| = 1`` (module notes).

    Returns
    -------
    ndarray, shape (2,), or None
        The unit direction, or None when sticking is allowed (no re-slide exists).
    """
    w = np.asarray(w, dtype=float)
    a, b = w[:2, :2], w[:2, 2]
    bn = float(np.hypot(*b))
    if bn == 0.0:
        return None
    if mu == 0.0:
        return b / bn
    if np.hypot(*np.linalg.solve(a, b)) <= mu:
        return None

    def excess(lam):
        return np.hypot(*np.linalg.solve(lam * np.eye(2) + mu * a, b)) - 1.0

    lam = brentq(excess, 0.0, bn, xtol=1e-300, rtol=4 * np.finfo(float).eps)
    e = np.linalg.solve(lam * np.eye(2) + mu * a, b)
    return e / np.hypot(*e)


# ---------------------------------------------------------------------------- the integration


class _Path:
    """The accumulated state of one impact (scaled units) and its restitution law."""

    def __init__(self, vn0: float, kappa: float, law: str):
        self.kappa, self.law, self.vn0 = float(kappa), law, vn0
        self.pn = 0.0
        self.pt = np.zeros(2)
        self.vn = vn0
        self.wn = 0.0
        self.wt = 0.0
        self.compressing = True
        self.pc = math.nan
        self.wc = math.nan
        self.ended = False

    def end_compression(self, pc: float, wc: float) -> None:
        """Record the end of compression; end the impact at once where the law says so."""
        self.compressing, self.pc, self.wc, self.vn = False, pc, wc, 0.0
        if self.kappa == 0.0:
            self.ended = True

    def end_value(self, pn: float, vn: float, wn: float) -> float:
        """Rises through 0 where the impact ends (restitution only)."""
        if self.law == "poisson":
            return pn - (1.0 + self.kappa) * self.pc
        if self.law == "newton":
            return vn + self.kappa * self.vn0
        return wn - (1.0 - self.kappa**2) * self.wc  # stronge


def _event(fun, terminal=True, direction=0.0):
    fun.terminal, fun.direction = terminal, direction
    return fun


def _run(rhs, span, y0, events, rtol, exact=()):
    """``solve_ivp`` (DOP853) up to the first terminal event, with an accurate end state.

    The state at a terminal event is not taken from the dense output (which can be off by
    far more than the tolerance where a component is stiff, as the slip angle is on a
    stopping ray): the last step is integrated again from its start to the event. For the
    events listed in ``exact`` the event's location is then corrected by Newton steps
    (rate from a central difference along the solution) until the event function vanishes.

    Returns ``(t, y, fired, sol)``; ``fired`` is the index of the terminal event (None if
    the end of ``span`` was reached).
    """
    opts = dict(method="DOP853", rtol=rtol, atol=_ATOL)
    sol = solve_ivp(rhs, span, y0, events=events, **opts)
    if sol.status < 0:
        raise RuntimeError(f"integration failed: {sol.message}")
    fired = _fired(sol, events)
    if fired is None:
        if sol.status == 1:
            raise RuntimeError("a terminal event could not be identified")
        return float(sol.t[-1]), sol.y[:, -1], None, sol
    ta, ya, te = float(sol.t[-2]), sol.y[:, -2], float(sol.t[-1])
    event = events[fired]
    for _ in range(4):
        y = ya if te == ta else solve_ivp(rhs, (ta, te), ya, **opts).y[:, -1]
        if fired not in exact:
            break
        h = 1e-6 * max(te - ta, 1e-12)
        dy = np.asarray(rhs(te, y))
        rate = (event(te + h, y + h * dy) - event(te - h, y - h * dy)) / (2 * h)
        step = -event(te, y) / rate if rate != 0.0 else 0.0
        if not abs(step) > 4 * np.finfo(float).eps * max(abs(te), te - ta):
            break
        te = max(te + step, ta)
    return te, y, fired, sol


def _fired(sol, events) -> int | None:
    """Index of the terminal event that stopped ``sol`` (None if none did)."""
    if sol.status != 1:
        return None
    for i, (te, event) in enumerate(zip(sol.t_events, events, strict=True)):
        if event.terminal and te.size and te[-1] == sol.t[-1]:
            return i
    return None


def _first_slide(rates: _Rates, path: _Path, vt0: np.ndarray, rtol: float):
    """Integrate the slide that starts with slip ``vt0`` until it stops or the impact ends.

    Returns ``(stopped, turn, slip_min, slip, angle)``: whether the slip stopped, the angle
    its direction turned, its smallest speed, and its speed and angle at the end.
    """
    mu, s = rates.mu, float(np.hypot(*vt0))
    phi0 = phi = math.atan2(vt0[1], vt0[0])
    switch = _SWITCH * s
    gamma = 1e-3 * (math.hypot(rates.b1, rates.b2) + mu * max(rates.a11, rates.a22))
    slip_min = s
    use_u = False

    def law_event(pn_of, vn_of, wn_of):
        if path.compressing:
            return _event(lambda t, y: vn_of(t, y), True, 1.0)
        return _event(lambda t, y: path.end_value(pn_of(t, y), vn_of(t, y), wn_of(t, y)), True, 1.0)

    def after_law_event(pn, vn, wn):
        path.pn, path.vn, path.wn = pn, vn, wn
        if path.compressing:
            path.end_compression(pn, wn)  # sets v_n = 0, its value by definition
        else:
            path.ended = True

    for _ in range(_MAX_SEGMENTS):
        g = rates.slide(math.cos(phi), math.sin(phi))[2]
        if use_u or (s <= switch and g < -gamma):
            use_u = False
            # ---- the u form: u = ln(s_switch / s), y = (phi, vn, pn, p1, p2, wn, wt)
            s_sw = s
            u_max = max(math.log(s_sw / _STOPPED), 1.0)

            def rhs_u(u, y, s_sw=s_sw):
                c, sn = math.cos(y[0]), math.sin(y[0])
                _, _, g, f, rn = rates.slide(c, sn)
                slip = s_sw * math.exp(-u)
                h = -slip / g
                return [-f / g, rn * h, h, -mu * c * h, -mu * sn * h, y[1] * h, -mu * slip * h]

            def settled(u, y, s_sw=s_sw):
                return rates.settled(y[0], s_sw * math.exp(-u)) - _SETTLED

            def shrinking(u, y):
                return rates.slide(math.cos(y[0]), math.sin(y[0]))[2] + 0.5 * gamma

            events = [
                law_event(lambda u, y: y[2], lambda u, y: y[1], lambda u, y: y[5]),
                _event(settled, True, -1.0),
                _event(shrinking, True, 1.0),
            ]
            y0 = [phi, path.vn, path.pn, path.pt[0], path.pt[1], path.wn, path.wt]
            if settled(0.0, y0) <= 0.0:
                fired = 1
            else:
                u, y, fired, _ = _run(rhs_u, (0.0, u_max), y0, events, rtol, exact=(0,))
                phi, s = float(y[0]), s_sw * math.exp(-u)
                path.pn, path.vn, path.wn = float(y[2]), float(y[1]), float(y[5])
                path.pt, path.wt = np.array([y[3], y[4]]), float(y[6])
                slip_min = min(slip_min, s)
            if fired is None or fired == 1:
                # on a stopping ray (or the slip is below _STOPPED): a straight line to zero
                phi = rates.stopping_ray(phi)
                c, sn = math.cos(phi), math.sin(phi)
                a1, a2, g, _, rn = rates.slide(c, sn)
                d = np.array([c, sn])
                slip = _advance(path, s * d, -mu * d, np.array([a1, a2]), rn, s / -g)
                if not path.ended:
                    return True, phi - phi0, 0.0, 0.0, phi
                s = float(np.hypot(*slip))
                return False, phi - phi0, min(slip_min, s), s, phi
            if fired == 0:
                after_law_event(path.pn, path.vn, path.wn)
                if path.ended:
                    return False, phi - phi0, slip_min, s, phi
            else:  # the slip no longer shrinks fast: back to the p_n form
                switch = 0.5 * s
            continue

        # ---- the p_n form: y = (s, phi, vn, p1, p2, wn, wt)
        def rhs_p(t, y):
            c, sn = math.cos(y[1]), math.sin(y[1])
            _, _, g, f, rn = rates.slide(c, sn)
            return [g, f / y[0], rn, -mu * c, -mu * sn, y[2], -mu * y[0]]

        def slip_minimum(t, y):
            return rates.slide(math.cos(y[1]), math.sin(y[1]))[2]

        events = [
            law_event(lambda t, y: t, lambda t, y: y[2], lambda t, y: y[5]),
            _event(lambda t, y, switch=switch: y[0] - switch, True, -1.0),
            _event(slip_minimum, False, 1.0),
        ]
        p_max = path.pn + 1e6 * (1.0 + abs(path.vn) + s)
        y0 = [s, phi, path.vn, path.pt[0], path.pt[1], path.wn, path.wt]
        t, y, fired, sol = _run(rhs_p, (path.pn, p_max), y0, events, rtol, exact=(0,))
        if fired is None:
            raise RuntimeError("the impact did not end within a very large normal impulse")
        s, phi = float(y[0]), float(y[1])
        if sol.y_events[2].size:
            slip_min = min(slip_min, float(sol.y_events[2][:, 0].min()))
        slip_min = min(slip_min, s)
        path.pt, path.wt = np.array([y[3], y[4]]), float(y[6])
        if fired == 0:
            after_law_event(t, float(y[2]), float(y[5]))
            if path.ended:
                return False, phi - phi0, slip_min, s, phi
        else:  # the slip fell to the switch value
            path.pn, path.vn, path.wn = t, float(y[2]), float(y[5])
            if rates.slide(math.cos(phi), math.sin(phi))[2] < -gamma:
                use_u = True
            else:
                switch = 0.5 * s
    raise RuntimeError("too many segments in the first slide")


def _law_step(path: _Path, rn: float) -> float:
    """Normal impulse to the law's end under constant ``dv_n/dp_n = rn`` (inf: not reached)."""
    vn = path.vn
    if path.law == "poisson":
        return max((1.0 + path.kappa) * path.pc - path.pn, 0.0)
    if path.law == "newton":
        rise = -path.kappa * path.vn0 - vn
        if rise <= 0.0:
            return 0.0
        return rise / rn if rn > 0.0 else math.inf
    rest = (1.0 - path.kappa**2) * path.wc - path.wn  # normal work still to be done
    if rest <= 0.0:
        return 0.0
    # smallest positive root of vn x + rn x^2 / 2 = rest
    disc = vn * vn + 2.0 * rn * rest
    if disc < 0.0:
        return math.inf
    if vn > 0.0:
        return 2.0 * rest / (vn + math.sqrt(disc))
    return (math.sqrt(disc) - vn) / rn if rn > 0.0 else math.inf


def _advance(path: _Path, vt, q, rt, rn: float, dp_max: float = math.inf) -> np.ndarray:
    """Advance with constant rates, over at most ``dp_max``, stopping at the impact's end.

    ``dp_t/dp_n = q``, ``v_t = vt + rt (p_n - p_start)``, ``dv_n/dp_n = rn``; velocities and
    works are exact (linear and quadratic in ``p_n``). Returns the slip at the end.
    """
    vt = np.asarray(vt, dtype=float)
    rt = np.asarray(rt, dtype=float)
    qv, qr = float(q @ vt), float(q @ rt)
    done = 0.0
    while not path.ended:
        dp, event = dp_max - done, None
        if path.compressing:
            if rn > 0.0 and -path.vn / rn <= dp:
                dp, event = -path.vn / rn, "compression"
        else:
            step = _law_step(path, rn)
            if step <= dp:
                dp, event = step, "end"
        if dp == math.inf:
            raise RuntimeError("the impact does not end under constant rates")
        path.wt += qv * dp + qr * ((done + dp) ** 2 - done**2) / 2
        path.wn += path.vn * dp + 0.5 * rn * dp * dp
        path.vn += rn * dp
        path.pt = path.pt + q * dp
        path.pn += dp
        done += dp
        if event == "compression":
            path.end_compression(path.pn, path.wn)
        elif event == "end":
            path.ended = True
        else:
            break
    return vt + rt * done


def reference_impact(w, velocity, mu: float, kappa: float, law: str, rtol: float = 1e-12):
    """Solve one frictional impact at a point contact by Keller's method.

    Parameters
    ----------
    w : array_like, shape (3, 3)
        Collision matrix in the contact frame ``(t1, t2, n)``, symmetric positive definite.
    velocity : array_like, shape (3,)
        Contact velocity before the impact, ``v_n < 0``.
    mu : float
        Coulomb friction coefficient, ``>= 0``.
    kappa : float
        Restitution coefficient in ``[0, 1]`` (of the chosen law).
    law : {"newton", "poisson", "stronge"}
    rtol : float
        Relative tolerance of the integration (the default is the tested one).

    Returns
    -------
    Reference
    """
    if law not in LAWS:
        raise ValueError(f"law must be one of {LAWS}, not {law!r}")
    w = np.asarray(w, dtype=float)
    v0 = np.asarray(velocity, dtype=float)
    if not v0[2] < 0.0:
        raise ValueError("the contact must approach: velocity[2] < 0")
    speed = float(np.linalg.norm(v0))
    wmax = float(np.linalg.eigvalsh(w)[-1])
    rates = _Rates(w / wmax, mu)
    vt0 = v0[:2] / speed
    path = _Path(v0[2] / speed, kappa, law)
    sequence, counts, ambiguous = [], [], False
    stick_margin = slip_min = stop_to_end = math.nan
    turn, stopped, p_stop = 0.0, True, 0.0
    vt_end = np.zeros(2)
    if vt0[0] != 0.0 or vt0[1] != 0.0:
        sequence.append("slide")
        stopped, turn, slip_min, slip, angle = _first_slide(rates, path, vt0, rtol)
        if stopped:
            p_stop, slip_min = path.pn, math.nan
        else:
            vt_end = slip * np.array([math.cos(angle), math.sin(angle)])
    if stopped:
        sequence.append("stick")
        ratio = rates.stick_ratio()
        stick_margin = float(np.hypot(*ratio)) - float(mu)
        if stick_margin <= 0.0:
            rn = rates.wnn + float(rates.w[2, :2] @ ratio)
            vt_end = _advance(path, np.zeros(2), ratio, np.zeros(2), rn)
        else:
            angles = reslide_directions(rates.w, mu)
            counts.append(len(angles))
            if len(angles) != 1:
                ambiguous = True
            if not angles:
                e = reslide_direction_by_lambda(rates.w, mu)
            else:
                e = np.array([math.cos(angles[0]), math.sin(angles[0])])
            sequence.append("slide")
            a1, a2, _, _, rn = rates.slide(e[0], e[1])
            vt_end = _advance(path, np.zeros(2), -mu * e, np.array([a1, a2]), rn)
        if sequence[0] == "slide":
            stop_to_end = (path.pn - p_stop) / path.pn
    pscale = speed / wmax
    impulse = np.array([path.pt[0], path.pt[1], path.pn]) * pscale
    after = np.array([vt_end[0], vt_end[1], path.vn]) * speed
    escale = speed * speed / wmax
    wc = path.wc * escale
    wr = (path.wn - path.wc) * escale
    wt = path.wt * escale
    return Reference(
        impulse=impulse,
        velocity=after,
        compression_impulse=path.pc * pscale,
        sequence=tuple(sequence),
        reslide_directions=tuple(counts),
        work_normal_compression=wc,
        work_normal_restitution=wr,
        work_tangential=wt,
        dissipated=-(wc + wr + wt),
        margins=Margins(float(stick_margin), float(slip_min), float(stop_to_end)),
        slip_turn=turn,
        ambiguous=ambiguous,
    )


def near_boundary(ref: Reference, tol: float = 1e-6) -> bool:
    """True if any margin of ``ref`` is within ``tol`` of a branch boundary."""
    m = ref.margins
    return any(abs(x) < tol for x in (m.stick, m.slip_min, m.stop_to_end) if not math.isnan(x))


# ------------------------------------------------------------------------------ random bodies


def random_body(rng: np.random.Generator):
    """A random rigid body and a contact on it: ``(W, mass, inertia, offset, frame)``.

    Mass ``10^U(-1, 1)`` kg; size ``L = 10^U(-1, 0)`` m; principal moments ``m L^2
    U(0.05, 1)``, redrawn until they obey the triangle inequality; a random orientation
    (uniform on SO(3)); the contact at ``L U(0.2, 1.5)`` from the centre of mass in a
    random direction; the normal random with the centre of mass on its positive side
    (``offset . n <= 0``) and ``t1`` at a random angle about it.
    """
    mass = 10.0 ** rng.uniform(-1.0, 1.0)
    size = 10.0 ** rng.uniform(-1.0, 0.0)
    while True:
        moments = mass * size**2 * rng.uniform(0.05, 1.0, 3)
        if 2.0 * moments.max() <= moments.sum():
            break
    rot = Rotation.random(random_state=rng).as_matrix()
    inertia = rot @ np.diag(moments) @ rot.T
    offset = rng.normal(size=3)
    offset *= size * rng.uniform(0.2, 1.5) / np.linalg.norm(offset)
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    if offset @ n > 0.0:
        n = -n
    helper = np.eye(3)[np.argmin(np.abs(n))]
    t1 = np.cross(n, helper)
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(n, t1)
    angle = rng.uniform(0.0, 2 * np.pi)
    t1, t2 = (
        math.cos(angle) * t1 + math.sin(angle) * t2,
        -math.sin(angle) * t1 + math.cos(angle) * t2,
    )
    frame = np.column_stack([t1, t2, n])
    return collision_matrix(mass, inertia, offset, frame), mass, inertia, offset, frame


def random_cases(count: int, seed: int, pairs: float = 0.25):
    """Random impacts: ``(W (count, 3, 3), velocity (count, 3), mu (count,), kappa (count,))``.

    Case ``k`` depends on ``seed`` and ``k`` only (the first cases of a longer draw are the
    cases of a shorter one). A fraction ``pairs`` are two random bodies touching
    (``W1 + W2``: body 2's matrix is that of another random body; any symmetric positive
    definite sum is a valid pair, body 2 being turned to share the frame). Approach speed
    ``10^U(-1, 1) U(0.2, 1)`` m/s; slip ``|v_n| 10^U(-2, 0.7)`` in a random direction (small
    slips make sticks likely, large ones long slides); ``mu ~ U(0, 1.5)``,
    ``kappa ~ U(0, 1)``.
    """
    rng = np.random.default_rng(seed)
    ws = np.empty((count, 3, 3))
    vel = np.empty((count, 3))
    mu = np.empty(count)
    kappa = np.empty(count)
    for k in range(count):
        w = random_body(rng)[0]
        if rng.uniform() < pairs:
            w = pair_matrix(w, random_body(rng)[0])
        ws[k] = w
        vn = -(10.0 ** rng.uniform(-1.0, 1.0)) * rng.uniform(0.2, 1.0)
        slip = abs(vn) * 10.0 ** rng.uniform(-2.0, 0.7)
        angle = rng.uniform(0.0, 2 * np.pi)
        vel[k] = (slip * math.cos(angle), slip * math.sin(angle), vn)
        mu[k] = rng.uniform(0.0, 1.5)
        kappa[k] = rng.uniform(0.0, 1.0)
    return ws, vel, mu, kappa


#: Seeded examples: name -> (seed, index into random_cases(index + 1, seed), law, the slip
#: at the start set to zero?, mu replacing the drawn one or None). Each is far from every
#: branch boundary (``near_boundary`` is False).
EXAMPLES = {
    "slide": (7, 0, "newton", False, None),  # slides throughout
    "slide-stick": (7, 1, "poisson", False, None),
    "slide-stick-slide": (7, 1345, "stronge", False, None),  # stops, then re-slides
    "turn": (7, 48, "newton", False, None),  # the slip turns by 168 degrees, then sticks
    "stick-from-rest": (7, 2, "poisson", True, None),  # |W_tt^-1 W_tn| = 0.031 < mu = 0.885
    "slide-from-rest": (7, 0, "stronge", True, 0.2),  # |W_tt^-1 W_tn| = 0.443 > mu
    "energy-newton": (7, 1532, "newton", False, None),  # Newton's law creates energy
}


def example(name: str):
    """One of :data:`EXAMPLES` as ``(W, velocity, mu, kappa, law)``."""
    seed, index, law, at_rest, mu = EXAMPLES[name]
    ws, vs, mus, kappas = _example_cases(seed)
    v = vs[index].copy()
    if at_rest:
        v[:2] = 0.0
    return ws[index], v, float(mus[index] if mu is None else mu), float(kappas[index]), law


@functools.cache
def _example_cases(seed: int):
    """The random cases the examples are drawn from (enough for every index used)."""
    return random_cases(1 + max(e[1] for e in EXAMPLES.values() if e[0] == seed), seed)
