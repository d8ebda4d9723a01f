r"""Tangential compliance in time: the Mindlin law and its simulation.

:class:`Mindlin` is the tangential law that
:func:`spinimpact.dynamics.simulate` takes as ``tangential=``: a tangential
spring at the contact whose stiffness follows the normal law's elastic stiffness
(Mindlin's no-slip stiffness ``k_t = 8 G^* a`` for Hertz contact), capped by
Coulomb friction. The integration is
:func:`spinimpact.core.tangential.integrate_tangential` (its docstring states the
variant and why); this module validates, runs it and packages a
:class:`TangentialSimulation`. It does not import :mod:`spinimpact.model.dynamics`.

References
----------
.. [1] R. D. Mindlin, "Compliance of elastic bodies in contact", Journal of
   Applied Mechanics 16 (1949) 259-268.
.. [2] A. Di Renzo, F. P. Di Maio, "Comparison of contact-force models for the
   simulation of collisions in DEM-based granular flow codes", Chemical
   Engineering Science 59 (2004) 525-541.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import check, scalar
from ..core import tangential as kernels
from .body import Body
from .contact import ContactLaw, HertzContact, HuntCrossleyContact, LinearContact, _tolerance
from .impact import Impact, State, solve
from .result import Result, freeze

__all__ = ["Mindlin", "TangentialSimulation", "simulate_tangential"]

_ONE = "simulate() integrates one impact at a time (use solve() for arrays)"


@dataclass(frozen=True)
class Mindlin:
    r"""Mindlin's tangential contact stiffness with Coulomb slip, for :func:`simulate`.

    Parameters
    ----------
    poisson_ratio : float, optional
        ``nu`` in ``(-1, 0.5]`` of the body (and of the plane, or a rigid plane):
        the stiffness ratio is then ``r = 2(1 - nu)/(2 - nu)``. Default: the
        ``poisson_ratio`` of a :class:`HertzContact`.
    stiffness_ratio : float, optional
        ``r = k_t/k_n`` directly, ``> 0`` (instead of ``poisson_ratio``): ``k_t``
        is ``r`` times the normal law's elastic stiffness ``n k delta^{n-1}``.
        Large values approach the rigid (no tangential compliance) model.
    spring : {"scaled", "incremental", "total", "history"}
        How a stuck spring follows its changing stiffness
        (:func:`spinimpact.core.tangential.integrate_tangential`); ``"scaled"``
        (default) is the simplest rule whose energy never grows; ``"history"`` the
        exact no-slip elastic solution (the force unloads along its loading history;
        its energy never grows either), the one closest to the measured bounces of
        ``docs/validation.md`` among these rules.

    Notes
    -----
    With Hertz normal contact, ``k_t = 8 G^* a`` with ``a = sqrt(R delta)``:
    Mindlin's (1949) stiffness of a contact that does not slip, the "no-slip"
    Hertz-Mindlin model of DEM codes; Coulomb's law caps ``|F| <= mu N``. The
    spring is loaded incrementally and scaled down with the stiffness as the
    contact shrinks, the variant whose energy never grows
    (:mod:`spinimpact.core.tangential`). Mindlin-Deresiewicz micro-slip (a
    stiffness that falls as ``|F|`` approaches ``mu N``) is not modelled here: the
    impulse-space law :class:`~spinimpact.MindlinDeresiewicz` has it.

    Examples
    --------
    >>> Mindlin(poisson_ratio=0.23).ratio(None)
    0.8700564971751412
    """

    poisson_ratio: float | None = None
    stiffness_ratio: float | None = None
    spring: str = "scaled"

    def __post_init__(self) -> None:
        if not isinstance(self.spring, str):
            raise TypeError(f"spring must be one of {kernels.SPRINGS}, got {self.spring!r}")
        if self.spring not in kernels.SPRINGS:
            raise ValueError(f"spring must be one of {kernels.SPRINGS}, got {self.spring!r}")
        if self.poisson_ratio is not None and self.stiffness_ratio is not None:
            raise ValueError("give poisson_ratio or stiffness_ratio, not both")
        if self.poisson_ratio is not None:
            nu = scalar("poisson_ratio", self.poisson_ratio, why="a law takes one value")
            check("poisson_ratio", np.float64(nu), lambda x: (x > -1) & (x <= 0.5), "in (-1, 0.5]")
            object.__setattr__(self, "poisson_ratio", nu)
        if self.stiffness_ratio is not None:
            r = scalar("stiffness_ratio", self.stiffness_ratio, why="a law takes one value")
            check("stiffness_ratio", np.float64(r), lambda x: (x > 0) & (x <= 1e12),
                  "in (0, 1e12]")  # fmt: skip
            object.__setattr__(self, "stiffness_ratio", r)

    def ratio(self, contact: ContactLaw | None) -> float:
        """The stiffness ratio ``r = k_t/k_n`` with this normal ``contact`` law."""
        if self.stiffness_ratio is not None:
            return float(self.stiffness_ratio)
        nu = self.poisson_ratio
        if nu is None:
            if not isinstance(contact, HertzContact):
                raise ValueError(
                    "Mindlin() takes Poisson's ratio from a HertzContact; with "
                    f"{type(contact).__name__} give poisson_ratio or stiffness_ratio"
                )
            nu = contact.poisson_ratio
        return float(kernels.mindlin_stiffness_ratio(nu))

    def to_dict(self) -> dict[str, Any]:
        """The law's name and parameters as plain Python values."""
        return {"law": "Mindlin", "poisson_ratio": self.poisson_ratio,
                "stiffness_ratio": self.stiffness_ratio, "spring": self.spring}  # fmt: skip


