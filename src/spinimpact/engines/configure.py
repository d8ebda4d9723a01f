"""An engine configured by a dictionary of its own contact settings: run it, write it out.

:func:`run` bounces a batch of spheres in PyBullet or MuJoCo with every contact setting
taken from one dictionary in the engine's own terms (:data:`MUJOCO_SETTINGS`,
:data:`PYBULLET_SETTINGS`), and :func:`mjcf` and :func:`pybullet_source` write such a
dictionary as the engine's own configuration: an MJCF fragment, or PyBullet calls as
Python source. The scene :func:`run` loads is built from the same text that
:func:`mjcf` writes, so a written configuration is the one that was measured.
:func:`spinimpact.engines.calibrate` and :func:`spinimpact.engines.restitution_settings`
search these dictionaries.

In MuJoCo the ball touches the surface through a contact ``<pair>`` taking every
attribute from the ``<default><pair .../></default>`` class (a pair, because only a
pair has ``solreffriction``: the friction's own time constant); the surface's and
ball's geoms collide through nothing else. In PyBullet the surface has restitution and
lateral friction 1 and no rolling or spinning friction, so that the ball's values are the
contact's (Bullet multiplies restitution and friction of the two bodies).
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._validation import require, setting
from ..model.body import Body
from .common import (
    CONFIGURABLE,
    LEAD_STEPS,
    Stepped,
    check_engine,
    choice,
    from_engine,
    no_more,
    spacing,
    start_heights,
    to_engine,
    whole_number,
)
from .pybullet import PYBULLET_DEFAULTS

__all__ = [
    "MUJOCO_SETTINGS",
    "PYBULLET_SETTINGS",
    "defaults",
    "mjcf",
    "pybullet_source",
    "run",
    "version",
]

#: MuJoCo's own values of the contact settings (its documentation, "XML Reference"): the
#: time step (s), the pair's ``solref`` (time constant s, damping ratio), ``solimp``,
#: ``solreffriction`` (0 0: follow ``solref``), ``friction`` (two sliding, one
#: torsional, two rolling coefficients), ``condim``, and the options ``impratio`` and
#: ``cone``.
MUJOCO_SETTINGS: dict[str, Any] = {
    "timestep": 0.002,
    "solref": (0.02, 1.0),
    "solimp": (0.9, 0.95, 0.001, 0.5, 2.0),
    "solreffriction": (0.0, 0.0),
    "friction": (1.0, 1.0, 0.005, 0.0001, 0.0001),
    "condim": 3,
    "impratio": 1.0,
    "cone": "pyramidal",
    "noslip_iterations": 0,
}

#: PyBullet's values in a fresh process (the time step 1/240 s, 50 solver iterations,
#: the contact parameters of :data:`spinimpact.engines.PYBULLET_DEFAULTS`) and
#: ``changeDynamics``' restitution 0, lateral friction 0.5, rolling and spinning 0.
PYBULLET_SETTINGS: dict[str, Any] = {
    "timestep": 1.0 / 240.0,
    "restitution": 0.0,
    "lateral_friction": 0.5,
    "rolling_friction": 0.0,
    "spinning_friction": 0.0,
    **PYBULLET_DEFAULTS,
    "solver_iterations": 50,
}

#: ``setPhysicsEngineParameter``'s names of the global PyBullet settings.
_PYBULLET_GLOBAL = {
    "contact_breaking_threshold": "contactBreakingThreshold",
    "contact_erp": "contactERP",
    "restitution_velocity_threshold": "restitutionVelocityThreshold",
    "contact_slop": "contactSlop",
    "solver_iterations": "numSolverIterations",
}
#: ``changeDynamics``' names of the ball's settings.
_PYBULLET_BODY = {
    "restitution": "restitution",
    "lateral_friction": "lateralFriction",
    "rolling_friction": "rollingFriction",
    "spinning_friction": "spinningFriction",
}
#: Time after the first contact at which PyBullet's rebound is read, s (as ``bounce``).
_SETTLE = 0.05
#: A MuJoCo contact must end within this many of its (slowest) time constants.
_MUJOCO_CAP = 40


def defaults(engine: str) -> dict[str, Any]:
    """A copy of the engine's own defaults: :data:`MUJOCO_SETTINGS` or :data:`PYBULLET_SETTINGS`."""
    check_engine(engine, CONFIGURABLE)
    return dict(MUJOCO_SETTINGS if engine == "mujoco" else PYBULLET_SETTINGS)


def version(engine: str) -> str:
    """The installed engine's version: ``mujoco.__version__``, PyBullet's API version."""
    if check_engine(engine, CONFIGURABLE) == "mujoco":
        return str(require("mujoco", "the MuJoCo version").__version__)
    pb = require("pybullet", "the PyBullet version")
    return f"API {pb.getAPIVersion()}"


