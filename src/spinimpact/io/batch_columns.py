"""The output columns of batch files of the paper's bodies, rigid or under a tangential law.

A row of the paper's bodies is written as its input columns, then every flat column of
its result that is not an input: an :class:`~spinimpact.Impact` from
:func:`~spinimpact.solve`, or with a tangential compliance law (``spinimpact batch
--tangential``, :func:`~spinimpact.io.batch.run_batch` with ``defaults["tangential"]``) a
:class:`~spinimpact.CompliantImpact` from ``solve(..., tangential=law)``. The names come
from the result types (:meth:`~spinimpact.model.result.Result.column_names`), so a new
field of a result is a new column of the file.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

import numpy as np

from ..model.body import Body
from ..model.impact import Impact, solve

__all__ = ["INPUT_FIELDS", "LEADING", "RESULT_COLUMNS", "column_kinds", "result_columns"]

#: Columns of an :class:`Impact` that a batch row already holds as input columns
#: (``before_vx`` is the row's ``vx``, ...): not repeated in the output.
INPUT_FIELDS = ("mass", "radius", "gyration", "mu", "kappa", "before_vx", "before_vy",
                "before_omega")  # fmt: skip
#: Result columns written first, right after the inputs (the headline of a row).
LEADING = ("regime",)


def result_columns(result: type = Impact) -> tuple[str, ...]:
    """The output columns of a batch file: ``result``'s flat columns less the inputs.

    Parameters
    ----------
    result : type
        The result type whose :meth:`~spinimpact.model.result.Result.column_names`
        give the vocabulary (:class:`~spinimpact.Impact`, or
        :class:`~spinimpact.CompliantImpact` under a tangential law).

    Returns
    -------
    tuple of str
        :data:`LEADING` first, then the other columns in the result's order,
        without :data:`INPUT_FIELDS`.

    Examples
    --------
    >>> result_columns()[:4]
    ('regime', 'zeta', 'after_vx', 'after_vy')
    """
    names = [n for n in result.column_names() if n not in INPUT_FIELDS]
    return tuple(n for n in LEADING if n in names) + tuple(n for n in names if n not in LEADING)


def _reader(name: str) -> Callable[[Impact], np.ndarray]:
    def column(impact: Impact) -> np.ndarray:
        return impact.columns()[name]

    column.__name__ = column.__qualname__ = f"column_{name}"
    column.__doc__ = f"The ``{name}`` column of an Impact (its result's shape)."
    return column


#: Output column -> how to read it from an :class:`Impact` (``impact.columns()[name]``).
RESULT_COLUMNS: dict[str, Callable[[Impact], np.ndarray]] = {
    name: _reader(name) for name in result_columns()
}


@functools.cache
def column_kinds(tangential: Any = None) -> dict[str, str]:
    """Each output column's kind: ``"float"``, ``"text"`` (regime) or ``"flag"`` (bool),
    in the order written.

    Parameters
    ----------
    tangential : Walton, Stronge or MindlinDeresiewicz, optional
        A tangential compliance law: the columns are then those of a
        :class:`~spinimpact.CompliantImpact` (:func:`result_columns` of it).

    Read from the dtypes of one solved impact, so a new field gets the right kind.

    Examples
    --------
    >>> from spinimpact import Walton
    >>> list(column_kinds(Walton(0.3)))[:4]
    ['regime', 'zeta', 'after_vx', 'after_vy']
    >>> column_kinds(Walton(0.3))["tangential_restitution"]
    'float'
    """
    probe = solve(Body.solid_sphere(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.3, kappa=0.8,
                  tangential=tangential)  # fmt: skip
    kinds = {"b": "flag", "U": "text", "S": "text", "O": "text"}
    columns = probe.columns()
    return {
        n: kinds.get(np.asarray(columns[n]).dtype.kind, "float")
        for n in result_columns(type(probe))
    }
