"""spinimpact.model.fit: recovery of known parameters, the flat likelihood of sticking
bounces, masks, uncertainties that scale as they must, model comparison and bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

from spinimpact import Body, TabulatedRestitution, solve
from spinimpact.cli._common import jsonable
from spinimpact.model import fit as fit_module
from spinimpact.model.fit import FitWarning, fit
from spinimpact.model.fit_data import MeasuredBounces
from spinimpact.model.fit_models import make_model

BALL = Body.solid_sphere(mass=0.058, radius=0.033)
SD = np.array([0.05, 0.05, 3.0])


def incidences(n=16, seed=0, ratios=(0.3, 4.0)):
    rng = np.random.default_rng(seed)
    vy = -rng.uniform(2.0, 6.0, n)
    vx = np.linspace(*ratios, n) * -vy
    return vx, vy, rng.normal(0.0, 20.0, n)


def bounces(after, vx, vy, om, noise=0.0, seed=1, sigmas=True, scale=1.0):
    rng = np.random.default_rng(seed)
    values = [a + noise * scale * rng.normal(0.0, s, np.shape(a))
              for a, s in zip((after.vx, after.vy, after.omega), SD, strict=True)]  # fmt: skip
    kw = dict(zip(("sigma_after_vx", "sigma_after_vy", "sigma_after_omega"), SD * scale,
                  strict=True)) if sigmas else {}  # fmt: skip
    return MeasuredBounces(vx, vy, om, *values, **kw)


def test_the_rigid_model_is_solve_on_all_bounces_at_once():
    vx, vy, om = incidences(50)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om)
    model = make_model(BALL, data, restitution="power", reference_speed=4.0)
    pred = model.predict(np.array([0.3, 0.7, -0.2]), data)
    kappa = np.minimum(0.7 * (-vy / 4.0) ** -0.2, 1.0)
    after = solve(BALL, vx, vy, om, mu=0.3, kappa=kappa).after
    np.testing.assert_allclose(pred, np.stack([after.vx, after.vy, after.omega], -1), rtol=0,
                               atol=1e-12)  # fmt: skip


@pytest.mark.parametrize(
    "restitution, kappa, truth",
    [
        ("constant", 0.7, {"mu": 0.3, "kappa": 0.7}),
        ("power", lambda v: 0.8 * (v / 4.0) ** -0.15, {"mu": 0.3, "kappa_ref": 0.8,
                                                       "exponent": -0.15}),
        ((2.0, 4.0, 6.0), TabulatedRestitution([2.0, 4.0, 6.0], [0.9, 0.75, 0.6]),
         {"mu": 0.3, "kappa_at_2": 0.9, "kappa_at_4": 0.75, "kappa_at_6": 0.6}),
    ],
)  # fmt: skip
def test_noise_free_data_give_back_the_parameters(restitution, kappa, truth):
    vx, vy, om = incidences(30)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=kappa).after, vx, vy, om)
    res = fit(data, BALL, restitution=restitution, reference_speed=4.0)
    assert res.names == tuple(truth)
    for name, value in truth.items():
        assert res[name].estimate == pytest.approx(value, abs=1e-6)
        assert res[name].low <= value <= res[name].high
    assert res.chi2 < 1e-8 and res.converged


def test_the_gyration_can_be_fitted():
    shell = Body.spherical_shell(mass=0.058, radius=0.033)
    vx, vy, om = incidences(30)
    data = bounces(solve(shell, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om)
    res = fit(data, BALL, free_gyration=True)  # starts from the solid sphere's gyration
    assert res["gyration"].estimate == pytest.approx(float(shell.gyration), rel=1e-6)


def test_sticking_bounces_only_bound_mu_from_below():
    """Every bounce sticks: the likelihood is flat above the least mu that stops the
    largest slip, so the interval is one-sided and its bound is just below that mu."""
    vx, vy, om = incidences(20, ratios=(0.2, 1.5))
    after = solve(BALL, vx, vy, om, mu=0.5, kappa=0.7)
    assert set(np.asarray(after.regime)) <= {"stick-compression", "stick-restitution"}
    data = bounces(after.after, vx, vy, om)
    res = fit(data, BALL)
    slip = np.abs(vx + 0.033 * om)
    needed = float(np.max(slip / ((1 + 0.7) * 3.5 * -vy)))  # eq. 4.15 at the boundary
    mu = res["mu"]
    assert mu.one_sided and mu.high == np.inf
    assert 0.9 * needed < mu.low < needed
    assert res.n_sliding == 0 and res.n_sticking == 20
    assert np.isinf(mu.standard_error)
    assert "only bound mu" in res.identifiability
    # kappa stays determined; the model is linear in it here (vy+ = -kappa vy, a sticking
    # rebound does not depend on it), so the profile interval is the Wald interval
    k = res["kappa"]
    assert k.high - k.low == pytest.approx(2 * 1.959964 * k.standard_error, rel=1e-4)


def test_sliding_bounces_determine_mu():
    vx, vy, om = incidences(20, ratios=(3.0, 6.0))
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om, noise=1.0)
    res = fit(data, BALL)
    assert res.n_sliding == 20 and res.n_sticking == 0
    assert not res["mu"].one_sided and res["mu"].low < 0.3 < res["mu"].high


def test_missing_values_are_left_out():
    vx, vy, om = incidences(20)
    after = solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after
    data = bounces(after, vx, vy, om, noise=1.0)
    obs = data.observed.copy()
    obs[::3, 0] = np.nan
    obs[1::4, 2] = np.nan
    holes = MeasuredBounces(vx, vy, om, *obs.T, *data.sigma.T)
    wrong = obs.copy()
    wrong[np.isnan(obs)] = 1e3
    res = fit(holes, BALL)
    assert res.n_observations == 60 - 7 - 5
    assert np.isnan(res.residuals[::3, 0]).all() and np.isfinite(res.residuals[2::3, 0]).all()
    same = fit(holes.select(np.arange(20)), BALL)
    assert res["mu"].estimate == same["mu"].estimate


def test_uncertainties_scale_with_the_noise():
    vx, vy, om = incidences(40)
    after = solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after
    one = fit(bounces(after, vx, vy, om, noise=1.0, scale=1.0), BALL)
    two = fit(bounces(after, vx, vy, om, noise=1.0, scale=2.0), BALL)
    np.testing.assert_allclose(two.standard_error, 2 * one.standard_error, rtol=0.05)
    # without sigmas the common sigma is estimated from the scatter, in m/s
    est = fit(bounces(after, vx, vy, om, noise=1.0, sigmas=False), BALL)
    assert not est.sigma_given and est.reduced_chi2 == pytest.approx(1.0)
    assert 0.02 < est.scale < 0.2


def test_information_criteria_prefer_the_model_that_made_the_data():
    vx, vy, om = incidences(60)
    power = solve(BALL, vx, vy, om, mu=0.3, kappa=lambda v: 0.8 * (v / 4.0) ** -0.3).after
    data = bounces(power, vx, vy, om, noise=1.0)
    assert fit(data, BALL, restitution="power").aic < fit(data, BALL).aic - 10
    const = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om, noise=1.0)
    assert fit(const, BALL).bic < fit(const, BALL, restitution="power").bic


def test_fixed_parameters_and_the_result_as_plain_values():
    vx, vy, om = incidences(20)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om, noise=1.0)
    res = fit(data, BALL, fixed={"kappa": 0.7})
    assert res.names == ("mu",) and res.fixed == {"kappa": 0.7}
    text = json.dumps(jsonable(res.to_dict()))
    assert json.loads(text)["parameters"]["mu"]["estimate"] == res["mu"].estimate
    assert tuple(res.columns()) == res.column_names()
    with pytest.raises(KeyError, match="kappa"):
        res["kappa"]
    assert [e.name for e in fit(data, BALL)] == ["mu", "kappa"]
    assert res[0] == res["mu"] and len(res) == 1


def stall_the_optimizer(monkeypatch):
    """Make every least-squares run of fit() report that it did not converge."""
    real = fit_module.minimize

    def stalled(*args, **kwargs):
        out = real(*args, **kwargs)
        out.success, out.message = False, "maximum number of evaluations reached"
        return out

    monkeypatch.setattr(fit_module, "minimize", stalled)


def test_a_fit_that_does_not_converge_warns(monkeypatch):
    stall_the_optimizer(monkeypatch)
    vx, vy, om = incidences(20)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om)
    with pytest.warns(FitWarning, match="did not converge"):
        res = fit(data, BALL)
    assert not res.converged


VX, VY, OM = incidences(6)


@pytest.mark.parametrize(
    "kwargs, error, match",
    [
        ({"vy": [-1, -1, 0.5, -1, -1, -1]}, ValueError, r"vy must be < 0.*index 2"),
        ({"vx": [0, 1, np.nan, 0, 0, 0]}, ValueError, r"vx must be finite.*index 2"),
        ({"after_vx": [0, np.inf, 0, 0, 0, 0]}, ValueError, r"after_vx must be finite or NaN"),
        ({"after_vx": ["a"] * 6}, TypeError, "after_vx"),
        ({"after_vx": None, "after_vy": None, "after_omega": None}, ValueError, "no measured"),
        ({"sigma_after_vx": 0.1}, ValueError, "all three sigmas or none"),
        ({"sigma_after_vx": [0.1, 0, 0.1, 0.1, 0.1, 0.1], "sigma_after_vy": 0.1,
          "sigma_after_omega": 1.0}, ValueError, r"sigma_after_vx must be > 0.*index 1"),
        ({"after_vy": [1.0] * 5}, ValueError, "one value per bounce"),
    ],
)  # fmt: skip
def test_bad_bounces_are_refused_by_name(kwargs, error, match):
    base = {"vx": VX, "vy": VY, "omega": OM, "after_vx": VX * 0.7, "after_vy": -VY * 0.6}
    base.update(kwargs)
    with pytest.raises(error, match=match):
        MeasuredBounces(**base)


def test_unknown_and_missing_columns():
    with pytest.raises(ValueError, match="missing column.*omega"):
        MeasuredBounces.from_columns({"vx": VX, "vy": VY, "after_vx": VX})
    with pytest.raises(ValueError, match="unknown column.*after_spin"):
        MeasuredBounces.from_columns({"vx": VX, "vy": VY, "omega": OM, "after_spin": VX})


@pytest.mark.parametrize(
    "kwargs, error, match",
    [
        ({"model": "soft"}, ValueError, "model must be one of"),
        ({"restitution": "linear"}, ValueError, "restitution must be"),
        ({"restitution": [3.0, 2.0]}, ValueError, "knots must be strictly increasing"),
        ({"fixed": {"nu": 0.3}}, ValueError, "unknown parameter 'nu'"),
        ({"fixed": {"kappa": 1.5}}, ValueError, r"kappa.*must be in \[0, 1\]"),
        ({"fixed": {"kappa": 0.7, "mu": 0.3}}, ValueError, "every parameter is fixed"),
        ({"confidence": 1.0}, ValueError, "confidence"),
        ({"confidence": 0.3}, ValueError, r"confidence must be in \(0.5, 1\)"),
        ({"confidence": "high"}, TypeError, "confidence"),
        ({"free_gyration": 1}, TypeError, "free_gyration"),
        ({"start": {"mu": "x"}}, TypeError, r"start\['mu'\]"),
        ({"start": {"nu": 0.3}}, ValueError, "start names an unknown parameter 'nu'"),
    ],
)  # fmt: skip
def test_bad_options_are_refused_by_name(kwargs, error, match):
    data = MeasuredBounces(VX, VY, OM, after_vx=VX * 0.7, after_vy=-VY * 0.6)
    with pytest.raises(error, match=match):
        fit(data, BALL, **kwargs)


def test_too_few_values_for_the_parameters():
    data = MeasuredBounces(VX[:2], VY[:2], OM[:2], after_vx=[0.5, np.nan], after_vy=[np.nan, 1.0])
    with pytest.raises(
        ValueError, match="too few usable values: 2 measured value.*need at least 3"
    ):
        fit(data, BALL)
    with pytest.raises(TypeError, match="bounces must be"):
        fit({"vx": VX}, BALL)


def test_the_p_value_flags_sigmas_that_are_too_small():
    vx, vy, om = incidences(40)
    after = solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after
    honest = fit(bounces(after, vx, vy, om, noise=1.0), BALL)
    assert 0.001 < honest.p_value
    noisy = fit(bounces(after, vx, vy, om, noise=5.0), BALL)  # sigmas claim 5x too little
    assert noisy.p_value < 1e-6
    assert np.isnan(fit(bounces(after, vx, vy, om, noise=1.0, sigmas=False), BALL).p_value)


def test_a_model_that_gives_no_number_is_an_error_not_a_silent_fit(monkeypatch):
    from spinimpact.model.fit_models import FitModel

    vx, vy, om = incidences(10)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om)
    monkeypatch.setattr(FitModel, "predict", lambda self, theta, b: np.full((len(b), 3), np.nan))
    with pytest.raises(ValueError, match="non-finite rebound at mu = "):
        fit(data, BALL, fixed={"kappa": 0.7}, start={"mu": 0.2})


@pytest.mark.slow
def test_random_truths_are_recovered_from_exact_data():
    """40 random (mu, kappa, body) truths over mixed sliding and sticking bounces: the
    start scan and the optimizer find the one minimum every time."""
    rng = np.random.default_rng(40)
    for _ in range(40):
        mu, kappa = rng.uniform(0.05, 1.0), rng.uniform(0.3, 0.95)
        body = Body.preset(rng.choice(["solid-disk", "ring", "solid-sphere"]), mass=1.0,
                           radius=rng.uniform(0.01, 0.2))  # fmt: skip
        n = 20
        vy = -rng.uniform(0.5, 8.0, n)
        vx = rng.uniform(-8.0, 8.0, n)
        om = rng.normal(0.0, 3.0, n) / float(body.radius)
        after = solve(body, vx, vy, om, mu=mu, kappa=kappa)
        if not np.any(np.asarray(after.regime) == "slip"):
            continue
        res = fit(bounces(after.after, vx, vy, om), body)
        assert res["mu"].estimate == pytest.approx(mu, rel=1e-6)
        assert res["kappa"].estimate == pytest.approx(kappa, rel=1e-6)


@pytest.mark.parametrize("mu, kappa", [(0.0, 0.7), (0.3, 1.0)])
def test_a_truth_on_a_bound_is_an_end_of_its_interval(mu, kappa):
    vx, vy, om = incidences(20)
    data = bounces(solve(BALL, vx, vy, om, mu=mu, kappa=kappa).after, vx, vy, om, noise=1.0)
    res = fit(data, BALL)
    assert res["mu"].low <= mu <= res["mu"].high
    assert res["kappa"].low <= kappa <= res["kappa"].high
    if mu == 0.0:
        # every bounce slides on a smooth surface: together they bound mu from above
        assert res["mu"].low == 0.0 and res["mu"].high < 0.01 and res.n_sliding == 20
    else:
        assert res["kappa"].high == 1.0


def test_profiles_that_keep_finding_lower_chi2_are_a_warning(monkeypatch):
    real = fit_module.intervals

    def restless(prob, x, conf, se):
        out = real(prob, x, conf, se)
        out.better = x + 1e-3  # as if a profile had met a lower minimum every time
        return out

    monkeypatch.setattr(fit_module, "intervals", restless)
    vx, vy, om = incidences(20)
    data = bounces(solve(BALL, vx, vy, om, mu=0.3, kappa=0.7).after, vx, vy, om, noise=1.0)
    with pytest.warns(FitWarning, match="several minima"):
        fit(data, BALL)


def test_the_package_exports_fitwarning_and_the_docstring_names_every_model():
    import spinimpact
    from spinimpact.model.fit_models import TANGENTIAL

    assert spinimpact.FitWarning is FitWarning and "FitWarning" in spinimpact.__all__
    doc = fit.__doc__.split("model :")[1].split("restitution :")[0]
    for name in TANGENTIAL:
        assert f'"{name}"' in doc
