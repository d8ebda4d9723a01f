"""Readers of batch input: a CSV or Parquet file as a header, then chunks of rows.

Each reader is a generator that first yields the header (a list of column names)
and then one :class:`Chunk` per ``chunk_size`` rows, so memory stays bounded by
the chunk whatever the file size. :func:`check_header` and :func:`chunk_numbers`
are what every kind of batch file (the paper's bodies, planar bodies, pendulums)
does with them: check the header, and read a column's cells as numbers, naming
the row, line and column of each bad cell.
"""

from __future__ import annotations

import contextlib
import csv
import io
import re
import sys
from collections.abc import Callable, Collection, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import require, row_problems
from .._words import count

__all__ = [
    "SUFFIXES",
    "BatchError",
    "Chunk",
    "RowNotes",
    "check_header",
    "chunk_numbers",
    "column_or_default",
    "csv_chunks",
    "file_format",
    "parquet_chunks",
]

#: Accepted file suffixes and their formats.
SUFFIXES = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}


class BatchError(ValueError):
    """A row or the header of a batch input cannot be used; the message names where."""


@dataclass
class Chunk:
    """Rows ``first .. first + n - 1`` of the input."""

    first: int  #: 1-based number of the first data row
    columns: dict[str, np.ndarray]  #: input cells: str (CSV) or typed (Parquet)
    empty: dict[str, np.ndarray]  #: True where a cell is empty / null
    lines: np.ndarray | None  #: CSV line number of each row (None for Parquet)
    messages: np.ndarray  #: problems found while reading ('' where none)
    arrow: dict[str, Any] | None = None  #: Parquet input: the typed columns, passed through
    #: CSV input read by pyarrow (:mod:`spinimpact.io._arrow_csv`): the stripped text
    #: cells as Arrow string arrays, passed through to Arrow output
    text: dict[str, Any] | None = None
    #: With ``text``: ``numbers(name) -> (values, rest)``, the plain numbers read by Arrow
    #: (NaN elsewhere) and the indices of non-empty cells left to :func:`chunk_numbers`
    numbers: Callable[[str], tuple[np.ndarray, np.ndarray]] | None = None

    def where(self, i: int, column: str | None = None) -> str:
        """``"row 5 (line 6), column vy"``: where row ``i`` of the chunk is in the file."""
        line = f" (line {self.lines[i]})" if self.lines is not None else ""
        return f"row {self.first + i}{line}" + (f", column {column}" if column else "")


def file_format(path: Path, role: str) -> str:
    """The format of ``path`` by its suffix (see :data:`SUFFIXES`).

    Parameters
    ----------
    path : pathlib.Path
        The file.
    role : str
        ``"input"`` or ``"output"``, for the message.

    Returns
    -------
    str
        ``"csv"`` or ``"parquet"``.

    Raises
    ------
    ValueError
        For any other suffix.
    """
    fmt = SUFFIXES.get(path.suffix.lower())
    if fmt is None:
        raise ValueError(f"the {role} file must end in .csv, .parquet or .pq, got {str(path)!r}")
    return fmt


def csv_chunks(
    path: Path, chunk_size: int, skip: bool, advance: Callable[[int], None]
) -> Iterator[Any]:
    """The header, then chunks of rows of a CSV file (text cells, stripped).

    Parameters
    ----------
    path : pathlib.Path
        A UTF-8 CSV file (a byte-order mark is allowed) with a header line; ``-`` is
        standard input.
    chunk_size : int
        Rows per chunk.
    skip : bool
        Whether a row with the wrong number of fields is kept, padded, with its
        problem in :attr:`Chunk.messages` (``True``) or stops the run (``False``).
    advance : callable
        Called with the number of characters read so far, after each chunk.

    Raises
    ------
    BatchError
        For an empty file, or (``skip=False``) a row of the wrong length, naming
        its row and line.
    """
    size = 0

    def lines(f: Any) -> Iterator[str]:
        nonlocal size
        for line in f:
            size += len(line)
            yield line

    with _text_input(path) as f:
        reader = csv.reader(lines(f))
        try:
            header = [h.strip() for h in _records(reader, "the header (line 1)")[0]]
        except IndexError:
            raise BatchError(
                f"{path} is empty: expected a header with columns vx, vy, omega"
            ) from None
        yield header
        first = 1
        while True:
            rows, numbers, problems = [], [], []
            while True:
                where = f"row {first + len(rows)} (line {reader.line_num + 1})"
                record = _records(reader, where)
                if not record:
                    break
                record = record[0]
                if not record or (len(record) == 1 and not record[0].strip()):
                    continue  # blank line
                where = f"row {first + len(rows)} (line {reader.line_num})"
                if len(record) != len(header):
                    message = f"{where}: expected {count(len(header), 'field')}, got {len(record)}"
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
            columns = _text_columns(header, rows)
            empty = {h: c == "" for h, c in columns.items()}
            advance(size)
            yield Chunk(first, columns, empty, np.array(numbers), np.array(problems, dtype=object))
            first += len(rows)


