"""``spinimpact sphere`` and ``spinimpact pair``: a spinning sphere on a (moving, tilted)
plane in 3D, and two spheres colliding; ``spinimpact batch`` solves files of them (the
hidden, deprecated ``--batch`` still runs it and says so).

A person's inputs are converted once, here: ``--speed`` (in ``--speed-unit``) with
``--incidence-from-surface-deg`` (below the surface) and ``--heading-deg`` (the heading
``d``: ``cos d t_1 + sin d t_2``, with ``t_1`` the direction along the surface closest to
``+x``, or to ``-y`` for a normal along ``x``, and ``t_2 = n x t_1``: ``-z`` for the default
normal, so headings turn counter-clockwise seen from above), and ``--spin-rpm`` about
``--spin-axis topspin`` (``n x e``, a ball rolling forward along ``e``), ``backspin``,
``sidespin`` (``n``), a combination (:mod:`spinimpact.model.spin_axis`) or ``x,y,z``.
``--ball`` and ``--surface`` fill the body and mu, kappa from the presets
(:data:`~spinimpact.BALLS`, :data:`~spinimpact.GROUNDS`). For two balls the "surface" is a
horizontal table (``y`` up). The names, units and signs: ``docs/conventions.md``.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import click
import numpy as np

from .._words import count
from ..model.body import Body, check_sphere
from ..model.pair import solve_pair
from ..model.presets import BALLS, GROUNDS
from ..model.sphere3d import Surface, solve_sphere
from ..model.spin_axis import combine_axes, parse_spin_axis
from ._common import DEFAULTS, SPEED_UNITS, _options, image_format, progress
from ._compliance import tangential_law, tangential_options
from ._sphere_report import report
from ._vocabulary import deprecated
from ._vocabulary import help as _help

__all__ = ["sphere_command", "pair_command", "surface_frame", "incidence", "spin_vector"]

SPHERES = ("solid-sphere", "spherical-shell")
_UP = (0.0, 1.0, 0.0)
_DEFAULT = click.core.ParameterSource.DEFAULT
_KEYS = {"json": "as_json", "plot": "plot", "html": "html_path"}


class _Vector(click.ParamType):
    """``x,y,z``: three finite numbers separated by commas."""

    name = "x,y,z"

    def convert(self, value: Any, param: Any, ctx: Any) -> tuple[float, float, float]:
        if isinstance(value, tuple):
            return value
        try:
            parts = tuple(float(p) for p in str(value).split(","))
        except ValueError:
            parts = ()
        if len(parts) != 3 or not all(map(math.isfinite, parts)):
            self.fail(f"expected three finite numbers x,y,z separated by commas, got {value!r}")
        return parts  # type: ignore[return-value]


VECTOR = _Vector()


def _unit(vector: Any, what: str) -> np.ndarray:
    v = np.asarray(vector, dtype=float)
    size = float(np.linalg.norm(v))
    if not size > 1e-12:
        raise click.UsageError(f"{what} must be a direction, got the zero vector {tuple(v)}")
    return v / size


def surface_frame(normal: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(n, t_1, t_2)``: the unit normal and the surface's headings 0° and 90°."""
    n = _unit(normal, "--normal")
    for guess in ((1.0, 0.0, 0.0), (0.0, -1.0, 0.0)):
        t = np.asarray(guess) - np.dot(guess, n) * n
        if np.linalg.norm(t) > 1e-6:
            break
    t1 = t / np.linalg.norm(t)
    return n, t1, np.cross(n, t1)


def incidence(speed: float, angle_deg: float, direction_deg: float, normal: Any,
              k: str = "") -> np.ndarray:  # fmt: skip
    """Velocity relative to the surface from a speed (m/s), its angle below the surface and
    its heading along it (degrees): ``speed (cos a e - sin a n)``, ``e`` the heading.
    ``k``: the ball's number in the options named by errors (``""``, ``"1"``, ``"2"``)."""
    if not (math.isfinite(speed) and speed > 0):
        raise click.UsageError(f"--speed{k} must be a finite number > 0, got {speed!r}")
    if not (math.isfinite(angle_deg) and 0 <= angle_deg <= 90):
        raise click.UsageError(
            "--incidence-from-surface-deg must be in [0, 90] (degrees below the surface), "
            f"got {angle_deg!r}"
        )
    if not math.isfinite(direction_deg):
        raise click.UsageError(f"--heading{k}-deg must be finite, got {direction_deg!r}")
    n, t1, t2 = surface_frame(normal)
    a, d = math.radians(angle_deg), math.radians(direction_deg)
    heading = math.cos(d) * t1 + math.sin(d) * t2
    return speed * (math.cos(a) * heading - math.sin(a) * n)


