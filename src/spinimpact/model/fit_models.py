"""The models :func:`spinimpact.fit` fits: parameters, bounds and the vectorized rebound.

A model maps a parameter vector to the predicted rebound ``(after_vx, after_vy,
after_omega)`` of every bounce at once. The rigid model is the kernel
:func:`spinimpact.core.kinematics.rebound` that :func:`spinimpact.solve` builds its
``after`` state from (one call over all bounces, no loop); the normal restitution is a
constant ``kappa``, a power law of the impact speed ``|vy|`` or a table interpolated
linearly in ``|vy|`` (the :class:`~spinimpact.TabulatedRestitution` of the fitted knots).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import as_real_array, check
from . import compliance
from .body import Body
from .fit_data import MeasuredBounces
from .impact import solve

__all__ = ["Parameter", "FitModel", "make_model", "TANGENTIAL", "LAWS", "MU_INFINITY"]

#: The tangential compliance laws of :mod:`spinimpact.model.compliance` a fit can use:
#: model name -> (class name, its parameter, low, high, meaning). A law is offered when
#: the module defines it.
LAWS = {
    "walton": ("Walton", "beta0", -1.0, 1.0, "tangential restitution of sticking impacts"),
    "stronge": ("Stronge", "poisson_ratio", -0.999, 0.5, "Poisson's ratio (Mindlin's k_t/k_n)"),
    "mindlin-deresiewicz": (
        "MindlinDeresiewicz",
        "poisson_ratio",
        -0.999,
        0.5,
        "Poisson's ratio (Mindlin's k_t/k_n), with micro-slip",
    ),
}
#: Tangential models: the rigid Coulomb contact of the paper, then each compliance law.
TANGENTIAL = ("rigid", *(k for k, v in LAWS.items() if hasattr(compliance, v[0])))
#: A friction coefficient at which every realistic bounce sticks, and the largest that
#: :func:`~spinimpact.solve` accepts: the upper bound of ``mu`` in a fit, where its
#: profile is evaluated to decide whether the data bound ``mu`` from above at all.
MU_INFINITY = 1e6


@dataclass(frozen=True)
class Parameter:
    """One parameter of a model: its name, bounds, unit and meaning."""

    name: str
    low: float
    high: float
    unit: str
    meaning: str


@dataclass(frozen=True, eq=False)
class FitModel:
    """A model of the rebound with named parameters (see :func:`make_model`)."""

    tangential: str
    restitution: str
    parameters: tuple[Parameter, ...]
    body: Body
    knots: np.ndarray | None = None
    reference_speed: float = 1.0

    @property
    def names(self) -> tuple[str, ...]:
        """Parameter names, in the order of a parameter vector."""
        return tuple(p.name for p in self.parameters)

    @property
    def description(self) -> str:
        """The model in words, e.g. ``rigid, constant kappa``."""
        kinds = {
            "constant": "constant kappa",
            "power": f"kappa = kappa_ref (|vy|/{self.reference_speed:.4g} m/s)^exponent",
            "tabulated": "kappa tabulated in |vy|",
        }
        return f"{self.tangential}, {kinds[self.restitution]}"

    def values(self, theta: Any) -> dict[str, Any]:
        """Parameter vector to a name -> value dictionary (an entry may be an array of
        values, which broadcasts against the bounces: a scan over it in one call)."""
        return {n: float(v) if np.ndim(v) == 0 else np.asarray(v)
                for n, v in zip(self.names, theta, strict=True)}  # fmt: skip

    def kappa(self, p: dict[str, float], speed: np.ndarray) -> np.ndarray:
        """Normal restitution at impact speeds ``|vy|`` (m/s), clipped to ``[0, 1]``."""
        if self.restitution == "constant":
            k = np.full(np.shape(speed), p["kappa"])
        elif self.restitution == "power":
            k = p["kappa_ref"] * (np.asarray(speed) / self.reference_speed) ** p["exponent"]
        else:
            k = np.interp(speed, self.knots, [p[n] for n in _knot_names(self.knots)])
        return np.clip(k, 0.0, 1.0)

    def zeta(self, p: dict[str, float]) -> Any:
        """``zeta = 1 + R^2/rho^2`` of the body, with the fitted gyration if it is free."""
        if "gyration" in p:
            return 1.0 + (np.asarray(self.body.radius) / p["gyration"]) ** 2
        return self.body.zeta

    def _body(self, p: dict[str, float]) -> Body:
        b = self.body
        if "gyration" not in p:
            return b
        return Body(mass=b.mass, radius=b.radius, gyration=p["gyration"], name=b.name)

    def _compliant(self, p: dict[str, float], bounces: MeasuredBounces) -> Any:
        """:func:`~spinimpact.solve` under the compliance law, on all bounces at once."""
        cls, name = getattr(compliance, LAWS[self.tangential][0]), LAWS[self.tangential][1]
        law = cls(**{name: p[name]})
        kappa = self.kappa(p, -bounces.vy)
        return solve(self._body(p), bounces.vx, bounces.vy, bounces.omega, mu=p["mu"],
                     kappa=kappa, tangential=law)  # fmt: skip

    def predict(self, theta: np.ndarray, bounces: MeasuredBounces) -> np.ndarray:
        """Predicted rebound of every bounce, shape ``(n, 3)``: ``vx^+, vy^+, omega^+``.

        The rigid model calls the kernel :func:`spinimpact.core.kinematics.rebound` that
        :func:`spinimpact.solve` builds its ``after`` state from (the same numbers, without
        the other fields); a compliance model calls ``solve(..., tangential=law)``."""
        p = self.values(theta)
        if self.tangential != "rigid":
            a = self._compliant(p, bounces).after
            return np.stack(np.broadcast_arrays(a.vx, a.vy, a.omega), axis=-1)
        kappa = self.kappa(p, -bounces.vy)
        b = self.body
        vx1, vy1, om1, _ = core.rebound(bounces.vx, bounces.vy, bounces.omega, b.mass, b.radius,
                                        self.zeta(p), p["mu"], kappa)  # fmt: skip
        return np.stack(np.broadcast_arrays(vx1, vy1, om1), axis=-1)

    def contact(self, theta: np.ndarray, bounces: MeasuredBounces) -> tuple[np.ndarray, np.ndarray]:
        """Which bounces slide throughout at ``theta`` (regime ``slip``, eq. 4.15) and
        which stick (``stick-compression``, ``stick-restitution``; under a compliance law
        ``stick`` and ``slip-reversal``): only sliding bounces measure ``mu``; a sticking
        one only says ``mu`` is large enough to stop its slip."""
        p = self.values(theta)
        if self.tangential != "rigid":
            regime = np.asarray(self._compliant(p, bounces).regime)
            return regime == "slip", (regime == "stick") | (regime == "slip-reversal")
        kappa = self.kappa(p, -bounces.vy)
        slip = core.slip_velocity(bounces.vx, bounces.omega, self.body.radius)
        code = np.asarray(core.regime_code(slip, bounces.vy, self.zeta(p), p["mu"], kappa))
        regime = np.asarray(core.REGIMES)[code]
        return regime == "slip", (regime == "stick-compression") | (regime == "stick-restitution")

    def scale(self) -> np.ndarray:
        """Unit weights when no sigmas are given: m/s for velocities, ``R omega`` for spin."""
        return np.array([1.0, 1.0, float(np.mean(self.body.radius))])


def _knot_names(knots: np.ndarray) -> list[str]:
    return [f"kappa_at_{s:g}" for s in knots]


def make_model(
    body: Body,
    bounces: MeasuredBounces,
    *,
    tangential: str = "rigid",
    restitution: str | Sequence[float] = "constant",
    free_gyration: bool = False,
    reference_speed: float | None = None,
) -> FitModel:
    """The :class:`FitModel` named by the options of :func:`spinimpact.fit`.

    Parameters
    ----------
    body : Body
        The body (its radius converts spin to contact-point speed).
    bounces : MeasuredBounces
        The data (for the default reference speed of a power law).
    tangential : str
        One of :data:`TANGENTIAL`: ``"rigid"``, or a compliance law of
        :mod:`spinimpact.model.compliance` with its parameter fitted (``"walton"``:
        ``beta0``; ``"stronge"``: ``poisson_ratio``).
    restitution : {"constant", "power"} or sequence of float
        ``kappa`` constant; ``kappa = kappa_ref (|vy|/v_ref)^exponent``; or knot speeds
        (m/s, increasing) at which ``kappa`` is fitted and interpolated linearly.
    free_gyration : bool
        Fit the body's radius of gyration ``rho`` (m) too.
    reference_speed : float, optional
        ``v_ref`` of the power law, m/s (default: the geometric mean of ``|vy|``, which
        makes ``kappa_ref`` and ``exponent`` nearly uncorrelated).

    Raises
    ------
    TypeError, ValueError
        For an unknown model or bad knots.
    """
    if not isinstance(body, Body):
        raise TypeError(f"body must be a spinimpact.Body, got {type(body).__name__}")
    if not isinstance(tangential, str):
        raise TypeError(f"model must be one of {', '.join(TANGENTIAL)}, got {tangential!r}")
    if tangential not in TANGENTIAL:
        raise ValueError(f"model must be one of {', '.join(TANGENTIAL)}, got {tangential!r}")
    # mu is bounded by MU_INFINITY, solve's own bound: the optimizer never leaves its domain
    params = [Parameter("mu", 0.0, MU_INFINITY, "", "Coulomb friction coefficient")]
    if tangential in LAWS:
        _, name, low, high, meaning = LAWS[tangential]
        params.append(Parameter(name, low, high, "", meaning))
    knots = None
    speeds = -bounces.vy
    vref = float(np.exp(np.mean(np.log(speeds)))) if reference_speed is None else reference_speed
    if isinstance(restitution, str):
        if restitution == "constant":
            params.append(Parameter("kappa", 0.0, 1.0, "", "normal restitution"))
        elif restitution == "power":
            params += [
                Parameter(
                    "kappa_ref", 0.0, 1.0, "", f"normal restitution at |vy| = {vref:.4g} m/s"
                ),
                Parameter("exponent", -5.0, 5.0, "", "power of |vy| in kappa"),
            ]
        else:
            raise ValueError(
                f"restitution must be 'constant', 'power' or knot speeds, got {restitution!r}"
            )
        kind = restitution
    else:
        knots = as_real_array("knots", restitution)
        if knots.ndim != 1 or knots.size < 2:
            raise ValueError(f"knots must be at least two speeds, got {knots.tolist()!r}")
        check("knots", knots, lambda s: s > 0, "> 0 (impact speeds |vy|, m/s)")
        if np.any(np.diff(knots) <= 0):
            raise ValueError(f"knots must be strictly increasing, got {knots.tolist()!r}")
        params += [Parameter(n, 0.0, 1.0, "", f"normal restitution at |vy| = {s:g} m/s")
                   for n, s in zip(_knot_names(knots), knots, strict=True)]  # fmt: skip
        kind = "tabulated"
    if free_gyration:
        low = 1e-3 * float(np.min(body.radius))  # keeps zeta = 1 + R^2/rho^2 finite
        params.append(Parameter("gyration", low, np.inf, "m", "radius of gyration rho"))
    return FitModel(tangential, kind, tuple(params), body, knots, vref)
