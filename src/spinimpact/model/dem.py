r"""A contact force for DEM loops, and the small DEM loop that runs it.

:class:`ContactForce` holds one contact's law (Hertz's normal force with a damping of
choice; the Mindlin-Deresiewicz tangential force with its loading history, or one of the
usual DEM variants) and produces the two arrays a compiled loop needs: the parameters
(:meth:`ContactForce.parameters`) and a fresh state per contact
(:meth:`ContactForce.new_state`). Inside ``numba.njit`` code, call
:func:`spinimpact.dem.contact_force` with them once per contact per step; the physics is
:mod:`spinimpact.core.dem_force` (its docstring gives the equations).

:func:`wall_impact` and :func:`pair_impact` step a sphere on a wall, and two spheres, with
that force (the loop of :mod:`spinimpact.core.dem_loop`) and return a :class:`DemImpact`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .._validation import scalar, whole
from ..core import dem_force as kernels
from ..core import dem_law, dem_loop
from .body import Body
from .result import Result, freeze

__all__ = ["MODELS", "DAMPINGS", "ContactForce", "DemImpact", "wall_impact", "pair_impact",
           "viscous_damping", "log_decrement_damping"]  # fmt: skip

#: The tangential models, by name (:mod:`spinimpact.core.dem_force`).
MODELS = {"micro-slip": kernels.MICRO_SLIP, "history": kernels.HISTORY,
          "incremental": kernels.INCREMENTAL, "scaled": kernels.SCALED,
          "total": kernels.TOTAL}  # fmt: skip
#: The normal dampings, by name.
DAMPINGS = {"none": kernels.NO_DAMPING, "hunt-crossley": kernels.HUNT_CROSSLEY,
            "viscous": kernels.VISCOUS}  # fmt: skip
#: What the friction limit multiplies ``mu`` by.
LIMITS = ("elastic", "total")
#: The most cells a contact's history may keep (its state: 25 MB).
MAX_CELLS = 1 << 20


def log_decrement_damping(restitution):
    r"""``beta = -ln e / sqrt(ln^2 e + pi^2)``: the viscous damping ratio the DEM codes
    derive from the restitution ``e`` (exact for a linear spring; for Hertz's spring it
    gives a different restitution, :func:`viscous_damping` gives the exact one).

    Examples
    --------
    >>> round(log_decrement_damping(0.5), 4)
    0.2155
    """
    e = scalar("restitution", restitution)
    if not 0.0 < e <= 1.0:
        raise ValueError(f"restitution must be in (0, 1], got {restitution!r}")
    return -math.log(e) / math.hypot(math.log(e), math.pi)


def _viscous_restitution(beta):
    """The restitution of Hertz's spring with the viscous damping ``beta`` (speed-free):
    ``x'' = -(x^{3/2} + 2 sqrt(5/6) beta sqrt(3/2) x^{1/4} x')``, ``x(0) = 0``,
    ``x'(0) = 1``, the force never attractive; returns ``-x'`` where ``x`` returns to 0."""
    from scipy.integrate import solve_ivp

    c = kernels.VISCOUS_FACTOR * beta * math.sqrt(1.5)

    def rhs(_t, y):
        x = max(y[0], 0.0)
        return [y[1], -max(x**1.5 + c * x**0.25 * y[1], 0.0)]

    def back(_t, y):
        return y[0]

    back.terminal, back.direction = True, -1
    run = solve_ivp(rhs, (0.0, 100.0), [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=back, first_step=1e-6)  # fmt: skip
    return -float(run.y_events[0][0][1])


def viscous_damping(restitution):
    r"""The viscous damping ratio ``beta`` with which Hertz's spring rebounds with
    Newton's restitution ``e`` exactly (the damping force
    ``2 sqrt(5/6) beta sqrt(S_n m^*) delta'``, ``S_n = 2 E^* sqrt(R delta)``).

    The restitution of this damping does not depend on the speed (the force scales as
    Hertz's does), so ``beta`` depends on ``e`` alone; it is found by integrating the
    normal impact (DOP853, ``rtol = 1e-12``) and solving for ``e``. The DEM codes' formula,
    :func:`log_decrement_damping`, is exact for a linear spring only.

    Examples
    --------
    >>> round(viscous_damping(0.5), 4), round(log_decrement_damping(0.5), 4)
    (0.2553, 0.2155)
    """
    e = scalar("restitution", restitution)
    if not 0.0 < e <= 1.0:
        raise ValueError(f"restitution must be in (0, 1], got {restitution!r}")
    return _viscous_beta(e)


@functools.lru_cache(maxsize=256)
def _viscous_beta(e):
    """:func:`viscous_damping` of a checked float (cached)."""
    from scipy.optimize import brentq

    if e == 1.0:
        return 0.0
    hi = 0.5
    while _viscous_restitution(hi) > e:
        hi *= 2.0
        if hi > 1e6:
            raise ValueError(f"restitution = {e!r} is below what this damping reaches")
    return float(brentq(lambda b: _viscous_restitution(b) - e, 0.0, hi, xtol=1e-14,
                        rtol=1e-12))  # fmt: skip


def _positive(name, value):
    x = scalar(name, value)
    if not (x > 0.0 and math.isfinite(x)):
        raise ValueError(f"{name} must be a positive finite number, got {value!r}")
    return x


def _finite(name, value):
    x = scalar(name, value)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def _two(name, value):
    """Two finite numbers (a tangential vector's components)."""
    try:
        a, b = value
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be two numbers (its tangential components), "
                        f"got {value!r}") from None  # fmt: skip
    return _finite(f"{name}[0]", a), _finite(f"{name}[1]", b)


def _resolved(dt, duration, speed):
    """``dt`` checked against the contact's duration at the normal ``speed``: at least ten
    steps a contact (fewer cannot resolve it: the rebound comes out wrong by any amount)."""
    if dt > duration / 10.0:
        raise ValueError(f"dt = {dt!r} s is more than a tenth of the contact's duration "
                         f"({duration:.3g} s at {speed:.3g} m/s): take at least 10 steps a "
                         "contact")  # fmt: skip
    return dt


def _choice(name, value, options):
    if not isinstance(value, str):
        raise TypeError(f"{name} must be one of {', '.join(map(repr, options))}, got {value!r}")
    if value not in options:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, options))}, "
                         f"got {value!r}")  # fmt: skip
    return value


