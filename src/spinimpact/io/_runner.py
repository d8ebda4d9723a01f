"""Running a sweep's chunks: in order, locally or on a Dask cluster, in bounded memory;
what a sweep will cost before it starts (:func:`estimate`); the reductions it folds.

:func:`estimate` runs trial chunks of the sweep itself (its first points, grown only
while they are cheap: :mod:`spinimpact._long`), timed, and weighs one of at most
:data:`TRIAL_POINTS` with :mod:`tracemalloc`; it scales them to the whole sweep: the
points, the time on this machine, the memory a chunk holds at its peak and the bytes of
the output, beside the memory available and the space free on the output's disk.
:meth:`SweepEstimate.problems` names what cannot fit.
"""

from __future__ import annotations

import dataclasses
import math
import os
import shutil
import tracemalloc
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import _long as _trials
from .. import core
from .._long import duration_text
from .._validation import require
from .._words import count
from ._fields import DEFAULT_FIELDS, TableColumns, npy_encoded_size, plan

__all__ = [
    "RESIDENT_FACTOR",
    "TRIAL_POINTS",
    "ChunkWork",
    "Discard",
    "SweepEstimate",
    "SweepResult",
    "available_memory",
    "chunks_in_order",
    "map_in_order",
    "dask_client",
    "estimate",
    "estimate_sweep",
]

#: Most points of the trial chunk an estimate weighs (memory and output), and a sixteenth of
#: the most it times (fewer if the sweep's chunks are smaller or its points slow).
TRIAL_POINTS = 16_384
#: Resident memory of a run over the bytes it allocates: the allocators keep memory freed
#: between chunks (measured 1.0 to 2.2 for 1e7-point sweeps to nothing, .npy and Parquet).
RESIDENT_FACTOR = 2


def chunks_in_order(count: int, work: Callable[[int], Any], client: Any, window: int) -> Iterator:
    """Results of ``work(k)`` for each of ``count`` chunks, in order, locally or on a Dask client
    with at most ``window`` chunks in flight (bounded memory)."""
    for _, result in map_in_order(range(count), work, client, window):
        yield result


def map_in_order(items: Iterable, work: Callable[[Any], Any], client: Any, window: int) -> Iterator:
    """``(item, work(item))`` for each of ``items``, in their order, locally (each item is
    taken from ``items`` only when its result is wanted) or on a Dask client with at most
    ``window`` items in flight (bounded memory: the batch's chunks of a file, the sweep's
    chunk numbers)."""
    if client is None:
        for item in items:
            yield item, work(item)
        return
    pending: deque[tuple[Any, Any]] = deque()
    for item in items:
        pending.append((item, client.submit(work, item, pure=False)))
        if len(pending) >= window:
            first, future = pending.popleft()
            yield first, future.result()
    while pending:
        first, future = pending.popleft()
        yield first, future.result()


def dask_client(address: str, *, timeout: float = 30) -> Any:
    """Connect to the Dask scheduler at ``address``, for ``run_sweep(..., client=...)``.

    Parameters
    ----------
    address : str
        The scheduler's address, e.g. ``"tcp://10.0.0.5:8786"``.
    timeout : float
        Seconds to wait for the connection.

    Returns
    -------
    distributed.Client

    Raises
    ------
    ImportError
        Without ``distributed``, naming the ``[dask]`` extra.
    """
    distributed = require("distributed", "sweeps on a Dask cluster")
    return distributed.Client(address, timeout=timeout)


class Discard:
    """The sink of a sweep without output: reductions only."""

    def __enter__(self) -> Discard:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def write(self, data: dict) -> None:
        pass


