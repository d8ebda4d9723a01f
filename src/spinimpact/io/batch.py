"""Batch files: solve every row of a CSV (or Parquet) file of incidences, in chunks.

This module solves the paper's bodies; a file whose columns describe planar bodies
(``rx, ry``) or pendulums (``gx, gy, px, py``) is solved as
:mod:`spinimpact.io.planar_batch` describes (:func:`run_batch` reads the header and
:func:`body_kind` decides).

Columns ``vx, vy, omega`` are required; ``mu, kappa, mass, radius, gyration,
body`` are optional per row (an empty cell, a Parquet null or a missing column
takes the default; a row gives either a ``body`` preset or a ``gyration``). The
output holds the input columns, then every column of the
:class:`~spinimpact.Impact` that is not an input (:data:`RESULT_COLUMNS`, taken
from :meth:`Impact.column_names <spinimpact.model.result.Result.column_names>`,
so a new field of the result is a new column of the file; under a tangential law,
``defaults["tangential"]``, those of the :class:`~spinimpact.CompliantImpact`). Memory stays bounded
by the chunk size, whatever the file size. Output goes to a temporary file that
is renamed only when the whole run succeeded.
"""

from __future__ import annotations

import contextlib
import functools
import itertools
import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .._long import Estimate
from .._validation import available, require
from ..model.body import PRESETS, Body
from ..model.impact import solve
from ..model.registry import Problem
from ._arrow_csv import csv_chunks as arrow_csv_chunks
from ._background import BackgroundRows
from ._batch_cost import estimate_batch, rows_in
from ._rows import STDIO, ArrowRows, CsvRows, FieldError, chosen_fields, output_target
from ._runner import map_in_order
from ._stop import check as stop_check
from ._tables import (
    SUFFIXES,
    BatchError,
    Chunk,
    RowNotes,
    check_header,
    column_or_default,
    csv_chunks,
    file_format,
    parquet_chunks,
)
from .atomic import atomic_path
from .batch_columns import RESULT_COLUMNS, column_kinds, result_columns
from .planar_batch import PlanarBatch, body_kind
from .problem_batch import TWO_D, ProblemBatch, problem_of, units_file, write_units

__all__ = [
    "RESULT_COLUMNS",
    "REQUIRED",
    "OPTIONAL",
    "SUFFIXES",
    "BatchError",
    "BatchSummary",
    "FieldError",
    "body_kind",
    "input_kind",
    "result_columns",
    "run_batch",
]

REQUIRED = ("vx", "vy", "omega")
OPTIONAL = ("mu", "kappa", "mass", "radius", "gyration", "body")
NUMERIC = ("vx", "vy", "omega", "mu", "kappa", "mass", "radius", "gyration")


@dataclass(frozen=True)
class BatchSummary:
    """What :func:`run_batch` did."""

    rows: int  #: data rows read
    skipped: int  #: rows written with an error instead of results (``on_error="skip"``)
    output: Path  #: the file written
    kind: str = "paper"  #: what the file described: "paper", "planar" or "pendulum"


def _law_kappa(chunk: Chunk, law: Any, kappa: np.ndarray, note: Callable) -> None:
    """Note each row whose ``kappa`` the tangential ``law`` cannot take (its ``kappa_ok``;
    ``MindlinDeresiewicz``: ``kappa > 0``), in the law's words (``kappa_rule``), naming
    the row and column, or saying the value is the default's."""
    if law is None:
        return
    refused = np.isfinite(kappa) & ~np.asarray(law.kappa_ok(kappa), dtype=bool)
    column = "kappa" in chunk.columns
    for i in np.flatnonzero(refused):
        default = not column or bool(chunk.empty["kappa"][i])
        where = chunk.where(i) if not column else chunk.where(i, "kappa")
        name = "kappa (the default)" if default else "kappa"
        note(i, f"{where}: {name} must be {law.kappa_rule}, got {float(kappa[i])!r}")


