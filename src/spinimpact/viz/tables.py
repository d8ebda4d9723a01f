"""The tables of an impact report, as plain data, built once for every output.

The terminal report (:mod:`spinimpact.viz.report`, Rich) and the HTML page
(:mod:`spinimpact.viz.html`) render the same :class:`Table` objects, which hold
nothing but strings: the same rows and numbers, only the markup differs.

Every number is formatted by :func:`number` (six significant digits, ``inf``,
``-inf``, ``undefined`` for NaN, never ``-0``); units sit in the column
headings or the row labels, or, for the inputs, beside the value. Labels come in
two notations chosen by ``typeset``: plain ASCII (``omega``, ``tau1``,
``mu_hat``) for a terminal, or typeset Unicode (``ω``, ``τ₁``, ``μ̂``) for a page.

Examples
--------
>>> from spinimpact import Body, solve
>>> imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 3.0, -4.0, 10.0, mu=0.2, kappa=0.8)
>>> rebound = impact_tables(imp)[1]
>>> rebound.title, rebound.columns, rebound.rows[0]
('Rebound', ('', 'before', 'after'), ('vx (m/s)', '3', '1.85714'))
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from typing import TYPE_CHECKING, Any

from ._labels import min_energy_words, notation

if TYPE_CHECKING:
    from ..model.dynamics import Simulation
    from ..model.impact import Impact
    from ..model.particle import ParticleImpact

__all__ = ["Table", "number", "duration", "impact_tables", "regime_summary",
           "simulation_table"]  # fmt: skip


@dataclass(frozen=True)
class Table:
    """One table of a report: a title, column headings and rows of formatted strings.

    Attributes
    ----------
    key : str
        Stable name (``"rebound"``, ``"energy"``, ...) for renderers that lay out or style.
    title : str
        Heading of the table, e.g. ``"Energy budget"``.
    columns : tuple of str
        Column headings, with the unit of their column where it has one (``"normal (J)"``).
    rows : tuple of tuple of str
        Rows as long as ``columns``: a label (with the row's unit where the columns
        have none), then the formatted values.
    note : str
        A sentence shown under the table (``""`` for none).
    """

    key: str
    title: str
    columns: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    note: str = ""

    def values(self) -> list[str]:
        """Every cell but the row labels, row by row: the strings every output shows."""
        return [cell for row in self.rows for cell in row[1:]]


def number(x: Any, unit: str = "") -> str:
    """Format one number for a report: six significant digits and an optional unit.

    Parameters
    ----------
    x : float
        The value, in the SI unit named by ``unit`` (or dimensionless).
    unit : str, optional
        Unit written after the number (``"kg"``, ``"N s"``); none by default.

    Returns
    -------
    str
        ``"1.85714"``, ``"0.1 m"``; ``"inf"`` or ``"-inf"`` for infinities,
        ``"undefined"`` for NaN (a quantity the impact does not define, such as
        ``tau*`` without friction). ``-0`` is written ``0``.

    Examples
    --------
    >>> number(2 / 3, "m/s"), number(-0.0), number(float("inf")), number(float("nan"))
    ('0.666667 m/s', '0', 'inf', 'undefined')
    """
    x = float(x) + 0.0  # no "-0"
    if math.isnan(x):
        text = "undefined"
    elif math.isinf(x):
        text = "inf" if x > 0 else "-inf"
    else:
        text = f"{x:.6g}"
    return f"{text} {unit}".rstrip()


def duration(seconds: Any) -> str:
    """Format a time for a report in a unit that suits it: µs below 1 ms, ms below 1 s,
    else s (six significant digits, as :func:`number`). Micro is the micro sign ``µ``
    everywhere (µs, µm), never ``u``.

    Examples
    --------
    >>> duration(6.18087e-6), duration(0.0031416), duration(2.5)
    ('6.18087 µs', '3.1416 ms', '2.5 s')
    """
    t = float(seconds)
    for unit, scale in (("µs", 1e-6), ("ms", 1e-3)):
        if abs(t) < 1e3 * scale:
            return number(t / scale, unit)
    return number(t, "s")


def _labelled(
    label: Callable[[str], str], key: str, title: str, columns: tuple, *rows: tuple, note: str = ""
) -> Table:
    """A :class:`Table` whose headings and row labels are put in the notation of ``label``."""
    columns = tuple(label(c) for c in columns)
    return Table(key, title, columns, tuple((label(r[0]), *r[1:]) for r in rows), note)


def _share(value: Any, total: float) -> str:
    """``value`` as a percentage of ``total`` (empty when ``total`` is 0)."""
    return f"{float(value) / total:.2%}" if total else ""


def _flag(value: Any) -> str:
    return "yes" if bool(value) else "no"


def _verdict(change: Any) -> str:
    """What an energy change ``E+ - E-`` (J) does to the energy."""
    change = float(change)
    if change > 0:
        return "creates energy"
    return "conserves energy" if change == 0 else "dissipates energy"


def regime_summary(imp: Impact, *, typeset: bool = False) -> str:
    """The incidence ratio beside the two thresholds that decide the regime.

    Parameters
    ----------
    imp : Impact
        A single impact (shape ``()``).
    typeset : bool, optional
        Unicode symbols (``ζμ``, ``≤``) instead of ASCII (``zeta*mu``, ``<=``).

    Returns
    -------
    str
        ``"|u-/v-| = 0.5 (stick in compression if <= zeta*mu = 0.7; ...)"``.

    Notes
    -----
    The contact sticks in compression if :math:`|u^-/v^-| \\le \\zeta\\mu`, before
    the rebound if :math:`|u^-/v^-| \\le (1+\\kappa)\\zeta\\mu` (eqs. 4.6, 4.14, 4.15).

    References
    ----------
    V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
    surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy
    of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    """
    from ..core import regime_thresholds

    label = notation(typeset)
    if imp.regime == "frictionless":
        return f"{label('mu')} = 0: no friction, so the slip u and the spin do not change"
    if imp.regime == "no-slip":
        return f"{label('|u-/v-|')} = 0: the contact point has no slip before or after"
    low, high = regime_thresholds(imp.body.zeta, imp.mu, imp.kappa)
    return (
        f"{label('|u-/v-|')} = {number(imp.incidence_ratio)} (stick in compression if "
        f"{label('<= zeta*mu')} = {number(low)}; stick before rebound if "
        f"{label('<= (1+kappa)*zeta*mu')} = {number(high)})"
    )


def impact_tables(
    imp: Impact, particle: ParticleImpact | None = None, *, typeset: bool = False
) -> tuple[Table, ...]:
    """The tables describing one impact, in the order a report shows them.

    Parameters
    ----------
    imp : Impact
        A single impact (shape ``()``), from :func:`spinimpact.solve`.
    particle : ParticleImpact, optional
        Whittaker's material particle with the same ``vx``, ``vy``, ``mu``,
        ``kappa`` and mass (:func:`spinimpact.solve_particle`); adds a last table
        comparing it with the rigid body.
    typeset : bool, optional
        Labels in typeset Unicode (``ω``, ``τ₁``, ``μ̂``) instead of ASCII
        (``omega``, ``tau1``, ``mu_hat``). The values are the same either way.

    Returns
    -------
    tuple of Table
        Keys ``inputs`` (body, m in kg, R and rho in m, zeta, mu, kappa),
        ``rebound`` (vx, vy in m/s, omega in rad/s, slip u in m/s), ``impulses``
        (tau0, tau*, tau1, f1 in N s), ``energy`` (E-, E+, Delta E, Em in J and
        as a share of E-), ``works`` (J, by phase), ``coefficients``,
        ``outcome`` (yes/no flags) and, with ``particle``, ``particle``.

    Raises
    ------
    ValueError
        If ``imp`` holds more than one impact.

    Notes
    -----
    The quantities are the fields of :class:`~spinimpact.Impact`: the normal
    impulses at the end of compression, of slip and of the impact (eqs. 3.2, 4.3,
    3.6), the friction impulse (eq. 5.7), the kinetic energies (eqs. 5.1-5.10),
    the works by phase (eqs. 6.1-6.11), the three restitution coefficients (eqs.
    1.1-1.3), the tangential impact coefficient :math:`\\hat\\mu = f_1/\\tau_1`
    (eq. 7.4), the friction work ratio :math:`W_r^t/W_c^t` (eqs. 6.15-6.19) and
    the minimum kinetic energy during the impact (eqs. 8.1-8.6). The particle
    follows Whittaker's unidirectional-slip model (eq. 8.7), which can create
    energy; the rigid body never does.

    References
    ----------
    V. A. Lubarda, "On the frictional impact of a spinning disk against a fixed
    surface", Proceedings of the Section of Natural Sciences, Montenegrin Academy
    of Sciences and Arts (Glasnik Odjeljenja prirodnih nauka, CANU) 19 (2010).
    """
    if imp.shape != ():
        raise ValueError(f"a report describes one impact; this Impact has shape {imp.shape}")
    label = notation(typeset)
    table = partial(_labelled, label)

    b, n, e0 = imp.body, number, float(imp.kinetic_energy_before)
    before, after, o = imp.before, imp.after, imp.outcome
    wn = (imp.work_compression_normal, imp.work_restitution_normal)
    wt = (imp.work_compression_tangential, imp.work_restitution_tangential)
    energies = (
        ("kinetic energy before, E-", e0),
        ("kinetic energy after, E+", imp.kinetic_energy_after),
        ("dissipated, E- - E+", imp.dissipated_energy),
        ("minimum during impact, Em", imp.min_kinetic_energy),
    )
    phases = ("compression", "restitution", "whole impact")
    works = zip(phases, (*wn, wn[0] + wn[1]), (*wt, wt[0] + wt[1]), strict=True)
    tables = (
        table(
            "inputs",
            "Inputs",
            ("input", "value"),
            ("body", str(b.name)),
            ("mass m", n(b.mass, "kg")),
            ("contact radius R", n(b.radius, "m")),
            ("radius of gyration rho", n(b.gyration, "m")),
            ("zeta = 1 + R^2/rho^2", n(b.zeta)),
            ("friction mu", n(imp.mu)),
            ("restitution kappa", n(imp.kappa)),
        ),
        table(
            "rebound",
            "Rebound",
            ("", "before", "after"),
            ("vx (m/s)", n(before.vx), n(after.vx)),
            ("vy (m/s)", n(before.vy), n(after.vy)),
            ("omega (rad/s)", n(before.omega), n(after.omega)),
            ("slip u = vx + R*omega (m/s)", n(imp.slip_before), n(imp.slip_after)),
        ),
        table(
            "impulses",
            "Impulses",
            ("impulse", "N s"),
            ("end of compression, tau0", n(imp.tau0)),
            ("end of slip, tau*", n(imp.tau_star)),
            ("end of impact, tau1", n(imp.tau1)),
            ("friction impulse, f1", n(imp.tangential_impulse)),
        ),
        table(
            "energy",
            "Energy budget",
            ("energy", "J", "of E-"),
            *((name, n(value), _share(value, e0)) for name, value in energies),
            note=f"Minimum energy at {label('tau_m')} = {n(imp.tau_min_energy, 'N s')}: "
            f"{min_energy_words(imp)}",
        ),
        table(
            "works",
            "Works of the contact forces",
            ("phase", "normal (J)", "friction (J)", "total (J)"),
            *(
                (phase, n(normal), n(friction), n(normal + friction))
                for phase, normal, friction in works
            ),
        ),
        table(
            "coefficients",
            "Coefficients",
            ("coefficient", "value"),
            ("Newton restitution -v+/v-", n(imp.newton_restitution)),
            ("Poisson restitution (tau1-tau0)/tau0", n(imp.poisson_restitution)),
            ("energetic restitution sqrt(-Wr^n/Wc^n)", n(imp.energetic_restitution)),
            ("tangential impact coefficient mu_hat = f1/tau1", n(imp.impulse_ratio)),
            ("friction work ratio Wr^t/Wc^t", n(imp.work_ratio_tangential)),
        ),
        table(
            "outcome",
            "Outcome",
            ("rebound outcome", ""),
            ("backward rebound", _flag(o.backward)),
            ("reversed spin", _flag(o.reversed_spin)),
            ("vertical rebound", _flag(o.vertical)),
            ("leaves spinning", _flag(o.spinning)),
            ("leaves without slip (u+ = 0)", _flag(o.rolling)),
        ),
    )
    if particle is not None:
        tables += (_particle_table(imp, particle, label),)
    return tables


def _particle_table(imp: Impact, particle: ParticleImpact, label: Callable[[str], str]) -> Table:
    """The rigid body beside Whittaker's particle with the same incidence (eq. 8.7)."""
    if particle.shape != ():
        raise ValueError(f"a report describes one impact; this particle has shape {particle.shape}")
    limit = float(particle.energy_threshold)
    when = (
        f"that model creates energy whenever |vx/vy| < {number(limit)}"
        if limit > 0
        else f"that model creates no energy at this {label('mu and kappa')}"
    )
    change = -float(imp.dissipated_energy)
    return _labelled(
        label,
        "particle",
        "Compared with a material particle",
        ("", "rigid body", "particle (eq. 8.7)"),
        ("vx+ (m/s)", number(imp.after.vx), number(particle.after.vx)),
        ("vy+ (m/s)", number(imp.after.vy), number(particle.after.vy)),
        ("energy change E+ - E- (J)", number(change), number(particle.energy_change)),
        ("energy", _verdict(change), _verdict(particle.energy_change)),
        note="Whittaker's unidirectional-slip model (eq. 8.7) for a material particle with the "
        f"same vx, vy; {when}. The rigid body never gains energy.",
    )


def simulation_table(sim: Simulation) -> Table:
    """A compliant-contact simulation beside the rigid closed form at its restitution.

    Parameters
    ----------
    sim : Simulation
        Result of :func:`spinimpact.dynamics.simulate`.

    Returns
    -------
    Table
        Key ``simulation``: rebound velocities (m/s, rad/s), dissipated energy (J),
        ``mu_hat`` and the three restitution coefficients, simulated, rigid and
        their difference (simulated minus rigid, two significant digits).

    Notes
    -----
    The rigid column is :meth:`Simulation.rigid`: the closed form at the law's own
    Newton restitution, which Keller's result says the rebound must match; the
    differences measure the compliance and the integrator.
    """
    rigid = sim.rigid()
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
    return Table(
        "simulation",
        "Simulated vs rigid closed form",
        ("", "simulated", "rigid", "difference"),
        tuple((name, number(a), number(b), f"{float(a) - float(b):.2e}") for name, a, b in rows),
        note=f"Rigid regime at kappa = {number(rigid.kappa)}: {rigid.regime}",
    )
