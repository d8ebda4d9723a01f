"""Camera tracks from a CSV file: one row a sample, grouped into tracks.

Columns (SI units; lines starting with ``#`` are comments): ``t`` (s), ``x``, ``y``, ``z``
(m, the ball's centre), and optionally ``set`` and ``trajectory`` (or ``track``): rows with
the same values form one track, named by them (``backspin 6``); without them the whole file
is one track, named by the file. Rows of a track must come in increasing time. Every other
column is refused, so that a misspelt name is not silently ignored.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np

from ..model.track import Track, as_track

__all__ = ["read_tracks", "COLUMNS", "GROUPS"]

#: The columns every track file has.
COLUMNS = ("t", "x", "y", "z")
#: Columns that group rows into tracks (any of them may be present).
GROUPS = ("set", "trajectory", "track")


def read_tracks(path: str | os.PathLike[str], *, up: str = "z",
                min_samples: int = 6) -> list[Track]:  # fmt: skip
    """Read the tracks of a CSV file (module docstring).

    Parameters
    ----------
    path : str or path-like
    up : {"z", "y"}
        The file's vertical axis.
    min_samples : int
        The fewest samples a track may have.

    Returns
    -------
    list of Track
        In the order of their first rows; each sample's ``rows`` entry is its line in the file.

    Raises
    ------
    ValueError
        A missing or unknown column, a cell that is not a number, too few samples, a NaN, or a
        time that does not increase within a track: the message names the file, the track and
        the line.
    OSError
        The file cannot be read.
    """
    p = Path(path)
    groups: dict[tuple[str, ...], list[tuple[int, list[float]]]] = {}
    with open(p, newline="") as f:
        lines = (line for line in enumerate(f, start=1) if not line[1].lstrip().startswith("#"))
        numbered = list(lines)
        if not numbered:
            raise ValueError(f"{p}: empty file; a track file needs the columns "
                             f"{', '.join(COLUMNS)}")  # fmt: skip
        reader = csv.reader(text for _, text in numbered)
        header = [h.strip() for h in next(reader)]
        missing = [c for c in COLUMNS if c not in header]
        unknown = [h for h in header if h not in COLUMNS + GROUPS]
        if missing or unknown:
            what = []
            if missing:
                what.append(f"missing column(s) {', '.join(missing)}")
            if unknown:
                what.append(f"unknown column(s) {', '.join(unknown)}")
            raise ValueError(f"{p}: {'; '.join(what)}; the columns are {', '.join(COLUMNS)} and "
                             f"optionally {', '.join(GROUPS)}")  # fmt: skip
        at = {h: i for i, h in enumerate(header)}
        keys = [g for g in GROUPS if g in at]
        for (line, _), row in zip(numbered[1:], reader, strict=False):
            if not any(cell.strip() for cell in row):
                continue
            if len(row) != len(header):
                raise ValueError(f"{p}, line {line}: {len(row)} cells, the header has "
                                 f"{len(header)}")  # fmt: skip
            values = []
            for c in COLUMNS:
                cell = row[at[c]].strip()
                try:
                    values.append(float(cell))
                except ValueError:
                    raise ValueError(f"{p}, line {line}: column {c} is not a number: "
                                     f"{cell!r}") from None  # fmt: skip
            key = tuple(row[at[g]].strip() for g in keys)
            groups.setdefault(key, []).append((line, values))
    tracks = []
    for key, samples in groups.items():
        name = " ".join(key) if key else p.stem
        data = np.array([v for _, v in samples], dtype=float)
        rows = np.array([line for line, _ in samples])
        tracks.append(as_track(data[:, 0], data[:, 1:], name=f"{name} ({p.name})", rows=rows,
                               up=up, min_samples=min_samples))  # fmt: skip
    if not tracks:
        raise ValueError(f"{p}: no samples")
    return tracks
