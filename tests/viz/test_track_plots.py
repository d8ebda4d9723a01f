"""Figures of track fits: what they draw, and what they refuse."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact.model.track import as_track
from spinimpact.model.track_arc import fit_arc
from spinimpact.viz.track import plot_prediction, plot_track


def test_a_flight_is_drawn_in_side_and_top_views_beside_its_residuals():
    t = np.linspace(0.0, 0.3, 30)
    p = np.stack([5 * t, 0 * t, 1 + 2 * t - 9.80665 * t**2 / 2], 1)
    p[10, 2] += 0.04  # an outlier, drawn as a cross
    f = fit_arc(as_track(t, p, name="arc"), air_density=0.0, drag_coefficient=0.5, sigma=0.001)
    fig = plot_track(f)
    side, top, res = fig.axes
    assert side.get_ylabel() == "$z$ (m)" and top.get_ylabel() == "$y$ (m)"
    assert res.get_ylabel() == "measured $-$ fitted (mm)"
    labels = side.get_legend_handles_labels()[1]
    assert labels == ["measured", "outliers set aside", "fitted"]
    assert "arc: one flight" in side.get_title()


def test_wrong_results_are_refused():
    with pytest.raises(TypeError, match="fit must be a BounceFit or an ArcFit"):
        plot_track({"mu": 0.2})
    with pytest.raises(TypeError, match="pred must be a Prediction"):
        plot_prediction(None)
