"""Atomic outputs: named, locked temporaries that the next run removes after a kill;
renames that wait for the whole command; links and permissions handled as ``cp`` would."""

import ctypes
import errno
import os
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import textwrap
import time
import weakref
from pathlib import Path

import numpy as np
import pytest

from spinimpact.io import _stop
from spinimpact.io._sinks import npy_columns, parquet_columns
from spinimpact.io.atomic import (
    TEMPORARY_TAG,
    atomic_directory,
    atomic_outputs,
    atomic_path,
    remove_stale,
)

NOBODY = 65534
as_root = pytest.mark.skipif(
    not hasattr(os, "geteuid") or os.geteuid() != 0, reason="needs root to run a child as nobody"
)


def child(code, *args, user=None, check=True):
    """Run ``code`` in a fresh interpreter; with ``user``, it drops to that user (uid and
    gid) after its imports and before running ``code`` (the interpreter itself may lie
    where that user cannot read)."""
    drop = (
        "import os, sys, spinimpact.io.atomic\n"  # what the code imports, read as root
        f"os.setgroups([]); os.setgid({user}); os.setuid({user})\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", (drop if user else "") + textwrap.dedent(code), *map(str, args)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    if check:
        assert run.returncode == 0, run.stderr[-2000:]
    return run


def hidden(folder):
    return sorted(p.name for p in folder.iterdir() if p.name.startswith("."))


@pytest.fixture
def shared():
    """A directory everyone may write, reachable by another user (tmp_path is not)."""
    folder = tempfile.mkdtemp(prefix="spinimpact-test-")
    os.chmod(folder, 0o777)
    yield Path(folder)
    shutil.rmtree(folder, ignore_errors=True)


KILL_INSIDE = """
    import os, signal, sys
    from spinimpact.io.atomic import atomic_path, atomic_directory
    target, kind = sys.argv[1:3]
    opener = atomic_directory if kind == "dir" else atomic_path
    with opener(target) as tmp:
        if kind == "dir":
            (tmp / "x.npy").write_bytes(b"0" * 1000)
        else:
            tmp.write_bytes(b"0" * 1000)
        os.kill(os.getpid(), signal.SIGKILL)
"""


@pytest.mark.parametrize("kind", ["file", "dir"])
@pytest.mark.slow
def test_a_killed_runs_temporary_is_named_and_removed_by_the_next_run(tmp_path, kind):
    target = tmp_path / ("out.csv" if kind == "file" else "grid")
    run = child(KILL_INSIDE, target, kind, check=False)
    assert run.returncode == -signal.SIGKILL
    (left,) = hidden(tmp_path)  # SIGKILL leaves it: nothing can run in the killed process
    assert left.startswith(f".{target.name}.{TEMPORARY_TAG}-")
    keep = tmp_path / ".keep.csv.part"  # not named as ours: never touched
    keep.write_text("mine")
    with atomic_path(tmp_path / "other.csv") as tmp:  # any later output in that folder
        tmp.write_text("new")
    assert hidden(tmp_path) == [".keep.csv.part"]
    assert sorted(p.name for p in tmp_path.iterdir()) == [".keep.csv.part", "other.csv"]


LIVE = """
    import sys
    from spinimpact.io.atomic import atomic_path
    with atomic_path(sys.argv[1]) as tmp:
        tmp.write_text("partial")
        print(tmp.name, flush=True)
        sys.stdin.readline()  # hold the temporary until told
"""


@pytest.mark.slow
def test_a_running_processs_temporary_is_left_alone(tmp_path):
    target = tmp_path / "out.csv"
    with subprocess.Popen(
        [sys.executable, "-c", textwrap.dedent(LIVE), str(target)],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        text=True,
    ) as proc:
        name = proc.stdout.readline().strip()
        assert name.startswith(f".out.csv.{TEMPORARY_TAG}-")
        assert remove_stale(tmp_path) == []  # locked by its process
        assert (tmp_path / name).read_text() == "partial"
        proc.stdin.write("\n")
        proc.stdin.flush()
        assert proc.wait(timeout=60) == 0
    assert target.read_text() == "partial"
    assert hidden(tmp_path) == []


def test_a_newborn_temporary_is_removed_only_when_old(tmp_path):
    # Before its lock is taken a temporary has a "newborn" name for a moment; one left by
    # a kill at that moment is removed once it is a minute old, so a live one is safe.
    newborn = tmp_path / ".out.csv.spinimpact-new-abc123"
    newborn.write_text("")
    assert remove_stale(tmp_path) == []
    old = time.time() - 120
    os.utime(newborn, (old, old))
    assert remove_stale(tmp_path) == [newborn.name]


def test_a_link_named_as_a_temporary_is_not_followed(tmp_path):
    victim = tmp_path / "victim"
    victim.mkdir()
    (victim / "data").write_text("keep")
    (tmp_path / f".x.{TEMPORARY_TAG}-abc").symlink_to(victim)
    assert remove_stale(tmp_path) == []
    assert (victim / "data").read_text() == "keep"


def test_renames_wait_for_the_end_of_atomic_outputs(tmp_path):
    a, b = tmp_path / "a.txt", tmp_path / "b.txt"
    a.write_text("old a")
    with atomic_outputs():
        with atomic_path(a) as tmp:
            tmp.write_text("new a")
        with atomic_path(b) as tmp:
            tmp.write_text("new b")
        assert a.read_text() == "old a" and not b.exists()  # not yet
    assert (a.read_text(), b.read_text()) == ("new a", "new b")
    assert hidden(tmp_path) == []


def test_a_failure_after_writing_changes_no_output(tmp_path):
    a = tmp_path / "a.txt"
    a.write_text("old a")
    with pytest.raises(OSError, match="No space"), atomic_outputs():
        with atomic_path(a) as tmp:
            tmp.write_text("new a")
        with atomic_directory(tmp_path / "grid") as tmp:
            (tmp / "x.npy").write_bytes(b"1")
        raise OSError(errno.ENOSPC, "No space left on device")  # e.g. stdout on /dev/full
    assert a.read_text() == "old a"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt"]


def test_a_stop_recorded_before_the_end_changes_no_output(tmp_path):
    a = tmp_path / "a.txt"
    a.write_text("old a")
    with _stop.stop_on_signals():
        with pytest.raises(_stop.Stopped) as stopped, atomic_outputs():
            with atomic_path(a) as tmp:
                tmp.write_text("new a")
                signal.raise_signal(signal.SIGTERM)  # while a temporary exists: recorded
                tmp.write_text("newer a")  # ... and the work goes on to a safe point
        assert stopped.value.signum == signal.SIGTERM
    assert a.read_text() == "old a"
    assert hidden(tmp_path) == []


def test_a_signal_outside_any_output_stops_at_once():
    with _stop.stop_on_signals(), pytest.raises(_stop.Stopped):
        signal.raise_signal(signal.SIGINT)
        pytest.fail("not stopped")  # pragma: no cover
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # restored


def _wait_for_the_retry() -> None:
    """Run Python code for up to 10 s: a deferred stop is raised here (20 ms later)."""
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        time.sleep(0.001)
    pytest.fail("not stopped after the callback returned")  # pragma: no cover


def test_a_signal_inside_a_callback_from_compiled_code_stops_once_back(capfd):
    # llvmlite calls back into Python while Numba compiles; an exception raised there is
    # printed and swallowed by ctypes. The stop must wait until the callback has returned.
    where = {"__name__": "llvmlite.binding.callback", "signal": signal}
    exec("def notify():\n    signal.raise_signal(signal.SIGINT)\n", where)
    callback = ctypes.CFUNCTYPE(None)(where["notify"])
    returned = False
    with _stop.stop_on_signals(), pytest.raises(_stop.Stopped) as stopped:
        callback()  # through C, as compiled code calls it
        returned = True
        _wait_for_the_retry()
    assert returned
    assert stopped.value.signum == signal.SIGINT
    assert capfd.readouterr().err == ""  # nothing swallowed and printed
    assert signal.getsignal(signal.SIGALRM) is signal.SIG_DFL  # restored


@pytest.mark.parametrize("where", ["importlib._bootstrap", "__del__"])
def test_a_signal_where_exceptions_are_swallowed_stops_once_back(where, capfd):
    # A weak-reference callback of the import system's module locks, or a __del__, prints
    # and swallows an exception raised in it (seen in the signal stress test: "Exception
    # ignored in: <function _get_module_lock.<locals>.cb>"). The stop must wait.
    if where == "__del__":

        class Doomed:
            def __del__(self):
                signal.raise_signal(signal.SIGINT)

        def trigger():
            Doomed()  # dropped at once: __del__ runs here
    else:
        module = {"__name__": where, "signal": signal}
        exec("def cb(_ref):\n    signal.raise_signal(signal.SIGINT)\n", module)

        class Target:
            pass

        def trigger():
            target = Target()
            ref = weakref.ref(target, module["cb"])
            del target  # the callback runs here, as at the end of an import
            return ref

    returned = False
    with _stop.stop_on_signals(), pytest.raises(_stop.Stopped) as stopped:
        trigger()
        returned = True
        _wait_for_the_retry()
    assert returned
    assert stopped.value.signum == signal.SIGINT
    assert capfd.readouterr().err == ""  # nothing swallowed and printed


def test_writes_through_a_link_onto_its_target(tmp_path):
    target = tmp_path / "data" / "out.csv"
    target.parent.mkdir()
    target.write_text("old")
    os.chmod(target, 0o640)
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    with atomic_path(link) as tmp:
        assert tmp.parent == target.parent  # the temporary lies beside the real file
        tmp.write_text("new")
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == "new"
    assert stat.S_IMODE(target.stat().st_mode) == 0o640
    dangling = tmp_path / "dangling.csv"
    dangling.symlink_to(tmp_path / "data" / "fresh.csv")
    with atomic_path(dangling) as tmp:
        tmp.write_text("fresh")
    assert dangling.is_symlink() and (tmp_path / "data" / "fresh.csv").read_text() == "fresh"


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
@pytest.mark.parametrize("sink", ["atomic_path", "parquet_columns"])
def test_a_link_to_a_device_is_written_to_and_kept(tmp_path, sink):
    link = tmp_path / "out.parquet"
    link.symlink_to("/dev/full")
    with pytest.raises(OSError) as error:
        if sink == "atomic_path":
            with atomic_path(link) as tmp, open(tmp, "w") as f:
                f.write("x")
        else:
            pytest.importorskip("pyarrow")
            with parquet_columns(link) as out:
                out.write({"vx": np.arange(100_000.0)})
    assert "No space left on device" in str(error.value) or error.value.errno == errno.ENOSPC
    assert link.is_symlink() and os.readlink(link) == "/dev/full"
    assert [p.name for p in tmp_path.iterdir()] == ["out.parquet"]


WRITE = """
    import sys
    from spinimpact.io.atomic import atomic_path
    try:
        with atomic_path(sys.argv[1]) as tmp:
            tmp.write_text("replaced")
    except PermissionError as error:
        print(error)
        sys.exit(13)
"""


@as_root
@pytest.mark.slow
def test_a_read_only_file_of_another_user_is_not_replaced(shared):
    target = shared / "report.html"
    target.write_text("root's")
    os.chmod(target, 0o444)  # owned by root; the folder lets anyone create and rename
    run = child(WRITE, target, user=NOBODY, check=False)
    assert run.returncode == 13, run.stderr
    assert run.stdout.strip() == f"[Errno 13] Permission denied: '{target}'"
    assert target.read_text() == "root's"
    assert sorted(p.name for p in shared.iterdir()) == ["report.html"]


@pytest.mark.slow
def test_a_file_the_process_may_not_write_is_refused(shared):
    # Whoever runs the tests: a 0444 file of another user (root runs the writer as nobody),
    # or the user's own 0444 file (as cp, which opens the file for writing, refuses it).
    target = shared / "out.csv"
    target.write_text("keep")
    os.chmod(target, 0o444)
    user = NOBODY if os.geteuid() == 0 else None
    run = child(WRITE, target, user=user, check=False)
    assert run.returncode == 13
    assert target.read_text() == "keep"


@as_root
def test_root_keeps_the_owner_and_mode_of_the_file_it_replaces(shared):
    target = shared / "out.csv"
    target.write_text("nobody's")
    os.chown(target, NOBODY, NOBODY)
    os.chmod(target, 0o604)
    with atomic_path(target) as tmp:
        tmp.write_text("new")
    info = target.stat()
    assert (info.st_uid, info.st_gid, stat.S_IMODE(info.st_mode)) == (NOBODY, NOBODY, 0o604)
    assert target.read_text() == "new"


NPY_FULL = """
    import resource, signal, sys
    import numpy as np
    from spinimpact.io._sinks import npy_columns
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails with EFBIG
    resource.setrlimit(resource.RLIMIT_FSIZE, (1000, 1000))
    n = int(sys.argv[2])
    try:
        with npy_columns(sys.argv[1], ["vx"], n) as out:
            out.write({"vx": np.zeros(n)})
    except OSError as error:
        print(error.errno)
"""


# 50,000 values fail as they are written; 500 (4 kB) wait in the file's buffer and fail
# when it is flushed at close, which used to raise before the folder was removed.
@pytest.mark.parametrize("values", [50_000, 500])
@pytest.mark.slow
def test_a_npy_sweep_that_fills_the_disk_leaves_no_folder(tmp_path, values):
    run = child(NPY_FULL, tmp_path / "grid", values)
    assert run.stdout.strip() == str(errno.EFBIG)
    assert list(tmp_path.iterdir()) == []


def test_new_outputs_get_ordinary_permissions(tmp_path):
    with atomic_path(tmp_path / "a.csv") as tmp:
        tmp.write_text("x")
        assert stat.S_IMODE(tmp.stat().st_mode) == 0o600  # private while partial
    with npy_columns(tmp_path / "grid", ["vx"], 1) as out:
        out.write({"vx": np.zeros(1)})
    mask = os.umask(0)
    os.umask(mask)
    assert stat.S_IMODE((tmp_path / "a.csv").stat().st_mode) == 0o666 & ~mask
    assert stat.S_IMODE((tmp_path / "grid").stat().st_mode) == 0o777 & ~mask
    assert stat.S_IMODE((tmp_path / "grid" / "vx.npy").stat().st_mode) == 0o666 & ~mask


def test_discard_all_removes_every_live_temporary_and_keeps_the_old_output(tmp_path):
    # what a process that ends at once after running out of memory calls first
    from spinimpact.io.atomic import discard_all

    a = tmp_path / "a.txt"
    a.write_text("old a")
    with pytest.raises(RuntimeError), atomic_outputs(), atomic_path(a) as tmp:
        tmp.write_text("new a")
        assert hidden(tmp_path) != []
        discard_all()
        assert hidden(tmp_path) == []
        raise RuntimeError("the run fails")
    assert a.read_text() == "old a"
    assert hidden(tmp_path) == []
