"""The explorer's settings: the page's inputs as text, checked and turned into one solver call.

A setting is a mapping of field names to the text a person typed (``{"problem": "sphere",
"speed": "20", "speed_unit": "km/h", ...}``): the same text lives in the page's address
(:func:`to_query`, :func:`from_query`), so a link reproduces the view. :func:`evaluate`
checks every field the way the library does (:func:`spinimpact._validation.scalar` with
the rules of ``mu``, ``kappa``, ``mass``, ...; the command line's conversions of a speed
with its unit, an angle and a spin in rpm about an axis, :mod:`spinimpact.cli.sphere`) and
calls the library's public solver (:func:`~spinimpact.solve`,
:func:`~spinimpact.solve_sphere`, :func:`~spinimpact.solve_planar`,
:func:`~spinimpact.solve_pendulum`). Nothing here computes physics; a bad field gives a
message keyed by the field's name, to be shown beside it.

Examples
--------
>>> found = evaluate({"problem": "paper", "speed": "5", "angle": "53.13010235415598",
...                   "spin": "95.49296585513721"})  # 3 m/s along, 4 m/s down, 10 rad/s
>>> found.errors
{}
>>> round(float(found.setting.result.after.vx), 5)
1.85714
>>> evaluate({"problem": "paper", "mu": "-1"}).errors["mu"]
'mu must be >= 0, got -1.0'
"""

from __future__ import annotations

import math
import shlex
from dataclasses import dataclass, field
from typing import Any
from urllib.parse import parse_qsl, urlencode

import numpy as np

from .._validation import scalar

__all__ = [
    "Field",
    "FIELDS",
    "PROBLEMS",
    "defaults",
    "relevant",
    "from_query",
    "to_query",
    "Setting",
    "Evaluation",
    "evaluate",
]

#: The problems the explorer shows: name -> a line for the menu.
PROBLEMS: dict[str, str] = {
    "paper": "the paper's bodies: a disk, ring, sphere or shell in plane motion",
    "sphere": "a ball in 3D on a surface",
    "pair": "two balls colliding on a table (ball 2 at rest)",
    "planar": "a rod or a block in plane motion",
    "pendulum": "a rod pendulum on a fixed pivot",
}
_BALLS = ("tennis", "table-tennis", "golf", "soccer")
_SURFACES = ("hard", "clay", "grass", "table", "green", "pitch")
_AXES = ("topspin", "backspin", "sidespin", "topspin+sidespin")


@dataclass(frozen=True)
class Field:
    """One input of the page.

    Attributes
    ----------
    name : str
        Key in the address and in a setting.
    label : str
        What the page calls it.
    unit : str
        Its unit as shown (``""``: none).
    default : str
        The text used when the address gives none (``""``: taken from a preset).
    problems : tuple of str
        The problems it belongs to.
    choices : tuple of str, optional
        For a menu: the values allowed.
    """

    name: str
    label: str
    unit: str
    default: str
    problems: tuple[str, ...]
    choices: tuple[str, ...] | None = None


