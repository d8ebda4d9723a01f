"""CSV files as a reader sees them: a number is written the same way in an input column as
in a result column (no quotes), the header is plain names, and text is quoted only where
it must be (a comma, a quote or a line break in it), so the file reads back to the same
cells."""

import csv

import pytest

from spinimpact.cli import main

pytest.importorskip("pyarrow")


def _run(*args):
    try:
        main([str(a) for a in args])
    except SystemExit as stop:
        assert stop.code in (0, None)


def test_batch_csv_quotes_neither_numbers_nor_names(tmp_path, capsys):
    source = tmp_path / "in.csv"
    source.write_text("vx,vy,omega\n3,-4,0\n1,-1,2\n")
    target = tmp_path / "out.csv"
    _run("batch", source, "--output", target)
    lines = target.read_text().splitlines()
    assert lines[0].startswith("vx,vy,omega,regime,")
    assert lines[1].startswith("3,-4,0,stick-restitution,3.5,")
    assert lines[2].startswith("1,-1,2,stick-restitution,3.5,")
    # the one text that holds a comma is the only one quoted
    assert lines[1].count('"') == 2 and '"sliding, then stick (Fig. 5a)"' in lines[1]


def test_text_that_needs_quotes_gets_them_and_reads_back(tmp_path, capsys):
    """With --on-error skip the error column holds sentences with commas: those cells are
    quoted, and every cell reads back as written."""
    source = tmp_path / "in.csv"
    source.write_text('vx,vy,omega,note\n3,-4,0,"a, b"\n1,1,2,"say ""hi"""\n')
    target = tmp_path / "out.csv"
    _run("batch", source, "--output", target, "--on-error", "skip")
    with target.open(newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0][:4] == ["vx", "vy", "omega", "note"]
    assert rows[1][:5] == ["3", "-4", "0", "a, b", "stick-restitution"]
    assert rows[2][:4] == ["1", "1", "2", 'say "hi"']
    assert "vy must be < 0" in rows[2][-1]


def test_sweep_csv_writes_plain_names(tmp_path, capsys):
    target = tmp_path / "sweep.csv"
    _run("sweep", "--vx", "-1:1:3", "--omega", "0", "--output", target)
    lines = target.read_text().splitlines()
    assert lines[0] == "vx,vy,omega,mu,kappa,after_vx,after_vy,after_omega,regime"
    assert '"' not in target.read_text() and len(lines) == 4
