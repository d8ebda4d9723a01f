"""Every field of many planar impacts in one pass over memory (optional ``[fast]`` extra).

The array path of :func:`spinimpact.solve_planar` and :func:`spinimpact.solve_pendulum`
runs the coupled collision matrix's process (:func:`spinimpact.core.planar.planar_process`),
the works of its phases and the kinetic energies as NumPy expressions over whole arrays.
:func:`planar_fields` takes the contact's velocities and collision matrix, which the array
path forms, and computes every other field of one impact after another with the per-contact
law on floats (:mod:`spinimpact.core.scalar_planar`), reading each input once and writing
each output once, in parallel over cores.

The per-contact law performs the array kernels' IEEE operations in their order, and the
remaining expressions are those of :mod:`spinimpact.model._fast_planar` (one impact on
floats, equal to the array path bit for bit), so every field equals the array path's bit for
bit (``tests/model/test_fused_planar.py``). The body enters twice, through the impulse's
effect on its velocities: a free body (``kind`` 0, parameters ``rx, ry``: the contact from
the centre of mass) or a pendulum (``kind`` 1, parameters ``J_O, px, py, gx, gy``: the
moment of inertia about the pivot, the contact and the centre of mass from the pivot).

Compiled kernels are cached on disk as those of :mod:`spinimpact.core.fused` are. Nothing
is validated here.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from . import law as _law  # registers the per-contact law for compiled callers
from .fused import HAVE_NUMBA, _njit
from .fused_impact import _column

__all__ = ["HAVE_NUMBA", "PLANAR_FLOATS", "planar_fields"]

if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    import numba

_planar = _law.scalar_planar
_ENERGY_RTOL = 1e-12  # as model.planar: a rise of the energy beyond rounding

#: The float rows of :func:`planar_fields`' table, in order.
PLANAR_FLOATS = (
    "after_vx", "after_vy", "after_omega", "slip_after", "normal_velocity_after", "tau0",
    "tau_star", "tau1", "tangential_impulse", "impulse_ratio", "kinetic_energy_before",
    "kinetic_energy_after", "dissipated_energy", "dissipated_fraction",
    "work_compression_normal", "work_compression_tangential", "work_restitution_normal",
    "work_restitution_tangential", "min_kinetic_energy", "tau_min_energy",
    "newton_restitution", "poisson_restitution", "energetic_restitution",
)  # fmt: skip

#: The inputs of :func:`planar_fields`, in order (``q0 ... q4``: the body's parameters).
INPUTS = ("vx", "vy", "omega", "slip", "vn", "a", "b", "d", "mu", "kappa", "mass", "inertia",
          "q0", "q1", "q2", "q3", "q4")  # fmt: skip


def _apply(kind, vx, vy, om, m, j, q0, q1, q2, q3, q4, f, tau):
    """Velocities after the contact impulse ``(f, tau)``, as the bodies' ``apply_impulse``."""
    if kind == 0:  # core.planar.planar_apply_impulse: q0, q1 = rx, ry
        return vx + f / m, vy + tau / m, om + (q0 * tau - q1 * f) / j
    o = om + (q1 * tau - q2 * f) / q0  # core.planar.pendulum_apply_impulse
    return -o * q4, o * q3, o  # Pendulum.centre_velocity: (-omega gy, omega gx)


def _energy(vx, vy, om, m, j):  # core.energetics.kinetic_energy
    return 0.5 * m * (vx * vx + vy * vy) + 0.5 * j * om * om


