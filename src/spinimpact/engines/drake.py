r"""The bounce in Drake (the ``[engines]`` extra): free spheres in a discrete MultibodyPlant.

Drake [1]_ models contact as compliant: with point contact (``ContactModel.kPoint``)
each touching pair has a normal force of the Hunt & Crossley form [2]_

.. math:: f_n = k\,x\,(1 + d\,\dot x)_+ ,

penetration ``x``, its rate ``x_dot``, point stiffness ``k`` (N/m) and Hunt-Crossley
dissipation ``d`` (s/m), and regularized Coulomb friction ``mu`` ([3]_, "Contact
Modeling"). A discrete plant advances it by one convex or non-convex problem per time
step, the *discrete contact approximation*:

* ``"lagged"`` (``kLagged``, Drake's default and :func:`run`'s): convex, so its solver
  always converges; the normal force in Coulomb's law is the previous step's;
* ``"similar"`` (``kSimilar``): convex too, and named by Drake's documentation as the
  approximation for strong transients, but it makes a sliding contact "glide": the
  sphere leaves with extra normal velocity in proportion to its slip;
* ``"tamsi"`` (``kTamsi``): the original, non-convex solver, deprecated by Drake
  (removal on or after 2026-09-01);
* ``kSap`` is not offered: it models dissipation by a relaxation time, not by
  Hunt & Crossley's ``d``.

On the 144 standard cases at one contact phase (``docs/engines.md``), with 100 steps
per contact, the calibrated contact missed by at most 0.23 % of the speed scale with
``"lagged"``, 6.4 % with ``"similar"`` (its gliding: the normal rebound was too fast
on sliding bounces) and 0.31 % with ``"tamsi"``, which took 40 times longer to step.

A linear spring with Hunt & Crossley dissipation has a head-on restitution that
depends on ``d |vy|`` only (the equation of motion is unchanged when ``x`` and
``x_dot`` scale with ``|vy|`` and ``d`` with ``1/|vy|``). :func:`run`'s calibrated
contact therefore finds, for each ``kappa``, the product ``c = d |vy|`` by secant
iterations on head-on bounces at 1 m/s and contact phase 0.5 until the restitution is
``kappa`` to :data:`_KAPPA_TOLERANCE`, and gives each impact ``d = c / |vy|``. Even with
``d = 0`` the implicit time stepping loses energy (about 5 % of the rebound speed at
100 steps per contact), so ``kappa`` must lie below that undamped restitution.

References
----------
.. [1] R. Tedrake and the Drake Development Team, "Drake: Model-based design and
   verification for robotics", 2019, https://drake.mit.edu.
.. [2] K. H. Hunt and F. R. E. Crossley, "Coefficient of restitution interpreted as
   damping in vibroimpact", Journal of Applied Mechanics 42 (1975) 440-445.
.. [3] Drake documentation, ``MultibodyPlant``, "Contact Modeling" and
   ``DiscreteContactApproximation``, https://drake.mit.edu/doxygen_cxx/.
"""

from __future__ import annotations

import importlib
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
    whole_number,
)

__all__ = ["run"]

