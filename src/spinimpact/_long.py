"""Long runs: one rule for every command and function that may run for minutes.

**The rule.** A long run (a batch, a sweep, a flight with a fine step, ...) first measures
itself on trials (its own first part, grown only while cheap, below) and scales them to the
whole run (:class:`Estimate`). A run estimated to take more than :data:`ANNOUNCE_SECONDS`
says so before it starts (the command line prints the estimate on stderr); one estimated to
take more than :data:`REFUSE_SECONDS` is refused (:class:`TooLong`, a ``ValueError`` naming
the estimate) unless forced: ``force=True`` in Python, ``--force`` on the command line. On a
terminal, a long command shows a progress bar.

**The trials** are the run's first points (or balls, or rows), run as the run itself would.
They start at :data:`FIRST` points and grow :data:`GROWTH` times at each step, up to the
largest size asked for (a chunk at most), while the trials so far and the next one fit in a
time budget. The next trial's time is predicted from the last one's time per point (an
overestimate: a small trial's cost per call weighs more on each point). The budget is a
:data:`SHARE` of the time the whole run would take as the trials so far predict it
(:func:`fit_line`: after one trial, at its cost per point; from the second on, a cost per
call apart from a cost per point, so that a first trial dominated by its cost per call does
not swell the budget), at least :data:`MIN_SECONDS` and at most :data:`MAX_SECONDS`: a run
of slow points (a law that steps each impact in time, a millisecond a point) is measured on
about a thousand, and a run of fast points in about a tenth of its own time.

This module imports nothing of the package, so every layer may use it.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

__all__ = [
    "ANNOUNCE_SECONDS",
    "FIRST",
    "GROWTH",
    "MAX_SECONDS",
    "MIN_SECONDS",
    "REFUSE_SECONDS",
    "SHARE",
    "Estimate",
    "TooLong",
    "Trials",
    "duration_text",
    "fit_line",
    "grow",
    "ladder",
]

#: A run estimated to take longer than this, seconds, says its estimate before it starts.
ANNOUNCE_SECONDS = 60.0
#: A run estimated to take longer than this, seconds, is refused unless forced.
REFUSE_SECONDS = 3600.0

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
        points.append(m)
        seconds.append(best)
        spent += took
        per_run, per_point = fit_line(tuple(points), tuple(seconds))  # the run, as now known
        budget = min(MAX_SECONDS, max(MIN_SECONDS, SHARE * (per_run + per_point * sweep_points)))
    return Trials(tuple(points), tuple(seconds), spent)


def fit_line(points: tuple[int, ...], seconds: tuple[float, ...]) -> tuple[float, float]:
    """``(per_run, per_point)``: a run's time as ``per_run + per_point * points``, fitted to
    the two largest trials (a cost per run, such as starting threads, and a cost per point),
    or proportional to the points with one trial (or when the larger was not slower)."""
    per_point = seconds[-1] / points[-1]
    if len(points) >= 2 and seconds[-1] > seconds[-2] and points[-1] > points[-2]:
        per_point = (seconds[-1] - seconds[-2]) / (points[-1] - points[-2])
    return max(seconds[-1] - per_point * points[-1], 0.0), per_point


def duration_text(seconds: float) -> str:
    """Seconds in words: ``"1.4 h"``, ``"3.2 days"``."""
    for unit, length in (("days", 86400), ("h", 3600), ("min", 60)):
        if seconds >= length:
            return f"{seconds / length:.2g} {unit}"
    return f"{seconds:.2g} s"


@dataclass(frozen=True)
class Estimate:
    """How long a run will take on this machine, measured on its own first part."""

    what: str  #: the run, in words: ``"this flight (1 ball, dt = 1e-07 s)"``
    seconds: float  #: the time it will take here, s (NaN: not known)
    measured: str  #: what the estimate was measured on: ``"its first 256 rows"``

    @property
    def announced(self) -> bool:
        """Whether the run should say its estimate first (over :data:`ANNOUNCE_SECONDS`)."""
        return self.seconds > ANNOUNCE_SECONDS  # False for NaN

    @property
    def too_long(self) -> bool:
        """Whether the run is refused unless forced (over :data:`REFUSE_SECONDS`)."""
        return self.seconds > REFUSE_SECONDS  # False for NaN

    def __str__(self) -> str:
        took = "an unknown time" if math.isnan(self.seconds) else duration_text(self.seconds)
        return f"{self.what} will take about {took} here (measured on {self.measured})"

    def refusal(self, force: str) -> str:
        """The one-line refusal, naming how to force the run (``force``: ``"--force"``)."""
        return (
            f"{self.what} would take about {duration_text(self.seconds)} here, over the limit "
            f"of {duration_text(REFUSE_SECONDS)} (measured on {self.measured}); {force} runs "
            "it anyway"
        )

    def check(self, force: bool, name: str = "force=True") -> None:
        """Raise :class:`TooLong` if the run is too long and not forced."""
        if self.too_long and not force:
            raise TooLong(self, name)


class TooLong(ValueError):
    """A run estimated to take more than :data:`REFUSE_SECONDS`, not forced.

    :attr:`estimate` is its :class:`Estimate`; the message names it and the way to force
    the run (``force=True``); the command line says ``--force`` instead.
    """

    def __init__(self, estimate: Estimate, force: str = "force=True") -> None:
        self.estimate = estimate
        super().__init__(estimate.refusal(force))
