"""Sweeps in bounded memory: grids, random samples, files, reductions, Dask."""

import math
import subprocess
import sys

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.core import REGIMES
from spinimpact.io.sweep import (
    ALIASES,
    FIELDS,
    Axis,
    Sweep,
    dask_client,
    parse_axis,
    run_sweep,
)
from spinimpact.model.impact import Impact

BODY = Body.solid_sphere(mass=1.0, radius=0.1)


def make(chunk_size=997, samples=None, **spec):
    axes = dict(vx="-5:5:61", vy="-4", omega="-50:50:41", mu="0.3", kappa="0.8") | spec
    return Sweep(
        BODY, {k: parse_axis(k, v) for k, v in axes.items()}, samples=samples, chunk_size=chunk_size
    )


def test_grid_sweep_equals_solve_on_the_whole_grid():
    sweep = make()
    result = run_sweep(sweep, histogram=("after_vx", -5, 5, 10))
    vx, omega = np.linspace(-5, 5, 61), np.linspace(-50, 50, 41)
    imp = solve(BODY, vx[:, None], -4.0, omega[None, :], mu=0.3, kappa=0.8)
    assert result.points == imp.after.vx.size
    for code, name in enumerate(REGIMES):
        assert result.regime_counts[code] == np.sum(imp.regime == name)
    hist, _ = np.histogram(imp.after.vx, bins=10, range=(-5, 5))
    np.testing.assert_array_equal(result.histogram, hist)


@pytest.mark.slow
def test_chunk_size_does_not_change_a_grid():
    a = run_sweep(make(chunk_size=1), histogram=("energy_loss", 0, 1, 7))
    b = run_sweep(make(chunk_size=100_000), histogram=("energy_loss", 0, 1, 7))
    np.testing.assert_array_equal(a.regime_counts, b.regime_counts)
    np.testing.assert_array_equal(a.histogram, b.histogram)


def test_npy_output_matches_solve(tmp_path):
    out = tmp_path / "grid"
    run_sweep(make(), output=out, fields=("after_vx", "regime", "impulse_ratio", "slip_after"))
    vx, omega = np.load(out / "vx.npy"), np.load(out / "omega.npy")
    imp = solve(BODY, vx, -4.0, omega, mu=0.3, kappa=0.8)
    np.testing.assert_array_equal(np.load(out / "after_vx.npy"), imp.after.vx)
    np.testing.assert_array_equal(np.asarray(REGIMES)[np.load(out / "regime.npy")], imp.regime)
    np.testing.assert_array_equal(np.load(out / "impulse_ratio.npy"), imp.impulse_ratio)
    np.testing.assert_array_equal(np.load(out / "slip_after.npy"), imp.slip_after)
    with pytest.raises(ValueError, match="already exists"):
        run_sweep(make(), output=out)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["grid"]  # no temporary left


def test_random_sweep_to_parquet(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    sweep = make(samples=5000, chunk_size=1000, vx="uniform:-5:5", omega="uniform:-50:50")
    result = run_sweep(sweep, output=tmp_path / "s.parquet", fields=("after_omega", "energy_loss"))
    table = pq.read_table(tmp_path / "s.parquet").to_pydict()
    assert len(table["vx"]) == result.points == 5000
    assert min(table["vx"]) >= -5 and max(table["vx"]) < 5
    imp = solve(BODY, np.array(table["vx"]), -4.0, np.array(table["omega"]), mu=0.3, kappa=0.8)
    np.testing.assert_array_equal(table["after_omega"], imp.after.omega)
    np.testing.assert_allclose(
        table["energy_loss"], imp.dissipated_energy / imp.kinetic_energy_before, rtol=1e-12
    )  # two routes to E-: the kinetic energy of the state and of the body


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(vy="1"), "vy must be < 0"),
        (dict(vy="-4:1:3"), "vy must be < 0"),
        (dict(vx="uniform:-1:1", omega="0"), "samples must be a positive integer"),
        (dict(vx="uniform:-1:1", samples=10), "either a grid or random samples"),
        (dict(kappa="0:2:3"), r"kappa must be in \[0, 1\]"),
        (dict(mu="abc"), "mu must be a number, START:STOP:NUM"),
    ],
)
def test_bad_sweeps(kwargs, message):
    with pytest.raises(ValueError, match=message):
        make(**kwargs)


