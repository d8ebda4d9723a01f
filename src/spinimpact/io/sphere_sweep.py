"""Sweeps of one sphere in 3D on one plane surface over incidences, in bounded memory.

A :class:`SphereSweep` is a :class:`~spinimpact.io.sweep.Sweep` whose body is a sphere
(a :class:`~spinimpact.Body`: solid sphere, spherical shell, or any radius of gyration)
on a fixed :class:`~spinimpact.Surface` (its normal and velocity), with axes
``vx, vy, vz`` (m/s), ``wx, wy, wz`` (rad/s), ``mu, kappa``.
:func:`~spinimpact.io.sweep.run_sweep` runs it as any sweep: chunk by chunk, to Parquet
or ``.npy`` files, folding regime fractions and histograms on the fly, locally or on Dask.

Each chunk is solved by :func:`~spinimpact.solve_sphere` at once, so the fields are the
:class:`~spinimpact.SphereImpact` columns of the same names (:func:`sphere_fields`), the
very numbers the function gives. ``regime`` is computed as its index into
:data:`spinimpact.core.REGIMES` (the paper sweep's regimes) and written as names (a
dictionary column in Parquet, text in CSV; in ``.npy`` files the index, the names in
``metadata.json`` with the body and the surface); ``grips`` as a flag. Random points
depend on the seed alone, as in every sweep.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, validated, whole
from ..model.body import Body
from ..model.sphere3d import SphereImpact, Surface, solve_sphere
from ._axes import positive_int
from ._fields import ALIASES, regime_codes
from .sweep import Sweep

__all__ = ["SPHERE_INPUTS", "SphereSweep", "sphere_fields"]

#: The inputs a sphere's sweep varies: the centre's velocity, the spin, mu and kappa.
SPHERE_INPUTS = ("vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa")
#: The surface's columns: fixed for the sweep (in its description), not fields.
_SURFACE = tuple(f"{v}_{c}" for v in ("normal", "surface_velocity") for c in "xyz")


@functools.cache
def sphere_fields() -> tuple[str, ...]:
    """The fields of a sphere's sweep: the result's columns that are not inputs.

    Returns
    -------
    tuple of str
        :meth:`SphereImpact.column_names <spinimpact.model.result.Result.column_names>`
        less the body's columns, ``mu, kappa``, the incidence and the surface.

    Examples
    --------
    >>> sphere_fields()[:4]
    ('after_vx', 'after_vy', 'after_vz', 'after_wx')
    >>> sphere_fields()[-3:]
    ('sidespin', 'gyrospin', 'grips')
    """
    inputs = {*Body.COLUMNS, "mu", "kappa", *_SURFACE, *(f"before_{n}" for n in SPHERE_INPUTS)}
    return tuple(n for n in SphereImpact.column_names() if n not in inputs)


@dataclass(frozen=True)
class SphereSweep(Sweep):
    """A sweep over the incidences of one sphere on one surface (see the module docstring).

    Parameters
    ----------
    body : Body
        One sphere (scalar mass, radius and gyration).
    axes : dict
        ``name -> Axis`` for each of ``vx, vy, vz`` (m/s), ``wx, wy, wz`` (rad/s),
        ``mu, kappa``.
    samples, seed
        As for :class:`~spinimpact.io.sweep.Sweep`.
    chunk_size : int
        Points evaluated at a time (default 100,000: a chunk solved whole holds about
        230 MB); memory is bounded by it.
    surface : Surface, optional
        One plane (a single normal and velocity); by default ``y = 0`` at rest.

    Raises
    ------
    TypeError
        For a body that is not a :class:`~spinimpact.Body`, a surface that is not a
        :class:`~spinimpact.Surface`, or a bad ``samples`` or ``chunk_size``.
    ValueError
        For an array of bodies or surfaces, a missing or extra axis, grid and random axes
        mixed, an axis value that is not finite (or ``mu < 0``, ``kappa`` outside
        ``[0, 1]``), or any point of the sweep whose contact point does not approach the
        surface.

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.io.sweep import parse_axis, run_sweep
    >>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
    >>> spec = dict(vx="-2:2:5", vy="-1", vz="0", wx="0", wy="0", wz="0", mu="0.5", kappa="0.8")
    >>> sweep = SphereSweep(ball, {n: parse_axis(n, v) for n, v in spec.items()})
    >>> result = run_sweep(sweep)
    >>> result.points
    5
    >>> {name: share for name, share in result.regime_fractions.items() if share}
    {'no-slip': 0.2, 'stick-compression': 0.4, 'stick-restitution': 0.4}
    """

    #: Points per chunk: solve_sphere holds about 2.3 kB a point (230 MB a chunk).
    chunk_size: int = 100_000
    surface: Surface = field(default_factory=Surface)

    def __post_init__(self) -> None:
        object.__setattr__(self, "seed", whole("seed", self.seed, 0))
        b = self.body
        if not isinstance(b, Body):
            raise TypeError(f"body must be a spinimpact.Body, got {type(b).__name__}")
        if any(np.ndim(getattr(b, n)) for n in ("mass", "radius", "gyration")):
            raise ValueError("a sweep needs a single body, not an array of bodies")
        s = self.surface
        if not isinstance(s, Surface):
            raise TypeError(f"surface must be a spinimpact.Surface, got {type(s).__name__}")
        if np.shape(s.normal) != (3,) or np.shape(s.velocity) != (3,):
            raise ValueError("a sweep needs a single surface, not an array of surfaces")
        self._check_axes()
        positive_int("chunk_size", self.chunk_size)
        for a in self.axes.values():  # the contact point's approach is checked below
            for x in [a.lo] if a.kind == "fixed" else [a.lo, a.hi]:
                validated(a.name, x) if a.name in ("mu", "kappa") else as_real_array(a.name, x)
        self._check_approach()
        object.__setattr__(self, "_body", {})

    inputs = SPHERE_INPUTS
    regimes = core.REGIMES
    #: The fields written when none are named: the state after the impact and the regime.
    default_fields = (*(f"after_{n}" for n in SPHERE_INPUTS[:6]), "regime")

    def _check_approach(self) -> None:
        """The contact's normal velocity ``(v - V_s) . n`` is affine in ``vx, vy, vz``: its
        largest value over the sweep is at a corner, and must be < 0."""
        n = np.asarray(self.surface.normal, float)
        corner = {}
        for i, name in enumerate(("vx", "vy", "vz")):
            a = self.axes[name]
            ends = (a.lo,) if a.kind == "fixed" else (a.lo, a.hi)
            corner[name] = max(ends, key=lambda x, k=n[i]: x * k)
        worst = float(np.dot([*corner.values()], n) - np.dot(self.surface.velocity, n))
        if not worst < 0:
            at = ", ".join(f"{k} = {v:g}" for k, v in corner.items())
            raise ValueError(
                "the contact point must approach the surface at every point of the sweep, but "
                f"its normal velocity (v - surface velocity) . normal reaches {worst:.6g} m/s "
                f"at {at}; narrow the range of vx, vy or vz"
            )

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for: itself (:func:`sphere_fields`) or an alias's field."""
        fields = sphere_fields()
        if name in fields:
            return name
        if ALIASES.get(name) in fields:
            return ALIASES[name]
        aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items())
        raise ValueError(f"{role} must be among {', '.join(fields)} (or {aliases}); got {name!r}")

    def column_dtype(self, name: str) -> np.dtype:
        """``int8`` regime codes, ``bool`` for ``grips``, else ``float64``."""
        if name not in self.inputs and self.field_name(name, "column") == "grips":
            return np.dtype(bool)
        return super().column_dtype(name)

    def description(self) -> dict[str, Any]:
        """The regimes' names, the body, the axes and the surface."""
        s = self.surface
        surface = {"normal": s.normal.tolist(), "velocity": s.velocity.tolist()}
        return super().description() | {"surface": surface}

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """As :meth:`Sweep.evaluate <spinimpact.io.sweep.Sweep.evaluate>`, the fields named
        by :func:`sphere_fields` (or aliases)."""
        c = self.chunk(k)
        out: dict[str, Any] = dict(c)
        wanted = {name: self.field_name(name) for name in fields}
        if wanted:
            v = np.stack(np.broadcast_arrays(c["vx"], c["vy"], c["vz"]), axis=-1)
            w = np.stack(np.broadcast_arrays(c["wx"], c["wy"], c["wz"]), axis=-1)
            imp = solve_sphere(self.body, v, w, mu=c["mu"], kappa=c["kappa"], surface=self.surface)
            columns = imp.columns()
            columns["regime"] = regime_codes(columns["regime"], core.REGIMES)
            for name, f in wanted.items():
                out[name] = columns[f]
        n = self.chunk_length(k)
        return {name: np.broadcast_to(value, (n,)) for name, value in out.items()}
