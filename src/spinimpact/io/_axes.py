"""The axes of a sweep: each input fixed, on an evenly spaced grid, or uniform random."""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = [
    "INPUTS",
    "KINDS",
    "NAMES",
    "Axis",
    "axis_names",
    "parse_axis",
    "positive_int",
    "uniform_stream",
]

#: The inputs a sweep varies (SI units): vx, vy in m/s, omega in rad/s, mu and kappa.
INPUTS = ("vx", "vy", "omega", "mu", "kappa")
#: The names of the paper's, the planar and the sphere sweeps' axes: :data:`INPUTS`, then a
#: sphere's ``vz`` (m/s) and spin ``wx, wy, wz`` (rad/s) (problem ``sphere``).
#: A name's place here numbers its random stream, so new names go at the end. Any numeric
#: input of a registered problem may be an axis too (:func:`axis_names`,
#: :mod:`~spinimpact.io.problem_sweep`); its stream is numbered by its name.
NAMES = (*INPUTS, "vz", "wx", "wy", "wz")
#: The kinds of axis.
KINDS = ("fixed", "grid", "uniform")


def axis_names() -> tuple[str, ...]:
    """Every name an axis may have: :data:`NAMES`, then each numeric input of the registered
    problems (:func:`spinimpact.problems`) not among them, in registration order."""
    from ..model.registry import problems

    extra = (i.name for p in problems() for i in p.inputs if not i.text)
    return tuple(dict.fromkeys((*NAMES, *extra)))


def _stream(name: str) -> int:
    """The number of ``name``'s random stream: its place in :data:`NAMES`, else a number
    made of its name's bytes (at least 256, so it differs from every place)."""
    if name in NAMES:
        return NAMES.index(name)
    return int.from_bytes(b"\x01" + name.encode(), "big")


def _real(name: str, value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError(f"{name} must be a real number, got {value!r}")
    return float(value)


@dataclass(frozen=True)
class Axis:
    """One input of a sweep: ``fixed`` at ``lo``, an evenly spaced ``grid`` of
    ``num`` values on ``[lo, hi]``, or ``uniform`` random on ``[lo, hi)`` (SI units).

    Parameters
    ----------
    name : str
        The input, one of :func:`axis_names`; a sweep takes the axis only under this name.
    kind : {"fixed", "grid", "uniform"}
    lo, hi : float
        The value (``fixed``; ``hi`` unused), or the ends (finite; ``lo < hi`` for
        ``uniform``).
    num : int
        Number of grid points, ``>= 1``; ``1`` for the other kinds.

    Raises
    ------
    TypeError
        For a name or kind that is not a string, ends that are not real numbers, or a
        ``num`` that is not an integer (``2.5``, ``True``).
    ValueError
        For an unknown name or kind, ends that are not finite, ``lo >= hi`` for a
        uniform axis, ``num < 1``, or ``num != 1`` for an axis that is not a grid.

    Examples
    --------
    >>> Axis("vx", "grid", -5.0, 5.0, 3).take([0, 1, 2])
    array([-5.,  0.,  5.])
    >>> Axis("vx", "grid", -5.0, 5.0, 0)
    Traceback (most recent call last):
    ...
    ValueError: vx: a grid's num must be an integer >= 1, got 0
    """

    name: str
    kind: str
    lo: float
    hi: float = math.nan
    num: int = 1

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or (
            self.name not in NAMES and self.name not in axis_names()
        ):
            names = ", ".join(axis_names())
            raise ValueError(f"an axis's name must be one of {names}, got {self.name!r}")
        if not isinstance(self.kind, str) or self.kind not in KINDS:
            raise ValueError(
                f"{self.name}: an axis's kind must be one of {', '.join(KINDS)}, got {self.kind!r}"
            )
        lo = _real(f"{self.name}: lo", self.lo)
        hi = _real(f"{self.name}: hi", self.hi)
        for x in [lo] if self.kind == "fixed" else [lo, hi]:
            if not math.isfinite(x):
                raise ValueError(f"{self.name} must be finite, got {x!r}")
        if self.kind == "uniform" and not lo < hi:
            raise ValueError(f"{self.name}: uniform:LOW:HIGH needs LOW < HIGH, got {lo!r}, {hi!r}")
        num = self.num
        if isinstance(num, bool) or not isinstance(num, numbers.Integral):
            raise TypeError(f"{self.name}: num must be an integer, got {num!r}")
        if self.kind == "grid" and num < 1:
            raise ValueError(f"{self.name}: a grid's num must be an integer >= 1, got {num!r}")
        if self.kind != "grid" and num != 1:
            raise ValueError(f"{self.name}: num is a grid's number of points; a {self.kind} "
                             f"axis has 1, got {num!r}")  # fmt: skip
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)
        object.__setattr__(self, "num", int(num))

    def take(self, index: np.ndarray) -> np.ndarray:
        """The grid's values at the points ``index`` (integers in ``[0, num)``).

        Equal to ``numpy.linspace(lo, hi, num)[index]`` bit for bit (the same
        operations: ``i*step + lo``, the last point ``hi``) without building the grid, so
        the memory of a chunk does not grow with the number of grid points.
        """
        index = np.asarray(index)
        if self.kind != "grid":
            return np.full(index.shape, self.lo)
        if self.num == 1:
            return np.full(index.shape, 0.0 * (self.hi - self.lo) + self.lo)
        step = (self.hi - self.lo) / (self.num - 1)
        if step == 0:  # linspace's route when the step underflows
            out = index / (self.num - 1) * (self.hi - self.lo) + self.lo
        else:
            out = index * step + self.lo
        out[index == self.num - 1] = self.hi
        return out

    def values(self) -> np.ndarray:
        """The grid's values (or the single fixed value); the whole grid in memory."""
        return (
            np.linspace(self.lo, self.hi, self.num) if self.kind == "grid" else np.array([self.lo])
        )


