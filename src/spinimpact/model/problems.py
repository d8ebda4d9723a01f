"""The built-in impact problems, each declared once (:mod:`spinimpact.model.registry`).

=========  =====================================================================  ==============
problem    what it solves                                                         solver
=========  =====================================================================  ==============
paper      a disk, ring, sphere, shell or spool on a plane (Lubarda 2010)         ``solve``
planar     a free planar body touching at an offset from its centre of mass       ``solve_planar``
pendulum   a rigid pendulum on a fixed pivot striking the surface                 ``solve_pendulum``
sphere     a sphere in 3D, any spin vector, on a fixed, moving or tilted plane    ``solve_sphere``
pair       two spheres in 3D                                                      ``solve_pair``
=========  =====================================================================  ==============

Every solver here is the package's own function, called once over all rows; the
declarations add nothing to the physics.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from typing import Any

import numpy as np

from ..core import REGIMES
from ..core import planar as planar_kernels
from ..core.planar import PLANAR_REGIMES
from .body import PRESETS, Body
from .impact import Impact, solve
from .pair import PairImpact, solve_pair
from .planar import LAWS, PendulumImpact, PlanarImpact, solve_pendulum, solve_planar
from .planar_body import Pendulum, PlanarBody
from .registry import Input, Problem, register
from .sphere3d import SphereImpact, Surface, solve_sphere

__all__ = ["PAPER", "PLANAR", "PENDULUM", "SPHERE", "PAIR", "SPHERE_PRESETS", "PROCESS_COLUMNS"]

#: The presets of :data:`~spinimpact.model.body.PRESETS` that are spheres.
SPHERE_PRESETS = ("solid-sphere", "spherical-shell")


def _surface() -> tuple[Input, ...]:
    return (
        Input("mu", "1", "Coulomb friction coefficient", 0.2, rule="mu", fittable=True),
        Input("kappa", "1", "coefficient of restitution", 0.8, rule="kappa", fittable=True),
    )


def _body(presets: tuple[str, ...], default: str, suffix: str = "", who: str = "") -> tuple:
    return (
        Input(
            f"body{suffix}",
            None,
            f"{who}body preset (or give gyration{suffix})",
            default,
            choices=presets,
        ),
        Input(f"mass{suffix}", "kg", f"{who}mass", 1.0, rule="mass"),
        Input(f"radius{suffix}", "m", f"{who}radius", 0.1, rule="radius"),
        Input(
            f"gyration{suffix}",
            "m",
            f"{who}radius of gyration about the centre (replaces the preset)",
            rule="gyration",
            optional=True,
            fittable=True,
        ),
    )


def _vector(prefix: str, unit: str, what: str, vector: str, suffix: str = "", default=None):
    return tuple(
        Input(
            f"{prefix}{c}{suffix}",
            unit,
            f"{what}, {c} component",
            None if default is None else default[k],
            vector=vector + suffix,
        )
        for k, c in enumerate("xyz")
    )


def _value(column: np.ndarray) -> Any:
    """A column that is one value broadcast to every row (a stride of 0: an input a sweep
    holds fixed, a default) as that value, else the column: a body or a surface of numbers
    is solved as one, as fast as one, with the same numbers."""
    if column.ndim == 1 and column.size and column.strides == (0,):
        return column[0] if column.dtype == object else float(column[0])
    return column


def _same(column: np.ndarray) -> bool:
    """Whether every row of a non-empty column holds the same value."""
    return column.strides == (0,) or bool((column == column[0]).all())


def _one_body(c: dict[str, np.ndarray], suffix: str = "") -> Body:
    """The rows' body: one preset for all (the common case, without a name per row), one
    radius of gyration for all, or each row's preset or radius of gyration."""
    gyration, names = c[f"gyration{suffix}"], c[f"body{suffix}"]
    mass, radius = c[f"mass{suffix}"], c[f"radius{suffix}"]
    if names.size and np.isnan(gyration).all() and _same(names):
        return Body.preset(str(names[0]), mass=_value(mass), radius=_value(radius))
    if np.ndim(_value(gyration)) == 0 and not np.isnan(gyration[0]):
        return Body(mass=_value(mass), radius=_value(radius), gyration=_value(gyration))
    preset = np.where(np.isnan(gyration), names, "")
    return Body.from_columns(mass=mass, radius=radius, preset=preset, gyration=gyration)


