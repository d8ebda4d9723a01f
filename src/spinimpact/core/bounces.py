"""A sequence of flights and bounces for many balls at once, then the roll to rest.

:func:`fly` joins :mod:`spinimpact.core.flight` (each arc to the ground, the impact located to
integrator precision, or the exact parabola without air),
:func:`~spinimpact.core.ground.ground_bounce` (the exact 3D impact) and
:func:`~spinimpact.core.ground.roll_to_rest`. A ball stops bouncing when its vertical rebound
speed falls below ``settle_speed`` (it then slides and rolls on the ground), after
``max_bounces`` bounces, or at ``t_stop``.

The loop runs over the arcs (the first flight, the flight after the first bounce, ...); each
arc advances every ball still bouncing, so the work is vectorized over the balls.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from .aero import AeroConstants
from .flight import integrate_to_ground, parabola_to_ground
from .ground import ground_bounce, roll_to_rest

__all__ = ["STOPS", "Flights", "fly", "assemble_path"]

#: Why each ball's run ended (codes of :attr:`Flights.stop`).
STOPS = ("rest", "time", "bounces")


class Flights(NamedTuple):
    """Everything :func:`fly` computes, as arrays over ``n`` balls and ``B = max_bounces``."""

    bounces: Any  #: number of bounces, (n,)
    bounce_time: Any  #: (n, B), s (NaN past the last)
    bounce_position: Any  #: centre at the impact, (n, B, 3), m
    velocity_before: Any  #: (n, B, 3), m/s
    spin_before: Any  #: (n, B, 3), rad/s
    velocity_after: Any  #: (n, B, 3), m/s
    spin_after: Any  #: (n, B, 3), rad/s
    regime: Any  #: (n, B) codes into ``core.REGIMES`` (-1 past the last)
    grips: Any  #: (n, B) bool
    surface: Any  #: (n, B): 0 the ground, 1 the wall (-1 past the last)
    next_apex_height: Any  #: top of the arc after each bounce, (n, B), m (NaN: none)
    apex_height: Any  #: top of the first arc, (n,), m
    apex_time: Any  #: (n,), s
    final_time: Any  #: (n,), s
    final_position: Any  #: (n, 3), m
    final_velocity: Any  #: (n, 3), m/s
    final_spin: Any  #: (n, 3), rad/s
    stop: Any  #: (n,) codes into :data:`STOPS`
    path: list  #: pieces of path, for :func:`assemble_path` (empty unless recorded)


def fly(
    position, velocity, spin, *, mass, radius, inertia, zeta, mu, kappa, rolling,
    aero: AeroConstants, max_bounces, t_stop, settle_speed, dt, record=False, rebound_slip=None,
    frictionless=False, wall=None,
) -> Flights:  # fmt: skip
    """Fly, bounce and roll ``n`` balls (module docstring).

    Parameters
    ----------
    position, velocity, spin : ndarray, shape (n, 3)
        Launch state: centre position (m, ``y >= R``), velocity (m/s), spin (rad/s).
    mass, radius, inertia, zeta : float
        The ball: ``m`` (kg), ``R`` (m), ``J`` (kg m^2), ``1 + R^2/rho^2``.
    mu, kappa, rolling : float
        The ground: Coulomb friction, restitution, rolling resistance.
    aero : AeroConstants
        The air (:func:`spinimpact.core.aero.aero_constants`); all zero: the exact parabola.
    max_bounces : int
        Bounces to follow (>= 1).
    t_stop : float
        Stopping time, s.
    settle_speed : float
        Vertical rebound speed below which the ball stays on the ground, m/s (> 0).
    dt : float
        Integrator step, s.
    record : bool
        Keep the path for pictures.
    rebound_slip : callable, optional
        A tangential compliance law for the bounces
        (:func:`~spinimpact.core.ground.ground_bounce`).
    frictionless : bool
        That law applies no friction (its bounces are labelled ``frictionless``).
    wall : tuple, optional
        ``(n_w, C_w, mu_w, kappa_w)``: a vertical wall met where ``n_w . p = C_w`` (``n_w``
        its unit normal towards the ball), with its own friction and restitution. Balls
        bounce off it in flight (a rolling ball does not meet it).
    """
    p = np.array(position, dtype=float)
    v = np.array(velocity, dtype=float)
    w = np.array(spin, dtype=float)
    n, nb = len(p), max_bounces
    t = np.zeros(n)
    vec = np.full((n, nb, 3), np.nan)
    out = {k: vec.copy() for k in ("pos", "vb", "wb", "va", "wa")}
    b_time, nxt = np.full((n, nb), np.nan), np.full((n, nb), np.nan)
    regime, grips = np.full((n, nb), -1), np.zeros((n, nb), dtype=bool)
    surface = np.full((n, nb), -1)
    count = np.zeros(n, dtype=int)
    stop = np.full(n, 1)
    apex_h, apex_t = np.full(n, np.nan), np.full(n, np.nan)
    path: list = []
    exact = aero.drag == 0 and aero.lift == 0 and aero.spin_decay == 0
    ball = {"mass": mass, "radius": radius, "inertia": inertia, "zeta": zeta}
    ground = {**ball, "mu": mu, "kappa": kappa}
    plane, against = None, {}
    if wall is not None:
        plane = (wall[0], wall[1])
        against = {**ball, "mu": wall[2], "kappa": wall[3], "normal": wall[0]}

    def settle(idx: np.ndarray) -> None:
        """Slide and roll the balls ``idx`` from where they are to rest or ``t_stop``."""
        if not idx.size:
            return
        roll, pieces = roll_to_rest(t[idx], p[idx], v[idx], w[idx], rolling=rolling,
                                    gravity=aero.gravity, t_stop=t_stop,
                                    samples=51 if record else 0, mu=mu, **ball)  # fmt: skip
        t[idx], p[idx], v[idx], w[idx] = roll.time, roll.position, roll.velocity, roll.spin
        stop[idx] = np.where(roll.at_rest, 0, 1)
        path.extend((idx[i], ts, ps) for i, ts, ps in pieces)

    # a ball placed on the ground and moving along it (|v_y| < settle_speed) slides and rolls
    placed = (p[:, 1] <= radius) & (np.abs(v[:, 1]) < settle_speed)
    apex_h[placed], apex_t[placed] = p[placed, 1], 0.0
    settle(np.flatnonzero(placed))
    active, arc = np.flatnonzero(~placed), 0
    while active.size:
        if exact:
            seg = parabola_to_ground(t[active], p[active], v[active], w[active],
                                     gravity=aero.gravity, radius=radius, t_stop=t_stop,
                                     record=record, wall=plane)  # fmt: skip
        else:
            seg = integrate_to_ground(t[active], p[active], v[active], w[active], aero,
                                      radius=radius, t_stop=t_stop, dt=dt,
                                      record=record, wall=plane)  # fmt: skip
        path += [(active[i], ts, ps) for i, ts, ps in seg.path]
        if arc == 0:
            apex_h[active], apex_t[active] = seg.apex_height, seg.apex_time
        else:
            nxt[active, count[active] - 1] = seg.apex_height
        t[active], p[active], v[active], w[active] = seg.time, seg.position, seg.velocity, seg.spin
        hi = active[seg.hit]
        k = count[hi]
        b_time[hi, k], out["pos"][hi, k] = t[hi], p[hi]
        out["vb"][hi, k], out["wb"][hi, k] = v[hi], w[hi]
        on_wall = seg.surface[seg.hit] == 1
        for sel, contact in ((~on_wall, ground), (on_wall, against)):
            if sel.any():
                j, kj = hi[sel], k[sel]
                b = ground_bounce(v[j], w[j], rebound_slip=rebound_slip,
                                  frictionless=frictionless, **contact)  # fmt: skip
                v[j], w[j] = b.velocity, b.spin
                regime[j, kj], grips[j, kj] = b.regime, b.grips
        out["va"][hi, k], out["wa"][hi, k] = v[hi], w[hi]
        surface[hi, k] = np.where(on_wall, 1, 0)
        count[hi] += 1
        full = count[hi] >= nb
        stop[hi[full]] = 2
        down = ~full & ~on_wall & (v[hi, 1] < settle_speed)  # only the ground keeps it down
        settle(hi[down])
        active = hi[~full & ~down]
        arc += 1
    return Flights(count, b_time, out["pos"], out["vb"], out["wb"], out["va"], out["wa"], regime,
                   grips, surface, nxt, apex_h, apex_t, t, p, v, w, stop, path)  # fmt: skip


def assemble_path(path: list, n: int):
    """Each ball's recorded path in time order: ``(times (n, k), positions (n, k, 3))``,
    padded with NaN to the longest."""
    if not path:
        return np.full((n, 0), np.nan), np.full((n, 0, 3), np.nan)
    ids = np.concatenate([np.repeat(i, ts.shape[1]) for i, ts, _ in path])
    times = np.concatenate([ts.ravel() for _, ts, _ in path])
    pts = np.concatenate([ps.reshape(-1, 3) for _, _, ps in path])
    order = np.lexsort((times, ids))
    ids, times, pts = ids[order], times[order], pts[order]
    counts = np.bincount(ids, minlength=n)
    k = int(counts.max())
    slot = np.arange(len(ids)) - np.repeat(np.cumsum(counts) - counts, counts)
    out_t, out_p = np.full((n, k), np.nan), np.full((n, k, 3), np.nan)
    out_t[ids, slot], out_p[ids, slot] = times, pts
    return out_t, out_p
