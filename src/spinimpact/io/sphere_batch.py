"""Batch files of spheres in 3D: every row solved by :func:`~spinimpact.solve_sphere` (a
sphere on a plane) or :func:`~spinimpact.solve_pair` (two spheres), in chunks.

The columns say what a file holds:

* spheres: ``vx, vy, vz`` (m/s) and ``wx, wy, wz`` (rad/s), and optionally ``mu, kappa``
  (1), ``mass`` (kg), ``radius, gyration`` (m), ``body`` (``solid-sphere`` or
  ``spherical-shell``), the surface's normal ``normal_x, normal_y, normal_z`` and velocity
  ``surface_velocity_x, surface_velocity_y, surface_velocity_z`` (m/s);
* pairs (columns ``vx2 ... wz2``): ball 1's ``vx ... wz`` and ball 2's ``vx2 ... wz2``,
  optionally ``normal_x, normal_y, normal_z`` (from ball 2's centre to ball 1's),
  ``mu, kappa`` and each ball's ``mass, radius, gyration, body`` (ball 2:
  ``mass2, radius2, gyration2, body2``).

An empty cell (or a Parquet null) or a missing column takes the run's default. The output
holds the input columns, then the optional inputs the file lacks (with the values used),
then every column of :class:`~spinimpact.SphereImpact` or :class:`~spinimpact.PairImpact`
that is not an input, ``regime`` first. A bad row (a cell that is not a number or breaks
a rule, a zero normal, a contact that does not approach, a result that is not finite) is
named by its row, line and column. Memory is bounded by the chunk; the output is written
under a temporary name and renamed only when the whole run succeeded.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import LARGEST, available, require, row_problems
from ..model.body import Body
from ..model.pair import PairImpact, solve_pair
from ..model.sphere3d import SphereImpact, Surface, solve_sphere
from ._tables import (
    BatchError,
    Chunk,
    check_header,
    chunk_numbers,
    csv_chunks,
    file_format,
    parquet_chunks,
)
from .atomic import atomic_path

try:  # the batch-row writers and the stop check are moving (io._rows, io._stop)
    from ._rows import ArrowRows, CsvRows
except ImportError:  # pragma: no cover (the layout before the move)
    from ._sinks import ArrowRows, CsvRows
try:
    from ._stop import check as _stop_check
except ImportError:  # pragma: no cover

    def _stop_check() -> None:
        """No signal is recorded in this layout: Ctrl-C raises at once."""


__all__ = ["SPHERES", "BALL", "SphereBatchSummary", "sphere_kind", "run_sphere_batch"]

#: The presets a row's ``body`` may name.
SPHERES = ("solid-sphere", "spherical-shell")
#: Velocity and spin columns of one ball (ball 2's end in ``2``).
BALL = ("vx", "vy", "vz", "wx", "wy", "wz")
_NORMAL = ("normal_x", "normal_y", "normal_z")
_SURFACE = ("surface_velocity_x", "surface_velocity_y", "surface_velocity_z")
_BODY = ("mass", "radius", "gyration")
#: Results that may be infinite (a slip that never stops) or undefined (no travel after).
_MAY_BE_INFINITE = ("tau_star",)
_MAY_BE_NAN = ("topspin", "gyrospin", "angle_between_paths")


@dataclass(frozen=True)
class SphereBatchSummary:
    """What :func:`run_sphere_batch` did."""

    rows: int  #: data rows read
    skipped: int  #: rows written with an error instead of results (``on_error="skip"``)
    output: Path  #: the file written
    kind: str  #: "sphere" or "pair"


def sphere_kind(header: list[str]) -> str:
    """``"pair"`` if the columns hold a second ball (``vx2 ... wz2``), else ``"sphere"``.

    Raises
    ------
    BatchError
        A pair file with a surface velocity column (two free balls have no surface).
    """
    if not any(f"{c}2" in header for c in BALL):
        return "sphere"
    for name in _SURFACE:
        if name in header:
            raise BatchError(f"column {name!r} describes a surface, but columns vx2 ... wz2 "
                             "make this a file of two balls; drop or rename it")  # fmt: skip
    return "pair"


def _finite(name: str) -> Callable[[np.ndarray], np.ndarray]:
    def problems(values: np.ndarray) -> np.ndarray:
        out = np.full(values.shape, "", dtype=object)
        with np.errstate(invalid="ignore"):
            bad = ~(np.abs(values) <= LARGEST)
        for i in np.flatnonzero(bad):
            out[i] = (
                f"{name} must be finite and at most {LARGEST:g} in magnitude, got {values[i]!r}"
            )
        return out

    return problems


def _rules(name: str) -> Callable[[np.ndarray], np.ndarray]:
    base = name.rstrip("2")
    if base in ("mu", "kappa", *_BODY):
        return functools.partial(row_problems, base)
    return _finite(name)


@functools.cache
def _result_kinds(pair: bool) -> dict[str, str]:
    """Each result column's kind (``float``, ``text``, ``flag``), from one solved impact."""
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    if pair:
        probe: Any = solve_pair(ball, ball, velocity1=[1, 0, 0], spin1=[0, 0, 0], velocity2=[0] * 3,
                                spin2=[0] * 3, normal=[-1, 0, 0], mu=0.3, kappa=0.5)  # fmt: skip
    else:
        probe = solve_sphere(ball, [1, -1, 0], [0, 0, 0], mu=0.3, kappa=0.5)
    kinds = {"b": "flag", "U": "text", "S": "text", "O": "text"}
    return {n: kinds.get(np.asarray(c).dtype.kind, "float") for n, c in probe.columns().items()}


