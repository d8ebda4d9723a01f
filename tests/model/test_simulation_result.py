"""Simulation (spinimpact.dynamics.simulate) speaks the shared result vocabulary."""

import dataclasses
import json

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.dynamics import HertzContact, Simulation, simulate
from spinimpact.model.result import Result

BALL = Body.solid_sphere(mass=0.05, radius=0.02)
LAW = HertzContact(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02, alpha=0.05)


@pytest.fixture(scope="module")
def sim():
    return simulate(BALL, 0.5, -3.0, 0.0, mu=0.3, contact=LAW)


def test_simulation_is_a_frozen_result_over_time(sim):
    assert isinstance(sim, Result)
    n = sim.t.size
    assert n > 400 and sim.shape == (n,) and len(sim) == n
    with pytest.raises(TypeError, match="not indexable"):
        sim[0]  # one impact over time, not many impacts
    with pytest.raises(dataclasses.FrozenInstanceError):
        sim.mu = 0.5
    with pytest.raises(ValueError, match="read-only"):
        sim.normal_force[0] = 1.0
    floats = [f.name for f in dataclasses.fields(sim) if f.type == "float"]
    assert len(floats) == 14 and all(type(getattr(sim, n)) is float for n in floats)


def test_columns_are_one_row_per_sample(sim):
    cols = sim.columns()
    assert tuple(cols) == Simulation.column_names()
    n = sim.t.size
    assert {c.shape for c in cols.values()} == {(n,)}
    np.testing.assert_array_equal(cols["t"], sim.t)
    np.testing.assert_array_equal(cols["normal_force"], sim.normal_force)
    # per-simulation values repeat on every row
    np.testing.assert_array_equal(cols["before_vx"], 0.5)
    np.testing.assert_array_equal(cols["after_vy"], sim.after.vy)
    np.testing.assert_array_equal(cols["zeta"], 3.5)
    assert {"mass", "radius", "gyration", "slip", "tau", "compression"} <= set(cols)


def test_to_dict_is_plain_and_complete(sim):
    d = sim.to_dict()
    assert set(d) == {f.name for f in dataclasses.fields(Simulation)}
    assert d["contact"]["law"] == "HertzContact" and d["contact"]["alpha"] == 0.05
    assert d["body"]["name"] == "solid-sphere" and d["body"]["mass"] == 0.05
    assert d["before"] == {"vx": 0.5, "vy": -3.0, "omega": 0.0}
    assert d["after"]["vx"] == float(sim.after.vx)
    assert d["newton_restitution"] == sim.newton_restitution
    assert isinstance(d["t"], list) and len(d["t"]) == sim.t.size
    back = json.loads(json.dumps(d))
    assert back["tau"][-1] == pytest.approx(sim.tau1, rel=1e-15)
