"""A fit follows the rule of every long run (spinimpact._long): one evaluation of its model
over all bounces, timed, times the evaluations a fit makes per free parameter; said first
over a minute, refused over an hour unless forced. The clock is replaced by one that the
model's solver advances, so nothing about this machine's speed is asserted."""

import numpy as np
import pytest

import spinimpact._long as long
from spinimpact import Body, MeasuredBounces, fit, solve
from spinimpact._long import TooLong
from spinimpact.model import fit_models
from spinimpact.model.fit import EVALUATIONS_PER_PARAMETER


@pytest.fixture
def bounces():
    rng = np.random.default_rng(3)
    n = 30
    ball = Body.solid_sphere(mass=0.057, radius=0.033)
    vx, vy, om = rng.uniform(1, 8, n), rng.uniform(-6, -2, n), rng.uniform(-100, 100, n)
    imp = solve(ball, vx, vy, om, mu=0.3, kappa=0.8)
    spread = {"after_vx": 0.02, "after_vy": 0.02, "after_omega": 1.0}
    noisy = {k: getattr(imp.after, k[6:]) + rng.normal(0, s, n) for k, s in spread.items()}
    return MeasuredBounces(vx=vx, vy=vy, omega=om, **noisy), ball


@pytest.fixture
def slow_model(monkeypatch):
    """Each evaluation of the rigid model 'takes' ``seconds`` on a clock only it advances."""
    now = [0.0]
    monkeypatch.setattr(long, "clock", lambda: now[0])
    state = type("State", (), {"seconds": 1.0})()
    predict = fit_models.FitModel.predict

    def slow(self, *args, **kwargs):
        now[0] += state.seconds
        return predict(self, *args, **kwargs)

    monkeypatch.setattr(fit_models.FitModel, "predict", slow)
    return state


def test_a_fit_over_an_hour_is_refused_unless_forced_and_over_a_minute_announced(
    bounces, slow_model
):
    data, ball = bounces
    slow_model.seconds = 10.0  # 2 free parameters: 2 * 200 * 10 s, over an hour
    with pytest.raises(TooLong, match=r"this fit \(30 bounces, 2 free parameters\) would take "
                       r"about 1.1 h here"):  # fmt: skip
        fit(data, ball)
    assert EVALUATIONS_PER_PARAMETER * 2 * 10.0 > 3600
    slow_model.seconds = 0.2  # 80 s: announced, then run
    heard = []
    res = fit(data, ball, announce=heard.append)
    assert len(heard) == 1 and 70 < heard[0].seconds < 90
    assert res["mu"].low < 0.3 < res["mu"].high
    slow_model.seconds = 10.0
    assert fit(data, ball, force=True)["kappa"].estimate == pytest.approx(0.8, abs=0.01)
