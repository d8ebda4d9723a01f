r"""The Hertz-Mindlin-Deresiewicz impact of :mod:`spinimpact.core.mdr` from a precomputed table.

The dimensionless numbers
-------------------------
:func:`spinimpact.core.mdr.mdr_slip` works in units ``m = 1``, ``|v_n^-| = 1``, ``R = 1``
(Hertz's law makes the rebound depend on the incidence through ratios only). What is left
are the scaled slip before ``u = c_t^-/|v_n^-|``, the body's ``zeta``, the friction ``mu``,
the restitution ``kappa`` (through the Hunt-Crossley damping ``a(kappa)`` and so the normal
motion ``delta(t)``) and Mindlin's stiffness ratio ``r = 4 G*/E*``. The reduced contact's
springs obey, while the contact point slips at ``u``,

.. math::

    \dot s_j = u \;\text{(clipped to)}\; |s_j| \le \frac{\mu}{r}\, w_j(t)\, g(t), \qquad
    \dot u = -\zeta\, r\, K \sum_j s_j ,

with ``w_j = delta - x_j^2``, ``g`` the damping's and the midpoint rule's factor and ``K``
a spring's stiffness over ``r``: all of them functions of ``kappa`` (and the resolution)
alone. With ``sigma_j = r s_j/mu`` and ``U = r u/mu``,

.. math::

    \dot\sigma_j = U \;\text{with}\; |\sigma_j| \le w_j g, \qquad
    \dot U = -(\zeta r)\, K \sum_j \sigma_j ,

so ``r c_t^+/(mu |v_n^-|)`` is a function of three numbers only: ``r c_t^-/(mu |v_n^-|)``,
``q = zeta r`` (the square of Stronge's and Maw's frequency ratio ``Omega``) and ``kappa``.
The scaling is exact, step by step, in the solver too (its arithmetic differs by rounding
only; ``tests/core/test_mdr_table.py`` checks it). ``zeta`` and ``r`` do not enter apart.

The table holds the share of Coulomb's impulse the impact uses,

.. math:: \phi = \frac{c_t^- - c_t^+}{(1 + \kappa)\, \zeta \mu |v_n^-|} \in [0, 1],

as a function of the incidence ratio ``X = c_t^-/((1 + kappa) zeta mu |v_n^-|)`` (``X =
U/((1 + kappa) q)``; Walton's ``beta_slide = 1/X - 1``), ``q`` and ``kappa``; ``phi`` is odd in
``X``. The slip after is ``c_t^+ = c_t^- - (1 + kappa) zeta mu |v_n^-| phi``.

Where it bends
--------------
Along ``X``, ``phi`` changes regime at

* ``X* (q, kappa)``: above it the contact slides throughout and ``phi = 1``, the gross-slip
  closed form (the solver's own sum of spring bounds gives ``1 - 1.2e-6`` at most, the
  midpoint rule's share); below it the centre of the contact sticks at some time. In the
  table's range ``phi`` joins 1 there with a continuous slope and a jump in curvature.
* ``X_A = U_A(kappa)/((1 + kappa) q)``: below it the centre sticks at touch-down (the slip
  is slower than the Coulomb bound of the centre grows, ``U_A`` about ``1 + a``); just above
  it ``phi`` grows like ``(X - X_A)^{3/2}``.

Elsewhere in ``(q, kappa)`` (on a coarse map of ``kappa`` in ``[0.5, 1]`` and ``q`` in
``[1.8, 6]``: ``kappa`` below about 0.85 at ``q = 2`` or 0.7 at ``q = 3.5``, and ``q`` above
about 4.2) ``phi`` has further corners whose number and place change with ``q`` and ``kappa`` (more
stick-slip transitions while the tangential oscillation reverses): a grid resolves them only
at a cost the table does not pay, and those impacts are solved in time.

Range, grid and error
---------------------
``kappa`` in ``[0.85, 1]`` (13 nodes), ``q = zeta r`` in ``[2, 4]`` (41 nodes):
a sphere (``zeta = 7/2``) at any Poisson ratio in ``[0, 0.5]`` (``r = 2(1 - nu)/(2 - nu)`` in
``[2/3, 1]``: ``q`` in ``[2.33, 3.5]``), a disk (3, ``q`` in ``[2, 3]``), a thin shell
(5/2) with ``nu <= 1/3``. ``X`` is cut at ``X_A`` and ``X*``: on ``[0, X_A]`` the table's
axis is ``t = X/X_A``, on ``[X_A, X*]`` it is ``theta`` with ``(X - X_A)/(X* - X_A) = (1 -
cos(pi theta))/2`` (the ``3/2`` power and the curvature's jump become smooth in ``theta``),
65 nodes each. ``U_A`` is tabulated on ``kappa`` (from the solver's first step,
:func:`build_touch`), ``X*`` on ``(kappa, q)`` (bisection on ``stuck``,
:func:`build_threshold`), ``phi`` on ``(stretch, kappa, q, t)``; each is read by local cubic
(four-point Lagrange) interpolation along each axis.

The table's error in ``phi``, measured against the full solution at its default resolution
(256 springs, 2048 steps) on 4,000 random points off the grid (``python -m
benchmarks.mdr_table``, which builds the table and stores that figure in it as
``max_error``), is at most ``8.9e-6``; the error in the slip after is ``(1 + kappa)
zeta mu |v_n^-|`` times it. :func:`table_slip` uses the table only where :data:`MARGIN`
times that is at most :data:`BOUND`, ``1e-4 |v_n^-|`` (``(1 + kappa) zeta mu <= 5.6``; a
sphere at ``kappa = 1``: ``mu <= 0.80``), and solves every other impact in time with
:func:`spinimpact.core.mdr.mdr_slip`.

``stuck`` (whether the centre of the contact stuck at some time) is ``|X| < X*`` with the
interpolated ``X*``: it can differ from the full solution's within the table's error of
``X*`` (up to ``3e-5`` of ``X*``, measured at 24 random points) of the threshold. Both
flow into the result's ``regime``; every other field of the result follows from the slip
after as it does for the solution in time.
"""

