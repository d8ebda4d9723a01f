"""Batch files of spheres and of pairs (spinimpact.io.sphere_batch): every row equals
solve_sphere / solve_pair, the chunk size changes nothing, bad rows are named by row, line
and column, and a failed run leaves no file."""

import csv

import numpy as np
import pytest

from spinimpact import Body, PairImpact, SphereImpact, Surface, solve_pair, solve_sphere
from spinimpact.io._tables import BatchError
from spinimpact.io.sphere_batch import run_sphere_batch, sphere_kind

# run_sphere_batch is the older alias of run_batch: its warning is checked once, below
pytestmark = pytest.mark.filterwarnings("ignore:run_sphere_batch is deprecated:DeprecationWarning")

DEFAULTS = {"mu": 0.3, "kappa": 0.7, "mass": 0.5, "radius": 0.04}


def write(path, header, rows):
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)
    return path


def read(path):
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def text(x):
    """A number as the shortest text that reads back to it."""
    return repr(float(x))


def sphere_rows(n=40, seed=1):
    """Random spheres on random moving, tilted surfaces, each approaching its surface."""
    rng = np.random.default_rng(seed)
    normal = rng.normal(size=(n, 3)) * [0.3, 1, 0.3] + [0, 2, 0]
    surface = rng.normal(size=(n, 3))
    unit = normal / np.linalg.norm(normal, axis=1, keepdims=True)
    rel = rng.normal(size=(n, 3)) * 5
    along = np.sum(rel * unit, 1)
    rel -= (along + np.abs(along) + 0.5)[:, None] * unit  # normal part -|along| - 0.5 < 0
    v = surface + rel
    w = rng.normal(size=(n, 3)) * 100
    mu, kappa = rng.uniform(0, 0.8, n), rng.uniform(0, 1, n)
    mass, radius = rng.uniform(0.05, 2, n), rng.uniform(0.01, 0.2, n)
    gyration = np.where(np.arange(n) % 3 == 0, radius * rng.uniform(0.5, 0.8, n), np.nan)
    body = np.where(np.arange(n) % 3 == 1, "spherical-shell", "")
    return v, w, mu, kappa, mass, radius, gyration, body, normal, surface


def test_sphere_rows_equal_solve_sphere(tmp_path):
    v, w, mu, kappa, mass, radius, gyration, body, normal, surface = sphere_rows()
    header = ["vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa", "mass", "radius", "gyration",
              "body", "normal_x", "normal_y", "normal_z", "surface_velocity_x",
              "surface_velocity_y", "surface_velocity_z"]  # fmt: skip
    rows = [[*map(text, v[i]), *map(text, w[i]), text(mu[i]), text(kappa[i]), text(mass[i]),
             text(radius[i]), "" if np.isnan(gyration[i]) else text(gyration[i]), body[i],
             *map(text, normal[i]), *map(text, surface[i])] for i in range(len(v))]  # fmt: skip
    source = write(tmp_path / "in.csv", header, rows)
    summary = run_sphere_batch(source, tmp_path / "out.csv", chunk_size=7)
    assert (summary.rows, summary.skipped, summary.kind) == (len(v), 0, "sphere")
    out = read(tmp_path / "out.csv")
    preset = np.where(body == "", "solid-sphere", body)
    ball = Body.from_columns(mass=mass, radius=radius, preset=np.where(np.isnan(gyration),
                             preset, ""), gyration=gyration)  # fmt: skip
    imp = solve_sphere(ball, v, w, mu=mu, kappa=kappa, surface=Surface(normal, surface))
    want = imp.columns()
    names = [n for n in SphereImpact.column_names() if not n.startswith("before")]
    assert list(out[0])[: len(header)] == header
    assert list(out[0])[len(header) :] == ["regime", "zeta"] + [
        n for n in names if n not in header and n not in ("regime", "zeta")
    ]
    for name in names:
        if name in header:
            continue
        got = [r[name] for r in out]
        if want[name].dtype.kind in "US":
            assert got == want[name].tolist(), name
        elif want[name].dtype.kind == "b":
            assert got == ["true" if x else "false" for x in want[name]], name
        else:  # written by repr: the same float, bit for bit
            np.testing.assert_array_equal(np.array(got, float), want[name], err_msg=name)


