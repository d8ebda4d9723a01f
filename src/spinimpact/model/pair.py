"""``solve_pair()``: two spinning spheres colliding, in 3D (billiards, DEM, ball on ball).

Keller's method with the pair's collision matrix: the relative velocity of the contact
point changes with ``W = diag(W_tt, W_tt, W_nn)``, ``W_nn = 1/m_1 + 1/m_2``,
``W_tt = W_nn + R_1^2/J_1 + R_2^2/J_2`` (:func:`spinimpact.core.sphere3d.pair_parameters`),
isotropic in the tangent plane, so the slip keeps its direction and the paper's closed
forms hold along it with the reduced mass ``m* = 1/W_nn`` and ``zeta = W_tt/W_nn``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import core
from .._validation import approach, check, validated, vector3
from ..core import sphere3d as kernels
from . import _fast_sphere, _fused_sphere
from .body import Body, as_body, check_sphere
from .impact import _restitution
from .result import Array, Result, freeze
from .sphere3d import State3, Vector, _state, _summary, _vector, _xyz

__all__ = ["PairImpact", "solve_pair"]

#: Relative tolerance on ``|c_1 - c_2| = R_1 + R_2`` when centres are given.
_TOUCH_RTOL = 1e-9


@dataclass(frozen=True, eq=False)
class PairImpact(Result):
    """Everything :func:`solve_pair` computes (names as :class:`~spinimpact.Impact`'s).

    ``normal`` points from ball 2's centre to ball 1's; ``slip_*`` and
    ``normal_velocity_*`` are the contact point's velocity of ball 1 relative to ball 2;
    ``friction_impulse`` acts on ball 1 (its opposite on ball 2); energies are the pair's
    (``dissipated_fraction``: of the kinetic energy in the centre-of-mass frame, the part an
    impact can lose); ``angle_between_paths`` is the angle between the two centres'
    velocities after the impact, rad (NaN where one is at rest). Columns of the two balls
    are prefixed ``ball1_``, ``ball2_``.
    """

    ball1: Body
    ball2: Body
    mu: Array
    kappa: Array
    normal: Vector
    before1: State3
    before2: State3
    after1: State3
    after2: State3
    slip_before: Vector
    slip_after: Vector
    normal_velocity_before: Array
    normal_velocity_after: Array
    regime: Array
    tau0: Array
    tau_star: Array
    tau1: Array
    friction_impulse: Vector
    impulse_ratio: Array
    kinetic_energy_before: Array
    kinetic_energy_after: Array
    dissipated_energy: Array
    dissipated_fraction: Array
    work_compression_normal: Array
    work_compression_tangential: Array
    work_restitution_normal: Array
    work_restitution_tangential: Array
    newton_restitution: Array
    poisson_restitution: Array
    energetic_restitution: Array
    grips: Array
    angle_between_paths: Array

    _shape_field = "tau1"
    _body_prefix = True

    def __repr__(self) -> str:
        a, b = self.after1, self.after2
        return _summary(self, "PairImpact", lambda: (
            f"v1={_xyz(a.velocity)} m/s, v2={_xyz(b.velocity)} m/s; "
            f"dissipated {self.dissipated_energy:.6g} J"))  # fmt: skip


def _energy(m, inertia, v, w):  # type: ignore[no-untyped-def]
    return 0.5 * m * kernels.dot(v, v) + 0.5 * inertia * kernels.dot(w, w)


def _normal(normal: Any, centres: Any, r1: np.ndarray, r2: np.ndarray) -> np.ndarray:
    if (normal is None) == (centres is None):
        raise ValueError("give either normal (from ball 2's centre to ball 1's) or centres")
    if normal is not None:
        n = vector3("normal", normal)
        length = np.sqrt(kernels.dot(n, n))
        check("the length of normal", length, lambda x: x > 1e-12, "> 0 (a direction)")
        return n / length[..., None]
    if not isinstance(centres, tuple | list) or len(centres) != 2:
        raise TypeError("centres must be a pair (centre1, centre2) of 3-vectors")
    d = vector3("centre1", centres[0]) - vector3("centre2", centres[1])
    gap = np.sqrt(kernels.dot(d, d))
    touch = r1 + r2
    for bad, what in ((gap < touch * (1 - _TOUCH_RTOL), "overlap"),
                      (gap > touch * (1 + _TOUCH_RTOL), "do not touch")):  # fmt: skip
        bad = np.broadcast_to(bad, np.broadcast_shapes(gap.shape, touch.shape))
        if bad.any():
            i = tuple(int(k) for k in np.argwhere(bad)[0]) if bad.ndim else ()
            g, t = np.broadcast_to(gap, bad.shape)[i], np.broadcast_to(touch, bad.shape)[i]
            where = f" (first offending index {i[0] if len(i) == 1 else i})" if i else ""
            raise ValueError(
                f"the centres must be radius1 + radius2 = {float(t)!r} apart, but they are "
                f"{float(g)!r} apart: the balls {what}{where}"
            )
    return d / gap[..., None]


def solve_pair(
    ball1: Body,
    ball2: Body,
    *,
    velocity1: Any,
    spin1: Any,
    velocity2: Any,
    spin2: Any,
    mu: Any,
    kappa: Any,
    normal: Any = None,
    centres: Any = None,
) -> PairImpact:
    """Solve the frictional impact of two spinning spheres.

    Parameters
    ----------
    ball1, ball2 : Body
        Masses, radii and radii of gyration.
    velocity1, velocity2 : array_like, shape (..., 3)
        Centre velocities before the impact, m/s.
    spin1, spin2 : array_like, shape (..., 3)
        Spin vectors before the impact, rad/s.
    mu : float or array_like
        Coulomb friction coefficient between the balls, ``>= 0``.
    kappa : float, array_like or callable
        Coefficient of restitution in ``[0, 1]``, or a model of the normal approach speed.
    normal : array_like, shape (..., 3), optional
        Direction from ball 2's centre to ball 1's (normalised here).
    centres : (array_like, array_like), optional
        The two centres instead of ``normal``; they must be ``R_1 + R_2`` apart (to
        ``1e-9`` relative).

    Returns
    -------
    PairImpact

    Raises
    ------
    TypeError
        Balls that are not :class:`~spinimpact.Body`, inputs that are not numbers.
    ValueError
        Vectors without 3 components, a zero-length normal, overlapping or separate
        balls, non-finite values, a ball that cannot be a sphere (a radius of gyration
        above a thin shell's ``sqrt(2/3) R``), or balls that do not approach each other
        along the normal at ``1e-50`` m/s or faster.

    Examples
    --------
    A cue ball with side spin (english) hits an object ball full on:

    >>> from spinimpact import Body, solve_pair
    >>> cue = obj = Body.solid_sphere(mass=0.17, radius=0.028575)
    >>> imp = solve_pair(cue, obj, velocity1=[0.0, 0.0, -2.0], spin1=[0.0, 30.0, 0.0],
    ...                  velocity2=[0, 0, 0], spin2=[0, 0, 0], normal=[0, 0, 1],
    ...                  mu=0.06, kappa=0.93)
    >>> round(float(imp.after2.vz), 4), str(imp.regime)
    (-1.93, 'slip')
    """
    ball1, ball2 = as_body(ball1, "ball1"), as_body(ball2, "ball2")
    for name, ball in (("ball1", ball1), ("ball2", ball2)):
        check_sphere(ball, f"{name}'s gyration")
    one = _fast_sphere.pair_impact(ball1, ball2, velocity1, spin1, velocity2, spin2, mu, kappa,
                                   normal, centres, (PairImpact, State3, Vector))  # fmt: skip
    if one is not None:  # one impact of plain numbers: the same PairImpact, in microseconds
        return one
    v1, w1 = vector3("velocity1", velocity1), vector3("spin1", spin1)
    v2, w2 = vector3("velocity2", velocity2), vector3("spin2", spin2)
    mu_ = validated("mu", mu)
    p1 = [np.asarray(x) for x in (ball1.mass, ball1.radius, ball1.inertia)]
    p2 = [np.asarray(x) for x in (ball2.mass, ball2.radius, ball2.inertia)]
    n = _normal(normal, centres, p1[1], p2[1])
    many = _fused_sphere.pair_impact(ball1, ball2, v1, w1, v2, w2, mu_, kappa, n,
                                     (PairImpact, State3, Vector))  # fmt: skip
    if many is not None:  # many impacts: every field from one compiled pass, bit for bit
        return many
    given = [] if callable(kappa) else [np.shape(kappa)]
    shape = np.broadcast_shapes(*(x.shape[:-1] for x in (v1, w1, v2, w2, n)), mu_.shape,
                                *(x.shape for x in (*p1, *p2)), *given)  # fmt: skip
    v1, w1, v2, w2, n = (np.broadcast_to(x, (*shape, 3)) for x in (v1, w1, v2, w2, n))
    m1, r1, j1, m2, r2, j2, mu_ = (np.broadcast_to(x, shape) for x in (*p1, *p2, mu_))
    other = v2 + kernels.cross(w2, r2[..., None] * n)  # ball 2's material at the contact
    c = kernels.sphere_contact(v1, w1, n, r1, other)
    cn, speed = c.normal_velocity, c.slip_speed
    approach("the contact point's normal velocity", cn,
             "the balls must approach each other along the normal")  # fmt: skip
    kappa_ = np.broadcast_to(_restitution(kappa, cn), shape)
    m, zeta = kernels.pair_parameters(m1, j1, r1, m2, j2, r2)
    r = kernels.sphere_rebound(c, n, m, zeta, mu_, kappa_)
    v1b, v2b = v1 + r.impulse / m1[..., None], v2 - r.impulse / m2[..., None]
    w1b = w1 + kernels.sphere_spin_change(n, r1, j1, r.friction)
    w2b = w2 + kernels.sphere_spin_change(n, r2, j2, r.friction)
    c1 = kernels.sphere_contact(v1b, w1b, n, r1, v2b + kernels.cross(w2b, r2[..., None] * n))
    works = core.contact_phase_works(speed, cn, m, zeta, mu_, kappa_)
    loss = core.contact_dissipated_energy(speed, cn, m, zeta, mu_, kappa_)
    e0 = _energy(m1, j1, v1, w1) + _energy(m2, j2, v2, w2)
    e1 = _energy(m1, j1, v1b, w1b) + _energy(m2, j2, v2b, w2b)
    momentum = m1[..., None] * v1 + m2[..., None] * v2
    e_cm = e0 - 0.5 * kernels.dot(momentum, momentum) / (m1 + m2)  # in the centre-of-mass frame
    tau0 = core.compression_impulse(m, cn)
    kappas = core.restitution_by_definition(
        cn, c1.normal_velocity, tau0, r.normal_impulse,
        works.compression_normal, works.restitution_normal,
    )  # fmt: skip
    stuck = core.sticks(speed, cn, zeta, mu_, kappa_)
    s1, s2 = np.sqrt(kernels.dot(v1b, v1b)), np.sqrt(kernels.dot(v2b, v2b))
    # atan2(|a x b|, a.b) keeps full precision near 0 and pi (arccos of the cosine would not)
    sine = kernels.cross(v1b, v2b)
    angle = np.arctan2(np.sqrt(kernels.dot(sine, sine)), kernels.dot(v1b, v2b))
    angle = np.where((s1 > 0) & (s2 > 0), angle, np.nan)
    return PairImpact(
        ball1=ball1, ball2=ball2, mu=freeze(mu_), kappa=freeze(kappa_), normal=_vector(n),
        before1=_state(v1, w1), before2=_state(v2, w2),
        after1=_state(v1b, w1b), after2=_state(v2b, w2b),
        slip_before=_vector(c.slip), slip_after=_vector(np.where(stuck[..., None], 0.0, c1.slip)),
        normal_velocity_before=freeze(cn), normal_velocity_after=freeze(c1.normal_velocity),
        regime=freeze(np.asarray(core.REGIMES)[core.regime_code(speed, cn, zeta, mu_, kappa_)]),
        tau0=freeze(tau0), tau_star=freeze(core.stick_impulse(m, speed, zeta, mu_)),
        tau1=freeze(r.normal_impulse), friction_impulse=_vector(r.friction),
        impulse_ratio=freeze(r.friction_magnitude / r.normal_impulse),
        kinetic_energy_before=freeze(e0), kinetic_energy_after=freeze(e1),
        dissipated_energy=freeze(loss), dissipated_fraction=freeze(loss / e_cm),
        work_compression_normal=freeze(works.compression_normal),
        work_compression_tangential=freeze(works.compression_tangential),
        work_restitution_normal=freeze(works.restitution_normal),
        work_restitution_tangential=freeze(works.restitution_tangential),
        newton_restitution=freeze(kappas.newton), poisson_restitution=freeze(kappas.poisson),
        energetic_restitution=freeze(kappas.energetic), grips=freeze(stuck),
        angle_between_paths=freeze(angle),
    )  # fmt: skip
