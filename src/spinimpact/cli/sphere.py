"""``spinimpact sphere`` and ``spinimpact pair``: a spinning sphere on a (moving, tilted)
plane in 3D, and two spheres colliding; ``--batch`` solves a file
(:func:`spinimpact.io.sphere_batch.run_sphere_batch`).

A person's inputs are converted once, here: ``--speed`` with ``--angle-deg`` (below the
surface) and ``--direction-deg`` (the heading ``d``: ``cos d t_1 + sin d t_2``, with
``t_1`` the direction along the surface closest to ``+x``, or to ``-y`` for a normal along
``x``, and ``t_2 = n x t_1``: ``-z`` for the default normal, so headings turn
counter-clockwise seen from above), and ``--rpm`` about ``--axis topspin`` (``n x e``, a
ball rolling forward along ``e``), ``backspin``, ``sidespin`` (``n``) or ``x,y,z``. For
two balls the "surface" is a horizontal table (``y`` up).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import click
import numpy as np

from ..model.body import Body, check_sphere
from ..model.pair import solve_pair
from ..model.sphere3d import Surface, solve_sphere
from ._common import DEFAULTS, _options, float_option, image_format, progress
from ._compliance import tangential_law, tangential_options
from ._sphere_report import report

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


def incidence(speed: float, angle_deg: float, direction_deg: float, normal: Any) -> np.ndarray:
    """Velocity relative to the surface from a speed (m/s), its angle below the surface and
    its heading along it (degrees): ``speed (cos a e - sin a n)``, ``e`` the heading."""
    if not (math.isfinite(speed) and speed > 0):
        raise click.UsageError(f"--speed must be a finite number > 0 (m/s), got {speed!r}")
    if not (math.isfinite(angle_deg) and 0 <= angle_deg <= 90):
        raise click.UsageError(
            f"--angle-deg must be in [0, 90] (degrees below the surface), got {angle_deg!r}"
        )
    if not math.isfinite(direction_deg):
        raise click.UsageError(f"--direction-deg must be finite, got {direction_deg!r}")
    n, t1, t2 = surface_frame(normal)
    a, d = math.radians(angle_deg), math.radians(direction_deg)
    heading = math.cos(d) * t1 + math.sin(d) * t2
    return speed * (math.cos(a) * heading - math.sin(a) * n)


def spin_vector(rpm: float, axis: str, normal: Any, travel: Any, option: str = "--axis") -> Any:
    """Spin (rad/s) of ``rpm`` revolutions per minute about ``axis``: ``topspin`` (about
    ``n x e``, ``e`` the direction of ``travel`` along the surface), ``backspin``,
    ``sidespin`` (about ``n``) or a direction ``x,y,z`` (right-handed)."""
    if not math.isfinite(rpm):
        raise click.UsageError(f"--rpm must be finite, got {rpm!r}")
    name = axis.strip().lower()
    n = _unit(normal, "--normal")
    if name == "sidespin":
        direction = n
    elif name in ("topspin", "backspin"):
        along = np.asarray(travel, float) - np.dot(travel, n) * n
        if not np.linalg.norm(along) > 1e-12 * max(1.0, float(np.linalg.norm(travel))):
            raise click.UsageError(
                f"{option} {name} needs a direction of travel along the surface, but the "
                "velocity is along the normal: give the axis as x,y,z"
            )
        direction = np.cross(n, along / np.linalg.norm(along)) * (1 if name == "topspin" else -1)
    else:
        try:
            vector = VECTOR.convert(axis, None, None)
        except click.BadParameter:
            raise click.UsageError(
                f"{option} must be topspin, backspin, sidespin or a direction x,y,z; got {axis!r}"
            ) from None
        direction = _unit(vector, option)
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
    person = (f"speed{k}", f"direction{k}_deg") + (("angle_deg",) if k == "" else ())
    v = o[f"velocity{k}"]
    if _one_of(ctx, f"velocity{k}", person):
        if o[f"speed{k}"] is None:
            raise click.UsageError(f"{_given(ctx, *person)[0]} needs --speed{k}")
        if k == "" and o["angle_deg"] is None:
            raise click.UsageError("--speed needs --angle-deg (degrees below the surface)")
        angle = o["angle_deg"] if k == "" else 0.0
        heading = o[f"direction{k}_deg"] or 0.0
        v = incidence(o[f"speed{k}"], angle, heading, normal) + np.asarray(frame, float)
    w = o[f"spin{k}"]
    if _one_of(ctx, f"spin{k}", (f"rpm{k}", f"axis{k}")):
        if o[f"rpm{k}"] is None or o[f"axis{k}"] is None:
            raise click.UsageError(f"--rpm{k} and --axis{k} go together")
        travel = np.asarray(v, float) - np.asarray(frame, float)
        w = spin_vector(o[f"rpm{k}"], o[f"axis{k}"], normal, travel, f"--axis{k}")
    return np.asarray(v, float), np.asarray(w, float)


def _body(o: dict, k: str = "") -> Body:
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
    plot, html_path = o["plot"], o["html_path"]
    _ = plot is None or image_format(plot, "--plot")
    if html_path is not None and Path(html_path).suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(f"--html must end in .html or .htm, got {html_path!r}")
    for option, path in (("--plot", plot), ("--html", html_path)):
        if path is not None and not Path(path).parent.is_dir():
            raise click.UsageError(f"{option}: no such directory {str(Path(path).parent)!r}")


def _batch(ctx: click.Context, pair: bool, o: dict, single: tuple[str, ...]) -> None:
    """``--batch SOURCE --output OUT``: every row of a file, through run_sphere_batch."""
    from ..io.sphere_batch import run_sphere_batch

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
    defaults = {"mu": o["mu"], "kappa": o["kappa"], "normal": o["normal"]}
    if pair:
        defaults.update({f"{n}{s}": o[f"{n}{k}"] for n in ones for k, s in (("1", ""), ("2", "2"))})
    else:
        defaults.update({n: o[n] for n in ones}, surface_velocity=o["surface_velocity"])
    with progress() as bar:
        task = bar.add_task(f"solving {Path(o['batch']).name}", total=None)
        summary = run_sphere_batch(
            o["batch"], o["output"], defaults=defaults, pair=pair,
            on_error=o["on_error"], chunk_size=o["chunk_size"],
            progress=lambda done, total: bar.update(task, completed=done, total=total),
        )  # fmt: skip
    note = f" ({summary.skipped} with errors: see the 'error' column)" if summary.skipped else ""
    what = "pairs of spheres" if summary.kind == "pair" else "spheres"
    click.echo(f"wrote {summary.rows} rows ({what}) to {summary.output}{note}")


def _float(name: str, help: str) -> Any:
    return click.option(f"--{name.replace('_', '-')}", type=float, default=None, help=help)


def _vector(name: str, help: str, default: Any = None) -> Any:
    shown = {"show_default": ",".join(f"{x:g}" for x in default)} if default else {}
    option = f"--{name.replace('_', '-')}"
    return click.option(option, type=VECTOR, default=default, help=help, **shown)


def _ball(k: str, which: str) -> Any:
    """A ball's body options (``k``: "" for the sphere, "1"/"2" for a pair)."""
    return _options(
        click.option(f"--body{k}", type=click.Choice(SPHERES), default=None,
                     help=f"{which}: preset (default {SPHERES[0]})."),  # fmt: skip
        *(click.option(f"--{n}{k}", type=float, default=DEFAULTS[n], show_default=True,
                       help=f"{which}: {n}, {u}.") for n, u in (("mass", "kg"), ("radius", "m"))),
        _float(f"gyration{k}", f"{which}: radius of gyration rho, m, instead of a preset "
               "(a thick shell lies between 0.632 R and 0.816 R)."),
    )  # fmt: skip


