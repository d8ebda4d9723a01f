"""The same bounce in general-purpose physics engines, beside the exact answer.

Robotics, game and DEM developers usually bounce balls in a general engine. This
module sets up PyBullet and MuJoCo (the ``[engines]`` extra,
``pip install 'spinimpact[engines]'``) to bounce exactly the impact that
:func:`spinimpact.solve` solves, so the engine's error can be measured case by
case:

>>> from spinimpact import Body
>>> from spinimpact.engines import bounce
>>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
>>> run = bounce("pybullet", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}; error {run.error:.0%}")
vy+ -0.002 m/s, exact 0.500; error 17%
>>> run = bounce("mujoco", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}; error {run.error:.0%}")
vy+ 0.574 m/s, exact 0.500; error 2%

At its default settings PyBullet lost this bounce altogether (the error is
over the incidence speed scale, here ``|vx| = 3`` m/s); with its contact margin,
position correction and restitution threshold set to 0 it gives the exact
answer, and a calibrated MuJoCo contact comes within a few percent (see
``docs/performance.md`` for many impacts):

>>> exact = dict(contact_breaking_threshold=0, contact_erp=0, restitution_velocity_threshold=0)
>>> run = bounce("pybullet", ball, vx=3.0, vy=-1.0, omega=0.0, mu=0.1, kappa=0.5, **exact)
>>> print(f"vy+ {run.vy:.3f} m/s, exact {run.exact.after.vy:.3f}")
vy+ 0.500 m/s, exact 0.500
>>> bool(run.error < 1e-12)
True

The engines see the body as a sphere of the body's radius with the isotropic
inertia ``mass * gyration**2`` (so a disk or a shell bounces with its own
``zeta``), gravity is switched off so that only the impact acts, and friction
and restitution are set to the Coulomb ``mu`` and the ``kappa`` of the exact
solution as each engine defines them. Paper axes map to the engines' z-up axes
as x -> x, y -> z, and the spin ``omega`` (counter-clockwise, about the paper's
z = x cross y) is the angular velocity ``(0, -omega, 0)``.

Time-stepping engines resolve an impact at the steps, so their answer depends
on where, within a time step, the body reaches the surface: the ``phase`` in
[0, 1) of that instant. :func:`standard_cases` samples it uniformly.

The physics stays in :mod:`spinimpact.core`: this module only drives the
engines and compares their output with :func:`spinimpact.solve`.
"""

from __future__ import annotations

import importlib.util
import math
import numbers
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._validation import as_real_array, broadcast, check, validated
from ..model.body import Body
from ..model.impact import Impact, solve

#: The engines this module can drive, each from the ``[engines]`` extra.
ENGINES = ("pybullet", "mujoco")
#: Modules the docstring examples need (tests/test_docs.py skips them without).
__doctest_requires__ = ENGINES

#: The engine set-ups compared in ``docs/performance.md`` and by ``make bench``:
#: (label, engine, settings for :func:`bounce`), each engine's defaults first.
CONFIGURATIONS = (
    ("PyBullet, 240 Hz (its default)", "pybullet", {}),
    ("PyBullet, 1000 Hz", "pybullet", {"hz": 1000.0}),
    (
        "PyBullet, 240 Hz, exact-contact settings",
        "pybullet",
        {
            "contact_breaking_threshold": 0.0,
            "contact_erp": 0.0,
            "restitution_velocity_threshold": 0.0,
        },
    ),
    ("MuJoCo, its default contact", "mujoco", {"contact": "default"}),
    ("MuJoCo, calibrated, pyramidal", "mujoco", {"friction_time": None}),
    ("MuJoCo, calibrated, elliptic + solreffriction", "mujoco", {}),
)

__all__ = [
    "CONFIGURATIONS",
    "PYBULLET_DEFAULTS",
    "ENGINES",
    "EngineRun",
    "available",
    "bounce",
    "standard_cases",
]


#: Whole time steps of free flight before the step in which contact begins.
_LEAD_STEPS = 2
#: A calibrated MuJoCo contact's default depth of penetration, a fraction of the radius.
_PENETRATION = 0.01
#: How close a calibrated MuJoCo contact's head-on restitution is made to kappa.
_KAPPA_TOLERANCE = 1e-5
#: Time after the first contact at which the rebound is read, s.
_SETTLE = 0.05


