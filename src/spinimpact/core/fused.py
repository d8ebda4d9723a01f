"""Fused one-pass kernels for large batches (optional ``[fast]`` extra: Numba).

The closed forms cost a few flops per impact, so large batches are limited by
memory bandwidth: the plain NumPy path (:func:`spinimpact.core.rebound`) makes
about a dozen passes over memory with temporaries, while these kernels read
each input once and write each output once, in parallel over cores.

They perform the same IEEE operations in the same order as the NumPy kernels
(no fast-math, no fused multiply-add), so the results are identical bit for
bit; ``tests/core/test_fused.py`` checks this over all regimes. Without Numba
:func:`rebound` takes the NumPy path, and for one impact the law on floats; with it, arrays
below :data:`THRESHOLD` impacts run a serial kernel on the calling thread.

The compiled kernels are cached on disk (Numba's ``cache=True``) where Numba finds a
writable place (``__pycache__`` beside this file, the user's cache folder under
``HOME``, or ``NUMBA_CACHE_DIR``); where it finds none (a read-only installation and a
read-only ``HOME``) they are compiled in memory on first use instead
(``tests/io/test_sweep_numba_cache.py``).
"""

from __future__ import annotations

import math

import numpy as np

from .._limits import address_limit
from .._validation import require
from .kinematics import rebound as _rebound_numpy
from .scalar import rebound as _scalar_rebound

__all__ = ["HAVE_NUMBA", "THRESHOLD", "rebound"]

_NUMBA_ERROR: ImportError | None = None  #: why Numba did not import, if it did not
try:  # pragma: no cover - depends on the optional extra
    import numba

    HAVE_NUMBA = True
except ImportError as err:  # pragma: no cover
    numba = None
    HAVE_NUMBA = False
    _NUMBA_ERROR = err


def _start_thread_pool() -> None:
    """Start Numba's worker threads now, while the process holds little memory.

    Numba starts them on the first parallel call, and its default threading layer ignores a
    thread that fails to start: the call then waits forever for it. Under an address-space
    limit a batch reaches that first call with most of the limit in use (a chunk read), and
    a thread's stack no longer fits; started at import, they do.
    """
    try:
        from numba.np.ufunc import parallel

        parallel._launch_threads()
    except Exception:  # noqa: BLE001 - the first parallel call meets (and reports) it again
        pass


if HAVE_NUMBA and address_limit() is not None:
    _start_thread_pool()


def _njit(function, *, parallel=True):
    """``numba.njit`` with an on-disk cache, or without one where none can be written.

    Numba looks for a cache folder when the function is decorated, at import, and raises
    ``RuntimeError("cannot cache function ...: no locator available ...")`` if no
    candidate is writable; the kernels then compile in memory on their first call.
    ``parallel=False`` gives a kernel that runs on the calling thread (no thread pool to
    wake: small arrays).
    """
    options = {"parallel": parallel, "fastmath": False, "error_model": "numpy"}
    try:
        return numba.njit(cache=True, **options)(function)
    except RuntimeError as err:  # pragma: no cover - depends on the file system
        if "no locator available" not in str(err):
            raise
        return numba.njit(cache=False, **options)(function)


if HAVE_NUMBA:
    # Both kernels are branch-free (both forms of f1 computed, then selected) so
    # that LLVM vectorizes them; each line mirrors an expression of
    # kinematics.tangential_impulse / rebound exactly, in the same order.

    @_njit
    def _rebound_scalar(vx, vy, omega, m, r, z, f_mu, k, out_vx, out_vy, out_om):
        c = (1.0 + k) * z * f_mu  # sticks: |u| <= (1 + kappa) zeta mu |vy| (eq. 4.6)
        zm1 = z - 1.0
        mr = m * r
        for i in numba.prange(out_vx.size):
            v = vy[i]
            u = vx[i] + r * omega[i]  # eq. 4.4
            stick = -m * u / z  # -mu sign(u) tau_* = -m u/zeta (eq. 4.3)
            slide = -f_mu * np.sign(u) * ((1.0 + k) * (-m * v))  # -mu sign(u) tau_1 (eq. 5.7)
            f1 = (stick if abs(u) <= c * abs(v) else slide) + 0.0
            out_vx[i] = vx[i] + f1 / m  # eq. 2.1
            out_vy[i] = -k * v + 0.0  # eq. 3.4
            out_om[i] = omega[i] + zm1 * f1 / mr  # eq. 2.3

    @numba.njit(inline="always")
    def _rebound_at(i, vx, vy, omega, mass, radius, zeta, mu, kappa, out_vx, out_vy, out_om):
        """Impact ``i`` of the array kernels (inlined into each loop)."""
        m, r, z, f_mu, k, v = mass[i], radius[i], zeta[i], mu[i], kappa[i], vy[i]
        u = vx[i] + r * omega[i]
        stick = -m * u / z
        slide = -f_mu * np.sign(u) * ((1.0 + k) * (-m * v))
        f1 = (stick if abs(u) <= (1.0 + k) * z * f_mu * abs(v) else slide) + 0.0
        out_vx[i] = vx[i] + f1 / m
        out_vy[i] = -k * v + 0.0
        out_om[i] = omega[i] + (z - 1.0) * f1 / (m * r)

    @_njit
    def _rebound_arrays(vx, vy, omega, mass, radius, zeta, mu, kappa, out_vx, out_vy, out_om):
        for i in numba.prange(out_vx.size):
            _rebound_at(i, vx, vy, omega, mass, radius, zeta, mu, kappa, out_vx, out_vy, out_om)

    def _serial(vx, vy, omega, mass, radius, zeta, mu, kappa, out_vx, out_vy, out_om):
        for i in range(out_vx.size):
            _rebound_at(i, vx, vy, omega, mass, radius, zeta, mu, kappa, out_vx, out_vy, out_om)

    _rebound_serial = _njit(_serial, parallel=False)


