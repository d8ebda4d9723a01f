"""Any rigid body in 3D touching a plane at one point: :func:`solve_rigid`.

A die landing on a corner, a coin on its rim, a rod, a robot link: the collision matrix
couples the two tangential directions with the normal, so the slip direction turns
during the impact and may stop, stick or slide again along the direction the matrix
dictates. The impact is solved by Keller's method in the normal impulse
(:mod:`spinimpact.core.scalar_rigid` gives the theory); :func:`solve_contact` takes the
collision matrix itself (two bodies: add theirs; an articulated body known to an engine:
:func:`spinimpact.core.rigid3d.jacobian_matrix`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import approach, as_real_array, broadcast, check, validated, vector3
from .result import Array, Result, freeze
from .sphere3d import State3, Surface, Vector

__all__ = [
    "RigidBody",
    "RigidHistory",
    "RigidImpact",
    "rigid_history",
    "solve_contact",
    "solve_rigid",
]

#: The restitution laws by name, as :func:`spinimpact.solve_planar` names them.
LAWS = ("poisson", "newton", "energetic")


def _rotation(orientation: Any) -> np.ndarray:
    """A rotation matrix (..., 3, 3) from a matrix or a unit quaternion ``(w, x, y, z)``."""
    q = as_real_array("orientation", orientation)
    if q.shape[-1:] == (4,):
        norm = np.linalg.norm(q, axis=-1)
        check("the length of orientation", norm, lambda x: np.abs(x - 1.0) <= 1e-9,
              "1 (a unit quaternion w, x, y, z)")  # fmt: skip
        w, x, y, z = np.moveaxis(q, -1, 0)
        return np.stack([
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
            np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
            np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
        ], -2)  # fmt: skip
    if q.shape[-2:] != (3, 3):
        raise ValueError(f"orientation must be a 3 x 3 rotation matrix or a unit quaternion "
                         f"(w, x, y, z), got shape {q.shape}")  # fmt: skip
    gap = np.abs(np.swapaxes(q, -1, -2) @ q - np.eye(3)).max(axis=(-2, -1))
    check("orientation", gap, lambda g: g <= 1e-9, "a rotation (R^T R = I to 1e-9)")
    check("the determinant of orientation", np.linalg.det(q), lambda d: d > 0,
          "> 0 (a rotation, not a reflection)")  # fmt: skip
    return q


@dataclass(frozen=True, eq=False)
class RigidBody:
    """A rigid body for :func:`solve_rigid`: its mass, its inertia tensor about the centre of
    mass and the contact point's offset from the centre of mass, both in the world frame.

    Build one from the body's own frame with :meth:`principal`, or take a preset:
    :meth:`cuboid` (a box or die on a corner), :meth:`rod`, :meth:`cylinder` (a coin or
    can on its rim).

    Parameters
    ----------
    mass : float or array_like
        Mass (kg), ``> 0``.
    inertia : array_like, shape (..., 3, 3)
        Inertia tensor about the centre of mass, world frame (kg m^2): symmetric, positive
        definite, its principal moments obeying the triangle inequality.
    offset : array_like, shape (..., 3)
        Contact point minus centre of mass, world frame (m).
    """

    mass: Any
    inertia: Any
    offset: Any

    def __post_init__(self) -> None:
        mass = validated("mass", self.mass)
        inertia = as_real_array("inertia", self.inertia)
        if inertia.shape[-2:] != (3, 3):
            raise ValueError(f"inertia must be a 3 x 3 tensor, got shape {inertia.shape}")
        asym = np.abs(inertia - np.swapaxes(inertia, -1, -2)).max(axis=(-2, -1))
        size = np.abs(inertia).max(axis=(-2, -1))
        check("inertia", asym - 1e-12 * size, lambda a: a <= 0, "symmetric")
        moments = np.linalg.eigvalsh(inertia)
        check("the principal moments of inertia", moments[..., 0], lambda m: m > 0,
              "> 0 (positive definite)")  # fmt: skip
        check("the principal moments of inertia",
              moments[..., 0] + moments[..., 1] - moments[..., 2] + 1e-12 * moments[..., 2],
              lambda t: t >= 0, "a triangle (each at most the sum of the other two)")  # fmt: skip
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "inertia", inertia)
        object.__setattr__(self, "offset", vector3("offset", self.offset))

    @classmethod
    def principal(cls, mass: Any, moments: Any, offset: Any,
                  orientation: Any = None) -> RigidBody:  # fmt: skip
        """A body given in its own principal frame.

        Parameters
        ----------
        mass : float or array_like
            Mass (kg).
        moments : array_like, shape (..., 3)
            Principal moments of inertia about the centre of mass (kg m^2).
        offset : array_like, shape (..., 3)
            The contact point from the centre of mass, in the body's frame (m).
        orientation : array_like, optional
            The body's orientation: a rotation matrix (body to world) or a unit quaternion
            ``(w, x, y, z)``. Default: the body's axes are the world's.
        """
        moments = vector3("moments", moments)
        check("moments", moments, lambda m: m > 0, "> 0")
        r = np.eye(3) if orientation is None else _rotation(orientation)
        inertia = r @ (moments[..., :, None] * np.swapaxes(r, -1, -2))
        world_offset = np.einsum("...ij,...j->...i", r, vector3("offset", offset))
        return cls(mass, inertia, world_offset)

    @classmethod
    def cuboid(cls, mass: Any, size: Any, corner: Any = (-1, -1, -1),
               orientation: Any = None) -> RigidBody:  # fmt: skip
        """A uniform box (a die: equal sides) touching at one corner.

        ``size`` gives the side lengths ``(a, b, c)`` along the body's axes (m); ``corner``
        the signs ``(+-1, +-1, +-1)`` of the touching corner in the body's frame.
        """
        a, b, c = np.moveaxis(vector3("size", size), -1, 0)
        m = validated("mass", mass)
        moments = np.stack([b * b + c * c, a * a + c * c, a * a + b * b], -1) * m[..., None] / 12
        signs = vector3("corner", corner)
        check("corner", np.abs(signs), lambda s: s == 1, "signs of +-1")
        offset = 0.5 * signs * np.stack([a, b, c], -1)
        return cls.principal(m, moments, offset, orientation)

    @classmethod
    def rod(cls, mass: Any, length: Any, orientation: Any = None) -> RigidBody:
        """A thin uniform rod along the body's x axis, touching at its end ``x = -L/2``
        (a tiny moment about its axis, ``1e-9`` of the others, keeps the tensor invertible)."""
        m = validated("mass", mass)
        big = m * validated("length", length, "radius") ** 2 / 12
        moments = np.stack([1e-9 * big, big, big], -1)
        offset = np.stack([-0.5 * np.asarray(length, float), 0 * big, 0 * big], -1)
        return cls.principal(m, moments, offset, orientation)

    @classmethod
    def cylinder(cls, mass: Any, radius: Any, height: Any, rim_angle: Any = 0.0,
                 orientation: Any = None) -> RigidBody:  # fmt: skip
        """A uniform solid cylinder (a coin, a can) with its axis along the body's z axis,
        touching at the rim of its lower face, at the angle ``rim_angle`` (radians) about
        the axis from the body's x axis."""
        m = validated("mass", mass)
        r = validated("radius", radius)
        h = validated("height", height, "radius")
        side = m * (3 * r * r + h * h) / 12
        moments = np.stack([side, side, 0.5 * m * r * r], -1)
        angle = as_real_array("rim_angle", rim_angle)
        offset = np.stack([r * np.cos(angle), r * np.sin(angle), -0.5 * h + 0 * angle], -1)
        return cls.principal(m, moments, offset, orientation)

    def matrix(self) -> np.ndarray:
        """The collision matrix at the contact point, world frame (1/kg)."""
        from ..core import rigid3d  # Numba, where installed, loads with it: only when used

        return rigid3d.body_matrix(self.mass, self.inertia, self.offset)


