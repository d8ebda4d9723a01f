"""Readable text report of one impact, rendered with Rich."""

from __future__ import annotations

import math

from rich.console import Console
from rich.table import Table

from ..core import regime_thresholds
from ..model.impact import Impact
from ..model.particle import ParticleImpact

__all__ = ["print_report"]


def _g(x: float, unit: str = "") -> str:
    x = float(x)
    if math.isinf(x):
        text = "inf"
    elif math.isnan(x):
        text = "undefined"
    else:
        text = f"{x:.6g}"
    return f"{text} {unit}".rstrip()


def _table(title: str, *columns: str) -> Table:
    table = Table(title=title, title_justify="left", title_style="bold", show_edge=False)
    for i, c in enumerate(columns):
        table.add_column(c, justify="left" if i == 0 else "right")
    return table


def print_report(
    imp: Impact, particle: ParticleImpact | None = None, console: Console | None = None
) -> None:
    """Print the regime, rebound, energy budget, works by phase, coefficients and
    outcome of a single impact; with ``particle``, the Whittaker particle beside it."""
    console = console or Console(highlight=False, soft_wrap=True)
    b = imp.body
    compression_limit, impact_limit = regime_thresholds(b.zeta, imp.mu, imp.kappa)
    console.print(
        f"[bold]Impact of a {b.name} body[/bold]  m = {_g(b.mass, 'kg')}, R = {_g(b.radius, 'm')}, "
        f"rho = {_g(b.gyration, 'm')}, zeta = {_g(b.zeta)};  "
        f"mu = {_g(imp.mu)}, kappa = {_g(imp.kappa)}"
    )
    console.print(
        f"Regime: [bold]{imp.regime}[/bold]   |u-/v-| = {_g(imp.incidence_ratio)}  "
        f"(stick in compression if <= zeta*mu = {_g(compression_limit)}; "
        f"stick before rebound if <= (1+kappa)*zeta*mu = {_g(impact_limit)})"
    )
    console.print(
        f"Normal impulse: tau0 = {_g(imp.tau0, 'N s')}, tau* = {_g(imp.tau_star, 'N s')}, "
        f"tau1 = {_g(imp.tau1, 'N s')};  friction impulse f1 = {_g(imp.tangential_impulse, 'N s')}"
    )
    console.print()

    t = _table("Rebound", "", "before", "after")
    t.add_row("vx (m/s)", _g(imp.before.vx), _g(imp.after.vx))
    t.add_row("vy (m/s)", _g(imp.before.vy), _g(imp.after.vy))
    t.add_row("omega (rad/s)", _g(imp.before.omega), _g(imp.after.omega))
    t.add_row("slip u (m/s)", _g(imp.slip_before), _g(imp.slip_after))
    console.print(t)
    console.print()

    e0 = float(imp.kinetic_energy_before)
    t = _table("Energy budget", "", "J", "of E-")
    for label, value in (
        ("kinetic energy before, E-", imp.kinetic_energy_before),
        ("kinetic energy after, E+", imp.kinetic_energy_after),
        ("dissipated, E- - E+", imp.dissipated_energy),
        ("minimum during impact, Em", imp.min_kinetic_energy),
    ):
        t.add_row(label, _g(value), f"{float(value) / e0:.2%}" if e0 else "")
    console.print(t)
    console.print(
        f"Minimum energy at tau_m = {_g(imp.tau_min_energy, 'N s')}: {imp.min_energy_case}"
    )
    console.print()

    t = _table("Works of the contact forces (J)", "phase", "normal", "friction", "total")
    rows = (
        ("compression", imp.work_compression_normal, imp.work_compression_tangential),
        ("restitution", imp.work_restitution_normal, imp.work_restitution_tangential),
        (
            "whole impact",
            imp.work_compression_normal + imp.work_restitution_normal,
            imp.work_compression_tangential + imp.work_restitution_tangential,
        ),
    )
    for phase, wn, wt in rows:
        t.add_row(phase, _g(wn), _g(wt), _g(wn + wt))
    console.print(t)
    console.print()

    t = _table("Coefficients", "", "value")
    t.add_row("Newton restitution -v+/v-", _g(imp.newton_restitution))
    t.add_row("Poisson restitution (tau1-tau0)/tau0", _g(imp.poisson_restitution))
    t.add_row("energetic restitution sqrt(-Wr^n/Wc^n)", _g(imp.energetic_restitution))
    t.add_row("tangential impact coefficient mu_hat = f1/tau1", _g(imp.impulse_ratio))
    t.add_row("friction work ratio Wr^t/Wc^t", _g(imp.work_ratio_tangential))
    console.print(t)
    console.print()

    o = imp.outcome
    flags = [
        ("backward rebound", o.backward),
        ("reversed spin", o.reversed_spin),
        ("vertical rebound", o.vertical),
        ("leaves spinning", o.spinning),
        ("leaves rolling (u+ = 0)", o.rolling),
    ]
    console.print("Outcome: " + ", ".join(f"{name}: {'yes' if v else 'no'}" for name, v in flags))

    if particle is not None:
        verdict = "CREATES energy" if particle.creates_energy else "dissipates energy"
        limit = float(particle.energy_threshold)
        when = (
            f"that model creates energy whenever |vx/vy| < {_g(limit)}"
            if limit > 0
            else "that model creates no energy at this mu and kappa"
        )
        console.print(
            f"Compare: a material particle under Whittaker's unidirectional-slip model (eq. 8.7) "
            f"with the same vx, vy leaves at vx+ = {_g(particle.after.vx, 'm/s')} and its energy "
            f"changes by {_g(particle.energy_change, 'J')} ({verdict}; {when}). "
            f"The rigid body never gains energy."
        )


def print_simulation(sim, console: Console | None = None) -> None:
    """Print a compliant-contact simulation beside the rigid closed form at the
    law's own restitution."""
    console = console or Console(highlight=False, soft_wrap=True)
    rigid = sim.rigid()
    console.print(f"[bold]Compliant impact[/bold] with {sim.contact!r}")
    console.print(
        f"contact duration {_g(sim.contact_duration * 1e3, 'ms')}, peak normal force "
        f"{_g(sim.peak_force, 'N')}, largest compression {_g(sim.max_compression * 1e6, 'µm')}"
    )
    if sim.stick_time == sim.stick_time:  # not NaN
        console.print(
            f"slip stops at t = {_g(sim.stick_time * 1e3, 'ms')} (tau = {_g(sim.tau_star, 'N s')})"
        )
    t = _table("Simulated vs rigid closed form", "", "simulated", "rigid", "difference")
    rows = (
        ("vx+ (m/s)", sim.after.vx, rigid.after.vx),
        ("vy+ (m/s)", sim.after.vy, rigid.after.vy),
        ("omega+ (rad/s)", sim.after.omega, rigid.after.omega),
        ("dissipated energy (J)", sim.dissipated_energy, rigid.dissipated_energy),
        ("mu_hat = f1/tau1", sim.impulse_ratio, rigid.impulse_ratio),
        ("Newton restitution", sim.newton_restitution, rigid.newton_restitution),
        ("Poisson restitution", sim.poisson_restitution, rigid.poisson_restitution),
        ("energetic restitution", sim.energetic_restitution, rigid.energetic_restitution),
    )
    for label, a, b in rows:
        t.add_row(label, _g(a), _g(b), f"{float(a) - float(b):.2e}")
    console.print(t)
    console.print(f"Rigid regime at kappa = {_g(rigid.kappa)}: {rigid.regime}")
