"""`run_batch(..., client=...)` and `spinimpact batch --dask`: chunks solved on a Dask
cluster, the output the same, byte for byte, as without one."""

import numpy as np
import pytest

from spinimpact.io.batch import BatchError, run_batch

from tests.io.test_batch import write_csv

distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")
pytestmark = pytest.mark.slow  # a cluster starts in about 2 s

DEFAULTS = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere", gyration=None)


@pytest.fixture(scope="module")
def client():
    """An in-process cluster: two workers of one thread, so chunks are in flight at once."""
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0"
        ) as cluster,
        distributed.Client(cluster) as c,
    ):
        yield c


def write(path, header, rows):
    write_csv(path, header, rows)
    return path


def paper_rows(n, bad_every=0):
    rng = np.random.default_rng(11)
    rows = []
    for i in range(n):
        vy = -rng.uniform(0.1, 5)
        if bad_every and i % bad_every == 3:
            vy = 1.0  # not approaching: a bad row
        rows.append([repr(float(x)) for x in (rng.normal(0, 3), vy, rng.normal(0, 60))])
    return rows


def pair_rows(n):
    rng = np.random.default_rng(12)
    rows = []
    for _ in range(n):
        v1 = [rng.uniform(0.5, 2), rng.normal(0, 0.3), rng.normal(0, 0.3)]
        w1 = rng.normal(0, 20, 3)
        rows.append([*(repr(float(x)) for x in (*v1, *w1)), *(["0"] * 6), "-1", "0", "0"])
    return rows


PAIR = ["vx", "vy", "vz", "wx", "wy", "wz", "vx2", "vy2", "vz2", "wx2", "wy2", "wz2",
        "normal_x", "normal_y", "normal_z"]  # fmt: skip


@pytest.mark.parametrize(
    "header, rows, suffix, on_error",
    [
        (["vx", "vy", "omega"], paper_rows(1003), ".csv", "stop"),
        (["vx", "vy", "omega"], paper_rows(1003, bad_every=97), ".csv", "skip"),
        (PAIR, pair_rows(501), ".csv", "stop"),
        (PAIR, pair_rows(501), ".parquet", "stop"),
    ],
    ids=["paper", "paper-skip", "pair", "pair-parquet"],
)
def test_dask_output_is_byte_for_byte_the_local_one(
    tmp_path, client, header, rows, suffix, on_error
):
    if suffix == ".parquet":
        pytest.importorskip("pyarrow", reason="the [parquet] extra is not installed")
    source = write(tmp_path / "in.csv", header, rows)
    common = dict(defaults=DEFAULTS, on_error=on_error, chunk_size=64)
    local = run_batch(source, tmp_path / f"local{suffix}", **common)
    with distributed.get_task_stream(client) as tasks:
        remote = run_batch(source, tmp_path / f"dask{suffix}", client=client, **common)
    assert len(tasks.data) == -(-len(rows) // 64)  # every chunk was solved on the cluster
    assert (remote.rows, remote.skipped, remote.kind) == (local.rows, local.skipped, local.kind)
    assert remote.rows == len(rows) and (remote.skipped > 0) == (on_error == "skip")
    assert (tmp_path / f"dask{suffix}").read_bytes() == (tmp_path / f"local{suffix}").read_bytes()


def test_a_bad_row_on_the_cluster_is_named_and_nothing_is_written(tmp_path, client):
    source = write(tmp_path / "in.csv", ["vx", "vy", "omega"], paper_rows(1003, bad_every=500))
    with pytest.raises(BatchError, match=r"row 4 \(line 5\)"):
        run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, chunk_size=64, client=client)
    assert not (tmp_path / "out.csv").exists()
