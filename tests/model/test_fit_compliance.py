"""fit() with the tangential compliance laws of spinimpact.model.compliance: the law's
parameter is recovered, and the rigid model is worse by the information criteria."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.model import compliance
from spinimpact.model.fit import fit
from spinimpact.model.fit_data import MeasuredBounces
from spinimpact.model.fit_models import TANGENTIAL

BALL = Body.solid_sphere(mass=0.058, radius=0.033)
SD = np.array([0.05, 0.05, 3.0])


def measured(law, n=30, seed=2, kappa=0.7):
    rng = np.random.default_rng(seed)
    vy = -rng.uniform(2.0, 6.0, n)
    vx = np.linspace(0.1, 4.0, n) * -vy
    imp = solve(BALL, vx, vy, 0.0, mu=0.3, kappa=kappa, tangential=law)
    after = (imp.after.vx, imp.after.vy, imp.after.omega)
    obs = [a + rng.normal(0.0, s, n) for a, s in zip(after, SD, strict=True)]
    return MeasuredBounces(vx, vy, np.zeros(n), *obs, *SD), imp


def law(name, value):
    if not hasattr(compliance, name):
        pytest.skip(f"spinimpact.model.compliance has no {name} here")
    if name == "MindlinDeresiewicz":
        return compliance.MindlinDeresiewicz(poisson_ratio=value)
    return getattr(compliance, name)(value)


@pytest.mark.parametrize(
    "model, cls, param, value, kappa", [("walton", "Walton", "beta0", 0.4, 0.7),
                                        ("stronge", "Stronge", "poisson_ratio", 0.3, 0.7),
                                        ("mindlin-deresiewicz", "MindlinDeresiewicz",
                                         "poisson_ratio", 0.3, 0.9)]
)  # fmt: skip
@pytest.mark.slow
def test_the_laws_parameter_is_recovered(model, cls, param, value, kappa):
    data, imp = measured(law(cls, value), kappa=kappa)
    assert model in TANGENTIAL
    res = fit(data, BALL, model=model)
    assert res.names == ("mu", param, "kappa")
    for name, truth in (("mu", 0.3), (param, value), ("kappa", kappa)):
        assert res[name].low < truth < res[name].high, (name, res[name])
    # the regimes at the estimate (a bounce at the edge of sliding may differ from the truth's)
    at = {name: res[name].estimate for name in res.names}
    imp = solve(BALL, data.vx, data.vy, 0.0, mu=at["mu"], kappa=at["kappa"],
                tangential=law(cls, at[param]))  # fmt: skip
    regime = np.asarray(imp.regime)
    assert res.n_sliding == int(np.sum(regime == "slip"))
    assert res.n_sticking == int(np.sum(regime != "slip"))
    rigid = fit(data, BALL)
    assert res.aic < rigid.aic - 100  # the grip the rigid law cannot make


def test_walton_prediction_is_solve_with_the_law():
    from spinimpact.model.fit_models import make_model

    data, _ = measured(law("Walton", 0.2))
    model = make_model(BALL, data, tangential="walton")
    pred = model.predict(np.array([0.25, 0.2, 0.8]), data)
    imp = solve(BALL, data.vx, data.vy, data.omega, mu=0.25, kappa=0.8,
                tangential=compliance.Walton(0.2))  # fmt: skip
    np.testing.assert_array_equal(pred, np.stack([imp.after.vx, imp.after.vy, imp.after.omega], -1))
