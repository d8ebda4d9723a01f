"""One impact in microseconds: the scalar path of :func:`~spinimpact.solve`.

On a single impact the array path spends nearly all its time in NumPy's per-call
overhead (validation, broadcasting, a few dozen 0-d array operations). When every input
is one plain number (a Python or NumPy real scalar, or a 0-d array) and the body's numbers
are floats, :func:`paper_impact` validates the numbers with the same rules
(:data:`spinimpact._validation.RULES`) and computes every field with the per-contact law on
floats (:mod:`spinimpact.core.scalar`), which performs the array kernels' operations in
their order: the :class:`~spinimpact.Impact` is the one the array path returns, field for
field, bit for bit and of the same types (``tests/model/test_fast.py``).

Anything else (an array, a restitution model, a value the rules refuse) returns ``None``,
and ``solve`` takes the array path, which raises the usual errors: so the errors are the
same on both paths by construction.
"""

from __future__ import annotations

import math
from dataclasses import fields
from typing import Any

import numpy as np

from .._validation import LARGEST, RULES
from ..core import scalar as law
from ..core.impulse import REGIMES as _REGIME_NAMES
from ..core.works import MIN_ENERGY_CASES

__all__ = ["REGIMES", "build", "number", "paper_impact", "spread"]

_FLOAT = np.float64
_TRUE, _FALSE = np.True_, np.False_
#: NumPy scalar types whose conversion to float is the one ``numpy.asarray(x, float64)`` does.
_NUMPY_REALS = frozenset(
    {np.float64, np.float32, np.float16, np.int8, np.int16, np.int32, np.int64,
     np.uint8, np.uint16, np.uint32, np.uint64}
)  # fmt: skip
_EXACT_INT = 2**53  # Python ints beyond it may not convert as NumPy does: array path
REGIMES = tuple(_REGIME_NAMES)  #: plain str, as the array path names them (``freeze``)
_CASES = tuple(MIN_ENERGY_CASES)
_RULES = {name: tuple(ok for ok, _ in rules) for name, rules in RULES.items()}
_NAMES: dict[type, frozenset[str]] = {}


def build(kind: type, values: dict[str, Any]) -> Any:
    """An instance of the frozen result dataclass ``kind`` holding ``values``.

    The result classes have no ``__post_init__``: an instance is its fields, so filling
    ``__dict__`` makes the object the dataclass's ``__init__`` would (a tenth of its cost
    for 30 fields). Values that do not name exactly the class's fields go through
    ``__init__``, which raises as usual.
    """
    names = _NAMES.get(kind)
    if names is None:
        plain = not hasattr(kind, "__post_init__")
        names = _NAMES[kind] = frozenset(f.name for f in fields(kind)) if plain else frozenset()
    if values.keys() != names:
        return kind(**values)
    obj = object.__new__(kind)
    obj.__dict__.update(values)
    return obj


def number(value: Any, rules: str) -> float | None:
    """``value`` as a float if it is one real number the array path would accept under
    ``RULES[rules]`` (finite, at most ``LARGEST`` in magnitude); ``None`` otherwise."""
    kind = type(value)
    if kind is float or kind is _FLOAT:
        x = float(value)
    elif kind is int:
        if not -_EXACT_INT <= value <= _EXACT_INT:
            return None
        x = float(value)
    elif kind in _NUMPY_REALS or (
        kind is np.ndarray and value.ndim == 0 and value.dtype.type in _NUMPY_REALS
    ):
        x = float(value)
    else:
        return None
    if not (math.isfinite(x) and abs(x) <= LARGEST):
        return None
    for ok in _RULES[rules]:
        if not ok(x):
            return None
    return x


def _item(x: Any) -> Any:
    return x.reshape(()) if type(x) is np.ndarray else x


#: Dtypes of the array path's string fields (``numpy.asarray(names)[codes]``).
_TEXT = {"regime": np.asarray(_REGIME_NAMES).dtype, "min_energy_case": np.asarray(
    MIN_ENERGY_CASES).dtype}  # fmt: skip


