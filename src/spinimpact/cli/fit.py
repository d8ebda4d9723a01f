"""``spinimpact fit bounces.csv``: fit friction and restitution to measured bounces, or
``kappa(|v|)`` to drop tests (``--drops``), and print the estimates with their intervals."""

from __future__ import annotations

import json
import warnings
from dataclasses import replace
from pathlib import Path
from typing import Any

import click
import numpy as np

from .._long import TooLong
from ..model.body import PRESETS, Body
from ..model.fit_models import TANGENTIAL
from ..model.presets import BALLS
from ._common import announce, image_format, jsonable
from ._measured import read_columns, read_table, row_error
from ._vocabulary import deprecated
from ._vocabulary import help as _help

__all__ = ["fit_command", "read_columns", "read_table", "DROP_COLUMNS"]

#: Columns of a drop-test file: heights (m) or speeds (m/s), with optional sigmas.
DROP_COLUMNS = {
    "heights": ("drop_height", "rebound_height"),
    "speeds": ("impact_speed", "rebound_speed"),
}


def _knots(text: str) -> str | list[float]:
    if text in ("constant", "power"):
        return text
    try:
        return [float(x) for x in text.split(",")]
    except ValueError:
        raise click.BadParameter(
            f"{text!r}: give constant, power, or knot speeds in m/s such as 1,2,4",
            param_hint="--restitution",
        ) from None


def _fixed(items: tuple[str, ...]) -> dict[str, float]:
    out = {}
    for item in items:
        name, sep, value = item.partition("=")
        try:
            out[name.strip()] = float(value)
        except ValueError:
            sep = ""
        if not sep:
            raise click.BadParameter(f"{item!r}: write NAME=VALUE, e.g. kappa=0.98",
                                     param_hint="--fix")  # fmt: skip
    return out


def _drops(columns: dict[str, np.ndarray], o: dict[str, Any], path: str, lines: np.ndarray) -> Any:
    from ..model.fit_drops import fit_drops

    for kind, (before, after) in DROP_COLUMNS.items():
        if before in columns and after in columns:
            allowed = {before, after, f"sigma_{before}", f"sigma_{after}"}
            unknown = sorted(set(columns) - allowed)
            if unknown:
                raise ValueError(f"unknown column(s) for drop tests: {', '.join(unknown)}; "
                                 f"the columns are {', '.join(sorted(allowed))}")  # fmt: skip
            for name in columns:
                bad = np.flatnonzero(np.isnan(columns[name]))
                if bad.size:
                    raise ValueError(f"{path}: row {int(lines[bad[0]])}: column {name} is empty")
            sb, sa = columns.get(f"sigma_{before}"), columns.get(f"sigma_{after}")
            return fit_drops(columns[before], columns[after], heights=kind == "heights",
                             sigma_before=sb, sigma_after=sa, restitution=o["restitution"],
                             confidence=o["confidence"])  # fmt: skip
    names = " or ".join(" and ".join(c) for c in DROP_COLUMNS.values())
    raise ValueError(f"missing columns: a drop-test file needs {names}")


