"""solve_planar() and PlanarBody: the paper's bodies as the case r = (0, -R), presets,
the result vocabulary, history(), bad input."""

import math
import re

import numpy as np
import pytest

from spinimpact import Body, PlanarBody, solve, solve_planar

from tests.cases import random_cases

LAWS = ("newton", "poisson", "energetic")


@pytest.fixture(scope="module")
def paper():
    c = random_cases(20_000, seed=31)
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])
    return c, body, imp


@pytest.mark.parametrize("law", LAWS)
def test_paper_bodies_give_solve_under_every_law(paper, law):
    """With r = (0, -R) every field equals solve() to rounding, whatever the law."""
    c, body, imp = paper
    p = solve_planar(PlanarBody.from_body(body), c["vx"], c["vy"], c["omega"], mu=c["mu"],
                     kappa=c["kappa"], law=law)  # fmt: skip
    assert np.array_equal(p.regime, imp.regime)
    speed = np.abs(c["vx"]) + np.abs(c["vy"]) + c["radius"] * np.abs(c["omega"])
    energy = imp.kinetic_energy_before
    impulse = c["mass"] * speed
    scales = {
        "after_vx": speed, "after_vy": speed, "slip_after": speed,
        "tau0": impulse, "tau1": impulse, "tangential_impulse": impulse, "tau_min_energy": impulse,
        "kinetic_energy_after": energy, "dissipated_energy": energy, "min_kinetic_energy": energy,
        "work_compression_normal": energy, "work_compression_tangential": energy,
        "work_restitution_normal": energy, "work_restitution_tangential": energy,
        "dissipated_fraction": 1.0, "impulse_ratio": 1.0 + c["mu"],
        "newton_restitution": 1.0, "poisson_restitution": 1.0, "energetic_restitution": 1.0,
    }  # fmt: skip
    mine, theirs = p.columns(), imp.columns()
    for name, scale in scales.items():
        err = np.abs(mine[name] - theirs[name]) / scale
        # different, equivalent arithmetic (the coupled formulas with b = 0): the
        # restitution coefficients divide by the small normal works, hence 1e-10
        assert np.max(err) < (1e-10 if "restitution" in name else 1e-12), name
    spin = c["radius"] * np.abs(p.after.omega - imp.after.omega) / speed
    assert np.max(spin) < 1e-12
    assert not p.creates_energy.any()


def test_presets_geometry():
    rod = PlanarBody.rod(mass=2.0, length=1.2, angle=math.pi / 2)
    assert rod.rx == pytest.approx(0.0, abs=1e-15) and rod.ry == pytest.approx(-0.6)
    assert rod.inertia == pytest.approx(2.0 * 1.2**2 / 12)
    block = PlanarBody.block(mass=1.0, width=0.4, height=0.2, angle=0.0)
    assert (block.rx, block.ry) == (pytest.approx(-0.2), pytest.approx(-0.1))
    assert block.inertia == pytest.approx((0.16 + 0.04) / 12)
    disk = PlanarBody.eccentric_disk(mass=1.0, radius=0.1, gyration=0.05, offset=0.0, angle=1.0)
    assert (disk.rx, disk.ry) == (pytest.approx(0.0), pytest.approx(-0.1))
    ecc = PlanarBody.eccentric_disk(mass=1.0, radius=0.1, gyration=0.05, offset=0.03, angle=0.0)
    assert (ecc.rx, ecc.ry) == (pytest.approx(-0.03), pytest.approx(-0.1))
    assert ecc.collision_matrix.tn != 0


def test_a_coupled_contact_makes_the_laws_differ():
    """A rod at 30 degrees, sliding forward: slip stops and the laws disagree."""
    rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(30))
    imps = {law: solve_planar(rod, 0.3, -1.0, 0.0, mu=0.4, kappa=0.6, law=law) for law in LAWS}
    assert imps["newton"].newton_restitution == pytest.approx(0.6, rel=1e-12)
    assert imps["poisson"].poisson_restitution == pytest.approx(0.6, rel=1e-12)
    assert imps["energetic"].energetic_restitution == pytest.approx(0.6, rel=1e-12)
    taus = {law: float(i.tau1) for law, i in imps.items()}
    assert len({round(t, 9) for t in taus.values()}) > 1, taus


def test_result_vocabulary_and_indexing():
    rod = PlanarBody.rod(mass=1.0, length=1.0, angle=np.array([0.5, 1.0, 1.5]))
    imp = solve_planar(rod, 0.2, -1.0, 1.0, mu=0.3, kappa=0.7)
    assert imp.shape == (3,) and len(imp) == 3
    one = imp[1]
    assert one.shape == () and float(one.body.ry) == pytest.approx(float(rod.ry[1]))
    cols = imp.columns()
    assert list(cols) == list(type(imp).column_names())
    assert {"after_vx", "regime", "creates_energy", "inertia", "rx"} <= set(cols)
    d = one.to_dict()
    assert d["law"] == "poisson" and d["body"]["name"] == "rod"
    assert [i.regime for i in imp] == list(imp.regime)


def test_history_ends_at_the_rebound_and_finds_the_energy_minimum():
    rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(40))
    for vx in (-1.5, 0.0, 0.4, 2.0):
        imp = solve_planar(rod, vx, -1.0, 0.5, mu=0.3, kappa=0.8, law="energetic")
        h = imp.history(n=2001)
        assert h.vx[-1] == pytest.approx(float(imp.after.vx), abs=1e-12)
        assert h.omega[-1] == pytest.approx(float(imp.after.omega), abs=1e-12)
        assert h.kinetic_energy[0] == pytest.approx(float(imp.kinetic_energy_before))
        # the minimum over a fine grid is never below the closed form's minimum
        assert h.kinetic_energy.min() >= float(imp.min_kinetic_energy) - 1e-12
        assert h.kinetic_energy.min() - float(imp.min_kinetic_energy) < 1e-6


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (lambda: PlanarBody(1.0, 0.0, 0.1, -0.1), ValueError, "inertia must be > 0"),
        (lambda: PlanarBody(1.0, -2.0, 0.1, -0.1), ValueError, "inertia must be > 0"),
        (lambda: PlanarBody(1.0, 1.0, 0.1, 0.0), ValueError, "ry must be < 0"),
        (lambda: PlanarBody("1", 1.0, 0.1, -0.1), TypeError, "mass must be a real number"),
        (lambda: PlanarBody.rod(mass=1, length=1, angle=4.0), ValueError, "angle must be in"),
        (lambda: PlanarBody.eccentric_disk(mass=1, radius=0.1, gyration=0.05, offset=0.2,
                                           angle=0), ValueError, "offset must be < radius"),
        (lambda: solve_planar(Body.ring(mass=1, radius=1), 0, -1, 0, mu=0.1, kappa=0.5),
         TypeError, "body must be a spinimpact.PlanarBody"),
        (lambda: solve_planar(PlanarBody(1, 1, 0, -1), 0, -1, 0, mu=0.1, kappa=0.5,
                              law="routh"), ValueError, "law must be one of"),
        (lambda: solve_planar(PlanarBody(1, 1, 0.5, -1), 0, -1, 3.0, mu=0.1, kappa=0.5),
         ValueError, "must be < 0 (the contact point must approach the surface)"),
        (lambda: solve_planar(PlanarBody(1, 1, 0, -1), 0, -1, 0, mu=-0.1, kappa=0.5),
         ValueError, "mu must be >= 0"),
    ],
)  # fmt: skip
def test_bad_input_is_named(call, error, message):
    with pytest.raises(error, match=re.escape(message)):
        call()