#: A calibrated contact's default depth of penetration, a fraction of the radius.
_PENETRATION = 0.01
#: How close a calibrated contact's head-on restitution is made to kappa.
_KAPPA_TOLERANCE = 1e-5
#: A contact time must span at least this many time steps.
_MIN_STEPS = 20
#: Drake's default time step of a discrete plant (``MultibodyPlantConfig``), s.
_DRAKE_TIME_STEP = 1e-3
#: The discrete contact approximations offered, by the names of :func:`run`.
_APPROXIMATIONS = ("lagged", "similar", "tamsi")


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
    """Bounce one free sphere per impact in Drake and read the rebounds.

    Parameters
    ----------
    body : Body
        The body, with scalar mass (kg), radius (m) and gyration (m).
    vx, vy, omega : ndarray
        Flat incidence velocities (m/s, ``vy < 0``) and spins (rad/s), in the
        paper's axes, already validated.
    mu, kappa : ndarray
        Flat Coulomb friction coefficients and coefficients of restitution
        (below the undamped restitution, about 0.95, for the calibrated contact).
    phase : ndarray
        Flat contact phases in ``[0, 1)``.
    **settings
        ``contact`` (``"calibrated"`` or ``"default"``), ``approximation``
        (``"lagged"``, ``"similar"`` or ``"tamsi"``), ``time_step`` (s),
        ``scene_size`` (spheres per plant, default 64) and, for the calibrated
        contact, ``contact_time`` (s); see :func:`spinimpact.engines.bounce`.

    Returns
    -------
    Stepped
        The rebounds (flat), the steps taken (summed over the scenes), the wall
        time of the stepping (s) and every setting used; for the calibrated
        contact also the contact's ``stiffness`` (N/m) and each impact's
        Hunt-Crossley ``dissipation`` (s/m).

    Raises
    ------
    TypeError
        For a setting of the wrong type.
    ValueError
        For an unknown setting, a setting out of range, a contact time shorter
        than 20 time steps, or a ``kappa`` the calibrated contact cannot reach.
    ImportError
        If Drake is not installed.
    RuntimeError
        If a sphere has not left the surface after 20 contact times.
    """
    contact = choice("contact", settings.pop("contact", "calibrated"), ("calibrated", "default"))
    calibrated = contact == "calibrated"
    approximation = choice(
        "approximation",
        settings.pop("approximation", "lagged"),
        _APPROXIMATIONS,
    )
    scene_size = whole_number("scene_size", settings.pop("scene_size", 64))
    radius, mass = float(body.radius), float(body.mass)
    time_rule = "a finite time > 0 (s)"
    used: dict[str, Any] = {"contact": contact, "approximation": approximation}
    if not calibrated:
        if "contact_time" in settings:
            raise ValueError("contact_time applies only to contact='calibrated', not 'default'")
        time_step = setting(
            "time_step", settings.pop("time_step", _DRAKE_TIME_STEP), low=0.0, rule=time_rule
        )
        contact_time = 0.5  # only bounds the steps: Drake's default contact sets its own
    else:
        # As MuJoCo's calibrated contact: the sphere sinks about 1 % of its radius
        # (about |vy| contact_time / pi for a linear spring), in about 100 steps.
        speed = float(np.max(np.abs(vy)))
        default_time = _PENETRATION * math.pi * radius / speed
        contact_time = setting(
            "contact_time", settings.pop("contact_time", default_time), low=0.0, rule=time_rule
        )
        time_step = setting(
            "time_step", settings.pop("time_step", contact_time / 100), low=0.0, rule=time_rule
        )
        if contact_time < _MIN_STEPS * time_step:
            raise ValueError(
                f"contact_time must span at least {_MIN_STEPS} time steps "
                f"({_MIN_STEPS * time_step:g} s), got {contact_time!r}"
            )
        used.update(contact_time=contact_time, penetration=speed * contact_time / math.pi / radius)
    used.update(time_step=time_step, scene_size=scene_size)
    no_more("drake", settings)
    if calibrated and (np.any(kappa <= 0) or np.any(kappa >= 1)):
        bad = kappa[(kappa <= 0) | (kappa >= 1)][0]
        raise ValueError(
            f"kappa must be in (0, 1) for a calibrated Drake contact (a Hunt-Crossley "
            f"contact reaches neither end), got {float(bad)!r}"
        )
    drake = _Drake()
    cap = LEAD_STEPS + 2 + int(20 * contact_time / time_step)
    scene = _Scene(drake, radius, mass, float(body.inertia), time_step, approximation, cap)
    dissipation = None
    if calibrated:
        stiffness = mass * (math.pi / contact_time) ** 2  # a linear spring's contact time
        scene.stiffness = stiffness
        levels, which = np.unique(kappa, return_inverse=True)
        product = _calibrate(scene, levels, contact_time)  # d |vy| for each kappa
        dissipation = product[which.ravel()] / np.abs(vy)
        used.update(stiffness=stiffness, dissipation=dissipation)
    parts, steps, seconds = [], 0, 0.0
    for lo in range(0, vx.size, scene_size):  # Drake's step cost grows faster than n
        part = slice(lo, lo + scene_size)
        d = None if dissipation is None else dissipation[part]
        out = scene.bounce(vx[part], vy[part], omega[part], mu[part], phase[part], d)
        parts.append(out[:3])
        steps, seconds = steps + out[3], seconds + out[4]
    rebound = (np.concatenate([p[i] for p in parts]) for i in range(3))
    return Stepped(*rebound, steps, seconds, used)


