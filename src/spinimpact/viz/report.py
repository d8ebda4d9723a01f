"""Readable text report of one impact, rendered with Rich.

The tables come from :mod:`spinimpact.viz.tables`, the same builder the HTML
page uses, in its ASCII notation (``omega``, ``tau1``, ``mu_hat``), so the
terminal and the page show the same rows and numbers.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from rich.console import Console
from rich.table import Table as RichTable
from rich.text import Text

from ..model.impact import Impact
from ..model.particle import ParticleImpact
from .tables import Table, impact_tables, number, regime_summary, simulation_table

if TYPE_CHECKING:
    from ..model.dynamics import Simulation

__all__ = ["print_report", "print_simulation"]

_STYLES = {"creates energy": "bold red"}


def _rich(table: Table) -> RichTable:
    """A builder table as a Rich table: labels left, values right, no markup parsed."""
    out = RichTable(title=table.title, title_justify="left", title_style="bold", show_edge=False)
    for i, heading in enumerate(table.columns):
        out.add_column(Text(heading), justify="left" if i == 0 else "right")
    for row in table.rows:
        out.add_row(*(Text(cell, style=_STYLES.get(cell, "")) for cell in row))
    return out


def _console(console: Console | None) -> Console:
    return console or Console(highlight=False, soft_wrap=True)


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
    console.print(Text(f"Impact of a {imp.body.name} body on a rough surface", style="bold"))
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
    The contact duration is printed in ms and the largest compression in µm;
    the table is :func:`~spinimpact.viz.tables.simulation_table`.
    """
    console = _console(console)
    console.print(Text.assemble(("Compliant impact", "bold"), f" with {sim.contact!r}"))
    console.print(
        f"contact duration {number(sim.contact_duration * 1e3, 'ms')}, peak normal force "
        f"{number(sim.peak_force, 'N')}, largest compression "
        f"{number(sim.max_compression * 1e6, 'µm')}",
        markup=False,
    )
    if sim.stick_time == sim.stick_time:  # not NaN
        console.print(
            f"slip stops at t = {number(sim.stick_time * 1e3, 'ms')} "
            f"(tau = {number(sim.tau_star, 'N s')})",
            markup=False,
        )
    table = simulation_table(sim)
    console.print(_rich(table))
    console.print(Text(table.note))
