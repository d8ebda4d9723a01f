"""One sphere impact in microseconds: the scalar path of :func:`~spinimpact.solve_sphere`
and :func:`~spinimpact.solve_pair`.

As :mod:`spinimpact.model._fast` does for :func:`~spinimpact.solve`: when the velocities
and spins are each three plain numbers (a list, a tuple or an array of three, of shape
``(3,)`` or ``(1, ..., 1, 3)``), ``mu`` and ``kappa`` plain numbers (or arrays of one
element), the surface holds one normal and one velocity and the bodies' numbers are floats,
:func:`sphere_impact` and :func:`pair_impact` compute every field with the per-contact law
on floats (:mod:`spinimpact.core.scalar3d`, :mod:`spinimpact.core.scalar`), in the array
path's operations and order: the same result, field for field, bit for bit, NumPy scalars
or, when an input was an array of one impact, read-only arrays of the broadcast shape
(``tests/model/test_fast_sphere.py``, ``tests/model/test_fast_paths.py``). Anything else,
or a value the array path would refuse, returns ``None`` and the solver takes the array
path, which raises the usual errors.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._validation import LARGEST, SMALLEST
from ..core import scalar3d as law3
from ._fast import REGIMES, number
from ._fast_result import Layout, layout_for

__all__ = ["SHARED_FIELDS", "pair_impact", "sphere_impact"]

_NDARRAY = np.ndarray
#: NumPy's own arctan2, not the C library's (they differ in the last bit at times)
_ATAN2 = np.arctan2
_LEVEL = ((0.0, 1.0, 0.0), (0.0, 0.0, 0.0))  #: normal and velocity of ``Surface()``
_TOUCH_RTOL = 1e-9  # as model.pair: how far from touching two given centres may be
_XYZ = ("x", "y", "z")
_STATE = ("vx", "vy", "vz", "wx", "wy", "wz")
#: The float fields a sphere's and a pair's results share, in the order the paths give them.
SHARED_FIELDS = (
    "normal_velocity_before", "normal_velocity_after", "tau0", "tau_star", "tau1",
    "impulse_ratio", "kinetic_energy_before", "kinetic_energy_after", "dissipated_energy",
    "dissipated_fraction", "work_compression_normal", "work_compression_tangential",
    "work_restitution_normal", "work_restitution_tangential", "newton_restitution",
    "poisson_restitution", "energetic_restitution",
)  # fmt: skip


def _vector3(value: Any) -> tuple[tuple[float, float, float], tuple[int, ...]] | None:
    """``((x, y, z), shape)`` if ``value`` is three numbers ``vector3`` accepts (``shape``:
    the impacts' shape, ``()`` but for an array of shape ``(1, ..., 1, 3)``), else ``None``."""
    kind = type(value)
    shape: tuple[int, ...] = ()
    if kind is tuple or kind is list:
        if len(value) != 3:
            return None
        x, y, z = value
        if type(x) is float and type(y) is float and type(z) is float:  # the common case
            if -LARGEST <= x <= LARGEST and -LARGEST <= y <= LARGEST and -LARGEST <= z <= LARGEST:
                return (x, y, z), shape
            return None
    elif kind is _NDARRAY:
        if value.size != 3 or value.shape[-1] != 3 or value.dtype.kind not in "iuf":
            return None
        shape = value.shape[:-1]
        value = value.reshape(3).tolist()
    else:
        return None
    x, y, z = (number(c, "vx") for c in value)  # finite, at most LARGEST: as vector3
    if x is None or y is None or z is None:
        return None
    return (x, y, z), shape


def _surface_vector(a: Any) -> tuple[tuple, tuple[int, ...]] | None:
    if type(a) is _NDARRAY and a.size == 3 and a.shape[-1] == 3:
        return tuple(a.reshape(3).tolist()), a.shape[:-1]
    return None


def _number(value: Any, rules: str) -> tuple[float | None, tuple[int, ...]]:
    """``number(value, rules)`` and the shape of an array of one element (else ``()``)."""
    if type(value) is _NDARRAY and value.ndim:
        if value.size != 1 or value.dtype.kind not in "iuf":
            return None, ()
        return number(value[(0,) * value.ndim], rules), value.shape
    return number(value, rules), ()


def _floats(ball: Any) -> bool:
    return (type(ball.mass) is float and type(ball.radius) is float
            and type(ball.gyration) is float)  # fmt: skip


def _shape(*shapes: tuple[int, ...]) -> tuple[int, ...] | None:
    """The broadcast shape of the impacts, ``None`` for plain numbers (all ``()``); every
    length is 1 (arrays of one element), so it is ``(1,) * the most dimensions``."""
    most = max(map(len, shapes))
    return (1,) * most if most else None


def _vector(kind: type) -> Layout:
    return Layout(kind, _XYZ)


def _sphere_layout(kind: type, state: type, vector: type) -> Layout:
    v, s = _vector(vector), Layout(state, _STATE)
    return Layout(
        kind,
        ("mu", "kappa", *SHARED_FIELDS, "rebound_speed", "rebound_angle", "topspin", "sidespin",
         "gyrospin"),
        nested=(("normal", v), ("surface_velocity", v), ("before", s), ("after", s),
                ("slip_before", v), ("slip_after", v), ("friction_impulse", v)),
        flags=("grips",), text={"regime": REGIMES}, given=("body",),
    )  # fmt: skip


def _pair_layout(kind: type, state: type, vector: type) -> Layout:
    v, s = _vector(vector), Layout(state, _STATE)
    return Layout(
        kind, ("mu", "kappa", *SHARED_FIELDS, "angle_between_paths"),
        nested=(("normal", v), ("before1", s), ("before2", s), ("after1", s), ("after2", s),
                ("slip_before", v), ("slip_after", v), ("friction_impulse", v)),
        flags=("grips",), text={"regime": REGIMES}, given=("ball1", "ball2"),
    )  # fmt: skip


def sphere_impact(body: Any, velocity: Any, spin: Any, mu: Any, kappa: Any, surface: Any,
                  kinds: tuple) -> Any:  # fmt: skip
    """The :class:`~spinimpact.SphereImpact` of one impact, or ``None``.

    Parameters
    ----------
    body, velocity, spin, mu, kappa, surface
        As given to :func:`~spinimpact.solve_sphere` (``body`` already checked to be a
        :class:`~spinimpact.Body`; ``surface`` ``None`` or anything).
    kinds : tuple
        The classes ``(SphereImpact, State3, Vector, Surface)``.

    Returns
    -------
    SphereImpact or None
        ``None`` unless all inputs are single plain numbers and vectors, the body's numbers
        floats, and the contact point approaches the surface.
    """
    if not _floats(body) or callable(kappa):
        return None
    kind, state, vector, plane = kinds
    n_shape = vs_shape = ()
    if surface is None:  # Surface(): exactly these, without building one
        n, vs = _LEVEL
    elif isinstance(surface, plane):
        a, b = _surface_vector(surface.normal), _surface_vector(surface.velocity)
        if a is None or b is None:
            return None
        (n, n_shape), (vs, vs_shape) = a, b
    else:
        return None
    a, b = _vector3(velocity), _vector3(spin)
    (mu_, mu_shape), (k, k_shape) = _number(mu, "mu"), _number(kappa, "kappa")
    if a is None or b is None or mu_ is None or k is None:
        return None
    (v, v_shape), (w, w_shape) = a, b
    m, radius, zeta = body.mass, body.radius, body.zeta
    if not law3.sphere_contact(v, w, n, radius, vs)[0] <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    (cn, ct, v1, w1, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1, loss, fraction,
     wcn, wct, wrn, wrt, newton, poisson, energetic, speed, up, along, top, side, gyro, code,
     stuck) = law3.sphere_impact_fields(v, w, n, vs, m, radius, body.inertia, zeta, mu_,
                                        k)  # fmt: skip
    layout = layout_for(_sphere_layout, kind, state, vector)
    floats = (
        mu_, k, cn, cn1, tau0, tau_star, tau1, ratio, e0, e1, loss, fraction, wcn, wct, wrn,
        wrt, newton, poisson, energetic, speed, _ATAN2(up, along), top, side, gyro, *n, *vs,
        *v, *w, *v1, *w1, *ct, *slip1, *friction,
    )  # fmt: skip
    shape = _shape(v_shape, w_shape, mu_shape, k_shape, n_shape, vs_shape)
    return layout.result(floats, (stuck,), {"body": body, "regime": REGIMES[code]}, shape)


def _pair_normal(normal: Any, centres: Any, touch: float) -> tuple | None:
    """``(n, shape)``: the unit normal as ``solve_pair`` forms it and the shape of the array
    it came from, or ``None`` where it would refuse it."""
    if (normal is None) == (centres is None):
        return None
    if normal is not None:
        given = _vector3(normal)
        if given is None:
            return None
        n, shape = given
        length = math.sqrt(law3._dot(n, n))
        if not length > 1e-12:
            return None
        return (n[0] / length, n[1] / length, n[2] / length), shape
    if type(centres) not in (list, tuple) or len(centres) != 2:
        return None
    a, b = _vector3(centres[0]), _vector3(centres[1])
    if a is None or b is None:
        return None
    (a, a_shape), (b, b_shape) = a, b
    d = (a[0] - b[0], a[1] - b[1], a[2] - b[2])
    gap = math.sqrt(law3._dot(d, d))
    if gap < touch * (1 - _TOUCH_RTOL) or gap > touch * (1 + _TOUCH_RTOL):
        return None
    return (d[0] / gap, d[1] / gap, d[2] / gap), _shape(a_shape, b_shape) or ()


def pair_impact(ball1: Any, ball2: Any, velocity1: Any, spin1: Any, velocity2: Any,
                spin2: Any, mu: Any, kappa: Any, normal: Any, centres: Any,
                kinds: tuple) -> Any:  # fmt: skip
    """The :class:`~spinimpact.PairImpact` of one impact of two spheres, or ``None``.

    As :func:`sphere_impact`, for :func:`~spinimpact.solve_pair` (``kinds``:
    ``(PairImpact, State3, Vector)``): the same result bit for bit
    (``tests/model/test_fast_sphere.py``).
    """
    if not (_floats(ball1) and _floats(ball2)) or callable(kappa):
        return None
    m1, r1, j1 = ball1.mass, ball1.radius, ball1.inertia
    m2, r2, j2 = ball2.mass, ball2.radius, ball2.inertia
    a, b = _vector3(velocity1), _vector3(spin1)
    c, d = _vector3(velocity2), _vector3(spin2)
    (mu_, mu_shape), (k, k_shape) = _number(mu, "mu"), _number(kappa, "kappa")
    if a is None or b is None or c is None or d is None or mu_ is None or k is None:
        return None
    given = _pair_normal(normal, centres, r1 + r2)
    if given is None:
        return None
    (v1, v1_shape), (w1, w1_shape), (v2, v2_shape), (w2, w2_shape) = a, b, c, d
    n, n_shape = given
    r2n = (r2 * n[0], r2 * n[1], r2 * n[2])
    other = law3._cross(w2, r2n)
    other = (v2[0] + other[0], v2[1] + other[1], v2[2] + other[2])
    if not law3.sphere_contact(v1, w1, n, r1, other)[0] <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    (cn, ct, v1b, w1b, v2b, w2b, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1,
     loss, fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, sine, cosine, code,
     stuck) = law3.pair_impact_fields(v1, w1, v2, w2, n, m1, r1, j1, m2, r2, j2, mu_,
                                      k)  # fmt: skip
    layout = layout_for(_pair_layout, *kinds)
    floats = (
        mu_, k, cn, cn1, tau0, tau_star, tau1, ratio, e0, e1, loss, fraction, wcn, wct, wrn,
        wrt, newton, poisson, energetic, _ATAN2(sine, cosine), *n, *v1, *w1, *v2, *w2, *v1b,
        *w1b, *v2b, *w2b, *ct, *slip1, *friction,
    )  # fmt: skip
    shape = _shape(v1_shape, w1_shape, v2_shape, w2_shape, mu_shape, k_shape, n_shape)
    rest = {"ball1": ball1, "ball2": ball2, "regime": REGIMES[code]}
    return layout.result(floats, (stuck,), rest, shape)
