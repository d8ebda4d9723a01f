"""``spinimpact solve`` (the terminal report, or JSON) and ``spinimpact report``
(the HTML page) for one impact."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from ..model.impact import solve
from ..model.particle import ParticleImpact, solve_particle
from ._common import (
    body_options,
    incidence_options,
    jsonable,
    make_body,
    solve_options,
    surface_options,
)
from ._compliance import print_compliant, tangential_law, tangential_options
from ._problem_options import problem_options, solve_problem
from ._vocabulary import help as _help

__all__ = ["solve_command", "report_command"]


def _particle(o: dict[str, Any]) -> ParticleImpact:
    """Whittaker's particle with the options' incidence, surface and mass."""
    return solve_particle(o["vx"], o["vy"], mu=o["mu"], kappa=o["kappa"], mass=o["mass"])


#: The paper's-body options, which --problem replaces by --set.
_PAPER = ("body", "mass", "radius", "gyration", "vx", "vy", "omega", "mu", "kappa")
_ANY_PROBLEM = (
    "Solve one impact of this registered problem instead (spinimpact problems lists them); "
    "its inputs are given with --set.",
    "With --problem, e.g. --set vx=2 --set wz=30 (repeatable; a vector by its name takes all "
    "its components; inputs not given take their defaults).",
)


def _one_problem(ctx: click.Context, name: str, items: tuple[str, ...], law: Any) -> Any:
    if law is not None:
        raise click.UsageError("--tangential goes with the paper's bodies; not with --problem")
    return solve_problem(ctx, name, items, _PAPER)


@click.command("solve")
@body_options
@incidence_options
@surface_options
@tangential_options
@problem_options(*_ANY_PROBLEM)
@click.option(
    "--json",
    "as_json",
    is_flag=True,
    help=_help("json", "Every Impact field; infinite or undefined values are null."),
)
@click.pass_context
def solve_command(
    ctx: click.Context, as_json: bool, problem: str | None, set_items: tuple, **options: Any
) -> None:
    """Solve one impact and print the report (regime, rebound, energy, works, mu_hat).

    With no options it solves the documented default case: a 1 kg solid sphere
    of radius 0.1 m at vx = 3 m/s, vy = -4 m/s with 10 rad/s of backspin, on a
    surface with mu = 0.2 and kappa = 0.8.

    \b
    Equations of Lubarda (2010), Keller's method in the normal impulse tau:
      slip u = vx + R omega (eq. 4.4); regime from |u/v| against zeta mu and
      (1 + kappa) zeta mu (eqs. 4.6, 4.14, 4.15); tau0, tau*, tau1 (eqs. 3.2,
      4.3, 3.6); rebound (eqs. 3.4, 4.13, 4.16); energy (eqs. 5.1-5.10); works
      (eqs. 6.1-6.11, ratio 6.15-6.19); mu_hat = f1/tau1 (eqs. 7.4, 7.7-7.9);
      least kinetic energy (eqs. 8.1-8.6); Whittaker's particle (eq. 8.7).
      --tangential walton|stronge|mindlin-deresiewicz: the contact point's tangential
      restitution beta = -u+/u- of Walton's law, Stronge's, or Hertz contact with
      Mindlin-Deresiewicz micro-slip (docs/compliance.md).
    --problem NAME --set INPUT=VALUE ...: one impact of any registered problem
      (spinimpact problems NAME lists its inputs), reported as its inputs and every
      result column with their units.
    """
    law = tangential_law(options)
    if problem is not None:
        declared, values, result = _one_problem(ctx, problem, set_items, law)
        if as_json:
            click.echo(json.dumps(jsonable(result[0].to_dict()), indent=2))
        else:
            from ..viz.problems import result_tables
            from ..viz.report import print_tables

            print_tables(result_tables(declared, values, result))
        return
    if set_items:
        raise click.UsageError("--set goes with --problem NAME")
    if law is not None:
        o = options
        body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
        soft = solve(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], kappa=o["kappa"],
                     tangential=law)  # fmt: skip
        if as_json:
            click.echo(json.dumps(jsonable(soft.to_dict()), indent=2))
        else:
            print_compliant(soft)
        return
    imp = solve_options(options)
    if as_json:
        click.echo(json.dumps(jsonable(imp.to_dict()), indent=2))
    else:
        from ..viz.report import print_report  # Rich is imported only when a report is printed

        print_report(imp, _particle(options))


@click.command("report")
@body_options
@incidence_options
@surface_options
@problem_options(*_ANY_PROBLEM)
@click.option(
    "--output", default="impact.html", show_default=True, help=_help("output", "The HTML page.")
)
@click.pass_context
def report_command(
    ctx: click.Context, output: str, problem: str | None, set_items: tuple, **options: Any
) -> None:
    """Write one self-contained HTML page about an impact: inputs, regime, rebound,
    energy budget, works by phase, coefficients, outcome and figures (with --problem:
    the inputs and result columns of one impact of that problem)."""
    from ..io import atomic_path
    from ..viz.html import impact_report_html

    if Path(output).suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(f"--output must end in .html, got {output!r}")
    if problem is not None:
        from ..viz.problems import problem_report_html

        page = problem_report_html(*_one_problem(ctx, problem, set_items, None))
    elif set_items:
        raise click.UsageError("--set goes with --problem NAME")
    else:
        page = impact_report_html(solve_options(options), _particle(options))
    with atomic_path(output) as tmp:
        tmp.write_text(page, encoding="utf-8")
    click.echo(f"wrote {output}")
