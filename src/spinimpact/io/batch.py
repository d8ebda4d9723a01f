"""Batch files: solve every row of a CSV (or Parquet) file of incidences, in chunks.

Columns ``vx, vy, omega`` are required; ``mu, kappa, mass, radius, gyration,
body`` are optional per row (an empty cell, a Parquet null or a missing column
takes the default; a row gives either a ``body`` preset or a ``gyration``). The
output holds the input columns and every scalar field of the
:class:`~spinimpact.Impact` (see :data:`RESULT_COLUMNS`). Memory stays bounded
by the chunk size, whatever the file size. Output goes to a temporary file that
is renamed only when the whole run succeeded.
"""

from __future__ import annotations

import csv
import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import row_problems
from ..model.body import PRESETS, Body
from ..model.impact import Impact, solve
from .atomic import atomic_path

__all__ = [
    "RESULT_COLUMNS",
    "REQUIRED",
    "OPTIONAL",
    "SUFFIXES",
    "BatchError",
    "BatchSummary",
    "run_batch",
]

REQUIRED = ("vx", "vy", "omega")
OPTIONAL = ("mu", "kappa", "mass", "radius", "gyration", "body")
NUMERIC = ("vx", "vy", "omega", "mu", "kappa", "mass", "radius", "gyration")
#: Accepted file suffixes and their formats.
SUFFIXES = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}

_TEXT = ("regime", "min_energy_case")
_FLAGS = ("backward", "reversed_spin", "vertical", "spinning", "rolling")

#: Output column -> how to read it from an Impact.
RESULT_COLUMNS: dict[str, Callable[[Impact], Any]] = {
    "regime": lambda i: i.regime,
    "zeta": lambda i: np.broadcast_to(i.body.zeta, i.shape),
    "after_vx": lambda i: i.after.vx,
    "after_vy": lambda i: i.after.vy,
    "after_omega": lambda i: i.after.omega,
    "slip_before": lambda i: i.slip_before,
    "slip_after": lambda i: i.slip_after,
    "incidence_ratio": lambda i: i.incidence_ratio,
    "tau0": lambda i: i.tau0,
    "tau_star": lambda i: i.tau_star,
    "tau1": lambda i: i.tau1,
    "tangential_impulse": lambda i: i.tangential_impulse,
    "impulse_ratio": lambda i: i.impulse_ratio,
    "kinetic_energy_before": lambda i: i.kinetic_energy_before,
    "kinetic_energy_after": lambda i: i.kinetic_energy_after,
    "dissipated_energy": lambda i: i.dissipated_energy,
    "work_compression_normal": lambda i: i.work_compression_normal,
    "work_compression_tangential": lambda i: i.work_compression_tangential,
    "work_restitution_normal": lambda i: i.work_restitution_normal,
    "work_restitution_tangential": lambda i: i.work_restitution_tangential,
    "work_ratio_tangential": lambda i: i.work_ratio_tangential,
    "min_kinetic_energy": lambda i: i.min_kinetic_energy,
    "tau_min_energy": lambda i: i.tau_min_energy,
    "min_energy_case": lambda i: i.min_energy_case,
    "newton_restitution": lambda i: i.newton_restitution,
    "poisson_restitution": lambda i: i.poisson_restitution,
    "energetic_restitution": lambda i: i.energetic_restitution,
    "backward": lambda i: i.outcome.backward,
    "reversed_spin": lambda i: i.outcome.reversed_spin,
    "vertical": lambda i: i.outcome.vertical,
    "spinning": lambda i: i.outcome.spinning,
    "rolling": lambda i: i.outcome.rolling,
}


class BatchError(ValueError):
    """A row of the input cannot be used; the message names the row and column."""


@dataclass(frozen=True)
class BatchSummary:
    rows: int  #: data rows read
    skipped: int  #: rows written with an error instead of results (``on_error="skip"``)
    output: Path


@dataclass
class _Chunk:
    """Rows ``first .. first + n - 1`` of the input."""

    first: int  #: 1-based number of the first data row
    columns: dict[str, np.ndarray]  #: input cells: str (CSV) or typed (Parquet)
    empty: dict[str, np.ndarray]  #: True where a cell is empty / null
    lines: np.ndarray | None  #: CSV line number of each row (None for Parquet)
    messages: np.ndarray  #: problems found while reading ('' where none)
    arrow: dict[str, Any] | None = None  #: Parquet input: the typed columns, passed through


def _where(chunk: _Chunk, i: int, column: str | None) -> str:
    row = chunk.first + i
    line = f" (line {chunk.lines[i]})" if chunk.lines is not None else ""
    return f"row {row}{line}" + (f", column {column}" if column else "")


