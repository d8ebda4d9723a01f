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
core kernels, without building the whole result); ``regime`` is computed as its
integer code, ``spinimpact.core.REGIMES[code]`` being the Impact's text. Older
names stay accepted (:data:`ALIASES`). Files name the regimes: a dictionary column
of names in Parquet, names in CSV, and in a directory of ``.npy`` files the codes in
``regime.npy`` with the names in ``metadata.json`` (:mod:`spinimpact.io._fields`).

Before computing, :func:`run_sweep` weighs a trial chunk (:func:`estimate_sweep`) and
refuses a sweep whose chunk would not fit in the memory available or whose output
would not fit on its disk; grid chunks compute their own points, so memory does not
grow with the length of an axis.

Random samples depend on the seed alone: each uniform input draws from its own
stream (:class:`numpy.random.PCG64` seeded with ``[seed, index of the input in
INPUTS]``), point ``i`` taking the stream's ``i``-th number, so the points are the
same whatever the chunk size or the Dask cluster, and the first ``n`` points of a
longer sweep are those of a sweep of ``n``.

Every other problem (a sphere in 3D, a planar body or a pendulum, a body under a
tangential law, two spheres) is swept by :class:`~spinimpact.io.problem_sweep.ProblemSweep`,
a :class:`Sweep` with its own inputs, fields and regimes (:attr:`Sweep.inputs`,
:meth:`Sweep.field_name`, :attr:`Sweep.regimes`), run by the same :func:`run_sweep`. Every
output describes the sweep (:meth:`Sweep.description`: regimes, body, axes, seed) and each
column's unit.
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
from .._validation import callback, validated, whole
from ..model.body import Body
from ._axes import INPUTS, Axis, parse_axis, positive_int, uniform_stream
from ._fields import (
    ALIASES,
    DEFAULT_FIELDS,
    FIELDS,
    REBOUND_FIELDS,
    field_name,
    npy_folder,
    output_kind,
    plan,
    rebound_fields,
    table_columns,
    write_npy_metadata,
)
from ._runner import (
    TRIAL_POINTS,
    ChunkWork,
    Discard,
    SweepEstimate,
    SweepResult,
    chunks_in_order,
    dask_client,
    estimate_sweep,
)
from ._sinks import npy_columns
from ._units import unit_of

__all__ = [
    "ALIASES",
    "FIELDS",
    "INPUTS",
    "Axis",
    "Sweep",
    "SweepEstimate",
    "SweepResult",
    "dask_client",
    "estimate_sweep",
    "field_name",
    "output_kind",
    "parse_axis",
    "run_sweep",
]


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
            positive_int("samples", self.samples, " for random axes")
        kinds = {a.kind for a in self.axes.values()}
        if "uniform" in kinds:
            if "grid" in kinds:
                raise ValueError("a sweep is either a grid or random samples, not both")
            if self.samples is None:
                raise ValueError("samples must be a positive integer for random axes, got None")
        elif self.samples is not None:
            raise ValueError("samples is for random (uniform) axes only")
        positive_int("chunk_size", self.chunk_size)
        self._check_size()

    def _check_size(self) -> None:
        """The points must be numbered by NumPy's index type (``intp``)."""
        most = int(np.iinfo(np.intp).max)
        if self.size <= most:
            return
        if self.random:
            raise ValueError(f"samples must be at most {most:,} (the most NumPy can index), "
                             f"got {self.samples:,}")  # fmt: skip
        grid = " x ".join(f"{n} {a.num}" for n, a in self.axes.items() if a.kind == "grid")
        raise ValueError(
            f"the grid has {self.size:,} points ({grid}), more than {most:,}, the most NumPy can "
            "index: give its axes fewer points"
        )

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

    def unit(self, name: str) -> str | None:
        """The SI unit of column ``name`` in the files (``None``: text or a flag)."""
        return unit_of(name)

    def description(self) -> dict[str, Any]:
        """What a file of the sweep says about itself: the regimes' names (the ``regime``
        codes index them), the body, the axes (SI units), the samples and the seed."""
        axes = {}
        for n, a in self.axes.items():
            ends = {"lo": a.lo, "hi": a.hi} | ({"num": a.num} if a.kind == "grid" else {})
            axes[n] = {"kind": a.kind} | ({"value": a.lo} if a.kind == "fixed" else ends)
        random = {"samples": self.samples, "seed": self.seed} if self.random else {}
        return {"regimes": list(self.regimes), "body": self.body.to_dict(), "axes": axes} | random

    def metadata(self) -> dict[str, str]:
        """:meth:`description` as a Parquet file's key-value metadata (JSON text values)."""
        return {
            k: v if isinstance(v, str) else json.dumps(v) for k, v in self.description().items()
        }

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
                name: uniform_stream(self.seed, name, start, n, a.lo, a.hi)
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


