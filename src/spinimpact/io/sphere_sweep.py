"""Sweeps of one sphere in 3D on one plane surface: the older entry point, kept as an alias.

:class:`~spinimpact.io.problem_sweep.ProblemSweep` sweeps every registered problem, a
sphere in 3D (``problem="sphere"``) included: the sphere as ``body=``, the incidence,
``mu`` and ``kappa`` as axes, the surface's normal and velocity held fixed (``fixed=``).
:class:`SphereSweep` builds that sweep and warns once that it is deprecated;
:func:`sphere_fields` and :data:`SPHERE_INPUTS` stay for the code that names them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..model.body import Body
from ..model.sphere3d import Surface
from ._deprecated import OldSweep, warn_deprecated
from .problem_sweep import problem_fields

__all__ = ["SphereSweep", "sphere_fields"]

_NEW = 'spinimpact.io.problem_sweep.ProblemSweep(problem="sphere", body=..., axes=..., fixed=...)'


def __getattr__(name: str) -> Any:
    if name == "SPHERE_INPUTS":  # the axes of a sphere's sweep
        warn_deprecated("SPHERE_INPUTS", "the inputs of spinimpact.problem('sphere')")
        return ("vx", "vy", "vz", "wx", "wy", "wz", "mu", "kappa")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def sphere_fields() -> tuple[str, ...]:
    """Deprecated: the fields of a sphere's sweep are ``problem_fields("sphere", body=Body)``
    (:func:`~spinimpact.io.problem_sweep.problem_fields`), which this returns.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", DeprecationWarning)
    ...     "grips" in sphere_fields() and "zeta" not in sphere_fields()
    True
    """
    warn_deprecated("sphere_fields", 'spinimpact.io.problem_sweep.problem_fields("sphere")')
    return problem_fields("sphere", body=Body)


class SphereSweep(OldSweep):
    """Deprecated: a sphere's sweep is a :class:`~spinimpact.io.problem_sweep.ProblemSweep`.

    ``SphereSweep(body, axes, samples=None, seed=0, chunk_size=100_000, surface=None)``
    warns once per process and returns ``ProblemSweep(problem="sphere", body=body,
    axes=axes, fixed=...)``, the surface's normal and velocity held fixed: the same
    columns, fields, regimes and numbers.

    Parameters
    ----------
    body : Body
        One sphere (scalar mass, radius and gyration).
    axes : dict
        ``name -> Axis`` (or an axis's text) for ``vx, vy, vz`` (m/s), ``wx, wy, wz``
        (rad/s), ``mu, kappa``.
    samples, seed, chunk_size
        As for :class:`~spinimpact.io.problem_sweep.ProblemSweep`.
    surface : Surface, optional
        One plane; by default ``y = 0`` at rest. It holds its normal normalised, and that
        is what the sweep is given: a sweep of the normal as typed
        (``fixed={"normal_x": ...}``) can differ from it in the last bit.

    Raises
    ------
    TypeError
        For a body that is not a :class:`~spinimpact.Body` or a surface that is not a
        :class:`~spinimpact.Surface`, and as ``ProblemSweep``.
    ValueError
        For an array of surfaces, and as ``ProblemSweep`` (a contact point that does not
        approach the surface somewhere in the sweep, in the same words as before).
    """

    replacement = _NEW

    @staticmethod
    def settings(body: Body, surface: Surface | None = None) -> dict[str, Any]:
        """Problem ``sphere``, the surface's normal and velocity held fixed."""
        if not isinstance(body, Body):
            raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
        surface = Surface() if surface is None else surface
        if not isinstance(surface, Surface):
            raise TypeError(f"surface must be a spinimpact.Surface, got {type(surface).__name__}")
        if np.shape(surface.normal) != (3,) or np.shape(surface.velocity) != (3,):
            raise ValueError("a sweep needs a single surface, not an array of surfaces")
        fixed = {f"normal_{k}": float(x) for k, x in zip("xyz", surface.normal, strict=True)}
        fixed |= {f"surface_velocity_{k}": float(x)
                  for k, x in zip("xyz", surface.velocity, strict=True)}  # fmt: skip
        return {"problem": "sphere", "fixed": fixed}
