"""Batch files: solve every row of a CSV (or Parquet) file of incidences, in chunks.

Columns ``vx, vy, omega`` are required; ``mu, kappa, mass, radius, gyration,
body`` are optional per row (an empty cell or a missing column takes the
default). The output holds the input columns and every scalar field of the
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

from ._validation import row_problems
from .io import atomic_path
from .model.body import PRESETS, Body
from .model.impact import Impact, solve

__all__ = ["RESULT_COLUMNS", "REQUIRED", "OPTIONAL", "BatchError", "BatchSummary", "run_batch"]

REQUIRED = ("vx", "vy", "omega")
OPTIONAL = ("mu", "kappa", "mass", "radius", "gyration", "body")
NUMERIC = ("vx", "vy", "omega", "mu", "kappa", "mass", "radius", "gyration")

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


def _where(row: int, column: str) -> str:
    return f"row {row} (line {row + 1}), column {column}"


def _numbers(name: str, cells: np.ndarray, first_row: int, default: Any, errors) -> np.ndarray:
    """Column of numbers from text or numeric cells.

    An empty cell takes ``default``; for the required columns (``default`` is
    ``None``) it is an error, except for ``gyration``, where it means "use the
    row's body preset" and is returned as NaN.
    """
    optional_nan = name == "gyration" and default is None
    if cells.dtype.kind in "iuf":
        values = cells.astype(float)
        empty = np.isnan(values) if optional_nan else np.zeros(values.shape, bool)
    else:
        text = np.char.strip(cells.astype(str))
        empty = text == ""
        values = np.full(text.size, np.nan)
        try:
            values[~empty] = text[~empty].astype(float)
        except ValueError:
            for i in np.flatnonzero(~empty):
                try:
                    values[i] = float(text[i])
                except ValueError:
                    errors(i, f"{_where(first_row + i, name)}: {str(text[i])!r} is not a number")
        if default is not None:
            values[empty] = default
        elif not optional_nan:
            for i in np.flatnonzero(empty):
                errors(i, f"{_where(first_row + i, name)}: empty, but {name} is required")
    problems = row_problems(name, values)
    for i in np.flatnonzero((problems != "") & ~empty):
        errors(i, f"{_where(first_row + i, name)}: {problems[i]}")
    return values


def _solve_chunk(
    columns: dict[str, np.ndarray], first_row: int, defaults: dict[str, Any], skip: bool
):
    """Solve one chunk. Returns (results by column, error message per row)."""
    n = len(next(iter(columns.values())))
    messages = np.full(n, "", dtype=object)

    def errors(i: int, message: str) -> None:
        if not skip:
            raise BatchError(message)
        if not messages[i]:
            messages[i] = message

    values = {}
    for name in NUMERIC:
        if name in columns:
            values[name] = _numbers(name, columns[name], first_row, defaults.get(name), errors)
        elif name == "gyration":
            values[name] = np.full(n, np.nan if defaults.get(name) is None else defaults[name])
        else:
            values[name] = np.full(n, float(defaults[name]))
    preset = np.full(n, defaults.get("body") or "", dtype=object)
    if "body" in columns:
        cells = np.char.strip(columns["body"].astype(str))
        given = cells != ""
        preset[given] = cells[given]
        values["gyration"][given & ("gyration" not in columns)] = np.nan
    custom = ~np.isnan(values["gyration"])
    for i in np.flatnonzero(~custom & ~np.isin(preset, list(PRESETS))):
        what = repr(str(preset[i])) if preset[i] else "nothing (no body and no gyration)"
        errors(
            i, f"{_where(first_row + i, 'body')}: must be one of {', '.join(PRESETS)}; got {what}"
        )

    good = messages == ""
    out: dict[str, np.ndarray] = {}
    if good.any():
        take = {k: v[good] for k, v in values.items()}
        body = Body.from_columns(
            mass=take["mass"],
            radius=take["radius"],
            preset=np.where(custom[good], "", preset[good]),
            gyration=take["gyration"],
        )
        imp = solve(body, take["vx"], take["vy"], take["omega"], mu=take["mu"], kappa=take["kappa"])
        for name, get in RESULT_COLUMNS.items():
            column = np.asarray(get(imp))
            if good.all():
                out[name] = column
            else:  # rows with errors get no results (None: an empty cell)
                out[name] = np.full(n, None, dtype=object)
                out[name][good] = column.tolist()
    else:
        out = {name: np.full(n, None, dtype=object) for name in RESULT_COLUMNS}
    return out, messages


def _cell(value: Any) -> Any:
    if isinstance(value, bool | np.bool_):
        return "true" if value else "false"
    return value


def _csv_chunks(path: Path, chunk_size: int, advance: Callable[[int], None]) -> Iterator:
    with open(path, newline="", encoding="utf-8") as f:

        def lines() -> Iterator[str]:
            for line in f:
                advance(len(line.encode("utf-8")))
                yield line

        reader = csv.reader(lines())
        try:
            header = [h.strip() for h in next(reader)]
        except StopIteration:
            raise BatchError(
                f"{path} is empty: expected a header with columns vx, vy, omega"
            ) from None
        yield header
        row = 1
        while True:
            rows = []
            for record in reader:
                if len(record) != len(header):
                    raise BatchError(
                        f"row {row + len(rows)} (line {row + len(rows) + 1}): expected "
                        f"{len(header)} fields, got {len(record)}"
                    )
                rows.append(record)
                if len(rows) == chunk_size:
                    break
            if not rows:
                return
            cells = np.array(rows, dtype=str).reshape(len(rows), len(header))
            yield row, {h: cells[:, j] for j, h in enumerate(header)}
            row += len(rows)


def _parquet_chunks(path: Path, chunk_size: int, advance: Callable[[int], None]) -> Iterator:
    import pyarrow.parquet as pq

    file = pq.ParquetFile(path)
    yield list(file.schema_arrow.names)
    row = 1
    for batch in file.iter_batches(batch_size=chunk_size):
        cols = {
            name: batch.column(name).to_numpy(zero_copy_only=False) for name in batch.schema.names
        }
        advance(batch.num_rows)
        yield row, cols
        row += batch.num_rows


def _is_parquet(path: Path) -> bool:
    return path.suffix.lower() in (".parquet", ".pq")


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
        ``"stop"`` raises :class:`BatchError` naming the first bad row and column,
        and writes nothing. ``"skip"`` writes bad rows with an ``error`` column
        and empty results.
    progress : callable, optional
        Called as ``progress(done, total)`` in bytes (CSV) or rows (Parquet).
    """
    source, output = Path(source), Path(output)
    if on_error not in ("stop", "skip"):
        raise ValueError(f"on_error must be 'stop' or 'skip', got {on_error!r}")
    if not isinstance(chunk_size, int) or chunk_size < 1:
        raise ValueError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    if not source.is_file():
        raise ValueError(f"input file {str(source)!r} does not exist")
    if source.resolve() == output.resolve():
        raise ValueError("the output file must differ from the input file")
    parquet_in, parquet_out = _is_parquet(source), _is_parquet(output)
    if parquet_in or parquet_out:
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise ValueError(
                "Parquet needs the optional extra: pip install 'spinimpact[parquet]'"
            ) from None
    done = 0
    total = source.stat().st_size
    if parquet_in:
        import pyarrow.parquet as pq

        total = pq.ParquetFile(source).metadata.num_rows

    def advance(amount: int) -> None:
        nonlocal done
        done += amount
        if progress is not None:
            progress(done, total)

    chunks = (_parquet_chunks if parquet_in else _csv_chunks)(source, chunk_size, advance)
    header = next(chunks)
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        raise BatchError(f"missing column {missing[0]!r}: the input needs columns vx, vy, omega")
    skip = on_error == "skip"
    names = header + [c for c in RESULT_COLUMNS if c not in header] + (["error"] if skip else [])
    rows = skipped = 0
    with atomic_path(output) as tmp:
        writer = _ParquetSink(tmp) if parquet_out else _CsvSink(tmp, names)
        try:
            for first_row, columns in chunks:
                results, messages = _solve_chunk(columns, first_row, defaults, skip)
                table = {h: columns[h] for h in header}
                table.update({k: v for k, v in results.items() if k not in header})
                if skip:
                    table["error"] = messages
                writer.write(names, table)
                rows += len(messages)
                skipped += int((messages != "").sum())
        finally:
            writer.close()
    return BatchSummary(rows=rows, skipped=skipped, output=output)


