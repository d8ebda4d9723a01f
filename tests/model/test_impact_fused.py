"""solve() on arrays through the fused all-field kernel equals its NumPy path, bit for bit."""

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.core import fused_impact
from spinimpact.model import _impact_fused

from tests.cases import random_cases

needs_numba = pytest.mark.skipif(
    not fused_impact.HAVE_NUMBA, reason="the [fast] extra (numba) is not installed"
)


def _numpy_path(monkeypatch, *args, **kwargs):
    with monkeypatch.context() as m:
        m.setattr(_impact_fused, "THRESHOLD", 2**62)  # every size takes the NumPy kernels
        return solve(*args, **kwargs)


def assert_same(fast, plain):
    """Same columns, dtypes, shapes and IEEE values (NaN where NaN, signs of zero too)."""
    a, b = fast.columns(), plain.columns()
    assert list(a) == list(b)
    for name in a:
        x, y = np.asarray(a[name]), np.asarray(b[name])
        assert (x.dtype, x.shape) == (y.dtype, y.shape), name
        if x.dtype.kind == "f":
            np.testing.assert_array_equal(x.view(np.int64), y.view(np.int64), err_msg=name)
        else:
            np.testing.assert_array_equal(x, y, err_msg=name)
    assert type(fast.regime) is type(plain.regime)


def _edge_cases():
    """Boundaries of the regimes, exact in binary, and extreme parameters."""
    rows = [  # vx, vy, omega, radius, zeta, mu, kappa
        (2.0, -1.0, 0.0, 0.5, 2.0, 0.5, 1.0),  # |u| = (1 + kappa) zeta mu |v|: sticks at tau_1
        (1.0, -1.0, 0.0, 0.5, 2.0, 0.5, 1.0),  # |u| = zeta mu |v|: sticks at tau_0
        (0.5, -1.0, 12.5, 0.1, 3.5, 0.5, 0.8),  # vertical, non-spinning rebound
        (1.2, -1.0, 30.0, 0.1, 3.5, 0.5, 0.2),  # slips throughout
        (0.5, -1.0, 30.0, 0.1, 3.5, 0.25, 1.0),  # slip, vx+ = s (1 + kappa) mu |v|: vertical
        (3.0, -1.0, 0.0, 0.1, 3.0, 1e-310, 0.5),  # tiny mu: tau_* overflows to inf
        (3.0, -1.0, 0.0, 0.1, 3.0, 1e6, 0.0),  # huge mu, no restitution
        (0.0, -2.0, 0.0, 0.1, 2.5, 0.4, 0.5),  # no slip, no spin
        (-2.0, -3.0, 20.0, 0.1, 1.05, 0.3, 0.0),  # rolling incidence, spool
        (5.0, -0.1, -3.0, 1.0, 5.0, 0.0, 1.0),  # frictionless
    ]
    cols = np.array(rows).T
    names = ("vx", "vy", "omega", "radius", "zeta", "mu", "kappa")
    return dict(zip(names, cols, strict=True))


@needs_numba
def test_every_field_equals_the_numpy_path_in_every_regime(monkeypatch):
    c = random_cases(20_000, seed=14)
    assert set(c["target"]) == {"frictionless", "no-slip", "stick-compression",
                                "stick-restitution", "slip"}  # fmt: skip
    body = Body.from_columns(
        mass=c["mass"], radius=c["radius"], preset=np.full(c["mass"].size, ""),
        gyration=c["gyration"],
    )  # fmt: skip
    args = (body, c["vx"], c["vy"], c["omega"])
    fast = solve(*args, mu=c["mu"], kappa=c["kappa"])
    plain = _numpy_path(monkeypatch, *args, mu=c["mu"], kappa=c["kappa"])
    assert_same(fast, plain)
    # every regime and every minimum-energy case is present, so every branch was compared
    assert set(fast.regime) == set(c["target"])
    assert len(set(fast.min_energy_case)) == 5
    assert fast.outcome.backward.any() and fast.outcome.reversed_spin.any()


@needs_numba
def test_edges_of_the_regimes_and_extreme_parameters(monkeypatch):
    e = _edge_cases()
    body = Body(mass=2.0, radius=e["radius"], gyration=e["radius"] / np.sqrt(e["zeta"] - 1.0))
    args = (body, e["vx"], e["vy"], e["omega"])
    fast = solve(*args, mu=e["mu"], kappa=e["kappa"])
    assert_same(fast, _numpy_path(monkeypatch, *args, mu=e["mu"], kappa=e["kappa"]))
    assert fast.outcome.vertical[2] and not fast.outcome.spinning[2]
    assert fast.outcome.vertical[4] and fast.outcome.spinning[4]
    assert np.isinf(fast.tau_star[5]) and np.isnan(fast.work_ratio_tangential[-1])


@needs_numba
@pytest.mark.parametrize("preset", ["solid_sphere", "ring", "solid_disk"])
def test_one_body_scalar_surface_broadcast_shapes(monkeypatch, preset):
    c = random_cases(600, seed=3)
    body = getattr(Body, preset)(mass=0.3, radius=0.05)
    vx = c["vx"].reshape(20, 30)
    vy = c["vy"][:30]  # broadcasts along the first axis
    args = (body, vx, vy, 7.0)
    for mu in (0.0, 0.3, c["mu"][:30]):
        fast = solve(*args, mu=mu, kappa=0.7)
        assert fast.shape == (20, 30)
        assert_same(fast, _numpy_path(monkeypatch, *args, mu=mu, kappa=0.7))


@needs_numba
def test_results_read_only_and_callers_arrays_untouched():
    c = random_cases(100, seed=5)
    vx = c["vx"].copy()
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), vx, c["vy"], 0.0, mu=0.3, kappa=0.8)
    for name, column in imp.columns().items():
        assert not np.asarray(column).flags.writeable, name
    assert vx.flags.writeable and np.shares_memory(imp.before.vx, vx) is False
    vx[0] = 99.0  # the result keeps the value it was given
    assert imp.before.vx[0] == c["vx"][0]
    one = imp[3]
    assert one.shape == () and str(one.regime) == str(imp.regime[3])


@needs_numba
def test_threshold_decides_the_path(monkeypatch):
    """Below the threshold (or on 0-d input) fused_fields declines; at it, it computes."""
    from spinimpact.model.impact import Outcome, State

    args = [np.full(3, v) for v in (1.0, -1.0, 0.0, 0.3, 0.8, 1.0, 0.1, 0.05, 5.0)]
    assert _impact_fused.fused_fields(State, Outcome, *args, threshold=4) is None
    assert _impact_fused.fused_fields(State, Outcome, *args, threshold=3) is not None
    zero_d = [np.asarray(a[0]) for a in args]
    assert _impact_fused.fused_fields(State, Outcome, *zero_d, threshold=0) is None


def test_without_numba_solve_takes_the_numpy_path(monkeypatch):
    monkeypatch.setattr(fused_impact, "HAVE_NUMBA", False)
    from spinimpact.model.impact import Outcome, State

    args = [np.full(3, v) for v in (1.0, -1.0, 0.0, 0.3, 0.8, 1.0, 0.1, 0.05, 5.0)]
    assert _impact_fused.fused_fields(State, Outcome, *args) is None
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), np.ones(4), -1.0, 0.0, mu=0.3, kappa=0.8)
    assert imp.regime.dtype.kind == "U" and imp.shape == (4,)