def positive_int(name: str, value: Any, extra: str = "") -> int:
    """``value`` as an int: a whole number >= 1 (not a bool), else an error naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be a positive integer{extra}, got {value!r}")
    if value < 1:
        raise ValueError(f"{name} must be a positive integer{extra}, got {value!r}")
    return int(value)


def uniform_stream(seed: int, name: str, start: int, n: int, lo: float, hi: float) -> np.ndarray:
    """Points ``start`` to ``start + n`` of input ``name``'s random stream, uniform on
    ``[lo, hi)``: the stream is advanced to ``start`` (each value takes one 64-bit draw),
    so the numbers do not depend on how the points are cut into chunks."""
    bits = np.random.PCG64(np.random.SeedSequence([seed, _stream(name)]))
    bits.advance(start)
    return np.random.Generator(bits).uniform(lo, hi, n)


def parse_axis(name: str, text: str | float) -> Axis:
    """An :class:`Axis` from its text.

    Parameters
    ----------
    name : str
        One of :func:`axis_names`.
    text : str or float
        ``"3"`` (fixed), ``"-5:5:101"`` or ``"grid:-5:5:101"`` (grid: start, stop, number
        of points) or ``"uniform:-5:5"`` (random).

    Raises
    ------
    ValueError
        For an unknown ``name``, text of none of the three forms, or numbers an
        :class:`Axis` refuses (not finite, ``LOW >= HIGH``, ``NUM < 1``).

    Examples
    --------
    >>> parse_axis("vx", "-5:5:101")
    Axis(name='vx', kind='grid', lo=-5.0, hi=5.0, num=101)
    """
    if name not in NAMES and name not in axis_names():
        raise ValueError(f"sweep inputs are {', '.join(axis_names())}; got {name!r}")
    parts = str(text).split(":")
    if len(parts) == 4 and parts[0] == "grid":
        parts = parts[1:]
    try:
        if len(parts) == 1:
            spec: tuple = ("fixed", float(parts[0]))
        elif len(parts) == 3 and parts[0] == "uniform":
            spec = ("uniform", float(parts[1]), float(parts[2]))
        elif len(parts) == 3:
            spec = ("grid", float(parts[0]), float(parts[1]), int(parts[2]))
        else:
            spec = ()
    except ValueError:
        spec = ()
    if spec:
        return Axis(name, *spec)  # its own message for what the numbers break
    raise ValueError(
        f"{name} must be a number, START:STOP:NUM (a grid; grid:START:STOP:NUM alike) or "
        f"uniform:LOW:HIGH, got {text!r}"
    )