def available(engine: str) -> bool:
    """Whether ``engine`` (one of :data:`ENGINES`) can be imported here."""
    _check_engine(engine)
    return importlib.util.find_spec(engine) is not None


def _check_engine(engine: str) -> None:
    if engine not in ENGINES:
        raise ValueError(f"engine must be one of {', '.join(ENGINES)}; got {engine!r}")


def _import(engine: str) -> Any:
    _check_engine(engine)
    if not available(engine):
        raise ModuleNotFoundError(
            f"the {engine} engine is not installed; install it with "
            f"pip install 'spinimpact[engines]'"
        )
    return importlib.import_module(engine)


@dataclass(frozen=True)
class EngineRun:
    """An engine's rebounds of a batch of impacts, beside the exact answer.

    Attributes
    ----------
    engine : str
        ``"pybullet"`` or ``"mujoco"``.
    settings : Mapping
        The engine settings used (time step, solver options, ...); for the
        calibrated MuJoCo contact also its ``stiffness`` (1/s^2) and the flat
        array of each impact's calibrated ``damping`` (1/s), the negated
        ``solref`` of its contact pair.
    vx, vy, omega : ndarray
        The engine's rebound velocity and spin, in the paper's axes.
    exact : Impact
        :func:`spinimpact.solve` of the same impacts.
    phase : ndarray
        Where, as a fraction of the time step, the body reached the surface.
    steps : int
        Time steps the engine took for the batch.
    seconds : float
        Wall time of the engine's stepping for the whole batch (setting up the
        scene is not counted), s.
    """

    engine: str
    settings: Mapping[str, Any]
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    exact: Impact
    phase: np.ndarray
    steps: int
    seconds: float
    _scale: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        before, radius = self.exact.before, self.exact.body.radius
        scale = np.maximum.reduce(
            [np.abs(before.vx), np.abs(before.vy), np.abs(radius * before.omega)]
        )
        object.__setattr__(self, "_scale", scale)

    @property
    def scale(self) -> np.ndarray:
        """Speed scale of each impact: ``max(|vx|, |vy|, R |omega|)`` before it, m/s."""
        return self._scale

    def errors(self) -> dict[str, np.ndarray]:
        """Error of each rebound quantity relative to the incidence speed scale.

        ``|vx_engine - vx_exact| / scale``, the same for ``vy`` and, as the
        rim speed, ``R |omega_engine - omega_exact| / scale``, with
        :attr:`scale` ``= max(|vx|, |vy|, R |omega|)`` before the impact. (Errors
        relative to each exact value would blow up where it is near zero, as
        when a ball leaves rolling with ``omega`` about 0.)
        """
        exact, radius = self.exact.after, self.exact.body.radius
        return {
            "vx": np.abs(self.vx - exact.vx) / self.scale,
            "vy": np.abs(self.vy - exact.vy) / self.scale,
            "omega": np.abs(radius * (self.omega - exact.omega)) / self.scale,
        }

    @property
    def error(self) -> np.ndarray:
        """The largest of the three :meth:`errors` of each impact."""
        return np.maximum.reduce(list(self.errors().values()))

    @property
    def seconds_per_impact(self) -> float:
        """Wall time of the engine's stepping per impact, s."""
        return self.seconds / max(self.vx.size, 1)

    def summary(self) -> dict[str, dict[str, float]]:
        """Median, 95th percentile and maximum of each error and of the worst of three."""
        out = {}
        for name, err in {**self.errors(), "worst": self.error}.items():
            out[name] = {
                "median": float(np.median(err)),
                "p95": float(np.percentile(err, 95)),
                "max": float(np.max(err)),
            }
        return out


