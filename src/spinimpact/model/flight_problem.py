"""The ball's flight as a registered problem: launches batched, swept and tabled like impacts.

:func:`~spinimpact.flight` flies a ball from its launch (speed, elevation, heading, height,
spin) through the air, bounces it exactly on a ground and rolls it to rest. Declared here
as problem ``flight`` (:mod:`spinimpact.model.registry`), its launch and ball inputs get
what every problem gets: ``spinimpact batch`` of a file of launches (one row a ball),
``spinimpact sweep --problem flight`` over any launch input, ``spinimpact solve --problem
flight`` and ``spinimpact problems flight``, each input with its unit, default and rule.

The spin is given as two signed rates in rpm, ``topspin_rpm`` (about the horizontal axis
across the heading; negative is backspin) and ``sidespin_rpm`` (about the vertical, counter-
clockwise seen from above), so that any mix of the two is a pair of numbers, as the
``flight`` command's ``--spin-axis topspin:0.8+sidespin:0.2`` is. Each row names its ball
and ground presets; rows of the same pair are flown together (one call of
:func:`~spinimpact.flight` per pair present). A row's result is the ball's summary
(:class:`FlightSummary`): its launch, where and how it came to rest, and its first bounce.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from . import problems as _built_in  # noqa: F401  (the impact problems are listed first)
from .flight import flight, launch
from .presets import BALLS, GROUNDS
from .registry import Input, Problem, register
from .result import Array, Result, freeze

__all__ = ["FLIGHT", "FlightSummary"]

#: The first bounce's columns a row reports (NaN, or empty text, for a ball that never
#: bounced).
FIRST_BOUNCE = ("time", "position_x", "position_z", "speed_before", "speed_after",
                "angle_before", "angle_after", "regime", "grips")  # fmt: skip
_TEXT = ("regime",)
_FLAG = ("grips",)


@dataclass(frozen=True, eq=False)
class FlightSummary(Result):
    """One row of a batch of flights: the launch, the end, and the first bounce, per ball.

    Attributes
    ----------
    launch_vx, launch_vy, launch_vz : m/s
        Launch velocity (``y`` up, ``x`` along heading 0).
    launch_wx, launch_wy, launch_wz : rad/s
        Launch spin.
    bounce_count : int
        Bounces of the ball.
    apex_height, apex_time : m, s
        Top of the first arc.
    flight_time : s
        Time of the first bounce (NaN if none).
    final_time : s
        Time the ball came to rest, or the stopping time.
    final_position_x, final_position_z : m
        Where it came to rest (or stopped) on the ground.
    stop : str
        ``rest``, ``time`` or ``bounces`` (as :class:`~spinimpact.model.flight_result.Flight`).
    bounce1_time ... bounce1_grips
        The first bounce (:attr:`Flight.bounces`): time (s), position (m), speeds (m/s) and
        angles above the ground (rad) before and after, regime, and whether the ball
        gripped.
    """

    launch_vx: Array
    launch_vy: Array
    launch_vz: Array
    launch_wx: Array
    launch_wy: Array
    launch_wz: Array
    bounce_count: Array
    apex_height: Array
    apex_time: Array
    flight_time: Array
    final_time: Array
    final_position_x: Array
    final_position_z: Array
    stop: Array
    bounce1_time: Array
    bounce1_position_x: Array
    bounce1_position_z: Array
    bounce1_speed_before: Array
    bounce1_speed_after: Array
    bounce1_angle_before: Array
    bounce1_angle_after: Array
    bounce1_regime: Array
    bounce1_grips: Array

    _shape_field = "final_time"


_FIELDS = tuple(f.name for f in fields(FlightSummary))


def _empty(name: str, n: int) -> np.ndarray:
    if name.endswith(_TEXT) or name == "stop":
        return np.full(n, "", dtype=object)
    if name.endswith(_FLAG):
        return np.zeros(n, dtype=bool)
    return np.full(n, np.nan)


def _vectors(c: dict[str, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Launch velocity (m/s) and spin (rad/s) of each row: the spin is ``topspin_rpm``
    about ``up x heading`` plus ``sidespin_rpm`` about ``up``."""
    velocity, top = launch(c["speed"], c["elevation_deg"], c["heading_deg"], 1.0, "topspin")
    _, side = launch(c["speed"], c["elevation_deg"], c["heading_deg"], 1.0, "sidespin")
    top_rpm, side_rpm = (
        np.asarray(c[k], dtype=float)[:, None] for k in ("topspin_rpm", "sidespin_rpm")
    )
    return velocity, top_rpm * top + side_rpm * side  # each of top, side: 1 rpm


