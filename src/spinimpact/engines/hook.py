r"""Exact impacts inside an engine's own time loop: the event hook's shared part.

A time-stepping engine resolves an impact at its steps, with its own contact model.
An *impact hook* takes one free body's impacts on one plane away from the engine: the
engine integrates the body's flight as usual, and the hook

1. predicts the body's flight over the coming step (a free body under gravity: the
   exact parabola of its centre of mass, its spin constant over the step) and finds the
   instant within the step at which a point of the body first reaches the plane;
2. takes the engine's step with the engine's own contact between this body and this
   plane switched off (for as long as the hook is open);
3. where the body touched, advances it exactly to that instant, applies the exact
   velocity change there (:func:`spinimpact.solve_sphere` for a sphere centred on its
   centre of mass, :func:`spinimpact.solve_rigid` for any other shape touching at one
   point), flies it exactly to the step's end, and writes that position, orientation,
   velocity and spin into the engine.

The engines (semi-implicit Euler in MuJoCo's default and in Bullet) give the exact
velocity of a body under constant gravity at every step, but a position that lags the
exact flight by ``g h t / 2`` after ``t`` seconds of flight with steps of ``h``. The
hook therefore keeps the exact position of the centre of mass beside the engine's,
from the engine's velocities, and finds each contact on the exact flight; the engine's
own position keeps its integration error between impacts (reported by
:attr:`HookStep.drift <spinimpact.engines.HookStep.drift>`), and is set to the exact one
at every impact. If anything else moves the body between two steps (the user sets its
position), the hook takes the engine's position as the exact one from there.

Where the hook is not valid it refuses, with a ``ValueError`` that leaves the engine's
state as it was before the step:

* a body already inside the plane, or resting on it: an impact whose contact point
  approaches at ``rest_speed`` or slower (by default the speed gravity gives in one
  step), or a body that would need more than
  :data:`~spinimpact.engines.hook.MAX_IMPACTS` impacts in one step;
* several points touching at once (an edge or a face landing flat): the law is for one
  contact point;
* any force but gravity on the body during a step (a contact with another body, an
  applied force, damping, an actuator): the flight the hook predicts would be wrong.

A hook drives the engine's step itself, so a model or world takes one hook: its body's
impacts on its plane.

For a body whose inertia is not isotropic (all principal moments equal), the spin of
free flight changes within a step (Euler's equations) while the hook holds it constant
over the step in which the body touches; the impact itself is exact for the state the
hook reaches at the contact.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from .._validation import scalar, setting
from ..model._hooks import tangential_law
from ..model.body import Body
from ..model.rigid import LAWS, RigidBody, solve_rigid
from ..model.sphere3d import Surface, solve_sphere

__all__ = ["MAX_IMPACTS", "HookImpact", "HookStep"]

#: The most impacts the hook resolves within one time step; more means the body is
#: coming to rest on the plane, which the hook refuses.
MAX_IMPACTS = 16

#: The worlds (a MuJoCo model, a PyBullet client) that have an open hook: a hook takes the
#: engine's step, so a second one on the same world would step it twice.
_OPEN: set = set()


def _give_back(world: Any, release: Callable[[], None]) -> None:
    """Give a world's contact back (a hook closed, or dropped without being closed)."""
    _OPEN.discard(world)
    release()


#: Samples of the coming step at which a rotating body's points are tested for contact
#: before the first crossing is refined.
_SAMPLES = 8
#: Heights within this fraction of the body's size count as touching.
_TOUCH = 1e-9
_INSIDE = ("the body is inside the plane at the start of the step (resting or penetrating): "
           "the hook handles impacts from free flight only")  # fmt: skip


@dataclass(frozen=True, eq=False)
class HookImpact:
    """One impact the hook applied: the state at the contact instant, before and after.

    Vectors are in the engine's world frame, SI units.
    """

    time: float  #: the contact instant, on the engine's clock, s
    point: np.ndarray  #: the contact point on the plane, m
    position: np.ndarray  #: the centre of mass at the contact instant, m
    orientation: np.ndarray  #: the body's orientation then, a unit quaternion (w, x, y, z)
    velocity_before: np.ndarray  #: centre-of-mass velocity, m/s
    spin_before: np.ndarray  #: angular velocity, rad/s
    velocity_after: np.ndarray  #: m/s
    spin_after: np.ndarray  #: rad/s
    exact: Any  #: the law's full result: a SphereImpact or a RigidImpact


