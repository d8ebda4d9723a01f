"""``spinimpact sweep``: a grid or random samples of incidences in bounded memory.

For one of the paper's bodies (``--body``, ``--gyration``) by default; with ``--planar``
for one planar body (``rod``, ``block``, ``eccentric-disk``: the geometry options of
``spinimpact planar``; ``custom``: ``--inertia, --rx, --ry``) or a rod ``pendulum`` on a
pivot (axes ``--omega, --mu, --kappa`` only), under one restitution ``--law``: the
:class:`~spinimpact.io.problem_sweep.ProblemSweep` of problem ``planar`` or ``pendulum``
with the body and the law held fixed. The fields are then the
:class:`~spinimpact.PlanarImpact` columns and the regimes the planar ones. With
``--sphere``, one sphere in 3D (:mod:`~spinimpact.cli._sphere_sweep`); with
``--tangential``, one of the paper's bodies under that law (problem ``paper``); with
``--problem NAME``, any registered problem (:mod:`~spinimpact.cli._problem_sweep`).

Before computing, trial chunks (the sweep's first points, grown while they take at most
a tenth of its time and 2 s) estimate the time, the memory of a chunk and the size of
the output (:func:`~spinimpact.io.sweep.estimate_sweep`); a sweep whose chunk does
not fit in memory, whose output does not fit on its disk, or that would take more than
an hour is refused in one line unless ``--force`` is given; ``--dry-run`` prints the
estimate and stops.
"""

from __future__ import annotations

import math
from typing import Any

import click

from .._long import ANNOUNCE_SECONDS, REFUSE_SECONDS
from .._words import count
from ..model.planar import LAWS
from ._common import DEFAULTS, body_options, make_body, progress
from ._compliance import sweep_class, tangential_law, tangential_options
from ._problem_sweep import ProblemSweepCommand, problem_sweep
from ._sphere_sweep import SPHERE_ONLY, sphere_options, sphere_sweep
from ._vocabulary import help as _help
from .planar import orientation_options

__all__ = ["sweep_command"]

_PLANAR = ("rod", "block", "eccentric-disk", "pendulum", "custom")
_CUSTOM = ("inertia", "rx", "ry")
_GEOMETRY = ("length", "width", "height", "radius", "gyration", "offset", "angle", "angle_deg")
#: Options that only a --planar sweep takes.
_PLANAR_ONLY = ("law", *_CUSTOM, "length", "width", "height", "offset", "angle", "angle_deg")
#: The axes of --vx and --omega when not typed: a grid, or ranges to draw random points from.
_GRID = {"vx": "-5:5:201", "omega": "-50:50:201"}
_RANDOM = {"vx": "uniform:-5:5", "omega": "uniform:-50:50"}
#: A sweep estimated to take longer than this is refused unless --force is given (the rule
#: of every long run: :mod:`spinimpact._long`).
MAX_SECONDS = REFUSE_SECONDS


def _given(ctx: click.Context, name: str) -> bool:
    """Whether the user typed option ``name`` (rather than leaving its default)."""
    source = ctx.get_parameter_source(name)
    return source not in (None, click.core.ParameterSource.DEFAULT)


def _flag(name: str) -> str:
    return "--orientation-deg" if name == "angle_deg" else "--" + name.replace("_", "-")


def _planar_body(ctx: click.Context, o: dict[str, Any]) -> Any:
    """The :class:`~spinimpact.PlanarBody` or :class:`~spinimpact.Pendulum` of the options.

    Raises
    ------
    click.UsageError
        For ``--body``, an option the body does not take, or a custom body without
        its three numbers.
    """
    from ..model.planar_body import PlanarBody
    from .planar import GEOMETRY, make_planar_body

    name = o["planar"]
    if o["body"] is not None:
        raise click.UsageError("give either --body (the paper's bodies) or --planar, not both")
    takes = [*_CUSTOM] if name == "custom" else [*GEOMETRY[name], "angle"]
    for option in (*_CUSTOM, *_GEOMETRY):
        if _given(ctx, option) and option not in takes:
            raise click.UsageError(
                f"{_flag(option)} does not apply to --planar {name} (it takes "
                + ", ".join(_flag(n) for n in takes)
                + ")"
            )
    if name == "custom":
        missing = [_flag(n) for n in _CUSTOM if o[n] is None]
        if missing:
            raise click.UsageError(
                f"--planar custom needs --inertia, --rx and --ry ({missing[0]} is missing)"
            )
        return PlanarBody(o["mass"], o["inertia"], o["rx"], o["ry"])
    geometry = {n: o[n] if _given(ctx, n) else None for n in _GEOMETRY}
    return make_planar_body(name, o["mass"], geometry)


