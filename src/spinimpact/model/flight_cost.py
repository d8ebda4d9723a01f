"""What a flight will cost before it runs, and its refusal when it would run for hours.

A flight's time grows as its step shrinks (a step of ``1e-7`` s flies a serve for about two
hours). :func:`fly_chunks` runs a flight's chunks of balls under the rule of
:mod:`spinimpact._long`: it first times a few steps of the run itself (the first chunk's
first 16 and :data:`PROBE_STEPS` steps, their difference the cost of a step) and bounds the
whole run by them (no ball flies longer than
``t_stop``). Only when that bound exceeds :data:`~spinimpact._long.ANNOUNCE_SECONDS` is the
flight estimated: its first chunk is flown with the coarsest step the air allows (a power of
:data:`~spinimpact._long.GROWTH` times the step asked for), which counts the steps its arcs
take and times what the flight costs besides them (the bounces, the roll); the steps, scaled
to the step asked for, cost what the probe measured each, and the chunks cost alike.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .. import _long

__all__ = ["PROBE_STEPS", "fly_chunks"]

#: Steps of the run's first chunk timed to bound the whole run's time.
PROBE_STEPS = 256


def fly_chunks(
    fly: Callable[[slice, float], Any],
    probe: Callable[[slice, float, int], Any],
    n: int,
    chunk: int,
    dt: float,
    limit: float,
    bound_steps: float,
    *,
    what: str,
    force: bool = False,
    announce: Callable[[_long.Estimate], None] | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> list:
    """The parts ``fly(slice, dt)`` of each chunk of ``n`` balls, in order, after the
    estimate (module docstring).

    Parameters
    ----------
    fly : callable
        ``fly(balls, step)``: one chunk of balls (a slice) flown with ``step``.
    probe : callable
        ``probe(balls, step, k)``: the first ``k`` steps of those balls' first arc.
    n, chunk : int
        Balls, and balls a chunk.
    dt : float
        The step asked for, s.
    limit : float
        The largest step the air allows, s (``inf`` without air: nothing to estimate).
    bound_steps : float
        The most steps a ball may take (``t_stop / dt`` and one an arc).
    what : str
        The run in words, for the estimate.
    force : bool
        Run even a flight estimated over :data:`~spinimpact._long.REFUSE_SECONDS`.
    announce, progress : callable, optional
        ``announce(estimate)`` before the run when it is estimated to take more than
        :data:`~spinimpact._long.ANNOUNCE_SECONDS`; ``progress(done, n)`` after each chunk.

    Raises
    ------
    spinimpact._long.TooLong
        A ``ValueError`` naming the estimate, unless ``force``.
    """
    chunks = math.ceil(n / chunk)
    first = slice(0, min(n, chunk))
    parts = []
    if math.isfinite(limit) and limit > 0:
        probe(first, dt, 1)  # the first call's costs are not the steps'
        took = []
        for k in (PROBE_STEPS // _long.GROWTH**2, PROBE_STEPS):
            start = _long.clock()
            probe(first, dt, k)
            took.append(_long.clock() - start)
        per_step = _long.fit_line((PROBE_STEPS // _long.GROWTH**2, PROBE_STEPS), tuple(took))[1]
        if 2.0 * chunks * bound_steps * per_step > _long.ANNOUNCE_SECONDS:
            cost = _estimate(fly, first, dt, limit, chunks, per_step, what)
            cost.check(force)
            if announce is not None and cost.announced:
                announce(cost)
    for k in range(len(parts), chunks):
        sl = slice(k * chunk, min(n, (k + 1) * chunk))
        parts.append(fly(sl, dt))
        if progress is not None:
            progress(sl.stop, n)
    return parts


def _estimate(
    fly: Callable[[slice, float], Any], first: slice, dt: float, limit: float, chunks: int,
    per_step: float, what: str,
) -> _long.Estimate:  # fmt: skip
    """The flight's time: its first chunk flown with the coarsest step within ``limit`` (a
    power of :data:`~spinimpact._long.GROWTH` times ``dt``) counts the steps of its arcs
    and the cost outside them; the steps, scaled to ``dt``, cost ``per_step`` each."""
    coarse = dt * _long.GROWTH ** max(int(math.floor(math.log(limit / dt, _long.GROWTH))), 0)
    start = _long.clock()
    run = fly(first, coarse)[0]
    took = _long.clock() - start
    steps = _arc_steps(run.bounce_time, coarse)
    per_flight = max(took - steps * per_step, 0.0)
    seconds = chunks * (per_flight + steps * coarse / dt * per_step)
    measured = (
        f"its first {PROBE_STEPS} steps and a flight of its first chunk with steps of "
        f"{coarse:.3g} s"
    )
    return _long.Estimate(what, seconds, measured)


def _arc_steps(bounce_time: np.ndarray, step: float) -> float:
    """Steps the arcs of a chunk take together: each arc advances all its balls until the
    last lands (the longest arc of each number), one step at least."""
    t = np.where(np.isnan(bounce_time), 0.0, bounce_time)
    arcs = np.diff(t, axis=1, prepend=0.0).clip(min=0.0)
    return float(np.sum(np.ceil(arcs.max(axis=0, initial=0.0) / step) + 1))
