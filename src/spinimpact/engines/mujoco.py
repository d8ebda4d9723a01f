r"""The bounce in MuJoCo (the ``[engines]`` extra): one model of free spheres on a floor.

MuJoCo [1]_ has no coefficient of restitution and no hard Coulomb friction: its
contacts are soft constraints, solved as a convex optimisation each time step
[2]_, whose reference acceleration follows a spring-damper set by ``solref``
and whose impedance is set by ``solimp`` ([3]_, "Solver parameters"). A
negative ``solref = (-stiffness, -damping)``, with the flat impedance ``solimp``
0.99 used here, makes the normal contact nearly the linear spring-damper
``a = -k * depth - b * velocity`` (per unit mass, stiffness ``k``, damping
``b``), whose head-on restitution depends only on its damping ratio ``xi``, not
on the speed:

.. math:: \kappa = \exp\left(-\frac{\pi \xi}{\sqrt{1 - \xi^2}}\right),
   \qquad \xi = \frac{b}{2 \sqrt{k}}

(the damped linear oscillator; ``xi`` is not the body's ``zeta``). MuJoCo's
constraint solver shifts it slightly, so :func:`run`'s calibrated contact starts
from this damping and corrects it by secant iterations on head-on bounces until
the restitution is ``kappa`` to :data:`_KAPPA_TOLERANCE`.

References
----------
.. [1] E. Todorov, T. Erez and Y. Tassa, "MuJoCo: A physics engine for
   model-based control", 2012 IEEE/RSJ International Conference on Intelligent
   Robots and Systems (IROS), Vilamoura, 2012, pp. 5026-5033,
   doi:10.1109/IROS.2012.6386109.
.. [2] E. Todorov, "Convex and analytically-invertible dynamics with contacts and
   constraints: Theory and implementation in MuJoCo", 2014 IEEE International
   Conference on Robotics and Automation (ICRA), Hong Kong, 2014,
   pp. 6054-6061, doi:10.1109/ICRA.2014.6907751.
.. [3] MuJoCo documentation, "Modeling", https://mujoco.readthedocs.io/en/stable/modeling.html
   (solver parameters ``solref``, ``solimp``, ``solreffriction``; contact pairs;
   friction cones).
"""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np

from .._validation import require, setting
from ..model.body import Body
from .common import (
    LEAD_STEPS,
    Stepped,
    choice,
    from_engine,
    no_more,
    spacing,
    start_heights,
    to_engine,
)

__all__ = ["run"]

#: A calibrated contact's default depth of penetration, a fraction of the radius.
_PENETRATION = 0.01
#: How close a calibrated contact's head-on restitution is made to kappa.
_KAPPA_TOLERANCE = 1e-5
#: A contact time must span at least this many time steps.
_MIN_STEPS = 20


def run(
    body: Body,
    vx: np.ndarray,
    vy: np.ndarray,
    omega: np.ndarray,
    mu: np.ndarray,
    kappa: np.ndarray,
    phase: np.ndarray,
    **settings: Any,
) -> Stepped:
    """Bounce one free sphere per impact in one MuJoCo model and read the rebounds.

    Parameters
    ----------
    body : Body
        The body, with scalar mass (kg), radius (m) and gyration (m).
    vx, vy, omega : ndarray
        Flat incidence velocities (m/s, ``vy < 0``) and spins (rad/s), in the
        paper's axes, already validated.
    mu, kappa : ndarray
        Flat Coulomb friction coefficients and coefficients of restitution
        (in about ``[0.01, 0.99]`` for the calibrated contact).
    phase : ndarray
        Flat contact phases in ``[0, 1)``.
    **settings
        ``contact`` (``"calibrated"`` or ``"default"``), ``timestep`` (s), and
        for the calibrated contact ``contact_time`` (s) and ``friction_time``
        (a fraction of the contact time, or ``None``); see
        :func:`spinimpact.engines.bounce`.

    Returns
    -------
    Stepped
        The rebounds (flat), the steps taken, the wall time of the stepping (s)
        and every setting used; for the calibrated contact also its
        ``stiffness`` (1/s^2), each impact's ``damping`` (1/s) and the estimated
        ``penetration`` (a fraction of the radius).

    Raises
    ------
    TypeError
        For a setting of the wrong type.
    ValueError
        For an unknown setting, a setting out of range, a contact time shorter
        than 20 time steps, or a ``kappa`` the calibrated contact cannot reach.
    ImportError
        If MuJoCo is not installed.
    RuntimeError
        If a sphere has not left the floor after 20 contact times.
    """
    contact = choice("contact", settings.pop("contact", "calibrated"), ("calibrated", "default"))
    calibrated = contact == "calibrated"
    radius, mass, inertia = float(body.radius), float(body.mass), float(body.inertia)
    time_rule = "a finite time > 0 (s)"
    if not calibrated:
        for name in ("contact_time", "friction_time"):
            if name in settings:
                raise ValueError(f"{name} applies only to contact='calibrated', not 'default'")
        timestep = setting("timestep", settings.pop("timestep", 0.002), low=0.0, rule=time_rule)
        used: dict[str, Any] = {"contact": contact, "timestep": timestep}
    else:
        # By default the contact lasts long enough for about 100 steps but short
        # enough that the sphere sinks about 1 % of its radius: penetration is
        # about |vy| contact_time / pi for a linear spring.
        speed = float(np.max(np.abs(vy)))
        default_time = _PENETRATION * math.pi * radius / speed
        contact_time = setting(
            "contact_time", settings.pop("contact_time", default_time), low=0.0, rule=time_rule
        )
        timestep = setting(
            "timestep", settings.pop("timestep", contact_time / 100), low=0.0, rule=time_rule
        )
        friction_time = settings.pop("friction_time", 0.6)
        if friction_time is not None:
            friction_time = setting(
                "friction_time",
                friction_time,
                low=0.0,
                rule="None or a finite fraction of the contact time > 0",
            )
        if contact_time < _MIN_STEPS * timestep:
            raise ValueError(
                f"contact_time must span at least {_MIN_STEPS} time steps "
                f"({_MIN_STEPS * timestep:g} s), got {contact_time!r}"
            )
        used = {
            "contact": contact,
            "timestep": timestep,
            "contact_time": contact_time,
            "friction_time": friction_time,
            "penetration": speed * contact_time / math.pi / radius,
        }
    no_more("mujoco", settings)
    mj = require("mujoco", "engines.bounce('mujoco', ...)")
    opts = {
        "timestep": repr(timestep),
        "gravity": "0 0 0",
        "solver": "Newton",
        "iterations": 100,
        "tolerance": "1e-10",
    }
    if calibrated:
        opts.update(integrator="implicitfast", cone="elliptic" if friction_time else "pyramidal")
    scene = (opts, radius, mass, inertia, spacing(radius))
    heights = start_heights(radius, vy, phase, timestep)
    cap = LEAD_STEPS + 2 + int(20 * (contact_time if calibrated else 0.5) / timestep)
    if not calibrated:
        model = mj.MjModel.from_xml_string(_xml(*scene, heights, mu, None))
        return Stepped(*_step(mj, model, vx, vy, omega, cap), used)
    stiffness = (math.pi / contact_time) ** 2  # per unit mass: the contact's duration
    friction = f' solreffriction="{friction_time * contact_time!r} 1"' if friction_time else ""
    pairs = f'solref="{-stiffness!r} -1" solimp="0.99 0.99 0.001 0.5 2"{friction}'
    # Under the pyramidal cone friction enters even a head-on bounce: calibrate each
    # (kappa, mu) pair with its own mu.
    levels, which = np.unique(np.stack([kappa, mu], axis=1), axis=0, return_inverse=True)
    damping = _damping(mj, scene, pairs, levels[:, 0], levels[:, 1], cap)
    model = mj.MjModel.from_xml_string(_xml(*scene, heights, mu, pairs))
    model.pair_solref[:, 1] = -damping[which.ravel()]
    out = _step(mj, model, vx, vy, omega, cap)
    used["stiffness"] = stiffness
    # the calibrated damping of each impact's pair, 1/s (solref's second entry is -damping)
    used["damping"] = model.pair_solref[:, 1] * -1.0
    return Stepped(*out, used)