def _is_random(o: dict[str, Any], samples: int | None) -> bool:
    """Whether the user asked for random points: ``--samples`` or a typed uniform axis."""
    typed = [o[n] for n in ("vx", "vy", "omega", "mu", "kappa") if o[n] is not None]
    return samples is not None or any(t.strip().startswith("uniform:") for t in typed)


def _axes(o: dict[str, Any], samples: int | None) -> dict[str, str]:
    """The axes' texts: what was typed, and for ``--vx`` and ``--omega`` not typed a grid
    (:data:`_GRID`), or with random points the same ranges drawn at random (:data:`_RANDOM`)."""
    defaults = _RANDOM if _is_random(o, samples) else _GRID
    texts = {n: o[n] for n in ("vx", "vy", "omega", "mu", "kappa")}
    return {n: defaults[n] if t is None else t for n, t in texts.items()}


def _planar_axes(
    ctx: click.Context, o: dict[str, Any], body: Any, samples: int | None
) -> dict[str, str]:
    """The axes' texts of a planar sweep; unless given, ``omega`` is ``0`` (a free body) or
    2 rad/s turning the contact toward the surface (a pendulum)."""
    from ..model.planar_body import Pendulum

    axes = _axes(o, samples)
    if isinstance(body, Pendulum):
        for name in ("vx", "vy"):
            if _given(ctx, name):
                raise click.UsageError(
                    f"--{name} does not apply to --planar pendulum: its centre moves with --omega"
                )
            del axes[name]
    if not _given(ctx, "omega"):
        axes["omega"] = f"{-math.copysign(2.0, float(body.px)):g}" if "vx" not in axes else "0"
    return axes


def _refuse_what_cannot_fit(cost: Any, dask: bool) -> None:
    """Refuse in one line a sweep whose chunk does not fit in memory, whose output does not
    fit on its disk, or that would take over :data:`MAX_SECONDS` (on a Dask cluster, only
    the output is checked: the chunks run elsewhere).

    Raises
    ------
    click.ClickException
        Naming what does not fit and ``--force``.
    """
    import dataclasses

    if dask:
        cost = dataclasses.replace(cost, available_memory=None)
    problems = cost.problems(max_seconds=None if dask else MAX_SECONDS)
    if problems:
        raise click.ClickException(
            f"this sweep cannot run as asked: {'; '.join(problems)} (estimated from its first "
            f"{count(cost.measured_points, 'point')}; --force runs it anyway)"
        )


def _histogram(text: str | None) -> tuple[str, float, float, int] | None:
    """``FIELD:LOW:HIGH:BINS`` as ``(field, low, high, bins)``, or ``None`` for no histogram.

    Raises
    ------
    click.UsageError
        If the text does not have that form.
    """
    if not text:
        return None
    parts = text.split(":")
    try:
        if len(parts) != 4:
            raise ValueError
        return (parts[0], float(parts[1]), float(parts[2]), int(parts[3]))
    except ValueError:
        raise click.UsageError(f"--histogram must be FIELD:LOW:HIGH:BINS, got {text!r}") from None


def _dask_client(address: str | None) -> Any:
    """A ``dask.distributed`` client of the scheduler at ``address`` (``None``: none).

    Raises
    ------
    ImportError
        If the ``[dask]`` extra is not installed; the message says how to install it.
    """
    if not address:
        return None
    try:
        from distributed import Client
    except ImportError:
        raise ImportError(
            "--dask needs the optional extra: pip install 'spinimpact[dask]'", name="distributed"
        ) from None
    return Client(address, timeout=30)


