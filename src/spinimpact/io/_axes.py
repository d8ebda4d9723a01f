"""The axes of a sweep: each input fixed, on an evenly spaced grid, or uniform random."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["INPUTS", "Axis", "parse_axis"]

#: The inputs a sweep varies (SI units): vx, vy in m/s, omega in rad/s, mu and kappa.
INPUTS = ("vx", "vy", "omega", "mu", "kappa")


@dataclass(frozen=True)
class Axis:
    """One input of a sweep: ``fixed`` at ``lo``, an evenly spaced ``grid`` of
    ``num`` values on ``[lo, hi]``, or ``uniform`` random on ``[lo, hi)`` (SI units)."""

    name: str
    kind: str
    lo: float
    hi: float = math.nan
    num: int = 1

    def values(self) -> np.ndarray:
        """The grid's values (or the single fixed value)."""
        return (
            np.linspace(self.lo, self.hi, self.num) if self.kind == "grid" else np.array([self.lo])
        )


def parse_axis(name: str, text: str | float) -> Axis:
    """An :class:`Axis` from its text.

    Parameters
    ----------
    name : str
        One of :data:`INPUTS`.
    text : str or float
        ``"3"`` (fixed), ``"-5:5:101"`` (grid: start, stop, number of points) or
        ``"uniform:-5:5"`` (random).

    Raises
    ------
    ValueError
        For an unknown ``name`` or text of none of the three forms.

    Examples
    --------
    >>> parse_axis("vx", "-5:5:101")
    Axis(name='vx', kind='grid', lo=-5.0, hi=5.0, num=101)
    """
    if name not in INPUTS:
        raise ValueError(f"sweep inputs are {', '.join(INPUTS)}; got {name!r}")
    parts = str(text).split(":")
    try:
        if len(parts) == 1:
            return Axis(name, "fixed", float(parts[0]))
        if len(parts) == 3 and parts[0] == "uniform":
            lo, hi = float(parts[1]), float(parts[2])
            if not lo < hi:
                raise ValueError
            return Axis(name, "uniform", lo, hi)
        if len(parts) == 3:
            num = int(parts[2])
            if num < 1:
                raise ValueError
            return Axis(name, "grid", float(parts[0]), float(parts[1]), num)
    except ValueError:
        pass
    raise ValueError(
        f"{name} must be a number, START:STOP:NUM (a grid) or uniform:LOW:HIGH, got {text!r}"
    )