def _moduli(youngs_modulus, poisson_ratio, wall_youngs_modulus, wall_poisson_ratio):
    """``(E*, G*)`` of two elastic bodies (the second rigid where its modulus is ``None``):
    ``1/E* = sum (1 - nu^2)/E``, ``1/G* = sum (2 - nu)/G`` (Mindlin: ``k_t = 8 G* a``)."""
    e, nu = _positive("youngs_modulus", youngs_modulus), scalar("poisson_ratio", poisson_ratio)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"poisson_ratio must be in (-1, 0.5), got {poisson_ratio!r}")
    compliance = (1.0 - nu * nu) / e
    shear = (2.0 - nu) * 2.0 * (1.0 + nu) / e
    if wall_youngs_modulus is not None:
        e2 = _positive("wall_youngs_modulus", wall_youngs_modulus)
        nu2 = scalar("wall_poisson_ratio", wall_poisson_ratio)
        if not -1.0 < nu2 < 0.5:
            raise ValueError(f"wall_poisson_ratio must be in (-1, 0.5), "
                             f"got {wall_poisson_ratio!r}")  # fmt: skip
        compliance += (1.0 - nu2 * nu2) / e2
        shear += (2.0 - nu2) * 2.0 * (1.0 + nu2) / e2
    return 1.0 / compliance, 1.0 / shear