@click.command("sweep", cls=ProblemSweepCommand)
@body_options
@click.option(
    "--planar",
    type=click.Choice(list(_PLANAR)),
    default=None,
    help=_help(
        "planar",
        "A rod on its end, a block on a corner, an eccentric disk, a rod "
        "pendulum on a pivot (axes --omega, --mu, --kappa), or a custom body (--inertia, --rx, "
        "--ry). Geometry as in 'spinimpact planar'; --mass applies.",
    ),
)
@click.option("--length", type=float, default=None, help=_help("length", "Default 1."))
@click.option("--width", type=float, default=None, help=_help("width", "Default 0.2."))
@click.option("--height", type=float, default=None, help=_help("height", "Default 0.1."))
@click.option(
    "--offset",
    type=float,
    default=None,
    help=_help(
        "offset", "Default 0.02; its --radius (0.1) and --gyration (0.07) are the options above."
    ),
)
@orientation_options
@click.option("--inertia", type=float, default=None, help=_help("inertia", "Custom body."))
@click.option("--rx", type=float, default=None, help=_help("rx", "Custom body."))
@click.option("--ry", type=float, default=None, help=_help("ry", "Custom body."))
@click.option(
    "--law",
    type=click.Choice(list(LAWS)),
    default="poisson",
    show_default=True,
    help=_help("law", "Of a --planar sweep (the paper's bodies obey the three alike)."),
)
@click.option(
    "--vx",
    default=None,
    help=_help(
        "vx",
        "A number, START:STOP:NUM (a grid) or uniform:LOW:HIGH (random, with "
        "--samples). Default -5:5:201, or uniform:-5:5 for random points.",
    ),
)
@click.option("--vy", default="-4", show_default=True, help=_help("vy", "As --vx."))
@click.option(
    "--omega",
    default=None,
    help=_help(
        "omega",
        "As --vx. Default -50:50:201, or uniform:-50:50 for random points "
        "(--planar: 0, a pendulum 2 rad/s toward the surface).",
    ),
)
@click.option("--mu", default=str(DEFAULTS["mu"]), show_default=True, help=_help("mu", "As --vx."))
@click.option(
    "--kappa", default=str(DEFAULTS["kappa"]), show_default=True, help=_help("kappa", "As --vx.")
)
@click.option(
    "--samples",
    type=click.IntRange(1),
    default=None,
    help=_help(
        "samples",
        "The uniform axes are drawn at random (and --vx, --omega not typed "
        "default to uniform ranges).",
    ),
)
@click.option(
    "--seed",
    type=int,
    default=0,
    show_default=True,
    help=_help("seed", "The same seed gives the same points whatever --chunk-size or --dask."),
)
@click.option(
    "--chunk-size",
    type=click.IntRange(1),
    default=1_000_000,
    show_default=True,
    help=_help("chunk-size", "--dry-run estimates it; --planar: default 100000."),
)
@click.option(
    "--output",
    default=None,
    help="Output file: FILE.parquet or FILE.csv ([parquet] extra), or a new directory of "
    ".npy files (a name without a suffix, or ending in /): one per column and "
    "metadata.json. The inputs and --fields; regime as names (a dictionary column in "
    'Parquet; in .npy, int8 indices into metadata.json\'s "regimes"), units in '
    "Parquet field metadata and metadata.json.",
)
@click.option(
    "--fields",
    default="after_vx,after_vy,after_omega,regime",
    show_default=True,
    help="Result columns to write, comma-separated, named as the Impact's columns (after_vx, "
    "after_vy, after_omega, regime, slip_before, slip_after, impulse_ratio, "
    "dissipated_energy, dissipated_fraction; energy_loss is an alias of dissipated_fraction). "
    "--planar: any PlanarImpact column that is not an input (also creates_energy, tau0, "
    "tau1, newton_restitution, ...). --sphere: any SphereImpact column that is not an "
    "input (default after_vx..after_wz, regime; also grips, topspin, rebound_angle, ...).",
)
@click.option("--histogram", default=None, help=_help("histogram"))
@sphere_options
@tangential_options
@click.option("--dask", "dask_address", default=None, help=_help("dask"))
@click.option(
    "--problem",
    default=None,
    metavar="NAME",
    help=_help(
        "problem",
        "Sweep any registered problem (spinimpact problems lists them), e.g. --problem pair: "
        "its inputs become the options (spinimpact sweep --problem pair --help), each a "
        "number, START:STOP:NUM or uniform:LOW:HIGH; inputs not given take the problem's "
        "defaults; --fields names its result columns (default the after_* ones and regime).",
    ),
)
@click.option(
    "--dry-run",
    is_flag=True,
    help=_help(
        "dry-run",
        "Points, time, memory a chunk, output size; the points it was "
        "measured on: the sweep's first, as many as are cheap.",
    ),
)
@click.option(
    "--force",
    is_flag=True,
    help=_help("force", "Or not to fit in memory or on disk."),
)
@click.pass_context
def sweep_command(
    ctx,
    samples,
    seed,
    chunk_size,
    output,
    fields,
    histogram,
    dask_address,
    dry_run,
    force,
    **o: Any,
) -> None:
    """Sweep a grid or random samples of incidence conditions in bounded memory:
    regime fractions (always), a histogram, and/or the fields written to files.

    One of the paper's bodies (--body, --gyration), or with --planar one planar body or
    pendulum under one --law, e.g. --planar rod --length 1 --orientation-deg 45 --law newton.
    With --problem NAME, any registered problem (two spheres: --problem pair), its inputs as
    options: spinimpact sweep --problem pair --help lists them."""
    from ..io.sweep import estimate_sweep, parse_axis, run_sweep

    make = sweep_class(o)  # Sweep, or the problem sweep of the --tangential law
    problem = o.get("problem")  # with --problem, the options are the problem's inputs
    if problem is None and o["sphere"] is None:
        for name in SPHERE_ONLY:
            if _given(ctx, name):
                raise click.UsageError(f"{_flag(name)} needs --sphere (a sphere's sweep)")
    if problem is not None:
        sweep = problem_sweep(ctx, o, samples, seed, chunk_size, tangential_law(o))
        fields = fields if _given(ctx, "fields") else ",".join(sweep.default_fields)
    elif o["sphere"] is not None:
        sweep, default_fields = sphere_sweep(ctx, o, samples, seed, chunk_size)
        fields = default_fields or fields
    elif o["planar"] is None:
        for name in _PLANAR_ONLY:
            if _given(ctx, name):
                raise click.UsageError(f"{_flag(name)} needs --planar (a planar body's sweep)")
        body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
        texts = _axes(o, samples)
        sweep = make(
            body,
            {name: parse_axis(name, text) for name, text in texts.items()},
            samples=samples,
            seed=seed,
            chunk_size=chunk_size,
        )
    else:
        from ..io.problem_sweep import ProblemSweep
        from ..model.planar_body import Pendulum

        body = _planar_body(ctx, o)
        texts = _planar_axes(ctx, o, body, samples)
        size = {"chunk_size": chunk_size} if _given(ctx, "chunk_size") else {}
        sweep = ProblemSweep(
            problem="pendulum" if isinstance(body, Pendulum) else "planar",
            body=body,
            axes={name: parse_axis(name, text) for name, text in texts.items()},
            fixed={"law": o["law"]},
            samples=samples,
            seed=seed,
            **size,
        )
    hist = _histogram(histogram)
    names = tuple(f.strip() for f in fields.split(",") if f.strip())
    if dry_run or not force:
        cost = estimate_sweep(sweep, histogram=hist, output=output, fields=names)
        if dry_run:
            click.echo(f"estimate: {cost}")
        _refuse_what_cannot_fit(cost, dask=bool(dask_address))
        if dry_run:
            return
        if cost.seconds > ANNOUNCE_SECONDS:  # False for NaN
            click.echo(f"spinimpact: {cost}", err=True)
    client = _dask_client(dask_address)
    try:
        with progress() as bar:
            task = bar.add_task(count(sweep.size, "point"), total=sweep.chunks)
            result = run_sweep(
                sweep,
                histogram=hist,
                output=output,
                fields=names,
                client=client,
                progress=lambda done, total: bar.update(task, completed=done),
                check=False,  # checked above, or --force
            )
    except MemoryError as exc:  # a traceback helps nobody: say what to change
        raise click.ClickException(
            f"out of memory ({exc or 'MemoryError'}): lower --chunk-size (now {sweep.chunk_size:,})"
        ) from None
    finally:
        if client is not None:
            client.close()
    about = f" ({body.name}, {o['law']} law)" if o.get("planar") else ""
    about = f" ({sweep.body.name})" if o.get("sphere") else about
    about = f" (problem {o['problem']})" if o.get("problem") else about
    click.echo(f"{count(result.points, 'point')}{about}")
    width = max(map(len, result.regimes)) + 1
    for name, fraction in result.regime_fractions.items():
        click.echo(f"  {name:{width}s} {fraction:.6f}")
    if result.histogram is not None:
        click.echo(f"histogram of {hist[0]}:")
        for lo, hi, n in zip(
            result.bin_edges[:-1], result.bin_edges[1:], result.histogram, strict=True
        ):
            click.echo(f"  [{lo:.6g}, {hi:.6g})  {n}")
    if output:
        click.echo(f"wrote {output}")