def spin_vector(rpm: float, axis: str, normal: Any, travel: Any,
                option: str = "--spin-axis") -> Any:  # fmt: skip
    """Spin (rad/s) of ``rpm`` revolutions per minute about ``axis``: ``topspin`` (about
    ``n x e``, ``e`` the direction of ``travel`` along the surface), ``backspin``,
    ``sidespin`` (about ``n``), a combination of them (``topspin+sidespin``: halfway;
    ``topspin:0.8+sidespin:0.2``: weighted, :mod:`spinimpact.model.spin_axis`) or a
    direction ``x,y,z`` (right-handed)."""
    if not math.isfinite(rpm):
        raise click.UsageError(f"{option.replace('axis', 'rpm')} must be finite, got {rpm!r}")
    n = _unit(normal, "--normal")
    if "," in axis:
        try:
            vector = VECTOR.convert(axis, None, None)
        except click.BadParameter:
            raise click.UsageError(
                f"{option} must be topspin, backspin, sidespin, a combination such as "
                f"topspin+sidespin, or a direction x,y,z; got {axis!r}"
            ) from None
        direction = _unit(vector, option)
        return rpm * 2 * math.pi / 60 * direction
    parts = parse_spin_axis(axis, option)
    named = {"sidespin": n}
    if any(name != "sidespin" for name, _ in parts):
        along = np.asarray(travel, float) - np.dot(travel, n) * n
        if not np.linalg.norm(along) > 1e-12 * max(1.0, float(np.linalg.norm(travel))):
            raise click.UsageError(
                f"{option} {axis} needs a direction of travel along the surface, but the "
                "velocity is along the normal: give the axis as x,y,z"
            )
        top = np.cross(n, along / np.linalg.norm(along))
        named.update(topspin=top * 1, backspin=top * -1)
    direction = combine_axes(parts, named, option)
    return rpm * 2 * math.pi / 60 * direction


def _given(ctx: click.Context, *names: str) -> list[str]:
    """The options among ``names`` that the user typed, as ``--option``."""
    typed = [n for n in names if ctx.get_parameter_source(n) not in (None, _DEFAULT)]
    return [f"--{n.replace('_', '-')}" for n in typed]


def _one_of(ctx: click.Context, vector: str, alternative: tuple[str, ...]) -> bool:
    """Whether the alternative inputs are used (and not together with the vector)."""
    typed = _given(ctx, *alternative)
    if typed and _given(ctx, vector):
        raise click.UsageError(f"give either --{vector} or {typed[0]} (and its companions)")
    return bool(typed)


def _state(ctx: click.Context, o: dict, k: str, normal: Any, frame: Any) -> tuple:
    """Velocity and spin of one ball from its options: ``k`` is ``""`` (a sphere on the
    surface of normal ``normal`` moving with ``frame``) or ``"1"``, ``"2"`` (a ball of a
    pair: speeds and headings along the table, ``normal`` up, ``frame`` zero)."""
    person = (f"speed{k}", f"heading{k}_deg") + (("incidence_from_surface_deg",) if k == "" else ())
    v = o[f"velocity{k}"]
    if _one_of(ctx, f"velocity{k}", person):
        if o[f"speed{k}"] is None:
            raise click.UsageError(f"{_given(ctx, *person)[0]} needs --speed{k}")
        if k == "" and o["incidence_from_surface_deg"] is None:
            raise click.UsageError(
                "--speed needs --incidence-from-surface-deg (degrees below the surface)"
            )
        angle = o["incidence_from_surface_deg"] if k == "" else 0.0
        heading = o[f"heading{k}_deg"] or 0.0
        speed = o[f"speed{k}"] * SPEED_UNITS[o["speed_unit"]]
        v = incidence(speed, angle, heading, normal, k) + np.asarray(frame, float)
    w = o[f"spin{k}"]
    if _one_of(ctx, f"spin{k}", (f"spin{k}_rpm", f"spin{k}_axis")):
        if o[f"spin{k}_rpm"] is None or o[f"spin{k}_axis"] is None:
            raise click.UsageError(f"--spin{k}-rpm and --spin{k}-axis go together")
        travel = np.asarray(v, float) - np.asarray(frame, float)
        w = spin_vector(o[f"spin{k}_rpm"], o[f"spin{k}_axis"], normal, travel, f"--spin{k}-axis")
    return np.asarray(v, float), np.asarray(w, float)


