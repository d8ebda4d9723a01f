"""Command line: ``spinimpact solve`` prints the complete impact report.

One module per group of commands: :mod:`~spinimpact.cli.solve` (``solve``,
``report``), :mod:`~spinimpact.cli.batch`, :mod:`~spinimpact.cli.sweep`,
:mod:`~spinimpact.cli.simulate`, :mod:`~spinimpact.cli.pictures` (``map``,
``figures``), :mod:`~spinimpact.cli.planar`, :mod:`~spinimpact.cli.fit` and
:mod:`~spinimpact.cli.track`; what they share is in
:mod:`~spinimpact.cli._common`.

Errors in the input are reported as one line on stderr with exit status 2 and
no traceback (:func:`~spinimpact.cli._common.errors_to_exit_2`).
"""

from __future__ import annotations

import click
import numpy as np

from ._common import DEFAULTS, errors_to_exit_2
from .batch import batch_command
from .engines import engines_command
from .explore import explore_command
from .fit import fit_command
from .flight import flight_command
from .pictures import figures_command, map_command
from .planar import planar_command
from .problems import problems_command
from .simulate import simulate_command
from .solve import report_command, solve_command
from .sphere import pair_command, sphere_command
from .sweep import sweep_command
from .track import track_command

__all__ = ["main", "cli", "DEFAULTS"]


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="spinimpact")
def cli() -> None:
    """Exact frictional impact of a spinning rigid body on a fixed rough surface.

    Conventions: SI units; x along the surface, y up; omega counter-clockwise
    positive; the contact-point slip is u = vx + R*omega.
    """


for _command in (
    solve_command,
    report_command,
    batch_command,
    simulate_command,
    sweep_command,
    map_command,
    figures_command,
    planar_command,
    sphere_command,
    pair_command,
    flight_command,
    fit_command,
    track_command,
    problems_command,
    explore_command,
    engines_command,
):
    cli.add_command(_command)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``spinimpact`` command.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name; by default ``sys.argv[1:]``.

    Notes
    -----
    Exits with status 0 on success, 2 on bad input (one line on stderr, see
    :func:`~spinimpact.cli._common.errors_to_exit_2`), 130 on Ctrl-C (SIGINT) and
    128 + 15 on SIGTERM (also when the signal comes after the command has finished and
    renamed its outputs into place, with a line saying so). Output files are renamed
    into place only when the whole command, its standard output included, succeeded
    (:func:`~spinimpact.io.atomic.atomic_outputs`): a run that fails or is stopped
    leaves every old output as it was and no temporary file. A signal is recorded,
    and the run stops where stopping is safe (:mod:`spinimpact.io._stop`).
    Floating-point overflow, division by zero and invalid operations raise instead
    of producing ``inf`` or ``NaN`` in a report.
    """
    import sys

    from ..io._stop import stop_on_signals
    from ..io.atomic import atomic_outputs

    # The program (not a call from Python) keeps its handlers: a signal during the shutdown
    # after a finished command exits 128 + its number rather than killing the process.
    with stop_on_signals(keep=argv is None), errors_to_exit_2(program=argv is None):
        # Any floating-point trouble becomes a clean error rather than inf/NaN in a report.
        with np.errstate(over="raise", divide="raise", invalid="raise"), atomic_outputs():
            cli.main(args=argv, prog_name="spinimpact", standalone_mode=False)
            sys.stdout.flush()  # a full standard output fails the run before any rename
