"""``simulate()``: the impact in time with a compliant normal contact law."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, validated
from ..core import contact as kernels
from .body import Body
from .contact import ContactLaw
from .impact import Impact, State, solve

__all__ = ["Simulation", "simulate"]


@dataclass(frozen=True, eq=False)
class Simulation:
    """Result of :func:`simulate`: the rebound, the restitution the contact law
    produced, and the time series of the contact.

    Attributes
    ----------
    before, after : State
    newton_restitution, poisson_restitution, energetic_restitution : float
        ``-v+/v-`` (eq. 1.1); ``(tau1 - tau0)/tau0`` with ``tau0`` the impulse at
        the end of compression (eq. 1.2); ``sqrt(-W_r^n/W_c^n)`` from the works of
        the normal force (eq. 1.3).
    contact_duration, peak_force, max_compression : float
        s, N, m. The compression is largest at the end of compression (an event);
        the peak force is the largest over the output samples.
    tau0, tau1, tau_star : float
        Normal impulse at the end of compression, of the contact, and when the
        slip stopped (``nan`` if it never did).
    stick_time : float
        Time at which the slip stopped (``nan`` if never).
    tangential_impulse, impulse_ratio, dissipated_energy : float
        ``f1``, ``f1/tau1`` and ``E^- - E^+``.
    t, normal_force, friction_force, vx, vy, omega, slip, tau, compression : ndarray
        Time series at the integrator's steps (the stick event is a sample).
    """

    body: Body
    mu: float
    contact: ContactLaw
    before: State
    after: State
    newton_restitution: float
    poisson_restitution: float
    energetic_restitution: float
    contact_duration: float
    peak_force: float
    max_compression: float
    tau0: float
    tau1: float
    tau_star: float
    stick_time: float
    tangential_impulse: float
    impulse_ratio: float
    dissipated_energy: float
    t: np.ndarray
    normal_force: np.ndarray
    friction_force: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    slip: np.ndarray
    tau: np.ndarray
    compression: np.ndarray

    def rigid(self) -> Impact:
        """The rigid-body closed form with ``kappa`` set to this law's Newton
        restitution: Keller's result says the rebound must agree."""
        b = self.before
        return solve(self.body, b.vx, b.vy, b.omega, mu=self.mu,
                     kappa=min(max(self.newton_restitution, 0.0), 1.0))  # fmt: skip


def _scalar(name: str, value: Any, rules: str | None = None) -> float:
    arr = validated(name, value, rules)
    if arr.ndim:
        raise ValueError(
            f"{name} must be a single number: simulate() integrates one impact at a time "
            "(use solve() for arrays)"
        )
    return float(arr)


def simulate(
    body: Body | None,
    vx: float,
    vy: float,
    omega: float,
    *,
    mu: float,
    contact: ContactLaw,
    rtol: float = 1e-10,
    _mass: float | None = None,
) -> Simulation:
    """Integrate one impact in time with a compliant normal force and Coulomb friction.

    The equations of motion (2.4) with ``N = contact.force(delta, delta_dot)``
    (never tensile; the contact ends when it falls to zero) and
    ``F = -mu N sign(u)`` while the contact point slips; when ``u`` reaches zero
    (located as an event to integrator precision) the contact point sticks and
    ``F = 0`` from then on, as in the paper. Tangential compliance is ignored.

    Parameters
    ----------
    body : Body
    vx, vy, omega : float
        Incidence, ``vy < 0``.
    mu : float
        Coulomb friction, ``>= 0``.
    contact : ContactLaw
        :class:`LinearContact`, :class:`HertzContact` or :class:`HuntCrossleyContact`.
    rtol : float
        Relative tolerance of the integrator, in ``[1e-13, 1e-3]``; errors against
        the rigid closed form shrink with it.

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.dynamics import simulate, HertzContact
    >>> ball = Body.solid_sphere(mass=0.05, radius=0.02)
    >>> law = HertzContact(youngs_modulus=2e9, poisson_ratio=0.35, radius=0.02, alpha=0.05)
    >>> sim = simulate(ball, 1.0, -3.0, 20.0, mu=0.3, contact=law)
    >>> rigid = sim.rigid()
    >>> bool(abs(sim.after.vx - rigid.after.vx) < 1e-8)
    True
    """
    if not isinstance(contact, ContactLaw):
        raise ValueError(f"contact must be a spinimpact contact law, got {type(contact).__name__}")
    if body is None and _mass is not None:  # the normal drop used by ContactLaw.normal_impact
        body = Body(mass=_mass, radius=1.0, gyration=1.0)
    if not isinstance(body, Body):
        raise ValueError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    m = _scalar("mass", body.mass)
    r = _scalar("radius", body.radius)
    j = _scalar("inertia", body.inertia, "mass")  # positive, like a mass
    vx_, vy_, om_, mu_ = (
        _scalar(n, v) for n, v in (("vx", vx), ("vy", vy), ("omega", omega), ("mu", mu))
    )
    tol = float(as_real_array("rtol", rtol))
    if not 1e-13 <= tol <= 1e-3:
        raise ValueError(f"rtol must be in [1e-13, 1e-3], got {tol!r}")

    run = kernels.integrate_contact(
        contact.force, m, r, j, mu_, vx_, vy_, om_,
        time_scale=contact.time_scale(m, abs(vy_)), rtol=tol,
        exponent=contact.separation_exponent,
    )  # fmt: skip
    t, y, stuck = run["t"], run["y"], run["stuck"]
    delta, vxs, vys, oms, tau, f, work_n = y
    normal = np.maximum([contact.force(d, -v) for d, v in zip(delta, vys, strict=True)], 0.0)
    slip = np.where(stuck, 0.0, vxs + r * oms)
    ratio = np.where(stuck, 0.0, -mu_ * np.sign(vxs + r * oms))
    end = y[:, -1]
    tau0, tau1 = run["tau0"], end[4]
    e0 = float(core.kinetic_energy(vx_, vy_, om_, m, j))
    e1 = float(core.kinetic_energy(end[1], end[2], end[3], m, j))
    # Restitution measured on the simulated process (tau0 at the event v = 0, tau1
    # the integrated impulse), not by core.restitution_coefficients' closed tau0.
    w_c, w_r = run["work_n0"], end[6] - run["work_n0"]
    t_star = run["t_star"]
    tau_star = float(np.interp(t_star, t, tau)) if not math.isnan(t_star) else math.nan
    return Simulation(
        body=body,
        mu=mu_,
        contact=contact,
        before=State(vx_, vy_, om_),
        after=State(end[1], end[2], end[3]),
        newton_restitution=-end[2] / vy_,
        poisson_restitution=(tau1 - tau0) / tau0,
        energetic_restitution=math.sqrt(max(-w_r / w_c, 0.0)),
        contact_duration=run["t1"],
        peak_force=float(normal.max()),
        max_compression=float(np.interp(run["t0"], t, delta)),  # delta is largest where v = 0
        tau0=tau0,
        tau1=tau1,
        tau_star=tau_star,
        stick_time=t_star,
        tangential_impulse=end[5],
        impulse_ratio=end[5] / tau1,
        dissipated_energy=e0 - e1,
        t=t,
        normal_force=normal,
        friction_force=ratio * normal,
        vx=vxs,
        vy=vys,
        omega=oms,
        slip=slip,
        tau=tau,
        compression=delta,
    )
