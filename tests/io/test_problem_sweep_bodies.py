"""ProblemSweep with a body and inputs held fixed: a sphere on a surface, a planar body or a
pendulum under a restitution law, one of the paper's bodies under a tangential law. Every
field is the solver's column of its name, as the solver gives it for one body (and one
surface) over the chunk's points, to the last bit; the files hold the axes alone and
describe the rest."""

import json
import math
import re

import numpy as np
import pytest

from spinimpact import (
    Body,
    MindlinDeresiewicz,
    Pendulum,
    PlanarBody,
    Stronge,
    Walton,
    solve,
    solve_pendulum,
    solve_planar,
    solve_sphere,
)
from spinimpact.core import REGIMES
from spinimpact.core.compliance import COMPLIANT_REGIMES
from spinimpact.core.planar import PLANAR_REGIMES
from spinimpact.io.problem_sweep import ProblemSweep, problem_fields
from spinimpact.io.sweep import run_sweep
from spinimpact.model.problems import PROCESS_COLUMNS
from spinimpact.model.sphere3d import Surface

TILT = (0.2, 1.0, -0.1)
BELT = (1.0, -0.5, 0.3)
SPHERE_RANDOM = dict(vx="uniform:-3:3", vy="uniform:-6:-2", vz="uniform:-3:3",
                     wx="uniform:-80:80", wy="uniform:-80:80", wz="uniform:-80:80",
                     mu="uniform:0:1", kappa="uniform:0:1")  # fmt: skip
SPHERE_GRID = dict(vx="-2:2:5", vy="-4:-1:3", vz="-1:1:3", wx="-30:30:3", wy="0",
                   wz="-50:50:3", mu="0:0.8:3", kappa="0.2:1:2")  # fmt: skip
PLANAR_RANDOM = dict(vx="uniform:-3:3", vy="uniform:-3:-0.5", omega="uniform:-1:1",
                     mu="uniform:0:1", kappa="uniform:0:1")  # fmt: skip
PLANAR_GRID = dict(vx="-2:2:9", vy="-2:-0.5:3", omega="-1:1:5", mu="0:1:5", kappa="0:1:3")
PAPER_RANDOM = dict(vx="uniform:-6:6", vy="uniform:-5:-0.5", omega="uniform:-200:200",
                    mu="0.4", kappa="uniform:0.05:1")  # fmt: skip
# slip u = vx + R*omega is 0 at many points of this grid: beta = -u+/u- is NaN there
PAPER_GRID = dict(vx="-5:5:11", vy="-4:-0.5:3", omega="-50:50:11", mu="0:1:3", kappa="0.1:1:2")


def every_point(sweep, fields, reference=None):
    """Every point's inputs and fields; with ``reference(chunk) -> columns``, the same
    fields from the reference, chunk by chunk (regimes as indices into the sweep's)."""
    parts, want = [], []
    for k in range(sweep.chunks):
        got = sweep.evaluate(k, fields)
        parts.append(got)
        if reference is not None:
            n = sweep.chunk_length(k)
            columns = reference(sweep.chunk(k))
            want.append({f: np.broadcast_to(codes(sweep, columns[f]) if f == "regime"
                                             else columns[f], (n,)) for f in fields})  # fmt: skip
    join = lambda ps: {n: np.concatenate([p[n] for p in ps]) for n in ps[0]}  # noqa: E731
    return join(parts), (join(want) if want else None)


def codes(sweep, names):
    return np.asarray([sweep.regimes.index(str(r)) for r in np.asarray(names).ravel()], np.int8)


def assert_fields_equal(sweep, fields, reference):
    got, want = every_point(sweep, fields, reference)
    for name in fields:
        np.testing.assert_array_equal(got[name], want[name], err_msg=name)  # NaN where NaN
        assert got[name].dtype == (np.int8 if name == "regime" else want[name].dtype), name
    return got


def surface_inputs(normal, velocity):
    normal = {f"normal_{k}": x for k, x in zip("xyz", normal, strict=True)}
    return normal | {f"surface_velocity_{k}": x for k, x in zip("xyz", velocity, strict=True)}