def checked(engine: str, settings: Mapping[str, Any]) -> dict[str, Any]:
    """The engine's defaults updated with ``settings``, each checked.

    Raises
    ------
    TypeError
        For a setting of the wrong type.
    ValueError
        For an unknown setting or one out of range (negative, not finite, a time step
        that is not > 0, a vector of the wrong length).
    """
    out = defaults(engine)
    given = dict(settings)
    for name, default in out.items():
        if name not in given:
            continue
        value = given.pop(name)
        if name in ("cone",):
            out[name] = choice(name, value, ("pyramidal", "elliptic"))
        elif name in ("condim", "solver_iterations", "noslip_iterations"):
            options = (1, 3, 4, 6) if name == "condim" else None
            out[name] = whole_number(name, value, low=int(name != "noslip_iterations"))
            if options and out[name] not in options:
                raise ValueError(f"condim must be 1, 3, 4 or 6, got {value!r}")
        elif isinstance(default, tuple):
            if (
                isinstance(value, str)
                or not hasattr(value, "__len__")
                or len(value) != len(default)
            ):
                raise TypeError(f"{name} must be {len(default)} numbers, got {value!r}")
            out[name] = tuple(_number(f"{name}[{i}]", v, True) for i, v in enumerate(value))
        else:
            out[name] = _number(name, value, name != "timestep")
    no_more(engine, given)
    return out


def _number(name: str, value: Any, zero: bool) -> float:
    rule = "a finite number >= 0" if zero else "a finite number > 0"
    return setting(name, value, low=0.0, closed=zero, rule=rule)


# -- the engines' own text -----------------------------------------------------------------
def _text(*values: Any) -> str:
    """Numbers as MJCF or Python text, each the shortest that reads back to the same float."""
    return " ".join(repr(float(v)) for v in values)


def _mujoco_parts(settings: Mapping[str, Any]) -> tuple[str, str]:
    """The ``<option>`` attributes and the ``<pair>`` default's attributes."""
    s = settings
    option = (
        f'timestep="{_text(s["timestep"])}" impratio="{_text(s["impratio"])}" cone="{s["cone"]}" '
        f'noslip_iterations="{s["noslip_iterations"]}"'
    )
    pair = (
        f'solref="{_text(*s["solref"])}" solimp="{_text(*s["solimp"])}" '
        f'solreffriction="{_text(*s["solreffriction"])}" friction="{_text(*s["friction"])}" '
        f'condim="{s["condim"]}"'
    )
    return option, pair


def mjcf(settings: Mapping[str, Any], *, note: str = "") -> str:
    """MuJoCo settings as an MJCF fragment to paste into a model.

    Parameters
    ----------
    settings : Mapping
        MuJoCo settings (keys of :data:`MUJOCO_SETTINGS`; the missing ones take MuJoCo's
        defaults).
    note : str
        A line for the leading comment (what the settings are for).

    Returns
    -------
    str
        An XML comment naming the MuJoCo version, an ``<option>`` element and a
        ``<default>`` class for contact pairs, and a comment showing the ``<pair>`` each
        ball and surface need: ``<contact><pair geom1="ball" geom2="floor"/></contact>``,
        with ``contype="0" conaffinity="0"`` on both geoms so that they touch only
        through the pair.
    """
    option, pair = _mujoco_parts(checked("mujoco", settings))
    lines = [f"<!-- MuJoCo {version('mujoco')}{': ' + note if note else ''} -->"]
    lines += [f"<option {option}/>", "<default>", f"  <pair {pair}/>", "</default>"]
    lines.append(
        "<!-- each contact as a pair, the geoms touching through it alone: <contact><pair "
        'geom1="ball" geom2="floor"/></contact>, contype="0" conaffinity="0" on both -->'
    )
    return "\n".join(lines) + "\n"


def pybullet_source(settings: Mapping[str, Any], *, note: str = "") -> str:
    """PyBullet settings as Python source: the calls that set them.

    Parameters
    ----------
    settings : Mapping
        PyBullet settings (keys of :data:`PYBULLET_SETTINGS`; the missing ones take
        PyBullet's defaults).
    note : str
        A line for the leading comment.

    Returns
    -------
    str
        Source text for a module that has ``p`` (``import pybullet as p``) and the body
        ids ``plane`` and ``ball``: ``p.setTimeStep``, ``p.setPhysicsEngineParameter``
        and one ``p.changeDynamics`` for each body, after a comment naming PyBullet's API
        version.
    """
    s = checked("pybullet", settings)
    glob = ", ".join(
        f"{api}={int(s[k]) if k == 'solver_iterations' else float(s[k])!r}"
        for k, api in _PYBULLET_GLOBAL.items()
    )
    ball = ", ".join(f"{api}={float(s[k])!r}" for k, api in _PYBULLET_BODY.items())
    lines = [
        f"# PyBullet {version('pybullet')}{': ' + note if note else ''}",
        f"p.setTimeStep({float(s['timestep'])!r})",
        f"p.setPhysicsEngineParameter({glob})",
        "p.changeDynamics(plane, -1, restitution=1.0, lateralFriction=1.0, "
        "rollingFriction=0.0, spinningFriction=0.0)",
        f"p.changeDynamics(ball, -1, {ball})",
    ]
    return "\n".join(lines) + "\n"


