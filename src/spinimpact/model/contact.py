"""Compliant contact laws for :func:`spinimpact.dynamics.simulate`.

Each law is a small immutable object with a signed force ``N(delta, delta_dot)``
(compression ``delta`` into the surface, ``delta_dot = -v``), built from
physical constants or calibrated to a target restitution at a given speed.
The force kernels live in :mod:`spinimpact.core.contact`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .._validation import as_real_array, check
from ..core import contact as kernels
from .restitution import TabulatedRestitution

__all__ = ["ContactLaw", "LinearContact", "HertzContact", "HuntCrossleyContact", "NormalImpact"]


def _param(name: str, value: Any, ok, rule: str) -> float:
    arr = as_real_array(name, value)
    if arr.ndim:
        raise ValueError(f"{name} must be a single number, got an array of shape {arr.shape}")
    check(name, arr, ok, rule)
    return float(arr)


@dataclass(frozen=True)
class NormalImpact:
    """The normal (frictionless) part of a compliant impact, at one speed."""

    speed: float  #: impact speed |vy|, m/s
    restitution: float  #: Newton's -v+/v-
    duration: float  #: contact time, s
    peak_force: float  #: N
    max_compression: float  #: m


class ContactLaw:
    """Base class of the compliant normal contact laws."""

    def force(self, delta: float, delta_dot: float) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    def time_scale(self, mass: float, speed: float) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    #: power with which the force vanishes at separation (N ~ delta^n)
    separation_exponent: float = 1.0

    def normal_impact(self, mass: float, speed: float, *, rtol: float = 1e-10) -> NormalImpact:
        """Drop without spin or friction at ``speed``: the law's restitution,
        contact duration, peak force and largest compression."""
        from .dynamics import simulate

        m = _param("mass", mass, lambda x: x > 0, "> 0")
        v = _param("speed", speed, lambda x: x > 0, "> 0")
        sim = simulate(None, 0.0, -v, 0.0, mu=0.0, contact=self, rtol=rtol, _mass=m)
        return NormalImpact(v, float(sim.newton_restitution), sim.contact_duration,
                            sim.peak_force, sim.max_compression)  # fmt: skip

    def restitution(self, mass: float, speed: float, *, rtol: float = 1e-10) -> float:
        """Newton's restitution ``kappa`` this law gives at impact ``speed`` (m/s)."""
        return self.normal_impact(mass, speed, rtol=rtol).restitution

    def restitution_model(
        self, mass: float, speeds: Any, *, rtol: float = 1e-10
    ) -> TabulatedRestitution:
        """``kappa(|vy|)`` of this law for a body of ``mass``, tabulated at ``speeds``
        (m/s) and interpolated between them; pass it to ``solve(kappa=...)``.

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
        kappas = [self.restitution(mass, float(v), rtol=rtol) for v in s]
        return TabulatedRestitution(s, np.clip(kappas, 0.0, 1.0))


@dataclass(frozen=True)
class LinearContact(ContactLaw):
    """Kelvin-Voigt spring and dashpot, ``N = k delta + c delta_dot`` (never tensile).

    Its restitution does not depend on the speed.

    Parameters
    ----------
    stiffness : float
        ``k`` in N/m, ``> 0``.
    damping : float
        ``c`` in N s/m, ``>= 0``.
    """

    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "stiffness", _param("stiffness", self.stiffness, lambda x: x > 0, "> 0")
        )
        object.__setattr__(
            self, "damping", _param("damping", self.damping, lambda x: x >= 0, ">= 0")
        )

    def force(self, delta: float, delta_dot: float) -> float:
        return kernels.linear_force(delta, delta_dot, self.stiffness, self.damping)

    def time_scale(self, mass: float, speed: float) -> float:
        # the spring period, or the damper's relaxation time when that is shorter
        scale = float(np.sqrt(mass / self.stiffness))
        return min(scale, mass / self.damping) if self.damping > 0 else scale

    @classmethod
    def calibrated(cls, *, stiffness: float, kappa: float, mass: float) -> LinearContact:
        """The damping that gives restitution ``kappa`` for a body of ``mass``
        (any speed: the law is linear)."""
        k = _param("kappa", kappa, lambda x: (x > 0) & (x <= 1), "in (0, 1]")
        m = _param("mass", mass, lambda x: x > 0, "> 0")
        stiffness = cls(stiffness).stiffness  # validated before use
        c_crit = 2.0 * np.sqrt(stiffness * m)
        return _calibrate(lambda c: cls(stiffness, c * c_crit), k, m, 1.0)


@dataclass(frozen=True)
class HuntCrossleyContact(ContactLaw):
    """Hunt-Crossley, ``N = k delta^n (1 + 3/2 alpha delta_dot)`` (never tensile).

    Dissipation grows with the impact speed, so ``kappa`` falls with speed
    (approximately ``1 - alpha v`` for small ``alpha v``).

    Parameters
    ----------
    stiffness : float
        ``k`` in N/m^n, ``> 0``.
    exponent : float
        ``n >= 1``: 3/2 for Hertz sphere-on-plane contact, 1 for a linear spring.
    alpha : float
        Damping factor in s/m, ``>= 0``.
    """

    stiffness: float
    exponent: float = 1.5
    alpha: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "stiffness", _param("stiffness", self.stiffness, lambda x: x > 0, "> 0")
        )
        object.__setattr__(
            self,
            "exponent",
            _param("exponent", self.exponent, lambda x: (x >= 1) & (x <= 10), "in [1, 10]"),
        )
        object.__setattr__(self, "alpha", _param("alpha", self.alpha, lambda x: x >= 0, ">= 0"))

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
        """The ``alpha`` that gives restitution ``kappa`` at impact ``speed``."""
        k = _param("kappa", kappa, lambda x: (x > 0) & (x <= 1), "in (0, 1]")
        m = _param("mass", mass, lambda x: x > 0, "> 0")
        v = _param("speed", speed, lambda x: x > 0, "> 0")
        law = cls(stiffness, exponent)  # validated before use
        return _calibrate(lambda a: cls(law.stiffness, law.exponent, a / v), k, m, v)


@dataclass(frozen=True, init=False, repr=False)
class HertzContact(HuntCrossleyContact):
    """Elastic Hertz contact of a sphere on a rigid plane, ``N = 4/3 E* sqrt(R) delta^{3/2}``,
    with optional Hunt-Crossley damping ``alpha``.

    Built from material constants: ``E* = E/(1 - nu^2)``. The Hertz law is for
    point contact (a sphere); a cylinder or disk pressed along a line has no
    closed power law - use :class:`LinearContact` or :class:`HuntCrossleyContact`
    with a fitted stiffness there.

    Parameters
    ----------
    youngs_modulus : float
        ``E`` in Pa, ``> 0``.
    poisson_ratio : float
        ``nu`` in ``(-1, 0.5]``.
    radius : float
        Radius of curvature at the contact, m (the body's contact radius).
    alpha : float
        Hunt-Crossley damping factor, s/m (``0``: elastic, ``kappa = 1``).
    """

    def __init__(
        self, youngs_modulus: float, poisson_ratio: float, radius: float, alpha: float = 0.0
    ):
        e = _param("youngs_modulus", youngs_modulus, lambda x: x > 0, "> 0")
        nu = _param("poisson_ratio", poisson_ratio, lambda x: (x > -1) & (x <= 0.5), "in (-1, 0.5]")
        r = _param("radius", radius, lambda x: x > 0, "> 0")
        object.__setattr__(self, "youngs_modulus", e)
        object.__setattr__(self, "poisson_ratio", nu)
        object.__setattr__(self, "radius", r)
        super().__init__(float(kernels.hertz_stiffness(e, nu, r)), 1.5, alpha)

    def duration(self, mass: float, speed: float) -> float:
        """Classical elastic Hertz contact duration (ignores ``alpha``)."""
        return float(kernels.hertz_duration(mass, speed, self.stiffness))

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
