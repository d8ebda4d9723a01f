"""``solve_planar()``: the exact single-point impact of any planar rigid body.

The contact may lie anywhere on the body (:class:`~spinimpact.model.planar_body.PlanarBody`);
the normal and tangential impulses then couple through the collision matrix, slip can
stop, stick or reverse, and Newton's, Poisson's and Stronge's restitution laws differ
(:mod:`spinimpact.core.planar`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import approach, as_real_array, broadcast, validated, whole
from ..core import planar as kernels
from . import _fast_planar, _fused_planar
from .impact import State, _restitution
from .planar_body import Pendulum, PlanarBody
from .result import Array, Result, freeze, regime_counts

__all__ = [
    "PlanarImpact",
    "PendulumImpact",
    "PlanarHistory",
    "solve_planar",
    "solve_pendulum",
    "LAWS",
]

#: Restitution laws :func:`solve_planar` accepts.
LAWS = kernels.LAWS

#: Energy gains smaller than this fraction of the incidence energy are rounding
#: (the energy balance sums a handful of terms of that size).
_ENERGY_RTOL = 1e-12


@dataclass(frozen=True, eq=False)
class PlanarHistory(Result):
    """The process of one planar impact over the normal impulse ``tau``."""

    tau: np.ndarray  #: normal impulse, N s
    vx: np.ndarray  #: centre velocity along the surface, m/s
    vy: np.ndarray  #: centre normal velocity, m/s
    omega: np.ndarray  #: spin, rad/s
    slip: np.ndarray  #: tangential velocity of the contact point, m/s
    normal_velocity: np.ndarray  #: normal velocity of the contact point, m/s
    force_ratio: np.ndarray  #: F/N
    tangential_impulse: np.ndarray  #: f(tau), N s
    kinetic_energy: np.ndarray  #: E(tau), J
    tau0: float
    tau_star: float
    tau1: float

    _per_impact = False
    _shape_field = "tau"


@dataclass(frozen=True, eq=False)
class PlanarImpact(Result):
    """Everything :func:`solve_planar` computes about a planar impact (or an array of them).

    The fields share :class:`~spinimpact.Impact`'s names where they mean the same:
    ``tau0`` ends compression (the contact's normal velocity vanishes), ``tau_star`` is
    where the slip stops (``0`` without initial slip, ``inf`` if it never stops) and
    ``tau1`` ends the impact under ``law``. Units are SI.

    Attributes
    ----------
    law : str
        ``newton``, ``poisson`` or ``energetic`` (Stronge).
    slip_before, slip_after : tangential velocity of the contact point, m/s.
    normal_velocity_before, normal_velocity_after : its normal velocity, m/s.
    regime : str
        One of :data:`~spinimpact.core.planar.PLANAR_REGIMES`.
    newton_restitution, poisson_restitution, energetic_restitution :
        ``-v^+/v^-``, ``(tau_1 - tau_0)/tau_0`` and ``sqrt(-W_r^n/W_c^n)`` of the contact
        point, each by its own definition: they differ when the impulses couple.
    creates_energy : bool
        The law gave the body more kinetic energy than it had (possible under Newton's law).
    """

    body: PlanarBody
    law: str
    mu: Array
    kappa: Array
    before: State
    after: State
    slip_before: Array
    slip_after: Array
    normal_velocity_before: Array
    normal_velocity_after: Array
    regime: Array
    tau0: Array
    tau_star: Array
    tau1: Array
    tangential_impulse: Array
    impulse_ratio: Array
    kinetic_energy_before: Array
    kinetic_energy_after: Array
    dissipated_energy: Array
    dissipated_fraction: Array
    work_compression_normal: Array
    work_compression_tangential: Array
    work_restitution_normal: Array
    work_restitution_tangential: Array
    min_kinetic_energy: Array
    tau_min_energy: Array
    newton_restitution: Array
    poisson_restitution: Array
    energetic_restitution: Array
    creates_energy: Array

    _shape_field = "tau1"

    def __getitem__(self, index: Any) -> PlanarImpact:
        imp = super().__getitem__(index)
        b = self.body
        parts = {n: getattr(b, n) for n in b.COLUMNS}
        if any(np.ndim(x) for x in parts.values()):
            parts = {n: np.broadcast_to(x, self.shape)[index] for n, x in parts.items()}
            b = type(b)(**parts, name=b.name)
        return dataclasses.replace(imp, body=b)

    def history(self, n: int = 201) -> PlanarHistory:
        """The process over the normal impulse: ``n`` even points on ``[0, tau_1]`` plus the
        breakpoints ``tau_0`` and ``tau_*``. Only for a single impact."""
        if self.shape != ():
            raise ValueError(
                f"history() describes one impact, but this PlanarImpact has shape {self.shape};"
                " select one with impact[i]"
            )
        n = whole("n", n, 2)
        t0, ts, t1 = float(self.tau0), float(self.tau_star), float(self.tau1)
        grid = np.union1d(np.linspace(0.0, t1, int(n)), [t for t in (t0, ts) if 0 < t < t1])
        b, w = self.body, self.body.collision_matrix
        args = (self.slip_before, self.normal_velocity_before, w.tt, w.tn, w.nn, self.mu)
        st = kernels.planar_state_at(grid, *args, self.tau_star)
        before = (self.before.vx, self.before.vy, self.before.omega)
        vx, vy, om = b.apply_impulse(*before, st.friction_impulse, grid)
        return PlanarHistory(
            tau=grid,
            vx=vx,
            vy=vy,
            omega=om,
            slip=st.slip,
            normal_velocity=st.normal,
            force_ratio=st.force_ratio,
            tangential_impulse=st.friction_impulse,
            kinetic_energy=b.kinetic_energy(vx, vy, om),
            tau0=t0,
            tau_star=ts,
            tau1=t1,
        )

    def __repr__(self) -> str:
        if self.shape != ():
            summary = regime_counts(self.regime)
            return f"<PlanarImpact ({self.law}) of shape {self.shape}: {summary}>"
        a = self.after
        return (
            f"<PlanarImpact {self.regime} ({self.law}): after vx={a.vx:.6g} m/s, "
            f"vy={a.vy:.6g} m/s, omega={a.omega:.6g} rad/s; dissipated "
            f"{self.dissipated_energy:.6g} J>"
        )


@dataclass(frozen=True, eq=False, repr=False)
class PendulumImpact(PlanarImpact):
    """A :class:`PlanarImpact` whose body is a :class:`~spinimpact.Pendulum`
    (:func:`solve_pendulum`); ``before``/``after`` give its centre of mass's velocity."""

    body: Pendulum  # type: ignore[assignment]


def solve_planar(
    body: PlanarBody, vx: Any, vy: Any, omega: Any, *, mu: Any, kappa: Any, law: str = "poisson"
) -> PlanarImpact:
    """Solve the frictional impact of a planar rigid body touching the surface at one point.

    Parameters
    ----------
    body : PlanarBody
        Mass, moment of inertia and contact offset (any of them arrays).
    vx, vy : float or array_like
        Velocity of the centre of mass before the impact, m/s.
    omega : float or array_like
        Spin before the impact, rad/s, counter-clockwise positive.
    mu : float or array_like
        Coulomb friction coefficient, ``>= 0``.
    kappa : float, array_like or callable
        Coefficient of restitution of ``law``, in ``[0, 1]``, or a model of the contact
        point's impact speed ``|v^-|``.
    law : {"poisson", "newton", "energetic"}
        Poisson's kinetic law (the paper's, the default), Newton's kinematic law or
        Stronge's energetic law.

    Returns
    -------
    PlanarImpact

    Raises
    ------
    TypeError
        A ``body`` that is not a :class:`PlanarBody`, a ``law`` that is not a string, or
        an input that is not a real number.
    ValueError
        Bad values; the contact point must approach the surface (``v^- < 0``).

    Examples
    --------
    >>> import math
    >>> from spinimpact import PlanarBody, solve_planar
    >>> rod = PlanarBody.rod(mass=1.0, length=1.0, angle=math.radians(60))
    >>> imp = solve_planar(rod, vx=0.0, vy=-1.0, omega=0.0, mu=0.5, kappa=0.5, law="newton")
    >>> str(imp.regime), round(float(imp.newton_restitution), 12)
    ('no-slip', 0.5)
    """
    if not isinstance(body, PlanarBody):
        raise TypeError(f"body must be a spinimpact.PlanarBody, got {type(body).__name__}")
    return _solve(PlanarImpact, body, vx, vy, omega, mu, kappa, law)


def solve_pendulum(
    pendulum: Pendulum, omega: Any, *, mu: Any, kappa: Any, law: str = "poisson"
) -> PlanarImpact:
    """Solve the impact of a rigid pendulum, on a fixed frictionless pivot, on the surface.

    Parameters
    ----------
    pendulum : Pendulum
        Mass, inertia, centre of mass and contact point relative to the pivot.
    omega : float or array_like
        Spin before the impact, rad/s, counter-clockwise positive; the contact point
        must approach the surface (``omega px < 0``).
    mu, kappa, law
        As for :func:`solve_planar`.

    Returns
    -------
    PendulumImpact
        A :class:`PlanarImpact` with the pendulum as its body; ``before``/``after``
        give the centre of mass's velocity and the spin.

    Notes
    -----
    The collision matrix has rank one, so the contact's slip and normal velocity vanish
    together, at the end of compression. Then either the friction cone holds the
    contact and the pendulum stops (``locked``), or the slip reverses for the
    restitution phase; in the second case the energetic coefficient is the geometric
    mean of Newton's and Poisson's, ``eta^2 = kappa_N kappa_P`` (the normal velocity
    rises at one rate in compression and another in restitution).

    Examples
    --------
    >>> import math
    >>> from spinimpact import Pendulum, solve_pendulum
    >>> p = Pendulum.rod(mass=1.0, length=1.0, angle=math.radians(60))
    >>> imp = solve_pendulum(p, omega=-2.0, mu=0.2, kappa=0.8, law="poisson")
    >>> str(imp.regime)
    'reverse-compression'
    >>> kn, kp, eta = (float(x) for x in (imp.newton_restitution, imp.poisson_restitution,
    ...                                   imp.energetic_restitution))
    >>> round(eta**2 - kn * kp, 12)
    0.0
    """
    if not isinstance(pendulum, Pendulum):
        raise TypeError(f"pendulum must be a spinimpact.Pendulum, got {type(pendulum).__name__}")
    one = _fast_planar.pendulum_impact(PendulumImpact, State, pendulum, omega, mu, kappa, law)
    if one is not None:  # one impact of plain numbers: the same result, in microseconds
        return one
    om = as_real_array("omega", omega)
    vx, vy = pendulum.centre_velocity(om)
    return _solve(PendulumImpact, pendulum, vx, vy, om, mu, kappa, law)


def _solve(kind, body, vx, vy, omega, mu, kappa, law):  # type: ignore[no-untyped-def]
    if not isinstance(law, str):
        raise TypeError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
    if law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
    one = _fast_planar.planar_impact(kind, State, body, vx, vy, omega, mu, kappa, law)
    if one is not None:  # one impact of plain numbers: the same result, in microseconds
        return one
    vx_, vy_, om_ = (as_real_array(n, v) for n, v in (("vx", vx), ("vy", vy), ("omega", omega)))
    mu_ = validated("mu", mu)
    parts = {n: np.asarray(getattr(body, n)) for n in body.COLUMNS}
    broadcast(vx=vx_, vy=vy_, omega=om_, mu=mu_, **parts)  # names the shapes if they clash
    u0, v0 = body.contact_velocity(vx_, vy_, om_)
    approach("the contact point's normal velocity", np.asarray(v0),
             "the contact point must approach the surface")  # fmt: skip
    kappa_ = _restitution(kappa, v0)
    w = body.collision_matrix
    u0, v0, mu_, kappa_, vx_, vy_, om_, a, b, d = np.broadcast_arrays(
        u0, v0, mu_, kappa_, vx_, vy_, om_, w.tt, w.tn, w.nn, *parts.values()
    )[:10]
    many = _fused_planar.planar_impact(kind, State, body, law, vx_, vy_, om_, u0, v0, a, b, d,
                                       mu_, kappa_)  # fmt: skip
    if many is not None:  # many impacts: every field from one compiled pass, bit for bit
        return many
    contact = (u0, v0, a, b, d, mu_)
    p = kernels.planar_process(*contact, kappa_, LAWS.index(law))
    vx1, vy1, om1 = body.apply_impulse(vx_, vy_, om_, p.friction_impulse, p.tau_end)
    zero = 0.0 * p.tau_end
    wcn, wct = kernels.planar_work(zero, p.tau_compression, *contact, p.tau_slip)
    wrn, wrt = kernels.planar_work(p.tau_compression, p.tau_end, *contact, p.tau_slip)
    e0 = body.kinetic_energy(vx_, vy_, om_)
    loss = -(wcn + wct + wrn + wrt)
    tau_m = kernels.planar_min_energy_impulse(*contact, p.tau_slip, p.tau_end)
    f_m = kernels.planar_state_at(tau_m, *contact, p.tau_slip).friction_impulse
    at_min = body.apply_impulse(vx_, vy_, om_, f_m, tau_m)
    kappas = core.restitution_by_definition(v0, p.normal_after, p.tau_compression, p.tau_end,
                                            wcn, wrn)  # fmt: skip
    return kind(
        body=body,
        law=law,
        mu=freeze(mu_),
        kappa=freeze(kappa_),
        before=State(freeze(vx_), freeze(vy_), freeze(om_)),
        after=State(freeze(vx1), freeze(vy1), freeze(om1)),
        slip_before=freeze(u0),
        slip_after=freeze(p.slip_after),
        normal_velocity_before=freeze(v0),
        normal_velocity_after=freeze(p.normal_after),
        regime=freeze(np.asarray(kernels.PLANAR_REGIMES)[p.regime]),
        tau0=freeze(p.tau_compression),
        tau_star=freeze(p.tau_slip),
        tau1=freeze(p.tau_end),
        tangential_impulse=freeze(p.friction_impulse),
        impulse_ratio=freeze(p.friction_impulse / p.tau_end),
        kinetic_energy_before=freeze(e0),
        kinetic_energy_after=freeze(body.kinetic_energy(vx1, vy1, om1)),
        dissipated_energy=freeze(loss),
        dissipated_fraction=freeze(loss / e0),
        work_compression_normal=freeze(wcn),
        work_compression_tangential=freeze(wct),
        work_restitution_normal=freeze(wrn),
        work_restitution_tangential=freeze(wrt),
        min_kinetic_energy=freeze(body.kinetic_energy(*at_min)),
        tau_min_energy=freeze(tau_m),
        newton_restitution=freeze(kappas.newton),
        poisson_restitution=freeze(kappas.poisson),
        energetic_restitution=freeze(kappas.energetic),
        creates_energy=freeze(loss < -_ENERGY_RTOL * e0),
    )
