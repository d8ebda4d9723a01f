"""solve(..., tangential=law) and solve_sphere(..., tangential=law): the laws' rigid limits
equal today's results, the results' fields by their definitions, bad input named."""

from __future__ import annotations

import json

import numpy as np
import pytest

from spinimpact import (
    Body,
    CompliantImpact,
    CompliantSphereImpact,
    MindlinDeresiewicz,
    State,
    State3,
    Stronge,
    Surface,
    Walton,
    solve,
    solve_sphere,
)
from spinimpact.core.sphere3d import sphere_contact

from tests.cases import SPHERE_ZETAS, random_cases

N = 3000


def _body(c):
    return Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])


def _speed_scale(c):
    return np.abs(c["vx"]) + np.abs(c["vy"]) + np.abs(c["omega"] * c["radius"])


def test_walton_beta0_zero_is_the_rigid_solve_in_every_regime():
    c = random_cases(N, seed=11)
    args = (_body(c), c["vx"], c["vy"], c["omega"])
    rigid = solve(*args, mu=c["mu"], kappa=c["kappa"])
    soft = solve(*args, mu=c["mu"], kappa=c["kappa"], tangential=Walton(0.0))
    assert isinstance(soft, CompliantImpact) and isinstance(soft.after, State)
    scale = _speed_scale(c)
    for name in ("vx", "vy"):
        err = np.abs(getattr(soft.after, name) - getattr(rigid.after, name)) / scale
        assert err.max() < 1e-14, name  # the same formulas: rounding only
    err = np.abs(soft.after.omega - rigid.after.omega) * c["radius"] / scale
    assert err.max() < 1e-14
    assert np.array_equal(soft.slip_after == 0, rigid.slip_after == 0)
    atol = 1e-15 * float(np.max(c["mass"] * scale))
    np.testing.assert_allclose(soft.tangential_impulse, rigid.tangential_impulse, rtol=1e-13,
                               atol=atol)  # fmt: skip
    atol = 1e-12 * float(np.max(rigid.kinetic_energy_before))
    np.testing.assert_allclose(soft.dissipated_energy, rigid.dissipated_energy, rtol=1e-9,
                               atol=atol)  # fmt: skip
    # regimes: the rigid law's two sticking regimes are Walton's "stick"
    mapped = np.where(np.isin(rigid.regime, ["stick-compression", "stick-restitution"]), "stick",
                      rigid.regime)  # fmt: skip
    assert np.array_equal(soft.regime, mapped)


def test_walton_beta0_zero_is_the_rigid_solve_sphere():
    rng = np.random.default_rng(5)
    c = random_cases(N, seed=12, zetas=SPHERE_ZETAS)
    body = _body(c)
    side = rng.normal(0, 2, N)  # velocity out of the plane: the slip turns, keeps its line
    velocity = np.stack([c["vx"], c["vy"], side], -1)
    spin = np.stack([rng.normal(0, 20, N), rng.normal(0, 20, N), c["omega"]], -1)
    normal = np.stack([rng.normal(0, 0.2, N), np.ones(N), rng.normal(0, 0.2, N)], -1)
    surface = Surface(normal=normal, velocity=np.stack([rng.normal(0, 0.3, N), np.zeros(N),
                                                         rng.normal(0, 0.3, N)], -1))  # fmt: skip
    kw = dict(mu=c["mu"], kappa=c["kappa"], surface=surface)
    try:
        rigid = solve_sphere(body, velocity, spin, **kw)
    except ValueError:  # a tilted plane may turn a few impacts away: keep the approaching
        cn = sphere_contact(velocity, spin, surface.normal, c["radius"],
                            surface.velocity).normal_velocity  # fmt: skip
        keep = cn < -1e-3
        body = Body(mass=c["mass"][keep], radius=c["radius"][keep],
                           gyration=c["gyration"][keep])  # fmt: skip
        velocity, spin = velocity[keep], spin[keep]
        surface = Surface(normal=surface.normal[keep], velocity=surface.velocity[keep])
        kw = dict(mu=c["mu"][keep], kappa=c["kappa"][keep], surface=surface)
        rigid = solve_sphere(body, velocity, spin, **kw)
    soft = solve_sphere(body, velocity, spin, tangential=Walton(0.0), **kw)
    assert isinstance(soft, CompliantSphereImpact) and isinstance(soft.after, State3)
    scale = np.abs(velocity).sum(-1) + np.abs(spin).sum(-1) * np.asarray(body.radius)
    err = np.abs(soft.after.velocity - rigid.after.velocity).max(-1) / scale
    assert err.max() < 1e-14
    err = np.abs(soft.after.spin - rigid.after.spin).max(-1) * np.asarray(body.radius) / scale
    assert err.max() < 1e-14
    np.testing.assert_allclose(soft.dissipated_energy, rigid.dissipated_energy, rtol=1e-8,
                               atol=1e-12 * float(np.max(rigid.kinetic_energy_before)))  # fmt: skip


