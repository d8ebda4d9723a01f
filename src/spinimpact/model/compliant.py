"""Impacts under a tangential compliance law: :class:`CompliantImpact` (the paper's bodies,
``solve(..., tangential=law)``) and :class:`CompliantSphereImpact` (3D spheres,
``solve_sphere(..., tangential=law)``).

The law gives the slip after the impact, ``c_t^+ = -beta c_t^-``
(:mod:`spinimpact.core.compliance`); the friction impulse ``f_1 = m (c_t^+ - c_t^-)/zeta``
goes back to the body as in the rigid law, and the normal problem is the rigid one
(``c_n^+ = -kappa c_n^-``, ``tau_1 = (1 + kappa) tau_0``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import broadcast, validated
from ..core import compliance as laws
from ..core import sphere3d as kernels
from .body import Body
from .impact import State, _restitution
from .result import Array, Result, freeze, regime_counts
from .sphere3d import (
    State3,
    Surface,
    Vector,
    _incidence,
    _spin_components,
    _state,
    _summary,
    _vector,
    _xyz,
)

__all__ = ["CompliantImpact", "CompliantSphereImpact", "solve_compliant", "solve_sphere_compliant"]


def _ratio(num: Any, den: Any) -> np.ndarray:
    """``num/den``, NaN where ``den = 0``."""
    den = np.asarray(den)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(den != 0, num / np.where(den != 0, den, 1.0), np.nan)


def _regime(slip: Any, slip_after: Any, mu: Any, stuck: Any, law: Any) -> Array:
    code = laws.compliant_regime_code(
        slip, slip_after, mu, stuck, getattr(law, "frictionless", False)
    )
    return freeze(np.asarray(laws.COMPLIANT_REGIMES)[code])


@dataclass(frozen=True, eq=False)
class CompliantImpact(Result):
    """The impact of one of the paper's bodies under a tangential compliance law.

    The names of :class:`~spinimpact.Impact` where they mean the same; units SI.

    Attributes
    ----------
    body : Body
    law : TangentialLaw
        The law (:class:`~spinimpact.Walton`, :class:`~spinimpact.Stronge` or
        :class:`~spinimpact.MindlinDeresiewicz`).
    mu, kappa : float or ndarray
    before, after : State
        Incidence and rebound ``(vx, vy, omega)``.
    slip_before, slip_after : float or ndarray
        Contact-point slip ``u^- = vx + R omega`` and ``u^+``, m/s.
    tangential_restitution : float or ndarray
        ``beta = -u^+/u^-`` (NaN for ``u^- = 0``).
    centre_tangential_restitution : float or ndarray
        ``e_t = vx^+/vx^-`` of the centre (NaN for ``vx^- = 0``), as Kharaz et al. measure.
    regime : str or ndarray of str
        ``frictionless``, ``no-slip``, ``stick``, ``slip-reversal`` or ``slip``
        (:data:`~spinimpact.core.compliance.COMPLIANT_REGIMES`).
    tau0, tau1 : float or ndarray
        Normal impulse at the end of compression and of the impact, N s.
    tangential_impulse, impulse_ratio : float or ndarray
        ``f_1``, N s, and ``f_1/tau_1``.
    kinetic_energy_before, kinetic_energy_after, dissipated_energy, dissipated_fraction
        ``E^-``, ``E^+``, ``E^- - E^+`` (J) and its share of ``E^-``.
    newton_restitution : float or ndarray
        ``-vy^+/vy^-`` (``= kappa``).
    """

    body: Body
    law: object
    mu: Array
    kappa: Array
    before: State
    after: State
    slip_before: Array
    slip_after: Array
    tangential_restitution: Array
    centre_tangential_restitution: Array
    regime: Array
    tau0: Array
    tau1: Array
    tangential_impulse: Array
    impulse_ratio: Array
    kinetic_energy_before: Array
    kinetic_energy_after: Array
    dissipated_energy: Array
    dissipated_fraction: Array
    newton_restitution: Array

    _shape_field = "tau1"

    def __repr__(self) -> str:
        if self.shape != ():
            summary = regime_counts(self.regime)
            return f"<CompliantImpact of shape {self.shape} ({self.law!r}): {summary}>"
        a = self.after
        return (
            f"<CompliantImpact {self.regime} ({self.law!r}): after vx={a.vx:.6g} m/s, "
            f"vy={a.vy:.6g} m/s, omega={a.omega:.6g} rad/s; "
            f"beta={self.tangential_restitution:.6g}>"
        )


def solve_compliant(law: Any, body: Body, vx: Any, vy: Any, omega: Any, *, mu: Any,
                    kappa: Any) -> CompliantImpact:  # fmt: skip
    """:func:`~spinimpact.solve` under a tangential compliance ``law`` (validated as there)."""
    if not isinstance(body, Body):
        raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    vx_, vy_, om_, mu_ = (
        validated(n, v) for n, v in (("vx", vx), ("vy", vy), ("omega", omega), ("mu", mu))
    )
    kappa_ = _restitution(kappa, vy_)
    vx_, vy_, om_, mu_, kappa_, m, r, g, zeta = broadcast(
        vx=vx_, vy=vy_, omega=om_, mu=mu_, kappa=kappa_, mass=np.asarray(body.mass),
        radius=np.asarray(body.radius), gyration=np.asarray(body.gyration),
        zeta=np.asarray(body.zeta),
    )  # fmt: skip
    law.check_kappa(kappa_)
    inertia = m * g**2
    slip = core.slip_velocity(vx_, om_, r)
    slip1, stuck = law.rebound_slip(slip, vy_, zeta, mu_, kappa_)
    f1 = laws.tangential_impulse_of(m, zeta, slip, slip1)
    vx1, om1 = laws.impulse_to_body(vx_, om_, m, r, zeta, f1)
    vy1 = core.rebound_normal_velocity(vy_, kappa_)
    tau0 = core.compression_impulse(m, vy_)
    tau1 = core.total_impulse(m, vy_, kappa_)
    e0 = core.kinetic_energy(vx_, vy_, om_, m, inertia)
    e1 = core.kinetic_energy(vx1, vy1, om1, m, inertia)
    return CompliantImpact(
        body=body, law=law, mu=freeze(mu_), kappa=freeze(kappa_),
        before=State(freeze(vx_), freeze(vy_), freeze(om_)),
        after=State(freeze(vx1), freeze(vy1), freeze(om1)),
        slip_before=freeze(slip), slip_after=freeze(slip1),
        tangential_restitution=freeze(_ratio(-slip1, slip)),
        centre_tangential_restitution=freeze(_ratio(vx1, vx_)),
        regime=_regime(slip, slip1, mu_, stuck, law), tau0=freeze(tau0), tau1=freeze(tau1),
        tangential_impulse=freeze(f1), impulse_ratio=freeze(f1 / tau1),
        kinetic_energy_before=freeze(e0), kinetic_energy_after=freeze(e1),
        dissipated_energy=freeze(e0 - e1), dissipated_fraction=freeze((e0 - e1) / e0),
        newton_restitution=freeze(-vy1 / vy_),
    )  # fmt: skip


@dataclass(frozen=True, eq=False)
class CompliantSphereImpact(Result):
    """A sphere's impact in 3D under a tangential compliance law (the names of
    :class:`~spinimpact.SphereImpact` where they mean the same; units SI).

    The slip keeps its direction (the collision matrix is isotropic in the tangent plane),
    so the law acts along it: ``c_t^+ = -beta c_t^-`` as vectors.

    Attributes
    ----------
    before, after : State3
        Centre velocity and spin vector, before and after (ground frame).
    slip_before, slip_after : Vector
        Tangential velocity of the contact point relative to the surface, m/s.
    tangential_restitution : float or ndarray
        ``beta = -|c_t^+|/|c_t^-|`` signed: ``c_t^+ = -beta c_t^-`` (NaN for no slip).
    regime : str or ndarray of str
        As :class:`CompliantImpact`'s.
    friction_impulse : Vector
        ``F``, N s; ``impulse_ratio = |F|/tau_1``.
    dissipated_energy, dissipated_fraction
        Energy lost in the surface's frame (J), and its share of the kinetic energy there.
    rebound_speed, rebound_angle, topspin, sidespin, gyrospin
        As :class:`~spinimpact.SphereImpact`'s.
    """

    body: Body
    law: object
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
    tangential_restitution: Array
    regime: Array
    tau0: Array
    tau1: Array
    friction_impulse: Vector
    impulse_ratio: Array
    kinetic_energy_before: Array
    kinetic_energy_after: Array
    dissipated_energy: Array
    dissipated_fraction: Array
    newton_restitution: Array
    rebound_speed: Array
    rebound_angle: Array
    topspin: Array
    sidespin: Array
    gyrospin: Array

    _shape_field = "tau1"

    def __repr__(self) -> str:
        a = self.after
        return _summary(self, f"CompliantSphereImpact ({self.law!r})", lambda: (
            f"v={_xyz(a.velocity)} m/s, spin={_xyz(a.spin)} rad/s; "
            f"beta={self.tangential_restitution:.6g}"))  # fmt: skip


def solve_sphere_compliant(
    law: Any, body: Body, velocity: Any, spin: Any, *, mu: Any, kappa: Any,
    surface: Surface | None = None,
) -> CompliantSphereImpact:  # fmt: skip
    """:func:`~spinimpact.solve_sphere` under a tangential compliance ``law``."""
    if not isinstance(body, Body):
        raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    v, w, nrm, vs, m, radius, inertia, zeta, mu_, kappa_, c = _incidence(
        body, velocity, spin, mu, kappa, surface
    )
    law.check_kappa(kappa_)
    cn, speed = c.normal_velocity, c.slip_speed
    speed1, stuck = law.rebound_slip(speed, cn, zeta, mu_, kappa_)  # signed, along c_t^-
    f1 = laws.tangential_impulse_of(m, zeta, speed, speed1)
    friction = np.asarray(f1)[..., None] * c.direction
    tau1 = core.total_impulse(m, cn, kappa_)
    v1 = v + (np.asarray(tau1)[..., None] * nrm + friction) / m[..., None]
    w1 = w + kernels.sphere_spin_change(nrm, radius, inertia, friction)
    c1 = kernels.sphere_contact(v1, w1, nrm, radius, vs)
    e0 = 0.5 * m * kernels.dot(v, v) + 0.5 * inertia * kernels.dot(w, w)
    e1 = 0.5 * m * kernels.dot(v1, v1) + 0.5 * inertia * kernels.dot(w1, w1)
    rel0, rel = v - vs, v1 - vs  # the surface's frame sees the energy the impact dissipates
    e0_rel = 0.5 * m * kernels.dot(rel0, rel0) + 0.5 * inertia * kernels.dot(w, w)
    loss = e0_rel - (0.5 * m * kernels.dot(rel, rel) + 0.5 * inertia * kernels.dot(w1, w1))
    along = rel - kernels.dot(rel, nrm)[..., None] * nrm
    top, side, gyro = _spin_components(nrm, along, w1)
    return CompliantSphereImpact(
        body=body, law=law, mu=freeze(mu_), kappa=freeze(kappa_), normal=_vector(nrm),
        surface_velocity=_vector(vs), before=_state(v, w), after=_state(v1, w1),
        slip_before=_vector(c.slip),
        slip_after=_vector(np.asarray(speed1)[..., None] * c.direction),
        normal_velocity_before=freeze(cn), normal_velocity_after=freeze(c1.normal_velocity),
        tangential_restitution=freeze(_ratio(-speed1, speed)),
        regime=_regime(speed, speed1, mu_, stuck, law),
        tau0=freeze(core.compression_impulse(m, cn)), tau1=freeze(tau1),
        friction_impulse=_vector(friction),
        impulse_ratio=freeze(np.abs(f1) / tau1), kinetic_energy_before=freeze(e0),
        kinetic_energy_after=freeze(e1), dissipated_energy=freeze(loss),
        dissipated_fraction=freeze(loss / e0_rel),
        newton_restitution=freeze(-c1.normal_velocity / cn),
        rebound_speed=freeze(np.sqrt(kernels.dot(v1, v1))),
        rebound_angle=freeze(np.arctan2(kernels.dot(rel, nrm), np.sqrt(kernels.dot(along, along)))),
        topspin=freeze(top), sidespin=freeze(side), gyrospin=freeze(gyro),
    )  # fmt: skip
