"""``spinimpact map`` (maps over the incidence) and ``spinimpact figures`` (the
paper's figures, or those of the user's own impact). Matplotlib is imported only when
one of them runs."""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import Any

import click

from ..model.body import PRESETS
from ._common import image_format, make_body, progress, surface_options
from ._vocabulary import deprecated
from ._vocabulary import help as _help

__all__ = ["map_command", "figures_command"]


def _check_target(output: str) -> str:
    """The image format of ``--output``, after checking that the file can be written:
    done before anything is computed, so a bad path fails at once."""
    target = Path(output)
    parent = target.parent
    if target.is_dir():
        raise click.UsageError(f"--output {output!r} is a directory")
    fmt = image_format(output)
    if not parent.is_dir():
        raise click.UsageError(f"--output: no such directory {str(parent)!r}")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise click.UsageError(f"--output: cannot write in the directory {str(parent)!r}")
    return fmt


@click.command("map")
@click.option(
    "--body",
    type=click.Choice(list(PRESETS)),
    default=None,
    help=_help("body", "Default solid-sphere: only its zeta = 1 + R^2/rho^2 matters."),
)
@click.option(
    "--mass",
    type=float,
    default=1.0,
    show_default=True,
    help=_help("mass", "The maps are dimensionless: the mass changes nothing."),
)
@click.option(
    "--radius",
    type=float,
    default=0.1,
    show_default=True,
    help=_help("radius", "Changes the maps only through zeta, with --gyration."),
)
@click.option(
    "--gyration",
    type=float,
    default=None,
    help=_help("gyration", "A custom body, zeta = 1 + R^2/rho^2."),
)
@surface_options
@click.option(
    "--output",
    default="map.png",
    show_default=True,
    help=_help("output", "An image (.png, .svg, .pdf)."),
)
@click.option(
    "--extent",
    type=float,
    default=3.0,
    show_default=True,
    help=_help("extent", "The axes span [-extent, extent]."),
)
@click.option(
    "--resolution",
    type=click.IntRange(2, 4000),
    default=600,
    show_default=True,
    help="Grid points per axis of a map, at most: never more than a panel spans pixels at --dpi "
    "(more would add no pixel), so time and memory stay bounded by the image.",
)
@click.option(
    "--dpi",
    type=click.IntRange(50, 600),
    default=110,
    show_default=True,
    help=_help("dpi", "The figure is 15 x 9.2 inches."),
)
def map_command(output: str, extent: float, resolution: int, dpi: int, **options: Any) -> None:
    """Maps over the incidence at a fixed body, mu and kappa: regimes, rebound
    outcomes (backward, reversed spin, vertical), energy lost, mu_hat and the
    friction work ratio, with the regime boundaries drawn.

    The axes are vx/|vy| and R*omega/|vy|: every result is a function of these ratios,
    zeta, mu and kappa alone, so the maps do not depend on the mass or the size.
    """
    from ..io import atomic_path
    from ..viz.maps import plot_map

    fmt = _check_target(output)
    o = options
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    image = io.BytesIO()  # rendered before the file is opened: a stop ends it at once
    with progress() as bar:
        bar.add_task(f"drawing {output} at {dpi} dpi", total=None)
        fig = plot_map(body, mu=o["mu"], kappa=o["kappa"], extent=extent, n=resolution, dpi=dpi)
        fig.savefig(image, format=fmt, dpi=dpi)
    with atomic_path(output) as tmp:
        tmp.write_bytes(image.getbuffer())
    click.echo(f"wrote {output}")


#: The values of the paper's figures, used for every option of ``figures`` not given.
PAPER_CASE = {"mass": 1.0, "radius": 0.1, "vy": -1.0, "omega": 0.0, "mu": 0.25, "kappa": 0.6}
_CASE_OPTIONS = ("body", "mass", "radius", "gyration", "vx", "vy", "omega", "mu", "kappa")


def _case_option(name: str, help: str) -> Any:
    default = PAPER_CASE.get(name)
    return click.option(f"--{name}", type=float, default=default, show_default=True, help=help)


@click.command("figures")
@click.option(
    "--output-dir",
    "output",
    type=click.Path(file_okay=False, writable=True),
    default="figures",
    show_default=True,
    help=_help("output-dir"),
)
@deprecated("--output", "--output-dir", "output", type=click.Path(file_okay=False, writable=True))
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["png", "svg", "pdf"]),
    default="png",
    show_default=True,
    help=_help("format"),
)
@click.option(
    "--dpi",
    type=click.IntRange(50, 600),
    default=150,
    show_default=True,
    help=_help("dpi"),
)
@click.option(
    "--body",
    type=click.Choice(list(PRESETS)),
    default=None,
    help=_help("body", "Default solid-disk, as in the paper's figures."),
)
@_case_option("mass", _help("mass"))
@_case_option("radius", _help("radius"))
@_case_option("gyration", _help("gyration", "A custom body instead of a preset."))
@_case_option("vx", _help("vx", "The paper's figures: each its own."))
@_case_option("vy", _help("vy"))
@_case_option("omega", _help("omega"))
@_case_option("mu", _help("mu"))
@_case_option("kappa", _help("kappa"))
@click.pass_context
def figures_command(ctx: click.Context, output: str, fmt: str, dpi: int, **o: Any) -> None:
    """Regenerate the paper's Figures 2, 3, 4a, 4b, 5a, 5b and 5c, or draw your own
    impact.

    \b
    With none of the body, incidence or surface options: the paper's figures, for a
    solid disk (m = 1 kg, R = 0.1 m, no spin) at vy = -1 m/s on a surface with
    mu = 0.25 and kappa = 0.6, vx chosen to put each figure in its regime (see
    spinimpact.viz.plots.PAPER_FIGURES): fig2.png ... fig5c.png.
    With any of them: history, routh and energy (.png, ...) of that one impact, the
    options not given taking the values above (vx = 1 m/s).

    Each file is written to a temporary name and renamed when complete.
    """
    from click.core import ParameterSource

    from ..io import atomic_path
    from ..viz.plots import PAPER_FIGURES, impact_figures, paper_figure

    own = [n for n in _CASE_OPTIONS if ctx.get_parameter_source(n) != ParameterSource.DEFAULT]
    figures: Any = ((name, None) for name in PAPER_FIGURES)
    if own:  # the user's own impact: solved (and checked) before anything is written
        from ..model.impact import solve

        preset = o["body"] or ("solid-disk" if o["gyration"] is None else None)
        body = make_body(preset, o["mass"], o["radius"], o["gyration"])
        vx = 1.0 if o["vx"] is None else o["vx"]
        imp = solve(body, vx, o["vy"], o["omega"], mu=o["mu"], kappa=o["kappa"])
        figures = impact_figures(imp).items()
    folder = Path(output)
    folder.mkdir(parents=True, exist_ok=True)
    for name, fig in figures:
        target = folder / f"{name}.{fmt}"
        with atomic_path(target) as tmp:
            (fig or paper_figure(name)).savefig(tmp, format=fmt, dpi=dpi)
        click.echo(f"wrote {target}")
