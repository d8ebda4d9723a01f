"""Readable text report of one impact, rendered with Rich.

The tables come from :mod:`spinimpact.viz.tables`, the same builder the HTML
page uses, in its ASCII notation (``omega``, ``tau1``, ``mu_hat``), so the
terminal and the page show the same rows and numbers.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from rich.console import Console
from rich.table import Table as RichTable
from rich.text import Text

from ..model.impact import Impact
from ..model.particle import ParticleImpact
from ._labels import report_title
from .tables import Table, duration, impact_tables, number, regime_summary, simulation_table

if TYPE_CHECKING:
    from ..model.dynamics import Simulation
    from ..model.planar import PlanarImpact

__all__ = [
    "print_tables",
    "print_report",
    "print_simulation",
    "planar_tables",
    "print_planar_report",
    "console",
    "PIPED_WIDTH",
]

#: Columns of a report printed where no terminal tells its width (a pipe, a file) and
#: ``COLUMNS`` is not set: Rich would assume 80 and squeeze wider tables, wrapping rows.
PIPED_WIDTH = 160

_STYLES = {"creates energy": "bold red"}


def _rich(table: Table) -> RichTable:
    """A builder table as a Rich table: labels left, values right, no markup parsed."""
    out = RichTable(
        title=Text(table.title), title_justify="left", title_style="bold", show_edge=False
    )
    for i, heading in enumerate(table.columns):
        out.add_column(Text(heading), justify="left" if i == 0 else "right")
    for row in table.rows:
        out.add_row(*(Text(cell, style=_STYLES.get(cell, "")) for cell in row))
    return out


def console(*, stderr: bool = False) -> Console:
    """The console reports print to: no highlighting, long lines kept whole, and
    :data:`PIPED_WIDTH` columns when it is not a terminal (unless ``COLUMNS`` says)."""
    out = Console(highlight=False, soft_wrap=True, stderr=stderr)
    if not out.is_terminal and "COLUMNS" not in os.environ:
        out.width = PIPED_WIDTH
    return out


def _console(given: Console | None) -> Console:
    return given or console()


def print_tables(tables: tuple[Table, ...], console: Console | None = None) -> None:
    """Print builder tables (:class:`~spinimpact.viz.tables.Table`) with Rich, each with its
    note under it."""
    console = _console(console)
    for table in tables:
        console.print(_rich(table))
        if table.note:
            console.print(Text(table.note))
        console.print()


def print_report(
    imp: Impact, particle: ParticleImpact | None = None, console: Console | None = None
) -> None:
    """Print the complete report of one impact on a terminal.

    The regime and its thresholds, then the tables of
    :func:`~spinimpact.viz.tables.impact_tables`: inputs, rebound, impulses,
    energy budget, works by phase, coefficients, the outcome flags (as one
    line) and, with ``particle``, Whittaker's particle beside the rigid body.

    Parameters
    ----------
    imp : Impact
        A single impact (shape ``()``), from :func:`spinimpact.solve`.
    particle : ParticleImpact, optional
        Whittaker's particle with the same incidence, from
        :func:`spinimpact.solve_particle`.
    console : rich.console.Console, optional
        Where to print; by default standard output, without syntax highlighting.

    Raises
    ------
    ValueError
        If ``imp`` holds more than one impact.

    Notes
    -----
    Units are SI: velocities in m/s, spin in rad/s (counter-clockwise
    positive), impulses in N s, energies and works in J.

    References
    ----------
    V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
    surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy
    of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    """
    tables = impact_tables(imp, particle)
    console = _console(console)
    console.print(Text(report_title(imp), style="bold"))
    console.print(Text.assemble("Regime: ", (str(imp.regime), "bold"), "   ", regime_summary(imp)))
    for table in tables:
        console.print()
        if table.key == "outcome":
            flags = ", ".join(f"{name}: {value}" for name, value in table.rows)
            console.print(Text(f"{table.title}: {flags}"))
            continue
        console.print(_rich(table))
        if table.note:
            console.print(Text(table.note))


def print_simulation(sim: Simulation, console: Console | None = None) -> None:
    """Print a compliant-contact simulation beside the rigid closed form at the
    law's own restitution.

    Parameters
    ----------
    sim : Simulation
        Result of :func:`spinimpact.dynamics.simulate`.
    console : rich.console.Console, optional
        Where to print; by default standard output, without syntax highlighting.

    Notes
    -----
    Times are printed in µs, ms or s (:func:`~spinimpact.viz.tables.duration`) and the
    largest compression in µm;
    the table is :func:`~spinimpact.viz.tables.simulation_table`.
    """
    console = _console(console)
    console.print(Text.assemble(("Compliant impact", "bold"), f" with {sim.contact!r}"))
    console.print(
        f"contact duration {duration(sim.contact_duration)}, peak normal force "
        f"{number(sim.peak_force, 'N')}, largest compression "
        f"{number(sim.max_compression * 1e6, 'µm')}",
        markup=False,
    )
    if sim.stick_time == sim.stick_time:  # not NaN
        console.print(
            f"slip stops at t = {duration(sim.stick_time)} (tau = {number(sim.tau_star, 'N s')})",
            markup=False,
        )
    table = simulation_table(sim)
    console.print(_rich(table))
    console.print(Text(table.note))


def planar_tables(imp: PlanarImpact) -> tuple[Table, ...]:
    """The tables of a planar impact's report, in ASCII labels.

    Parameters
    ----------
    imp : PlanarImpact
        A single impact (shape ``()``), from :func:`spinimpact.solve_planar` or
        :func:`spinimpact.solve_pendulum`.

    Returns
    -------
    tuple of Table
        Keys ``inputs`` (body, its geometry in kg, kg m^2 and m, the collision matrix in
        1/kg, mu, kappa, the law), ``rebound`` (centre velocity, spin and the contact's
        slip and normal velocity, before and after), ``impulses`` (tau0, tau*, tau1, f1 in
        N s; mu_hat), ``energy`` (J and share of E-), ``works`` (J, by phase) and
        ``coefficients`` (the three restitution coefficients; whether energy is created).
    """
    from .planar import LAW_NAMES

    if imp.shape != ():
        raise ValueError(f"a report describes one impact; this PlanarImpact has shape {imp.shape}")
    b, w, e0, n = imp.body, imp.body.collision_matrix, float(imp.kinetic_energy_before), number
    units = {"mass": "kg", "inertia": "kg m^2"}
    wn = (imp.work_compression_normal, imp.work_restitution_normal)
    wt = (imp.work_compression_tangential, imp.work_restitution_tangential)
    phases = ("compression", "restitution", "whole impact")
    energy = {
        "kinetic energy before, E-": e0,
        "kinetic energy after, E+": imp.kinetic_energy_after,
        "dissipated, E- - E+": imp.dissipated_energy,
        "minimum during impact, Em": imp.min_kinetic_energy,
    }
    velocities = {
        "vx (m/s)": (imp.before.vx, imp.after.vx),
        "vy (m/s)": (imp.before.vy, imp.after.vy),
        "omega (rad/s)": (imp.before.omega, imp.after.omega),
        "contact slip u (m/s)": (imp.slip_before, imp.slip_after),
        "contact normal velocity v (m/s)": (imp.normal_velocity_before, imp.normal_velocity_after),
    }
    rows: dict[str, tuple] = {
        "inputs": (
            ("body", str(b.name)),
            *((name, n(getattr(b, name), units.get(name, "m"))) for name in b.COLUMNS),
            ("W_tt, W_tn, W_nn (1/kg)", ", ".join(n(x) for x in (w.tt, w.tn, w.nn))),
            ("friction mu", n(imp.mu)),
            ("restitution kappa", n(imp.kappa)),
            ("restitution law", LAW_NAMES[imp.law]),
        ),
        "rebound": tuple((k, n(x), n(y)) for k, (x, y) in velocities.items()),
        "impulses": (
            ("end of compression, tau0", n(imp.tau0)),
            ("end of slip, tau*", n(imp.tau_star)),
            ("end of impact, tau1", n(imp.tau1)),
            ("tangential impulse, f1", n(imp.tangential_impulse)),
            ("mu_hat = f1/tau1 (no unit)", n(imp.impulse_ratio)),
        ),
        "energy": tuple((k, n(x), f"{float(x) / e0:.2%}" if e0 else "") for k, x in energy.items()),
        "works": tuple(
            (p, n(x), n(y), n(x + y))
            for p, x, y in zip(phases, (*wn, sum(wn)), (*wt, sum(wt)), strict=True)
        ),
        "coefficients": (
            ("Newton restitution -v+/v-", n(imp.newton_restitution)),
            ("Poisson restitution (tau1-tau0)/tau0", n(imp.poisson_restitution)),
            ("energetic restitution sqrt(-Wr^n/Wc^n)", n(imp.energetic_restitution)),
            ("creates energy (E+ > E-)", "yes" if bool(imp.creates_energy) else "no"),
        ),
    }
    heads = {
        "inputs": ("Inputs", ("input", "value")),
        "rebound": ("Rebound", ("", "before", "after")),
        "impulses": ("Impulses", ("impulse", "N s")),
        "energy": ("Energy budget", ("energy", "J", "of E-")),
        "works": (
            "Works of the contact forces",
            ("phase", "normal (J)", "friction (J)", "total (J)"),
        ),
        "coefficients": ("Coefficients", ("coefficient", "value")),
    }
    note = {"energy": f"Minimum energy at tau_m = {n(imp.tau_min_energy, 'N s')}"}
    return tuple(Table(k, *heads[k], rows[k], note.get(k, "")) for k in heads)


def print_planar_report(imp: PlanarImpact, console: Console | None = None) -> None:
    """Print the report of one planar impact (:func:`spinimpact.solve_planar` or
    :func:`spinimpact.solve_pendulum`): the regime and law, then the tables of
    :func:`planar_tables` (inputs with the collision matrix,
    rebound with the contact velocity, impulses, energy budget, works, coefficients).

    Parameters
    ----------
    imp : PlanarImpact
        A single impact (shape ``()``).
    console : rich.console.Console, optional
        Where to print; by default standard output, without syntax highlighting.
    """
    from .planar import LAW_NAMES

    tables = planar_tables(imp)
    console = _console(console)
    surface = "a rough surface" if float(imp.mu) > 0 else "a smooth surface (mu = 0)"
    console.print(Text(f"Planar impact: {imp.body.name} on {surface}", style="bold"))
    gain = ("   creates energy", "bold red") if bool(imp.creates_energy) else ""
    law = f"   law: {LAW_NAMES[imp.law]}"
    console.print(Text.assemble("Regime: ", (str(imp.regime), "bold"), law, gain))
    for table in tables:
        console.print()
        console.print(_rich(table))
        if table.note:
            console.print(Text(table.note))