def spread(one: Any, shape: tuple[int, ...]) -> Any:
    """The result ``one`` of one impact with every field an array of ``shape`` (all its
    lengths 1; read-only, of the dtype the array path gives), as the array path returns
    one-element inputs."""
    values = {}
    for name, v in one.__dict__.items():
        if hasattr(v, "_items"):  # a nested result
            values[name] = spread(v, shape)
        elif isinstance(v, np.generic) or name in _TEXT:  # text of one impact: a str
            a = np.array(v, dtype=_TEXT[name] if name in _TEXT else v.dtype, ndmin=len(shape))
            a.setflags(write=False)
            values[name] = a
        else:
            values[name] = v
    return build(type(one), values)


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
    nd = np.ndarray
    if (
        type(vx) is nd or type(vy) is nd or type(omega) is nd or type(mu) is nd
        or type(kappa) is nd
    ) and any(type(x) is nd and x.ndim for x in (vx, vy, omega, mu, kappa)):  # fmt: skip
        arrays = [x for x in (vx, vy, omega, mu, kappa) if type(x) is np.ndarray and x.ndim]
        if any(a.size != 1 for a in arrays):
            return None
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
        one = paper_impact(body, *(_item(x) for x in (vx, vy, omega, mu, kappa)), kinds)
        return None if one is None else spread(one, shape)
    m, r, g, z = body.mass, body.radius, body.gyration, body.zeta
    if not (type(m) is float and type(r) is float and type(g) is float and type(z) is float):
        return None
    if callable(kappa):
        return None
    vx_ = number(vx, "vx")
    vy_ = number(vy, "vy")
    om_ = number(omega, "omega")
    mu_ = number(mu, "mu")
    k = number(kappa, "kappa")
    if vx_ is None or vy_ is None or om_ is None or mu_ is None or k is None:
        return None
    impact, state, outcome = kinds
    inertia = m * (g * g)
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
    flags = law.outcome_flags(vx_, vy_, om_, r, z, mu_, k)
    # the three restitution coefficients by their definitions (core.restitution)
    eta2 = -wrn / wcn
    f = _FLOAT
    return build(
        impact,
        {
            "body": body,
            "mu": f(mu_),
            "kappa": f(k),
            "before": build(state, {"vx": f(vx_), "vy": f(vy_), "omega": f(om_)}),
            "after": build(state, {"vx": f(vx1), "vy": f(vy1), "omega": f(om1)}),
            "slip_before": f(slip),
            "slip_after": f(slip1),
            "incidence_ratio": f(ratio),
            "regime": REGIMES[code],
            "tau0": f(tau0),
            "tau_star": f(tau_star),
            "tau1": f(tau1),
            "tangential_impulse": f(f1),
            "impulse_ratio": f(mu_hat),
            "kinetic_energy_before": f(e0),
            "kinetic_energy_after": f(law.kinetic_energy(vx1, vy1, om1, m, inertia)),
            "dissipated_energy": f(loss),
            "dissipated_fraction": f(loss / e0),
            "work_compression_normal": f(wcn),
            "work_compression_tangential": f(wct),
            "work_restitution_normal": f(wrn),
            "work_restitution_tangential": f(wrt),
            "work_ratio_tangential": f(law.work_ratio_tangential(ratio, z, mu_, k)),
            "min_kinetic_energy": f(e_min),
            "tau_min_energy": f(tau_m),
            "min_energy_case": _CASES[case],
            "newton_restitution": f(-vy1 / vy_),
            "poisson_restitution": f((m * (vy1 - vy_) - tau0) / tau0),
            "energetic_restitution": f(math.sqrt(eta2 if eta2 > 0.0 else 0.0)),
            "outcome": build(
                outcome,
                {
                    "backward": _TRUE if flags[0] else _FALSE,
                    "reversed_spin": _TRUE if flags[1] else _FALSE,
                    "vertical": _TRUE if flags[2] else _FALSE,
                    "spinning": _TRUE if flags[3] else _FALSE,
                    "rolling": _TRUE if flags[4] else _FALSE,
                },
            ),  # fmt: skip
        },
    )
