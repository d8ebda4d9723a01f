"""Batch files of spheres in 3D and of pairs: the older entry point, kept as an alias.

:func:`spinimpact.io.batch.run_batch` solves files of every registered problem, spheres
(``problem="sphere"``) and pairs (``problem="pair"``) included, through their declarations
(:mod:`spinimpact.model.problems`): same rows, same columns, with ``--fields``, units,
``on_error="skip"`` and standard input and output. :func:`run_sphere_batch` calls it and
warns once that it is deprecated.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..model.problems import SPHERE_PRESETS
from ..model.registry import detect
from ._deprecated import warn_deprecated
from ._tables import BatchError

__all__ = ["SPHERES", "BALL", "SphereBatchSummary", "sphere_kind", "run_sphere_batch"]

#: The presets a row's ``body`` may name.
SPHERES = SPHERE_PRESETS
#: Velocity and spin columns of one ball (ball 2's end in ``2``).
BALL = ("vx", "vy", "vz", "wx", "wy", "wz")


@dataclass(frozen=True)
class SphereBatchSummary:
    """What :func:`run_sphere_batch` did."""

    rows: int  #: data rows read
    skipped: int  #: rows written with an error instead of results (``on_error="skip"``)
    output: Path  #: the file written
    kind: str  #: "sphere" or "pair"


def sphere_kind(header: list[str]) -> str:
    """``"pair"`` if the columns hold a second ball (``vx2 ... wz2``), else ``"sphere"``.

    Raises
    ------
    BatchError
        For columns that do not describe spheres or pairs alone (a surface velocity in a
        file of two balls, say).
    """
    if not any(f"{c}2" in header for c in BALL):
        return "sphere"
    try:
        return detect(header).name
    except ValueError as exc:
        raise BatchError(str(exc)) from None


def run_sphere_batch(
    source: str | os.PathLike[str],
    output: str | os.PathLike[str],
    *,
    defaults: dict[str, Any] | None = None,
    pair: bool | None = None,
    on_error: str = "stop",
    chunk_size: int = 100_000,
    progress: Callable[[int, int], None] | None = None,
) -> SphereBatchSummary:
    """Deprecated: :func:`spinimpact.io.batch.run_batch` solves files of spheres and pairs.

    Parameters
    ----------
    source, output, on_error, chunk_size, progress
        As for :func:`~spinimpact.io.batch.run_batch`.
    defaults : dict, optional
        Values for inputs a file lacks (``mu``, ``kappa``, ``mass``, ``normal``, ...).
    pair : bool, optional
        ``True`` requires a file of pairs, ``False`` one of spheres; ``None``: the columns
        decide.

    Returns
    -------
    SphereBatchSummary
    """
    from .batch import run_batch

    warn_deprecated("run_sphere_batch", "spinimpact.io.batch.run_batch, which solves files of "
                    "every registered problem (problem='sphere' or 'pair')")  # fmt: skip
    name = None if pair is None else ("pair" if pair else "sphere")

    def check(kind: str) -> None:
        if kind not in ("sphere", "pair"):
            raise BatchError(f"{source} does not describe spheres or pairs (problem {kind!r})")

    summary = run_batch(source, output, defaults=dict(defaults or {}), on_error=on_error,
                        chunk_size=chunk_size, progress=progress, problem=name,
                        check_kind=check)  # fmt: skip
    return SphereBatchSummary(summary.rows, summary.skipped, summary.output, summary.kind)
