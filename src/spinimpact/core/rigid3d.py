"""Any rigid body in 3D at one contact: collision matrices and many impacts at once.

:func:`contact_impact` solves many impacts given in the contact frame (the collision
matrix ``W`` and the contact point's velocity) by Keller's method
(:func:`spinimpact.core.scalar_rigid.rigid_impact`, whose notes give the theory), one
impact after another in a compiled kernel, in parallel over cores (the ``[fast]`` extra,
Numba). Without Numba one impact is solved in Python and arrays are refused with the
extra's name: the sliding phase is an integration per impact, which NumPy cannot spread
over an array without a loop in Python.

:func:`body_matrix` gives ``W`` for one body, :func:`frame` the contact frame of a
surface normal; two bodies touching add their matrices (``W = W_1 + W_2``), and a body
known to an engine by its generalized mass matrix ``M`` and contact Jacobian ``J`` has
``W = J M^-1 J^T`` (:func:`jacobian_matrix`).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from . import rigid_slide as _slide
from . import scalar_rigid as _scalar
from .fused import HAVE_NUMBA, _njit

__all__ = [
    "ContactImpact",
    "apply_impulse",
    "body_matrix",
    "contact_impact",
    "frame",
    "jacobian_matrix",
]

if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    import numba
    from numba.extending import register_jitable

    for _f in (
        _slide._slide_rate,
        _slide._step,
        _slide._event,
        _slide._rate,
        _slide._root,
        _slide._slide,
        _slide._turn,
        _slide._settle,
        _slide._settled_slip,
        _slide._stop_direction,
        _slide._stop_close,
        _slide._finish_stop,
        _slide._impulse_work,
        _scalar._stick_ratio,
        _scalar.reslide_direction,
        _scalar._linear,
        _scalar.rigid_impact,
    ):
        register_jitable(_f)

#: The local error per step of the sliding phase, a fraction of the speed scale.
RTOL = 1e-13


class ContactImpact(NamedTuple):
    """Many impacts at one contact each, in the contact frame ``(t1, t2, n)``.

    Attributes
    ----------
    velocity : ndarray, shape (..., 3)
        The contact point's velocity after the impact (m/s).
    impulse : ndarray, shape (..., 3)
        The contact impulse (N s), tangential components first.
    compression_impulse : ndarray
        The normal impulse at the end of compression (N s).
    work_compression_normal, work_restitution_normal : ndarray
        The normal force's work in compression (negative) and in restitution (J).
    work_compression_tangential, work_restitution_tangential : ndarray
        Friction's work in compression and in restitution (J, never positive).
    dissipated : ndarray
        The kinetic energy the impact takes, ``-p . (v_before + v_after) / 2`` (J;
        negative where the law creates energy).
    stop_impulse : ndarray
        The normal impulse at which the slip stopped (N s; NaN where it did not).
    sequence : ndarray of str
        The phases in order: ``"slide"``, ``"slide-stick"``, ``"slide-reslide"`` (stopped
        and slid again along the direction ``W`` dictates) or ``"stick"``.
    steps : ndarray of int
        Integration steps of the sliding phase.
    ended : ndarray of bool
        Whether the impact ended (``False``: the bodies never separate, the normal velocity
        falling while they press: a jam; every other field is then NaN).
    """

    velocity: np.ndarray
    impulse: np.ndarray
    compression_impulse: np.ndarray
    work_compression_normal: np.ndarray
    work_restitution_normal: np.ndarray
    work_compression_tangential: np.ndarray
    work_restitution_tangential: np.ndarray
    dissipated: np.ndarray
    stop_impulse: np.ndarray
    sequence: np.ndarray
    steps: np.ndarray
    ended: np.ndarray


_FLOATS = 12  # v (3), p (3), p_c, normal works (2), tangential works (2), p_stop


def _one(w, v, mu, kappa, law, rtol, p_max):
    return _scalar.rigid_impact(w[0, 0], w[0, 1], w[0, 2], w[1, 1], w[1, 2], w[2, 2],
                                v[0], v[1], v[2], mu, kappa, law, rtol, p_max)  # fmt: skip


def _rigid_kernel(w, s_w, v, s_v, mu, s_mu, kappa, s_kappa, law, rtol, p_max, s_p, out, codes):
    """Every impact ``i``: ``W = w[i * s_w]``, ``v[i * s_v]``, ... into ``out[:, i]`` and
    ``codes[:, i]`` (sequence, steps, ended)."""
    for i in numba.prange(codes.shape[1]):
        r = _scalar.rigid_impact(
            w[i * s_w, 0], w[i * s_w, 1], w[i * s_w, 2], w[i * s_w, 4], w[i * s_w, 5],
            w[i * s_w, 8], v[i * s_v, 0], v[i * s_v, 1], v[i * s_v, 2], mu[i * s_mu],
            kappa[i * s_kappa], law, rtol, p_max[i * s_p],
        )  # fmt: skip
        out[0, i], out[1, i], out[2, i], out[3, i], out[4, i] = r[0], r[1], r[2], r[3], r[4]
        out[5, i], out[6, i], out[7, i], out[8, i], out[9, i] = r[5], r[6], r[7], r[8], r[9]
        out[10, i], out[11, i] = r[10], r[11]
        codes[0, i] = r[12]
        codes[1, i] = r[13]
        codes[2, i] = 1 if r[14] else 0


if HAVE_NUMBA:  # pragma: no branch
    _rigid_kernel = _njit(_rigid_kernel)


def _rows(a: np.ndarray, shape: tuple[int, ...], tail: tuple[int, ...]) -> tuple[np.ndarray, int]:
    """``a`` broadcast to ``shape + tail`` as read-only rows, and the row step (0: one row
    for every impact)."""
    a = np.broadcast_to(np.asarray(a, dtype=np.float64), (*shape, *tail))
    flat = a.reshape(-1, int(np.prod(tail, dtype=np.int64)))
    if flat.shape[0] == 0:
        rows, step = np.zeros((1, flat.shape[1])), 0
    elif flat.shape[0] == 1 or flat.strides[0] == 0:
        rows, step = np.ascontiguousarray(flat[:1]), 0
    else:
        rows, step = np.ascontiguousarray(flat), 1
    rows.setflags(write=False)
    return rows, step


def contact_impact(W, velocity, mu, kappa, law: str = "poisson", *, rtol: float = RTOL,
                   p_max: Any = np.inf) -> ContactImpact:  # fmt: skip
    """Many impacts, each of a rigid body (or two) at one point contact (Keller's method).

    Parameters
    ----------
    W : array_like, shape (..., 3, 3)
        The collision matrix in the contact frame ``(t1, t2, n)`` (1/kg): symmetric,
        positive definite (its upper triangle is read).
    velocity : array_like, shape (..., 3)
        The contact point's velocity relative to the surface before the impact (m/s),
        normal component negative (approaching).
    mu, kappa : float or array_like
        Coulomb's friction coefficient and the restitution coefficient of ``law``.
    law : {"poisson", "newton", "energetic"}
        Where the impact ends: Poisson's, Newton's or Stronge's energetic law
        (:mod:`spinimpact.core.scalar_rigid`).
    rtol : float
        Local error per step of the sliding phase, a fraction of the speed scale.
    p_max : float or array_like
        Stop at this normal impulse (N s) if the impact has not ended: the state part-way
        (an array of them along one impact gives its history).

    Returns
    -------
    ContactImpact
        Arrays of the broadcast shape of the impacts. Not validated here (the model's
        :func:`spinimpact.solve_rigid` validates).

    Raises
    ------
    ImportError
        For more than one impact without Numba, naming the ``[fast]`` extra.
    """
    code = _scalar.LAW_CODES.index(law)
    shape = np.broadcast_shapes(np.shape(W)[:-2], np.shape(velocity)[:-1], np.shape(mu),
                                np.shape(kappa), np.shape(p_max))  # fmt: skip
    n = int(np.prod(shape, dtype=np.int64))
    out = np.empty((_FLOATS, n))
    codes = np.empty((3, n), dtype=np.int64)
    if HAVE_NUMBA:
        w, s_w = _rows(W, shape, (3, 3))
        v, s_v = _rows(velocity, shape, (3,))
        m, s_m = _rows(np.asarray(mu, np.float64)[..., None], shape, (1,))
        k, s_k = _rows(np.asarray(kappa, np.float64)[..., None], shape, (1,))
        c, s_c = _rows(np.asarray(p_max, np.float64)[..., None], shape, (1,))
        _rigid_kernel(w, s_w, v, s_v, m[:, 0], s_m, k[:, 0], s_k, code, float(rtol), c[:, 0],
                      s_c, out, codes)  # fmt: skip
    elif n == 1:
        w = np.broadcast_to(np.asarray(W, np.float64), (*shape, 3, 3)).reshape(3, 3)
        v = np.broadcast_to(np.asarray(velocity, np.float64), (*shape, 3)).reshape(3)
        m = float(np.broadcast_to(mu, shape).reshape(-1)[0])
        k = float(np.broadcast_to(kappa, shape).reshape(-1)[0])
        c = float(np.broadcast_to(p_max, shape).reshape(-1)[0])
        r = _one(w, v, m, k, code, float(rtol), c)
        out[:, 0] = r[:_FLOATS]
        codes[:, 0] = r[12], r[13], int(r[14])
    else:  # pragma: no cover - depends on the optional extra
        from .._validation import require

        require("numba", "many rigid-body impacts in 3D")
    ended = codes[2].astype(bool)
    limit = np.broadcast_to(np.asarray(p_max, np.float64), shape).reshape(-1)
    out[:, ~ended & (out[5] < limit)] = np.nan  # no end: a jam (p_max reached: part-way)
    v0 = np.broadcast_to(np.asarray(velocity, np.float64), (*shape, 3)).reshape(n, 3)
    v1 = out[0:3].T
    p = out[3:6].T
    dissipated = -0.5 * np.einsum("ij,ij->i", p, v0 + v1)
    sequence = np.asarray(_scalar.SEQUENCES)[codes[0]]
    return ContactImpact(
        velocity=v1.reshape(*shape, 3), impulse=p.reshape(*shape, 3),
        compression_impulse=out[6].reshape(shape),
        work_compression_normal=out[7].reshape(shape),
        work_restitution_normal=out[8].reshape(shape),
        work_compression_tangential=out[9].reshape(shape),
        work_restitution_tangential=out[10].reshape(shape),
        dissipated=dissipated.reshape(shape), stop_impulse=out[11].reshape(shape),
        sequence=sequence.reshape(shape), steps=codes[1].reshape(shape),
        ended=ended.reshape(shape),
    )  # fmt: skip


def _cross_matrix(r: np.ndarray) -> np.ndarray:
    """``[r]x``, with ``[r]x a = r x a``, for rows of vectors ``(..., 3)``."""
    z = np.zeros(r.shape[:-1])
    x, y, w = r[..., 0], r[..., 1], r[..., 2]
    return np.stack([np.stack([z, -w, y], -1), np.stack([w, z, -x], -1),
                     np.stack([-y, x, z], -1)], -2)  # fmt: skip


def _inverse3(a: np.ndarray) -> np.ndarray:
    """The inverse of each 3 x 3 matrix in ``(..., 3, 3)``, by its adjugate over its
    determinant (several times faster than ``np.linalg.inv`` for many small matrices)."""
    a = np.asarray(a, dtype=np.float64)
    cof = np.empty(np.broadcast_shapes(a.shape, (3, 3)))
    for i in range(3):
        for j in range(3):
            i1, i2 = (i + 1) % 3, (i + 2) % 3
            j1, j2 = (j + 1) % 3, (j + 2) % 3
            # the cofactor of a[i, j], placed transposed: the adjugate
            cof[..., j, i] = a[..., i1, j1] * a[..., i2, j2] - a[..., i1, j2] * a[..., i2, j1]
    det = np.sum(a[..., 0, :] * cof[..., :, 0], axis=-1)
    return cof / det[..., None, None]


def body_matrix(mass, inertia, offset) -> np.ndarray:
    """The collision matrix of a free rigid body at a contact point, in the world frame.

    ``W = I/m - [r]x J^-1 [r]x`` (Stronge, *Impact Mechanics*, 2000, ch. 5; derived from
    ``dv = p/m`` and ``dw = J^-1 (r x p)`` at the point ``v + w x r``): the contact point's
    velocity changes by ``W p`` under an impulse ``p`` there (:func:`apply_impulse`).

    Parameters
    ----------
    mass : float or array_like
        Mass (kg).
    inertia : array_like, shape (..., 3, 3)
        The inertia tensor about the centre of mass, in the world frame (kg m^2).
    offset : array_like, shape (..., 3)
        The contact point from the centre of mass, in the world frame (m).

    Returns
    -------
    ndarray, shape (..., 3, 3)
    """
    r = _cross_matrix(np.asarray(offset, dtype=np.float64))
    inverse = _inverse3(inertia)
    m = np.asarray(mass, dtype=np.float64)[..., None, None]
    return np.eye(3) / m - r @ inverse @ r


def apply_impulse(mass, inertia, offset, velocity, spin, impulse) -> tuple[np.ndarray, np.ndarray]:
    """A free body's centre velocity and spin after an impulse at a point of it:
    ``v + p/m`` and ``w + J^-1 (r x p)`` (world frame; shapes as :func:`body_matrix`'s, the
    vectors ``(..., 3)``)."""
    p = np.asarray(impulse, dtype=np.float64)
    turn = np.cross(np.asarray(offset, dtype=np.float64), p)
    moment = np.einsum("...ij,...j->...i", _inverse3(inertia), turn)
    return velocity + p / np.asarray(mass, dtype=np.float64)[..., None], spin + moment


def jacobian_matrix(mass_matrix, jacobian) -> np.ndarray:
    """``W = J M^-1 J^T`` for a system with generalized mass matrix ``M`` (n x n) and the
    contact point's velocity ``J q_dot`` (``J`` 3 x n): what an engine knows of an
    articulated body. Shapes ``(..., n, n)`` and ``(..., 3, n)``; returns ``(..., 3, 3)``."""
    m = np.asarray(mass_matrix, dtype=np.float64)
    j = np.asarray(jacobian, dtype=np.float64)
    return j @ np.linalg.solve(m, np.swapaxes(j, -1, -2))


def frame(normal: Any) -> np.ndarray:
    """A right-handed contact frame for each unit normal: columns ``t1, t2, n``.

    ``t1`` is the world x axis made normal to ``n`` (the y axis where ``n`` is within 45
    degrees of x); results in the world frame do not depend on this choice.
    """
    n = np.asarray(normal, dtype=np.float64)
    n = n / np.linalg.norm(n, axis=-1, keepdims=True)
    x = np.where((np.abs(n[..., :1]) < np.sqrt(0.5)), [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    t1 = x - np.sum(x * n, axis=-1, keepdims=True) * n
    t1 /= np.linalg.norm(t1, axis=-1, keepdims=True)
    t2 = np.cross(n, t1)
    return np.stack([t1, t2, n], axis=-1)
