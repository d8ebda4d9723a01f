"""Many planar impacts in one pass over memory: the fused path of ``solve_planar`` and
``solve_pendulum``.

For arrays of at least :data:`THRESHOLD` impacts and with Numba installed, the solvers
validate their inputs and form the contact's velocities and collision matrix as always, then
take every other field from :mod:`spinimpact.core.fused_planar` (one compiled pass, in
parallel) instead of the NumPy kernels; the fields are equal bit for bit
(``tests/model/test_fused_planar.py``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._validation import available
from ..core.planar import LAWS, PLANAR_REGIMES
from .planar_body import Pendulum

__all__ = ["THRESHOLD", "planar_impact"]

#: Fewest impacts for which the fused path is taken (the NumPy path remains for 0-d input,
#: empty arrays and without Numba).
THRESHOLD = 1


def _owned(a: np.ndarray) -> np.ndarray:
    view = a.view()
    view.setflags(write=False)
    return view


def _frozen(a: Any) -> np.ndarray:
    out = np.array(a)
    out.setflags(write=False)
    return out


def planar_impact(kind: type, state: type, body: Any, law: str, vx: np.ndarray,
                  vy: np.ndarray, omega: np.ndarray, slip: np.ndarray, vn: np.ndarray,
                  a: np.ndarray, b: np.ndarray, d: np.ndarray, mu: np.ndarray,
                  kappa: np.ndarray, *, threshold: int | None = None) -> Any:  # fmt: skip
    """The result of many planar impacts from the fused kernel, or ``None``.

    Parameters
    ----------
    kind, state : type
        The result class (:class:`~spinimpact.PlanarImpact` or ``PendulumImpact``) and
        :class:`~spinimpact.State`.
    body : PlanarBody or Pendulum
        The body, already validated.
    law : str
        One of :data:`~spinimpact.core.planar.LAWS`.
    vx, vy, omega, slip, vn, a, b, d, mu, kappa : ndarray
        The array path's validated, broadcast arrays: the incidence, the contact's slip and
        normal velocity, the collision matrix and the coefficients.
    threshold : int, optional
        Fewest impacts to take the fused path (default :data:`THRESHOLD`).

    Returns
    -------
    PlanarImpact, PendulumImpact or None
        ``None`` without Numba, for one impact (0-d) or below the threshold.
    """
    least = THRESHOLD if threshold is None else threshold
    if vx.ndim == 0 or vx.size == 0 or vx.size < least or not available("numba"):
        return None
    from ..core import fused_planar

    if not fused_planar.HAVE_NUMBA:
        return None
    if isinstance(body, Pendulum):
        params = (body.inertia_pivot, body.px, body.py, body.gx, body.gy)
    else:
        params = (body.rx, body.ry, 0.0, 0.0, 0.0)
    fields, code, creates = fused_planar.planar_fields(
        int(isinstance(body, Pendulum)), LAWS.index(law), vx, vy, omega, slip, vn, a, b, d,
        mu, kappa, body.mass, body.inertia, *params,
    )  # fmt: skip
    out = {name: _owned(v) for name, v in fields.items()}
    after = state(*(out.pop(f"after_{n}") for n in ("vx", "vy", "omega")))
    return kind(
        body=body, law=law, mu=_frozen(mu), kappa=_frozen(kappa),
        before=state(_frozen(vx), _frozen(vy), _frozen(omega)), after=after,
        slip_before=_frozen(slip), normal_velocity_before=_frozen(vn),
        regime=_owned(np.asarray(PLANAR_REGIMES)[code]), creates_energy=_owned(creates),
        **out,
    )  # fmt: skip
