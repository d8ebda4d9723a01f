"""The per-contact law on floats (core.scalar, core.scalar3d, core.law): the array kernels'
results bit for bit, from Python and from numba.njit code; the docs' example runs."""

import re
from pathlib import Path

import numpy as np
import pytest

from spinimpact import Body, Surface, contact_law, core, solve_pair, solve_sphere
from spinimpact.core import law, scalar
from spinimpact.core.outcomes import rebound_outcomes
from spinimpact.core.works import contact_phase_works

from tests.cases import random_cases
from tests.sphere_cases import random_sphere_cases

ROOT = Path(__file__).resolve().parents[2]
PAPER = ("vx", "vy", "omega", "mass", "radius", "zeta", "mu", "kappa")


def same(a, b):
    """Equal bit for bit (signed zeros and NaN included), elementwise."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return np.array_equal(a.view(np.uint64), b.view(np.uint64))


@pytest.fixture(scope="module")
def cases():
    c = random_cases(2000, seed=1414)
    c["slip"] = c["vx"] + c["radius"] * c["omega"]
    return c


def _rows(c, names):
    return zip(*(c[k].tolist() for k in names), strict=True)


def test_paper_bodies_bit_for_bit(cases):
    c = cases
    args = [c[k] for k in PAPER]
    want_rebound = core.rebound(*args)
    want_regime = core.regime_code(c["slip"], c["vy"], c["zeta"], c["mu"], c["kappa"])
    want_loss = core.dissipated_energy(*args)
    want_flags = rebound_outcomes(
        c["vx"], c["vy"], c["omega"], c["radius"], c["zeta"], c["mu"], c["kappa"]
    )
    got = [law.rebound(*row) for row in _rows(c, PAPER)]
    for j in range(4):
        assert same([g[j] for g in got], want_rebound[j])
    codes = [
        law.regime(*row) for row in _rows(c, ("vx", "vy", "omega", "radius", "zeta", "mu", "kappa"))
    ]
    assert np.array_equal(codes, want_regime)
    assert set(codes) == {0, 1, 2, 3, 4}
    assert same([law.dissipated_energy(*row) for row in _rows(c, PAPER)], want_loss)
    flags = [
        law.outcome_flags(*row)
        for row in _rows(c, ("vx", "vy", "omega", "radius", "zeta", "mu", "kappa"))
    ]
    for j in range(5):
        assert np.array_equal([f[j] for f in flags], want_flags[j])


def test_contact_level_bit_for_bit(cases):
    c = cases
    seam = ("slip", "vy", "mass", "zeta", "mu", "kappa")
    s, vy, m, z, mu, k = (c[n] for n in seam)
    got = [law.contact_impact(*row) for row in _rows(c, seam)]
    want = [
        core.compression_impulse(m, vy),
        core.stick_impulse(m, s, z, mu),
        core.total_impulse(m, vy, k),
        core.tangential_impulse(m, s, vy, z, mu, k),
        core.rebound_slip(s, vy, z, mu, k),
        core.impulse_ratio(s, vy, z, mu, k),
        core.regime_code(s, vy, z, mu, k),
        *contact_phase_works(s, vy, m, z, mu, k),
        core.works.contact_dissipated_energy(s, vy, m, z, mu, k),
        core.works.contact_min_energy_impulse(s, vy, m, z, mu, k),
        core.works.contact_min_energy_case(s, vy, m, z, mu, k),
    ]
    for j, w in enumerate(want):
        assert same([g[j] for g in got], w), j
    # the single-purpose functions agree with the all-at-once one
    for row, g in zip(_rows(c, seam), got, strict=True):
        assert law.contact_impulses(*row) == g[:4]
        assert law.contact_works(*row) == g[7:11]
        assert same(law.contact_dissipated_energy(*row), g[11])
    tau1 = core.total_impulse(m, vy, k)
    got_work = [law.work_tangential(0.0, *row) for row in zip(tau1, m, s, z, mu, strict=True)]
    assert same(got_work, core.works.work_tangential(0.0 * tau1, tau1, m, s, z, mu))
    ratio = np.abs(s) / np.abs(vy)
    want_ratio = core.work_ratio_tangential(ratio, z, mu, k)
    got_ratio = [law.work_ratio_tangential(*row) for row in zip(ratio, z, mu, k, strict=True)]
    assert same(got_ratio, want_ratio)


def test_sign_is_numpys():
    for x in (-2.0, -0.0, 0.0, 3.0, float("nan"), float("inf")):
        assert same(scalar.sign(x), np.sign(x))


def test_sphere_bit_for_bit():
    ball = Body.spherical_shell(mass=0.057, radius=0.033)
    n, vs, v, w, mu, kappa = random_sphere_cases(600, seed=3)
    imp = solve_sphere(ball, v, w, mu=mu, kappa=kappa, surface=Surface(normal=n, velocity=vs))
    unit = Surface(normal=n).normal  # normalised as solve_sphere does
    after = imp.after
    regimes = set()
    for i in range(len(mu)):
        args = (tuple(v[i]), tuple(w[i]), tuple(unit[i]), tuple(vs[i]))
        got = law.sphere_rebound(
            *args, ball.mass, ball.radius, ball.inertia, ball.zeta, mu[i], kappa[i]
        )
        want = [after.vx[i], after.vy[i], after.vz[i], after.wx[i], after.wy[i], after.wz[i]]
        assert same(got, want), i
        code = law.sphere_regime(*args, ball.radius, ball.zeta, mu[i], kappa[i])
        assert core.REGIMES[code] == imp.regime[i]
        regimes.add(code)
        loss = law.sphere_dissipated_energy(
            *args, ball.mass, ball.radius, ball.zeta, mu[i], kappa[i]
        )
        assert same(loss, imp.dissipated_energy[i])
    assert regimes >= {0, 2, 3, 4}


def test_pair_bit_for_bit():
    b1 = Body.solid_sphere(mass=0.17, radius=0.028575)
    b2 = Body(mass=0.3, radius=0.04, gyration=0.02)
    n, vs, v, w, mu, kappa = random_sphere_cases(300, seed=4)
    v = v - vs  # approaching sphere 2 at rest but for its motion across the normal
    rng = np.random.default_rng(5)
    v2, w2 = rng.normal(0, 1, (len(mu), 3)), rng.normal(0, 20, (len(mu), 3))
    v2 -= np.sum(v2 * n, axis=1)[:, None] * n  # sphere 2 moves across the normal only
    imp = solve_pair(
        b1, b2, velocity1=v, spin1=w, velocity2=v2, spin2=w2, normal=n, mu=mu, kappa=kappa
    )
    unit = imp.normal
    for i in range(len(mu)):
        got = law.pair_rebound(
            tuple(v[i]),
            tuple(w[i]),
            tuple(v2[i]),
            tuple(w2[i]),
            (unit.x[i], unit.y[i], unit.z[i]),
            b1.mass,
            b1.radius,
            b1.inertia,
            b2.mass,
            b2.radius,
            b2.inertia,
            mu[i],
            kappa[i],
        )
        want = [
            getattr(s, f)[i]
            for s in (imp.after1, imp.after2)
            for f in ("vx", "vy", "vz", "wx", "wy", "wz")
        ]
        assert same(got, want), i


def test_the_public_path_is_the_law():
    assert contact_law.rebound is law.rebound is scalar.rebound
    assert set(contact_law.__all__) == set(law.__all__)
    assert all(callable(getattr(contact_law, name)) for name in law.__all__ if name != "HAVE_NUMBA")


# --- compiled callers ------------------------------------------------------------------


def _numba():
    return pytest.importorskip("numba", reason="the [fast] extra (numba) is not installed")


@pytest.mark.slow
def test_compiled_callers_get_the_same_bits(cases):
    nb = _numba()
    assert law.HAVE_NUMBA

    @nb.njit
    def every(vx, vy, om, m, r, z, mu, k, out, codes):
        for i in range(vx.size):
            a, b, c, f = law.rebound(vx[i], vy[i], om[i], m[i], r[i], z[i], mu[i], k[i])
            loss = law.dissipated_energy(vx[i], vy[i], om[i], m[i], r[i], z[i], mu[i], k[i])
            t0, ts, t1, f1 = law.impulses(vx[i], vy[i], om[i], m[i], r[i], z[i], mu[i], k[i])
            all_ = law.contact_impact(vx[i] + r[i] * om[i], vy[i], m[i], z[i], mu[i], k[i])
            out[i, 0], out[i, 1], out[i, 2], out[i, 3] = a, b, c, f
            out[i, 4], out[i, 5], out[i, 6] = loss, ts, all_[12]
            out[i, 7] = all_[8] + all_[10]
            codes[i] = law.regime(vx[i], vy[i], om[i], r[i], z[i], mu[i], k[i])

    c = cases
    n = len(c["vx"])
    out, codes = np.empty((n, 8)), np.empty(n, dtype=np.int64)
    every(*(c[k] for k in PAPER), out, codes)
    py = np.array(
        [
            [
                *law.rebound(*row),
                law.dissipated_energy(*row),
                law.impulses(*row)[1],
                law.contact_impact(
                    row[0] + row[4] * row[2], row[1], row[3], row[5], row[6], row[7]
                )[12],
            ]
            for row in _rows(c, PAPER)
        ]
    )
    assert same(out[:, :7], py)
    assert np.array_equal(
        codes, core.regime_code(c["slip"], c["vy"], c["zeta"], c["mu"], c["kappa"])
    )

    @nb.njit
    def sphere(v, w, n, vs, m, r, j, z, mu, k):
        return law.sphere_rebound(
            (v[0], v[1], v[2]),
            (w[0], w[1], w[2]),
            (n[0], n[1], n[2]),
            (vs[0], vs[1], vs[2]),
            m,
            r,
            j,
            z,
            mu,
            k,
        )

    nrm, vs, v, w, mu, kappa = random_sphere_cases(50, seed=6)
    for i in range(50):
        args = (
            v[i],
            w[i],
            nrm[i],
            vs[i],
            0.057,
            0.033,
            0.057 * 0.033**2 * 2 / 3,
            2.5,
            mu[i],
            kappa[i],
        )
        py_args = (*(tuple(x) for x in args[:4]), *args[4:])
        assert same(sphere(*args), law.sphere_rebound(*py_args))


def _docs_example():
    text = (ROOT / "docs" / "compiled.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)
    return next(b for b in blocks if "numba.njit" in b)


@pytest.mark.slow
def test_the_docs_example_runs():
    _numba()
    code = _docs_example().replace("n = 1_000_000", "n = 2_000")
    assert "n = 2_000" in code
    namespace: dict = {}
    exec(compile(code, "docs/compiled.md", "exec"), namespace)  # noqa: S102
    c = namespace
    want = core.rebound(
        c["vx"], c["vy"], c["omega"], c["mass"], c["radius"], c["zeta"], c["mu"], c["kappa"]
    )
    for j in range(3):
        assert same(c["after"][:, j], want[j])
    assert c["lost"] == pytest.approx(
        float(
            np.sum(
                core.dissipated_energy(
                    c["vx"],
                    c["vy"],
                    c["omega"],
                    c["mass"],
                    c["radius"],
                    c["zeta"],
                    c["mu"],
                    c["kappa"],
                )
            )
        ),
        rel=1e-12,  # a sum in another order
    )


@pytest.mark.parametrize("name", ["newton", "poisson", "energetic"])
@pytest.mark.slow
def test_planar_bit_for_bit_from_python_and_compiled_code(name):
    from spinimpact import PlanarBody, solve_planar

    from tests.planar_reference import random_planar_cases

    c = random_planar_cases(800, seed=8)
    keep = c["ry"] < 0  # a PlanarBody touches below its centre
    c = {k: v[keep] for k, v in c.items()}
    body = PlanarBody(mass=c["mass"], inertia=c["inertia"], rx=c["rx"], ry=c["ry"])
    imp = solve_planar(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"], law=name)
    want = [imp.after.vx, imp.after.vy, imp.after.omega, imp.tangential_impulse, imp.tau1]
    code = ("newton", "poisson", "energetic").index(name)
    names = ("vx", "vy", "omega", "mass", "inertia", "rx", "ry", "mu", "kappa")
    got = [law.planar_rebound(*row, code) for row in _rows(c, names)]
    for j in range(5):
        assert same([g[j] for g in got], want[j]), j
    assert len(set(imp.regime.tolist())) >= 7
    nb = _numba()

    @nb.njit
    def every(vx, vy, om, m, j, rx, ry, mu, k, which, out):
        for i in range(vx.size):
            r = law.planar_rebound(
                vx[i], vy[i], om[i], m[i], j[i], rx[i], ry[i], mu[i], k[i], which
            )
            for q in range(5):
                out[i, q] = r[q]

    out = np.empty((len(c["vx"]), 5))
    every(*(c[k] for k in names), code, out)
    assert same(out, np.array(got))


@pytest.mark.slow
def test_the_law_without_numba_is_plain_python():
    """With Numba missing, spinimpact.contact_law imports and computes the same numbers."""
    import subprocess
    import sys

    code = (
        "import sys; sys.modules['numba'] = None\n"
        "from spinimpact import contact_law as law\n"
        "assert not law.HAVE_NUMBA\n"
        "print(repr(law.rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == repr(law.rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8))
