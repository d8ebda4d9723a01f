r"""Compliant normal contact laws for :func:`spinimpact.dynamics.simulate`.

Each law is a small immutable object with a signed force ``N(delta, delta_dot)``
in N of the compression ``delta`` (m, into the surface) and its rate
``delta_dot = -v_y`` (m/s), built from physical constants or calibrated to a
target restitution at a given speed. The force kernels and the integrator live
in :mod:`spinimpact.core.contact`; this module validates and packages, and does
not depend on :mod:`spinimpact.model.dynamics`.

References
----------
.. [1] H. Hertz, "Ueber die Berührung fester elastischer Körper", Journal für
   die reine und angewandte Mathematik 92 (1882) 156-171.
.. [2] K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution interpreted as
   damping in vibroimpact", Journal of Applied Mechanics 42 (1975) 440-445.
.. [3] W. J. Stronge, *Impact Mechanics*, Cambridge University Press,
   Cambridge (2000).
"""

from __future__ import annotations

from dataclasses import dataclass, fields, is_dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, check, scalar, setting
from ..core import contact as kernels
from .restitution import TabulatedRestitution
from .result import Array, Result, freeze

__all__ = ["ContactLaw", "LinearContact", "HertzContact", "HuntCrossleyContact", "NormalImpact"]

#: What each contact-law parameter must be beyond one finite real number and the shared
#: rules of its name (``mass``, ``radius``, ``kappa``): (predicate, "NAME must be ...").
_RULES = {
    "stiffness": (lambda x: x > 0, "> 0"),
    "damping": (lambda x: x >= 0, ">= 0"),
    "alpha": (lambda x: x >= 0, ">= 0"),
    "exponent": (lambda x: (x >= 1) & (x <= 10), "in [1, 10]"),
    "youngs_modulus": (lambda x: x > 0, "> 0"),
    "poisson_ratio": (lambda x: (x > -1) & (x <= 0.5), "in (-1, 0.5]"),
    "kappa": (lambda x: x > 0, "in (0, 1]"),  # a target restitution: 0 cannot be reached
}


def _parameter(name: str, value: Any) -> float:
    """One number (:func:`~spinimpact._validation.scalar`, with the shared rules of
    its name; a ``speed`` obeys those of a mass: ``> 0``) obeying ``_RULES[name]``."""
    x = scalar(name, value, "mass" if name == "speed" else None,
               why="a contact law takes one value of each parameter")  # fmt: skip
    if name in _RULES:
        ok, rule = _RULES[name]
        check(name, np.float64(x), ok, rule)
    return x


def _tolerance(rtol: Any) -> float:
    """The integrator's relative tolerance, a setting in ``[1e-13, 1e-3]``."""
    tol = setting("rtol", rtol, rule="a number in [1e-13, 1e-3]")
    check("rtol", np.float64(tol), lambda x: (x >= 1e-13) & (x <= 1e-3), "in [1e-13, 1e-3]")
    return tol


@dataclass(frozen=True, eq=False)
class NormalImpact(Result):
    """The normal (frictionless, spinless) part of a compliant impact at one speed
    (:meth:`ContactLaw.normal_impact`)."""

    speed: Array  #: impact speed ``|vy|``, m/s
    restitution: Array  #: Newton's -v+/v- (eq. 1.1)
    duration: Array  #: contact time, s
    peak_force: Array  #: largest normal force, N
    max_compression: Array  #: largest compression, m


