"""Many sphere impacts in one pass over memory: the fused path of ``solve_sphere``/``solve_pair``.

For arrays of at least :data:`THRESHOLD` impacts, with Numba installed and ``kappa`` given
as numbers (not a model of the impact speed), :func:`~spinimpact.solve_sphere` and
:func:`~spinimpact.solve_pair` take every computed field from
:mod:`spinimpact.core.fused_sphere` (one compiled pass, in parallel) instead of the NumPy
kernels; the fields are equal bit for bit (``tests/model/test_fused_sphere.py``). The
inputs are validated by the same functions as the array path's; wherever anything would be
refused (a value out of its range, a contact that does not approach), these functions
return ``None`` and the array path raises its usual error, so messages do not change.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import core
from .._validation import SMALLEST, available, validated, vector3
from ._fast_sphere import SHARED_FIELDS

__all__ = ["THRESHOLD", "pair_impact", "sphere_impact"]

#: Fewest impacts for which the fused path is taken (the NumPy path remains for 0-d input,
#: empty arrays, a callable ``kappa`` and without Numba).
THRESHOLD = 1


def _kernels() -> Any:
    """:mod:`spinimpact.core.fused_sphere`, or ``None`` without a working Numba (imported on
    first use, so that ``import spinimpact`` stays light)."""
    if not available("numba"):
        return None
    from ..core import fused_sphere

    return fused_sphere if fused_sphere.HAVE_NUMBA else None


def _owned(a: np.ndarray) -> np.ndarray:
    """A fresh kernel output as a read-only result field (no copy: nobody else holds it)."""
    view = a.view()
    view.setflags(write=False)
    return view


def _frozen(a: np.ndarray) -> Any:
    """An input as a read-only result field: a copy, as :func:`~.result.freeze` makes."""
    out = np.array(a)
    out.setflags(write=False)
    return out


def _vector(kind: type, a: np.ndarray) -> Any:
    return kind(*(_frozen(a[..., i]) for i in range(3)))


def _fields(kind: type, fields: dict[str, np.ndarray], prefix: str, names: tuple) -> Any:
    return kind(*(_owned(fields[f"{prefix}{n}"]) for n in names))


def _common(fields: dict, code: np.ndarray, grips: np.ndarray, vector: type) -> dict:
    """The fields every sphere result shares, from the kernel's table."""
    out = {name: _owned(fields[name]) for name in SHARED_FIELDS}
    for name in ("slip_before", "slip_after", "friction_impulse"):
        out[name] = _fields(vector, fields, f"{name}_", ("x", "y", "z"))
    out["regime"] = _owned(np.asarray(core.REGIMES)[code])
    out["grips"] = _owned(grips)
    return out


def _shape(least: int | None, *shapes: tuple[int, ...]) -> tuple[int, ...] | None:
    """The impacts' broadcast shape, or ``None`` where the fused path does not apply."""
    try:
        shape = np.broadcast_shapes(*shapes)
    except ValueError:
        return None  # the array path says why
    size = int(np.prod(shape, dtype=np.int64))
    if shape == () or size == 0 or size < (THRESHOLD if least is None else least):
        return None
    return shape


_STATE = ("vx", "vy", "vz", "wx", "wy", "wz")


