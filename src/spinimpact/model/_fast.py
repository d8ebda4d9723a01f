"""One impact in microseconds: the scalar path of :func:`~spinimpact.solve`.

On a single impact the array path spends nearly all its time in NumPy's per-call
overhead (validation, broadcasting, a few dozen 0-d array operations). When every input
is one plain number (a Python or NumPy real scalar, or an array holding one element) and
the body's numbers are floats, :func:`paper_impact` validates the numbers with the same
rules (:data:`spinimpact._validation.RULES`) and computes every field with the per-contact
law on floats (:mod:`spinimpact.core.scalar`), which performs the array kernels' operations
in their order: the :class:`~spinimpact.Impact` is the one the array path returns, field
for field, bit for bit and of the same types (NumPy scalars, or for one-element arrays
read-only arrays of the broadcast shape: ``tests/model/test_fast.py``,
``tests/model/test_fast_paths.py``). :mod:`spinimpact.model._fast_result` makes the result.

Anything else (a longer array, a restitution model, a value the rules refuse) returns
``None``, and ``solve`` takes the array path, which raises the usual errors: so the errors
are the same on both paths by construction. The helpers here (:func:`number`,
:func:`numbers`) serve the other solvers' scalar paths too.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._validation import LARGEST, RULES
from ..core import scalar as law
from ..core.impulse import REGIMES as _REGIME_NAMES
from ..core.works import MIN_ENERGY_CASES
from ._fast_result import Layout, layout_for

__all__ = ["REGIMES", "number", "numbers", "paper_impact", "paper_numbers"]

_FLOAT = np.float64
_NDARRAY = np.ndarray
#: NumPy scalar types whose conversion to float is the one ``numpy.asarray(x, float64)`` does.
_NUMPY_REALS = frozenset(
    {np.float64, np.float32, np.float16, np.int8, np.int16, np.int32, np.int64,
     np.uint8, np.uint16, np.uint32, np.uint64}
)  # fmt: skip
_EXACT_INT = 2**53  # Python ints beyond it may not convert as NumPy does: array path
REGIMES = tuple(_REGIME_NAMES)  #: plain str, as the array path names them (``freeze``)
_CASES = tuple(MIN_ENERGY_CASES)
_RULES = {name: tuple(ok for ok, _ in rules) for name, rules in RULES.items()}


def number(value: Any, rules: str) -> float | None:
    """``value`` as a float if it is one real number the array path would accept under
    ``RULES[rules]`` (finite, at most ``LARGEST`` in magnitude); ``None`` otherwise."""
    kind = type(value)
    if kind is float:
        x = value
    elif kind is _FLOAT:
        x = float(value)
    elif kind is int:
        if not -_EXACT_INT <= value <= _EXACT_INT:
            return None
        x = float(value)
    elif kind in _NUMPY_REALS or (
        kind is _NDARRAY and value.ndim == 0 and value.dtype.type in _NUMPY_REALS
    ):
        x = float(value)
    else:
        return None
    if not -LARGEST <= x <= LARGEST:  # also refuses NaN and the infinities
        return None
    for ok in _RULES[rules]:
        if not ok(x):
            return None
    return x


def numbers(values: tuple, rules: tuple[str, ...]) -> tuple[list[float], Any] | None:
    """``[number(x, rule), ...]`` of ``values`` and the shape of the impacts: ``None`` for
    plain numbers, else the broadcast shape of the arrays of one element among them (each
    read as its element). ``None`` when a value is not a number the array path accepts
    under its rule, or is an array of more or fewer elements (the array path's business)."""
    shape = None
    out = []
    for x, rule in zip(values, rules):  # noqa: B905 - of one length, written together
        if type(x) is _NDARRAY and x.ndim:
            if x.size != 1 or x.dtype.type not in _NUMPY_REALS:
                return None
            if shape is None or x.ndim > len(shape):  # every length is 1: the most dims
                shape = x.shape
            x = x[(0,) * x.ndim]
        y = number(x, rule)
        if y is None:
            return None
        out.append(y)
    return out, shape


_INPUTS = ("vx", "vy", "omega", "mu", "kappa")


def paper_numbers(body: Any, vx: Any, vy: Any, omega: Any, mu: Any, kappa: Any) -> Any:
    """``((m, R, zeta, J), [vx, vy, omega, mu, kappa], shape)`` as floats (``J = m rho^2``
    as the array path forms it; ``shape`` as :func:`numbers` gives it) for one impact of a
    paper's body, or ``None`` unless the body's numbers are floats and the inputs numbers
    the array path accepts."""
    m, r, g, z = body.mass, body.radius, body.gyration, body.zeta
    if not (type(m) is float and type(r) is float and type(g) is float and type(z) is float):
        return None
    given = numbers((vx, vy, omega, mu, kappa), _INPUTS)
    if given is None:
        return None
    return (m, r, z, m * (g * g)), *given


def _layout(impact: type, state: type, outcome: type) -> Layout:
    motion = Layout(state, ("vx", "vy", "omega"))
    return Layout(
        impact,
        ("mu", "kappa", "slip_before", "slip_after", "incidence_ratio", "tau0", "tau_star",
         "tau1", "tangential_impulse", "impulse_ratio", "kinetic_energy_before",
         "kinetic_energy_after", "dissipated_energy", "dissipated_fraction",
         "work_compression_normal", "work_compression_tangential", "work_restitution_normal",
         "work_restitution_tangential", "work_ratio_tangential", "min_kinetic_energy",
         "tau_min_energy", "newton_restitution", "poisson_restitution",
         "energetic_restitution"),
        nested=(("before", motion), ("after", motion), ("outcome", Layout(
            outcome, (), flags=("backward", "reversed_spin", "vertical", "spinning",
                                "rolling"))),
        ),
        text={"regime": REGIMES, "min_energy_case": _CASES}, given=("body",),
    )  # fmt: skip


def paper_impact(body: Any, vx: Any, vy: Any, omega: Any, mu: Any, kappa: Any, kinds: tuple):
    """The :class:`~spinimpact.Impact` of one impact of a paper's body, or ``None``.

    Parameters
    ----------
    body : Body
        The body (already checked to be one).
    vx, vy, omega, mu, kappa : object
        As given to :func:`~spinimpact.solve`.
    kinds : tuple
        The result classes ``(Impact, State, Outcome)`` (passed in, so that this module
        does not import the one that calls it).

    Returns
    -------
    Impact or None
        ``None`` unless every input is one number the array path accepts (a scalar, or an
        array holding one element: the result then has the broadcast shape) and the body's
        numbers are floats; the caller then takes the array path.
    """
    given = paper_numbers(body, vx, vy, omega, mu, kappa)
    if given is None:
        return None
    (m, r, z, inertia), (vx_, vy_, om_, mu_, k), shape = given
    slip = vx_ + r * om_
    (tau0, tau_star, tau1, f1, slip1, mu_hat, code, wcn, wct, wrn, wrt, loss, tau_m, case) = (
        law.contact_impact(slip, vy_, m, z, mu_, k)
    )
    vx1 = vx_ + f1 / m
    vy1 = -k * vy_ + 0.0
    om1 = om_ + (z - 1.0) * f1 / (m * r)
    e0 = law.kinetic_energy(vx_, vy_, om_, m, inertia)
    ratio = abs(slip) / abs(vy_)
    # the state at tau_m (core.kinematics.state_at), for the least kinetic energy
    f_m = (-m * slip / z if tau_m >= tau_star else -mu_ * law.sign(slip) * tau_m) + 0.0
    e_min = law.kinetic_energy(
        vx_ + f_m / m, vy_ + tau_m / m, om_ + (z - 1.0) * f_m / (m * r), m, inertia
    )
    # the three restitution coefficients by their definitions (core.restitution)
    eta2 = -wrn / wcn
    floats = (
        mu_, k, slip, slip1, ratio, tau0, tau_star, tau1, f1, mu_hat, e0,
        law.kinetic_energy(vx1, vy1, om1, m, inertia), loss, loss / e0, wcn, wct, wrn, wrt,
        law.work_ratio_tangential(ratio, z, mu_, k), e_min, tau_m, -vy1 / vy_,
        (m * (vy1 - vy_) - tau0) / tau0, math.sqrt(eta2 if eta2 > 0.0 else 0.0),
        vx_, vy_, om_, vx1, vy1, om1,
    )  # fmt: skip
    rest = {"body": body, "regime": REGIMES[code], "min_energy_case": _CASES[case]}
    flags = law.outcome_flags(vx_, vy_, om_, r, z, mu_, k)
    return layout_for(_layout, *kinds).result(floats, flags, rest, shape)
