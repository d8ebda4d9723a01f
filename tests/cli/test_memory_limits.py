"""Commands under an address-space limit (``ulimit -v``): they finish, or stop with one
line naming the option that bounds their memory, exit 2, the old output intact and no
temporary file left; never a traceback.

Thread pools (OpenBLAS, Numba, pyarrow) reserve address space per thread, so under a limit
they are capped (spinimpact._limits): a small batch runs under 800 MiB, where it used to
die with a MemoryError traceback inside Numba's start-up. A chunk too large for the limit
is refused in one line naming --chunk-size."""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.limits import under_limits

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(sys.platform != "linux", reason="RLIMIT_AS as Linux counts it"),
]

MiB = 2**20
OLD = b"old output the user keeps\n"


def batch(folder: Path, rows: int, limit: int, *args: str) -> subprocess.CompletedProcess:
    rng = np.random.default_rng(1)
    cells = np.column_stack([rng.uniform(-5, 5, rows), rng.uniform(-5, -0.1, rows),
                             rng.uniform(-50, 50, rows)])  # fmt: skip
    np.savetxt(folder / "in.csv", cells, delimiter=",", header="vx,vy,omega", comments="")
    (folder / "out.csv").write_bytes(OLD)
    command = [sys.executable, "-m", "spinimpact", "batch", "in.csv", "--output", "out.csv"]
    return subprocess.run(under_limits([*command, *args], RLIMIT_AS=limit), cwd=folder,
                          capture_output=True, text=True, timeout=300)  # fmt: skip


@pytest.fixture(scope="module", autouse=True)
def compiled(tmp_path_factory):
    """Every kernel and a batch without a limit first: Numba compiles its kernels (and caches
    them on disk) outside the limit. LLVM compiling under a tight limit can abort the
    process, which no handler can catch; a user meets the limit with kernels already
    compiled (under a limit, a command loads them all before it reads any data)."""
    load = "from spinimpact.core.preload import load_kernels; load_kernels()"
    subprocess.run([sys.executable, "-c", load], capture_output=True, check=True, timeout=600)
    folder = tmp_path_factory.mktemp("compile")
    rng = np.random.default_rng(2)
    cells = np.column_stack([rng.uniform(-5, 5, 50), rng.uniform(-5, -0.1, 50),
                             rng.uniform(-50, 50, 50)])  # fmt: skip
    np.savetxt(folder / "in.csv", cells, delimiter=",", header="vx,vy,omega", comments="")
    command = [sys.executable, "-m", "spinimpact", "batch", "in.csv", "--output", "out.csv"]
    subprocess.run(command, cwd=folder, capture_output=True, check=True, timeout=300)


def test_a_small_batch_runs_under_800_mib_of_address_space(tmp_path):
    out = batch(tmp_path, 1000, 800 * MiB)
    assert out.returncode == 0, out.stderr
    assert (tmp_path / "out.csv").read_text().count("\n") == 1001


def test_a_chunk_too_large_for_the_limit_is_refused_naming_chunk_size(tmp_path):
    out = batch(tmp_path, 300_000, 600 * MiB, "--chunk-size", "300000")
    assert out.returncode == 2, out.stderr
    assert "Traceback" not in out.stderr and len(out.stderr.splitlines()) == 1
    assert out.stderr.startswith("spinimpact: error: out of memory (")
    assert "lower --chunk-size" in out.stderr
    assert (tmp_path / "out.csv").read_bytes() == OLD
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv", "out.csv"]


@pytest.mark.parametrize(
    ("error", "out_of_memory"),
    [
        (OSError("/x/workqueue.so: failed to map segment from shared object"), True),
        (ImportError("libfoo.so: failed to map segment from shared object"), True),
        (OSError(12, "Cannot allocate memory"), True),
        (OSError(2, "No such file or directory"), False),
    ],
)
def test_a_library_that_cannot_be_mapped_is_out_of_memory(monkeypatch, capsys, error,
                                                          out_of_memory):  # fmt: skip
    from spinimpact.cli._common import errors_to_exit_2

    monkeypatch.setattr("sys.argv", ["spinimpact", "batch", "in.csv"])
    with pytest.raises(SystemExit) as stop, errors_to_exit_2():
        raise error
    assert stop.value.code == 2
    message = capsys.readouterr().err
    assert message.startswith("spinimpact: error: out of memory (") == out_of_memory
    assert ("lower --chunk-size" in message) == out_of_memory


def test_under_a_limit_numbas_threads_start_at_import():
    # Numba's default threading layer ignores a worker thread that fails to start, and its
    # first parallel call then waits for it forever: a batch that reached that call with a
    # large chunk in memory hung. Under a limit the threads start when spinimpact imports.
    pytest.importorskip("numba")
    probe = ("import spinimpact.core.fused as f, numba.np.ufunc.parallel as p; "
             "print(f.HAVE_NUMBA, p._is_initialized)")  # fmt: skip
    limited = subprocess.run(under_limits([sys.executable, "-c", probe], RLIMIT_AS=800 * MiB),
                             capture_output=True, text=True, timeout=120)  # fmt: skip
    assert limited.stdout.split() == ["True", "True"], limited.stderr
    free = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          timeout=120)  # fmt: skip
    assert free.stdout.split() == ["True", "False"], free.stderr  # no limit: started lazily


@pytest.mark.parametrize("limited", [True, False])
def test_a_call_that_failed_without_an_exception_is_out_of_memory_under_a_limit(
    monkeypatch, capsys, limited
):
    # Under ulimit -v, Python may find no room even for the MemoryError's traceback: the
    # call then "returned NULL without setting an exception" (a SystemError).
    from spinimpact.cli._common import errors_to_exit_2

    monkeypatch.setattr("spinimpact._limits.address_limit", lambda: 600 * MiB if limited else None)
    monkeypatch.setattr("sys.argv", ["spinimpact", "batch", "in.csv"])
    error = SystemError("<function f at 0x1> returned NULL without setting an exception")
    if not limited:  # without a limit it is a bug, and keeps its traceback
        with pytest.raises(SystemError), errors_to_exit_2():
            raise error
        return
    with pytest.raises(SystemExit) as stop, errors_to_exit_2():
        raise error
    assert stop.value.code == 2
    assert capsys.readouterr().err.startswith("spinimpact: error: out of memory (")
