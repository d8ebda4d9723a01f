"""Sweeps of a planar body or a pendulum through the older PlanarSweep (an alias of
ProblemSweep): every field is solve_planar's (solve_pendulum's) column of its name, the
regimes are counted, the outputs say what they hold."""

import json
import math

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.core.planar import LAWS, PLANAR_REGIMES
from spinimpact.io.planar_sweep import PROCESS_FIELDS, PlanarSweep, planar_fields
from spinimpact.io.sweep import parse_axis, run_sweep
from spinimpact.model.planar import PendulumImpact, PlanarImpact

pytestmark = pytest.mark.filterwarnings(
    "ignore:(PlanarSweep|planar_fields) is deprecated:DeprecationWarning"
)

ROD = PlanarBody.rod(mass=1.5, length=0.8, angle=math.radians(40))
BLOCK = PlanarBody.block(mass=2.0, width=0.3, height=0.1, angle=0.3)
PENDULUM = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
# the contact approaches at every point: vy + omega*rx < 0 over the whole box
RANDOM = dict(vx="uniform:-3:3", vy="uniform:-3:-0.5", omega="uniform:-1:1", mu="uniform:0:1",
              kappa="uniform:0:1")  # fmt: skip
GRID = dict(vx="-2:2:9", vy="-2:-0.5:3", omega="-1:1:5", mu="0:1:5", kappa="0:1:3")


def axes(spec):
    return {n: parse_axis(n, v) for n, v in spec.items()}


def every_point(sweep, fields):
    parts = [sweep.evaluate(k, fields) for k in range(sweep.chunks)]
    return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}


def assert_fields_equal(got, columns, fields):
    for name in fields:
        want = columns[name]
        if name == "regime":
            want = np.array([PLANAR_REGIMES.index(r) for r in want])
        # the same kernels on the same numbers: equal to the last bit
        np.testing.assert_array_equal(got[name], want, err_msg=name)


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("body", [ROD, BLOCK], ids=["rod", "block"])
@pytest.mark.parametrize(("spec", "samples"), [(RANDOM, 2000), (GRID, None)], ids=["rand", "grid"])
def test_every_field_is_the_planar_impact_column_of_its_name(body, law, spec, samples):
    sweep = PlanarSweep(body, axes(spec), samples=samples, chunk_size=601, law=law)
    fields = planar_fields()
    got = every_point(sweep, fields)
    imp = solve_planar(body, got["vx"], got["vy"], got["omega"], mu=got["mu"], kappa=got["kappa"],
                       law=law)  # fmt: skip
    assert_fields_equal(got, imp.columns(), fields)
    # the fast path (the process alone) gives the same numbers
    fast = every_point(sweep, tuple(f for f in PROCESS_FIELDS if f in fields))
    assert_fields_equal(fast, imp.columns(), [f for f in PROCESS_FIELDS if f in fields])


@pytest.mark.parametrize("law", LAWS)
def test_pendulum_fields_equal_solve_pendulum(law):
    spec = dict(omega="uniform:-6:-0.1", mu="uniform:0:1", kappa="uniform:0:1")
    sweep = PlanarSweep(PENDULUM, axes(spec), samples=1500, chunk_size=400, law=law)
    assert sweep.inputs == ("omega", "mu", "kappa")
    fields = planar_fields(pendulum=True)
    got = every_point(sweep, fields)
    imp = solve_pendulum(PENDULUM, got["omega"], mu=got["mu"], kappa=got["kappa"], law=law)
    assert_fields_equal(got, imp.columns(), fields)
    result = run_sweep(sweep)
    shares = {k: v for k, v in result.regime_fractions.items() if v}
    assert set(shares) == {"locked", "reverse-compression"} and result.points == 1500


def test_fields_are_the_columns_that_are_not_inputs():
    assert set(planar_fields()) == set(PlanarImpact.column_names()) - {
        "mass", "inertia", "rx", "ry", "mu", "kappa", "before_vx", "before_vy", "before_omega"
    }  # fmt: skip
    assert {"before_vx", "before_vy"} <= set(planar_fields(pendulum=True))
    assert set(planar_fields(pendulum=True)) < set(PendulumImpact.column_names())
    for name in ("after_vx", "after_vy", "after_omega", "regime", "dissipated_fraction",
                 "creates_energy"):  # fmt: skip
        assert name in planar_fields()


def test_regime_fractions_and_histogram_count_every_point():
    sweep = PlanarSweep(ROD, axes(RANDOM), samples=3000, chunk_size=700, law="newton")
    result = run_sweep(sweep, histogram=("creates_energy", 0, 2, 2))
    got = every_point(sweep, ("regime", "creates_energy"))
    counts = np.bincount(got["regime"], minlength=len(PLANAR_REGIMES))
    np.testing.assert_array_equal(result.regime_counts, counts)
    assert result.regimes == PLANAR_REGIMES and result.regime_counts.sum() == result.points == 3000
    # each fraction is rounded once: their sum is 1 to rounding (10 terms, rel 1e-15)
    assert sum(result.regime_fractions.values()) == pytest.approx(1.0, rel=1e-15, abs=0)
    energy = got["creates_energy"]
    assert result.histogram.tolist() == [int((~energy).sum()), int(energy.sum())]


