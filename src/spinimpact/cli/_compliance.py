"""The tangential compliance options (``--tangential``, ``--beta0``, ``--poisson-ratio``,
``--stiffness-ratio``) and the plain-text reports of a :class:`~spinimpact.CompliantImpact`
and a :class:`~spinimpact.CompliantSphereImpact`."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import click
import numpy as np

from ..model.compliance import (
    CompliantImpact,
    CompliantSphereImpact,
    MindlinDeresiewicz,
    Stronge,
    TangentialLaw,
    Walton,
)

__all__ = [
    "tangential_options", "tangential_law", "print_compliant", "print_compliant_sphere",
    "sweep_class",
]  # fmt: skip


def tangential_options(function: Callable) -> Callable:
    """Add the tangential compliance options to a command."""
    options = [
        click.option(
            "--tangential",
            type=click.Choice(["rigid", "walton", "stronge", "mindlin-deresiewicz"]),
            default="rigid",
            show_default=True,
            help="Tangential law: the rigid law (the contact point leaves at rest when it "
            "sticks), Walton's three-parameter model (--beta0), Stronge's lumped "
            "compliance or Hertz-Mindlin-Deresiewicz contact with micro-slip (either with "
            "--poisson-ratio or --stiffness-ratio). See docs/compliance.md.",
        ),
        click.option(
            "--beta0",
            type=float,
            default=None,
            help="Walton: tangential restitution of sticking impacts, in [-1, 1].",
        ),
        click.option(
            "--poisson-ratio",
            type=float,
            default=None,
            help="Poisson's ratio nu in (-1, 0.5]. Stronge, mindlin-deresiewicz: "
            "k_t/k_n = 2(1-nu)/(2-nu) (Mindlin).",
        ),
        click.option(
            "--stiffness-ratio",
            type=float,
            default=None,
            help="Tangential over normal contact stiffness k_t/k_n > 0. Stronge, "
            "mindlin-deresiewicz.",
        ),
    ]
    for option in reversed(options):
        function = option(function)
    return function


def tangential_law(o: dict[str, Any]) -> TangentialLaw | None:
    """The law the options name (``None`` for the rigid law).

    Raises
    ------
    click.UsageError
        For a parameter of another law, or a law without its parameter.
    ValueError, TypeError
        From the law, for a parameter out of range.
    """
    kind, beta0 = o["tangential"], o["beta0"]
    nu, ratio = o["poisson_ratio"], o["stiffness_ratio"]
    if kind != "walton" and beta0 is not None:
        raise click.UsageError("--beta0 applies to --tangential walton only")
    if kind not in ("stronge", "mindlin-deresiewicz") and (nu is not None or ratio is not None):
        which = "--poisson-ratio" if nu is not None else "--stiffness-ratio"
        raise click.UsageError(
            f"{which} applies to --tangential stronge and mindlin-deresiewicz only"
        )
    if kind == "walton":
        if beta0 is None:
            raise click.UsageError("--tangential walton needs --beta0 (in [-1, 1])")
        return Walton(beta0)
    if kind in ("stronge", "mindlin-deresiewicz"):
        if (nu is None) == (ratio is None):
            raise click.UsageError(
                f"--tangential {kind} needs exactly one of --poisson-ratio and --stiffness-ratio"
            )
        law = Stronge if kind == "stronge" else MindlinDeresiewicz
        return law(poisson_ratio=nu) if nu is not None else law(stiffness_ratio=ratio)
    return None


def print_compliant(imp: CompliantImpact) -> None:
    """A plain-text report of one impact under a tangential compliance law."""
    b, a = imp.before, imp.after
    rows = [
        ("law", repr(imp.law)),
        ("regime", str(imp.regime)),
        ("tangential restitution beta = -u+/u-", f"{float(imp.tangential_restitution):.6g}"),
        ("centre e_t = vx+/vx-", f"{float(imp.centre_tangential_restitution):.6g}"),
        ("before vx, vy (m/s), omega (rad/s)", f"{b.vx:.6g}, {b.vy:.6g}, {b.omega:.6g}"),
        ("after vx, vy (m/s), omega (rad/s)", f"{a.vx:.6g}, {a.vy:.6g}, {a.omega:.6g}"),
        ("slip u before, after (m/s)", f"{imp.slip_before:.6g}, {imp.slip_after:.6g}"),
        ("friction impulse f1 (N s)", f"{imp.tangential_impulse:.6g}"),
        ("dissipated energy (J)", f"{imp.dissipated_energy:.6g} "
                                  f"({100 * float(imp.dissipated_fraction):.4g} %)"),
    ]  # fmt: skip
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        click.echo(f"{key:<{width}}  {value}")


def print_compliant_sphere(imp: CompliantSphereImpact) -> None:
    """A plain-text report of a sphere's impact in 3D under a tangential compliance law
    (vectors ``x, y, z`` in the ground's frame)."""

    def xyz(*parts: Any) -> str:
        return ", ".join(f"{float(x) + 0.0:.6g}" for x in parts)  # + 0.0: no "-0"

    b, a, slip0, slip1, f = (
        imp.before,
        imp.after,
        imp.slip_before,
        imp.slip_after,
        imp.friction_impulse,
    )
    rows = [
        ("law", repr(imp.law)),
        ("regime", str(imp.regime)),
        ("beta = -|c_t+|/|c_t-| (signed)", xyz(imp.tangential_restitution)),
        ("before velocity (m/s)", xyz(*b.velocity)),
        ("before spin (rad/s)", xyz(*b.spin)),
        ("after velocity (m/s)", xyz(*a.velocity)),
        ("after spin (rad/s)", xyz(*a.spin)),
        ("contact-point slip before (m/s)", xyz(slip0.x, slip0.y, slip0.z)),
        ("contact-point slip after (m/s)", xyz(slip1.x, slip1.y, slip1.z)),
        ("friction impulse F (N s)", xyz(f.x, f.y, f.z)),
        ("rebound speed (m/s), angle (deg)",
         xyz(imp.rebound_speed, np.degrees(imp.rebound_angle))),
        ("dissipated energy (J)", f"{float(imp.dissipated_energy):.6g} "
                                  f"({100 * float(imp.dissipated_fraction):.4g} %)"),
    ]  # fmt: skip
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        click.echo(f"{key:<{width}}  {value}")


def sweep_class(o: dict[str, Any]) -> Callable:
    """What builds the sweep of the paper's bodies that the options ask for:
    :class:`~spinimpact.io.sweep.Sweep`, or with a tangential law the
    :class:`~spinimpact.io.problem_sweep.ProblemSweep` of problem ``paper`` under that law
    (called as ``Sweep`` is: ``make(body, axes, samples=..., seed=..., chunk_size=...)``).

    Raises
    ------
    click.UsageError
        For a law with ``--planar`` or ``--sphere`` (their sweeps take the rigid law).
    """
    import functools

    from ..io.problem_sweep import ProblemSweep
    from ..io.sweep import Sweep

    law = tangential_law(o)
    if law is None:
        return Sweep
    if o.get("planar") is not None or o.get("sphere") is not None:
        which = "--planar" if o.get("planar") is not None else "--sphere"
        raise click.UsageError(f"--tangential {law.name} does not apply to {which} sweeps")
    return functools.partial(ProblemSweep, problem="paper", tangential=law)
