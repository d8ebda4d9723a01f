"""``spinimpact flight``: a ball through the air, bouncing exactly, until it rolls to rest.

One ball: the bounce table and the summary (Rich), or ``--json``; ``--plot`` (side and top
views, bounces marked) and ``--animate`` (``.gif``; ``.mp4`` where ffmpeg is installed), each
written atomically. ``--samples N`` flies N balls with normally scattered speed, angles and
spin (``--speed-sd`` ...; seeded), with a progress bar, and prints the spread of the first
two bounces. The names, units and signs of every option: ``docs/conventions.md``.
"""

from __future__ import annotations

import io
import json
import math
from pathlib import Path
from typing import Any

import click
import numpy as np

from .._words import count
from ..model.flight import AIR_DENSITY, flight
from ..model.presets import BALLS, GROUNDS
from ..model.spin_axis import parse_spin_axis
from ._common import SPEED_UNITS, announce, image_format, jsonable, long_run, progress
from ._compliance import tangential_law, tangential_options
from ._vocabulary import deprecated
from ._vocabulary import help as _help
from .sphere import VECTOR

__all__ = ["flight_command"]

#: m/s in one unit of each ``--speed-unit`` (the shared table, under its older name here).
UNITS = SPEED_UNITS


def _axis(value: str) -> Any:
    """``topspin``, ``backspin``, ``sidespin``, a combination of them or a vector ``x,y,z``."""
    if "," not in value:
        try:
            parse_spin_axis(value, "--spin-axis")
        except ValueError as exc:
            raise click.UsageError(str(exc)) from None
        return value.strip().lower()
    try:
        parts = [float(p) for p in value.split(",")]
    except ValueError:
        parts = []
    if len(parts) != 3:
        raise click.UsageError(
            "--spin-axis must be topspin, backspin, sidespin, a combination such as "
            f"topspin+sidespin, or x,y,z; got {value!r}"
        )
    return parts


def _spin(o: dict) -> dict[str, Any]:
    """``--spin x,y,z`` (rad/s) as a rate and axis, or ``--spin-rpm`` about ``--spin-axis``."""
    if o["spin"] is None:
        return {"spin_axis": _axis(o["spin_axis"])}
    ctx = click.get_current_context()
    typed = [n for n in ("spin_rpm", "spin_axis", "spin_sd_rpm")
             if ctx.get_parameter_source(n).name != "DEFAULT"]  # fmt: skip
    if typed:
        raise click.UsageError(f"give either --spin or --{typed[0].replace('_', '-')}")
    w = np.asarray(o["spin"], float)
    rate = float(np.linalg.norm(w))
    if rate == 0:
        return {"spin_rpm": 0.0, "spin_axis": "topspin"}
    return {"spin_rpm": rate * 60 / (2 * math.pi), "spin_axis": list(w / rate)}


def _targets(o: dict) -> None:
    """Check the output paths before anything is computed."""
    if o["plot"] is not None:
        image_format(o["plot"], "--plot")
    if o["animate"] is not None:
        if Path(o["animate"]).suffix.lower() not in (".gif", ".mp4"):
            raise click.UsageError(f"--animate must end in .gif or .mp4, got {o['animate']!r}")
        if o["samples"] is not None:
            raise click.UsageError("--animate moves one ball; leave out --samples")
    for option in ("plot", "animate"):
        path = o[option]
        if path is not None and not Path(path).parent.is_dir():
            raise click.UsageError(f"--{option}: no such directory {str(Path(path).parent)!r}")


#: The launch options checked by the declarations of problem ``flight`` (their inputs).
_DECLARED = {"speed": "speed", "elevation_deg": "elevation_deg", "heading_deg": "heading_deg",
             "launch_height": "launch_height"}  # fmt: skip


def _check_launch(o: dict) -> None:
    """Each launch option by the rules its input of problem ``flight`` declares
    (``spinimpact problems flight``), the error naming the option."""
    from .._validation import RULES, rule_problems
    from ..model.registry import problem

    declared = problem("flight")
    for option, name in _DECLARED.items():
        rules = RULES.get(declared.input(name).rule or "", ())
        found = rule_problems(f"--{option.replace('_', '-')}", np.asarray([o[option]]), rules)
        if found[0]:
            raise click.UsageError(str(found[0]))