@pytest.mark.slow
def test_sweep_command(tmp_path):
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "spinimpact",
            "sweep",
            "--vx",
            "-2:2:11",
            "--omega",
            "0",
            "--histogram",
            "after_vx:-2:2:4",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 0, out.stderr
    assert "11 points" in out.stdout and "stick-compression" in out.stdout
    bad = subprocess.run(
        [sys.executable, "-m", "spinimpact", "sweep", "--histogram", "after_vx:1"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert bad.returncode == 2 and "FIELD:LOW:HIGH:BINS" in bad.stderr


@pytest.mark.slow
def test_dask_cluster_gives_the_same_numbers(tmp_path):
    distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")
    sweep = make(samples=60_000, chunk_size=5000, vx="uniform:-5:5", omega="uniform:-50:50")
    local = run_sweep(sweep, histogram=("after_vx", -5, 5, 16))
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
        ) as cluster,
        dask_client(cluster.scheduler_address) as client,
    ):
        remote = run_sweep(sweep, histogram=("after_vx", -5, 5, 16), client=client)
        run_sweep(sweep, output=tmp_path / "dask", fields=("after_vx",), client=client)
    np.testing.assert_array_equal(local.regime_counts, remote.regime_counts)
    np.testing.assert_array_equal(local.histogram, remote.histogram)
    run_sweep(sweep, output=tmp_path / "local", fields=("after_vx",))
    for name in ("vx", "after_vx"):
        np.testing.assert_array_equal(
            np.load(tmp_path / "dask" / f"{name}.npy"), np.load(tmp_path / "local" / f"{name}.npy")
        )


def test_outputs_are_ordinary_files_and_targets_are_checked(tmp_path):
    import os
    import stat

    pytest.importorskip("pyarrow", reason="the [parquet] extra is not installed")
    run_sweep(make(), output=tmp_path / "s.parquet")
    run_sweep(make(), output=tmp_path / "d")
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE((tmp_path / "s.parquet").stat().st_mode) == 0o666 & ~umask
    assert stat.S_IMODE((tmp_path / "d").stat().st_mode) == 0o777 & ~umask
    (tmp_path / "dir.parquet").mkdir()
    with pytest.raises(ValueError, match="is a directory"):
        run_sweep(make(), output=tmp_path / "dir.parquet")
    with pytest.raises(ValueError, match="does not exist"):
        run_sweep(make(), output=tmp_path / "missing" / "x.parquet")
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


def test_random_points_do_not_depend_on_the_order_of_the_axes():
    spec = dict(vx="uniform:-5:5", vy="-4", omega="uniform:-50:50", mu="0.3", kappa="0.8")
    a = Sweep(BODY, {k: parse_axis(k, v) for k, v in spec.items()}, samples=100)
    b = Sweep(BODY, {k: parse_axis(k, v) for k, v in reversed(spec.items())}, samples=100)
    np.testing.assert_array_equal(
        a.evaluate(0, ("after_vx",))["after_vx"], b.evaluate(0, ("after_vx",))["after_vx"]
    )