@dataclass(frozen=True)
class ContactForce:
    r"""One contact's force law for a DEM loop.

    Parameters
    ----------
    modulus : float
        Effective Young's modulus ``E^*`` (Pa): ``N_el = 4/3 E^* sqrt(R) delta^{3/2}``.
    shear_modulus : float
        Effective shear modulus ``G^*`` (Pa): Mindlin's stiffness ``k_t = 8 G^* a``.
    radius : float
        Effective radius ``R`` (m).
    mass : float
        Effective mass ``m^*`` (kg), for the viscous dampings.
    mu : float
        Coulomb friction coefficient.
    model : {"micro-slip", "history", "incremental", "scaled", "total"}
        The tangential force (:mod:`spinimpact.core.dem_force`): Mindlin-Deresiewicz
        micro-slip with the loading history (default), the history spring (no micro-slip),
        and three usual DEM springs.
    damping : {"none", "hunt-crossley", "viscous"}
        The normal damping.
    damping_coefficient : float
        Hunt-Crossley's ``a`` (s/m) or the viscous ``beta``; ``0`` with no damping.
    tangential_damping : float
        ``beta_t`` of the tangential viscous damping (``0``: none).
    friction_limit : {"total", "elastic"}
        ``mu`` times the whole normal force, damping included (default: as the
        impulse-space micro-slip law, :func:`spinimpact.core.mdr.mdr_slip`, LIGGGHTS and
        Kratos take it), or ``mu`` times its elastic part.
    damping_capped : bool
        Whether the friction limit bounds the spring's and the damper's force together
        (otherwise the damper's force is added beyond it).
    cells : int
        Cells that keep the loading history (micro-slip and history models; at least 2):
        more than the steps of a loading keeps it whole.

    Examples
    --------
    >>> force = ContactForce.sphere_on_wall(youngs_modulus=7.0e10, poisson_ratio=0.33,
    ...                                     radius=0.1, density=2700.0, mu=0.4)
    >>> state = force.new_state()
    >>> n, f1, f2 = force.step(state, overlap=1e-6, overlap_rate=0.2, displacement=(1e-7, 0.0))
    >>> round(n, 3), round(f1, 4)
    (33.122, -2.6577)
    """

    modulus: float
    shear_modulus: float
    radius: float
    mass: float
    mu: float
    model: str = "micro-slip"
    damping: str = "none"
    damping_coefficient: float = 0.0
    tangential_damping: float = 0.0
    friction_limit: str = "total"
    damping_capped: bool = True
    cells: int = 128

    def __post_init__(self):
        for name in ("modulus", "shear_modulus", "radius", "mass"):
            _positive(name, getattr(self, name))
        mu = scalar("mu", self.mu)
        if not (mu >= 0.0 and math.isfinite(mu)):
            raise ValueError(f"mu must be a finite number >= 0, got {self.mu!r}")
        _choice("model", self.model, tuple(MODELS))
        _choice("damping", self.damping, tuple(DAMPINGS))
        _choice("friction_limit", self.friction_limit, LIMITS)
        for name in ("damping_coefficient", "tangential_damping"):
            x = scalar(name, getattr(self, name))
            if not (x >= 0.0 and math.isfinite(x)):
                raise ValueError(f"{name} must be a finite number >= 0, "
                                 f"got {getattr(self, name)!r}")  # fmt: skip
        if self.damping == "none" and self.damping_coefficient != 0.0:
            raise ValueError(f"damping_coefficient must be 0 with damping='none', "
                             f"got {self.damping_coefficient!r}")  # fmt: skip
        if not isinstance(self.damping_capped, bool):
            raise TypeError(f"damping_capped must be True or False, got {self.damping_capped!r}")
        if whole("cells", self.cells, 2) > MAX_CELLS:
            raise ValueError(f"cells must be at most {MAX_CELLS}, got {self.cells!r}")

    @classmethod
    def sphere_on_wall(cls, *, youngs_modulus, poisson_ratio, radius, mu, density=None,
                       mass=None, wall_youngs_modulus=None, wall_poisson_ratio=None,
                       restitution=1.0, damping="viscous", speed=None, **options):  # fmt: skip
        r"""The force of a sphere on a wall (rigid unless ``wall_youngs_modulus`` is given).

        ``restitution < 1`` sets the normal damping: ``"viscous"`` (default) with the
        exact ``beta`` of :func:`viscous_damping`, or ``"hunt-crossley"`` calibrated at
        the normal impact ``speed`` (m/s; required then). Give ``density`` (kg/m^3) or
        ``mass`` (kg). ``options``: the other fields of :class:`ContactForce`.
        """
        r = _positive("radius", radius)
        if (density is None) == (mass is None):
            raise ValueError("give exactly one of density and mass")
        m = (_positive("mass", mass) if mass is not None
             else 4.0 / 3.0 * math.pi * r**3 * _positive("density", density))  # fmt: skip
        e_star, g_star = _moduli(youngs_modulus, poisson_ratio, wall_youngs_modulus,
                                 wall_poisson_ratio)  # fmt: skip
        kind, coefficient = _damping_for(restitution, damping, speed)
        return cls(e_star, g_star, r, m, mu, damping=kind, damping_coefficient=coefficient,
                   **options)  # fmt: skip

    @classmethod
    def two_spheres(cls, *, youngs_modulus, poisson_ratio, radius, mu, density,
                    other_radius=None, restitution=1.0, damping="viscous", speed=None,
                    **options):  # fmt: skip
        r"""The force between two spheres of one material (``other_radius``: the second
        sphere's, default the same): ``R = R_1 R_2/(R_1 + R_2)``,
        ``m^* = m_1 m_2/(m_1 + m_2)``. ``speed``: the approach speed (Hunt-Crossley)."""
        r1 = _positive("radius", radius)
        r2 = r1 if other_radius is None else _positive("other_radius", other_radius)
        rho = _positive("density", density)
        m1, m2 = (4.0 / 3.0 * math.pi * x**3 * rho for x in (r1, r2))
        e_star, g_star = _moduli(youngs_modulus, poisson_ratio, youngs_modulus, poisson_ratio)
        kind, coefficient = _damping_for(restitution, damping, speed)
        return cls(e_star, g_star, r1 * r2 / (r1 + r2), m1 * m2 / (m1 + m2), mu, damping=kind,
                   damping_coefficient=coefficient, **options)  # fmt: skip

    def parameters(self) -> np.ndarray:
        """The parameter array of :func:`spinimpact.dem.contact_force`."""
        return kernels.parameters(
            self.modulus, self.shear_modulus, self.radius, self.mass, self.mu,
            MODELS[self.model], DAMPINGS[self.damping], self.damping_coefficient,
            self.tangential_damping, float(self.friction_limit == "total"),
            float(self.damping_capped), self.cells,
        )  # fmt: skip

    def new_state(self) -> np.ndarray:
        """A fresh contact state (zeros), to keep per contact."""
        return kernels.new_state(self.cells)

    def step(self, state, overlap, overlap_rate, displacement, velocity=(0.0, 0.0)):
        """One step from Python: ``(N, F1, F2)`` (N), ``state`` updated in place.

        ``overlap`` (m) and its rate (m/s, positive while closing), ``displacement``: the
        contact point's tangential displacement over the step (m, two components),
        ``velocity``: its tangential velocity (m/s, for the tangential damping).
        """
        if not (isinstance(state, np.ndarray) and state.dtype == np.float64
                and state.ndim == 1):  # fmt: skip
            raise TypeError(f"state must be a 1-D float64 array (new_state()), got {state!r}")
        size = kernels.state_size(self.cells)
        if state.size != size:
            raise ValueError(f"state must hold {size} floats for cells = {self.cells}, got "
                             f"{state.size} (use new_state())")  # fmt: skip
        d1, d2 = _two("displacement", displacement)
        u1, u2 = _two("velocity", velocity)
        out = kernels.contact_force(state, self.parameters(), _finite("overlap", overlap),
                                    _finite("overlap_rate", overlap_rate), d1, d2, u1,
                                    u2)  # fmt: skip
        return tuple(float(x) for x in out)

    def time_scale(self, speed):
        """Hertz's contact duration at the normal ``speed`` (m/s), undamped (s)."""
        from ..core.contact import hertz_duration

        k = 4.0 / 3.0 * self.modulus * math.sqrt(self.radius)
        return float(hertz_duration(self.mass, _positive("speed", speed), k))


