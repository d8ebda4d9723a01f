"""The tangential compliance laws on floats (core.scalar_tangential, core.scalar_stronge,
registered by core.law) and the approach checks: the library's results bit for bit, from
Python and from numba.njit code."""

import math

import numpy as np
import pytest

from spinimpact import Body, Stronge, Surface, Walton, contact_law, solve, solve_sphere
from spinimpact.core import compliance, law, sphere3d
from spinimpact.core.stronge import COMPILED_FROM, stronge_restitution

from tests.cases import random_cases
from tests.sphere_cases import random_sphere_cases

PAPER = ("vx", "vy", "omega", "mass", "radius", "zeta", "mu", "kappa")
WALTONS = (-1.0, -0.4, 0.0, 0.35, 1.0)  # beta0: no friction, ..., the rigid law, ..., elastic
STRONGES = (0.3, 0.8701, 2.5)  # k_t/k_n: soft, aluminium oxide (nu = 0.23), stiff


def same(a, b):
    """Equal bit for bit (signed zeros and NaN included), elementwise."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def _rows(c, names, k=None):
    rows = zip(*(c[n].tolist() for n in names), strict=True)
    return list(rows) if k is None else list(rows)[:k]


@pytest.fixture(scope="module")
def cases():
    c = random_cases(300, seed=2718)
    c["gyration"] = c["radius"] / np.sqrt(c["zeta"] - 1.0)
    c["slip"] = c["vx"] + c["radius"] * c["omega"]
    return c


def _solve(c, tangential):
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"],
                tangential=tangential)  # fmt: skip
    return imp, (imp.after.vx, imp.after.vy, imp.after.omega, imp.tangential_impulse)


def _zeta(c):
    """The bodies' own ``zeta``, as ``solve`` takes it from ``Body`` (to the last bit)."""
    return Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"]).zeta


@pytest.mark.parametrize("beta0", WALTONS)
def test_walton_bit_for_bit(cases, beta0):
    c = dict(cases, zeta=_zeta(cases))
    imp, want = _solve(c, Walton(beta0))
    got = [law.walton_rebound(*row, beta0) for row in _rows(c, PAPER)]
    for j in range(4):
        assert same([g[j] for g in got], want[j]), j
    seam = [law.walton_contact(*row, beta0) for row in _rows(c, ("slip", "vy", "zeta", "mu",
                                                                   "kappa"))]  # fmt: skip
    after, stuck = compliance.walton_slip(c["slip"], c["vy"], c["zeta"], c["mu"], c["kappa"], beta0)
    assert same([s[0] for s in seam], after)
    assert [s[1] for s in seam] == stuck.tolist()
    if beta0 != -1.0:  # both branches are reached (-1: no friction, all frictionless)
        stuck_regime = "slip-reversal" if beta0 > 0 else "stick"
        assert {stuck_regime, "slip"} <= set(imp.regime.tolist())


def test_walton_beta0_zero_is_the_rigid_laws_slip(cases):
    seam = ("slip", "vy", "zeta", "mu", "kappa")
    for row in _rows(cases, seam):
        assert same(law.walton_contact(*row, 0.0)[0], law.rebound_slip(*row))


@pytest.mark.parametrize("ratio", STRONGES)
def test_stronge_bit_for_bit(cases, ratio):
    c = dict(cases, zeta=_zeta(cases))
    imp, want = _solve(c, Stronge(stiffness_ratio=ratio))
    got = [law.stronge_rebound(*row, ratio) for row in _rows(c, PAPER)]
    for j in range(4):
        assert same([g[j] for g in got], want[j]), j
    seam = [law.stronge_contact(*row, ratio) for row in _rows(c, ("slip", "vy", "zeta", "mu",
                                                                    "kappa"))]  # fmt: skip
    want_seam = stronge_restitution(c["slip"], c["vy"], c["zeta"], c["mu"], c["kappa"], ratio)
    assert same([s[0] for s in seam], want_seam.slip_after)
    assert [s[1] for s in seam] == want_seam.stuck.tolist()
    assert [s[2] for s in seam] == want_seam.transitions.tolist()
    assert {"stick", "slip-reversal", "slip"} <= set(imp.regime.tolist())
    if ratio > 0.5:  # a stiffer spring: stick, slip and stick again in some impacts
        assert max(s[2] for s in seam) >= 2