def _speed_unit(ctx: click.Context, o: dict, speeds: tuple[str, ...]) -> None:
    """Refuse ``--speed-unit`` without a speed it applies to (vectors are in m/s)."""
    if _given(ctx, "speed_unit") and not _given(ctx, *speeds):
        raise click.UsageError(
            f"--speed-unit applies to {' and '.join('--' + n for n in speeds)}; "
            "vectors (--velocity ...) are in m/s"
        )


def _body(ctx: click.Context, o: dict, k: str = "") -> Body:
    if o[f"ball{k}"] is not None:
        names = (f"body{k}", f"gyration{k}", f"mass{k}", f"radius{k}")
        typed = _given(ctx, *names)
        if typed:
            raise click.UsageError(f"give either --ball{k} or {typed[0]}, not both")
        return BALLS[o[f"ball{k}"]].body
    name, gyration = o[f"body{k}"], o[f"gyration{k}"]
    if gyration is not None:
        if name is not None:
            raise click.UsageError(f"give either --body{k} or --gyration{k}, not both")
        body = Body(mass=o[f"mass{k}"], radius=o[f"radius{k}"], gyration=gyration)
        check_sphere(body, f"--gyration{k}")  # named as typed
        return body
    return Body.preset(name or SPHERES[0], mass=o[f"mass{k}"], radius=o[f"radius{k}"])


def _check_targets(o: dict) -> None:
    """Check ``--plot`` and ``--html`` before anything is solved or printed."""
    if o["output"] is not None:
        raise click.UsageError("--output goes with --batch (the file a batch run writes)")
    for name, default in (("on_error", "stop"), ("chunk_size", 100_000)):
        if o[name] != default:
            option = "--" + name.replace("_", "-")
            raise click.UsageError(f"{option} goes with a file of impacts: spinimpact batch")
    plot, html_path = o["plot"], o["html_path"]
    _ = plot is None or image_format(plot, "--plot")
    if html_path is not None and Path(html_path).suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(f"--html must end in .html or .htm, got {html_path!r}")
    for option, path in (("--plot", plot), ("--html", html_path)):
        if path is not None and not Path(path).parent.is_dir():
            raise click.UsageError(f"{option}: no such directory {str(Path(path).parent)!r}")


