"""`spinimpact batch` (and `report`) outputs as the shell sees them: a run that fails
changes no file, links are written through, permissions respected, temporaries of killed
runs removed; `--fields` and `-` for standard input and output."""

import csv
import io
import os
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from spinimpact.cli import main
from spinimpact.io.atomic import TEMPORARY_TAG
from spinimpact.io.batch import result_columns

from tests.limits import under_limits

HAS_FULL = os.path.exists("/dev/full")


def spinimpact(*args, **kwargs):
    if "stdout" not in kwargs:
        kwargs.setdefault("capture_output", True)
    return subprocess.run(
        [sys.executable, "-m", "spinimpact", *map(str, args)], text=True, timeout=120, **kwargs
    )


def incidences(path, n=3):
    rows = [f"{1 + i % 5},{-1 - i % 3},{i % 11 - 5}" for i in range(n)]
    path.write_text("vx,vy,omega\n" + "\n".join(rows) + "\n")
    return path


def one_error_line(run):
    assert run.returncode == 2, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("spinimpact: error: "), run.stderr
    return lines[0]


@pytest.mark.skipif(not HAS_FULL, reason="needs /dev/full")
@pytest.mark.parametrize("command", ["batch", "report"])
@pytest.mark.slow
def test_a_full_standard_output_leaves_the_old_output(tmp_path, command):
    keep = tmp_path / ("keep.csv" if command == "batch" else "keep.html")
    keep.write_text("old")
    args = [incidences(tmp_path / "in.csv"), "--output", keep] if command == "batch" else [
        "--output", keep]  # fmt: skip
    with open("/dev/full", "w") as full:
        run = spinimpact(command, *args, stdout=full, stderr=subprocess.PIPE)
    assert "No space left on device" in one_error_line(run)
    assert keep.read_text() == "old"
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


@pytest.mark.slow
def test_a_write_that_fails_part_way_leaves_the_old_output(tmp_path):
    keep = tmp_path / "keep.csv"
    keep.write_text("old")
    command = [sys.executable, "-m", "spinimpact", "batch", incidences(tmp_path / "in.csv", 2000),
               "--output", keep]  # fmt: skip
    # files of at most 20,000 bytes; SIGXFSZ ignored, so a write past that fails (EFBIG)
    command = under_limits(command, ignore=["SIGXFSZ"], RLIMIT_FSIZE=20_000)
    run = subprocess.run(command, capture_output=True, text=True, timeout=120)
    assert "File too large" in one_error_line(run)
    assert keep.read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv", "keep.csv"]


@pytest.mark.slow
def test_a_linked_output_is_written_through_the_link(tmp_path):
    (tmp_path / "results").mkdir()
    target = tmp_path / "results" / "out.csv"
    target.write_text("old")
    link = tmp_path / "out.csv"
    link.symlink_to(target)
    run = spinimpact("batch", incidences(tmp_path / "in.csv"), "--output", link)
    assert run.returncode == 0, run.stderr
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text().splitlines()[0].startswith("vx,vy,omega,")


@pytest.mark.skipif(not HAS_FULL, reason="needs /dev/full")
@pytest.mark.parametrize("command", ["batch", "sweep"])
@pytest.mark.slow
def test_a_link_to_a_full_device_fails_and_stays(tmp_path, command):
    pytest.importorskip("pyarrow")
    link = tmp_path / "out.parquet"
    link.symlink_to("/dev/full")
    args = {
        "batch": [incidences(tmp_path / "in.csv")],
        "sweep": ["--vx", "-1:1:5", "--omega", "0"],
    }[command]
    run = spinimpact(command, *args, "--output", link)
    assert "No space left on device" in one_error_line(run)
    assert link.is_symlink() and os.readlink(link) == "/dev/full"


# The interpreter lies where only root may read (/root): the child runs the command once
# as root into a scratch file, so every module is imported, then drops to nobody and runs it.
DROP_AND_RUN = """
    import contextlib, io, os, sys
    import spinimpact.cli
    scratch = os.path.join(os.path.dirname(sys.argv[-1]), "scratch.csv")
    with contextlib.redirect_stdout(io.StringIO()):
        spinimpact.cli.main(sys.argv[1:-1] + [scratch])
    os.remove(scratch)
    os.remove(scratch[: -len(".csv")] + ".units.json")  # the CSV's side file of units
    os.setgroups([]); os.setgid(65534); os.setuid(65534)
    spinimpact.cli.main(sys.argv[1:])
"""


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() != 0, reason="needs root")
@pytest.mark.slow
def test_a_read_only_output_of_root_is_not_replaced_by_an_unprivileged_run(tmp_path):
    # Every command writes through atomic_path (tests/io/test_atomic.py checks it as
    # nobody too); batch is the quick one to run.
    import shutil
    import tempfile

    shared = Path(tempfile.mkdtemp(prefix="spinimpact-test-"))  # tmp_path is root's alone
    try:
        os.chmod(shared, 0o777)
        source = incidences(shared / "in.csv")
        keep = shared / "keep.csv"
        keep.write_text("root's")
        os.chmod(keep, 0o444)
        run = subprocess.run(
            [sys.executable, "-c", textwrap.dedent(DROP_AND_RUN), "batch", source, "--output",
             keep],
            capture_output=True,
            text=True,
            timeout=120,
        )  # fmt: skip
        assert one_error_line(run) == f"spinimpact: error: {keep}: Permission denied"
        assert keep.read_text() == "root's"
        assert sorted(p.name for p in shared.iterdir()) == ["in.csv", "keep.csv"]
    finally:
        shutil.rmtree(shared, ignore_errors=True)