def test_stronge_one_impact_and_a_batch_agree(cases):
    """The array kernel takes a few impacts through Python and many through its compiled
    loop (with Numba): the same function, the same bits."""
    c = cases
    k = 2 * COMPILED_FROM
    args = [c[n][:k] for n in ("slip", "vy", "zeta", "mu", "kappa")]
    many = stronge_restitution(*args, 0.8701)
    for i in range(k):
        one = stronge_restitution(*(a[i] for a in args), 0.8701)
        assert same(one.slip_after, many.slip_after[i])


def _sphere_cases(seed, n=200):
    normal, vs, v, w, mu, kappa = random_sphere_cases(n, seed)
    return Surface(normal=normal, velocity=vs), v, w, mu, kappa


@pytest.mark.parametrize(
    "tangential, name, parameter",
    [(Walton(b), "sphere_walton_rebound", b) for b in (-0.4, 0.0, 0.5)]
    + [(Stronge(stiffness_ratio=r), "sphere_stronge_rebound", r) for r in (0.8701, 2.5)],
)
def test_sphere_bit_for_bit(tangential, name, parameter):
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    surface, v, w, mu, kappa = _sphere_cases(31)
    imp = solve_sphere(ball, v, w, mu=mu, kappa=kappa, surface=surface, tangential=tangential)
    a = imp.after
    want = np.stack([a.vx, a.vy, a.vz, a.wx, a.wy, a.wz], axis=1)
    f = getattr(law, name)
    got = [
        f(tuple(v[i]), tuple(w[i]), tuple(surface.normal[i]), tuple(surface.velocity[i]),
          ball.mass, ball.radius, ball.inertia, ball.zeta, mu[i], kappa[i], parameter)
        for i in range(len(mu))
    ]  # fmt: skip
    assert same(got, want)
    assert len(set(imp.regime.tolist())) >= 3


# --- approaching -------------------------------------------------------------------------


def test_approaching_truth_table():
    table = [(-3.0, True), (-1e-300, True), (-math.inf, True), (-0.0, False), (0.0, False),
             (1e-300, False), (2.0, False), (math.inf, False), (math.nan, False)]  # fmt: skip
    for vy, want in table:
        assert law.approaching(vy) is want, vy


def test_sphere_and_pair_approaching_truth_table():
    up, still = (0.0, 1.0, 0.0), (0.0, 0.0, 0.0)
    for vy, want in ((-2.0, True), (0.0, False), (1.5, False), (math.nan, False)):
        # a sphere on a level plane, spinning about the normal (no normal velocity from it)
        assert law.sphere_approaching((3.0, vy, 0.0), (0.0, 40.0, 0.0), up, still, 0.1) is want
        # the surface moving up at 1 m/s: the relative normal velocity is vy - 1
        assert law.sphere_approaching((0.0, vy, 0.0), still, up, up, 0.1) is (vy - 1.0 < 0)
        # ball 1 above ball 2 (normal from 2 to 1), moving along the normal
        assert law.pair_approaching((0.0, vy, 0.0), still, still, still, up, 0.03, 0.04) is want
        assert law.pair_approaching(still, still, (0.0, -vy, 0.0), still, up, 0.03, 0.04) is want
    # sideways motion and spin do not make contacts approach
    assert not law.pair_approaching((5.0, 0.0, 0.0), (0.0, 0.0, 9.0), still, (1.0, 2.0, 3.0),
                                    up, 0.03, 0.04)  # fmt: skip


