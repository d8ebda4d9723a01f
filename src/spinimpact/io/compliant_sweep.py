"""Sweeps of one of the paper's bodies under a tangential compliance law, in bounded memory.

A :class:`CompliantSweep` is a :class:`~spinimpact.io.sweep.Sweep` (axes ``vx, vy, omega,
mu, kappa``) with a law (:class:`~spinimpact.Walton`, :class:`~spinimpact.Stronge` or
:class:`~spinimpact.MindlinDeresiewicz`).
:func:`~spinimpact.io.sweep.run_sweep` runs it as any sweep: chunk by chunk, to Parquet,
CSV or ``.npy`` files, folding regime fractions and histograms on the fly, locally or on
Dask. Each chunk is solved by ``solve(..., tangential=law)`` at once, so the fields are the
:class:`~spinimpact.CompliantImpact` columns of the same names (:func:`compliant_fields`),
the very numbers the function gives; ``regime`` is the index into
:data:`~spinimpact.core.compliance.COMPLIANT_REGIMES`, written as names.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.compliance import COMPLIANT_REGIMES
from ..model.body import Body
from ..model.compliance import CompliantImpact, TangentialLaw
from ..model.impact import solve
from ._axes import INPUTS
from ._fields import ALIASES
from .sweep import Sweep

__all__ = ["CompliantSweep", "compliant_fields"]

_ORDER = np.argsort(COMPLIANT_REGIMES)
_SORTED = np.asarray(COMPLIANT_REGIMES)[_ORDER]


@functools.cache
def compliant_fields() -> tuple[str, ...]:
    """The fields of a compliant sweep: :class:`~spinimpact.CompliantImpact`'s columns that
    are not inputs (the body's, ``mu``, ``kappa``, ``before_*``).

    Examples
    --------
    >>> compliant_fields()[:4]
    ('after_vx', 'after_vy', 'after_omega', 'slip_before')
    """
    inputs = {*Body.COLUMNS, "mu", "kappa", *(f"before_{n}" for n in INPUTS)}
    return tuple(n for n in CompliantImpact.column_names() if n not in inputs)


@dataclass(frozen=True)
class CompliantSweep(Sweep):
    """A sweep over the incidences of one of the paper's bodies under a tangential law.

    Parameters
    ----------
    body, axes, samples, seed
        As for :class:`~spinimpact.io.sweep.Sweep`.
    chunk_size : int
        Points evaluated at a time (default 100,000: a chunk is solved whole).
    tangential : TangentialLaw
        The law (:class:`~spinimpact.Walton`, :class:`~spinimpact.Stronge` or
        :class:`~spinimpact.MindlinDeresiewicz`).

    Raises
    ------
    TypeError
        For a ``tangential`` that is not a law, and as :class:`~spinimpact.io.sweep.Sweep`.

    Examples
    --------
    >>> from spinimpact import Body, Walton
    >>> from spinimpact.io.sweep import parse_axis, run_sweep
    >>> spec = dict(vx="0.5:8:4", vy="-2", omega="0", mu="0.3", kappa="0.8")
    >>> sweep = CompliantSweep(Body.solid_sphere(mass=1.0, radius=0.1),
    ...                        {n: parse_axis(n, v) for n, v in spec.items()},
    ...                        tangential=Walton(0.4))
    >>> {name: share for name, share in run_sweep(sweep).regime_fractions.items() if share}
    {'slip-reversal': 0.25, 'slip': 0.75}
    """

    chunk_size: int = 100_000
    tangential: Any = None

    regimes = COMPLIANT_REGIMES

    def __post_init__(self) -> None:
        if not isinstance(self.tangential, TangentialLaw):
            raise TypeError(
                "tangential must be a tangential compliance law (spinimpact.Walton, "
                f"spinimpact.Stronge or spinimpact.MindlinDeresiewicz), got {self.tangential!r}"
            )
        super().__post_init__()

    def field_name(self, name: str, role: str = "fields") -> str:
        """The field ``name`` stands for: itself (:func:`compliant_fields`) or an alias's."""
        fields = compliant_fields()
        if name in fields:
            return name
        if ALIASES.get(name) in fields:
            return ALIASES[name]
        aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items())
        raise ValueError(f"{role} must be among {', '.join(fields)} (or {aliases}); got {name!r}")

    def description(self) -> dict[str, Any]:
        """The regimes' names, the body, the axes and the law."""
        return super().description() | {"tangential": self.tangential.to_dict()}

    def evaluate(self, k: int, fields: tuple[str, ...]) -> dict[str, np.ndarray]:
        """Inputs and ``fields`` of chunk ``k``, each an array of the chunk's length."""
        c = self.chunk(k)
        out: dict[str, Any] = dict(c)
        wanted = {name: self.field_name(name) for name in fields}
        if wanted:
            imp = solve(self.body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"],
                        tangential=self.tangential)  # fmt: skip
            columns = imp.columns()
            columns["regime"] = _ORDER[np.searchsorted(_SORTED, columns["regime"])].astype(np.int8)
            for name, f in wanted.items():
                out[name] = columns[f]
        n = self.chunk_length(k)
        return {name: np.broadcast_to(value, (n,)) for name, value in out.items()}