def _inputs(o: dict) -> dict[str, Any]:
    """The launch as :func:`~spinimpact.flight` takes it; scattered with ``--samples``."""
    _check_launch(o)
    speed = o["speed"] * UNITS[o["speed_unit"]]
    spin = _spin(o)
    given = {"speed": speed, "angle": o["elevation_deg"], "direction": o["heading_deg"],
             "spin_rpm": spin.pop("spin_rpm", o["spin_rpm"])}  # fmt: skip
    o["spin_axis_value"] = spin["spin_axis"]
    if o["samples"] is None:
        ctx = click.get_current_context()
        names = ("speed_sd", "elevation_sd_deg", "heading_sd_deg", "spin_sd_rpm", "seed")
        typed = [n for n in names if ctx.get_parameter_source(n).name != "DEFAULT"]
        if typed:
            raise click.UsageError(f"--{typed[0].replace('_', '-')} goes with --samples N")
        return given
    for name in ("speed_sd", "elevation_sd_deg", "heading_sd_deg", "spin_sd_rpm"):
        if not (math.isfinite(o[name]) and o[name] >= 0):
            raise click.UsageError(f"--{name.replace('_', '-')} must be >= 0 (a standard "
                                   f"deviation), got {o[name]!r}")  # fmt: skip
    rng = np.random.default_rng(o["seed"])
    n = o["samples"]
    spread = {"speed": o["speed_sd"] * UNITS[o["speed_unit"]], "angle": o["elevation_sd_deg"],
              "direction": o["heading_sd_deg"], "spin_rpm": o["spin_sd_rpm"]}  # fmt: skip
    out = {k: v + spread[k] * rng.standard_normal(n) for k, v in given.items()}
    out["speed"] = np.abs(out["speed"])  # a speed scattered below zero is a speed the other way
    return out


def _wall(o: dict) -> Any:
    """The wall the ``--wall-*`` options describe, or ``None``."""
    from ..model.presets import Wall

    if o["wall_distance"] is None:
        ctx = click.get_current_context()
        names = ("wall_heading_deg", "wall_mu", "wall_kappa")
        typed = [n for n in names if ctx.get_parameter_source(n).name != "DEFAULT"]
        if typed:
            raise click.UsageError(f"--{typed[0].replace('_', '-')} needs --wall-distance")
        return None
    return Wall(o["wall_distance"], o["wall_heading_deg"], mu=o["wall_mu"],
                kappa=o["wall_kappa"])  # fmt: skip


def _print_one(f: Any) -> None:
    from ..viz.flight import flight_tables
    from ..viz.report import _rich, console

    out = console()
    bounces, summary = flight_tables(f)
    out.print(_rich(bounces))
    out.print()
    out.print(_rich(summary))


def _print_many(f: Any) -> None:
    from rich.table import Table
    from rich.text import Text

    from ..viz.report import console

    b = f.bounces
    table = Table(title=Text(f"{count(f.shape[0], f'{f.ball.name} ball')} on {f.ground.name}"),
                  title_justify="left", show_edge=False)  # fmt: skip
    for i, head in enumerate(("quantity", "mean", "sd", "min", "max")):
        table.add_column(head, justify="left" if i == 0 else "right")
    rows = [("apex height (m)", f.apex_height), ("bounces", f.bounce_count)]
    for k in range(min(2, b.time.shape[-1])):
        rows += [(f"bounce {k + 1}: x (m)", b.position.x[:, k]),
                 (f"bounce {k + 1}: z (m)", b.position.z[:, k]),
                 (f"bounce {k + 1}: speed out (m/s)", b.speed_after[:, k]),
                 (f"bounce {k + 1}: grips (share)", b.grips[:, k].astype(float))]  # fmt: skip
    for name, values in rows:
        x = np.asarray(values, float)
        x = x[~np.isnan(x)]
        stats = [f"{s:.4g}" for s in (x.mean(), x.std(), x.min(), x.max())] if x.size else ["-"] * 4
        table.add_row(Text(name), *stats)
    console().print(table)


