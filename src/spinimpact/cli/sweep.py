"""``spinimpact sweep``: a grid or random samples of incidences in bounded memory."""

from __future__ import annotations

from typing import Any

import click

from ._common import DEFAULTS, body_options, make_body, progress

__all__ = ["sweep_command"]


def _histogram(text: str | None) -> tuple[str, float, float, int] | None:
    """``FIELD:LOW:HIGH:BINS`` as ``(field, low, high, bins)``, or ``None`` for no histogram.

    Raises
    ------
    click.UsageError
        If the text does not have that form.
    """
    if not text:
        return None
    parts = text.split(":")
    try:
        if len(parts) != 4:
            raise ValueError
        return (parts[0], float(parts[1]), float(parts[2]), int(parts[3]))
    except ValueError:
        raise click.UsageError(f"--histogram must be FIELD:LOW:HIGH:BINS, got {text!r}") from None


def _dask_client(address: str | None) -> Any:
    """A ``dask.distributed`` client of the scheduler at ``address`` (``None``: none).

    Raises
    ------
    ImportError
        If the ``[dask]`` extra is not installed; the message says how to install it.
    """
    if not address:
        return None
    try:
        from distributed import Client
    except ImportError:
        raise ImportError(
            "--dask needs the optional extra: pip install 'spinimpact[dask]'", name="distributed"
        ) from None
    return Client(address, timeout=30)


@click.command("sweep")
@body_options
@click.option(
    "--vx",
    default="-5:5:201",
    show_default=True,
    help="Number, START:STOP:NUM or uniform:LOW:HIGH.",
)
@click.option("--vy", default="-4", show_default=True, help="As --vx; values < 0.")
@click.option("--omega", default="-50:50:201", show_default=True, help="As --vx, rad/s.")
@click.option("--mu", default=str(DEFAULTS["mu"]), show_default=True, help="As --vx.")
@click.option("--kappa", default=str(DEFAULTS["kappa"]), show_default=True, help="As --vx.")
@click.option(
    "--samples", type=click.IntRange(1), default=None, help="Random points (uniform axes)."
)
@click.option(
    "--seed",
    type=int,
    default=0,
    show_default=True,
    help="Seed of the random points (the points also depend on --chunk-size).",
)
@click.option("--chunk-size", type=click.IntRange(1), default=1_000_000, show_default=True)
@click.option(
    "--output",
    default=None,
    help="FILE.parquet ([parquet] extra) or a new directory of .npy files, one per column.",
)
@click.option(
    "--fields",
    default="after_vx,after_vy,after_omega,regime",
    show_default=True,
    help="Comma-separated fields to write, named as the Impact's columns (after_vx, "
    "after_vy, after_omega, regime, slip_before, slip_after, impulse_ratio, "
    "dissipated_energy, dissipated_fraction; energy_loss is an alias of dissipated_fraction).",
)
@click.option("--histogram", default=None, help="FIELD:LOW:HIGH:BINS, accumulated on the fly.")
@click.option("--dask", "dask_address", default=None, help="Run the chunks on this Dask scheduler.")
def sweep_command(
    samples, seed, chunk_size, output, fields, histogram, dask_address, **o: Any
) -> None:
    """Sweep a grid or random samples of incidence conditions in bounded memory:
    regime fractions (always), a histogram, and/or the fields written to files."""
    from ..io.sweep import Sweep, parse_axis, run_sweep

    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    axes = {name: parse_axis(name, o[name]) for name in ("vx", "vy", "omega", "mu", "kappa")}
    sweep = Sweep(body, axes, samples=samples, seed=seed, chunk_size=chunk_size)
    hist = _histogram(histogram)
    client = _dask_client(dask_address)
    try:
        with progress() as bar:
            task = bar.add_task(f"{sweep.size:,} points", total=sweep.chunks)
            result = run_sweep(
                sweep,
                histogram=hist,
                output=output,
                fields=tuple(f.strip() for f in fields.split(",") if f.strip()),
                client=client,
                progress=lambda done, total: bar.update(task, completed=done),
            )
    finally:
        if client is not None:
            client.close()
    click.echo(f"{result.points:,} points")
    for name, fraction in result.regime_fractions.items():
        click.echo(f"  {name:18s} {fraction:.6f}")
    if result.histogram is not None:
        click.echo(f"histogram of {hist[0]}:")
        for lo, hi, count in zip(
            result.bin_edges[:-1], result.bin_edges[1:], result.histogram, strict=True
        ):
            click.echo(f"  [{lo:.6g}, {hi:.6g})  {count}")
    if output:
        click.echo(f"wrote {output}")
