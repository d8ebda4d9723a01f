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

import math
from typing import Any

import numpy as np

from . import law as _law  # registers the per-contact law for compiled callers
from .fused import HAVE_NUMBA, _njit

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


def _energy(m, j, v, w):
    dot = _scalar3d._dot
    return 0.5 * m * dot(v, v) + 0.5 * j * dot(w, w)


def _sphere_kernel(vec, s_vec, num, s_num, out, code, grips):
    """Every sphere impact: vectors ``vec[k][i * s_vec[k]]`` (velocity, spin, normal,
    surface velocity), numbers ``num[k][i * s_num[k]]`` (mass, radius, inertia, zeta, mu,
    kappa); the float fields into ``out[:, i]``."""
    dot = _scalar3d._dot
    for i in numba.prange(code.shape[0]):
        v = _three(vec[0], i, s_vec[0])
        w = _three(vec[1], i, s_vec[1])
        n = _three(vec[2], i, s_vec[2])
        vs = _three(vec[3], i, s_vec[3])
        m, radius, inertia = num[0][i * s_num[0]], num[1][i * s_num[1]], num[2][i * s_num[2]]
        zeta, mu, k = num[3][i * s_num[3]], num[4][i * s_num[4]], num[5][i * s_num[5]]
        cn, ct, speed, e = _scalar3d.sphere_contact(v, w, n, radius, vs)
        (tau0, tau_star, tau1, f1, _a, _b, c, wcn, wct, wrn, wrt, loss, _c, _d) = (
            _scalar.contact_impact(speed, cn, m, zeta, mu, k)
        )
        friction = (f1 * e[0], f1 * e[1], f1 * e[2])
        total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
        v1 = (v[0] + total[0] / m, v[1] + total[1] / m, v[2] + total[2] / m)
        w1 = _scalar3d._spin_change(w, n, radius, inertia, friction)
        cn1, ct1, _e, _f = _scalar3d.sphere_contact(v1, w1, n, radius, vs)
        e0 = _energy(m, inertia, v, w)
        vrel = (v[0] - vs[0], v[1] - vs[1], v[2] - vs[2])
        e0_rel = _energy(m, inertia, vrel, w)
        stuck = speed <= (1.0 + k) * zeta * mu * abs(cn)
        rel = (v1[0] - vs[0], v1[1] - vs[1], v1[2] - vs[2])
        up = dot(rel, n)
        along = (rel[0] - up * n[0], rel[1] - up * n[1], rel[2] - up * n[2])
        travel = math.sqrt(dot(along, along))
        if travel > 0.0:
            et = (along[0] / travel, along[1] / travel, along[2] / travel)
            top = dot(w1, _scalar3d._cross(n, et))
            gyro = dot(w1, et)
        else:
            top = gyro = np.nan
        eta2 = -wrn / wcn
        out[0, i] = cn
        for j in range(3):
            out[1 + j, i] = ct[j]
            out[4 + j, i] = v1[j]
            out[7 + j, i] = w1[j]
            out[10 + j, i] = 0.0 if stuck else ct1[j]
            out[17 + j, i] = friction[j]
        out[13, i] = cn1
        out[14, i] = tau0
        out[15, i] = tau_star
        out[16, i] = tau1
        out[20, i] = (-f1 + 0.0) / tau1
        out[21, i] = e0
        out[22, i] = _energy(m, inertia, v1, w1)
        out[23, i] = loss
        out[24, i] = loss / e0_rel
        out[25, i] = wcn
        out[26, i] = wct
        out[27, i] = wrn
        out[28, i] = wrt
        out[29, i] = -cn1 / cn
        out[30, i] = (tau1 - tau0) / tau0
        out[31, i] = math.sqrt(eta2 if eta2 > 0.0 else 0.0)
        out[32, i] = math.sqrt(dot(v1, v1))
        out[33, i] = up
        out[34, i] = travel
        out[35, i] = top
        out[36, i] = dot(w1, n)
        out[37, i] = gyro
        code[i] = c
        grips[i] = stuck


