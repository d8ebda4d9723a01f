"""``spinimpact batch``: solve every row of a CSV or Parquet file, in chunks.

The file's columns say what it holds, so no option has to (and none can contradict
it): ``vx, vy, omega`` alone or with ``mass, radius, gyration, body`` are the paper's
bodies; columns ``mass, inertia, rx, ry`` (and ``vx, vy, omega``) are free planar
bodies, solved by :func:`~spinimpact.solve_planar`; ``mass, inertia, gx, gy, px, py``
(and ``omega``) are pendulums on a pivot, solved by :func:`~spinimpact.solve_pendulum`
(:func:`spinimpact.io.batch.body_kind`). Reading the kind from the header means a file
of rods is never solved, silently, as the default sphere.
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Any

import click

from .._words import count
from ..model.planar import LAWS
from ..model.registry import problem as get_problem
from ..model.registry import problems
from ._common import DEFAULTS, announce, body_options, long_run, progress, surface_options
from ._compliance import tangential_law, tangential_options
from ._problem_options import problem_name, problem_options, settings
from ._vocabulary import help as _help
from .sweep import _dask_client

__all__ = ["batch_command"]

#: Options that describe one of the paper's bodies: not for files of planar bodies.
_PAPER_OPTIONS = ("body", "mass", "radius", "gyration")


def _given(ctx: click.Context, name: str) -> bool:
    """Whether the user typed option ``name`` (rather than leaving its default)."""
    source = ctx.get_parameter_source(name)
    return source not in (None, click.core.ParameterSource.DEFAULT)


@click.command("batch")
@click.argument("source", type=click.Path(dir_okay=False, allow_dash=True))
@click.option(
    "--output",
    required=True,
    help="Output file: .csv, or .parquet with the [parquet] extra; - writes CSV to "
    "standard output.",
)
@click.option(
    "--fields",
    default=None,
    metavar="A,B,...",
    help="Result columns to write after the input columns, in this order (default: all). "
    "A wrong name gives the list of valid ones.",
)
@body_options
@surface_options
@click.option(
    "--law",
    type=click.Choice(list(LAWS)),
    default=None,
    help="Restitution law of rows without a 'law' cell (planar bodies and pendulums; "
    "default poisson). The paper's bodies obey the three laws alike.",
)
@tangential_options
@click.option(
    "--on-error",
    type=click.Choice(["stop", "skip"]),
    default="stop",
    show_default=True,
    help="stop: the first bad row ends the run and nothing is written; "
    "skip: bad rows are written with an 'error' column.",
)
@click.option(
    "--chunk-size",
    type=click.IntRange(1),
    default=100_000,
    show_default=True,
    help="Rows per chunk.",
)
@problem_options(
    "Listed by spinimpact problems; by default the file's columns say which.",
    "Its default, for rows or files that lack it, e.g. --set normal=0,0.96,0.28 --set "
    "body=spherical-shell (repeatable; a vector by its name takes all its components).",
)
@click.option("--dask", "dask_address", default=None, metavar="ADDRESS",
              help="Solve the chunks on the Dask scheduler at ADDRESS ([dask] extra); the "
              "output is the same as without it.")  # fmt: skip
@click.option("--force", is_flag=True, help=_help("force"))
@click.pass_context
def batch_command(
    ctx: click.Context,
    source: str,
    output: str,
    fields: str | None,
    on_error: str,
    chunk_size: int,
    problem: str | None,
    set_items: tuple[str, ...],
    force: bool,
    dask_address: str | None,
    **options: Any,
) -> None:
    """Solve every row of SOURCE (CSV or Parquet; - reads CSV from standard input); its
    columns say what it holds.

    \b
    The paper's bodies: vx, vy, omega, and optionally mu, kappa, mass, radius,
      gyration, body per row (--body, --mass, --radius, --gyration give the defaults).
    Free planar bodies: mass, inertia, rx, ry, vx, vy, omega (kg, kg m^2, m, m/s, rad/s;
      r = contact point - centre of mass, ry < 0), optionally mu, kappa, law.
    Pendulums on a pivot: mass, inertia, gx, gy, px, py, omega (centre of mass and
      contact point from the pivot, m), optionally mu, kappa, law.

    --tangential walton|stronge|mindlin-deresiewicz: the paper's bodies under a law
      (solve(..., tangential=law)); the result fields are then CompliantImpact's.

    Writes the input columns plus every result field that is not an input (for planar
    files also the law, mu and kappa used where the file lacks them), or those --fields
    names; Parquet fields carry their units. An output file is replaced only when the
    whole run succeeded; a stop (Ctrl-C, SIGTERM) leaves it as it was.
    """
    from .._validation import validated
    from ..io.batch import FieldError, run_batch

    o = options
    if o["gyration"] is not None and o["body"] is not None:
        raise click.UsageError("give either --body or --gyration, not both")
    defaults = {k: o[k] for k in ("mu", "kappa", "mass", "radius", "gyration")}
    for name, value in defaults.items():  # check the defaults before reading any row
        if value is not None:
            try:
                validated(name, value)
            except ValueError as exc:
                raise click.UsageError(f"--{exc}") from None
    defaults["body"] = None if o["gyration"] is not None else (o["body"] or DEFAULTS["body"])
    defaults["law"] = o["law"]
    defaults["tangential"] = tangential_law(o)
    chosen_problem = None if problem is None else problem_name(problem)
    given_settings = settings(set_items)
    defaults.update(given_settings)
    chosen = None if fields is None else [f for f in fields.split(",") if f.strip()]

    def check_kind(kind: str) -> None:
        declared = get_problem(kind)
        vectors = declared.vectors()
        for name in given_settings:
            if name not in declared.names and name not in vectors:
                raise click.UsageError(
                    f"--set {name}: problem {kind!r} has no input {name!r}; its inputs are "
                    f"{', '.join(declared.names)} (vectors: {', '.join(vectors) or 'none'})"
                )
        given = [f"--{n}" for n in _PAPER_OPTIONS if _given(ctx, n)]
        what = {"planar": "free planar bodies", "pendulum": "pendulums"}.get(kind)
        law = defaults["tangential"]
        if law is not None and not get_problem(kind).tangential:
            names = [p.name for p in problems() if p.tangential]
            raise click.UsageError(
                f"--tangential {law.name} applies to the paper's bodies and to spheres in 3D "
                f"(problems {', '.join(names)}), but the columns of {source} describe "
                f"{what or get_problem(kind).summary}"
            )
        if what is not None and given:
            raise click.UsageError(
                f"{given[0]} describes the paper's bodies, but the columns of {source} describe "
                f"{what}: their mass and geometry come from the file"
            )

    client = _dask_client(dask_address)
    with long_run(), progress() as bar, contextlib.ExitStack() as stack:
        if client is not None:
            stack.callback(client.close)
        task = bar.add_task(f"solving {Path(source).name}", total=None)
        try:
            summary = run_batch(
                source,
                output,
                defaults=defaults,
                on_error=on_error,
                chunk_size=chunk_size,
                progress=lambda done, total: bar.update(task, completed=done, total=total),
                fields=chosen,
                check_kind=check_kind,
                problem=chosen_problem,
                client=client,
                force=force,
                announce=announce,
            )
        except FieldError as exc:
            raise click.UsageError(f"--fields: {exc}") from None
    note = f" ({summary.skipped} with errors: see the 'error' column)" if summary.skipped else ""
    # With --output -, standard output holds the rows: the summary goes to stderr.
    click.echo(f"wrote {count(summary.rows, 'row')} to {summary.output}{note}", err=output == "-")
