"""Geometry checks of drawn figures shared by the figure tests: where a legend sits, and
which markers hide one another."""

import math

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg

#: A legend further than this from every panel (its tick labels and axis labels
#: included) floats detached, inches: about one line of small text.
ATTACHED = 0.12
#: Markers whose centres are closer than this hide one another, inches (a 7-point
#: marker is about 0.1 inch across).
APART = 0.04


def draw(fig):
    """Draw ``fig`` without a display at 40 dpi (the layout in inches does not depend on
    it; drawing is faster); return its renderer."""
    if fig.canvas is None or not hasattr(fig.canvas, "get_renderer"):
        FigureCanvasAgg(fig)
    fig.set_dpi(40)
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def legends(fig):
    """Every legend of ``fig``: the figure's and each axes'."""
    return [*fig.legends, *(ax.get_legend() for ax in fig.axes if ax.get_legend())]


def legend_gaps(fig):
    """For each legend of ``fig``, inches from its frame to the nearest panel with axes
    drawn (its ticks, tick labels and axis labels included; 0 where they meet)."""
    renderer = draw(fig)
    found = legends(fig)
    boxes = [legend.get_window_extent(renderer) for legend in found]
    for legend in found:  # a panel's extent would include its own legend
        legend.set_visible(False)
    try:
        panels = [ax.get_tightbbox(renderer) for ax in fig.axes if ax.axison]
    finally:
        for legend in found:
            legend.set_visible(True)
    gaps = []
    for box in boxes:
        near = min(
            math.hypot(
                max(p.x0 - box.x1, box.x0 - p.x1, 0.0), max(p.y0 - box.y1, box.y0 - p.y1, 0.0)
            )
            for p in panels
        )
        gaps.append(near / fig.dpi)
    return gaps


def stacked_markers(ax):
    """Pairs of legend labels of the single-point markers of ``ax`` drawn on one another
    (centres closer than :data:`APART`)."""
    draw(ax.figure)
    marks = []
    for line in ax.get_lines():
        x, y = (np.asarray(v, float) for v in line.get_data())
        if line.get_marker() in ("None", "", " ", None) or x.size != 1 or not line.get_visible():
            continue
        centre = ax.transData.transform((x[0], y[0])) / ax.figure.dpi
        marks.append((line.get_label(), centre))
    return [
        (a, b)
        for i, (a, pa) in enumerate(marks)
        for b, pb in marks[i + 1 :]
        if math.dist(pa, pb) < APART
    ]