def run_sweep(
    sweep: Sweep,
    *,
    histogram: tuple[str, float, float, int] | None = None,
    output: str | os.PathLike[str] | None = None,
    fields: tuple[str, ...] = DEFAULT_FIELDS,
    client: Any = None,
    progress: Callable[[int, int], None] | None = None,
    check: bool = True,
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
        ``FILE.parquet`` (``[parquet]`` extra), ``FILE.csv`` (the same extra), or a name
        without a suffix (or ending in ``/``): a new directory of ``.npy`` files, one per
        column, and ``metadata.json``. Each holds the inputs and ``fields``; ``regime``
        is a dictionary column of the regimes' names in Parquet, names in CSV, and
        indices into ``metadata.json``'s ``"regimes"`` in ``regime.npy``.
    fields : tuple of str
        Fields to write to ``output``, by the names of :data:`FIELDS` or :data:`ALIASES`.
    client : distributed.Client, optional
        Run the chunks on its Dask cluster (see :func:`dask_client`).
    progress : callable, optional
        Called after each chunk as ``progress(done, total)`` in chunks.
    check : bool
        Refuse, before computing anything, a sweep of more than 16,384 points whose
        chunk would not fit in the memory available or whose output would not fit on
        its disk (:func:`estimate_sweep`); ``False`` runs it anyway.

    Returns
    -------
    SweepResult
        The regime fractions, and the histogram if asked for.

    Raises
    ------
    ValueError
        For an unknown field, a bad histogram, an output that exists (a directory), whose
        directory does not, or whose suffix is none of the three, or (``check``) a sweep
        that cannot fit.
    ImportError
        For Parquet or CSV output without pyarrow, naming the ``[parquet]`` extra.

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
    kind, columns = plan(sweep, fields, histogram, output)
    callback("progress", progress, "progress(done, total)")
    if check and sweep.size > TRIAL_POINTS:
        cost = estimate_sweep(sweep, histogram=histogram, output=output, fields=fields, timed=False)
        problems = cost.problems()
        if problems:
            raise ValueError(
                f"the sweep cannot run as asked: {'; '.join(problems)} (check=False runs it anyway)"
            )
    regimes = tuple(sweep.regimes)
    result = SweepResult(regime_counts=np.zeros(len(regimes), np.int64), regimes=regimes)
    if histogram is not None:
        result.histogram = np.zeros(int(histogram[3]), np.int64)
        result.bin_edges = np.linspace(histogram[1], histogram[2], int(histogram[3]) + 1)
    window = 4 if client is None else 2 * max(1, len(getattr(client, "nthreads", lambda: {1: 1})()))
    work = ChunkWork(sweep, columns, histogram)
    dtypes = {c: sweep.column_dtype(c) for c in columns}
    if kind is None:
        sink: Any = Discard()
    elif kind == "npy":
        sink = npy_columns(output, columns, sweep.size, dtypes)  # type: ignore[arg-type]
    else:
        sink = table_columns(output, kind, sweep.metadata(), regimes, sweep.unit)  # type: ignore[arg-type]
    with sink as writer:
        if kind == "npy":
            write_npy_metadata(npy_folder(writer), sweep.description(), dtypes, sweep.unit)
        done = 0
        # no enumerate(): its reused tuple would keep the last chunk alive during the next
        for n, counts, hist, data in chunks_in_order(sweep.chunks, work, client, window):
            writer.write(data)
            del data  # one chunk's columns alive at a time
            result.points += n
            result.regime_counts += counts
            if hist is not None:
                result.histogram += hist
            done += 1
            if progress is not None:
                progress(done, sweep.chunks)
    return result
