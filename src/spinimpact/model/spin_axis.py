"""Spin about a named axis: ``topspin``, ``backspin``, ``sidespin`` and their combinations.

A combination ``topspin+sidespin`` is the axis halfway between the two named axes (equal
parts); ``topspin:0.8+sidespin:0.2`` weighs them: the axis is the normalised sum
``0.8 a_topspin + 0.2 a_sidespin`` of the named unit axes, and the rate (rpm) is the
whole spin's, about that axis. A weight may be negative (``sidespin:-1``: the other way);
weights that cancel (``topspin+backspin``) are refused. The named axes themselves depend
on the surface's normal ``n`` and the direction of travel ``e`` along it: topspin is about
``n x e`` (a ball rolling forward along ``e``), backspin the opposite, sidespin about ``n``
(counter-clockwise seen from above). ``docs/conventions.md`` states them for every command.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

__all__ = ["AXES", "parse_spin_axis", "combine_axes"]

#: The named spin axes.
AXES = ("topspin", "backspin", "sidespin")


def parse_spin_axis(text: str, name: str = "spin_axis") -> tuple[tuple[str, float | None], ...]:
    """The named parts of a spin axis ``text``: ``((name, weight or None), ...)``.

    Parameters
    ----------
    text : str
        ``topspin``, ``backspin``, ``sidespin``, or several joined by ``+``, each
        optionally weighted ``name:weight`` (e.g. ``topspin:0.8+sidespin:0.2``).
    name : str
        The parameter named in errors.

    Returns
    -------
    tuple of (str, float or None)
        Each axis named, once, with its weight (``None``: not given, 1).

    Raises
    ------
    ValueError
        For an unknown name, a name given twice, or a weight that is not a finite number.
    """
    parts = []
    for piece in str(text).lower().replace(" ", "").split("+"):
        axis, _, weight = piece.partition(":")
        if axis not in AXES:
            raise ValueError(
                f"{name} must be topspin, backspin, sidespin, a combination such as "
                f"topspin+sidespin or topspin:0.8+sidespin:0.2, or a direction x,y,z; "
                f"got {text!r}"
            )
        if any(axis == seen for seen, _ in parts):
            raise ValueError(f"{name} names {axis} twice in {text!r}")
        w = None
        if weight:
            try:
                w = float(weight)
            except ValueError:
                w = math.nan
            if not math.isfinite(w):
                raise ValueError(f"{name}: the weight of {axis} must be a finite number, "
                                 f"got {weight!r} in {text!r}")  # fmt: skip
        parts.append((axis, w))
    return tuple(parts)


def combine_axes(parts: tuple[tuple[str, float | None], ...],
                 directions: Mapping[str, Any], name: str = "spin_axis") -> np.ndarray:  # fmt: skip
    """The unit spin axis of ``parts`` (from :func:`parse_spin_axis`).

    Parameters
    ----------
    parts : tuple of (str, float or None)
    directions : mapping
        Each named axis's unit vector (arrays of shape ``(..., 3)``).
    name : str
        The parameter named in errors.

    Returns
    -------
    ndarray, shape (..., 3)
        One name without a weight: its direction as given (bit for bit); otherwise the
        normalised weighted sum.

    Raises
    ------
    ValueError
        Where the weights cancel (no direction left), or a lone weight is zero.
    """
    if len(parts) == 1 and parts[0][1] is None:
        return np.asarray(directions[parts[0][0]], dtype=float)
    total = sum((1.0 if w is None else w) * np.asarray(directions[a], float) for a, w in parts)
    length = np.sqrt(np.sum(total * total, axis=-1))
    text = "+".join(a if w is None else f"{a}:{w:g}" for a, w in parts)
    if not np.all(length > 1e-12):
        raise ValueError(f"{name} {text} has no direction: its weighted axes cancel")
    return total / length[..., None]
