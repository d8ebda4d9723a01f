"""Sweeps over incidence conditions that need not fit in memory.

A :class:`Sweep` is a grid (the Cartesian product of evenly spaced axes) or a
set of random samples over any of ``vx, vy, omega, mu, kappa`` for one body.
It is evaluated chunk by chunk, so memory stays bounded by the chunk size
whatever the number of points, either streaming the fields to Parquet or
``.npy`` files or folding them into reductions (regime fractions, histograms)
on the fly. Given a Dask client, the same chunks run on a Dask cluster and give
the same numbers.

Random samples are drawn per chunk from ``numpy.random.default_rng([seed,
chunk])``, so a sweep is reproducible for a given seed and chunk size.
"""

from __future__ import annotations

import math
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import core
from .._validation import validated
from ..core import fused
from ..model.body import Body

__all__ = ["Axis", "Sweep", "SweepResult", "FIELDS", "run_sweep", "parse_axis"]

INPUTS = ("vx", "vy", "omega", "mu", "kappa")


def _f_rebound(c: dict[str, np.ndarray], b: dict[str, float]) -> tuple[np.ndarray, ...]:
    return fused.rebound(
        c["vx"], c["vy"], c["omega"], b["mass"], b["radius"], b["zeta"], c["mu"], c["kappa"]
    )


def _f_regime(c, b):
    slip = core.slip_velocity(c["vx"], c["omega"], b["radius"])
    return core.regime_code(slip, c["vy"], b["zeta"], c["mu"], c["kappa"])


def _f_loss(c, b):
    args = (c["vx"], c["vy"], c["omega"], b["mass"], b["radius"], b["zeta"], c["mu"], c["kappa"])
    inertia = b["mass"] * b["radius"] ** 2 / (b["zeta"] - 1.0)
    e0 = core.kinetic_energy(c["vx"], c["vy"], c["omega"], b["mass"], inertia)
    return core.dissipated_energy(*args) / e0


def _f_impulse_ratio(c, b):
    slip = core.slip_velocity(c["vx"], c["omega"], b["radius"])
    return core.impulse_ratio(slip, c["vy"], b["zeta"], c["mu"], c["kappa"])


def _f_slip_after(c, b):
    slip = core.slip_velocity(c["vx"], c["omega"], b["radius"])
    return core.rebound_slip(slip, c["vy"], b["zeta"], c["mu"], c["kappa"])


#: Fields a sweep can write or reduce, and how each is computed from a chunk.
FIELDS: dict[str, Callable[[dict, dict], np.ndarray]] = {
    "after_vx": lambda c, b: _f_rebound(c, b)[0],
    "after_vy": lambda c, b: _f_rebound(c, b)[1],
    "after_omega": lambda c, b: _f_rebound(c, b)[2],
    "regime": _f_regime,  # integer code: spinimpact.core.REGIMES[code]
    "energy_loss": _f_loss,  # dissipated energy / incidence energy
    "impulse_ratio": _f_impulse_ratio,
    "slip_after": _f_slip_after,
}


@dataclass(frozen=True)
class Axis:
    """One input of a sweep: ``fixed`` at ``lo``, an evenly spaced ``grid`` of
    ``num`` values on ``[lo, hi]``, or ``uniform`` random on ``[lo, hi)``."""

    name: str
    kind: str
    lo: float
    hi: float = math.nan
    num: int = 1

    def values(self) -> np.ndarray:
        return (
            np.linspace(self.lo, self.hi, self.num) if self.kind == "grid" else np.array([self.lo])
        )


def parse_axis(name: str, text: str | float) -> Axis:
    """``"3"`` (fixed), ``"-5:5:101"`` (grid: start, stop, number of points) or
    ``"uniform:-5:5"`` (random)."""
    if name not in INPUTS:
        raise ValueError(f"sweep inputs are {', '.join(INPUTS)}; got {name!r}")
    parts = str(text).split(":")
    try:
        if len(parts) == 1:
            return Axis(name, "fixed", float(parts[0]))
        if len(parts) == 3 and parts[0] == "uniform":
            lo, hi = float(parts[1]), float(parts[2])
            if not lo < hi:
                raise ValueError
            return Axis(name, "uniform", lo, hi)
        if len(parts) == 3:
            num = int(parts[2])
            if num < 1:
                raise ValueError
            return Axis(name, "grid", float(parts[0]), float(parts[1]), num)
    except ValueError:
        pass
    raise ValueError(
        f"{name} must be a number, START:STOP:NUM (a grid) or uniform:LOW:HIGH, got {text!r}"
    )