@dataclass(frozen=True, eq=False)
class RigidImpact(Result):
    """The impact of a rigid body (or of a contact given by its collision matrix).

    Vectors are in the world frame, by components; every field is an array of the impacts'
    shape. ``after`` is NaN for :func:`solve_contact` (no body: map ``impulse`` to yours).
    """

    after: State3  #: centre velocity (m/s) and spin (rad/s) after the impact
    impulse: Vector  #: the contact impulse on the body, N s
    contact_before: Vector  #: the contact point's velocity relative to the surface, m/s
    contact_after: Vector  #: the same after the impact, m/s
    normal_impulse: Array  #: N s
    compression_impulse: Array  #: the normal impulse at the end of compression, N s
    stop_impulse: Array  #: the normal impulse at which the slip stopped (NaN if never), N s
    regime: Array  #: the phases: slide, slide-stick, slide-reslide or stick
    work_compression_normal: Array  #: the normal force's work in compression, J (<= 0)
    work_restitution_normal: Array  #: the normal force's work in restitution, J
    work_compression_tangential: Array  #: friction's work in compression, J (<= 0)
    work_restitution_tangential: Array  #: friction's work in restitution, J (<= 0)
    dissipated_energy: Array  #: kinetic energy lost, J (< 0: the law created energy)
    newton_restitution: Array  #: ``-v_n^+ / v_n^-``
    poisson_restitution: Array  #: restitution over compression impulse
    energetic_restitution: Array  #: ``sqrt(W_r / -W_c)``
    creates_energy: Array  #: whether the impact created kinetic energy
    law: str = "poisson"  #: the restitution law

    @property
    def velocity(self) -> np.ndarray:
        """The centre velocity after the impact, shape (..., 3), m/s."""
        return self.after.velocity

    @property
    def spin(self) -> np.ndarray:
        """The spin vector after the impact, shape (..., 3), rad/s."""
        return self.after.spin

    @property
    def sequence(self) -> np.ndarray:
        """The phases, as :attr:`regime` names them."""
        return np.asarray(self.regime)