def standard_cases(phases: int = 8) -> dict[str, np.ndarray]:
    """The grid of impacts on which the engines are compared (documented figures).

    A solid sphere of radius 0.1 m: ``vx`` in {-2, 0, 1, 3} m/s, ``vy`` in
    {-1, -3} m/s, rim speed ``R omega`` in {-3, 0, 2} m/s, ``mu`` in
    {0.1, 0.3, 0.6}, ``kappa`` in {0.5, 0.8}: 144 impacts spanning sticking and
    sliding, backspin and topspin, each at ``phases`` contact phases
    ``(j + 1/2)/phases`` spread evenly over a time step.

    Returns
    -------
    dict
        Flat arrays ``vx, vy, omega, mu, kappa, phase`` (keyword arguments of
        :func:`bounce`), ``144 * phases`` long.
    """
    if isinstance(phases, bool) or not isinstance(phases, int | np.integer) or phases < 1:
        raise ValueError(f"phases must be a whole number >= 1, got {phases!r}")
    radius = 0.1
    grid = np.meshgrid(
        [-2.0, 0.0, 1.0, 3.0],
        [-1.0, -3.0],
        [-3.0, 0.0, 2.0],
        [0.1, 0.3, 0.6],
        [0.5, 0.8],
        (np.arange(phases) + 0.5) / phases,
        indexing="ij",
    )
    vx, vy, rim, mu, kappa, phase = (g.ravel() for g in grid)
    return {"vx": vx, "vy": vy, "omega": rim / radius, "mu": mu, "kappa": kappa, "phase": phase}


def bounce(
    engine: str,
    body: Body,
    vx: Any,
    vy: Any,
    omega: Any,
    *,
    mu: Any,
    kappa: Any,
    phase: Any = 0.5,
    **settings: Any,
) -> EngineRun:
    """Bounce ``body`` off the plane in a physics engine and compare with :func:`solve`.

    Parameters
    ----------
    engine : {"pybullet", "mujoco"}
        The engine (from the ``[engines]`` extra).
    body : Body
        The body, with scalar mass, radius and gyration; the engine sees a sphere
        of its radius with isotropic inertia ``mass * gyration**2``.
    vx, vy, omega : float or array_like
        Incidence velocity (m/s, ``vy < 0``) and spin (rad/s), as in :func:`solve`.
    mu : float or array_like
        Coulomb friction coefficient, ``>= 0``.
    kappa : float or array_like
        Coefficient of restitution in ``[0, 1]``, set as the engine defines it
        (see the engine's notes below).
    phase : float or array_like
        Where within a time step the body reaches the surface, in ``[0, 1)``:
        it starts ``(2 + phase)`` time steps of free flight above the plane.
    **settings
        Engine options, below.

    Returns
    -------
    EngineRun
        The engine's rebounds, the exact :class:`~spinimpact.Impact`, the errors
        and the wall time of the stepping.

    Notes
    -----
    **PyBullet** settings: ``hz`` (240, its default step rate),
    ``solver_iterations`` (50), and the contact parameters
    ``contact_breaking_threshold`` (m), ``contact_erp`` and
    ``restitution_velocity_threshold`` (m/s), by default the values PyBullet
    starts with (:data:`PYBULLET_DEFAULTS`). Bullet keeps some of them for the
    whole process, so every run sets them all. The sphere's restitution is
    ``kappa`` and its lateral friction ``mu`` against a plane with both equal to
    1 (Bullet multiplies the two bodies' values, and caps friction at 10, so
    ``mu <= 10``); rolling and spinning friction, velocity damping and Bullet's
    velocity clamp (100 m/s and rad/s by default) are removed. Bullet's
    restitution is Newton's velocity ratio, which for a body whose contact normal
    passes through its centre is Poisson's ``kappa``; with
    ``contact_breaking_threshold=0, contact_erp=0,
    restitution_velocity_threshold=0`` its one-step impulse solve is the exact
    rigid-body answer. Velocities are read 50 ms after contact.

    **MuJoCo** has no coefficient of restitution or hard Coulomb friction: its
    contacts are soft constraints. ``contact="calibrated"`` (the default) gives
    each sphere a contact pair with friction ``mu`` (``condim=3``) and a linear
    spring-damper normal law (``solref`` as ``(-stiffness, -damping)``, flat
    ``solimp`` 0.99). Its stiffness sets the head-on contact duration
    ``contact_time``, by default ``0.01 pi R / max|vy|`` so the sphere sinks
    about 1 % of its radius (the estimate is ``settings["penetration"]``); its
    damping is calibrated, by secant iterations on head-on bounces at the
    contact phase 0.5, so that the head-on restitution is ``kappa`` to 1e-5 at
    any speed (other phases shift it by up to a few 1e-3); ``kappa`` must lie in
    about [0.01, 0.99]. Friction is a velocity-damping target with time constant
    ``friction_time * contact_time`` (``solreffriction``, default 0.6, which needs
    the elliptic cone); with ``friction_time=None`` it follows the normal
    ``solref`` under MuJoCo's default pyramidal cone, which leaves much of the
    slip unresolved. ``timestep`` defaults to ``contact_time / 100``; Newton
    solver, 100 iterations, tolerance 1e-10, ``implicitfast`` integrator.
    ``contact="default"`` is MuJoCo's own contact with only the friction set
    (``timestep=0.002``): its restitution is fixed by the default ``solref``
    whatever ``kappa`` is. Steps run until every sphere has left the surface.
    The spin is read from the free joint's body-frame angular velocity rotated
    to the world frame.

    All impacts of a call share one scene (one world, bodies far apart), which
    is how an engine is run at scale; setting up the scene is a Python loop
    over the impacts through the engine's API, and is not timed.

    Raises
    ------
    ValueError
        For an unknown engine or setting, or inputs outside their ranges.
    ModuleNotFoundError
        If the engine is not installed.
    """
    _check_engine(engine)
    if not isinstance(body, Body):
        raise ValueError(f"body must be a spinimpact.Body, got {body!r}")
    for name in ("mass", "radius", "gyration"):
        if np.ndim(getattr(body, name)) != 0:
            raise ValueError(
                f"body.{name} must be a single number for an engine run, "
                f"got an array of shape {np.shape(getattr(body, name))}"
            )
    arrays = {
        "vx": validated("vx", vx),
        "vy": validated("vy", vy),
        "omega": validated("omega", omega),
        "mu": validated("mu", mu),
        "kappa": validated("kappa", kappa),
        "phase": as_real_array("phase", phase),
    }
    check("phase", arrays["phase"], lambda p: (p >= 0) & (p < 1), "in [0, 1)")
    shaped = dict(zip(arrays, broadcast(**arrays), strict=True))
    shape = shaped["vx"].shape
    if shaped["vx"].size == 0:
        raise ValueError(f"the inputs hold no impact (broadcast shape {shape})")
    runner = {"pybullet": _pybullet, "mujoco": _mujoco}[engine]
    module = _import(engine)
    flat = {k: np.ravel(v) for k, v in shaped.items()}
    out, steps, seconds, used = runner(module, body, **flat, **settings)
    exact = solve(
        body, shaped["vx"], shaped["vy"], shaped["omega"], mu=shaped["mu"], kappa=shaped["kappa"]
    )
    vx_after, vy_after, omega_after = (_shaped(x, shape) for x in out)
    return EngineRun(
        engine,
        used,
        vx_after,
        vy_after,
        omega_after,
        exact,
        _shaped(shaped["phase"], shape),
        steps,
        seconds,
    )


