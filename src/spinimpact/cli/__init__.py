"""Command line: ``spinimpact solve`` prints the complete impact report.

Errors in the input are reported as one line on stderr with exit status 2 and
no traceback.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path
from typing import Any

import click
import numpy as np

from ..model.body import PRESETS, Body
from ..model.impact import solve
from ..model.particle import solve_particle

__all__ = ["main", "cli"]

#: The documented default case (``spinimpact solve`` with no options): a 1 kg
#: solid sphere of radius 0.1 m, moving right at 3 m/s and down at 4 m/s with
#: 10 rad/s of backspin, on a surface with mu = 0.2 and kappa = 0.8. Its contact
#: sticks during restitution.
DEFAULTS: dict[str, Any] = {
    "body": "solid-sphere",
    "mass": 1.0,
    "radius": 0.1,
    "vx": 3.0,
    "vy": -4.0,
    "omega": 10.0,
    "mu": 0.2,
    "kappa": 0.8,
}


def _jsonable(value: Any) -> Any:
    """Non-finite floats become ``null`` so the output is strict JSON."""
    if isinstance(value, dict):
        return {k: _jsonable(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_jsonable(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def _body(body: str | None, mass: float, radius: float, gyration: float | None) -> Body:
    if gyration is not None:
        if body is not None:
            raise click.UsageError("give either --body or --gyration, not both")
        return Body(mass=mass, radius=radius, gyration=gyration)
    return Body.preset(body or DEFAULTS["body"], mass=mass, radius=radius)


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="spinimpact")
def cli() -> None:
    """Exact frictional impact of a spinning rigid body on a fixed rough surface.

    Conventions: SI units; x along the surface, y up; omega counter-clockwise
    positive; the contact-point slip is u = vx + R*omega.
    """


def _options(*decorators):
    """Bundle click options so several commands share them."""

    def wrap(function):
        for decorator in reversed(decorators):
            function = decorator(function)
        return function

    return wrap


def _default(name: str, help: str):
    """A float option whose default is the documented default case's."""
    return click.option(
        f"--{name}", type=float, default=DEFAULTS[name], show_default=True, help=help
    )


body_options = _options(
    click.option(
        "--body",
        type=click.Choice(list(PRESETS)),
        default=None,
        help=f"Body preset (default {DEFAULTS['body']}).",
    ),
    _default("mass", "Mass m, kg."),
    _default("radius", "Contact radius R, m."),
    click.option(
        "--gyration",
        type=float,
        default=None,
        help="Radius of gyration rho, m: a custom body instead of a preset (rho > R for a spool).",
    ),
)
surface_options = _options(
    _default("mu", "Friction >= 0."),
    _default("kappa", "Restitution in [0, 1]."),
)
incidence_options = _options(
    _default("vx", "Incidence vx, m/s."),
    _default("vy", "Incidence vy < 0, m/s."),
    _default("omega", "Incidence spin, rad/s, counter-clockwise positive."),
)


def _solve_options(o: dict[str, Any]):
    """The Impact described by the shared body, incidence and surface options."""
    body = _body(o["body"], o["mass"], o["radius"], o["gyration"])
    return solve(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], kappa=o["kappa"])


def _progress():
    """A Rich progress bar on stderr, shown only on a terminal."""
    from rich.console import Console
    from rich.progress import BarColumn, Progress, TaskProgressColumn, TimeRemainingColumn

    console = Console(stderr=True)
    return Progress(
        "[progress.description]{task.description}",
        BarColumn(),
        TaskProgressColumn(),
        TimeRemainingColumn(),
        console=console,
        disable=not console.is_terminal,
        transient=True,
    )


def _image_format(path: str) -> str:
    fmt = Path(path).suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise click.UsageError(f"--output must end in .png, .svg or .pdf, got {path!r}")
    return fmt


