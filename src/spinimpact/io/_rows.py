"""Writers of batch rows: the input cells, the results and the errors, chunk by chunk.

* :class:`ArrowRows`: Parquet, or fast CSV, through pyarrow
  (:class:`~spinimpact.io._sinks.ArrowWriter`);
* :class:`CsvRows`: CSV with Python's csv module, when pyarrow is not installed;
* :func:`chosen_fields`: the result columns a run writes (``--fields``);
* :func:`output_target`: where they write: a temporary file renamed onto the output
  on success (:func:`~spinimpact.io.atomic.atomic_path`), or standard output for ``-``.
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
import sys
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import IO, Any

import numpy as np

from ._sinks import ArrowWriter
from ._tables import Chunk
from ._units import unit_metadata
from .atomic import atomic_path

__all__ = ["STDIO", "ArrowRows", "CsvRows", "FieldError", "chosen_fields", "output_target"]

#: The file name that means standard input (for a source) or standard output.
STDIO = "-"


@contextlib.contextmanager
def output_target(output: str | os.PathLike[str]) -> Iterator[Path | IO[bytes]]:
    """Where a batch writes ``output``: a temporary path, or standard output for ``-``.

    Rows written to standard output are streamed as they are solved, so a run that
    fails part way has already written the rows before the failure.
    """
    if str(output) != STDIO:
        with atomic_path(output) as tmp:
            yield tmp
        return
    sys.stdout.flush()
    stream = sys.stdout.buffer
    try:
        yield stream
    finally:
        stream.flush()


class FieldError(ValueError):
    """An output field that the file's result vocabulary does not have."""


def chosen_fields(kinds: dict[str, str], fields: Sequence[str], kind: str) -> dict[str, str]:
    """``kinds`` (output column -> kind) restricted to ``fields``, in their order.

    Raises
    ------
    FieldError
        For no field, or a name not in ``kinds``: the message lists the valid ones.
    """
    if isinstance(fields, str):
        fields = [f for f in fields.split(",") if f.strip()]
    names = list(dict.fromkeys(str(f).strip() for f in fields))
    what = {"paper": "the paper's bodies", "planar": "free planar bodies",
            "pendulum": "pendulums"}.get(kind, f"problem {kind!r}")  # fmt: skip
    for name in names or [""]:
        if name not in kinds:
            got = f"unknown output field {name!r}" if name else "no output field given"
            raise FieldError(f"{got}; the fields for {what} are: {', '.join(kinds)}")
    return {n: kinds[n] for n in names}


class CsvRows:
    """Batch output as CSV with Python's csv module (used when pyarrow is not installed).

    Parameters
    ----------
    path : pathlib.Path or binary stream
        The file to write, or a stream to write to (left open).
    header : list of str
        The input columns, written back as they were read.
    kinds : dict
        Result column -> ``"float"``, ``"text"`` or ``"flag"`` (written ``true``/``false``).
    skip : bool
        Whether an ``error`` column follows the results.
    """

    def __init__(
        self, path: Path | IO[bytes], header: list[str], kinds: dict[str, str], skip: bool
    ) -> None:
        self.owned = isinstance(path, Path)
        if isinstance(path, Path):
            self.file = open(path, "w", newline="", encoding="utf-8")  # noqa: SIM115 (close())
        else:  # a stream that stays open (standard output)
            self.file = io.TextIOWrapper(path, encoding="utf-8", newline="")
        self.writer = csv.writer(self.file)
        self.header, self.kinds, self.skip = header, kinds, skip
        self.started = False

    def _start(self) -> None:
        if not self.started:
            self.started = True
            self.writer.writerow(self.header + list(self.kinds) + (["error"] if self.skip else []))

    def write(self, chunk: Chunk, values: dict, results: dict, messages: np.ndarray) -> None:
        """Write the rows of ``chunk``: its cells, ``results`` and (skip mode) ``messages``."""
        self._start()
        good = messages == ""
        columns = []
        for name in self.header:
            cells = chunk.columns[name]
            if chunk.arrow is None:  # CSV input: the (stripped) text cells
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

    def close(self, complete: bool = True) -> None:
        """Finish the file (with no rows, the header alone); ``complete=False``: after a
        failure, write nothing more."""
        if complete:
            self._start()
        if self.owned:
            self.file.close()
        else:
            self.file.flush()
            self.file.detach()  # the stream itself stays open


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
                elif column.dtype.kind in "Ub":  # every row solved: NumPy str or bool
                    arrays.append(pa.array(column, field.type))
                else:
                    arrays.append(pa.array(column.tolist(), field.type))
            elif name == "error":
                arrays.append(pa.array([m or None for m in messages.tolist()], pa.string()))
            elif chunk.arrow is not None:
                arrays.append(chunk.arrow[name])
            elif field.type == pa.float64():  # parsed numbers; null where empty or unreadable
                v = values[name]
                arrays.append(pa.array(v, mask=chunk.empty[name] | np.isnan(v)))
            elif chunk.text is not None:  # CSV read by Arrow: its text, as it is
                arrays.append(chunk.text[name])
            else:
                arrays.append(pa.array(chunk.columns[name], pa.string()))
        self.out.write(pa.Table.from_arrays(arrays, schema=schema))

    def close(self, complete: bool = True) -> None:
        """Finish the file; with no rows, a valid empty file with the schema
        (``complete=False``: after a failure, none)."""
        empty = self._schema(None) if self.out.schema is None and complete else None
        self.out.close(empty)
