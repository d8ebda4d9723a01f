"""Thread pools within an address-space limit (``ulimit -v``).

NumPy's and SciPy's OpenBLAS, Numba and pyarrow each start a pool of threads sized by the
machine's cores, and each thread reserves address space (its stack, a malloc arena of 64
MiB, OpenBLAS's buffers) whether it uses it or not. Under a limit of a few GiB a run then
fails to start a thread ("can't start new thread"), raises MemoryError inside a library's
start-up, or (OpenBLAS) spins forever. When the process has such a limit,
:func:`bound_threads` caps those pools at one thread each and the malloc arenas at two, by
the libraries' own environment variables (a variable already set is kept), before any of
them is loaded (importing this module calls it; ``import spinimpact`` imports it first).
Without a limit nothing changes.

This module imports nothing of the package.
"""

from __future__ import annotations

import contextlib
import os

__all__ = ["POOL_VARIABLES", "address_limit", "bound_threads"]

#: The environment variables that size the libraries' thread pools.
POOL_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS",
                  "NUMBA_NUM_THREADS", "ARROW_IO_THREADS")  # fmt: skip


def address_limit() -> int | None:
    """The process's address-space limit in bytes (``ulimit -v``), or ``None`` if it has
    none (or the platform cannot tell)."""
    try:
        import resource
    except ImportError:  # pragma: no cover (not POSIX)
        return None
    soft = resource.getrlimit(resource.RLIMIT_AS)[0]
    return None if soft == resource.RLIM_INFINITY else int(soft)


def bound_threads() -> bool:
    """Under an address-space limit, cap the thread pools and malloc arenas (module
    docstring); return whether there was a limit."""
    if address_limit() is None:
        return False
    for name in POOL_VARIABLES:
        os.environ.setdefault(name, "1")
    os.environ.setdefault("MALLOC_ARENA_MAX", "2")  # for child processes
    with contextlib.suppress(OSError, AttributeError):  # glibc only: this process's arenas
        import ctypes

        ctypes.CDLL(None).mallopt(-8, 2)  # M_ARENA_MAX
    return True


bound_threads()
