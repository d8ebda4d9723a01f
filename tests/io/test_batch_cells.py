"""What a batch file's cells may hold: memory bounded by the chunk whatever the cells hold,
numbers only when they are plain numbers, and the output columns the user chose."""

import csv
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.io.batch import FieldError, result_columns, run_batch
from spinimpact.io.planar_batch import PlanarBatch

DEFAULTS = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere", gyration=None)

# Run in a child: warm every code path on a one-row file, then cap the address space at
# what the process holds plus LIMIT_MB, and solve a file whose one long cell would make a
# fixed-width text array of rows x columns x the longest cell (4 bytes a character).
_CHILD = textwrap.dedent(
    """
    import resource, sys
    from spinimpact.io.batch import run_batch

    def status(key):
        for line in open("/proc/self/status"):
            if line.startswith(key):
                return int(line.split()[1]) * 1024

    source, warm, output, limit_mb, chunk = sys.argv[1:6]
    defaults = dict(mu=0.3, kappa=0.8, mass=1.0, radius=0.1, body="solid-sphere")
    run_batch(warm, output, defaults=defaults)
    base = status("VmSize:")
    limit = base + int(limit_mb) * 2**20
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    summary = run_batch(source, output, defaults=defaults, chunk_size=int(chunk))
    print(summary.rows, (status("VmPeak:") - base) / 2**20)
    """
)


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="needs Linux /proc")
@pytest.mark.slow
def test_memory_is_bounded_by_the_chunk_whatever_the_cells_hold(tmp_path):
    # 50,000 rows, 10,000 a chunk; one cell of an extra column holds 100,000 characters.
    # A fixed-width array of one chunk would need 10,000 x 4 x 100,000 x 4 bytes = 14.9 GiB.
    source = tmp_path / "in.csv"
    with open(source, "w") as f:
        f.write("vx,vy,omega,note\n")
        for i in range(50_000):
            f.write(f"1.5,-2,{i % 7},{'x' * 100_000 if i == 5 else 'ok'}\n")
    warm = tmp_path / "warm.csv"
    warm.write_text("vx,vy,omega,note\n1,-2,3,x\n")
    output = tmp_path / "out.csv"
    limit_mb = 256  # the chunk needs ~25 MB; 256 MB leaves room and is far below 14.9 GiB
    run = subprocess.run(
        [sys.executable, "-c", _CHILD, source, warm, output, str(limit_mb), "10000"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr[-2000:]
    rows, growth_mb = run.stdout.split()
    assert int(rows) == 50_000
    assert float(growth_mb) < limit_mb
    with open(output, newline="") as f:
        notes = [row["note"] for row in csv.DictReader(f)]
    assert len(notes) == 50_000 and notes[5] == "x" * 100_000  # the long cell, intact


@pytest.mark.parametrize(
    "cell",
    [
        "-4\x00",  # a NUL that a fixed-width array would drop
        "\u0661\u0662",  # Arabic-Indic digits: float() reads 12
        "1_000",  # Python's digit grouping: float() reads 1000
        "\uff11",  # a fullwidth digit
        "0x10",
        "1,5",
        "--1",
        "1e",
        "",  # in a required column, reported as empty
    ],
)
def test_a_cell_that_is_not_a_plain_number_is_refused_naming_row_and_column(tmp_path, cell):
    source = tmp_path / "in.csv"
    with open(source, "w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows([["vx", "vy", "omega"], ["1", "-2", "3"], ["1", "-2", cell]])
    with pytest.raises(ValueError) as error:
        run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS)
    message = str(error.value)
    assert message.startswith("row 2 (line 3), column omega: ")
    if cell:
        assert f"{cell!r} is not a number" in message
    assert not (tmp_path / "out.csv").exists()


def test_plain_numbers_in_every_spelling_are_read_exactly(tmp_path):
    cells = ["3", "+3", "3.", ".5", "-0.25", "1e1", "2.5E-1", " 7 ", "1e400"]
    source = tmp_path / "in.csv"
    rows = [["vx", "vy", "omega"]] + [[c, "-1", "0"] for c in cells]
    with open(source, "w", newline="") as f:
        csv.writer(f).writerows(rows)
    run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, on_error="skip")
    with open(tmp_path / "out.csv", newline="") as f:
        out = list(csv.DictReader(f))
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    for cell, row in zip(cells[:-1], out, strict=False):
        want = solve(body, float(cell), -1.0, 0.0, mu=0.3, kappa=0.8).columns()["after_vx"]
        assert float(row["after_vx"]) == want, cell  # read as float() reads it: exactly
        assert row["error"] == ""
    assert out[-1]["error"] == "row 9 (line 10), column vx: vx must be finite, got inf"


def test_a_long_bad_cell_is_quoted_short(tmp_path):
    source = tmp_path / "in.csv"
    source.write_text("vx,vy,omega\n" + "9" * 50 + "x,-2,3\n")
    with pytest.raises(ValueError, match=r"'9{40}\.\.\.' \(51 characters\) is not a number"):
        run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS)


