"""The micro-slip law on floats from the table (core.scalar_mdr, registered by core.law):
the library's results bit for bit where Numba is installed (to rounding without it: the
array path then reads the table with NumPy), from Python and from numba.njit code, and NaN
where the table does not hold."""

import math

import numpy as np
import pytest

from spinimpact import Body, MindlinDeresiewicz, contact_law, solve, solve_sphere
from spinimpact.core import law, mdr_table
from spinimpact.core.fused import HAVE_NUMBA

from tests.core.test_law_tangential import same as bit_for_bit


def same(a, b):
    """Bit for bit where Numba is installed; without it, to rounding (1e-15 of the values'
    scale), since the array path then sums the table's cells with NumPy, in another order."""
    if HAVE_NUMBA:
        return bit_for_bit(a, b)
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.allclose(a, b, rtol=1e-13, atol=1e-15 * np.abs(b).max())


RATIOS = (0.8701, 2.0 / 3.0, 1.0)  # nu = 0.23, 0.5, 0


def _cases(n, ratio, seed):
    """Impacts inside the table's range and bound: spheres, disks and rings whose
    ``zeta r`` is in ``[2, 4]``, ``kappa`` in ``[0.85, 1]``, ``mu`` under the bound, slips
    on both sides of the stick thresholds, and a few with no slip or no friction."""
    rng = np.random.default_rng(seed)
    zetas = np.array([z for z in (2.5, 3.0, 3.5, 4.0, 5.0) if 2.01 <= z * ratio <= 3.99])
    zeta = rng.choice(zetas, n)
    kappa = rng.uniform(0.85, 1.0, n)
    kappa[::17] = 1.0
    mu = rng.uniform(0.01, 1.0, n) * 5.0 / ((1.0 + kappa) * zeta)
    mu[5::23] = 0.0
    vy = -(10 ** rng.uniform(-1, 1, n))
    x = rng.uniform(-1.6, 1.6, n)  # the incidence ratio X
    mass = 10 ** rng.uniform(-2, 1, n)
    radius = 10 ** rng.uniform(-2, 0, n)
    omega = rng.uniform(-1, 1, n) * 3.0 * np.abs(vy) / radius
    slip = x * (1.0 + kappa) * zeta * np.maximum(mu, 0.05) * np.abs(vy)
    slip[3::19] = 0.0
    vx = slip - radius * omega
    gyration = radius / np.sqrt(zeta - 1.0)
    return dict(vx=vx, vy=vy, omega=omega, mass=mass, radius=radius, gyration=gyration,
                mu=mu, kappa=kappa)  # fmt: skip


@pytest.fixture(scope="module")
def table():
    return contact_law.mdr_table()


@pytest.mark.parametrize("ratio", RATIOS)
def test_paper_bodies_bit_for_bit(table, ratio):
    c = _cases(400, ratio, seed=int(ratio * 1000))
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    mdl = MindlinDeresiewicz(stiffness_ratio=ratio)
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"], tangential=mdl)
    rows = zip(c["vx"], c["vy"], c["omega"], c["mass"], c["radius"], body.zeta, c["mu"],
               c["kappa"], strict=True)  # fmt: skip
    got = np.array([law.mdr_rebound(*map(float, row), ratio, table) for row in rows])
    assert not np.isnan(got).any()
    want = (imp.after.vx, imp.after.vy, imp.after.omega, imp.tangential_impulse)
    for j in range(4):
        assert same(got[:, j], want[j]), j
    # every regime of the law is reached: no friction, no slip, stick, reversal, slip
    assert set(imp.regime.tolist()) == {"frictionless", "no-slip", "stick", "slip-reversal",
                                        "slip"}  # fmt: skip


def test_seam_equals_table_slip(table):
    c = _cases(300, RATIOS[0], seed=5)
    zeta = Body(mass=1.0, radius=1.0, gyration=c["gyration"] / c["radius"]).zeta
    slip = c["vx"] + c["radius"] * c["omega"]
    after, stuck = mdr_table.table_slip(slip, c["vy"], zeta, c["mu"], c["kappa"], RATIOS[0])
    seam = [law.mdr_contact(*map(float, row), RATIOS[0], table)
            for row in zip(slip, c["vy"], zeta, c["mu"], c["kappa"], strict=True)]  # fmt: skip
    assert same([s[0] for s in seam], after)
    assert [s[1] for s in seam] == stuck.tolist()
    assert all(type(s[0]) is float and type(s[1]) is bool for s in seam)