def _shaped(x: np.ndarray, shape: tuple[int, ...]) -> Any:
    """Read-only array of ``shape``; a NumPy scalar for 0-d, as :func:`solve` gives."""
    arr = np.reshape(np.array(x, dtype=np.float64), shape)
    arr.setflags(write=False)
    return arr[()]


def _setting(settings: dict[str, Any], name: str, default: Any, ok: Any, rule: str) -> Any:
    value = settings.pop(name, default)
    if isinstance(value, bool) or not ok(value):
        raise ValueError(f"{name} must be {rule}, got {value!r}")
    return value


def _number(settings: dict[str, Any], name: str, default: float, low: float, rule: str) -> float:
    """A finite real setting ``> low`` (``>= low`` where ``rule`` says so)."""
    closed = ">=" in rule

    def ok(v: Any) -> bool:
        if not isinstance(v, numbers.Real) or not math.isfinite(v):
            return False
        return v >= low if closed else v > low

    return float(_setting(settings, name, default, ok, rule))


def _no_more(engine: str, settings: dict[str, Any]) -> None:
    if settings:
        raise ValueError(f"unknown {engine} setting(s): {', '.join(sorted(settings))}")


#: PyBullet 3.2.7's contact parameters in a fresh process (setting these values
#: explicitly reproduces a fresh process's results bit for bit). Some are global to
#: the process in Bullet, so every run sets them all.
PYBULLET_DEFAULTS = {
    "contact_breaking_threshold": 0.02,
    "contact_erp": 0.08,
    "restitution_velocity_threshold": 0.2,
}