def _vector(a: np.ndarray) -> Vector:
    return Vector(*(freeze(a[..., k]) for k in range(3)))


def _contact(matrix: np.ndarray, velocity: np.ndarray, normal: np.ndarray, mu, kappa,
             law: str) -> tuple[Any, np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """Solve in the contact frame; returns the core result, the normal velocity before,
    and the world impulse and contact velocity after."""
    if not isinstance(law, str):
        raise TypeError(f"law must be a string, one of {', '.join(LAWS)}; got {law!r}")
    if law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}; got {law!r}")
    from ..core import rigid3d  # Numba, where installed, loads with it: only when used

    mu = validated("mu", mu)
    kappa = validated("kappa", kappa)
    axes = rigid3d.frame(normal)
    local_w = np.swapaxes(axes, -1, -2) @ matrix @ axes
    local_v = np.einsum("...ji,...j->...i", axes, velocity)
    approach("the contact point's normal velocity", local_v[..., 2],
             "the contact point must approach the surface")  # fmt: skip
    result = rigid3d.contact_impact(local_w, local_v, mu, kappa, law)
    impulse = np.einsum("...ij,...j->...i", axes, result.impulse)
    after = np.einsum("...ij,...j->...i", axes, result.velocity)
    return result, local_v[..., 2], impulse, after


