r"""Camera tracks of a ball: the samples, their frame, and the flight evaluated at them.

A camera gives positions at uneven times, with millimetre noise, outliers and gaps; it gives
neither velocity nor spin. A :class:`Track` holds one ball's samples (:func:`as_track` checks
them and names the track and the row of anything wrong); :func:`fly_to` flies balls to the
sample times with the package's flight equations (:mod:`spinimpact.core.aero`, stepped by
:func:`spinimpact.core.flight.rk4_step`); :func:`find_bounce` splits a track at its contact
with a level surface. The fits are in :mod:`spinimpact.model.track_arc` (one flight) and
:mod:`spinimpact.model.track_bounce` (flights joined by the exact bounce law).

Frames. Tracks are read in their own frame: ``up="z"`` (the camera's usual frame, ``x``
along the flight, ``z`` up, ``y`` lateral) or ``up="y"`` (the package's). Inside, positions
are turned into the package's frame by the proper rotation ``(x, y, z) -> (x, z, -y)``, which
turns spin vectors alike; every result is given back in the track's frame.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..core.aero import AeroConstants, aero_constants
from ..core.flight import rk4_step
from .flight import AIR_DENSITY, GRAVITY
from .presets import Ball

__all__ = ["Track", "Air", "Bounce", "plain", "as_track", "find_bounce", "fly_to", "frame_rotation",
           "spin_axes", "MAX_STEP", "MIN_SAMPLES"]  # fmt: skip

#: The largest integration step, s: a tenth of the shortest time scale of the air for a
#: table-tennis ball at 10 m/s and 6000 rpm (about 0.2 s), :func:`fly_to`.
MAX_STEP = 0.02
#: m: a sample lower than the bounce's parabolas by more than this is an outlier, which
#: :func:`find_bounce` passes over to the next candidate.
OUTLIER_BELOW = 0.01
#: Samples a flight needs: more than the 9 numbers of its state.
MIN_SAMPLES = 6

_Z_UP = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, -1.0, 0.0]])


def plain(result: Any, convert: dict[str, Any] | None = None) -> dict[str, Any]:
    """A result's fields as plain numbers, lists and dicts (for JSON): arrays as lists, the
    fields named in ``convert`` through their function, a field ``track`` left out."""
    out: dict[str, Any] = {}
    for k in result.__dataclass_fields__:
        if k == "track":
            continue
        v = getattr(result, k)
        if convert and k in convert:
            v = convert[k](v)
        out[k] = v.tolist() if isinstance(v, np.ndarray) else v
    return out


def frame_rotation(up: str) -> np.ndarray:
    """The rotation from a track's frame to the package's (``package = P @ track``).

    Parameters
    ----------
    up : {"z", "y"}
        The track's vertical axis.
    """
    if up == "z":
        return _Z_UP
    if up == "y":
        return np.eye(3)
    raise ValueError(f"up must be 'z' or 'y' (the track's vertical axis), got {up!r}")


@dataclass(frozen=True, eq=False)
class Track:
    """One measured track: times (s) and positions (m) of the ball's centre.

    Attributes
    ----------
    name : str
        How errors and results name the track.
    time : ndarray, shape (n,)
        s, strictly increasing.
    position : ndarray, shape (n, 3)
        m, in the track's frame.
    rows : ndarray, shape (n,)
        Where each sample came from (the line in its file, or its index).
    up : str
        The track's vertical axis, ``"z"`` or ``"y"``.
    """

    name: str
    time: np.ndarray
    position: np.ndarray
    rows: np.ndarray
    up: str = "z"

    def __len__(self) -> int:
        return len(self.time)

    def select(self, keep: Any) -> Track:
        """The track with only the samples ``keep`` (a boolean mask or indices)."""
        return Track(self.name, self.time[keep], self.position[keep], self.rows[keep], self.up)


def as_track(time: Any, position: Any, *, name: str = "track", rows: Any = None,
             up: str = "z", min_samples: int = MIN_SAMPLES) -> Track:  # fmt: skip
    """Check and package a track.

    Parameters
    ----------
    time : array_like, shape (n,)
        s, strictly increasing (gaps and uneven steps are fine).
    position : array_like, shape (n, 3)
        m, the ball's centre.
    name : str
        The track's name in errors and results.
    rows : array_like, optional
        Row numbers for errors (default: the 0-based indices).
    up : {"z", "y"}
        The vertical axis of the positions.
    min_samples : int
        The fewest samples accepted.

    Raises
    ------
    TypeError
        Times or positions that are not arrays of real numbers.
    ValueError
        Too few samples, a NaN or infinite value, a time that does not increase, or positions
        not of shape ``(n, 3)``; the message names the track and the first bad row.
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a str, got {name!r}")
    frame_rotation(up)
    arrays = []
    for what, value in (("time", time), ("position", position)):
        a = np.asarray(value)
        if a.dtype == object or not (np.issubdtype(a.dtype, np.number) or a.dtype == bool):
            raise TypeError(f"track {name}: {what} must be an array of real numbers, "
                            f"got {type(value).__name__} of {a.dtype}")  # fmt: skip
        if np.iscomplexobj(a):
            raise TypeError(f"track {name}: {what} must be real, got complex values")
        arrays.append(a.astype(float))
    t, p = arrays
    if t.ndim != 1 or p.shape != (t.size, 3):
        raise ValueError(f"track {name}: time must have shape (n,) and position (n, 3), got "
                         f"{t.shape} and {p.shape}")  # fmt: skip
    rows = np.arange(t.size) if rows is None else np.asarray(rows)
    if rows.shape != t.shape:
        raise ValueError(f"track {name}: rows must have one entry per sample")
    if t.size < min_samples:
        raise ValueError(f"track {name}: {t.size} sample(s); a flight needs at least "
                         f"{min_samples}")  # fmt: skip
    bad = ~np.isfinite(t) | ~np.all(np.isfinite(p), axis=1)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"track {name}, row {rows[i]}: time or position is NaN or infinite "
                         f"(t = {t[i]!r}, position = {p[i].tolist()!r})")  # fmt: skip
    step = np.diff(t)
    if np.any(step <= 0):
        i = int(np.flatnonzero(step <= 0)[0]) + 1
        raise ValueError(f"track {name}, row {rows[i]}: time does not increase "
                         f"(t = {t[i]:.7g} s after {t[i - 1]:.7g} s)")  # fmt: skip
    return Track(name, t, p, rows, up)