def _batch(ctx: click.Context, pair: bool, o: dict, single: tuple[str, ...]) -> None:
    """``--batch SOURCE --output OUT`` (deprecated): every row of a file, through
    ``spinimpact batch``'s :func:`~spinimpact.io.batch.run_batch`."""
    from ..io.batch import run_batch

    command = "pair" if pair else "sphere"  # fmt: skip
    if o["output"] is None:
        raise click.UsageError("--batch needs --output (a .csv or .parquet file)")
    typed = _given(ctx, *single) + [f"--{n}" for n in ("json", "plot", "html") if o[_KEYS[n]]]
    if typed:
        raise click.UsageError(
            f"{typed[0]} describes one impact; with --batch each row of the file gives its own"
        )
    for k in ("", "1", "2"):
        if f"body{k}" in o and o[f"body{k}"] is not None and o[f"gyration{k}"] is not None:
            raise click.UsageError(f"give either --body{k} or --gyration{k}, not both")
    ones = ("mass", "radius", "gyration", "body")
    mu, kappa = _surface(o)
    defaults = {"mu": mu, "kappa": kappa, "normal": o["normal"]}
    for k in ("", "1", "2"):  # a ball preset gives its numbers
        if o.get(f"ball{k}") is not None:
            ball = BALLS[o[f"ball{k}"]]
            _body(ctx, o, k)  # refuses body options given with it
            o.update({f"mass{k}": ball.mass, f"radius{k}": ball.radius,
                      f"gyration{k}": ball.gyration, f"body{k}": None})  # fmt: skip
    if pair:
        defaults.update({f"{n}{s}": o[f"{n}{k}"] for n in ones for k, s in (("1", ""), ("2", "2"))})
    else:
        defaults.update({n: o[n] for n in ones}, surface_velocity=o["surface_velocity"])
    with progress() as bar:
        task = bar.add_task(f"solving {Path(o['batch']).name}", total=None)
        summary = run_batch(
            o["batch"], o["output"], defaults=defaults, problem=command,
            on_error=o["on_error"], chunk_size=o["chunk_size"],
            progress=lambda done, total: bar.update(task, completed=done, total=total),
        )  # fmt: skip
    note = f" ({summary.skipped} with errors: see the 'error' column)" if summary.skipped else ""
    what = "pairs of spheres" if summary.kind == "pair" else "spheres"
    click.echo(f"wrote {count(summary.rows, 'row')} ({what}) to {summary.output}{note}")
    click.echo(
        f"spinimpact: warning: '{command} --batch' is deprecated; use 'spinimpact batch "
        f"FILE --output OUT' (the file's columns say it holds {command}s)",
        err=True,
    )


def _float(name: str, help: str) -> Any:
    return click.option(f"--{name.replace('_', '-')}", type=float, default=None, help=help)


def _vector(name: str, help: str, default: Any = None) -> Any:
    shown = {"show_default": ",".join(f"{x:g}" for x in default)} if default else {}
    option = f"--{name.replace('_', '-')}"
    return click.option(option, type=VECTOR, default=default, help=help, **shown)


def _ball(k: str, which: str) -> Any:
    """A ball's body options (``k``: "" for the sphere, "1"/"2" for a pair)."""
    return _options(
        click.option(f"--ball{k}", type=click.Choice(list(BALLS)), default=None,
                     help=_help("ball", f"{which}, instead of the body options.")),
        click.option(f"--body{k}", type=click.Choice(SPHERES), default=None,
                     help=_help("body", f"{which} (default {SPHERES[0]}).")),
        *(click.option(f"--{n}{k}", type=float, default=DEFAULTS[n], show_default=True,
                       help=_help(n, f"{which}.")) for n in ("mass", "radius")),
        _float(f"gyration{k}", _help("gyration", f"{which}, instead of a preset (a thick "
               "shell lies between 0.632 R and 0.816 R).")),
    )  # fmt: skip


def _surface_value(name: str) -> Any:
    """``--mu``/``--kappa``: the documented default, or the ``--surface`` preset's."""
    return click.option(f"--{name}", type=float, default=None, help=_help(
        name, f"Default {DEFAULTS[name]:g}, or the --surface preset's where given (this "
        "overrides it)."))  # fmt: skip


def _surface(o: dict) -> tuple[float, float]:
    """mu and kappa: typed, else the ``--surface`` preset's, else the documented defaults."""
    ground = GROUNDS[o["surface"]] if o.get("surface") is not None else None
    fallback = {n: DEFAULTS[n] if ground is None else getattr(ground, n) for n in ("mu", "kappa")}
    return tuple(fallback[n] if o[n] is None else o[n] for n in ("mu", "kappa"))  # type: ignore[return-value]


_SPEED_UNIT = click.option(
    "--speed-unit", type=click.Choice(list(SPEED_UNITS)), default="m/s", show_default=True,
    help=_help("speed-unit"),
)  # fmt: skip

_common_options = _options(
    _surface_value("mu"),
    _surface_value("kappa"),
    click.option("--json", "as_json", is_flag=True,
                 help=_help("json", "Every field; angles in rad; undefined values null.")),
    click.option("--plot", default=None,
                 help=_help("plot", "The side and top views with the arrows.")),
    click.option("--html", "html_path", default=None, help=_help("html", "(.html)")),
    click.option("--dpi", type=click.IntRange(50, 600), default=110, show_default=True,
                 help=_help("dpi")),
    # Deprecated: spinimpact batch solves files of spheres and pairs (hidden; a run says so)
    click.option("--batch", default=None, type=click.Path(dir_okay=False), hidden=True),
    click.option("--output", default=None, hidden=True),
    click.option("--on-error", type=click.Choice(["stop", "skip"]), default="stop",
                 hidden=True),
    click.option("--chunk-size", type=click.IntRange(1), default=100_000, hidden=True),
)  # fmt: skip

