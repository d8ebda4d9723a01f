"""Planar rigid bodies that touch the surface anywhere: a rod, a block, an eccentric disk.

A :class:`PlanarBody` is its mass, its moment of inertia about the centre of mass and
the position of the contact point relative to the centre of mass at the instant of
impact, in the surface's axes (``x`` along the surface, ``y`` up). Its collision matrix
(:func:`~spinimpact.core.impulse.planar_collision_matrix`) couples the normal and
tangential impulses unless the contact lies straight below the centre of mass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import core
from .._validation import as_real_array, check, validated
from ..core import planar as kernels
from .body import Body
from .result import BodyColumns

__all__ = ["PlanarBody", "Pendulum"]


def _number(name: str, value: object, rules: str | None = None) -> float | np.ndarray:
    arr = validated(name, value, rules) if rules else as_real_array(name, value)
    return float(arr) if arr.ndim == 0 else arr


def _positive(name: str, value: object) -> float | np.ndarray:
    return _number(name, value, "mass")  # the rules of a strictly positive size


@dataclass(frozen=True, eq=False)
class PlanarBody(BodyColumns):
    """A rigid body in plane motion touching the surface at offset ``r`` from its centre
    of mass.

    Parameters
    ----------
    mass : float or array_like
        Mass ``m``, kg, ``> 0``.
    inertia : float or array_like
        Moment of inertia ``J`` about the centre of mass, kg m^2, ``> 0``.
    rx, ry : float or array_like
        Position of the contact point relative to the centre of mass, m, in the
        surface's axes at the instant of impact. ``ry < 0``: the centre of mass lies
        above the surface.
    name : str, optional
        Label used in reports; the presets set it.

    Attributes
    ----------
    collision_matrix : CollisionMatrix
        ``W = [[1/m + ry^2/J, -rx ry/J], [-rx ry/J, 1/m + rx^2/J]]``, 1/kg.

    Examples
    --------
    >>> rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(45))
    >>> round(float(rod.rx), 4), round(float(rod.ry), 4)
    (-0.3536, -0.3536)
    >>> w = rod.collision_matrix
    >>> round(float(w.tn * rod.mass), 4)    # coupling: the contact is off the normal
    -1.5
    """

    mass: float | np.ndarray
    inertia: float | np.ndarray
    rx: float | np.ndarray
    ry: float | np.ndarray
    name: str = "custom"

    def __post_init__(self) -> None:
        object.__setattr__(self, "mass", _positive("mass", self.mass))
        object.__setattr__(self, "inertia", _positive("inertia", self.inertia))
        for name in ("rx", "ry"):
            object.__setattr__(self, name, _number(name, getattr(self, name)))
        check(
            "ry",
            np.asarray(self.ry),
            lambda y: y < 0,
            "< 0 (the contact point must lie below the centre of mass)",
        )

    #: The body's flat column names in results.
    COLUMNS = ("mass", "inertia", "rx", "ry")

    @property
    def collision_matrix(self) -> core.CollisionMatrix:
        return core.planar_collision_matrix(self.mass, self.inertia, self.rx, self.ry)

    # -- the body's side of the contact seam ----------------------------------------------
    def contact_velocity(self, vx, vy, omega):  # type: ignore[no-untyped-def]
        """Slip and normal velocity ``(u, v)`` of the contact point, m/s."""
        return kernels.planar_contact_velocity(vx, vy, omega, self.rx, self.ry)

    def apply_impulse(self, vx, vy, omega, friction, normal):  # type: ignore[no-untyped-def]
        """Velocities ``(vx, vy, omega)`` after the contact impulse ``(f, tau)``."""
        return kernels.planar_apply_impulse(
            vx, vy, omega, self.mass, self.inertia, self.rx, self.ry, friction, normal
        )

    def kinetic_energy(self, vx, vy, omega):  # type: ignore[no-untyped-def]
        """``m (vx^2 + vy^2)/2 + J omega^2/2``, J."""
        return core.kinetic_energy(vx, vy, omega, self.mass, self.inertia)

    # -- presets -------------------------------------------------------------------------
    @classmethod
    def from_body(cls, body: Body) -> PlanarBody:
        """One of the paper's bodies: the contact straight below the centre, ``r = (0, -R)``."""
        if not isinstance(body, Body):
            raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
        return cls(body.mass, body.inertia, 0.0 * body.radius, -body.radius, name=body.name)

    @classmethod
    def rod(cls, *, mass: object, length: object, angle: object) -> PlanarBody:
        """A uniform slender rod striking with its lower end.

        Parameters
        ----------
        mass : float or array_like
            kg.
        length : float or array_like
            m; ``J = m L^2/12``.
        angle : float or array_like
            Angle of the rod to the surface, rad, in ``(0, pi)``: the centre of mass
            lies at ``(L/2)(cos angle, sin angle)`` from the contact (``pi/2``: vertical).
        """
        m, length_, th = _positive("mass", mass), _positive("length", length), _angle(angle)
        half = 0.5 * np.asarray(length_)
        return cls(m, m * length_**2 / 12.0, -half * np.cos(th), -half * np.sin(th), name="rod")

    @classmethod
    def block(cls, *, mass: object, width: object, height: object, angle: object) -> PlanarBody:
        """A uniform rectangular block (or plate) landing on a corner.

        Parameters
        ----------
        mass : float or array_like
            kg.
        width, height : float or array_like
            Sides of the rectangle, m; ``J = m (w^2 + h^2)/12``.
        angle : float or array_like
            Tilt of the side of length ``width`` that starts at the contact corner, rad,
            in ``[0, pi/2)``: that side rises at ``angle`` from the surface, and the
            block lies above it.
        """
        m, w, h = _positive("mass", mass), _positive("width", width), _positive("height", height)
        th = _angle(angle, low=0.0, high=math.pi / 2, text="in [0, pi/2)", closed_low=True)
        c, s = np.cos(th), np.sin(th)
        hx, hy = 0.5 * np.asarray(w), 0.5 * np.asarray(h)
        rx, ry = -(hx * c - hy * s), -(hx * s + hy * c)
        return cls(m, m * (w * w + h * h) / 12.0, rx, ry, name="block")

    @classmethod
    def eccentric_disk(
        cls, *, mass: object, radius: object, gyration: object, offset: object, angle: object
    ) -> PlanarBody:
        """A disk (or a sphere in plane motion) whose centre of mass is off its centre.

        Parameters
        ----------
        mass : float or array_like
            kg.
        radius : float or array_like
            Radius ``R`` of the rim, m: the geometric centre is ``R`` above the contact.
        gyration : float or array_like
            Radius of gyration about the centre of mass, m (``J = m rho^2``).
        offset : float or array_like
            Distance ``e`` of the centre of mass from the geometric centre, m, ``< R``.
        angle : float or array_like
            Direction of the offset from the geometric centre, rad (``0``: along ``+x``).
        """
        m, r = _positive("mass", mass), _positive("radius", radius)
        g = _positive("gyration", gyration)
        e = _number("offset", offset)
        check("offset", np.asarray(e), lambda x: x >= 0, ">= 0")
        if np.any(np.asarray(e) >= np.asarray(r)):
            raise ValueError(f"offset must be < radius ({r!r}), got {e!r}")
        th = _number("angle", angle)
        return cls(m, m * g * g, -e * np.cos(th), -r - e * np.sin(th), name="eccentric-disk")


