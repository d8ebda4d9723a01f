"""Tangential compliance laws that :func:`~spinimpact.solve` and
:func:`~spinimpact.solve_sphere` accept (``tangential=law``).

* :class:`Walton`: the three-parameter model of DEM practice (normal restitution ``kappa``,
  friction ``mu`` and the tangential restitution ``beta0`` of sticking impacts).
* :class:`Stronge`: Stronge's lumped-parameter contact, a normal and a tangential spring
  whose stiffness ratio follows from Poisson's ratio (Mindlin).
* :class:`MindlinDeresiewicz`: Hertz contact, elastic in shear with Coulomb friction at
  every point of the contact area (micro-slip), solved in time or read from a precomputed
  table (the model closest to the measured bounces of ``docs/validation.md``).

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

import numpy as np

from .._validation import check, scalar, whole
from ..core import compliance as kernels
from ..core import mdr, mdr_table
from ..core.scalar_tangential import stronge_contact, walton_contact
from . import _fast_tangential
from .body import Body
from .compliant import (
    CompliantImpact,
    CompliantSphereImpact,
    solve_compliant,
    solve_sphere_compliant,
)
from .impact import State

__all__ = ["TangentialLaw", "Walton", "Stronge", "MindlinDeresiewicz", "CompliantImpact",
           "CompliantSphereImpact"]  # fmt: skip


def _number(name: str, value: Any, low: float, high: float, rule: str) -> float:
    x = scalar(name, value)
    if not low <= x <= high:
        raise ValueError(f"{name} must be {rule}, got {x!r}")
    return x


def _set_ratio(law: Any) -> None:
    """Validate a law's ``poisson_ratio`` or ``stiffness_ratio`` (one of the two) and set
    ``stiffness_ratio`` (Mindlin's ``2(1 - nu)/(2 - nu)`` from Poisson's ratio)."""
    name = type(law).__name__
    nu, ratio = law.poisson_ratio, law.stiffness_ratio
    if (nu is None) == (ratio is None):
        raise TypeError(f"{name} takes one of poisson_ratio and stiffness_ratio, "
                        f"got poisson_ratio={nu!r}, stiffness_ratio={ratio!r}")  # fmt: skip
    if nu is not None:
        nu = scalar("poisson_ratio", nu)
        if not -1.0 < nu <= 0.5:
            raise ValueError(f"poisson_ratio must be in (-1, 0.5], got {nu!r}")
        object.__setattr__(law, "poisson_ratio", nu)
        ratio = float(kernels.mindlin_stiffness_ratio(nu))
    else:
        ratio = _number("stiffness_ratio", ratio, 0.0, 1e12, "in (0, 1e12]")
        if ratio == 0.0:
            raise ValueError("stiffness_ratio must be in (0, 1e12], got 0.0")
    object.__setattr__(law, "stiffness_ratio", ratio)


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

    def kappa_ok(self, kappa: Any) -> np.ndarray:
        """Where the law can take the restitution ``kappa`` (already in ``[0, 1]``): all."""
        return np.ones(np.shape(kappa), dtype=bool)

    def check_kappa(self, kappa: Any) -> None:
        """Raise ``ValueError`` naming ``kappa`` (and the first index) where the law cannot
        take it (:meth:`kappa_ok`)."""
        check("kappa", np.asarray(kappa, dtype=float), self.kappa_ok, self.kappa_rule)

    kappa_rule: ClassVar[str] = "in [0, 1]"

    def to_dict(self) -> dict[str, Any]:
        """The law's name and parameters as plain Python values."""
        return {"law": self.name, **{k: v for k, v in vars(self).items()}}

    def _solve_plane(self, body: Any, vx: Any, vy: Any, omega: Any, *, mu: Any,
                     kappa: Any) -> CompliantImpact:  # fmt: skip
        scalar = self._on_floats()  # the law on floats, and its parameter
        if scalar is not None and isinstance(body, Body):
            one = _fast_tangential.plane_impact(
                scalar[0], scalar[1], (CompliantImpact, State), body, vx, vy, omega, mu, kappa,
                self.frictionless, self)  # fmt: skip
            if one is not None:  # one impact of plain numbers: the same result, in microseconds
                return one
        return solve_compliant(self, body, vx, vy, omega, mu=mu, kappa=kappa)

    def _on_floats(self) -> tuple | None:
        """``(rule, parameter)``: the law's per-contact function on floats,
        ``rule(slip, vy, zeta, mu, kappa, parameter) -> (slip_after, stuck, ...)``, for the
        scalar path of one impact; ``None`` where there is none (a subclass may change
        ``rebound_slip``)."""
        scalar = _SCALAR.get(type(self))
        return None if scalar is None else (scalar[0], getattr(self, scalar[1]))

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
        _set_ratio(self)

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


#: Most springs * steps of :class:`MindlinDeresiewicz` (its tables: a few of this many floats).
MAX_CELLS = 2**24


