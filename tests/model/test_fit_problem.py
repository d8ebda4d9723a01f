"""fit_problem: any registered problem fitted from its declaration, judged on bounces
generated with known parameters plus seeded noise."""

from __future__ import annotations

import json

import numpy as np
import pytest

from spinimpact import (
    BALLS,
    Body,
    MeasuredBounces,
    MindlinDeresiewicz,
    Walton,
    fit,
    fit_problem,
    solve,
    solve_sphere,
)
from spinimpact.cli._common import jsonable
from spinimpact.model.fit import NoScatterError

TENNIS = BALLS["tennis"]
SOLID = Body.solid_sphere(mass=0.058, radius=0.033)
AFTER = ("after_vx", "after_vy", "after_vz", "after_wx", "after_wy", "after_wz")
SIGMA_V, SIGMA_W = 0.05, 3.0  # m/s, rad/s: high-speed video of a ball


def incidences(n, seed):
    """3D incidences, steep to grazing, with side spin (about the direction of travel) and
    spin about the normal (wy) as well as top- and backspin."""
    rng = np.random.default_rng(seed)
    speed = rng.uniform(3.0, 8.0, n)
    angle = np.radians(np.linspace(10.0, 70.0, n))  # from the normal
    heading = rng.uniform(-0.6, 0.6, n)  # out of the x-y plane
    v = np.stack([speed * np.sin(angle) * np.cos(heading), -speed * np.cos(angle),
                  speed * np.sin(angle) * np.sin(heading)], -1)  # fmt: skip
    w = rng.normal(0.0, 60.0, (n, 3))
    w[:, 1] += rng.choice([-1.0, 1.0], n) * rng.uniform(40.0, 120.0, n)  # spin about the normal
    return v, w


def measured(body, n=30, seed=1, mu=0.4, kappa=0.75, tangential=None, sigmas=True):
    """Columns of ``n`` sphere bounces, their rebound measured with noise (the spin not
    at all on every fourth bounce)."""
    v, w = incidences(n, seed)
    after = solve_sphere(body, v, w, mu=mu, kappa=kappa, tangential=tangential).after
    rng = np.random.default_rng(seed + 100)
    data = {f"v{k}": v[:, i] for i, k in enumerate("xyz")}
    data |= {f"w{k}": w[:, i] for i, k in enumerate("xyz")}
    for q in AFTER:
        sigma = SIGMA_V if q[6] == "v" else SIGMA_W
        data[q] = getattr(after, q[6:]) + rng.normal(0.0, sigma, n)
        if q[6] == "w":
            data[q][::4] = np.nan
        if sigmas:
            data[f"sigma_{q}"] = np.full(n, sigma)
    return data


def inside(est, true):
    return est.low <= true <= est.high


@pytest.mark.slow
def test_3d_bounces_with_side_spin_recover_mu_and_kappa_within_their_intervals():
    data = measured(TENNIS, mu=0.4, kappa=0.75)
    res = fit_problem("sphere", data, body=TENNIS)
    assert res.names == ("mu", "kappa")
    assert inside(res["mu"], 0.4) and inside(res["kappa"], 0.75)
    # the intervals are informative, not merely wide: 3D data determine both
    assert res["mu"].high - res["mu"].low < 0.03
    assert res["kappa"].high - res["kappa"].low < 0.03
    assert res.n_sliding > 0 and res.n_sliding + res.n_sticking == 30
    assert res.quantities == AFTER and res.observed.shape == (30, 6)
    # chi2 with the true sigmas: near its degrees of freedom (p not tiny)
    assert res.p_value > 1e-3
    assert res.problem == "sphere" and res.law is None
    assert res.body["name"] == "tennis" and res.body["radius"] == TENNIS.radius
    assert res.body["source"]["gyration"] == "fixed"
    # the mass plays no part in a sphere's rebound velocities: left at its default, said so
    only_shape = fit_problem("sphere", data, fixed={"radius": TENNIS.radius,
                                                    "gyration": TENNIS.gyration})  # fmt: skip
    assert only_shape.body["source"]["mass"].startswith("default (no part")
    assert only_shape["mu"].estimate == pytest.approx(res["mu"].estimate, rel=1e-9)