@dataclass(frozen=True, eq=False)
class Pendulum(BodyColumns):
    """A rigid pendulum on a fixed frictionless pivot, striking the surface at one point.

    Parameters
    ----------
    mass : float or array_like
        Mass ``m``, kg, ``> 0``.
    inertia : float or array_like
        Moment of inertia about the centre of mass, kg m^2, ``> 0``.
    gx, gy : float or array_like
        Centre of mass relative to the pivot, m.
    px, py : float or array_like
        Contact point relative to the pivot, m, at the instant of impact; ``py < 0``
        (the pivot lies above the surface).
    name : str, optional

    Notes
    -----
    The pivot leaves one motion, the rotation ``omega``: the collision matrix
    (:func:`~spinimpact.core.planar.pendulum_collision_matrix`) has rank one, the slip
    and the normal velocity of the contact stay proportional, and they vanish together.
    If the friction cone can hold the contact there, the pendulum stops against the
    surface (regime ``locked``); if not, the slip reverses and it rebounds.
    """

    mass: float | np.ndarray
    inertia: float | np.ndarray
    gx: float | np.ndarray
    gy: float | np.ndarray
    px: float | np.ndarray
    py: float | np.ndarray
    name: str = "pendulum"

    COLUMNS = ("mass", "inertia", "gx", "gy", "px", "py")

    def __post_init__(self) -> None:
        object.__setattr__(self, "mass", _positive("mass", self.mass))
        object.__setattr__(self, "inertia", _positive("inertia", self.inertia))
        for name in ("gx", "gy", "px", "py"):
            object.__setattr__(self, name, _number(name, getattr(self, name)))
        check("py", np.asarray(self.py), lambda y: y < 0,
              "< 0 (the pivot must lie above the surface, not at the contact)")  # fmt: skip

    @property
    def inertia_pivot(self) -> float | np.ndarray:
        """Moment of inertia about the pivot, ``J_G + m |g|^2``, kg m^2."""
        return self.inertia + self.mass * (self.gx**2 + self.gy**2)

    @property
    def collision_matrix(self) -> core.CollisionMatrix:
        return kernels.pendulum_collision_matrix(self.inertia_pivot, self.px, self.py)

    def centre_velocity(self, omega):  # type: ignore[no-untyped-def]
        """Velocity of the centre of mass, ``omega e_z x g = (-omega gy, omega gx)``, m/s."""
        return -omega * self.gy, omega * self.gx

    def contact_velocity(self, vx, vy, omega):  # type: ignore[no-untyped-def]
        """Slip and normal velocity of the contact, from ``omega`` alone, m/s."""
        return kernels.pendulum_contact_velocity(omega, self.px, self.py)

    def apply_impulse(self, vx, vy, omega, friction, normal):  # type: ignore[no-untyped-def]
        """``(vx, vy, omega)`` after the contact impulse: the spin changes by
        ``(px tau - py f)/J_O`` and the centre follows it."""
        om = kernels.pendulum_apply_impulse(
            omega, self.inertia_pivot, self.px, self.py, friction, normal
        )
        return (*self.centre_velocity(om), om)

    def kinetic_energy(self, vx, vy, omega):  # type: ignore[no-untyped-def]
        """``m (vx^2 + vy^2)/2 + J_G omega^2/2`` (``= J_O omega^2/2``), J."""
        return core.kinetic_energy(vx, vy, omega, self.mass, self.inertia)

    @classmethod
    def rod(cls, *, mass: object, length: object, angle: object) -> Pendulum:
        """A uniform rod hanging from a pivot at one end, striking with the other.

        ``angle`` is the rod's angle below the horizontal, rad, in ``(0, pi)``: the tip
        is at ``L (cos angle, -sin angle)`` from the pivot (``pi/2``: hanging straight
        down). ``J_G = m L^2/12``, the centre of mass at mid-length.
        """
        m, length_, th = _positive("mass", mass), _positive("length", length), _angle(angle)
        px, py = np.asarray(length_) * np.cos(th), -np.asarray(length_) * np.sin(th)
        return cls(m, m * length_**2 / 12.0, px / 2.0, py / 2.0, px, py, name="rod-pendulum")


def _angle(
    value: object,
    *,
    low: float = 0.0,
    high: float = math.pi,
    text: str = "in (0, pi)",
    closed_low: bool = False,
) -> float | np.ndarray:
    arr = as_real_array("angle", value)
    check(
        "angle",
        arr,
        lambda a: ((a >= low) if closed_low else (a > low)) & (a < high),
        f"{text} rad",
    )
    return float(arr) if arr.ndim == 0 else arr