class ContactLaw:
    """Base class of the compliant normal contact laws.

    A law gives the signed force ``force(delta, delta_dot)`` in N (the integrator
    applies ``max(N, 0)``), a ``time_scale(mass, speed)`` in s of the order of
    the contact duration, the power ``separation_exponent`` with which the
    force vanishes at separation, and whether it is ``elastic``.

    Every restitution a law reports is in ``[0, 1]``: exactly 1 for an elastic law,
    and for a damped one the value measured on the integrated impact, clipped to at
    most 1 (see :meth:`restitutions`).
    """

    @property
    def elastic(self) -> bool:
        """Whether the law has no damping: its force depends on the compression
        alone, so it returns all the energy it stores and its restitution is 1."""
        return False

    def restitutions(self, run: kernels.ContactRun) -> tuple[float, float, float]:
        """Newton's, Poisson's and the energetic restitution of an integrated impact
        (:func:`~spinimpact.core.contact.integrate_contact`) as this law gives them.

        An elastic law's are exactly 1: its force is a function of the compression
        alone, so the work of compression comes back in full and the impulses of the
        two phases are equal, whatever the integrator's error. A damped law's are the
        values measured on the process, clipped to ``[0, 1]``: a passive force (a
        spring and a dashpot that never pull) cannot return more energy than it
        received, so a value above 1 is integration error (of the order of the
        tolerance; ``docs/dynamics.md`` gives measured sizes).
        """
        if self.elastic:
            return 1.0, 1.0, 1.0
        measured = (run.newton_restitution, run.poisson_restitution, run.energetic_restitution)
        return tuple(min(max(float(k), 0.0), 1.0) for k in measured)  # type: ignore[return-value]

    def force(self, delta: float, delta_dot: float) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    def time_scale(self, mass: float, speed: float) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    #: power with which the force vanishes at separation (N ~ delta^n)
    separation_exponent: float = 1.0

    def to_dict(self) -> dict[str, Any]:
        """The law's name and parameters as plain Python values."""
        names = [f.name for f in fields(self)] if is_dataclass(self) else []
        return {"law": type(self).__name__, **{n: getattr(self, n) for n in names}}

    def normal_impact(self, mass: float, speed: float, *, rtol: float = 1e-10) -> NormalImpact:
        """A drop without spin or friction: the law's restitution, contact
        duration, peak force and largest compression.

        Parameters
        ----------
        mass : float
            Mass of the body, kg, ``> 0``.
        speed : float
            Impact speed ``|vy|``, m/s, ``> 0``.
        rtol : float
            Relative tolerance of the integrator, in ``[1e-13, 1e-3]``.

        Returns
        -------
        NormalImpact
        """
        m, v, tol = _parameter("mass", mass), _parameter("speed", speed), _tolerance(rtol)
        run = kernels.integrate_normal_impact(
            self.force, m, v, time_scale=self.time_scale(m, v), rtol=tol,
            exponent=self.separation_exponent,
        )  # fmt: skip
        values = (v, self.restitutions(run)[0], run.t1, run.peak_force, run.max_compression)
        return NormalImpact(*(freeze(x) for x in values))

    def restitution(self, mass: float, speed: float, *, rtol: float = 1e-10) -> float:
        """Newton's restitution ``kappa`` in ``[0, 1]`` this law gives a body of
        ``mass`` (kg) at impact ``speed`` (m/s): exactly 1 for an elastic law, so
        ``solve(kappa=law.restitution(...))`` always accepts it."""
        return float(self.normal_impact(mass, speed, rtol=rtol).restitution)

    def restitution_model(
        self, mass: float, speeds: Any, *, rtol: float = 1e-10
    ) -> TabulatedRestitution:
        """``kappa(|vy|)`` of this law for a body of ``mass`` (kg), tabulated at
        ``speeds`` (m/s) and interpolated between them; pass it to ``solve(kappa=...)``.

        Examples
        --------
        >>> law = HuntCrossleyContact(stiffness=1e8, exponent=1.5, alpha=0.2)
        >>> model = law.restitution_model(0.05, [0.5, 1.0, 2.0, 4.0])
        >>> bool(model(1.0) > model(4.0))   # damping: slower impacts bounce better
        True
        """
        s = as_real_array("speeds", speeds)
        if s.ndim != 1 or s.size < 1:
            raise ValueError(f"speeds must be a 1-D array of speeds, got shape {s.shape}")
        s = np.sort(s)
        kappas = [self.restitution(mass, float(v), rtol=rtol) for v in s]  # in [0, 1]
        return TabulatedRestitution(s, kappas)