@dataclass(frozen=True, eq=False)
class HookStep:
    """What one :meth:`~spinimpact.engines.hook.Hook.step` of a hook did."""

    impacts: tuple[HookImpact, ...]  #: the impacts applied within the step, in order
    time: float  #: the engine's clock after the step, s
    #: The engine's position of the centre of mass minus the exact flight's after the
    #: step, m: the engine's integration error since the last impact (zero after one).
    drift: np.ndarray

    @property
    def impacted(self) -> bool:
        """Whether the hook applied an impact in this step."""
        return bool(self.impacts)


# -- rotations (quaternions w, x, y, z) ---------------------------------------------------
def quat_matrix(q: np.ndarray) -> np.ndarray:
    """The rotation matrix of a unit quaternion ``(w, x, y, z)``."""
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])  # fmt: skip


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``a x b`` of two 3-vectors (``np.cross`` costs ten times more on one pair)."""
    return np.array(
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    )


def _turn(w: np.ndarray, u: float, q: np.ndarray) -> np.ndarray:
    """``q`` turned for ``u`` seconds at the constant world angular velocity ``w``."""
    rate = math.sqrt(float(w @ w))
    if rate == 0.0 or u == 0.0:
        return q
    half = 0.5 * rate * u
    a = np.array([math.cos(half), *(math.sin(half) / rate * w)])
    out = np.array([
        a[0] * q[0] - a[1] * q[1] - a[2] * q[2] - a[3] * q[3],
        a[0] * q[1] + a[1] * q[0] + a[2] * q[3] - a[3] * q[2],
        a[0] * q[2] - a[1] * q[3] + a[2] * q[0] + a[3] * q[1],
        a[0] * q[3] + a[1] * q[2] - a[2] * q[1] + a[3] * q[0],
    ])  # fmt: skip
    return out / math.sqrt(float(out @ out))


# -- the body, the plane and the law ------------------------------------------------------
@dataclass(frozen=True, eq=False)
class Geometry:
    """What a hook knows of its body and plane, from the engine (SI units, world frame).

    ``points`` (k, 3) are the centres of the body's round parts and its corners, in the
    body's frame from its centre of mass; ``radii`` (k,) their radii (0 for a corner).
    ``moments`` and ``axes`` give the inertia about the centre of mass in the body's
    frame (principal moments; their axes as the columns of a rotation matrix).
    """

    mass: float
    moments: np.ndarray
    axes: np.ndarray
    points: np.ndarray
    radii: np.ndarray
    origin: np.ndarray  #: a point of the plane
    normal: np.ndarray  #: the plane's unit normal, towards the body

    @cached_property
    def size(self) -> float:
        """The farthest reach of the body from its centre of mass, m."""
        return float(np.max(np.linalg.norm(self.points, axis=1) + self.radii))

    @cached_property
    def ball(self) -> Body | None:
        """The :class:`~spinimpact.Body` of a sphere centred on its centre of mass with
        isotropic inertia (the closed-form route), else ``None``."""
        m = self.moments
        one = len(self.radii) == 1 and float(np.max(np.abs(self.points))) <= 1e-12 * self.size
        if not one or np.ptp(m) > 1e-12 * np.max(m):
            return None
        gyration = math.sqrt(float(np.mean(m)) / self.mass)
        if gyration > math.sqrt(2.0 / 3.0) * float(self.radii[0]):
            return None  # not a sphere's inertia: the general route takes it
        return Body(mass=self.mass, radius=float(self.radii[0]), gyration=gyration)


@dataclass(frozen=True, eq=False)
class Law:
    """The impact law a hook applies: Coulomb's ``mu``, the restitution ``kappa`` and,
    for a sphere, an optional tangential law; ``rest_speed`` (m/s, or ``None`` for the
    speed gravity gives in one step) is the slowest approach the hook takes as an impact."""

    mu: float
    kappa: float
    tangential: Any
    law: str
    rest_speed: float | None

    @classmethod
    def checked(cls, mu: Any, kappa: Any, tangential: Any, law: Any, rest_speed: Any) -> Law:
        """The law, its inputs validated (``TypeError`` or ``ValueError`` naming them)."""
        if not isinstance(law, str):
            raise TypeError(f"law must be one of {', '.join(LAWS)}; got {law!r}")
        if law not in LAWS:
            raise ValueError(f"law must be one of {', '.join(LAWS)}; got {law!r}")
        if rest_speed is not None:
            rest_speed = setting("rest_speed", rest_speed, low=0.0, closed=True,
                                 rule="None or a finite speed >= 0 (m/s)")  # fmt: skip
        if tangential is not None:
            tangential = tangential_law(tangential)
        mu = scalar("mu", mu, why="a hook applies one law")
        kappa = scalar("kappa", kappa, why="a hook applies one law")
        return cls(mu, kappa, tangential, law, rest_speed)


# -- the flight and the contact -----------------------------------------------------------
def _heights(geo: Geometry, x: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """Each point's gap to the plane, m (negative inside)."""
    return (x - geo.origin) @ geo.normal + (geo.points @ rot.T) @ geo.normal - geo.radii


