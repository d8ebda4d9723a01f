"""CSV batch input read by pyarrow equals what the Python csv reader yields, and so do the
batch outputs made from it."""

import itertools
import random

import numpy as np
import pytest

from spinimpact.io import _arrow_csv, _tables
from spinimpact.io._tables import BatchError, chunk_numbers
from spinimpact.io.batch import run_batch

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

DEFAULTS = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere", gyration=None)


def _python(path, chunk_size, skip):
    return list(_tables.csv_chunks(path, chunk_size, skip, lambda done: None))


def _arrow(path, chunk_size, skip):
    return list(_arrow_csv.csv_chunks(path, chunk_size, skip, lambda done: None))


def _numbers(chunk, name):
    notes = []
    values = chunk_numbers(chunk, name, None, lambda i, m: notes.append((i, m)))
    return values.view(np.int64).tolist(), notes  # NaN, -0.0 and all: bit for bit


def assert_same_chunks(got, want, numeric=("vx", "vy", "omega")):
    assert got[0] == want[0]  # the header
    assert len(got) == len(want)
    for a, b in zip(got[1:], want[1:], strict=True):
        assert a.first == b.first
        assert list(a.columns) == list(b.columns)
        for name in b.columns:
            assert list(a.columns[name]) == list(b.columns[name]), name
            np.testing.assert_array_equal(a.empty[name], b.empty[name])
        assert [a.lines[i] for i in range(len(b.lines))] == list(b.lines)
        assert a.messages.tolist() == b.messages.tolist()
        for name in numeric:
            if name in b.columns:
                assert _numbers(a, name) == _numbers(b, name), name


TRICKY = {
    "bom and crlf": "\ufeffvx,vy,omega\r\n1,-2,3\r\n4.5,-1e-3,-0\r\n",
    "blank lines": "vx,vy,omega\n\n1,-2,3\n\n\n.5,-2.,+7\n",
    "quoted": 'vx,vy,omega,note\n"1.5",-2,3,"a, b"\n2,"-3",4,"say ""hi"""\n',
    "quoted newline": 'vx,vy,omega,note\n1,-2,3,"two\nlines"\n5,-6,7,x\n',
    "blanks around": "vx , vy,omega\n 1 ,\t-2\t,3\u3000\n\x1c4\x1f,-5, \u2003 6\n",
    "empty cells": "vx,vy,omega,mu\n1,,3,\n,-2,,0.5\n",
    "not numbers": "vx,vy,omega\ninf,-nan,1_000\n\u0661\u0662,--1,1e\n0x10,1e5e5,Infinity\n",
    "a line of blanks": "vx,vy,omega\n1,-2,3\n   \n4,-5,6\n",
    "no trailing newline": "vx,vy,omega\n1,-2,3",
}


@pytest.mark.parametrize("name", list(TRICKY))
@pytest.mark.parametrize("skip", [True, False])
def test_tricky_files_give_the_python_readers_chunks(tmp_path, name, skip):
    path = tmp_path / "in.csv"
    path.write_bytes(TRICKY[name].encode())
    got = _arrow(path, 2, skip)
    assert_same_chunks(got, _python(path, 2, skip))
    read_by_arrow = {isinstance(c.columns, _arrow_csv._Cells) for c in got[1:]}
    assert read_by_arrow == {name != "a line of blanks"}  # that one: Python's reader


@pytest.mark.parametrize("skip", [True, False])
def test_a_row_of_the_wrong_length_hands_over_to_the_python_reader(tmp_path, skip):
    path = tmp_path / "in.csv"
    rows = [f"{i},-{i + 1},{i % 3}" for i in range(20)]
    rows[13] = "1,-2"  # after four chunks of three rows
    path.write_text("vx,vy,omega\n" + "\n".join(rows) + "\n")
    if skip:
        got = _arrow(path, 3, skip)
        assert_same_chunks(got, _python(path, 3, skip))
        assert got[5].messages[1] == "row 14 (line 15): expected 3 fields, got 2"
    else:
        with pytest.raises(BatchError, match=r"^row 14 \(line 15\): expected 3 fields, got 2$"):
            _arrow(path, 3, skip)


