"""One sphere impact in microseconds: the scalar path of :func:`~spinimpact.solve_sphere`.

As :mod:`spinimpact.model._fast` does for :func:`~spinimpact.solve`: when the velocity and
spin are each three plain numbers (a list, a tuple or an array of shape ``(3,)``), ``mu``
and ``kappa`` are plain numbers, the surface holds one normal and one velocity and the
body's numbers are floats, :func:`sphere_impact` computes every field of
:class:`~spinimpact.SphereImpact` with the per-contact law on floats
(:mod:`spinimpact.core.scalar3d`, :mod:`spinimpact.core.scalar`), in the array path's
operations and order: the same result, field for field, bit for bit
(``tests/model/test_fast_sphere.py``). Anything else, or a value the array path would
refuse, returns ``None`` and ``solve_sphere`` takes the array path, which raises the
usual errors.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._validation import SMALLEST
from ..core import scalar as law
from ..core import scalar3d as law3
from ._fast import REGIMES, build, number

__all__ = ["pair_impact", "sphere_impact"]

_FLOAT = np.float64
_NAN = math.nan
#: NumPy's own arctan2, not the C library's (they differ in the last bit at times)
_ATAN2 = np.arctan2
_LEVEL = ((0.0, 1.0, 0.0), (0.0, 0.0, 0.0))  #: normal and velocity of ``Surface()``
_TOUCH_RTOL = 1e-9  # as model.pair: how far from touching two given centres may be


def _vector3(value: Any) -> tuple[float, float, float] | None:
    """Three floats if ``value`` is three numbers ``vector3`` accepts, else ``None``."""
    if type(value) is np.ndarray:
        if value.shape != (3,) or value.dtype.kind not in "iuf":
            return None
        value = value.tolist()
    elif type(value) not in (list, tuple) or len(value) != 3:
        return None
    x, y, z = (number(c, "vx") for c in value)  # finite, at most LARGEST: as vector3
    if x is None or y is None or z is None:
        return None
    return x, y, z


def _surface_vector(a: Any) -> tuple[float, float, float] | None:
    return tuple(a.tolist()) if type(a) is np.ndarray and a.shape == (3,) else None


def _vec(vector: type, a: tuple) -> Any:
    return build(vector, {"x": _FLOAT(a[0]), "y": _FLOAT(a[1]), "z": _FLOAT(a[2])})


def _state(state: type, a: tuple, b: tuple) -> Any:
    names = ("vx", "vy", "vz", "wx", "wy", "wz")
    return build(state, dict(zip(names, map(_FLOAT, (*a, *b)), strict=True)))


def _floats(ball: Any) -> bool:
    return all(type(getattr(ball, n)) is float for n in ("mass", "radius", "gyration", "zeta"))


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
    m, radius, zeta = body.mass, body.radius, body.zeta
    kind, state, vector, plane = kinds
    if surface is None:  # Surface(): exactly these, without building one
        n, vs = _LEVEL
    elif isinstance(surface, plane):
        n, vs = _surface_vector(surface.normal), _surface_vector(surface.velocity)
    else:
        return None
    v, w = _vector3(velocity), _vector3(spin)
    mu_, k = number(mu, "mu"), number(kappa, "kappa")
    if v is None or w is None or n is None or vs is None or mu_ is None or k is None:
        return None
    inertia = body.inertia
    cn, ct, speed, e = law3.sphere_contact(v, w, n, radius, vs)
    if not cn <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    (tau0, tau_star, tau1, f1, _, _, code, wcn, wct, wrn, wrt, loss, _, _) = law.contact_impact(
        speed, cn, m, zeta, mu_, k
    )
    friction = (f1 * e[0], f1 * e[1], f1 * e[2])
    total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
    v1 = (v[0] + total[0] / m, v[1] + total[1] / m, v[2] + total[2] / m)
    w1 = law3._spin_change(w, n, radius, inertia, friction)
    cn1, ct1, _, _ = law3.sphere_contact(v1, w1, n, radius, vs)
    dot = law3._dot
    e0 = 0.5 * m * dot(v, v) + 0.5 * inertia * dot(w, w)
    e1 = 0.5 * m * dot(v1, v1) + 0.5 * inertia * dot(w1, w1)
    vrel = (v[0] - vs[0], v[1] - vs[1], v[2] - vs[2])
    e0_rel = 0.5 * m * dot(vrel, vrel) + 0.5 * inertia * dot(w, w)
    stuck = speed <= (1.0 + k) * zeta * mu_ * abs(cn)
    rel = (v1[0] - vs[0], v1[1] - vs[1], v1[2] - vs[2])
    up = dot(rel, n)
    along = (rel[0] - up * n[0], rel[1] - up * n[1], rel[2] - up * n[2])
    travel = math.sqrt(dot(along, along))
    if travel > 0.0:
        et = (along[0] / travel, along[1] / travel, along[2] / travel)
        top, gyro = dot(w1, law3._cross(n, et)), dot(w1, et)
    else:
        top = gyro = _NAN
    eta2 = -wrn / wcn
    f = _FLOAT

    def vec(a: tuple) -> Any:
        return _vec(vector, a)

    def st(a: tuple, b: tuple) -> Any:
        return _state(state, a, b)

    return build(kind, {
        "body": body, "mu": f(mu_), "kappa": f(k), "normal": vec(n),
        "surface_velocity": vec(vs), "before": st(v, w), "after": st(v1, w1),
        "slip_before": vec(ct), "slip_after": vec((0.0, 0.0, 0.0) if stuck else ct1),
        "normal_velocity_before": f(cn), "normal_velocity_after": f(cn1),
        "regime": REGIMES[code], "tau0": f(tau0), "tau_star": f(tau_star), "tau1": f(tau1),
        "friction_impulse": vec(friction), "impulse_ratio": f((-f1 + 0.0) / tau1),
        "kinetic_energy_before": f(e0), "kinetic_energy_after": f(e1),
        "dissipated_energy": f(loss), "dissipated_fraction": f(loss / e0_rel),
        "work_compression_normal": f(wcn), "work_compression_tangential": f(wct),
        "work_restitution_normal": f(wrn), "work_restitution_tangential": f(wrt),
        "newton_restitution": f(-cn1 / cn), "poisson_restitution": f((tau1 - tau0) / tau0),
        "energetic_restitution": f(math.sqrt(eta2 if eta2 > 0.0 else 0.0)),
        "rebound_speed": f(math.sqrt(dot(v1, v1))), "rebound_angle": _ATAN2(up, travel),
        "topspin": f(top), "sidespin": f(dot(w1, n)), "gyrospin": f(gyro),
        "grips": np.True_ if stuck else np.False_,
    })  # fmt: skip


def _pair_normal(normal: Any, centres: Any, touch: float) -> tuple | None:
    """The unit normal as ``solve_pair`` forms it, or ``None`` where it would refuse it."""
    if (normal is None) == (centres is None):
        return None
    if normal is not None:
        n = _vector3(normal)
        if n is None:
            return None
        length = math.sqrt(law3._dot(n, n))
        if not length > 1e-12:
            return None
        return (n[0] / length, n[1] / length, n[2] / length)
    if type(centres) not in (list, tuple) or len(centres) != 2:
        return None
    a, b = _vector3(centres[0]), _vector3(centres[1])
    if a is None or b is None:
        return None
    d = (a[0] - b[0], a[1] - b[1], a[2] - b[2])
    gap = math.sqrt(law3._dot(d, d))
    if gap < touch * (1 - _TOUCH_RTOL) or gap > touch * (1 + _TOUCH_RTOL):
        return None
    return (d[0] / gap, d[1] / gap, d[2] / gap)


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
    v1, w1 = _vector3(velocity1), _vector3(spin1)
    v2, w2 = _vector3(velocity2), _vector3(spin2)
    mu_, k = number(mu, "mu"), number(kappa, "kappa")
    if v1 is None or w1 is None or v2 is None or w2 is None or mu_ is None or k is None:
        return None
    n = _pair_normal(normal, centres, r1 + r2)
    if n is None:
        return None
    dot, cross = law3._dot, law3._cross

    def material(v: tuple, w: tuple) -> tuple:  # ball 2's material point at the contact
        a = cross(w, (r2 * n[0], r2 * n[1], r2 * n[2]))
        return (v[0] + a[0], v[1] + a[1], v[2] + a[2])

    cn, ct, speed, e = law3.sphere_contact(v1, w1, n, r1, material(v2, w2))
    if not cn <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    kind, state, vector = kinds
    m, zeta = law3.pair_parameters(m1, j1, r1, m2, j2, r2)
    (tau0, tau_star, tau1, f1, _, _, code, wcn, wct, wrn, wrt, loss, _, _) = law.contact_impact(
        speed, cn, m, zeta, mu_, k
    )
    friction = (f1 * e[0], f1 * e[1], f1 * e[2])
    total = (tau1 * n[0] + friction[0], tau1 * n[1] + friction[1], tau1 * n[2] + friction[2])
    v1b = (v1[0] + total[0] / m1, v1[1] + total[1] / m1, v1[2] + total[2] / m1)
    v2b = (v2[0] - total[0] / m2, v2[1] - total[1] / m2, v2[2] - total[2] / m2)
    w1b = law3._spin_change(w1, n, r1, j1, friction)
    w2b = law3._spin_change(w2, n, r2, j2, friction)
    cn1, ct1, _, _ = law3.sphere_contact(v1b, w1b, n, r1, material(v2b, w2b))

    def energy(m_: float, j: float, v: tuple, w: tuple) -> float:
        return 0.5 * m_ * dot(v, v) + 0.5 * j * dot(w, w)

    e0 = energy(m1, j1, v1, w1) + energy(m2, j2, v2, w2)
    e1 = energy(m1, j1, v1b, w1b) + energy(m2, j2, v2b, w2b)
    p = (m1 * v1[0] + m2 * v2[0], m1 * v1[1] + m2 * v2[1], m1 * v1[2] + m2 * v2[2])
    e_cm = e0 - 0.5 * dot(p, p) / (m1 + m2)
    stuck = speed <= (1.0 + k) * zeta * mu_ * abs(cn)
    s1, s2 = math.sqrt(dot(v1b, v1b)), math.sqrt(dot(v2b, v2b))
    sine = cross(v1b, v2b)
    angle = _ATAN2(math.sqrt(dot(sine, sine)), dot(v1b, v2b)) if s1 > 0 and s2 > 0 else _NAN
    eta2 = -wrn / wcn
    f = _FLOAT
    return build(kind, {
        "ball1": ball1, "ball2": ball2, "mu": f(mu_), "kappa": f(k), "normal": _vec(vector, n),
        "before1": _state(state, v1, w1), "before2": _state(state, v2, w2),
        "after1": _state(state, v1b, w1b), "after2": _state(state, v2b, w2b),
        "slip_before": _vec(vector, ct),
        "slip_after": _vec(vector, (0.0, 0.0, 0.0) if stuck else ct1),
        "normal_velocity_before": f(cn), "normal_velocity_after": f(cn1),
        "regime": REGIMES[code], "tau0": f(tau0), "tau_star": f(tau_star), "tau1": f(tau1),
        "friction_impulse": _vec(vector, friction), "impulse_ratio": f((-f1 + 0.0) / tau1),
        "kinetic_energy_before": f(e0), "kinetic_energy_after": f(e1),
        "dissipated_energy": f(loss), "dissipated_fraction": f(loss / e_cm),
        "work_compression_normal": f(wcn), "work_compression_tangential": f(wct),
        "work_restitution_normal": f(wrn), "work_restitution_tangential": f(wrt),
        "newton_restitution": f(-cn1 / cn), "poisson_restitution": f((tau1 - tau0) / tau0),
        "energetic_restitution": f(math.sqrt(eta2 if eta2 > 0.0 else 0.0)),
        "grips": np.True_ if stuck else np.False_, "angle_between_paths": f(angle),
    })  # fmt: skip
