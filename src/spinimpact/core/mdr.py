r"""Hertz-Mindlin-Deresiewicz impact, by the method of dimensionality reduction (MDR).

A sphere (or any body with a circular Hertz contact) strikes a plane. The normal contact is
Hertz's, ``N = k delta^{3/2} (1 + a d delta/dt)`` (Hunt-Crossley damping ``a`` calibrated to
the restitution ``kappa``); the tangential contact is elastic with Coulomb friction at every
point of the contact area (Mindlin-Deresiewicz partial slip, or micro-slip), under the whole
loading history of the impact: the area grows and then shrinks while the tangential load
rises, falls and reverses.

The method
----------
Popov and Hess's method of dimensionality reduction [1]_ replaces the circular contact of
radius ``a`` by a row of independent springs on the segment ``|x| < a``: a spring at ``x`` has
normal stiffness ``E* dx`` and is pressed by ``w(x) = delta - x^2/R``; its tangential stiffness
is ``4 G* dx = r E* dx`` (``r = 4 G*/E*``, Mindlin's stiffness ratio) and it slips once its
tangential force would exceed ``mu`` times its normal force,

.. math:: |s(x)| \le \frac{\mu}{r}\, w(x) \left(1 + a \dot\delta\right),

where ``s(x)`` is its tangential displacement: it follows the displacement of the body's
contact point while it sticks, starts at zero when the spring comes into contact and is zero
out of contact. For a paraboloid this reproduces exactly the three-dimensional half-space
solutions of Hertz (normal), Cattaneo-Mindlin (tangential loading at constant normal load) and
Mindlin-Deresiewicz (any sequence of normal and tangential loading), within the usual
uncoupled approximation of elastically similar bodies [1]_, [2]_. Each spring stands for the
annulus of the real contact at radius ``|x|`` (the flat-punch increment of that radius):
a spring that sticks while the contact shrinks keeps the loading history of its annulus, and
the contact's edge, where the pressure vanishes, slips.

In the limit ``mu -> infinity`` (no slip anywhere but at the receding edge) the tangential
force is ``F(t) = F_load(delta) + 8 G* a (xi - xi_load(delta))`` while the contact shrinks,
with ``F_load`` and ``xi_load`` the force and displacement at the same compression while it
grew; :func:`spinimpact.core.tangential.integrate_tangential` integrates that rule
(``spring="history"``) with exact events, an independent check of this module.

Numerics
--------
The rebound depends on the incidence only through ratios, so the impact is solved in units
``m = 1``, ``|v_n^-| = 1``, ``R = 1`` and ``k = 5/4`` (an elastic impact then compresses to
``delta = 1``). The normal motion does not depend on the tangential one: it is integrated once
per ``kappa`` (DOP853, ``rtol = 1e-12``) and sampled at ``steps + 1`` equal times from touch
to separation. The tangential motion is a leapfrog (the contact point's slip velocity at half
steps, the springs at whole steps) with ``springs`` springs at the midpoints of equal cells of
``[0, sqrt(delta_max)]`` (the contact is symmetric in ``x``). With NumPy, every impact with the
same ``kappa`` is stepped together (an array over impacts), so a Python loop runs over time
steps and distinct ``kappa`` values only; with Numba (:mod:`spinimpact.core.mdr_kernel`) the
steps are compiled, one impact per thread. A spring that comes into contact during a step moves
for the part of the step after it did (the compression linear over the step). The springs'
normal forces are scaled down where the midpoint rule makes their sum exceed Hertz's force,
so that the friction impulse never exceeds ``mu`` times the normal impulse. The defaults
(256 springs, 2048 steps) agree with four times as many of each within ``1e-5`` of
``|v_n^-|`` in the slip after the impact (``2.2e-6`` measured on the 40 random impacts of
``tests/core/test_mdr.py``, ``mu <= 0.8``); in the no-slip limit (``mu -> infinity``), where
the springs leave contact carrying their whole load, the gap to the converged value is
``4.3e-5`` of the slip. ``steps`` must resolve the tangential oscillation (at least 16
steps a period at the stiffest point: a ``ValueError`` says how many are needed).

References
----------
.. [1] V. L. Popov, M. Hess, *Method of Dimensionality Reduction in Contact Mechanics and
   Friction*, Springer (2015).
.. [2] R. D. Mindlin, H. Deresiewicz, "Elastic spheres in contact under varying oblique
   forces", Journal of Applied Mechanics 20 (1953) 327-344.
"""