def _planar_kernel(x, s, kind, law, out, code, creates):
    """Every impact: inputs ``x[k][i * s[k]]`` (:data:`INPUTS`); floats into ``out[:, i]``."""
    for i in numba.prange(code.shape[0]):
        vx, vy, om = x[0][i * s[0]], x[1][i * s[1]], x[2][i * s[2]]
        u0, v0 = x[3][i * s[3]], x[4][i * s[4]]
        a, b, d = x[5][i * s[5]], x[6][i * s[6]], x[7][i * s[7]]
        mu, k, m, j = x[8][i * s[8]], x[9][i * s[9]], x[10][i * s[10]], x[11][i * s[11]]
        q0, q1, q2 = x[12][i * s[12]], x[13][i * s[13]], x[14][i * s[14]]
        q3, q4 = x[15][i * s[15]], x[16][i * s[16]]
        c, tau_s, tau_c, tau_f, _s1, _s2, f1, u1, vn1 = _planar.planar_process(
            u0, v0, a, b, d, mu, k, law
        )
        vx1, vy1, om1 = _apply(kind, vx, vy, om, m, j, q0, q1, q2, q3, q4, f1, tau_f)
        wcn, wct = _planar.planar_work(0.0 * tau_f, tau_c, u0, v0, a, b, d, mu, tau_s)
        wrn, wrt = _planar.planar_work(tau_c, tau_f, u0, v0, a, b, d, mu, tau_s)
        e0 = _energy(vx, vy, om, m, j)
        loss = -(wcn + wct + wrn + wrt)
        tau_m = _planar.planar_min_energy_impulse(u0, v0, a, b, d, mu, tau_s, tau_f)
        f_m = _planar.planar_state_at(tau_m, u0, v0, a, b, d, mu, tau_s)[0]
        xm, ym, om_m = _apply(kind, vx, vy, om, m, j, q0, q1, q2, q3, q4, f_m, tau_m)
        eta2 = _planar._divide(-wrn, wcn)
        out[0, i] = vx1
        out[1, i] = vy1
        out[2, i] = om1
        out[3, i] = u1
        out[4, i] = vn1
        out[5, i] = tau_c
        out[6, i] = tau_s
        out[7, i] = tau_f
        out[8, i] = f1
        out[9, i] = _planar._divide(f1, tau_f)
        out[10, i] = e0
        out[11, i] = _energy(vx1, vy1, om1, m, j)
        out[12, i] = loss
        out[13, i] = _planar._divide(loss, e0)
        out[14, i] = wcn
        out[15, i] = wct
        out[16, i] = wrn
        out[17, i] = wrt
        out[18, i] = _energy(xm, ym, om_m, m, j)
        out[19, i] = tau_m
        out[20, i] = -vn1 / v0
        out[21, i] = _planar._divide(tau_f - tau_c, tau_c)
        out[22, i] = _planar._sqrt(_planar._maximum(eta2, 0.0))
        code[i] = c
        creates[i] = loss < -_ENERGY_RTOL * e0


if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    _inline = numba.njit(inline="always", error_model="numpy")
    _apply = _inline(_apply)
    _energy = _inline(_energy)
    _planar_kernel = _njit(_planar_kernel)


def planar_fields(kind: int, law: int, *inputs: Any) -> tuple[dict, np.ndarray, np.ndarray]:
    """Every field of many planar impacts, equal bit for bit to the array path's.

    Parameters
    ----------
    kind : int
        ``0`` a free planar body, ``1`` a pendulum (the meaning of ``q0 ... q4``).
    law : int
        ``0`` Newton, ``1`` Poisson, ``2`` Stronge (index into
        :data:`spinimpact.core.planar.LAWS`).
    *inputs : float or array_like
        The 17 arrays of :data:`INPUTS`, broadcast together: the centre's velocity (m/s)
        and spin (rad/s) before the impact, the contact's slip and normal velocity (m/s),
        the collision matrix ``W_tt, W_tn, W_nn`` (1/kg), ``mu``, ``kappa``, the mass (kg)
        and moment of inertia about the centre of mass (kg m^2), and the body's parameters
        (m or kg m^2; unused ones may be 0).

    Returns
    -------
    fields : dict
        :data:`PLANAR_FLOATS` -> float64 array of the broadcast shape.
    code : ndarray of int8
        The regime code (into :data:`spinimpact.core.planar.PLANAR_REGIMES`).
    creates : ndarray of bool
        Where the impact would create energy (``creates_energy``).

    Raises
    ------
    ImportError
        Without Numba, naming the ``[fast]`` extra.
    """
    if not HAVE_NUMBA:
        from .._validation import require

        require("numba", "the fused planar kernel")
    if len(inputs) != len(INPUTS):
        raise TypeError(f"planar_fields takes {len(INPUTS)} inputs, got {len(inputs)}")
    shape = np.broadcast_shapes(*(np.shape(a) for a in inputs))
    x, s = zip(*(_column(a, shape) for a in inputs), strict=True)
    n = int(np.prod(shape, dtype=np.int64))
    out = np.empty((len(PLANAR_FLOATS), n))
    code = np.empty(n, dtype=np.int8)
    creates = np.empty(n, dtype=np.bool_)
    _planar_kernel(x, np.asarray(s, np.int64), int(kind), int(law), out, code, creates)
    fields = {name: out[k].reshape(shape) for k, name in enumerate(PLANAR_FLOATS)}
    return fields, code.reshape(shape), creates.reshape(shape)
