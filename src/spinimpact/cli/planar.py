"""``spinimpact planar``: the impact of a planar body touching the surface anywhere (a rod,
a block on a corner, an eccentric disk) or of a pendulum on a fixed pivot.

Prints the report (or JSON with ``--json``) and, on request, the report as an HTML page
(``--html``), Routh's diagram
(``--plot``), the three restitution laws side by side (``--laws-plot``) and the map of
regimes over the body's orientation and the slip ratio (``--map-plot``). The body's
orientation is given in degrees (``--orientation-deg``, measured from the surface) and
converted once here to the radians of the Python API; the older ``--angle`` (radians) is a
deprecated hidden option. Names, units and signs: ``docs/conventions.md``.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import click

from ..model.planar import LAWS, PlanarImpact, solve_pendulum, solve_planar
from ..model.planar_body import Pendulum, PlanarBody
from ._common import jsonable
from ._vocabulary import deprecated
from ._vocabulary import help as _help

__all__ = [
    "planar_command",
    "GEOMETRY",
    "make_planar_body",
    "flag",
    "orientation_options",
    "solve_planar_options",
    "preset_geometry",
]

#: Each body's geometry options and their defaults (m; the angle in degrees).
GEOMETRY: dict[str, dict[str, float]] = {
    "rod": {"length": 1.0, "angle_deg": 45.0},
    "block": {"width": 0.2, "height": 0.1, "angle_deg": 30.0},
    "eccentric-disk": {"radius": 0.1, "gyration": 0.07, "offset": 0.02, "angle_deg": 0.0},
    "pendulum": {"length": 1.0, "angle_deg": 60.0},
}
_SPEED = 2.0  #: default |omega| of a pendulum, rad/s, toward the surface
_GEOMETRY_OPTIONS = "length width height radius gyration offset angle angle_deg".split()


def flag(name: str) -> str:
    """The option of a geometry name: ``angle_deg`` is ``--orientation-deg``."""
    return "--orientation-deg" if name == "angle_deg" else "--" + name.replace("_", "-")


def make_planar_body(body: str, mass: float, geometry: dict[str, Any]) -> PlanarBody | Pendulum:
    """The body named by ``--body`` with the geometry options the user gave.

    Parameters
    ----------
    body : {"rod", "block", "eccentric-disk", "pendulum"}
    mass : float
        kg.
    geometry : dict
        ``length``, ``width``, ``height``, ``radius``, ``gyration``, ``offset`` (m),
        ``angle`` (rad, the deprecated ``--angle``) and ``angle_deg`` (degrees,
        ``--orientation-deg``); ``None`` where not given.

    Raises
    ------
    click.UsageError
        An option the body does not take, or both ``--angle`` and ``--orientation-deg``.
    ValueError
        A value out of range (from the body's preset).
    """
    spec = GEOMETRY[body]
    for name, value in geometry.items():
        if value is not None and name not in spec and name != "angle":
            raise click.UsageError(
                f"{flag(name)} does not apply to --body {body} (it takes "
                + ", ".join(flag(n) for n in spec)
                + ")"
            )
    if geometry.get("angle") is not None and geometry.get("angle_deg") is not None:
        raise click.UsageError(
            "give either --orientation-deg or its old form --angle (rad), not both"
        )
    size = {n: spec[n] if geometry.get(n) is None else geometry[n] for n in spec}
    deg = size.pop("angle_deg")
    in_rad = geometry.get("angle") is not None
    angle = geometry["angle"] if in_rad else math.radians(deg)
    preset = {
        "rod": PlanarBody.rod,
        "block": PlanarBody.block,
        "eccentric-disk": PlanarBody.eccentric_disk,
        "pendulum": Pendulum.rod,
    }[body]
    try:
        return preset(mass=mass, angle=angle, **size)
    except ValueError as exc:  # the preset speaks radians; say what the user typed
        if in_rad or not str(exc).startswith("angle"):
            raise
        raise ValueError(f"--orientation-deg {deg:g} is {angle:.6g} rad: {exc}") from None


def solve_planar_options(o: dict[str, Any]) -> tuple[PlanarImpact, dict[str, Any]]:
    """The impact the command's options describe, and the incidence it used.

    Returns ``(impact, incidence)`` with ``incidence`` the keyword arguments of
    :func:`~spinimpact.viz.planar.plot_laws` (``body``, ``vx``, ``vy``, ``omega``,
    ``mu``, ``kappa``).
    """
    body = make_planar_body(o["body"], o["mass"], {n: o[n] for n in _GEOMETRY_OPTIONS})
    surface = {"mu": o["mu"], "kappa": o["kappa"]}
    if isinstance(body, Pendulum):
        for name in ("vx", "vy"):
            if o[name] is not None:
                raise click.UsageError(
                    f"--{name} does not apply to --body pendulum: its centre moves with --omega"
                )
        # default: |omega| = 2 rad/s, turning the contact toward the surface (omega px < 0)
        omega = o["omega"] if o["omega"] is not None else -math.copysign(_SPEED, float(body.px))
        imp = solve_pendulum(body, omega, law=o["law"], **surface)
        return imp, {"body": body, "vx": None, "vy": None, "omega": omega, **surface}
    vx = 1.0 if o["vx"] is None else o["vx"]
    vy = -1.0 if o["vy"] is None else o["vy"]
    omega = 0.0 if o["omega"] is None else o["omega"]
    imp = solve_planar(body, vx, vy, omega, law=o["law"], **surface)
    return imp, {"body": body, "vx": vx, "vy": vy, "omega": omega, **surface}


def _image(option: str, path: str | None) -> str | None:
    """The image format of ``path`` from its suffix (png, svg or pdf), or ``None``."""
    if path is None:
        return None
    fmt = Path(path).suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise click.UsageError(f"{option} must end in .png, .svg or .pdf, got {path!r}")
    return fmt


#: How the page names each geometry option (the angle's meaning depends on the body).
_MEANING = {
    "length": "length L",
    "width": "width (the side along the tilt)",
    "height": "height",
    "radius": "rim radius R",
    "gyration": "radius of gyration about the centre of mass",
    "offset": "offset of the centre of mass from the disk's centre",
    "rod": "angle to the surface",
    "block": "tilt of the width side",
    "eccentric-disk": "direction of the offset",
    "pendulum": "angle below the horizontal",
}


def preset_geometry(o: dict[str, Any]) -> dict[str, str]:
    """The preset's parameters as the command used them (given or default), in words and
    units, for the HTML page: e.g. ``{"length L": "1 m", "angle to the surface":
    "45° (0.785398 rad)"}``."""
    spec = GEOMETRY[o["body"]]
    out = {
        _MEANING[n]: f"{(spec[n] if o[n] is None else o[n]):.6g} m"
        for n in spec
        if n != "angle_deg"
    }
    deg = spec["angle_deg"] if o["angle_deg"] is None else o["angle_deg"]
    rad = math.radians(deg) if o["angle"] is None else o["angle"]
    out[_MEANING[o["body"]]] = f"{math.degrees(rad):.6g}° ({rad:.6g} rad)"
    return out


def _html_target(path: str | None) -> None:
    """Check ``--html`` before anything is solved or printed."""
    if path is None:
        return
    if Path(path).suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(f"--html must end in .html or .htm, got {path!r}")
    parent = Path(path).parent
    if not parent.is_dir():
        raise click.UsageError(f"--html: no such directory {str(parent)!r}")


def orientation_options(function: Any) -> Any:
    """``--orientation-deg`` (Python name ``angle_deg``) and its old names ``--angle-deg``
    and ``--angle`` (radians), hidden; shared by ``planar`` and ``sweep --planar``."""
    for option in reversed((
        click.option("--orientation-deg", "angle_deg", type=float, default=None, help=_help(
            "orientation-deg", "Per body: rod: its angle to the surface (default 45); block: "
            "the tilt of --width (30); eccentric-disk: the direction of the offset (0); "
            "pendulum: the rod's angle below the horizontal (60).")),
        deprecated("--angle-deg", "--orientation-deg", "angle_deg", type=float),
        deprecated("--angle", "--orientation-deg (in degrees)", type=float),
    )):  # fmt: skip
        function = option(function)
    return function


def _length(name: str, which: str) -> Any:
    return click.option(f"--{name}", type=float, default=None, help=which)


@click.command("planar")
@click.option(
    "--body",
    type=click.Choice(list(GEOMETRY)),
    default="rod",
    show_default=True,
    help=_help(
        "body",
        "A slender rod on its end, a block on a corner, a disk with its centre of "
        "mass off-centre, or a rod pendulum on a fixed pivot.",
    ),
)
@click.option("--mass", type=float, default=1.0, show_default=True, help=_help("mass"))
@_length("length", _help("length", "Rod, pendulum; default 1."))
@_length("width", _help("width", "Block; default 0.2."))
@_length("height", _help("height", "Block; default 0.1."))
@_length("radius", _help("radius", "The rim of the eccentric-disk; default 0.1."))
@_length("gyration", _help("gyration", "Eccentric-disk; default 0.07."))
@_length("offset", _help("offset", "Less than R (eccentric-disk; default 0.02)."))
@orientation_options
@click.option("--vx", type=float, default=None, help=_help("vx", "Default 1; not for a pendulum."))
@click.option("--vy", type=float, default=None, help=_help("vy", "Default -1; not for a pendulum."))
@click.option(
    "--omega",
    type=float,
    default=None,
    help=_help("omega", "Default 0; pendulum: 2 rad/s toward the surface."),
)
@click.option("--mu", type=float, default=0.3, show_default=True, help=_help("mu"))
@click.option("--kappa", type=float, default=0.8, show_default=True, help=_help("kappa"))
@click.option(
    "--law",
    type=click.Choice(list(LAWS)),
    default="poisson",
    show_default=True,
    help=_help("law"),
)
@click.option(
    "--json",
    "as_json",
    is_flag=True,
    help=_help("json", "Every PlanarImpact field; infinite or undefined values are null."),
)
@click.option("--plot", default=None, help=_help("plot", "Routh's diagram."))
@click.option("--laws-plot", default=None, help=_help("laws-plot"))
@click.option(
    "--html",
    "html_path",
    default=None,
    help=_help(
        "html",
        "(.html): the tables, the body's geometry, the regime explained, "
        "Routh's diagram and the three laws.",
    ),
)
@click.option(
    "--map-plot",
    default=None,
    help=_help(
        "map-plot",
        "Also where Newton's law creates energy; over the orientation's "
        "whole range (--orientation-deg is ignored) and u-/|v-| (not for a pendulum).",
    ),
)
@click.option(
    "--resolution",
    type=click.IntRange(2, 2000),
    default=200,
    show_default=True,
    help=_help("resolution", "Of --map-plot."),
)
@click.option(
    "--dpi",
    type=click.IntRange(50, 600),
    default=110,
    show_default=True,
    help=_help("dpi"),
)
def planar_command(
    as_json: bool,
    plot: str | None,
    laws_plot: str | None,
    map_plot: str | None,
    html_path: str | None,
    resolution: int,
    dpi: int,
    **options: Any,
) -> None:
    """Solve the impact of a planar body touching the surface off its centre line.

    The impulses couple through the collision matrix W: the slip can stop, stick or
    reverse, and Newton's, Poisson's and Stronge's laws differ. SI units, but the body's
    orientation in degrees (--orientation-deg; see docs/conventions.md).
    """
    paths = {"--plot": plot, "--laws-plot": laws_plot, "--map-plot": map_plot}
    formats = {option: _image(option, path) for option, path in paths.items()}
    if map_plot is not None and options["body"] == "pendulum":
        raise click.UsageError("--map-plot needs --body rod, block or eccentric-disk")
    _html_target(html_path)
    imp, incidence = solve_planar_options(options)
    if as_json:
        click.echo(json.dumps(jsonable(imp.to_dict()), indent=2))
    else:
        from ..viz.report import print_planar_report

        print_planar_report(imp)
    if html_path is not None:
        from ..io import atomic_path
        from ..viz.planar_html import planar_report_html

        page = planar_report_html(imp, geometry=preset_geometry(options))
        with atomic_path(html_path) as tmp:
            tmp.write_text(page, encoding="utf-8")
        if not as_json:
            click.echo(f"wrote {html_path}")
    if not any(paths.values()):
        return
    from ..io import atomic_path
    from ..viz.planar import plot_laws, plot_planar_map, plot_routh_planar

    def planar_map() -> Any:  # the body's geometry at every angle of the map
        sizes = {n: options[n] for n in _GEOMETRY_OPTIONS if not n.startswith("angle")}
        o = options

        def factory(angle: Any) -> Any:
            return make_planar_body(o["body"], o["mass"], {**sizes, "angle": angle})

        return plot_planar_map(factory, mu=o["mu"], kappa=o["kappa"], law=o["law"], n=resolution)

    draws = {
        "--plot": lambda: plot_routh_planar(imp),
        "--laws-plot": lambda: plot_laws(**incidence),
        "--map-plot": planar_map,
    }
    for option, draw in draws.items():
        path = paths[option]
        if path is not None:
            with atomic_path(path) as tmp:
                draw().savefig(tmp, format=formats[option], dpi=dpi)
            if not as_json:
                click.echo(f"wrote {path}")
