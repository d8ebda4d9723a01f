"""How close ``solve()`` and ``spinimpact batch`` come to their limits, as ratios.

Part of ``make bench`` (:mod:`benchmarks.bench`); alone::

    .venv/bin/python -m benchmarks.limits [--n 10000000] [--rows 1000000]

Two limits, each measured in the same run on the same machine:

* ``solve()`` on ``n`` impacts, every field of the ``Impact``, against the **memory
  bound**: the time to copy as many bytes as it moves (the input arrays it reads once,
  ``vx, vy, omega``, plus every array of the result it writes), i.e. a copy of a buffer
  half that size (a copy reads and writes each byte). Reported as ``copy time / solve
  time`` (1 would be memory speed; the target is at least 0.3) against two copies: into
  fresh memory, as ``solve()`` must write its new result (the faster of NumPy's copy and
  a parallel Numba copy; the operating system supplies and zeroes each new page), and,
  stricter, a parallel copy into memory already touched (no page faults).
* ``batch`` on a ``rows``-row file, CSV and Parquet, against **Arrow's I/O**: pyarrow
  reading the same input file and writing a table of the batch's own output columns
  (read back from its output beforehand, outside the timing) in the same format.
  Reported as ``batch time / Arrow time``: the target is at most 2.
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

import numpy as np

from benchmarks.bench import best as one_time
from spinimpact import Body, solve
from spinimpact.io.batch import run_batch

BODY_COLUMNS = ("mass", "radius", "gyration", "zeta")  # the body's, not solve()'s, arrays
DEFAULTS = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere")


def _interleaved(fns, repeat: int) -> list[float]:
    """Best time of each of ``fns``, run in turn ``repeat`` times: a busy spell of the
    machine then slows each of them, not one alone."""
    best = [float("inf")] * len(fns)
    for _ in range(repeat):
        for k, fn in enumerate(fns):
            best[k] = min(best[k], one_time(fn, 1))
    return best


def _copies(nbytes: int) -> dict[str, object]:
    """Copies of a buffer of ``nbytes`` bytes: into fresh memory (as ``solve()`` allocates
    its result; NumPy's, and with Numba a parallel one) and into memory already touched."""
    src = np.ones(max(nbytes // 8, 1))
    ways: dict[str, object] = {"fresh": src.copy}
    try:
        import numba
    except ImportError:  # pragma: no cover - the [fast] extra
        return ways

    @numba.njit(parallel=True)
    def pcopy(a, b):
        for i in numba.prange(a.size):
            b[i] = a[i]

    def parallel_fresh():
        pcopy(src, np.empty_like(src))

    dst = np.empty_like(src)
    pcopy(src, dst)
    ways["parallel fresh"] = parallel_fresh
    ways["touched"] = lambda: pcopy(src, dst)
    return ways


def solve_limit(n: int, repeat: int = 4) -> dict:
    """``solve()`` of ``n`` impacts with every field, against copies of its bytes."""
    rng = np.random.default_rng(0)
    vx, vy, om = rng.normal(0, 3, n), -rng.uniform(0.1, 5, n), rng.normal(0, 60, n)
    ball = Body.solid_sphere(mass=1.0, radius=0.1)

    def run():
        solve(ball, vx, vy, om, mu=0.3, kappa=0.8)

    imp = solve(ball, vx, vy, om, mu=0.3, kappa=0.8)  # compiles or loads the kernel first
    written = sum(np.asarray(v).nbytes for k, v in imp.columns().items() if k not in BODY_COLUMNS)
    moved = written + vx.nbytes + vy.nbytes + om.nbytes
    del imp
    ways = _copies(moved // 2)
    t_solve, *times = _interleaved([run, *ways.values()], repeat)
    t = dict(zip(ways, times, strict=True))
    t_fresh = min(v for k, v in t.items() if k != "touched")
    t_touched = t.get("touched", t_fresh)
    return dict(n=n, moved=moved, t_solve=t_solve, t_fresh=t_fresh, t_touched=t_touched,
                ratio=t_fresh / t_solve, ratio_touched=t_touched / t_solve)  # fmt: skip


def _input(folder: Path, rows: int) -> tuple[Path, Path]:
    import pyarrow as pa
    import pyarrow.csv as pcsv
    import pyarrow.parquet as pq

    rng = np.random.default_rng(1)
    table = pa.table(
        {"vx": rng.normal(0, 3, rows), "vy": -rng.uniform(0.1, 5, rows),
         "omega": rng.normal(0, 60, rows), "mu": rng.uniform(0, 1, rows)}
    )  # fmt: skip
    csv_in, pq_in = folder / "in.csv", folder / "in.parquet"
    pcsv.write_csv(table, csv_in)
    pq.write_table(table, pq_in)
    return csv_in, pq_in


def batch_limit(rows: int, repeat: int = 3) -> list[dict]:
    """``batch`` of ``rows`` rows, CSV and Parquet, against Arrow reading the input and
    writing the output's columns."""
    import pyarrow.csv as pcsv
    import pyarrow.parquet as pq

    out = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        csv_in, pq_in = _input(folder, rows)
        for fmt, source, read, write, load in (
            ("CSV", csv_in, pcsv.read_csv, pcsv.write_csv, pcsv.read_csv),
            ("Parquet", pq_in, pq.read_table, pq.write_table, pq.read_table),
        ):
            target = folder / f"out{source.suffix}"
            run_batch(source, target, defaults=DEFAULTS)  # imports and compiles, untimed
            table = load(target)  # the batch's own output columns, as Arrow reads them back
            copy = folder / f"arrow{source.suffix}"

            def batch(source=source, target=target):
                run_batch(source, target, defaults=DEFAULTS)

            def arrow(read=read, write=write, source=source, table=table, copy=copy):
                read(source)
                write(table, copy)

            t_batch, t_arrow = _interleaved([batch, arrow], repeat)
            out.append(dict(fmt=fmt, rows=rows, columns=table.num_columns, t_batch=t_batch,
                            t_arrow=t_arrow, ratio=t_batch / t_arrow))  # fmt: skip
    return out


def lines(n: int, rows: int) -> list[str]:
    """The two limits as printable lines."""
    s = solve_limit(n)
    text = [
        f"solve() of {s['n']:,} impacts, every Impact field: {s['t_solve']:.3f} s to move "
        f"{s['moved'] / 1e9:.2f} GB: {s['ratio']:.2f} of a copy of those bytes into fresh "
        f"memory ({s['t_fresh']:.3f} s), {s['ratio_touched']:.2f} of a parallel copy into "
        f"memory already touched ({s['t_touched']:.3f} s) (target >= 0.3)"
    ]
    for b in batch_limit(rows):
        text.append(
            f"batch of {b['rows']:,} {b['fmt']} rows ({b['columns']} output columns): "
            f"{b['t_batch']:.2f} s; Arrow reading the input and writing those columns: "
            f"{b['t_arrow']:.2f} s: {b['ratio']:.2f} times Arrow's I/O (target <= 2)"
        )
    return text


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--n", type=int, default=10_000_000, help="impacts solved")
    parser.add_argument("--rows", type=int, default=1_000_000, help="rows of the batch files")
    args = parser.parse_args()
    for line in lines(args.n, args.rows):
        print(line)


if __name__ == "__main__":
    main()
