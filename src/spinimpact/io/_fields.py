"""What a sweep computes at its points: the fields, named as the Impact's columns.

Each field is the :class:`~spinimpact.Impact` column of the same name, computed
from a chunk's inputs with the same core kernels that :func:`~spinimpact.solve`
calls, without building the whole result (so a sweep keeps the fused one-pass
rebound kernel). ``regime`` is the integer code of the Impact's text,
``spinimpact.core.REGIMES[code]``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .. import core
from ..core import fused

__all__ = ["ALIASES", "FIELDS", "REBOUND_FIELDS", "field_name", "rebound_fields"]

REBOUND_FIELDS = ("after_vx", "after_vy", "after_omega")


def _incidence(c: dict[str, Any], b: dict[str, float]) -> tuple[Any, ...]:
    """The kernels' arguments ``(vx, vy, omega, m, R, zeta, mu, kappa)`` of a chunk."""
    return (c["vx"], c["vy"], c["omega"], b["mass"], b["radius"], b["zeta"], c["mu"], c["kappa"])


def _slip(c: dict[str, Any], b: dict[str, float]) -> Any:
    return core.slip_velocity(c["vx"], c["omega"], b["radius"])


def rebound_fields(c: dict[str, Any], b: dict[str, float]) -> tuple[np.ndarray, ...]:
    """``after_vx, after_vy, after_omega`` of a chunk in one pass (:func:`fused.rebound`).

    Parameters
    ----------
    c : dict
        The chunk's inputs ``vx, vy`` (m/s), ``omega`` (rad/s), ``mu, kappa``.
    b : dict
        The body's ``mass`` (kg), ``radius`` (m), ``zeta`` and ``inertia`` (kg m^2).
    """
    return fused.rebound(*_incidence(c, b))  # one pass over memory (Numba) or NumPy


def _regime(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.regime_code(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


def _dissipated_energy(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.dissipated_energy(*_incidence(c, b))


def _dissipated_fraction(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    before = core.kinetic_energy(c["vx"], c["vy"], c["omega"], b["mass"], b["inertia"])
    return _dissipated_energy(c, b) / before


def _impulse_ratio(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.impulse_ratio(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


def _slip_after(c: dict[str, Any], b: dict[str, float]) -> np.ndarray:
    return core.rebound_slip(_slip(c, b), c["vy"], b["zeta"], c["mu"], c["kappa"])


#: Fields a sweep can write or reduce, each named as the :class:`~spinimpact.Impact`
#: column it equals, and how it is computed from a chunk's inputs ``c`` and body ``b``.
FIELDS: dict[str, Callable[[dict, dict], Any]] = {
    "after_vx": lambda c, b: rebound_fields(c, b)[0],  # m/s
    "after_vy": lambda c, b: rebound_fields(c, b)[1],  # m/s
    "after_omega": lambda c, b: rebound_fields(c, b)[2],  # rad/s
    "slip_before": _slip,  # m/s
    "slip_after": _slip_after,  # m/s
    "regime": _regime,  # integer code: spinimpact.core.REGIMES[code]
    "impulse_ratio": _impulse_ratio,  # 1
    "dissipated_energy": _dissipated_energy,  # J
    "dissipated_fraction": _dissipated_fraction,  # dissipated / incidence kinetic energy, 1
}

#: Older field names, still accepted: alias -> the field it means. A field asked
#: for by an alias is written under the alias, so existing scripts find their columns.
ALIASES: dict[str, str] = {"energy_loss": "dissipated_fraction"}


def field_name(name: str, role: str = "fields") -> str:
    """The :data:`FIELDS` name of ``name`` (itself, or what an alias stands for).

    Parameters
    ----------
    name : str
        A field or an alias.
    role : str
        What ``name`` was given as, for the message (``"fields"``, ``"histogram field"``).

    Raises
    ------
    ValueError
        For a name that is neither a field nor an alias.

    Examples
    --------
    >>> field_name("energy_loss")
    'dissipated_fraction'
    """
    if name in FIELDS:
        return name
    if name in ALIASES:
        return ALIASES[name]
    aliases = ", ".join(f"{a} for {f}" for a, f in ALIASES.items())
    raise ValueError(f"{role} must be among {', '.join(FIELDS)} (or {aliases}); got {name!r}")