@dataclass(frozen=True)
class LinearContact(ContactLaw):
    r"""Linear spring-dashpot (Kelvin-Voigt) contact; its restitution does not
    depend on the speed.

    Parameters
    ----------
    stiffness : float
        ``k``, N/m, ``> 0``.
    damping : float
        ``c``, N s/m, ``>= 0``.

    Notes
    -----
    .. math:: N = \max(k \delta + c \dot\delta,\ 0)

    The force never pulls: the contact ends when ``N`` falls to zero, which for
    ``c > 0`` is before ``delta`` returns to zero. The law is linear, so the
    restitution depends on the damping ratio ``c/(2 sqrt(k m))`` only (Stronge 2000).
    """

    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        for name in ("stiffness", "damping"):
            object.__setattr__(self, name, _parameter(name, getattr(self, name)))

    @property
    def elastic(self) -> bool:
        """No dashpot (``damping = 0``): the restitution is 1."""
        return self.damping == 0.0

    def force(self, delta: float, delta_dot: float) -> float:
        return kernels.linear_force(delta, delta_dot, self.stiffness, self.damping)

    def time_scale(self, mass: float, speed: float) -> float:
        # the spring period, or the damper's relaxation time when that is shorter
        scale = float(np.sqrt(mass / self.stiffness))
        return min(scale, mass / self.damping) if self.damping > 0 else scale

    @classmethod
    def calibrated(cls, *, stiffness: float, kappa: float, mass: float) -> LinearContact:
        """The damping that gives restitution ``kappa`` in ``(0, 1]`` for a body of
        ``mass`` (kg), at any speed (the law is linear); ``stiffness`` in N/m."""
        k, m = _parameter("kappa", kappa), _parameter("mass", mass)
        stiffness = cls(stiffness).stiffness  # validated before use
        c_crit = 2.0 * np.sqrt(stiffness * m)
        return _calibrate(lambda c: cls(stiffness, c * c_crit), k, m, 1.0)


@dataclass(frozen=True)
class HuntCrossleyContact(ContactLaw):
    r"""Hunt-Crossley contact: a power-law spring with damping proportional to it,
    so ``kappa`` falls with the impact speed.

    Parameters
    ----------
    stiffness : float
        ``k``, N/m^n, ``> 0``.
    exponent : float
        ``n`` in ``[1, 10]``: 3/2 for Hertz sphere-on-plane contact, 1 for a linear spring.
    alpha : float
        Damping factor, s/m, ``>= 0``.

    Notes
    -----
    .. math:: N = \max\left(k \delta^n \left(1 + \tfrac{3}{2}\alpha\dot\delta\right),\ 0\right)

    Hunt and Crossley (1975) made the damping proportional to the elastic force so
    that the force is continuous at first touch; the restitution then depends on
    ``alpha v`` only and is about ``1 - alpha v`` for small ``alpha v``. With
    ``n = 3/2`` and ``alpha = 0`` this is Hertz's elastic law (Hertz 1882).
    """

    stiffness: float
    exponent: float = 1.5
    alpha: float = 0.0

    def __post_init__(self) -> None:
        for name in ("stiffness", "exponent", "alpha"):
            object.__setattr__(self, name, _parameter(name, getattr(self, name)))

    @property
    def elastic(self) -> bool:
        """No damping (``alpha = 0``): the restitution is 1."""
        return self.alpha == 0.0

    def force(self, delta: float, delta_dot: float) -> float:
        return kernels.hunt_crossley_force(
            delta, delta_dot, self.stiffness, self.exponent, self.alpha
        )

    @property
    def separation_exponent(self) -> float:  # type: ignore[override]
        """The force vanishes like ``delta^n`` at separation."""
        return self.exponent

    def time_scale(self, mass: float, speed: float) -> float:
        return float(kernels.power_law_time_scale(mass, speed, self.stiffness, self.exponent))

    @classmethod
    def calibrated(
        cls, *, stiffness: float, kappa: float, mass: float, speed: float, exponent: float = 1.5
    ) -> HuntCrossleyContact:
        """The ``alpha`` (s/m) that gives restitution ``kappa`` in ``(0, 1]`` to a
        body of ``mass`` (kg) at impact ``speed`` (m/s)."""
        k, m, v = _parameter("kappa", kappa), _parameter("mass", mass), _parameter("speed", speed)
        law = cls(stiffness, exponent)  # validated before use
        return _calibrate(lambda a: cls(law.stiffness, law.exponent, a / v), k, m, v)


