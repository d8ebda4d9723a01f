"""What the commands print: counts agree with their nouns ("1 row", "2 rows"), every file
written is announced as "wrote PATH", times and lengths use one symbol for micro (µ), and
tables printed into a pipe or a file are not squeezed into 80 columns."""

import re

import pytest


@pytest.fixture
def incidences(tmp_path):
    def write(rows):
        path = tmp_path / f"in{len(rows)}.csv"
        path.write_text("vx,vy,omega\n" + "".join(f"{r},-1,0\n" for r in rows))
        return path

    return write


@pytest.mark.parametrize("rows, words", [(1, "1 row"), (2, "2 rows")])
def test_batch_counts_its_rows_in_words(cli, tmp_path, incidences, rows, words):
    target = tmp_path / "out.csv"
    status, out, err = cli("batch", incidences(list(range(rows))), "--output", target)
    assert status == 0, err
    assert out.strip() == f"wrote {words} to {target}"


def test_a_sweep_of_one_point_says_point(cli):
    status, out, err = cli("sweep", "--vx", "1", "--omega", "0")
    assert status == 0, err
    assert re.search(r"^1 point\b", out, re.M), out


@pytest.mark.slow
def test_report_says_what_it_wrote(cli, tmp_path):
    page = tmp_path / "impact.html"
    status, out, err = cli("report", "--output", page)
    assert status == 0, err
    assert out.strip() == f"wrote {page}"


@pytest.mark.slow
def test_map_and_figures_say_what_they_wrote(cli, tmp_path):
    image = tmp_path / "map.png"
    status, out, err = cli("map", "--output", image, "--resolution", 10, "--dpi", 50)
    assert status == 0, err
    assert out.strip() == f"wrote {image}"
    status, out, err = cli("figures", "--output", tmp_path / "figs", "--dpi", 50)
    assert status == 0, err
    lines = out.strip().splitlines()
    assert lines and all(line.startswith(f"wrote {tmp_path / 'figs'}") for line in lines)


def test_simulate_writes_micro_as_one_symbol(cli):
    status, out, err = cli("simulate")
    assert status == 0, err
    assert re.search(r"contact duration [\d.]+ µs", out), out
    assert " us" not in out and "µm" in out


def test_tables_are_not_squeezed_into_80_columns_in_a_pipe(cli, monkeypatch):
    """At 30,000 rpm the bounce table is 82 columns wide: printed into a pipe (no terminal,
    no COLUMNS) it used to wrap each row onto two lines."""
    monkeypatch.delenv("COLUMNS", raising=False)
    status, out, err = cli("flight", "--spin-rpm", 30000, "--speed", 200, "--speed-unit", "km/h")
    assert status == 0, err
    table = out.split("\n\n")[0].splitlines()[3:]  # the bounce rows, under title and heading
    assert table and all(re.match(r"^ \d+ +│", row) for row in table), "\n".join(table)
