"""CSV batch input through pyarrow's reader: the chunks of :func:`~._tables.csv_chunks`, faster.

:func:`csv_chunks` yields what :func:`spinimpact.io._tables.csv_chunks` yields (the
header, then one :class:`~spinimpact.io._tables.Chunk` per ``chunk_size`` rows), with the
same cells, rows and messages, but parses the file with pyarrow's multi-threaded CSV
reader and reads the plain numbers with Arrow's string-to-float conversion (correctly
rounded, as Python's ``float`` is) instead of one Python object per cell:

* the cells are kept as text (Arrow ``string`` columns, stripped as ``str.strip`` strips
  them), so the output repeats them as the Python reader would;
* cells that are not plain ASCII numbers (``inf``, ``nan``, anything unreadable) go
  through the Python reader's own rules and messages
  (:func:`~spinimpact.io._tables.chunk_numbers`);
* line numbers, which only messages need, are counted by Python's csv module when a
  message first asks for one;
* anything the Arrow reader does not read as the csv module would (a row with the wrong
  number of fields, a line of blanks, text that is not UTF-8, a header over several
  lines) hands the rest of the file, from the first row not yet yielded, to the Python
  reader, which then reports or keeps it as it always has.

Standard input (``-``), or no pyarrow, is read by the Python reader throughout, and so is
any file under an address-space limit (``ulimit -v``): when an allocation fails in the
Arrow reader's read-ahead thread, ``pyarrow.csv.open_csv`` (pyarrow 26) waits forever for
that thread, which waits for itself, so a chunk too large for the limit hung the run
instead of stopping it with one line naming ``--chunk-size``.
"""

from __future__ import annotations

import csv
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from .._limits import address_limit
from .._validation import available
from . import _tables
from ._tables import Chunk

__all__ = ["chunk_head", "csv_chunks"]

#: Bytes Arrow reads per block: large enough to parse in parallel, small next to a chunk.
BLOCK_SIZE = 1 << 22
#: Plain numbers Arrow's conversion reads exactly as ``float`` does (``inf`` and ``nan``
#: are left to the Python rules): ASCII digits, optional sign, point and exponent.
_ARROW_PLAIN = r"^[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?$"
#: What ``str.strip`` strips: every character that ``str.isspace`` calls whitespace.
_WHITESPACE = "".join(c for c in map(chr, range(0x110000)) if c.isspace())
#: The characters of plain numbers: a cell of these alone that Arrow converts is one
#: that :data:`_ARROW_PLAIN` matches (``tests/io/test_arrow_csv.py``), found without a
#: regular expression.
_NUMBER_CHARS = "0123456789+-.eE"


class _Fallback(Exception):
    """The Arrow reader cannot read the rest of the file as the csv module would."""


def csv_chunks(
    path: Path, chunk_size: int, skip: bool, advance: Callable[[int], None]
) -> Iterator[Any]:
    """The header, then chunks of rows of a CSV file, as :func:`~._tables.csv_chunks`.

    Same parameters, results and errors; ``advance`` gets the bytes read so far.
    """
    if str(path) == "-" or not available("pyarrow") or address_limit() is not None:
        yield from _tables.csv_chunks(path, chunk_size, skip, advance)
        return
    header, simple = _header(path)
    if header is None or not simple:
        yield from _tables.csv_chunks(path, chunk_size, skip, advance)
        return
    yield header
    done = 0  # rows yielded so far
    try:
        for chunk in _arrow_chunks(path, header, chunk_size, advance):
            yield chunk
            done += len(chunk.messages)
    except _Fallback:
        rest = _tables.csv_chunks(path, chunk_size, skip, advance)
        next(rest)  # the header, read already
        yield from _skipped(rest, done, chunk_size)


def _header(path: Path) -> tuple[list[str] | None, bool]:
    """The stripped header as the csv module reads it, and whether it is one plain line."""
    with open(path, newline="", encoding="utf-8-sig") as f:
        reader = csv.reader(f)
        try:
            record = next(reader)
        except (StopIteration, UnicodeDecodeError):
            return None, False
        return [h.strip() for h in record], reader.line_num == 1 and bool(record)


def _skipped(chunks: Iterator[Chunk], done: int, chunk_size: int) -> Iterator[Chunk]:
    """The Python reader's chunks after its first ``done`` rows (``done`` is a whole
    number of chunks, so its chunks fall where the Arrow chunks would have)."""
    for chunk in chunks:
        if chunk.first > done:
            yield chunk


