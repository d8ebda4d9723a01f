"""``spinimpact batch``: solve every row of a CSV or Parquet file, in chunks."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from ._common import DEFAULTS, body_options, progress, surface_options

__all__ = ["batch_command"]


@click.command("batch")
@click.argument("source", type=click.Path(dir_okay=False))
@click.option(
    "--output", required=True, help="Output file: .csv, or .parquet with the [parquet] extra."
)
@body_options
@surface_options
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
def batch_command(source: str, output: str, on_error: str, chunk_size: int, **options: Any) -> None:
    """Solve every row of SOURCE (CSV or Parquet): columns vx, vy, omega, and
    optionally mu, kappa, mass, radius, gyration, body per row (the options give
    the defaults). Writes the input columns plus every scalar Impact field."""
    from .._validation import validated
    from ..io.batch import run_batch

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

    with progress() as bar:
        task = bar.add_task(f"solving {Path(source).name}", total=None)
        summary = run_batch(
            source,
            output,
            defaults=defaults,
            on_error=on_error,
            chunk_size=chunk_size,
            progress=lambda done, total: bar.update(task, completed=done, total=total),
        )
    note = f" ({summary.skipped} with errors: see the 'error' column)" if summary.skipped else ""
    click.echo(f"wrote {summary.rows} rows to {summary.output}{note}")