#: Fewest impacts for which ``fused=None`` runs the parallel Numba kernel. One impact takes
#: the law on floats (a few microseconds); below this, with Numba, a serial Numba kernel on
#: the calling thread (no thread pool to wake: the parallel kernel's floor is about 30 us,
#: with a tail of several milliseconds whenever other processes hold the cores), and the
#: NumPy path without Numba. Same bits on every path.
THRESHOLD = 10_000


def _frozen(a):
    """A read-only flat view of ``a`` (never the caller's array itself): broadcast views
    must not be written, and Numba asks for the flag to be explicit (else NumPy warns)."""
    v = (a if a.ndim == 1 else np.ascontiguousarray(a).reshape(-1)).view()
    v.setflags(write=False)
    return v


def rebound(vx, vy, omega, mass, radius, zeta, mu, kappa, *, fused=None, out=None):
    """Rebound ``(vx+, vy+, omega+)`` in one pass over memory.

    Same arguments and results as :func:`spinimpact.core.rebound` (without ``f1``), all
    broadcast to one shape; the results are float64 arrays of that shape (0-d for one
    impact), equal bit for bit whichever path computes them. ``fused=None`` picks the
    fastest: the per-contact law on floats (:func:`spinimpact.core.scalar.rebound`) for one
    impact, a serial Numba kernel below :data:`THRESHOLD` impacts, the parallel Numba kernel
    from there on, and the NumPy path without Numba; ``False`` forces the NumPy path; ``True``
    requires Numba and runs its parallel kernel. ``out`` may give three preallocated
    C-contiguous float64 arrays of the broadcast shape to write into (avoids page-faulting
    fresh memory on every call in a loop over chunks).

    Raises
    ------
    ImportError
        For ``fused=True`` without Numba, naming the ``[fast]`` extra.
    ValueError
        For an ``out`` that is not three C-contiguous float64 arrays of the shape.

    Examples
    --------
    >>> vx, vy, omega = rebound(2.0, -3.0, 0.0, 1.0, 0.1, 3.5, 0.5, 0.8)
    >>> vx.shape, round(float(vx) / 2.0, 12)   # the 5/7 rule of a solid sphere
    ((), 0.714285714286)
    """
    if fused and not HAVE_NUMBA:
        require("numba", "fused=True")  # raises ImportError naming the [fast] extra
        raise ImportError(f"fused=True needs numba, which failed to import: {_NUMBA_ERROR}")
    given = [np.asarray(a, dtype=np.float64) for a in (vx, vy, omega, mass, radius, zeta, mu,
                                                         kappa)]  # fmt: skip
    shape = np.broadcast_shapes(*(a.shape for a in given))
    if out is not None and (len(out) != 3 or any(
        o.shape != shape or not o.flags.c_contiguous or o.dtype != np.float64 for o in out
    )):  # fmt: skip
        raise ValueError(f"out must be three C-contiguous float64 arrays of shape {shape}")
    size = math.prod(shape)
    serial = fused is None and HAVE_NUMBA and 1 < size < THRESHOLD
    if fused is None:
        fused = HAVE_NUMBA and size >= THRESHOLD
    if not fused and not serial:
        if size == 1:  # one impact: floats, not 0-d arrays (a dozen NumPy calls saved)
            values = _scalar_rebound(*(a.item() for a in given))[:3]
        else:
            values = _rebound_numpy(*np.broadcast_arrays(*given))[:3]
        if out is None:
            out = tuple(np.empty(shape) for _ in range(3))
        for target, value in zip(out, values, strict=True):
            target[...] = value
        return tuple(out)
    args = np.broadcast_arrays(*given)
    if out is None:
        out = tuple(np.empty(shape) for _ in range(3))
    targets = [o.reshape(-1) for o in out]
    velocities = [_frozen(a) for a in args[:3]]
    params = [np.asarray(p, dtype=np.float64) for p in (mass, radius, zeta, mu, kappa)]
    if serial:
        _rebound_serial(*velocities, *(_frozen(a) for a in args[3:]), *targets)
    elif all(p.size == 1 for p in params):  # the common sweep: one body, one surface
        _rebound_scalar(*velocities, *(float(p.reshape(-1)[0]) for p in params), *targets)
    else:
        # 1-D broadcast views (stride 0 for a repeated value) go in as they are:
        # copying them would cost more memory traffic than the kernel itself.
        _rebound_arrays(*velocities, *(_frozen(a) for a in args[3:]), *targets)
    return tuple(out)