_common_options = _options(
    float_option("mu", "Friction >= 0."),
    float_option("kappa", "Restitution in [0, 1]."),
    click.option("--json", "as_json", is_flag=True,
                 help="Print every field as JSON (angles in rad; undefined values null)."),
    click.option("--plot", default=None,
                 help="Write the side and top views with the arrows (.png, .svg, .pdf)."),
    click.option("--html", "html_path", default=None,
                 help="Write the report as one self-contained HTML page (.html)."),
    click.option("--dpi", type=click.IntRange(50, 600), default=110, show_default=True,
                 help="Image dots per inch."),
    click.option("--batch", default=None, type=click.Path(dir_okay=False),
                 help="Solve every row of this CSV or Parquet file instead (columns above)."),
    click.option("--output", default=None, help="With --batch: the output file (.csv, .parquet)."),
    click.option("--on-error", type=click.Choice(["stop", "skip"]), default="stop",
                 show_default=True,
                 help="With --batch: stop at the first bad row (nothing written), or write "
                 "bad rows with an 'error' column."),
    click.option("--chunk-size", type=click.IntRange(1), default=100_000, show_default=True,
                 help="With --batch: rows per chunk."),
)  # fmt: skip

_SPHERE_SINGLE = ("velocity", "spin", "speed", "angle_deg", "direction_deg", "rpm", "axis")


@click.command("sphere")
@_ball("", "The sphere")
@_vector("velocity", "Centre velocity before, m/s (ground frame).", (3.0, -4.0, 0.0))
@_vector("spin", "Spin vector before, rad/s (right-handed).", (0.0, 0.0, 10.0))
@_float("speed", "Instead of --velocity: speed relative to the surface, m/s.")
@_float("angle_deg", "With --speed: angle below the surface, degrees (90: head-on).")
@_float("direction_deg", "With --speed: heading along the surface, degrees, counter-clockwise "
        "seen from above (0: +x; 90: -z for the default normal).")  # fmt: skip
@_float("rpm", "Instead of --spin: spin rate, revolutions per minute.")
@click.option("--axis", default=None,
              help="With --rpm: topspin, backspin, sidespin or a direction x,y,z.")  # fmt: skip