@dataclass(frozen=True, init=False, repr=False)
class HertzContact(HuntCrossleyContact):
    r"""Elastic Hertz contact of a sphere on a rigid plane, built from material
    constants, with optional Hunt-Crossley damping.

    Parameters
    ----------
    youngs_modulus : float
        ``E``, Pa, ``> 0``.
    poisson_ratio : float
        ``nu`` in ``(-1, 0.5]``.
    radius : float
        Radius of curvature at the contact ``R``, m (the body's contact radius).
    alpha : float
        Hunt-Crossley damping factor, s/m (``0``: elastic, ``kappa = 1``).

    Notes
    -----
    .. math::

        N = \tfrac{4}{3} E^* \sqrt{R}\, \delta^{3/2}
            \left(1 + \tfrac{3}{2}\alpha\dot\delta\right), \qquad
        E^* = \frac{E}{1 - \nu^2}

    Hertz's law (1882) is for point contact (a sphere); a cylinder or disk pressed
    along a line has no closed power law - use :class:`LinearContact` or
    :class:`HuntCrossleyContact` with a fitted stiffness there. The damping is
    Hunt and Crossley's (1975).
    """

    def __init__(
        self, youngs_modulus: float, poisson_ratio: float, radius: float, alpha: float = 0.0
    ):
        e = _parameter("youngs_modulus", youngs_modulus)
        nu = _parameter("poisson_ratio", poisson_ratio)
        r = _parameter("radius", radius)
        object.__setattr__(self, "youngs_modulus", e)
        object.__setattr__(self, "poisson_ratio", nu)
        object.__setattr__(self, "radius", r)
        super().__init__(float(kernels.hertz_stiffness(e, nu, r)), 1.5, alpha)

    @classmethod
    def calibrated(  # type: ignore[override]
        cls, *, youngs_modulus: float, poisson_ratio: float, radius: float, kappa: float,
        mass: float, speed: float,
    ) -> HertzContact:  # fmt: skip
        """The Hertz law of these material constants (Pa, -, m) whose Hunt-Crossley
        damping ``alpha`` (s/m) gives restitution ``kappa`` in ``(0, 1]`` to a body of
        ``mass`` (kg) at impact ``speed`` (m/s); still a :class:`HertzContact`.

        Examples
        --------
        >>> law = HertzContact.calibrated(youngs_modulus=2e9, poisson_ratio=0.35,
        ...                               radius=0.02, kappa=0.8, mass=0.05, speed=3.0)
        >>> type(law).__name__, round(law.restitution(0.05, 3.0), 6)
        ('HertzContact', 0.8)
        """
        k, m, v = _parameter("kappa", kappa), _parameter("mass", mass), _parameter("speed", speed)
        law = cls(youngs_modulus, poisson_ratio, radius)  # validated before use
        e, nu, r = law.youngs_modulus, law.poisson_ratio, law.radius
        return _calibrate(lambda a: cls(e, nu, r, a / v), k, m, v)

    def duration(self, mass: float, speed: float) -> float:
        """Classical elastic Hertz contact duration in s (ignores ``alpha``) of a
        body of ``mass`` (kg) at impact ``speed`` (m/s)."""
        m = scalar("mass", mass)
        v = scalar("speed", speed)
        check("mass", np.asarray(m), lambda x: x > 0, "> 0")
        check("speed", np.asarray(v), lambda x: x > 0, "> 0")
        return float(kernels.hertz_duration(m, v, self.stiffness))

    def to_dict(self) -> dict[str, Any]:
        """The material constants, the damping and the resulting stiffness."""
        names = ("youngs_modulus", "poisson_ratio", "radius", "alpha", "stiffness", "exponent")
        return {"law": type(self).__name__, **{n: getattr(self, n) for n in names}}

    def __repr__(self) -> str:
        return (
            f"HertzContact(youngs_modulus={self.youngs_modulus:g}, "
            f"poisson_ratio={self.poisson_ratio:g}, radius={self.radius:g}, alpha={self.alpha:g})"
        )


def _calibrate(make, kappa: float, mass: float, speed: float):
    """Root-find the dimensionless damping ``x`` in ``make(x)`` giving ``kappa``.

    The bracket grows geometrically until the damping is strong enough.
    """
    from scipy.optimize import brentq

    if kappa == 1.0:
        return make(0.0)

    def gap(x: float) -> float:
        return make(x).restitution(mass, speed, rtol=1e-11) - kappa

    hi = 0.5
    while gap(hi) > 0:
        hi *= 4.0
        if hi > 1e8:
            raise ValueError(
                f"kappa = {kappa:g} is below what this law can reach; choose a larger kappa"
            )
    x = brentq(gap, 0.0, hi, xtol=1e-14, rtol=1e-12)
    return make(x)