def _stack(c: dict[str, np.ndarray], *names: str) -> np.ndarray:
    return np.stack([c[n] for n in names], -1)


def _plane(c: dict[str, np.ndarray], *names: str) -> Any:
    """A surface's (or a contact's) vector from the columns ``names``: one vector where it
    is the same in every row, else one a row."""
    values = tuple(_value(c[n]) for n in names)
    return values if not any(np.ndim(v) for v in values) else _stack(c, *names)


def _ends(ranges: Mapping[str, tuple[float, float]], name: str) -> tuple[float, ...]:
    """The values ``name`` takes at the corners of a box of inputs: one if it is fixed."""
    lo, hi = ranges[name]
    return (lo,) if lo == hi else (lo, hi)


def _refuse_departure(
    what: str, worst: float, at: dict[str, float], narrow: str, arm: str = ""
) -> str:
    """The message of a box of inputs whose contact point does not approach everywhere."""
    where = ", ".join(f"{n} = {v:g}" for n, v in at.items())
    return (
        f"the contact point must approach the surface at every point of the sweep, but its "
        f"normal velocity {what} reaches {worst:.6g} m/s at {where}{arm}; narrow the range "
        f"of {narrow}"
    )


# -- the paper's bodies ------------------------------------------------------------------
def _solve_paper(c: dict[str, np.ndarray], tangential: Any = None) -> Impact:
    return solve(
        _one_body(c),
        c["vx"],
        c["vy"],
        c["omega"],
        mu=c["mu"],
        kappa=c["kappa"],
        tangential=tangential,
    )


PAPER = register(
    Problem(
        "paper",
        "a spinning disk, ring, sphere, shell or spool on a fixed rough plane (Lubarda 2010)",
        (
            Input("vx", "m/s", "centre velocity along the surface"),
            Input(
                "vy", "m/s", "centre velocity normal to the surface (< 0: approaching)", rule="vy"
            ),
            Input("omega", "rad/s", "spin, counter-clockwise positive"),
            *_surface(),
            *_body(tuple(PRESETS), "solid-sphere"),
        ),
        _solve_paper,
        Impact,
        tangential=True,
        may_be_nan=("tangential_restitution", "centre_tangential_restitution"),  # 0/0 at u = 0
        example={"vx": 3.0, "vy": -4.0, "omega": 10.0},
        regimes=REGIMES,
    )
)


# -- planar bodies and pendulums -----------------------------------------------------------
def _laws(c: dict[str, np.ndarray], solve_one) -> Any:
    """Solve each law's rows at once and put the columns back in row order."""
    law = c["law"]
    if law.size and _same(law):
        return solve_one(c, str(law[0]))
    used = [each for each in LAWS if (law == each).any()]
    if len(used) == 1:
        return solve_one(c, used[0])
    return _Merged(
        {
            each: (law == each, solve_one({k: v[law == each] for k, v in c.items()}, each))
            for each in used
        }
    )


class _Merged:
    """The columns of several results, each over some rows, as one result's ``columns()``."""

    def __init__(self, parts: dict[str, tuple[np.ndarray, Any]]) -> None:
        self.parts = parts

    def columns(self) -> dict[str, np.ndarray]:
        out: dict[str, np.ndarray] = {}
        n = next(iter(self.parts.values()))[0].size
        for rows, result in self.parts.values():
            for name, column in result.columns().items():
                column = np.asarray(column)
                if name not in out:
                    out[name] = np.empty(
                        n, dtype=column.dtype if column.dtype.kind in "fb" else object
                    )
                out[name][rows] = column
        return out


def _solve_planar(c: dict[str, np.ndarray], tangential: Any = None) -> Any:
    return _laws(
        c,
        lambda c, law: solve_planar(
            PlanarBody(*(_value(c[n]) for n in PlanarBody.COLUMNS)),
            c["vx"],
            c["vy"],
            c["omega"],
            mu=c["mu"],
            kappa=c["kappa"],
            law=law,
        ),
    )


