r"""``simulate()``: the impact in time with a compliant normal contact law.

The integration is :func:`spinimpact.core.contact.integrate_contact`; this module
validates the input and packages the run as a :class:`Simulation`, one of the
package's :class:`~spinimpact.model.result.Result` objects.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import core
from .._validation import SMALLEST, scalar
from ..core import contact as kernels
from .body import Body, as_body
from .contact import ContactLaw, _tolerance
from .impact import Impact, State, solve
from .result import Result, freeze

__all__ = ["Simulation", "simulate"]

_ONE = "simulate() integrates one impact at a time (use solve() for arrays)"


@dataclass(frozen=True, eq=False)
class Simulation(Result):
    """Result of :func:`simulate`: the rebound, the restitution the contact law
    produced, and the time series of the contact.

    One simulation is one impact over time: ``shape`` is that of the time series
    ``t``, :meth:`columns` gives one row per sample (the body, the incidence
    ``before_*`` and the rebound ``after_*`` repeated on every row) and the
    result is not indexable by impact.

    Attributes
    ----------
    body : Body
    mu : float
        Coulomb friction coefficient.
    contact : ContactLaw
    before, after : State
        Incidence and rebound: ``vx, vy`` in m/s, ``omega`` in rad/s.
    newton_restitution, poisson_restitution, energetic_restitution : float
        ``-v+/v-`` (eq. 1.1); ``(tau1 - tau0)/tau0`` with ``tau0`` the impulse at
        the end of compression (eq. 1.2); ``sqrt(-W_r^n/W_c^n)`` from the works of
        the normal force (eq. 1.3). Measured on this run and clipped to ``[0, 1]``
        for a damped law, exactly 1 for an elastic one
        (:meth:`ContactLaw.restitutions`): the rebound ``after`` is the one
        integrated, so ``-after.vy/before.vy`` may differ from 1 by the
        integration error.
    contact_duration, peak_force, max_compression : float
        s, N, m. The compression is largest at the end of compression (an event);
        the peak force is the largest over the output samples.
    tau0, tau1, tau_star : float
        Normal impulse in N s at the end of compression, of the contact, and when
        the slip stopped (``nan`` if it never did).
    stick_time : float
        Time in s at which the slip stopped (``nan`` if never).
    tangential_impulse, impulse_ratio, dissipated_energy : float
        ``f1`` in N s, ``f1/tau1``, and ``E^- - E^+`` in J.
    t, normal_force, friction_force, vx, vy, omega, slip, tau, compression : ndarray
        Time series at the integrator's steps (the stick event is a sample): s, N,
        N, m/s, m/s, rad/s, m/s, N s, m.
    """

    _per_impact = False  # one impact over time: not indexable by impact
    _shape_field = "t"

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
        restitution: Keller's result says the rebound must agree, to rounding where
        the restitution is the one measured on this run, and to the integration
        error for an elastic law (restitution exactly 1) or where the measured
        value was clipped to 1."""
        b = self.before
        return solve(self.body, b.vx, b.vy, b.omega, mu=self.mu, kappa=self.newton_restitution)

    def __repr__(self) -> str:
        a = self.after
        return (
            f"<Simulation ({self.contact!r}): after vx={a.vx:.6g} m/s, vy={a.vy:.6g} m/s, "
            f"omega={a.omega:.6g} rad/s; Newton restitution {self.newton_restitution:.6g}, "
            f"contact {self.contact_duration:.6g} s, {self.t.size} samples>"
        )