def _solve_chunk(chunk: Chunk, defaults: dict[str, Any]):
    """Solve one chunk. Returns (input numbers, results by column, error message per row)."""
    n = chunk.messages.size
    note = RowNotes()
    values = {
        name: column_or_default(
            chunk, name, defaults.get(name), note, required=name != "gyration"
        )  # fmt: skip
        for name in NUMERIC
    }
    values["gyration"] = np.array(values["gyration"])  # a preset in a row clears its own
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
            note(i, f"{chunk.where(i, 'body')}: give either body or gyration, not both")
        values["gyration"][given & ~own_gyration] = np.nan  # the row's preset wins
    # every row the default preset (no body or gyration column): one preset body
    one_preset = defaults.get("body") in PRESETS and defaults.get("gyration") is None
    one_preset = one_preset and not {"body", "gyration"} & set(chunk.columns)
    custom = ~np.isnan(values["gyration"])
    unknown = np.zeros(n, bool) if one_preset else ~custom & ~np.isin(preset, list(PRESETS))
    for i in np.flatnonzero(unknown):
        what = repr(str(preset[i])) if preset[i] else "nothing (no body and no gyration)"
        note(i, f"{chunk.where(i, 'body')}: must be one of {', '.join(PRESETS)}; got {what}")
    _law_kappa(chunk, defaults.get("tangential"), values["kappa"], note)
    messages = note.messages(chunk)
    good = messages == ""
    solved: dict[str, np.ndarray] = {}
    if good.any():
        take = {k: v[good] for k, v in values.items()}
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            if one_preset:  # the same numbers as from_columns, without a name per row
                body = Body.preset(defaults["body"], mass=take["mass"], radius=take["radius"])
            else:
                body = Body.from_columns(
                    mass=take["mass"],
                    radius=take["radius"],
                    preset=np.where(custom[good], "", preset[good]),
                    gyration=take["gyration"],
                )
            imp = solve(body, take["vx"], take["vy"], take["omega"], mu=take["mu"],
                        kappa=take["kappa"], tangential=defaults.get("tangential"))  # fmt: skip
        solved = imp.columns()
    results = {}
    for name, kind in column_kinds(defaults.get("tangential")).items():
        if good.all():  # every row solved: the arrays as they are (float, str or bool)
            column = np.asarray(solved[name])
        elif kind == "float":
            column = np.full(n, np.nan)
            if good.any():
                column[good] = solved[name]
        else:  # str or bool; None on error rows
            column = np.full(n, None, dtype=object)
            if good.any():
                column[good] = np.asarray(solved[name]).tolist()
        results[name] = column
    return values, results, messages


def _have_pyarrow() -> bool:
    return available("pyarrow")


def _input_format(source: Path) -> str:
    if str(source) == STDIO:
        return "csv"
    if not source.is_file():
        raise ValueError(f"input file {str(source)!r} does not exist or is not a file")
    return file_format(source, "input")


def input_kind(source: str | os.PathLike[str]) -> str:
    """What the file ``source`` describes, read from its header alone (:func:`body_kind`).

    Parameters
    ----------
    source : str or os.PathLike
        A ``.csv``, ``.parquet`` or ``.pq`` batch input.

    Returns
    -------
    str
        ``"paper"`` (the paper's bodies), ``"planar"`` (columns ``rx, ry``) or
        ``"pendulum"`` (columns ``gx, gy, px, py``).

    Raises
    ------
    BatchError
        For an empty file or a header that mixes kinds (see :func:`body_kind`).
    ValueError
        For a missing input or an unknown suffix.
    ImportError
        For Parquet without pyarrow, naming the ``[parquet]`` extra.
    """
    source = Path(source)
    read = parquet_chunks if _input_format(source) == "parquet" else csv_chunks
    chunks = read(source, 1, True, lambda done: None)
    try:
        return body_kind(next(chunks))
    finally:
        chunks.close()


