"""What a batch will cost, measured before it runs: the rule of every long run
(:mod:`spinimpact._long`) applied to :func:`~spinimpact.io.batch.run_batch`.

The first rows of the file's first chunk are solved as the run will solve them (two rows
first, untimed, so that compiling a kernel is not counted as the rows' time), in trials
grown while they are cheap (at most a tenth of the run's predicted time, 2 s at most; a
law that steps each impact in time is measured on its first 64 rows); their time per row
and per chunk, scaled to the file's rows (:func:`rows_in`), is the estimate. A batch over a
minute says so first; one over an hour is refused unless forced.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

from .._long import Estimate, fit_line, grow, ladder
from .._words import count
from ._arrow_csv import chunk_head
from ._tables import Chunk

__all__ = ["estimate_batch", "rows_in"]


def rows_in(path: Path, fmt: str, sample: int = 1 << 20) -> int:
    """The data rows of a batch input: Parquet's count, or for CSV the file's size over the
    bytes per line of its first ``sample`` bytes (exact when the file is no larger)."""
    if fmt == "parquet":
        import pyarrow.parquet as pq

        return int(pq.ParquetFile(path).metadata.num_rows)
    size = path.stat().st_size
    with open(path, "rb") as f:
        head = f.read(sample)
    lines = head.count(b"\n") + (not head.endswith(b"\n") and len(head) == size and bool(head))
    if len(head) < size and lines:
        lines = round(lines * size / len(head))
    return max(lines - 1, 0)  # less the header


def estimate_batch(
    first: Chunk, solve_chunk: Callable, rows: int, chunk_size: int, kind: str
) -> Estimate:
    """How long a batch of ``rows`` rows of problem ``kind`` will take here, measured on the
    first rows of its ``first`` chunk, solved by ``solve_chunk``."""
    sizes = ladder(first.messages.size, first.messages.size)
    solve_chunk(chunk_head(first, 2))  # untimed: compiled kernels and imports warm up first
    trials = grow(lambda m: lambda: solve_chunk(chunk_head(first, m)), sizes, 1, 0, max(rows, 1))
    per_chunk, per_row = fit_line(trials.points, trials.seconds)
    seconds = per_chunk * math.ceil(rows / chunk_size) + per_row * rows
    what = f"this batch ({count(rows, 'row')} of problem {kind!r})"
    return Estimate(what, seconds, f"its first {count(trials.points[-1], 'row')}")