def test_walton_sticking_impact_leaves_with_beta0_and_spins_faster_than_rolling():
    ball = Body.solid_sphere(mass=0.0057, radius=0.033)
    imp = solve(ball, 2.0, -3.0, 0.0, mu=0.6, kappa=0.8, tangential=Walton(0.35))
    assert str(imp.regime) == "slip-reversal"
    assert float(imp.tangential_restitution) == pytest.approx(0.35, rel=1e-14)
    u = imp.after.vx + ball.radius * imp.after.omega
    assert float(u) == pytest.approx(-0.35 * 2.0, rel=1e-13)
    assert float(-imp.after.omega * ball.radius) > float(imp.after.vx)  # overspin
    # the friction impulse by its definition: the change of the centre's momentum
    assert float(imp.tangential_impulse) == pytest.approx(
        ball.mass * float(imp.after.vx - imp.before.vx), rel=1e-12
    )
    # centre restitution by definition
    assert float(imp.centre_tangential_restitution) == pytest.approx(float(imp.after.vx) / 2.0)


def test_walton_sliding_impacts_do_not_depend_on_beta0():
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    a, b = (solve(ball, 10.0, -1.0, 0.0, mu=0.2, kappa=0.8, tangential=Walton(x))
            for x in (0.0, 0.9))  # fmt: skip
    assert str(a.regime) == str(b.regime) == "slip"
    assert float(a.after.vx) == float(b.after.vx)
    beta_slide = -1 + 1.8 * 3.5 * 0.2 / 10.0
    assert float(a.tangential_restitution) == pytest.approx(beta_slide, rel=1e-13)


@pytest.mark.parametrize("beta0", [-1.0, -0.4, 0.0, 0.5, 1.0])
def test_energy_never_increases(beta0):
    c = random_cases(N, seed=13)
    imp = solve(_body(c), c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"],
                tangential=Walton(beta0))  # fmt: skip
    tol = 1e-12 * np.asarray(imp.kinetic_energy_before)
    assert np.all(np.asarray(imp.dissipated_energy) >= -tol)
    beta = np.asarray(imp.tangential_restitution)
    assert np.all(np.abs(beta[np.isfinite(beta)]) <= 1 + 1e-12)


def test_beta0_minus_one_is_a_smooth_surface():
    imp = solve(Body.solid_disk(mass=1.0, radius=0.1), 1.0, -1.0, 5.0, mu=0.7, kappa=0.5,
                tangential=Walton(-1.0))  # fmt: skip
    assert float(imp.tangential_impulse) == 0.0
    assert float(imp.after.omega) == 5.0


def test_result_shape_indexing_json_and_columns():
    imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), np.array([1.0, 0.0, 9.0]), -2.0,
                np.array([3.0, 0.0, 0.0]), mu=0.3, kappa=0.7, tangential=Walton(0.2))  # fmt: skip
    assert imp.shape == (3,) and imp[1].shape == ()
    assert str(imp[1].regime) == "no-slip" and np.isnan(imp[1].tangential_restitution)
    data = json.loads(json.dumps(imp.to_dict(), allow_nan=True))
    assert data["law"] == {"law": "walton", "beta0": 0.2}
    assert set(imp.columns()) == set(CompliantImpact.column_names())
    assert "tangential_restitution" in imp.columns()
    assert "slip-reversal" in repr(imp[0]) or "stick" in repr(imp[0])


def test_the_law_is_a_frozen_value():
    law = Walton(0.3)
    assert law == Walton(beta0=0.3) and hash(law) == hash(Walton(0.3))
    with pytest.raises(AttributeError):
        law.beta0 = 0.1  # type: ignore[misc]
    assert repr(law) == "Walton(beta0=0.3)"


@pytest.mark.parametrize(
    "make, error, message",
    [
        (lambda: Walton(1.5), ValueError, "beta0 must be in [-1, 1], got 1.5"),
        (lambda: Walton(float("nan")), ValueError, "beta0 must be finite"),
        (lambda: Walton("0.2"), TypeError, "beta0 must be a real number"),
        (lambda: Walton(True), TypeError, "beta0"),
        (lambda: Walton([0.1, 0.2]), ValueError, "beta0 must be a single number"),
    ],
)
def test_bad_parameters_are_named(make, error, message):
    with pytest.raises(error, match=message.replace("[", r"\[").replace("]", r"\]")):
        make()