def _records(reader: Any, where: str) -> list[list[str]]:
    """``[the next record]`` of the csv ``reader``, ``[]`` at the end; a field longer than
    the csv module takes is a :class:`BatchError` naming ``where`` it starts."""
    try:
        return [next(reader)]
    except StopIteration:
        return []
    except csv.Error as err:
        if "field limit" not in str(err):
            raise BatchError(f"{where}: {err}") from None
        raise BatchError(
            f"{where}: a field longer than {csv.field_size_limit():,} characters, the most a "
            'CSV field may hold here: is a quote (") left open?'
        ) from None


@contextlib.contextmanager
def _text_input(path: Path) -> Iterator[Any]:
    """``path`` opened as UTF-8 text for the csv module; ``-``: standard input, left open."""
    if str(path) != "-":
        with open(path, newline="", encoding="utf-8-sig") as f:
            yield f
        return
    buffer = getattr(sys.stdin, "buffer", None)
    if buffer is None:  # a text stream that is not a file (tests, embedding)
        yield sys.stdin
        return
    f = io.TextIOWrapper(buffer, encoding="utf-8-sig", newline="")
    try:
        yield f
    finally:
        f.detach()


def _text_columns(header: list[str], rows: list[list[str]]) -> dict[str, np.ndarray]:
    """The rows' stripped cells by column, as arrays of Python strings.

    Object arrays hold each cell at its own length; a fixed-width ``str`` array would
    give every cell the longest cell's width (one 10,000-character cell in 100,000
    rows: 4 GB), and would drop a trailing NUL character.
    """
    columns = {}
    for name, cells in zip(header, zip(*rows, strict=True), strict=True):
        column = np.empty(len(rows), dtype=object)
        column[:] = [c.strip() for c in cells]
        columns[name] = column
    return columns


def parquet_chunks(
    path: Path, chunk_size: int, skip: bool, advance: Callable[[int], None]
) -> Iterator[Any]:
    """The header, then chunks of rows of a Parquet file (typed cells, nulls marked empty).

    Same parameters as :func:`csv_chunks`; ``advance`` gets the number of rows read.

    Raises
    ------
    ImportError
        Without pyarrow, naming the ``[parquet]`` extra.
    """
    pq = require("pyarrow.parquet", "Parquet files")
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
        yield Chunk(first, columns, empty, None, np.full(batch.num_rows, "", dtype=object), arrow)
        first += batch.num_rows


def check_header(
    header: list[str], skip: bool, outputs: Collection[str], required: Sequence[str]
) -> None:
    """Raise :class:`BatchError` for a header the run cannot use.

    Parameters
    ----------
    header : list of str
        The input's column names.
    skip : bool
        Whether an ``error`` column will be written (so an input may not have one).
    outputs : collection of str
        The output columns the run adds: no input column may carry their names.
    required : sequence of str
        Columns the input must have.

    Raises
    ------
    BatchError
        For a duplicate column, an input column named as an output column, or a
        missing required column (the message lists what was found).
    """
    seen: set[str] = set()
    for name in header:
        if name in seen:
            raise BatchError(f"duplicate column {name!r} in the header")
        seen.add(name)
        if name in outputs or (skip and name == "error"):
            raise BatchError(f"input column {name!r} has the name of an output column; rename it")
    missing = [c for c in required if c not in header]
    if missing:
        found = ", ".join(repr(h) for h in header[:8])
        raise BatchError(
            f"missing column {missing[0]!r}: the input needs columns {', '.join(required)} "
            f"(found {found}; is the file comma-separated?)"
        )


class RowNotes:
    """What is wrong with a chunk's rows, noted as it is found: ``note(i, message)``; then
    :meth:`messages` keeps each row's first problem, in row order."""

    def __init__(self) -> None:
        self.found: list[tuple[int, str]] = []

    def __call__(self, i: int, message: str) -> None:
        self.found.append((i, message))

    def messages(self, chunk: Chunk) -> np.ndarray:
        """The chunk's reading messages, then for each row without one the first noted."""
        out = chunk.messages.copy()
        for i, message in sorted(self.found, key=lambda item: item[0]):
            out[i] = out[i] or message
        return out


def column_or_default(
    chunk: Chunk,
    name: str,
    default: Any,
    note: Callable[[int, str], None],
    problems: Callable[[np.ndarray], np.ndarray] | None = None,
    required: bool = True,
) -> np.ndarray:
    """Column ``name`` of ``chunk`` read by :func:`chunk_numbers`, or, where the file has no
    such column, ``default`` (NaN for ``None``) viewed for every row (read-only, no copies)."""
    if name in chunk.columns:
        return chunk_numbers(chunk, name, default, note, problems, required=required)
    value = np.float64(np.nan if default is None else float(default))
    return np.broadcast_to(value, (chunk.messages.size,))


