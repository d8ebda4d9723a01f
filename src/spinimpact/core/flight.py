"""Flight to the ground: many balls at once, each to its own impact, located precisely.

Two routes give the same kind of :class:`Segment` (the state of every ball where its arc
ends: on the ground, or in the air at the stopping time):

* :func:`parabola_to_ground` -- no air: the exact parabola. The time to the ground solves
  ``y + v_y t - g t^2/2 = R`` in closed form (the root without cancellation:
  ``(v_y + q)/g`` when rising, ``2 h/(q - v_y)`` when falling, ``q = sqrt(v_y^2 + 2 g h)``).
* :func:`integrate_to_ground` -- with air (:mod:`spinimpact.core.aero`): classical fourth-order
  Runge-Kutta steps of ``dt`` (each ball from its own time). When a step ends below the
  ground, the crossing is bracketed on the step's cubic Hermite interpolant of the height
  (dense output, exact for the parabola) and then polished on the integrator itself: the
  step size ``s`` with ``y(RK4 step of s) = R`` is found by Newton's method on ``s`` (the
  derivative of the height is ``v_y``), so the impact is where the integrator's own solution
  meets the ground, to rounding. The apex of the arc is the zero of the interpolant's
  derivative inside the step where ``v_y`` changes sign.

An optional vertical wall is a second plane: the step's interpolant of each gap
(``n . p - C``, for the ground ``y - R``) brackets its crossing, the earliest is polished
(``d gap/ds = n . v``), and the segment says which was met.

Loops run over time steps only; every step advances all the balls still in the air.

**How large a step may be** (:func:`air_time_scales`, :data:`STEP_FRACTION`): the air changes
the motion at three rates, each bounded by the largest speed ``v_max`` and spin ``w_max`` a
ball can reach: drag at ``k_d v_max`` (the speed over its drag deceleration), spin decay at
``k_s v_max`` (the spin's e-folding rate) and Magnus lift, which turns the velocity at
``k_l w_max`` radians per second. A step is small when it is a small fraction of the shortest
of their inverses, the time scales of the air; gravity alone sets no limit (the Hermite
interpolant and the Runge-Kutta step are exact on the parabola, and each impact is located
inside its step). The energy bounds ``v_max`` and ``w_max``: lift does no work, and drag, spin
decay, the bounces (``kappa <= 1``, the slip never rising) and the roll only take energy
away, so ``m v^2 + J w^2 <= m v_0^2 + J w_0^2 + 2 m g (y_0 - R)`` at every time.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from .aero import AeroConstants, derivatives

__all__ = ["Segment", "rk4_step", "parabola_to_ground", "integrate_to_ground", "STEP_FRACTION",
           "air_time_scales"]  # fmt: skip

#: The largest step, as a fraction of the shortest time scale of the air
#: (:func:`air_time_scales`). At this fraction the first three bounces of a serve, a lob, a
#: golf drive, a table-tennis smash and a free kick (tests/model/test_flight_step.py) lie within
#: 2e-4 m, 4e-5 s and 4e-5 m/s of those with a step 16 times finer; the errors grow as
#: ``dt^4`` beyond it, and a step of seconds diverges.
STEP_FRACTION = 0.25


class Segment(NamedTuple):
    """Where each ball's arc ends (arrays over the balls)."""

    time: Any  #: s
    position: Any  #: centre, (n, 3), m (``y = R`` exactly on the ground)
    velocity: Any  #: (n, 3), m/s
    spin: Any  #: (n, 3), rad/s
    hit: Any  #: bool: reached the ground or the wall (otherwise the stopping time, in the air)
    surface: Any  #: what it hit: 0 the ground, 1 the wall, -1 nothing
    apex_height: Any  #: height of the centre at the top of the arc, m (NaN: not reached)
    apex_time: Any  #: s
    path: list  #: ``[(index, times (m, k), positions (m, k, 3)), ...]`` when recorded