@dataclass(frozen=True)
class MindlinDeresiewicz(TangentialLaw):
    """Hertz normal contact with Mindlin-Deresiewicz tangential contact: elastic in shear,
    Coulomb friction at every point of the contact area (micro-slip), under the impact's
    whole loading history.

    Give one of ``poisson_ratio`` and ``stiffness_ratio``.

    Parameters
    ----------
    poisson_ratio : float, optional
        Poisson's ratio ``nu`` in ``(-1, 0.5]``; Mindlin's ratio ``4 G*/E* = 2(1 - nu)/(2 - nu)``
        (one material, or a rigid plane).
    stiffness_ratio : float, optional
        ``4 G*/E*`` directly (two materials:
        :func:`spinimpact.core.tangential.mindlin_stiffness_ratio`).
    springs, steps : int
        Resolution: springs of the reduced contact and time steps of an impact (defaults
        256 and 2048: within ``1e-5`` of ``|v_n^-|`` of four times finer in the slip after
        on random impacts with ``mu <= 0.8``; within ``5e-5`` in the no-slip limit).
    method : {"table", "integrate"}
        ``"table"`` (the default): the impacts inside the precomputed table's range
        (:mod:`spinimpact.core.mdr_table`: ``kappa`` in ``[0.85, 1]``, ``zeta r`` in
        ``[2, 4]``, ``(1 + kappa) zeta mu`` small enough for its error, the default
        resolution) are read from it, within ``1e-4`` of ``|v_n^-|`` of the solution in time
        in the slip after, in microseconds; every other impact is solved in time.
        ``"integrate"``: every impact is solved in time.

    Notes
    -----
    The normal force is Hertz's with Hunt-Crossley damping calibrated to ``kappa`` (Newton's
    restitution, in ``(0, 1]``); with a Hertz contact the rebound depends on the incidence
    through ratios only, so no modulus, size or speed is needed. The contact is solved in
    time by the method of dimensionality reduction (Popov and Hess), which for a paraboloid
    reproduces the half-space solutions of Cattaneo-Mindlin and Mindlin-Deresiewicz; see
    :mod:`spinimpact.core.mdr`. The contact is taken to be circular (a sphere's); with a
    non-spherical :class:`~spinimpact.Body` only its mass, inertia and contact radius enter.
    Cost: about ``springs * steps`` operations per impact, impacts stepped together
    (``python -m benchmarks.compliance`` measures it), and tens of milliseconds for each
    distinct ``kappa``; an impact read from the table costs about what Walton's law costs
    (``docs/compliance.md``).

    Examples
    --------
    >>> from spinimpact import Body, MindlinDeresiewicz, solve
    >>> law = MindlinDeresiewicz(poisson_ratio=0.23)
    >>> ball = Body.solid_sphere(mass=1.0, radius=0.1)
    >>> imp = solve(ball, [0.05, 0.5], -1.0, 0.0, mu=0.3, kappa=1.0, tangential=law)
    >>> imp.regime.tolist(), imp.tangential_restitution.round(2).tolist()
    (['stick', 'slip-reversal'], [-0.27, 0.17])
    """

    poisson_ratio: float | None = None
    stiffness_ratio: float | None = None
    springs: int = 256
    steps: int = 2048
    method: str = "table"
    name: ClassVar[str] = "mindlin-deresiewicz"

    def __post_init__(self) -> None:
        _set_ratio(self)
        for key, low in (("springs", 1), ("steps", 8)):
            value = whole(key, getattr(self, key))
            if value < low:
                raise ValueError(f"{key} must be at least {low}, got {value!r}")
            object.__setattr__(self, key, value)
        if self.springs * self.steps > MAX_CELLS:  # the tables of one kappa: 8 bytes a cell
            raise ValueError(f"springs * steps must be at most {MAX_CELLS} (memory), got "
                             f"{self.springs} * {self.steps}")  # fmt: skip
        if self.method not in ("table", "integrate"):
            raise ValueError(f"method must be 'table' or 'integrate', got {self.method!r}")

    kappa_rule: ClassVar[str] = ("> 0 under MindlinDeresiewicz (Hunt-Crossley damping "
                                 "cannot stop the ball: kappa in (0, 1])")  # fmt: skip

    def kappa_ok(self, kappa: Any) -> np.ndarray:
        """``kappa > 0``: Hunt-Crossley damping cannot make a Hertz impact perfectly plastic."""
        return np.asarray(kappa) > 0.0

    def rebound_slip(self, slip: Any, vy: Any, zeta: Any, mu: Any, kappa: Any) -> tuple:
        solver = mdr_table.table_slip if self.method == "table" else mdr.mdr_slip
        return solver(slip, vy, zeta, mu, kappa, self.stiffness_ratio, springs=self.springs,
                      steps=self.steps)  # fmt: skip

    def _on_floats(self) -> tuple | None:
        """The table's impact on floats, compiled
        (:func:`~spinimpact.core.mdr_table_kernel.contact_one`), where this law reads the
        table (the default method and resolution) and Numba is installed; ``None``
        otherwise. Without Numba the array path reads the table with NumPy, whose sums
        differ from the law on floats in the last bit, so one impact takes that path too."""
        from ..core import mdr_table_kernel  # imported here: Numba is heavy, and optional

        table = mdr_table.load_table()
        if (type(self) is not MindlinDeresiewicz or self.method != "table"
                or (self.springs, self.steps) != (table.springs, table.steps)
                or not mdr_table_kernel.HAVE_NUMBA):  # fmt: skip
            return None
        return mdr_table_kernel.contact_one, self.stiffness_ratio

    def __repr__(self) -> str:
        which = ("poisson_ratio", self.poisson_ratio)
        if self.poisson_ratio is None:
            which = ("stiffness_ratio", self.stiffness_ratio)
        extra = (
            ""
            if (self.springs, self.steps) == (256, 2048)
            else (f", springs={self.springs}, steps={self.steps}")
        )
        if self.method != "table":
            extra += f", method={self.method!r}"
        return f"MindlinDeresiewicz({which[0]}={which[1]!r}{extra})"


#: The laws whose one impact of plain numbers takes the scalar path
#: (:mod:`spinimpact.model._fast_tangential`): their per-contact function on floats and the
#: name of its parameter. A subclass is not in it (it may change ``rebound_slip``).
_SCALAR = {Walton: (walton_contact, "beta0"), Stronge: (stronge_contact, "stiffness_ratio")}