_ALL = tuple(PROBLEMS)
_MOVING = ("paper", "sphere", "planar")
_BALL = ("sphere", "pair")
FIELDS: dict[str, Field] = {
    f.name: f
    for f in (
        Field("problem", "problem", "", "paper", _ALL, tuple(PROBLEMS)),
        Field("ball", "ball", "", "tennis", _BALL, ("custom", *_BALLS)),
        Field("surface", "surface", "", "hard", ("sphere",), ("custom", *_SURFACES)),
        Field(
            "body",
            "body",
            "",
            "solid-sphere",
            ("paper", *_BALL),
            ("solid-sphere", "solid-disk", "ring", "spherical-shell"),
        ),
        Field("shape", "body", "", "rod", ("planar",), ("rod", "block")),
        Field("mass", "mass m", "kg", "1", _ALL),
        Field("radius", "radius R", "m", "0.1", ("paper", *_BALL)),
        Field("length", "length L", "m", "1", ("planar", "pendulum")),
        Field("width", "width", "m", "0.2", ("planar",)),
        Field("height", "height", "m", "0.1", ("planar",)),
        Field("orientation", "orientation from the surface", "deg", "45", ("planar", "pendulum")),
        Field("speed", "speed", "", "5", (*_MOVING, "pair")),
        Field("speed_unit", "speed unit", "", "m/s", (*_MOVING, "pair"), ("m/s", "km/h", "mph")),
        Field("angle", "incidence from the surface", "deg", "45", _MOVING),
        Field("heading", "heading from +x", "deg", "0", _BALL),
        Field("spin", "spin", "rpm", "300", _ALL),
        Field("spin_axis", "spin axis (or x,y,z)", "", "backspin", _BALL),
        Field("normal", "normal from ball 2 to ball 1 (x,y,z)", "", "-1,0,0.5", ("pair",)),
        Field("mu", "friction mu", "", "", _ALL),
        Field("kappa", "restitution kappa", "", "", _ALL),
        Field(
            "law",
            "restitution law",
            "",
            "poisson",
            ("planar", "pendulum"),
            ("poisson", "newton", "energetic"),
        ),
        Field(
            "tangential",
            "tangential law",
            "",
            "rigid",
            ("paper", "sphere"),
            ("rigid", "walton", "stronge", "mindlin-deresiewicz"),
        ),
        Field("beta0", "Walton's beta0", "", "0.4", ("paper", "sphere")),
        Field("poisson_ratio", "Poisson's ratio nu", "", "0.3", ("paper", "sphere")),
    )
}
#: Defaults that differ by problem (a pendulum must turn toward the surface: omega < 0).
_PROBLEM_DEFAULTS = {"pendulum": {"spin": "-20"}}


def defaults(problem: str = "paper") -> dict[str, str]:
    """Every field's default text for ``problem``."""
    out = {name: f.default for name, f in FIELDS.items()}
    out.update(_PROBLEM_DEFAULTS.get(problem, {}), problem=problem)
    return out


def relevant(values: dict[str, str]) -> tuple[str, ...]:
    """The fields that apply to ``values`` (its problem, preset and laws), in page order."""
    kind = values.get("problem", "paper")
    out = [n for n, f in FIELDS.items() if kind in f.problems]
    drop = set()
    if kind in _BALL and values.get("ball", "tennis") != "custom":
        drop |= {"body", "mass", "radius"}
    if kind == "planar":
        drop |= {"length"} if values.get("shape") == "block" else {"width", "height"}
    law = values.get("tangential", "rigid")
    if law != "walton":
        drop.add("beta0")
    if law not in ("stronge", "mindlin-deresiewicz"):
        drop.add("poisson_ratio")
    return tuple(n for n in out if n not in drop)


def from_query(query: str) -> dict[str, str]:
    """The setting an address's query string (``?problem=sphere&speed=20``) describes: its
    problem's defaults, then the fields the query gives (unknown keys are ignored)."""
    given = dict(parse_qsl(query.lstrip("?"), keep_blank_values=True))
    kind = given.get("problem", "paper")
    out = defaults(kind if kind in PROBLEMS else "paper")
    out.update({k: v for k, v in given.items() if k in FIELDS})
    return out


def to_query(values: dict[str, str]) -> str:
    """The query string (with its ``?``) of the fields that apply to ``values``."""
    return "?" + urlencode({n: values.get(n, FIELDS[n].default) for n in relevant(values)})


@dataclass(frozen=True)
class Setting:
    """One checked setting and its solution.

    Attributes
    ----------
    problem : str
        A key of :data:`PROBLEMS`.
    values : dict
        The text of the fields that apply.
    inputs : dict
        What the solver was given, in SI units (the velocity in m/s, the spin in rad/s,
        angles of bodies in rad), as plain floats and strings.
    body : Body, PlanarBody or Pendulum
    result : Result
        The solver's result (one impact).
    law : TangentialLaw or None
    command : str
        The command line that computes the same impact (``spinimpact ... --json``).
    ball, ground : str or None
        The ball and surface presets of a ball in 3D (``None``: custom).
    """

    problem: str
    values: dict[str, str]
    inputs: dict[str, Any]
    body: Any
    result: Any
    law: Any
    command: str
    ball: str | None = None
    ground: str | None = None