def test_usable_is_where_the_library_reads_the_table(table):
    rng = np.random.default_rng(8)
    n = 2000
    zeta = rng.choice([2.5, 3.0, 3.5, 5.0], n)
    mu = rng.uniform(0.0, 1.2, n)
    kappa = rng.uniform(0.7, 1.0, n)
    ratio = rng.uniform(0.5, 1.2, n)
    rows = list(zip(zeta, mu, kappa, ratio, strict=True))
    want = [bool(mdr_table.table_rows(z, m, k, r)) for z, m, k, r in rows]
    got = [law.mdr_usable(z, m, k, r, table) for z, m, k, r in rows]
    assert got == want
    assert 0.2 < np.mean(got) < 0.8  # both sides are tried


def test_outside_the_table_every_output_is_nan(table):
    assert law.mdr_contact(0.1, -1.0, 3.5, 0.3, 0.6, 0.87, table)[0] != 0.1
    assert math.isnan(law.mdr_contact(0.1, -1.0, 3.5, 0.3, 0.6, 0.87, table)[0])  # kappa
    assert math.isnan(law.mdr_contact(0.1, -1.0, 3.5, 1.2, 0.9, 0.87, table)[0])  # mu: bound
    assert math.isnan(law.mdr_contact(0.1, -1.0, 5.0, 0.1, 0.9, 1.0, table)[0])  # q = 5
    assert all(math.isnan(v) for v in law.mdr_rebound(1.0, -1.0, 0.0, 1.0, 0.1, 3.5, 0.3, 0.6,
                                                      0.87, table))  # fmt: skip
    zero, up = (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)
    out = law.sphere_mdr_rebound((1.0, -1.0, 0.0), zero, up, zero, 1.0, 0.1, 0.004, 3.5, 0.3,
                                 0.6, 0.87, table)  # fmt: skip
    assert len(out) == 6 and all(math.isnan(v) for v in out)


def test_spheres_bit_for_bit(table):
    rng = np.random.default_rng(11)
    n = 200
    ball = Body.solid_sphere(mass=0.0027, radius=0.02)
    velocity = np.column_stack([rng.uniform(-5, 5, n), -rng.uniform(0.5, 8, n),
                                rng.uniform(-5, 5, n)])  # fmt: skip
    spin = rng.uniform(-300, 300, (n, 3))
    kappa = rng.uniform(0.85, 1.0, n)
    mu = rng.uniform(0.0, 0.7, n)
    mdl = MindlinDeresiewicz(poisson_ratio=0.3)
    imp = solve_sphere(ball, velocity, spin, mu=mu, kappa=kappa, tangential=mdl)
    got = np.array([
        law.sphere_mdr_rebound(tuple(velocity[i]), tuple(spin[i]), (0.0, 1.0, 0.0),
                               (0.0, 0.0, 0.0), ball.mass, ball.radius, ball.inertia,
                               ball.zeta, mu[i], kappa[i], mdl.stiffness_ratio, table)
        for i in range(n)
    ])  # fmt: skip
    assert not np.isnan(got).any()
    assert same(got[:, :3], imp.after.velocity)
    assert same(got[:, 3:], imp.after.spin)


def test_compiled_loop_gives_the_same_bits(table):
    numba = pytest.importorskip("numba")
    c = _cases(300, RATIOS[0], seed=13)
    zeta = Body(mass=1.0, radius=1.0, gyration=c["gyration"] / c["radius"]).zeta
    columns = [np.ascontiguousarray(c[k], dtype=float)
               for k in ("vx", "vy", "omega", "mass", "radius")]  # fmt: skip
    columns += [np.ascontiguousarray(zeta), c["mu"], c["kappa"]]

    @numba.njit
    def loop(vx, vy, omega, mass, radius, zeta, mu, kappa, ratio, tab):
        out = np.empty((vx.size, 4))
        for i in range(vx.size):
            out[i] = contact_law.mdr_rebound(vx[i], vy[i], omega[i], mass[i], radius[i],
                                             zeta[i], mu[i], kappa[i], ratio, tab)  # fmt: skip
        return out

    compiled = loop(*columns, RATIOS[0], table)
    plain = np.array([law.mdr_rebound(*map(float, row), RATIOS[0], table)
                      for row in zip(*columns, strict=True)])  # fmt: skip
    assert same(compiled, plain)