def _solve_pendulum(c: dict[str, np.ndarray], tangential: Any = None) -> Any:
    return _laws(
        c,
        lambda c, law: solve_pendulum(
            Pendulum(*(_value(c[n]) for n in Pendulum.COLUMNS)),
            c["omega"],
            mu=c["mu"],
            kappa=c["kappa"],
            law=law,
        ),
    )


class _Columns:
    """Named columns as a result's ``columns()``."""

    def __init__(self, columns: dict[str, Any]) -> None:
        self._columns = columns

    def columns(self) -> dict[str, Any]:
        return self._columns


#: The columns of a planar body's or a pendulum's impact process alone, without its works
#: and energies: :func:`_planar_process` computes them about five times faster.
PROCESS_COLUMNS = (
    "before_vx",
    "before_vy",
    "after_vx",
    "after_vy",
    "after_omega",
    "slip_before",
    "slip_after",
    "normal_velocity_before",
    "normal_velocity_after",
    "regime",
    "tau0",
    "tau_star",
    "tau1",
    "tangential_impulse",
)


def _planar_process(c: dict[str, np.ndarray], tangential: Any = None) -> Any:
    """:data:`PROCESS_COLUMNS` by the steps of :func:`~spinimpact.solve_planar` (or
    :func:`~spinimpact.solve_pendulum`) without the works and energies: the same kernels on
    the same numbers (``regime`` as indices into :data:`PLANAR_REGIMES`; a column the same
    in every row may come back as one number)."""
    return _laws(c, _process_one)


def _process_one(c: dict[str, np.ndarray], law: str) -> _Columns:
    # a sweep's fixed inputs as numbers (the columns may come back as numbers: a sweep
    # broadcasts them), its varying ones as arrays
    c = {name: _value(column) for name, column in c.items()}
    omega = c["omega"]
    if "px" in c:  # a pendulum: its centre moves with omega
        body: Any = Pendulum(*(c[n] for n in Pendulum.COLUMNS))
        vx, vy = body.centre_velocity(omega)
    else:
        body = PlanarBody(*(c[n] for n in PlanarBody.COLUMNS))
        vx, vy = c["vx"], c["vy"]
    u, v = body.contact_velocity(vx, vy, omega)
    w = body.collision_matrix
    p = planar_kernels.planar_process(u, v, w.tt, w.tn, w.nn, c["mu"], c["kappa"],
                                      LAWS.index(law))  # fmt: skip
    after = body.apply_impulse(vx, vy, omega, p.friction_impulse, p.tau_end)
    values = (vx, vy, *after, u, p.slip_after, v, p.normal_after, np.asarray(p.regime, np.int8),
              p.tau_compression, p.tau_slip, p.tau_end, p.friction_impulse)  # fmt: skip
    return _Columns(dict(zip(PROCESS_COLUMNS, values, strict=True)))


def _planar_ranges(ranges: Mapping[str, tuple[float, float]]) -> str | None:
    """A free planar body's contact point approaches where ``vy + omega*rx < 0``: affine in
    each input, so its largest value over a box is at a corner."""
    corners = []
    for lever in _ends(ranges, "rx"):
        omega = max(_ends(ranges, "omega"), key=lambda w, k=lever: w * k)
        vy = ranges["vy"][1]
        corners.append((0.0 + vy + omega * lever, vy, omega, lever))
    worst, vy, omega, lever = max(corners, key=lambda c: c[0])
    if worst < 0:
        return None
    return _refuse_departure("vy + omega*rx", worst, {"vy": vy, "omega": omega}, "vy or omega",
                             f" (rx = {lever:.6g} m)")  # fmt: skip