from __future__ import annotations

import functools
import math
from typing import NamedTuple

import numpy as np

from .._validation import require

__all__ = ["HERTZ", "NormalHistory", "MdrTrace", "hunt_crossley_damping", "normal_history",
           "spring_positions", "mdr_slip", "mdr_trace", "spring_update",
           "active_springs"]  # fmt: skip

#: Hertz stiffness in the solver's units (m = 1, ``|v_n|`` = 1, R = 1): elastic compression 1.
HERTZ = 1.25

#: Impacts stepped together at most (rows of the springs' array), to bound memory.
CHUNK = 128


def _normal_run(damping: float, dense: bool = False):
    """One normal impact in the solver's units: ``delta'' = -k delta^1.5 (1 + a delta')``
    from ``delta = 0, delta' = 1`` until ``N = 0`` (falling), as ``solve_ivp``'s result."""
    from scipy.integrate import solve_ivp

    k, a = HERTZ, damping

    def rhs(_t, y):
        d = max(y[0], 0.0)
        return [y[1], -max(k * d**1.5 * (1.0 + a * y[1]), 0.0)]

    def separation(_t, y):  # delta (1 + a delta'): N^(2/3)-like, falls through zero once
        return y[0] * (1.0 + a * y[1])

    separation.terminal, separation.direction = True, -1
    run = solve_ivp(rhs, (0.0, 100.0), [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=separation, dense_output=dense)  # fmt: skip
    if run.status != 1:
        raise RuntimeError(f"the normal contact did not end: {run.message}")
    return run


@functools.lru_cache(maxsize=1024)
def hunt_crossley_damping(kappa: float) -> float:
    """The Hunt-Crossley damping ``a`` (in units of ``1/|v_n^-|``) for which a Hertz impact
    rebounds with Newton's restitution ``kappa`` (``0 < kappa <= 1``).

    Examples
    --------
    >>> hunt_crossley_damping(1.0)
    0.0
    >>> round(hunt_crossley_damping(0.98), 6)
    0.030611
    """
    from scipy.optimize import brentq

    if not 0.0 < kappa <= 1.0:
        raise ValueError(f"kappa must be in (0, 1] for a Hunt-Crossley contact, got {kappa!r}")
    if kappa == 1.0:
        return 0.0

    def gap(a):
        run = _normal_run(a)
        return -run.y_events[0][0][1] - kappa

    hi = 0.5
    while gap(hi) > 0.0:
        hi *= 4.0
        if hi > 1e8:
            raise ValueError(f"kappa = {kappa!r} is below what this contact can reach")
    return float(brentq(gap, 0.0, hi, xtol=1e-15, rtol=1e-13))


class NormalHistory(NamedTuple):
    """The normal motion of one impact in the solver's units, at ``steps + 1`` equal times."""

    t: np.ndarray  #: time from touch to separation
    delta: np.ndarray  #: compression
    rate: np.ndarray  #: d delta/dt
    force: np.ndarray  #: N
    damping: float  #: Hunt-Crossley ``a``


@functools.lru_cache(maxsize=64)
def normal_history(kappa: float, steps: int) -> NormalHistory:
    """The normal motion for restitution ``kappa`` sampled at ``steps + 1`` equal times."""
    a = hunt_crossley_damping(kappa)
    run = _normal_run(a, dense=True)
    t = np.linspace(0.0, float(run.t_events[0][0]), steps + 1)
    delta, rate = run.sol(t)
    delta = np.maximum(delta, 0.0)
    delta[0] = 0.0
    force = np.maximum(HERTZ * delta**1.5 * (1.0 + a * rate), 0.0)
    force[-1] = 0.0
    for x in (t, delta, rate, force):
        x.setflags(write=False)
    return NormalHistory(t, delta, rate, force, a)


def spring_positions(delta_max: float, springs: int) -> np.ndarray:
    """Midpoints of ``springs`` equal cells of ``[0, sqrt(delta_max)]`` (units of ``sqrt(R)``)."""
    width = math.sqrt(delta_max) / springs
    return (np.arange(springs) + 0.5) * width


def spring_update(s, step, limit):
    """The springs after the contact point moves by ``step``: each follows it, held within
    ``|s| <= limit`` (Coulomb, spring by spring; ``limit = 0``: out of contact, ``s = 0``).
    Returns ``(s, stuck)``, ``stuck`` whether each spring held without slipping."""
    trial = s + step
    return np.clip(trial, -limit, limit), np.abs(trial) < limit


class MdrTrace(NamedTuple):
    """One impact over time (:func:`mdr_trace`), in the solver's units (``m = 1``,
    ``|v_n^-| = 1``, ``R = 1``; multiply forces by ``m |v_n^-|^2/delta_scale`` to restore units)."""

    t: np.ndarray  #: times of the whole steps
    compression: np.ndarray  #: delta
    normal_force: np.ndarray  #: N
    tangential_force: np.ndarray  #: F on the body's contact point
    slip: np.ndarray  #: contact point's slip velocity (interpolated to whole steps)
    stick_radius: np.ndarray  #: radius of the stuck core over the contact radius (0: sliding)
    spring_energy: np.ndarray  #: elastic energy of the tangential springs
    dissipated: np.ndarray  #: energy dissipated by slip so far (tangential)


def active_springs(limits, share):
    """One past the last spring in contact at each step, or at the step before (a spring
    that leaves contact is zeroed at that step): the springs are ordered outwards."""
    inside = (limits > 0.0) | (share > 0.0)
    count = np.where(inside.any(axis=1), inside.shape[1] - np.argmax(inside[:, ::-1], axis=1), 0)
    return np.maximum(count, np.concatenate(([0], count[:-1]))).astype(np.int64)


class Springs(NamedTuple):
    """The reduced contact of one ``kappa`` and resolution (:func:`_setup`)."""

    hist: NormalHistory
    x: np.ndarray  #: the springs' positions
    limits: np.ndarray  #: Coulomb's bound over mu, per step and spring
    stiffness: float  #: a spring's tangential stiffness
    share: np.ndarray  #: the part of each step each spring is in contact
    active: np.ndarray  #: one past the last spring to visit at each step
    factor: np.ndarray  #: limits = max(delta - x^2, 0) * factor, per step


@functools.lru_cache(maxsize=16)
def _setup(kappa: float, steps: int, springs: int, ratio: float):
    """The springs of one ``kappa`` and resolution (cached: read-only arrays)."""
    hist = normal_history(float(kappa), int(steps))
    x = spring_positions(float(hist.delta.max()), springs)
    width = x[1] - x[0] if springs > 1 else 2.0 * x[0]
    w = hist.delta[:, None] - x**2  # the springs' compression, delta - x^2
    # their normal forces, E* sqrt(R) w dx each (E* sqrt(R) = 3 k/4, both sides of x = 0),
    # add up to Hertz's elastic force but for the midpoint rule's error; where they add up
    # to more, they are scaled down to it, so that with the damping's factor N/N_el
    # Coulomb's bound holds for the sum of the springs exactly
    pressure = np.maximum(w, 0.0)
    total = 1.5 * HERTZ * width * pressure.sum(axis=1)
    elastic = HERTZ * hist.delta**1.5
    damping = np.divide(hist.force, elastic, out=np.zeros_like(elastic), where=elastic > 0)
    fit = np.minimum(np.divide(elastic, total, out=np.ones_like(total), where=total > 0), 1.0)
    scale = damping * fit
    factor = scale / ratio
    limits = pressure * factor[:, None]  # |s| <= mu * limits
    stiffness = 1.5 * ratio * HERTZ * width
    # the share of each step a spring spends in contact: 1 inside, the part after the
    # crossing (w linear over the step) for a spring that comes into contact
    share = np.ones_like(w)
    share[1:] = np.where(w[:-1] > 0.0, 1.0, np.maximum(w[1:], 0.0) / (w[1:] - w[:-1]))
    share[w <= 0.0] = 0.0
    active = active_springs(limits, share)
    for a in (limits, share, active, factor):
        a.setflags(write=False)
    return Springs(hist, x, limits, stiffness, share, active, factor)


def _step_all(u0, zeta, mu, hist, limits, stiffness, share):
    """Leapfrog over the steps for rows of impacts; returns ``(u+, stuck)``."""
    dt = float(hist.t[1] - hist.t[0])
    s = np.zeros((u0.size, limits.shape[1]))
    u = u0.copy()
    stuck = np.zeros(u0.size, dtype=bool)
    cap = mu[:, None]
    last = limits.shape[0] - 1
    for i in range(1, last + 1):
        s, held = spring_update(s, dt * u[:, None] * share[i], cap * limits[i])
        stuck |= held[:, 0]
        force = -stiffness * s.sum(axis=1)
        u = u + (dt if i < last else 0.5 * dt) * zeta * force
    return u, stuck


def mdr_slip(slip, vy, zeta, mu, kappa, stiffness_ratio, springs=256, steps=2048,
             engine="auto"):  # fmt: skip
    r"""Slip of the contact point after a Hertz-Mindlin-Deresiewicz impact, vectorized.

    Parameters
    ----------
    slip : array_like
        Tangential velocity of the contact point before, ``c_t^-`` (m/s).
    vy : array_like
        Normal velocity before, ``v_n^- < 0`` (m/s).
    zeta : array_like
        The seam's ``zeta = m W_tt`` (``1 + m R^2/I``; 7/2 for a solid sphere).
    mu : array_like
        Friction coefficient ``>= 0``.
    kappa : array_like
        Newton's restitution in ``(0, 1]`` (the Hunt-Crossley damping is calibrated to it).
    stiffness_ratio : float
        Mindlin's ``r = 4 G*/E* = k_t/k_n``.
    springs, steps : int
        Springs of the reduced contact and time steps of the impact.
    engine : {"auto", "numba", "numpy"}
        The compiled steps of :mod:`spinimpact.core.mdr_kernel` (Numba: one impact per
        thread, about 0.5 ms an impact at the defaults) or NumPy's (every impact of a chunk
        at once, a few ms an impact); ``"auto"``: Numba where it is installed. The two
        agree to rounding.

    Returns
    -------
    slip_after : ndarray
        ``c_t^+`` (m/s).
    stuck : ndarray of bool
        Whether the centre of the contact stuck at some time (otherwise it slid throughout).

    Examples
    --------
    Near normal incidence the contact point leaves still moving forward (``beta < 0``),
    at a moderate angle it reverses (``beta > 0``), at a large one it slides throughout:

    >>> slip, stuck = mdr_slip([0.05, 0.5, 2.0], -1.0, 3.5, 0.3, 1.0, 0.87, springs=64, steps=512)
    >>> (-slip / [0.05, 0.5, 2.0]).round(2).tolist(), stuck.tolist()
    ([-0.27, 0.17, 0.05], [True, True, False])
    """
    given = (slip, vy, zeta, mu, kappa)
    slip, vy, zeta, mu, kappa = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in given))
    shape = slip.shape
    slip, vy, zeta, mu, kappa = (v.ravel() for v in (slip, vy, zeta, mu, kappa))
    speed = np.abs(vy)
    out = np.zeros(slip.size)
    stuck = np.zeros(slip.size, dtype=bool)
    live = (slip != 0.0) & (mu > 0.0)
    if engine not in ("auto", "numba", "numpy"):
        raise ValueError(f"engine must be 'auto', 'numba' or 'numpy', got {engine!r}")
    compiled = False
    if engine != "numpy":  # imported here: Numba is heavy, and optional
        from . import mdr_kernel

        compiled = mdr_kernel.HAVE_NUMBA
        if engine == "numba" and not compiled:
            require("numba", "engine='numba'")
    values, groups = np.unique(kappa, return_inverse=True)
    for g, value in enumerate(values):  # a loop over distinct kappa, not over impacts
        rows = np.flatnonzero(live & (groups == g))
        if rows.size == 0:
            continue
        sp = _setup(float(value), int(steps), int(springs), float(stiffness_ratio))
        hist, limits, stiffness, share = sp.hist, sp.limits, sp.stiffness, sp.share
        _check_resolution(hist, steps, stiffness_ratio, float(zeta[rows].max()))
        if compiled:
            dt = float(hist.t[1] - hist.t[0])
            u, held = mdr_kernel.step_rows(slip[rows] / speed[rows], zeta[rows], mu[rows],
                                           hist.delta, sp.factor, sp.x**2, sp.active,
                                           stiffness, dt)  # fmt: skip
            out[rows], stuck[rows] = u * speed[rows], held
            continue
        for start in range(0, rows.size, CHUNK):
            part = rows[start : start + CHUNK]
            u, held = _step_all(slip[part] / speed[part], zeta[part], mu[part], hist, limits,
                                stiffness, share)  # fmt: skip
            out[part] = u * speed[part]
            stuck[part] = held
    out = np.where(live, out, slip) + 0.0
    stuck = np.where(live, stuck, slip == 0.0)
    return out.reshape(shape), stuck.reshape(shape)