def air_time_scales(c: AeroConstants, *, energy: float, rotation: float) -> dict[str, float]:
    """The time scales of the air for balls of bounded energy (module docstring), s.

    Parameters
    ----------
    c : AeroConstants
    energy : float
        The largest ``v_0^2 + (J/m) w_0^2 + 2 g (y_0 - R)`` over the balls, m^2/s^2: no ball's
        speed squared exceeds it at any time.
    rotation : float
        ``J/m``, m^2: the spin squared never exceeds ``energy / (J/m)``.

    Returns
    -------
    dict
        ``drag`` ``1/(k_d v_max)``, ``spin decay`` ``1/(k_s v_max)`` and ``Magnus lift``
        ``1/(k_l w_max)``, with ``v_max = sqrt(energy)``, ``w_max = sqrt(energy m/J)``;
        ``inf`` where that effect is absent (all of them without air).

    Examples
    --------
    A tennis ball at 30 m/s without spin, 1 m up: drag takes about 1.7 s to change its speed
    by as much as the speed.

    >>> from spinimpact.core.aero import aero_constants
    >>> c = aero_constants(mass=0.0577, radius=0.0335, inertia=0.0577 * 0.000629,
    ...                    density=1.225, drag_coefficient=0.507, lift_slope=1.0,
    ...                    lift_max=0.5, spin_decay=0.019, gravity=9.80665)
    >>> e = 30.0**2 + 2 * 9.80665 * (1.0 - 0.0335)
    >>> round(air_time_scales(c, energy=e, rotation=0.000629)["drag"], 3)
    1.739
    """
    speed, spin = np.sqrt(energy), np.sqrt(energy / rotation)
    rates = {"drag": c.drag * speed, "spin decay": c.spin_decay * speed,
             "Magnus lift": c.lift * spin}  # fmt: skip
    return {k: (float(1.0 / r) if r > 0 else np.inf) for k, r in rates.items()}


def rk4_step(position, velocity, spin, h, c: AeroConstants):
    """One classical Runge-Kutta step of size ``h`` (an array over the balls), s.

    Returns the new ``(position, velocity, spin)``.
    """
    hh = np.asarray(h, dtype=float)[..., None]
    a1, b1 = derivatives(velocity, spin, c)
    v2, w2 = velocity + 0.5 * hh * a1, spin + 0.5 * hh * b1
    a2, b2 = derivatives(v2, w2, c)
    v3, w3 = velocity + 0.5 * hh * a2, spin + 0.5 * hh * b2
    a3, b3 = derivatives(v3, w3, c)
    v4, w4 = velocity + hh * a3, spin + hh * b3
    a4, b4 = derivatives(v4, w4, c)
    sixth = hh / 6.0
    position = position + sixth * (velocity + 2.0 * v2 + 2.0 * v3 + v4)
    velocity = velocity + sixth * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    spin = spin + sixth * (b1 + 2.0 * b2 + 2.0 * b3 + b4)
    return position, velocity, spin


def _hermite(theta, y0, y1, m0, m1):
    """Cubic Hermite interpolant on ``[0, 1]`` (``m``: the derivatives times the step)."""
    t2, t3 = theta * theta, theta * theta * theta
    return ((2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + theta) * m0
            + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * m1)  # fmt: skip


def _hermite_slope(theta, y0, y1, m0, m1):
    t2 = theta * theta
    return ((6 * t2 - 6 * theta) * y0 + (3 * t2 - 4 * theta + 1) * m0
            + (6 * theta - 6 * t2) * y1 + (3 * t2 - 2 * theta) * m1)  # fmt: skip


def _bisect(fun, n, iterations=60):
    """The root of ``fun`` on ``[0, 1]`` for each of ``n`` problems, ``fun(0) >= 0 > fun(1)``."""
    lo, hi = np.zeros(n), np.ones(n)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        above = fun(mid) >= 0
        lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
    return 0.5 * (lo + hi)


def _gap(p, normal, offset):
    """Signed distance of the centre from where it touches a plane: ``n . p - C``."""
    return np.einsum("ij,ij->i", p, normal) - offset


def _crossing(p, v, p1, v1, h, normal, offset):
    """Fraction of the step where the gap's cubic Hermite interpolant crosses zero."""
    g0, g1 = _gap(p, normal, offset), _gap(p1, normal, offset)
    m0, m1 = h * np.einsum("ij,ij->i", v, normal), h * np.einsum("ij,ij->i", v1, normal)
    return _bisect(lambda th: _hermite(th, g0, g1, m0, m1), len(h))


