"""``flight()``: a spinning ball through the air, bouncing exactly, until it rolls to rest.

Inputs as a person gives them -- speed, launch angle, direction, height, spin in rpm about a
named axis -- or as vectors; any of them may be arrays (a Monte Carlo of serves), solved in
chunks of bounded memory. The physics is in :mod:`spinimpact.core.aero` (drag, Magnus lift,
spin decay), :mod:`spinimpact.core.flight` (each arc to the ground, its impact located to
integrator precision; the exact parabola without air), :mod:`spinimpact.core.ground` (the
exact 3D bounce of :func:`~spinimpact.solve_sphere`; the slide and roll to rest) and
:mod:`spinimpact.core.bounces` (the sequence).

Axes: ``x`` along the ground, ``y`` up, ``z = x cross y``. A direction (heading) ``d``
points along ``cos d e_x - sin d e_z``, so headings turn counter-clockwise seen from above,
as in ``spinimpact sphere``. The launch angle is the elevation above the ground (negative:
downwards, as in a serve). Spin axes: ``topspin`` (about ``e_y x h``, ``h`` the heading: a
ball rolling forward), ``backspin``, ``sidespin`` (about ``+y``: seen from above it turns
counter-clockwise and curves to the left of its heading) or a vector.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._long import Estimate
from .._validation import as_real_array, broadcast, callback, check, setting, vector3, whole
from ..core import impulse
from ..core.aero import aero_constants
from ..core.bounces import STOPS, assemble_path, fly
from ..core.compliance import COMPLIANT_REGIMES
from ..core.flight import STEP_FRACTION, air_time_scales, integrate_to_ground
from ._hooks import tangential_law
from .flight_cost import fly_chunks
from .flight_result import Bounces, Flight
from .presets import Ball, Ground, Wall
from .presets import ball as as_ball
from .presets import ground as as_ground
from .result import freeze
from .sphere3d import _state, _vector
from .spin_axis import combine_axes, parse_spin_axis

__all__ = ["flight", "launch", "AIR_DENSITY", "GRAVITY", "RPM"]

#: Density of air at sea level in the ISO standard atmosphere (15 degC), kg/m^3.
AIR_DENSITY = 1.225
#: Standard gravity, m/s^2.
GRAVITY = 9.80665
#: rad/s in one revolution per minute.
RPM = 2.0 * np.pi / 60.0


def launch(speed: Any, angle: Any, direction: Any = 0.0, spin_rpm: Any = 0.0,
           spin_axis: Any = "topspin") -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """Velocity and spin vectors from a speed, angles in degrees and a spin in rpm.

    Parameters
    ----------
    speed : float or array_like
        m/s, ``>= 0``.
    angle : float or array_like
        Elevation above the ground, degrees in ``[-90, 90]``.
    direction : float or array_like
        Heading, degrees (counter-clockwise seen from above; 0 is ``+x``).
    spin_rpm : float or array_like
        Revolutions per minute about ``spin_axis`` (a negative rate turns the other way).
    spin_axis : str or array_like
        ``topspin``, ``backspin``, ``sidespin``, a combination of them
        (``topspin+sidespin``: halfway; ``topspin:0.8+sidespin:0.2``: weighted; see
        :mod:`spinimpact.model.spin_axis`) or a vector (any length > 0).

    Returns
    -------
    velocity, spin : ndarray, shape (..., 3)
        m/s and rad/s.

    Examples
    --------
    >>> v, w = launch(10.0, 0.0, spin_rpm=60.0)   # along +x with 1 rev/s of topspin
    >>> v.round(12).tolist(), (w / (2 * np.pi)).round(12).tolist()[2]
    ([10.0, 0.0, 0.0], -1.0)
    """
    s = as_real_array("speed", speed)
    check("speed", s, lambda a: a >= 0, ">= 0 (m/s)")
    a = as_real_array("angle", angle)
    check("angle", a, lambda x: np.abs(x) <= 90, "in [-90, 90] (degrees above the ground)")
    d = np.radians(as_real_array("direction", direction))
    rpm = as_real_array("spin_rpm", spin_rpm)
    s, a, d, rpm = broadcast(speed=s, angle=a, direction=d, spin_rpm=rpm)
    a = np.radians(a)
    heading = np.stack([np.cos(d), np.zeros_like(d), -np.sin(d)], axis=-1)
    up = np.array([0.0, 1.0, 0.0])
    velocity = s[..., None] * (np.cos(a)[..., None] * heading + np.sin(a)[..., None] * up)
    if isinstance(spin_axis, str):
        parts = parse_spin_axis(spin_axis)
        top = np.cross(up, heading)
        named = {"topspin": top, "backspin": top * -1.0,
                 "sidespin": np.broadcast_to(up, heading.shape)}  # fmt: skip
        axis = combine_axes(parts, named)
    else:
        axis = vector3("spin_axis", spin_axis)
        try:
            np.broadcast_shapes(axis.shape[:-1], s.shape)
        except ValueError:
            raise ValueError(f"spin_axis of shape {axis.shape} (vectors along the last axis) "
                             f"does not broadcast with the shape {s.shape} of speed, angle, "
                             "direction and spin_rpm") from None  # fmt: skip
        length = np.sqrt(np.sum(axis * axis, axis=-1))
        check("the length of spin_axis", length, lambda x: x > 1e-12, "> 0 (a direction)")
        axis = axis / length[..., None]
    spin = (rpm * RPM)[..., None] * axis
    shape = np.broadcast_shapes(velocity.shape, spin.shape)
    return np.broadcast_to(velocity, shape).copy(), np.broadcast_to(spin, shape).copy()


def flight(ball: Ball | str, ground: Ground | str, *, speed: Any = None, angle: Any = None,
           direction: Any = 0.0, height: Any = 1.0, spin_rpm: Any = 0.0,
           spin_axis: Any = "topspin", velocity: Any = None, spin: Any = None,
           position: Any = None, air_density: float = AIR_DENSITY, gravity: float = GRAVITY,
           max_bounces: int = 30, t_stop: float = 60.0, settle_speed: float = 0.05,
           dt: float = 5e-3, chunk: int = 4096, path: bool | None = None,
           progress: Callable[[int, int], None] | None = None,
           tangential: Any = None, wall: Wall | None = None, force: bool = False,
           announce: Callable[[Estimate], None] | None = None) -> Flight:  # fmt: skip
    """Fly a spinning ball, bounce it exactly on the ground, and roll it to rest.

    Parameters
    ----------
    ball : Ball or str
        A :class:`~spinimpact.model.presets.Ball` or a preset name (``tennis``,
        ``table-tennis``, ``golf``, ``soccer``).
    ground : Ground or str
        A :class:`~spinimpact.model.presets.Ground` or a preset name (``hard``, ``clay``,
        ``grass``, ``table``, ``green``, ``pitch``).
    speed, angle, direction, spin_rpm, spin_axis
        As :func:`launch` (m/s, degrees, rpm); or give ``velocity`` (m/s) and ``spin``
        (rad/s) as vectors instead.
    height : float or array_like
        Launch height of the centre, m (``>= R``: the ball starts on or above the ground);
        or give ``position`` (a vector; ``x, z`` default 0).
    air_density : float
        kg/m^3 (default sea level); ``0`` flies the exact parabola.
    gravity : float
        m/s^2.
    max_bounces : int
        Bounces to follow; the run stops at the last (``stop == "bounces"``).
    t_stop : float
        Stopping time, s.
    settle_speed : float
        Vertical rebound speed (m/s) below which the ball stays down and slides, then rolls
        (its rolling resistance is the ground's ``rolling``).
    dt : float
        Step of the fourth-order Runge-Kutta integrator, s (impacts are located within a
        step to the integrator's precision); at most
        :data:`~spinimpact.core.flight.STEP_FRACTION` of the shortest time scale of the air
        (:func:`~spinimpact.core.flight.air_time_scales`), unused without air.
    chunk : int
        Balls solved together: memory is bounded by the chunk.
    path : bool, optional
        Keep each ball's path (for pictures); by default for up to 16 balls.
    progress : callable, optional
        Called as ``progress(done, total)`` after each chunk.
    tangential : Walton or Stronge, optional
        A tangential compliance law for every bounce, as in :func:`~spinimpact.solve_sphere`
        (then ``regime`` takes the compliant regimes' names and ``grips`` says the contact
        stuck during the impact).
    wall : Wall, optional
        A vertical wall across the ball's way (:class:`~spinimpact.model.presets.Wall`), with
        its own ``mu`` and ``kappa``: the ball bounces off it in flight (``bounces.surface``
        is ``"wall"``); a rolling ball does not meet it.
    force : bool
        Fly even a flight estimated to take more than an hour (a step much finer than
        needed); otherwise it is refused before it runs.
    announce : callable, optional
        ``announce(estimate)``, an :class:`~spinimpact._long.Estimate`: called before the
        run when it may take more than a minute (its first steps bound it), with the time
        measured on trials of its first chunk (:mod:`spinimpact.model.flight_cost`).

    Returns
    -------
    Flight

    Raises
    ------
    TypeError, ValueError
        Bad input, named: a negative speed, a spin axis of length zero, a ball that starts
        below the ground, a step or stopping time that is not positive, a step too large
        for the flight (the message names the limit), inputs whose shapes do not broadcast
        (the message names them and their shapes), ...; a flight estimated to take more
        than an hour, unless ``force`` (:class:`~spinimpact._long.TooLong`, naming the
        estimate).

    Examples
    --------
    A first serve on a hard court: 50 m/s, 6 degrees down from 2.8 m, 2000 rpm of topspin.

    >>> f = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0)
    >>> x, z = float(f.bounces.position.x[0]), float(f.bounces.position.z[0])
    >>> round(x, 2), z, bool(f.bounces.grips[0])
    (15.49, 0.0, True)
    """
    ball_, ground_ = as_ball(ball), as_ground(ground)
    callback("progress", progress, "progress(done, total)")
    callback("announce", announce, "announce(estimate)")
    law = None if tangential is None else tangential_law(tangential)
    radius = ball_.radius
    if velocity is None:
        missing = [k for k, x in (("speed", speed), ("angle", angle)) if x is None]
        if missing:
            raise ValueError(f"{' and '.join(missing)} missing: give speed (m/s) and angle "
                             "(degrees above the ground), or velocity as a vector")  # fmt: skip
        v, w0 = launch(speed, angle, direction, spin_rpm, spin_axis)
        if spin is not None:
            raise ValueError("give spin as a vector with velocity, or spin_rpm and spin_axis")
    else:
        if speed is not None or angle is not None:
            raise ValueError("give either velocity or speed and angle, not both")
        v = vector3("velocity", velocity)
        w0 = np.zeros(3) if spin is None else vector3("spin", spin)
    if position is None:
        h = as_real_array("height", height)
        p = np.stack([np.zeros_like(h), h, np.zeros_like(h)], axis=-1)
    else:
        p = vector3("position", position)
    rule = f">= the ball's radius {radius:g} m (the ball must start on or above the ground)"
    check("the launch height of the centre", p[..., 1], lambda y: y >= radius, rule)
    plane = None
    if wall is not None:
        if not isinstance(wall, Wall):
            raise TypeError(f"wall must be a spinimpact Wall, got {wall!r}")
        plane = (wall.normal, radius - wall.distance, wall.mu, wall.kappa)
        gap = p @ wall.normal - plane[1]
        check("the launch point's distance from the wall less the ball's radius", gap,
              lambda x: x >= 0, ">= 0 (the ball must start in front of the wall)")  # fmt: skip
    named = {"speed, angle, direction and spin_rpm": v} if velocity is None else {
        "velocity": v, "spin": w0}  # fmt: skip
    named["height" if position is None else "position"] = p
    shape = broadcast(**{k: x[..., 0] for k, x in named.items()})[0].shape
    v, w0, p = (np.broadcast_to(x, (*shape, 3)).reshape(-1, 3) for x in (v, w0, p))
    density = _number("air_density", air_density, "kg/m^3", closed=True)
    g = _number("gravity", gravity, "m/s^2")
    t_stop = _number("t_stop", t_stop, "s")
    settle = _number("settle_speed", settle_speed, "m/s")
    dt = _number("dt", dt, "s")
    nb = whole("max_bounces", max_bounces, 1)
    chunk = whole("chunk", chunk, 1)
    n = len(v)
    record = n <= 16 if path is None else bool(path)
    body = ball_.body
    aero = aero_constants(
        mass=ball_.mass, radius=radius, inertia=body.inertia, density=density,
        drag_coefficient=ball_.drag_coefficient, lift_slope=ball_.lift_slope,
        lift_max=ball_.lift_max, spin_decay=ball_.spin_decay, gravity=g,
    )  # fmt: skip
    limit = _check_step(dt, aero, p, v, w0, ball_)
    slip_law = None if law is None else law.rebound_slip

    def fly_chunk(sl: slice, step: float) -> tuple:
        run = fly(p[sl], v[sl], w0[sl], mass=ball_.mass, radius=radius, inertia=body.inertia,
                  zeta=body.zeta, mu=ground_.mu, kappa=ground_.kappa, rolling=ground_.rolling,
                  aero=aero, max_bounces=nb, t_stop=t_stop, settle_speed=settle, dt=step,
                  record=record, rebound_slip=slip_law, wall=plane,
                  frictionless=law is not None and law.frictionless)  # fmt: skip
        used = max(1, int(run.bounces.max(initial=0)))
        trimmed = run._replace(**{k: getattr(run, k)[:, :used] for k in _PER_BOUNCE})
        return trimmed, assemble_path(run.path, sl.stop - sl.start) if record else None

    def probe(sl: slice, step: float, k: int) -> None:
        integrate_to_ground(np.zeros(sl.stop - sl.start), p[sl], v[sl], w0[sl], aero,
                            radius=radius, t_stop=k * step, dt=step, wall=plane)  # fmt: skip

    exact = aero.drag == 0 and aero.lift == 0 and aero.spin_decay == 0
    what = f"this flight ({n:,} ball{'s' * (n != 1)}, dt = {dt:g} s)"
    parts = fly_chunks(fly_chunk, probe, n, chunk, dt, np.inf if exact else limit,
                       t_stop / dt + nb, what=what, force=force, announce=announce,
                       progress=progress)  # fmt: skip
    return _package(ball_, ground_, law, wall, p, v, w0, parts, shape, record)


def _number(name: str, value: Any, unit: str, closed: bool = False) -> float:
    """A finite real setting ``> 0`` (``>= 0`` when ``closed``), the sign said in the error."""
    finite = setting(name, value)
    return setting(name, finite, low=0.0, closed=closed, rule=f"{'>=' if closed else '>'} 0 "
                   f"({unit})")  # fmt: skip


def _check_step(dt: float, aero: Any, p: np.ndarray, v: np.ndarray, w: np.ndarray,
                ball_: Ball) -> float:  # fmt: skip
    """Refuse a step larger than :data:`~spinimpact.core.flight.STEP_FRACTION` of the
    shortest time scale of the air (:func:`~spinimpact.core.flight.air_time_scales`);
    return that largest step, s."""
    rotation = ball_.body.inertia / ball_.mass
    height = np.maximum(p[:, 1] - ball_.radius, 0.0)
    energy = np.sum(v * v, -1) + rotation * np.sum(w * w, -1) + 2.0 * aero.gravity * height
    scales = air_time_scales(aero, energy=float(energy.max(initial=0.0)), rotation=rotation)
    which = min(scales, key=scales.__getitem__)
    limit = STEP_FRACTION * scales[which]
    if dt > limit:
        raise ValueError(
            f"dt must be <= {limit:.3g} s for this flight, got {dt!r}: a step may be at most "
            f"{STEP_FRACTION:g} of the shortest time scale of the air, here that of "
            f"{which}, {scales[which]:.3g} s at the largest speed and spin the ball can reach"
        )
    return limit


_PER_BOUNCE = ("bounce_time", "bounce_position", "velocity_before", "spin_before",
               "velocity_after", "spin_after", "regime", "grips", "surface",
               "next_apex_height")  # fmt: skip


def _pad(arrays: list[np.ndarray], fill: Any) -> np.ndarray:
    """Join chunks along the first axis, padding the second to the longest."""
    k = max(a.shape[1] for a in arrays)
    out = []
    for a in arrays:
        pad = [(0, 0), (0, k - a.shape[1])] + [(0, 0)] * (a.ndim - 2)
        out.append(np.pad(a, pad, constant_values=fill))
    return np.concatenate(out)


def _angle(vel: np.ndarray, normal: np.ndarray, sign: float) -> np.ndarray:
    """Angle of the velocity towards (``sign = -1``) or away from (``+1``) the surface of
    unit ``normal``, rad (for the ground: below or above it)."""
    vn = np.sum(vel * normal, axis=-1)
    along = vel - vn[..., None] * normal
    return np.arctan2(sign * vn, np.sqrt(np.sum(along * along, axis=-1)))


def _package(ball_, ground_, law, wall, p, v, w0, parts, shape, record) -> Flight:
    runs = [r for r, _ in parts]

    def cat(name: str) -> np.ndarray:
        return np.concatenate([getattr(r, name) for r in runs])

    def per_bounce(name: str, fill: Any) -> np.ndarray:
        a = _pad([getattr(r, name) for r in runs], fill)
        return a.reshape((*shape, *a.shape[1:]))

    def one(a: np.ndarray) -> np.ndarray:
        return a.reshape((*shape, *a.shape[1:]))

    vb, va = per_bounce("velocity_before", np.nan), per_bounce("velocity_after", np.nan)
    code = per_bounce("regime", -1)
    names = np.asarray((*(impulse.REGIMES if law is None else COMPLIANT_REGIMES), ""))
    where = per_bounce("surface", -1)
    normal = np.where((where == 1)[..., None], np.zeros(3) if wall is None else wall.normal,
                      np.array([0.0, 1.0, 0.0]))  # fmt: skip
    bounces = Bounces(
        time=freeze(per_bounce("bounce_time", np.nan)),
        position=_vector(per_bounce("bounce_position", np.nan)),
        before=_state(vb, per_bounce("spin_before", np.nan)),
        after=_state(va, per_bounce("spin_after", np.nan)),
        speed_before=freeze(np.sqrt(np.sum(vb * vb, -1))),
        speed_after=freeze(np.sqrt(np.sum(va * va, -1))),
        angle_before=freeze(_angle(vb, normal, -1.0)), angle_after=freeze(_angle(va, normal, 1.0)),
        regime=freeze(names[code]), grips=freeze(per_bounce("grips", False)),
        surface=freeze(np.asarray(["ground", "wall", ""])[where]),
        next_apex_height=freeze(per_bounce("next_apex_height", np.nan)),
    )  # fmt: skip
    if record:
        path_t = _pad([pt for _, (pt, _) in parts], np.nan)
        path_p = _pad([pp for _, (_, pp) in parts], np.nan)
    else:
        path_t, path_p = np.zeros((len(p), 0)), np.zeros((len(p), 0, 3))
    first = per_bounce("bounce_time", np.nan)[..., 0]
    return Flight(
        ball=ball_, ground=ground_, tangential=law, wall=wall, launch_position=_vector(one(p)),
        launch=_state(one(v), one(w0)),
        bounce_count=freeze(one(cat("bounces"))), bounces=bounces,
        apex_height=freeze(one(cat("apex_height"))), apex_time=freeze(one(cat("apex_time"))),
        flight_time=freeze(first), final_time=freeze(one(cat("final_time"))),
        final_position=_vector(one(cat("final_position"))),
        final_velocity=_vector(one(cat("final_velocity"))),
        final_spin=_vector(one(cat("final_spin"))),
        stop=freeze(np.asarray(STOPS)[one(cat("stop"))]),
        path_time=freeze(one(path_t)), path_position=freeze(one(path_p)),
    )  # fmt: skip
