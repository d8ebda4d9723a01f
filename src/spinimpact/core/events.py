r"""Integration with events found inside the integrator's steps, not only at their ends.

SciPy's ``solve_ivp`` looks for an event where the event function has opposite signs
at the two ends of a step, so a function that dips through zero and back within one
step is never seen: a short slip phase of a stuck contact (the spring force touching
Coulomb's cap for a moment), a short stick phase of a slipping one.
:func:`integrate_events` steps SciPy's DOP853 itself and watches each event function
on the step's dense output (the integrator's own interpolant, of the integrator's
order):

* at ``watch`` evenly spaced points of each step (the step itself bounded by
  ``max_step``, which the caller sets to a fraction of the shortest oscillation
  period, so that the points resolve every extremum), it looks for a change of sign,
  as ``solve_ivp`` does between step ends (an event that crosses zero once, without
  dips, may be looked at at the step ends only: ``Event.watched``);
* where three consecutive points bracket a minimum of the function that stays
  positive at the points (a maximum for a rising event), the parabola through them
  predicts the minimum's value; when that lies at least a quarter of the way from the
  lowest point down to zero (a dip that could reach zero), the minimum is searched for
  on the interpolant (bounded Brent, stopping at the first value at or below zero),
  and if zero is reached, the crossing before it is the event;
* each crossing is polished by Brent's method on the interpolant to ``4 eps``, as
  ``solve_ivp`` polishes its own;
* where the right-hand side changes form at a terminal event (a contact force that
  ends at separation: ``Event.integrate_to``), the step that holds it is integrated
  anew from its start up to the event and the run's final state is that
  integration's, since the interpolant of a step across such a change is less
  accurate than the integrator. Elsewhere the state at an event is the interpolant's,
  the same on which the root was found (so that, for example, a slip found to stop
  has stopped in the returned state to the root's precision).

A dip is missed only where the parabola misjudges its minimum by more than three
quarters of its height, which steps that resolve the oscillations rule out for smooth
functions; a dip that reaches below zero by less than the interpolant's error is
below the integrator's precision either way.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable, Sequence
from typing import NamedTuple

import numpy as np

__all__ = ["Event", "EventRun", "integrate_events"]

_EPS = float(np.finfo(float).eps)


class Event(NamedTuple):
    """An event function ``g(t, y)`` whose zero crossing in ``direction`` (``-1``:
    falling, ``+1``: rising) is an event; ``terminal`` ones end the integration.
    ``watched=False``: evaluated at the ends of the steps only, as ``solve_ivp`` does
    (for a function known to cross zero once, without dips). ``integrate_to``: the
    right-hand side changes form where this event ends the run (a force that stops at
    separation), so the state there is integrated up to the event, not interpolated."""

    function: Callable[[float, np.ndarray], float]
    direction: int
    terminal: bool = True
    watched: bool = True
    integrate_to: bool = False


class EventRun(NamedTuple):
    """The result of :func:`integrate_events`."""

    t: float  #: end time: the first terminal event, or ``t_bound``
    y: np.ndarray  #: state at ``t``
    sol: Callable | None  #: dense solution on ``[t0, t]`` (``None`` when ``t == t0``)
    t_events: list[np.ndarray]  #: per event, the times of its crossings up to ``t``
    y_events: list[np.ndarray]  #: per event, the states at those times
    status: int  #: 1 a terminal event, 0 ``t_bound`` reached, -1 the integrator failed
    message: str


class _Below(Exception):
    """Raised by the minimum search at the first point at or below zero."""

    def __init__(self, t: float) -> None:
        self.t = t


def _vertex(ta, ha, tb, hb, tc, hc):
    """Lowest value of the parabola through three points (times relative to ``ta``)."""
    xb, xc = tb - ta, tc - ta
    f01, f12 = (hb - ha) / xb, (hc - hb) / (xc - xb)
    curvature = (f12 - f01) / xc
    if curvature <= 0:
        return hb
    slope = f01 + curvature * xb
    return hb - slope * slope / (4.0 * curvature)


def _crossing(h, hist, s, value):
    """The first zero of ``h`` (falling) between the last samples ``hist`` and the new
    sample ``(s, value)``, or ``None``."""
    ta, ha = hist[-1]
    if ha >= 0.0 >= value:
        from scipy.optimize import brentq

        def fixed(t, a=ta, va=ha):  # the samples' own values at the bracket's ends
            return va if t == a else (value if t == s else h(t))

        return brentq(fixed, ta, s, xtol=4 * _EPS, rtol=4 * _EPS)
    if len(hist) < 2:
        return None
    (t0, h0), (t1, h1) = hist
    if not (h0 > h1 < value and h1 > 0.0) or _vertex(t0, h0, t1, h1, s, value) > 0.75 * h1:
        return None
    from scipy.optimize import brentq, minimize_scalar

    def probe(t):
        v = h(t)
        if v <= 0.0:
            raise _Below(t)
        return v

    try:
        minimize_scalar(probe, bounds=(t0, s), method="bounded",
                        options={"xatol": 1e-9 * (s - t0)})  # fmt: skip
    except _Below as below:
        return brentq(lambda t: h0 if t == t0 else h(t), t0, below.t, xtol=4 * _EPS,
                      rtol=4 * _EPS)  # fmt: skip
    return None


def _up_to(fun, t0, y0, t1, rtol, atol, max_step):
    """Integrate from ``t0`` to exactly ``t1``: the step ends, their interpolants and
    ``y(t1)``. The right-hand side may change its form at an event (a force that ends at
    separation); an interpolant of a step across it is less accurate than the steps."""
    from scipy.integrate import DOP853

    solver = DOP853(fun, t0, y0, t1, rtol=rtol, atol=atol, max_step=max_step)
    times, dense = [], []
    while solver.status == "running":
        solver.step()
        times.append(solver.t)
        dense.append(solver.dense_output())
    if solver.status == "failed":
        raise RuntimeError(f"integration to the event at t = {t1!r} failed")
    return times, dense, solver.y.copy()


def integrate_events(
    fun: Callable, t0: float, y0: np.ndarray, t_bound: float, events: Sequence[Event], *,
    rtol: float, atol, max_step: float = math.inf, watch: int = 4,
) -> EventRun:  # fmt: skip
    """Integrate ``dy/dt = fun(t, y)`` with DOP853 from ``t0`` towards ``t_bound``,
    finding every event crossing inside the steps (module docstring).

    Parameters
    ----------
    fun : callable
        ``fun(t, y)``, the right-hand side.
    t0, y0, t_bound : float, ndarray, float
        Start, initial state (s, state units), end.
    events : sequence of Event
        Event functions with their directions (``+-1``) and whether they end the run.
    rtol, atol, max_step
        Passed to the integrator; ``max_step`` in s.
    watch : int
        Points of each step at which the event functions are evaluated.

    Returns
    -------
    EventRun

    Examples
    --------
    An event function that dips below zero between 0.29 s and 0.31 s, inside one step
    (``solve_ivp`` sees it positive at both ends of its steps and misses it):

    >>> import numpy as np
    >>> dip = Event(lambda t, y: (t - 0.3) ** 2 - 1e-4, -1)
    >>> run = integrate_events(lambda t, y: [0.0], 0.0, np.array([1.0]), 1.0, [dip],
    ...                        rtol=1e-10, atol=1e-12, max_step=1.0)
    >>> round(run.t, 12), run.status
    (0.29, 1)
    """
    from scipy.integrate import DOP853, OdeSolution

    for ev in events:
        if ev.direction not in (-1, 1):
            raise ValueError(f"event direction must be -1 or 1, got {ev.direction!r}")
    solver = DOP853(fun, t0, np.asarray(y0, dtype=float), t_bound, rtol=rtol, atol=atol,
                    max_step=max_step)  # fmt: skip
    ts, interps, states = [t0], [], [solver.y.copy()]

    def y_at(t):
        i = min(max(bisect.bisect_right(ts, t) - 1, 0), len(interps) - 1)
        return interps[i](t)

    def falling(ev):  # the event as a function that falls through zero, of t
        sign = -float(ev.direction)
        return lambda t: sign * ev.function(t, y_at(t))

    hs = [falling(ev) for ev in events]
    hists = [[(t0, -float(ev.direction) * ev.function(t0, solver.y))] for ev in events]
    found: list[list[float]] = [[] for _ in events]
    fractions = np.arange(1, watch + 1) / watch
    status, message = None, ""
    while status is None:
        message = solver.step() or ""
        if solver.status == "failed":
            return EventRun(solver.t, solver.y, None, [], [], -1, message)
        t_old, t_new = solver.t_old, solver.t
        interps.append(solver.dense_output())
        ts.append(t_new)
        states.append(solver.y.copy())
        times = t_old + (t_new - t_old) * fractions
        times[-1] = t_new
        samples = interps[-1](times).T
        stop, stopper = math.inf, None
        for i, ev in enumerate(events):
            sign, hist = -float(ev.direction), hists[i]
            points = zip(times, samples, strict=True) if ev.watched else [(t_new, samples[-1])]
            for s, y in points:
                value = sign * ev.function(s, y)
                root = _crossing(hs[i], hist, s, value)
                hist[:] = [*hist[-1:], (s, value)]
                if root is not None:
                    found[i].append(root)
                    if ev.terminal:
                        stop, stopper = min((stop, stopper), (root, ev), key=lambda x: x[0])
                        break
        if stop < math.inf:
            status, message = 1, "A termination event occurred."
        elif solver.status == "finished":
            status, stop = 0, t_new
    n = bisect.bisect_left(ts, stop)  # ts[n - 1] < stop <= ts[n]
    if status == 1 and n > 0 and stopper.integrate_to:  # its step integrated anew up to it
        times, dense, y_end = _up_to(fun, ts[n - 1], states[n - 1], stop, rtol, atol, max_step)
        ts, interps = [*ts[:n], *times], [*interps[: n - 1], *dense]
    else:
        ts, interps = [*ts[:n], stop], interps[: max(n, 1)]
        y_end = y_at(stop) if status == 1 else solver.y.copy()
    t_events = [np.array([t for t in f if t <= stop]) for f in found]
    y_events = [np.array([y_at(t) for t in te]).reshape(te.size, len(y_end)) for te in t_events]
    sol = OdeSolution(ts, interps) if stop > t0 else None
    return EventRun(stop, np.asarray(y_end, dtype=float), sol, t_events, y_events, status,
                    message)  # fmt: skip