def _print(res: Any) -> None:
    from rich.console import Console
    from rich.table import Table
    from rich.text import Text

    console = Console()
    level = f"{100 * res.confidence:g} %"
    table = Table(title=Text(f"fit: {res.model}"), title_justify="left")
    for col in ("parameter", "estimate", "std. error", f"{level} interval (profile likelihood)"):
        table.add_column(col, justify="left" if col == "parameter" else "right")
    for name in res.names:
        e = res[name]
        ival = f">= {e.low:.5g} (one-sided)" if e.one_sided else f"[{e.low:.5g}, {e.high:.5g}]"
        table.add_row(Text(name), f"{e.estimate:.5g}", f"{e.standard_error:.3g}", ival)
    for name, value in res.fixed.items():
        table.add_row(Text(name), f"{value:.5g}", "fixed", "")
    console.print(table)
    if res.body is not None:  # drop tests have none: there the body plays no part
        b = res.body
        about = f"body: {b['name']}, "
        if b["radius"] is None:
            about += f"zeta = {b['zeta']:.4g} (its radius plays no part without spin)"
        else:
            about += f"R = {b['radius']:.4g} m, rho = {b['gyration']:.4g} m, zeta = {b['zeta']:.4g}"
        console.print(Text(about))
    sig = "sigmas given" if res.sigma_given else f"one sigma estimated: {res.scale:.3g} m/s"
    from ..model.fit_drops import DropFit

    what = "drops" if isinstance(res, DropFit) else "bounces"
    console.print(Text(f"{res.n_bounces} {what}, {res.n_observations} measured values, "
                       f"{res.dof} degrees of freedom ({sig})"))  # fmt: skip
    if res.sigma_given:
        note = ""
        if res.p_value < 1e-3:
            note = ": the model does not explain the data within the given sigmas"
        console.print(Text(f"chi2 = {res.chi2:.4g}, reduced chi2 = {res.reduced_chi2:.4g}, "
                           f"p = {res.p_value:.3g}{note}"))  # fmt: skip
    else:
        console.print(Text("goodness of fit: not testable without sigmas"))
    console.print(Text(f"AIC = {res.aic:.5g}, BIC = {res.bic:.5g}"))
    if res.n_sliding or res.n_sticking:
        console.print(Text(f"friction: {res.identifiability}"))
    names = res.names
    loose = [n for n, e in zip(names, res.standard_error, strict=True) if not np.isfinite(e)]
    if loose:
        why = "infinite standard error; the intervals show what the data allow"
        console.print(Text(f"not determined locally by these data: {', '.join(loose)} ({why})"))
    for i in range(len(names)):
        for j in range(i):
            r = float(res.correlation[i, j])
            if abs(r) > 0.9:  # the data constrain a combination more than either alone
                console.print(Text(f"strongly correlated: {names[j]} and {names[i]} "
                                   f"(r = {r:.3f})"))  # fmt: skip


@click.command("fit")
@click.argument("bounces", type=click.Path(dir_okay=False))
@click.option("--tangential", "model", type=click.Choice(TANGENTIAL), default="rigid",
              show_default=True, help=_help("tangential", "The model fitted."))  # fmt: skip
@deprecated("--model", "--tangential", "model", type=click.Choice(TANGENTIAL))
@click.option("--restitution", default="constant", show_default=True,
              help=_help("restitution", "kappa: constant, power (kappa_ref "
                   "(|vy|/v_ref)^exponent), or knot speeds in m/s (e.g. 1,2,4) between which "
                   "kappa is interpolated."))  # fmt: skip
@click.option("--fix", multiple=True, metavar="NAME=VALUE",
              help=_help("fix", "E.g. --fix kappa=0.98 (repeatable)."))  # fmt: skip
@click.option("--free-gyration", is_flag=True, help=_help("free-gyration"))
@click.option("--ball", type=click.Choice(list(BALLS)), default=None,
              help=_help("ball", "Gives the radius and gyration: no --radius."))  # fmt: skip
@click.option("--body", type=click.Choice(list(PRESETS)), default=None,
              help=_help("body", "With --radius, which may be left out when no spin "
                               "is given or measured."))  # fmt: skip
@click.option("--radius", type=float, default=None,
              help=_help("radius", "Needed whenever spin is measured or given."))  # fmt: skip
@click.option("--gyration", type=float, default=None, help=_help("gyration", "A custom body."))
@click.option("--confidence", type=float, default=0.95, show_default=True,
              help=_help("confidence"))  # fmt: skip
@click.option("--drops", is_flag=True,
              help=_help("drops", "drop_height,rebound_height (m) or "
                   "impact_speed,rebound_speed (m/s), optional sigma_<column>."))  # fmt: skip
@click.option("--plot", default=None, help=_help("plot", "Measured against fitted, and residuals."))
@click.option("--corner", default=None, help=_help("corner"))
@click.option("--json-file", "json_path", default=None, help=_help("json-file"))
@deprecated("--json", "--json-file", "json_path")
@click.option("--dpi", type=click.IntRange(20, 1200), default=100, show_default=True,
              help=_help("dpi"))  # fmt: skip
@click.option("--problem", default=None, metavar="NAME",
              help="The problem. Fit any registered one (spinimpact problems lists them): "
                   "the file holds its inputs per bounce and measured result columns, "
                   "optional sigma_<column>.")  # fmt: skip