def test_number_characters_read_by_arrow_are_the_plain_numbers():
    """A cell of the characters 0-9 + - . e E that Arrow converts is one that the Python
    rule (_tables._PLAIN) accepts, with the value float() gives: the premise of the fast
    path. Exhaustive to four characters, random beyond."""
    alphabet = "019+-.eE"
    cells = ["".join(p) for k in range(1, 5) for p in itertools.product(alphabet, repeat=k)]
    rng = random.Random(14)
    cells += ["".join(rng.choice("0123456789+-.eE") for _ in range(rng.randint(5, 12)))
              for _ in range(3000)]  # fmt: skip
    for cell in cells:
        try:
            value = pa.compute.cast(pa.array([cell]), pa.float64())[0].as_py()
        except pa.ArrowInvalid:
            value = None
        plain = _tables._PLAIN.fullmatch(cell) is not None
        assert (value is not None) == plain, cell
        if plain:
            assert np.float64(value).view(np.int64) == np.float64(float(cell)).view(np.int64)


def test_whitespace_is_what_str_strip_strips():
    cells = [c + "1" + c for c in _arrow_csv._WHITESPACE] + ["\u200b1", "a b"]
    got = _arrow_csv._stripped(pa.chunked_array([pa.array(cells)])).to_pylist()
    assert got == [c.strip() for c in cells]


def _long_file(path, n=1000, bad=()):
    rng = np.random.default_rng(7)
    lines = ["vx,vy,omega,mu,body"]
    for i in range(n):
        body = ["", "ring", "solid-disk"][i % 3]
        mu = "" if i % 4 else repr(float(rng.uniform(0, 1)))
        cells = [repr(float(rng.normal(0, 3))), repr(float(-rng.uniform(0.1, 5))),
                 repr(float(rng.normal(0, 60))), mu, body]  # fmt: skip
        lines.append(",".join(cells))
    for i, row in bad:
        lines[i + 1] = row
    path.write_text("\n".join(lines) + "\n")


def _both(monkeypatch, source, target, **kwargs):
    """The batch through the Arrow reader, then through the Python reader alone."""
    fast = target.with_name("fast" + target.suffix)
    plain = target.with_name("plain" + target.suffix)
    run_batch(source, fast, defaults=DEFAULTS, **kwargs)
    with monkeypatch.context() as m:
        m.setattr(_arrow_csv, "available", lambda module: False)
        run_batch(source, plain, defaults=DEFAULTS, **kwargs)
    return fast, plain


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_batch_output_equals_the_python_readers(tmp_path, monkeypatch, suffix):
    source = tmp_path / "in.csv"
    _long_file(source)
    fast, plain = _both(monkeypatch, source, tmp_path / f"out{suffix}", chunk_size=300)
    if suffix == ".csv":
        assert fast.read_bytes() == plain.read_bytes()
    else:
        assert pq.read_table(fast).equals(pq.read_table(plain), check_metadata=True)


def test_skipped_rows_and_their_messages_are_the_same(tmp_path, monkeypatch):
    source = tmp_path / "in.csv"
    bad = [(5, "1,-2,x,,"), (250, "1,0,3,,"), (600, "1,-2,3,,moon"), (900, "1,-2,3,,,")]
    _long_file(source, bad=bad)
    fast, plain = _both(monkeypatch, source, tmp_path / "out.csv", chunk_size=128,
                        on_error="skip")  # fmt: skip
    assert fast.read_bytes() == plain.read_bytes()
    text = fast.read_text()
    assert "row 6 (line 7), column omega: 'x' is not a number" in text
    assert "row 901 (line 902): expected 5 fields, got 6" in text


def test_the_first_bad_row_stops_the_run_with_the_same_message(tmp_path, monkeypatch):
    source = tmp_path / "in.csv"
    _long_file(source, bad=[(700, "1,-2,3,-0.5,")])
    for reader in (True, False):
        with monkeypatch.context() as m:
            if not reader:
                m.setattr(_arrow_csv, "available", lambda module: False)
            with pytest.raises(BatchError, match=r"^row 701 \(line 702\), column mu: mu must"):
                run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, chunk_size=128)
        assert not (tmp_path / "out.csv").exists()