class _Drake:
    """The parts of pydrake :func:`run` uses, imported once (Drake takes about a second)."""

    def __init__(self):
        require("pydrake", "engines.bounce('drake', ...)")
        get = importlib.import_module
        plant, framework = get("pydrake.multibody.plant"), get("pydrake.systems.framework")
        geometry, tree = get("pydrake.geometry"), get("pydrake.multibody.tree")
        self.DiagramBuilder = framework.DiagramBuilder
        self.Simulator = get("pydrake.systems.analysis").Simulator
        self.add_plant = plant.AddMultibodyPlantSceneGraph
        self.approximations = plant.DiscreteContactApproximation
        self.point = plant.ContactModel.kPoint
        self.CoulombFriction = plant.CoulombFriction
        self.SpatialInertia, self.UnitInertia = tree.SpatialInertia, tree.UnitInertia
        self.Sphere, self.Box = geometry.Sphere, geometry.Box
        self.ProximityProperties = geometry.ProximityProperties
        self.add_material = geometry.AddContactMaterial
        self.RigidTransform = get("pydrake.math").RigidTransform
        self.SpatialVelocity = get("pydrake.multibody.math").SpatialVelocity

    def approximation(self, name: str):
        """Drake's ``DiscreteContactApproximation`` of :func:`run`'s ``name``.

        Raises
        ------
        ValueError
            If the installed Drake no longer has it (TAMSI is deprecated).
        """
        member = {"lagged": "kLagged", "similar": "kSimilar", "tamsi": "kTamsi"}[name]
        if not hasattr(self.approximations, member):
            raise ValueError(f"approximation {name!r} is not in the installed Drake")
        return getattr(self.approximations, member)


class _Scene:
    """One kind of Drake scene: spheres of one body, each over its own block of ground."""

    def __init__(self, drake, radius, mass, inertia, time_step, approximation, cap):
        self.drake, self.radius, self.mass, self.inertia = drake, radius, mass, inertia
        self.time_step, self.approximation, self.cap = time_step, approximation, cap
        self.stiffness: float | None = None  # None: Drake's default contact

    def _material(self, mu: float, dissipation: float | None):
        """Proximity properties of one side of a contact pair.

        Drake combines two geometries' point stiffnesses in series, their
        dissipations weighted by the other's stiffness, and their friction
        coefficients as ``2 mu1 mu2 / (mu1 + mu2)``: both sides get the same
        dissipation and friction and twice the pair's stiffness.
        """
        dr = self.drake
        props = dr.ProximityProperties()
        stiffness = None if self.stiffness is None else 2.0 * self.stiffness
        dr.add_material(
            properties=props,
            dissipation=dissipation,
            point_stiffness=stiffness,
            friction=dr.CoulombFriction(mu, mu),
        )
        return props

    def bounce(self, vx, vy, omega, mu, phase, dissipation):
        """Bounce one sphere per impact; ``(vx, vy, omega, steps, seconds)`` of the rebounds.

        Each sphere touches only its own ground block (a box whose top face is the
        plane ``z = 0``), whose friction and dissipation are the sphere's; the
        spheres stand ``spacing`` apart along y. The free bodies' generalized
        velocities are their angular and linear velocities in the world frame.
        """
        dr, n, radius = self.drake, vx.size, self.radius
        builder = dr.DiagramBuilder()
        plant, _ = dr.add_plant(builder, self.time_step)
        plant.set_contact_model(dr.point)
        plant.set_discrete_contact_approximation(dr.approximation(self.approximation))
        plant.mutable_gravity_field().set_gravity_vector([0.0, 0.0, 0.0])
        apart = spacing(radius)
        gyration2 = self.inertia / self.mass
        unit = dr.UnitInertia(gyration2, gyration2, gyration2)
        bodies = []
        for i in range(n):  # the engine's API creates bodies one by one
            d = None if dissipation is None else float(dissipation[i])
            ball = plant.AddRigidBody(f"ball{i}", dr.SpatialInertia(self.mass, np.zeros(3), unit))
            plant.RegisterCollisionGeometry(
                ball, dr.RigidTransform(), dr.Sphere(radius), f"ball{i}", self._material(mu[i], d)
            )
            plant.RegisterCollisionGeometry(
                plant.world_body(),
                dr.RigidTransform([0.0, apart * i, -0.5 * apart]),
                dr.Box(0.5 * apart, 0.5 * apart, apart),
                f"ground{i}",
                self._material(mu[i], d),
            )
            bodies.append(ball)
        plant.Finalize()
        simulator = dr.Simulator(builder.Build())
        context = plant.GetMyMutableContextFromRoot(simulator.get_mutable_context())
        heights = start_heights(radius, vy, phase, self.time_step)
        linear, angular = to_engine(vx, vy, omega)
        for i, ball in enumerate(bodies):
            plant.SetFreeBodyPose(context, ball, dr.RigidTransform([0.0, apart * i, heights[i]]))
            plant.SetFreeBodySpatialVelocity(
                context, ball, dr.SpatialVelocity(angular[i], linear[i])
            )
        simulator.Initialize()
        z = np.array([b.floating_positions_start() for b in bodies]) + 6  # after a quaternion
        v = np.array([b.floating_velocities_start_in_v() for b in bodies])
        steps, touched = 0, False
        start = time.perf_counter()
        while steps < self.cap:
            steps += 1
            simulator.AdvanceTo(steps * self.time_step)
            height = plant.GetPositions(context)[z]
            touched = touched or bool(np.any(height < radius))
            if touched and np.all(height > radius):
                if np.all(plant.GetVelocities(context)[v + 5] > 0):
                    break
        else:
            raise RuntimeError(
                f"Drake: not every sphere had left the surface after {self.cap} steps"
            )
        seconds = time.perf_counter() - start
        velocity = plant.GetVelocities(context)
        spin, centre = velocity[v[:, None] + np.arange(3)], velocity[v[:, None] + np.arange(3, 6)]
        return (*from_engine(centre, spin), steps, seconds)