@cli.command("solve")
@body_options
@incidence_options
@surface_options
@click.option(
    "--json",
    "as_json",
    is_flag=True,
    help="Print every Impact field as JSON (infinite or undefined values are null).",
)
def solve_command(as_json: bool, **options: Any) -> None:
    """Solve one impact and print the report (regime, rebound, energy, works, mu_hat).

    With no options it solves the documented default case: a 1 kg solid sphere
    of radius 0.1 m at vx = 3 m/s, vy = -4 m/s with 10 rad/s of backspin, on a
    surface with mu = 0.2 and kappa = 0.8.
    """
    imp = _solve_options(options)
    if as_json:
        click.echo(json.dumps(_jsonable(imp.to_dict()), indent=2))
    else:
        from ..viz.report import print_report  # Rich is imported only when a report is printed

        o = options
        print_report(
            imp, solve_particle(o["vx"], o["vy"], mu=o["mu"], kappa=o["kappa"], mass=o["mass"])
        )


@cli.command("report")
@body_options
@incidence_options
@surface_options
@click.option("--output", default="impact.html", show_default=True, help="HTML file to write.")
def report_command(output: str, **options: Any) -> None:
    """Write one self-contained HTML page about an impact: inputs, regime, rebound,
    energy budget, works by phase, coefficients, outcome and figures."""
    from ..io import atomic_path
    from ..viz.html import impact_report_html

    if Path(output).suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(f"--output must end in .html, got {output!r}")
    o = options
    imp = _solve_options(o)
    page = impact_report_html(
        imp, solve_particle(o["vx"], o["vy"], mu=o["mu"], kappa=o["kappa"], mass=o["mass"])
    )
    with atomic_path(output) as tmp:
        tmp.write_text(page, encoding="utf-8")
    click.echo(output)


@cli.command("batch")
@click.argument("source", type=click.Path(dir_okay=False))
@click.option(
    "--output", required=True, help="Output file: .csv, or .parquet with the [parquet] extra."
)
@body_options
@surface_options
@click.option(
    "--on-error",
    type=click.Choice(["stop", "skip"]),
    default="stop",
    show_default=True,
    help="stop: the first bad row ends the run and nothing is written; "
    "skip: bad rows are written with an 'error' column.",
)
@click.option(
    "--chunk-size",
    type=click.IntRange(1),
    default=100_000,
    show_default=True,
    help="Rows per chunk.",
)
def batch_command(source: str, output: str, on_error: str, chunk_size: int, **options: Any) -> None:
    """Solve every row of SOURCE (CSV or Parquet): columns vx, vy, omega, and
    optionally mu, kappa, mass, radius, gyration, body per row (the options give
    the defaults). Writes the input columns plus every scalar Impact field."""
    from .._validation import validated
    from ..io.batch import run_batch

    o = options
    if o["gyration"] is not None and o["body"] is not None:
        raise click.UsageError("give either --body or --gyration, not both")
    defaults = {k: o[k] for k in ("mu", "kappa", "mass", "radius", "gyration")}
    for name, value in defaults.items():  # check the defaults before reading any row
        if value is not None:
            try:
                validated(name, value)
            except ValueError as exc:
                raise click.UsageError(f"--{exc}") from None
    defaults["body"] = None if o["gyration"] is not None else (o["body"] or DEFAULTS["body"])

    with _progress() as bar:
        task = bar.add_task(f"solving {Path(source).name}", total=None)
        summary = run_batch(
            source,
            output,
            defaults=defaults,
            on_error=on_error,
            chunk_size=chunk_size,
            progress=lambda done, total: bar.update(task, completed=done, total=total),
        )
    note = f" ({summary.skipped} with errors: see the 'error' column)" if summary.skipped else ""
    click.echo(f"wrote {summary.rows} rows to {summary.output}{note}")