def test_outputs_hold_the_fields_with_their_types_and_metadata(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    sweep = PlanarSweep(ROD, axes(GRID), chunk_size=500, law="energetic")
    fields = ("after_vx", "regime", "creates_energy", "energy_loss")
    run_sweep(sweep, output=tmp_path / "s.parquet", fields=fields)
    run_sweep(sweep, output=tmp_path / "d", fields=fields)
    table = pq.read_table(tmp_path / "s.parquet")
    meta = table.schema.metadata
    assert json.loads(meta[b"regimes"]) == list(PLANAR_REGIMES)
    assert json.loads(meta[b"fixed"]) == {"law": "energetic"}
    assert json.loads(meta[b"body"])["name"] == "rod"
    assert table.schema.field("after_vx").metadata == {b"unit": b"m/s"}
    got = every_point(sweep, fields)
    for name in ("vx", "kappa", *fields):
        want = np.asarray(PLANAR_REGIMES)[got[name]] if name == "regime" else got[name]
        np.testing.assert_array_equal(table.column(name).to_numpy(), want, err_msg=name)
        np.testing.assert_array_equal(np.load(tmp_path / "d" / f"{name}.npy"), got[name])
    assert (
        str(table.schema.field("regime").type)
        == "dictionary<values=string, indices=int8, ordered=0>"
    )
    described = json.loads((tmp_path / "d" / "metadata.json").read_text())
    assert described["regimes"] == list(PLANAR_REGIMES)
    assert described["fixed"] == {"law": "energetic"} and described["body"] == ROD.to_dict()
    assert np.load(tmp_path / "d" / "creates_energy.npy").dtype == bool
    assert np.load(tmp_path / "d" / "regime.npy").dtype == np.int8
    energy = solve_planar(ROD, got["vx"], got["vy"], got["omega"], mu=got["mu"],
                          kappa=got["kappa"], law="energetic").dissipated_fraction  # fmt: skip
    np.testing.assert_array_equal(got["energy_loss"], energy)  # the alias


@pytest.mark.parametrize(
    ("body", "spec", "kwargs", "error", "message"),
    [
        (ROD, dict(RANDOM, omega="uniform:-50:50"), {"samples": 10}, ValueError,
         "must approach the surface at every point.*vy = -0.5, omega = -50"),
        (PENDULUM, dict(omega="-1:1:3", mu="0.3", kappa="0.5"), {}, ValueError,
         "normal velocity omega\\*px reaches"),
        (PENDULUM, dict(vx="1", omega="-1", mu="0.3", kappa="0.5"), {}, ValueError,
         "problem 'pendulum' has no input 'vx'"),
        (ROD, dict(GRID, mu="-1:1:3"), {}, ValueError, "mu must be >= 0"),
        (ROD, dict(GRID, vy="nan"), {}, ValueError, "vy must be finite"),
        (ROD, GRID, {"law": "hooke"}, ValueError, "law must be one of"),
        (ROD, GRID, {"law": 1}, TypeError, "law must be one of"),
        (ROD, GRID, {"samples": 5}, ValueError, "samples is for random"),
        ("rod", GRID, {}, TypeError, "PlanarBody or Pendulum"),
        (PlanarBody.rod(mass=[1.0, 2.0], length=1.0, angle=0.5), GRID, {}, ValueError,
         "a single body"),
    ],
)  # fmt: skip
def test_bad_sweeps_are_named(body, spec, kwargs, error, message):
    with pytest.raises(error, match=message):
        PlanarSweep(body, axes(spec), **kwargs)


def test_unknown_fields_list_the_planar_ones():
    sweep = PlanarSweep(ROD, axes(GRID))
    with pytest.raises(ValueError, match="fields must be among after_vx.*creates_energy"):
        run_sweep(sweep, fields=("zeta",))
    with pytest.raises(ValueError, match="histogram field must be among"):
        run_sweep(sweep, histogram=("before_vx", 0, 1, 2))  # an input of a free body
    assert sweep.chunk_size == 100_000  # a chunk solved whole: about 60 MB


def test_axes_are_taken_only_under_their_own_names():
    from spinimpact.io.sweep import Axis

    built_as_vx = axes(GRID) | {"vy": Axis("vx", "fixed", 4.0)}
    with pytest.raises(ValueError, match=r"axes\['vy'\] is an axis of vx"):
        PlanarSweep(ROD, built_as_vx)
    with pytest.raises(ValueError, match="problem 'planar' has no input 'spin'"):
        PlanarSweep(ROD, axes(GRID) | {"spin": Axis("omega", "fixed", 1.0)})
    with pytest.raises(TypeError, match="samples must be a positive integer"):
        PlanarSweep(ROD, axes(GRID), samples=True)
    with pytest.raises(TypeError, match="chunk_size must be a positive integer"):
        PlanarSweep(ROD, axes(GRID), chunk_size=True)