from __future__ import annotations

import numpy as np

from .._validation import require
from . import mdr
from .mdr_data import BOUND, FIELDS, FILE, MARGIN, MdrTable, load_table

__all__ = ["BOUND", "MARGIN", "FIELDS", "FILE", "MdrTable", "load_table", "impulse_share",
           "table_slip", "in_table", "breaks", "table_rows", "build_touch", "build_threshold",
           "build_share"]  # fmt: skip


def _weights(axis, x):
    """Rows of the four nodes around ``x`` on the equal-step ``axis`` and their cubic
    Lagrange weights: ``(first, w)`` with ``w`` of shape ``x.shape + (4,)``."""
    h = axis[1] - axis[0]
    s = (x - axis[0]) / h
    first = np.clip(np.floor(s).astype(np.int64) - 1, 0, axis.size - 4)
    p = s - first  # position from the first node, in [1, 2] inside
    p0, p1, p2, p3 = p, p - 1.0, p - 2.0, p - 3.0
    w = np.stack([-p1 * p2 * p3 / 6.0, p0 * p2 * p3 / 2.0, -p0 * p1 * p3 / 2.0,
                  p0 * p1 * p2 / 6.0], axis=-1)  # fmt: skip
    return first, w


def _interp1(table, axis, x):
    """Local cubic interpolation of ``table`` (1-D) at ``x``."""
    first, w = _weights(axis, x)
    return sum(w[..., i] * table[first + i] for i in range(4))


def _interp2(table, axes, points):
    """Local cubic interpolation of ``table`` (2-D) at ``points`` (two arrays)."""
    (f0, w0), (f1, w1) = (_weights(a, x) for a, x in zip(axes, points, strict=True))
    out = np.zeros(np.shape(points[0]))
    for i in range(4):
        for j in range(4):
            out += w0[..., i] * w1[..., j] * table[f0 + i, f1 + j]
    return out


def _interp3(table, axes, points):
    """Local cubic interpolation of ``table`` (3-D) at ``points`` (three arrays)."""
    (f0, w0), (f1, w1), (f2, w2) = (_weights(a, x) for a, x in zip(axes, points, strict=True))
    flat = table.reshape(-1)
    n1, n2 = table.shape[1], table.shape[2]
    out = np.zeros(np.shape(points[0]))
    for i in range(4):
        for j in range(4):
            w = w0[..., i] * w1[..., j]
            base = ((f0 + i) * n1 + (f1 + j)) * n2 + f2
            for k in range(4):
                out += w * w2[..., k] * flat[base + k]
    return out


def in_table(q, kappa, table: MdrTable | None = None):
    """Whether ``(q, kappa)`` lies in the table's range (``q = zeta r``)."""
    tab = load_table() if table is None else table
    q, kappa = np.asarray(q, dtype=float), np.asarray(kappa, dtype=float)
    return ((kappa >= tab.kappa[0]) & (kappa <= tab.kappa[-1]) & (q >= tab.q[0])
            & (q <= tab.q[-1]))  # fmt: skip