@_vector("normal", "Outward normal of the surface (normalised).", (0.0, 1.0, 0.0))
@_vector("surface_velocity", "Velocity of the surface (racket, belt), m/s.", (0.0, 0.0, 0.0))
@_common_options
@tangential_options
@click.pass_context
def sphere_command(ctx: click.Context, **o: Any) -> None:
    """A spinning sphere on a plane in 3D: x along the surface, y up, z = x cross y.

    \b
    Vectors: --velocity vx,vy,vz --spin wx,wy,wz (SI units). Or a person's inputs:
      --speed 20 --angle-deg 16 --direction-deg 0 --rpm 3000 --axis topspin
    The surface: --normal (tilted) and --surface-velocity (moving); the impact is solved in
    the surface's frame, the results are in the ground's.
    --batch FILE --output OUT: columns vx,vy,vz,wx,wy,wz, optionally mu, kappa, mass,
      radius, gyration, body, normal_x..z, surface_velocity_x..z (pairs of balls:
      spinimpact pair --batch).
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
    body = _body(o)
    v, w = _state(ctx, o, "", o["normal"], o["surface_velocity"])
    surface = Surface(normal=o["normal"], velocity=o["surface_velocity"])
    imp = solve_sphere(body, v, w, mu=o["mu"], kappa=o["kappa"], surface=surface, tangential=law)
    report(imp, o["as_json"], o["plot"], o["html_path"], o["dpi"])


def _pair_ball(k: str) -> Any:
    velocity = (2.0, 0.0, 0.0) if k == "1" else (0.0, 0.0, 0.0)
    spin = (0.0, 0.0, -20.0) if k == "1" else (0.0, 0.0, 0.0)
    return _options(
        _ball(k, f"Ball {k}"),
        _vector(f"velocity{k}", f"Velocity of ball {k}'s centre, m/s.", velocity),
        _vector(f"spin{k}", f"Spin vector of ball {k}, rad/s.", spin),
        _float(f"speed{k}", f"Instead of --velocity{k}: speed along the table (y up), m/s."),
        _float(f"direction{k}_deg", f"With --speed{k}: heading, degrees, counter-clockwise "
               "seen from above (0: +x, 90: -z)."),
        _float(f"rpm{k}", f"Instead of --spin{k}: spin rate, rpm."),
        click.option(f"--axis{k}", default=None, help=f"With --rpm{k}: topspin, backspin, "
                     "sidespin (about the table's normal y, ball's own travel) or x,y,z."),
    )  # fmt: skip


_PAIR_SINGLE = ("centre1", "centre2") + tuple(
    f"{n}{k}{'_deg' * (n == 'direction')}"
    for k in "12" for n in ("velocity", "spin", "speed", "direction", "rpm", "axis")
)  # fmt: skip


@click.command("pair")
@_pair_ball("1")
@_pair_ball("2")
@_vector("normal", "Direction from ball 2's centre to ball 1's (normalised; default -1,0,1: "
         "a 45° cut), or give --centre1 and --centre2.")  # fmt: skip
@_vector("centre1", "Instead of --normal: ball 1's centre, m.")
@_vector("centre2", "Instead of --normal: ball 2's centre, m (radius1 + radius2 apart).")
@_common_options
@click.pass_context
def pair_command(ctx: click.Context, **o: Any) -> None:
    """Two spinning spheres colliding (billiards, DEM, ball on ball), in 3D.

    \b
    --velocity1 vx,vy,vz --spin1 wx,wy,wz (and 2), --normal from ball 2 to ball 1; or
      --speed1 2 --direction1-deg 0 --rpm1 600 --axis1 topspin (on a table, y up).
    --batch FILE --output OUT: columns vx,vy,vz,wx,wy,wz (ball 1), vx2,...,wz2 (ball 2),
      optionally normal_x..z, mu, kappa, mass, radius, gyration, body, mass2, radius2,
      gyration2, body2.
    """
    if o["batch"] is not None:
        return _batch(ctx, True, o, _PAIR_SINGLE)
    _check_targets(o)
    centres = (o["centre1"], o["centre2"])
    if (centres[0] is None) != (centres[1] is None):
        raise click.UsageError("--centre1 and --centre2 go together")
    if centres[0] is not None and o["normal"] is not None:
        raise click.UsageError("give either --normal or --centre1 and --centre2, not both")
    normal = (-1.0, 0.0, 1.0) if o["normal"] is None and centres[0] is None else o["normal"]
    states = [_state(ctx, o, k, _UP, (0.0, 0.0, 0.0)) for k in "12"]
    imp = solve_pair(
        _body(o, "1"), _body(o, "2"), velocity1=states[0][0], spin1=states[0][1],
        velocity2=states[1][0], spin2=states[1][1], mu=o["mu"], kappa=o["kappa"],
        normal=normal, centres=None if centres[0] is None else centres,
    )  # fmt: skip
    report(imp, o["as_json"], o["plot"], o["html_path"], o["dpi"])
