"""spinimpact.model.fit_drops: kappa(|v|) from drop tests, with uncertainties."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import TabulatedRestitution
from spinimpact.model.fit_drops import fit_drops

G = 9.80665
H0 = np.linspace(0.2, 2.0, 10)
V0 = np.sqrt(2 * G * H0)


def kappa(v):
    return 0.9 * (v / 4.0) ** -0.1


def rebound_heights(noise=0.0, seed=0):
    h1 = (kappa(V0) * V0) ** 2 / (2 * G)
    return h1 + np.random.default_rng(seed).normal(0.0, noise, h1.shape)


def test_a_power_law_is_recovered_from_exact_heights_and_speeds():
    """Exact data have no scatter to estimate a sigma from: the sigmas are given."""
    h1 = rebound_heights()
    sd = {"sigma_before": 1e-3, "sigma_after": 1e-3}
    by_height = fit_drops(H0, h1, restitution="power", **sd)
    by_speed = fit_drops(V0, np.sqrt(2 * G * h1), heights=False, restitution="power", **sd)
    for res in (by_height, by_speed):
        k0 = kappa(np.exp(np.mean(np.log(V0))))  # kappa at the reference speed
        assert res["kappa_ref"].estimate == pytest.approx(k0, abs=1e-7)
        assert res["exponent"].estimate == pytest.approx(-0.1, abs=1e-6)
        assert res.names == ("kappa_ref", "exponent")  # mu plays no part in a drop


def test_a_constant_kappa_agrees_with_the_tabulated_model_of_one_drop():
    res = fit_drops([1.0, 1.0], [0.64, 0.64], sigma_before=1e-3, sigma_after=1e-3)
    table = TabulatedRestitution.from_drop_heights([1.0], [0.64])
    assert res["kappa"].estimate == pytest.approx(float(table.kappas[0]), abs=1e-9)


def test_the_height_error_becomes_the_speed_error():
    """sigma_v = g sigma_h / v: ten times the height error gives ten times the standard
    errors (for small errors, where the first order holds)."""
    h1 = rebound_heights(noise=1e-4)
    small = fit_drops(H0, h1, sigma_before=1e-5, sigma_after=1e-4, restitution="power")
    large = fit_drops(H0, h1, sigma_before=1e-4, sigma_after=1e-3, restitution="power")
    np.testing.assert_allclose(large.standard_error, 10 * small.standard_error, rtol=1e-6)
    assert small["exponent"].low < -0.1 < small["exponent"].high


@pytest.mark.parametrize(
    "args, kwargs, match",
    [
        (([1.0, 0.5], [0.6]), {}, "must be 1-D of one length"),
        (([1.0, 0.5], [1.2, 0.3]), {}, "cannot rebound higher"),
        (([1.0, 2.0, 3.0], [0.5, 2.5, 3.5]), {},
         r"^rebound height 2\.5 > drop height 2\.0 at index 1 "),
        (([1.0, 2.0], [0.5, 2.5]), {"heights": False},
         r"^rebound speed 2\.5 > drop speed 2\.0 at index 1 "),
        (([1.0, -0.5], [0.6, 0.3]), {}, r"drop heights must be > 0.*index 1"),
        (([1.0, 0.5], [0.6, 0.3]), {"sigma_before": 0.01}, "together"),
        (([1.0, 0.5], [0.6, 0.3]), {"sigma_before": 0.01, "sigma_after": 0.0}, "> 0"),
        (([1.0, 0.5], [0.6, 0.3]), {"gravity": -9.8}, "gravity"),
        (([1.0], [0.6]), {}, r"too few drops: 1 drop\(s\)"),
    ],
)  # fmt: skip
def test_bad_drop_tests_are_refused(args, kwargs, match):
    with pytest.raises(ValueError, match=match):
        fit_drops(*args, **kwargs)


def test_the_drop_fit_is_the_fit_of_the_drops_alone_with_its_kappa_curve():
    """The unmeasured curve points change nothing: estimates, intervals, chi2 and the
    per-drop arrays equal those of fit() on the drops as bounces; the curve is the fitted
    law, its band holds it and meets fitted_low/high at the drops' speeds."""
    from spinimpact import Body, MeasuredBounces, fit

    h1 = rebound_heights(noise=2e-3, seed=4)
    res = fit_drops(H0, h1, sigma_before=1e-3, sigma_after=2e-3, restitution="power")
    v1 = np.sqrt(2 * G * h1)
    s = np.hypot(G * 2e-3 / v1, (v1 / V0) * G * 1e-3 / V0)
    zeros = np.zeros_like(V0)
    plain = fit(MeasuredBounces(zeros, -V0, zeros, after_vy=v1, sigma_after_vx=1.0,
                                sigma_after_vy=s, sigma_after_omega=1.0),
                Body.solid_sphere(mass=1.0, radius=1.0), restitution="power",
                fixed={"mu": 0.0})  # fmt: skip
    for name in ("estimate", "interval_low", "interval_high", "fitted", "fitted_low",
                 "fitted_high", "sigma", "observed"):  # fmt: skip
        np.testing.assert_allclose(getattr(res, name), getattr(plain, name), rtol=1e-7,
                                   atol=1e-12, equal_nan=True, err_msg=name)  # fmt: skip
    assert (res.chi2, res.dof, res.n_bounces) == pytest.approx((plain.chi2, plain.dof, 10))
    assert res.fixed == {} and "mu" not in repr(res) and res.model.startswith("drop tests")
    np.testing.assert_allclose(res.kappa, v1 / V0)
    np.testing.assert_allclose(res.sigma_kappa, s / V0)
    ref = np.exp(np.mean(np.log(V0)))
    k_ref, exponent = res.estimate
    np.testing.assert_allclose(res.curve_kappa, k_ref * (res.curve_speed / ref) ** exponent)
    assert res.curve_speed.min() < V0.min() and res.curve_speed.max() > V0.max()
    assert np.all(res.curve_kappa_low <= res.curve_kappa + 1e-12)
    assert np.all(res.curve_kappa_high >= res.curve_kappa - 1e-12)
    assert np.all(res.curve_kappa_high - res.curve_kappa_low > 0)
    low = np.interp(V0, res.curve_speed, res.curve_kappa_low)
    np.testing.assert_allclose(low, res.fitted_low[:, 1] / V0, rtol=2e-3)