def aero_of(ball: Ball, *, drag_coefficient: float | None = None, air_density: float = AIR_DENSITY,
            gravity: float = GRAVITY) -> AeroConstants:  # fmt: skip
    """The ball's constants of flight (:func:`spinimpact.core.aero.aero_constants`)."""
    return aero_constants(
        mass=ball.mass, radius=ball.radius, inertia=ball.body.inertia, density=air_density,
        drag_coefficient=ball.drag_coefficient if drag_coefficient is None else drag_coefficient,
        lift_slope=ball.lift_slope, lift_max=ball.lift_max, spin_decay=ball.spin_decay,
        gravity=gravity,
    )  # fmt: skip


def fly_to(t0: Any, position: Any, velocity: Any, spin: Any, targets: Any, aero: AeroConstants,
           max_step: float = MAX_STEP) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """Fly ``b`` balls from their own times ``t0`` to their times ``targets``.

    Each ball is first carried to its first target (backwards if that comes before its
    ``t0``), then all are stepped together by :func:`spinimpact.core.flight.rk4_step`, each in
    equal steps of at most ``max_step`` over its targets, and the positions at the targets are
    read from each step's cubic Hermite interpolant (positions and velocities at its ends; its
    error is of order ``step^4`` times the fourth derivative of the path, below 1e-9 m for a
    table-tennis ball at :data:`MAX_STEP`).

    Parameters
    ----------
    t0 : array_like, shape (b,)
        s.
    position, velocity, spin : array_like, shape (b, 3)
        The package's frame (m, m/s, rad/s).
    targets : array_like, shape (m,) or (b, m)
        s, non-decreasing along the last axis (shared by every ball, or each ball's own).
    aero : AeroConstants
        Its ``drag`` may be an array over the balls.
    max_step : float
        The largest Runge-Kutta step, s.

    Returns
    -------
    position, velocity : ndarray, shape (b, m, 3)
        At each target (the velocity from the interpolant's derivative).
    """
    t = np.asarray(t0, dtype=float)
    p, v, w = (np.array(a, dtype=float) for a in (position, velocity, spin))
    b = len(t)
    targets = np.broadcast_to(np.asarray(targets, dtype=float), (b, np.shape(targets)[-1]))
    span = targets[:, 0] - t
    n = max(1, int(np.ceil(np.max(np.abs(span), initial=0.0) / max_step)))
    for _ in range(n):
        p, v, w = rk4_step(p, v, w, span / n, aero)
    length = targets[:, -1] - targets[:, 0]
    n = max(1, int(np.ceil(np.max(length, initial=0.0) / max_step)))
    h = length / n
    ps, vs = [p], [v]
    for _ in range(n):  # the loop runs over time steps; every ball advances together
        p, v, w = rk4_step(p, v, w, h, aero)
        ps.append(p)
        vs.append(v)
    ps_, vs_ = np.stack(ps, axis=1), np.stack(vs, axis=1)
    hh = np.where(h > 0, h, 1.0)[:, None]
    x = (targets - targets[:, :1]) / hh
    j = np.clip(np.floor(x).astype(int), 0, n - 1)
    th = (x - j)[..., None]
    hh = hh[..., None]
    y0 = np.take_along_axis(ps_, j[..., None], axis=1)
    y1 = np.take_along_axis(ps_, j[..., None] + 1, axis=1)
    m0 = hh * np.take_along_axis(vs_, j[..., None], axis=1)
    m1 = hh * np.take_along_axis(vs_, j[..., None] + 1, axis=1)
    t2, t3 = th * th, th * th * th
    pos = ((2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + th) * m0
           + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1)  # fmt: skip
    vel = ((6 * t2 - 6 * th) * y0 + (3 * t2 - 4 * th + 1) * m0
           + (6 * th - 6 * t2) * y1 + (3 * t2 - 2 * th) * m1) / hh  # fmt: skip
    return pos, vel


