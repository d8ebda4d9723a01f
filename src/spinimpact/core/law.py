"""The compiled per-contact law: scalar impact functions for your own ``numba.njit`` loops.

A DEM, robotics or game code meets one contact at a time, inside its own compiled loop.
The functions here take plain floats (one contact) and return floats, ints, bools or
tuples of them; they are the functions of :mod:`spinimpact.core.scalar` (and of the
3D sphere law, :mod:`spinimpact.core.scalar3d`, and the planar law,
:mod:`spinimpact.core.scalar_planar`), registered with Numba's
``register_jitable`` when Numba is installed (the ``[fast]`` extra). So the same function
object is

* plain Python when called from Python (no compilation, no dispatch cost), and
* compiled into the caller when called from ``numba.njit`` code (inlined by LLVM where
  it pays), at a few nanoseconds per contact (``make bench``).

Without Numba they are the same plain Python functions. They perform the array kernels'
IEEE operations in the same order, so their results equal those of
:func:`spinimpact.solve` and :mod:`spinimpact.core`'s kernels bit for bit
(``tests/core/test_law.py``), provided the calling code is compiled without
``fastmath`` (which lets LLVM reorder and contract operations).

The short public path is :mod:`spinimpact.contact_law`; ``docs/compiled.md`` shows a loop
over a million contacts. Nothing is validated here (a compiled loop has no room for it):
pass what :func:`spinimpact.solve` would accept (``vy < 0``, ``mu >= 0``, ``kappa`` in
``[0, 1]``, positive mass and radius, ``zeta > 1``).

Functions
---------
The paper's bodies (a disk, ring, sphere, shell or spool touching below its centre;
arguments ``vx, vy, omega, mass, radius, zeta, mu, kappa``):
``rebound`` (``vx+, vy+, omega+, f1``), ``regime`` (code into
:data:`~spinimpact.core.impulse.REGIMES`), ``impulses`` (``tau0, tau_star, tau1, f1``),
``dissipated_energy``, ``kinetic_energy``, ``outcome_flags``.

Any contact with ``W_tn = 0`` (the seam; arguments ``slip, vy, mass, zeta, mu, kappa``):
``contact_impulses``, ``regime_code``, ``contact_works``, ``contact_dissipated_energy``,
``contact_min_energy_impulse``, ``contact_impact`` (all of them at once), ``rebound_slip``,
``impulse_ratio``, ``stick_impulse``, ``work_tangential``, ``work_ratio_tangential``,
``min_energy_case``, ``sign``.

Spheres in 3D (:mod:`spinimpact.core.scalar3d`): ``sphere_rebound``, ``sphere_regime``,
``sphere_dissipated_energy``, ``sphere_contact``, and two spheres, ``pair_rebound``,
``pair_parameters``.

Whether there is an impact at all: ``approaching(vy)`` (``c_n < 0``; the paper's bodies
and any contact of the seam), ``sphere_approaching``, ``pair_approaching``.

Tangential compliance laws (:mod:`spinimpact.core.scalar_tangential`,
:mod:`spinimpact.core.scalar_stronge`; ``solve(..., tangential=Walton(beta0))`` and
``Stronge(...)``): ``walton_rebound`` and ``stronge_rebound`` (the paper's bodies, arguments
of ``rebound`` then ``beta0`` or ``stiffness_ratio``; ``vx+, vy+, omega+, f1``),
``sphere_walton_rebound`` and ``sphere_stronge_rebound`` (a sphere in 3D, arguments of
``sphere_rebound`` then the law's parameter), ``walton_contact`` (``slip_after, stuck``) and
``stronge_contact`` (``slip_after, stuck, transitions``) on the seam.

Micro-slip (:mod:`spinimpact.core.scalar_mdr`; ``solve(...,
tangential=MindlinDeresiewicz(...))`` where the precomputed table holds): ``mdr_rebound``,
``sphere_mdr_rebound`` (arguments of ``walton_rebound`` / ``sphere_walton_rebound`` with
Mindlin's ``stiffness_ratio``, then the table), ``mdr_contact`` (``slip_after, stuck``),
``mdr_usable`` (whether the table holds for the impact; the others return NaN where it does
not) and ``mdr_table()`` (the table's arrays, the last argument of each).

Planar bodies touching off their centre (:mod:`spinimpact.core.scalar_planar`, the coupled
collision matrix): ``planar_rebound`` (a free body), ``planar_process`` (any ``W``: a
pendulum's too), ``planar_state_at``, ``planar_work``, ``planar_min_energy_impulse``.
"""

from __future__ import annotations

from . import impulse, kinematics, scalar, scalar3d, scalar_mdr, scalar_planar, scalar_stronge
from . import scalar_tangential as tangential
from .scalar import *  # noqa: F403 - the law's public names
from .scalar3d import *  # noqa: F403
from .scalar_mdr import *  # noqa: F403
from .scalar_planar import *  # noqa: F403
from .scalar_tangential import *  # noqa: F403

__all__ = [
    "HAVE_NUMBA",
    *scalar.__all__,
    *scalar3d.__all__,
    *scalar_planar.__all__,
    *tangential.__all__,
    *scalar_mdr.__all__,
]

#: Functions of the array modules written for floats and arrays alike (operators only), which
#: the law on floats calls: the formula is written once, for both.
_SHARED = (
    impulse.compression_impulse,
    impulse.total_impulse,
    impulse.rebound_normal_velocity,
    kinematics.slip_velocity,
)

try:  # pragma: no cover - depends on the optional extra
    from numba.extending import register_jitable

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover
    HAVE_NUMBA = False


def _functions(module):
    """Every function defined in ``module``, public and private (helpers must be
    registered too, so that compiled callers can resolve the calls inside the law)."""
    return [
        f for f in vars(module).values()
        if callable(f) and getattr(f, "__module__", None) == module.__name__
    ]  # fmt: skip


if HAVE_NUMBA:  # pragma: no branch
    for _m in (scalar, scalar3d, scalar_planar, scalar_stronge, tangential):
        for _f in _functions(_m):
            register_jitable(_f)
    # The micro-slip law passes the table's arrays down three calls. Inlined in Numba's IR,
    # those calls cost no reference counting of the arrays (about 50 ns a call otherwise);
    # the small sums under share_of are left to LLVM (inlined in the IR as well, they take
    # minutes to compile).
    _INLINED = (scalar_mdr.mdr_rebound, scalar_mdr.sphere_mdr_rebound, scalar_mdr.mdr_contact,
                scalar_mdr.mdr_usable, scalar_mdr.share_of)  # fmt: skip
    for _f in _functions(scalar_mdr):
        register_jitable(inline="always")(_f) if _f in _INLINED else register_jitable(_f)
    for _f in _SHARED:
        register_jitable(_f)  # registers the function object itself; returns it unchanged
