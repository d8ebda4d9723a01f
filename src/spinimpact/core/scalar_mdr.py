r"""The micro-slip law for one contact, on floats, read from the precomputed table.

The compiled per-contact counterpart of ``solve(..., tangential=MindlinDeresiewicz(...))``
(Hertz's normal contact, Mindlin-Deresiewicz micro-slip, Hunt-Crossley damping) where that
impact is read from the table of :mod:`spinimpact.core.mdr_table`: the table's range
(``kappa`` in ``[0.85, 1]``, ``q = zeta r`` in ``[2, 4]``) and error bound
(``(1 + kappa) zeta mu`` small enough that the slip after is within ``1e-4`` of
``|v_n^-|``). There the slip after is

.. math:: c_t^+ = c_t^- - (1 + \kappa)\,\zeta\,\mu\,|c_n^-|\,\phi(X, q, \kappa),
   \qquad X = \frac{c_t^-}{(1 + \kappa)\,\zeta\,\mu\,|c_n^-|},

``phi`` the table's share of Coulomb's impulse, read by local cubic (four-point Lagrange)
interpolation along each axis; the friction impulse goes back to the body as in the rigid
law and the normal problem is the rigid one (``c_n^+ = -kappa c_n^-``), as for Walton's law
(:mod:`spinimpact.core.scalar_tangential`). Outside the range or the bound the impact must
be solved in time (:func:`spinimpact.core.mdr.mdr_slip`), which a compiled loop cannot do:
the functions here return NaN there, and :func:`mdr_usable` says beforehand.

The table's arrays are an argument (``table``, the tuple :func:`mdr_table` returns), so a
compiled caller receives them once rather than as constants frozen into its code. The
array path (:func:`spinimpact.core.mdr_table.impulse_share` with Numba,
:mod:`spinimpact.core.mdr_table_kernel`) reads every row with :func:`share_of`, so where
Numba is installed (the ``[fast]`` extra) the results equal the library's bit for bit
(``tests/core/test_law_mdr.py``); without it the library reads the table with NumPy, whose
sums differ in the last bit. Numba-compatible;
registered for compiled callers by :mod:`spinimpact.core.law`. Nothing is validated.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .impulse import total_impulse
from .kinematics import slip_velocity
from .mdr_data import BOUND, MARGIN, load_table
from .scalar3d import _sphere_after, sphere_contact
from .scalar_tangential import _rebound, sliding_change, tangential_impulse_of

__all__ = [
    "mdr_table",
    "mdr_usable",
    "mdr_contact",
    "mdr_rebound",
    "sphere_mdr_rebound",
]


@functools.cache
def mdr_table():
    """The shipped table as the tuple the functions here take (read once a process).

    Returns
    -------
    tuple
        ``(axes, limits, touch, threshold, share)``: ``axes`` the first node, step and
        number of nodes of the ``kappa``, ``q`` and ``t`` axes (nine floats); ``limits``
        the range (``kappa`` low and high, ``q`` low and high), the trusted error of ``phi``
        (:data:`~spinimpact.core.mdr_table.MARGIN` times the error measured off the grid)
        and the bound on the slip after (:data:`~spinimpact.core.mdr_table.BOUND`, in units
        of ``|v_n^-|``); then the tabulated ``U_A``, ``X*`` and ``phi`` (read-only arrays).
    """
    tab = load_table()
    axes = table_axes(tab)
    limits = np.array([tab.kappa[0], tab.kappa[-1], tab.q[0], tab.q[-1],
                       MARGIN * tab.max_error, BOUND])  # fmt: skip
    for a in (axes, limits):
        a.setflags(write=False)
    return axes, limits, tab.touch, tab.threshold, tab.share


def table_axes(tab):
    """The first node, step and number of nodes of an
    :class:`~spinimpact.core.mdr_table.MdrTable`'s ``kappa``, ``q`` and ``t`` axes (nine
    floats, the ``axes`` that :func:`share_of` takes)."""
    return np.array([tab.kappa[0], tab.kappa[1] - tab.kappa[0], tab.kappa.size,
                     tab.q[0], tab.q[1] - tab.q[0], tab.q.size,
                     tab.t[0], tab.t[1] - tab.t[0], tab.t.size])  # fmt: skip


def _place(x, start, step, size):
    """The first of the four nodes around ``x`` on an equal-step axis (``size`` nodes) and
    their cubic Lagrange weights (five numbers)."""
    s = (x - start) / step
    first = min(max(int(math.floor(s)) - 1, 0), size - 4)
    p = s - first
    p1, p2, p3 = p - 1.0, p - 2.0, p - 3.0
    return first, -p1 * p2 * p3 / 6.0, p * p2 * p3 / 2.0, -p * p1 * p3 / 2.0, p * p1 * p2 / 6.0


def _row(a, i, j, w0, w1, w2, w3):
    """``a[i, j:j + 4]`` weighted by ``w0 .. w3``, summed."""
    return w0 * a[i, j] + w1 * a[i, j + 1] + w2 * a[i, j + 2] + w3 * a[i, j + 3]


def _square(a, i, j, u0, u1, u2, u3, w0, w1, w2, w3):
    """``a[i:i + 4, j:j + 4]`` weighted by ``u`` along rows and ``w`` along columns, summed
    (written out: a compiled caller reads it without loops, views or temporary arrays)."""
    return (u0 * _row(a, i, j, w0, w1, w2, w3) + u1 * _row(a, i + 1, j, w0, w1, w2, w3)
            + u2 * _row(a, i + 2, j, w0, w1, w2, w3)
            + u3 * _row(a, i + 3, j, w0, w1, w2, w3))  # fmt: skip


def _line(a, s, i, j, m, w0, w1, w2, w3):
    """``a[s, i, j, m:m + 4]`` weighted by ``w0 .. w3``, summed."""
    return (w0 * a[s, i, j, m] + w1 * a[s, i, j, m + 1] + w2 * a[s, i, j, m + 2]
            + w3 * a[s, i, j, m + 3])  # fmt: skip


def _plane(a, s, i, j, m, u, w):
    """``a[s, i, j:j + 4, m:m + 4]`` weighted by the four weights ``u`` (along ``j``) and
    ``w`` (along ``m``), summed."""
    return (u[0] * _line(a, s, i, j, m, w[0], w[1], w[2], w[3])
            + u[1] * _line(a, s, i, j + 1, m, w[0], w[1], w[2], w[3])
            + u[2] * _line(a, s, i, j + 2, m, w[0], w[1], w[2], w[3])
            + u[3] * _line(a, s, i, j + 3, m, w[0], w[1], w[2], w[3]))  # fmt: skip


def share_of(x, q, kappa, axes, touch, threshold, share):
    """``(phi, stuck)`` at one point inside the table's range: the share of Coulomb's
    impulse (odd in ``x``) and whether the centre of the contact stuck (``|x| < X*``); NaN
    and ``False`` where ``x`` is NaN. As :func:`spinimpact.core.mdr_table.impulse_share`
    (to rounding: the sums are taken in another order)."""
    if math.isnan(x):
        return math.nan, False
    fk, k0, k1, k2, k3 = _place(kappa, axes[0], axes[1], int(axes[2]))
    fq, q0, q1, q2, q3 = _place(q, axes[3], axes[4], int(axes[5]))
    xa = k0 * touch[fk] + k1 * touch[fk + 1] + k2 * touch[fk + 2] + k3 * touch[fk + 3]
    xa /= (1.0 + kappa) * q
    star = _square(threshold, fk, fq, k0, k1, k2, k3, q0, q1, q2, q3)
    ax = abs(x)
    if ax >= star:
        phi = 1.0
    else:
        if ax <= xa:
            stretch, t = 0, ax / xa
        else:
            part = min(max((ax - xa) / (star - xa), 0.0), 1.0)
            stretch, t = 1, math.acos(1.0 - 2.0 * part) / math.pi
        ft, t0, t1, t2, t3 = _place(t, axes[6], axes[7], int(axes[8]))
        q0123, t0123 = (q0, q1, q2, q3), (t0, t1, t2, t3)
        phi = (k0 * _plane(share, stretch, fk, fq, ft, q0123, t0123)
               + k1 * _plane(share, stretch, fk + 1, fq, ft, q0123, t0123)
               + k2 * _plane(share, stretch, fk + 2, fq, ft, q0123, t0123)
               + k3 * _plane(share, stretch, fk + 3, fq, ft, q0123, t0123))  # fmt: skip
    return float(phi if x > 0.0 else (-phi if x < 0.0 else 0.0)), bool(ax < star)


def mdr_usable(zeta, mu, kappa, stiffness_ratio, table):
    """Whether an impact is read from the table: ``q = zeta r`` and ``kappa`` in its range,
    and ``(1 + kappa) zeta mu`` times its trusted error at most its bound (the conditions of
    :func:`spinimpact.core.mdr_table.table_rows` at the default resolution).

    Parameters
    ----------
    zeta, mu, kappa : float
        ``W_tt/W_nn``, friction and Newton's restitution.
    stiffness_ratio : float
        Mindlin's ``r = 4 G*/E*`` (``2(1 - nu)/(2 - nu)`` for one material on a rigid plane).
    table : tuple
        :func:`mdr_table`.

    Examples
    --------
    >>> t = mdr_table()
    >>> mdr_usable(3.5, 0.3, 0.9, 0.87, t), mdr_usable(3.5, 0.3, 0.6, 0.87, t)
    (True, False)
    """
    limits = table[1]
    q = zeta * stiffness_ratio
    inside = limits[0] <= kappa <= limits[1] and limits[2] <= q <= limits[3]
    return bool(inside and (1.0 + kappa) * zeta * mu * limits[4] <= limits[5])


def mdr_contact(slip, vy, zeta, mu, kappa, stiffness_ratio, table):
    r"""Slip after one impact under Mindlin-Deresiewicz micro-slip, from the table.

    Parameters
    ----------
    slip, vy : float
        Slip ``c_t^-`` and normal velocity ``c_n^- < 0`` of the contact point, m/s.
    zeta, mu, kappa : float
        ``W_tt/W_nn``, friction (``>= 0``) and Newton's restitution (in ``(0, 1]``).
    stiffness_ratio : float
        Mindlin's ``r = 4 G*/E*``.
    table : tuple
        :func:`mdr_table`.

    Returns
    -------
    tuple
        ``(slip_after, stuck)``: :math:`c_t^+` (m/s) and whether the centre of the contact
        stuck at some time, as :func:`spinimpact.core.mdr_table.table_slip`; ``(nan, False)``
        where :func:`mdr_usable` is false (solve that impact in time).

    Examples
    --------
    >>> t = mdr_table()
    >>> after, stuck = mdr_contact(0.1, -1.0, 3.5, 0.3, 0.9, 0.87, t)
    >>> round(after, 4), stuck    # the centre stuck: the slip fell from 0.1 to 0.022 m/s
    (0.0223, True)
    """
    if not mdr_usable(zeta, mu, kappa, stiffness_ratio, table):
        return math.nan, False
    if slip == 0.0:
        return slip + 0.0, True
    if mu == 0.0:
        return slip + 0.0, False
    change = sliding_change(vy, zeta, mu, kappa)
    phi, stuck = share_of(slip / change, zeta * stiffness_ratio, kappa, table[0], table[2],
                          table[3], table[4])  # fmt: skip
    return slip - change * phi, stuck


def mdr_rebound(vx, vy, omega, mass, radius, zeta, mu, kappa, stiffness_ratio, table):
    """Rebound of one of the paper's bodies under micro-slip, from the table.

    Parameters
    ----------
    vx, vy, omega, mass, radius, zeta, mu, kappa : float
        As :func:`spinimpact.core.scalar.rebound` (``kappa`` in ``(0, 1]``).
    stiffness_ratio : float
        Mindlin's ``r = 4 G*/E*`` (``MindlinDeresiewicz(...).stiffness_ratio``).
    table : tuple
        :func:`mdr_table`.

    Returns
    -------
    tuple of float
        ``(vx^+, vy^+, omega^+, f_1)`` (m/s, m/s, rad/s, N s): ``solve(body, vx, vy, omega,
        mu=mu, kappa=kappa, tangential=MindlinDeresiewicz(stiffness_ratio=r))``'s ``after``
        and ``tangential_impulse``, bit for bit with Numba installed, where
        :func:`mdr_usable`; NaN elsewhere
        (``vy^+`` too: nothing of the impact is read from the table there).
    """
    slip = slip_velocity(vx, omega, radius)
    slip_after = mdr_contact(slip, vy, zeta, mu, kappa, stiffness_ratio, table)[0]
    if math.isnan(slip_after):
        return math.nan, math.nan, math.nan, math.nan
    return _rebound(vx, vy, omega, mass, radius, zeta, kappa, slip, slip_after)


def sphere_mdr_rebound(velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta,
                       mu, kappa, stiffness_ratio, table):  # fmt: skip
    """Rebound of a sphere from a plane in 3D under micro-slip, from the table.

    Parameters
    ----------
    velocity, spin, normal, surface_velocity, mass, radius, inertia, zeta, mu, kappa
        As :func:`spinimpact.core.scalar_tangential.sphere_walton_rebound`.
    stiffness_ratio : float
        Mindlin's ``r = 4 G*/E*``.
    table : tuple
        :func:`mdr_table`.

    Returns
    -------
    tuple of float
        ``(vx+, vy+, vz+, wx+, wy+, wz+)``: ``solve_sphere(...,
        tangential=MindlinDeresiewicz(stiffness_ratio=r))``'s ``after``, bit for bit with
        Numba installed, where
        :func:`mdr_usable`; six NaNs elsewhere.
    """
    cn, _, speed, e = sphere_contact(velocity, spin, normal, radius, surface_velocity)
    speed_after = mdr_contact(speed, cn, zeta, mu, kappa, stiffness_ratio, table)[0]
    if math.isnan(speed_after):
        return math.nan, math.nan, math.nan, math.nan, math.nan, math.nan
    f1 = tangential_impulse_of(mass, zeta, speed, speed_after)
    tau1 = total_impulse(mass, cn, kappa)
    return _sphere_after(velocity, spin, normal, mass, radius, inertia, tau1, f1, e)