@cli.command("simulate")
@body_options
@incidence_options
@click.option("--mu", type=float, default=DEFAULTS["mu"], show_default=True, help="Friction >= 0.")
@click.option(
    "--contact",
    type=click.Choice(["hertz", "hunt-crossley", "linear"]),
    default="hertz",
    show_default=True,
    help="Normal contact law.",
)
@click.option("--youngs-modulus", type=float, default=None, help="E, Pa (hertz; default 2e9).")
@click.option("--poisson-ratio", type=float, default=None, help="nu (hertz; default 0.35).")
@click.option(
    "--stiffness", type=float, default=None, help="k: N/m (linear) or N/m^n (hunt-crossley)."
)
@click.option("--damping", type=float, default=None, help="c, N s/m (linear; default 0).")
@click.option("--exponent", type=float, default=None, help="n (hunt-crossley; default 1.5).")
@click.option(
    "--alpha", type=float, default=None, help="Damping, s/m (hertz, hunt-crossley; default 0)."
)
@click.option(
    "--target-kappa",
    type=float,
    default=None,
    help="Calibrate the damping so the law gives this restitution at the impact speed.",
)
@click.option("--rtol", type=float, default=1e-10, show_default=True, help="Integrator tolerance.")
@click.option("--plot", "plot_file", default=None, help="Write N(t), F(t) and the velocities here.")
def simulate_command(plot_file: str | None, **o: Any) -> None:
    """Integrate one impact in time with a compliant contact law and compare it
    with the rigid-body closed form at the law's own restitution."""
    from ..dynamics import HertzContact, HuntCrossleyContact, LinearContact, simulate

    body = _body(o["body"], o["mass"], o["radius"], o["gyration"])
    speed, target = abs(o["vy"]), o["target_kappa"]
    default_k = {"linear": 1e6, "hunt-crossley": 1e8}
    allowed = {
        "hertz": {"youngs_modulus", "poisson_ratio", "alpha"},
        "linear": {"stiffness", "damping"},
        "hunt-crossley": {"stiffness", "exponent", "alpha"},
    }[o["contact"]]
    for name in ("youngs_modulus", "poisson_ratio", "stiffness", "damping", "exponent", "alpha"):
        flag = "--" + name.replace("_", "-")
        if o[name] is not None and name not in allowed:
            raise click.UsageError(f"{flag} does not apply to --contact {o['contact']}")
        if o[name] is not None and target is not None and name in ("damping", "alpha"):
            raise click.UsageError(f"give either {flag} or --target-kappa, not both")
    o["youngs_modulus"] = 2e9 if o["youngs_modulus"] is None else o["youngs_modulus"]
    o["poisson_ratio"] = 0.35 if o["poisson_ratio"] is None else o["poisson_ratio"]
    o["damping"] = o["damping"] or 0.0
    o["alpha"] = o["alpha"] or 0.0
    o["exponent"] = 1.5 if o["exponent"] is None else o["exponent"]
    if o["contact"] == "hertz":
        if o["stiffness"] is not None:
            raise click.UsageError(
                "--stiffness is for linear and hunt-crossley; hertz uses E and nu"
            )
        law = HertzContact(o["youngs_modulus"], o["poisson_ratio"], float(body.radius), o["alpha"])
        if target is not None:
            law = HuntCrossleyContact.calibrated(
                stiffness=law.stiffness, kappa=target, mass=o["mass"], speed=speed
            )
    elif o["contact"] == "linear":
        k = o["stiffness"] if o["stiffness"] is not None else default_k["linear"]
        law = (
            LinearContact.calibrated(stiffness=k, kappa=target, mass=o["mass"])
            if target is not None
            else LinearContact(k, o["damping"])
        )
    else:
        k = o["stiffness"] if o["stiffness"] is not None else default_k["hunt-crossley"]
        law = (
            HuntCrossleyContact.calibrated(
                stiffness=k, kappa=target, mass=o["mass"], speed=speed, exponent=o["exponent"]
            )
            if target is not None
            else HuntCrossleyContact(k, o["exponent"], o["alpha"])
        )
    sim = simulate(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], contact=law, rtol=o["rtol"])
    from ..viz.report import print_simulation

    print_simulation(sim)
    if plot_file:
        from ..io import atomic_path
        from ..viz.plots import plot_simulation

        fmt = _image_format(plot_file)
        with atomic_path(plot_file) as tmp:
            plot_simulation(sim).savefig(tmp, format=fmt, dpi=110)
        click.echo(f"wrote {plot_file}")


