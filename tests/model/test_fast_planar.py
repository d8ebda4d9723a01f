"""The scalar path of solve_planar() and solve_pendulum(): the array path's result, bit for
bit, in every regime and under every restitution law; the same errors."""

import math

import numpy as np
import pytest

from spinimpact import Pendulum, PlanarBody, solve_pendulum, solve_planar
from spinimpact.model import _fast_planar

from tests.planar_reference import random_planar_cases
from tests.same_result import array_path, assert_same

LAWS = ("newton", "poisson", "energetic")


def _array_path(monkeypatch, solver, *args, **kwargs):
    with monkeypatch.context() as m:  # a pendulum's scalar path starts from its spin
        m.setattr(_fast_planar, "pendulum_impact", lambda *a: None)
        return array_path(m, _fast_planar, "planar_impact", solver, *args, **kwargs)


@pytest.fixture(scope="module")
def cases():
    return random_planar_cases(400, seed=77)


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.slow
def test_every_regime_bit_for_bit(cases, law, monkeypatch):
    c = cases
    seen = set()
    for i in np.flatnonzero(c["ry"] < 0):  # a PlanarBody touches below its centre
        body = PlanarBody(mass=c["mass"][i], inertia=c["inertia"][i], rx=c["rx"][i],
                          ry=c["ry"][i])  # fmt: skip
        args = (body, float(c["vx"][i]), float(c["vy"][i]), float(c["omega"][i]))
        kw = dict(mu=float(c["mu"][i]), kappa=float(c["kappa"][i]), law=law)
        fast = solve_planar(*args, **kw)
        assert_same(fast, _array_path(monkeypatch, solve_planar, *args, **kw))
        seen.add(str(fast.regime))
    assert {"frictionless", "no-slip", "stick-compression", "stick-restitution", "slip",
            "reverse-compression", "reverse-restitution", "slip-from-rest"} <= seen  # fmt: skip


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.slow
def test_pendulums_bit_for_bit(law, monkeypatch):
    rng = np.random.default_rng(5)
    seen = set()
    for _ in range(150):
        angle = rng.uniform(0.05, math.pi - 0.05)
        p = Pendulum.rod(mass=10 ** rng.uniform(-1, 1), length=10 ** rng.uniform(-1, 0.5),
                         angle=angle)  # fmt: skip
        omega = -math.copysign(10 ** rng.uniform(-1, 1), math.cos(angle))
        kw = dict(mu=rng.choice([0.0, rng.uniform(0, 2)]), kappa=rng.uniform(0, 1), law=law)
        fast = solve_pendulum(p, omega, **kw)
        assert_same(fast, _array_path(monkeypatch, solve_pendulum, p, omega, **kw))
        seen.add(str(fast.regime))
    assert {"locked", "reverse-compression", "frictionless"} <= seen


@pytest.mark.parametrize(
    "bad",
    [
        dict(vy=1.0),
        dict(vx=math.nan),
        dict(mu=-0.5),
        dict(kappa=1.5),
        dict(law="stronge"),
        dict(law=2),
        dict(omega="spin"),
        dict(vy=[-1.0]),
    ],
)
def test_errors_and_odd_values_are_the_array_paths(bad, monkeypatch):
    rod = PlanarBody.rod(mass=1.0, length=0.5, angle=0.7)
    kw = dict(vx=1.0, vy=-2.0, omega=3.0, mu=0.3, kappa=0.8) | bad
    try:
        slow = _array_path(monkeypatch, solve_planar, rod, **kw)
    except (TypeError, ValueError) as err:
        with pytest.raises(type(err)) as fast:
            solve_planar(rod, **kw)
        assert str(fast.value) == str(err)
    else:
        assert_same(solve_planar(rod, **kw), slow)