def test_chunk_size_changes_nothing(tmp_path):
    v, w, *_ = sphere_rows(25, seed=2)
    rows = [[*map(text, v[i]), *map(text, w[i])] for i in range(len(v))]
    header = ["vx", "vy", "vz", "wx", "wy", "wz"]
    source = write(tmp_path / "in.csv", header, rows)
    small, large = tmp_path / "small.csv", tmp_path / "large.csv"
    defaults = {**DEFAULTS, "normal": (0, 1, 0.1)}
    run_sphere_batch(source, small, defaults=defaults, chunk_size=1, on_error="skip")
    run_sphere_batch(source, large, defaults=defaults, chunk_size=1000, on_error="skip")
    assert small.read_text() == large.read_text()
    assert "error" in read(small)[0]


def test_pair_rows_equal_solve_pair(tmp_path):
    rng = np.random.default_rng(3)
    n = 30
    v1, v2 = rng.normal(size=(n, 3)) * 3, rng.normal(size=(n, 3)) * 3
    w1, w2 = rng.normal(size=(n, 3)) * 50, rng.normal(size=(n, 3)) * 50
    normal = rng.normal(size=(n, 3))
    flip = np.sum((v1 - v2) * normal, 1) > 0  # approach: (v1 - v2).n < 0
    normal[flip] *= -1
    mass2 = rng.uniform(0.1, 3, n)
    header = ["vx", "vy", "vz", "wx", "wy", "wz", "vx2", "vy2", "vz2", "wx2", "wy2", "wz2",
              "normal_x", "normal_y", "normal_z", "mass2", "body2"]  # fmt: skip
    rows = [[*map(text, [*v1[i], *w1[i], *v2[i], *w2[i], *normal[i], mass2[i]]),
             "spherical-shell"] for i in range(n)]  # fmt: skip
    source = write(tmp_path / "pairs.csv", header, rows)
    defaults = {**DEFAULTS, "mass2": 9.0, "radius2": 0.03}
    summary = run_sphere_batch(source, tmp_path / "out.csv", defaults=defaults, pair=True)
    assert (summary.rows, summary.kind) == (n, "pair")
    out = read(tmp_path / "out.csv")
    b1 = Body.solid_sphere(mass=0.5, radius=0.04)
    b2 = Body.spherical_shell(mass=mass2, radius=0.03)
    want = solve_pair(b1, b2, velocity1=v1, spin1=w1, velocity2=v2, spin2=w2, normal=normal,
                      mu=0.3, kappa=0.7).columns()  # fmt: skip
    for name in PairImpact.column_names():
        if name.startswith("before") or name in header:
            continue
        got = [r[name] for r in out]
        if want[name].dtype.kind in "US":
            assert got == want[name].tolist(), name
        elif want[name].dtype.kind != "b":
            np.testing.assert_array_equal(np.array(got, float), want[name], err_msg=name)
    assert [r["mu"] for r in out] == ["0.3"] * n  # the default each row was solved with


BALL = ["vx", "vy", "vz", "wx", "wy", "wz"]