def _xml(opts, radius, mass, inertia, spacing, heights, mu, pairs) -> str:
    """MJCF of a floor and one free sphere per impact, side by side along y.

    With ``pairs`` (the ``solref``/``solimp`` attributes of a contact pair) each
    sphere touches the floor only through its own ``<pair>`` of friction ``mu``;
    without, through MuJoCo's default contact with the geom friction ``mu``.
    """
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


def _rotate(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotate the vectors ``v`` (n, 3) by the unit quaternions ``q`` (n, 4), w first."""
    w, u = q[:, :1], q[:, 1:]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def _step(mj, model, vx, vy, omega, max_steps):
    """Step ``model`` from the given incidence until every sphere has bounced clear.

    Returns ``(vx, vy, omega, steps, seconds)``: the rebounds in the paper's axes,
    the steps taken and the wall time of the stepping. The free joint's angular
    velocity is in the body frame: it is rotated to the world frame by the
    body's orientation before it is read.
    """
    data = mj.MjData(model)
    linear, angular = to_engine(vx, vy, omega)  # at the start the body frame is the world's
    data.qvel[:] = np.concatenate([linear, angular], axis=1).ravel()
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
    spin = _rotate(data.qpos.reshape(-1, 7)[:, 3:], qvel[:, 3:])
    return (*from_engine(qvel[:, :3], spin), steps, seconds)


def _damping(mj, scene, pairs, kappa, mu, cap):
    """Contact damping (1/s) for which a head-on MuJoCo bounce has restitution ``kappa``.

    Secant iterations on all the ``(kappa, mu)`` pairs at once, in one model of
    head-on bounces at the contact phase 0.5, starting from the damped linear
    oscillator's ``b = 2 xi sqrt(k)`` with ``kappa = exp(-pi xi / sqrt(1 -
    xi^2))``, until the restitution is within :data:`_KAPPA_TOLERANCE` of
    ``kappa`` (MuJoCo's solver leaves noise of a few 1e-6 in it with pyramidal
    friction cones).
    """
    if np.any(kappa <= 0) or np.any(kappa >= 1):
        bad = kappa[(kappa <= 0) | (kappa >= 1)][0]
        raise ValueError(
            f"kappa must be in (0, 1) for a calibrated MuJoCo contact (a spring-damper "
            f"reaches neither end), got {float(bad)!r}"
        )
    opts, radius = scene[0], scene[1]
    n = kappa.size
    vy = np.full(n, -1.0)
    heights = start_heights(radius, vy, np.full(n, 0.5), float(opts["timestep"]))
    model = mj.MjModel.from_xml_string(_xml(*scene, heights, mu, pairs))
    stiffness = -model.pair_solref[0, 0]
    log = np.log(kappa)
    guess = 2.0 * np.sqrt(stiffness) * -log / np.sqrt(math.pi**2 + log**2)

    def restitution(b):
        model.pair_solref[:, 1] = -b
        return _step(mj, model, np.zeros(n), vy, np.zeros(n), cap)[1]

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
