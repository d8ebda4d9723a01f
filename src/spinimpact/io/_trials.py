"""The trial chunks a sweep's estimate is measured on, grown only while they are cheap.

The trials are the sweep's first points, run as a chunk of the sweep runs
(:func:`~spinimpact.io.sweep.estimate_sweep`). They start at :data:`FIRST` points and
grow :data:`GROWTH` times at each step, up to the largest size asked for (a chunk at
most), while the trials so far and the next one fit in a time budget. The next trial's
time is predicted from the last one's time per point (an overestimate: a small trial's
cost per call weighs more on each point). The budget is a :data:`SHARE` of the time the
whole sweep would take at the first trial's cost per point, at least
:data:`MIN_SECONDS` and at most :data:`MAX_SECONDS`: a sweep of fast points (the rigid
law, well under a microsecond a point) is measured on its first 262,144 points, one of
slow points (a law that steps each impact in time, a millisecond a point) on about a
thousand, and a small sweep in about a tenth of its own time.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["FIRST", "GROWTH", "MAX_SECONDS", "MIN_SECONDS", "SHARE", "Trials", "grow", "ladder"]

#: Points of the first trial (fewer if the sweep's chunks are smaller).
FIRST = 64
#: Each trial has this many times the points of the one before.
GROWTH = 4
#: The trials' time budget, seconds: a share of the sweep's predicted time, within bounds.
SHARE = 0.1
MIN_SECONDS = 0.05
MAX_SECONDS = 2.0

#: The clock the trials are timed with (a test may replace it).
clock: Callable[[], float] = time.perf_counter


@dataclass(frozen=True)
class Trials:
    """The trials that ran: their points and the shortest of each one's runs."""

    points: tuple[int, ...]  #: points of each trial, in the order they ran (growing)
    seconds: tuple[float, ...]  #: the shortest of each trial's runs, seconds
    spent: float  #: seconds all their runs took together


def ladder(chunk_points: int, top: int) -> list[int]:
    """The trial sizes: :data:`FIRST` points, :data:`GROWTH` times more at each step,
    up to ``top`` points (each at most ``chunk_points``), growing."""
    top = min(chunk_points, top)
    sizes, m = [], min(chunk_points, FIRST)
    while m < top:
        sizes.append(m)
        m *= GROWTH
    return [*sizes, top]


def _seconds(run: Callable[[], object], runs: int) -> tuple[float, float]:
    """The shortest of ``runs`` timings of ``run()`` (the least disturbed by other work),
    and their sum."""
    best, total = math.inf, 0.0
    for _ in range(runs):
        start = clock()
        run()
        took = clock() - start
        best, total = min(best, took), total + took
    return best, total


def grow(
    trial: Callable[[int], Callable[[], object]],
    sizes: list[int],
    runs: int,
    weighed_up_to: int,
    sweep_points: int,
) -> Trials:
    """Run ``trial(m)()`` ``runs`` times for each size ``m`` of ``sizes`` in turn while
    the trials fit in the budget (see the module's text); the first always runs.

    A trial of at most ``weighed_up_to`` points may be run once more afterwards (to weigh
    it), so its predicted cost counts ``runs + 1`` runs. ``sweep_points`` sets the budget.
    """
    points: list[int] = []
    seconds: list[float] = []
    spent = 0.0
    budget = MAX_SECONDS
    for m in sizes:
        if points:
            predicted = seconds[-1] / points[-1] * m * (runs + (m <= weighed_up_to))
            if spent + predicted > budget:
                break
        best, took = _seconds(trial(m), runs)
        if not points:  # the sweep's time at the first trial's cost per point
            budget = min(MAX_SECONDS, max(MIN_SECONDS, SHARE * best / m * sweep_points))
        points.append(m)
        seconds.append(best)
        spent += took
    return Trials(tuple(points), tuple(seconds), spent)
