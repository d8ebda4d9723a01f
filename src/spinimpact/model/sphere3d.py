"""``solve_sphere()``: a spinning sphere on a fixed, moving or tilted plane, in 3D.

Axes: ``x`` along the surface, ``y`` up along its normal, ``z = x cross y`` (out of the page).
A 3D impact in the ``x, y`` plane with ``spin = (0, 0, omega)`` is the paper's problem and
gives :func:`~spinimpact.solve`'s numbers to rounding. The physics is in
:mod:`spinimpact.core.sphere3d`: the slip keeps its direction, so the scalar seam holds
along it, and the spin about the normal is unchanged.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import approach, check, validated, vector3, whole
from ..core import sphere3d as kernels
from . import _fast_sphere, _fused_sphere
from ._hooks import tangential_law
from .body import Body, as_body, check_sphere
from .impact import _restitution
from .result import Array, Result, freeze, regime_counts

__all__ = ["Vector", "State3", "Surface", "SphereImpact", "SphereHistory", "solve_sphere"]


@dataclass(frozen=True, eq=False)
class Vector(Result):
    """A 3-vector (or an array of them) by components."""

    x: Array
    y: Array
    z: Array

    _column_prefix = True

    @property
    def array(self) -> np.ndarray:
        """The components stacked on a last axis of length 3."""
        return np.stack([np.asarray(self.x), np.asarray(self.y), np.asarray(self.z)], axis=-1)


@dataclass(frozen=True, eq=False)
class State3(Result):
    """Velocity of the centre (m/s) and spin vector (rad/s) of a sphere."""

    vx: Array
    vy: Array
    vz: Array
    wx: Array
    wy: Array
    wz: Array

    @property
    def velocity(self) -> np.ndarray:
        return np.stack([np.asarray(self.vx), np.asarray(self.vy), np.asarray(self.vz)], -1)

    @property
    def spin(self) -> np.ndarray:
        return np.stack([np.asarray(self.wx), np.asarray(self.wy), np.asarray(self.wz)], -1)


def _xyz(vector: Any) -> str:
    return "(" + ", ".join(f"{float(x) + 0.0:.6g}" for x in vector) + ")"


def _summary(imp: Result, name: str, text: Callable[[], str]) -> str:
    """The one-line repr of a 3D impact result: the regime counts of an array, or of one
    impact its regime and ``text()`` (its rebound; ``name`` may carry a law)."""
    if imp.shape != ():
        return f"<{name} of shape {imp.shape}: {regime_counts(imp.regime)}>"  # type: ignore[attr-defined]
    return f"<{name} {imp.regime}: after {text()}>"  # type: ignore[attr-defined]


def _state(v: np.ndarray, w: np.ndarray) -> State3:
    return State3(*(freeze(v[..., i]) for i in range(3)), *(freeze(w[..., i]) for i in range(3)))


def _vector(a: np.ndarray) -> Vector:
    return Vector(*(freeze(a[..., i]) for i in range(3)))


@dataclass(frozen=True, eq=False)
class Surface:
    """A plane surface: its outward unit normal and the velocity of its material.

    Parameters
    ----------
    normal : array_like, shape (..., 3)
        Outward normal (any length > 0; it is normalised). Default ``(0, 1, 0)``.
    velocity : array_like, shape (..., 3)
        Velocity of the surface (a racket, paddle or belt), m/s; the surface is rigid and
        of infinite mass, so the impact is solved in its frame and reported in the
        ground's. Default at rest.
    """

    normal: Any = (0.0, 1.0, 0.0)
    velocity: Any = (0.0, 0.0, 0.0)

    def __post_init__(self) -> None:
        n = vector3("normal", self.normal)
        length = np.sqrt(np.sum(n * n, axis=-1))
        check("the length of normal", length, lambda x: x > 1e-12, "> 0 (a direction)")
        object.__setattr__(self, "normal", n / length[..., None])
        object.__setattr__(self, "velocity", vector3("surface velocity", self.velocity))


@dataclass(frozen=True, eq=False)
class SphereHistory(Result):
    """The process of one sphere impact over the normal impulse ``tau``."""

    tau: np.ndarray  #: normal impulse, N s
    velocity: np.ndarray  #: centre velocity, (n, 3), m/s
    spin: np.ndarray  #: spin vector, (n, 3), rad/s
    slip_speed: np.ndarray  #: ``|c_t|``, m/s
    normal_velocity: np.ndarray  #: c_n, m/s
    force_ratio: np.ndarray  #: ``|F|/N`` while slipping, 0 once stuck
    friction_magnitude: np.ndarray  #: ``|F(tau)|``, N s
    kinetic_energy: np.ndarray  #: E(tau), J (ground frame)
    tau0: float
    tau_star: float
    tau1: float

    _per_impact = False
    _shape_field = "tau"


@dataclass(frozen=True, eq=False)
class SphereImpact(Result):
    """Everything :func:`solve_sphere` computes (the names of :class:`~spinimpact.Impact`
    where they mean the same). Vectors are :class:`Vector` and :class:`State3` results
    (``imp.after.velocity`` stacks them); units SI.

    Attributes
    ----------
    slip_before, slip_after : Vector
        Tangential velocity of the contact point relative to the surface, m/s.
    regime : str
        As :func:`~spinimpact.solve`'s, along the (fixed) slip direction.
    friction_impulse : Vector
        ``F``, N s; ``impulse_ratio = |F|/tau_1``.
    dissipated_energy : energy lost in the surface's frame, ``-(W^n + W^t) >= 0``, J
        (kinetic energies are reported in the ground frame); ``dissipated_fraction`` is its
        share of the kinetic energy in the surface's frame.
    rebound_speed : ``|v^+|``, m/s; ``rebound_angle``: angle of ``v^+ - V_s`` above the
        surface, rad.
    topspin, sidespin, gyrospin : spin after about ``n x e_t`` (positive: rolling forward),
        about ``n`` and about ``e_t``, rad/s, with ``e_t`` the direction of travel along the
        surface after the impact (NaN for topspin and gyrospin when there is none).
    grips : bool
        The ball leaves without slip (``c_t^+ = 0``); otherwise it skids.
    """

    body: Body
    mu: Array
    kappa: Array
    normal: Vector
    surface_velocity: Vector
    before: State3
    after: State3
    slip_before: Vector
    slip_after: Vector
    normal_velocity_before: Array
    normal_velocity_after: Array
    regime: Array
    tau0: Array
    tau_star: Array
    tau1: Array
    friction_impulse: Vector
    impulse_ratio: Array
    kinetic_energy_before: Array
    kinetic_energy_after: Array
    dissipated_energy: Array
    dissipated_fraction: Array
    work_compression_normal: Array
    work_compression_tangential: Array
    work_restitution_normal: Array
    work_restitution_tangential: Array
    newton_restitution: Array
    poisson_restitution: Array
    energetic_restitution: Array
    rebound_speed: Array
    rebound_angle: Array
    topspin: Array
    sidespin: Array
    gyrospin: Array
    grips: Array

    _shape_field = "tau1"

    def __repr__(self) -> str:
        a = self.after
        return _summary(self, "SphereImpact", lambda: (
            f"v={_xyz(a.velocity)} m/s, spin={_xyz(a.spin)} rad/s; "
            f"dissipated {self.dissipated_energy:.6g} J"))  # fmt: skip

    def history(self, n: int = 201) -> SphereHistory:
        """The process over ``tau`` (one impact): ``n`` points on ``[0, tau_1]`` plus
        ``tau_0`` and ``tau_*``."""
        if self.shape != ():
            raise ValueError(
                f"history() describes one impact, but this SphereImpact has shape {self.shape};"
                " select one with impact[i]"
            )
        n = whole("n", n, 2)
        t0, ts, t1 = float(self.tau0), float(self.tau_star), float(self.tau1)
        grid = np.union1d(np.linspace(0.0, t1, n), [t for t in (t0, ts) if 0 < t < t1])
        b = self.body
        speed = float(np.sqrt(np.sum(self.slip_before.array**2)))
        direction = self.slip_before.array / speed if speed > 0 else np.zeros(3)
        f = core.friction_impulse_at(grid, b.mass, speed, b.zeta, self.mu)  # <= 0
        friction = f[:, None] * direction
        nrm = self.normal.array
        v = self.before.velocity + (grid[:, None] * nrm + friction) / b.mass
        w = self.before.spin + kernels.sphere_spin_change(nrm, b.radius, b.inertia, friction)
        energy = 0.5 * b.mass * np.sum(v * v, -1) + 0.5 * b.inertia * np.sum(w * w, -1)
        return SphereHistory(
            tau=grid, velocity=v, spin=w,
            slip_speed=core.slip_at(grid, b.mass, speed, b.zeta, self.mu) * np.sign(speed),
            normal_velocity=float(self.normal_velocity_before) + grid / b.mass,
            force_ratio=np.abs(core.force_ratio_at(grid, b.mass, speed, b.zeta, self.mu)),
            friction_magnitude=-f, kinetic_energy=energy, tau0=t0, tau_star=ts, tau1=t1,
        )  # fmt: skip


def _spin_components(normal, travel, spin):
    """Topspin, sidespin, gyrospin of ``spin`` for travel along ``travel`` (tangent)."""
    speed = np.sqrt(np.sum(travel * travel, -1))
    with np.errstate(invalid="ignore", divide="ignore"):
        e = np.where(
            speed[..., None] > 0, travel / np.where(speed > 0, speed, 1)[..., None], np.nan
        )
    top = kernels.dot(spin, kernels.cross(normal, e))
    return top, kernels.dot(spin, normal), kernels.dot(spin, e)


def _incidence(body, velocity, spin, mu, kappa, surface):
    """Validated, broadcast inputs of one or many sphere impacts and their contact
    (``kernels.sphere_contact``), refusing a contact point that does not approach:
    ``(v, w, normal, surface_velocity, m, radius, inertia, zeta, mu, kappa, contact)``."""
    check_sphere(body)
    surface = Surface() if surface is None else surface
    if not isinstance(surface, Surface):
        raise TypeError(f"surface must be a spinimpact.Surface, got {type(surface).__name__}")
    v, w, mu_ = vector3("velocity", velocity), vector3("spin", spin), validated("mu", mu)
    nrm, vs = surface.normal, surface.velocity
    parts = [np.asarray(x) for x in (body.mass, body.radius, body.inertia, body.zeta)]
    given = [] if callable(kappa) else [np.shape(kappa)]
    shape = np.broadcast_shapes(v.shape[:-1], w.shape[:-1], nrm.shape[:-1], vs.shape[:-1],
                                mu_.shape, *(x.shape for x in parts), *given)  # fmt: skip
    v, w, nrm, vs = (np.broadcast_to(x, (*shape, 3)) for x in (v, w, nrm, vs))
    m, radius, inertia, zeta, mu_ = (np.broadcast_to(x, shape) for x in (*parts, mu_))
    c = kernels.sphere_contact(v, w, nrm, radius, vs)
    approach("the contact point's normal velocity", c.normal_velocity,
             "the sphere must approach the surface")  # fmt: skip
    kappa_ = np.broadcast_to(_restitution(kappa, c.normal_velocity), shape)
    return v, w, nrm, vs, m, radius, inertia, zeta, mu_, kappa_, c


def solve_sphere(
    body: Body, velocity: Any, spin: Any, *, mu: Any, kappa: Any,
    surface: Surface | None = None, tangential: Any = None,
) -> SphereImpact:  # fmt: skip
    """Solve the frictional impact of a spinning sphere on a plane, in 3D.

    Parameters
    ----------
    body : Body
        The sphere: mass, radius and radius of gyration (``Body.solid_sphere``,
        ``Body.spherical_shell``, or any gyration for a thick shell).
    velocity : array_like, shape (..., 3)
        Centre velocity before the impact, m/s (ground frame).
    spin : array_like, shape (..., 3)
        Spin vector before the impact, rad/s (right-handed).
    mu : float or array_like
        Coulomb friction coefficient, ``>= 0``.
    kappa : float, array_like or callable
        Coefficient of restitution in ``[0, 1]``, or a model of the normal impact speed.
    surface : Surface, optional
        The plane's normal and velocity; by default ``y = 0`` at rest.
    tangential : Walton, Stronge or MindlinDeresiewicz, optional
        A tangential compliance law; the result is then a
        :class:`~spinimpact.CompliantSphereImpact` with the law's tangential restitution.

    Returns
    -------
    SphereImpact

    Raises
    ------
    TypeError
        A ``body`` that is not a :class:`~spinimpact.Body`, a ``surface`` that is not a
        :class:`Surface`, or inputs that are not numbers.
    ValueError
        Vectors without 3 components, a zero-length normal, non-finite values, a body that
        cannot be a sphere (a radius of gyration above a thin shell's ``sqrt(2/3) R``:
        :func:`~spinimpact.model.body.check_sphere`), or a contact point that does not
        approach the surface at ``1e-50`` m/s or faster (as :func:`~spinimpact.solve`
        refuses ``|vy| < 1e-50``).

    Examples
    --------
    A tennis ball with side spin: the spin about the normal survives the bounce.

    >>> from spinimpact import Body, solve_sphere
    >>> ball = Body.spherical_shell(mass=0.057, radius=0.033)
    >>> imp = solve_sphere(ball, velocity=[20.0, -8.0, 3.0], spin=[0.0, 150.0, -200.0],
    ...                    mu=0.6, kappa=0.75)
    >>> str(imp.regime), float(imp.after.wy)
    ('stick-restitution', 150.0)
    """
    body = as_body(body)
    if tangential is not None:  # the law solves it (spinimpact.model.compliance)
        return tangential_law(tangential)._solve_sphere(body, velocity, spin, mu=mu,
                                                        kappa=kappa, surface=surface)  # fmt: skip
    check_sphere(body)  # before the fast path, which skips _incidence (it checks too)
    kinds = (SphereImpact, State3, Vector, Surface)
    one = _fast_sphere.sphere_impact(body, velocity, spin, mu, kappa, surface, kinds)
    if one is not None:  # one impact of plain numbers: the same SphereImpact, in microseconds
        return one
    many = _fused_sphere.sphere_impact(body, velocity, spin, mu, kappa, surface, kinds)
    if many is not None:  # many impacts: every field from one compiled pass, bit for bit
        return many
    v, w, nrm, vs, m, radius, inertia, zeta, mu_, kappa_, c = _incidence(
        body, velocity, spin, mu, kappa, surface
    )
    cn, speed = c.normal_velocity, c.slip_speed
    r = kernels.sphere_rebound(c, nrm, m, zeta, mu_, kappa_)
    v1 = v + r.impulse / m[..., None]
    w1 = w + kernels.sphere_spin_change(nrm, radius, inertia, r.friction)
    c1 = kernels.sphere_contact(v1, w1, nrm, radius, vs)
    works = core.contact_phase_works(speed, cn, m, zeta, mu_, kappa_)
    loss = core.contact_dissipated_energy(speed, cn, m, zeta, mu_, kappa_)
    e0 = 0.5 * m * kernels.dot(v, v) + 0.5 * inertia * kernels.dot(w, w)
    e1 = 0.5 * m * kernels.dot(v1, v1) + 0.5 * inertia * kernels.dot(w1, w1)
    vrel = v - vs  # the energy the surface's frame sees, which the impact dissipates from
    e0_rel = 0.5 * m * kernels.dot(vrel, vrel) + 0.5 * inertia * kernels.dot(w, w)
    tau0 = core.compression_impulse(m, cn)
    kappas = core.restitution_by_definition(
        cn, c1.normal_velocity, tau0, r.normal_impulse,
        works.compression_normal, works.restitution_normal,
    )  # fmt: skip
    rel = v1 - vs
    along = rel - kernels.dot(rel, nrm)[..., None] * nrm
    top, side, gyro = _spin_components(nrm, along, w1)
    stuck = core.sticks(speed, cn, zeta, mu_, kappa_)
    return SphereImpact(
        body=body, mu=freeze(mu_), kappa=freeze(kappa_), normal=_vector(nrm),
        surface_velocity=_vector(vs), before=_state(v, w), after=_state(v1, w1),
        slip_before=_vector(c.slip), slip_after=_vector(np.where(stuck[..., None], 0.0, c1.slip)),
        normal_velocity_before=freeze(cn), normal_velocity_after=freeze(c1.normal_velocity),
        regime=freeze(np.asarray(core.REGIMES)[core.regime_code(speed, cn, zeta, mu_, kappa_)]),
        tau0=freeze(tau0), tau_star=freeze(core.stick_impulse(m, speed, zeta, mu_)),
        tau1=freeze(r.normal_impulse), friction_impulse=_vector(r.friction),
        impulse_ratio=freeze(r.friction_magnitude / r.normal_impulse),
        kinetic_energy_before=freeze(e0), kinetic_energy_after=freeze(e1),
        dissipated_energy=freeze(loss), dissipated_fraction=freeze(loss / e0_rel),
        work_compression_normal=freeze(works.compression_normal),
        work_compression_tangential=freeze(works.compression_tangential),
        work_restitution_normal=freeze(works.restitution_normal),
        work_restitution_tangential=freeze(works.restitution_tangential),
        newton_restitution=freeze(kappas.newton), poisson_restitution=freeze(kappas.poisson),
        energetic_restitution=freeze(kappas.energetic),
        rebound_speed=freeze(np.sqrt(kernels.dot(v1, v1))),
        rebound_angle=freeze(np.arctan2(kernels.dot(rel, nrm), np.sqrt(kernels.dot(along, along)))),
        topspin=freeze(top), sidespin=freeze(side), gyrospin=freeze(gyro), grips=freeze(stuck),
    )  # fmt: skip