def _first_root(a: float, b: float, c: float, span: float, touch: float) -> float | None:
    """The first time in ``[0, span]`` at which ``c + b u + a u^2`` falls through zero."""
    if c <= touch and (b < 0.0 or (b == 0.0 and a < 0.0)):
        return 0.0  # touching and approaching (or about to be pulled in)
    if a == 0.0:
        roots = [-c / b] if b != 0.0 else []
    else:
        disc = b * b - 4.0 * a * c
        if disc < 0.0:
            return None
        q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
        roots = [q / a] + ([c / q] if q != 0.0 else [])
    falling = [u for u in roots if 0.0 < u <= span and 2.0 * a * u + b < 0.0]
    return min(falling) if falling else None


def _gap(geo, i, u, x, v, g, a, w):
    """Point ``i``'s gap and its rate at ``u`` s into the flight; ``a`` is the point's
    world offset from the centre of mass at ``u = 0``."""
    rate = math.sqrt(float(w @ w))
    if rate > 0.0:
        k = w / rate
        th = rate * u
        arm = a * math.cos(th) + _cross(k, a) * math.sin(th) + k * (k @ a) * (1 - math.cos(th))
    else:
        arm = a
    n = geo.normal
    gap = (x + v * u + 0.5 * g * u * u - geo.origin) @ n + arm @ n - geo.radii[i]
    return float(gap), float((v + g * u + _cross(w, arm)) @ n)


def _refine(geo, i, lo, hi, x, v, g, a, w) -> float:
    """The root of point ``i``'s gap in ``[lo, hi]`` (gap >= 0 at ``lo``, < 0 at ``hi``):
    Newton's steps, bisection where one would leave the bracket, to rounding."""
    eps = np.finfo(float).eps
    u = 0.5 * (lo + hi)
    for _ in range(200):
        f, df = _gap(geo, i, u, x, v, g, a, w)
        if f == 0.0:
            return u
        if f < 0.0:
            hi = u
        else:
            lo = u
        new = u - f / df if df != 0.0 else lo
        if not lo < new < hi:
            new = 0.5 * (lo + hi)
        if abs(new - u) <= 2.0 * eps * abs(u) or hi - lo <= 4.0 * eps * hi:
            return new
        u = new
    return u


def first_touch(geo, span, x, v, g, q, w) -> tuple[float, int] | None:
    """The first time in ``[0, span]`` (s) at which a point of the body reaches the plane
    on the flight from centre ``x``, velocity ``v``, orientation ``q`` and spin ``w``
    under gravity ``g``, and which point; ``None`` if none does.

    Raises
    ------
    ValueError
        If a point touching at the start sinks into the plane without an approach (a
        resting contact).
    """
    n, touch = geo.normal, _TOUCH * geo.size
    h0 = float((x - geo.origin) @ n)
    b, acc = float(v @ n), 0.5 * float(g @ n)
    if geo.ball is not None:  # a sphere about its centre of mass: a parabola
        u = _first_root(acc, b, h0 - float(geo.radii[0]), span, touch)
        return None if u is None else (u, 0)
    if h0 - geo.size + min(0.0, b * span) + min(0.0, acc * span * span) > touch:
        return None  # the bounding sphere stays clear of the plane
    rot = quat_matrix(q)
    arms = geo.points @ rot.T
    gaps = _heights(geo, x, rot)
    rates = (v + np.cross(w, arms)) @ n
    now = np.flatnonzero((gaps <= touch) & (rates < 0.0))
    if now.size:
        return 0.0, int(now[np.argmin(gaps[now])])
    times = np.linspace(0.0, span, _SAMPLES + 1)
    prev = gaps
    for k in range(1, _SAMPLES + 1):
        u = times[k]
        rotu = quat_matrix(_turn(w, u, q))
        cur = _heights(geo, x + v * u + 0.5 * g * u * u, rotu)
        down = np.flatnonzero(cur < 0.0)
        if down.size:
            best = None
            for i in down:
                if prev[i] < 0.0 or (k == 1 and prev[i] <= touch):
                    raise ValueError(
                        "the body sinks into the plane at a contact that is not an impact "
                        "(a resting or sliding contact): the hook handles impacts from free "
                        "flight only; close it and let the engine take the contact"
                    )
                root = _refine(geo, i, times[k - 1], u, x, v, g, arms[i], w)
                if best is None or root < best[0]:
                    best = (root, int(i))
            return best
        prev = cur
    return None