def spin_axes(velocity: np.ndarray, up: str) -> np.ndarray:
    """Rows ``topspin``, ``sidespin``, ``gyrospin``: unit axes in the track's frame, from
    the heading of ``velocity`` (its horizontal part) and the vertical."""
    rot = frame_rotation(up)
    v = rot @ np.asarray(velocity, dtype=float)
    heading = np.array([v[0], 0.0, v[2]])
    size = np.linalg.norm(heading)
    heading = heading / size if size > 0 else np.array([1.0, 0.0, 0.0])
    vertical = np.array([0.0, 1.0, 0.0])
    axes = np.stack([np.cross(vertical, heading), vertical, heading])
    return axes @ rot  # each row back in the track's frame (rot is orthogonal)


class Bounce(dict):
    """Where :func:`find_bounce` splits a track: ``index`` (the first sample after the
    contact), ``time`` (s, estimated contact), ``height`` (m, the centre's height then, in the
    track's frame)."""


def _parabola_fit(t: np.ndarray, z: np.ndarray, t0: float, g: float) -> tuple[float, float]:
    """Height and vertical velocity at ``t0`` of ``z = a + b s - g s^2/2`` (least squares,
    refitted once without the samples more than 5 mm off the first fit)."""
    s = t - t0
    a = np.stack([np.ones_like(s), s], axis=1)
    y = z + 0.5 * g * s * s
    coef = np.linalg.lstsq(a, y, rcond=None)[0]
    near = np.abs(y - a @ coef) <= 5e-3
    if near.sum() >= 3:
        coef = np.linalg.lstsq(a[near], y[near], rcond=None)[0]
    return float(coef[0]), float(coef[1])