#: Cells of a column without empty cells, which Arrow reads in one cast: the finite
#: numbers it reads must be Python's, and every other cell must go to the Python rules.
_WHOLE_COLUMN = [
    "1", "+1", "-1.5", ".5", "5.", "1e5", "1E+05", "1.e5", "+.5e-3", "-0", "0001",
    "1.7976931348623157e308", "4.9e-324", "1e-400", "inf", "-Infinity", "nan", "NaN",
    "+nan", "nan(1)", "1e999", "-1e999", "1_000", "0x10", "1,5", "1d5", "\u0663", "1e",
    "e5", "+", ".", "1..2", "--1", "1e5e5", "infx", "0x1p3",
]  # fmt: skip


@pytest.mark.parametrize("stripped_first", [False, True])
@pytest.mark.parametrize("bad", [None, *_WHOLE_COLUMN])
def test_a_column_read_in_one_cast_is_read_as_cell_by_cell(bad, stripped_first):
    pa = pytest.importorskip("pyarrow")
    good = ["1", "-2.5", "3e-3", ".25", "1.e2"]
    cells = good + ([] if bad is None else [bad])
    source = _arrow_csv._Source({"c": pa.chunked_array([cells[:2], cells[2:]])})
    if stripped_first:  # its text made first (as a chunk's head for the trials makes it)
        assert source.text["c"].to_pylist() == cells
    values, rest = _arrow_csv._Numbers(source)("c")
    assert source.text["c"].to_pylist() == cells and not source.empty["c"].any()
    expected = [float(c) for c in good]
    assert values[: len(good)].tolist() == expected
    if bad is None:
        assert rest.size == 0
        return
    read = float(bad) if _tables._PLAIN.fullmatch(bad) else None
    if read is not None and np.isfinite(read):  # a plain finite number: read here
        assert rest.size == 0 and values[-1] == read
    else:  # anything else: left to the Python rules (which read or refuse it by its text)
        assert rest.tolist() == [len(good)] and np.isnan(values[-1])


@pytest.mark.parametrize("cells", [["1", " 2", "3"], ["1", "", "3"], ["1", "2\u00a0", "x"]])
def test_a_column_with_blanks_or_empty_cells_is_stripped_then_read(cells):
    pa = pytest.importorskip("pyarrow")
    source = _arrow_csv._Source({"c": pa.chunked_array([cells])})
    values, rest = _arrow_csv._Numbers(source)("c")
    stripped = [c.strip() for c in cells]
    assert source.text["c"].to_pylist() == stripped
    assert source.empty["c"].tolist() == [c == "" for c in stripped]
    plain = [_tables._PLAIN.fullmatch(c) is not None for c in stripped]
    assert [float(c) if p else None for c, p in zip(stripped, plain, strict=True)] == [
        None if np.isnan(v) else v for v in values.tolist()
    ]
    assert rest.tolist() == [i for i, c in enumerate(stripped) if c and not plain[i]]


def test_under_an_address_limit_the_python_reader_reads_the_file(tmp_path, monkeypatch):
    # pyarrow's CSV reader, when an allocation fails in its read-ahead thread, waits for
    # that thread forever: under ulimit -v a chunk too large for the limit hung the run.
    path = tmp_path / "in.csv"
    path.write_text("vx,vy,omega\n1,-1,0\n2,-1,3\n")
    got = _arrow(path, 2, False)
    assert all(isinstance(c.columns, _arrow_csv._Cells) for c in got[1:])
    monkeypatch.setattr(_arrow_csv, "address_limit", lambda: 600 * 2**20)
    limited = _arrow(path, 2, False)
    assert not any(isinstance(c.columns, _arrow_csv._Cells) for c in limited[1:])
    assert_same_chunks(limited, _python(path, 2, False))
