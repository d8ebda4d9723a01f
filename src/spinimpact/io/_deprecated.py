"""Older entry points kept as aliases: each says once per process that it is deprecated.

:func:`warn_deprecated` is how every alias in :mod:`spinimpact.io` warns
(:func:`~spinimpact.io.sphere_batch.run_sphere_batch`, and the per-problem sweeps of
:mod:`~spinimpact.io.sphere_sweep`, :mod:`~spinimpact.io.planar_sweep` and
:mod:`~spinimpact.io.compliant_sweep`): a :class:`DeprecationWarning` naming what
replaces it, the first time it is used in a process only.
"""

from __future__ import annotations

import warnings
from typing import Any

__all__ = ["OldSweep", "warn_deprecated"]

#: The old names that have warned in this process.
_WARNED: set[str] = set()


def warn_deprecated(old: str, new: str, *, stacklevel: int = 3) -> None:
    """Warn that ``old`` is deprecated and ``new`` replaces it, once per process.

    Parameters
    ----------
    old : str
        The deprecated name (``"SphereSweep"``); the message starts with it.
    new : str
        What to use instead, in words (``"spinimpact.io.problem_sweep.ProblemSweep(...)"``).
    stacklevel : int
        As for :func:`warnings.warn`; the default names the line that called the function
        that calls this one.
    """
    if old in _WARNED:
        return
    _WARNED.add(old)
    warnings.warn(f"{old} is deprecated: use {new}", DeprecationWarning, stacklevel=stacklevel)


class OldSweep:
    """What the older per-problem sweeps share: ``Old(body, axes, samples=None, seed=0,
    chunk_size=100_000, ...)`` warns once that ``Old`` is deprecated and returns the
    :class:`~spinimpact.io.problem_sweep.ProblemSweep` that :meth:`settings` describes.

    A subclass names its replacement (:attr:`replacement`) and turns the body and its own
    last parameter (a surface, a law) into ProblemSweep's settings (:meth:`settings`).
    """

    #: What to use instead, in words.
    replacement = "spinimpact.io.problem_sweep.ProblemSweep"

    def __new__(
        cls,
        body: Any,
        axes: dict[str, Any],
        samples: int | None = None,
        seed: int = 0,
        chunk_size: int = 100_000,
        *args: Any,
        **kwargs: Any,
    ) -> Any:
        from .problem_sweep import ProblemSweep

        warn_deprecated(cls.__name__, cls.replacement)
        settings = cls.settings(body, *args, **kwargs)
        return ProblemSweep(body=body, axes=axes, samples=samples, seed=seed,
                            chunk_size=chunk_size, **settings)  # fmt: skip

    @staticmethod
    def settings(body: Any, *args: Any, **kwargs: Any) -> dict[str, Any]:
        """The problem and the rest of ProblemSweep's settings for ``body`` and the older
        sweep's last parameter; a ``TypeError`` or ``ValueError`` for what it refuses."""
        raise NotImplementedError
