"""Where the figures put their marks: one marker for events that fall on one point, and
round colour-bar ticks on both sides of a zero in the bar's middle."""

from __future__ import annotations

import numpy as np

__all__ = ["same_points", "round_ticks"]


def same_points(events: list, tol: float) -> list[list]:
    """``events`` (tuples starting with their position) grouped where their positions
    agree within ``tol``, each group in the given order: one marker for each group."""
    groups: list[list] = []
    for event in events:
        for group in groups:
            if abs(group[0][0] - event[0]) <= tol:
                group.append(event)
                break
        else:
            groups.append([event])
    return groups


def round_ticks(low: float, high: float) -> list[float]:
    """Round ticks for a bar from ``low < 0`` to ``high > 0`` with 0 in its middle: each
    half gets its own round step (1, 2, 2.5 or 5 times a power of ten), the ticks
    inside the bar only."""
    from matplotlib.ticker import MaxNLocator

    def half(a: float, b: float, bins: int) -> np.ndarray:
        ticks = MaxNLocator(nbins=bins, steps=[1, 2, 2.5, 5, 10]).tick_values(a, b)
        return ticks[(ticks >= a) & (ticks <= b)]

    below = half(low, 0.0, 4) if low < 0 else np.zeros(1)
    above = half(0.0, high, 2) if high > 0 else np.zeros(1)
    return sorted({float(t) for t in (*below, *above)})