def breaks(q, kappa, table: MdrTable | None = None):
    """``(X_A, X*)`` at ``(q, kappa)`` (inside the table's range): the incidence ratios
    below which the centre of the contact sticks at touch-down, and at some time."""
    tab = load_table() if table is None else table
    touch = _interp1(tab.touch, tab.kappa, kappa) / ((1.0 + kappa) * q)
    return touch, _interp2(tab.threshold, (tab.kappa, tab.q), (kappa, q))


def impulse_share(incidence, q, kappa, table: MdrTable | None = None, engine="auto"):
    r"""``phi`` and ``stuck`` from the table, vectorized (inside its range only).

    Parameters
    ----------
    incidence : array_like
        ``X = c_t^-/((1 + kappa) zeta mu |v_n^-|)`` (dimensionless, signed).
    q : array_like
        ``zeta r``, ``r = 4 G*/E*`` (dimensionless).
    kappa : array_like
        Newton's restitution.
    table : MdrTable, optional
        Default: the shipped one.
    engine : {"auto", "numba", "numpy"}
        Numba's compiled rows (:mod:`spinimpact.core.mdr_table_kernel`) or NumPy's arrays;
        ``"auto"``: Numba where it is installed. The two agree to rounding.

    Returns
    -------
    share : ndarray
        ``phi = (c_t^- - c_t^+)/((1 + kappa) zeta mu |v_n^-|)``, odd in ``X``; 1 in sliding.
    stuck : ndarray of bool
        Whether the centre of the contact stuck at some time (``|X| < X*``).
    """
    tab = load_table() if table is None else table
    given = (incidence, q, kappa)
    x, q, kappa = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in given))
    if engine not in ("auto", "numba", "numpy"):
        raise ValueError(f"engine must be 'auto', 'numba' or 'numpy', got {engine!r}")
    if engine != "numpy":  # imported here: Numba is heavy, and optional
        from . import mdr_table_kernel

        if mdr_table_kernel.HAVE_NUMBA:
            share, stuck = mdr_table_kernel.share_rows(x.ravel(), q.ravel(), kappa.ravel(), tab)
            return share.reshape(x.shape), stuck.reshape(x.shape)
        if engine == "numba":
            require("numba", "engine='numba'")
    touch, star = breaks(q, kappa, tab)
    ax = np.abs(x)
    stuck = ax < star
    low = ax <= touch
    t = np.where(low, ax / touch, _angle((ax - touch) / (star - touch)))
    share = np.ones(x.shape)
    for stretch, rows in enumerate((low, stuck & ~low)):
        if rows.any():
            share[rows] = _interp3(tab.share[stretch], (tab.kappa, tab.q, tab.t),
                                   (kappa[rows], q[rows], t[rows]))  # fmt: skip
    return share * np.sign(x), stuck


def table_rows(zeta, mu, kappa, stiffness_ratio, springs=256, steps=2048):
    """Where :func:`table_slip` reads the table (``True``) rather than solving in time:
    ``zeta r`` and ``kappa`` in its range, ``(1 + kappa) zeta mu`` times :data:`MARGIN`
    times its measured error at most :data:`BOUND`, and the table's resolution."""
    tab = load_table()
    zeta, mu, kappa = (np.asarray(v, dtype=float) for v in (zeta, mu, kappa))
    use = in_table(zeta * stiffness_ratio, kappa, tab)
    use = use & ((1.0 + kappa) * zeta * mu * (MARGIN * tab.max_error) <= BOUND)
    return use & ((int(springs), int(steps)) == (tab.springs, tab.steps))


