"""One vocabulary for the command line: each option's one name, meaning and unit.

:data:`TERMS` maps every visible option name (without the leading ``--``; a ball's
number, as in ``--mass1``, left out) to its :class:`Term`. Every command builds its
options' help from it (:func:`help`), ``docs/conventions.md`` lists it, and
``tests/cli/test_vocabulary.py`` walks every command and fails for a visible option
that is not here, for two names with the same meaning, and for an option whose help
does not begin with its term's text (one name, one meaning, one unit).

Old names keep working as hidden options that say once on stderr that they are
deprecated and which option replaces them (:func:`deprecated`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

import click

__all__ = ["Term", "TERMS", "term", "help", "concept", "deprecated", "Deprecated"]


@dataclass(frozen=True)
class Term:
    """One concept: what it is (``meaning``) and its unit (``""`` when it has none)."""

    meaning: str
    unit: str = ""

    @property
    def text(self) -> str:
        """How every help of the option begins: ``"meaning, unit"``."""
        return f"{self.meaning}, {self.unit}" if self.unit else self.meaning


_DEG = "degrees"
#: Every visible option of every command: its one meaning and unit.
TERMS: dict[str, Term] = {
    # bodies and balls
    "body": Term("Body preset"),
    "ball": Term(
        "Ball preset: its mass, radius, radius of gyration (and, in flight, its air coefficients)"
    ),
    "mass": Term("Mass m", "kg"),
    "radius": Term("Contact radius R (a ball's radius)", "m"),
    "gyration": Term("Radius of gyration rho about the centre of mass", "m"),
    "free-gyration": Term("Fit the radius of gyration too"),
    "length": Term("Length L of a rod or pendulum", "m"),
    "width": Term("Width of a block: its side along the tilt", "m"),
    "height": Term("Height of a block: its side across the tilt", "m"),
    "offset": Term("Offset of the centre of mass from an eccentric disk's centre", "m"),
    "orientation-deg": Term("The body's orientation, measured from the surface", _DEG),
    "inertia": Term("Moment of inertia J about the centre of mass", "kg m^2"),
    "rx": Term("Contact point from the centre of mass along x", "m"),
    "ry": Term("Contact point from the centre of mass along y (< 0)", "m"),
    # the surface
    "surface": Term("Surface preset (mu, kappa; in flight also rolling resistance)"),
    "mu": Term("Friction coefficient mu >= 0"),
    "kappa": Term("Restitution coefficient kappa in [0, 1]"),
    "law": Term("Restitution law"),
    "normal": Term(
        "Contact normal x,y,z, normalised: the surface's outward normal (for two "
        "balls, from ball 2's centre to ball 1's)"
    ),
    "surface-velocity": Term("Velocity x,y,z of the surface (racket, belt)", "m/s"),
    "centre": Term("Centre x,y,z of a ball", "m"),
    # incidence: velocity, speed, angles
    "vx": Term("Incidence vx, along the surface", "m/s"),
    "vy": Term("Incidence vy, along the normal (< 0: approaching)", "m/s"),
    "vz": Term("Incidence vz, along z = x cross y", "m/s"),
    "velocity": Term("Centre velocity x,y,z before the impact (ground frame)", "m/s"),
    "speed": Term("Speed, in --speed-unit"),
    "speed-unit": Term("Unit of the speeds given as --speed (vectors stay in m/s)"),
    "incidence-from-surface-deg": Term(
        "Incidence angle below the surface, measured from the surface (90: head-on)", _DEG
    ),
    "elevation-deg": Term("Launch angle above the horizontal (negative: downwards)", _DEG),
    "heading-deg": Term(
        "Heading along the surface, measured from +x counter-clockwise seen from above (90: -z)",
        _DEG,
    ),
    # spin
    "omega": Term("Incidence spin about z, counter-clockwise positive", "rad/s"),
    "wx": Term("Incidence spin about x, right-handed", "rad/s"),
    "wy": Term("Incidence spin about y, right-handed", "rad/s"),
    "wz": Term("Incidence spin about z, right-handed", "rad/s"),
    "spin": Term("Spin vector x,y,z before the impact, right-handed", "rad/s"),
    "spin-rpm": Term("Spin rate about --spin-axis", "rpm"),
    "spin-axis": Term(
        "Spin axis: topspin, backspin, sidespin, a combination (topspin+sidespin, "
        "topspin:0.8+sidespin:0.2) or a direction x,y,z"
    ),
    # contact laws
    "tangential": Term("Tangential law"),
    "beta0": Term("Walton: tangential restitution of sticking impacts, in [-1, 1]"),
    "poisson-ratio": Term("Poisson's ratio nu in (-1, 0.5]"),
    "stiffness-ratio": Term("Tangential over normal contact stiffness k_t/k_n > 0"),
    "contact": Term("Normal contact law"),
    "youngs-modulus": Term("Young's modulus E", "Pa"),
    "stiffness": Term("Normal contact stiffness k", "N/m or N/m^n"),
    "damping": Term("Linear contact damping c", "N s/m"),
    "exponent": Term("Hunt-Crossley force exponent n"),
    "alpha": Term("Hunt-Crossley damping alpha", "s/m"),
    "rtol": Term("Relative tolerance of the time integrator"),
    "spring": Term("How the stuck mindlin spring follows its stiffness"),
    # flight
    "launch-height": Term("Launch height of the ball's centre above the ground", "m"),
    "air-density": Term("Density of the air (0: the exact parabola)", "kg/m^3"),
    "max-bounces": Term("Most bounces to follow"),
    "t-stop": Term("Time at which to stop", "s"),
    "dt": Term("Integrator step (impacts are located within it)", "s"),
    "speed-sd": Term("With --samples: standard deviation of the speed, in --speed-unit"),
    "elevation-sd-deg": Term("With --samples: standard deviation of the elevation", _DEG),
    "heading-sd-deg": Term("With --samples: standard deviation of the heading", _DEG),
    "spin-sd-rpm": Term("With --samples: standard deviation of the spin rate", "rpm"),
    "wall-distance": Term(
        "Distance of a vertical wall from the origin along --wall-heading-deg", "m"
    ),
    "wall-heading-deg": Term(
        "With --wall-distance: the heading the wall faces back along, measured as --heading-deg",
        _DEG,
    ),
    "wall-mu": Term("With --wall-distance: the wall's friction coefficient"),
    "wall-kappa": Term("With --wall-distance: the wall's restitution coefficient"),
    "animate": Term("Animation file to write (.gif; .mp4 with ffmpeg)"),
    "fps": Term("Frames per second of --animate"),
    # many impacts
    "samples": Term("Number of random samples"),
    "seed": Term("Seed of the random samples"),
    "batch": Term("Solve every row of this CSV or Parquet file instead"),
    "problem": Term("The problem"),
    "set": Term("An input of the problem, as INPUT=VALUE"),
    "fields": Term("Result columns to write"),
    "on-error": Term(
        "stop: the first bad row ends the run and nothing is written; skip: bad rows are "
        "written with an 'error' column"
    ),
    "chunk-size": Term("Rows per chunk"),
    "histogram": Term("Histogram FIELD:LOW:HIGH:BINS, accumulated on the fly"),
    "dask": Term("Solve the chunks on the Dask scheduler at ADDRESS ([dask] extra)"),
    "host": Term("Network interface the explorer listens on (127.0.0.1: this computer only)"),
    "port": Term("TCP port of the explorer (0: any free port)"),
    "open": Term("Open the explorer's page in the default web browser"),
    "dry-run": Term("Print the estimate and stop"),
    "force": Term("Run even what is estimated to take over an hour"),
    "planar": Term("Sweep a planar body of this kind instead"),
    "sphere": Term("Sweep a sphere in 3D of this preset instead"),
    # fitting
    "restitution": Term("Restitution model of a fit"),
    "fix": Term("Hold a parameter at a value"),
    "confidence": Term("Level of the confidence intervals"),
    "drops": Term("The file holds drop tests"),
    "corner": Term("Image file of the corner plot of the parameters (.png, .svg, .pdf)"),
    # camera tracks
    "up": Term("The track file's vertical axis"),
    "sigma": Term("Noise of each measured coordinate", "m"),
    "predict": Term("Predict each track's bounce and outgoing flight from its incoming samples"),
    "free-lift": Term("Fit the ball's lift slope too (shared by every track)"),
    # outputs
    "output": Term("Output file"),
    "output-dir": Term("Output directory (created if missing)"),
    "format": Term("Image format"),
    "json": Term("Print as JSON"),
    "json-file": Term("Write every result field as JSON to this file"),
    "plot": Term("Image file of the figure (.png, .svg, .pdf)"),
    "laws-plot": Term("Image file of the three restitution laws side by side"),
    "map-plot": Term(
        "Image file of the map of regimes over the body's orientation and the slip ratio"
    ),
    "html": Term("Write the report as one self-contained HTML page"),
    "dpi": Term("Image resolution", "dots per inch"),
    "resolution": Term("Grid points per axis of a map"),
    "extent": Term("Half-span of the map's axes vx/|vy| and R*omega/|vy|"),
}


def concept(name: str) -> str:
    """The term of an option name: ``--mass1`` and ``--heading2-deg`` are ``mass`` and
    ``heading-deg`` (a ball's number is not part of the concept)."""
    return re.sub(r"(?<=[a-z])[12](?=-|$)", "", name.lstrip("-"))


def term(name: str) -> Term:
    """The :class:`Term` of option ``name`` (``"mass"``, ``"--mass1"``)."""
    return TERMS[concept(name)]


def help(name: str, extra: str = "") -> str:  # noqa: A001 - click's word
    """The help of option ``name``: its term's text, then the command's ``extra``."""
    text = term(name).text + "."
    return f"{text} {extra}" if extra else text


class Deprecated(click.Option):
    """A hidden old name of an option: it still works, and says once on stderr that it is
    deprecated and which option replaces it.

    With ``into`` (the new option's Python name) the value goes to the new option, which
    the command reads alone; typing both is an error. Without it the command reads the old
    option itself (a value in another unit, such as radians).
    """

    def __init__(self, decls: list[str], *, new: str, into: str | None = None,
                 **kw: Any) -> None:  # fmt: skip
        super().__init__(decls, hidden=True, expose_value=into is None, **kw)
        self.new, self.into = new, into

    def handle_parse_result(self, ctx: click.Context, opts: Any, args: list[str]) -> Any:
        typed = self.name in opts
        if typed:
            old = self.opts[0]
            if self.into is not None and self.into in opts:
                raise click.UsageError(f"give {self.new} or its old name {old}, not both")
            click.echo(f"spinimpact: {old} is deprecated; use {self.new}", err=True)
        value, args = super().handle_parse_result(ctx, opts, args)
        if typed and self.into is not None:
            ctx.params[self.into] = value
            ctx.set_parameter_source(self.into, click.core.ParameterSource.COMMANDLINE)
        return value, args


def deprecated(old: str, new: str, into: str | None = None, **kw: Any) -> Any:
    """A hidden option ``old`` (``"--rpm"``) replaced by ``new`` (``"--spin-rpm"``).

    Parameters
    ----------
    old, new : str
        The old and new option, as typed.
    into : str, optional
        The new option's Python name, to receive the value; ``None``: the command reads
        ``old``'s value under its own name.
    **kw
        ``type`` and the like, as the new option's.
    """
    dest = old.lstrip("-").replace("-", "_") + ("_deprecated" if into else "")
    return click.option(old, dest, cls=Deprecated, new=new, into=into, default=None, **kw)