def _damping_for(restitution, damping, speed):
    if speed is not None:
        _positive("speed", speed)
    e = scalar("restitution", restitution)
    if not 0.0 < e <= 1.0:
        raise ValueError(f"restitution must be in (0, 1], got {restitution!r}")
    _choice("damping", damping, tuple(DAMPINGS))
    if damping == "none" and e != 1.0:
        raise ValueError(f"restitution must be 1 with damping='none', got {restitution!r}")
    if e == 1.0:
        return "none", 0.0
    if damping == "viscous":
        return "viscous", viscous_damping(e)
    from ..core.mdr import hunt_crossley_damping

    if speed is None:
        raise ValueError("speed (the normal impact speed, m/s) is needed to calibrate "
                         "damping='hunt-crossley' to a restitution")  # fmt: skip
    return "hunt-crossley", hunt_crossley_damping(e) / _positive("speed", speed)


@dataclass(frozen=True, repr=False)
class DemImpact(Result):
    """One impact stepped by the DEM loop.

    Attributes
    ----------
    vx, vy, omega : float
        The velocities after the contact (m/s, m/s, rad/s); for two spheres, arrays of the
        two spheres' values.
    steps : int
        Steps the contact took.
    contact_duration : float
        s.
    dt : float
        The step, s.
    trace : ndarray
        One row per step (when asked for): the columns of :data:`TRACE_COLUMNS`.
    """

    vx: object
    vy: object
    omega: object
    steps: object
    contact_duration: object
    dt: object
    trace: object


