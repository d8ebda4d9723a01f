"""Measured data in a CSV file: named float columns with the line of each row, and the
library's errors about the i-th row named by that line (``spinimpact fit``)."""

from __future__ import annotations

import csv
import math
import re
from typing import Any

import numpy as np

__all__ = ["read_columns", "read_table", "row_error"]


def read_columns(path: str) -> dict[str, np.ndarray]:
    """A CSV file as named float columns; an empty cell is NaN (not measured), lines
    starting with ``#`` are comments.

    Raises
    ------
    ValueError
        Naming the file, line and column of a cell that is not a number, or a file
        with no header or no rows.
    """
    return read_table(path)[0]


def read_table(path: str) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """:func:`read_columns` and the file's line number (from 1) of each data row, so that
    an error about a row names the line it is on, comments and blank lines counted."""
    numbers: list[int] = []

    def content(fh: Any) -> Any:  # the lines csv reads, with their line numbers kept
        for number, line in enumerate(fh, start=1):
            if not line.lstrip().startswith("#"):
                numbers.append(number)
                yield line

    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.reader(content(fh))
        header = next(reader, None)
        if not header:
            raise ValueError(f"{path}: empty file (no header line)")
        names = [h.strip() for h in header]
        if len(set(names)) != len(names):
            raise ValueError(f"{path}: repeated column names in the header: {names}")
        rows, lines = [], []
        for row in reader:
            line = numbers[-1]  # a quoted cell may span lines: the row's last line
            if not any(cell.strip() for cell in row):
                continue
            if len(row) != len(names):
                raise ValueError(
                    f"{path}: row {line} has {len(row)} cells, the header {len(names)}"
                )
            values = []
            for name, cell in zip(names, row, strict=True):
                text = cell.strip()
                try:
                    values.append(float(text) if text else math.nan)
                except ValueError:
                    raise ValueError(
                        f"{path}: row {line}, column {name}: {text!r} is not a number"
                    ) from None
                if text.lower() in ("nan", "inf", "-inf", "+inf", "infinity", "-infinity"):
                    raise ValueError(f"{path}: row {line}, column {name}: {text!r}; leave a "
                                     f"value that was not measured empty")  # fmt: skip
            rows.append(values)
            lines.append(line)
    if not rows:
        raise ValueError(f"{path}: no rows after the header")
    table = np.array(rows, dtype=float)
    return {name: table[:, i] for i, name in enumerate(names)}, np.array(lines)


#: How the library names the first bad element of an array (``_validation.check``,
#: ``fit_drops``): turned into the file's row by :func:`row_error`.
_INDEX = re.compile(r" \(first offending index (\d+)\)| at index (\d+)")


def row_error(path: str, lines: np.ndarray, exc: ValueError) -> ValueError:
    """The library's error about the i-th data row, naming the row by its line in the file
    (as the errors about a cell do) instead of by its index among the data rows."""
    text = str(exc)
    found = list(_INDEX.finditer(text))
    if not found:
        return exc

    def line(m: re.Match[str]) -> int:
        return int(lines[int(m.group(1) or m.group(2))])

    if len(found) == 1:
        at = found[0]
        return ValueError(f"{path}: row {line(at)}: {text[: at.start()]}{text[at.end() :]}")
    # several rows named in one message (impossible rebounds): each by its line
    return ValueError(f"{path}: " + _INDEX.sub(lambda m: f" at row {line(m)}", text))
