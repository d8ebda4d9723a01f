"""``spinimpact map`` (maps over the incidence) and ``spinimpact figures`` (the
paper's figures). Matplotlib is imported only when one of them runs."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from ._common import body_options, image_format, make_body, surface_options

__all__ = ["map_command", "figures_command"]


@click.command("map")
@body_options
@surface_options
@click.option(
    "--output", default="map.png", show_default=True, help="Image file (.png, .svg, .pdf)."
)
@click.option(
    "--extent",
    type=float,
    default=3.0,
    show_default=True,
    help="Axes span [-extent, extent] in vx/|vy| and R*omega/|vy|.",
)
@click.option(
    "--resolution",
    type=click.IntRange(2, 4000),
    default=600,
    show_default=True,
    help="Grid points per axis.",
)
@click.option("--dpi", type=click.IntRange(50, 600), default=110, show_default=True)
def map_command(output: str, extent: float, resolution: int, dpi: int, **options: Any) -> None:
    """Maps over the incidence at a fixed body, mu and kappa: regimes, rebound
    outcomes (backward, reversed spin, vertical), energy lost, mu_hat and the
    friction work ratio, with the regime boundaries drawn."""
    from ..io import atomic_path
    from ..viz.plots import plot_map

    fmt = image_format(output)
    o = options
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    fig = plot_map(body, mu=o["mu"], kappa=o["kappa"], extent=extent, n=resolution)
    with atomic_path(output) as tmp:
        fig.savefig(tmp, format=fmt, dpi=dpi)
    click.echo(output)


@click.command("figures")
@click.option(
    "--output",
    type=click.Path(file_okay=False, writable=True),
    default="figures",
    show_default=True,
    help="Directory to write into (created if missing).",
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["png", "svg", "pdf"]),
    default="png",
    show_default=True,
    help="Image format.",
)
@click.option("--dpi", type=click.IntRange(50, 600), default=150, show_default=True)
def figures_command(output: str, fmt: str, dpi: int) -> None:
    """Regenerate the paper's Figures 2, 3, 4a, 4b, 5a, 5b and 5c.

    Inputs: a solid disk (m = 1 kg, R = 0.1 m, no spin) at vy = -1 m/s on a
    surface with mu = 0.25 and kappa = 0.6, and vx chosen to put each figure in
    its regime (see spinimpact.viz.plots.PAPER_FIGURES). Each file is written to a
    temporary name and renamed when complete.
    """
    from ..io import atomic_path
    from ..viz.plots import PAPER_FIGURES, paper_figure

    folder = Path(output)
    folder.mkdir(parents=True, exist_ok=True)
    for name in PAPER_FIGURES:
        target = folder / f"{name}.{fmt}"
        with atomic_path(target) as tmp:
            paper_figure(name).savefig(tmp, format=fmt, dpi=dpi)
        click.echo(str(target))
