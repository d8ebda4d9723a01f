"""The precomputed micro-slip table's file and constants (:mod:`spinimpact.core.mdr_table`
explains what it holds; :mod:`spinimpact.core.scalar_mdr` reads it one contact at a time).

Kept apart from :mod:`~spinimpact.core.mdr_table` so that the law on floats, which the
compiled per-contact law (:mod:`spinimpact.core.law`) registers, can load the table without
importing the array kernels that call the compiled law.
"""

from __future__ import annotations

import functools
from importlib import resources
from typing import NamedTuple

import numpy as np

__all__ = ["BOUND", "MARGIN", "FILE", "FIELDS", "MdrTable", "load_table"]

#: The error the table may make in the slip after, in units of ``|v_n^-|``.
BOUND = 1e-4

#: The table is trusted to ``MARGIN`` times the largest error measured off its grid.
MARGIN = 2.0

#: The shipped table (``python -m benchmarks.mdr_table`` writes it).
FILE = "mdr_table.npz"


class MdrTable(NamedTuple):
    """The tabulated impact (:func:`load_table`): read-only arrays, equal steps on each axis."""

    kappa: np.ndarray  #: the nodes in ``kappa``
    q: np.ndarray  #: the nodes in ``q = zeta r``
    t: np.ndarray  #: the nodes of each of the two stretches of ``X``, on ``[0, 1]``
    touch: np.ndarray  #: ``U_A``, the touch-down stick threshold in ``U``, on ``kappa``
    threshold: np.ndarray  #: ``X*`` on ``(kappa, q)``
    share: np.ndarray  #: ``phi`` on ``(stretch, kappa, q, t)``, ``X`` in ``[0, X_A]`` or after
    max_error: float  #: the largest error in ``phi`` measured on points off the grid
    springs: int  #: the full solution's resolution the table was built at
    steps: int


FIELDS = ("kappa", "q", "t", "touch", "threshold", "share")


@functools.cache
def load_table() -> MdrTable:
    """The table shipped in ``spinimpact/core/data`` (read once a process)."""
    with resources.files("spinimpact.core").joinpath("data", FILE).open("rb") as fh:
        data = dict(np.load(fh))
    arrays = [np.asarray(data[k], dtype=float) for k in FIELDS]
    for a in arrays:
        a.setflags(write=False)
    return MdrTable(*arrays, float(data["max_error"]), int(data["springs"]), int(data["steps"]))