def test_bad_input_through_the_law_is_named_as_in_solve():
    ball = Body.solid_sphere(mass=1.0, radius=0.1)
    with pytest.raises(ValueError, match="vy must be < 0"):
        solve(ball, 1.0, 1.0, 0.0, mu=0.2, kappa=0.5, tangential=Walton(0.1))
    with pytest.raises(ValueError, match="kappa must be in"):
        solve(ball, 1.0, -1.0, 0.0, mu=0.2, kappa=1.5, tangential=Walton(0.1))
    with pytest.raises(TypeError, match="tangential must be a tangential compliance law"):
        solve(ball, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5, tangential="walton")
    with pytest.raises(TypeError, match="tangential must be"):
        solve_sphere(ball, [1.0, -1.0, 0.0], [0.0, 0.0, 0.0], mu=0.2, kappa=0.5, tangential=0.3)
    with pytest.raises(ValueError, match="normal velocity must be < 0"):
        solve_sphere(ball, [1.0, 1.0, 0.0], [0.0, 0.0, 0.0], mu=0.2, kappa=0.5,
                     tangential=Walton(0.1))  # fmt: skip


# -- Stronge -----------------------------------------------------------------------------


@pytest.mark.slow
def test_stronge_through_solve_energy_regimes_and_its_rigid_limit():
    c = random_cases(400, seed=21)
    args = (_body(c), c["vx"], c["vy"], c["omega"])
    rigid = solve(*args, mu=c["mu"], kappa=c["kappa"])
    soft = solve(*args, mu=c["mu"], kappa=c["kappa"], tangential=Stronge(poisson_ratio=0.3))
    assert {"slip", "stick", "slip-reversal", "no-slip", "frictionless"} <= set(soft.regime)
    assert np.all(soft.dissipated_energy >= -1e-12 * soft.kinetic_energy_before)
    np.testing.assert_array_equal(soft.after.vy, rigid.after.vy)
    # the friction impulse moves the centre and the spin as the rigid law's does
    m = np.asarray(_body(c).mass)
    err = np.abs(soft.after.vx - (c["vx"] + soft.tangential_impulse / m)) / _speed_scale(c)
    assert err.max() < 1e-13
    ratio = 1e5
    stiff = solve(*args, mu=c["mu"], kappa=c["kappa"],
                  tangential=Stronge(stiffness_ratio=ratio))  # fmt: skip
    bound = c["mu"] * np.abs(c["vy"]) * np.sqrt(c["zeta"] / ratio)  # docs/compliance.md
    assert np.all(np.abs(stiff.slip_after - rigid.slip_after) <= bound + 1e-13 * _speed_scale(c))


def test_stronge_sphere_in_a_plane_is_the_2d_solve():
    c = random_cases(300, seed=22, zetas=SPHERE_ZETAS)
    body, law = _body(c), Stronge(stiffness_ratio=2.5)
    flat = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"], tangential=law)
    zero = np.zeros_like(c["vx"])
    sphere = solve_sphere(body, np.stack([c["vx"], c["vy"], zero], -1),
                          np.stack([zero, zero, c["omega"]], -1), mu=c["mu"], kappa=c["kappa"],
                          tangential=law)  # fmt: skip
    scale = _speed_scale(c)
    assert np.max(np.abs(sphere.after.vx - flat.after.vx) / scale) < 1e-13
    assert np.max(np.abs((sphere.after.wz - flat.after.omega) * c["radius"]) / scale) < 1e-13
    same = np.isfinite(flat.tangential_restitution)
    beta3, beta2 = sphere.tangential_restitution[same], flat.tangential_restitution[same]
    np.testing.assert_allclose(beta3, beta2, rtol=1e-9, atol=1e-12)
    assert np.array_equal(sphere.regime, flat.regime)


def test_stronge_parameters():
    law = Stronge(poisson_ratio=0.25)
    assert law.stiffness_ratio == pytest.approx(1.5 / 1.75, rel=1e-15)
    assert law.to_dict() == {"law": "stronge", "poisson_ratio": 0.25,
                             "stiffness_ratio": law.stiffness_ratio}  # fmt: skip
    assert repr(law) == "Stronge(poisson_ratio=0.25)"
    assert repr(Stronge(stiffness_ratio=2.0)) == "Stronge(stiffness_ratio=2.0)"
    assert float(law.frequency_ratio(3.5)) == pytest.approx(np.sqrt(3.5 * 1.5 / 1.75))
    for kwargs, error, message in [
        ({}, TypeError, "one of poisson_ratio and stiffness_ratio"),
        ({"poisson_ratio": 0.3, "stiffness_ratio": 1.0}, TypeError, "one of"),
        ({"poisson_ratio": 0.6}, ValueError, r"poisson_ratio must be in \(-1, 0.5\], got 0.6"),
        ({"poisson_ratio": -1.0}, ValueError, "poisson_ratio must be in"),
        ({"poisson_ratio": "0.3"}, TypeError, "poisson_ratio must be a real number"),
        ({"stiffness_ratio": 0.0}, ValueError, "stiffness_ratio must be in"),
        ({"stiffness_ratio": -2.0}, ValueError, "stiffness_ratio must be in"),
        ({"stiffness_ratio": float("inf")}, ValueError, "stiffness_ratio must be finite"),
    ]:
        with pytest.raises(error, match=message):
            Stronge(**kwargs)