def test_approaching_is_the_check_the_solvers_make():
    """On random incidences, half of them reversed: approaching says exactly where the
    contact point's normal velocity (the number solve_sphere and solve_pair check) is < 0."""
    surface, v, w, mu, kappa = _sphere_cases(7, n=100)
    v = v * np.where(np.arange(len(mu)) % 2, 1.0, -1.0)[:, None]
    n, vs = surface.normal, surface.velocity
    want = sphere3d.sphere_contact(v, w, n, 0.033, vs).normal_velocity < 0
    got = [law.sphere_approaching(tuple(v[i]), tuple(w[i]), tuple(n[i]), tuple(vs[i]), 0.033)
           for i in range(len(mu))]  # fmt: skip
    assert got == want.tolist() and 0 < sum(got) < len(got)
    w2 = np.roll(w, 1, axis=0)
    other = vs + sphere3d.cross(w2, 0.04 * n)
    want = sphere3d.sphere_contact(v, w, n, 0.03, other).normal_velocity < 0
    got = [law.pair_approaching(tuple(v[i]), tuple(w[i]), tuple(vs[i]), tuple(w2[i]), tuple(n[i]),
                                0.03, 0.04) for i in range(len(mu))]  # fmt: skip
    assert got == want.tolist()
    for vy in (-1.0, 1.0):  # solve refuses exactly what approaching calls no impact
        ok = law.approaching(vy)
        try:
            solve(Body.solid_sphere(mass=1.0, radius=0.1), 1.0, vy, 0.0, mu=0.3, kappa=0.5)
        except ValueError:
            assert not ok
        else:
            assert ok


def test_the_public_path_has_them():
    for name in ("walton_rebound", "stronge_rebound", "sphere_walton_rebound",
                 "sphere_stronge_rebound", "walton_contact", "stronge_contact", "approaching",
                 "sphere_approaching", "pair_approaching"):  # fmt: skip
        assert getattr(contact_law, name) is getattr(law, name)
        assert name in contact_law.__all__


# --- compiled callers --------------------------------------------------------------------


@pytest.mark.slow
def test_compiled_callers_get_the_same_bits(cases):
    nb = pytest.importorskip("numba", reason="the [fast] extra (numba) is not installed")
    assert law.HAVE_NUMBA

    @nb.njit
    def every(vx, vy, om, m, r, z, mu, k, beta0, ratio, out, flags):
        for i in range(vx.size):
            args = (vx[i], vy[i], om[i], m[i], r[i], z[i], mu[i], k[i])
            a = law.walton_rebound(*args, beta0)
            b = law.stronge_rebound(*args, ratio)
            for j in range(4):
                out[i, j] = a[j]
                out[i, 4 + j] = b[j]
            flags[i] = law.approaching(vy[i])

    @nb.njit
    def sphere(v, w, n, vs, m, r, j, z, mu, k, beta0, ratio):
        args = ((v[0], v[1], v[2]), (w[0], w[1], w[2]), (n[0], n[1], n[2]),
                (vs[0], vs[1], vs[2]))  # fmt: skip
        a = law.sphere_walton_rebound(*args, m, r, j, z, mu, k, beta0)
        b = law.sphere_stronge_rebound(*args, m, r, j, z, mu, k, ratio)
        near = law.sphere_approaching(*args, r)
        pair = law.pair_approaching(args[0], args[1], args[3], args[1], args[2], r, r)
        return a, b, near, pair

    c = cases
    k = 120
    flags = np.empty(k, dtype=np.bool_)
    for beta0, ratio in ((0.35, 0.8701), (-0.4, 2.5)):
        out = np.empty((k, 8))
        every(*(c[n][:k] for n in PAPER), beta0, ratio, out, flags)
        py = [(*law.walton_rebound(*row, beta0), *law.stronge_rebound(*row, ratio))
              for row in _rows(c, PAPER, k)]  # fmt: skip
        assert same(out, py)
        assert flags.all()
    ball = Body.solid_sphere(mass=0.0027, radius=0.02)
    surface, v, w, mu, kappa = _sphere_cases(11, n=60)
    for i in range(60):
        args = (v[i], w[i], surface.normal[i], surface.velocity[i], ball.mass, ball.radius,
                ball.inertia, ball.zeta, mu[i], kappa[i])  # fmt: skip
        a, b, near, pair = sphere(*args, 0.35, 0.8701)
        py = (*(tuple(x) for x in args[:4]), *args[4:])
        assert same(a, law.sphere_walton_rebound(*py, 0.35))
        assert same(b, law.sphere_stronge_rebound(*py, 0.8701))
        assert near == law.sphere_approaching(*py[:4], ball.radius)
        assert pair == law.pair_approaching(py[0], py[1], py[3], py[1], py[2], ball.radius,
                                            ball.radius)  # fmt: skip
