"""Balls and grounds for :func:`spinimpact.flight`, with the sources of their numbers.

A :class:`Ball` is a sphere (mass, radius, radius of gyration) with its aerodynamic
coefficients; a :class:`Ground` is a level surface with its Coulomb friction ``mu``,
restitution ``kappa`` and rolling resistance. :data:`BALLS` and :data:`GROUNDS` hold the
presets; docs/flight.md names where each number comes from and which are assumptions (most
surface numbers are: they vary from court to court and with the ball's speed and spin).

Examples
--------
>>> ball = BALLS["tennis"]
>>> ball.mass, ball.radius
(0.0577, 0.0335)
>>> round(ball.body.zeta, 3)   # a thick rubber shell: between the thin shell's 2.5 and 3.5
2.781
>>> GROUNDS["hard"].mu
0.7
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, replace

import numpy as np

from .._validation import check, scalar
from .body import Body, accept_as_body, check_sphere

__all__ = ["Ball", "Ground", "Wall", "BALLS", "GROUNDS", "thick_shell_gyration", "ball",
           "ground"]  # fmt: skip


def thick_shell_gyration(radius: float, wall: float) -> float:
    """Radius of gyration of a uniform spherical shell of outer ``radius`` and ``wall``
    thickness (m): ``rho^2 = (2/5) (R^5 - r^5)/(R^3 - r^3)``, ``r = R - wall``."""
    inner = radius - wall
    return math.sqrt(0.4 * (radius**5 - inner**5) / (radius**3 - inner**3))


def _nonnegative(name: str, value: float) -> float:
    x = scalar(name, value)
    check(name, np.asarray(x), lambda a: a >= 0, ">= 0")
    return x


@accept_as_body
@dataclass(frozen=True, eq=False)
class Ball:
    """A ball: a sphere with aerodynamic coefficients (:mod:`spinimpact.core.aero`).

    Parameters
    ----------
    name : str
    mass, radius, gyration : float
        kg, m, m (``J = m rho^2``); ``gyration`` at most a thin shell's ``sqrt(2/3)
        radius``, the largest any sphere has.
    drag_coefficient : float
        ``C_D >= 0`` (constant).
    lift_slope, lift_max : float
        The lift law ``C_L = S/(1/lift_slope + S/lift_max)``, ``S = R |omega|/|v|``
        (``lift_max = inf``: linear); Stepanek's tennis fit is ``1`` and ``0.5``.
    spin_decay : float
        ``C_M >= 0``: the air's torque is ``C_M S`` times ``rho A R v^2 / 2``.
    """

    name: str
    mass: float
    radius: float
    gyration: float
    drag_coefficient: float
    lift_slope: float = 1.0
    lift_max: float = 0.5
    spin_decay: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")
        body = Body(mass=self.mass, radius=self.radius, gyration=self.gyration, name=self.name)
        check_sphere(body)
        for k in ("mass", "radius", "gyration"):
            object.__setattr__(self, k, scalar(k, getattr(body, k)))
        for k in ("drag_coefficient", "lift_slope", "spin_decay"):
            object.__setattr__(self, k, _nonnegative(k, getattr(self, k)))
        lift_max = self.lift_max
        if isinstance(lift_max, bool) or not isinstance(lift_max, numbers.Real):
            raise TypeError(f"lift_max must be a real number, got {lift_max!r}")
        if not float(lift_max) > 0:
            raise ValueError(f"lift_max must be > 0 (inf: a linear law), got {lift_max!r}")
        object.__setattr__(self, "lift_max", float(lift_max))

    @property
    def body(self) -> Body:
        """The ball as a :class:`~spinimpact.Body` (for :func:`~spinimpact.solve_sphere`)."""
        return Body(mass=self.mass, radius=self.radius, gyration=self.gyration, name=self.name)

    def replace(self, **changes: object) -> Ball:
        """A copy with some numbers changed (``ball.replace(drag_coefficient=0.0)``)."""
        return replace(self, **changes)  # type: ignore[arg-type]

    def to_dict(self) -> dict[str, object]:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


@dataclass(frozen=True, eq=False)
class Ground:
    """A level ground: ``mu >= 0``, ``kappa`` in ``[0, 1]``, and the coefficient of rolling
    resistance ``rolling >= 0`` (a rolling ball slows at ``rolling * g``)."""

    name: str
    mu: float
    kappa: float
    rolling: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")
        object.__setattr__(self, "mu", scalar("mu", self.mu))
        object.__setattr__(self, "kappa", scalar("kappa", self.kappa))
        object.__setattr__(self, "rolling", _nonnegative("rolling", self.rolling))

    def replace(self, **changes: object) -> Ground:
        """A copy with some numbers changed."""
        return replace(self, **changes)  # type: ignore[arg-type]

    def to_dict(self) -> dict[str, object]:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


@dataclass(frozen=True, eq=False)
class Wall:
    """A vertical wall across the ball's way: the plane ``dot(h, p) = distance`` (m), ``h`` the
    horizontal heading ``direction`` (degrees, counter-clockwise seen from above, 0: ``+x``),
    facing the launch point, with its own ``mu`` and ``kappa``."""

    distance: float
    direction: float = 0.0
    mu: float = 0.5
    kappa: float = 0.7
    name: str = "wall"

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {self.name!r}")
        object.__setattr__(self, "distance", scalar("distance", self.distance))
        object.__setattr__(self, "direction", scalar("direction", self.direction))
        object.__setattr__(self, "mu", scalar("mu", self.mu))
        object.__setattr__(self, "kappa", scalar("kappa", self.kappa))

    @property
    def normal(self) -> np.ndarray:
        """Unit normal of the wall towards the launch point, ``-h``."""
        d = math.radians(self.direction)
        return np.array([-math.cos(d), 0.0, math.sin(d)])

    def to_dict(self) -> dict[str, object]:
        return {k: getattr(self, k) for k in self.__dataclass_fields__}


_TENNIS_R = 0.0335
_GOLF_R = 0.04267 / 2
_SOCCER_R = 0.69 / (2 * math.pi)

#: Ball presets (sources and assumptions: docs/flight.md).
BALLS: dict[str, Ball] = {
    "tennis": Ball("tennis", 0.0577, _TENNIS_R, thick_shell_gyration(_TENNIS_R, 0.006),
                   drag_coefficient=0.507, lift_slope=1.0, lift_max=0.5, spin_decay=0.019),
    "table-tennis": Ball("table-tennis", 0.0027, 0.020, 0.020 * math.sqrt(2 / 3),
                         drag_coefficient=0.50, lift_slope=1.0, lift_max=0.5, spin_decay=0.019),
    "golf": Ball("golf", 0.04593, _GOLF_R, _GOLF_R * math.sqrt(0.4), drag_coefficient=0.25,
                 lift_slope=2.5, lift_max=0.4, spin_decay=0.019),
    "soccer": Ball("soccer", 0.430, _SOCCER_R, _SOCCER_R * math.sqrt(2 / 3),
                   drag_coefficient=0.25, lift_slope=1.0, lift_max=0.5, spin_decay=0.019),
}  # fmt: skip

#: Ground presets (sources and assumptions: docs/flight.md).
GROUNDS: dict[str, Ground] = {
    "hard": Ground("hard", mu=0.7, kappa=0.75, rolling=0.05),
    "clay": Ground("clay", mu=0.82, kappa=0.75, rolling=0.08),
    "grass": Ground("grass", mu=0.55, kappa=0.70, rolling=0.06),
    "table": Ground("table", mu=0.25, kappa=math.sqrt(0.23 / 0.30), rolling=0.01),
    "green": Ground("green", mu=0.4, kappa=0.4, rolling=(6 * 0.3048) ** 2 / (2 * 9.80665 * 3.048)),
    "pitch": Ground("pitch", mu=0.6, kappa=math.sqrt(0.8 / 2.0), rolling=0.06),
}


def _named(kind: str, table: dict, value: object) -> object:
    if isinstance(value, str):
        if value not in table:
            raise ValueError(f"{kind} must be one of {', '.join(table)}; got {value!r}")
        return table[value]
    return value


def ball(value: Ball | str) -> Ball:
    """A :class:`Ball`, or the preset of that name."""
    out = _named("ball", BALLS, value)
    if not isinstance(out, Ball):
        raise TypeError(f"ball must be a Ball or one of {', '.join(BALLS)}; got {value!r}")
    return out


def ground(value: Ground | str) -> Ground:
    """A :class:`Ground`, or the preset of that name."""
    out = _named("ground", GROUNDS, value)
    if not isinstance(out, Ground):
        raise TypeError(f"ground must be a Ground or one of {', '.join(GROUNDS)}; got {value!r}")
    return out