def _pendulum_ranges(ranges: Mapping[str, tuple[float, float]]) -> str | None:
    """A pendulum's contact point approaches where ``omega*px < 0``."""
    corners = []
    for lever in _ends(ranges, "px"):
        omega = max(_ends(ranges, "omega"), key=lambda w, k=lever: w * k)
        corners.append((0.0 + omega * lever, omega, lever))
    worst, omega, lever = max(corners, key=lambda c: c[0])
    if worst < 0:
        return None
    return _refuse_departure("omega*px", worst, {"omega": omega}, "omega",
                             f" (px = {lever:.6g} m)")  # fmt: skip


_LAW = Input("law", None, "restitution law", "poisson", choices=tuple(LAWS))
_INERTIA = Input("inertia", "kg m^2", "moment of inertia about the centre of mass", rule="mass")

PLANAR = register(
    Problem(
        "planar",
        "a free planar body (rod, block, eccentric disk) touching at an offset r",
        (
            Input("mass", "kg", "mass", rule="mass"),
            _INERTIA,
            Input("rx", "m", "contact point from the centre of mass, along the surface"),
            Input("ry", "m", "contact point from the centre of mass, normal (< 0)"),
            Input("vx", "m/s", "centre velocity along the surface"),
            Input("vy", "m/s", "centre velocity normal to the surface"),
            Input("omega", "rad/s", "spin, counter-clockwise positive"),
            *_surface(),
            _LAW,
        ),
        _solve_planar,
        PlanarImpact,
        marks=("rx", "ry"),
        check_ranges=_planar_ranges,
        partial=(PROCESS_COLUMNS, _planar_process),
        example={
            "mass": 1.0,
            "inertia": 1 / 12,
            "rx": 0.4,
            "ry": -0.2,
            "vx": 1.0,
            "vy": -1.0,
            "omega": 0.0,
        },
        regimes=PLANAR_REGIMES,
    )
)

PENDULUM = register(
    Problem(
        "pendulum",
        "a rigid pendulum on a fixed pivot striking the surface",
        (
            Input("mass", "kg", "mass", rule="mass"),
            _INERTIA,
            Input("gx", "m", "centre of mass from the pivot, along the surface"),
            Input("gy", "m", "centre of mass from the pivot, normal"),
            Input("px", "m", "contact point from the pivot, along the surface"),
            Input("py", "m", "contact point from the pivot, normal (< 0)"),
            Input("omega", "rad/s", "angular velocity about the pivot"),
            *_surface(),
            _LAW,
        ),
        _solve_pendulum,
        PendulumImpact,
        marks=("gx", "gy", "px", "py"),
        check_ranges=_pendulum_ranges,
        partial=(PROCESS_COLUMNS, _planar_process),
        example={
            "mass": 1.0,
            "inertia": 1 / 3,
            "gx": 0.5,
            "gy": 0.0,
            "px": 1.0,
            "py": -0.1,
            "omega": -2.0,
        },
        regimes=PLANAR_REGIMES,
    )
)


# -- spheres in 3D -----------------------------------------------------------------------------
def _solve_sphere(c: dict[str, np.ndarray], tangential: Any = None) -> SphereImpact:
    plane = Surface(
        normal=_plane(c, "normal_x", "normal_y", "normal_z"),
        velocity=_plane(c, *(f"surface_velocity_{k}" for k in "xyz")),
    )
    return solve_sphere(
        _one_body(c),
        _stack(c, "vx", "vy", "vz"),
        _stack(c, "wx", "wy", "wz"),
        mu=c["mu"],
        kappa=c["kappa"],
        surface=plane,
        tangential=tangential,
    )


def _sphere_ranges(ranges: Mapping[str, tuple[float, float]]) -> str | None:
    """A sphere's contact point approaches where ``(v - V_s) . n < 0``: the sign of an
    expression affine in each of ``v``, ``V_s`` and ``n`` (the normal's length does not
    change it), so its largest value over a box is at a corner."""
    names = {k: [f"{p}{k}" for p in ("v", "normal_", "surface_velocity_")] for k in "xyz"}
    corners = []
    for normal in itertools.product(*(_ends(ranges, names[k][1]) for k in "xyz")):
        for moving in itertools.product(*(_ends(ranges, names[k][2]) for k in "xyz")):
            plane = Surface(normal=normal, velocity=moving)
            n = np.asarray(plane.normal, float)
            v = {f"v{k}": max(_ends(ranges, f"v{k}"), key=lambda x, a=n[i]: x * a)
                 for i, k in enumerate("xyz")}  # fmt: skip
            worst = float(np.dot([*v.values()], n) - np.dot(plane.velocity, n))
            corners.append((worst, v))
    worst, v = max(corners, key=lambda c: c[0])
    if worst < 0:
        return None
    return _refuse_departure("(v - surface velocity) . normal", worst, v, "vx, vy or vz")