@dataclass(frozen=True)
class Sweep:
    """A sweep over the inputs of one body (see the module docstring).

    Parameters
    ----------
    body : Body
        A single body (scalar mass, radius, gyration).
    axes : dict
        ``name -> Axis`` for each of ``vx, vy, omega, mu, kappa`` (all required).
    samples : int, optional
        Number of random points; required when any axis is ``uniform``, which
        excludes ``grid`` axes.
    seed : int
    chunk_size : int
    """

    body: Body
    axes: dict[str, Axis]
    samples: int | None = None
    seed: int = 0
    chunk_size: int = 1_000_000
    _body: dict[str, float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        b = self.body
        if any(np.ndim(x) for x in (b.mass, b.radius, b.gyration)):
            raise ValueError("a sweep needs a single body, not an array of bodies")
        missing = [n for n in INPUTS if n not in self.axes]
        if missing:
            raise ValueError(f"the sweep needs a value or range for {', '.join(missing)}")
        kinds = {a.kind for a in self.axes.values()}
        if "uniform" in kinds:
            if "grid" in kinds:
                raise ValueError("a sweep is either a grid or random samples, not both")
            if not isinstance(self.samples, int) or self.samples < 1:
                raise ValueError(
                    f"samples must be a positive integer for random axes, got {self.samples!r}"
                )
        elif self.samples is not None:
            raise ValueError("samples is for random (uniform) axes only")
        if not isinstance(self.chunk_size, int) or self.chunk_size < 1:
            raise ValueError(f"chunk_size must be a positive integer, got {self.chunk_size!r}")
        for a in self.axes.values():  # every value an axis can take obeys the input rules
            ends = [a.lo] if a.kind == "fixed" else [a.lo, a.hi]
            for x in ends:
                validated(a.name, x)
        body = {"mass": float(b.mass), "radius": float(b.radius), "zeta": float(b.zeta)}
        object.__setattr__(self, "_body", body)

    @property
    def random(self) -> bool:
        return self.samples is not None

    @property
    def size(self) -> int:
        if self.random:
            return self.samples  # type: ignore[return-value]
        return math.prod(a.num for a in self.axes.values())

    @property
    def chunks(self) -> int:
        return -(-self.size // self.chunk_size)

    def chunk(self, k: int) -> dict[str, np.ndarray]:
        """Input arrays of chunk ``k`` (points ``k*chunk_size`` onwards)."""
        start = k * self.chunk_size
        n = min(self.chunk_size, self.size - start)
        # Fixed inputs stay Python numbers, so the kernels take their fast
        # scalar-parameter path; varying inputs are arrays of the chunk's length.
        if self.random:
            rng = np.random.default_rng([self.seed, k])
            out: dict[str, Any] = {}
            for name in INPUTS:  # a fixed order: the draws do not depend on dict order
                a = self.axes[name]
                out[name] = rng.uniform(a.lo, a.hi, n) if a.kind == "uniform" else a.lo
            return out
        shape = tuple(self.axes[name].num for name in INPUTS)
        index = np.unravel_index(np.arange(start, start + n), shape)
        return {
            name: self.axes[name].values()[i]
            if self.axes[name].kind == "grid"
            else self.axes[name].lo
            for name, i in zip(INPUTS, index, strict=True)
        }

    def chunk_length(self, k: int) -> int:
        return min(self.chunk_size, self.size - k * self.chunk_size)

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """Inputs and ``fields`` of chunk ``k``, each an array of the chunk's length."""
        c = self.chunk(k)
        out = dict(c)
        if any(name.startswith("after_") for name in fields):  # one fused pass for all three
            out["after_vx"], out["after_vy"], out["after_omega"] = _f_rebound(c, self._body)
        for name in fields:
            if name not in out:
                out[name] = FIELDS[name](c, self._body)
        n = self.chunk_length(k)
        return {name: np.broadcast_to(out[name], (n,)) for name in (*c, *fields)}


@dataclass
class SweepResult:
    """Reductions of a sweep, folded chunk by chunk."""

    points: int = 0
    regime_counts: np.ndarray = field(default_factory=lambda: np.zeros(len(core.REGIMES), np.int64))
    histogram: np.ndarray | None = None
    bin_edges: np.ndarray | None = None

    @property
    def regime_fractions(self) -> dict[str, float]:
        total = max(self.points, 1)
        return {
            name: int(c) / total for name, c in zip(core.REGIMES, self.regime_counts, strict=True)
        }


def _reduce_chunk(sweep: Sweep, k: int, histogram: tuple[str, float, float, int] | None):
    """Regime counts (and a histogram) of chunk ``k``: small, picklable, summable."""
    fields = ("regime",) + ((histogram[0],) if histogram and histogram[0] != "regime" else ())
    data = sweep.evaluate(k, fields)
    counts = np.bincount(data["regime"], minlength=len(core.REGIMES))
    hist = None
    if histogram:
        name, lo, hi, bins = histogram
        hist, _ = np.histogram(data[name], bins=bins, range=(lo, hi))
    return data["regime"].size, counts, hist


def _chunks_in_order(
    sweep: Sweep, work: Callable[[int], Any], client: Any, window: int
) -> Iterator:
    """Results of ``work(k)`` for every chunk, in order, locally or on a Dask client
    with at most ``window`` chunks in flight (bounded memory)."""
    if client is None:
        for k in range(sweep.chunks):
            yield work(k)
        return
    pending: dict[int, Any] = {}
    for k in range(sweep.chunks):
        pending[k] = client.submit(work, k, pure=False)
        if len(pending) >= window:
            first = min(pending)
            yield pending.pop(first).result()
    for k in sorted(pending):
        yield pending.pop(k).result()


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

    Always returns the regime fractions (and the ``histogram = (field, lo, hi,
    bins)`` if asked). With ``output`` ending in ``.parquet`` the inputs and
    ``fields`` are streamed to one Parquet file; any other ``output`` is a
    directory of ``.npy`` files, one per column. ``client`` is a
    ``dask.distributed.Client``: the chunks then run on its cluster.
    """
    for name in fields:
        if name not in FIELDS:
            raise ValueError(f"fields must be among {', '.join(FIELDS)}; got {name!r}")
    if histogram is not None:
        name, lo, hi, bins = histogram
        if name not in FIELDS:
            raise ValueError(f"histogram field must be among {', '.join(FIELDS)}; got {name!r}")
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi) or not 1 <= int(bins) <= 10**6:
            raise ValueError(
                f"histogram needs LOW < HIGH and 1 <= BINS <= 1000000, got {lo}:{hi}:{bins}"
            )
    result = SweepResult()
    if histogram is not None:
        result.histogram = np.zeros(int(histogram[3]), np.int64)
        result.bin_edges = np.linspace(histogram[1], histogram[2], int(histogram[3]) + 1)
    window = 4 if client is None else 2 * max(1, len(getattr(client, "nthreads", lambda: {1: 1})()))

    def fold(n, counts, hist, k):
        result.points += n
        result.regime_counts += counts
        if hist is not None:
            result.histogram += hist
        if progress is not None:
            progress(k + 1, sweep.chunks)

    if output is None:
        work = _ReduceWork(sweep, histogram)
        for k, (n, counts, hist) in enumerate(_chunks_in_order(sweep, work, client, window)):
            fold(n, counts, hist, k)
        return result
    columns = tuple(INPUTS) + tuple(f for f in fields if f not in INPUTS)
    work = _EvaluateWork(sweep, tuple(dict.fromkeys(fields + ("regime",))), histogram)
    writer = (
        _ParquetColumns(output, columns)
        if str(output).endswith(".parquet")
        else _NpyColumns(output, columns, sweep.size)
    )
    try:
        for k, (data, hist) in enumerate(_chunks_in_order(sweep, work, client, window)):
            writer.write({c: data[c] for c in columns})
            counts = np.bincount(data["regime"], minlength=len(core.REGIMES))
            fold(data["regime"].size, counts, hist, k)
        writer.commit()
    finally:
        writer.discard()
    return result


@dataclass(frozen=True)
class _ReduceWork:
    sweep: Sweep
    histogram: tuple[str, float, float, int] | None

    def __call__(self, k: int):
        return _reduce_chunk(self.sweep, k, self.histogram)


@dataclass(frozen=True)
class _EvaluateWork:
    sweep: Sweep
    fields: tuple[str, ...]
    histogram: tuple[str, float, float, int] | None

    def __call__(self, k: int):
        data = self.sweep.evaluate(k, self.fields)
        hist = None
        if self.histogram:
            name, lo, hi, bins = self.histogram
            values = data[name] if name in data else self.sweep.evaluate(k, (name,))[name]
            hist, _ = np.histogram(values, bins=int(bins), range=(lo, hi))
        return data, hist


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


class _ParquetColumns:
    """Streams chunks to one Parquet file under a temporary name; renamed on success."""

    def __init__(self, path, columns) -> None:
        try:
            import pyarrow.parquet  # noqa: F401
        except ImportError:
            raise ValueError(
                "Parquet output needs the optional extra: pip install 'spinimpact[parquet]'"
            ) from None
        self.target = Path(path)
        if self.target.is_dir():
            raise ValueError(f"output {str(self.target)!r} is a directory")
        if not self.target.parent.is_dir():
            raise ValueError(f"the directory of the output {str(self.target)!r} does not exist")
        fd, name = tempfile.mkstemp(
            prefix=f".{self.target.name}.", suffix=".part", dir=self.target.parent
        )
        os.close(fd)
        self.tmp, self.writer = Path(name), None

    def write(self, data: dict[str, np.ndarray]) -> None:
        import pyarrow as pa
        import pyarrow.parquet as pq

        table = pa.table({k: np.ascontiguousarray(v) for k, v in data.items()})
        if self.writer is None:
            self.writer = pq.ParquetWriter(self.tmp, table.schema)
        self.writer.write_table(table)

    def commit(self) -> None:
        if self.writer is not None:
            self.writer.close()
            self.writer = None
        os.chmod(self.tmp, 0o666 & ~_umask())
        os.replace(self.tmp, self.target)

    def discard(self) -> None:
        if self.writer is not None:
            self.writer.close()
        self.tmp.unlink(missing_ok=True)


class _NpyColumns:
    """Streams chunks into one ``.npy`` file per column of a new directory.

    Each chunk is appended with an ordinary file write after the ``.npy``
    header (no memory map), so resident memory stays bounded by the chunk.
    """

    def __init__(self, path, columns, size: int) -> None:
        self.target = Path(path)
        if self.target.exists():
            raise ValueError(f"output directory {str(self.target)!r} already exists")
        if not self.target.parent.is_dir():
            raise ValueError(f"the directory of the output {str(self.target)!r} does not exist")
        self.tmp = Path(tempfile.mkdtemp(prefix=f".{self.target.name}.", dir=self.target.parent))
        self.files = {}
        for c in columns:
            dtype = np.dtype(np.int8 if c == "regime" else np.float64)
            f = open(self.tmp / f"{c}.npy", "wb")  # noqa: SIM115 (closed in commit/discard)
            np.lib.format.write_array_header_1_0(
                f,
                {
                    "descr": np.lib.format.dtype_to_descr(dtype),
                    "fortran_order": False,
                    "shape": (size,),
                },
            )
            self.files[c] = (f, dtype)

    def write(self, data: dict[str, np.ndarray]) -> None:
        for c, values in data.items():
            f, dtype = self.files[c]
            f.write(np.ascontiguousarray(values, dtype=dtype).tobytes())

    def _close(self) -> None:
        for f, _ in self.files.values():
            f.close()
        self.files = {}

    def commit(self) -> None:
        self._close()
        os.chmod(self.tmp, 0o777 & ~_umask())
        for child in self.tmp.iterdir():
            os.chmod(child, 0o666 & ~_umask())
        os.replace(self.tmp, self.target)

    def discard(self) -> None:
        self._close()
        if self.tmp.exists():
            shutil.rmtree(self.tmp)
