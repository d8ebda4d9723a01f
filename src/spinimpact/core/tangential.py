r"""Tangential compliance in time: a Mindlin spring with Coulomb slip at the contact.

:func:`integrate_tangential` integrates one impact of a body on a plane (centre
velocity ``(v_x, v_y)``, spin ``omega``) whose contact is compliant in both
directions: the normal force is a power-law spring with Hunt-Crossley and/or
viscous damping (the laws of :mod:`spinimpact.core.contact`),

.. math:: N = \max\left(k \delta^n (1 + a \dot\delta) + c \dot\delta,\ 0\right),

and the tangential force ``F`` is carried by a spring whose stiffness follows the
elastic normal stiffness, ``k_t = r\, n k \delta^{n-1}``, with Coulomb's cap
``|F| <= mu N``. For Hertz's law (``n = 3/2``, ``k = 4/3 E^* sqrt(R)``) and
``r = 4 G^*/E^*`` this is Mindlin's no-slip stiffness ``k_t = 8 G^* a`` with
``a = sqrt(R delta)`` (Mindlin 1949; Johnson 1985, sec. 7.2); for a sphere of one
material on a rigid plane, or on a plane of the same material,
``r = 2(1 - nu)/(2 - nu)``.

The variant ("no-slip Mindlin, incremental, scaled on unloading")
-----------------------------------------------------------------
While the contact sticks the spring is loaded incrementally,
``dF/dt = -k_t u`` (``u = v_x + R omega``, the velocity of the body's contact
point), as DEM codes integrate the "Hertz-Mindlin no-slip" model (Di Renzo and
Di Maio 2004); while the contact area shrinks (``dk_t/dt < 0``) the force is
also scaled down with the stiffness, ``dF/dt = -k_t u + F (dk_t/dt)/k_t`` (the
spring keeps its displacement and loses stiffness). This is the default,
``spring="scaled"``, chosen because with it the quantity

.. math:: E = T + U_n(\delta) + \frac{F^2}{2 k_t},

(``T`` the kinetic energy, ``U_n = k delta^{n+1}/(n+1)`` the normal spring's
energy) never increases: ``dE/dt = -F^2 |dk_t/dt|/(2 k_t^2)`` while sticking,
less than that while slipping, minus the normal damping's power. The two other
rules DEM codes use are available for comparison: ``"incremental"`` (no
scaling) gives ``dE/dt = +F^2 |dk_t/dt|/(2 k_t^2)`` while unloading in stick,
``"total"`` (``F = -k_t xi``, the displacement times the current stiffness)
gives ``dE/dt = +F^2 dk_t/dt/(2 k_t^2)`` while loading; either can return more
energy than the spring stored. With a linear normal spring (``n = 1``) the
stiffness is constant and the four rules coincide: the lumped two-spring model of
Stronge (2000), conservative while sticking.

The fourth rule, ``"history"``, is the exact elastic solution of a contact that sticks
while its area grows and then shrinks (Mindlin & Deresiewicz 1953): the traction field is
a superposition of flat-punch increments, one per contact radius, and while the area
shrinks only the force beyond the loading history's at the same compression unloads with
the stiffness,

.. math:: \frac{dF}{dt} = -k_t u + \left(F - F_\mathrm{mem}(\delta)\right)
   \frac{\min(\dot k_t, 0)}{k_t},

with ``F_mem(delta)`` the force at the same compression while loading, stuck or sliding
(equivalently ``F = F_mem + k_t (xi - xi_mem)``; :mod:`spinimpact.core.spring_history`).
While the contact slides after the end of compression, the part beyond the history
(``F - F_mem``) is the part that slips. The springs' energy is that of the traction field,
``U_mem + F_mem D + k_t D^2/2`` with ``D = (F - F_mem)/k_t`` and ``U_mem`` the integral of
``F dF/k_t`` along the loading; it falls by ``|dk_t/dt| D^2/2`` while the contact shrinks,
plus the slip's ``mu N |w|``, so ``E`` never increases (measured: by at most ``2e-10`` of
itself on 150 random impacts). It is the no-micro-slip limit of
:mod:`spinimpact.core.mdr` (which adds Coulomb's law at every point of the contact) and
agrees with it as ``mu`` grows (``tests/core/test_mdr.py``).

While the contact slips, ``F = sigma mu N`` (``sigma = +-1``); slip ends when the
force the spring would take in stick no longer exceeds the cap, i.e. when the
interface slip velocity ``w = u - d xi/dt`` (``xi`` the spring's displacement)
reaches zero. Both switches are events of :func:`spinimpact.core.events.integrate_events`,
watched inside every step, not only at its ends (a stuck spring's force can touch
the cap for a small part of a step and fall back, a slip phase that comparing signs
at step ends misses), with steps of at most an eighth of the normal and, while
sticking, the tangential oscillation period at the stiffest point, and located to
the integrator's precision; the event functions are written without divisions by
``delta`` so that they stay finite at first touch and at separation.

References
----------
.. [1] R. D. Mindlin, "Compliance of elastic bodies in contact", Journal of
   Applied Mechanics 16 (1949) 259-268.
.. [2] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985).
.. [3] A. Di Renzo, F. P. Di Maio, "Comparison of contact-force models for the
   simulation of collisions in DEM-based granular flow codes", Chemical
   Engineering Science 59 (2004) 525-541.
.. [4] W. J. Stronge, *Impact Mechanics*, Cambridge University Press (2000).
.. [5] R. D. Mindlin, H. Deresiewicz, "Elastic spheres in contact under varying oblique
   forces", Journal of Applied Mechanics 20 (1953) 327-344.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .compliance import mindlin_stiffness_ratio as one_material_ratio
from .events import Event, integrate_events
from .spring_history import loading_history
from .tangential_run import TangentialRun, sampled

__all__ = ["SPRINGS", "TangentialRun", "integrate_tangential", "mindlin_stiffness_ratio"]

#: The rules a stuck spring may follow when its stiffness changes (:func:`integrate_tangential`).
SPRINGS = ("scaled", "incremental", "total", "history")

#: Most stick/slip switches one impact may take before the run is refused.
MAX_SEGMENTS = 20000


def mindlin_stiffness_ratio(poisson_ratio, poisson_ratio_plane=None, youngs_ratio=None):
    r"""Ratio ``r = k_t/k_n`` of Mindlin's no-slip tangential stiffness to the
    Hertz normal contact stiffness, ``8 G^* a / (2 E^* a) = 4 G^*/E^*``.

    Parameters
    ----------
    poisson_ratio : array_like
        ``nu`` of the body.
    poisson_ratio_plane : array_like, optional
        ``nu`` of the plane; ``None``: a rigid plane (or, the same thing for this
        ratio, a plane of the body's own material).
    youngs_ratio : array_like, optional
        ``E_body/E_plane`` when ``poisson_ratio_plane`` is given (``0``: rigid plane).

    Notes
    -----
    .. math::

        \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}, \qquad
        \frac{1}{G^*} = \frac{2-\nu_1}{G_1} + \frac{2-\nu_2}{G_2}, \qquad
        G_i = \frac{E_i}{2(1+\nu_i)}

    (Johnson 1985, sec. 7.2). One material, or a rigid plane:
    ``r = 2(1-nu)/(2-nu)``.

    Examples
    --------
    >>> round(float(mindlin_stiffness_ratio(0.23)), 6)
    0.870056
    >>> round(float(mindlin_stiffness_ratio(0.23, 0.23, 1.0)), 6)
    0.870056
    """
    nu1 = np.asarray(poisson_ratio, dtype=float)
    if poisson_ratio_plane is None:
        return one_material_ratio(nu1)
    nu2 = np.asarray(poisson_ratio_plane, dtype=float)
    ratio = np.asarray(youngs_ratio, dtype=float)  # E1/E2; compliances in units of 1/E1
    e_c = (1.0 - nu1**2) + (1.0 - nu2**2) * ratio
    g_c = 2.0 * (2.0 - nu1) * (1.0 + nu1) + 2.0 * (2.0 - nu2) * (1.0 + nu2) * ratio
    return 4.0 * e_c / g_c


def integrate_tangential(
    mass: float, radius: float, inertia: float, mu: float, vx: float, vy: float, omega: float,
    *, stiffness: float, exponent: float, alpha: float = 0.0, damping: float = 0.0,
    stiffness_ratio: float, time_scale: float, rtol: float = 1e-10, samples: int = 400,
    spring: str = "scaled",
) -> TangentialRun:  # fmt: skip
    r"""Integrate one impact with Hertz(-type) normal and Mindlin tangential compliance.

    Parameters
    ----------
    mass, radius, inertia : float
        ``m`` in kg, contact radius ``R`` in m, ``J`` about the centre in kg m^2.
    mu : float
        Coulomb friction coefficient.
    vx, vy, omega : float
        Incidence, m/s (``vy < 0``) and rad/s.
    stiffness, exponent : float
        Normal spring ``k delta^n`` (N/m^n, ``n >= 1``).
    alpha : float
        Hunt-Crossley damping, s/m (``a = 3 alpha/2``).
    damping : float
        Viscous damping ``c``, N s/m; only with ``exponent == 1`` (a linear
        spring-dashpot), where the force jumps to ``c |v_y|`` at first touch.
    stiffness_ratio : float
        ``r = k_t / (n k delta^{n-1})`` (:func:`mindlin_stiffness_ratio`).
    time_scale : float
        Order of the contact duration, s.
    rtol : float
        Relative tolerance of the integrator (DOP853).
    samples : int
        Evenly spaced output times, to which every switch is added.
    spring : {"scaled", "incremental", "total", "history"}
        How the stuck spring follows a changing stiffness: ``"scaled"`` (default)
        ``dF/dt = -k_t u + F min(dk_t/dt, 0)/k_t``, the rule whose energy never grows;
        ``"incremental"`` ``dF/dt = -k_t u`` (the plain incremental update);
        ``"total"`` ``F = -k_t xi`` with ``xi`` the accumulated displacement, i.e.
        ``dF/dt = -k_t u + F (dk_t/dt)/k_t`` (codes that store the displacement and
        multiply it by the current stiffness); ``"history"`` the exact no-slip elastic
        rule, ``dF/dt = -k_t u + (F - F_mem(delta)) min(dk_t/dt, 0)/k_t`` with the
        loading history's force ``F_mem`` (see the module's docstring). The four
        coincide for ``n = 1``.

    Returns
    -------
    TangentialRun

    Notes
    -----
    State ``(delta, v_x, v_y, omega, tau, f, W_n, F, xi)``; equations (2.4) with
    the tangential force ``F``:
    ``m dv_x/dt = F``, ``J domega/dt = R F``, ``m dv_y/dt = N``. See the module's
    docstring for the stick and slip rules and the energy they keep from growing.
    """
    if damping > 0 and exponent != 1.0:
        raise ValueError("viscous damping needs a linear spring (exponent 1)")
    if spring not in SPRINGS:
        raise ValueError(f"spring must be one of {SPRINGS}, got {spring!r}")
    k, n, a, c, r = stiffness, exponent, 1.5 * alpha, damping, stiffness_ratio
    # the share of dk_t/dt (when < 0, when > 0) that rescales F: see ``spring``
    down, up = {"scaled": (1.0, 0.0), "incremental": (0.0, 0.0), "total": (1.0, 1.0),
                "history": (1.0, 0.0)}[spring]  # fmt: skip
    history = spring == "history" and n != 1.0
    memory = [None]  # spring="history": the force F_mem(delta) of the loading history
    speed = abs(vy)
    vscale = abs(vx) + speed + abs(radius * omega)
    fscale = mass * vscale / time_scale
    p_scale = mass * vscale
    atol = rtol * np.array([speed * time_scale, vscale, vscale, vscale / radius, p_scale,
                            p_scale, p_scale * vscale, fscale, vscale * time_scale])  # fmt: skip

    def normal(d, dd):
        return k * math.copysign(abs(d) ** n, d) * (1.0 + a * dd) + c * dd

    def kt(d):
        return r * n * k * abs(d) ** (n - 1.0) if n != 1.0 else r * k

    def rates(y, sigma=0.0):
        """(N, dN/dt / k_t, [N/k_t] min(dk_t/dt, 0)/k_t): finite at delta = 0; under
        spring="history" the last less the loading history's share (slip ``sigma``)."""
        d, dd = y[0], -y[2]
        big_n = max(normal(d, dd), 0.0)
        ddd = -big_n / mass
        shape = dd * (1.0 + a * dd)
        n_rate = (shape + (a * d + (c / k if n == 1.0 else 0.0)) * ddd / n) / r
        rescale = (n - 1.0) / n * shape
        unload = (down * min(rescale, 0.0) + up * max(rescale, 0.0)) / r
        if history and memory[0] is not None and sigma and mu > 0.0 and dd < 0.0 and d > 0.0:
            # F_mem min(dk_t/dt, 0)/(sigma mu k_t): that part of the force does not unload
            unload -= memory[0].ratio(d) / (sigma * mu) * (n - 1.0) / n * dd / r
        return big_n, n_rate, unload

    def rhs(_t, y, stick, sigma):
        d, vx_, vy_, om, _tau, _f, _wn, force, _xi = y
        big_n, n_rate, unload = rates(y, 0.0 if stick else sigma)
        u = vx_ + radius * om
        if stick:
            f_t = force
            rate = (n - 1.0) * (-vy_) / d if d > 0 and n != 1.0 else 0.0
            scale = down * min(rate, 0.0) + up * max(rate, 0.0)
            if history:  # only the force beyond the loading history's unloads with k_t
                held = memory[0](d) if memory[0] is not None else force  # loading: F_mem = F
                df = -kt(d) * u + (force - held) * scale
            else:
                df = -kt(d) * u + force * scale
            dxi = u
        else:
            f_t = sigma * mu * big_n
            df = 0.0
            dxi = -sigma * mu * (n_rate - unload)
        return [-vy_, f_t / mass, big_n / mass, f_t * radius / inertia, big_n, f_t, big_n * vy_,
                df, dxi]  # fmt: skip

    def force_of(y, stick, sigma):  # the tangential force of a state
        return y[7] if stick else sigma * mu * max(normal(y[0], -y[2]), 0.0)

    def compression_end(_t, y):
        return y[2]

    def separation(_t, y):
        big_n = normal(y[0], -y[2])
        return math.copysign(abs(big_n) ** (1.0 / n), big_n)

    def cap_up(_t, y):  # F reaches +mu N
        return mu * max(normal(y[0], -y[2]), 0.0) - y[7]

    def cap_down(_t, y):  # F reaches -mu N
        return mu * max(normal(y[0], -y[2]), 0.0) + y[7]

    def slip_end(_t, y, sigma):  # -sigma w: the slip velocity reaches zero
        _, n_rate, unload = rates(y, sigma)
        u = y[1] + radius * y[3]
        return -sigma * u + mu * (unload - n_rate)

    y = np.array([0.0, vx, vy, omega, 0.0, 0.0, 0.0, 0.0, 0.0])
    u0 = vx + radius * omega
    # first touch: the contact sticks if the cap opens at once (c > 0) or faster
    # than the trial force grows (-sigma w(0+) < 0)
    if u0 == 0.0 or c > 0.0:
        stick, sigma = True, 0.0
    else:
        sigma = -math.copysign(1.0, u0)
        stick = -sigma * u0 - mu * speed * (1.0 + a * speed) / r <= 0.0
    if mu == 0.0:  # frictionless: F = 0 throughout (a slip phase that never ends)
        stick, sigma = False, 1.0
    t, t0, tau0, work0 = 0.0, math.nan, math.nan, math.nan
    segments, switches, idle = [], [], 0
    horizon = 1e3 * time_scale
    # the watch's resolution: steps of at most 1/8 of the shortest period, normal or (while
    # sticking) tangential, at the stiffest point (elastic peak compression)
    d_max = ((n + 1.0) * mass * speed**2 / (2.0 * k)) ** (1.0 / (n + 1.0))
    k_peak = k if n == 1.0 else n * k * d_max ** (n - 1.0)
    w_n = math.sqrt(k_peak / mass)
    w_t = math.sqrt(r * k_peak * (1.0 / mass + radius**2 / inertia))
    while True:

        def fun(tt, yy, stick=stick, sigma=sigma):
            return rhs(tt, yy, stick, sigma)

        # v_y and N^(1/n) cross zero once (N >= 0 until separation): step ends suffice
        events = [Event(compression_end, 1, terminal=history and math.isnan(t0), watched=False),
                  Event(separation, -1, watched=False, integrate_to=True)]  # fmt: skip
        if stick:
            events += [Event(cap_up, -1), Event(cap_down, -1)]
        elif mu != 0.0:
            events.append(Event(functools.partial(slip_end, sigma=sigma), -1))
        w_max = max(w_n, w_t) if stick else w_n
        sol = integrate_events(fun, t, y, t + horizon, events, rtol=rtol, atol=atol,
                               max_step=2.0 * math.pi / w_max / 8.0)  # fmt: skip
        if sol.status == -1:
            raise RuntimeError(f"contact integration failed: {sol.message}")
        if sol.status == 0:
            raise RuntimeError("contact did not end within 1000 time scales")
        if sol.t_events[0].size and math.isnan(t0):
            t0, y0 = float(sol.t_events[0][0]), sol.y_events[0][0]
            tau0, work0 = float(y0[4]), float(y0[6])
        if sol.t > t:
            segments.append((t, sol.t, sol.sol, stick, sigma))
            idle = 0
        else:  # a switch at the very start: neither stick nor slip can go on (tangency)
            idle += 1
        t, y = sol.t, sol.y.copy()
        if sol.t_events[1].size:
            break
        if (
            history
            and memory[0] is None
            and sol.t_events[0].size
            and not any(e.size for e in sol.t_events[2:])
        ):  # the end of compression: the loading history is complete
            memory[0] = loading_history(segments, y, k, n, r, force_of)
            continue
        if idle > 4:
            raise RuntimeError(f"stick and slip both end at once at t = {t:g} s (a tangency "
                               "the event rules cannot resolve); try another rtol")  # fmt: skip
        if len(segments) > MAX_SEGMENTS:
            raise RuntimeError(f"more than {MAX_SEGMENTS} stick/slip switches in one impact")
        switches.append(t)
        big_n = max(normal(y[0], -y[2]), 0.0)
        if stick:  # the cap is reached: slip opposite to the spring's pull
            sigma = 1.0 if sol.t_events[2].size else -1.0
            y[7] = sigma * mu * big_n
        else:  # slip has stopped: the spring holds the cap force
            y[7] = sigma * mu * big_n
        stick = not stick
    kept = memory[0] if history else None  # spring="history": its loading history
    return sampled(segments, t, y, t0, tau0, work0, switches, samples, mass, radius, inertia,
                   mu, vy, normal, kt, k, n, rates, kept)  # fmt: skip