class _Plan:
    """What a file of one kind reads, writes and how it solves a chunk."""

    def __init__(self, kind: str, header: list[str], skip: bool, defaults: dict[str, Any]):
        self.pair, self.header = kind == "pair", list(header)
        self.balls = ("", "2") if self.pair else ("",)
        self.required = BALL + (tuple(f"{c}2" for c in BALL) if self.pair else ())
        bodies = tuple(f"{c}{k}" for k in self.balls for c in _BODY)
        self.optional = ("mu", "kappa", *bodies, *_NORMAL) + (() if self.pair else _SURFACE)
        self.defaults = self._defaults(defaults)
        for name in self.optional:
            if name not in header and self.defaults.get(name) is None and "gyration" not in name:
                raise BatchError(f"the file has no column {name!r} and no default was given")
        # the result's columns, less those the file holds as inputs (before_vx is vx, ...):
        # an optional input the file lacks is written with the value each row used
        result = PairImpact if self.pair else SphereImpact
        names = [n for n in result.column_names() if not n.startswith("before")
                 and not (n in self.optional and n in header)]  # fmt: skip
        kinds = _result_kinds(self.pair)
        self.kinds = {n: kinds[n] for n in ["regime"] + [n for n in names if n != "regime"]}
        self.numeric = tuple(n for n in (*self.required, *self.optional) if n in header)
        check_header(header, skip, self.kinds, self.required)

    def _defaults(self, given: dict[str, Any]) -> dict[str, Any]:
        out: dict[str, Any] = {n: given.get(n) for n in ("mu", "kappa")}
        for k in self.balls:
            for c in _BODY:
                out[f"{c}{k}"] = given.get(f"{c}{k}")
            body = given.get(f"body{k}")
            out[f"body{k}"] = None if out[f"gyration{k}"] is not None else (body or SPHERES[0])
        vectors = ((_NORMAL, "normal", None if self.pair else (0.0, 1.0, 0.0)),
                   (_SURFACE, "surface_velocity", (0.0, 0.0, 0.0)))  # fmt: skip
        for names, key, fallback in vectors[: 1 if self.pair else 2]:
            vector = given.get(key)
            vector = fallback if vector is None else vector
            out.update(
                zip(names, [None] * 3 if vector is None else map(float, vector), strict=True)
            )
        return out

    def solve(self, chunk: Chunk) -> tuple[dict, dict, np.ndarray]:
        """Solve one chunk: (input numbers, output columns, error message per row)."""
        n = chunk.messages.size
        found: list[tuple[int, str]] = []

        def note(i: int, message: str) -> None:
            found.append((i, message))

        values: dict[str, np.ndarray] = {}
        for name in (*self.required, *self.optional):
            default = self.defaults.get(name)
            if name in chunk.columns:
                optional = name.startswith("gyration")
                values[name] = chunk_numbers(chunk, name, default, note, _rules(name),
                                             required=not optional)  # fmt: skip
            else:
                values[name] = np.full(n, np.nan if default is None else float(default))
        presets = {k: self._presets(chunk, values, k, note) for k in self.balls}
        self._check_geometry(chunk, values, note)
        messages = chunk.messages.copy()
        for i, message in sorted(found, key=lambda item: item[0]):
            messages[i] = messages[i] or message
        results = {name: np.full(n, np.nan) if kind == "float" else np.full(n, None, object)
                   for name, kind in self.kinds.items()}  # fmt: skip
        self._solve_rows(np.flatnonzero(messages == ""), chunk, values, presets, results, messages)
        return values, results, messages

    def _presets(self, chunk: Chunk, values: dict, k: str, note: Callable) -> np.ndarray:
        """Each row's preset name for ball ``k`` ("" where it has its own gyration)."""
        n, column = chunk.messages.size, f"body{k}"
        preset = np.full(n, self.defaults[column] or "", dtype=object)
        own = ~np.isnan(values[f"gyration{k}"])
        if column in chunk.columns:
            given = ~chunk.empty[column]
            cells = np.array([str(c).strip() for c in chunk.columns[column]], dtype=object)
            preset[given] = cells[given]
            for i in np.flatnonzero(given & own):
                if f"gyration{k}" in chunk.columns and not chunk.empty[f"gyration{k}"][i]:
                    note(
                        i, f"{chunk.where(i, column)}: give either body{k} or gyration{k}, not both"
                    )
            own &= ~given  # a row's preset wins over a default gyration
        preset[own] = ""
        for i in np.flatnonzero(~own & ~np.isin(preset, SPHERES)):
            what = repr(str(preset[i])) if preset[i] else "nothing (no body and no gyration)"
            note(i, f"{chunk.where(i, column)}: must be one of {', '.join(SPHERES)}; got {what}")
        values[f"gyration{k}"] = np.where(own, values[f"gyration{k}"], np.nan)
        return preset

    def _check_geometry(self, chunk: Chunk, v: dict, note: Callable) -> None:
        """A normal of length > 0, and a contact that approaches (c_n < 0)."""
        normal = np.stack([v[c] for c in _NORMAL], -1)
        with np.errstate(all="ignore"):
            size = np.sqrt(np.sum(normal * normal, -1))
            first = np.stack([v[c] for c in BALL[:3]], -1)
            names = [f"{c}2" for c in BALL[:3]] if self.pair else _SURFACE
            other = np.stack([v[c] for c in names], -1)
            approach = np.sum((first - other) * normal, -1) / size
        for i in np.flatnonzero(np.isfinite(size) & ~(size > 1e-12)):
            note(i, f"{chunk.where(i)}, columns normal_x, normal_y, normal_z: the normal must be a "
                 f"direction, got {tuple(float(c) for c in normal[i])}")  # fmt: skip
        what = "vx - vx2, ..." if self.pair else "the velocity relative to the surface"
        for i in np.flatnonzero(np.isfinite(approach) & ~(approach < 0)):
            note(i, f"{chunk.where(i)}: the contact must approach, but the normal component of "
                 f"{what} is {float(approach[i])!r} m/s")  # fmt: skip

    def _solve_rows(self, rows, chunk, values, presets, results, messages) -> None:
        """Solve ``rows`` at once; where that fails, halve them to name the bad rows."""
        if rows.size == 0:
            return
        try:
            with np.errstate(all="ignore"):
                columns = self._columns({k: v[rows] for k, v in values.items()},
                                        {k: p[rows] for k, p in presets.items()})  # fmt: skip
        except (ValueError, TypeError, ArithmeticError) as exc:
            if rows.size == 1:
                messages[rows[0]] = f"{chunk.where(int(rows[0]))}: {exc}"
                return
            half = rows.size // 2
            for part in (rows[:half], rows[half:]):
                self._solve_rows(part, chunk, values, presets, results, messages)
            return
        for name, column in results.items():
            solved = np.asarray(columns[name])
            column[rows] = solved if self.kinds[name] == "float" else solved.tolist()
        for i in rows:
            bad = [name for name, kind in self.kinds.items() if kind == "float"
                   and not np.isfinite(results[name][i])
                   and not (name in _MAY_BE_INFINITE and np.isinf(results[name][i]))
                   and not (name in _MAY_BE_NAN and np.isnan(results[name][i]))]  # fmt: skip
            if bad:
                messages[i] = (
                    f"{chunk.where(int(i))}: {bad[0]} is {float(results[bad[0]][i])!r}, "
                    "not a finite number: the row's numbers are too far apart in scale"
                )
                for name, column in results.items():
                    column[i] = np.nan if self.kinds[name] == "float" else None

    def _columns(self, v: dict, presets: dict) -> dict[str, np.ndarray]:
        def body(k: str) -> Body:
            return Body.from_columns(mass=v[f"mass{k}"], radius=v[f"radius{k}"],
                                     preset=presets[k], gyration=v[f"gyration{k}"])  # fmt: skip

        def vec(names: tuple[str, ...]) -> np.ndarray:
            return np.stack([v[c] for c in names], -1)

        surface = {"mu": v["mu"], "kappa": v["kappa"]}
        if self.pair:
            return solve_pair(body(""), body("2"), velocity1=vec(BALL[:3]), spin1=vec(BALL[3:]),
                              velocity2=vec(tuple(f"{c}2" for c in BALL[:3])),
                              spin2=vec(tuple(f"{c}2" for c in BALL[3:])), normal=vec(_NORMAL),
                              **surface).columns()  # fmt: skip
        plane = Surface(normal=vec(_NORMAL), velocity=vec(_SURFACE))
        return solve_sphere(body(""), vec(BALL[:3]), vec(BALL[3:]), surface=plane,
                            **surface).columns()  # fmt: skip