def stacked(c, *names):
    return np.stack(np.broadcast_arrays(*(c[n] for n in names)), axis=-1)


@pytest.mark.slow  # a few seconds, all cases together
@pytest.mark.parametrize("tilted", [False, True], ids=["flat", "tilted"])
@pytest.mark.parametrize(
    "body",
    [Body.solid_sphere(mass=0.2, radius=0.05), Body.spherical_shell(mass=0.057, radius=0.033),
     Body(mass=0.1, radius=0.04, gyration=0.02)],
    ids=["solid", "shell", "custom"],
)  # fmt: skip
@pytest.mark.parametrize(("spec", "samples"), [(SPHERE_RANDOM, 1500), (SPHERE_GRID, None)],
                         ids=["random", "grid"])  # fmt: skip
def test_a_sphere_on_a_surface(body, tilted, spec, samples):
    normal, velocity = (TILT, BELT) if tilted else ((0.0, 1.0, 0.0), (0.0, 0.0, 0.0))
    sweep = ProblemSweep(problem="sphere", body=body, axes=spec, samples=samples,
                         chunk_size=701, fixed=surface_inputs(normal, velocity))  # fmt: skip
    assert sweep.inputs == ("vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa")
    assert sweep.regimes == REGIMES
    plane = Surface(normal=normal, velocity=velocity)  # the numbers as typed, normalised once

    def reference(c):
        return solve_sphere(body, stacked(c, "vx", "vy", "vz"), stacked(c, "wx", "wy", "wz"),
                            mu=c["mu"], kappa=c["kappa"], surface=plane).columns()  # fmt: skip

    fields = problem_fields("sphere", body=Body)
    assert "zeta" not in fields and {"grips", "topspin", "after_wz"} <= set(fields)
    got = assert_fields_equal(sweep, fields, reference)
    assert got["grips"].dtype == bool


@pytest.mark.slow  # a few seconds, all cases together
@pytest.mark.parametrize("law", ["poisson", "newton", "energetic"])
@pytest.mark.parametrize(
    "body",
    [PlanarBody.rod(mass=1.5, length=0.8, angle=math.radians(40)),
     PlanarBody.block(mass=2.0, width=0.3, height=0.1, angle=0.3),
     PlanarBody(0.7, 0.003, 0.01, -0.05)],
    ids=["rod", "block", "custom"],
)  # fmt: skip
@pytest.mark.parametrize(("spec", "samples"), [(PLANAR_RANDOM, 1000), (PLANAR_GRID, None)],
                         ids=["random", "grid"])  # fmt: skip
def test_a_planar_body_under_a_law(body, law, spec, samples):
    sweep = ProblemSweep(problem="planar", body=body, axes=spec, fixed={"law": law},
                         samples=samples, chunk_size=601)  # fmt: skip
    assert sweep.inputs == ("vx", "vy", "omega", "mu", "kappa")
    assert sweep.regimes == PLANAR_REGIMES

    def reference(c):
        return solve_planar(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"],
                            law=law).columns()  # fmt: skip

    fields = problem_fields("planar", body=PlanarBody)
    got = assert_fields_equal(sweep, fields, reference)
    assert got["creates_energy"].dtype == bool
    # the process alone, by the declaration's cheaper solver: the same numbers
    assert_fields_equal(sweep, tuple(f for f in PROCESS_COLUMNS if f in fields), reference)
    assert_fields_equal(sweep, ("after_omega", "regime"), reference)


@pytest.mark.parametrize("law", ["poisson", "newton", "energetic"])
def test_a_pendulum_under_a_law(law):
    pendulum = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
    spec = dict(omega="-6:-0.1:11", mu="0:1:5", kappa="0:1:4")
    sweep = ProblemSweep(problem="pendulum", body=pendulum, axes=spec, fixed={"law": law},
                         chunk_size=100)  # fmt: skip
    assert sweep.inputs == ("omega", "mu", "kappa")

    def reference(c):
        return solve_pendulum(pendulum, c["omega"], mu=c["mu"], kappa=c["kappa"],
                              law=law).columns()  # fmt: skip

    fields = problem_fields("pendulum", body=Pendulum)
    assert {"before_vx", "before_vy"} <= set(fields)
    assert_fields_equal(sweep, fields, reference)
    assert_fields_equal(sweep, tuple(f for f in PROCESS_COLUMNS if f in fields), reference)