@click.command("flight")
@click.option(
    "--ball",
    type=click.Choice(list(BALLS)),
    default="tennis",
    show_default=True,
    help=_help("ball", "Sources: docs/flight.md."),
)
@click.option(
    "--surface",
    type=click.Choice(list(GROUNDS)),
    default="hard",
    show_default=True,
    help=_help("surface"),
)
@click.option(
    "--speed", type=float, default=30.0, show_default=True, help=_help("speed", "At launch.")
)
@click.option(
    "--speed-unit",
    type=click.Choice(list(UNITS)),
    default="m/s",
    show_default=True,
    help=_help("speed-unit", "And --speed-sd."),
)
@click.option(
    "--elevation-deg", type=float, default=0.0, show_default=True, help=_help("elevation-deg")
)
@click.option(
    "--heading-deg", type=float, default=0.0, show_default=True, help=_help("heading-deg")
)
@click.option(
    "--launch-height", type=float, default=1.0, show_default=True, help=_help("launch-height")
)
@click.option("--spin-rpm", type=float, default=0.0, show_default=True, help=_help("spin-rpm"))
@click.option(
    "--spin-axis",
    default="topspin",
    show_default=True,
    help=_help(
        "spin-axis", "Sidespin is about +y: the ball curves left; topspin about y x heading."
    ),
)
@click.option(
    "--spin",
    type=VECTOR,
    default=None,
    help=_help("spin", "At launch, instead of --spin-rpm and --spin-axis."),
)
@click.option("--mu", type=float, default=None, help=_help("mu", "Instead of the surface's."))
@click.option("--kappa", type=float, default=None, help=_help("kappa", "Instead of the surface's."))
@click.option(
    "--air-density", type=float, default=AIR_DENSITY, show_default=True, help=_help("air-density")
)
@click.option(
    "--max-bounces",
    type=click.IntRange(1),
    default=30,
    show_default=True,
    help=_help("max-bounces"),
)
@click.option("--t-stop", type=float, default=60.0, show_default=True, help=_help("t-stop"))
@click.option("--dt", type=float, default=5e-3, show_default=True, help=_help("dt"))
@click.option(
    "--samples",
    type=click.IntRange(1),
    default=None,
    help=_help("samples", "Fly this many balls, scattered by the --*-sd options."),
)
@click.option("--speed-sd", type=float, default=0.0, help=_help("speed-sd"))
@click.option("--elevation-sd-deg", type=float, default=0.0, help=_help("elevation-sd-deg"))
@click.option("--heading-sd-deg", type=float, default=0.0, help=_help("heading-sd-deg"))
@click.option("--spin-sd-rpm", type=float, default=0.0, help=_help("spin-sd-rpm"))
@click.option(
    "--seed", type=int, default=0, show_default=True, help=_help("seed", "With --samples.")
)
@click.option("--wall-distance", type=float, default=None, help=_help("wall-distance"))
@click.option(
    "--wall-heading-deg", type=float, default=0.0, show_default=True, help=_help("wall-heading-deg")
)
@click.option(
    "--wall-mu",
    type=float,
    default=0.5,
    show_default=True,
    help=_help("wall-mu", "An assumption by default."),
)
@click.option(
    "--wall-kappa",
    type=float,
    default=0.7,
    show_default=True,
    help=_help("wall-kappa", "An assumption by default."),
)
@click.option("--json", "as_json", is_flag=True, help=_help("json", "Every field, in SI units."))
@click.option("--plot", default=None, help=_help("plot", "Side and top views."))
@click.option("--animate", default=None, help=_help("animate"))
@click.option("--fps", type=click.IntRange(1, 60), default=20, show_default=True, help=_help("fps"))
@click.option(
    "--dpi", type=click.IntRange(50, 600), default=110, show_default=True, help=_help("dpi")
)
@click.option("--force", is_flag=True, help=_help("force", "A very fine --dt."))
@deprecated("--angle", "--elevation-deg", "elevation_deg", type=float)
@deprecated("--direction", "--heading-deg", "heading_deg", type=float)
@deprecated("--height", "--launch-height", "launch_height", type=float)
@deprecated("--angle-sd", "--elevation-sd-deg", "elevation_sd_deg", type=float)
@deprecated("--direction-sd", "--heading-sd-deg", "heading_sd_deg", type=float)
@deprecated("--spin-sd", "--spin-sd-rpm", "spin_sd_rpm", type=float)
@deprecated("--wall-direction", "--wall-heading-deg", "wall_heading_deg", type=float)
@tangential_options
def flight_command(**o: Any) -> None:
    """A spinning ball through the air (drag, Magnus lift, spin decay), bouncing exactly on
    the ground, then sliding and rolling to rest.

    \b
    Axes: x along the ground, y up, z = x cross y. Example, a first serve:
      spinimpact flight --ball tennis --surface hard --speed 50 --elevation-deg -6
        --launch-height 2.8 --spin-rpm 2000 --spin-axis topspin --plot serve.png
    """
    from ..model.presets import ground as as_ground

    _targets(o)
    ground = as_ground(o["surface"])
    changes = {k: o[k] for k in ("mu", "kappa") if o[k] is not None}
    ground = ground.replace(**changes) if changes else ground
    inputs = _inputs(o)
    law = tangential_law(o)
    kw = dict(
        height=o["launch_height"], spin_axis=o["spin_axis_value"], air_density=o["air_density"],
        max_bounces=o["max_bounces"], t_stop=o["t_stop"], dt=o["dt"], tangential=law,
        wall=_wall(o),
    )  # fmt: skip
    n = 1 if o["samples"] is None else o["samples"]
    many = {} if o["samples"] is None else {"path": o["plot"] is not None, "chunk": 1024}
    with long_run(), progress() as bar:
        task = bar.add_task(f"flying {n} ball{'s' * (n != 1)}", total=n)
        done = lambda d, _: bar.update(task, completed=d)  # noqa: E731
        f = flight(o["ball"], ground, **inputs, **kw, **many, force=o["force"],
                   announce=announce, progress=done)  # fmt: skip
    if o["as_json"]:
        d = f.to_dict()
        for name in ("path_time", "path_position"):
            d.pop(name)
        click.echo(json.dumps(jsonable(d), indent=2))
    elif o["samples"] is None:
        _print_one(f)
    else:
        _print_many(f)
    _write(f, o)