def _pair_kernel(vec, s_vec, num, s_num, out, code, grips):
    """Every impact of two spheres: vectors (velocity1, spin1, velocity2, spin2, normal),
    numbers (mass1, radius1, inertia1, mass2, radius2, inertia2, mu, kappa)."""
    dot, cross = _scalar3d._dot, _scalar3d._cross
    for i in numba.prange(code.shape[0]):
        v1 = _three(vec[0], i, s_vec[0])
        w1 = _three(vec[1], i, s_vec[1])
        v2 = _three(vec[2], i, s_vec[2])
        w2 = _three(vec[3], i, s_vec[3])
        n = _three(vec[4], i, s_vec[4])
        m1, r1, j1 = num[0][i * s_num[0]], num[1][i * s_num[1]], num[2][i * s_num[2]]
        m2, r2, j2 = num[3][i * s_num[3]], num[4][i * s_num[4]], num[5][i * s_num[5]]
        mu, k = num[6][i * s_num[6]], num[7][i * s_num[7]]
        r2n = (r2 * n[0], r2 * n[1], r2 * n[2])
        a = cross(w2, r2n)
        cn, ct, speed, e = _scalar3d.sphere_contact(
            v1, w1, n, r1, (v2[0] + a[0], v2[1] + a[1], v2[2] + a[2])
        )
        m, zeta = _scalar3d.pair_parameters(m1, j1, r1, m2, j2, r2)
        (tau0, tau_star, tau1, f1, _a, _b, c, wcn, wct, wrn, wrt, loss, _c, _d) = (
            _scalar.contact_impact(speed, cn, m, zeta, mu, k)
        )
        friction = (f1 * e[0], f1 * e[1], f1 * e[2])
        total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
        v1b = (v1[0] + total[0] / m1, v1[1] + total[1] / m1, v1[2] + total[2] / m1)
        v2b = (v2[0] - total[0] / m2, v2[1] - total[1] / m2, v2[2] - total[2] / m2)
        w1b = _scalar3d._spin_change(w1, n, r1, j1, friction)
        w2b = _scalar3d._spin_change(w2, n, r2, j2, friction)
        b = cross(w2b, r2n)
        cn1, ct1, _e, _f = _scalar3d.sphere_contact(
            v1b, w1b, n, r1, (v2b[0] + b[0], v2b[1] + b[1], v2b[2] + b[2])
        )
        e0 = _energy(m1, j1, v1, w1) + _energy(m2, j2, v2, w2)
        p = (m1 * v1[0] + m2 * v2[0], m1 * v1[1] + m2 * v2[1], m1 * v1[2] + m2 * v2[2])
        e_cm = e0 - 0.5 * dot(p, p) / (m1 + m2)
        stuck = speed <= (1.0 + k) * zeta * mu * abs(cn)
        s1, s2 = math.sqrt(dot(v1b, v1b)), math.sqrt(dot(v2b, v2b))
        sine = cross(v1b, v2b)
        eta2 = -wrn / wcn
        out[0, i] = cn
        for j in range(3):
            out[1 + j, i] = ct[j]
            out[4 + j, i] = v1b[j]
            out[7 + j, i] = w1b[j]
            out[10 + j, i] = v2b[j]
            out[13 + j, i] = w2b[j]
            out[16 + j, i] = 0.0 if stuck else ct1[j]
            out[23 + j, i] = friction[j]
        out[19, i] = cn1
        out[20, i] = tau0
        out[21, i] = tau_star
        out[22, i] = tau1
        out[26, i] = (-f1 + 0.0) / tau1
        out[27, i] = e0
        out[28, i] = _energy(m1, j1, v1b, w1b) + _energy(m2, j2, v2b, w2b)
        out[29, i] = loss
        out[30, i] = loss / e_cm
        out[31, i] = wcn
        out[32, i] = wct
        out[33, i] = wrn
        out[34, i] = wrt
        out[35, i] = -cn1 / cn
        out[36, i] = (tau1 - tau0) / tau0
        out[37, i] = math.sqrt(eta2 if eta2 > 0.0 else 0.0)
        if s1 > 0 and s2 > 0:
            out[38, i] = math.sqrt(dot(sine, sine))
            out[39, i] = dot(v1b, v2b)
        else:
            out[38, i] = np.nan
            out[39, i] = np.nan
        code[i] = c
        grips[i] = stuck


if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    _inline = numba.njit(inline="always", error_model="numpy")
    _three = _inline(_three)
    _energy = _inline(_energy)
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


def _number_rows(a: Any, shape: tuple[int, ...]) -> tuple[np.ndarray, int]:
    """A read-only 1-D float64 input and its step: 0 for one value repeated."""
    a = np.broadcast_to(np.asarray(a, dtype=np.float64), shape).reshape(-1)
    if a.size <= 1 or a.strides[0] == 0:
        col, step = (np.array(a[:1]) if a.size else np.zeros(1)), 0
    else:
        col, step = np.ascontiguousarray(a), 1
    col.setflags(write=False)
    return col, step


def _run(kernel, floats, vectors, numbers, shape):
    if not HAVE_NUMBA:
        from .._validation import require

        require("numba", "the fused sphere kernels")
    vec, s_vec = zip(*(_vector_rows(a, shape) for a in vectors), strict=True)
    num, s_num = zip(*(_number_rows(a, shape) for a in numbers), strict=True)
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