@pytest.mark.slow  # a few seconds, all cases together
@pytest.mark.parametrize(
    "law",
    [Walton(0.3), Walton(-0.5), Stronge(poisson_ratio=0.3), Stronge(stiffness_ratio=0.8),
     MindlinDeresiewicz(poisson_ratio=0.3)],
    ids=["walton", "walton-negative", "stronge", "stronge-ratio", "mindlin-deresiewicz"],
)  # fmt: skip
@pytest.mark.parametrize(
    "body",
    [Body.solid_sphere(mass=0.057, radius=0.033), Body.ring(mass=1.0, radius=0.2),
     Body(mass=0.2, radius=0.01, gyration=0.03)],
    ids=["sphere", "ring", "spool"],
)  # fmt: skip
@pytest.mark.parametrize(("spec", "samples"), [(PAPER_RANDOM, 500), (PAPER_GRID, None)],
                         ids=["random", "grid"])  # fmt: skip
def test_one_of_the_papers_bodies_under_a_tangential_law(body, law, spec, samples):
    if isinstance(law, MindlinDeresiewicz):  # integrated in time: a few points are enough
        spec = {**spec, "vx": "-5:5:3", "omega": "-50:50:3"} if samples is None else spec
        samples = samples and 20
    sweep = ProblemSweep(problem="paper", body=body, axes=spec, samples=samples,
                         chunk_size=300, tangential=law)  # fmt: skip
    assert sweep.inputs == ("vx", "vy", "omega", "mu", "kappa")
    assert sweep.regimes == COMPLIANT_REGIMES

    def reference(c):
        return solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"],
                     tangential=law).columns()  # fmt: skip

    fields = problem_fields("paper", law, body=Body)
    assert "tangential_restitution" in fields and "zeta" not in fields
    got = assert_fields_equal(sweep, fields, reference)
    if samples is None:  # the grid holds points of zero slip, where beta = -u+/u- is 0/0
        assert np.isnan(got["tangential_restitution"]).any()


