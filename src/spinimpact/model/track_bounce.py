r"""Flights across a bounce: balls flown to a level surface, bounced by the exact law, flown on.

:func:`flights` is the model of a track that crosses a surface, evaluated for many states at
once: each ball's state before the bounce (position, velocity, spin, drag coefficient) is
flown to the surface (:func:`to_surface`, whose last step is
:func:`spinimpact.core.flight.integrate_to_ground`: the contact located to the integrator's
precision), bounced by the exact 3D law of :func:`spinimpact.solve_sphere`
(:func:`spinimpact.core.ground.ground_bounce`; rigid, with Walton's tangential restitution, or
with Mindlin-Deresiewicz micro-slip read from its table, :mod:`spinimpact.core.mdr_table`)
and flown on (:func:`spinimpact.model.track.fly_to`). The fits of
:mod:`spinimpact.model.track_fit` and the predictions of :mod:`spinimpact.model.track_predict`
are built on it. Every ball of a call is flown in one batch: the loops run over time steps.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.compliance import mindlin_stiffness_ratio, walton_slip
from ..core.flight import integrate_to_ground, rk4_step
from ..core.ground import GroundBounce, ground_bounce
from ..core.mdr_table import table_slip
from .track import MAX_STEP, Air, fly_to, frame_rotation

__all__ = ["flights", "to_surface", "AtContact", "LAWS", "LAW_PARAMETERS", "BOUNDS", "CONTACT",
           "shared_names"]  # fmt: skip

#: The bounce laws and the shared parameters each adds to ``mu``, ``kappa`` and
#: ``contact_height``: Walton's tangential restitution of sticking impacts, and Poisson's ratio
#: of the ball (on a rigid table) for micro-slip (Mindlin's ``4 G*/E* = 2(1 - nu)/(2 - nu)``).
LAW_PARAMETERS = {"rigid": (), "walton": ("beta0",), "mindlin-deresiewicz": ("poisson_ratio",)}
LAWS = tuple(LAW_PARAMETERS)
#: Each shared parameter's range.
BOUNDS = {"mu": (0.0, 10.0), "kappa": (0.0, 1.0), "beta0": (-1.0, 1.0),
          "poisson_ratio": (-0.99, 0.5), "contact_height": (-np.inf, np.inf),
          "lift_slope": (0.0, 5.0)}  # fmt: skip
STEP = np.r_[np.full(3, 1e-6), np.full(3, 1e-5), np.full(3, 1e-2), 1e-4]
SCALE = np.r_[np.full(3, 1e-3), np.full(3, 1e-2), np.full(3, 30.0), 0.05]
SHARED_STEP = {"mu": 1e-5, "kappa": 1e-5, "beta0": 1e-5, "poisson_ratio": 1e-5,
               "contact_height": 1e-6, "lift_slope": 1e-5}  # fmt: skip
SHARED_SCALE = {"mu": 0.05, "kappa": 0.05, "beta0": 0.1, "poisson_ratio": 0.1,
                "contact_height": 1e-3, "lift_slope": 0.1}  # fmt: skip


def shared_names(law: str) -> tuple[str, ...]:
    """The shared parameters of a fit under ``law``: ``mu``, ``kappa``, ``contact_height``
    and the law's own (:data:`LAW_PARAMETERS`)."""
    return ("mu", "kappa", "contact_height") + LAW_PARAMETERS[law]


#: What :func:`flights` gives at each contact, besides its time.
CONTACT = ("contact_position", "velocity_before", "spin_before", "velocity_after", "spin_after")


@dataclass(frozen=True, eq=False)
class AtContact:
    """The ball at its contact with the surface (tracks' frame), as a fitted shot
    (:class:`~spinimpact.model.track_fit.Shot`) and a prediction
    (:class:`~spinimpact.model.track_predict.Prediction`) give it."""

    contact_time: float  #: s
    contact_position: np.ndarray  #: centre, m
    velocity_before: np.ndarray  #: m/s
    spin_before: np.ndarray  #: rad/s
    velocity_after: np.ndarray  #: m/s
    spin_after: np.ndarray  #: rad/s


