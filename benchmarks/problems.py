"""Batch files of every registered problem, timed against the paper's bodies in one run.

Each problem's rows are its declared example (:attr:`spinimpact.Problem.example`) with
every velocity and spin input scaled by its own random factor in [0.5, 1.5] (signs, and so
the approach, kept), written to CSV; ``run_batch`` then solves each file with the same
output columns (``--fields regime,dissipated_energy``), and the time per row is printed
beside its ratio to the paper's bodies' (measured in the same run, best of ``--repeat``,
after an untimed batch of 16 rows of each problem), in wall time and in the process's CPU
time (all its threads), which other work on a busy machine does not inflate.

With ``--format parquet`` the rows are read from and written to Parquet instead (no text to
parse or format: the cost of the columns themselves falls away).

Run from the repository root:
``.venv/bin/python -m benchmarks.problems [--rows N] [--repeat K] [--format csv|parquet]``.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np
from rich.console import Console
from rich.table import Table

from spinimpact import problems
from spinimpact.io.batch import run_batch

FIELDS = ("regime", "dissipated_energy")


def write_rows(declared, path: Path, rows: int, seed: int = 7) -> None:
    """``rows`` perturbed copies of the problem's example, as CSV (or Parquet, by the
    suffix of ``path``)."""
    rng = np.random.default_rng(seed)
    names = list(declared.example)
    columns = []
    for name in names:
        value = np.full(rows, float(declared.example[name]))
        if declared.unit(name) in ("m/s", "rad/s"):
            value *= rng.uniform(0.5, 1.5, rows)
        columns.append(value)
    if path.suffix == ".parquet":
        import pyarrow as pa
        import pyarrow.parquet as pq

        pq.write_table(pa.table(dict(zip(names, columns, strict=True))), path)
        return
    np.savetxt(path, np.column_stack(columns), delimiter=",", header=",".join(names),
               comments="", fmt="%.17g")  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--format", choices=("csv", "parquet"), default="csv")
    args = parser.parse_args()
    table = Table(title=f"spinimpact batch, {args.rows:,} rows of {args.format}, "
                        f"fields {','.join(FIELDS)}")  # fmt: skip
    for heading in ("problem", "wall s", "wall us/row", "wall ratio", "CPU s", "CPU ratio"):
        table.add_column(heading, justify="right")
    base = cpu_base = None
    with tempfile.TemporaryDirectory() as folder:
        # the impact problems (a flight, also registered, has no regime or energy loss of its
        # own, and takes about a millisecond a ball: not comparable)
        impacts = [p for p in problems() if set(FIELDS) <= set(p.result_columns())]
        for declared in impacts:
            source = Path(folder) / f"{declared.name}.{args.format}"
            write_rows(declared, source, args.rows)
            defaults = {"mu": 0.3, "kappa": 0.7, "mass": 1.0, "radius": 0.1,
                        "body": "solid-sphere"}  # fmt: skip
            warm = Path(folder) / f"warm-{declared.name}.{args.format}"
            write_rows(declared, warm, 16)  # untimed: imports and compiled kernels first
            run_batch(warm, Path(folder) / f"warm.{args.format}", defaults=defaults,
                      fields=FIELDS)  # fmt: skip
            best = cpu = float("inf")
            for _ in range(args.repeat):
                start, start_cpu = time.perf_counter(), time.process_time()
                out = Path(folder) / f"out.{args.format}"
                run_batch(source, out, defaults=defaults, fields=FIELDS)
                best = min(best, time.perf_counter() - start)
                cpu = min(cpu, time.process_time() - start_cpu)
            base = best if base is None else base
            cpu_base = cpu if cpu_base is None else cpu_base
            table.add_row(
                declared.name,
                f"{best:.2f}",
                f"{1e6 * best / args.rows:.2f}",
                f"{best / base:.2f}",
                f"{cpu:.2f}",
                f"{cpu / cpu_base:.2f}",
            )
    Console().print(table)


if __name__ == "__main__":
    main()
