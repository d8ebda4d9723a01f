"""A toy impact problem, declared as any user would declare one: a point mass bouncing off
a plane with restitution ``e`` (``v+ = -e v-``). Tests register it (the ``toy`` fixture of
tests/conftest.py) to show that a declaration alone gets solve, batch, sweep, fit and
command-line options, with no other change to the package."""

from dataclasses import dataclass

import numpy as np

from spinimpact import Input, Problem
from spinimpact.model.result import Result, freeze


@dataclass(frozen=True, eq=False)
class ToyImpact(Result):
    """The toy's result: the normal velocity before and after (m/s) and a regime."""

    speed_before: np.ndarray
    speed_after: np.ndarray
    regime: np.ndarray


def solve_toy(columns, tangential=None):
    """The toy's solver: named input columns in, a ToyImpact out, vectorized over rows."""
    v = columns["speed"]
    if (v >= 0).any():
        raise ValueError(f"speed must be < 0, got {float(v[np.argmax(v >= 0)])!r}")
    return ToyImpact(speed_before=freeze(v), speed_after=freeze(-columns["e"] * v),
                     regime=freeze(np.full(v.shape, "bounce")))  # fmt: skip


TOY = Problem(
    "toy",
    "a point mass bouncing off a plane",
    (
        Input("speed", "m/s", "normal velocity before (< 0)"),
        Input("e", "1", "coefficient of restitution", 0.5, rule="kappa", fittable=True),
    ),
    solve_toy,
    ToyImpact,
    marks=("speed",),
    units={"speed_before": "m/s", "speed_after": "m/s"},
    example={"speed": -2.0},
)
