"""Every field of an impact in one pass over memory (optional ``[fast]`` extra: Numba).

:func:`spinimpact.solve` builds its result from the NumPy kernels of
:mod:`spinimpact.core.impulse`, :mod:`~spinimpact.core.works`,
:mod:`~spinimpact.core.kinematics`, :mod:`~spinimpact.core.energetics`,
:mod:`~spinimpact.core.outcomes` and :mod:`~spinimpact.core.restitution`: several dozen
passes over memory with a temporary array for each intermediate. For large arrays the
closed forms are cheap and the cost is memory traffic, so :func:`impact_fields` computes
every field for one impact after another, reading each input once and writing each output
once, in parallel over cores.

Each line of the kernel mirrors an expression of those kernels, in the same order of IEEE
operations (no fast-math, no fused multiply-add), so every field equals the NumPy path's
bit for bit; ``tests/core/test_fused_impact.py`` checks this over all five regimes. The
two text fields (``regime`` and ``min_energy_case``) are NumPy fixed-width Unicode arrays,
as ``numpy.asarray(REGIMES)[code]`` makes them; the kernel writes their code points
directly into those arrays, so no Python string is made per impact.

The compiled kernel is cached on disk as those of :mod:`spinimpact.core.fused` are
(:func:`spinimpact.core.fused._njit`).
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from .fused import HAVE_NUMBA, _njit
from .impulse import REGIMES
from .outcomes import _RTOL
from .works import MIN_ENERGY_CASES

__all__ = ["FLOATS", "HAVE_NUMBA", "INPUTS", "ImpactFields", "impact_fields"]

if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    import numba


class ImpactFields(NamedTuple):
    """The arrays of :class:`~spinimpact.Impact` that are not its inputs, by column name."""

    after_vx: Any
    after_vy: Any
    after_omega: Any
    slip_before: Any
    slip_after: Any
    incidence_ratio: Any
    regime: Any
    tau0: Any
    tau_star: Any
    tau1: Any
    tangential_impulse: Any
    impulse_ratio: Any
    kinetic_energy_before: Any
    kinetic_energy_after: Any
    dissipated_energy: Any
    dissipated_fraction: Any
    work_compression_normal: Any
    work_compression_tangential: Any
    work_restitution_normal: Any
    work_restitution_tangential: Any
    work_ratio_tangential: Any
    min_kinetic_energy: Any
    tau_min_energy: Any
    min_energy_case: Any
    newton_restitution: Any
    poisson_restitution: Any
    energetic_restitution: Any
    backward: Any
    reversed_spin: Any
    vertical: Any
    spinning: Any
    rolling: Any


#: The inputs of :func:`impact_fields`, in order.
INPUTS = ("vx", "vy", "omega", "mass", "radius", "gyration", "zeta", "mu", "kappa")
_TEXT = ("regime", "min_energy_case")
_FLAGS = ("backward", "reversed_spin", "vertical", "spinning", "rolling")


def _code_points(names: tuple[str, ...]) -> np.ndarray:
    """``names`` as NumPy makes them (fixed-width Unicode), as a (len, width) uint32 table."""
    text = np.asarray(names)
    return text.view(np.uint32).reshape(len(names), -1).copy()


_REGIME_TABLE = _code_points(REGIMES)
_CASE_TABLE = _code_points(MIN_ENERGY_CASES)
_REGIME_DTYPE = np.asarray(REGIMES).dtype
_CASE_DTYPE = np.asarray(MIN_ENERGY_CASES).dtype


#: The computed fields, in the order of :class:`ImpactFields`'s float fields.
FLOATS = tuple(f for f in ImpactFields._fields if f not in _TEXT + _FLAGS)


def _sign(x):  # numpy.sign of a float that is not NaN
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else 0.0)


def _maximum(a, b):  # numpy.maximum of two floats that are not NaN: b where equal (+-0)
    return a if a > b else b


def _minimum(a, b):  # numpy.minimum likewise
    return a if a < b else b


def _work_tangential(a, b, mass, slip, zeta, mu, tau_star):
    """:func:`~spinimpact.core.works.work_tangential` of one impact, given ``tau_*``."""
    lo = _minimum(a, tau_star)
    hi = _minimum(b, tau_star)
    speed0 = abs(slip)
    rate = zeta * mu / mass
    speed_lo = _maximum(speed0 - rate * lo, 0.0)
    speed_hi = _maximum(speed0 - rate * hi, 0.0)
    return -mu * (hi - lo) * (speed_lo + speed_hi) / 2.0


def _energy(vx, vy, omega, mass, inertia):
    """:func:`~spinimpact.core.energetics.kinetic_energy` of one impact."""
    return 0.5 * mass * (vx * vx + vy * vy) + 0.5 * inertia * omega * omega


def _kernel(x, s, o, flags, regime, case_text, regime_table, case_table):
    """Every field of every impact: inputs ``x[k][i * s[k]]`` (``s[k]`` 0 or 1)."""
    for i in numba.prange(regime.shape[0]):
        vx, vy, om = x[0][i * s[0]], x[1][i * s[1]], x[2][i * s[2]]
        m, r, g, z = x[3][i * s[3]], x[4][i * s[4]], x[5][i * s[5]], x[6][i * s[6]]
        mu, k = x[7][i * s[7]], x[8][i * s[8]]
        inertia = m * (g * g)
        slip = vx + r * om  # kinematics.slip_velocity (eq. 4.4)
        w = abs(vy)
        sg = _sign(slip)
        stick = abs(slip) <= (1.0 + k) * z * mu * w  # impulse.sticks (eq. 4.6)
        early = abs(slip) <= z * mu * w  # impulse.sticks_in_compression (eq. 4.14)
        tau0 = -m * vy  # eq. 3.2
        tau1 = (1.0 + k) * tau0  # eq. 3.6
        # impulse.tangential_impulse and kinematics.rebound (eqs. 2.1-2.3, 5.7)
        f1 = (-m * slip / z if stick else -mu * sg * tau1) + 0.0
        vx1 = vx + f1 / m
        vy1 = -k * vy + 0.0
        om1 = om + (z - 1.0) * f1 / (m * r)
        # impulse.stick_impulse (eq. 4.3)
        num = m * abs(slip)
        den = z * mu
        tau_star = 0.0 if num == 0 else (num / den if den > 0 else np.inf)
        # works.contact_phase_works (eqs. 6.1, 6.2), contact_dissipated_energy (eq. 5.10)
        wcn = (tau0 - 0.0) * (2.0 * vy + (0.0 + tau0) / m) / 2.0
        wrn = (tau1 - tau0) * (2.0 * vy + (tau0 + tau1) / m) / 2.0
        loss = 0.5 * m * vy * vy * (1.0 - k * k)
        loss = loss - _work_tangential(0.0, tau1, m, slip, z, mu, tau_star)
        e0 = _energy(vx, vy, om, m, inertia)
        # works.contact_min_energy_impulse (eqs. 8.2-8.6), energetics.kinetic_energy_at
        sliding = m * (w + mu * abs(slip)) / (1.0 + z * mu * mu)
        tau_m = tau0 if early else _minimum(sliding, tau1)
        f_m = (-m * slip / z if tau_m >= tau_star else -mu * sg * tau_m) + 0.0
        # impulse.incidence_ratio, works.work_ratio_tangential (eqs. 6.15-6.18)
        ratio = abs(slip) / w
        defined = mu > 0 and ratio > 0
        xr = ratio / (z * mu if defined else 1.0)
        if not defined:
            work_ratio = np.nan
        elif xr <= 1.0:
            work_ratio = 0.0
        elif xr <= 1.0 + k:
            work_ratio = (xr - 1.0) * (xr - 1.0) / (2.0 * xr - 1.0)
        else:
            work_ratio = k * (1.0 - (1.0 + k) / (2.0 * xr - 1.0))
        o[0][i] = vx1
        o[1][i] = vy1
        o[2][i] = om1
        o[3][i] = slip
        o[4][i] = (0.0 if stick else slip - sg * (1.0 + k) * z * mu * w) + 0.0  # rebound_slip
        o[5][i] = ratio
        o[6][i] = tau0
        o[7][i] = tau_star
        o[8][i] = tau1
        o[9][i] = f1
        o[10][i] = (slip / ((1.0 + k) * z * vy) if stick else -mu * sg) + 0.0  # impulse_ratio
        o[11][i] = e0
        o[12][i] = _energy(vx1, vy1, om1, m, inertia)
        o[13][i] = loss
        o[14][i] = loss / e0
        o[15][i] = wcn
        o[16][i] = _work_tangential(0.0, tau0, m, slip, z, mu, tau_star)
        o[17][i] = wrn
        o[18][i] = _work_tangential(tau0, tau1, m, slip, z, mu, tau_star)
        o[19][i] = work_ratio
        o[20][i] = _energy(vx + f_m / m, vy + tau_m / m, om + (z - 1.0) * f_m / (m * r), m, inertia)
        o[21][i] = tau_m
        # impulse.restitution_coefficients (eqs. 1.1-1.3)
        o[22][i] = -vy1 / vy
        o[23][i] = (m * (vy1 - vy) - tau0) / tau0
        o[24][i] = np.sqrt(_maximum(-wrn / wcn, 0.0))
        # impulse.regime_code and works.contact_min_energy_case, as code points
        code = 0 if mu == 0 else (1 if slip == 0 else 4 - int(stick) - int(early))
        if code == 0:
            case = 4
        elif code <= 2:
            case = 1
        elif code == 3:
            case = 0
        else:
            case = 2 if tau_m < tau1 else 3
        for j in range(regime_table.shape[1]):
            regime[i, j] = regime_table[code, j]
        for j in range(case_table.shape[1]):
            case_text[i, j] = case_table[case, j]
        # outcomes.rebound_outcomes
        b = r * om
        c = (1.0 + k) * mu * w
        za = (z - 1.0) * vx
        gx = za - b if stick else z * (vx - sg * c)
        gw = b - za if stick else z * (b - sg * (z - 1.0) * c)
        size_x = abs(za) + abs(b) if stick else z * (abs(vx) + c)
        size_w = abs(za) + abs(b) if stick else z * (abs(b) + (z - 1.0) * c)
        zero_x = abs(gx) <= _RTOL * size_x
        zero_w = abs(gw) <= _RTOL * size_w
        flags[0][i] = vx != 0 and not zero_x and _sign(gx) == -_sign(vx)
        flags[1][i] = b != 0 and not zero_w and _sign(gw) == -_sign(b)
        flags[2][i] = zero_x
        flags[3][i] = not zero_w
        flags[4][i] = stick


if HAVE_NUMBA:  # pragma: no branch - depends on the optional extra
    _inline = numba.njit(inline="always", error_model="numpy")
    _sign = _inline(_sign)
    _maximum = _inline(_maximum)
    _minimum = _inline(_minimum)
    _work_tangential = _inline(_work_tangential)
    _energy = _inline(_energy)
    _kernel = _njit(_kernel)


def _column(a: np.ndarray, shape: tuple[int, ...]) -> tuple[np.ndarray, int]:
    """A read-only 1-D float64 input and its step: 0 for one value repeated, else 1."""
    a = np.broadcast_to(np.asarray(a, dtype=np.float64), shape)
    if all(st == 0 for st, n in zip(a.strides, a.shape, strict=True) if n > 1):
        col, step = np.array([a.flat[0]]) if a.size else np.zeros(1), 0
    else:
        col, step = np.ascontiguousarray(a).reshape(-1).view(), 1
    col.setflags(write=False)  # one Numba type for every input, whoever owns it
    return col, step


def impact_fields(vx, vy, omega, mass, radius, gyration, zeta, mu, kappa) -> ImpactFields:
    """Every computed field of :func:`spinimpact.solve` in one pass over memory.

    Parameters
    ----------
    vx, vy, omega, mass, radius, gyration, zeta, mu, kappa : float or array
        As for :func:`spinimpact.core.rebound`, with the radius of gyration ``rho`` (m)
        for the moment of inertia ``J = m rho^2``; broadcast together. Not validated.

    Returns
    -------
    ImpactFields
        New arrays of the broadcast shape: the floats of :data:`FLOATS`, ``regime`` and
        ``min_energy_case`` as fixed-width Unicode arrays (the dtypes of
        ``numpy.asarray(REGIMES)`` and ``numpy.asarray(MIN_ENERGY_CASES)``) and the five
        boolean outcome flags; each equal bit for bit to the NumPy kernels'.

    Raises
    ------
    ImportError
        Without Numba, naming the ``[fast]`` extra.
    """
    if not HAVE_NUMBA:
        from .._validation import require

        require("numba", "the fused all-field kernel")
    args = (vx, vy, omega, mass, radius, gyration, zeta, mu, kappa)
    shape = np.broadcast_shapes(*(np.shape(a) for a in args))
    columns, steps = zip(*(_column(a, shape) for a in args), strict=True)
    n = int(np.prod(shape, dtype=np.int64))
    floats = tuple(np.empty(n) for _ in FLOATS)
    flags = tuple(np.empty(n, dtype=np.bool_) for _ in _FLAGS)
    regime = np.empty(n, dtype=_REGIME_DTYPE)
    case = np.empty(n, dtype=_CASE_DTYPE)
    codes = (a.view(np.uint32).reshape(n, -1) for a in (regime, case))
    _kernel(columns, steps, floats, flags, *codes, _REGIME_TABLE, _CASE_TABLE)
    out = dict(zip(FLOATS, floats, strict=True))
    out.update(zip(_FLAGS, flags, strict=True), regime=regime, min_energy_case=case)
    return ImpactFields(**{f: out[f].reshape(shape) for f in ImpactFields._fields})
