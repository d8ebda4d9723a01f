"""Sweeps of one of the paper's bodies under a tangential compliance law: the older entry
point, kept as an alias.

:class:`~spinimpact.io.problem_sweep.ProblemSweep` sweeps every registered problem under
the tangential law it takes, the paper's bodies (``problem="paper"``) included: the body
as ``body=``, the law as ``tangential=``, the incidence, ``mu`` and ``kappa`` as axes.
:class:`CompliantSweep` builds that sweep and warns once that it is deprecated;
:func:`compliant_fields` stays for the code that names it.
"""

from __future__ import annotations

from typing import Any

from ..model.body import Body
from ..model.compliance import TangentialLaw, Walton
from ._deprecated import OldSweep, warn_deprecated
from .problem_sweep import problem_fields

__all__ = ["CompliantSweep", "compliant_fields"]

_NEW = ('spinimpact.io.problem_sweep.ProblemSweep(problem="paper", body=..., axes=..., '
        "tangential=...)")  # fmt: skip


def compliant_fields() -> tuple[str, ...]:
    """Deprecated: the fields of a compliant sweep are ``problem_fields("paper", law)``
    (:func:`~spinimpact.io.problem_sweep.problem_fields`, the same under every law), which
    this returns.

    Examples
    --------
    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", DeprecationWarning)
    ...     "tangential_restitution" in compliant_fields()
    True
    """
    warn_deprecated("compliant_fields",
                    'spinimpact.io.problem_sweep.problem_fields("paper", law)')  # fmt: skip
    return problem_fields("paper", Walton(0.0), body=Body)


class CompliantSweep(OldSweep):
    """Deprecated: a sweep under a tangential law is a
    :class:`~spinimpact.io.problem_sweep.ProblemSweep`.

    ``CompliantSweep(body, axes, samples=None, seed=0, chunk_size=100_000,
    tangential=law)`` warns once per process and returns ``ProblemSweep(problem="paper",
    body=body, axes=axes, tangential=law)``: the same columns, fields, regimes and numbers.

    Parameters
    ----------
    body : Body
        One of the paper's bodies (scalar mass, radius and gyration).
    axes : dict
        ``name -> Axis`` (or an axis's text) for ``vx, vy`` (m/s), ``omega`` (rad/s),
        ``mu, kappa``.
    samples, seed, chunk_size
        As for :class:`~spinimpact.io.problem_sweep.ProblemSweep`.
    tangential : TangentialLaw
        The law (:class:`~spinimpact.Walton`, :class:`~spinimpact.Stronge` or
        :class:`~spinimpact.MindlinDeresiewicz`).

    Raises
    ------
    TypeError
        For a ``tangential`` that is not a law, and as ``ProblemSweep``.
    """

    replacement = _NEW

    @staticmethod
    def settings(body: Body, tangential: Any = None) -> dict[str, Any]:
        """Problem ``paper`` under the law ``tangential``."""
        if not isinstance(tangential, TangentialLaw):
            raise TypeError(
                "tangential must be a tangential compliance law (spinimpact.Walton, "
                f"spinimpact.Stronge or spinimpact.MindlinDeresiewicz), got {tangential!r}"
            )
        if not isinstance(body, Body):
            raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
        return {"problem": "paper", "tangential": tangential}
