"""``solve()``: the complete impact of a spinning body on a rough surface."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, broadcast, check, validated, whole
from . import _fast, _impact_fused, result
from ._hooks import tangential_law
from .body import Body, as_body
from .result import Result, freeze, plain_repr, regime_counts

__all__ = ["State", "Outcome", "History", "Impact", "solve"]

Array = result.Array
_out = freeze


@dataclass(frozen=True, eq=False)
class State(Result):
    """Velocity state of the body: centre velocity ``(vx, vy)``, m/s, and spin ``omega``, rad/s.

    ``omega`` is positive counter-clockwise (about +z, out of the page).
    """

    vx: Array
    vy: Array
    omega: Array
    __repr__ = plain_repr


@dataclass(frozen=True, eq=False)
class Outcome(Result):
    """Qualitative rebound outcome, decided from the incidence alone.

    The closed-form conditions are those of :mod:`spinimpact.core.outcomes`.

    Attributes
    ----------
    backward : bool
        The horizontal velocity of the centre reverses (``vx^- != 0``).
    reversed_spin : bool
        The spin reverses (``omega^- != 0``).
    vertical : bool
        The centre leaves along the normal, ``vx^+ = 0``.
    spinning : bool
        The body leaves spinning, ``omega^+ != 0``.
    rolling : bool
        The contact point leaves without slip, ``u^+ = 0`` (the contact stuck).
    """

    _column_prefix = False  # the flags keep their names as columns: backward, rolling, ...

    backward: Array
    reversed_spin: Array
    vertical: Array
    spinning: Array
    rolling: Array
    __repr__ = plain_repr


@dataclass(frozen=True, eq=False)
class History(Result):
    """The impact process of one impact, sampled over the normal impulse ``tau``.

    Every array has the length of ``tau``. ``tau0``, ``tau_star`` and ``tau1``
    mark the end of compression, of slip and of the impact.
    """

    tau: np.ndarray  #: normal impulse, N s
    vx: np.ndarray  #: centre velocity along the surface, m/s (eqs. 4.11, 4.12)
    vy: np.ndarray  #: normal velocity, m/s (eq. 3.3)
    omega: np.ndarray  #: spin, rad/s (eqs. 4.9, 4.12)
    slip: np.ndarray  #: contact-point velocity u, m/s (eqs. 4.5, 4.12)
    force_ratio: np.ndarray  #: F/N (eq. 6.4)
    tangential_impulse: np.ndarray  #: f(tau), N s (eqs. 7.2, 7.3; Routh's diagram)
    kinetic_energy: np.ndarray  #: E(tau), J (eq. 8.1)
    tau0: float
    tau_star: float
    tau1: float

    _per_impact = False  # one impact over tau: not indexable by impact
    _shape_field = "tau"


@dataclass(frozen=True, eq=False)
class Impact(Result):
    """Everything :func:`solve` computes about an impact (or an array of impacts).

    Each numeric field has the broadcast shape of the inputs (a NumPy scalar for scalar
    inputs). Units are SI; equation numbers are those of Lubarda (2010), cited in
    :func:`solve`.

    Attributes
    ----------
    body : Body
        The body, as given to :func:`solve` (indexing an Impact indexes its arrays).
    mu, kappa : float or ndarray
        Friction and normal restitution used (``kappa`` evaluated from a restitution
        model if one was given).
    before, after : State
        Incidence and rebound velocities (eqs. 3.4, 4.13, 4.16).
    slip_before, slip_after : float or ndarray
        Contact-point velocity ``u^-``, ``u^+``, m/s (eqs. 4.4, 7.11).
    incidence_ratio : float or ndarray
        ``|u^-/v^-|`` (eqs. 4.6, 4.14, 4.15).
    regime : str or ndarray of str
        ``frictionless`` (``mu = 0``), ``no-slip`` (``u^- = 0``), ``stick-compression``
        (``tau_* <= tau_0``), ``stick-restitution`` (``tau_0 < tau_* <= tau_1``) or
        ``slip`` (``tau_* > tau_1``).
    tau0, tau_star, tau1 : float or ndarray
        Normal impulse, N s, at the end of compression (eq. 3.2), of slip (eq. 4.3; ``0``
        if ``u^- = 0``, ``inf`` if ``mu = 0``) and of the impact (eq. 3.6).
    tangential_impulse, impulse_ratio : float or ndarray
        ``f_1``, N s (eqs. 5.7, 7.6), and ``mu_hat = f_1/tau_1`` (eqs. 7.4, 7.7-7.9).
    kinetic_energy_before, kinetic_energy_after, dissipated_energy : float or ndarray
        ``E^-``, ``E^+`` and ``Delta E = E^- - E^+ >= 0``, J (eqs. 5.1-5.10).
    dissipated_fraction : float or ndarray
        ``Delta E / E^-``, the share of the incidence energy lost, in ``[0, 1]``.
    work_compression_normal, work_compression_tangential : float or ndarray
        ``W_c^n``, ``W_c^t``, J (eqs. 6.1, 6.6-6.11).
    work_restitution_normal, work_restitution_tangential : float or ndarray
        ``W_r^n``, ``W_r^t``, J (eqs. 6.2, 6.6-6.11).
    work_ratio_tangential : float or ndarray
        ``W_r^t/W_c^t`` (eqs. 6.15-6.19); NaN with no friction work.
    min_kinetic_energy, tau_min_energy, min_energy_case : float, float, str or ndarray
        ``E_m`` (J), ``tau_m`` (N s) and which case of Fig. 5 holds (eqs. 8.1-8.6).
    newton_restitution, poisson_restitution, energetic_restitution : float or ndarray
        ``kappa_N = -v^+/v^-`` (eq. 1.1), ``kappa_P = (tau_1 - tau_0)/tau_0`` (eq. 1.2)
        and ``eta = sqrt(-W_r^n/W_c^n)`` (eq. 1.3), each evaluated from the computed
        process by its own definition; all equal ``kappa`` (section 3).
    outcome : Outcome
        Backward rebound, reversed spin, vertical, spinning, rolling.
    """

    body: Body
    mu: Array
    kappa: Array
    before: State
    after: State
    slip_before: Array
    slip_after: Array
    incidence_ratio: Array
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
    work_ratio_tangential: Array
    min_kinetic_energy: Array
    tau_min_energy: Array
    min_energy_case: Array
    newton_restitution: Array
    poisson_restitution: Array
    energetic_restitution: Array
    outcome: Outcome

    _shape_field = "tau1"

    def history(self, n: int = 201, *, tau: Any = None) -> History:
        """The impact process over the normal impulse ``tau`` (Figs. 2-5).

        Parameters
        ----------
        n : int
            Number of evenly spaced points on ``[0, tau_1]``; ``tau_0`` and
            ``tau_*`` (when inside the impact) are added so the kinks are exact.
        tau : array_like, optional
            Explicit impulses in ``[0, tau_1]`` to sample instead.

        Returns
        -------
        History
            Velocities, slip, force ratio, friction impulse and kinetic energy at ``tau``.

        Raises
        ------
        ValueError
            For an Impact of more than one impact (select one with ``impact[i]``), ``n``
            not an integer >= 2, or ``tau`` outside ``[0, tau_1]``.
        """
        if self.shape != ():
            raise ValueError(
                f"history() describes one impact, but this Impact has shape {self.shape}; "
                "select one with impact[i]"
            )
        tau0, tau_star, tau1 = float(self.tau0), float(self.tau_star), float(self.tau1)
        if tau is None:
            n = whole("n", n, 2)
            marks = [t for t in (tau0, tau_star) if 0.0 < t < tau1]
            grid = np.union1d(np.linspace(0.0, tau1, int(n)), marks)
        else:
            grid = as_real_array("tau", tau)
            check("tau", grid, lambda t: (t >= 0) & (t <= tau1), f"in [0, tau1 = {tau1:g}]")
        b = self.body
        args = (self.before.vx, self.before.vy, self.before.omega, b.mass, b.radius, b.zeta)
        slip0 = float(self.slip_before)
        vx, vy, omega = core.state_at(grid, *args, self.mu)
        return History(
            tau=grid,
            vx=vx,
            vy=vy,
            omega=omega,
            slip=core.slip_at(grid, b.mass, slip0, b.zeta, self.mu),
            force_ratio=core.force_ratio_at(grid, b.mass, slip0, b.zeta, self.mu),
            tangential_impulse=core.friction_impulse_at(grid, b.mass, slip0, b.zeta, self.mu),
            kinetic_energy=core.kinetic_energy_at(grid, *args, self.mu, b.inertia),
            tau0=tau0,
            tau_star=tau_star,
            tau1=tau1,
        )

    def __repr__(self) -> str:
        if self.shape != ():
            summary = regime_counts(self.regime)
            return f"<Impact of shape {self.shape}: {summary}>"
        a = self.after
        return (
            f"<Impact {self.regime}: after vx={a.vx:.6g} m/s, vy={a.vy:.6g} m/s, "
            f"omega={a.omega:.6g} rad/s; dissipated {self.dissipated_energy:.6g} J>"
        )


def _restitution(kappa: Any, vy: np.ndarray) -> np.ndarray:
    if callable(kappa):  # a RestitutionModel or any function of the impact speed
        model: Callable[[np.ndarray], Any] = kappa
        value = model(np.abs(vy))
        name = f"kappa (from {kappa!r})"
    else:
        value, name = kappa, "kappa"
    return validated(name, value, "kappa")


def solve(
    body: Body,
    vx: Any,
    vy: Any,
    omega: Any,
    *,
    mu: Any,
    kappa: Any,
    tangential: Any = None,
) -> Impact:
    r"""Solve the frictional impact of a spinning body on a fixed rough surface.

    Parameters
    ----------
    body : Body
        The body; its mass, radius and gyration may themselves be arrays.
    vx : float or array_like
        Incidence velocity of the centre along the surface, m/s (the paper's ``u_C^-``).
    vy : float or array_like
        Incidence normal velocity, m/s, ``< 0`` (approaching the surface; ``v^-``).
    omega : float or array_like
        Incidence spin, rad/s, counter-clockwise positive. A ball rolling to the
        right without slip has ``omega = -vx/R``.
    mu : float or array_like
        Kinetic Coulomb friction coefficient, ``>= 0``.
    kappa : float, array_like or callable
        Coefficient of normal restitution in ``[0, 1]``, or a restitution model:
        a callable of the impact speed ``|vy|`` returning ``kappa`` (for example
        :class:`~spinimpact.TabulatedRestitution`).
    tangential : Walton, Stronge or MindlinDeresiewicz, optional
        A tangential compliance law; the result is then a :class:`~spinimpact.CompliantImpact`.

    Returns
    -------
    Impact
        Every field with the broadcast shape of all the inputs.

    Raises
    ------
    TypeError
        For a ``body`` that is not a :class:`Body`, or an input that is not a real
        number or array of them.
    ValueError
        For non-finite input, ``vy >= 0``, ``mu < 0``, ``kappa`` outside
        ``[0, 1]``, or shapes that do not broadcast; the message names the
        parameter, the value and the first offending index.

    Notes
    -----
    Keller's method [2]_ as the paper [1]_ applies it: the normal impulse ``tau`` is the
    independent variable, friction is Coulomb's with stick once the contact point stops
    slipping at ``tau_*`` (eq. 4.3), and Poisson's restitution ends the impact at
    ``tau_1 = (1 + kappa) tau_0`` (eq. 3.6). With ``f_1 = -mu sign(u^-) min(tau_*, tau_1)``,

    .. math:: v_x^+ = v_x^- + f_1/m, \quad v_y^+ = -\kappa v_y^-, \quad
        \omega^+ = \omega^- + (\zeta - 1) f_1/(m R)

    (eqs. 2.1-2.3, 4.13, 4.16); the kernels of :mod:`spinimpact.core` give the rest.

    References
    ----------
    .. [1] V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
       surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy of
       Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    .. [2] J. B. Keller, "Impact with friction", Journal of Applied Mechanics 53 (1986) 1-4.

    Examples
    --------
    >>> from spinimpact import Body, solve
    >>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
    >>> imp = solve(ball, vx=2.0, vy=-3.0, omega=0.0, mu=0.5, kappa=0.8)
    >>> str(imp.regime), round(float(imp.after.vx / imp.before.vx), 12)   # 5/7 rule
    ('stick-compression', 0.714285714286)
    """
    body = as_body(body)
    if tangential is not None:  # the law solves it (spinimpact.model.compliance)
        return tangential_law(tangential)._solve_plane(body, vx, vy, omega, mu=mu, kappa=kappa)
    one = _fast.paper_impact(body, vx, vy, omega, mu, kappa, (Impact, State, Outcome))
    if one is not None:  # one impact of plain numbers: the same Impact, in microseconds
        return one
    vx_, vy_, om_, mu_ = (
        validated(n, v) for n, v in (("vx", vx), ("vy", vy), ("omega", omega), ("mu", mu))
    )
    kappa_ = _restitution(kappa, vy_)
    parts = {k: np.asarray(getattr(body, k)) for k in ("mass", "radius", "gyration", "zeta")}
    vx_, vy_, om_, mu_, kappa_, m, r, g, zeta = broadcast(
        vx=vx_, vy=vy_, omega=om_, mu=mu_, kappa=kappa_, **parts
    )
    many = _impact_fused.fused_fields(State, Outcome, vx_, vy_, om_, mu_, kappa_, m, r, g, zeta)
    if many is not None:  # arrays: every field in one pass over memory (Numba), same numbers
        return Impact(body=body, **many)
    inertia = m * g**2
    inc = (vx_, vy_, om_, m, r, zeta, mu_, kappa_)

    slip = core.slip_velocity(vx_, om_, r)
    vx1, vy1, om1, f1 = core.rebound(*inc)
    tau0 = core.compression_impulse(m, vy_)
    tau1 = core.total_impulse(m, vy_, kappa_)
    e0 = core.kinetic_energy(vx_, vy_, om_, m, inertia)
    loss = core.dissipated_energy(*inc)
    wcn, wct, wrn, wrt = core.phase_works(*inc)
    tau_m = core.min_energy_impulse(*inc)
    flags = core.rebound_outcomes(vx_, vy_, om_, r, zeta, mu_, kappa_)
    newton, poisson, energetic = core.restitution_coefficients(m, vy_, vy1, wcn, wrn)
    return Impact(
        body=body,
        mu=_out(mu_),
        kappa=_out(kappa_),
        before=State(_out(vx_), _out(vy_), _out(om_)),
        after=State(_out(vx1), _out(vy1), _out(om1)),
        slip_before=_out(slip),
        slip_after=_out(core.rebound_slip(slip, vy_, zeta, mu_, kappa_)),
        incidence_ratio=_out(core.incidence_ratio(slip, vy_)),
        regime=_out(np.asarray(core.REGIMES)[core.regime_code(slip, vy_, zeta, mu_, kappa_)]),
        tau0=_out(tau0),
        tau_star=_out(core.stick_impulse(m, slip, zeta, mu_)),
        tau1=_out(tau1),
        tangential_impulse=_out(f1),
        impulse_ratio=_out(core.impulse_ratio(slip, vy_, zeta, mu_, kappa_)),
        kinetic_energy_before=_out(e0),
        kinetic_energy_after=_out(core.kinetic_energy(vx1, vy1, om1, m, inertia)),
        dissipated_energy=_out(loss),
        dissipated_fraction=_out(loss / e0),
        work_compression_normal=_out(wcn),
        work_compression_tangential=_out(wct),
        work_restitution_normal=_out(wrn),
        work_restitution_tangential=_out(wrt),
        work_ratio_tangential=_out(
            core.work_ratio_tangential(core.incidence_ratio(slip, vy_), zeta, mu_, kappa_)
        ),
        min_kinetic_energy=_out(core.kinetic_energy_at(tau_m, *inc[:-1], inertia)),
        tau_min_energy=_out(tau_m),
        min_energy_case=_out(np.asarray(core.MIN_ENERGY_CASES)[core.min_energy_case(*inc)]),
        newton_restitution=_out(newton),
        poisson_restitution=_out(poisson),
        energetic_restitution=_out(energetic),
        outcome=Outcome(*(_out(x) for x in flags)),
    )
