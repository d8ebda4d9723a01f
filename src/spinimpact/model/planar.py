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
from .._validation import as_real_array, broadcast, check, validated
from ..core import planar as kernels
from .impact import State, _restitution
from .planar_body import PlanarBody
from .result import Array, Result, freeze

__all__ = ["PlanarImpact", "PlanarHistory", "solve_planar", "LAWS"]

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
        parts = {n: getattr(b, n) for n in PlanarBody.COLUMNS}
        if any(np.ndim(x) for x in parts.values()):
            parts = {n: np.broadcast_to(x, self.shape)[index] for n, x in parts.items()}
            b = PlanarBody(**parts, name=b.name)
        return dataclasses.replace(imp, body=b)

    def history(self, n: int = 201) -> PlanarHistory:
        """The process over the normal impulse: ``n`` even points on ``[0, tau_1]`` plus the
        breakpoints ``tau_0`` and ``tau_*``. Only for a single impact."""
        if self.shape != ():
            raise ValueError(
                f"history() describes one impact, but this PlanarImpact has shape {self.shape};"
                " select one with impact[i]"
            )
        if not isinstance(n, int | np.integer) or isinstance(n, bool) or n < 2:
            raise ValueError(f"n must be an integer >= 2, got {n!r}")
        t0, ts, t1 = float(self.tau0), float(self.tau_star), float(self.tau1)
        grid = np.union1d(np.linspace(0.0, t1, int(n)), [t for t in (t0, ts) if 0 < t < t1])
        b, w = self.body, self.body.collision_matrix
        args = (self.slip_before, self.normal_velocity_before, w.tt, w.tn, w.nn, self.mu)
        st = kernels.planar_state_at(grid, *args, self.tau_star)
        before = (self.before.vx, self.before.vy, self.before.omega)
        vx, vy, om = kernels.planar_apply_impulse(
            *before, b.mass, b.inertia, b.rx, b.ry, st.friction_impulse, grid
        )
        return PlanarHistory(
            tau=grid,
            vx=vx,
            vy=vy,
            omega=om,
            slip=st.slip,
            normal_velocity=st.normal,
            force_ratio=st.force_ratio,
            tangential_impulse=st.friction_impulse,
            kinetic_energy=core.kinetic_energy(vx, vy, om, b.mass, b.inertia),
            tau0=t0,
            tau_star=ts,
            tau1=t1,
        )

    def __repr__(self) -> str:
        if self.shape != ():
            names, counts = np.unique(self.regime, return_counts=True)
            summary = ", ".join(f"{n}: {c}" for n, c in zip(names, counts, strict=True))
            return f"<PlanarImpact ({self.law}) of shape {self.shape}: {summary}>"
        a = self.after
        return (
            f"<PlanarImpact {self.regime} ({self.law}): after vx={a.vx:.6g} m/s, "
            f"vy={a.vy:.6g} m/s, omega={a.omega:.6g} rad/s; dissipated "
            f"{self.dissipated_energy:.6g} J>"
        )


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
    if not isinstance(law, str):
        raise TypeError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
    if law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
    vx_, vy_, om_ = (as_real_array(n, v) for n, v in (("vx", vx), ("vy", vy), ("omega", omega)))
    mu_ = validated("mu", mu)
    shapes = broadcast(vx=vx_, vy=vy_, omega=om_, mass=np.asarray(body.mass),
                       inertia=np.asarray(body.inertia), rx=np.asarray(body.rx),
                       ry=np.asarray(body.ry))  # fmt: skip
    vx_, vy_, om_, m, inertia, rx, ry = shapes
    u0, v0 = kernels.planar_contact_velocity(vx_, vy_, om_, rx, ry)
    check("the contact point's normal velocity vy + omega*rx", v0, lambda v: v < 0,
          "< 0 (the contact point must approach the surface)")  # fmt: skip
    kappa_ = _restitution(kappa, v0)
    u0, v0, mu_, kappa_, m, inertia, rx, ry, vx_, vy_, om_ = broadcast(
        slip=u0, v=v0, mu=mu_, kappa=kappa_, mass=m, inertia=inertia, rx=rx, ry=ry,
        vx=vx_, vy=vy_, omega=om_,
    )  # fmt: skip
    w = core.planar_collision_matrix(m, inertia, rx, ry)
    contact = (u0, v0, w.tt, w.tn, w.nn, mu_)
    p = kernels.planar_process(*contact, kappa_, LAWS.index(law))
    vx1, vy1, om1 = kernels.planar_apply_impulse(
        vx_, vy_, om_, m, inertia, rx, ry, p.friction_impulse, p.tau_end
    )
    zero = 0.0 * p.tau_end
    wcn, wct = kernels.planar_work(zero, p.tau_compression, *contact, p.tau_slip)
    wrn, wrt = kernels.planar_work(p.tau_compression, p.tau_end, *contact, p.tau_slip)
    e0 = core.kinetic_energy(vx_, vy_, om_, m, inertia)
    loss = -(wcn + wct + wrn + wrt)
    tau_m = kernels.planar_min_energy_impulse(*contact, p.tau_slip, p.tau_end)
    f_m = kernels.planar_state_at(tau_m, *contact, p.tau_slip).friction_impulse
    at_min = kernels.planar_apply_impulse(vx_, vy_, om_, m, inertia, rx, ry, f_m, tau_m)
    with np.errstate(invalid="ignore", divide="ignore"):
        energetic = np.sqrt(np.maximum(-wrn / wcn, 0.0))
    return PlanarImpact(
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
        kinetic_energy_after=freeze(core.kinetic_energy(vx1, vy1, om1, m, inertia)),
        dissipated_energy=freeze(loss),
        dissipated_fraction=freeze(loss / e0),
        work_compression_normal=freeze(wcn),
        work_compression_tangential=freeze(wct),
        work_restitution_normal=freeze(wrn),
        work_restitution_tangential=freeze(wrt),
        min_kinetic_energy=freeze(core.kinetic_energy(*at_min, m, inertia)),
        tau_min_energy=freeze(tau_m),
        newton_restitution=freeze(-p.normal_after / v0),
        poisson_restitution=freeze((p.tau_end - p.tau_compression) / p.tau_compression),
        energetic_restitution=freeze(energetic),
        creates_energy=freeze(loss < -_ENERGY_RTOL * e0),
    )