@dataclass(frozen=True, eq=False)
class TangentialSimulation(Result):
    """Result of :func:`simulate` with ``tangential=``: the rebound and the contact in
    time with tangential compliance.

    One impact over time (``shape`` is that of ``t``; not indexable by impact).

    Attributes
    ----------
    body, mu, contact, tangential
        The inputs (``tangential`` a :class:`Mindlin`).
    stiffness_ratio : float
        ``r = k_t/k_n`` used.
    before, after : State
        Incidence and rebound (m/s, rad/s).
    tangential_restitution : float
        ``beta = -u+/u-`` of the contact point (``nan`` for ``u- = 0``); ``-1``:
        no friction, ``0``: leaves rolling, ``> 0``: the slip reversed.
    newton_restitution, poisson_restitution, energetic_restitution : float
        Measured on the run as in :class:`~spinimpact.dynamics.Simulation`.
    contact_duration, peak_force, max_compression : float
        s, N, m.
    switches : int
        Number of stick/slip switches (each located as an event).
    tangential_impulse, dissipated_energy : float
        N s, J (``E^- - E^+`` of the body).
    t, normal_force, tangential_force, spring_displacement, slip, contact_velocity,
    vx, vy, omega, tau, compression, energy : ndarray
        Series: s, N, N, m (the tangential spring's displacement), m/s (interface
        slip velocity, 0 while sticking), m/s (``u = vx + R omega``), m/s, m/s,
        rad/s, N s, m, J (``T + U_n + F^2/(2 k_t)``, with the traction field's energy in
        place of ``F^2/(2 k_t)`` for ``spring="history"``; it never increases).
    stuck : ndarray of bool
        Whether the contact sticks at each sample.
    """

    _per_impact = False
    _shape_field = "t"

    body: Body
    mu: float
    contact: ContactLaw
    tangential: Mindlin
    stiffness_ratio: float
    before: State
    after: State
    tangential_restitution: float
    newton_restitution: float
    poisson_restitution: float
    energetic_restitution: float
    contact_duration: float
    peak_force: float
    max_compression: float
    switches: int
    tangential_impulse: float
    dissipated_energy: float
    t: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    spring_displacement: np.ndarray
    slip: np.ndarray
    contact_velocity: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    tau: np.ndarray
    compression: np.ndarray
    energy: np.ndarray
    stuck: np.ndarray

    def rigid(self) -> Impact:
        """The rigid closed form (no tangential compliance) at this run's Newton
        restitution: the limit of a stiff tangential spring."""
        b = self.before
        return solve(self.body, b.vx, b.vy, b.omega, mu=self.mu, kappa=self.newton_restitution)

    def __repr__(self) -> str:
        a = self.after
        return (
            f"<TangentialSimulation ({self.tangential!r}, k_t/k_n={self.stiffness_ratio:.6g}, "
            f"{self.contact!r}): after vx={a.vx:.6g} m/s, vy={a.vy:.6g} m/s, "
            f"omega={a.omega:.6g} rad/s; beta={self.tangential_restitution:.6g}, "
            f"{self.switches} stick/slip switches, contact {self.contact_duration:.6g} s, "
            f"{self.t.size} samples>"
        )


