"""spinimpact.viz.fit: the measured-against-fitted figure and the corner plot draw the
fit's own numbers."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, solve
from spinimpact.model.fit import fit
from spinimpact.model.fit_data import MeasuredBounces
from spinimpact.viz.fit import plot_corner, plot_fit

pytest.importorskip("matplotlib")

BALL = Body.solid_sphere(mass=0.058, radius=0.033)


def data(n=20, same_speed=False, omega_measured=True):
    rng = np.random.default_rng(3)
    vy = np.full(n, -4.0) if same_speed else -rng.uniform(2, 6, n)
    theta = np.radians(np.linspace(10, 75, n))
    speed = 4.0 if same_speed else -vy / np.cos(theta)
    vx, vy = speed * np.sin(theta), -speed * np.cos(theta)
    after = solve(BALL, vx, vy, 0.0, mu=0.3, kappa=lambda v: 0.8 * (v / 3) ** -0.1).after
    om = after.omega + rng.normal(0, 3, n) if omega_measured else None
    sig = (0.05, 0.05, 3.0) if omega_measured else (0.05, 0.05, 1.0)
    return MeasuredBounces(vx, vy, np.zeros(n), after.vx + rng.normal(0, 0.05, n),
                   after.vy + rng.normal(0, 0.05, n), om, *sig)  # fmt: skip


def test_one_column_per_measured_quantity_with_the_fits_numbers():
    res = fit(data(), BALL, restitution="power")
    fig = plot_fit(res)
    assert len(fig.axes) == 6
    top = fig.axes[0]
    errorbars = [c for c in top.containers]
    ys = np.concatenate([np.asarray(c.lines[0].get_ydata()) for c in errorbars])
    np.testing.assert_allclose(np.sort(ys), np.sort(res.observed[:, 0]))
    assert "\\mu" in fig._suptitle.get_text()
    assert np.all(res.fitted_low <= res.fitted + 1e-12)
    assert np.all(res.fitted + 1e-12 >= res.fitted_low)
    assert np.all(res.fitted_high >= res.fitted - 1e-12)


def test_one_speed_draws_a_curve_and_a_missing_quantity_no_column():
    res = fit(data(same_speed=True, omega_measured=False), BALL)
    fig = plot_fit(res)
    assert len(fig.axes) == 4  # vx+ and vy+, each with its residuals
    fitted = [ln for ln in fig.axes[0].lines if ln.get_label() == "fitted"][0]
    assert np.all(np.diff(fitted.get_xdata()) > 0)  # a curve over the angle


def test_corner_plot_of_three_parameters():
    res = fit(data(), BALL, restitution="power")
    fig = plot_corner(res)
    drawn = [ax for ax in fig.axes if ax.axison]
    assert len(drawn) == 6  # 3 profiles and 3 pairs
    profile = fig.axes[0].lines[0]
    values, rise = res.profiles["mu"]
    np.testing.assert_allclose(profile.get_xdata(), values)
    np.testing.assert_allclose(profile.get_ydata(), rise)
    with pytest.raises(ValueError, match="at least two"):
        plot_corner(fit(data(), BALL, fixed={"kappa": 0.8}))


@pytest.mark.slow
def test_corner_plot_of_a_friction_the_data_only_bound():
    d = data(same_speed=True)
    steep = d.select(d.incidence_angle_deg < 40.0)  # these bounces all stick
    res = fit(steep, BALL, free_gyration=True)
    assert res["mu"].one_sided
    fig = plot_corner(res)
    shown = fig.axes[0].lines[0].get_xdata()
    assert shown.max() <= 3.0 * max(res["mu"].low, res["mu"].estimate)  # not out to 1e6
    assert any("flat" in t.get_text() for t in fig.axes[0].texts)
    assert res["mu"].low in [ln.get_xdata()[0] for ln in fig.axes[3].lines]  # dashed bound


def test_drop_tests_are_drawn_over_the_impact_speed_with_the_kappa_curve():
    from spinimpact.model.fit_drops import fit_drops

    res = fit_drops([2.0, 1.0, 0.5, 0.25], [1.25, 0.66, 0.35, 0.185], sigma_before=0.002,
                    sigma_after=0.005, restitution="power")  # fmt: skip
    fig = plot_fit(res)
    top, bottom = fig.axes[:2]
    assert len(fig.axes) == 2 and bottom.get_xlabel() == "impact speed (m/s)"
    (bars,) = top.containers
    np.testing.assert_allclose(bars.lines[0].get_xdata(), res.impact_speed)
    np.testing.assert_allclose(bars.lines[0].get_ydata(), res.rebound_speed / res.impact_speed)
    fitted = [ln for ln in top.lines if ln.get_label() == "fitted"][0]
    np.testing.assert_allclose(fitted.get_xdata(), res.curve_speed)
    np.testing.assert_allclose(fitted.get_ydata(), res.curve_kappa)
    np.testing.assert_allclose(bottom.lines[-1].get_xdata(), res.impact_speed)
    labels = {t.get_text() for t in fig.legends[0].get_texts()}
    assert labels == {"band", "fitted", "measured"}  # no slid / stuck: nothing slides
    title = fig._suptitle.get_text()
    assert title.startswith("drop tests") and "\\mu" not in title
    xmin, xmax = top.get_xlim()
    assert xmin > 1.0 and xmax < 8.0  # the impact speeds (2.2 to 6.3 m/s), not 0 +- 0.04


def test_corner_panels_show_the_intervals_and_share_each_column():
    """Diagonal panels about the interval (a rise up to about 10, not out to the far
    points the profile probed), each column one x axis, each row's ellipses over the
    values of its diagonal panel, every ellipse inside its panel."""
    res = fit(data(), BALL, restitution="power")
    fig = plot_corner(res)
    p = len(res.names)
    axes = np.array(fig.axes).reshape(p, p)
    for i in range(p):
        lo, hi = axes[i, i].get_xlim()
        est, low, high = res.estimate[i], res.interval_low[i], res.interval_high[i]
        assert lo < low < est < high < hi
        assert hi - lo < 4.0 * (high - low)  # about the interval
        assert axes[i, i].get_ylim()[1] == pytest.approx(2.6 * res.threshold)
        assert axes[i, i].get_ylim()[1] < 10.5
        for k in range(i + 1, p):
            assert axes[k, i].get_xlim() == (lo, hi)  # the column's x axis
        for j in range(i):
            assert axes[i, j].get_ylim() == (lo, hi)  # the row's parameter, same values
            ring = [ln for ln in axes[i, j].lines if ln.get_xdata().size > 100][0]
            x0, x1 = axes[i, j].get_xlim()
            assert x0 < ring.get_xdata().min() and ring.get_xdata().max() < x1
            assert lo < ring.get_ydata().min() and ring.get_ydata().max() < hi


def test_corner_panel_of_a_bound_only_friction_shows_the_bound_and_the_estimate():
    d = data(same_speed=True)
    res = fit(d.select(d.incidence_angle_deg < 40.0), BALL, free_gyration=True)
    lo, hi = plot_corner(res).axes[0].get_xlim()
    assert res["mu"].one_sided
    assert lo < res["mu"].low < res["mu"].estimate < hi < 3.0 * res["mu"].estimate
