"""The figure of a Hertz-Mindlin impact in time."""

import numpy as np
import pytest

from spinimpact import Body
from spinimpact.dynamics import HertzContact, Mindlin, simulate
from spinimpact.viz.tangential import _stick_spans, plot_tangential


def test_figure_has_its_panels_and_shades_the_stick_phase():
    ball = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
    law = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)
    sim = simulate(ball, 1.334, -3.665, 0.0, mu=0.092, contact=law, tangential=Mindlin())
    fig = plot_tangential(sim)
    assert len(fig.axes) == 4
    spans = _stick_spans(np.asarray(sim.t) * 1e6, np.asarray(sim.stuck))
    assert len(spans) == 1 and spans[0][0] < spans[0][1]
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert labels == ["normal $N$", "tangential $F$", r"$\pm\mu N$"]


def test_wrong_input():
    with pytest.raises(TypeError, match="TangentialSimulation"):
        plot_tangential("sim")