def test_fields_choose_the_output_columns_in_their_order(tmp_path):
    source = tmp_path / "in.csv"
    source.write_text("vx,vy,omega,label\n1,-2,3,a\n-1,-1,20,b\n")
    run_batch(
        source,
        tmp_path / "out.csv",
        defaults=DEFAULTS,
        fields=["after_vx", "regime", "after_vx", "rolling"],
    )
    with open(tmp_path / "out.csv", newline="") as f:
        reader = csv.DictReader(f)
        out = list(reader)
    assert reader.fieldnames == ["vx", "vy", "omega", "label", "after_vx", "regime", "rolling"]
    want = solve(Body.solid_sphere(mass=1.0, radius=0.1), 1.0, -2.0, 3.0, mu=0.3, kappa=0.8)
    assert float(out[0]["after_vx"]) == want.columns()["after_vx"]
    assert out[0]["regime"] == want.columns()["regime"]


@pytest.mark.parametrize("fields", [["after_vx", "bogus"], ["vx"], []])
def test_an_unknown_field_is_refused_listing_the_valid_ones(tmp_path, fields):
    source = tmp_path / "in.csv"
    source.write_text("vx,vy,omega\n1,-2,3\n")
    with pytest.raises(FieldError) as error:
        run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, fields=fields)
    message = str(error.value)
    assert "\n" not in message
    assert message.endswith("are: " + ", ".join(result_columns()))
    assert list(tmp_path.iterdir()) == [source]  # nothing written, no temporary


def test_fields_of_planar_files_come_from_their_own_vocabulary(tmp_path):
    source = tmp_path / "in.csv"
    source.write_text("mass,inertia,rx,ry,vx,vy,omega\n1,0.1,0.2,-0.5,1,-2,0\n")
    plan = PlanarBatch("planar", ["mass", "inertia", "rx", "ry", "vx", "vy", "omega"], False, {
        "mu": 0.3, "kappa": 0.8})  # fmt: skip
    assert "law" in plan.kinds and "zeta" not in plan.kinds
    run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, fields=["law", "after_omega"])
    with open(tmp_path / "out.csv", newline="") as f:
        reader = csv.DictReader(f)
        (row,) = list(reader)
    assert reader.fieldnames[-2:] == ["law", "after_omega"]
    assert row["law"] == "poisson"
    with pytest.raises(FieldError, match="the fields for free planar bodies are: law, mu, kappa"):
        run_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, fields=["zeta"])


def test_parquet_output_has_only_the_chosen_fields(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    source = tmp_path / "in.csv"
    source.write_text("vx,vy,omega\n1,-2,3\n")
    run_batch(source, tmp_path / "out.parquet", defaults=DEFAULTS, fields=["dissipated_energy"])
    table = pq.read_table(tmp_path / "out.parquet")
    assert table.column_names == ["vx", "vy", "omega", "dissipated_energy"]
    assert table.schema.field("dissipated_energy").metadata == {b"unit": b"J"}
    assert np.isfinite(table.column("dissipated_energy").to_numpy()).all()