@pytest.mark.slow
def test_a_killed_runs_temporary_is_removed_by_the_next_run(tmp_path):
    source = incidences(tmp_path / "in.csv", 200_000)
    output = tmp_path / "out.csv"
    with subprocess.Popen(
        [sys.executable, "-m", "spinimpact", "batch", source, "--output", output,
         "--chunk-size", "1000"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    ) as proc:  # fmt: skip
        deadline = time.monotonic() + 60
        # both temporaries (the CSV's and its units file's) are made one after the other:
        # the kill comes once both are there, whatever the machine's load
        while len([p for p in tmp_path.iterdir() if TEMPORARY_TAG in p.name]) < 2:
            assert proc.poll() is None and time.monotonic() < deadline, "no temporaries seen"
            time.sleep(0.01)
        proc.kill()  # SIGKILL: nothing can clean up in the process itself
    left = sorted(p.name for p in tmp_path.iterdir() if p.name.startswith("."))
    assert [name.split(TEMPORARY_TAG)[0] for name in left] == [".out.csv.", ".out.units.json."]
    small = incidences(tmp_path / "small.csv")
    run = spinimpact("batch", small, "--output", tmp_path / "other.csv")
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "in.csv",
        "other.csv",
        "other.units.json",
        "small.csv",
    ]


def run_main(capsys, monkeypatch, *args, stdin=None):
    """The command in this process (quicker than a subprocess): (status, stdout, stderr)."""
    if stdin is not None:
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(stdin.encode())))
    try:
        main([str(a) for a in args])
        status = 0
    except SystemExit as exit_:
        status = exit_.code
    out = capsys.readouterr()
    return subprocess.CompletedProcess(args, status, out.out, out.err)


def test_fields_choose_the_columns(tmp_path, capsys, monkeypatch):
    out = tmp_path / "out.csv"
    run = run_main(
        capsys, monkeypatch, "batch", incidences(tmp_path / "in.csv"), "--output", out,
        "--fields", "regime,after_vx,dissipated_fraction",
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    with open(out, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
    assert reader.fieldnames == ["vx", "vy", "omega", "regime", "after_vx", "dissipated_fraction"]
    assert len(rows) == 3 and all(r["regime"] for r in rows)


def test_a_bad_field_is_one_line_listing_the_valid_ones(tmp_path, capsys, monkeypatch):
    out = tmp_path / "out.csv"
    run = run_main(capsys, monkeypatch, "batch", incidences(tmp_path / "in.csv"), "--output",
                   out, "--fields", "regime,aftervx")  # fmt: skip
    line = one_error_line(run)
    assert line.startswith("spinimpact: error: --fields: unknown output field 'aftervx'; ")
    assert line.endswith(", ".join(result_columns()))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv"]


def test_dash_streams_into_a_pipe_with_fields(tmp_path, capsys, monkeypatch):
    source = incidences(tmp_path / "in.csv", 5)
    run = run_main(capsys, monkeypatch, "batch", "-", "--output", "-", "--fields", "regime",
                   stdin=source.read_text())  # fmt: skip
    assert run.returncode == 0, run.stderr
    rows = list(csv.reader(io.StringIO(run.stdout)))
    assert rows[0] == ["vx", "vy", "omega", "regime"] and len(rows) == 6
    assert run.stderr.strip() == "wrote 5 rows to -"


def test_a_bad_row_on_standard_input_is_one_line(capsys, monkeypatch):
    run = run_main(capsys, monkeypatch, "batch", "-", "--output", "-",
                   stdin="vx,vy,omega\n1,-2,\u0661\n")  # fmt: skip
    line = one_error_line(run)
    assert line == "spinimpact: error: row 1 (line 2), column omega: '\u0661' is not a number"
    assert run.stdout == ""


@pytest.mark.slow
def test_dash_reads_standard_input_and_writes_standard_output(tmp_path):
    source = incidences(tmp_path / "in.csv", 50)
    by_file = tmp_path / "out.csv"
    assert spinimpact("batch", source, "--output", by_file).returncode == 0
    run = spinimpact("batch", "-", "--output", "-", input=source.read_text())
    assert run.returncode == 0, run.stderr
    assert run.stdout == by_file.read_text()  # the same rows, byte for byte
    assert run.stderr.strip() == "wrote 50 rows to -"  # the summary keeps out of the data
    # standard output has no side file of units: only the file output's is there
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv", "out.csv", "out.units.json"]