# -- running a batch -------------------------------------------------------------------------
def run(
    engine: str,
    body: Body,
    vx: np.ndarray,
    vy: np.ndarray,
    omega: np.ndarray,
    phase: np.ndarray,
    settings: Mapping[str, Any],
) -> Stepped:
    """Bounce one sphere per impact with the engine set up by ``settings``.

    Parameters
    ----------
    engine : {"pybullet", "mujoco"}
        The engine.
    body : Body
        The body, with scalar mass, radius and gyration.
    vx, vy, omega, phase : ndarray
        Flat incidences in the paper's axes (m/s, ``vy < 0``; rad/s) and contact phases
        in ``[0, 1)``, already validated.
    settings : Mapping
        The engine's settings (:func:`checked` fills in its defaults).

    Returns
    -------
    Stepped
        The rebounds, the steps, the wall time of the stepping and every setting used.

    Raises
    ------
    RuntimeError
        If a MuJoCo sphere has not left the surface after 40 of its contact's time
        constants.
    """
    used = checked(engine, settings)
    if engine == "mujoco":
        return _run_mujoco(body, vx, vy, omega, phase, used)
    return _run_pybullet(body, vx, vy, omega, phase, used)


def _run_mujoco(body, vx, vy, omega, phase, s) -> Stepped:
    from .mujoco import _step

    mj = require("mujoco", "engines.calibrate('mujoco', ...)")
    option, pair = _mujoco_parts(s)
    radius, mass, inertia = float(body.radius), float(body.mass), float(body.inertia)
    apart, dt = spacing(radius), s["timestep"]
    heights = start_heights(radius, vy, phase, dt)
    bodies = "".join(
        f'<body pos="0 {_text(apart * i)} {_text(z)}"><freejoint/><inertial pos="0 0 0" '
        f'mass="{_text(mass)}" diaginertia="{_text(inertia, inertia, inertia)}"/>'
        f'<geom name="s{i}" type="sphere" size="{_text(radius)}" contype="0" conaffinity="0"/>'
        "</body>"
        for i, z in enumerate(heights)  # MJCF names every body: text, one per impact
    )
    pairs = "".join(f'<pair geom1="floor" geom2="s{i}"/>' for i in range(vx.size))
    xml = (
        f'<mujoco><option {option} gravity="0 0 0"/><default><pair {pair}/></default>'
        '<worldbody><geom name="floor" type="plane" size="0 0 1" contype="0" conaffinity="0"/>'
        f"{bodies}</worldbody><contact>{pairs}</contact></mujoco>"
    )
    model = mj.MjModel.from_xml_string(xml)
    slowest = max(s["solref"][0], s["solreffriction"][0], 2 * dt)
    cap = LEAD_STEPS + 2 + int(_MUJOCO_CAP * slowest / dt)
    return Stepped(*_step(mj, model, vx, vy, omega, cap), dict(s))


def _run_pybullet(body, vx, vy, omega, phase, s) -> Stepped:
    pb = require("pybullet", "engines.calibrate('pybullet', ...)")
    dt = s["timestep"]
    mass, radius, inertia = float(body.mass), float(body.radius), float(body.inertia)
    linear, angular = to_engine(vx, vy, omega)
    client = pb.connect(pb.DIRECT)
    try:
        kw = {"physicsClientId": client}
        pb.setGravity(0, 0, 0, **kw)
        pb.setTimeStep(dt, **kw)
        glob = {api: s[k] for k, api in _PYBULLET_GLOBAL.items()}
        glob["numSolverIterations"] = int(glob["numSolverIterations"])
        pb.setPhysicsEngineParameter(**glob, **kw)
        plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE, **kw), **kw)
        pb.changeDynamics(
            plane, -1, restitution=1.0, lateralFriction=1.0, rollingFriction=0.0,
            spinningFriction=0.0, **kw,
        )  # fmt: skip
        sphere = pb.createCollisionShape(pb.GEOM_SPHERE, radius=radius, **kw)
        height, apart = start_heights(radius, vy, phase, dt), spacing(radius)
        ball = {api: float(s[k]) for k, api in _PYBULLET_BODY.items()}
        ids = []
        for i in range(vx.size):  # the engine's API creates bodies one by one
            b = pb.createMultiBody(mass, sphere, basePosition=[0.0, apart * i, height[i]], **kw)
            pb.changeDynamics(
                b, -1, **ball, linearDamping=0.0, angularDamping=0.0, maxJointVelocity=1e30,
                localInertiaDiagonal=[inertia] * 3, **kw,
            )  # fmt: skip
            pb.resetBaseVelocity(b, linear[i].tolist(), angular[i].tolist(), **kw)
            ids.append(b)
        steps = LEAD_STEPS + 1 + math.ceil(_SETTLE / dt)
        start = time.perf_counter()
        for _ in range(steps):
            pb.stepSimulation(**kw)
        seconds = time.perf_counter() - start
        state = np.array([pb.getBaseVelocity(b, **kw) for b in ids]).reshape(-1, 2, 3)
    finally:
        pb.disconnect(client)
    return Stepped(*from_engine(state[:, 0], state[:, 1]), steps, seconds, dict(s))
