"""The figure of impacts under micro-slip (MindlinDeresiewicz) in time."""

import re

import matplotlib
import numpy as np
import pytest

from spinimpact import Body, MindlinDeresiewicz, Walton, solve
from spinimpact.viz.micro_slip import MOST_CURVES, plot_micro_slip

from tests.viz.layout import ATTACHED, legend_gaps, legends
from tests.viz.test_figure_text import _problems, _untypeset

matplotlib.use("Agg")

BALL = Body.solid_sphere(mass=2.6e-4, radius=2.5e-3)
LAW = MindlinDeresiewicz(poisson_ratio=0.23, springs=64, steps=512)


def test_the_curves_are_the_laws_impacts():
    """Each impact's slip curve ends at the law's slip after the impact, the friction
    ratio stays within Coulomb's bound, and the stuck core covers the whole contact at
    some time near normal incidence and never once the contact slides throughout."""
    vx = np.array([0.14, 0.67, 3.0])
    fig = plot_micro_slip(LAW, BALL, vx, -3.9, 0.0, mu=0.092, kappa=0.98)
    ratio, core, slip = fig.axes
    imp = solve(BALL, vx, -3.9, 0.0, mu=0.092, kappa=0.98, tangential=LAW)
    ends = [line.get_ydata()[-1] for line in slip.lines]
    np.testing.assert_allclose(ends, imp.slip_after / 3.9, rtol=1e-12)
    for line in ratio.lines[: vx.size]:
        y = np.asarray(line.get_ydata(), dtype=float)
        assert np.nanmax(np.abs(y)) <= 1.0 + 1e-9
    cores = [np.asarray(line.get_ydata()) for line in core.lines]
    assert cores[0].max() > 0.99 and cores[2].max() == 0.0
    labels = [t.get_text() for t in legend_of(fig).get_texts()]
    assert labels[0].endswith("stick") and labels[2].endswith("slip")


def legend_of(fig):
    (legend,) = legends(fig)
    return legend


@pytest.mark.slow
def test_the_legend_covers_no_curve_and_the_title_names_the_law_in_words():
    """The legend once sat on the stuck-core curves, and the title was the law's repr
    (``MindlinDeresiewicz(poisson_ratio=0.23)``) followed by untypeset symbols."""
    for law in (LAW, MindlinDeresiewicz(stiffness_ratio=0.8, springs=64, steps=512)):
        fig = plot_micro_slip(law, BALL, [0.14, 0.28, 0.67, 1.4], -3.9, 0.0, mu=0.092,
                              kappa=0.98)  # fmt: skip
        assert _problems(fig) == []
        assert _untypeset(fig) == []
        title = fig.get_suptitle()
        assert not re.search(r"\w\(\w+=", title), title
        assert "micro-slip" in title
        assert legend_gaps(fig)[0] < ATTACHED  # beside a panel, not floating
    one = plot_micro_slip(LAW, BALL, 0.2, -1.0, mu=0.3, kappa=1.0)
    assert r"Poisson's ratio $\nu$ = 0.23" in one.get_suptitle()


def test_labels_and_wrong_input():
    fig = plot_micro_slip(LAW, BALL, 0.2, -1.0, mu=0.3, kappa=1.0, labels=["one"])
    assert [t.get_text() for t in legend_of(fig).get_texts()] == ["one"]
    for args, kwargs, error, match in [
        ((Walton(0.3), BALL, 1.0, -1.0), {}, TypeError, "MindlinDeresiewicz"),
        ((LAW, "ball", 1.0, -1.0), {}, TypeError, "one spinimpact.Body"),
        ((LAW, BALL, 1.0, -1.0), {"mu": [0.1, 0.2]}, TypeError, "mu must be one number"),
        ((LAW, BALL, np.ones(MOST_CURVES + 1), -1.0), {}, ValueError, "at most 12"),
        ((LAW, BALL, 1.0, 1.0), {}, ValueError, "vy"),
        ((LAW, BALL, 1.0, -1.0), {"labels": ["a", "b"]}, ValueError, "one entry per impact"),
    ]:
        options = {"mu": 0.3, "kappa": 0.9} | kwargs
        with pytest.raises(error, match=match):
            plot_micro_slip(*args, **options)