def _contact(t: np.ndarray, z: np.ndarray, i: int, window: float, gravity: float,
             max_height: float | None, where: str) -> tuple[float, float, Any]:  # fmt: skip
    """The contact's time and height by the parabolas about candidate ``i``
    (:func:`find_bounce`), and the path they give at any time; ``ValueError`` beginning with
    ``where`` if it is not a bounce."""
    if max_height is not None and z[i] > max_height:
        raise ValueError(where + f"height {z[i]:.4g} m, above {max_height:g} m)")
    pre = (t < t[i]) & (t >= t[i] - window)
    after = np.flatnonzero(t > t[i])
    if pre.sum() < 3 or after.size < 3:
        raise ValueError(where + f"with {int(pre.sum())} sample(s) before it and {after.size} "
                         "after it within the window; at least 3 each are needed)")  # fmt: skip
    post = (t > t[i]) & (t <= t[after[0]] + window)
    a1, b1 = _parabola_fit(t[pre], z[pre], t[i], gravity)
    a2, b2 = _parabola_fit(t[post], z[post], t[i], gravity)
    if not (b1 < -0.5 and b2 > 0.3):
        raise ValueError(where + f"vertical velocity {b1:.3g} m/s before and {b2:.3g} m/s after "
                         "it: not a bounce)")  # fmt: skip
    s = (a1 - a2) / (b2 - b1)  # the parabolas share their curvature: one crossing

    def path(u: np.ndarray) -> np.ndarray:
        d = u - t[i]
        return np.where(d < s, a1 + b1 * d, a2 + b2 * d) - 0.5 * gravity * d * d

    return float(t[i] + s), float(a1 + b1 * s - 0.5 * gravity * s * s), path


def find_bounce(track: Track, *, window: float = 0.035, gravity: float = GRAVITY,
                max_height: float | None = None) -> Bounce:  # fmt: skip
    """Find the contact with a level surface in a track, from its positions alone.

    The samples within two of the lowest point of the running median of five heights (so
    that an isolated outlier far from the table is not taken for it) are the candidates,
    lowest first, until one passes:
    parabolas of curvature ``g`` are fitted to the heights within ``window`` before it and
    after it (``i`` itself in neither; each refitted once without the samples more than 5 mm
    off), and must show the ball coming down (``v < -0.5`` m/s) and going up (``v > 0.3``
    m/s). The contact is where the two parabolas meet.

    Parameters
    ----------
    track : Track
    window : float
        s, the span of samples fitted on each side.
    gravity : float
        m/s^2.
    max_height : float, optional
        m: a lowest sample above this height is not at the surface.

    Returns
    -------
    Bounce

    Raises
    ------
    ValueError
        No bounce in the track (it ends before or at the surface, or does not turn upwards),
        naming the track and the lowest candidate's row.
    """
    rot = frame_rotation(track.up)
    z = track.position @ rot[1]
    t = track.time
    padded = np.pad(z, 2, mode="edge")
    smooth = np.median(np.lib.stride_tricks.sliding_window_view(padded, 5), axis=1)
    near = int(np.argmin(smooth))  # then the samples next to it, lowest first
    lo = max(near - 2, 0)
    order = lo + np.argsort(z[lo : near + 3], kind="stable")
    error = None
    for k, i in enumerate(order):
        try:
            tc, height, path = _contact(t, z, int(i), window, gravity, max_height,
                                        f"track {track.name}: no bounce found (lowest sample at "
                                        f"row {track.rows[i]}, ")  # fmt: skip
        except ValueError as exc:
            error = error or exc
            continue
        lower = order[:k]  # rejected, lower candidates: accepted only as outliers below the path
        if np.all(path(t[lower]) - z[lower] > OUTLIER_BELOW):
            break
        raise error
    else:
        raise error
    return Bounce(index=int(np.searchsorted(t, tc, side="right")), time=float(tc),
                  height=float(height))  # fmt: skip


class Air:
    """The ball and the air of a fit: :meth:`aero` gives the constants of flight for a
    drag coefficient, :meth:`per_ball` for one a ball."""

    def __init__(self, ball: Ball, air_density: float = AIR_DENSITY, gravity: float = GRAVITY):
        self.ball, self.air_density, self.gravity = ball, float(air_density), float(gravity)

    def aero(self, drag_coefficient: float) -> AeroConstants:
        return aero_of(self.ball, drag_coefficient=float(drag_coefficient),
                       air_density=self.air_density, gravity=self.gravity)  # fmt: skip

    def with_lift(self, lift_slope: float) -> Air:
        """The same air, with the ball's lift slope ``a`` (its ``C_max`` kept)."""
        if lift_slope == self.ball.lift_slope:
            return self
        return Air(self.ball.replace(lift_slope=float(lift_slope)), self.air_density, self.gravity)

    def per_ball(self, drag_coefficient: np.ndarray) -> AeroConstants:
        """The constants with one drag coefficient a ball: ``k_d = rho A C_D / 2m`` as an
        array (every other constant as it is)."""
        unit = self.aero(1.0)
        return unit._replace(drag=unit.drag * np.asarray(drag_coefficient, dtype=float))
