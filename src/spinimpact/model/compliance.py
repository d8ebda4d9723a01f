"""Tangential compliance laws that :func:`~spinimpact.solve` and
:func:`~spinimpact.solve_sphere` accept (``tangential=law``).

* :class:`Walton`: the three-parameter model of DEM practice (normal restitution ``kappa``,
  friction ``mu`` and the tangential restitution ``beta0`` of sticking impacts).
* :class:`Stronge`: Stronge's lumped-parameter contact, a normal and a tangential spring
  whose stiffness ratio follows from Poisson's ratio (Mindlin).

Each gives the tangential restitution of the contact point ``beta = -u^+/u^-`` and reduces
to the rigid law in its rigid limit (``beta0 = 0``; a tangential spring infinitely stiff).
The physics is in :mod:`spinimpact.core.compliance`; ``docs/compliance.md`` derives it.

Examples
--------
>>> from spinimpact import Body, Walton, solve
>>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
>>> imp = solve(ball, vx=1.0, vy=-3.0, omega=0.0, mu=0.5, kappa=0.8, tangential=Walton(0.4))
>>> str(imp.regime), round(float(imp.tangential_restitution), 12)
('slip-reversal', 0.4)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

from .._validation import scalar
from ..core import compliance as kernels
from .compliant import (
    CompliantImpact,
    CompliantSphereImpact,
    solve_compliant,
    solve_sphere_compliant,
)

__all__ = ["TangentialLaw", "Walton", "Stronge", "CompliantImpact", "CompliantSphereImpact"]


def _number(name: str, value: Any, low: float, high: float, rule: str) -> float:
    x = scalar(name, value)
    if not low <= x <= high:
        raise ValueError(f"{name} must be {rule}, got {x!r}")
    return x


@dataclass(frozen=True)
class TangentialLaw:
    """Base of the tangential compliance laws: a frozen set of parameters that gives the
    slip of the contact point after the impact on the seam of :mod:`spinimpact.core`."""

    name: ClassVar[str] = "rigid"

    def rebound_slip(self, slip: Any, vy: Any, zeta: Any, mu: Any, kappa: Any) -> tuple:
        """``(c_t^+, stuck)`` from the contact point's ``c_t^-``, ``c_n^-`` and the seam's
        ``zeta``, ``mu``, ``kappa`` (arrays of one shape); ``stuck``: it stuck at all."""
        raise NotImplementedError

    @property
    def frictionless(self) -> bool:
        """Whether the law applies no friction whatever ``mu``: its impacts are
        ``frictionless``, as those with ``mu = 0``."""
        return False

    def to_dict(self) -> dict[str, Any]:
        """The law's name and parameters as plain Python values."""
        return {"law": self.name, **{k: v for k, v in vars(self).items()}}

    def _solve_plane(self, body: Any, vx: Any, vy: Any, omega: Any, *, mu: Any,
                     kappa: Any) -> CompliantImpact:  # fmt: skip
        return solve_compliant(self, body, vx, vy, omega, mu=mu, kappa=kappa)

    def _solve_sphere(self, body: Any, velocity: Any, spin: Any, *, mu: Any, kappa: Any,
                      surface: Any = None) -> CompliantSphereImpact:  # fmt: skip
        return solve_sphere_compliant(self, body, velocity, spin, mu=mu, kappa=kappa,
                                      surface=surface)  # fmt: skip


@dataclass(frozen=True)
class Walton(TangentialLaw):
    """Walton's tangential restitution: ``beta = min(beta0, beta_slide)``.

    Parameters
    ----------
    beta0 : float
        Tangential restitution of the contact point in sticking impacts, in ``[-1, 1]``:
        ``0`` is the rigid law (the contact point leaves at rest), ``> 0`` a slip reversal
        (the ball leaves spinning faster than rolling), ``-1`` no friction at all (the
        impacts' regime is then ``frictionless``, as for ``mu = 0``).

    Notes
    -----
    ``beta_slide = -1 + (1 + kappa) zeta mu |u^-/v^-|^(-1)`` is the restitution of an impact
    that slides throughout; the law takes whichever of the two needs less friction impulse
    (Walton 1993; Foerster et al. 1994). See :func:`spinimpact.core.compliance.walton_slip`.
    """

    beta0: float = 0.0
    name: ClassVar[str] = "walton"

    def __post_init__(self) -> None:
        object.__setattr__(self, "beta0", _number("beta0", self.beta0, -1.0, 1.0, "in [-1, 1]"))

    def rebound_slip(self, slip: Any, vy: Any, zeta: Any, mu: Any, kappa: Any) -> tuple:
        return kernels.walton_slip(slip, vy, zeta, mu, kappa, self.beta0)

    @property
    def frictionless(self) -> bool:
        """``beta0 = -1``: ``beta = min(-1, beta_slide) = -1`` for every impact, the contact
        point keeps its slip and no friction impulse acts (the outcome of ``mu = 0``)."""
        return self.beta0 == -1.0

    def __repr__(self) -> str:
        return f"Walton(beta0={self.beta0!r})"


