"""The Hertz-Mindlin-Deresiewicz impact from the precomputed table (spinimpact.core.mdr_table):
its error against the solution in time on points off the grid, the scaling law it rests on,
the rows it leaves to the solution in time, and bad input."""

import numpy as np
import pytest

from spinimpact import Body, MindlinDeresiewicz, solve
from spinimpact.core import mdr_table as mt
from spinimpact.core.mdr import mdr_slip
from spinimpact.core.tangential import mindlin_stiffness_ratio

FAST = {"springs": 48, "steps": 384}
#: Mindlin's ratio at Poisson's ratio 0, 0.23 and 0.5: the range of common materials.
RATIOS = [float(mindlin_stiffness_ratio(nu)) for nu in (0.0, 0.23, 0.5)]


def _rows(rng, n, ratio):
    """Random impacts with ``zeta r`` and ``kappa`` in the table's range, any incidence
    (the sliding side included), ``mu`` up to 1 and any speed."""
    kappa = np.repeat(rng.uniform(0.85, 1.0, n // 15), 15)  # a few kappa: a quick reference
    zeta = rng.uniform(2.0, 4.0, kappa.size) / ratio
    mu = rng.uniform(0.02, 1.0, kappa.size)
    vy = -rng.uniform(0.2, 8.0, kappa.size)
    slip = rng.uniform(-1.3, 1.3, kappa.size) * (1.0 + kappa) * zeta * mu * -vy
    return slip, vy, zeta, mu, kappa


@pytest.mark.slow
def test_the_table_is_within_its_bound_on_random_points_off_the_grid():
    """Within 1e-4 of |v_n| of the solution in time at its default resolution (the bound
    the table promises; measured 1.2e-5 at most), on 360 random impacts, three materials;
    the stuck flags agree but within 1e-3 of the threshold X*."""
    rng = np.random.default_rng(20261128)
    worst, used = 0.0, 0
    for ratio in RATIOS:
        slip, vy, zeta, mu, kappa = _rows(rng, 120, ratio)
        rows = mt.table_rows(zeta, mu, kappa, ratio)
        got, stuck = mt.table_slip(slip, vy, zeta, mu, kappa, ratio)
        want, held = mdr_slip(slip, vy, zeta, mu, kappa, ratio)
        worst = max(worst, float(np.max(np.abs(got - want) / -vy)))
        x = slip / ((1.0 + kappa) * zeta * mu * -vy)
        star = mt.breaks(zeta * ratio, kappa)[1]
        near = np.abs(np.abs(x) / star - 1.0) < 1e-3
        np.testing.assert_array_equal(stuck[~near], held[~near])
        used += int(rows.sum())
    assert worst <= mt.BOUND
    assert used >= 250  # the table answered most of them (295; the others: mu too large)


def test_the_outcome_depends_on_three_numbers():
    """r c_t^+/(mu |v_n|) is one function of r c_t^-/(mu |v_n|), zeta r and kappa: equal
    for different mu, |v_n|, zeta and r at equal numbers (to rounding, step by step)."""
    scaled = np.array([0.3, 1.0, 2.5, 6.0, -4.0])
    outs = []
    cases = [(3.5, 0.8, 0.3, -1.0), (2.8, 1.0, 0.7, -3.0), (4.0, 0.7, 0.05, -0.2)]
    for zeta, ratio, mu, vy in cases:
        after, _ = mdr_slip(scaled * mu * -vy / ratio, vy, zeta, mu, 0.9, ratio, **FAST)
        outs.append(after * ratio / (mu * -vy))
    np.testing.assert_allclose(outs[1], outs[0], rtol=1e-10, atol=1e-13)
    np.testing.assert_allclose(outs[2], outs[0], rtol=1e-10, atol=1e-13)


def test_the_rebound_does_not_depend_on_mass_or_size():
    law = MindlinDeresiewicz(poisson_ratio=0.23)
    small = solve(Body.solid_sphere(mass=0.003, radius=0.02), [0.2, 1.0], -2.0, 0.0, mu=0.2,
                  kappa=0.9, tangential=law)  # fmt: skip
    large = solve(Body.solid_sphere(mass=4.0, radius=0.5), [1.0, 5.0], -10.0, 0.0, mu=0.2,
                  kappa=0.9, tangential=law)  # fmt: skip
    np.testing.assert_allclose(large.tangential_restitution, small.tangential_restitution,
                               rtol=1e-12)  # fmt: skip


def test_numba_and_numpy_read_the_same_table():
    rng = np.random.default_rng(5)
    x, q, kappa = rng.uniform(-1.2, 1.2, 500), rng.uniform(2, 4, 500), rng.uniform(0.85, 1, 500)
    compiled = mt.impulse_share(x, q, kappa, engine="numba")
    arrays = mt.impulse_share(x, q, kappa, engine="numpy")
    np.testing.assert_allclose(compiled[0], arrays[0], rtol=1e-13, atol=1e-15)  # rounding
    np.testing.assert_array_equal(compiled[1], arrays[1])
    assert mt.impulse_share(x[:6].reshape(2, 3), 3.0, 0.9)[0].shape == (2, 3)
    for engine in ("numba", "numpy"):
        share, stuck = mt.impulse_share([np.nan, np.inf], 3.0, 0.9, engine=engine)
        assert np.isnan(share[0]) and share[1] == 1.0 and not stuck.any()


def test_gross_slip_is_the_closed_form_and_the_share_is_odd():
    phi, stuck = mt.impulse_share([-2.0, -0.4, 0.4, 2.0], 3.0, 0.95)
    assert phi[0] == -1.0 and phi[3] == 1.0 and not stuck[[0, 3]].any()
    assert phi[1] == -phi[2] and stuck[[1, 2]].all() and 0.0 < phi[2] < 1.0


def test_rows_outside_the_range_are_solved_in_time():
    """kappa or zeta r outside the table, a large mu, another resolution, no slip or no
    friction: exactly mdr_slip's numbers."""
    ratio = RATIOS[1]
    slip = np.array([0.5, 0.5, 0.5, 0.0, 0.5, -0.3])
    vy = np.array([-1.0, -1.0, -1.0, -1.0, -1.0, -2.0])
    zeta = np.array([3.5, 6.0, 3.5, 3.5, 3.5, 3.5])
    mu = np.array([0.3, 0.3, 20.0, 0.3, 0.0, 0.3])
    kappa = np.array([0.6, 0.9, 0.9, 0.9, 0.9, 0.9])
    rows = mt.table_rows(zeta, mu, kappa, ratio)
    assert rows.tolist() == [False, False, False, True, True, True]
    got = mt.table_slip(slip[:3], vy[:3], zeta[:3], mu[:3], kappa[:3], ratio)
    want = mdr_slip(slip[:3], vy[:3], zeta[:3], mu[:3], kappa[:3], ratio)
    for a, b in zip(got, want, strict=True):
        np.testing.assert_array_equal(a, b)
    out, stuck = mt.table_slip(slip[3:5], vy[3:5], zeta[3:5], mu[3:5], kappa[3:5], ratio)
    assert out.tolist() == [0.0, 0.5] and stuck.tolist() == [True, False]
    assert not mt.table_rows(3.5, 0.3, 0.9, ratio, **FAST)
    got = mt.table_slip(0.5, -1.0, 3.5, 0.3, 0.9, ratio, **FAST)
    np.testing.assert_array_equal(got[0], mdr_slip(0.5, -1.0, 3.5, 0.3, 0.9, ratio, **FAST)[0])


def test_the_law_reads_the_table_by_default_and_integrates_on_request():
    ball = Body.solid_sphere(mass=0.06, radius=0.02)
    vx = np.linspace(-3.0, 3.0, 13)
    table = solve(ball, vx, -2.0, 0.0, mu=0.3, kappa=0.92,
                  tangential=MindlinDeresiewicz(poisson_ratio=0.3))  # fmt: skip
    law = MindlinDeresiewicz(poisson_ratio=0.3, method="integrate")
    full = solve(ball, vx, -2.0, 0.0, mu=0.3, kappa=0.92, tangential=law)
    vn = 2.0  # m/s: the bound is in units of |v_n|
    assert np.max(np.abs(table.slip_after - full.slip_after)) <= mt.BOUND * vn
    assert table.regime.tolist() == full.regime.tolist()
    np.testing.assert_allclose(table.after.vy, full.after.vy, rtol=1e-15)
    assert repr(law) == "MindlinDeresiewicz(poisson_ratio=0.3, method='integrate')"
    assert law.to_dict()["method"] == "integrate"


def test_bad_input():
    with pytest.raises(ValueError, match="method must be 'table' or 'integrate', got 'fast'"):
        MindlinDeresiewicz(poisson_ratio=0.3, method="fast")
    with pytest.raises(ValueError, match="engine must be 'auto', 'numba' or 'numpy'"):
        mt.impulse_share(0.5, 3.0, 0.9, engine="gpu")
    with pytest.raises(ValueError, match=r"kappa must be in \(0, 1\]"):
        mt.table_slip(0.5, -1.0, 3.5, 0.3, 1.5, 0.87)  # outside: the solution in time refuses it


def test_the_shipped_table():
    tab = mt.load_table()
    assert (tab.springs, tab.steps) == (256, 2048)
    assert tab.share.shape == (2, tab.kappa.size, tab.q.size, tab.t.size)
    assert 0.0 < tab.max_error < 1e-4
    assert ((tab.share >= 0.0) & (tab.share <= 1.0)).all()
    assert (tab.touch[:, None] / ((1.0 + tab.kappa[:, None]) * tab.q) < tab.threshold).all()