def _event(p, v, w, h, theta, c, normal, offset, newton=4):
    """Polish the crossings of the planes ``n . p = C`` inside steps of size ``h`` from the
    interpolant's ``theta``: returns the step size to the crossing and the state there (on
    the plane to rounding; ``y = R`` exactly on the ground)."""
    s = theta * h
    for _ in range(newton):  # Newton on the integrator's own solution: d gap/ds = n . v
        ps, vs, _ = rk4_step(p, v, w, s, c)
        rate = np.einsum("ij,ij->i", vs, normal)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(rate < 0, _gap(ps, normal, offset) / rate, 0.0)
        s = np.clip(s - step, 0.0, h)
    ps, vs, ws = rk4_step(p, v, w, s, c)
    ps = ps - _gap(ps, normal, offset)[:, None] * normal
    ground = normal[:, 1] == 1.0
    ps[ground, 1] = offset[ground]
    return s, ps, vs, ws


def _apex(p, v, p1, v1, h):
    """Height and fraction of the step at the top of the arc (``v_y`` from > 0 to <= 0)."""
    y0, y1 = p[:, 1], p1[:, 1]
    m0, m1 = h * v[:, 1], h * v1[:, 1]
    theta = _bisect(lambda th: _hermite_slope(th, y0, y1, m0, m1), len(h))
    return _hermite(theta, y0, y1, m0, m1), theta


def integrate_to_ground(time, position, velocity, spin, c: AeroConstants, *, radius, t_stop,
                        dt, record=False, wall=None) -> Segment:  # fmt: skip
    """Integrate every ball from its own time until its centre comes down to ``y = R`` or
    the time reaches ``t_stop`` (module docstring).

    Parameters
    ----------
    time : ndarray, shape (n,)
        Start times, s.
    position, velocity, spin : ndarray, shape (n, 3)
        Centre position (m, ``y >= R``), velocity (m/s) and spin (rad/s) at the start.
    c : AeroConstants
    radius : float
        ``R``, m: the ground is the plane ``y = 0``, met when the centre is at ``y = R``.
    t_stop : float
        Stopping time, s.
    dt : float
        Step, s.
    record : bool
        Keep every step's position for pictures.
    wall : tuple, optional
        ``(n_w, C_w)``: a second plane, met where ``n_w . p = C_w`` (``n_w`` its unit
        normal towards the ball, ``C_w = n_w . q + R`` for a point ``q`` of the wall).
    """
    t, p, v, w = (np.array(a, dtype=float) for a in (time, position, velocity, spin))
    n = len(t)
    hit = np.zeros(n, dtype=bool)
    surface = np.full(n, -1)
    planes = [(np.array([0.0, 1.0, 0.0]), float(radius))]
    if wall is not None:
        planes.append((np.asarray(wall[0], dtype=float), float(wall[1])))
    falling = v[:, 1] <= 0
    apex_h = np.where(falling, p[:, 1], np.nan)
    apex_t = np.where(falling, t, np.nan)
    path: list = [(np.arange(n), t[:, None].copy(), p[:, None, :].copy())] if record else []
    active = np.flatnonzero(t < t_stop)
    ta, pa, va, wa = t[active], p[active], v[active], w[active]  # the balls in the air
    while active.size:
        h = np.minimum(dt, t_stop - ta)
        p1, v1, w1 = rk4_step(pa, va, wa, h, c)
        gaps = [_gap(p1, np.broadcast_to(nv, p1.shape), off) for nv, off in planes]
        cross = gaps[0] < 0
        for gap in gaps[1:]:
            cross = cross | (gap < 0)
        top = (va[:, 1] > 0) & (v1[:, 1] <= 0)
        if top.any():
            height, theta = _apex(pa[top], va[top], p1[top], v1[top], h[top])
            apex_h[active[top]], apex_t[active[top]] = height, ta[top] + theta * h[top]
        if cross.any():
            idx = np.flatnonzero(cross)
            first = np.full(idx.size, np.inf)
            which = np.zeros(idx.size, dtype=int)
            for k, (nv, off) in enumerate(planes):  # the earliest crossing in the step
                sel = gaps[k][idx] < 0
                if sel.any():
                    j = idx[sel]
                    normal = np.broadcast_to(nv, (j.size, 3))
                    th = _crossing(pa[j], va[j], p1[j], v1[j], h[j], normal, np.full(j.size, off))
                    earlier = th < first[sel]
                    first[sel] = np.where(earlier, th, first[sel])
                    which[sel] = np.where(earlier, k, which[sel])
            normal = np.stack([planes[k][0] for k in which]) if idx.size else np.zeros((0, 3))
            offset = np.array([planes[k][1] for k in which])
            s, pe, ve, we = _event(pa[idx], va[idx], wa[idx], h[idx], first, c, normal, offset)
            p1[idx], v1[idx], w1[idx] = pe, ve, we
            h[idx] = s
            hit[active[idx]] = True
            surface[active[idx]] = which
        t_new = np.where(h == t_stop - ta, t_stop, ta + h)
        if record:
            path.append((active, t_new[:, None], p1[:, None, :]))
        flying = ~cross & (t_new < t_stop)
        if flying.all():
            ta, pa, va, wa = t_new, p1, v1, w1
            continue
        done = ~flying  # write back the balls whose arc ended; keep the others
        t[active[done]], p[active[done]] = t_new[done], p1[done]
        v[active[done]], w[active[done]] = v1[done], w1[done]
        active = active[flying]
        ta, pa, va, wa = t_new[flying], p1[flying], v1[flying], w1[flying]
    return Segment(t, p, v, w, hit, surface, apex_h, apex_t, path)