def _normal_parameters(contact: ContactLaw) -> dict[str, float]:
    """The normal law as ``(stiffness, exponent, alpha, damping)`` of the kernel."""
    if isinstance(contact, HuntCrossleyContact):  # HertzContact included
        return {"stiffness": contact.stiffness, "exponent": contact.exponent,
                "alpha": contact.alpha, "damping": 0.0}  # fmt: skip
    if isinstance(contact, LinearContact):
        return {"stiffness": contact.stiffness, "exponent": 1.0, "alpha": 0.0,
                "damping": contact.damping}  # fmt: skip
    raise TypeError(
        "tangential compliance needs a LinearContact, HertzContact or HuntCrossleyContact, "
        f"got {type(contact).__name__}"
    )


def simulate_tangential(
    body: Body, vx: float, vy: float, omega: float, *, mu: float, contact: ContactLaw,
    tangential: Mindlin, rtol: float = 1e-10,
) -> TangentialSimulation:  # fmt: skip
    r"""One impact in time with normal and tangential compliance (the work of
    :func:`spinimpact.dynamics.simulate` when it is given ``tangential=``).

    Parameters are those of :func:`spinimpact.dynamics.simulate`, plus
    ``tangential``, a :class:`Mindlin` law.

    Examples
    --------
    >>> from spinimpact import Body
    >>> from spinimpact.dynamics import simulate, HertzContact
    >>> ball = Body.solid_sphere(mass=2.618e-4, radius=0.0025)
    >>> law = HertzContact(youngs_modulus=3.8e11, poisson_ratio=0.23, radius=0.0025)
    >>> sim = simulate(ball, 1.334, -3.665, 0.0, mu=0.092, contact=law, tangential=Mindlin())
    >>> round(float(sim.after.vx / sim.before.vx), 3), sim.switches   # e_t at 20 degrees
    (0.62, 2)
    >>> bool(sim.tangential_restitution > 0)   # the slip reversed: the ball grips
    True
    """
    if not isinstance(tangential, Mindlin):
        raise TypeError(f"tangential must be a Mindlin law, got {type(tangential).__name__}")
    if not isinstance(contact, ContactLaw):
        raise TypeError(f"contact must be a spinimpact contact law, got {type(contact).__name__}")
    if not isinstance(body, Body):
        raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    normal = _normal_parameters(contact)
    m = scalar("mass", body.mass, why=_ONE)
    r = scalar("radius", body.radius, why=_ONE)
    j = scalar("inertia", body.inertia, "mass", why=_ONE)
    vx_, vy_, om_, mu_ = (
        scalar(n, v, why=_ONE) for n, v in (("vx", vx), ("vy", vy), ("omega", omega), ("mu", mu))
    )
    ratio = tangential.ratio(contact)
    run = kernels.integrate_tangential(
        m, r, j, mu_, vx_, vy_, om_, **normal, stiffness_ratio=ratio,
        time_scale=contact.time_scale(m, abs(vy_)), rtol=_tolerance(rtol),
        spring=tangential.spring,
    )  # fmt: skip
    e0 = float(core.kinetic_energy(vx_, vy_, om_, m, j))
    e1 = float(core.kinetic_energy(run.vx[-1], run.vy[-1], run.omega[-1], m, j))
    u0, u1 = vx_ + r * om_, float(run.contact_velocity[-1])
    beta = -u1 / u0 if u0 != 0 else math.nan
    newton, poisson, energetic = contact.restitutions(run)  # type: ignore[arg-type]
    series = {name: freeze(getattr(run, name)) for name in _SERIES}
    return TangentialSimulation(
        body=body, mu=mu_, contact=contact, tangential=tangential, stiffness_ratio=ratio,
        before=State(*(freeze(x) for x in (vx_, vy_, om_))),
        after=State(*(freeze(x[-1]) for x in (run.vx, run.vy, run.omega))),
        tangential_restitution=beta, newton_restitution=newton, poisson_restitution=poisson,
        energetic_restitution=energetic, contact_duration=run.t1,
        peak_force=float(run.normal_force.max()),
        max_compression=float(np.interp(run.t0, run.t, run.compression)),
        switches=int(run.switches.size), tangential_impulse=float(run.tangential_impulse[-1]),
        dissipated_energy=e0 - e1, **series,
    )  # fmt: skip


#: The series of :class:`TangentialSimulation`, named as in the kernel's run.
_SERIES = ("t", "normal_force", "tangential_force", "spring_displacement", "slip",
           "contact_velocity", "vx", "vy", "omega", "tau", "compression", "energy",
           "stuck")  # fmt: skip
