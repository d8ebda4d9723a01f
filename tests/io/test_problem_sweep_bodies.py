"""ProblemSweep with a body and inputs held fixed runs every sweep of the per-problem sweeps
(a sphere on a surface, a planar body or a pendulum under a restitution law, one of the
paper's bodies under a tangential law), with their numbers to the last bit."""

import math

import numpy as np
import pytest

from spinimpact import Body, MindlinDeresiewicz, Pendulum, PlanarBody, Stronge, Walton
from spinimpact.io.compliant_sweep import CompliantSweep
from spinimpact.io.planar_sweep import PROCESS_FIELDS, PlanarSweep
from spinimpact.io.problem_sweep import ProblemSweep, problem_fields
from spinimpact.io.sphere_sweep import SphereSweep
from spinimpact.io.sweep import parse_axis
from spinimpact.model.sphere3d import Surface

pytestmark = pytest.mark.slow  # about 10 s in all, the law of micro-slip most of it

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


def axes(spec):
    return {n: parse_axis(n, v) for n, v in spec.items()}


def every_point(sweep, fields):
    parts = [sweep.evaluate(k, fields) for k in range(sweep.chunks)]
    return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}


def assert_same_sweep(old, new, fields):
    """The same points, columns, dtypes, units, regimes and numbers (NaN where NaN)."""
    assert new.inputs == tuple(old.inputs) and new.regimes == tuple(old.regimes)
    a, b = every_point(old, fields), every_point(new, fields)
    assert list(a) == list(b)
    for name in a:
        assert a[name].dtype == b[name].dtype, name
        np.testing.assert_array_equal(a[name], b[name], err_msg=name)
    for name in (*new.inputs, *fields):
        assert new.column_dtype(name) == old.column_dtype(name), name
        assert new.unit(name) == old.unit(name), name


def surface_inputs(normal, velocity):
    normal = {f"normal_{k}": x for k, x in zip("xyz", normal, strict=True)}
    return normal | {f"surface_velocity_{k}": x for k, x in zip("xyz", velocity, strict=True)}


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
    old = SphereSweep(body, axes(spec), samples=samples, chunk_size=701,
                      surface=Surface(normal=normal, velocity=velocity))  # fmt: skip
    new = ProblemSweep(problem="sphere", body=body, axes=spec, samples=samples, chunk_size=701,
                       fixed=surface_inputs(normal, velocity))  # fmt: skip
    fields = problem_fields("sphere", body=Body)
    assert set(fields) == set(old_fields(old))
    assert_same_sweep(old, new, fields)


def old_fields(sweep):
    """The fields an older sweep accepts, found by asking it for each result column."""
    names = set()
    for problem in ("paper", "planar", "pendulum", "sphere"):
        names |= set(problem_fields(problem))
    names |= set(problem_fields("paper", Walton(0.1)))
    accepted = set()
    for name in names:
        try:
            sweep.field_name(name)
        except ValueError:
            continue
        accepted.add(name)
    return accepted


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
    old = PlanarSweep(body, axes(spec), samples=samples, chunk_size=601, law=law)
    new = ProblemSweep(problem="planar", body=body, axes=spec, fixed={"law": law},
                       samples=samples, chunk_size=601)  # fmt: skip
    fields = problem_fields("planar", body=PlanarBody)
    assert set(fields) == old_fields(old)
    assert_same_sweep(old, new, fields)
    process = tuple(f for f in PROCESS_FIELDS if f in fields)  # the process alone
    assert_same_sweep(old, new, process)


@pytest.mark.parametrize("law", ["poisson", "newton", "energetic"])
def test_a_pendulum_under_a_law(law):
    pendulum = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
    spec = dict(omega="-6:-0.1:11", mu="0:1:5", kappa="0:1:4")
    old = PlanarSweep(pendulum, axes(spec), chunk_size=100, law=law)
    new = ProblemSweep(problem="pendulum", body=pendulum, axes=spec, fixed={"law": law},
                       chunk_size=100)  # fmt: skip
    fields = problem_fields("pendulum", body=Pendulum)
    assert set(fields) == old_fields(old)
    assert_same_sweep(old, new, fields)
    assert_same_sweep(old, new, tuple(f for f in PROCESS_FIELDS if f in fields))


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
    old = CompliantSweep(body, axes(spec), samples=samples, chunk_size=300, tangential=law)
    new = ProblemSweep(problem="paper", body=body, axes=spec, samples=samples, chunk_size=300,
                       tangential=law)  # fmt: skip
    fields = problem_fields("paper", law, body=Body)
    assert set(fields) == old_fields(old)
    assert_same_sweep(old, new, fields)