def _solve_flight(c: dict[str, np.ndarray], tangential: Any = None) -> FlightSummary:
    n = len(c["speed"])
    velocity, spin = _vectors(c)
    height = np.asarray(c["launch_height"], dtype=float)
    out = {name: _empty(name, n) for name in _FIELDS}
    pairs = np.char.add(np.asarray(c["ball"], dtype=str), np.char.add("|", np.asarray(
        c["surface"], dtype=str)))  # fmt: skip
    for pair in np.unique(pairs):  # one flight per (ball, ground) pair present, not per row
        rows = np.flatnonzero(pairs == pair)
        ball, ground = str(pair).split("|")
        f = flight(ball, ground, velocity=velocity[rows], spin=spin[rows],
                   height=height[rows], tangential=tangential, path=False)  # fmt: skip
        columns = f.columns()
        for name in _FIELDS:
            if name in columns:
                out[name][rows] = np.asarray(columns[name])
    return FlightSummary(**{name: freeze(value) for name, value in out.items()})


_UNITS = {
    **dict.fromkeys(("launch_vx", "launch_vy", "launch_vz"), "m/s"),
    **dict.fromkeys(("launch_wx", "launch_wy", "launch_wz"), "rad/s"),
    "bounce_count": "1",
    **dict.fromkeys(("apex_height", "final_position_x", "final_position_z"), "m"),
    **dict.fromkeys(("apex_time", "flight_time", "final_time", "bounce1_time"), "s"),
    **dict.fromkeys(("bounce1_position_x", "bounce1_position_z"), "m"),
    **dict.fromkeys(("bounce1_speed_before", "bounce1_speed_after"), "m/s"),
    **dict.fromkeys(("bounce1_angle_before", "bounce1_angle_after"), "rad"),
}

FLIGHT = register(
    Problem(
        "flight",
        "a spinning ball launched through the air, bouncing on a ground until it rests",
        (
            Input("ball", None, "ball preset", "tennis", choices=tuple(BALLS)),
            Input(
                "surface",
                None,
                "ground preset (mu, kappa, rolling resistance)",
                "hard",
                choices=tuple(GROUNDS),
            ),  # fmt: skip
            Input("speed", "m/s", "launch speed", rule="speed"),
            Input(
                "elevation_deg",
                "deg",
                "launch angle above the horizontal (< 0: downwards)",
                rule="elevation_deg",
            ),  # fmt: skip
            Input(
                "heading_deg", "deg", "heading, counter-clockwise from +x seen from above", 0.0
            ),  # fmt: skip
            Input(
                "launch_height",
                "m",
                "launch height of the ball's centre",
                1.0,
                rule="launch_height",
            ),  # fmt: skip
            Input(
                "topspin_rpm",
                "rpm",
                "spin about the horizontal across the heading (< 0: backspin)",
                0.0,
            ),  # fmt: skip
            Input(
                "sidespin_rpm",
                "rpm",
                "spin about the vertical, counter-clockwise seen from above",
                0.0,
            ),  # fmt: skip
        ),
        _solve_flight,
        FlightSummary,
        marks=("elevation_deg",),
        tangential=True,
        units=_UNITS,
        may_be_infinite=(),
        may_be_nan=("flight_time", *(f"bounce1_{k}" for k in FIRST_BOUNCE)),
        example={
            "speed": 50.0,
            "elevation_deg": -6.0,
            "launch_height": 2.8,
            "topspin_rpm": 2000.0,
        },  # fmt: skip
        regimes=(),
    )
)