@cli.command("sweep")
@body_options
@click.option(
    "--vx",
    default="-5:5:201",
    show_default=True,
    help="Number, START:STOP:NUM or uniform:LOW:HIGH.",
)
@click.option("--vy", default="-4", show_default=True, help="As --vx; values < 0.")
@click.option("--omega", default="-50:50:201", show_default=True, help="As --vx, rad/s.")
@click.option("--mu", default=str(DEFAULTS["mu"]), show_default=True, help="As --vx.")
@click.option("--kappa", default=str(DEFAULTS["kappa"]), show_default=True, help="As --vx.")
@click.option(
    "--samples", type=click.IntRange(1), default=None, help="Random points (uniform axes)."
)
@click.option(
    "--seed",
    type=int,
    default=0,
    show_default=True,
    help="Seed of the random points (the points also depend on --chunk-size).",
)
@click.option("--chunk-size", type=click.IntRange(1), default=1_000_000, show_default=True)
@click.option(
    "--output",
    default=None,
    help="FILE.parquet ([parquet] extra) or a new directory of .npy files, one per column.",
)
@click.option(
    "--fields",
    default="after_vx,after_vy,after_omega,regime",
    show_default=True,
    help="Comma-separated fields to write (after_vx, after_vy, after_omega, regime, "
    "energy_loss, impulse_ratio, slip_after).",
)
@click.option("--histogram", default=None, help="FIELD:LOW:HIGH:BINS, accumulated on the fly.")
@click.option("--dask", "dask_address", default=None, help="Run the chunks on this Dask scheduler.")
def sweep_command(
    samples, seed, chunk_size, output, fields, histogram, dask_address, **o: Any
) -> None:
    """Sweep a grid or random samples of incidence conditions in bounded memory:
    regime fractions (always), a histogram, and/or the fields written to files."""
    from ..io.sweep import Sweep, parse_axis, run_sweep

    body = _body(o["body"], o["mass"], o["radius"], o["gyration"])
    axes = {name: parse_axis(name, o[name]) for name in ("vx", "vy", "omega", "mu", "kappa")}
    sweep = Sweep(body, axes, samples=samples, seed=seed, chunk_size=chunk_size)
    hist = None
    if histogram:
        parts = histogram.split(":")
        try:
            if len(parts) != 4:
                raise ValueError
            hist = (parts[0], float(parts[1]), float(parts[2]), int(parts[3]))
        except ValueError:
            raise click.UsageError(
                f"--histogram must be FIELD:LOW:HIGH:BINS, got {histogram!r}"
            ) from None
    client = None
    if dask_address:
        try:
            from distributed import Client
        except ImportError:
            raise click.UsageError(
                "--dask needs the optional extra: pip install 'spinimpact[dask]'"
            ) from None

        client = Client(dask_address, timeout=30)
    try:
        with _progress() as bar:
            task = bar.add_task(f"{sweep.size:,} points", total=sweep.chunks)
            result = run_sweep(
                sweep,
                histogram=hist,
                output=output,
                fields=tuple(f.strip() for f in fields.split(",") if f.strip()),
                client=client,
                progress=lambda done, total: bar.update(task, completed=done),
            )
    finally:
        if client is not None:
            client.close()
    click.echo(f"{result.points:,} points")
    for name, fraction in result.regime_fractions.items():
        click.echo(f"  {name:18s} {fraction:.6f}")
    if result.histogram is not None:
        click.echo(f"histogram of {hist[0]}:")
        for lo, hi, count in zip(
            result.bin_edges[:-1], result.bin_edges[1:], result.histogram, strict=True
        ):
            click.echo(f"  [{lo:.6g}, {hi:.6g})  {count}")
    if output:
        click.echo(f"wrote {output}")


