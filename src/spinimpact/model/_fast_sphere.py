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
    cn = law3.sphere_contact(v, w, n, radius, vs)[0]
    if not cn <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    (cn, ct, v1, w1, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1, loss, fraction,
     wcn, wct, wrn, wrt, newton, poisson, energetic, speed, up, along, top, side, gyro, code,
     stuck) = law3.sphere_impact_fields(v, w, n, vs, m, radius, body.inertia, zeta, mu_,
                                        k)  # fmt: skip
    f = _FLOAT

    def vec(a: tuple) -> Any:
        return _vec(vector, a)

    def st(a: tuple, b: tuple) -> Any:
        return _state(state, a, b)

    return build(kind, {
        "body": body, "mu": f(mu_), "kappa": f(k), "normal": vec(n),
        "surface_velocity": vec(vs), "before": st(v, w), "after": st(v1, w1),
        **_shared(vector, cn, ct, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1,
                  loss, fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, code, stuck),
        "rebound_speed": f(speed), "rebound_angle": _ATAN2(up, along), "topspin": f(top),
        "sidespin": f(side), "gyrospin": f(gyro),
    })  # fmt: skip


def _shared(vector: type, cn: float, ct: tuple, slip1: tuple, cn1: float, tau0: float,
            tau_star: float, tau1: float, friction: tuple, ratio: float, e0: float, e1: float,
            loss: float, fraction: float, wcn: float, wct: float, wrn: float, wrt: float,
            newton: float, poisson: float, energetic: float, code: int,
            stuck: bool) -> dict:  # fmt: skip
    """The fields a sphere's and a pair's results share, as result values."""
    f = _FLOAT
    return {
        "slip_before": _vec(vector, ct), "slip_after": _vec(vector, slip1),
        "normal_velocity_before": f(cn), "normal_velocity_after": f(cn1),
        "regime": REGIMES[code], "tau0": f(tau0), "tau_star": f(tau_star), "tau1": f(tau1),
        "friction_impulse": _vec(vector, friction), "impulse_ratio": f(ratio),
        "kinetic_energy_before": f(e0), "kinetic_energy_after": f(e1),
        "dissipated_energy": f(loss), "dissipated_fraction": f(fraction),
        "work_compression_normal": f(wcn), "work_compression_tangential": f(wct),
        "work_restitution_normal": f(wrn), "work_restitution_tangential": f(wrt),
        "newton_restitution": f(newton), "poisson_restitution": f(poisson),
        "energetic_restitution": f(energetic), "grips": np.True_ if stuck else np.False_,
    }  # fmt: skip


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
    r2n = (r2 * n[0], r2 * n[1], r2 * n[2])
    a = law3._cross(w2, r2n)
    cn = law3.sphere_contact(v1, w1, n, r1, (v2[0] + a[0], v2[1] + a[1], v2[2] + a[2]))[0]
    if not cn <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    kind, state, vector = kinds
    (cn, ct, v1b, w1b, v2b, w2b, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1,
     loss, fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, sine, cosine, code,
     stuck) = law3.pair_impact_fields(v1, w1, v2, w2, n, m1, r1, j1, m2, r2, j2, mu_,
                                      k)  # fmt: skip
    f = _FLOAT
    return build(kind, {
        "ball1": ball1, "ball2": ball2, "mu": f(mu_), "kappa": f(k), "normal": _vec(vector, n),
        "before1": _state(state, v1, w1), "before2": _state(state, v2, w2),
        "after1": _state(state, v1b, w1b), "after2": _state(state, v2b, w2b),
        **_shared(vector, cn, ct, slip1, cn1, tau0, tau_star, tau1, friction, ratio, e0, e1,
                  loss, fraction, wcn, wct, wrn, wrt, newton, poisson, energetic, code, stuck),
        "angle_between_paths": f(_ATAN2(sine, cosine)),
    })  # fmt: skip
