"""``spinimpact engines calibrate ENGINE TIMESTEP``: contact settings for PyBullet or MuJoCo.

The command runs :func:`spinimpact.engines.calibrate` and prints the settings found with
their errors on the calibration incidences and on held-out ones (``--json``: every
field), and ``--output`` writes the engine's own configuration (an MJCF fragment for
MuJoCo, Python calls for PyBullet), renamed into place only when the run succeeded.
"""

from __future__ import annotations

import json

import click

from ._common import body_options, jsonable, make_body, surface_options
from ._vocabulary import help as _help

__all__ = ["engines_command"]


@click.group("engines")
def engines_command() -> None:
    """General physics engines (PyBullet, MuJoCo; the [engines] extra) set up to bounce as
    the exact answer does."""


@engines_command.command("calibrate")
@click.argument("engine", type=click.Choice(["pybullet", "mujoco"]))
@click.argument("timestep", type=float)
@body_options
@surface_options
@click.option(
    "--samples", type=click.IntRange(min=1), default=48, show_default=True,
    help=_help("samples", "Incidences drawn for the search, and as many held out."),
)  # fmt: skip
@click.option(
    "--seed", type=click.IntRange(min=0), default=0, show_default=True,
    help=_help("seed", "Of the search's incidences; the held-out ones use seed + 1."),
)  # fmt: skip
@click.option(
    "--output", default=None,
    help=_help("output", "The engine's configuration: MJCF for MuJoCo, Python for PyBullet."),
)  # fmt: skip
@click.option("--json", "as_json", is_flag=True, help=_help("json", "Every field."))
def calibrate_command(engine: str, timestep: float, **o) -> None:
    """Search ENGINE's contact settings at the time step TIMESTEP (s, never searched) for the
    rebounds (velocity and spin) closest to the exact ones, and measure them on held-out
    incidences."""
    from pathlib import Path

    from ..engines.calibration import calibrate

    if o["output"]:  # checked before the search, which takes minutes
        target = Path(o["output"])
        if target.is_dir():
            raise click.UsageError(f"--output {str(target)!r} is a directory")
        if not target.absolute().parent.is_dir():
            raise click.UsageError(f"the directory of --output {str(target)!r} does not exist")
    if not (timestep > 0 and timestep < float("inf")):
        raise click.UsageError(f"TIMESTEP must be a finite number > 0 (s), got {timestep!r}")
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    cal = calibrate(
        engine, body, mu=o["mu"], kappa=o["kappa"], dt=timestep, n=o["samples"], seed=o["seed"]
    )
    if o["output"]:
        from ..io import atomic_path

        with atomic_path(o["output"]) as tmp:
            tmp.write_text(cal.configuration(), encoding="utf-8")
    if o["as_json"]:
        click.echo(json.dumps(jsonable(cal.to_dict()), indent=2))
        return
    errors = cal.errors()
    click.echo(f"{engine} {cal.version}, time step {timestep!r} s, mu {o['mu']!r}, "
               f"kappa {o['kappa']!r}: {cal.evaluations} runs, {cal.seconds:.1f} s")  # fmt: skip
    click.echo("rebound error over the speed scale (median / worst of vx+, vy+, R omega+):")
    for name, label in (("calibration", "search's incidences"), ("held_out", "held out"),
                        ("start_held_out", "held out, at the start")):  # fmt: skip
        worst = errors[name]["worst"]
        click.echo(f"  {label:24s} {worst['median']:.3g} / {worst['max']:.3g}")
    click.echo(cal.configuration(), nl=False)