def table_slip(slip, vy, zeta, mu, kappa, stiffness_ratio, springs=256, steps=2048):
    """:func:`spinimpact.core.mdr.mdr_slip` from the table where it holds, in time elsewhere.

    Same parameters and returns as :func:`~spinimpact.core.mdr.mdr_slip` (velocities in
    m/s). The table is used where ``q = zeta r`` and ``kappa`` are in its range, the
    resolution is the table's, and ``(1 + kappa) zeta mu`` times :data:`MARGIN` times its
    measured error is at most :data:`BOUND` (``1e-4`` of ``|v_n^-|`` in the slip after);
    the other rows are solved in time by ``mdr_slip``.
    """
    tab = load_table()
    given = (slip, vy, zeta, mu, kappa)
    slip, vy, zeta, mu, kappa = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in given))
    shape = slip.shape
    slip, vy, zeta, mu, kappa = (v.ravel() for v in (slip, vy, zeta, mu, kappa))
    impulse = (1.0 + kappa) * zeta * mu * np.abs(vy)  # Coulomb's tangential impulse over m
    q = zeta * stiffness_ratio
    use = table_rows(zeta, mu, kappa, stiffness_ratio, springs, steps)
    out = slip + 0.0
    stuck = slip == 0.0
    live = use & (slip != 0.0) & (mu > 0.0)
    if live.any():
        rows = np.flatnonzero(live)
        share, held = impulse_share(slip[rows] / impulse[rows], q[rows], kappa[rows], tab)
        out[rows] = slip[rows] - impulse[rows] * share
        stuck[rows] = held
    rest = np.flatnonzero(~use)
    if rest.size:
        out[rest], stuck[rest] = mdr.mdr_slip(slip[rest], vy[rest], zeta[rest], mu[rest],
                                              kappa[rest], stiffness_ratio, springs=springs,
                                              steps=steps)  # fmt: skip
    return out.reshape(shape), stuck.reshape(shape)


def build_touch(kappa, springs=256, steps=2048):
    """``U_A``: the scaled slip ``r c_t^-/(mu |v_n^-|)`` below which the centre spring of
    the full solution holds in its first step (the bound's rate at touch-down, about
    ``1 + a``; ``phi``'s second derivative jumps there)."""
    sp = mdr._setup(float(kappa), int(steps), int(springs), 1.0)
    dt = float(sp.hist.t[1] - sp.hist.t[0])
    return float(sp.limits[1, 0] / (dt * sp.share[1, 0]))


def build_threshold(q, kappa, springs=256, steps=2048, rounds=44):
    """``X*`` for each ``q`` at one ``kappa`` by the full solution: the incidence ratio
    above which the contact slides throughout (bisection on ``stuck``; relative width
    ``2^-rounds`` of the bracket)."""
    q = np.asarray(q, dtype=float)
    grid = np.geomspace(0.05, 60.0, 48)
    _, st = _full(grid[None, :], q[:, None], kappa, springs, steps)
    first = np.argmin(st, axis=1)  # the first incidence that slides throughout
    if st[np.arange(q.size), first].any() or (first == 0).any():
        raise RuntimeError(f"no threshold in [0.05, 60] at kappa = {kappa}")
    lo, hi = grid[first - 1], grid[first]
    for _ in range(rounds):
        mid = 0.5 * (lo + hi)
        _, st = _full(mid, q, kappa, springs, steps)
        lo, hi = np.where(st, mid, lo), np.where(st, hi, mid)
    return hi


def build_share(t, q, kappa, touch, threshold, springs=256, steps=2048):
    """``phi`` on the two stretches ``X = t X_A`` and ``X = X_A + (X* - X_A) (1 - cos(pi
    t))/2`` (:func:`_angle`), by the full solution: shape ``(2, q.size, t.size)`` for one
    ``kappa``."""
    t, q = np.asarray(t, dtype=float)[None, :], np.asarray(q, dtype=float)[:, None]
    xa = touch / ((1.0 + kappa) * q)
    star = np.asarray(threshold, dtype=float)[:, None]
    if (xa >= star).any():
        raise RuntimeError(f"the touch-down threshold is not below X* at kappa = {kappa}")
    x = np.stack(np.broadcast_arrays(t * xa, xa + (star - xa) * 0.5 * (1.0 - np.cos(np.pi * t))))
    share, _ = _full(x, np.broadcast_to(q, x.shape), kappa, springs, steps)
    return share


def _angle(part):
    """The second stretch's axis: ``theta`` in ``[0, 1]`` with ``(X - X_A)/(X* - X_A) =
    (1 - cos(pi theta))/2`` (``part`` clipped to ``[0, 1]``)."""
    return np.arccos(1.0 - 2.0 * np.clip(part, 0.0, 1.0)) / np.pi


def _full(x, q, kappa, springs, steps):
    """``(phi, stuck)`` by the full solution at incidence ratio ``x`` (``zeta = q``,
    ``r = mu = |v_n| = 1``)."""
    x, q = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(q, dtype=float))
    impulse = (1.0 + kappa) * q
    after, stuck = mdr.mdr_slip(x * impulse, -1.0, q, 1.0, kappa, 1.0, springs=springs,
                                steps=steps)  # fmt: skip
    return (x * impulse - after) / impulse, stuck