@dataclass
class SweepResult:
    """Reductions of a sweep, folded chunk by chunk."""

    points: int = 0  #: points evaluated
    #: points per regime, in the order of ``spinimpact.core.REGIMES``
    regime_counts: np.ndarray = field(default_factory=lambda: np.zeros(len(core.REGIMES), np.int64))
    histogram: np.ndarray | None = None  #: counts per bin, if a histogram was asked for
    bin_edges: np.ndarray | None = None  #: the histogram's ``bins + 1`` edges
    regimes: tuple[str, ...] = core.REGIMES  #: the regimes' names (a planar sweep has more)

    @property
    def regime_fractions(self) -> dict[str, float]:
        """Share of the points in each regime, by name."""
        total = max(self.points, 1)
        return {
            name: int(c) / total for name, c in zip(self.regimes, self.regime_counts, strict=True)
        }


@dataclass(frozen=True)
class ChunkWork:
    """One chunk's reductions (and columns to write): small, picklable, summable."""

    sweep: Any  #: a :class:`~spinimpact.io.sweep.Sweep`
    columns: tuple[str, ...]  #: columns to send back for writing (may be empty)
    histogram: tuple[str, float, float, int] | None

    def __call__(self, k: int) -> tuple[int, np.ndarray, np.ndarray | None, dict]:
        hist_field = (self.histogram[0],) if self.histogram else ()
        names = dict.fromkeys(("regime", *self.columns, *hist_field))
        data = self.sweep.evaluate(k, tuple(n for n in names if n not in self.sweep.inputs))
        counts = np.bincount(data["regime"], minlength=len(self.sweep.regimes))
        hist = None
        if self.histogram:
            name, lo, hi, bins = self.histogram
            values = np.asarray(data[name], np.float64)  # flags count as 0 and 1
            hist, _ = np.histogram(values, bins=int(bins), range=(lo, hi))
        return data["regime"].size, counts, hist, {c: data[c] for c in self.columns}