def sphere_impact(body: Any, velocity: Any, spin: Any, mu: Any, kappa: Any, surface: Any,
                  kinds: tuple, *, threshold: int | None = None) -> Any:  # fmt: skip
    """The :class:`~spinimpact.SphereImpact` of many impacts from the fused kernel, or ``None``.

    Parameters
    ----------
    body, velocity, spin, mu, kappa, surface
        As given to :func:`~spinimpact.solve_sphere` (``body`` already checked to be a
        sphere).
    kinds : tuple
        The classes ``(SphereImpact, State3, Vector, Surface)``.
    threshold : int, optional
        Fewest impacts to take the fused path (default :data:`THRESHOLD`).

    Returns
    -------
    SphereImpact or None
        ``None`` without Numba, for one impact (0-d), below the threshold, for a callable
        ``kappa``, or wherever the array path would refuse the input.
    """
    fused = None if callable(kappa) else _kernels()
    if fused is None:
        return None
    kind, state, vector, plane = kinds
    try:
        surface = plane() if surface is None else surface
        if not isinstance(surface, plane):
            return None
        v, w = vector3("velocity", velocity), vector3("spin", spin)
        mu_, kappa_ = validated("mu", mu), validated("kappa", kappa)
    except (TypeError, ValueError):
        return None  # the array path raises the same error
    nrm, vs = surface.normal, surface.velocity
    parts = [np.asarray(x) for x in (body.mass, body.radius, body.inertia, body.zeta)]
    shape = _shape(threshold, v.shape[:-1], w.shape[:-1], nrm.shape[:-1], vs.shape[:-1],
                   mu_.shape, kappa_.shape, *(x.shape for x in parts))  # fmt: skip
    if shape is None:
        return None
    v, w, nrm, vs = (np.broadcast_to(x, (*shape, 3)) for x in (v, w, nrm, vs))
    fields, code, grips = fused.sphere_fields(v, w, nrm, vs, *parts, mu_, kappa_)
    if not np.all(fields["normal_velocity_before"] <= -SMALLEST):
        return None  # the array path refuses the contact that does not approach
    with np.errstate(invalid="ignore"):  # NaN where the ball leaves along the normal
        angle = np.arctan2(fields["rebound_up"], fields["rebound_along"])
    return kind(
        body=body, mu=_frozen(np.broadcast_to(mu_, shape)),
        kappa=_frozen(np.broadcast_to(kappa_, shape)),
        normal=_vector(vector, nrm), surface_velocity=_vector(vector, vs),
        before=state(*(_frozen(x[..., i]) for x in (v, w) for i in range(3))),
        after=_fields(state, fields, "after_", _STATE),
        **_common(fields, code, grips, vector),
        rebound_speed=_owned(fields["rebound_speed"]), rebound_angle=_owned(angle),
        topspin=_owned(fields["topspin"]), sidespin=_owned(fields["sidespin"]),
        gyrospin=_owned(fields["gyrospin"]),
    )  # fmt: skip


def pair_impact(ball1: Any, ball2: Any, v1: np.ndarray, w1: np.ndarray, v2: np.ndarray,
                w2: np.ndarray, mu: np.ndarray, kappa: Any, normal: np.ndarray, kinds: tuple,
                *, threshold: int | None = None) -> Any:  # fmt: skip
    """The :class:`~spinimpact.PairImpact` of many impacts from the fused kernel, or ``None``.

    As :func:`sphere_impact`, for :func:`~spinimpact.solve_pair`, given the array path's
    validated vectors ``v1, w1, v2, w2``, ``mu`` and unit ``normal`` (from ball 2's centre
    to ball 1's); ``kinds`` are the classes ``(PairImpact, State3, Vector)``.
    """
    fused = None if callable(kappa) else _kernels()
    if fused is None:
        return None
    kind, state, vector = kinds
    try:
        kappa_ = validated("kappa", kappa)
    except (TypeError, ValueError):
        return None  # the array path raises the same error
    p1 = [np.asarray(x) for x in (ball1.mass, ball1.radius, ball1.inertia)]
    p2 = [np.asarray(x) for x in (ball2.mass, ball2.radius, ball2.inertia)]
    shape = _shape(threshold, *(x.shape[:-1] for x in (v1, w1, v2, w2, normal)), mu.shape,
                   kappa_.shape, *(x.shape for x in (*p1, *p2)))  # fmt: skip
    if shape is None:
        return None
    v1, w1, v2, w2, n = (np.broadcast_to(x, (*shape, 3)) for x in (v1, w1, v2, w2, normal))
    fields, code, grips = fused.pair_fields(v1, w1, v2, w2, n, *p1, *p2, mu, kappa_)
    if not np.all(fields["normal_velocity_before"] <= -SMALLEST):
        return None  # the array path refuses the contact that does not approach
    with np.errstate(invalid="ignore"):
        angle = np.arctan2(fields["paths_sine"], fields["paths_cosine"])
    return kind(
        ball1=ball1, ball2=ball2, mu=_frozen(np.broadcast_to(mu, shape)),
        kappa=_frozen(np.broadcast_to(kappa_, shape)), normal=_vector(vector, n),
        before1=state(*(_frozen(x[..., i]) for x in (v1, w1) for i in range(3))),
        before2=state(*(_frozen(x[..., i]) for x in (v2, w2) for i in range(3))),
        after1=_fields(state, fields, "after1_", _STATE),
        after2=_fields(state, fields, "after2_", _STATE),
        **_common(fields, code, grips, vector), angle_between_paths=_owned(angle),
    )  # fmt: skip
