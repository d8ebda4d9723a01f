"""What sweeps write and refuse: files that name their regimes and units (Parquet, CSV,
``.npy`` with ``metadata.json``), output names of no known kind, and sweeps whose chunk or
output cannot fit, refused before anything large is allocated."""

import csv
import json

import numpy as np
import pytest

from spinimpact import solve
from spinimpact.core import REGIMES
from spinimpact.io.sweep import Sweep, estimate_sweep, parse_axis, run_sweep

from tests.io.test_sweep import BODY, every_point, make


def test_parquet_names_the_regimes_in_a_dictionary_column(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    sweep = make(chunk_size=700)
    run_sweep(sweep, output=tmp_path / "s.parquet", fields=("regime", "after_vx"))
    table = pq.read_table(tmp_path / "s.parquet")
    assert str(table.schema.field("regime").type) == (
        "dictionary<values=string, indices=int8, ordered=0>"
    )
    got = every_point(sweep, ("regime",))
    assert table.column("regime").to_pylist() == [REGIMES[c] for c in got["regime"]]
    assert json.loads(table.schema.metadata[b"regimes"]) == list(REGIMES)
    assert json.loads(table.schema.metadata[b"axes"])["vx"] == {
        "kind": "grid", "lo": -5.0, "hi": 5.0, "num": 61
    }  # fmt: skip
    assert json.loads(table.schema.metadata[b"axes"])["vy"] == {"kind": "fixed", "value": -4.0}


def test_npy_directory_names_the_regimes_units_and_body(tmp_path):
    spec = dict(vx="uniform:-5:5", vy="-4", omega="uniform:-50:50", mu="0.3", kappa="0.8")
    axes = {k: parse_axis(k, v) for k, v in spec.items()}
    out = tmp_path / "d"
    run_sweep(Sweep(BODY, axes, samples=3000, seed=5), output=out, fields=("regime", "after_omega"))
    meta = json.loads((out / "metadata.json").read_text())
    names = np.asarray(meta["regimes"])[np.load(out / "regime.npy")]  # how a reader gets names
    imp = solve(BODY, np.load(out / "vx.npy"), -4.0, np.load(out / "omega.npy"), mu=0.3, kappa=0.8)
    np.testing.assert_array_equal(names, imp.regime)
    assert meta["columns"]["regime"] == {
        "file": "regime.npy", "dtype": "int8", "values": "index into regimes"
    }  # fmt: skip
    assert meta["columns"]["after_omega"] == {
        "file": "after_omega.npy", "dtype": "float64", "unit": "rad/s"
    }  # fmt: skip
    assert meta["body"] == BODY.to_dict() and (meta["samples"], meta["seed"]) == (3000, 5)


def test_csv_output_is_a_csv_file_with_regime_names(tmp_path):
    pytest.importorskip("pyarrow.csv", reason="the [parquet] extra is not installed")
    sweep = make(chunk_size=900)
    run_sweep(sweep, output=tmp_path / "s.csv", fields=("after_vx", "regime"))
    run_sweep(sweep, output=tmp_path / "d", fields=("after_vx", "regime"))
    assert (tmp_path / "s.csv").is_file()
    with open(tmp_path / "s.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["vx", "vy", "omega", "mu", "kappa", "after_vx", "regime"]
    assert len(rows) == 1 + sweep.size
    columns = dict(zip(rows[0], zip(*rows[1:], strict=True), strict=True))
    for name in ("vx", "omega", "after_vx"):  # shortest text that reads back to the number
        np.testing.assert_array_equal(
            np.array(columns[name], float), np.load(tmp_path / "d" / f"{name}.npy")
        )
    assert list(columns["regime"]) == [REGIMES[c] for c in np.load(tmp_path / "d" / "regime.npy")]


@pytest.mark.parametrize("name", ["x.txt", "x.npy", "x.json", "run.v2"])
def test_an_output_name_of_no_known_kind_is_refused(tmp_path, name):
    with pytest.raises(ValueError, match=r"FILE\.parquet, FILE\.csv or a new directory"):
        run_sweep(make(), output=tmp_path / name)
    assert list(tmp_path.iterdir()) == []
    run_sweep(make(), output=f"{tmp_path / name}/")  # a trailing '/' asks for a directory
    assert (tmp_path / name / "vx.npy").is_file()


def test_sweeps_that_cannot_fit_are_refused_before_allocating(tmp_path):
    import tracemalloc

    huge = make(samples=10**12, chunk_size=10**12, vx="uniform:-5:5", omega="uniform:-50:50")
    tracemalloc.start()
    try:
        with pytest.raises(ValueError, match=r"a chunk of 1,000,000,000,000 points needs about"):
            run_sweep(huge)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 200 * 2**20  # the trial chunks only, never the chunk
    # an output larger than the disk (65 bytes a point: 59 TiB)
    big = make(samples=10**12, chunk_size=10**5, vx="uniform:-5:5", omega="uniform:-50:50")
    with pytest.raises(ValueError, match=r"the output needs about 59.1 TiB and .* is free"):
        run_sweep(big, output=tmp_path / "d")
    assert list(tmp_path.iterdir()) == []


def test_estimate_scales_trial_chunks():
    cost = estimate_sweep(make(chunk_size=200_000, vx="-5:5:10001", omega="-50:50:1001"))
    assert (cost.points, cost.chunks, cost.chunk_points) == (10_011_001, 51, 200_000)
    assert 0 < cost.seconds < 3600 and cost.output_bytes == 0 and cost.problems() == []
    assert 1e6 < cost.chunk_memory < 1e9  # tens of bytes a point
    assert str(cost).startswith("10,011,001 points in 51 chunks: about ")


@pytest.mark.parametrize("name", ["s.parquet", "s.csv", "d"])
def test_a_signal_stops_a_sweep_at_its_next_chunk_and_leaves_nothing(tmp_path, name):
    import os
    import signal

    from spinimpact.io import _stop

    pytest.importorskip("pyarrow.csv", reason="the [parquet] extra is not installed")
    done = []

    def progress(k, total):  # SIGTERM arrives while the first chunk is being written
        done.append(k)
        if k == 1:
            os.kill(os.getpid(), signal.SIGTERM)

    with _stop.stop_on_signals(), pytest.raises(_stop.Stopped):
        run_sweep(make(chunk_size=100), output=tmp_path / name, progress=progress)
    assert done == [1]  # not the 26 chunks of the sweep
    assert list(tmp_path.iterdir()) == []
