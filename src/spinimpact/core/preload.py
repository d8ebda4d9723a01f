"""Load every compiled kernel before a run fills its memory (under ``ulimit -v``).

Numba loads a kernel (from its on-disk cache, or compiling it) on the first call, and
LLVM places the machine code in freshly mapped memory. A batch makes that first call
with a chunk already read; under an address-space limit the mapping can then fail,
and LLVM aborts the process ("LLVM ERROR: Unable to allocate section memory"), which
no handler can catch. :func:`load_kernels` makes one tiny call of each kernel first,
while the process holds little memory, so that a chunk too large for the limit is met
by Python's ``MemoryError`` (a one-line error naming ``--chunk-size``) instead.
"""

from __future__ import annotations

from .fused import HAVE_NUMBA

__all__ = ["load_kernels"]


def load_kernels() -> bool:
    """Call each compiled kernel once on one impact (all of them together took 0.9 to 1.7 s
    when cached on disk, on a 2-core machine); return whether there were kernels to load (Numba
    is installed)."""
    if not HAVE_NUMBA:
        return False
    import numpy as np

    from . import fused, fused_impact, fused_planar, fused_sphere, rigid3d

    one = np.ones(1)
    fused.rebound(one, -one, one, one, one, 2 * one, one, one, fused=True)
    fused.rebound(one, -one, one, one, one, 2 * one, one, one)  # the serial kernel
    fused_impact.impact_fields(1.0, -1.0, 1.0, 1.0, 0.1, 0.05, 1.25, 0.3, 0.8)
    fused_planar.planar_fields(0, 0, *([one] * len(fused_planar.INPUTS)))
    down, zero = np.array([0.0, 0.0, -1.0]), np.zeros(3)
    up = np.array([0.0, 0.0, 1.0])
    fused_sphere.sphere_fields(down, zero, up, zero, 1.0, 0.1, 0.004, 3.5, 0.3, 0.8)
    fused_sphere.pair_fields(down, zero, zero, zero, up, 1.0, 0.1, 0.004, 1.0, 0.1, 0.004,
                             0.3, 0.8)  # fmt: skip
    rigid3d.contact_impact(np.eye(3), np.array([[0.3, 0.2, -1.0]]), 0.3, 0.8)
    return True
