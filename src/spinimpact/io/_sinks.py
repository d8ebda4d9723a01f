"""Writers of batch and sweep output, chunk by chunk.

* :class:`ArrowWriter`: tables to one Parquet or CSV file through pyarrow; both the
  batch rows and the sweep columns go through it.
* :class:`CsvRows` / :class:`ArrowRows`: batch rows (input cells, results, errors)
  with Python's csv module or with pyarrow.
* :func:`parquet_columns` / :func:`npy_columns`: sweep columns to one Parquet file
  or to a new directory of ``.npy`` files.

Every output is written under a temporary name and renamed only when the whole
run succeeded (:func:`~spinimpact.io.atomic.atomic_path` for single files). Parquet
files name each column's SI unit in its field metadata (:mod:`spinimpact.io._units`).
"""

from __future__ import annotations

import contextlib
import csv
import os
import shutil
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .._validation import require
from ._tables import Chunk
from ._units import unit_metadata
from .atomic import atomic_path, current_umask

__all__ = ["ArrowRows", "ArrowWriter", "CsvRows", "npy_columns", "parquet_columns"]


class ArrowWriter:
    """pyarrow tables to one Parquet or CSV file, opened on the first table.

    Parameters
    ----------
    path : pathlib.Path
        The file to write (normally a temporary path from ``atomic_path``).
    fmt : {"parquet", "csv"}
        File format; CSV quotes only the cells that need it.

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
            self.writer = pq.ParquetWriter(self.path, schema)
        else:
            pc = require("pyarrow.csv", "fast CSV")
            options = pc.WriteOptions(quoting_style="needed")
            self.writer = pc.CSVWriter(self.path, schema, write_options=options)

    def write(self, table: Any) -> None:
        """Append ``table``; the first one fixes the schema if :meth:`open` was not called."""
        if self.writer is None:
            self.open(table.schema)
        self.writer.write_table(table)

    def close(self, schema: Any = None) -> None:
        """Finish the file; with no table written, an empty file with ``schema``."""
        if self.writer is None:
            if schema is None:
                return
            self.open(schema)
        self.writer.close()
        self.writer = None


# -- batch rows ---------------------------------------------------------------------


class CsvRows:
    """Batch output as CSV with Python's csv module (used when pyarrow is not installed).

    Parameters
    ----------
    path : pathlib.Path
        The file to write.
    header : list of str
        The input columns, written back as they were read.
    kinds : dict
        Result column -> ``"float"``, ``"text"`` or ``"flag"`` (written ``true``/``false``).
    skip : bool
        Whether an ``error`` column follows the results.
    """

    def __init__(self, path: Path, header: list[str], kinds: dict[str, str], skip: bool) -> None:
        self.file = open(path, "w", newline="", encoding="utf-8")  # noqa: SIM115 (close())
        self.writer = csv.writer(self.file)
        self.header, self.kinds, self.skip = header, kinds, skip
        self.writer.writerow(header + list(kinds) + (["error"] if skip else []))

    def write(self, chunk: Chunk, values: dict, results: dict, messages: np.ndarray) -> None:
        """Write the rows of ``chunk``: its cells, ``results`` and (skip mode) ``messages``."""
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
            if self.kinds[name] == "float":  # shortest round-trip text (repr)
                text = list(map(float.__repr__, column.tolist()))
                columns.append(text if good.all() else np.where(good, text, "").tolist())
            elif self.kinds[name] == "flag":
                columns.append(["" if v is None else ("true" if v else "false") for v in column])
            else:
                columns.append(["" if v is None else v for v in column])
        if self.skip:
            columns.append(messages.tolist())
        self.writer.writerows(zip(*columns, strict=True))

    def close(self) -> None:
        self.file.close()


class ArrowRows:
    """Batch output as Parquet, or fast CSV, through pyarrow; missing values are nulls.

    CSV input columns are kept as text for CSV output and parsed to numbers (the
    ``numeric`` ones) for Parquet output; Parquet input columns keep their types.
    Floats are written in a shortest form that reads back to the same number. Each
    Parquet field with a unit names it in its metadata (``{"unit": "m/s"}``).

    Parameters
    ----------
    path, header, kinds, skip
        As for :class:`CsvRows`.
    fmt : {"parquet", "csv"}
        File format.
    numeric : sequence of str
        Input columns that are numbers (typed ``float64`` in Parquet output).
    """

    _TYPES = {"float": "float64", "text": "string", "flag": "bool_"}

    def __init__(
        self,
        path: Path,
        header: list[str],
        kinds: dict[str, str],
        skip: bool,
        fmt: str,
        numeric: Sequence[str],
    ) -> None:
        self.out = ArrowWriter(path, fmt)
        self.header, self.kinds, self.skip, self.fmt = header, kinds, skip, fmt
        self.numeric = frozenset(numeric)

    def _schema(self, chunk: Chunk | None) -> Any:
        pa = self.out.pa
        fields = []
        for name in self.header:
            arrow = chunk.arrow if chunk is not None else None
            if arrow is not None:
                fields.append(pa.field(name, arrow[name].type))
            elif name in self.numeric and self.fmt == "parquet":
                fields.append(pa.field(name, pa.float64(), metadata=unit_metadata(name)))
            else:
                fields.append(pa.field(name, pa.string()))
        for name, kind in self.kinds.items():
            kind_ = getattr(pa, self._TYPES[kind])()
            fields.append(pa.field(name, kind_, metadata=unit_metadata(name)))
        if self.skip:
            fields.append(pa.field("error", pa.string()))
        return pa.schema(fields)

    def write(self, chunk: Chunk, values: dict, results: dict, messages: np.ndarray) -> None:
        """Write the rows of ``chunk``: its cells, ``results`` and (skip mode) ``messages``."""
        pa = self.out.pa
        if self.out.schema is None:
            self.out.open(self._schema(chunk))
        schema = self.out.schema
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
        self.out.write(pa.Table.from_arrays(arrays, schema=schema))

    def close(self) -> None:
        """Finish the file; with no rows, a valid empty file with the schema."""
        self.out.close(self._schema(None) if self.out.schema is None else None)


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
    success. Each chunk is appended with an ordinary file write after the
    ``.npy`` header (no memory map), so resident memory stays bounded by the chunk.

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
    if target.exists():
        raise ValueError(f"output directory {str(target)!r} already exists")
    _check_target(target)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=target.parent))
    files = _NpyFiles()
    try:
        for c in columns:
            dtype = (dtypes or {}).get(c, np.int8 if c == "regime" else np.float64)
            files.add(tmp / f"{c}.npy", c, np.dtype(dtype), size)
        yield files
        files.close()
        umask = current_umask()
        os.chmod(tmp, 0o777 & ~umask)
        for child in tmp.iterdir():
            os.chmod(child, 0o666 & ~umask)
        os.replace(tmp, target)
    finally:
        files.close()
        if tmp.exists():
            shutil.rmtree(tmp)


class _NpyFiles:
    def __init__(self) -> None:
        self.files: dict[str, tuple[Any, np.dtype]] = {}

    def add(self, path: Path, name: str, dtype: np.dtype, size: int) -> None:
        f = open(path, "wb")  # noqa: SIM115 (closed in close())
        self.files[name] = (f, dtype)
        header = {"descr": np.lib.format.dtype_to_descr(dtype), "fortran_order": False}
        np.lib.format.write_array_header_1_0(f, header | {"shape": (size,)})

    def write(self, data: dict[str, np.ndarray]) -> None:
        for c, values in data.items():
            f, dtype = self.files[c]
            f.write(np.ascontiguousarray(values, dtype=dtype).tobytes())

    def close(self) -> None:
        for f, _ in self.files.values():
            f.close()
        self.files = {}