def _rebound(law: str, shared: dict[str, np.ndarray]) -> Any:
    """The law's ``rebound_slip`` for :func:`~spinimpact.core.ground.ground_bounce`
    (``None``: the rigid law), with the law's parameter of each ball."""
    if law == "rigid":
        return None
    if law == "walton":
        beta0 = shared["beta0"]
        return lambda slip, vy, zeta, mu, kappa: walton_slip(slip, vy, zeta, mu, kappa, beta0)
    nu = np.asarray(shared["poisson_ratio"], dtype=float)

    def micro_slip(slip: Any, vy: Any, zeta: Any, mu: Any, kappa: Any) -> tuple:
        rows = np.broadcast_arrays(slip, vy, zeta, mu, kappa, nu)
        out, stuck = np.full(rows[0].shape, np.nan), np.zeros(rows[0].shape, dtype=bool)
        for value in np.unique(nu[np.isfinite(nu)]):  # one ratio a call (a fit shares one)
            i = rows[5] == value
            out[i], stuck[i] = table_slip(*(r[i] for r in rows[:5]),
                                          float(mindlin_stiffness_ratio(value)))  # fmt: skip
        return out, stuck

    return micro_slip


def to_surface(t0: np.ndarray, p: np.ndarray, v: np.ndarray, w: np.ndarray, aero: Any,
               radius: float, max_time: float = 3.0) -> dict[str, np.ndarray]:  # fmt: skip
    """Fly balls (package's frame) until their centres come down to ``y = R``.

    All balls are stepped together by :func:`spinimpact.core.flight.rk4_step` in steps of
    :data:`~spinimpact.model.track.MAX_STEP`; the step in which each ball goes below the
    surface is then flown again by :func:`spinimpact.core.flight.integrate_to_ground`, which
    locates the contact inside it to the integrator's precision (one step for every ball, so
    each ball's own drag coefficient stays with it).

    Returns
    -------
    dict
        ``time`` ``(b,)``, ``position``, ``velocity``, ``spin`` ``(b, 3)`` at the contact and
        ``hit`` (bool; NaN where a ball does not come down within ``max_time``).
    """
    b = len(t0)
    h = MAX_STEP
    start = [np.array(t0, dtype=float), p.copy(), v.copy(), w.copy()]
    done = np.zeros(b, dtype=bool)
    t = np.array(t0, dtype=float)
    for _ in range(int(np.ceil(max_time / h))):  # time steps; all balls together
        p1, v1, w1 = rk4_step(p, v, w, np.full(b, h), aero)
        cross = (p1[:, 1] < radius) & ~done
        if cross.any():
            for k, x in enumerate((t, p, v, w)):
                start[k][cross] = x[cross]
            done |= cross
            if done.all():
                break
        t, p, v, w = t + h, p1, v1, w1
    out = {
        "time": np.full(b, np.nan),
        "position": np.full((b, 3), np.nan),
        "velocity": np.full((b, 3), np.nan),
        "spin": np.full((b, 3), np.nan),
        "hit": done,
    }
    if done.any():
        drag = np.asarray(aero.drag)
        sub = aero._replace(drag=drag[done]) if drag.ndim else aero
        seg = integrate_to_ground(np.zeros(int(done.sum())), start[1][done], start[2][done],
                                  start[3][done], sub, radius=radius, t_stop=h, dt=h)  # fmt: skip
        out["time"][done] = start[0][done] + seg.time
        out["position"][done], out["velocity"][done], out["spin"][done] = (
            seg.position, seg.velocity, seg.spin)  # fmt: skip
    return out