_SPHERE_SINGLE = ("velocity", "spin", "speed", "incidence_from_surface_deg", "heading_deg",
                  "spin_rpm", "spin_axis")  # fmt: skip


@click.command("sphere")
@_ball("", "The sphere")
@_vector("velocity", _help("velocity"), (3.0, -4.0, 0.0))
@_vector("spin", _help("spin"), (0.0, 0.0, 10.0))
@_float("speed", _help("speed", "Instead of --velocity: relative to the surface."))
@_SPEED_UNIT
@_float("incidence_from_surface_deg", _help("incidence-from-surface-deg", "With --speed."))
@_float("heading_deg", _help("heading-deg", "With --speed; t_1 (0) is the direction along the "
        "surface closest to +x, t_2 (90) = n x t_1."))  # fmt: skip
@_float("spin_rpm", _help("spin-rpm", "Instead of --spin."))
@click.option("--spin-axis", default=None, help=_help("spin-axis", "With --spin-rpm."))
@deprecated("--angle-deg", "--incidence-from-surface-deg", "incidence_from_surface_deg",
            type=float)  # fmt: skip
@deprecated("--direction-deg", "--heading-deg", "heading_deg", type=float)
@deprecated("--rpm", "--spin-rpm", "spin_rpm", type=float)
@deprecated("--axis", "--spin-axis", "spin_axis")
@_vector("normal", _help("normal"), (0.0, 1.0, 0.0))
@_vector("surface_velocity", _help("surface-velocity"), (0.0, 0.0, 0.0))
@click.option("--surface", type=click.Choice(list(GROUNDS)), default=None,
              help=_help("surface", "Default: mu and kappa as given."))  # fmt: skip
@_common_options
@tangential_options
@click.pass_context
def sphere_command(ctx: click.Context, **o: Any) -> None:
    """A spinning sphere on a plane in 3D: x along the surface, y up, z = x cross y.

    \b
    Vectors: --velocity vx,vy,vz --spin wx,wy,wz (SI units). Or a person's inputs:
      --speed 20 --incidence-from-surface-deg 16 --heading-deg 0 --spin-rpm 3000
      --spin-axis topspin (or topspin+sidespin, topspin:0.8+sidespin:0.2)
    Presets: --ball tennis --surface hard (docs/conventions.md).
    The surface: --normal (tilted) and --surface-velocity (moving); the impact is solved in
    the surface's frame, the results are in the ground's.
    A file of impacts: spinimpact batch FILE --output OUT (columns vx,vy,vz,wx,wy,wz,
      optionally mu, kappa, mass, radius, gyration, body, normal_x..z,
      surface_velocity_x..z; spinimpact problems sphere lists them).
    --tangential walton|stronge|mindlin-deresiewicz: the contact point's tangential
      restitution of Walton's, Stronge's or the micro-slip law along the slip
      (docs/compliance.md); a plain report or --json.
    """
    law = tangential_law(o)
    rigid_only = [n for n, k in (("--batch", "batch"), ("--plot", "plot"),
                                 ("--html", "html_path")) if o[k] is not None]  # fmt: skip
    if law is not None and rigid_only:
        raise click.UsageError(f"{rigid_only[0]} takes the rigid law only, not --tangential "
                               f"{law.name}")  # fmt: skip
    if o["batch"] is not None:
        return _batch(ctx, False, o, _SPHERE_SINGLE)
    _check_targets(o)
    _speed_unit(ctx, o, ("speed",))
    body = _body(ctx, o)
    v, w = _state(ctx, o, "", o["normal"], o["surface_velocity"])
    surface = Surface(normal=o["normal"], velocity=o["surface_velocity"])
    mu, kappa = _surface(o)
    imp = solve_sphere(body, v, w, mu=mu, kappa=kappa, surface=surface, tangential=law)
    report(imp, o["as_json"], o["plot"], o["html_path"], o["dpi"])