def solve_rigid(body: RigidBody, velocity: Any, spin: Any, *, mu: Any, kappa: Any,
                law: str = "poisson", surface: Surface | None = None) -> RigidImpact:  # fmt: skip
    """Solve the frictional impact of any rigid body touching a plane at one point, in 3D.

    Parameters
    ----------
    body : RigidBody
        Mass, inertia tensor and the contact point's offset (world frame).
    velocity : array_like, shape (..., 3)
        Centre-of-mass velocity before the impact (m/s).
    spin : array_like, shape (..., 3)
        Spin vector before the impact (rad/s).
    mu, kappa : float or array_like
        Coulomb's friction coefficient (``>= 0``) and the restitution coefficient of
        ``law`` (in ``[0, 1]``).
    law : {"poisson", "newton", "energetic"}
        Poisson's kinetic law (default), Newton's kinematic law or Stronge's energetic law.
    surface : Surface, optional
        The plane's normal and velocity; by default ``y = 0`` at rest.

    Returns
    -------
    RigidImpact

    Raises
    ------
    TypeError
        A ``body`` that is not a :class:`RigidBody`, a ``law`` that is not a string, or
        inputs that are not numbers.
    ValueError
        Bad values; the contact point must approach the surface.
    ImportError
        For more than one impact without Numba (the ``[fast]`` extra).

    Examples
    --------
    A die dropped on a corner, tilted, spinning about the vertical:

    >>> from spinimpact import RigidBody, solve_rigid
    >>> die = RigidBody.cuboid(mass=0.005, size=[0.016, 0.016, 0.016],
    ...                        orientation=[0.95, 0.2, 0.1, 0.2])  # doctest: +SKIP
    """
    if not isinstance(body, RigidBody):
        raise TypeError(f"body must be a spinimpact.RigidBody, got {type(body).__name__}")
    surface = Surface() if surface is None else surface
    if not isinstance(surface, Surface):
        raise TypeError(f"surface must be a spinimpact.Surface, got {type(surface).__name__}")
    v = vector3("velocity", velocity)
    w = vector3("spin", spin)
    v, w, offset = broadcast(velocity=v, spin=w, offset=body.offset)
    before = v + np.cross(w, offset) - surface.velocity
    matrix = body.matrix()
    result, vn, impulse, after = _contact(matrix, before, surface.normal, mu, kappa, law)
    from ..core import rigid3d

    v1, w1 = rigid3d.apply_impulse(body.mass, body.inertia, offset, v, w, impulse)
    return _finish(result, vn, impulse, before, after, v1, w1, law)


def solve_contact(matrix: Any, velocity: Any, *, mu: Any, kappa: Any, law: str = "poisson",
                  normal: Any = (0.0, 1.0, 0.0)) -> RigidImpact:  # fmt: skip
    """Solve one contact given by its collision matrix (world frame), for any system.

    ``matrix`` is ``W`` (..., 3, 3), with the contact point's relative velocity changing by
    ``W p`` under an impulse ``p``: one body's (:meth:`RigidBody.matrix`), two bodies'
    sum, or ``J M^-1 J^T`` of an articulated body
    (:func:`spinimpact.core.rigid3d.jacobian_matrix`). ``velocity`` is the contact point's
    velocity relative to the surface (m/s), ``normal`` the surface's normal (towards the
    body). The result's ``velocity`` and ``spin`` are NaN: map ``impulse`` to your bodies.
    """
    w = as_real_array("matrix", matrix)
    if w.shape[-2:] != (3, 3):
        raise ValueError(f"matrix must be 3 x 3, got shape {w.shape}")
    eig = np.linalg.eigvalsh(0.5 * (w + np.swapaxes(w, -1, -2)))
    check("the eigenvalues of matrix", eig[..., 0], lambda e: e > 0,
          "> 0 (a collision matrix is positive definite)")  # fmt: skip
    v = vector3("velocity", velocity)
    n = vector3("normal", normal)
    result, vn, impulse, after = _contact(w, v, n, mu, kappa, law)
    nan = np.full_like(impulse, np.nan)
    return _finish(result, vn, impulse, v, after, nan, nan, law)