def _numbers(
    chunk: _Chunk, name: str, default: Any, note: Callable[[int, str], None]
) -> np.ndarray:
    """Column ``name`` as float64; empty cells take ``default`` (NaN if None)."""
    cells, empty = chunk.columns[name], chunk.empty[name]
    if cells.dtype.kind in "iuf":
        values = np.where(empty, np.nan, cells.astype(np.float64))
    elif cells.dtype.kind == "b":
        for i in np.flatnonzero(~empty):
            note(i, f"{_where(chunk, i, name)}: a true/false value is not a number")
        values = np.full(cells.shape, np.nan)
    else:
        text = cells.astype(str)
        values = np.full(text.shape, np.nan)
        try:
            values[~empty] = text[~empty].astype(np.float64)
        except ValueError:
            for i in np.flatnonzero(~empty):
                try:
                    values[i] = float(text[i])
                except ValueError:
                    note(i, f"{_where(chunk, i, name)}: {str(text[i])!r} is not a number")
    if default is not None:
        values[empty] = default
    elif name != "gyration":  # an empty gyration means "use the row's body"
        for i in np.flatnonzero(empty):
            note(i, f"{_where(chunk, i, name)}: empty, but {name} is required")
    problems = row_problems(name, values)
    check = (problems != "") & ~(empty & np.isnan(values))
    for i in np.flatnonzero(check):
        note(i, f"{_where(chunk, i, name)}: {problems[i]}")
    return values


def _solve_chunk(chunk: _Chunk, defaults: dict[str, Any]):
    """Solve one chunk. Returns (results by column, error message per row)."""
    messages = chunk.messages.copy()
    n = messages.size
    found: list[tuple[int, str]] = []

    def note(i: int, message: str) -> None:
        found.append((i, message))

    values = {}
    for name in NUMERIC:
        if name in chunk.columns:
            values[name] = _numbers(chunk, name, defaults.get(name), note)
        else:
            default = defaults.get(name)
            values[name] = np.full(n, np.nan if default is None else float(default))
    preset = np.full(n, defaults.get("body") or "", dtype=object)
    if "body" in chunk.columns:
        given = ~chunk.empty["body"]
        cells = chunk.columns["body"]
        names = np.array(["" if c is None else str(c).strip() for c in cells], dtype=object)
        preset[given] = names[given]
        own_gyration = (
            ~chunk.empty["gyration"] if "gyration" in chunk.columns else np.zeros(n, bool)
        )
        for i in np.flatnonzero(given & own_gyration):
            note(i, f"{_where(chunk, i, 'body')}: give either body or gyration, not both")
        values["gyration"][given & ~own_gyration] = np.nan  # the row's preset wins
    custom = ~np.isnan(values["gyration"])
    for i in np.flatnonzero(~custom & ~np.isin(preset, list(PRESETS))):
        what = repr(str(preset[i])) if preset[i] else "nothing (no body and no gyration)"
        note(i, f"{_where(chunk, i, 'body')}: must be one of {', '.join(PRESETS)}; got {what}")
    for i, message in sorted(found, key=lambda item: item[0]):
        if not messages[i]:
            messages[i] = message
    good = messages == ""
    if good.any():
        take = {k: v[good] for k, v in values.items()}
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            body = Body.from_columns(
                mass=take["mass"],
                radius=take["radius"],
                preset=np.where(custom[good], "", preset[good]),
                gyration=take["gyration"],
            )
            imp = solve(
                body, take["vx"], take["vy"], take["omega"], mu=take["mu"], kappa=take["kappa"]
            )
    results = {}
    for name, get in RESULT_COLUMNS.items():
        if name in _TEXT or name in _FLAGS:  # str or bool; None on error rows
            column = np.full(n, None, dtype=object)
            if good.any():
                column[good] = np.asarray(get(imp)).tolist()
        else:
            column = np.full(n, np.nan)
            if good.any():
                column[good] = get(imp)
        results[name] = column
    return values, results, messages


def _csv_chunks(
    path: Path, chunk_size: int, skip: bool, advance: Callable[[int], None]
) -> Iterator:
    size = 0

    def lines(f) -> Iterator[str]:
        nonlocal size
        for line in f:
            size += len(line)
            yield line

    with open(path, newline="", encoding="utf-8-sig") as f:
        reader = csv.reader(lines(f))
        try:
            header = [h.strip() for h in next(reader)]
        except StopIteration:
            raise BatchError(
                f"{path} is empty: expected a header with columns vx, vy, omega"
            ) from None
        yield header
        first = 1
        while True:
            rows, numbers, problems = [], [], []
            for record in reader:
                if not record or (len(record) == 1 and not record[0].strip()):
                    continue  # blank line
                where = f"row {first + len(rows)} (line {reader.line_num})"
                if len(record) != len(header):
                    message = f"{where}: expected {len(header)} fields, got {len(record)}"
                    if not skip:
                        raise BatchError(message)
                    record = (record + [""] * len(header))[: len(header)]
                    problems.append(message)
                else:
                    problems.append("")
                rows.append(record)
                numbers.append(reader.line_num)
                if len(rows) == chunk_size:
                    break
            if not rows:
                advance(size)
                return
            cells = np.array(rows, dtype=str).reshape(len(rows), len(header))
            columns = {h: cells[:, j] for j, h in enumerate(header)}
            empty = {h: np.char.strip(c) == "" for h, c in columns.items()}
            columns = {h: np.char.strip(c) for h, c in columns.items()}
            advance(size)
            yield _Chunk(first, columns, empty, np.array(numbers), np.array(problems, dtype=object))
            first += len(rows)


