"""What the figure functions refuse: a wrong type is a TypeError naming the parameter and
what it should be (not an AttributeError from deep inside), and an incidence map is drawn
for any body size the solver accepts (the maps are dimensionless)."""

import warnings

import numpy as np
import pytest

from spinimpact import Body, ConstantRestitution, solve
from spinimpact.viz import maps
from spinimpact.viz.plots import (
    paper_figure,
    plot_energy,
    plot_history,
    plot_map,
    plot_routh,
    plot_simulation,
)

pytest.importorskip("matplotlib")

DISK = Body.solid_disk(mass=1.0, radius=0.1)


@pytest.mark.parametrize("plot", [plot_history, plot_routh, plot_energy])
@pytest.mark.parametrize("value", [None, 5, "impact"])
def test_impact_figures_name_their_parameter(plot, value):
    with pytest.raises(TypeError, match=r"imp must be a spinimpact\.Impact.*got"):
        plot(value)


def test_plot_simulation_names_its_parameter():
    for value in (None, solve(DISK, 1.0, -1.0, 0.0, mu=0.2, kappa=0.5)):
        with pytest.raises(TypeError, match=r"sim must be a Simulation.*simulate"):
            plot_simulation(value)


@pytest.mark.parametrize("body", [None, "solid-disk", 1.0])
def test_plot_map_names_the_body(body):
    with pytest.raises(TypeError, match="body must be a spinimpact.Body"):
        plot_map(body, mu=0.2, kappa=0.5)


@pytest.mark.parametrize("kappa, error", [
    (ConstantRestitution(0.5), TypeError),
    ([0.5, 0.6], ValueError),
    ("0.5", TypeError),
])  # fmt: skip
def test_plot_map_takes_one_number_for_kappa(kappa, error):
    with pytest.raises(error, match="kappa must be"):
        plot_map(DISK, mu=0.2, kappa=kappa)
    with pytest.raises(error, match="kappa must be"):
        maps.map_fields(DISK, mu=0.2, kappa=kappa, n=4)


def test_plot_map_takes_one_number_for_mu():
    with pytest.raises(ValueError, match="mu must be a single number"):
        plot_map(DISK, mu=[0.2, 0.3], kappa=0.5)
    with pytest.raises(ValueError, match="mu must be >= 0"):
        plot_map(DISK, mu=-1.0, kappa=0.5)


@pytest.mark.parametrize("name", [["fig2"], None, 2])
def test_paper_figure_needs_a_name(name):
    with pytest.raises(TypeError, match=r"name must be one of fig2.*got"):
        paper_figure(name)


@pytest.mark.parametrize("radius", [1e-49, 1e-50, 1e40])
def test_a_map_of_any_size_is_the_same_map(radius):
    """The maps are functions of vx/|vy|, R omega/|vy|, zeta, mu and kappa alone: a body
    of 1e-49 m gives the 0.1 m body's fields (it used to overflow casting its spins)."""
    tiny = Body.solid_disk(mass=1.0, radius=radius)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, _, got = maps.map_fields(tiny, mu=0.3, kappa=0.5, extent=3.0, n=21)
    _, _, want = maps.map_fields(DISK, mu=0.3, kappa=0.5, extent=3.0, n=21)
    for name in ("regime", "outcome", "dissipated_fraction", "impulse_ratio", "slip_after",
                 "after_vx"):  # fmt: skip
        np.testing.assert_array_equal(got[name], want[name], err_msg=name)
    # the spin after, rad/s, of this body: its sign draws the line omega+ = 0
    np.testing.assert_array_equal(np.sign(got["after_omega"]), np.sign(want["after_omega"]))