@pytest.mark.slow
def test_the_paper_problem_gives_the_2d_fit_s_numbers():
    """The same bounces through the registry's 'paper' problem and through fit(): one
    machinery, the same estimates and intervals (the paper's solver and fit's kernel
    agree to rounding)."""
    rng = np.random.default_rng(3)
    n = 24
    vy = -rng.uniform(2.0, 6.0, n)
    vx = np.linspace(0.3, 4.0, n) * -vy
    om = rng.normal(0.0, 20.0, n)
    true = solve(SOLID, vx, vy, om, mu=0.35, kappa=0.75).after
    noise = (("after_vx", 0.05), ("after_vy", 0.05), ("after_omega", 3.0))
    after = {q: getattr(true, q[6:]) + rng.normal(0.0, s, n) for q, s in noise}
    old = fit(MeasuredBounces(vx, vy, om, **after), SOLID)
    new = fit_problem("paper", {"vx": vx, "vy": vy, "omega": om, **after}, body=SOLID)
    for name in ("mu", "kappa"):
        assert new[name].estimate == pytest.approx(old[name].estimate, rel=1e-6)
        assert new[name].low == pytest.approx(old[name].low, rel=1e-5)
        assert new[name].high == pytest.approx(old[name].high, rel=1e-5)
    assert new.scale == pytest.approx(old.scale, rel=1e-6)
    assert new.n_sliding == old.n_sliding and new.n_sticking == old.n_sticking


@pytest.mark.slow
def test_a_tennis_ball_needs_its_own_body():
    """Fitted with its body (a thick shell), the tennis ball's mu comes back; fitted as a
    solid sphere of the same radius, the same bounces give another mu, whose interval
    misses the truth: the body decides how much a bounce's spin changes."""
    data = measured(TENNIS, mu=0.62, kappa=0.75)
    right = fit_problem("sphere", data, body=TENNIS)
    wrong = fit_problem("sphere", data, fixed={"body": "solid-sphere", "radius": TENNIS.radius})
    assert inside(right["mu"], 0.62)
    assert not inside(wrong["mu"], 0.62)
    assert not inside(right["mu"], wrong["mu"].estimate)
    assert wrong.body["name"] == "solid-sphere" and right.body["name"] == "tennis"


@pytest.mark.slow
def test_walton_fitted_to_3d_bounces():
    data = measured(SOLID, n=30, seed=5, mu=0.3, kappa=0.8, tangential=Walton(beta0=0.35))
    res = fit_problem("sphere", data, body=SOLID, tangential="walton")
    assert res.names == ("mu", "kappa", "beta0")
    for name, true in (("mu", 0.3), ("kappa", 0.8), ("beta0", 0.35)):
        assert inside(res[name], true), res[name]
    assert res.law == {"law": "walton", "beta0": res["beta0"].estimate}
    # the law's parameter held at a given value: fixed, and recorded with the law
    held = fit_problem("sphere", data, body=SOLID, tangential=Walton(beta0=0.35))
    assert held.names == ("mu", "kappa") and held.fixed["beta0"] == 0.35
    assert held.law == {"law": "walton", "beta0": 0.35}
    assert inside(held["mu"], 0.3) and "walton (beta0 = 0.35)" in held.model
    # the rigid law misses what Walton's grip does: a far worse chi2 on the same data
    rigid = fit_problem("sphere", data, body=SOLID)
    assert rigid.chi2 > 3 * res.chi2


@pytest.mark.slow
def test_micro_slip_fitted_to_3d_bounces():
    """Mindlin-Deresiewicz micro-slip, read from its table where kappa >= 0.85: the fit
    recovers mu, kappa and Poisson's ratio within their intervals."""
    law = MindlinDeresiewicz(poisson_ratio=0.3)
    data = measured(SOLID, n=30, seed=5, mu=0.3, kappa=0.9, tangential=law)
    res = fit_problem("sphere", data, body=SOLID, tangential="mindlin-deresiewicz")
    assert res.names == ("mu", "kappa", "poisson_ratio")
    for name, true in (("mu", 0.3), ("kappa", 0.9), ("poisson_ratio", 0.3)):
        assert inside(res[name], true), res[name]
    held = fit_problem("sphere", data, body=SOLID, tangential=law)
    assert held.names == ("mu", "kappa") and held.fixed["poisson_ratio"] == 0.3


@pytest.mark.slow
def test_the_intervals_cover_the_truth_at_their_level():
    """40 synthetic data sets of 16 bounces: the nominal 95 % intervals cover the true mu
    and kappa in at least 34 (85 %, three binomial standard errors below 95 %)."""
    covered = np.zeros(2, dtype=int)
    for seed in range(40):
        data = measured(TENNIS, n=16, seed=1000 + seed, mu=0.5, kappa=0.7)
        res = fit_problem("sphere", data, body=TENNIS)
        covered += [inside(res["mu"], 0.5), inside(res["kappa"], 0.7)]
    assert (covered >= 34).all(), covered