def _parquet_chunks(
    path: Path, chunk_size: int, skip: bool, advance: Callable[[int], None]
) -> Iterator:
    import pyarrow.parquet as pq

    file = pq.ParquetFile(path)
    yield list(file.schema_arrow.names)
    first, done = 1, 0
    for batch in file.iter_batches(batch_size=chunk_size):
        columns, empty, arrow = {}, {}, {}
        for j, name in enumerate(batch.schema.names):
            col = batch.column(j)
            arrow[name] = col
            empty[name] = col.is_null().to_numpy(zero_copy_only=False)
            columns[name] = col.to_numpy(zero_copy_only=False)
        done += batch.num_rows
        advance(done)
        yield _Chunk(first, columns, empty, None, np.full(batch.num_rows, "", dtype=object), arrow)
        first += batch.num_rows


def _have_pyarrow() -> bool:
    try:
        import pyarrow.csv  # noqa: F401
    except ImportError:
        return False
    return True


def _format(path: Path, role: str) -> str:
    fmt = SUFFIXES.get(path.suffix.lower())
    if fmt is None:
        raise ValueError(f"the {role} file must end in .csv, .parquet or .pq, got {str(path)!r}")
    return fmt


def run_batch(
    source: str | os.PathLike[str],
    output: str | os.PathLike[str],
    *,
    defaults: dict[str, Any],
    on_error: str = "stop",
    chunk_size: int = 100_000,
    progress: Callable[[int, int], None] | None = None,
) -> BatchSummary:
    """Solve every row of ``source`` and write ``output`` (CSV, or Parquet by suffix).

    Parameters
    ----------
    defaults : dict
        Values for the optional columns where a file lacks them: ``mu``,
        ``kappa``, ``mass``, ``radius`` and either ``body`` (a preset name) or
        ``gyration``.
    on_error : {"stop", "skip"}
        ``"stop"`` raises :class:`BatchError` naming the first bad row (and its
        line and column) and writes nothing. ``"skip"`` writes bad rows with an
        ``error`` column and empty results.
    progress : callable, optional
        Called after each chunk as ``progress(done, total)``: characters (CSV)
        or rows (Parquet).
    """
    source, output = Path(source), Path(output)
    if on_error not in ("stop", "skip"):
        raise ValueError(f"on_error must be 'stop' or 'skip', got {on_error!r}")
    if not isinstance(chunk_size, int | np.integer) or chunk_size < 1:
        raise ValueError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    if not source.is_file():
        raise ValueError(f"input file {str(source)!r} does not exist or is not a file")
    fmt_in, fmt_out = _format(source, "input"), _format(output, "output")
    if output.exists() and output.resolve() == source.resolve():
        raise ValueError("the output file must differ from the input file")
    if "parquet" in (fmt_in, fmt_out):
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise ValueError(
                "Parquet needs the optional extra: pip install 'spinimpact[parquet]'"
            ) from None
    skip = on_error == "skip"
    total = source.stat().st_size
    if fmt_in == "parquet":
        import pyarrow.parquet as pq

        total = pq.ParquetFile(source).metadata.num_rows

    def advance(done: int) -> None:
        if progress is not None:
            progress(done, total)

    chunks = (_parquet_chunks if fmt_in == "parquet" else _csv_chunks)(
        source, chunk_size, skip, advance
    )
    header = next(chunks)
    seen: set[str] = set()
    for name in header:
        if name in seen:
            raise BatchError(f"duplicate column {name!r} in the header")
        seen.add(name)
        if name in RESULT_COLUMNS or (skip and name == "error"):
            raise BatchError(f"input column {name!r} has the name of an output column; rename it")
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        found = ", ".join(repr(h) for h in header[:8])
        raise BatchError(
            f"missing column {missing[0]!r}: the input needs columns vx, vy, omega "
            f"(found {found}; is the file comma-separated?)"
        )
    rows = skipped = 0
    with atomic_path(output) as tmp:
        if fmt_out == "parquet" or _have_pyarrow():
            sink = _ArrowSink(tmp, header, skip, fmt_out)
        else:
            sink = _CsvSink(tmp, header, skip)
        try:
            for chunk in chunks:
                values, results, messages = _solve_chunk(chunk, defaults)
                bad = messages != ""
                if bad.any() and not skip:
                    raise BatchError(messages[int(np.argmax(bad))])
                sink.write(chunk, values, results, messages)
                rows += messages.size
                skipped += int(bad.sum())
        finally:
            sink.close()
    return BatchSummary(rows=rows, skipped=skipped, output=output)


