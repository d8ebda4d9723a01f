"""Synthetic camera tracks with known truth, made by :func:`spinimpact.flight`.

A table-tennis ball is flown and bounced by ``flight`` (the package's forward model, in its
y-up frame with the ground at y = 0, a step of 1 ms and the path recorded), sampled at about
180 Hz with jittered steps, a few samples dropped (gaps), Gaussian noise added and a few
samples moved 2-5 cm off the path (outliers). The track is given in a camera's z-up frame
whose table sits ``OFFSET`` below the origin, as the measured tracks are: ``(x, y, z)_track =
(x, -z, y + OFFSET)``, so the ball's centre at contact is at ``z = R + OFFSET``.
"""

from __future__ import annotations

import numpy as np

from spinimpact import Walton, flight
from spinimpact.model.presets import Ground
from spinimpact.model.presets import ball as as_ball
from spinimpact.model.track import as_track

BALL = as_ball("table-tennis")
OFFSET = 0.739  #: m: the table below the camera frame's origin
CONTACT_HEIGHT = BALL.radius + OFFSET  #: m, the truth of ``contact_height``


def to_track(v: np.ndarray) -> np.ndarray:
    """Package frame (y up) to the camera's (z up), for positions, velocities and spins."""
    v = np.asarray(v, dtype=float)
    return np.stack([v[..., 0], -v[..., 2], v[..., 1]], axis=-1)


def shot(rng: np.random.Generator, *, mu: float = 0.2, kappa: float = 0.88, beta0=None,
         sigma: float = 0.0015, before: float = 0.25, after: float = 0.2, outliers: int = 2,
         gaps: int = 2, spin=None, name: str = "synthetic", tangential=None):  # fmt: skip
    """One shot: the track, and the truth (state at t = 0 in the track's frame, contact).

    The bounce is rigid, Walton's with ``beta0`` or under the law ``tangential``.

    Returns
    -------
    track : Track
    truth : dict
        ``position``, ``velocity``, ``spin`` (track's frame, at t = 0), ``drag_coefficient``,
        ``contact_time``, ``contact_height``, ``after_velocity``, ``after_spin``.
    """
    vx = rng.uniform(4.0, 5.5)
    vy = -rng.uniform(0.5, 1.2)
    vz = rng.normal(0.0, 0.1)
    g = 9.80665
    # start high enough that the ball comes down to the table after about ``before`` s
    y0 = BALL.radius - vy * before + 0.5 * g * before**2
    w = np.array(spin if spin is not None else [rng.normal(0, 20), rng.normal(0, 30),
                                                rng.uniform(150.0, 300.0)])  # fmt: skip
    law = tangential if tangential is not None else (None if beta0 is None else Walton(beta0))
    f = flight(BALL, Ground("synthetic", mu, kappa), velocity=[vx, vy, vz], spin=w,
               position=[0.0, y0, 0.0], max_bounces=2, t_stop=before + after + 0.3, dt=1e-3,
               path=True, tangential=law)  # fmt: skip
    tc = float(np.asarray(f.bounces.time).reshape(-1)[0])
    pt, pp = np.asarray(f.path_time).reshape(-1), np.asarray(f.path_position).reshape(-1, 3)
    ok = np.isfinite(pt)
    pt, pp = pt[ok], pp[ok]
    n = int((tc + after) * 180) + 1
    t = np.cumsum(np.r_[0.0, rng.uniform(0.0045, 0.0066, n - 1)])
    t = t[t <= tc + after]
    drop = rng.choice(np.arange(3, t.size - 3), size=gaps, replace=False)
    t = np.delete(t, drop)
    pos = np.stack([np.interp(t, pt, pp[:, k]) for k in range(3)], axis=1)
    xyz = to_track(pos) + np.array([0.0, 0.0, OFFSET])
    xyz = xyz + rng.normal(0.0, sigma, xyz.shape)
    bad = rng.choice(np.arange(t.size), size=outliers, replace=False)
    xyz[bad] += rng.choice([-1, 1], (outliers, 3)) * rng.uniform(0.02, 0.05, (outliers, 3))
    truth = {
        "position": to_track([0.0, y0, 0.0]) + np.array([0.0, 0.0, OFFSET]),
        "velocity": to_track([vx, vy, vz]), "spin": to_track(w),
        "drag_coefficient": BALL.drag_coefficient, "contact_time": tc,
        "contact_height": CONTACT_HEIGHT,
        "after_velocity": to_track(np.asarray(f.bounces.after.velocity).reshape(-1, 3)[0]),
        "after_spin": to_track(np.asarray(f.bounces.after.spin).reshape(-1, 3)[0]),
        "outliers": bad,
    }  # fmt: skip
    return as_track(t, xyz, name=name), truth
