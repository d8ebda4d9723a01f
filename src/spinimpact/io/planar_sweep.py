"""Sweeps of one planar body or one pendulum: the older entry point, kept as an alias.

:class:`~spinimpact.io.problem_sweep.ProblemSweep` sweeps every registered problem, planar
bodies (``problem="planar"``) and pendulums (``problem="pendulum"``) included: the body
as ``body=``, the restitution law held fixed (``fixed={"law": ...}``), the incidence,
``mu`` and ``kappa`` as axes; a sweep asking for the impact process alone
(:data:`PROCESS_FIELDS`) computes it without the works and energies, as before.
:class:`PlanarSweep` builds that sweep and warns once that it is deprecated;
:func:`planar_fields`, :data:`PENDULUM_INPUTS` and :data:`PROCESS_FIELDS` stay for the
code that names them.
"""

from __future__ import annotations

from typing import Any

from ..model.planar_body import Pendulum, PlanarBody
from ..model.problems import PROCESS_COLUMNS
from ._deprecated import OldSweep, warn_deprecated
from .problem_sweep import problem_fields

__all__ = ["PROCESS_FIELDS", "PlanarSweep", "planar_fields"]

_NEW = ('spinimpact.io.problem_sweep.ProblemSweep(problem="planar" or "pendulum", body=..., '
        'axes=..., fixed={"law": ...})')  # fmt: skip
#: Fields of the impact process alone (no works, no energies): computed without the rest
#: (:data:`spinimpact.model.problems.PROCESS_COLUMNS`).
PROCESS_FIELDS = PROCESS_COLUMNS


def __getattr__(name: str) -> Any:
    if name == "PENDULUM_INPUTS":  # the axes of a pendulum's sweep
        warn_deprecated("PENDULUM_INPUTS", "the inputs of spinimpact.problem('pendulum')")
        return ("omega", "mu", "kappa")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def planar_fields(pendulum: bool = False) -> tuple[str, ...]:
    """Deprecated: the fields of a planar body's sweep are ``problem_fields("planar")``
    (a pendulum's ``problem_fields("pendulum")``:
    :func:`~spinimpact.io.problem_sweep.problem_fields`), which this returns.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", DeprecationWarning)
    ...     "before_vx" in planar_fields(), "before_vx" in planar_fields(pendulum=True)
    (False, True)
    """
    warn_deprecated("planar_fields", 'spinimpact.io.problem_sweep.problem_fields("planar")')
    if pendulum:
        return problem_fields("pendulum", body=Pendulum)
    return problem_fields("planar", body=PlanarBody)


class PlanarSweep(OldSweep):
    """Deprecated: a planar body's or a pendulum's sweep is a
    :class:`~spinimpact.io.problem_sweep.ProblemSweep`.

    ``PlanarSweep(body, axes, samples=None, seed=0, chunk_size=100_000, law="poisson")``
    warns once per process and returns ``ProblemSweep(problem="planar", body=body,
    axes=axes, fixed={"law": law})`` (``problem="pendulum"`` for a pendulum): the same
    columns, fields, regimes and numbers.

    Parameters
    ----------
    body : PlanarBody or Pendulum
        One body (scalar mass, inertia and geometry).
    axes : dict
        ``name -> Axis`` (or an axis's text) for ``vx, vy`` (m/s), ``omega`` (rad/s),
        ``mu, kappa``; for a pendulum ``omega, mu, kappa`` only.
    samples, seed, chunk_size
        As for :class:`~spinimpact.io.problem_sweep.ProblemSweep`.
    law : {"poisson", "newton", "energetic"}
        The restitution law (:func:`~spinimpact.solve_planar`).

    Raises
    ------
    TypeError
        For a body that is neither, and as ``ProblemSweep`` (a law that is not a name).
    ValueError
        As ``ProblemSweep``: an unknown law or axis, an array of bodies, a contact point
        that does not approach the surface somewhere in the sweep (in the same words as
        before).
    """

    replacement = _NEW

    @staticmethod
    def settings(body: PlanarBody | Pendulum, law: str = "poisson") -> dict[str, Any]:
        """Problem ``planar`` (``pendulum`` for a pendulum), the law held fixed."""
        if not isinstance(body, PlanarBody | Pendulum):
            raise TypeError(
                f"body must be a spinimpact.PlanarBody or Pendulum, got {type(body).__name__}"
            )
        problem = "pendulum" if isinstance(body, Pendulum) else "planar"
        return {"problem": problem, "fixed": {"law": law}}