def plan(geo: Geometry, law: Law, ball: Body | None, surface: Surface, span: float,
         start: float, x, v, g, turning) -> tuple[list[HookImpact], tuple | None]:  # fmt: skip
    """The impacts within a step of ``span`` seconds from the centre ``x`` and velocity
    ``v`` at time ``start`` (``turning()`` gives the orientation and spin, read only where
    needed), and the state at the step's end (``None`` if there is no impact).

    Raises
    ------
    ValueError
        Where the hook is not valid (see the module's notes); nothing has been changed.
    """
    touch = _TOUCH * geo.size
    if ball is not None:  # a ball's gap needs neither its orientation nor its spin
        n = geo.normal
        gap = float((x - geo.origin) @ n) - ball.radius
        if gap < -touch:
            raise ValueError(_INSIDE)
        if _first_root(0.5 * float(g @ n), float(v @ n), gap, span, touch) is None:
            return [], None
        q, w = turning()
    else:
        q, w = turning()
        if float(np.min(_heights(geo, x, quat_matrix(q)))) < -touch:
            raise ValueError(_INSIDE)
    rest = law.rest_speed if law.rest_speed is not None else abs(float(g @ geo.normal)) * span
    impacts: list[HookImpact] = []
    done = 0.0
    while True:
        hit = first_touch(geo, span - done, x, v, g, q, w)
        if hit is None:
            break
        u, i = hit
        x, v, q, done = x + v * u + 0.5 * g * u * u, v + g * u, _turn(w, u, q), done + u
        rot = quat_matrix(q)
        gaps = _heights(geo, x, rot)
        gaps[i] = np.inf
        if np.any(gaps <= touch):
            raise ValueError(
                f"{int(np.sum(gaps <= touch)) + 1} points of the body touch the plane at "
                f"once (an edge or a face landing): the hook's law is for one contact point"
            )
        arm = rot @ geo.points[i] - geo.radii[i] * geo.normal
        approach = 0.0 - float((v + _cross(w, arm)) @ geo.normal)  # 0.0 - x: no -0.0
        if approach <= rest:
            raise ValueError(
                f"the contact point approaches the plane at {approach:.3g} m/s, not faster "
                f"than rest_speed = {rest:.3g} m/s: a resting contact, which the hook does "
                f"not handle (close it and let the engine take the contact)"
            )
        if len(impacts) == MAX_IMPACTS:
            raise ValueError(
                f"more than {MAX_IMPACTS} impacts within one time step: the body is coming "
                f"to rest on the plane, which the hook does not handle"
            )
        exact = _apply(geo, law, ball, surface, rot, arm, v, w)
        v1, w1 = np.array(exact.after.velocity, float), np.array(exact.after.spin, float)
        impacts.append(HookImpact(start + done, x + arm, x.copy(), q, v, w, v1, w1, exact))
        v, w = v1, w1
    if not impacts:
        return impacts, None
    u = span - done
    return impacts, (x + v * u + 0.5 * g * u * u, v + g * u, _turn(w, u, q), w)


def _apply(geo, law, ball, surface, rot, arm, v, w):
    """The law's result at the contact: ``solve_sphere`` for the ball, else ``solve_rigid``
    with the inertia turned to the world frame."""
    if ball is not None:
        return solve_sphere(ball, v, w, mu=law.mu, kappa=law.kappa, surface=surface,
                            tangential=law.tangential)  # fmt: skip
    frame = rot @ geo.axes
    inertia = frame @ np.diag(geo.moments) @ frame.T
    body = RigidBody(geo.mass, 0.5 * (inertia + inertia.T), arm)
    return solve_rigid(body, v, w, mu=law.mu, kappa=law.kappa, law=law.law, surface=surface)