def _arrow_chunks(
    path: Path, header: list[str], chunk_size: int, advance: Callable[[int], None]
) -> Iterator[Chunk]:
    import pyarrow as pa
    import pyarrow.csv as pcsv

    names = [f"c{j}" for j in range(len(header))]

    def refuse(row: Any) -> str:
        return "error"  # a row the csv module reads otherwise: the Python reader takes over

    read = pcsv.ReadOptions(column_names=names, skip_rows=1, block_size=BLOCK_SIZE)
    parse = pcsv.ParseOptions(newlines_in_values=True, invalid_row_handler=refuse)
    convert = pcsv.ConvertOptions(
        column_types=dict.fromkeys(names, pa.string()),
        strings_can_be_null=False,
        quoted_strings_can_be_null=False,
    )
    first = 1
    counter = _LineCounter(path, chunk_size)
    with open(path, "rb") as f:
        try:
            reader = pcsv.open_csv(f, read_options=read, parse_options=parse,
                                   convert_options=convert)  # fmt: skip
            pending: list[Any] = []
            rows = 0
            for batch in _batches(reader):
                pending.append(batch)
                rows += batch.num_rows
                while rows >= chunk_size:
                    table = pa.Table.from_batches(pending)
                    yield _chunk(counter, header, table.slice(0, chunk_size), first)
                    advance(f.tell())
                    first += chunk_size
                    rest = table.slice(chunk_size)
                    pending, rows = rest.to_batches(), rest.num_rows
            if rows:
                yield _chunk(counter, header, pa.Table.from_batches(pending), first)
            advance(f.tell())
        except pa.ArrowInvalid as err:
            raise _Fallback from err


def _batches(reader: Any) -> Iterator[Any]:
    for batch in reader:
        if batch.num_rows:
            yield batch


def _chunk(counter: _LineCounter, header: list[str], table: Any, first: int) -> Chunk:
    n = table.num_rows
    source = _Source({name: table.column(j) for j, name in enumerate(header)})
    return Chunk(
        first,
        _Cells(source.text),
        source.empty,
        _Lines(counter, first, n),
        np.full(n, "", dtype=object),
        text=source.text,
        numbers=_Numbers(source),
    )


class _Made(Mapping):
    """A mapping whose values ``make(name)`` makes when first asked for (one per name of
    ``names``); ``made`` holds those made so far."""

    def __init__(self, make: Callable[[str], Any], names: list[str]) -> None:
        self.make, self.names, self.made = make, names, {}

    def __getitem__(self, name: str) -> Any:
        if name not in self.made:
            if name not in self.names:
                raise KeyError(name)
            self.made[name] = self.make(name)
        return self.made[name]

    def __contains__(self, name: object) -> bool:
        return name in self.names

    def __iter__(self) -> Iterator[str]:
        return iter(self.names)

    def __len__(self) -> int:
        return len(self.names)


class _Source:
    """A chunk's columns as Arrow read them, and, made on first use, each one's text
    (:func:`_stripped`) and empty cells (:func:`_is_empty`): a column of numbers alone,
    read in one cast by :class:`_Numbers`, needs neither."""

    def __init__(self, raw: dict[str, Any]) -> None:
        self.raw = raw
        self.text = _Made(self._text, list(raw))
        self.empty = _Made(self._empty, list(raw))

    def _text(self, name: str) -> Any:
        return _stripped(self.raw[name])

    def _empty(self, name: str) -> np.ndarray:
        return _is_empty(self.text[name])

    def head(self, m: int) -> _Source:
        """The first ``m`` rows, with what is made so far."""
        out = _Source({k: c.slice(0, m) for k, c in self.raw.items()})
        out.text.made = {k: t.slice(0, m) for k, t in self.text.made.items()}
        out.empty.made = {k: e[:m] for k, e in self.empty.made.items()}
        return out


def _stripped(column: Any) -> Any:
    """``column`` (a chunked string array) as one array of cells stripped as by ``str.strip``."""
    import pyarrow as pa
    import pyarrow.compute as pc

    col = column.combine_chunks() if isinstance(column, pa.ChunkedArray) else column
    return pc.utf8_trim(col, characters=_WHITESPACE)


def _is_empty(col: Any) -> np.ndarray:
    import pyarrow.compute as pc

    return pc.equal(pc.utf8_length(col), 0).to_numpy(zero_copy_only=False)


class _Cells(Mapping):
    """The text cells by column, as object arrays of ``str``, made when first asked for."""

    def __init__(self, text: Mapping[str, Any]) -> None:
        self.text = text
        self.made: dict[str, np.ndarray] = {}

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.made:
            column = np.empty(len(self.text[name]), dtype=object)
            column[:] = self.text[name].to_pylist()
            self.made[name] = column
        return self.made[name]

    def __contains__(self, name: object) -> bool:
        return name in self.text

    def __iter__(self) -> Iterator[str]:
        return iter(self.text)

    def __len__(self) -> int:
        return len(self.text)