def _pybullet(module, body, vx, vy, omega, mu, kappa, phase, **settings):
    """Run the impacts in one PyBullet world; return ((vx, vy, omega), steps, s, settings)."""
    pb = module
    hz = _number(settings, "hz", 240.0, 0.0, "a finite rate > 0 (Hz)")
    iterations = _setting(
        settings,
        "solver_iterations",
        50,
        lambda v: isinstance(v, numbers.Integral) and v >= 1,
        "a whole number >= 1",
    )
    contact = {
        name: _number(settings, name, default, 0.0, "a finite number >= 0")
        for name, default in PYBULLET_DEFAULTS.items()
    }
    _no_more("pybullet", settings)
    if np.any(mu > 10):
        raise ValueError(
            f"mu must be <= 10 for PyBullet (Bullet caps the combined friction at 10), "
            f"got {float(mu[mu > 10][0])!r}"
        )
    dt = 1.0 / hz
    mass, radius = float(body.mass), float(body.radius)
    inertia = float(body.inertia)
    client = pb.connect(pb.DIRECT)
    try:
        kw = {"physicsClientId": client}
        pb.setGravity(0, 0, 0, **kw)
        pb.setTimeStep(dt, **kw)
        pb.setPhysicsEngineParameter(
            numSolverIterations=int(iterations),
            contactBreakingThreshold=contact["contact_breaking_threshold"],
            contactERP=contact["contact_erp"],
            restitutionVelocityThreshold=contact["restitution_velocity_threshold"],
            **kw,
        )
        plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE, **kw), **kw)
        pb.changeDynamics(plane, -1, restitution=1.0, lateralFriction=1.0, **kw)
        sphere = pb.createCollisionShape(pb.GEOM_SPHERE, radius=radius, **kw)
        height = radius + np.abs(vy) * (_LEAD_STEPS + phase) * dt
        spacing = 4.0 * radius + 1.0  # far enough apart never to touch during the run
        ids = []
        for i in range(vx.size):  # the engine's API creates bodies one by one
            b = pb.createMultiBody(mass, sphere, basePosition=[0.0, spacing * i, height[i]], **kw)
            pb.changeDynamics(
                b,
                -1,
                restitution=float(kappa[i]),
                lateralFriction=float(mu[i]),
                rollingFriction=0.0,
                spinningFriction=0.0,
                linearDamping=0.0,
                angularDamping=0.0,
                maxJointVelocity=1e30,  # lift Bullet's default clamp of 100 m/s and rad/s
                localInertiaDiagonal=[inertia] * 3,
                **kw,
            )
            pb.resetBaseVelocity(b, [vx[i], 0.0, vy[i]], [0.0, -omega[i], 0.0], **kw)
            ids.append(b)
        # Contact starts in step _LEAD_STEPS + 1; the velocities are read
        # _SETTLE seconds later, once Bullet's penetration recovery is over.
        steps = _LEAD_STEPS + 1 + math.ceil(_SETTLE * hz)
        start = time.perf_counter()
        for _ in range(steps):
            pb.stepSimulation(**kw)
        seconds = time.perf_counter() - start
        state = np.array([pb.getBaseVelocity(b, **kw) for b in ids]).reshape(-1, 2, 3)
    finally:
        pb.disconnect(client)
    out = (state[:, 0, 0], state[:, 0, 2], -state[:, 1, 1])
    return out, steps, seconds, {"hz": hz, "solver_iterations": int(iterations), **contact}


def _mujoco_xml(opts, radius, mass, inertia, heights, spacing, mu, pairs) -> str:
    """MJCF of a floor and one free sphere per impact, side by side along y."""
    opt = " ".join(f'{k}="{v}"' for k, v in opts.items())
    bodies, contacts = [], []
    collide = "" if pairs is None else ' contype="0" conaffinity="0"'
    friction = "" if pairs is not None else ' friction="{mu:.17g} 0 0"'
    for i, z in enumerate(heights):  # MJCF names every body: text, one per impact
        geom_friction = friction.format(mu=mu[i])
        bodies.append(
            f'<body name="b{i}" pos="0 {spacing * i:.17g} {z:.17g}"><freejoint/>'
            f'<inertial pos="0 0 0" mass="{mass:.17g}" diaginertia="{inertia:.17g} '
            f'{inertia:.17g} {inertia:.17g}"/>'
            f'<geom name="s{i}" type="sphere" size="{radius:.17g}"{collide}{geom_friction}/></body>'
        )
        if pairs is not None:
            contacts.append(
                f'<pair geom1="floor" geom2="s{i}" condim="3" friction="{mu[i]:.17g} '
                f'{mu[i]:.17g} 0 0 0" margin="0" gap="0" {pairs}/>'
            )
    floor = f'<geom name="floor" type="plane" size="0 0 1" friction="0 0 0"{collide}/>'
    contact = f"<contact>{''.join(contacts)}</contact>" if contacts else ""
    return (
        f"<mujoco><option {opt}/><worldbody>{floor}{''.join(bodies)}</worldbody>{contact}</mujoco>"
    )