@pytest.mark.parametrize(
    "law",
    [
        Walton(beta0=0.3),
        Stronge(poisson_ratio=0.3),
        MindlinDeresiewicz(poisson_ratio=0.3, springs=16, steps=128),
    ],
)
def test_indexing_selects_the_body_of_each_impact(law):
    """As Impact[i]: an array-valued body is broadcast and indexed with the impacts, so
    that each selected impact equals the one solved alone with its own body (zeta
    included: a preset row keeps its exact zeta)."""
    body = Body(mass=[1.0, 2.0], radius=0.1, gyration=[0.05, 0.07])
    imp = solve(body, [[1.0], [2.0], [3.0]], -1.0, 0.0, mu=0.4, kappa=0.6, tangential=law)
    assert imp.shape == (3, 2)
    one = solve(Body(mass=2.0, radius=0.1, gyration=0.07), 3.0, -1.0, 0.0, mu=0.4, kappa=0.6,
                tangential=law)  # fmt: skip
    picked = imp[2, 1]
    assert picked.body.mass == 2.0 and picked.body.gyration == 0.07
    assert picked.body.zeta == one.body.zeta and picked.after.omega == one.after.omega
    row = imp[1]
    assert row.shape == (2,) and list(row.body.mass) == [1.0, 2.0]
    mixed = Body.from_columns(mass=np.array([1.0, 1.0]), radius=np.array([0.1, 0.1]),
                              preset=np.array(["solid-sphere", ""]),
                              gyration=np.array([np.nan, 0.05]))  # fmt: skip
    for k, each in enumerate(solve(mixed, 1.0, -1.0, 0.0, mu=0.4, kappa=0.6, tangential=law)):
        assert each.body.zeta == mixed.zeta[k] and np.ndim(each.body.mass) == 0
    assert Body.solid_sphere(mass=1.0, radius=0.1)._at((2,), 0).mass == 1.0
    sphere = solve_sphere(body, [[[1.0, -1.0, 0.0]], [[2.0, -1.0, 0.0]]], [0.0, 0.0, 0.0],
                          mu=0.4, kappa=0.6, tangential=law)  # fmt: skip
    assert sphere.shape == (2, 2) and sphere[1, 0].body.mass == 1.0
    assert sphere[1, 0].body.gyration == 0.05 and sphere[0].body.mass.shape == (2,)


def test_walton_beta0_minus_one_is_frictionless():
    """beta = min(-1, beta_slide) = -1: the contact point keeps its slip and no friction
    impulse acts, the outcome of mu = 0, so the regime is mu = 0's, "frictionless" (it
    was "stick": the stick branch's test (1 + beta0)|u-| <= ... holds trivially)."""
    c = random_cases(400, seed=5)
    args = (_body(c), c["vx"], c["vy"], c["omega"])
    soft = solve(*args, mu=c["mu"], kappa=c["kappa"], tangential=Walton(-1.0))
    none = solve(*args, mu=0.0, kappa=c["kappa"], tangential=Walton(0.3))
    np.testing.assert_array_equal(soft.after.vx, none.after.vx)
    np.testing.assert_array_equal(soft.after.omega, none.after.omega)
    assert (soft.tangential_impulse == 0).all() and (soft.regime == "frictionless").all()
    assert (none.regime == "frictionless").all()
    assert Walton(-1).frictionless and not Walton(-0.999).frictionless
    assert not Stronge(poisson_ratio=0.3).frictionless
    near = solve(*args, mu=c["mu"], kappa=c["kappa"], tangential=Walton(-0.999))
    assert "frictionless" not in set(near.regime[c["mu"] > 0])
    assert (c["mu"] > 0).sum() >= 300
    sphere = solve_sphere(Body.solid_sphere(mass=1.0, radius=0.1), [1.0, -2.0, 0.5],
                          [3.0, 0.0, 0.0], mu=0.4, kappa=0.7, tangential=Walton(-1.0))  # fmt: skip
    assert str(sphere.regime) == "frictionless"
    assert float(np.abs(sphere.friction_impulse.array).max()) == 0.0