class _Numbers:
    """``numbers(name)``: the column's plain numbers read by Arrow, and the rows left."""

    def __init__(self, source: _Source) -> None:
        self.source = source

    def __call__(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Float64 values (NaN where empty or not plain) and the indices of the non-empty
        cells that are not plain numbers (for the Python rules)."""
        import pyarrow as pa
        import pyarrow.compute as pc

        text, empty_ = self.source.text, self.source.empty
        if name not in text.made:  # the usual column: Arrow reads every cell as it is
            col = self.source.raw[name]
            col = col.combine_chunks() if isinstance(col, pa.ChunkedArray) else col
            try:
                values = np.array(pc.cast(col, pa.float64()).to_numpy(zero_copy_only=False))
            except pa.ArrowInvalid:
                pass  # an empty cell, blanks around a number, or no number: found below
            else:
                # each cell is a number, with nothing to strip: the text is the cell
                text.made[name] = col
                empty_.made[name] = np.zeros(len(col), bool)
                return self._finite(values)
        col, empty = text[name], empty_[name]
        if not empty.any():  # stripped, a column without empty cells may still cast whole
            try:
                values = np.array(pc.cast(col, pa.float64()).to_numpy(zero_copy_only=False))
            except pa.ArrowInvalid:
                pass  # a cell that is no number: found below
            else:
                return self._finite(values)
        plain = pc.and_(pc.equal(pc.utf8_trim(col, characters=_NUMBER_CHARS), ""),
                        pa.array(~empty))  # fmt: skip
        try:
            values = pc.cast(pc.if_else(plain, col, "0"), pa.float64())
        except pa.ArrowInvalid:  # a cell of number characters that is no number: "1e5e5"
            plain = pc.match_substring_regex(col, _ARROW_PLAIN)
            values = pc.cast(pc.if_else(plain, col, "0"), pa.float64())
        read = plain.to_numpy(zero_copy_only=False)
        values = values.to_numpy(zero_copy_only=False).copy()
        values[~read] = np.nan
        return values, np.flatnonzero(~read & ~empty)

    @staticmethod
    def _finite(values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A column Arrow cast whole: a finite number it read is a cell of digits, sign,
        point and exponent alone, read as the plain-number path reads it; ``inf``, ``nan``
        and overflows are left to the Python rules, as there."""
        odd = ~np.isfinite(values)
        values[odd] = np.nan
        return values, np.flatnonzero(odd)


class _LineCounter:
    """The csv module's line numbers of a file's rows, chunk by chunk, read on demand
    (once, front to back: chunks ask in order)."""

    def __init__(self, path: Path, chunk_size: int) -> None:
        self.path, self.chunk_size = path, chunk_size
        self.rows: Iterator[Chunk] | None = None

    def lines(self, first: int) -> np.ndarray:
        if self.rows is None:
            self.rows = _tables.csv_chunks(self.path, self.chunk_size, True, lambda done: None)
            next(self.rows)  # the header
        for chunk in self.rows:
            if chunk.first == first:
                assert chunk.lines is not None
                return chunk.lines
        raise AssertionError(f"no row {first} in {self.path}")  # pragma: no cover


class _Lines:
    """Line numbers of a chunk's rows, counted on first use (a quoted cell may span lines;
    blank lines are not rows)."""

    def __init__(self, counter: _LineCounter, first: int, n: int) -> None:
        self.counter, self.first, self.n = counter, first, n
        self.numbers: np.ndarray | None = None

    def __getitem__(self, i: int) -> int:
        if self.numbers is None:
            self.numbers = self.counter.lines(self.first)
        return int(self.numbers[i])

    def __len__(self) -> int:
        return self.n


def chunk_head(chunk: Chunk, m: int) -> Chunk:
    """The first ``m`` rows of ``chunk`` (read by Arrow or by Python's csv module, or from
    Parquet), as a chunk of their own: the trials of a batch's estimate
    (:mod:`spinimpact._long`). Row ``i`` of the head is row ``i`` of the chunk."""
    m = min(m, chunk.messages.size)
    if isinstance(chunk.numbers, _Numbers):  # read by Arrow: its lazy cells and numbers
        source = chunk.numbers.source.head(m)
        # no line numbers: counting them would open a reader the chunk then carries (and a
        # chunk sent to a Dask worker cannot); the trials' messages are not shown anyway
        return Chunk(chunk.first, _Cells(source.text), source.empty, None,
                     chunk.messages[:m].copy(), text=source.text,
                     numbers=_Numbers(source))  # fmt: skip
    arrow = None if chunk.arrow is None else {k: a.slice(0, m) for k, a in chunk.arrow.items()}
    return Chunk(
        chunk.first,
        {k: v[:m] for k, v in chunk.columns.items()},
        {k: e[:m] for k, e in chunk.empty.items()},
        None if chunk.lines is None else chunk.lines[:m],
        chunk.messages[:m].copy(),
        arrow,
    )
