"""One planar impact in microseconds: the scalar path of :func:`~spinimpact.solve_planar`
and :func:`~spinimpact.solve_pendulum`.

As :mod:`spinimpact.model._fast` does for :func:`~spinimpact.solve`: when ``vx, vy,
omega, mu, kappa`` are plain numbers (or arrays of one element) and the body's numbers
floats, :func:`planar_impact` computes every field with the planar law on floats
(:mod:`spinimpact.core.scalar_planar`) and the body's own methods, in the array path's
operations and order: the same :class:`~spinimpact.PlanarImpact` field for field, bit for
bit (NaN where it is NaN; ``tests/model/test_fast_planar.py``,
``tests/model/test_fast_paths.py``). :func:`pendulum_impact` does the same for a
pendulum's spin. Anything else, or a value the array path would refuse, returns ``None``
and the array path runs, raising the usual errors.
"""

from __future__ import annotations

from typing import Any

from .._validation import SMALLEST
from ..core import scalar_planar as law
from ..core.planar import LAWS, PLANAR_REGIMES
from ._fast import numbers
from ._fast_result import Layout, layout_for

__all__ = ["pendulum_impact", "planar_impact"]

_REGIMES = tuple(PLANAR_REGIMES)  #: plain str, as the array path's ``freeze`` gives
_ENERGY_RTOL = 1e-12  # as model.planar: a rise of the energy beyond rounding


def _layout(kind: type, state: type) -> Layout:
    motion = Layout(state, ("vx", "vy", "omega"))
    return Layout(
        kind,
        ("mu", "kappa", "slip_before", "slip_after", "normal_velocity_before",
         "normal_velocity_after", "tau0", "tau_star", "tau1", "tangential_impulse",
         "impulse_ratio", "kinetic_energy_before", "kinetic_energy_after", "dissipated_energy",
         "dissipated_fraction", "work_compression_normal", "work_compression_tangential",
         "work_restitution_normal", "work_restitution_tangential", "min_kinetic_energy",
         "tau_min_energy", "newton_restitution", "poisson_restitution",
         "energetic_restitution"),
        nested=(("before", motion), ("after", motion)), flags=("creates_energy",),
        text={"regime": _REGIMES}, given=("body", "law"),
    )  # fmt: skip


def planar_impact(kind: type, state: type, body: Any, vx: Any, vy: Any, omega: Any, mu: Any,
                  kappa: Any, law_name: Any) -> Any:  # fmt: skip
    """The :class:`~spinimpact.PlanarImpact` (or ``PendulumImpact``) of one impact, or
    ``None`` for the array path.

    Parameters
    ----------
    kind, state : type
        The result class and :class:`~spinimpact.State`.
    body : PlanarBody or Pendulum
        The body (already checked).
    vx, vy, omega, mu, kappa, law_name : object
        As given to the solver (``law_name`` already checked to be one of the laws).
    """
    for name in body.COLUMNS:
        if type(getattr(body, name)) is not float:
            return None
    given = numbers((vx, vy, omega, mu, kappa), ("vx", "vx", "omega", "mu", "kappa"))
    if given is None:
        return None
    (vx_, vy_, om_, mu_, k), shape = given
    return _impact(kind, state, body, vx_, vy_, om_, mu_, k, law_name, shape)


def pendulum_impact(kind: type, state: type, pendulum: Any, omega: Any, mu: Any, kappa: Any,
                    law_name: Any) -> Any:  # fmt: skip
    """:func:`planar_impact` of a :class:`~spinimpact.Pendulum` given its spin alone (the
    centre's velocity ``(-omega gy, omega gx)`` as the pendulum computes it), or ``None``;
    also ``None`` for a ``law_name`` that is not one of the laws (the array path says so)."""
    if type(law_name) is not str or law_name not in LAWS:
        return None
    for name in pendulum.COLUMNS:
        if type(getattr(pendulum, name)) is not float:
            return None
    given = numbers((omega, mu, kappa), ("omega", "mu", "kappa"))
    if given is None:
        return None
    (om, mu_, k), shape = given
    vx, vy = pendulum.centre_velocity(om)
    return _impact(kind, state, pendulum, vx, vy, om, mu_, k, law_name, shape)


def _impact(kind: type, state: type, body: Any, vx_: float, vy_: float, om_: float,
            mu_: float, k: float, law_name: str, shape: tuple[int, ...] | None) -> Any:  # fmt: skip
    u0, v0 = body.contact_velocity(vx_, vy_, om_)
    if not v0 <= -SMALLEST:
        return None  # the array path says why (as solve refuses |vy| < SMALLEST)
    w = body.collision_matrix
    a, b, d = w.tt, w.tn, w.nn
    code, tau_s, tau_c, tau_f, _, _, f1, u1, vn1 = law.planar_process(
        u0, v0, a, b, d, mu_, k, LAWS.index(law_name)
    )
    vx1, vy1, om1 = body.apply_impulse(vx_, vy_, om_, f1, tau_f)
    contact = (u0, v0, a, b, d, mu_)
    wcn, wct = law.planar_work(0.0 * tau_f, tau_c, *contact, tau_s)
    wrn, wrt = law.planar_work(tau_c, tau_f, *contact, tau_s)
    e0 = body.kinetic_energy(vx_, vy_, om_)
    loss = -(wcn + wct + wrn + wrt)
    tau_m = law.planar_min_energy_impulse(*contact, tau_s, tau_f)
    f_m = law.planar_state_at(tau_m, *contact, tau_s)[0]
    at_min = body.apply_impulse(vx_, vy_, om_, f_m, tau_m)
    eta2 = law._divide(-wrn, wcn)
    layout = layout_for(_layout, kind, state)
    floats = (
        mu_, k, u0, u1, v0, vn1, tau_c, tau_s, tau_f, f1, law._divide(f1, tau_f), e0,
        body.kinetic_energy(vx1, vy1, om1), loss, law._divide(loss, e0), wcn, wct, wrn, wrt,
        body.kinetic_energy(*at_min), tau_m, -vn1 / v0, law._divide(tau_f - tau_c, tau_c),
        law._sqrt(law._maximum(eta2, 0.0)), vx_, vy_, om_, vx1, vy1, om1,
    )  # fmt: skip
    flags = (loss < -_ENERGY_RTOL * e0,)
    return layout.result(floats, flags, {"body": body, "law": law_name,
                                         "regime": _REGIMES[code]}, shape)  # fmt: skip