@dataclass
class Evaluation:
    """What :func:`evaluate` found: a setting, or messages keyed by field name."""

    setting: Setting | None = None
    errors: dict[str, str] = field(default_factory=dict)


_RULES = {
    "mass": "mass",
    "radius": "radius",
    "length": "radius",
    "width": "radius",
    "height": "radius",
    "mu": "mu",
    "kappa": "kappa",
}
#: Which field a message of the command line's converters is about, by the option it names.
_OPTIONS = {
    "--speed": "speed",
    "--incidence-from-surface-deg": "angle",
    "--heading": "heading",
    "--spin-rpm": "spin",
    "--spin-axis": "spin_axis",
    "--orientation-deg": "orientation",
    "--beta0": "beta0",
    "beta0": "beta0",
    "poisson_ratio": "poisson_ratio",
    "--normal": "normal",
    "normal": "normal",
    "length": "length",
    "width": "width",
    "height": "height",
    "mass": "mass",
    "radius": "radius",
    "angle": "orientation",
}


def _field_of(message: str, default: str) -> str:
    for option, name in _OPTIONS.items():
        if message.startswith(option):
            return name
    return default


def _numbers(values: dict[str, str], names: tuple[str, ...], errors: dict[str, str]) -> dict:
    out: dict[str, float | None] = {}
    for name in names:
        f = FIELDS[name]
        if f.choices is not None:
            if values[name] not in f.choices:
                errors[name] = f"{name} must be one of {', '.join(f.choices)}, got {values[name]!r}"
            continue
        if name in ("spin_axis", "normal"):
            continue
        text = values[name].strip()
        if text == "" and name in ("mu", "kappa"):
            out[name] = None  # from the surface preset, or the library's default
            continue
        try:
            number = float(text)
        except ValueError:
            errors[name] = f"{name} must be a number, got {text!r}"
            continue
        try:
            out[name] = scalar(name, number, _RULES.get(name))
        except (TypeError, ValueError) as exc:
            errors[name] = str(exc)
    return out


def _fmt(x: float) -> str:
    return repr(float(x))


def evaluate(given: dict[str, str]) -> Evaluation:
    """Check a setting and solve it with the library's solver.

    Parameters
    ----------
    given : dict of str
        Field name -> text; fields left out take their defaults.

    Returns
    -------
    Evaluation
        ``setting`` (``None`` when something is wrong) and ``errors``: field name ->
        one-line message, the library's own words.
    """
    kind = given.get("problem", "paper")
    if kind not in PROBLEMS:
        return Evaluation(
            errors={"problem": f"problem must be one of {', '.join(PROBLEMS)}, got {kind!r}"}
        )
    values = defaults(kind) | {k: str(v) for k, v in given.items() if k in FIELDS}
    names = relevant(values)
    values = {n: values[n] for n in names}
    found = Evaluation()
    numbers = _numbers(values, names, found.errors)
    if found.errors:
        return found
    try:
        found.setting = _solve(kind, values, numbers)
    except Exception as exc:  # noqa: BLE001 - every refusal becomes a message on the page
        if not isinstance(exc, ValueError | TypeError) and type(exc).__name__ != "UsageError":
            raise
        message = str(getattr(exc, "message", None) or exc)
        found.errors[_field_of(message, _blame(kind, message))] = message
    return found


def _blame(kind: str, message: str) -> str:
    """The field a solver's refusal is about (an approach that fails: the spin or angle)."""
    words = message.split()
    head = words[0] if words else ""
    if head in FIELDS:
        return head
    return {"pendulum": "spin", "pair": "normal"}.get(kind, "angle")


def _law(values: dict[str, str], numbers: dict) -> Any:
    from ..cli._compliance import tangential_law

    kind = values.get("tangential", "rigid")
    return tangential_law(
        {
            "tangential": kind,
            "beta0": numbers.get("beta0") if kind == "walton" else None,
            "poisson_ratio": numbers.get("poisson_ratio"),
            "stiffness_ratio": None,
        }
    )


def _incidence(values: dict[str, str], numbers: dict) -> np.ndarray:
    from ..cli._common import SPEED_UNITS
    from ..cli.sphere import incidence

    speed = numbers["speed"] * SPEED_UNITS[values["speed_unit"]]
    return incidence(speed, numbers["angle"], numbers.get("heading", 0.0), (0.0, 1.0, 0.0))