def run_sphere_batch(
    source: str | os.PathLike[str],
    output: str | os.PathLike[str],
    *,
    defaults: dict[str, Any] | None = None,
    pair: bool | None = None,
    on_error: str = "stop",
    chunk_size: int = 100_000,
    progress: Callable[[int, int], None] | None = None,
) -> SphereBatchSummary:
    """Solve every row of ``source`` (spheres or pairs) and write ``output``.

    Parameters
    ----------
    source : str or os.PathLike
        Input file, ``.csv``, ``.parquet`` or ``.pq``, with the columns of the module's
        description.
    output : str or os.PathLike
        Output file, ``.csv``, ``.parquet`` or ``.pq`` (Parquet fields name their units).
    defaults : dict, optional
        Values for optional columns a file lacks or leaves empty: ``mu``, ``kappa``,
        ``mass``, ``radius``, ``gyration`` or ``body`` (and ``mass2``, ... for ball 2),
        ``normal`` and ``surface_velocity`` (3-sequences). Without one, ``body`` is
        ``solid-sphere``, a sphere's normal ``(0, 1, 0)`` and its surface at rest;
        ``mu``, ``kappa``, the masses, the radii and a pair's normal must be given.
    pair : bool, optional
        ``True`` requires a file of pairs, ``False`` one of spheres; ``None`` (default):
        the columns decide (:func:`sphere_kind`).
    on_error : {"stop", "skip"}
        ``"stop"`` raises :class:`~spinimpact.io._tables.BatchError` naming the first
        bad row and writes nothing; ``"skip"`` writes bad rows with an ``error`` column.
    chunk_size : int
        Rows solved at a time; memory is bounded by it.
    progress : callable, optional
        ``progress(done, total)`` after each chunk: characters (CSV) or rows (Parquet).

    Returns
    -------
    SphereBatchSummary
        Rows read, rows skipped, the output path and the kind of file.

    Raises
    ------
    BatchError
        A bad row (its row, line and column named) or header.
    ValueError, TypeError
        A bad ``on_error`` or ``chunk_size``, a missing input, an unknown suffix, or an
        output that is the input.
    ImportError
        Parquet without pyarrow, naming the ``[parquet]`` extra.
    """
    source, output = Path(source), Path(output)
    if on_error not in ("stop", "skip"):
        raise ValueError(f"on_error must be 'stop' or 'skip', got {on_error!r}")
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, int | np.integer):
        raise TypeError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    if chunk_size < 1:
        raise ValueError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    if not source.is_file():
        raise ValueError(f"input file {str(source)!r} does not exist or is not a file")
    fmt_in, fmt_out = file_format(source, "input"), file_format(output, "output")
    if output.exists() and output.resolve() == source.resolve():
        raise ValueError("the output file must differ from the input file")
    skip = on_error == "skip"
    total = source.stat().st_size
    if fmt_in == "parquet":
        total = require("pyarrow.parquet", "Parquet files").ParquetFile(source).metadata.num_rows
    read = parquet_chunks if fmt_in == "parquet" else csv_chunks
    chunks = read(source, int(chunk_size), skip, lambda done: progress and progress(done, total))
    header = next(chunks)
    kind = sphere_kind(header)
    if pair is not None and pair != (kind == "pair"):
        has = "pairs of balls (columns vx2 ... wz2)" if kind == "pair" else "single spheres"
        use = (
            "pairs (spinimpact pair --batch)" if kind == "pair" else "spheres (... sphere --batch)"
        )
        raise BatchError(f"{source} holds {has}: solve it as {use}")
    plan = _Plan(kind, header, skip, defaults or {})
    rows = skipped = 0
    with atomic_path(output) as tmp:
        pyarrow = fmt_out == "parquet" or _have_pyarrow()
        sink: Any = (ArrowRows(tmp, header, plan.kinds, skip, fmt_out, plan.numeric) if pyarrow
                     else CsvRows(tmp, header, plan.kinds, skip))  # fmt: skip
        try:
            for chunk in chunks:
                _stop_check()  # a recorded SIGINT/SIGTERM stops the run between chunks
                values, results, messages = plan.solve(chunk)
                bad = messages != ""
                if bad.any() and not skip:
                    raise BatchError(messages[int(np.argmax(bad))])
                sink.write(chunk, values, results, messages)
                rows, skipped = rows + messages.size, skipped + int(bad.sum())
        finally:
            sink.close()
    return SphereBatchSummary(rows=rows, skipped=skipped, output=output, kind=kind)


def _have_pyarrow() -> bool:
    return available("pyarrow")