@click.option("--force", is_flag=True, help=_help("force"))
def fit_command(bounces: str, **o: Any) -> None:
    """Fit friction and restitution to measured bounces in a CSV file.

    \b
    Columns (SI units; an empty cell is a value not measured):
      vx, vy, omega                 incidence (m/s, m/s < 0, rad/s), required
      after_vx, after_vy, after_omega   measured rebound, at least one
      sigma_after_vx, sigma_after_vy, sigma_after_omega   standard deviations
                                    (all three or none; none: one sigma estimated)
    The body is required (no shape is assumed: it decides how a bounce changes the
    spin): --ball, --body with --radius, or --radius with --gyration. Estimates by
    weighted least squares; intervals from the profile likelihood.
    """
    for option in ("plot", "corner"):
        if o[option] is not None:
            image_format(o[option], f"--{option}")
    if not Path(bounces).is_file():
        raise click.BadParameter(f"{bounces!r} is not a file", param_hint="BOUNCES")
    if o["problem"] is not None:
        return _fit_problem_file(bounces, o)
    if not o["drops"]:  # drops without spin need no body
        _one_body(o)
    restitution = _knots(o["restitution"])
    o["restitution"] = restitution
    fixed = _fixed(o["fix"])
    columns, lines = read_table(bounces)
    from ..model.fit_result import FitWarning

    with warnings.catch_warnings():
        warnings.simplefilter("error", FitWarning)  # a fit that does not converge: an error
        try:
            res = _drops(columns, o, bounces, lines) if o["drops"] else _bounces(columns, o, fixed)
        except FitWarning as exc:
            raise RuntimeError(str(exc)) from None
        except TooLong as exc:  # the rule of every long run: one line naming --force
            raise click.ClickException(exc.estimate.refusal("--force")) from None
        except ValueError as exc:  # name a bad row by its line in the file
            raise row_error(bounces, lines, exc) from None
    if o["corner"] is not None and len(res.names) < 2:
        raise ValueError(f"--corner needs at least two fitted parameters, got {len(res.names)}")
    _print(res)
    _write(res, o)


def _bounces(columns: dict[str, np.ndarray], o: dict[str, Any], fixed: dict[str, float]) -> Any:
    from ..model.fit import fit
    from ..model.fit_data import MeasuredBounces

    data = MeasuredBounces.from_columns(columns)
    spin = np.any(data.omega != 0) or np.any(data.measured[:, 2])
    sized = o["ball"] is not None or o["radius"] is not None
    if not sized and spin:
        raise click.UsageError("--radius is needed: the file gives or measures spin")
    if o["ball"] is not None:
        body = BALLS[o["ball"]].body
    elif o["gyration"] is not None:
        body = Body(mass=1.0, radius=o["radius"], gyration=o["gyration"])
    else:  # the mass plays no part, nor the radius without spin
        body = Body.preset(o["body"], mass=1.0, radius=o["radius"] if sized else 1.0)
    res = fit(data, body, model=o["model"], restitution=o["restitution"], fixed=fixed or None,
              free_gyration=o["free_gyration"], confidence=o["confidence"], force=o["force"],
              announce=announce)  # fmt: skip
    if not sized:  # say so, rather than record a radius nobody gave
        res = replace(res, body={**res.body, "radius": None, "gyration": None})
    return res


def _one_body(o: dict[str, Any]) -> None:
    """Exactly one of ``--ball``, ``--body``, ``--gyration``, with ``--radius`` where it
    needs one: no body is assumed."""
    given = [f"--{k}" for k in ("ball", "body", "gyration") if o[k] is not None]
    if not given:
        raise click.UsageError(
            "a body is needed (its shape decides how a bounce changes the spin): give --ball "
            f"({', '.join(BALLS)}), --body ({', '.join(PRESETS)}) with --radius, or "
            "--radius with --gyration for another body"
        )
    if len(given) > 1:
        raise click.UsageError(f"give one of --ball, --body, --gyration, not {' and '.join(given)}")
    if o["ball"] is not None and o["radius"] is not None:
        raise click.UsageError("--ball gives the radius: leave out --radius, or give --body or "
                               "--gyration with it")  # fmt: skip
    if o["gyration"] is not None and o["radius"] is None:
        raise click.UsageError("--gyration needs --radius: zeta = 1 + R^2/rho^2 depends on both")