def _pair_ball(k: str) -> Any:
    velocity = (2.0, 0.0, 0.0) if k == "1" else (0.0, 0.0, 0.0)
    spin = (0.0, 0.0, -20.0) if k == "1" else (0.0, 0.0, 0.0)
    return _options(
        _ball(k, f"Ball {k}"),
        _vector(f"velocity{k}", _help("velocity", f"Ball {k}."), velocity),
        _vector(f"spin{k}", _help("spin", f"Ball {k}."), spin),
        _float(f"speed{k}", _help("speed", f"Ball {k}, instead of --velocity{k}: along the "
               "table (y up).")),
        _float(f"heading{k}_deg", _help("heading-deg", f"Ball {k}, with --speed{k}.")),
        _float(f"spin{k}_rpm", _help("spin-rpm", f"Ball {k}, instead of --spin{k}.")),
        click.option(f"--spin{k}-axis", default=None, help=_help("spin-axis", f"Ball {k}, with "
                     f"--spin{k}-rpm: sidespin is about the table's normal y, topspin about "
                     "the ball's own travel.")),
        deprecated(f"--direction{k}-deg", f"--heading{k}-deg", f"heading{k}_deg", type=float),
        deprecated(f"--rpm{k}", f"--spin{k}-rpm", f"spin{k}_rpm", type=float),
        deprecated(f"--axis{k}", f"--spin{k}-axis", f"spin{k}_axis"),
    )  # fmt: skip


_PAIR_SINGLE = ("centre1", "centre2") + tuple(
    n.replace("#", k)
    for k in "12"
    for n in ("velocity#", "spin#", "speed#", "heading#_deg", "spin#_rpm", "spin#_axis")
)  # fmt: skip


@click.command("pair")
@_pair_ball("1")
@_pair_ball("2")
@_SPEED_UNIT
@_vector("normal", _help("normal", "Default -1,0,1: a 45° cut; or give --centre1 and "
         "--centre2."))  # fmt: skip
@_vector("centre1", _help("centre", "Ball 1, instead of --normal."))
@_vector("centre2", _help("centre", "Ball 2, instead of --normal (radius1 + radius2 apart)."))
@_common_options
@click.pass_context
def pair_command(ctx: click.Context, **o: Any) -> None:
    """Two spinning spheres colliding (billiards, DEM, ball on ball), in 3D.

    \b
    --velocity1 vx,vy,vz --spin1 wx,wy,wz (and 2), --normal from ball 2 to ball 1; or
      --speed1 2 --heading1-deg 0 --spin1-rpm 600 --spin1-axis topspin (on a table, y up).
    A file of impacts: spinimpact batch FILE --output OUT (columns vx,vy,vz,wx,wy,wz of
      ball 1, vx2,...,wz2 of ball 2, normal_x..z, optionally mu, kappa, mass, radius,
      gyration, body, mass2, radius2, gyration2, body2; spinimpact problems pair).
    """
    if o["batch"] is not None:
        return _batch(ctx, True, o, _PAIR_SINGLE)
    _check_targets(o)
    _speed_unit(ctx, o, ("speed1", "speed2"))
    centres = (o["centre1"], o["centre2"])
    if (centres[0] is None) != (centres[1] is None):
        raise click.UsageError("--centre1 and --centre2 go together")
    if centres[0] is not None and o["normal"] is not None:
        raise click.UsageError("give either --normal or --centre1 and --centre2, not both")
    normal = (-1.0, 0.0, 1.0) if o["normal"] is None and centres[0] is None else o["normal"]
    states = [_state(ctx, o, k, _UP, (0.0, 0.0, 0.0)) for k in "12"]
    mu, kappa = _surface(o)
    imp = solve_pair(
        _body(ctx, o, "1"), _body(ctx, o, "2"), velocity1=states[0][0], spin1=states[0][1],
        velocity2=states[1][0], spin2=states[1][1], mu=mu, kappa=kappa,
        normal=normal, centres=None if centres[0] is None else centres,
    )  # fmt: skip
    report(imp, o["as_json"], o["plot"], o["html_path"], o["dpi"])