def parabola_to_ground(time, position, velocity, spin, *, gravity, radius, t_stop,
                       record=False, samples=101, wall=None) -> Segment:  # fmt: skip
    """The exact parabola to the ground (no air): parameters as :func:`integrate_to_ground`,
    with ``gravity`` (``g``, m/s^2); ``samples`` points of each arc are kept with
    ``record``. A ``wall`` must be vertical (``n_w . e_y = 0``): the gap to it is then linear
    in time, ``n_w . p + (n_w . v) t - C_w``."""
    t, p, v, w = (np.array(a, dtype=float) for a in (time, position, velocity, spin))
    height = p[:, 1] - radius
    vy = v[:, 1]
    q = np.sqrt(vy * vy + 2.0 * gravity * height)
    with np.errstate(divide="ignore", invalid="ignore"):
        down = np.where(q - vy > 0, 2.0 * height / np.where(q - vy > 0, q - vy, 1.0), 0.0)
    flight = np.where(vy > 0, (vy + q) / gravity, down)
    surface = np.zeros(len(t), dtype=int)
    if wall is not None:
        nw, cw = np.asarray(wall[0], dtype=float), float(wall[1])
        closing = -(v @ nw)
        with np.errstate(divide="ignore", invalid="ignore"):
            to_wall = np.where(closing > 0, (p @ nw - cw) / np.where(closing > 0, closing, 1.0),
                               np.inf)  # fmt: skip
        first = to_wall < flight
        flight, surface = np.where(first, to_wall, flight), np.where(first, 1, 0)
    hit = t + flight <= t_stop
    surface = np.where(hit, surface, -1)
    span = np.where(hit, flight, np.maximum(t_stop - t, 0.0))
    g = np.array([0.0, -gravity, 0.0])
    end = p + v * span[:, None] + 0.5 * g * (span * span)[:, None]
    end[surface == 0, 1] = radius
    rising = vy > 0
    top_t = np.where(rising, t + vy / gravity, t)
    reached = top_t <= t + span
    apex_h = np.where(reached, np.where(rising, p[:, 1] + vy * vy / (2.0 * gravity), p[:, 1]),
                      np.nan)  # fmt: skip
    apex_t = np.where(reached, top_t, np.nan)
    path: list = []
    if record:
        frac = np.linspace(0.0, 1.0, samples)
        s = span[:, None] * frac
        pts = p[:, None, :] + v[:, None, :] * s[..., None] + 0.5 * g * (s * s)[..., None]
        pts[:, -1] = end
        path.append((np.arange(len(t)), t[:, None] + s, pts))
    return Segment(np.where(hit, t + flight, np.maximum(t, t_stop)), end, v + g * span[:, None],
                   w, hit, surface, apex_h, apex_t, path)  # fmt: skip
