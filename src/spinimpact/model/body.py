"""Rigid bodies: mass, contact radius and radius of gyration (paper section 2)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._validation import MAX_ZETA, as_real_array, check, validated
from .result import BodyColumns

__all__ = ["Body", "PRESETS", "SHELL_GYRATION", "as_body", "check_sphere"]

#: Squared radius of gyration over squared radius, ``rho^2/R^2``, of the presets.
PRESETS: dict[str, float] = {
    "solid-disk": 1.0 / 2.0,  # zeta = 3
    "ring": 1.0,  # zeta = 2
    "solid-sphere": 2.0 / 5.0,  # zeta = 7/2 (plane motion)
    "spherical-shell": 2.0 / 3.0,  # zeta = 5/2
}

#: A thin spherical shell's radius of gyration over its radius, ``sqrt(2/3)``: the largest
#: of any sphere (its mass is all at the radius), so ``zeta >= 5/2`` for every sphere.
SHELL_GYRATION = math.sqrt(2.0 / 3.0)
#: ``Body(gyration=R * sqrt(2/3))`` is a thin shell whichever way the product rounds.
_SHELL_BOUND = SHELL_GYRATION * (1.0 + 1e-12)


@dataclass(frozen=True, eq=False)
class Body(BodyColumns):
    """A rigid body that touches the surface at radius ``R`` from its centre.

    Parameters
    ----------
    mass : float or array_like
        Mass ``m`` in kg, ``> 0``.
    radius : float or array_like
        Distance ``R`` in m from the centre of mass to the contact point, ``> 0``.
    gyration : float or array_like
        Radius of gyration ``rho`` in m about the centre, ``> 0``; the moment of
        inertia is ``J = m rho^2``. Any value is allowed: a spool or yo-yo that
        touches on its axle has ``rho > R``.
    name : str, optional
        Label used in reports; the presets set it. Shown as plain text everywhere
        (never read as Rich markup, HTML or mathtext).

    Attributes
    ----------
    zeta : float or ndarray
        ``1 + R^2/rho^2`` (section 2), the ratio by which the contact point's
        velocity changes faster than the centre's under a tangential impulse.
    inertia : float or ndarray
        ``J = m rho^2`` in kg m^2.

    Examples
    --------
    >>> Body.solid_disk(mass=2.0, radius=0.1).zeta
    3.0
    >>> spool = Body(mass=0.2, radius=0.01, gyration=0.03)   # rolls on its axle
    >>> round(spool.zeta, 4)
    1.1111
    """

    mass: float | np.ndarray
    radius: float | np.ndarray
    gyration: float | np.ndarray
    name: str = "custom"
    #: zeta, computed once; the presets replace it by its exact value (3, 2, 7/2,
    #: 5/2), which ``1 + R^2/rho^2`` only rounds to (e.g. 3.4999999999999996)
    _zeta: float | np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a str, got {type(self.name).__name__} {self.name!r}")
        object.__setattr__(self, "name", str(self.name))  # np.str_ and other subclasses
        for name in ("mass", "radius", "gyration"):  # TypeError or ValueError, named
            arr = validated(name, getattr(self, name))
            object.__setattr__(self, name, float(arr) if arr.ndim == 0 else arr)
        with np.errstate(over="ignore"):
            zeta = 1.0 + (self.radius / self.gyration) ** 2
        if np.any(zeta > MAX_ZETA):
            raise ValueError(
                f"radius/gyration is too large: zeta = 1 + (radius/gyration)**2 must be <= "
                f"{MAX_ZETA:g} (radius {self.radius!r}, gyration {self.gyration!r})"
            )
        if np.any(zeta == 1.0):
            raise ValueError(
                "radius/gyration is too small: zeta = 1 + (radius/gyration)**2 rounds to 1 "
                f"(radius {self.radius!r}, gyration {self.gyration!r})"
            )
        object.__setattr__(self, "_zeta", zeta)

    @property
    def zeta(self) -> float | np.ndarray:
        return self._zeta  # type: ignore[return-value]

    #: The body's flat column names in results (:meth:`columns`).
    COLUMNS = ("mass", "radius", "gyration", "zeta")

    @property
    def inertia(self) -> float | np.ndarray:
        return self.mass * self.gyration**2

    @classmethod
    def preset(cls, name: str, *, mass: float, radius: float) -> Body:
        """Build a named preset: one of ``solid-disk``, ``ring``, ``solid-sphere``,
        ``spherical-shell``."""
        if not isinstance(name, str):
            raise TypeError(f"body must be one of {', '.join(PRESETS)}; got {name!r}")
        if name not in PRESETS:
            raise ValueError(f"body must be one of {', '.join(PRESETS)}; got {name!r}")
        r = as_real_array("radius", radius)
        body = cls(mass=mass, radius=radius, gyration=np.sqrt(PRESETS[name]) * r, name=name)
        object.__setattr__(body, "_zeta", 1.0 + 1.0 / PRESETS[name])
        return body

    @classmethod
    def solid_disk(cls, *, mass: float, radius: float) -> Body:
        """Uniform solid disk (or cylinder) rolling on its rim: ``rho^2 = R^2/2``, ``zeta = 3``."""
        return cls.preset("solid-disk", mass=mass, radius=radius)

    @classmethod
    def ring(cls, *, mass: float, radius: float) -> Body:
        """Thin ring (or thin-walled tube): ``rho = R``, ``zeta = 2``."""
        return cls.preset("ring", mass=mass, radius=radius)

    @classmethod
    def solid_sphere(cls, *, mass: float, radius: float) -> Body:
        """Uniform solid sphere in plane motion: ``rho^2 = 2R^2/5``, ``zeta = 7/2``."""
        return cls.preset("solid-sphere", mass=mass, radius=radius)

    @classmethod
    def spherical_shell(cls, *, mass: float, radius: float) -> Body:
        """Thin spherical shell in plane motion: ``rho^2 = 2R^2/3``, ``zeta = 5/2``."""
        return cls.preset("spherical-shell", mass=mass, radius=radius)

    @classmethod
    def from_zeta(cls, *, mass: float, radius: float, zeta: float) -> Body:
        """Body with a given ``zeta = 1 + R^2/rho^2`` (``zeta > 1``)."""
        z = as_real_array("zeta", zeta)
        check("zeta", z, lambda a: a > 1, "> 1")
        r = as_real_array("radius", radius)
        body = cls(mass=mass, radius=radius, gyration=r / np.sqrt(z - 1.0))
        object.__setattr__(body, "_zeta", float(z) if z.ndim == 0 else z)
        return body

    @classmethod
    def from_columns(
        cls,
        *,
        mass: np.ndarray,
        radius: np.ndarray,
        preset: np.ndarray,
        gyration: np.ndarray,
    ) -> Body:
        """One array-valued body from per-row columns, as in a batch file.

        Rows whose ``gyration`` is NaN use their ``preset`` (a name from
        :data:`PRESETS`) with its exact ``zeta``; the other rows are custom bodies.
        """
        preset = np.asarray(preset, dtype=object)
        gyration = np.array(gyration, dtype=float)
        custom = ~np.isnan(gyration)
        unknown = sorted({str(p) for p in preset[~custom]} - set(PRESETS))
        if unknown:
            raise ValueError(f"body must be one of {', '.join(PRESETS)}; got {unknown[0]!r}")
        ratio = np.array([PRESETS.get(str(p), 1.0) for p in preset])  # rho^2/R^2 of presets
        radius = as_real_array("radius", radius)
        gyration[~custom] = np.sqrt(ratio[~custom]) * radius[~custom]
        body = cls(mass=mass, radius=radius, gyration=gyration, name="mixed")
        zeta = np.where(custom, body.zeta, 1.0 + 1.0 / ratio)
        object.__setattr__(body, "_zeta", zeta)
        return body

    def _at(self, shape: tuple[int, ...], index: Any) -> Body:
        """The body of the impacts ``[index]`` of a result of ``shape``: itself when its
        parameters are numbers, else its parameters broadcast to ``shape`` and indexed."""
        parts = (self.mass, self.radius, self.gyration, self.zeta)
        if not any(np.ndim(x) for x in parts):
            return self
        m, r, g, z = (np.broadcast_to(x, shape)[index] for x in parts)
        return self._with_zeta(z, mass=m, radius=r, gyration=g)

    def _with_zeta(self, zeta: float | np.ndarray, **parts: object) -> Body:
        """Copy with other mass/radius/gyration (e.g. one element) and the given zeta."""
        body = Body(
            **{
                "mass": self.mass,
                "radius": self.radius,
                "gyration": self.gyration,
                "name": self.name,
                **parts,
            }
        )
        object.__setattr__(body, "_zeta", zeta)
        return body

    def __repr__(self) -> str:
        def fmt(x: float | np.ndarray) -> str:
            return f"{x:g}" if np.ndim(x) == 0 else f"array{np.shape(x)}"

        return (
            f"Body(name={self.name!r}, mass={fmt(self.mass)}, radius={fmt(self.radius)}, "
            f"gyration={fmt(self.gyration)}, zeta={fmt(self.zeta)})"
        )


def as_body(body: Any, name: str = "body") -> Body:
    """``body`` as a :class:`Body`: a Body as it is, a ball (:class:`~spinimpact.Ball`,
    e.g. ``BALLS["tennis"]``) as its :attr:`~spinimpact.Ball.body`.

    Every solver that takes a body takes a ball through this: ``solve``,
    ``solve_sphere``, ``solve_pair``, ``simulate`` and ``fit``.

    Parameters
    ----------
    body : Body or Ball
    name : str
        The parameter named in the error (``"ball1"``).

    Raises
    ------
    TypeError
        For anything else, naming ``name`` and the type given.
    """
    if isinstance(body, Body):
        return body
    if isinstance(body, BODY_LIKE):
        return body.body
    raise TypeError(
        f"{name} must be a spinimpact.Body or a spinimpact.Ball, got {type(body).__name__}"
    )


#: Types that stand for a body through their ``.body`` (a :class:`~spinimpact.Ball`, which
#: :mod:`spinimpact.model.presets` adds here, since that module imports this one).
BODY_LIKE: tuple[type, ...] = ()


def accept_as_body(kind: type) -> type:
    """Let :func:`as_body` take instances of ``kind`` through their ``.body``."""
    global BODY_LIKE
    BODY_LIKE = (*BODY_LIKE, kind)
    return kind


def check_sphere(body: Body, name: str = "gyration") -> None:
    """Refuse a body that cannot be a sphere: a radius of gyration above a thin shell's.

    A sphere's mass lies within its radius ``R``, so its radius of gyration is at most a
    thin spherical shell's, ``sqrt(2/3) R``. A disk, ring or spool in plane motion may
    exceed it (:func:`~spinimpact.solve` accepts them); the 3D solvers may not.

    Parameters
    ----------
    body : Body
        The sphere (``mass``, ``radius``, ``gyration``: numbers or arrays).
    name : str
        The parameter named in the error, e.g. ``"ball2's gyration"``.

    Raises
    ------
    ValueError
        Where ``gyration > sqrt(2/3) * radius`` (to ``1e-12`` relative), naming the
        gyration, the radius, the bound and, for arrays, the first offending index.
    """
    g, r = body.gyration, body.radius
    if type(g) is float and type(r) is float and g <= r * _SHELL_BOUND:
        return  # one plain sphere: no arrays
    g, r = np.broadcast_arrays(np.asarray(g, dtype=float), np.asarray(r, dtype=float))
    bad = ~(g <= r * _SHELL_BOUND)
    if not bad.any():
        return
    i = tuple(int(k) for k in np.argwhere(bad)[0]) if bad.ndim else ()
    where = f" (first offending index {i[0] if len(i) == 1 else i})" if i else ""
    what = f": the {body.name!r} preset is not a sphere" if body.name in PRESETS else ""
    raise ValueError(
        f"{name} must be <= sqrt(2/3) * radius = {float(r[i] * SHELL_GYRATION):g} m (a thin "
        f"spherical shell's, the largest of any sphere), got {float(g[i])!r} m with radius "
        f"{float(r[i])!r} m{where}{what}"
    )
