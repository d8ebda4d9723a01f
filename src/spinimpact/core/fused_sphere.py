"""Every field of many sphere impacts in one pass over memory (optional ``[fast]`` extra).

The array paths of :func:`spinimpact.solve_sphere` and :func:`spinimpact.solve_pair`
evaluate each quantity over whole arrays (:mod:`spinimpact.core.sphere3d`,
:mod:`spinimpact.core.impulse`, :mod:`spinimpact.core.works`): several dozen passes over
memory, with a temporary array for each intermediate, for closed forms that cost a few
nanoseconds each. :func:`sphere_fields` and :func:`pair_fields` compute every field of one
impact after another instead, reading each input once and writing each output once, in
parallel over cores.

Each impact is solved by the per-contact law on floats (:mod:`spinimpact.core.scalar3d`,
:mod:`spinimpact.core.scalar`), which performs the array kernels' IEEE operations in their
order, and the remaining fields are the expressions of :mod:`spinimpact.model._fast_sphere`
(one impact on floats, equal to the array path bit for bit). So every field equals the
array path's bit for bit (``tests/core/test_fused_sphere.py``). Two fields end in an
``atan2``, which is left to the caller's :func:`numpy.arctan2` (the C library's ``atan2``,
which a compiled kernel calls, may differ from NumPy's in the last bit): the kernels return
its two arguments.

Compiled kernels are cached on disk as those of :mod:`spinimpact.core.fused` are. Nothing
is validated here.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import law as _law  # registers the per-contact law for compiled callers
from .fused import HAVE_NUMBA, _njit
from .fused_impact import _column

__all__ = ["HAVE_NUMBA", "PAIR_FLOATS", "SPHERE_FLOATS", "pair_fields", "sphere_fields"]

if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    import numba

_scalar = _law.scalar
_scalar3d = _law.scalar3d

_VECTOR = ("x", "y", "z")
_STATE = ("vx", "vy", "vz", "wx", "wy", "wz")

#: The float rows of :func:`sphere_fields`' table, in order (``rebound_up`` and
#: ``rebound_along`` are the arguments of the rebound angle's ``atan2``).
SPHERE_FLOATS = (
    "normal_velocity_before",
    *(f"slip_before_{c}" for c in _VECTOR),
    *(f"after_{c}" for c in _STATE),
    *(f"slip_after_{c}" for c in _VECTOR),
    "normal_velocity_after", "tau0", "tau_star", "tau1",
    *(f"friction_impulse_{c}" for c in _VECTOR),
    "impulse_ratio", "kinetic_energy_before", "kinetic_energy_after", "dissipated_energy",
    "dissipated_fraction", "work_compression_normal", "work_compression_tangential",
    "work_restitution_normal", "work_restitution_tangential", "newton_restitution",
    "poisson_restitution", "energetic_restitution", "rebound_speed", "rebound_up",
    "rebound_along", "topspin", "sidespin", "gyrospin",
)  # fmt: skip

#: The float rows of :func:`pair_fields`' table (``paths_sine`` and ``paths_cosine`` are
#: the arguments of the angle between the paths' ``atan2``, NaN where it is undefined).
PAIR_FLOATS = (
    "normal_velocity_before",
    *(f"slip_before_{c}" for c in _VECTOR),
    *(f"after1_{c}" for c in _STATE),
    *(f"after2_{c}" for c in _STATE),
    *(f"slip_after_{c}" for c in _VECTOR),
    "normal_velocity_after", "tau0", "tau_star", "tau1",
    *(f"friction_impulse_{c}" for c in _VECTOR),
    "impulse_ratio", "kinetic_energy_before", "kinetic_energy_after", "dissipated_energy",
    "dissipated_fraction", "work_compression_normal", "work_compression_tangential",
    "work_restitution_normal", "work_restitution_tangential", "newton_restitution",
    "poisson_restitution", "energetic_restitution", "paths_sine", "paths_cosine",
)  # fmt: skip


def _three(a, i, s):
    return (a[i * s, 0], a[i * s, 1], a[i * s, 2])


def _put(out, k, i, vector):
    out[k, i] = vector[0]
    out[k + 1, i] = vector[1]
    out[k + 2, i] = vector[2]


def _sphere_kernel(vec, s_vec, num, s_num, out, code, grips):
    """Every sphere impact: vectors ``vec[k][i * s_vec[k]]`` (velocity, spin, normal,
    surface velocity), numbers ``num[k][i * s_num[k]]`` (mass, radius, inertia, zeta, mu,
    kappa); the float fields into ``out[:, i]``, by
    :func:`~spinimpact.core.scalar3d.sphere_impact_fields`."""
    for i in numba.prange(code.shape[0]):
        (cn, ct, v1, w1, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1, loss,
         fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, speed, up, along, top,
         side, gyro, c, stuck) = _scalar3d.sphere_impact_fields(
            _three(vec[0], i, s_vec[0]), _three(vec[1], i, s_vec[1]),
            _three(vec[2], i, s_vec[2]), _three(vec[3], i, s_vec[3]),
            num[0][i * s_num[0]], num[1][i * s_num[1]], num[2][i * s_num[2]],
            num[3][i * s_num[3]], num[4][i * s_num[4]], num[5][i * s_num[5]],
        )  # fmt: skip
        out[0, i] = cn
        _put(out, 1, i, ct)
        _put(out, 4, i, v1)
        _put(out, 7, i, w1)
        _put(out, 10, i, slip1)
        for k, x in enumerate((cn1, tau0, tau_star, tau1)):
            out[13 + k, i] = x
        _put(out, 17, i, friction)
        for k, x in enumerate((ratio, e0, e1, loss, fraction, wcn, wct, wrn, wrt, newton,
                               poisson, energetic, speed, up, along, top, side, gyro)):  # fmt: skip
            out[20 + k, i] = x
        code[i] = c
        grips[i] = stuck


def _pair_kernel(vec, s_vec, num, s_num, out, code, grips):
    """Every impact of two spheres: vectors (velocity1, spin1, velocity2, spin2, normal),
    numbers (mass1, radius1, inertia1, mass2, radius2, inertia2, mu, kappa), by
    :func:`~spinimpact.core.scalar3d.pair_impact_fields`."""
    for i in numba.prange(code.shape[0]):
        (cn, ct, v1, w1, v2, w2, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1,
         loss, fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, sine, cosine, c,
         stuck) = _scalar3d.pair_impact_fields(
            _three(vec[0], i, s_vec[0]), _three(vec[1], i, s_vec[1]),
            _three(vec[2], i, s_vec[2]), _three(vec[3], i, s_vec[3]),
            _three(vec[4], i, s_vec[4]), num[0][i * s_num[0]], num[1][i * s_num[1]],
            num[2][i * s_num[2]], num[3][i * s_num[3]], num[4][i * s_num[4]],
            num[5][i * s_num[5]], num[6][i * s_num[6]], num[7][i * s_num[7]],
        )  # fmt: skip
        out[0, i] = cn
        _put(out, 1, i, ct)
        _put(out, 4, i, v1)
        _put(out, 7, i, w1)
        _put(out, 10, i, v2)
        _put(out, 13, i, w2)
        _put(out, 16, i, slip1)
        for k, x in enumerate((cn1, tau0, tau_star, tau1)):
            out[19 + k, i] = x
        _put(out, 23, i, friction)
        for k, x in enumerate((ratio, e0, e1, loss, fraction, wcn, wct, wrn, wrt, newton,
                               poisson, energetic, sine, cosine)):  # fmt: skip
            out[26 + k, i] = x
        code[i] = c
        grips[i] = stuck


if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    _inline = numba.njit(inline="always", error_model="numpy")
    _three = _inline(_three)
    _put = _inline(_put)
    _sphere_kernel = _njit(_sphere_kernel)
    _pair_kernel = _njit(_pair_kernel)


def _vector_rows(a: Any, shape: tuple[int, ...]) -> tuple[np.ndarray, int]:
    """A read-only ``(n, 3)`` float64 input and its step: 0 for one vector repeated."""
    a = np.broadcast_to(np.asarray(a, dtype=np.float64), (*shape, 3)).reshape(-1, 3)
    if a.shape[0] <= 1 or a.strides[0] == 0:
        rows, step = (np.ascontiguousarray(a[:1]) if a.shape[0] else np.zeros((1, 3))), 0
    else:
        rows, step = np.ascontiguousarray(a), 1
    rows.setflags(write=False)
    return rows, step


def _run(kernel, floats, vectors, numbers, shape):
    if not HAVE_NUMBA:
        from .._validation import require

        require("numba", "the fused sphere kernels")
    vec, s_vec = zip(*(_vector_rows(a, shape) for a in vectors), strict=True)
    num, s_num = zip(*(_column(a, shape) for a in numbers), strict=True)
    n = int(np.prod(shape, dtype=np.int64))
    out = np.empty((len(floats), n))
    code = np.empty(n, dtype=np.int8)
    grips = np.empty(n, dtype=np.bool_)
    kernel(vec, np.asarray(s_vec, np.int64), num, np.asarray(s_num, np.int64), out, code, grips)
    fields = {name: out[k].reshape(shape) for k, name in enumerate(floats)}
    return fields, code.reshape(shape), grips.reshape(shape)


def sphere_fields(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta, mu,
                  kappa) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray]:  # fmt: skip
    """Every field of many sphere-on-plane impacts, equal bit for bit to the array path's.

    Parameters
    ----------
    velocity, spin, normal, surface_velocity : array_like, shape (..., 3)
        As for :func:`spinimpact.core.scalar3d.sphere_rebound` (``normal`` of unit length);
        broadcast with the numbers to the impacts' ``shape``.
    mass, radius, inertia, zeta, mu, kappa : float or array_like
        Mass (kg), radius (m), moment of inertia (kg m^2), ``zeta = 1 + m R^2 / J``,
        friction and restitution coefficients.

    Returns
    -------
    fields : dict
        :data:`SPHERE_FLOATS` -> float64 array of ``shape`` (rows of one table).
    code : ndarray of int8
        The regime code (into :data:`spinimpact.core.REGIMES`).
    grips : ndarray of bool
        Whether the ball leaves without slip.

    Raises
    ------
    ImportError
        Without Numba, naming the ``[fast]`` extra.
    """
    vectors = (velocity, spin, normal, surface_velocity)
    numbers = (mass, radius, inertia, zeta, mu, kappa)
    shape = np.broadcast_shapes(*(np.shape(a)[:-1] for a in vectors),
                                *(np.shape(a) for a in numbers))  # fmt: skip
    return _run(_sphere_kernel, SPHERE_FLOATS, vectors, numbers, shape)


def pair_fields(velocity1, spin1, velocity2, spin2, normal, mass1, radius1, inertia1, mass2,
                radius2, inertia2, mu, kappa) -> tuple[dict, np.ndarray, np.ndarray]:  # fmt: skip
    """Every field of many impacts of two spheres, as :func:`sphere_fields` (rows
    :data:`PAIR_FLOATS`); ``normal`` is the unit normal from sphere 2's centre to sphere
    1's, as :func:`spinimpact.core.scalar3d.pair_rebound` takes it."""
    vectors = (velocity1, spin1, velocity2, spin2, normal)
    numbers = (mass1, radius1, inertia1, mass2, radius2, inertia2, mu, kappa)
    shape = np.broadcast_shapes(*(np.shape(a)[:-1] for a in vectors),
                                *(np.shape(a) for a in numbers))  # fmt: skip
    return _run(_pair_kernel, PAIR_FLOATS, vectors, numbers, shape)