def test_the_files_hold_the_axes_and_describe_the_body_and_the_fixed_inputs(tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="the [parquet] extra is not installed")
    rod = PlanarBody.rod(mass=1.5, length=0.8, angle=math.radians(40))
    sweep = ProblemSweep(problem="planar", body=rod, axes=PLANAR_GRID, fixed={"law": "newton"})
    fields = ("after_vx", "regime", "creates_energy")
    run_sweep(sweep, output=tmp_path / "s.parquet", fields=fields)
    run_sweep(sweep, output=tmp_path / "d", fields=fields)
    table = pq.read_table(tmp_path / "s.parquet")
    assert table.column_names == ["vx", "vy", "omega", "mu", "kappa", *fields]
    meta = {k.decode(): v.decode() for k, v in table.schema.metadata.items()}
    described = json.loads((tmp_path / "d" / "metadata.json").read_text())
    for got in ({k: json.loads(v) if k != "problem" and k != "summary" else v
                 for k, v in meta.items()}, described):  # fmt: skip
        assert got["problem"] == "planar" and got["regimes"] == list(PLANAR_REGIMES)
        assert got["body"] == rod.to_dict() and got["body"]["name"] == "rod"
        assert got["fixed"] == {"law": "newton"}
        assert set(got["axes"]) == {"vx", "vy", "omega", "mu", "kappa"}
    assert sorted(p.name for p in (tmp_path / "d").iterdir()) == sorted(
        [*(f"{n}.npy" for n in (*sweep.inputs, *fields)), "metadata.json"]
    )
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    sphere = ProblemSweep(problem="sphere", body=ball, axes=SPHERE_GRID,
                          fixed=surface_inputs(TILT, BELT))  # fmt: skip
    described = sphere.description()
    assert described["body"] == ball.to_dict()
    assert described["fixed"] == surface_inputs(TILT, BELT)  # the body's preset is in "body"


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        (dict(problem="planar", body=PlanarBody.rod(mass=[1.0, 2.0], length=1.0, angle=0.5)),
         ValueError, "a sweep needs a single body, not an array of bodies"),
        (dict(problem="planar", body="rod"), TypeError, "body must be a spinimpact.Body, Ball"),
        (dict(problem="pendulum", body=PlanarBody(1.0, 0.1, 0.1, -0.1)), ValueError,
         "problem 'pendulum' needs a value or range for gx, gy, px, py"),
        (dict(problem="planar", body=PlanarBody(1.0, 0.1, 0.1, -0.1), axes={"mass": "1:2:3"}),
         ValueError, "mass is given twice: as an axis and held fixed"),
        (dict(problem="planar", body=PlanarBody(1.0, 0.1, 0.1, -0.1), fixed={"mass": 2.0}),
         ValueError, "mass is given twice: 1.0 by the body and 2.0 in fixed"),
        (dict(problem="planar", fixed={"law": "hooke"}), ValueError, "law must be one of"),
        (dict(problem="planar", fixed={"law": 1}), TypeError, "law must be one of"),
        (dict(problem="planar", fixed={"mass": "1:2:3"}), TypeError,
         "fixed['mass'] must be a number"),
        (dict(problem="planar", fixed={"mass": -1.0}), ValueError, "mass must be > 0"),
        (dict(problem="planar", fixed={"spin": 1.0}), ValueError, "has no input 'spin'"),
        (dict(problem="sphere", fixed={"normal_x": 1.0}, axes=SPHERE_GRID), ValueError,
         "normal of problem 'sphere' is given in part"),
        (dict(problem="planar", body=PlanarBody(1.0, 0.1, 0.1, -0.1),
              axes=dict(PLANAR_GRID, omega="-50:50:3")), ValueError,
         "must approach the surface at every point of the sweep, but its normal velocity vy + "
         "omega*rx reaches 4.5 m/s at vy = -0.5, omega = 50 (rx = 0.1 m); narrow the range of "
         "vy or omega"),
        (dict(problem="pendulum", body=Pendulum.rod(mass=1.0, length=1.0, angle=0.5),
              axes=dict(omega="-1:1:3")), ValueError, "normal velocity omega*px reaches"),
        (dict(problem="sphere", body=Body.solid_sphere(mass=1.0, radius=0.1),
              axes=dict(SPHERE_GRID, vy="-1:1:3"), fixed=surface_inputs(TILT, BELT)),
         ValueError, "its normal velocity (v - surface velocity) . normal reaches"),
    ],
)  # fmt: skip
def test_bad_bodies_and_fixed_inputs_are_named(kwargs, error, message):
    if kwargs["problem"] == "planar" and "axes" not in kwargs:
        kwargs = {**kwargs, "axes": PLANAR_GRID}
    kwargs.setdefault("axes", {})
    with pytest.raises(error, match=re.escape(message)):
        ProblemSweep(**kwargs)


@pytest.mark.slow
def test_a_sweep_with_a_body_runs_on_dask_with_the_same_numbers(tmp_path):
    distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed")
    rod = PlanarBody.rod(mass=1.5, length=0.8, angle=math.radians(40))
    sweep = ProblemSweep(problem="planar", body=rod, axes=PLANAR_RANDOM, fixed={"law": "newton"},
                         samples=3000, chunk_size=500)  # fmt: skip
    fields = ("after_vx", "regime", "dissipated_energy")
    local = run_sweep(sweep, output=tmp_path / "local", fields=fields)
    with distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                            dashboard_address=":0") as client:  # fmt: skip
        remote = run_sweep(sweep, output=tmp_path / "remote", fields=fields, client=client)
    np.testing.assert_array_equal(local.regime_counts, remote.regime_counts)
    for name in (*sweep.inputs, *fields):
        a, b = (np.load(tmp_path / run / f"{name}.npy") for run in ("local", "remote"))
        np.testing.assert_array_equal(a, b, err_msg=name)