def simulate(
    body: Body,
    vx: float,
    vy: float,
    omega: float,
    *,
    mu: float,
    contact: ContactLaw,
    rtol: float = 1e-10,
    tangential=None,
):
    r"""Integrate one impact in time with a compliant normal force and Coulomb friction.

    Parameters
    ----------
    body : Body
        One body (scalar mass, radius and gyration).
    vx, vy, omega : float
        Incidence: centre velocity in m/s (``vy < 0``) and spin in rad/s.
    mu : float
        Coulomb friction coefficient, ``>= 0``.
    contact : ContactLaw
        :class:`LinearContact`, :class:`HertzContact` or :class:`HuntCrossleyContact`.
    rtol : float
        Relative tolerance of the integrator, in ``[1e-13, 1e-3]``; errors against
        the rigid closed form shrink with it.
    tangential : Mindlin, optional
        A tangential compliance law (:class:`~spinimpact.model.mindlin.Mindlin`):
        the contact then has a tangential spring capped by Coulomb friction, and
        the result is a :class:`~spinimpact.model.mindlin.TangentialSimulation`.
        ``None`` (default): no tangential compliance, as below.

    Returns
    -------
    Simulation
        Or a :class:`~spinimpact.model.mindlin.TangentialSimulation` with ``tangential``.

    Raises
    ------
    TypeError
        If ``body`` is not a :class:`Body`, ``contact`` not a contact law, or a
        number is not a real number.
    ValueError
        If a number is out of range or an array.

    Notes
    -----
    The equations of motion (2.4),

    .. math::

        m \dot v_x = F, \qquad m \dot v_y = N, \qquad J \dot\omega = R F,

    with ``N = max(contact.force(delta, -v_y), 0)`` (the contact ends when it
    falls to zero) and ``F = -mu N sign(u)`` while the contact point slips; when
    ``u = v_x + R omega`` reaches zero (located as an event to integrator
    precision) the contact point sticks and ``F = 0`` from then on, as in the
    paper. Without ``tangential``, tangential compliance is ignored.

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
    body = as_body(body)
    if tangential is not None:
        from .mindlin import simulate_tangential

        return simulate_tangential(body, vx, vy, omega, mu=mu, contact=contact,
                                   tangential=tangential, rtol=rtol)  # fmt: skip
    if not isinstance(contact, ContactLaw):
        raise TypeError(f"contact must be a spinimpact contact law, got {type(contact).__name__}")
    m = scalar("mass", body.mass, why=_ONE)
    r = scalar("radius", body.radius, why=_ONE)
    j = scalar("inertia", body.inertia, why=_ONE)
    if not j >= SMALLEST:  # J = m rho^2 is not an input: name those it comes from
        raise ValueError(
            f"the moment of inertia mass * gyration**2 must be >= {SMALLEST:g} kg m^2, got "
            f"{j!r} (mass {m!r} kg, radius {r!r} m, gyration {float(body.gyration)!r} m): "
            "a heavier or larger body"
        )
    vx_, vy_, om_, mu_ = (
        scalar(n, v, why=_ONE) for n, v in (("vx", vx), ("vy", vy), ("omega", omega), ("mu", mu))
    )
    run = kernels.integrate_contact(
        contact.force, m, r, j, mu_, vx_, vy_, om_,
        time_scale=contact.time_scale(m, abs(vy_)), rtol=_tolerance(rtol),
        exponent=contact.separation_exponent,
    )  # fmt: skip
    e0 = float(core.kinetic_energy(vx_, vy_, om_, m, j))
    e1 = float(core.kinetic_energy(run.vx[-1], run.vy[-1], run.omega[-1], m, j))
    # Restitution measured on the simulated process (tau0 at the event v = 0, tau1
    # the integrated impulse), not by core.restitution_coefficients' closed tau0.
    t_star = run.t_star
    tau_star = float(np.interp(t_star, run.t, run.tau)) if not math.isnan(t_star) else math.nan
    tau1, f1 = float(run.tau[-1]), float(run.tangential_impulse[-1])
    newton, poisson, energetic = contact.restitutions(run)  # in [0, 1]; 1 if elastic
    return Simulation(
        body=body,
        mu=mu_,
        contact=contact,
        before=State(*(freeze(x) for x in (vx_, vy_, om_))),
        after=State(*(freeze(x[-1]) for x in (run.vx, run.vy, run.omega))),
        newton_restitution=newton,
        poisson_restitution=poisson,
        energetic_restitution=energetic,
        contact_duration=run.t1,
        peak_force=run.peak_force,
        max_compression=run.max_compression,
        tau0=run.tau0,
        tau1=tau1,
        tau_star=tau_star,
        stick_time=t_star,
        tangential_impulse=f1,
        impulse_ratio=f1 / tau1,
        dissipated_energy=e0 - e1,
        **{name: freeze(getattr(run, name)) for name in _SERIES},
    )


#: The time series of :class:`Simulation`, named as in :class:`~spinimpact.core.contact.ContactRun`.
_SERIES = ("t", "normal_force", "friction_force", "vx", "vy", "omega", "slip", "tau", "compression")