@pytest.mark.slow
def test_histogram_spec_errors():
    with pytest.raises(ValueError, match="histogram's bins must be an integer <= 1000000"):
        run_sweep(make(), histogram=("after_vx", -1.0, 1.0, 10**9))
    out = subprocess.run(
        [sys.executable, "-m", "spinimpact", "sweep", "--histogram", "after_vx:-1:1:10:extra"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert out.returncode == 2 and "FIELD:LOW:HIGH:BINS" in out.stderr


SPOOL = Body(mass=2.0, radius=0.02, gyration=0.05)  # rho > R: zeta < 2
RANDOM = dict(
    vx="uniform:-5:5", vy="uniform:-5:-0.1", omega="uniform:-300:300", mu="uniform:0:1",
    kappa="uniform:0:1",
)  # fmt: skip
# grid ends hit the edge cases: mu = 0 (frictionless), vx = omega = 0 (no slip), kappa 0 and 1
GRID = dict(vx="-2:2:9", vy="-3:-0.5:3", omega="-40:40:9", mu="0:1:5", kappa="0:1:3")


def every_point(sweep, fields):
    parts = [sweep.evaluate(k, fields) for k in range(sweep.chunks)]
    return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}


@pytest.mark.parametrize("body", [BODY, SPOOL, Body.ring(mass=0.5, radius=1.0)], ids=str)
@pytest.mark.parametrize(
    ("spec", "samples"), [(RANDOM, 3000), (GRID, None)], ids=["random", "grid"]
)
def test_every_sweep_field_is_the_impact_column_of_its_name(body, spec, samples):
    sweep = Sweep(
        body, {k: parse_axis(k, v) for k, v in spec.items()}, samples=samples, chunk_size=701
    )
    got = every_point(sweep, tuple(FIELDS))
    imp = solve(body, got["vx"], got["vy"], got["omega"], mu=got["mu"], kappa=got["kappa"])
    want = imp.columns()
    assert set(FIELDS) <= set(Impact.column_names())  # one vocabulary
    assert len(set(imp.regime)) == (len(REGIMES) if spec is GRID else 3)  # the cases cover them
    for name in FIELDS:
        if name == "regime":  # stored as its code
            np.testing.assert_array_equal(np.asarray(REGIMES)[got[name]], want[name])
            continue
        # The same core kernels on the same numbers: equal to rounding (today bit for
        # bit); atol, relative to the field's scale, covers values that cancel to ~0
        # (the after_vx of a ball that stuck).
        scale = np.max(np.abs(want[name]))
        np.testing.assert_allclose(got[name], want[name], rtol=1e-12, atol=1e-12 * scale)


def test_old_field_names_are_aliases(tmp_path):
    assert ALIASES == {"energy_loss": "dissipated_fraction"}
    sweep = make(chunk_size=500)
    data = every_point(sweep, ("energy_loss", "dissipated_fraction"))
    np.testing.assert_array_equal(data["energy_loss"], data["dissipated_fraction"])
    a = run_sweep(sweep, histogram=("energy_loss", 0, 1, 9))
    b = run_sweep(sweep, histogram=("dissipated_fraction", 0, 1, 9))
    np.testing.assert_array_equal(a.histogram, b.histogram)
    assert a.histogram.sum() == sweep.size  # every fraction lies in [0, 1)
    # a field asked for by its old name is written under that name
    run_sweep(sweep, output=tmp_path / "old", fields=("energy_loss",))
    assert sorted(p.name for p in (tmp_path / "old").iterdir()) == [
        "energy_loss.npy", "kappa.npy", "metadata.json", "mu.npy", "omega.npy", "vx.npy",
        "vy.npy",
    ]  # fmt: skip
    with pytest.raises(ValueError, match=r"fields must be among .*\(or energy_loss for "):
        run_sweep(sweep, fields=("loss",))
    with pytest.raises(ValueError, match="histogram field must be among"):
        run_sweep(sweep, histogram=("vx", 0, 1, 2))


def test_parquet_output_without_pyarrow_names_the_extra(tmp_path, monkeypatch):
    for name in ("pyarrow", "pyarrow.parquet"):
        monkeypatch.setitem(sys.modules, name, None)  # any import of pyarrow now fails
    with pytest.raises(ImportError, match=r"Parquet output needs pyarrow.*spinimpact\[parquet\]"):
        run_sweep(make(), output=tmp_path / "s.parquet")
    assert list(tmp_path.iterdir()) == []  # nothing started


def test_dask_client_without_distributed_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(ImportError, match=r"Dask cluster needs distributed.*spinimpact\[dask\]"):
        dask_client("tcp://127.0.0.1:1")


def test_wrong_types_and_values_of_counts():
    axes = {k: parse_axis(k, v) for k, v in RANDOM.items()}
    with pytest.raises(TypeError, match="samples must be a positive integer"):
        Sweep(BODY, axes, samples=10.0)
    with pytest.raises(ValueError, match="samples must be a positive integer"):
        Sweep(BODY, axes, samples=0)
    with pytest.raises(TypeError, match="chunk_size must be a positive integer"):
        Sweep(BODY, axes, samples=10, chunk_size=True)
    with pytest.raises(TypeError, match="body must be a spinimpact.Body"):
        Sweep("ball", axes, samples=10)


@pytest.mark.parametrize(("seed", "error"), [("x", TypeError), (1.5, TypeError), (-1, ValueError)])
def test_seed_is_named_when_wrong(seed, error):
    given = {"vx": "uniform:0:1", "vy": -1.0, "omega": 0.0, "mu": 0.3, "kappa": 0.5}
    axes = {n: parse_axis(n, v) for n, v in given.items()}
    with pytest.raises(error, match=r"^seed must be an integer"):
        Sweep(Body.ring(mass=1.0, radius=0.1), axes, samples=10, seed=seed)


FIXED = dict(vx="1", vy="-4", omega="0", mu="0.3", kappa="0.8")


def test_an_axis_is_taken_only_under_its_own_name():
    # built as vx, used as vy: vy = +4 would give an energy gain if computed under its key
    axes = {n: parse_axis(n, v) for n, v in FIXED.items()} | {"vy": Axis("vx", "fixed", 4.0)}
    with pytest.raises(ValueError, match=r"axes\['vy'\] is an axis of vx"):
        Sweep(BODY, axes)
    # even where the value would pass under both names
    axes["vy"] = Axis("vx", "fixed", -4.0)
    with pytest.raises(ValueError, match=r"axes\['vy'\] is an axis of vx"):
        Sweep(BODY, axes)
    axes["vy"] = Axis("vy", "fixed", 4.0)
    with pytest.raises(ValueError, match="vy must be < 0"):
        Sweep(BODY, axes)
    with pytest.raises(TypeError, match=r"axes\['vy'\] must be an Axis"):
        Sweep(BODY, axes | {"vy": -4.0})
    with pytest.raises(ValueError, match="no axis 'spin'"):
        Sweep(BODY, axes | {"vy": Axis("vy", "fixed", -4.0), "spin": Axis("omega", "fixed", 1)})


@pytest.mark.parametrize(
    ("args", "error", "message"),
    [
        (("vx", "grid", -1.0, 1.0, 0), ValueError, "num must be an integer >= 1, got 0"),
        (("vx", "grid", -1.0, 1.0, -5), ValueError, "num must be an integer >= 1, got -5"),
        (("vx", "grid", -1.0, 1.0, 2.5), TypeError, "num must be an integer"),
        (("vx", "grid", -1.0, 1.0, True), TypeError, "num must be an integer"),
        (("vx", "fixed", 1.0, math.nan, 5), ValueError, "a fixed axis has 1"),
        (("vx", "bogus", 1.0), ValueError, "kind must be one of fixed, grid, uniform"),
        (("vx", "bogus", 1.0, 2.0), ValueError, "kind must be one of fixed, grid, uniform"),
        (("spin", "fixed", 1.0), ValueError, "name must be one of vx, vy"),
        (("vx", "fixed", "3"), TypeError, "lo must be a real number"),
        (("vx", "fixed", True), TypeError, "lo must be a real number"),
        (("vx", "fixed", math.inf), ValueError, "vx must be finite"),
        (("vx", "grid", 0.0, math.nan, 3), ValueError, "vx must be finite"),
        (("vx", "uniform", 1.0, 1.0), ValueError, "needs LOW < HIGH"),
    ],
)
def test_bad_axes_are_refused_when_built(args, error, message):
    with pytest.raises(error, match=message):
        Axis(*args)


@pytest.mark.parametrize("text", ["0:1:0", "0:1:-5", "uniform:2:1"])
def test_bad_axis_texts_name_what_is_wrong(text):
    with pytest.raises(ValueError, match=r"num must be an integer >= 1|needs LOW < HIGH"):
        parse_axis("vx", text)


@pytest.mark.parametrize("spec", [RANDOM, FIXED], ids=["random", "grid"])
def test_counts_that_are_bools_are_refused(spec):
    axes = {k: parse_axis(k, v) for k, v in spec.items()}
    with pytest.raises(TypeError, match="samples must be a positive integer"):
        Sweep(BODY, axes, samples=True)
    with pytest.raises(TypeError, match="chunk_size must be a positive integer"):
        Sweep(BODY, axes, samples=10 if spec is RANDOM else None, chunk_size=True)


def test_a_grid_axis_is_never_built_whole():
    # 1e10 grid points (80 GB as one array): a chunk computes only its own values
    sweep = make(chunk_size=1000, vx="-5:5:10000000000", omega="0")
    assert sweep.size == 10**10
    last = sweep.chunk(sweep.chunks - 1)["vx"]
    assert last.size == 1000 and last[-1] == 5.0
    np.testing.assert_array_equal(
        sweep.chunk(7)["vx"], np.arange(7000, 8000) * (10 / (10**10 - 1)) - 5
    )


@pytest.mark.slow
def test_random_points_depend_on_the_seed_alone_not_on_the_chunks():
    spec = dict(RANDOM, mu="0.3")
    axes = {k: parse_axis(k, v) for k, v in spec.items()}
    runs = [
        every_point(Sweep(BODY, axes, samples=3000, seed=7, chunk_size=size), ("regime",))
        for size in (1, 7, 1000, 2999, 10**6)
    ]
    for other in runs[1:]:
        for name in ("vx", "vy", "omega", "mu", "kappa", "regime"):
            np.testing.assert_array_equal(other[name], runs[0][name], err_msg=name)
    # the first points of a longer sweep are the points of a shorter one
    longer = every_point(Sweep(BODY, axes, samples=4500, seed=7, chunk_size=640), ("regime",))
    np.testing.assert_array_equal(longer["vx"][:3000], runs[0]["vx"])
    # another seed gives other points; each input its own stream
    other = every_point(Sweep(BODY, axes, samples=3000, seed=8), ())
    assert not np.any(other["vx"] == runs[0]["vx"])
    assert not np.any((runs[0]["vx"] + 5) / 10 == (runs[0]["omega"] + 50) / 100)