def _finish(result, vn_before, impulse, before, after, v1, w1, law) -> RigidImpact:
    pn = result.impulse[..., 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        energetic = np.sqrt(
            np.maximum(-result.work_restitution_normal / result.work_compression_normal, 0)
        )
        newton = -result.velocity[..., 2] / vn_before
        poisson = pn / result.compression_impulse - 1.0
    state = State3(*(freeze(v1[..., k]) for k in range(3)), *(freeze(w1[..., k]) for k in range(3)))
    return RigidImpact(
        after=state, impulse=_vector(impulse), contact_before=_vector(before),
        contact_after=_vector(after), normal_impulse=freeze(pn),
        compression_impulse=freeze(result.compression_impulse),
        stop_impulse=freeze(result.stop_impulse), regime=freeze(result.sequence),
        work_compression_normal=freeze(result.work_compression_normal),
        work_restitution_normal=freeze(result.work_restitution_normal),
        work_compression_tangential=freeze(result.work_compression_tangential),
        work_restitution_tangential=freeze(result.work_restitution_tangential),
        dissipated_energy=freeze(result.dissipated), newton_restitution=freeze(newton),
        poisson_restitution=freeze(poisson), energetic_restitution=freeze(energetic),
        creates_energy=freeze(result.dissipated < 0), law=law,
    )  # fmt: skip


@dataclass(frozen=True, eq=False)
class RigidHistory:
    """One impact over the normal impulse: the slip's hodograph and the normal velocity.

    ``slip`` holds the contact point's tangential velocity along the contact frame's axes
    ``t1, t2`` (``axes``' first two columns, world frame), so that a plot of its two
    columns is the hodograph: a straight line towards the origin while the direction keeps,
    a curve while it turns, the origin itself while it sticks.
    """

    normal_impulse: np.ndarray  #: (n,), N s
    slip: np.ndarray  #: (n, 2), m/s, along t1 and t2
    normal_velocity: np.ndarray  #: (n,), m/s
    axes: np.ndarray  #: (3, 3): columns t1, t2, n in the world frame
    compression_impulse: float  #: N s
    stop_impulse: float  #: N s (NaN if the slip never stopped)
    final_impulse: float  #: the normal impulse at the end, N s
    sequence: str  #: the phases, as :attr:`RigidImpact.regime` names them


def rigid_history(body: RigidBody, velocity: Any, spin: Any, *, mu: Any, kappa: Any,
                  law: str = "poisson", surface: Surface | None = None,
                  points: int = 400) -> RigidHistory:  # fmt: skip
    """The process of one impact of :func:`solve_rigid` over the normal impulse, at
    ``points`` impulses from 0 to the end (and at the stop and the end of compression).

    Raises
    ------
    ValueError
        For more than one impact (it follows one).
    """
    from ..core import rigid3d

    one = solve_rigid(body, velocity, spin, mu=mu, kappa=kappa, law=law, surface=surface)
    if np.ndim(one.normal_impulse) != 0:
        raise ValueError("rigid_history follows one impact: give one body, velocity and spin")
    surface = Surface() if surface is None else surface
    axes = rigid3d.frame(surface.normal)
    matrix = np.swapaxes(axes, -1, -2) @ body.matrix() @ axes
    before = np.einsum("...ji,...j->...i", axes, one.contact_before.array)
    end = float(one.normal_impulse)
    marks = [float(one.compression_impulse), float(one.stop_impulse)]
    grid = np.unique(np.concatenate([np.linspace(0.0, end, int(points)),
                                     [m for m in marks if np.isfinite(m)]]))  # fmt: skip
    states = rigid3d.contact_impact(matrix, before, float(mu), float(kappa), law, p_max=grid)
    return RigidHistory(
        normal_impulse=grid, slip=states.velocity[:, :2], normal_velocity=states.velocity[:, 2],
        axes=np.asarray(axes), compression_impulse=marks[0], stop_impulse=marks[1],
        final_impulse=end, sequence=str(one.regime),
    )  # fmt: skip