@dataclass(frozen=True)
class Stronge(TangentialLaw):
    """Stronge's lumped-parameter tangential compliance: normal and tangential springs at
    the contact, Coulomb slip, stick while the tangential spring holds.

    Give one of the two parameters.

    Parameters
    ----------
    poisson_ratio : float, optional
        Poisson's ratio ``nu`` in ``(-1, 0.5]``; the stiffness ratio is then Mindlin's
        ``k_t/k_n = 2(1 - nu)/(2 - nu)`` (``nu = 0.23``, aluminium oxide: 0.8701).
    stiffness_ratio : float, optional
        ``k_t/k_n > 0`` directly (large values approach the rigid law).

    Notes
    -----
    Linear springs, as in Stronge's model: the normal one unloads with stiffness
    ``k_n/kappa^2``, so ``kappa`` is Stronge's energetic coefficient (with ``W_tn = 0``
    also Newton's and Poisson's). In stick the tangential spring oscillates at
    ``Omega = sqrt(zeta k_t/k_n)`` times the normal frequency; the impact is solved
    piecewise in closed form (:func:`spinimpact.core.compliance.stronge_restitution`), for
    any number of stick/slip changes. It slides throughout when Maw et al.'s normalized
    incidence angle is large, and then gives the rigid law's sliding rebound exactly.

    Examples
    --------
    >>> from spinimpact import Body, Stronge, solve
    >>> law = Stronge(poisson_ratio=0.23)
    >>> round(law.stiffness_ratio, 6)
    0.870056
    >>> imp = solve(Body.solid_sphere(mass=1.0, radius=0.1), 1.0, -1.0, 0.0, mu=0.5,
    ...             kappa=0.8, tangential=law)
    >>> str(imp.regime), bool(imp.tangential_restitution > 0)
    ('slip-reversal', True)
    """

    poisson_ratio: float | None = None
    stiffness_ratio: float | None = None
    name: ClassVar[str] = "stronge"

    def __post_init__(self) -> None:
        nu, ratio = self.poisson_ratio, self.stiffness_ratio
        if (nu is None) == (ratio is None):
            raise TypeError("Stronge takes one of poisson_ratio and stiffness_ratio, "
                            f"got poisson_ratio={nu!r}, stiffness_ratio={ratio!r}")  # fmt: skip
        if nu is not None:
            nu = scalar("poisson_ratio", nu)
            if not -1.0 < nu <= 0.5:
                raise ValueError(f"poisson_ratio must be in (-1, 0.5], got {nu!r}")
            object.__setattr__(self, "poisson_ratio", nu)
            ratio = float(kernels.mindlin_stiffness_ratio(nu))
        else:
            ratio = _number("stiffness_ratio", ratio, 0.0, 1e12, "in (0, 1e12]")
            if ratio == 0.0:
                raise ValueError("stiffness_ratio must be in (0, 1e12], got 0.0")
        object.__setattr__(self, "stiffness_ratio", ratio)

    def rebound_slip(self, slip: Any, vy: Any, zeta: Any, mu: Any, kappa: Any) -> tuple:
        out = kernels.stronge_restitution(slip, vy, zeta, mu, kappa, self.stiffness_ratio)
        return out.slip_after, out.stuck

    def frequency_ratio(self, zeta: Any) -> Any:
        """``Omega = sqrt(zeta k_t/k_n)``: the tangential over the normal frequency."""
        return (zeta * self.stiffness_ratio) ** 0.5

    def __repr__(self) -> str:
        if self.poisson_ratio is not None:
            return f"Stronge(poisson_ratio={self.poisson_ratio!r})"
        return f"Stronge(stiffness_ratio={self.stiffness_ratio!r})"