def chunk_numbers(
    chunk: Chunk,
    name: str,
    default: Any,
    note: Callable[[int, str], None],
    problems: Callable[[np.ndarray], np.ndarray] | None = None,
    required: bool = True,
) -> np.ndarray:
    """Column ``name`` of ``chunk`` as float64, each bad cell reported through ``note``.

    Parameters
    ----------
    chunk : Chunk
        The rows.
    name : str
        The column (it must be in ``chunk.columns``).
    default : float or None
        The value of an empty cell; ``None``: NaN, and (if ``required``) a problem.
    note : callable
        Called as ``note(i, message)`` for each problem of row ``i`` of the chunk; the
        message names the row, its line and the column.
    problems : callable, optional
        ``values -> messages`` ('' where a value is good), the rules of the column; by
        default :func:`~spinimpact._validation.row_problems` of ``name``. Empty cells
        without a default are not checked by it.
    required : bool
        Whether an empty cell without a default is a problem.

    Returns
    -------
    numpy.ndarray
        The numbers (NaN where a cell is empty without default or unreadable).
    """
    if chunk.numbers is not None:  # text read by Arrow: its numbers first (a column of
        values = _plain_numbers(chunk, name, None, None, note)  # numbers alone then has
        empty = chunk.empty[name]  # its empty cells at no cost)
    else:
        values, empty = _typed_numbers(chunk, name, note)
    if default is not None:
        values[empty] = default
    elif required:
        for i in np.flatnonzero(empty):
            note(i, f"{chunk.where(i, name)}: empty, but {name} is required")
    found = row_problems(name, values) if problems is None else problems(values)
    check = (found != "") & ~(empty & np.isnan(values))
    for i in np.flatnonzero(check):
        note(i, f"{chunk.where(i, name)}: {found[i]}")
    return values


def _typed_numbers(
    chunk: Chunk, name: str, note: Callable[[int, str], None]
) -> tuple[np.ndarray, np.ndarray]:
    """Column ``name`` of a chunk read by Python or from Parquet, as float64 (NaN where
    empty), and its empty cells."""
    empty, cells = chunk.empty[name], chunk.columns[name]
    if cells.dtype.kind in "iuf":
        return np.where(empty, np.nan, cells.astype(np.float64)), empty
    if cells.dtype.kind == "b":
        for i in np.flatnonzero(~empty):
            note(i, f"{chunk.where(i, name)}: a true/false value is not a number")
        return np.full(cells.shape, np.nan), empty
    return _plain_numbers(chunk, name, cells, empty, note), empty


#: A plain number: ASCII digits with an optional sign, point and exponent, or inf/nan
#: (reported by the column's rules). Python's ``float`` also reads ``1_000``, Arabic-Indic
#: and other Unicode digits; a CSV cell holding them is refused rather than reinterpreted.
_PLAIN = re.compile(
    r"[+-]?(?:(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?|inf(?:inity)?|nan)",
    re.IGNORECASE,
)
_SHOWN = 40  # characters of a bad cell quoted in a message


def _plain_numbers(
    chunk: Chunk,
    name: str,
    cells: np.ndarray | None,
    empty: np.ndarray | None,
    note: Callable[[int, str], None],
) -> np.ndarray:
    """Text cells as float64, NaN where empty; each cell that is not a plain number noted.

    ``cells`` (and ``empty``) are ``None`` for text read by Arrow (``chunk.numbers``): only
    the cells it did not read as numbers are then taken from ``chunk.columns``.
    """
    if cells is None and chunk.numbers is not None:
        values, given = chunk.numbers(name)
        cells = chunk.columns[name] if given.size else np.empty(0, dtype=object)
    else:
        assert cells is not None and empty is not None
        values, given = np.full(empty.shape, np.nan), np.flatnonzero(~empty)
    text = [(c if isinstance(c, str) else str(c)).strip() for c in cells[given].tolist()]
    if all(map(_PLAIN.fullmatch, text)):
        values[given] = np.fromiter(map(float, text), np.float64, count=len(text))
        return values
    for i, cell in zip(given.tolist(), text, strict=True):
        if _PLAIN.fullmatch(cell):
            values[i] = float(cell)
            continue
        shown = repr(cell if len(cell) <= _SHOWN else cell[:_SHOWN] + "...")
        more = f" ({len(cell)} characters)" if len(cell) > _SHOWN else ""
        note(i, f"{chunk.where(i, name)}: {shown}{more} is not a number")
    return values