def _rotate(q, v):
    """Rotate the vectors ``v`` (n, 3) by the unit quaternions ``q`` (n, 4), w first."""
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def _mujoco_run(mj, model, vx, vy, omega, max_steps):
    """Step ``model`` from the given incidence until every sphere has bounced clear.

    Returns ((vx, vy, omega) after, steps, seconds).
    """
    data = mj.MjData(model)
    qvel = np.zeros((vx.size, 6))
    qvel[:, 0], qvel[:, 2], qvel[:, 4] = vx, vy, -omega  # angular: body frame = world at start
    data.qvel[:] = qvel.ravel()
    steps, touched = 0, False
    start = time.perf_counter()
    while steps < max_steps:
        mj.mj_step(model, data)
        steps += 1
        touched = touched or data.ncon > 0
        if touched and data.ncon == 0 and np.all(data.qvel[2::6] > 0):
            break
    else:
        raise RuntimeError(f"MuJoCo: not every sphere had left the surface after {max_steps} steps")
    seconds = time.perf_counter() - start
    qvel = data.qvel.reshape(-1, 6)
    spin = _rotate(data.qpos.reshape(-1, 7)[:, 3:], qvel[:, 3:])  # free joint: body frame
    return (qvel[:, 0].copy(), qvel[:, 2].copy(), -spin[:, 1]), steps, seconds


def _mujoco(module, body, vx, vy, omega, mu, kappa, phase, **settings):
    """Run the impacts in one MuJoCo model; return ((vx, vy, omega), steps, s, settings)."""
    mj = module
    contact = _setting(
        settings,
        "contact",
        "calibrated",
        lambda v: v in ("calibrated", "default"),
        "'calibrated' or 'default'",
    )
    calibrated = contact == "calibrated"
    radius, mass, inertia = float(body.radius), float(body.mass), float(body.inertia)
    if not calibrated:
        for name in ("contact_time", "friction_time"):
            if name in settings:
                raise ValueError(f"{name} applies only to contact='calibrated', not 'default'")
        timestep = _number(settings, "timestep", 0.002, 0.0, "a finite time > 0 (s)")
        used: dict[str, Any] = {"contact": contact, "timestep": timestep}
    else:
        # By default the contact lasts long enough for about 100 steps but short
        # enough that the sphere sinks about 1 % of its radius: penetration is
        # about |vy| contact_time / pi for a linear spring.
        speed = float(np.max(np.abs(vy)))
        default_time = _PENETRATION * math.pi * radius / speed
        contact_time = _number(settings, "contact_time", default_time, 0.0, "a finite time > 0 (s)")
        timestep = _number(settings, "timestep", contact_time / 100, 0.0, "a finite time > 0 (s)")
        friction_time = _setting(
            settings,
            "friction_time",
            0.6,
            lambda v: v is None or (isinstance(v, numbers.Real) and 0 < v < math.inf),
            "None or a finite fraction of the contact time > 0",
        )
        if contact_time < 20 * timestep:
            raise ValueError(
                f"contact_time must span at least 20 time steps ({20 * timestep:g} s), "
                f"got {contact_time!r}"
            )
        used = {
            "contact": contact,
            "timestep": timestep,
            "contact_time": contact_time,
            "friction_time": friction_time,
            "penetration": speed * contact_time / math.pi / radius,
        }
    _no_more("mujoco", settings)
    opts = {
        "timestep": repr(timestep),
        "gravity": "0 0 0",
        "solver": "Newton",
        "iterations": 100,
        "tolerance": "1e-10",
    }
    if calibrated:
        opts.update(integrator="implicitfast", cone="elliptic" if friction_time else "pyramidal")
    spacing = 4.0 * radius + 1.0
    heights = radius + np.abs(vy) * (_LEAD_STEPS + phase) * timestep
    cap = _LEAD_STEPS + 2 + int(20 * (contact_time if calibrated else 0.5) / timestep)
    if not calibrated:
        xml = _mujoco_xml(opts, radius, mass, inertia, heights, spacing, mu, None)
        out, steps, seconds = _mujoco_run(mj, mj.MjModel.from_xml_string(xml), vx, vy, omega, cap)
        return out, steps, seconds, used
    stiffness = (math.pi / contact_time) ** 2  # per unit mass: the contact's duration
    friction = f' solreffriction="{friction_time * contact_time!r} 1"' if friction_time else ""
    pairs = f'solref="{-stiffness!r} -1" solimp="0.99 0.99 0.001 0.5 2"{friction}'
    # Under the pyramidal cone friction enters even a head-on bounce: calibrate each
    # (kappa, mu) pair with its own mu.
    levels, which = np.unique(np.stack([kappa, mu], axis=1), axis=0, return_inverse=True)
    damping = _mujoco_damping(
        mj, opts, radius, mass, inertia, spacing, pairs, levels[:, 0], levels[:, 1], cap
    )
    xml = _mujoco_xml(opts, radius, mass, inertia, heights, spacing, mu, pairs)
    model = mj.MjModel.from_xml_string(xml)
    model.pair_solref[:, 1] = -damping[which.ravel()]
    out, steps, seconds = _mujoco_run(mj, model, vx, vy, omega, cap)
    used["stiffness"] = stiffness
    # the calibrated damping of each impact's pair, 1/s (solref's second entry is -damping)
    used["damping"] = model.pair_solref[:, 1] * -1.0
    return out, steps, seconds, used


