"""The terminal report (or JSON), figure and page of ``spinimpact sphere`` and
``spinimpact pair``: :func:`print_sphere_report` for the rigid law's results, the plain
report of :func:`~spinimpact.cli._compliance.print_compliant_sphere` for a
:class:`~spinimpact.CompliantSphereImpact`."""

from __future__ import annotations

import json
from typing import Any

import click

from ..model.compliant import CompliantSphereImpact
from ..model.pair import PairImpact
from ..model.sphere3d import SphereImpact
from ._common import image_format, jsonable
from ._compliance import print_compliant_sphere

__all__ = ["print_sphere_report", "report"]


def print_sphere_report(imp: SphereImpact | PairImpact) -> None:
    """The terminal report: the headline, then the tables of
    :func:`~spinimpact.viz.sphere.sphere_tables` (Rich)."""
    from rich.text import Text

    from ..viz.report import _rich
    from ..viz.report import console as report_console
    from ..viz.sphere import headline, sphere_tables

    console = report_console()
    pair = isinstance(imp, PairImpact)
    title = f"Two spheres: {imp.ball1.name} on {imp.ball2.name}" if pair else (
        f"Sphere on a surface, in 3D: {imp.body.name}")  # fmt: skip
    console.print(Text(title, style="bold"))
    console.print(Text.assemble("Regime: ", (str(imp.regime), "bold"), "   ", headline(imp)))
    for table in sphere_tables(imp):
        console.print()
        console.print(_rich(table))


def report(imp: Any, as_json: bool, plot: str | None, html_path: str | None, dpi: int) -> None:
    """Print the report (or JSON) and write the figure and the page, each atomically
    (the figure and the page draw the rigid law's results only)."""
    if as_json:
        click.echo(json.dumps(jsonable(imp.to_dict()), indent=2))
    elif isinstance(imp, CompliantSphereImpact):
        print_compliant_sphere(imp)
    else:
        print_sphere_report(imp)
    if plot is None and html_path is None:
        return
    from ..io import atomic_path

    if plot is not None:
        from ..viz.sphere import plot_sphere

        with atomic_path(plot) as tmp:
            plot_sphere(imp).savefig(tmp, format=image_format(plot, "--plot"), dpi=dpi)
    if html_path is not None:
        from ..viz.sphere_html import sphere_report_html

        with atomic_path(html_path) as tmp:
            tmp.write_text(sphere_report_html(imp), encoding="utf-8")
    if not as_json:
        for path in (plot, html_path):
            if path is not None:
                click.echo(f"wrote {path}")