_VELOCITY = tuple(
    Input(f"v{k}", "m/s", f"centre velocity, {k} component", vector="velocity") for k in "xyz"
)
_SPIN = tuple(Input(f"w{k}", "rad/s", f"spin vector, {k} component", vector="spin") for k in "xyz")

SPHERE = register(
    Problem(
        "sphere",
        "a spinning sphere in 3D on a fixed, moving or tilted plane",
        (
            *_VELOCITY,
            *_SPIN,
            *_surface(),
            *_body(SPHERE_PRESETS, "solid-sphere"),
            *_vector(
                "normal_", "1", "the surface's outward normal", "normal", default=(0.0, 1.0, 0.0)
            ),
            *_vector(
                "surface_velocity_",
                "m/s",
                "the surface's velocity",
                "surface_velocity",
                default=(0.0, 0.0, 0.0),
            ),
        ),
        _solve_sphere,
        SphereImpact,
        marks=("vz", "wx", "wy", "wz"),
        tangential=True,
        may_be_nan=("topspin", "gyrospin"),
        check_ranges=_sphere_ranges,
        example={"vx": 2.0, "vy": -3.0, "vz": 0.0, "wx": 0.0, "wy": 0.0, "wz": 30.0},
        regimes=REGIMES,
    )
)


def _solve_pair(c: dict[str, np.ndarray], tangential: Any = None) -> PairImpact:
    return solve_pair(
        _one_body(c),
        _one_body(c, "2"),
        velocity1=_stack(c, "vx", "vy", "vz"),
        spin1=_stack(c, "wx", "wy", "wz"),
        velocity2=_stack(c, "vx2", "vy2", "vz2"),
        spin2=_stack(c, "wx2", "wy2", "wz2"),
        normal=_plane(c, "normal_x", "normal_y", "normal_z"),
        mu=c["mu"],
        kappa=c["kappa"],
    )


PAIR = register(
    Problem(
        "pair",
        "two spinning spheres colliding in 3D",
        (
            *(
                Input(i.name, i.unit, f"ball 1's {i.description}", vector=f"{i.vector}1")
                for i in _VELOCITY + _SPIN
            ),
            *(
                Input(f"{i.name}2", i.unit, f"ball 2's {i.description}", vector=f"{i.vector}2")
                for i in _VELOCITY + _SPIN
            ),
            *_vector(
                "normal_", "1", "the contact normal, from ball 2's centre to ball 1's", "normal"
            ),
            *_surface(),
            *_body(SPHERE_PRESETS, "solid-sphere", who="ball 1's "),
            *_body(SPHERE_PRESETS, "solid-sphere", "2", who="ball 2's "),
        ),
        _solve_pair,
        PairImpact,
        marks=tuple(f"{i.name}2" for i in _VELOCITY + _SPIN),
        echoes={
            f"before{k}_{i.name}": f"{i.name}{s}"
            for i in _VELOCITY + _SPIN
            for k, s in (("1", ""), ("2", "2"))
        },
        may_be_nan=("angle_between_paths",),
        example={
            "vx": 1.0,
            "vy": 0.0,
            "vz": 0.0,
            "wx": 0.0,
            "wy": 20.0,
            "wz": 0.0,
            "vx2": 0.0,
            "vy2": 0.0,
            "vz2": 0.0,
            "wx2": 0.0,
            "wy2": 0.0,
            "wz2": 0.0,
            "normal_x": -1.0,
            "normal_y": 0.0,
            "normal_z": 0.0,
        },
        regimes=REGIMES,
    )
)