@cli.command("map")
@body_options
@surface_options
@click.option(
    "--output", default="map.png", show_default=True, help="Image file (.png, .svg, .pdf)."
)
@click.option(
    "--extent",
    type=float,
    default=3.0,
    show_default=True,
    help="Axes span [-extent, extent] in vx/|vy| and R*omega/|vy|.",
)
@click.option(
    "--resolution",
    type=click.IntRange(2, 4000),
    default=600,
    show_default=True,
    help="Grid points per axis.",
)
@click.option("--dpi", type=click.IntRange(50, 600), default=110, show_default=True)
def map_command(output: str, extent: float, resolution: int, dpi: int, **options: Any) -> None:
    """Maps over the incidence at a fixed body, mu and kappa: regimes, rebound
    outcomes (backward, reversed spin, vertical), energy lost, mu_hat and the
    friction work ratio, with the regime boundaries drawn."""
    from ..io import atomic_path
    from ..viz.plots import plot_map

    fmt = _image_format(output)
    o = options
    body = _body(o["body"], o["mass"], o["radius"], o["gyration"])
    fig = plot_map(body, mu=o["mu"], kappa=o["kappa"], extent=extent, n=resolution)
    with atomic_path(output) as tmp:
        fig.savefig(tmp, format=fmt, dpi=dpi)
    click.echo(output)


@cli.command("figures")
@click.option(
    "--output",
    type=click.Path(file_okay=False, writable=True),
    default="figures",
    show_default=True,
    help="Directory to write into (created if missing).",
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["png", "svg", "pdf"]),
    default="png",
    show_default=True,
    help="Image format.",
)
@click.option("--dpi", type=click.IntRange(50, 600), default=150, show_default=True)
def figures_command(output: str, fmt: str, dpi: int) -> None:
    """Regenerate the paper's Figures 2, 3, 4a, 4b, 5a, 5b and 5c.

    Inputs: a solid disk (m = 1 kg, R = 0.1 m, no spin) at vy = -1 m/s on a
    surface with mu = 0.25 and kappa = 0.6, and vx chosen to put each figure in
    its regime (see spinimpact.viz.plots.PAPER_FIGURES). Each file is written to a
    temporary name and renamed when complete.
    """
    from ..io import atomic_path
    from ..viz.plots import PAPER_FIGURES, paper_figure

    folder = Path(output)
    folder.mkdir(parents=True, exist_ok=True)
    for name in PAPER_FIGURES:
        target = folder / f"{name}.{fmt}"
        with atomic_path(target) as tmp:
            paper_figure(name).savefig(tmp, format=fmt, dpi=dpi)
        click.echo(str(target))


def _terminate(signum: int, _frame: Any) -> None:
    """SIGTERM: unwind normally so temporary files are removed."""
    raise SystemExit(128 + signum)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``spinimpact`` command."""
    import csv
    import signal

    if hasattr(signal, "SIGTERM"):
        signal.signal(signal.SIGTERM, _terminate)
    try:
        # Any floating-point trouble becomes a clean error rather than inf/NaN in a report.
        with np.errstate(over="raise", divide="raise", invalid="raise"):
            cli.main(args=argv, prog_name="spinimpact", standalone_mode=False)
    except click.exceptions.NoArgsIsHelpError as exc:
        click.echo(exc.ctx.get_help() if exc.ctx else "")
        sys.exit(0)
    except click.exceptions.Abort:
        click.echo("spinimpact: aborted", err=True)
        sys.exit(130)
    except click.ClickException as exc:
        click.echo(f"spinimpact: error: {exc.format_message()}", err=True)
        sys.exit(2)
    except (ValueError, ArithmeticError, RuntimeError, csv.Error) as exc:
        click.echo(f"spinimpact: error: {exc}", err=True)
        sys.exit(2)
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename else ""
        click.echo(f"spinimpact: error: {where}{exc.strerror or exc}", err=True)
        sys.exit(2)