def test_the_toy_problem_s_e_is_fitted_from_its_declaration_alone(toy):
    rng = np.random.default_rng(4)
    speed = -rng.uniform(1.0, 5.0, 20)
    data = {"speed": speed, "speed_after": -0.6 * speed + rng.normal(0.0, 0.02, 20)}
    res = fit_problem("toy", data)
    assert res.names == ("e",) and inside(res["e"], 0.6)
    assert res["e"].high - res["e"].low < 0.02
    assert res.body["name"].startswith("none") and res.law is None


def test_the_result_is_json_with_problem_body_and_law():
    data = measured(SOLID, n=12, seed=2)
    res = fit_problem("sphere", data, body=SOLID, fixed={"kappa": 0.75})
    back = json.loads(json.dumps(jsonable(res.to_dict())))
    assert back["problem"] == "sphere" and back["fixed"]["kappa"] == 0.75
    assert back["body"]["gyration"] == pytest.approx(SOLID.gyration)
    assert back["parameters"]["mu"]["estimate"] == res["mu"].estimate
    assert back["quantities"] == list(AFTER) and len(back["inputs"]["vx"]) == 12
    assert tuple(res.columns()) == res.column_names()


def test_a_fit_without_its_body_is_refused_naming_the_inputs():
    data = measured(TENNIS, n=10)
    with pytest.raises(ValueError, match="a fit needs its body") as err:
        fit_problem("sphere", data)
    assert "body = 'solid-sphere'" in str(err.value) and "radius = 0.1 m" in str(err.value)
    # the radius alone leaves the shape to the default solid sphere: refused, named
    with pytest.raises(ValueError, match="depend on body .*not given"):
        fit_problem("sphere", data, fixed={"radius": TENNIS.radius})


def test_unknown_and_unfittable_parameters_are_refused():
    data = measured(SOLID, n=10)
    with pytest.raises(ValueError, match="'friction', which is neither an input"):
        fit_problem("sphere", data, body=SOLID, free=["mu", "friction"])
    with pytest.raises(ValueError, match="'vx', an input of problem 'sphere' that a fit"):
        fit_problem("sphere", {k: v for k, v in data.items() if k != "vx"} | {"vz": data["vz"]},
                    body=SOLID, free="vx")  # fmt: skip
    with pytest.raises(ValueError, match="beta0.*give tangential="):
        fit_problem("sphere", data, body=SOLID, free=["mu", "beta0"])
    with pytest.raises(ValueError, match="fixed names 'kapa'"):
        fit_problem("sphere", data, body=SOLID, fixed={"kapa": 0.7})
    with pytest.raises(ValueError, match="mu is both free and fixed"):
        fit_problem("sphere", data, body=SOLID, free=["mu"], fixed={"mu": 0.3})
    with pytest.raises(ValueError, match="unknown column 'after_spin'"):
        fit_problem("sphere", data | {"after_spin": data["after_wx"]}, body=SOLID)
    with pytest.raises(TypeError, match="free must be a parameter name"):
        fit_problem("sphere", data, body=SOLID, free=3)
    with pytest.raises(TypeError, match="not its class"):
        fit_problem("sphere", data, body=SOLID, tangential=Walton)
    with pytest.raises(ValueError, match="or a Walton, Stronge or MindlinDeresiewicz law"):
        fit_problem("sphere", data, body=SOLID, tangential="micro-slip")
    with pytest.raises(ValueError, match="does not apply to problem 'planar'"):
        fit_problem("planar", {"vx": [1.0]}, tangential="walton")
    with pytest.raises(ValueError, match="problem must be one of"):
        fit_problem("spheres", data)


def test_impossible_rebounds_and_data_without_scatter_are_refused():
    data = measured(SOLID, n=12, sigmas=False)
    bad = dict(data, after_vy=data["after_vy"].copy())
    bad["after_vy"][3] = -1.0  # into the surface
    with pytest.raises(ValueError, match=r"impossible rebound.*after_vy = -1 m/s at index 3"):
        fit_problem("sphere", bad, body=SOLID)
    v, w = incidences(12, 9)
    exact = solve_sphere(SOLID, v, w, mu=0.4, kappa=0.75).after
    clean = {f"v{k}": v[:, i] for i, k in enumerate("xyz")}
    clean |= {f"w{k}": w[:, i] for i, k in enumerate("xyz")}
    clean |= {f"after_{q}": getattr(exact, q) for q in ("vx", "vy", "vz")}
    with pytest.raises(NoScatterError, match="sigma_after_vx, sigma_after_vy, sigma_after_vz"):
        fit_problem("sphere", clean, body=SOLID)
