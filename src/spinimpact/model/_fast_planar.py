"""One planar impact in microseconds: the scalar path of :func:`~spinimpact.solve_planar`
and :func:`~spinimpact.solve_pendulum`.

As :mod:`spinimpact.model._fast` does for :func:`~spinimpact.solve`: when ``vx, vy,
omega, mu, kappa`` are plain numbers and the body's numbers floats, :func:`planar_impact`
computes every field with the planar law on floats (:mod:`spinimpact.core.scalar_planar`)
and the body's own methods, in the array path's operations and order: the same
:class:`~spinimpact.PlanarImpact` field for field, bit for bit (NaN where it is NaN;
``tests/model/test_fast_planar.py``). Anything else, or a value the array path would refuse,
returns ``None`` and the array path runs, raising the usual errors.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validation import SMALLEST
from ..core import scalar_planar as law
from ..core.planar import LAWS, PLANAR_REGIMES
from ._fast import build, number

__all__ = ["planar_impact"]

_FLOAT = np.float64
_REGIMES = tuple(PLANAR_REGIMES)  #: plain str, as the array path's ``freeze`` gives
_ENERGY_RTOL = 1e-12  # as model.planar: a rise of the energy beyond rounding


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
    if callable(kappa) or not all(type(getattr(body, n)) is float for n in body.COLUMNS):
        return None
    vx_, vy_, om_ = number(vx, "vx"), number(vy, "vx"), number(omega, "omega")
    mu_, k = number(mu, "mu"), number(kappa, "kappa")
    if vx_ is None or vy_ is None or om_ is None or mu_ is None or k is None:
        return None
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
    f = _FLOAT
    return build(kind, {
        "body": body, "law": law_name, "mu": f(mu_), "kappa": f(k),
        "before": build(state, {"vx": f(vx_), "vy": f(vy_), "omega": f(om_)}),
        "after": build(state, {"vx": f(vx1), "vy": f(vy1), "omega": f(om1)}),
        "slip_before": f(u0), "slip_after": f(u1), "normal_velocity_before": f(v0),
        "normal_velocity_after": f(vn1), "regime": _REGIMES[code], "tau0": f(tau_c),
        "tau_star": f(tau_s), "tau1": f(tau_f), "tangential_impulse": f(f1),
        "impulse_ratio": f(law._divide(f1, tau_f)), "kinetic_energy_before": f(e0),
        "kinetic_energy_after": f(body.kinetic_energy(vx1, vy1, om1)),
        "dissipated_energy": f(loss), "dissipated_fraction": f(law._divide(loss, e0)),
        "work_compression_normal": f(wcn), "work_compression_tangential": f(wct),
        "work_restitution_normal": f(wrn), "work_restitution_tangential": f(wrt),
        "min_kinetic_energy": f(body.kinetic_energy(*at_min)), "tau_min_energy": f(tau_m),
        "newton_restitution": f(-vn1 / v0),
        "poisson_restitution": f(law._divide(tau_f - tau_c, tau_c)),
        "energetic_restitution": f(law._sqrt(law._maximum(eta2, 0.0))),
        "creates_energy": np.True_ if loss < -_ENERGY_RTOL * e0 else np.False_,
    })  # fmt: skip
