"""Any rigid body in 3D as a registered problem: rows of bodies batched, swept and fitted.

Declared here as problem ``rigid`` (:mod:`spinimpact.model.registry`): a file whose columns
hold a body's inertia tensor (``ixx, iyy, izz``, optionally ``ixy, ixz, iyz``; world frame,
about the centre of mass) and the contact point's offset ``rx, ry, rz`` beside the centre's
velocity and spin is solved by :func:`~spinimpact.solve_rigid`, row by row in one call per
law, on the plane the normal and surface velocity columns give (``y = 0`` at rest by
default).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import problems as _built_in
from .registry import Input, Problem, register
from .rigid import RigidBody, RigidImpact, solve_rigid
from .sphere3d import Surface

__all__ = ["RIGID"]

_TENSOR = (("ixx", 0, 0), ("iyy", 1, 1), ("izz", 2, 2), ("ixy", 0, 1), ("ixz", 0, 2),
           ("iyz", 1, 2))  # fmt: skip


def _inertia(c: dict[str, np.ndarray]) -> np.ndarray:
    n = np.broadcast_shapes(*(np.shape(c[name]) for name, _, _ in _TENSOR))
    tensor = np.zeros((*n, 3, 3))
    for name, i, j in _TENSOR:
        tensor[..., i, j] = tensor[..., j, i] = c[name]
    return tensor


def _solve_rigid(c: dict[str, np.ndarray], tangential: Any = None) -> Any:
    return _built_in._laws(c, _solve_law)


def _solve_law(c: dict[str, np.ndarray], law: str) -> RigidImpact:
    plane = Surface(
        normal=_built_in._plane(c, "normal_x", "normal_y", "normal_z"),
        velocity=_built_in._plane(c, *(f"surface_velocity_{k}" for k in "xyz")),
    )
    return solve_rigid(
        RigidBody(c["mass"], _inertia(c), _built_in._stack(c, "rx", "ry", "rz")),
        _built_in._stack(c, "vx", "vy", "vz"),
        _built_in._stack(c, "wx", "wy", "wz"),
        mu=c["mu"],
        kappa=c["kappa"],
        law=law,
        surface=plane,
    )


RIGID = register(
    Problem(
        "rigid",
        "any rigid body in 3D touching a plane at one point (a die on a corner, a coin)",
        (
            Input("mass", "kg", "mass", rule="mass"),
            *(
                Input(
                    name,
                    "kg m^2",
                    f"inertia tensor about the centre of mass, {name[1:]}",
                    None if i == j else 0.0,
                )
                for name, i, j in _TENSOR
            ),  # fmt: skip
            *(
                Input(
                    f"r{k}",
                    "m",
                    f"contact point from the centre of mass, {k} component",
                    vector="offset",
                )
                for k in "xyz"
            ),  # fmt: skip
            *_built_in._VELOCITY,
            *_built_in._SPIN,
            *_built_in._surface(),
            *_built_in._vector(
                "normal_", "1", "the surface's outward normal", "normal", default=(0.0, 1.0, 0.0)
            ),  # fmt: skip
            *_built_in._vector(
                "surface_velocity_",
                "m/s",
                "the surface's velocity",
                "surface_velocity",
                default=(0.0, 0.0, 0.0),
            ),  # fmt: skip
            _built_in._LAW,
        ),
        _solve_rigid,
        RigidImpact,
        marks=("ixx", "rz"),
        example={
            "mass": 1.0,
            "ixx": 1 / 6,
            "iyy": 1 / 6,
            "izz": 1 / 6,
            "rx": 0.3,
            "ry": -0.4,
            "rz": 0.1,
            "vx": 1.0,
            "vy": -2.0,
            "vz": 0.5,
            "wx": 0.0,
            "wy": 3.0,
            "wz": 0.0,
        },  # fmt: skip
        may_be_nan=("stop_impulse",),
        units={
            **{f"impulse_{k}": "N s" for k in "xyz"},
            **{f"contact_{w}_{k}": "m/s" for w in ("before", "after") for k in "xyz"},
            "normal_impulse": "N s",
            "compression_impulse": "N s",
            "stop_impulse": "N s",
            **{
                f"work_{phase}_{part}": "J"
                for phase in ("compression", "restitution")
                for part in ("normal", "tangential")
            },  # fmt: skip
        },  # fmt: skip
        regimes=("slide", "slide-stick", "slide-reslide", "stick"),
    )
)
