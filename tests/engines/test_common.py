"""spinimpact.engines.common: the standard cases, the axes and EngineRun, without an engine."""

import json

import numpy as np
import pytest

from spinimpact import engines as E
from spinimpact import solve
from spinimpact.engines import common

from .bodies import SPHERE


def test_standard_cases_grid():
    c = E.standard_cases(phases=4)
    assert set(c) == {"vx", "vy", "omega", "mu", "kappa", "phase"}
    assert all(v.shape == (144 * 4,) for v in c.values())
    assert sorted(set(c["phase"])) == [0.125, 0.375, 0.625, 0.875]
    assert set(np.round(0.1 * c["omega"], 12)) == {-3.0, 0.0, 2.0}
    # every regime occurs for the solid sphere
    regimes = set(
        np.asarray(
            solve(
                SPHERE, **{k: c[k] for k in ("vx", "vy", "omega")}, mu=c["mu"], kappa=c["kappa"]
            ).regime
        ).astype(str)
    )
    assert regimes == {"slip", "stick-compression", "stick-restitution", "no-slip"}
    assert E.standard_cases(phases=np.int64(1))["phase"].tolist() == [0.5] * 144


@pytest.mark.parametrize("bad", [0, -1])
def test_standard_cases_rejects_bad_phases(bad):
    with pytest.raises(ValueError, match="phases"):
        E.standard_cases(phases=bad)


@pytest.mark.parametrize("bad", [2.5, True, "8", None])
def test_standard_cases_rejects_phases_of_the_wrong_type(bad):
    with pytest.raises(TypeError, match="phases must be a whole number >= 1"):
        E.standard_cases(phases=bad)


def test_axes():
    """Paper x -> x, y -> z; omega counter-clockwise about the paper's z = x cross y is
    a rotation about the engines' -y (x cross z = -y), and back."""
    vx, vy, omega = np.array([1.0, -2.0]), np.array([-3.0, -4.0]), np.array([5.0, -6.0])
    linear, angular = common.to_engine(vx, vy, omega)
    np.testing.assert_array_equal(linear, [[1.0, 0.0, -3.0], [-2.0, 0.0, -4.0]])
    np.testing.assert_array_equal(angular, [[0.0, -5.0, 0.0], [0.0, 6.0, 0.0]])
    # the paper's z, x cross y, is the engines' x cross z
    np.testing.assert_array_equal(np.cross([1, 0, 0], [0, 0, 1]), [0, -1, 0])
    back = common.from_engine(linear, angular)
    for got, expected in zip(back, (vx, vy, omega), strict=True):
        np.testing.assert_array_equal(got, expected)


def _run(delta=0.1):
    """An EngineRun built by hand: the exact rebound, off by ``delta`` m/s in vx."""
    vx, omega = np.array([[1.0, -2.0], [3.0, 0.0]]), np.array([10.0, -20.0])
    exact = solve(SPHERE, vx, -2.0, omega, mu=0.3, kappa=0.6)
    after = exact.after
    return E.EngineRun(
        engine="pybullet",
        settings={"hz": 240.0, "damping": np.array([1.0, 2.0, 3.0, 4.0])},
        vx=after.vx + delta,
        vy=after.vy,
        omega=after.omega,
        exact=exact,
        phase=np.full((2, 2), 0.25),
        steps=15,
        seconds=2.0,
        batch_size=4,
    )


def test_engine_run_errors_are_over_the_speed_scale():
    run = _run(delta=0.1)
    scale = np.array([[2.0, 2.0], [3.0, 2.0]])  # max(|vx|, |vy| = 2, R |omega| = 1 or 2)
    np.testing.assert_array_equal(run.scale, scale)
    np.testing.assert_allclose(run.errors()["vx"], 0.1 / scale, rtol=1e-12)
    assert np.all(run.errors()["vy"] == 0) and np.all(run.errors()["omega"] == 0)
    np.testing.assert_allclose(run.error, 0.1 / scale, rtol=1e-12)
    assert run.summary()["worst"]["max"] == pytest.approx(0.05, rel=1e-12)
    assert run.seconds_per_impact == 0.5


def test_engine_run_is_a_result():
    run = _run()
    assert run.shape == (2, 2) and len(run) == 2 and len(list(run)) == 2
    one = run[0, 1]
    assert one.shape == () and one.vx == run.vx[0, 1] and one.phase == 0.25
    assert one.exact.before.omega == -20.0 and one.error == run.error[0, 1]
    # the batch's wall time, steps and settings stay the batch's
    assert one.seconds_per_impact == 0.5 and one.steps == 15 and one.settings is run.settings
    d = run.to_dict()
    assert json.loads(json.dumps(d)) == d  # plain values only
    assert d["settings"] == {"hz": 240.0, "damping": [1.0, 2.0, 3.0, 4.0]}
    assert d["vx"] == run.vx.tolist() and d["batch_size"] == 4 and d["engine"] == "pybullet"
    assert d["exact"]["before"]["vx"] == [[1.0, -2.0], [3.0, 0.0]]
    names = E.EngineRun.column_names()
    assert names[:3] == ("vx", "vy", "omega") and names[-1] == "phase"
    assert "exact_after_vx" in names and "exact_mu" in names
    cols = run.columns()
    assert tuple(cols) == names
    assert all(c.shape == (2, 2) for c in cols.values())


def test_available_names_engines_only():
    assert all(isinstance(E.available(name), bool) for name in E.ENGINES)
    with pytest.raises(
        ValueError, match="engine must be one of pybullet, mujoco, drake; got 'numpy'"
    ):
        E.available("numpy")  # importable, but not an engine


def test_setting_helpers():
    assert common.whole_number("n", np.int32(3)) == 3
    with pytest.raises(TypeError, match="n must be a whole number >= 1, got 2.0"):
        common.whole_number("n", 2.0)
    with pytest.raises(ValueError, match="n must be a whole number >= 1, got 0"):
        common.whole_number("n", 0)
    assert common.choice("c", "a", ("a", "b")) == "a"
    with pytest.raises(ValueError, match="c must be 'a' or 'b', got 'z'"):
        common.choice("c", "z", ("a", "b"))
    with pytest.raises(TypeError, match="c must be 'a' or 'b', got 1"):
        common.choice("c", 1, ("a", "b"))
    common.no_more("ode", {})
    with pytest.raises(ValueError, match="unknown ode setting\\(s\\): a, b"):
        common.no_more("ode", {"b": 1, "a": 2})