def _tangential_options(values: dict[str, str]) -> list[str]:
    law = values.get("tangential", "rigid")
    if law == "walton":
        return ["--tangential", law, "--beta0", values["beta0"]]
    if law != "rigid":
        return ["--tangential", law, "--poisson-ratio", values["poisson_ratio"]]
    return []


def _surface(values: dict[str, str], numbers: dict, ground: str | None) -> tuple[float, float]:
    from ..model.presets import GROUNDS

    mu, kappa = numbers["mu"], numbers["kappa"]
    if ground is not None:
        mu = GROUNDS[ground].mu if mu is None else mu
        kappa = GROUNDS[ground].kappa if kappa is None else kappa
    return (0.2 if mu is None else mu), (0.8 if kappa is None else kappa)


def _normal(text: str) -> np.ndarray:
    """A direction typed as ``x,y,z`` (the command line's reading of ``--normal``)."""
    import click

    from ..cli.sphere import VECTOR

    try:
        return np.asarray(VECTOR.convert(text, None, None), dtype=float)
    except click.BadParameter as exc:
        raise click.UsageError(f"--normal: {exc.message}") from None


def _solve(kind: str, values: dict[str, str], n: dict) -> Setting:
    from .. import solve, solve_pair, solve_pendulum, solve_planar, solve_sphere
    from ..cli._common import SPEED_UNITS, make_body
    from ..cli.planar import make_planar_body
    from ..cli.sphere import incidence, spin_vector
    from ..model.presets import BALLS

    rad_s = n["spin"] * 2.0 * math.pi / 60.0
    cmd = ["spinimpact"]
    if kind in ("paper", "sphere"):
        law = _law(values, n)
        ball = values.get("ball") if kind == "sphere" and values.get("ball") != "custom" else None
        ground = values.get("surface") if kind == "sphere" else None
        ground = None if ground == "custom" else ground
        body: Any = (
            BALLS[ball].body if ball else make_body(values["body"], n["mass"], n["radius"], None)
        )
        mu, kappa = _surface(values, n, ground)
        velocity = _incidence(values, n)
        if kind == "paper":
            result = solve(
                body,
                float(velocity[0]),
                float(velocity[1]),
                rad_s,
                mu=mu,
                kappa=kappa,
                tangential=law,
            )
            inputs = {"vx": float(velocity[0]), "vy": float(velocity[1]), "omega": rad_s}
            cmd += [
                "solve",
                "--body",
                values["body"],
                "--mass",
                values["mass"],
                "--radius",
                values["radius"],
                "--vx",
                _fmt(velocity[0]),
                "--vy",
                _fmt(velocity[1]),
                "--omega",
                _fmt(rad_s),
            ]
        else:
            spin = np.asarray(spin_vector(n["spin"], values["spin_axis"], (0, 1, 0), velocity))
            result = solve_sphere(body, velocity, spin, mu=mu, kappa=kappa, tangential=law)
            inputs = dict(zip(("vx", "vy", "vz"), map(float, velocity), strict=True))
            inputs |= dict(zip(("wx", "wy", "wz"), map(float, spin), strict=True))
            cmd += ["sphere"] + (
                ["--ball", ball]
                if ball
                else [
                    "--body",
                    values["body"],
                    "--mass",
                    values["mass"],
                    "--radius",
                    values["radius"],
                ]
            )
            cmd += (["--surface", ground] if ground else []) + [
                "--speed",
                values["speed"],
                "--speed-unit",
                values["speed_unit"],
                "--incidence-from-surface-deg",
                values["angle"],
                "--heading-deg",
                values["heading"],
                "--spin-rpm",
                values["spin"],
                "--spin-axis",
                values["spin_axis"],
            ]
        inputs |= {
            "mass": float(body.mass),
            "radius": float(body.radius),
            "gyration": float(body.gyration),
            "mu": mu,
            "kappa": kappa,
        }
        if ground is None or values["mu"].strip():
            cmd += ["--mu", _fmt(mu)]
        if ground is None or values["kappa"].strip():
            cmd += ["--kappa", _fmt(kappa)]
        cmd += _tangential_options(values)
    elif kind == "pair":
        law, ground = None, None
        ball = values["ball"] if values["ball"] != "custom" else None
        body = BALLS[ball].body if ball else make_body(values["body"], n["mass"], n["radius"], None)
        mu, kappa = _surface(values, n, None)
        normal = _normal(values["normal"])
        up = (0.0, 1.0, 0.0)
        speed = n["speed"] * SPEED_UNITS[values["speed_unit"]]
        velocity = incidence(speed, 0.0, n["heading"], up)  # along the table
        spin = np.asarray(spin_vector(n["spin"], values["spin_axis"], up, velocity))
        rest = np.zeros(3)
        result = solve_pair(body, body, velocity1=velocity, spin1=spin, velocity2=rest,
                            spin2=rest, mu=mu, kappa=kappa, normal=normal)  # fmt: skip
        inputs = dict(zip(("vx", "vy", "vz"), map(float, velocity), strict=True))
        inputs |= dict(zip(("wx", "wy", "wz"), map(float, spin), strict=True))
        inputs |= {f"{k}2": 0.0 for k in ("vx", "vy", "vz", "wx", "wy", "wz")}
        inputs |= dict(zip(("normal_x", "normal_y", "normal_z"), map(float, normal), strict=True))
        inputs |= {"mu": mu, "kappa": kappa}
        for k in ("", "2"):
            inputs |= {f"mass{k}": float(body.mass), f"radius{k}": float(body.radius),
                       f"gyration{k}": float(body.gyration)}  # fmt: skip
        sizes = ("body", "mass", "radius")
        pick = (
            ["--ball1", ball, "--ball2", ball]
            if ball
            else [x for k in "12" for o in sizes for x in (f"--{o}{k}", values[o])]
        )
        cmd += ["pair", *pick, "--speed1", values["speed"], "--speed-unit",
                values["speed_unit"], "--heading1-deg", values["heading"], "--spin1-rpm",
                values["spin"], "--spin1-axis", values["spin_axis"], "--velocity2", "0,0,0",
                "--spin2", "0,0,0", "--normal", ",".join(_fmt(x) for x in normal),
                "--mu", _fmt(mu), "--kappa", _fmt(kappa)]  # fmt: skip
    else:
        law = None
        ball = ground = None
        mu, kappa = _surface(values, n, None)
        shape = values["shape"] if kind == "planar" else "pendulum"
        geometry = {k: n[k] for k in ("length", "width", "height") if k in n}
        body = make_planar_body(shape, n["mass"], geometry | {"angle_deg": n["orientation"]})
        inputs = {"mass": float(body.mass), "inertia": float(body.inertia)}
        cmd += ["planar", "--body", shape, "--mass", values["mass"]]
        cmd += [x for k in geometry for x in (f"--{k}", values[k])]
        cmd += ["--orientation-deg", values["orientation"]]
        if kind == "planar":
            velocity = _incidence(values, n)
            result = solve_planar(
                body,
                float(velocity[0]),
                float(velocity[1]),
                rad_s,
                mu=mu,
                kappa=kappa,
                law=values["law"],
            )
            inputs |= {
                "rx": float(body.rx),
                "ry": float(body.ry),
                "vx": float(velocity[0]),
                "vy": float(velocity[1]),
            }
            cmd += ["--vx", _fmt(velocity[0]), "--vy", _fmt(velocity[1])]
        else:
            result = solve_pendulum(body, rad_s, mu=mu, kappa=kappa, law=values["law"])
            inputs |= {k: float(getattr(body, k)) for k in ("gx", "gy", "px", "py")}
        inputs |= {"omega": rad_s, "mu": mu, "kappa": kappa, "law": values["law"]}
        cmd += [
            "--omega",
            _fmt(rad_s),
            "--mu",
            _fmt(mu),
            "--kappa",
            _fmt(kappa),
            "--law",
            values["law"],
        ]
    if law is not None:
        inputs["tangential"] = repr(law)
    return Setting(
        kind, values, inputs, body, result, law, shlex.join([*cmd, "--json"]), ball, ground
    )