class _CsvSink:
    def __init__(self, path: Path, names: list[str]) -> None:
        self.file = open(path, "w", newline="", encoding="utf-8")
        self.writer = csv.writer(self.file)
        self.writer.writerow(names)

    def write(self, names: list[str], table: dict[str, np.ndarray]) -> None:
        columns = []
        for name in names:
            col = table[name]
            values = col.tolist()
            if col.dtype.kind == "b":
                values = ["true" if v else "false" for v in values]
            elif col.dtype == object:
                values = ["" if v is None else _cell(v) for v in values]
            columns.append(values)
        self.writer.writerows(zip(*columns, strict=True))

    def close(self) -> None:
        self.file.close()


class _ParquetSink:
    def __init__(self, path: Path) -> None:
        self.path, self.writer = path, None

    def write(self, names: list[str], table: dict[str, np.ndarray]) -> None:
        import pyarrow as pa
        import pyarrow.parquet as pq

        arrays = {}
        for name in names:
            col = table[name]
            if col.dtype == object:  # results missing on error rows, or text
                kinds = {type(v) for v in col if v is not None}
                if kinds <= {float, np.float64, int}:
                    col = np.array([np.nan if v is None else v for v in col], dtype=float)
                elif kinds <= {bool, np.bool_}:
                    arrays[name] = pa.array(
                        [None if v is None else bool(v) for v in col], pa.bool_()
                    )
                    continue
                else:
                    col = np.array(["" if v is None else str(v) for v in col], dtype=object)
            arrays[name] = pa.array(col)
        batch = pa.table(arrays)
        if self.writer is None:
            self.writer = pq.ParquetWriter(self.path, batch.schema)
        self.writer.write_table(batch.cast(self.writer.schema))

    def close(self) -> None:
        if self.writer is not None:
            self.writer.close()