#: The columns of a trace (``DemImpact.trace``): time, overlap, forces, slip and energies.
TRACE_COLUMNS = dem_loop.TRACE_COLUMNS


def _trace(record, steps):
    if not isinstance(record, bool):
        raise TypeError(f"trace must be True or False, got {record!r}")
    return np.zeros((steps if record else 0, len(TRACE_COLUMNS)))


def wall_impact(force, body, vx, vy, omega, *, dt, max_steps=10_000_000, trace=False):
    r"""A sphere striking a wall, stepped with ``force`` at the step ``dt`` (s).

    Parameters
    ----------
    force : ContactForce
        The contact's law (its ``radius`` and ``mass`` are the body's).
    body : Body
        The sphere: its mass, radius and ``zeta`` (the inertia ``m R^2/(zeta - 1)``).
    vx, vy, omega : float
        The incidence (m/s, m/s with ``vy < 0``, rad/s counter-clockwise); the sphere
        touches the wall at ``t = 0``.
    dt : float
        The step, s.
    trace : bool
        Keep one row per step (:data:`TRACE_COLUMNS`).

    Returns
    -------
    DemImpact

    Examples
    --------
    >>> from spinimpact import Body
    >>> force = ContactForce.sphere_on_wall(youngs_modulus=7.0e10, poisson_ratio=0.33,
    ...                                     radius=0.1, density=2700.0, mu=0.4)
    >>> ball = Body.solid_sphere(mass=force.mass, radius=0.1)
    >>> run = wall_impact(force, ball, 0.0, -0.2, 2.0, dt=force.time_scale(0.2) / 400)
    >>> round(float(run.vy), 4), int(run.steps)
    (0.2, 400)
    """
    if not isinstance(force, ContactForce):
        raise TypeError(f"force must be a ContactForce, got {type(force).__name__}")
    if not isinstance(body, Body):
        raise TypeError(f"body must be a Body, got {type(body).__name__}")
    m, r, zeta = float(body.mass), float(body.radius), float(body.zeta)
    if not (math.isclose(m, force.mass, rel_tol=1e-9) and math.isclose(r, force.radius,
                                                                     rel_tol=1e-9)):  # fmt: skip
        raise ValueError(
            f"body must be the force's sphere: its mass {m!r} kg and radius {r!r} m differ "
            f"from the force's {force.mass!r} kg and {force.radius!r} m "
            "(ContactForce.sphere_on_wall gives both)"
        )
    step = _positive("dt", dt)
    steps = whole("max_steps", max_steps, 1)
    v_x, v_y, w = scalar("vx", vx), scalar("vy", vy), scalar("omega", omega)
    if not v_y < 0.0:
        raise ValueError(f"vy must be negative (towards the wall), got {vy!r}")
    _resolved(step, force.time_scale(-v_y), -v_y)
    rows = _trace(trace, min(steps, 1 << 22))
    out = dem_law.wall_impact(force.parameters(), force.new_state(), m, r,
                              m * r * r / (zeta - 1.0), v_x, v_y, w, step, steps, rows)  # fmt: skip
    ux, uy, uw, count, duration = out
    if count < 0:
        raise RuntimeError(f"the contact was still closed after max_steps = {steps} steps")
    return DemImpact(freeze(ux), freeze(uy), freeze(uw), freeze(count), freeze(duration),
                     freeze(step), freeze(rows[:count]))  # fmt: skip