def flights(t0: np.ndarray, states: np.ndarray, shared: dict[str, np.ndarray], air: Air,
            law: str, before: np.ndarray, after: np.ndarray, up: str,
            rebound: Any = None) -> dict[str, np.ndarray]:  # fmt: skip
    """Fly ``b`` states through their bounce (track's frame); every ball in one batch (one
    batch for each value of ``shared["lift_slope"]``, when given: the ball's lift slope, which
    the core integrator takes as one number).

    Parameters
    ----------
    t0 : ndarray, shape (b,)
        s, when the states hold.
    states : ndarray, shape (b, 10)
        Position (m), velocity (m/s), spin (rad/s) and ``C_D``, in the tracks' frame.
    shared : dict
        ``mu``, ``kappa``, ``contact_height`` (m) and the law's parameter (Walton's ``beta0``,
        micro-slip's ``poisson_ratio``): arrays ``(b,)``.
    air : Air
    law : {"rigid", "walton", "mindlin-deresiewicz"}
    before, after : ndarray, shape (b, m1) and (b, m2)
        s, the times flown before and after the bounce (``m1`` or ``m2`` may be 0).
    up : str
        The tracks' vertical axis.
    rebound : callable, optional
        ``rebound(velocity, spin) -> (velocity, spin)``, arrays ``(b, 3)`` in the tracks'
        frame: another bounce map in place of the exact law (for comparisons, such as a
        fitted rebound matrix); ``mu``, ``kappa`` and ``beta0`` are then unused.

    Returns
    -------
    dict
        ``before`` ``(b, m1, 3)`` and ``after`` ``(b, m2, 3)`` positions (NaN for a ball that
        never reaches the surface); ``contact_time`` ``(b,)``, ``contact_position``,
        ``velocity_before``, ``spin_before``, ``velocity_after``, ``spin_after`` ``(b, 3)``.
    """
    if "lift_slope" in shared:
        slopes, which = np.unique(shared["lift_slope"], return_inverse=True)
        if len(slopes) > 1:
            parts = []
            for k, a in enumerate(slopes):
                i = which == k
                sub = {n: v[i] for n, v in shared.items() if n != "lift_slope"}
                parts.append((i, flights(t0[i], states[i], sub, air.with_lift(a), law, before[i],
                                         after[i], up, rebound)))  # fmt: skip
            return {key: _merged(parts, key, len(states)) for key in parts[0][1]}
        air = air.with_lift(float(slopes[0]))
    rot = frame_rotation(up)
    ball = air.ball
    radius, body = ball.radius, ball.body
    lift = radius - shared["contact_height"]  # package height = track height + lift
    s = states[:, :9].reshape(-1, 3, 3) @ rot.T
    p, v, w = s[:, 0].copy(), s[:, 1], s[:, 2]
    p[:, 1] += lift
    aero = air.per_ball(states[:, 9])
    out: dict[str, np.ndarray] = {}

    def back(q: np.ndarray) -> np.ndarray:
        q = q.copy()
        q[..., 1] -= lift.reshape((-1,) + (1,) * (q.ndim - 2))
        return q @ rot

    b = len(states)
    out["before"] = (back(fly_to(t0, p, v, w, before, aero)[0]) if before.shape[1]
                     else np.zeros((b, 0, 3)))  # fmt: skip
    c = to_surface(t0, p, v, w, aero, radius)
    hit = c["hit"]
    vc = np.where(hit[:, None], c["velocity"], 0.0)
    wc = np.where(hit[:, None], c["spin"], 0.0)
    if rebound is None:
        bounce = ground_bounce(vc, wc, mass=ball.mass, radius=radius, inertia=body.inertia,
                               zeta=body.zeta, mu=shared["mu"], kappa=shared["kappa"],
                               rebound_slip=_rebound(law, shared))  # fmt: skip
    else:
        v1, w1 = rebound(vc @ rot, wc @ rot)
        bounce = GroundBounce(np.asarray(v1) @ rot.T, np.asarray(w1) @ rot.T, None, None)
    if after.shape[1]:
        start = np.where(hit, c["time"], t0)
        pc = np.where(hit[:, None], c["position"], p)
        q, _ = fly_to(start, pc, bounce.velocity, bounce.spin, after, aero)
        q[~hit] = np.nan
        out["after"] = back(q)
    else:
        out["after"] = np.zeros((b, 0, 3))
    out["before"][~hit] = np.nan
    out["contact_time"] = c["time"]
    out["contact_position"] = back(c["position"])
    for k, x in (("velocity_before", c["velocity"]), ("spin_before", c["spin"]),
                 ("velocity_after", bounce.velocity), ("spin_after", bounce.spin)):  # fmt: skip
        out[k] = np.where(hit[:, None], x @ rot, np.nan)
    return out


def _merged(parts: list, key: str, b: int) -> np.ndarray:
    """One output of :func:`flights` joined from its batches ``[(mask, out), ...]``."""
    first = parts[0][1][key]
    out = np.empty((b, *first.shape[1:]))
    for i, part in parts:
        out[i] = part[key]
    return out


def padded(times: list[np.ndarray]) -> np.ndarray:
    """Ragged time lists as one array, each row padded with its last time (or 0)."""
    m = max((len(t) for t in times), default=0)
    out = np.zeros((len(times), m))
    for i, t in enumerate(times):
        if len(t):
            out[i, : len(t)], out[i, len(t) :] = t, t[-1]
    return out