def size_text(n: float) -> str:
    """Bytes in words: ``"74.5 GiB"``."""
    for unit in ("bytes", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if abs(n) < 1024 or unit == "PiB":
            return f"{n:.0f} {unit}" if unit == "bytes" else f"{n:.3g} {unit}"
        n /= 1024
    raise AssertionError  # pragma: no cover


def available_memory() -> int | None:
    """Bytes this process may still allocate, or ``None`` where it cannot be told.

    The least of the memory the system has available (``MemAvailable``), the room left
    under the process's cgroup limit and the room left under its address-space limit
    (``ulimit -v``).
    """
    room = []
    try:
        with open("/proc/meminfo") as f:
            room += [int(line.split()[1]) * 1024 for line in f if line.startswith("MemAvailable:")]
    except (OSError, ValueError, IndexError):
        pass
    try:
        limit = Path("/sys/fs/cgroup/memory.max").read_text().strip()
        if limit != "max":
            room.append(int(limit) - int(Path("/sys/fs/cgroup/memory.current").read_text()))
    except (OSError, ValueError):
        pass
    try:
        import resource

        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        if soft != resource.RLIM_INFINITY:
            with open("/proc/self/status") as f:
                size = [int(line.split()[1]) * 1024 for line in f if line.startswith("VmSize:")]
            room.append(soft - (size[0] if size else 0))
    except (ImportError, OSError, ValueError):
        pass
    return max(0, min(room)) if room else None


def free_disk(path: str | os.PathLike[str]) -> int | None:
    """Bytes free on the disk that holds ``path``'s directory, or ``None``."""
    try:
        return shutil.disk_usage(Path(path).absolute().parent).free
    except OSError:
        return None


@dataclass(frozen=True)
class SweepEstimate:
    """What a sweep will cost, from a trial chunk (:func:`estimate`)."""

    points: int  #: points of the sweep
    chunks: int  #: chunks it runs in
    chunk_points: int  #: points of its largest chunk
    seconds: float  #: time on this machine (computing and encoding), scaled from the trial
    #: resident bytes a chunk needs: :data:`RESIDENT_FACTOR` times what it allocates at its
    #: peak (scaled from the trial)
    chunk_memory: int
    output_bytes: int  #: bytes of the output (0 without one)
    available_memory: int | None  #: :func:`available_memory`, when estimated
    free_disk: int | None  #: bytes free where the output goes, ``None`` without one
    trial_points: tuple[int, ...] = ()  #: points of each trial timed (the sweep's first)
    weighed_points: int = 0  #: points of the trial weighed (memory and output)

    @property
    def measured_points(self) -> int:
        """The most points of a trial: the estimate is measured on the sweep's first so many."""
        return max(self.trial_points, default=self.weighed_points)

    def problems(self, max_seconds: float | None = None) -> list[str]:
        """What cannot fit: the memory of a chunk, the output on its disk, and (if given)
        a time above ``max_seconds``; each a phrase, empty if the sweep fits."""
        out = []
        if self.available_memory is not None and self.chunk_memory > self.available_memory:
            out.append(
                f"a chunk of {count(self.chunk_points, 'point')} needs about "
                f"{size_text(self.chunk_memory)} of memory and {size_text(self.available_memory)}"
                " is available: use a smaller chunk size"
            )
        if self.free_disk is not None and self.output_bytes > self.free_disk:
            out.append(
                f"the output needs about {size_text(self.output_bytes)} and "
                f"{size_text(self.free_disk)} is free on its disk"
            )
        if max_seconds is not None and self.seconds > max_seconds:  # False for NaN
            out.append(
                f"{count(self.points, 'point')} would take about {duration_text(self.seconds)}"
            )
        return out

    def __str__(self) -> str:
        output = f", {size_text(self.output_bytes)} of output" if self.output_bytes else ""
        took = "" if math.isnan(self.seconds) else f"about {duration_text(self.seconds)} here, "
        measured = self.measured_points
        on = f" (measured on the sweep's first {count(measured, 'point')})" if measured else ""
        return (
            f"{count(self.points, 'point')} in {count(self.chunks, 'chunk')}: "
            f"{took}{size_text(self.chunk_memory)} of memory a chunk{output}{on}"
        )


def _trial(sweep: Any, m: int, work: tuple, encode: Callable | None) -> Callable:
    """A run of the first ``m`` points of ``sweep``, as a chunk of the sweep runs:
    ``run() -> (bytes of output, memory outside Python's allocator)``."""
    chunk = ChunkWork(dataclasses.replace(sweep, chunk_size=m), *work)

    def run() -> tuple[int, int]:
        data = chunk(0)[3]
        return encode(data) if encode is not None else (0, 0)

    return run


def estimate(
    sweep: Any,
    columns: tuple[str, ...] = (),
    histogram: tuple[str, float, float, int] | None = None,
    output: Any = None,
    encode: Callable[[dict], tuple[int, int]] | None = None,
    timed: bool = True,
) -> SweepEstimate:
    """Time and weigh trial chunks of ``sweep`` and scale them to the whole sweep.

    The trials are the sweep's first points, from 64 up to 16 times :data:`TRIAL_POINTS`
    (no more than a chunk), growing while they are cheap: the trials take a tenth of
    the sweep's own time, between 0.05 and 2 s (:mod:`spinimpact._long`), so a
    sweep of slow points is measured on fewer. A chunk's time is taken as ``a + b *
    points`` (a cost per chunk, such as starting threads, and a cost per point that
    grows once the arrays leave the caches), fitted to the two largest trials (or
    proportional to the one); its memory as proportional to its points, from the largest
    trial of at most :data:`TRIAL_POINTS` run again under :mod:`tracemalloc` (and
    pyarrow's own allocator), times :data:`RESIDENT_FACTOR`. A small trial runs first,
    so compiling is not counted.

    Parameters
    ----------
    sweep : Sweep
        The sweep; the trials are its first points.
    columns, histogram
        What each chunk computes and sends back, as in :class:`ChunkWork`.
    output : path, optional
        Where the output goes (for the free disk space).
    encode : callable, optional
        ``encode(data) -> (bytes, memory)``: a trial chunk's columns encoded as the output
        would be, in memory (their size and time are measured), and the memory it took
        outside Python's allocator (pyarrow's buffers).
    timed : bool
        Whether to time the sweep (``seconds`` is NaN otherwise; the trials then grow
        to :data:`TRIAL_POINTS` at most, each run once).
    """
    chunk_points = min(sweep.chunk_size, sweep.size)
    work = (columns, histogram)

    def trial(m: int) -> Callable:
        return _trial(sweep, m, work, encode)

    trial(min(chunk_points, _trials.FIRST))()  # compiles what compiles on first use
    top = 16 * TRIAL_POINTS if timed else TRIAL_POINTS
    sizes = _trials.ladder(chunk_points, top)
    trials = _trials.grow(trial, sizes, 2 if timed else 1, TRIAL_POINTS, sweep.size)
    weighed = max(m for m in trials.points if m <= TRIAL_POINTS)
    tracing = tracemalloc.is_tracing()
    if not tracing:
        tracemalloc.start()
    tracemalloc.reset_peak()
    base = tracemalloc.get_traced_memory()[0]
    encoded, outside = trial(weighed)()
    peak = tracemalloc.get_traced_memory()[1] - base + outside
    if not tracing:
        tracemalloc.stop()
    seconds = math.nan
    if timed:
        per_chunk, per_point = _trials.fit_line(trials.points, trials.seconds)
        seconds = sweep.chunks * per_chunk + sweep.size * per_point
    return SweepEstimate(
        points=sweep.size,
        chunks=sweep.chunks,
        chunk_points=chunk_points,
        seconds=seconds,
        chunk_memory=math.ceil(RESIDENT_FACTOR * peak / weighed * chunk_points),
        output_bytes=math.ceil(encoded / weighed * sweep.size) if output is not None else 0,
        available_memory=available_memory(),
        free_disk=free_disk(output) if output is not None else None,
        trial_points=trials.points if timed else (),
        weighed_points=weighed,
    )


def estimate_sweep(
    sweep: Any,
    *,
    histogram: tuple[str, float, float, int] | None = None,
    output: str | os.PathLike[str] | None = None,
    fields: tuple[str, ...] = DEFAULT_FIELDS,
    timed: bool = True,
) -> SweepEstimate:
    """What :func:`~spinimpact.io.sweep.run_sweep` with these arguments will cost (a trial chunk).

    The sweep's first points (trial chunks of 64 up to 262,144 points, grown while they
    take at most a tenth of the sweep's time and 2 s: :func:`estimate`) are computed, and
    encoded as the output would be, timed (unless ``timed`` is false) and weighed
    (:mod:`tracemalloc`); the figures are scaled to the sweep. Nothing is written.

    Returns
    -------
    SweepEstimate
        Points, chunks, time on this machine, memory a chunk holds at its peak, bytes
        of the output; the memory available and the space free on the output's disk;
        ``problems()`` names what cannot fit.

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.io.sweep import Sweep, parse_axis
    >>> axes = {n: parse_axis(n, v) for n, v in
    ...         dict(vx="-5:5:1001", vy="-1", omega="-50:50:1001", mu="0.3", kappa="0.8").items()}
    >>> cost = estimate_sweep(Sweep(Body.solid_sphere(mass=1.0, radius=0.1), axes), output="d")
    >>> cost.points, cost.output_bytes, cost.problems()  # 8 float64 columns and int8 regime
    (1002001, 65130065, [])
    """
    kind, columns = plan(sweep, fields, histogram, output)
    encode: Callable | None = None
    if kind in ("parquet", "csv"):
        meta, regimes = sweep.metadata(), sweep.regimes

        def encode(data: dict) -> tuple[int, int]:
            return TableColumns.encoded_size(data, kind, meta, regimes)

    elif kind == "npy":
        dtypes = {c: sweep.column_dtype(c) for c in columns}

        def encode(data: dict) -> tuple[int, int]:
            return npy_encoded_size(data, dtypes), 0

    return estimate(sweep, columns, histogram, output, encode, timed)