@pytest.mark.parametrize(
    ("header", "row", "message"),
    [
        (BALL, ["1", "x", "0", "0", "0", "0"], "row 2 (line 3), column vy: 'x' is not a number"),
        (BALL, ["1", "inf", "0", "0", "0", "0"], "column vy: vy must be finite"),
        (BALL, ["1", "1", "0", "0", "0", "0"],
         "row 2 (line 3): the contact point's normal velocity must be < 0"),
        (BALL, ["1", "-1", "0", "0", "0"], "row 2 (line 3): expected 6 fields, got 5"),
        ([*BALL, "mu"], ["1", "-1", "0", "0", "0", "0", "-0.5"], "column mu: mu must be >= 0"),
        ([*BALL, "mass"], ["1", "-1", "0", "0", "0", "0", "0"], "column mass: mass must be > 0"),
        ([*BALL, "body"], ["1", "-1", "0", "0", "0", "0", "ring"],
         "column body: must be one of solid-sphere, spherical-shell; got 'ring'"),
        ([*BALL, "body", "gyration"], ["1", "-1", "0", "0", "0", "0", "solid-sphere", "0.02"],
         "give either body or gyration, not both"),
        ([*BALL, "normal_x", "normal_y", "normal_z"], ["1", "-1", "0", "0", "0", "0", "0", "0",
         "0"], "the length of normal must be > 0 (a direction)"),
        ([*BALL, "gyration"], ["1", "-1", "0", "0", "0", "0", "1e-30"],
         "row 2 (line 3): radius/gyration is too large"),
    ],
)  # fmt: skip
@pytest.mark.slow
def test_bad_rows_are_named(tmp_path, header, row, message):
    good = ["2", "-3", "0", "0", "0", "0"] + [""] * (len(header) - 6)
    source = write(tmp_path / "in.csv", header, [good, row])
    target = tmp_path / "out.csv"
    target.write_text("previous")
    with pytest.raises(BatchError) as caught:
        run_sphere_batch(source, target, defaults=DEFAULTS)
    assert message in str(caught.value)
    assert target.read_text() == "previous"  # a failed run changes nothing
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.csv", "out.csv"]  # no temps
    summary = run_sphere_batch(source, target, defaults=DEFAULTS, on_error="skip")
    out = read(target)
    assert (summary.rows, summary.skipped) == (2, 1)
    assert out[0]["error"] == "" and out[0]["regime"] != ""
    assert message in out[1]["error"] and out[1]["regime"] == "" and out[1]["after_vx"] == ""


def test_headers_that_cannot_be_used(tmp_path):
    pair = [*BALL, "vx2", "vy2", "vz2", "wx2", "wy2", "wz2"]
    cases = [
        (pair + ["surface_velocity_x"], {"normal": (1, 0, 0)}, "is an input of problem 'sphere'"),
        (["vx", "vy", "vz", "wx", "wy"], {}, "missing column 'wz'"),
        ([*BALL, "regime"], {}, "input column 'regime' has the name of an output column"),
        (pair, {"mass2": 1, "radius2": 0.1}, "missing column 'normal_x'"),
    ]
    for header, extra, message in cases:
        source = write(tmp_path / "in.csv", header, [])
        with pytest.raises(BatchError, match=message):
            run_sphere_batch(source, tmp_path / "out.csv", defaults={**DEFAULTS, **extra})
    assert sphere_kind(pair) == "pair" and sphere_kind(BALL) == "sphere"
    source = write(tmp_path / "in.csv", BALL, [])
    with pytest.raises(BatchError, match="describe problem .sphere."):
        run_sphere_batch(source, tmp_path / "out.csv", defaults=DEFAULTS, pair=True)
    with pytest.raises(ValueError, match="must differ"):
        run_sphere_batch(source, source, defaults=DEFAULTS)
    with pytest.raises(ValueError, match="on_error"):
        run_sphere_batch(source, tmp_path / "o.csv", defaults=DEFAULTS, on_error="ignore")
    with pytest.raises(TypeError, match="chunk_size"):
        run_sphere_batch(source, tmp_path / "o.csv", defaults=DEFAULTS, chunk_size=2.5)
    summary = run_sphere_batch(source, tmp_path / "empty.csv", defaults=DEFAULTS)
    assert summary.rows == 0 and read(tmp_path / "empty.csv") == []


def test_parquet_in_and_out(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    import pyarrow as pa

    table = pa.table({"vx": [2.0, 1.0], "vy": [-3.0, -1.0], "vz": [0.0, 0.5],
                      "wx": [0.0, 0.0], "wy": [10.0, 0.0], "wz": [0.0, -5.0],
                      "mu": [0.2, None]})  # fmt: skip
    pq.write_table(table, tmp_path / "in.parquet")
    run_sphere_batch(tmp_path / "in.parquet", tmp_path / "out.parquet", defaults=DEFAULTS)
    out = pq.read_table(tmp_path / "out.parquet")
    imp = solve_sphere(Body.solid_sphere(mass=0.5, radius=0.04), [[2, -3, 0], [1, -1, 0.5]],
                       [[0, 10, 0], [0, 0, -5]], mu=[0.2, 0.3], kappa=0.7)  # fmt: skip
    assert out.column("after_vz").to_pylist() == imp.after.vz.tolist()
    assert out.schema.field("after_vx").metadata == {b"unit": b"m/s"}
    assert out.column("grips").type == pa.bool_()