def pair_impact(force, bodies, velocities, *, dt, max_steps=10_000_000, trace=False):
    r"""Two spheres in plane motion, stepped with ``force`` at ``dt`` (s).

    ``bodies``: the two spheres (:class:`Body`; sphere 2 sits above sphere 1, touching, at
    ``t = 0``); ``velocities``: ``((vx_1, vy_1, omega_1), (vx_2, vy_2, omega_2))``, closing
    (``vy_2 < vy_1``). Returns a :class:`DemImpact` whose ``vx``, ``vy`` and ``omega`` hold
    both spheres' values.
    """
    if not isinstance(force, ContactForce):
        raise TypeError(f"force must be a ContactForce, got {type(force).__name__}")
    if not (isinstance(bodies, (tuple, list)) and len(bodies) == 2):
        raise TypeError(f"bodies must be two Body objects, got {bodies!r}")
    for name, b in (("bodies[0]", bodies[0]), ("bodies[1]", bodies[1])):
        if not isinstance(b, Body):
            raise TypeError(f"{name} must be a Body, got {type(b).__name__}")
    shape = np.shape(velocities) if isinstance(velocities, (tuple, list, np.ndarray)) else ()
    if shape != (2, 3):
        raise TypeError(f"velocities must be ((vx_1, vy_1, omega_1), (vx_2, vy_2, omega_2)), "
                        f"got {velocities!r}")  # fmt: skip
    v = np.array([scalar(f"velocities[{i}][{j}]", velocities[i][j])
                  for i in range(2) for j in range(3)])  # fmt: skip
    if not v[4] < v[1]:
        raise ValueError(f"the spheres must close: vy of sphere 2 ({float(v[4])!r}) must be "
                         f"below vy of sphere 1 ({float(v[1])!r})")  # fmt: skip
    data = []
    for b in bodies:
        m, r, z = float(b.mass), float(b.radius), float(b.zeta)
        data += [m, r, m * r * r / (z - 1.0)]
    m_star = data[0] * data[3] / (data[0] + data[3])
    r_star = data[1] * data[4] / (data[1] + data[4])
    if not (math.isclose(m_star, force.mass, rel_tol=1e-9)
            and math.isclose(r_star, force.radius, rel_tol=1e-9)):  # fmt: skip
        raise ValueError(
            f"bodies must be the force's spheres: their reduced mass {m_star!r} kg and radius "
            f"{r_star!r} m differ from the force's {force.mass!r} kg and {force.radius!r} m "
            "(ContactForce.two_spheres gives both)"
        )
    step = _positive("dt", dt)
    _resolved(step, force.time_scale(float(v[1] - v[4])), float(v[1] - v[4]))
    steps = whole("max_steps", max_steps, 1)
    rows = _trace(trace, min(steps, 1 << 22))
    count, duration = dem_law.pair_impact(force.parameters(), force.new_state(),
                                          np.array(data), v, step, steps, rows)  # fmt: skip
    if count < 0:
        raise RuntimeError(f"the contact was still closed after max_steps = {steps} steps")
    return DemImpact(freeze(v[[0, 3]]), freeze(v[[1, 4]]), freeze(v[[2, 5]]), freeze(count),
                     freeze(duration), freeze(step), freeze(rows[:count]))  # fmt: skip
