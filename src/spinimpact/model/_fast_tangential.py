"""One impact under a tangential law in microseconds: the scalar path of
``solve(..., tangential=Walton(...))``, ``tangential=Stronge(...)`` and
``tangential=MindlinDeresiewicz(...)`` where its table holds.

As :mod:`spinimpact.model._fast` does for the rigid law: when ``vx, vy, omega, mu, kappa``
are plain numbers (or arrays of one element) and the body's numbers are floats,
:func:`plane_impact` computes every field of :class:`~spinimpact.CompliantImpact` with the
law's per-contact function on floats (:func:`spinimpact.core.scalar_tangential.walton_contact`,
:func:`~spinimpact.core.scalar_tangential.stronge_contact`, which the array kernels run row
by row) and the seam's impulses, in the operations and order of
:func:`spinimpact.model.compliant.solve_compliant`: the same result, field for field, bit
for bit (``tests/model/test_fast_paths.py``). Anything else returns ``None`` and the array
path runs, raising the usual errors.
"""

from __future__ import annotations

import math
from typing import Any

from ..core import impulse
from ..core import scalar as law
from ..core import scalar_tangential as tangential
from ..core.compliance import COMPLIANT_REGIMES
from ..core.kinematics import slip_velocity
from ._fast import paper_numbers
from ._fast_result import Layout, layout_for

__all__ = ["plane_impact"]

_REGIMES = tuple(COMPLIANT_REGIMES)


def _layout(kind: type, state: type) -> Layout:
    motion = Layout(state, ("vx", "vy", "omega"))
    return Layout(
        kind,
        ("mu", "kappa", "slip_before", "slip_after", "tangential_restitution",
         "centre_tangential_restitution", "tau0", "tau1", "tangential_impulse",
         "impulse_ratio", "kinetic_energy_before", "kinetic_energy_after",
         "dissipated_energy", "dissipated_fraction", "newton_restitution"),
        nested=(("before", motion), ("after", motion)), text={"regime": _REGIMES},
        given=("body", "law"),
    )  # fmt: skip


def _ratio(num: float, den: float) -> float:
    """``num/den``, NaN where ``den = 0`` (``model.compliant._ratio`` on floats)."""
    return num / den if den != 0.0 else math.nan


def regime_code(slip: float, slip_after: float, mu: float, stuck: bool,
                frictionless: bool) -> int:  # fmt: skip
    """:func:`spinimpact.core.compliance.compliant_regime_code` of one impact: 0
    frictionless, 1 no-slip, 2 stick, 3 slip-reversal, 4 slip."""
    if mu == 0.0 or frictionless:
        return 0
    if slip == 0.0:
        return 1
    if stuck:
        return 3 if slip_after * slip < 0.0 else 2
    return 4


def plane_impact(rule: Any, parameter: float, kinds: tuple, body: Any, vx: Any, vy: Any,
                 omega: Any, mu: Any, kappa: Any, frictionless: bool,
                 given_law: Any) -> Any:  # fmt: skip
    """The :class:`~spinimpact.CompliantImpact` of one impact, or ``None``.

    Parameters
    ----------
    rule : callable
        The law on the seam, ``rule(slip, vy, zeta, mu, kappa, parameter)`` returning
        ``(slip_after, stuck, ...)`` (``walton_contact``, ``stronge_contact``, the micro-slip
        table's ``mdr_contact``); a NaN ``slip_after`` from a finite slip means the rule
        cannot answer this impact on floats (outside the micro-slip table), and the array
        path runs.
    parameter : float
        Its parameter (``beta0``, ``stiffness_ratio``).
    kinds : tuple
        ``(CompliantImpact, State)``.
    body, vx, vy, omega, mu, kappa
        As given to :func:`~spinimpact.solve` (``body`` already checked to be a body).
    frictionless : bool
        The law applies no friction (Walton's ``beta0 = -1``).
    given_law : TangentialLaw
        The law object, kept in the result.
    """
    given = paper_numbers(body, vx, vy, omega, mu, kappa)
    if given is None:
        return None
    (m, r, z, inertia), (vx_, vy_, om_, mu_, k), shape = given
    slip = slip_velocity(vx_, om_, r)
    out = rule(slip, vy_, z, mu_, k, parameter)
    slip1, stuck = out[0], out[1]
    if math.isnan(slip1) and not math.isnan(slip):  # the rule cannot answer on floats here
        return None
    f1 = tangential.tangential_impulse_of(m, z, slip, slip1)
    vx1, om1 = tangential.impulse_to_body(vx_, om_, m, r, z, f1)
    vy1 = impulse.rebound_normal_velocity(vy_, k)
    tau0 = impulse.compression_impulse(m, vy_)
    tau1 = impulse.total_impulse(m, vy_, k)
    e0 = law.kinetic_energy(vx_, vy_, om_, m, inertia)
    e1 = law.kinetic_energy(vx1, vy1, om1, m, inertia)
    floats = (
        mu_, k, slip, slip1, _ratio(-slip1, slip), _ratio(vx1, vx_), tau0, tau1, f1, f1 / tau1,
        e0, e1, e0 - e1, (e0 - e1) / e0, -vy1 / vy_, vx_, vy_, om_, vx1, vy1, om1,
    )  # fmt: skip
    code = regime_code(slip, slip1, mu_, stuck, frictionless)
    rest = {"body": body, "law": given_law, "regime": _REGIMES[code]}
    return layout_for(_layout, *kinds).result(floats, (), rest, shape)
