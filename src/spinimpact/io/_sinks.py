"""Writers of batch and sweep output, chunk by chunk.

* :class:`ArrowWriter`: tables to one Parquet or CSV file through pyarrow; both the
  batch rows and the sweep columns go through it.
* :mod:`spinimpact.io._rows`: batch rows (input cells, results, errors) through it
  or Python's csv module.
* :func:`parquet_columns` / :func:`npy_columns`: sweep columns to one Parquet file
  or to a new directory of ``.npy`` files.

Every output is written under a temporary name and renamed only when the whole
run succeeded (:func:`~spinimpact.io.atomic.atomic_path` for single files). Parquet
files name each column's SI unit in its field metadata (:mod:`spinimpact.io._units`).
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import require
from . import _stop
from ._units import unit_metadata
from .atomic import atomic_directory, atomic_path

__all__ = ["ArrowWriter", "npy_columns", "parquet_columns"]


#: Characters that make a CSV cell need quotes (RFC 4180).
_STRUCTURAL = '[",\r\n]'
#: Rows of a table rendered as CSV text at a time (a few MB of text).
_CSV_ROWS = 16_384


def _structural_bytes(text: Any) -> bool:
    """Whether any cell of ``text`` (a large-string Arrow array) may hold a comma, a quote or
    a line break: one search of the cells' bytes, one after the other (a regular
    expression per cell takes about 14 times as long)."""
    offsets, data = text.buffers()[1:3]
    if data is None or len(text) == 0:
        return False
    ends = np.frombuffer(offsets, np.int64)[[text.offset, text.offset + len(text)]]
    cells = memoryview(data)[int(ends[0]) : int(ends[1])].tobytes()
    return any(c in cells for c in (b",", b'"', b"\r", b"\n"))


class ArrowWriter:
    """pyarrow tables to one Parquet or CSV file, opened on the first table.

    Parameters
    ----------
    path : pathlib.Path or pyarrow.NativeFile
        The file to write (normally a temporary path from ``atomic_path``), or a stream
        to write to (left open).
    fmt : {"parquet", "csv"}
        File format. CSV as Python's csv module writes it: the header is plain names,
        numbers and flags are never quoted, and a text cell is quoted (its quotes doubled)
        only where it holds a comma, a quote or a line break; the numbers are written as
        pyarrow writes them, in their shortest round-trip form.

    Raises
    ------
    ImportError
        Without pyarrow, naming the ``[parquet]`` extra.
    """

    def __init__(self, path: Path, fmt: str) -> None:
        self.pa = require("pyarrow", "Parquet files and fast CSV")
        self.path, self.fmt = path, fmt
        self.writer: Any = None
        self.schema: Any = None

    def open(self, schema: Any) -> None:
        """Start the file with ``schema`` (every later table must have it)."""
        self.schema = schema
        if self.fmt == "parquet":
            pq = require("pyarrow.parquet", "Parquet files")
            # Dictionary pages for text only: a chunk of distinct floats fits under the
            # dictionary's size limit, so every value would be hashed for nothing (the
            # values and types read back are the same either way).
            text = [f.name for f in schema if self.pa.types.is_string(f.type)]
            self.writer = pq.ParquetWriter(self.path, schema, use_dictionary=text)
        else:
            for f in schema:  # a CSV cell holds one number or text, not a list or record
                if self.pa.types.is_nested(f.type):
                    kind = "lists" if "list" in str(f.type) else "nested values"
                    raise ValueError(
                        f"column {f.name!r} holds {kind} ({f.type}), which a CSV file cannot "
                        "hold: write Parquet (.parquet), or drop the column"
                    )
            self.csv = require("pyarrow.csv", "fast CSV")
            owned = isinstance(self.path, str | os.PathLike)
            self.writer = open(self.path, "wb") if owned else self.path  # noqa: SIM115 (close)
            self.owned = owned
            line = io.StringIO()
            csv.writer(line, lineterminator="\n").writerow(schema.names)
            self.writer.write(line.getvalue().encode())

    def _csv_rows(self, table: Any) -> Iterator[Any]:
        """The CSV text of ``table``'s rows, a slice of :data:`_CSV_ROWS` at a time.

        Each column is cast to text as pyarrow's CSV writer casts it (numbers in their
        shortest round-trip form, flags ``true``/``false``, nulls empty); a text cell is
        quoted, its quotes doubled, only where it holds a comma, a quote or a line break.
        pyarrow's writer quotes every text cell, or refuses those that need it: it writes
        the slices where no cell needs quotes (faster), the cells are joined here where
        some do.
        """
        pa, types = self.pa, self.pa.types
        compute = require("pyarrow.compute", "fast CSV")
        text_types = (types.is_string, types.is_large_string, types.is_binary,
                      types.is_large_binary)  # fmt: skip
        large = pa.large_string()
        quote, comma, newline, none = (pa.scalar(c, large) for c in ('"', ",", "\n", ""))
        plain = self.csv.WriteOptions(include_header=False, quoting_style="none")
        for start in range(0, table.num_rows, _CSV_ROWS):
            part = table.slice(start, _CSV_ROWS)
            cells, quoted = list(part.columns), False
            for j, column in enumerate(cells):
                kind = column.type
                if types.is_dictionary(kind):
                    column, kind = column.cast(kind.value_type), kind.value_type
                if not any(test(kind) for test in text_types):
                    continue  # numbers and flags: never quoted
                text = compute.cast(column.combine_chunks(), large)
                if not _structural_bytes(text):
                    continue  # the usual column: no cell needs quotes, none is searched
                needs = compute.match_substring_regex(text, _STRUCTURAL)
                if compute.any(needs).as_py():
                    doubled = compute.replace_substring(text, '"', '""')
                    both = compute.binary_join_element_wise(quote, doubled, quote, none)
                    cells[j], quoted = compute.if_else(needs, both, text), True
            if not quoted:
                out = pa.BufferOutputStream()
                self.csv.write_csv(part, out, plain)
                yield out.getvalue()
                continue
            cells = [compute.fill_null(compute.cast(c, large), "") for c in cells]
            cells = [c.combine_chunks() if isinstance(c, pa.ChunkedArray) else c for c in cells]
            cells[-1] = compute.binary_join_element_wise(cells[-1], none, newline)
            rows = compute.binary_join_element_wise(*cells, comma)  # each ends in \n
            offsets, data = rows.buffers()[1:3]  # the rows' text, one after the other
            ends = np.frombuffer(offsets, np.int64)[[rows.offset, rows.offset + len(rows)]]
            yield memoryview(data)[int(ends[0]) : int(ends[1])]

    def write(self, table: Any) -> None:
        """Append ``table``; the first one fixes the schema if :meth:`open` was not called."""
        if self.writer is None:
            self.open(table.schema)
        try:
            if self.fmt == "csv":
                for block in self._csv_rows(table):
                    self.writer.write(block)
            else:
                self.writer.write_table(table)
        except self.pa.ArrowInvalid as err:
            if self.fmt != "csv" or "UTF8" not in str(err):
                raise
            raise ValueError(self._not_text(table)) from None

    def _not_text(self, table: Any) -> str:
        """What a CSV file could not take: the first cell of bytes that are not UTF-8."""
        types = self.pa.types
        for name, column in zip(table.column_names, table.columns, strict=True):
            if types.is_binary(column.type) or types.is_large_binary(column.type):
                for cell in column.to_pylist():
                    try:
                        _ = cell is None or cell.decode("utf-8")
                    except UnicodeDecodeError:
                        return (
                            f"column {name!r} holds bytes that are not UTF-8 text, such as "
                            f"{cell[:20]!r}, which a CSV file cannot hold: write Parquet "
                            "(.parquet), or drop the column"
                        )
        return "a column holds bytes that are not UTF-8 text, which a CSV file cannot hold"

    def close(self, schema: Any = None) -> None:
        """Finish the file; with no table written, an empty file with ``schema``."""
        if self.writer is None:
            if schema is None:
                return
            self.open(schema)
        if self.fmt == "parquet" or self.owned:
            self.writer.close()
        self.writer = None


# -- sweep columns ------------------------------------------------------------------


def _check_target(target: Path) -> None:
    if not target.parent.is_dir():
        raise ValueError(f"the directory of the output {str(target)!r} does not exist")


@contextlib.contextmanager
def parquet_columns(
    path: str | os.PathLike[str], metadata: dict[str, str] | None = None
) -> Iterator[Any]:
    """Stream chunks of named columns to one Parquet file, renamed into place on success.

    Each column with a unit names it in its field metadata (``{"unit": "m/s"}``).

    Parameters
    ----------
    path : str or os.PathLike
        The file to write.
    metadata : dict of str, optional
        Key-value metadata of the whole file (what the columns' codes mean, the body).

    Yields
    ------
    object
        With a method ``write(data)``: ``data`` maps column names to equal-length arrays.

    Raises
    ------
    ImportError
        Without pyarrow, naming the ``[parquet]`` extra.
    ValueError
        If ``path`` is a directory or its directory does not exist.
    """
    require("pyarrow.parquet", "Parquet output")
    target = Path(path)
    if target.is_dir():
        raise ValueError(f"output {str(target)!r} is a directory")
    _check_target(target)
    with atomic_path(target) as tmp:
        out = ArrowWriter(tmp, "parquet")
        try:
            yield _TableColumns(out, metadata)
        finally:
            out.close()


class _TableColumns:
    def __init__(self, out: ArrowWriter, metadata: dict[str, str] | None) -> None:
        self.out, self.metadata = out, metadata

    def write(self, data: dict[str, np.ndarray]) -> None:
        pa = self.out.pa
        table = pa.table({k: np.ascontiguousarray(v) for k, v in data.items()})
        fields = [f.with_metadata(unit_metadata(f.name) or {}) for f in table.schema]
        _stop.check()
        self.out.write(pa.Table.from_arrays(table.columns, schema=pa.schema(fields, self.metadata)))


@contextlib.contextmanager
def npy_columns(
    path: str | os.PathLike[str],
    columns: Sequence[str],
    size: int,
    dtypes: dict[str, Any] | None = None,
) -> Iterator[Any]:
    """Stream chunks into one ``.npy`` file per column of a new directory.

    The directory is built under a temporary name and renamed into place on
    success (:func:`~spinimpact.io.atomic.atomic_directory`); after a failure, a stop
    or a full disk it is removed, and after SIGKILL the next run removes it. Each
    chunk is appended with an ordinary file write after the ``.npy`` header (no
    memory map), so resident memory stays bounded by the chunk.

    Parameters
    ----------
    path : str or os.PathLike
        The directory to create; it must not exist.
    columns : sequence of str
        Column names; by default ``regime`` is stored as ``int8`` codes, the others as
        ``float64``.
    size : int
        Total number of values per column (written in the headers up front).
    dtypes : dict, optional
        Column -> NumPy dtype, for columns stored otherwise (``bool`` flags).

    Yields
    ------
    object
        With a method ``write(data)``: ``data`` maps each column to its next values.

    Raises
    ------
    ValueError
        If ``path`` exists or its directory does not.
    """
    target = Path(path)
    if os.path.lexists(target):
        raise ValueError(f"output directory {str(target)!r} already exists")
    _check_target(target)
    with atomic_directory(target) as tmp:
        files = _NpyFiles()
        try:
            for c in columns:
                dtype = (dtypes or {}).get(c, np.int8 if c == "regime" else np.float64)
                files.add(tmp / f"{c}.npy", c, np.dtype(dtype), size)
            yield files
            files.close()  # a full disk fails here, and the directory is removed
        finally:
            files.close(quiet=True)


class _NpyFiles:
    def __init__(self) -> None:
        self.files: dict[str, tuple[Any, np.dtype]] = {}

    def add(self, path: Path, name: str, dtype: np.dtype, size: int) -> None:
        f = open(path, "wb")  # noqa: SIM115 (closed in close())
        self.files[name] = (f, dtype)
        header = {"descr": np.lib.format.dtype_to_descr(dtype), "fortran_order": False}
        np.lib.format.write_array_header_1_0(f, header | {"shape": (size,)})

    def write(self, data: dict[str, np.ndarray]) -> None:
        _stop.check()
        for c, values in data.items():
            f, dtype = self.files[c]
            f.write(np.ascontiguousarray(values, dtype=dtype).tobytes())

    def close(self, quiet: bool = False) -> None:
        """Flush each file to disk and close it; ``quiet``: after a failure, ignore errors."""
        files, self.files = self.files, {}
        for f, _ in files.values():
            try:
                if not quiet:
                    f.flush()
                    os.fsync(f.fileno())
                f.close()
            except OSError:
                if not quiet:
                    for g, _ in files.values():
                        with contextlib.suppress(OSError):
                            g.close()
                    raise
