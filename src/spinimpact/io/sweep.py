"""Sweeps over incidence conditions that need not fit in memory.

A :class:`Sweep` is a grid (the Cartesian product of evenly spaced axes) or a
set of random samples over any of ``vx, vy, omega, mu, kappa`` for one body.
It is evaluated chunk by chunk, so memory stays bounded by the chunk size
whatever the number of points, either streaming the fields to Parquet or
``.npy`` files or folding them into reductions (regime fractions, histograms)
on the fly. Given a Dask client, the same chunks run on a Dask cluster and give
the same numbers.

The fields (:data:`FIELDS`) are named as the columns of
:class:`~spinimpact.Impact` and hold the same numbers (computed by the same
core kernels, without building the whole result); ``regime`` is stored as its
integer code, ``spinimpact.core.REGIMES[code]`` being the Impact's text. Older
names stay accepted (:data:`ALIASES`).

Random samples depend on the seed alone: each uniform input draws from its own
stream (:class:`numpy.random.PCG64` seeded with ``[seed, index of the input in
INPUTS]``), point ``i`` taking the stream's ``i``-th number, so the points are the
same whatever the chunk size or the Dask cluster, and the first ``n`` points of a
longer sweep are those of a sweep of ``n``.

A planar body or a pendulum is swept by
:class:`~spinimpact.io.planar_sweep.PlanarSweep`, a :class:`Sweep` with its own
inputs, fields and regimes (:attr:`Sweep.inputs`, :meth:`Sweep.field_name`,
:attr:`Sweep.regimes`), run by the same :func:`run_sweep`. A Parquet output names
the regimes its codes stand for and the body in its metadata, and each column's unit.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import core
from .._validation import validated, whole
from ..model.body import Body
from ._axes import INPUTS, Axis, parse_axis
from ._fields import ALIASES, FIELDS, REBOUND_FIELDS, field_name, rebound_fields
from ._runner import Discard, chunks_in_order, dask_client
from ._sinks import npy_columns, parquet_columns

__all__ = [
    "ALIASES",
    "FIELDS",
    "INPUTS",
    "Axis",
    "Sweep",
    "SweepResult",
    "dask_client",
    "field_name",
    "parse_axis",
    "run_sweep",
]


def _positive_int(name: str, value: Any, extra: str = "") -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer):
        raise TypeError(f"{name} must be a positive integer{extra}, got {value!r}")
    if value < 1:
        raise ValueError(f"{name} must be a positive integer{extra}, got {value!r}")
    return int(value)


def _uniform(seed: int, name: str, start: int, n: int, lo: float, hi: float) -> np.ndarray:
    """Points ``start`` to ``start + n`` of input ``name``'s random stream, uniform on
    ``[lo, hi)``: the stream is advanced to ``start`` (each value takes one 64-bit draw),
    so the numbers do not depend on how the points are cut into chunks."""
    bits = np.random.PCG64(np.random.SeedSequence([seed, INPUTS.index(name)]))
    bits.advance(start)
    return np.random.Generator(bits).uniform(lo, hi, n)


@dataclass(frozen=True)
class Sweep:
    """A sweep over the inputs of one body (see the module docstring).

    Parameters
    ----------
    body : Body
        A single body (scalar mass in kg, radius and gyration in m).
    axes : dict
        ``name -> Axis`` for each of ``vx, vy`` (m/s), ``omega`` (rad/s), ``mu,
        kappa`` (all required), each :class:`Axis` built under the name it is given as.
    samples : int, optional
        Number of random points; required when any axis is ``uniform``, which
        excludes ``grid`` axes.
    seed : int
        Seed of the random points.
    chunk_size : int
        Points evaluated at a time; memory is bounded by it.

    Raises
    ------
    TypeError
        For a ``body`` that is not a :class:`~spinimpact.Body`, an axis that is not an
        :class:`Axis`, or a ``samples`` or ``chunk_size`` that is not an integer
        (``True`` included).
    ValueError
        For an array of bodies, a missing or unknown axis, an axis given under another
        input's name, grid and random axes mixed, a missing or non-positive
        ``samples``, or an axis whose values break the input rules (``vy < 0``,
        ``mu >= 0``, ``kappa`` in ``[0, 1]``, ...).
    """

    body: Body
    axes: dict[str, Axis]
    samples: int | None = None
    seed: int = 0
    chunk_size: int = 1_000_000
    _body: dict[str, float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "seed", whole("seed", self.seed, 0))
        b = self.body
        if not isinstance(b, Body):
            raise TypeError(f"body must be a spinimpact.Body, got {type(b).__name__}")
        if any(np.ndim(x) for x in (b.mass, b.radius, b.gyration)):
            raise ValueError("a sweep needs a single body, not an array of bodies")
        self._check_axes()
        for name, a in self.axes.items():  # every value an axis can take obeys the input rules
            ends = [a.lo] if a.kind == "fixed" else [a.lo, a.hi]
            for x in ends:
                validated(name, x)
        body = {name: float(getattr(b, name)) for name in ("mass", "radius", "zeta", "inertia")}
        object.__setattr__(self, "_body", body)

    def _check_axes(self) -> None:
        """An :class:`Axis` of each input under its own name; a grid or random samples,
        not both; the counts. The axes are copied: later changes to the caller's dict
        do not reach the validated sweep."""
        if not isinstance(self.axes, dict):
            raise TypeError(f"axes must be a dict of name -> Axis, got {type(self.axes).__name__}")
        object.__setattr__(self, "axes", dict(self.axes))
        for key, a in self.axes.items():
            if key not in self.inputs:
                raise ValueError(
                    f"the sweep has no axis {key!r}: its inputs are {', '.join(self.inputs)}"
                )
            if not isinstance(a, Axis):
                raise TypeError(f"axes[{key!r}] must be an Axis, got {a!r}")
            if a.name != key:  # it would be validated as one input and computed as another
                raise ValueError(
                    f"axes[{key!r}] is an axis of {a.name}: build it as Axis({key!r}, ...) "
                    f"or parse_axis({key!r}, ...)"
                )
        missing = [n for n in self.inputs if n not in self.axes]
        if missing:
            raise ValueError(f"the sweep needs a value or range for {', '.join(missing)}")
        if self.samples is not None:
            _positive_int("samples", self.samples, " for random axes")
        kinds = {a.kind for a in self.axes.values()}
        if "uniform" in kinds:
            if "grid" in kinds:
                raise ValueError("a sweep is either a grid or random samples, not both")
            if self.samples is None:
                raise ValueError("samples must be a positive integer for random axes, got None")
        elif self.samples is not None:
            raise ValueError("samples is for random (uniform) axes only")
        _positive_int("chunk_size", self.chunk_size)

    #: The inputs it varies, in the order of the points and of the random draws.
    inputs = INPUTS
    #: Regime names; the ``regime`` field holds indices into them.
    regimes = core.REGIMES

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for (:func:`~spinimpact.io._fields.field_name`)."""
        return field_name(name, role)

    def column_dtype(self, name: str) -> np.dtype:
        """How column ``name`` is stored in ``.npy`` files: ``int8`` regime codes, else float."""
        return np.dtype(np.int8 if name == "regime" else np.float64)

    def metadata(self) -> dict[str, str]:
        """What a Parquet file of the sweep says about itself: regime names and the body."""
        body = json.dumps(self.body.to_dict())
        return {"regimes": json.dumps(list(self.regimes)), "body": body}

    @property
    def random(self) -> bool:
        """Whether the points are random samples (else a grid)."""
        return self.samples is not None

    @property
    def size(self) -> int:
        """Number of points."""
        if self.random:
            return self.samples  # type: ignore[return-value]
        return math.prod(a.num for a in self.axes.values())

    @property
    def chunks(self) -> int:
        """Number of chunks."""
        return -(-self.size // self.chunk_size)

    def chunk(self, k: int) -> dict[str, Any]:
        """Input values of chunk ``k`` (points ``k*chunk_size`` onwards).

        Fixed inputs stay Python numbers, so the kernels take their fast
        scalar-parameter path; varying inputs are arrays of the chunk's length.
        """
        start = k * self.chunk_size
        n = self.chunk_length(k)
        if self.random:
            return {
                name: _uniform(self.seed, name, start, n, a.lo, a.hi)
                if a.kind == "uniform"
                else a.lo
                for name, a in ((name, self.axes[name]) for name in self.inputs)
            }
        shape = tuple(self.axes[name].num for name in self.inputs)
        index = np.unravel_index(np.arange(start, start + n), shape)
        return {  # each grid's values at the chunk's points: the axes are never built whole
            name: self.axes[name].take(i) if self.axes[name].kind == "grid" else self.axes[name].lo
            for name, i in zip(self.inputs, index, strict=True)
        }

    def chunk_length(self, k: int) -> int:
        """Number of points in chunk ``k``."""
        return min(self.chunk_size, self.size - k * self.chunk_size)

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """Inputs and ``fields`` of chunk ``k``, each an array of the chunk's length.

        Parameters
        ----------
        k : int
            Chunk number, ``0 <= k < chunks``.
        fields : tuple of str
            Names from :data:`FIELDS` or :data:`ALIASES`; each comes back under the
            name asked for.

        Returns
        -------
        dict
            ``vx, vy, omega, mu, kappa`` and the fields, in that order.
        """
        c = self.chunk(k)
        known: dict[str, Any] = {}
        wanted = {name: field_name(name) for name in fields}
        if any(f in REBOUND_FIELDS for f in wanted.values()):  # one fused pass for all three
            known.update(zip(REBOUND_FIELDS, rebound_fields(c, self._body), strict=True))
        out = dict(c)
        for name, f in wanted.items():
            if f not in known:
                known[f] = FIELDS[f](c, self._body)
            out[name] = known[f]
        n = self.chunk_length(k)
        return {name: np.broadcast_to(value, (n,)) for name, value in out.items()}


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
class _Work:
    """One chunk's reductions (and columns to write): small, picklable, summable."""

    sweep: Sweep
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


def run_sweep(
    sweep: Sweep,
    *,
    histogram: tuple[str, float, float, int] | None = None,
    output: str | os.PathLike[str] | None = None,
    fields: tuple[str, ...] = ("after_vx", "after_vy", "after_omega", "regime"),
    client: Any = None,
    progress: Callable[[int, int], None] | None = None,
) -> SweepResult:
    """Evaluate ``sweep`` chunk by chunk.

    Parameters
    ----------
    sweep : Sweep
        The points.
    histogram : tuple, optional
        ``(field, low, high, bins)``: counts of a field (a name of :data:`FIELDS`
        or :data:`ALIASES`, in its unit) in ``bins`` equal bins on ``[low, high)``.
    output : str or os.PathLike, optional
        A ``.parquet`` file (``[parquet]`` extra), or any other name: a new directory
        of ``.npy`` files, one per column. Either holds the inputs and ``fields``.
    fields : tuple of str
        Fields to write to ``output``, by the names of :data:`FIELDS` or :data:`ALIASES`.
    client : distributed.Client, optional
        Run the chunks on its Dask cluster (see :func:`dask_client`).
    progress : callable, optional
        Called after each chunk as ``progress(done, total)`` in chunks.

    Returns
    -------
    SweepResult
        The regime fractions, and the histogram if asked for.

    Raises
    ------
    ValueError
        For an unknown field, a bad histogram, or an output that exists (a directory)
        or whose directory does not.
    ImportError
        For Parquet output without pyarrow, naming the ``[parquet]`` extra.

    Examples
    --------
    >>> from spinimpact import Body
    >>> axes = {n: parse_axis(n, v) for n, v in
    ...         dict(vx="-2:2:5", vy="-1", omega="0", mu="0.5", kappa="0.8").items()}
    >>> result = run_sweep(Sweep(Body.solid_sphere(mass=1.0, radius=0.1), axes),
    ...                    histogram=("energy_loss", 0, 1, 4))
    >>> result.points, result.histogram.tolist()
    (5, [0, 5, 0, 0])
    """
    for name in fields:
        sweep.field_name(name)
    if histogram is not None:
        name, lo, hi, bins = histogram
        sweep.field_name(name, "histogram field")
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi) or not 1 <= int(bins) <= 10**6:
            raise ValueError(
                f"histogram needs LOW < HIGH and 1 <= BINS <= 1000000, got {lo}:{hi}:{bins}"
            )
    regimes = tuple(sweep.regimes)
    result = SweepResult(regime_counts=np.zeros(len(regimes), np.int64), regimes=regimes)
    if histogram is not None:
        result.histogram = np.zeros(int(histogram[3]), np.int64)
        result.bin_edges = np.linspace(histogram[1], histogram[2], int(histogram[3]) + 1)
    window = 4 if client is None else 2 * max(1, len(getattr(client, "nthreads", lambda: {1: 1})()))
    columns = tuple(dict.fromkeys(sweep.inputs + tuple(fields))) if output is not None else ()
    work = _Work(sweep, columns, histogram)
    if output is None:
        sink: Any = Discard()
    elif str(output).endswith(".parquet"):
        sink = parquet_columns(output, sweep.metadata())
    else:
        dtypes = {c: sweep.column_dtype(c) for c in columns}
        sink = npy_columns(output, columns, sweep.size, dtypes)
    with sink as writer:
        chunks = chunks_in_order(sweep.chunks, work, client, window)
        for k, (n, counts, hist, data) in enumerate(chunks):
            writer.write(data)
            result.points += n
            result.regime_counts += counts
            if hist is not None:
                result.histogram += hist
            if progress is not None:
                progress(k + 1, sweep.chunks)
    return result