def _calibrate(scene: _Scene, kappa: np.ndarray, contact_time: float) -> np.ndarray:
    """``c = d |vy|`` (m/s times s/m) for which a head-on bounce has restitution ``kappa``.

    Secant iterations on all ``kappa`` at once, in one scene of head-on, frictionless
    bounces at 1 m/s and contact phase 0.5, from the small-dissipation estimate
    ``1 - kappa^2 = 4 c / 3`` of a linear spring (the energy ``k d x x_dot^2``
    dissipated over a half period); Drake's solver tolerance leaves noise of about
    1e-7 in the restitution.
    """
    n = kappa.size
    zero, speed, middle = np.zeros(n), np.full(n, -1.0), np.full(n, 0.5)

    def restitution(c):
        try:
            return scene.bounce(zero, speed, zero, zero, middle, c)[1]
        except RuntimeError:  # so much dissipation that a sphere stays on the surface
            raise ValueError(
                f"kappa = {float(np.min(kappa))!r} cannot be reached by the calibrated Drake "
                f"contact (with the dissipation it needs, the sphere stays on the surface); "
                f"kappa >= 0.01 can"
            ) from None

    undamped = restitution(zero)
    if np.any(kappa >= undamped - _KAPPA_TOLERANCE):
        per_contact = contact_time / scene.time_step
        raise ValueError(
            f"kappa must be below {float(undamped[0]):.4g} for a calibrated Drake contact "
            f"of {per_contact:.3g} time steps: without dissipation its bounce already has "
            f"that restitution (a smaller time_step raises it); got {float(np.max(kappa))!r}"
        )
    c0 = 0.75 * (1.0 - kappa**2)
    c1 = 1.05 * c0
    k0, k1 = restitution(c0), restitution(c1)
    for _ in range(30):
        if np.all(np.abs(k1 - kappa) <= _KAPPA_TOLERANCE):
            return c1
        step = np.where(k1 != k0, (k1 - kappa) * (c1 - c0) / (k1 - k0), 0.0)
        c0, k0 = c1, k1
        c1 = np.clip(c1 - step, 0.5 * c1, 2.0 * c1)  # dissipation stays positive
        k1 = restitution(c1)
    bad = kappa[np.abs(k1 - kappa) > _KAPPA_TOLERANCE][0]
    raise ValueError(
        f"kappa = {float(bad)!r} cannot be reached by the calibrated Drake contact "
        f"(its dissipation calibration did not converge)"
    )