def _write(res: Any, o: dict[str, Any]) -> None:
    from ..io import atomic_path

    if o["json_path"] is not None:
        with atomic_path(o["json_path"]) as tmp:
            tmp.write_text(json.dumps(jsonable(res.to_dict()), indent=2), encoding="utf-8")
    for option in ("plot", "corner"):
        path = o[option]
        if path is None:
            continue
        from ..viz.fit import plot_corner, plot_fit

        fig = plot_fit(res) if option == "plot" else plot_corner(res)
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=image_format(path, f"--{option}"), dpi=o["dpi"])
    for path in (o["json_path"], o["plot"], o["corner"]):
        if path is not None:
            click.echo(f"wrote {path}")


# -- spinimpact fit --problem NAME FILE: any registered problem ---------------------------------
def _fit_problem_file(path: str, o: dict[str, Any]) -> None:
    """``spinimpact fit --problem NAME FILE``: :func:`spinimpact.fit_problem` on the file's
    columns; the body from --ball, --body, --radius, --gyration or --fix; prints the estimates,
    the body and the law; --json-file writes every field."""
    from ..model.fit_problem import default_free, fit_problem
    from ..model.fit_result import FitWarning
    from ..model.registry import problem

    try:
        declared = problem(o["problem"])
    except ValueError as exc:
        raise click.BadParameter(str(exc), param_hint="--problem") from None
    for option, default in (("restitution", "constant"), ("drops", False), ("plot", None)):
        if o[option] != default:
            raise click.UsageError(f"--{option} does not apply with --problem")
    fixed: dict[str, Any] = {}
    for item in o["fix"]:
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise click.BadParameter(f"{item!r}: write NAME=VALUE, e.g. kappa=0.98",
                                     param_hint="--fix")  # fmt: skip
        try:
            fixed[name.strip()] = float(value)
        except ValueError:
            fixed[name.strip()] = value.strip()  # a preset's name (body=spherical-shell)
    for option in ("body", "radius", "gyration"):
        if o[option] is not None:
            if option in fixed:
                raise click.UsageError(f"give --{option} or --fix {option}=..., not both")
            fixed[option] = o[option]
    body = None
    if o.get("ball") is not None:  # a ball preset: mass, radius and gyration
        from ..model.presets import BALLS as balls

        body = balls[o["ball"]]
    columns, lines = read_table(path)
    free = None
    if o["free_gyration"]:  # the default free parameters and the gyration
        law = None if o["model"] == "rigid" else o["model"]
        free = [*default_free(declared, columns, fixed, law), "gyration"]
    with warnings.catch_warnings():
        warnings.simplefilter("error", FitWarning)  # a fit that does not converge: an error
        try:
            res = fit_problem(declared, columns, free=free, fixed=fixed, body=body,
                              tangential=None if o["model"] == "rigid" else o["model"],
                              confidence=o["confidence"], force=o["force"],
                              announce=announce)  # fmt: skip
        except TooLong as exc:  # the rule of every long run: one line naming --force
            raise click.ClickException(exc.estimate.refusal("--force")) from None
        except (FitWarning, ValueError) as exc:  # name a bad row by its line in the file
            bad = isinstance(exc, FitWarning)
            raise RuntimeError(str(exc)) if bad else row_error(path, lines, exc) from None
    if o["corner"] is not None and len(res.names) < 2:
        raise click.UsageError(f"--corner needs at least two fitted parameters, got "
                               f"{len(res.names)}")  # fmt: skip
    from dataclasses import replace

    from rich.console import Console
    from rich.text import Text

    numeric = {k: v for k, v in res.fixed.items() if not isinstance(v, str)}
    _print(replace(res, body=None, fixed=numeric))  # the body in its own words below

    body = ", ".join(f"{k} = {v} ({res.body['source'][k]})" for k, v in res.body.items()
                     if k not in ("name", "source"))  # fmt: skip
    law = "rigid" if res.law is None else ", ".join(f"{k} = {v}" for k, v in res.law.items())
    Console().print(Text(f"body: {res.body['name']}" + (f"; {body}" if body else "")))
    Console().print(Text(f"law: {law}"))
    _write(res, o)