class _CsvSink:
    """CSV output with Python's csv module (used when pyarrow is not installed)."""

    def __init__(self, path: Path, header: list[str], skip: bool) -> None:
        self.file = open(path, "w", newline="", encoding="utf-8")
        self.writer = csv.writer(self.file)
        self.header, self.skip = header, skip
        self.writer.writerow(header + list(RESULT_COLUMNS) + (["error"] if skip else []))

    def write(self, chunk: _Chunk, values, results, messages) -> None:
        good = messages == ""
        columns = []
        for name in self.header:
            cells = chunk.columns[name]
            if cells.dtype.kind in "US":
                columns.append(cells.tolist())
            else:  # Parquet input: typed cells, nulls empty
                text = [repr(c) if isinstance(c, float) else str(c) for c in cells.tolist()]
                columns.append(
                    np.where(chunk.empty[name], "", np.array(text, dtype=object)).tolist()
                )
        for name, column in results.items():
            if column.dtype.kind == "f":  # shortest round-trip text (repr)
                text = list(map(float.__repr__, column.tolist()))
                columns.append(text if good.all() else np.where(good, text, "").tolist())
            elif name in _FLAGS:
                columns.append(["" if v is None else ("true" if v else "false") for v in column])
            else:
                columns.append(["" if v is None else v for v in column])
        if self.skip:
            columns.append(messages.tolist())
        self.writer.writerows(zip(*columns, strict=True))

    def close(self) -> None:
        self.file.close()


class _ArrowSink:
    """Parquet, or fast CSV, through pyarrow, with a fixed schema; missing values are nulls.

    CSV input columns are kept as text for CSV output and parsed to numbers for
    Parquet output; Parquet input columns keep their types. Floats are written
    in a shortest form that reads back to the same number.
    """

    def __init__(self, path: Path, header: list[str], skip: bool, fmt: str) -> None:
        self.path, self.header, self.skip, self.fmt = path, header, skip, fmt
        self.writer = self.schema = None

    def _schema(self, chunk: _Chunk | None):
        import pyarrow as pa

        fields = []
        for name in self.header:
            arrow = chunk.arrow if chunk is not None else None
            if arrow is not None:
                fields.append(pa.field(name, arrow[name].type))
            elif name in NUMERIC and self.fmt == "parquet":
                fields.append(pa.field(name, pa.float64()))
            else:
                fields.append(pa.field(name, pa.string()))
        for name in RESULT_COLUMNS:
            kind = (
                pa.string() if name in _TEXT else (pa.bool_() if name in _FLAGS else pa.float64())
            )
            fields.append(pa.field(name, kind))
        if self.skip:
            fields.append(pa.field("error", pa.string()))
        return pa.schema(fields)

    def _open(self, schema) -> None:
        self.schema = schema
        if self.fmt == "parquet":
            import pyarrow.parquet as pq

            self.writer = pq.ParquetWriter(self.path, schema)
        else:
            import pyarrow.csv as pc

            options = pc.WriteOptions(quoting_style="needed")
            self.writer = pc.CSVWriter(self.path, schema, write_options=options)

    def write(self, chunk: _Chunk, values, results, messages) -> None:
        import pyarrow as pa

        if self.writer is None:
            self._open(self._schema(chunk))
        schema = self.schema
        good = messages == ""
        arrays = []
        for field in schema:
            name = field.name
            if name in results:
                column = results[name]
                if column.dtype.kind == "f":
                    arrays.append(pa.array(column, field.type, mask=None if good.all() else ~good))
                else:
                    arrays.append(pa.array(column.tolist(), field.type))
            elif name == "error":
                arrays.append(pa.array([m or None for m in messages.tolist()], pa.string()))
            elif chunk.arrow is not None:
                arrays.append(chunk.arrow[name])
            elif field.type == pa.float64():  # parsed numbers; null where empty or unreadable
                v = values[name]
                arrays.append(pa.array(v, mask=chunk.empty[name] | np.isnan(v)))
            else:
                arrays.append(pa.array(chunk.columns[name], pa.string()))
        self.writer.write_table(pa.Table.from_arrays(arrays, schema=self.schema))

    def close(self) -> None:
        if self.writer is None:  # no rows: still a valid, empty file with the schema
            self._open(self._schema(None))
        self.writer.close()