#: Steps per period of the stiffest tangential oscillation, at least (:func:`mdr_slip`).
STEPS_PER_PERIOD = 16


def _check_resolution(hist, steps, ratio, zeta):
    """``ValueError`` where the steps do not resolve the tangential oscillation: its
    period at the stiffest point is ``2 pi/sqrt(zeta r 1.5 k sqrt(delta_max))``."""
    omega = math.sqrt(zeta * ratio * 1.5 * HERTZ * math.sqrt(float(hist.delta.max())))
    need = math.ceil(STEPS_PER_PERIOD * float(hist.t[-1]) * omega / (2.0 * math.pi))
    if steps < need:
        raise ValueError(f"steps = {steps} do not resolve the tangential oscillation of "
                         f"stiffness_ratio = {ratio:g} (zeta = {zeta:g}): use steps >= "
                         f"{need}")  # fmt: skip


def mdr_trace(slip, vy, zeta, mu, kappa, stiffness_ratio, springs=256, steps=2048) -> MdrTrace:
    """One impact of :func:`mdr_slip` over time (scalars in, arrays of ``steps + 1`` out),
    with the springs' energy and the energy slip has dissipated (their sum with the
    tangential kinetic energy ``u^2/(2 zeta)`` never increases)."""
    sp = _setup(float(kappa), int(steps), int(springs), float(stiffness_ratio))
    hist, x, limits, stiffness, share = sp.hist, sp.x, sp.limits, sp.stiffness, sp.share
    _check_resolution(hist, steps, stiffness_ratio, float(zeta))
    dt = float(hist.t[1] - hist.t[0])
    n = limits.shape[0]
    s = np.zeros(springs)
    u = float(slip) / abs(float(vy))
    force, u_whole, radius, energy, lost = (np.zeros(n) for _ in range(5))
    u_whole[0] = u
    contact = np.sqrt(hist.delta)
    for i in range(1, n):
        before, step = s, dt * u * share[i]
        s, held = spring_update(before, step, mu * limits[i])
        # friction's work: the slip, (before + step) - s, times the spring force at the
        # step's middle (the leapfrog's own energy balance then closes to O(dt^2))
        lost[i] = lost[i - 1] + stiffness * float(np.sum((before + step - s) * 0.5 * (before + s)))
        force[i] = -stiffness * float(s.sum())
        inside = x < contact[i]
        radius[i] = (x[held & inside].max() / contact[i]) if (held & inside).any() else 0.0
        energy[i] = 0.5 * stiffness * float(np.sum(s * s))
        u_half = u + (dt if i < n - 1 else 0.5 * dt) * zeta * force[i]
        u_whole[i] = u_half if i == n - 1 else 0.5 * (u + u_half)
        u = u_half
    return MdrTrace(hist.t, hist.delta, hist.force, force, u_whole, radius, energy, lost)
