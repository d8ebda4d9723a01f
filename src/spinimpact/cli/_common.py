"""What every command shares: the documented default case, the body, incidence and
surface options, the body helper, the progress bar, the JSON helper and the
translation of errors into one line on stderr with exit status 2.

Only Click, NumPy and the model are imported here; Rich, Matplotlib and the file
readers are imported inside the functions that need them, so ``spinimpact
--help`` and ``spinimpact solve --json`` stay fast.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import Any

import click

from ..model.body import PRESETS, Body
from ..model.impact import Impact, solve
from ._vocabulary import help as _help

__all__ = [
    "DEFAULTS",
    "SPEED_UNITS",
    "body_options",
    "surface_options",
    "incidence_options",
    "float_option",
    "make_body",
    "solve_options",
    "progress",
    "image_format",
    "jsonable",
    "errors_to_exit_2",
    "announce",
    "long_run",
]

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

#: m/s in one unit of each ``--speed-unit``.
SPEED_UNITS: dict[str, float] = {"m/s": 1.0, "km/h": 1.0 / 3.6, "mph": 0.44704}


def jsonable(value: Any) -> Any:
    """``value`` with every non-finite float replaced by ``None``.

    Parameters
    ----------
    value : dict, list, float or any JSON value
        Typically :meth:`Impact.to_dict`'s output.

    Returns
    -------
    Any
        The same structure; ``json.dumps`` of it is strict JSON (no
        ``Infinity`` or ``NaN`` tokens), the non-finite values becoming ``null``.
    """
    if isinstance(value, dict):
        return {k: jsonable(v) for k, v in value.items()}
    if isinstance(value, list):
        return [jsonable(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def make_body(body: str | None, mass: float, radius: float, gyration: float | None) -> Body:
    """The body named by the ``--body``, ``--mass``, ``--radius`` and ``--gyration`` options.

    Parameters
    ----------
    body : str or None
        Preset name (:data:`spinimpact.model.body.PRESETS`); ``None`` means the
        default preset, or a custom body when ``gyration`` is given.
    mass : float
        Mass m, kg.
    radius : float
        Contact radius R, m.
    gyration : float or None
        Radius of gyration rho about the centre, m, for a custom body.

    Returns
    -------
    Body

    Raises
    ------
    click.UsageError
        If both a preset and a radius of gyration are given.
    ValueError
        If a number is out of range (from :class:`~spinimpact.Body`).
    """
    if gyration is not None:
        if body is not None:
            raise click.UsageError("give either --body or --gyration, not both")
        return Body(mass=mass, radius=radius, gyration=gyration)
    return Body.preset(body or DEFAULTS["body"], mass=mass, radius=radius)


def solve_options(o: dict[str, Any]) -> Impact:
    """The Impact described by the shared body, incidence and surface options.

    Parameters
    ----------
    o : dict
        The command's options: ``body``, ``mass`` (kg), ``radius`` (m),
        ``gyration`` (m), ``vx``, ``vy`` (m/s), ``omega`` (rad/s), ``mu``, ``kappa``.

    Returns
    -------
    Impact
        :func:`spinimpact.solve` of that case.
    """
    body = make_body(o["body"], o["mass"], o["radius"], o["gyration"])
    return solve(body, o["vx"], o["vy"], o["omega"], mu=o["mu"], kappa=o["kappa"])


def _options(*decorators: Callable) -> Callable:
    """Bundle click options so several commands share them."""

    def wrap(function: Callable) -> Callable:
        for decorator in reversed(decorators):
            function = decorator(function)
        return function

    return wrap


def float_option(name: str, help: str = "") -> Callable:
    """A float option ``--NAME`` whose default is the documented default case's.

    Parameters
    ----------
    name : str
        Key of :data:`DEFAULTS` and name of the option.
    help : str
        What the command adds to the option's meaning and unit
        (:mod:`~spinimpact.cli._vocabulary`).
    """
    return click.option(
        f"--{name}", type=float, default=DEFAULTS[name], show_default=True, help=_help(name, help)
    )


body_options = _options(
    click.option(
        "--body",
        type=click.Choice(list(PRESETS)),
        default=None,
        help=_help("body", f"Default {DEFAULTS['body']}."),
    ),
    float_option("mass"),
    float_option("radius"),
    click.option(
        "--gyration",
        type=float,
        default=None,
        help=_help("gyration", "A custom body instead of a preset (rho > R for a spool)."),
    ),
)
surface_options = _options(float_option("mu"), float_option("kappa"))
incidence_options = _options(float_option("vx"), float_option("vy"), float_option("omega"))


def progress() -> Any:
    """A Rich progress bar on stderr, shown only on a terminal.

    Returns
    -------
    rich.progress.Progress
        To use as a context manager; disabled (prints nothing) when stderr is not
        a terminal, so logs and pipes stay clean.
    """
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


def announce(estimate: Any) -> None:
    """Say a long run's estimate on stderr before it starts (over a minute:
    :data:`spinimpact._long.ANNOUNCE_SECONDS`)."""
    if estimate.announced:
        click.echo(f"spinimpact: {estimate}", err=True)


@contextmanager
def long_run() -> Iterator[None]:
    """Refuse a run estimated over an hour (:class:`spinimpact._long.TooLong`) in one line
    naming ``--force``, the command line's way to force it. Under an address-space limit
    (``ulimit -v``) the compiled kernels are loaded first (:mod:`spinimpact.core.preload`)."""
    from .._limits import address_limit
    from .._long import TooLong

    if address_limit() is not None:
        from ..core.preload import load_kernels

        load_kernels()
    try:
        yield
    except TooLong as exc:
        raise click.ClickException(exc.estimate.refusal("--force")) from None


def image_format(path: str, option: str = "--output") -> str:
    """The image format named by the suffix of ``option``'s file (``png``, ``svg``, ``pdf``).

    Raises
    ------
    click.UsageError
        For any other suffix.
    """
    fmt = Path(path).suffix.lower().lstrip(".")
    if fmt not in ("png", "svg", "pdf"):
        raise click.UsageError(f"{option} must end in .png, .svg or .pdf, got {path!r}")
    return fmt


def _fail(message: str) -> None:
    click.echo(f"spinimpact: error: {message}", err=True)
    sys.exit(2)


def _fail_now(message: str) -> None:
    """:func:`_fail`, then end the process at once with status 2, without the interpreter's
    shutdown: after memory ran out, that shutdown could add lines ("Exception ignored in
    ...") or abort in a native library ("terminate called without an active exception",
    status -6). A temporary output still alive is removed first
    (:func:`spinimpact.io.atomic.discard_all`); every old output is as it was."""
    import os

    from ..io.atomic import discard_all

    for stream in (sys.stdout, sys.stderr):
        with suppress(Exception):  # closed or broken: nothing more to say
            stream.flush()
    with suppress(Exception):
        discard_all()
    os.write(2, f"spinimpact: error: {message}\n".encode())
    os._exit(2)


#: The options that bound a command's memory, for the message when it runs out.
MEMORY_OPTIONS = {
    "batch": "--chunk-size",
    "sweep": "--chunk-size",
    "map": "--resolution or --dpi",
    "planar": "--resolution or --dpi",
    "figures": "--dpi",
    "flight": "--samples or --dpi",
}


#: What the system says when a shared library cannot be mapped for want of address space.
_NO_ROOM = ("failed to map segment from shared object", "Cannot allocate memory")


def _memory_advice() -> str:
    """What to lower when the command that ran (read from the command line) runs out of
    memory."""
    words = [w for w in sys.argv[1:] if not w.startswith("-")]
    option = MEMORY_OPTIONS.get(words[0] if words else "")
    if option is None:
        return "ask for less at a time, or allow the process more memory"
    return f"lower {option}, or allow the process more memory"


@contextmanager
def errors_to_exit_2(*, program: bool = False) -> Iterator[None]:
    """Turn every error in the input into one line on stderr and exit status 2.

    The package's error vocabulary, as the shell sees it:

    * a bad option or usage (:class:`click.ClickException`), a bad value
      (``ValueError``), a value of the wrong type (``TypeError``), a
      floating-point fault (``ArithmeticError``), a failed computation
      (``RuntimeError``), a malformed CSV file (``csv.Error``), a missing
      optional package (``ImportError``, whose message names the extra to
      install) and a file that cannot be read or written (``OSError``) print
      ``spinimpact: error: MESSAGE`` and exit with status 2, without a traceback;
    * running out of memory (``MemoryError``, a thread that cannot start, a compiled
      library that cannot be mapped into the address space, as Numba's thread pool under
      ``ulimit -v``, or under such a limit a call that failed without an exception, as
      Python's does when even the ``MemoryError`` finds no room) prints one
      line naming the option that bounds the command's memory
      (:data:`MEMORY_OPTIONS`), exit status 2;
    * a stop by a signal (:class:`~spinimpact.io._stop.Stopped`: Ctrl-C, SIGTERM)
      prints which and exits with status 128 + its number (130 for SIGINT, 143 for
      SIGTERM); Click's own abort prints ``spinimpact: aborted`` and exits with 130.

    Anything else is a bug and keeps its traceback. With ``program=True`` (the command
    line's own process, which ends next) running out of memory ends the process at once
    after its line (:func:`_fail_now`).
    """
    import csv
    import signal

    from ..io._stop import Stopped

    try:
        try:
            yield
        except RuntimeError as exc:  # a thread pool that cannot start is out of memory
            if "can't start new thread" not in str(exc):
                raise
            raise MemoryError(str(exc)) from None
        except (OSError, ImportError) as exc:  # a library that cannot be mapped: no memory
            if not any(text in str(exc) for text in _NO_ROOM):
                raise
            raise MemoryError(str(exc)) from None
        except SystemError as exc:  # under ulimit -v: the MemoryError itself had no room
            from .._limits import address_limit

            if address_limit() is None or "without setting an exception" not in str(exc):
                raise
            raise MemoryError("a call failed with no room left to say why") from None
    except MemoryError as exc:
        message = f"out of memory ({str(exc) or 'MemoryError'}): {_memory_advice()}"
        if program:  # the process ends here: skip a shutdown that memory may not allow
            _fail_now(message)
        _fail(message)
    except Stopped as exc:
        name = signal.Signals(exc.signum).name
        click.echo(f"spinimpact: stopped by {name}; no output was changed", err=True)
        sys.exit(128 + exc.signum)
    except click.exceptions.NoArgsIsHelpError as exc:
        click.echo(exc.ctx.get_help() if exc.ctx else "")
        sys.exit(0)
    except click.exceptions.Abort:
        click.echo("spinimpact: aborted", err=True)
        sys.exit(130)
    except click.ClickException as exc:
        _fail(exc.format_message())
    except (ValueError, TypeError, ArithmeticError, RuntimeError, ImportError, csv.Error) as exc:
        _fail(str(exc))
    except OSError as exc:
        where = f"{exc.filename}: " if exc.filename else ""
        _fail(f"{where}{exc.strerror or exc}")