class Hook:
    """The engine-independent part of a hook: the exact flight beside the engine's, the
    planning of each step and the state written back. Engine modules supply ``_read``
    (centre and velocity), ``_turning`` (orientation ``w, x, y, z`` and world spin),
    ``_write``, ``_clock``
    (time, time step, gravity), ``_save(impact)``, ``_restore(saved)`` (whether it could),
    ``_discard(saved)``, ``_advance(v, g, span)`` (the engine's step, returning the
    reason it was not free flight from velocity ``v``, or ``None``) and
    ``_vacant(world)`` before the engine is changed and ``_claim(world, release)`` once
    set up (the world marked as hooked, and ``release`` called to give the engine's contact
    back when the hook is closed or dropped)."""

    _geometry: Geometry
    _law: Law

    def _setup(self, geometry: Geometry, law: Law) -> None:
        self._geometry, self._law = geometry, law
        self._ball = geometry.ball
        if law.tangential is not None and self._ball is None:
            raise ValueError(
                "tangential applies to a sphere centred on its centre of mass with a "
                "sphere's inertia; this body takes the rigid-body law (solve_rigid)"
            )
        self._surface = Surface(normal=tuple(geometry.normal))
        self._exact: np.ndarray | None = None  # the exact centre of mass, m
        self._engine: np.ndarray | None = None  # the engine's, after the hook's last step
        self._open = True

    @property
    def geometry(self) -> Geometry:
        """The body and plane as read from the engine."""
        return self._geometry

    @property
    def position(self) -> np.ndarray:
        """The exact flight's centre of mass now (m): the engine's own position, less its
        integration error since the last impact
        (:attr:`HookStep.drift <spinimpact.engines.HookStep.drift>`)."""
        x = self._read()[0]
        if self._engine is not None and np.array_equal(x, self._engine):
            return self._exact.copy()
        return x

    def step(self) -> HookStep:
        """Take one engine step with this body's impacts on the plane made exact.

        Returns
        -------
        HookStep
            The impacts applied in the step (none in most steps) and the engine's drift.

        Raises
        ------
        ValueError
            Where the hook is not valid: a resting contact, several points touching at
            once, a force other than gravity on the body (the engine's state is then as
            it was before the call); see :mod:`spinimpact.engines.hook`.
        RuntimeError
            If the hook has been closed.
        """
        if not self._open:
            raise RuntimeError("this hook is closed: make a new one to resume")
        x, v = self._read()
        if self._engine is None or not (x == self._engine).all():
            self._exact = x.copy()  # first step, or the body was moved: start from here
        x = self._exact
        start, span, g = self._clock()
        impacts, end = plan(self._geometry, self._law, self._ball, self._surface, span, start,
                            x, v, g, self._turning)  # fmt: skip
        saved = self._save(bool(impacts))
        reason = self._advance(v, g, span)
        if reason is not None:
            kept = self._restore(saved)
            tail = "as it was before this step" if kept else "stepped: this body's flight is lost"
            raise ValueError(f"{reason}: the hook predicts free flight under gravity only; "
                             f"the engine's state is {tail}")  # fmt: skip
        self._discard(saved)
        if impacts:
            self._write(*end)
            exact = end[0]
        else:
            exact = x + span * (v + (0.5 * span) * g)
        engine = self._read()[0]
        self._exact, self._engine = exact, engine
        return HookStep(tuple(impacts), start + span, engine - exact)

    @staticmethod
    def _vacant(world: Any) -> None:
        """``ValueError`` if ``world`` has an open hook (checked before the engine is
        touched)."""
        if world in _OPEN:
            raise ValueError("this model already has an open hook: one hook a model (each "
                             "takes the engine's step); close the open one first")  # fmt: skip

    def _claim(self, world: Any, release: Callable[[], None]) -> None:
        """Mark ``world`` as hooked and arrange for ``release`` (which must not hold the
        hook) to run once: at :meth:`close`, or when the hook is dropped without being
        closed, so the engine's contact always comes back."""
        self._vacant(world)
        _OPEN.add(world)
        self._finalizer = weakref.finalize(self, _give_back, world, release)

    def close(self) -> None:
        """Give the contact between the body and the plane back to the engine."""
        if self._open:
            self._open = False
            self._finalizer()

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()