def _write(f: Any, o: dict) -> None:
    if o["plot"] is None and o["animate"] is None:
        return
    from ..io import atomic_path

    if o["plot"] is not None:
        from ..viz.flight import plot_flight

        with atomic_path(o["plot"]) as tmp:
            plot_flight(f).savefig(tmp, format=image_format(o["plot"], "--plot"), dpi=o["dpi"])
    if o["animate"] is not None:
        from ..viz.flight import animate_flight

        kind = Path(o["animate"]).suffix.lstrip(".").lower()
        dpi = min(o["dpi"], 100)
        if kind == "gif":  # rendered before the file is opened: a stop ends it at once
            image = io.BytesIO()
            with progress() as bar:
                task = bar.add_task(f"animating {o['animate']}", total=None)
                done = lambda d, n: bar.update(task, completed=d, total=n)  # noqa: E731
                animate_flight(f, image, format=kind, fps=o["fps"], dpi=dpi, progress=done)
            with atomic_path(o["animate"]) as tmp:
                tmp.write_bytes(image.getbuffer())
        else:  # ffmpeg writes a file: the frames check for a stop as they are drawn
            with atomic_path(o["animate"]) as tmp:
                animate_flight(f, tmp, format=kind, fps=o["fps"], dpi=dpi)
    if not o["as_json"]:
        for path in (o["plot"], o["animate"]):
            if path is not None:
                click.echo(f"wrote {path}")