def _mujoco_damping(mj, opts, radius, mass, inertia, spacing, pairs, kappa, mu, cap):
    """Contact damping for which a head-on MuJoCo bounce has restitution ``kappa``.

    Secant iterations on all the ``(kappa, mu)`` pairs at once, in one model of
    head-on bounces at the contact phase 0.5, starting from the damped linear oscillator's
    ``b = 2 zeta sqrt(k)`` with ``kappa = exp(-pi zeta / sqrt(1 - zeta^2))``,
    until the restitution is within ``_KAPPA_TOLERANCE`` of ``kappa`` (MuJoCo's
    solver leaves noise of a few 1e-6 in it with pyramidal friction cones).
    """
    if np.any(kappa <= 0) or np.any(kappa >= 1):
        bad = kappa[(kappa <= 0) | (kappa >= 1)][0]
        raise ValueError(
            f"kappa must be in (0, 1) for a calibrated MuJoCo contact (a spring-damper "
            f"reaches neither end), got {float(bad)!r}"
        )
    n = kappa.size
    vy = np.full(n, -1.0)
    heights = radius + (_LEAD_STEPS + 0.5) * float(opts["timestep"])
    xml = _mujoco_xml(opts, radius, mass, inertia, np.full(n, heights), spacing, mu, pairs)
    model = mj.MjModel.from_xml_string(xml)
    stiffness = -model.pair_solref[0, 0]
    log = np.log(kappa)
    guess = 2.0 * np.sqrt(stiffness) * -log / np.sqrt(math.pi**2 + log**2)

    def restitution(b):
        model.pair_solref[:, 1] = -b
        (_, vy_after, _), _, _ = _mujoco_run(mj, model, np.zeros(n), vy, np.zeros(n), cap)
        return vy_after

    b0, b1 = guess, 1.05 * guess
    k0, k1 = restitution(b0), restitution(b1)
    for _ in range(30):
        if np.all(np.abs(k1 - kappa) <= _KAPPA_TOLERANCE):
            return b1
        step = np.where(k1 != k0, (k1 - kappa) * (b1 - b0) / (k1 - k0), 0.0)
        b0, k0 = b1, k1
        b1 = np.maximum(b1 - step, 0.5 * b1)  # damping stays positive
        k1 = restitution(b1)
    bad = kappa[np.abs(k1 - kappa) > _KAPPA_TOLERANCE][0]
    raise ValueError(
        f"kappa = {float(bad)!r} cannot be reached by the calibrated MuJoCo contact "
        f"(its damping calibration did not converge); kappa in [0.01, 0.99] can"
    )