@pytest.mark.parametrize(
    "before, after, kwargs, message",
    [
        ([1.0], [0.6], {}, "too few drops: 1 drop(s) for 1 free parameter(s) (kappa); need at "
         "least 2"),
        ([1.0, 0.5], [0.6, 0.3], {"restitution": "power"}, "too few drops: 2 drop(s) for 2 "
         "free parameter(s) (kappa_ref, exponent); need at least 3"),
        ([], [], {}, "no drops given: the drop and rebound heights are empty"),
    ],
)  # fmt: skip
def test_too_few_drops_are_counted_in_drops(before, after, kwargs, message):
    """The drops are counted as drops (not as the bounces of the curve drawn with them)."""
    with pytest.raises(ValueError) as err:
        fit_drops(before, after, **kwargs)
    assert str(err.value) == message


def test_identical_drops_without_sigmas_are_refused_not_given_a_zero_width_interval():
    """Six identical drops: the scatter is 0, so no uncertainty can be estimated from it
    (it used to give kappa = 0.8 +- 0 [0.8, 0.8] and AIC = -inf)."""
    with pytest.raises(ValueError, match="the 6 drops show no scatter") as err:
        fit_drops([1.0] * 6, [0.64] * 6)
    assert "sigma_before and sigma_after" in str(err.value)
    res = fit_drops([1.0] * 6, [0.64] * 6, sigma_before=0.002, sigma_after=0.002)
    assert res["kappa"].estimate == pytest.approx(0.8, abs=1e-9)
    assert res["kappa"].high - res["kappa"].low > 1e-3 and np.isfinite(res.aic)