def run_batch(
    source: str | os.PathLike[str],
    output: str | os.PathLike[str],
    *,
    defaults: dict[str, Any],
    on_error: str = "stop",
    chunk_size: int = 100_000,
    progress: Callable[[int, int | None], None] | None = None,
    fields: Sequence[str] | None = None,
    check_kind: Callable[[str], None] | None = None,
    problem: str | Problem | None = None,
    client: Any = None,
    force: bool = False,
    announce: Callable[[Estimate], None] | None = None,
) -> BatchSummary:
    """Solve every row of ``source`` and write ``output`` (CSV, or Parquet by suffix).

    The header decides the solver (:func:`body_kind`): columns ``rx, ry`` make a file
    of free planar bodies and ``gx, gy, px, py`` one of pendulums, solved as
    :mod:`spinimpact.io.planar_batch` describes; otherwise the rows are the paper's
    bodies, solved by :func:`~spinimpact.solve`.

    Parameters
    ----------
    source : str or os.PathLike
        Input file, ``.csv``, ``.parquet`` or ``.pq`` (``"-"``: CSV from standard
        input), with columns ``vx, vy``
        (m/s) and ``omega`` (rad/s), and optionally ``mu, kappa`` (1), ``mass``
        (kg), ``radius, gyration`` (m) and ``body`` (a preset name). Planar bodies:
        ``mass, inertia, rx, ry, vx, vy, omega``; pendulums: ``mass, inertia, gx, gy,
        px, py, omega``; both optionally ``mu, kappa, law``.
    output : str or os.PathLike
        Output file, ``.csv``, ``.parquet`` or ``.pq`` (``"-"``: CSV on standard
        output, rows streamed as they are solved): the input columns, then
        :data:`RESULT_COLUMNS` (SI units, as the :class:`~spinimpact.Impact` fields), or
        for planar files :attr:`PlanarBatch.kinds <spinimpact.io.planar_batch.PlanarBatch>`'s
        columns. Parquet fields name their units in their metadata.
    defaults : dict
        Values for the optional columns where a file lacks them: ``mu``,
        ``kappa``, ``mass``, ``radius`` and either ``body`` (a preset name) or
        ``gyration``; for planar files ``mu``, ``kappa`` and ``law`` (``"newton"``,
        ``"poisson"``, the default, or ``"energetic"``). ``tangential``: a tangential
        compliance law for the paper's bodies (``solve(..., tangential=law)``, the
        :class:`~spinimpact.CompliantImpact` columns: :mod:`spinimpact.io.batch_columns`).
    on_error : {"stop", "skip"}
        ``"stop"`` raises :class:`BatchError` naming the first bad row (and its
        line and column) and writes nothing. ``"skip"`` writes bad rows with an
        ``error`` column and empty results.
    chunk_size : int
        Rows solved at a time; memory is bounded by it.
    progress : callable, optional
        Called after each chunk as ``progress(done, total)``: characters (CSV)
        or rows (Parquet); ``total`` is ``None`` for standard input.
    fields : sequence of str, optional
        The result columns to write after the input columns, in this order; by default
        all of them. Names from the file's result vocabulary (:func:`result_columns`
        for the paper's bodies, :class:`~spinimpact.io.planar_batch.PlanarBatch`'s
        ``kinds`` for planar bodies and pendulums).
    check_kind : callable, optional
        Called with the file's kind (:func:`body_kind`) once its header is read, before
        anything is written; it may raise to refuse the file.
    client : distributed.Client, optional
        Solve the chunks on its Dask cluster (:func:`~spinimpact.io.sweep.dask_client`),
        at most two per worker thread in flight; the chunks are read and written here, in
        order, so the output is the same, byte for byte, as without it.

    Returns
    -------
    BatchSummary
        Rows read, rows skipped, and the output path.

    Raises
    ------
    BatchError
        A ``ValueError`` naming the row, line and column of a bad cell, or a bad header.
    ValueError
        For a bad ``on_error`` or ``chunk_size``, a missing input, an unknown suffix,
        or an output that is the input.
    FieldError
        A ``ValueError`` for an unknown name in ``fields`` (the message lists the valid
        ones).
    TypeError
        For a ``chunk_size`` that is not an integer.
    ImportError
        For Parquet files without pyarrow, naming the ``[parquet]`` extra.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (folder / "in.csv").write_text("vx,vy,omega\\n2,-3,0\\n")
    >>> defaults = dict(mu=0.5, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere")
    >>> run_batch(folder / "in.csv", folder / "out.csv", defaults=defaults).rows
    1
    """
    source, output = Path(source), Path(output)
    if on_error not in ("stop", "skip"):
        raise ValueError(f"on_error must be 'stop' or 'skip', got {on_error!r}")
    if isinstance(chunk_size, bool) or not isinstance(chunk_size, int | np.integer):
        raise TypeError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    if chunk_size < 1:
        raise ValueError(f"chunk_size must be a positive integer, got {chunk_size!r}")
    to_stdout = str(output) == STDIO
    fmt_in = _input_format(source)
    fmt_out = "csv" if to_stdout else file_format(output, "output")
    if not to_stdout and output.exists() and output.resolve() == source.resolve():
        raise ValueError("the output file must differ from the input file")
    if "parquet" in (fmt_in, fmt_out):
        require("pyarrow.parquet", "Parquet files")
    skip = on_error == "skip"
    total: int | None = None if str(source) == STDIO else source.stat().st_size
    if fmt_in == "parquet":
        total = require("pyarrow.parquet", "Parquet files").ParquetFile(source).metadata.num_rows

    def advance(done: int) -> None:
        if progress is not None:
            progress(done, total)

    read = parquet_chunks if fmt_in == "parquet" else arrow_csv_chunks  # pyarrow's, or Python's
    chunks = read(source, int(chunk_size), skip, advance)
    header = next(chunks)
    chosen = problem_of(header, problem)
    kind = chosen.name
    if check_kind is not None:
        check_kind(kind)
    if kind not in TWO_D:
        plan: Any = ProblemBatch(chosen, header, skip, defaults)
        kinds, numeric, solve_chunk = plan.kinds, plan.numeric, plan.solve
    elif kind == "paper":
        kinds, numeric = column_kinds(defaults.get("tangential")), NUMERIC
        check_header(header, skip, kinds, REQUIRED)
        solve_chunk = functools.partial(_solve_chunk, defaults=defaults)
    elif defaults.get("tangential") is not None:
        raise BatchError(f"a tangential law applies to the paper's bodies, not to {kind} files")
    else:
        plan = PlanarBatch(kind, header, skip, defaults)
        kinds, numeric, solve_chunk = plan.kinds, plan.numeric, plan.solve
    if fields is not None:
        kinds = chosen_fields(kinds, fields, kind)
    first = next(chunks, None)
    if first is not None and str(source) != STDIO:
        rows_total = rows_in(source, fmt_in)
        estimate = estimate_batch(first, solve_chunk, rows_total, int(chunk_size), kind)
        estimate.check(force)
        if announce is not None and estimate.announced:
            announce(estimate)
    chunks = itertools.chain([] if first is None else [first], chunks)
    rows = skipped = 0
    side = units_file(output) if fmt_out == "csv" and not to_stdout else None
    with output_target(output) as target, contextlib.ExitStack() as stack:
        side_tmp = None if side is None else stack.enter_context(atomic_path(side))
        if fmt_out == "parquet" or _have_pyarrow():
            rows_out = ArrowRows(target, header, kinds, skip, fmt_out, numeric)
            sink: BackgroundRows | CsvRows = BackgroundRows(rows_out)  # Arrow frees the GIL
        else:
            sink = CsvRows(target, header, kinds, skip)
        complete = False
        try:
            window = 2 * max(1, len(client.nthreads())) if client is not None else 1
            for chunk, solved in map_in_order(chunks, solve_chunk, client, window):
                stop_check()  # a signal stops the run here, between chunks
                values, results, messages = solved
                bad = messages != ""
                if bad.any() and not skip:
                    raise BatchError(messages[int(np.argmax(bad))])
                sink.write(chunk, values, {n: results[n] for n in kinds}, messages)
                rows += messages.size
                skipped += int(bad.sum())
            complete = True
        finally:
            sink.close(complete)
        if side_tmp is not None:
            write_units(side_tmp, chosen, [*header, *kinds])
    return BatchSummary(rows=rows, skipped=skipped, output=output, kind=kind)
