"""`spinimpact batch --dask ADDRESS`: the chunks solved on a Dask cluster, the same output."""

import pytest

from tests.io.test_batch import write_csv


@pytest.mark.slow
def test_batch_on_a_dask_cluster_writes_the_same_file(cli, tmp_path):
    distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")
    rows = [[f"{0.1 * k:.1f}", f"{-1 - 0.01 * k:.2f}", f"{k - 50}"] for k in range(300)]
    write_csv(tmp_path / "in.csv", ["vx", "vy", "omega"], rows)
    common = ("batch", tmp_path / "in.csv", "--chunk-size", "32")
    status, _, err = cli(*common, "--output", tmp_path / "local.csv")
    assert status == 0, err
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0"
    ) as cluster:
        status, stdout, err = cli(*common, "--output", tmp_path / "dask.csv",
                                  "--dask", cluster.scheduler_address)  # fmt: skip
    assert status == 0, err
    assert "wrote 300 rows" in stdout
    assert (tmp_path / "dask.csv").read_bytes() == (tmp_path / "local.csv").read_bytes()


def test_batch_dask_without_distributed_is_one_line(cli, tmp_path, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "distributed", None)
    write_csv(tmp_path / "in.csv", ["vx", "vy", "omega"], [["1", "-1", "0"]])
    status, _, err = cli("batch", tmp_path / "in.csv", "--output", tmp_path / "o.csv",
                         "--dask", "tcp://127.0.0.1:1")  # fmt: skip
    assert status == 2 and "pip install 'spinimpact[dask]'" in err
    assert len(err.strip().splitlines()) == 1 and not (tmp_path / "o.csv").exists()
