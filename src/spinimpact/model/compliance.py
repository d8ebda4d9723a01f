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

__all__ = ["TangentialLaw", "Walton", "CompliantImpact", "CompliantSphereImpact"]


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
        (the ball leaves spinning faster than rolling), ``-1`` no friction at all.

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

    def __repr__(self) -> str:
        return f"Walton(beta0={self.beta0!r})"
