r"""A time-stepping contact force for DEM loops: Hertz normal force, Mindlin-Deresiewicz
tangential force with its loading history, and the usual DEM variants beside it.

A DEM code advances each contact by one time step at a time: it knows the overlap
``delta`` of the two surfaces at the new step, its rate, and the increment ``d xi`` of the
tangential displacement of the contact point over the step (``u dt``, ``u`` the contact
point's tangential velocity of the body relative to the other); it wants the forces. The
functions here compute them for one contact, from a state array the caller keeps per
contact (:func:`state_size` floats) and a parameter array (:func:`parameters`). They are
plain Python functions that Numba compiles into the caller's ``numba.njit`` loop
(registered with ``register_jitable`` by :mod:`spinimpact.core.dem_law`), like the
impact law of :mod:`spinimpact.core.law`.

Normal force
------------
Hertz's spring ``N_el = k delta^{3/2}``, ``k = 4/3 E^* sqrt(R)``, with one of

* no damping;
* Hunt and Crossley's, ``N = N_el (1 + a delta')``;
* the viscous damping of Tsuji et al. (1992) in the form the DEM codes use,
  ``N = N_el + c_n delta'`` with ``c_n = 2 sqrt(5/6) beta sqrt(S_n m^*)``,
  ``S_n = 2 E^* sqrt(R delta)`` (the normal contact stiffness ``dN_el/d delta``).

The force is never attractive (``N >= 0``).

Tangential force: Mindlin-Deresiewicz with the loading history (``model = MICRO_SLIP``)
---------------------------------------------------------------------------------------
The method of dimensionality reduction (Popov and Hess 2015; :mod:`spinimpact.core.mdr`)
replaces the circular contact of radius ``a = sqrt(R delta)`` by independent springs on
``|x| < a`` with normal stiffness ``E^* dx``, pressed by ``w(x) = delta - x^2/R``, and
tangential stiffness ``4 G^* dx``; each spring sticks until its tangential force reaches
``mu`` times its normal force. For a paraboloid this is exact for Hertz's normal force,
Cattaneo and Mindlin's partial slip and Mindlin and Deresiewicz's response to any
sequence of normal and tangential loading in one direction (elastically similar bodies).

The state keeps the springs in **cells** ``[x_j, x_{j+1}]`` (``x >= 0``; the contact is
symmetric), one displacement vector ``s_j`` per cell. A cell is created at each step in
which the contact grows beyond its largest radius so far, covering exactly the new annulus
``[x_n, a]``; its springs came into contact during that step, so it starts with the share
of the step's increment they moved through,

.. math:: s = d\xi\, \frac{\int_{x_n}^{a} (\delta - x^2/R)\, dx}
          {(\delta - \delta_\mathrm{prev}) (a - x_n)}.

Each cell's forces are the exact integrals over its part in contact
``[x_j, min(x_{j+1}, a)]``: normal ``n_j = 2 E^* int (delta - x^2/R) dx`` and tangential
stiffness ``k_j = 8 G^* (min(x_{j+1}, a) - x_j)``, so ``sum n_j`` is Hertz's force and
``sum k_j = 8 G^* a`` Mindlin's stiffness at every step, whatever the cells. At each step

1. every cell in contact moves by ``d xi`` (a cell that the contact re-enters is averaged
   with the springs entering it, weighted by stiffness, which never adds energy);
2. each cell is held to its Coulomb bound ``|k_j s_j| <= mu g n_j`` by scaling ``s_j``
   (``g = 1``: the limit is ``mu`` times the elastic normal force; ``g = N/N_el``: ``mu``
   times the whole normal force, damping included);
3. cells outside the contact hold nothing;
4. the spring force is ``-sum k_j s_j``.

The cells are created by the caller's steps, so the loading history is resolved as finely
as the steps resolve it. When ``cells`` cells are in use and the contact grows again, the
two neighbouring cells narrowest together are merged (their displacements averaged,
weighted by stiffness): the force is kept, the energy does not rise, and the cells stay
nearly even in ``x``, about ``a/cells`` wide. The step converges to the impact of
:func:`spinimpact.core.mdr.mdr_slip` (``docs/dem.md`` gives the measured order).

The history spring (``model = HISTORY``)
----------------------------------------
The same cells with no per-cell bound: the whole contact sticks (the exact no-slip elastic
solution of a contact whose area grows and shrinks, Mindlin and Deresiewicz 1953) or
slides as a whole at ``|F| = mu N`` (all cells then take a common correction). This is the
time-stepped form of ``spring="history"`` of
:func:`spinimpact.core.tangential.integrate_tangential`: the force beyond the loading
history's at the same compression unloads with the stiffness.

The usual DEM variants
----------------------
* ``model = INCREMENTAL``: ``F <- F - 8 G^* a d xi``, scaled back to ``mu N`` when it
  exceeds it ("Hertz-Mindlin no-slip", Di Renzo and Di Maio 2004).
* ``model = SCALED``: as ``INCREMENTAL``, but while the contact shrinks the force is first
  scaled down with the stiffness, ``F <- F a/a_prev`` (the spring keeps its displacement;
  the rule of Kratos's Hertz law and the default ``spring="scaled"`` of
  :func:`spinimpact.core.tangential.integrate_tangential`).
* ``model = TOTAL``: the displacement accumulates, ``xi <- xi + d xi``, the force is
  ``-8 G^* a xi`` with the current stiffness, and ``xi`` is scaled back so that the force
  is ``mu N`` when it would exceed it (the "shear history" of LIGGGHTS-type codes).

Tangential damping (optional, all models): ``-c_t u`` with
``c_t = 2 sqrt(5/6) beta_t sqrt(S_t m^*)``, ``S_t = 8 G^* a``. Where the limit covers the
damping (``damping_capped``), the sum of the spring's and the damper's force is scaled
back to ``mu N`` (the springs' state is left as it is).

Nothing is validated here (a compiled loop has no room for it):
:class:`spinimpact.dem.ContactForce` checks its inputs and fills the arrays.

References
----------
.. [1] V. L. Popov, M. Hess, *Method of Dimensionality Reduction in Contact Mechanics and
   Friction*, Springer (2015).
.. [2] R. D. Mindlin, H. Deresiewicz, "Elastic spheres in contact under varying oblique
   forces", Journal of Applied Mechanics 20 (1953) 327-344.
.. [3] Y. Tsuji, T. Tanaka, T. Ishida, "Lagrangian numerical simulation of plug flow of
   cohesionless particles in a horizontal pipe", Powder Technology 71 (1992) 239-250.
.. [4] A. Di Renzo, F. P. Di Maio, "Comparison of contact-force models for the simulation
   of collisions in DEM-based granular flow codes", Chemical Engineering Science 59
   (2004) 525-541.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["MICRO_SLIP", "HISTORY", "INCREMENTAL", "TOTAL", "SCALED", "NO_DAMPING", "HUNT_CROSSLEY",
           "VISCOUS", "HEADER", "state_size", "new_state", "parameters", "normal_force",
           "contact_force", "tangential_energy", "normal_energy", "VISCOUS_FACTOR"]  # fmt: skip

#: Tangential models (``params[P_MODEL]``).
MICRO_SLIP, HISTORY, INCREMENTAL, TOTAL, SCALED = 0, 1, 2, 3, 4
#: Normal damping (``params[P_DAMPING]``).
NO_DAMPING, HUNT_CROSSLEY, VISCOUS = 0, 1, 2
#: ``2 sqrt(5/6)``, the factor of the DEM codes' viscous damping coefficients.
VISCOUS_FACTOR = 2.0 * math.sqrt(5.0 / 6.0)

# The parameter array's layout.
P_E, P_G, P_R, P_M, P_MU, P_MODEL, P_DAMPING, P_NORMAL_COEF, P_TANGENT_COEF = range(9)
P_LIMIT_TOTAL, P_DAMPING_CAPPED, P_CELLS = 9, 10, 11
N_PARAMS = 12

# The state's layout: a header, then the cells' edges, then their displacements.
S_CELLS, S_OVERLAP, S_T1, S_T2 = 0, 1, 2, 3
#: Floats before the cells in a state array.
HEADER = 4


def state_size(cells):
    """Floats in one contact's state for up to ``cells`` cells (``4 + 3 cells + 1``)."""
    return HEADER + 3 * cells + 1


def new_state(cells):
    """A fresh state (no contact yet) for up to ``cells`` cells."""
    return np.zeros(state_size(cells))


def parameters(modulus, shear_modulus, radius, mass, mu, model, damping, normal_coef,
               tangent_coef, limit_total, damping_capped, cells):  # fmt: skip
    """The parameter array: effective ``E^*`` and ``G^*`` (Pa; the tangential stiffness is
    ``8 G^* a``), effective radius (m) and mass (kg), ``mu``, the codes above, the normal
    damping's coefficient (``a`` in s/m for Hunt-Crossley, ``beta`` for viscous), the
    tangential damping's ``beta_t``, whether the friction limit takes the whole normal
    force (1) or its elastic part (0), whether it covers the tangential damping (1), and
    the number of cells."""
    p = np.empty(N_PARAMS)
    p[P_E], p[P_G], p[P_R], p[P_M], p[P_MU] = modulus, shear_modulus, radius, mass, mu
    p[P_MODEL], p[P_DAMPING], p[P_NORMAL_COEF] = model, damping, normal_coef
    p[P_TANGENT_COEF], p[P_LIMIT_TOTAL] = tangent_coef, limit_total
    p[P_DAMPING_CAPPED], p[P_CELLS] = damping_capped, cells
    return p


def normal_force(params, overlap, overlap_rate):
    """``(N, N_el)``: the normal force (N, never negative) and its elastic part at
    ``overlap`` (m) closing at ``overlap_rate`` (m/s; positive while compressing)."""
    if overlap <= 0.0:
        return 0.0, 0.0
    e, r = params[P_E], params[P_R]
    elastic = 4.0 / 3.0 * e * math.sqrt(r) * overlap * math.sqrt(overlap)
    kind = int(params[P_DAMPING])
    if kind == HUNT_CROSSLEY:
        total = elastic * (1.0 + params[P_NORMAL_COEF] * overlap_rate)
    elif kind == VISCOUS:
        stiffness = 2.0 * e * math.sqrt(r * overlap)
        coef = VISCOUS_FACTOR * params[P_NORMAL_COEF] * math.sqrt(stiffness * params[P_M])
        total = elastic + coef * overlap_rate
    else:
        total = elastic
    return max(total, 0.0), elastic


def normal_energy(params, overlap):
    """The Hertz spring's energy, ``2/5 k delta^{5/2}`` (J)."""
    if overlap <= 0.0:
        return 0.0
    return 0.4 * 4.0 / 3.0 * params[P_E] * math.sqrt(params[P_R]) * overlap**2.5


def _band(e, r, overlap, lo, hi):
    """``2 E^* int_lo^hi (delta - x^2/R) dx``: the normal force of the springs on
    ``[lo, hi]``."""
    return 2.0 * e * (overlap * (hi - lo) - (hi * hi * hi - lo * lo * lo) / (3.0 * r))


def _merge(state, cells, a):
    """Merge the two neighbouring cells that are narrowest together (their displacements
    averaged, weighted by the stiffness of their parts in contact, so the force is kept
    and the energy does not rise); returns the new count. ``a``: the contact radius at the
    previous step. Merging the narrowest pair keeps the cells nearly even in ``x``."""
    base1, base2 = HEADER + cells + 1, HEADER + 2 * cells + 1
    n = int(state[S_CELLS])
    best, width = 0, math.inf
    for i in range(n - 1):
        w = state[HEADER + i + 2] - state[HEADER + i]
        if w < width:
            best, width = i, w
    lo, mid, hi = state[HEADER + best], state[HEADER + best + 1], state[HEADER + best + 2]
    w1, w2 = max(min(mid, a) - lo, 0.0), max(min(hi, a) - mid, 0.0)
    if w1 + w2 > 0.0:
        s1 = (w1 * state[base1 + best] + w2 * state[base1 + best + 1]) / (w1 + w2)
        s2 = (w1 * state[base2 + best] + w2 * state[base2 + best + 1]) / (w1 + w2)
    else:
        s1, s2 = 0.0, 0.0
    state[base1 + best], state[base2 + best] = s1, s2
    for i in range(best + 1, n - 1):  # shift the cells beyond the pair down by one
        state[HEADER + i] = state[HEADER + i + 1]
        state[base1 + i], state[base2 + i] = state[base1 + i + 1], state[base2 + i + 1]
    state[HEADER + n - 1] = state[HEADER + n]
    return n - 1


def _cells_step(state, params, overlap, dxi1, dxi2, bound_factor):
    """Steps the cells (micro-slip or history) to ``overlap``; returns the springs' force
    ``(sum k_j s_j)``, the stiffness ``sum k_j`` the step's increment met (a fresh cell's
    counted with its share), the fresh cell's index (``-1``: none) and its share.
    ``bound_factor``: ``mu g`` for micro-slip, a negative number for the history spring
    (no per-cell bound)."""
    e, g, r = params[P_E], params[P_G], params[P_R]
    cells = int(params[P_CELLS])
    base1, base2 = HEADER + cells + 1, HEADER + 2 * cells + 1
    previous = state[S_OVERLAP]
    a = math.sqrt(r * overlap) if overlap > 0.0 else 0.0
    a_prev = math.sqrt(r * previous) if previous > 0.0 else 0.0
    n = int(state[S_CELLS])
    grow = overlap - previous
    if a > state[HEADER + n]:  # the contact grows past its largest radius so far
        if n == cells:
            n = _merge(state, cells, a_prev)
        lo = state[HEADER + n]
        share = _band(e, r, overlap, lo, a) / (2.0 * e * grow * (a - lo)) if grow > 0.0 else 0.0
        share = min(max(share, 0.0), 1.0)
        state[HEADER + n + 1] = a
        state[base1 + n], state[base2 + n] = share * dxi1, share * dxi2
        n += 1
        state[S_CELLS] = n
        fresh = n - 1
    else:
        fresh, share = -1, 0.0
    fresh_share = share
    f1, f2, stiffness = 0.0, 0.0, 0.0
    for j in range(n):
        lo, hi = state[HEADER + j], state[HEADER + j + 1]
        top = min(hi, a)
        if top <= lo:  # out of contact
            state[base1 + j], state[base2 + j] = 0.0, 0.0
            continue
        if j != fresh:
            before = min(hi, a_prev)
            if before <= lo:  # the contact re-enters the cell: it held nothing
                share = 0.0  # its springs all came into contact during the step
                if grow > 0.0:
                    share = _band(e, r, overlap, lo, top) / (2.0 * e * grow * (top - lo))
                    share = min(max(share, 0.0), 1.0)
                state[base1 + j], state[base2 + j] = share * dxi1, share * dxi2
            elif top > before:  # it re-enters part of the cell: average with the new part
                old, new = before - lo, top - before
                share = 0.0
                if grow > 0.0:
                    share = _band(e, r, overlap, before, top) / (2.0 * e * grow * new)
                    share = min(max(share, 0.0), 1.0)
                total = old + new
                state[base1 + j] = (old * (state[base1 + j] + dxi1) + new * share * dxi1) / total
                state[base2 + j] = (old * (state[base2 + j] + dxi2) + new * share * dxi2) / total
            else:
                state[base1 + j] += dxi1
                state[base2 + j] += dxi2
        k = 8.0 * g * (top - lo)
        c1, c2 = k * state[base1 + j], k * state[base2 + j]  # the cell's force
        if bound_factor >= 0.0:
            limit = bound_factor * _band(e, r, overlap, lo, top)
            square = c1 * c1 + c2 * c2
            if square > limit * limit:
                scale = limit / math.sqrt(square)
                state[base1 + j] *= scale
                state[base2 + j] *= scale
                c1, c2 = c1 * scale, c2 * scale
        f1 += c1
        f2 += c2
        stiffness += k * fresh_share if j == fresh else k
    return f1, f2, stiffness, fresh, fresh_share


def _history_slide(state, params, overlap, f1, f2, stiffness, cap, fresh, share):
    """Scales the history spring's force back to ``cap`` by a common correction of the
    elastic displacement increment (the cells in contact take it whole, the fresh cell its
    share); returns the force."""
    size = math.hypot(f1, f2)
    if size <= cap or stiffness <= 0.0:
        return f1, f2
    cells = int(params[P_CELLS])
    base1, base2 = HEADER + cells + 1, HEADER + 2 * cells + 1
    t1, t2 = f1 * cap / size, f2 * cap / size
    c1, c2 = (t1 - f1) / stiffness, (t2 - f2) / stiffness
    a = math.sqrt(params[P_R] * overlap)
    for j in range(int(state[S_CELLS])):
        if min(state[HEADER + j + 1], a) > state[HEADER + j]:
            weight = share if j == fresh else 1.0
            state[base1 + j] += weight * c1
            state[base2 + j] += weight * c2
    return t1, t2


def contact_force(state, params, overlap, overlap_rate, dxi1, dxi2, u1, u2):
    """Step one contact: ``(N, F1, F2)``, the normal force (N, pushing the bodies apart)
    and the tangential force on the body (N, in the two tangent directions) at the new
    step; ``state`` is updated in place.

    Parameters
    ----------
    state : ndarray
        The contact's state (:func:`new_state`); zeros before the first touch.
    params : ndarray
        :func:`parameters`.
    overlap : float
        ``delta`` at the new step, m (the contact is open where it is not positive).
    overlap_rate : float
        ``d delta/dt``, m/s (for the normal damping).
    dxi1, dxi2 : float
        The tangential displacement of the contact point over the step, m (``u dt``), in
        a basis of the tangent plane that the caller keeps for the contact. Where the
        contact normal turns, carry the basis along with it (as DEM codes rotate their
        shear history into the new tangent plane); the state's components then stay valid
        as they are.
    u1, u2 : float
        The contact point's tangential velocity, m/s (for the tangential damping).
    """
    if state.size < HEADER + 3 * int(params[P_CELLS]) + 1:
        raise ValueError("contact_force: state is smaller than params' cells need (new_state)")
    if not (overlap == overlap and dxi1 == dxi1 and dxi2 == dxi2):
        raise ValueError("contact_force: the overlap or the displacement is NaN")
    model = int(params[P_MODEL])
    if overlap <= 0.0:  # open: the contact forgets its history
        state[:] = 0.0
        return 0.0, 0.0, 0.0
    total, elastic = normal_force(params, overlap, overlap_rate)
    cap_force = total if params[P_LIMIT_TOTAL] > 0.0 else elastic
    cap = params[P_MU] * cap_force
    a = math.sqrt(params[P_R] * overlap)
    stiffness = 8.0 * params[P_G] * a
    if model == MICRO_SLIP:
        factor = params[P_MU] * cap_force / elastic if elastic > 0.0 else 0.0
        f1, f2, _k, _fresh, _share = _cells_step(state, params, overlap, dxi1, dxi2, factor)
    elif model == HISTORY:
        f1, f2, k, fresh, share = _cells_step(state, params, overlap, dxi1, dxi2, -1.0)
        f1, f2 = _history_slide(state, params, overlap, f1, f2, k, cap, fresh, share)
    elif model == INCREMENTAL or model == SCALED:
        f1, f2 = state[S_T1], state[S_T2]
        previous = state[S_OVERLAP]
        previous_a = math.sqrt(params[P_R] * previous) if previous > 0.0 else 0.0
        # the stiffness at the step's middle; while the scaled spring shrinks, its force is
        # the stiffness times the displacement, so the step's end stiffness is exact
        middle = 4.0 * params[P_G] * (a + previous_a)
        if model == SCALED and 0.0 < overlap < previous:
            f1, f2 = f1 * a / previous_a, f2 * a / previous_a
            middle = stiffness
        f1 = f1 + middle * dxi1
        f2 = f2 + middle * dxi2
        size = math.hypot(f1, f2)
        if size > cap:
            f1, f2 = f1 * cap / size, f2 * cap / size
        state[S_T1], state[S_T2] = f1, f2
    else:  # TOTAL
        x1, x2 = state[S_T1] + dxi1, state[S_T2] + dxi2
        size = stiffness * math.hypot(x1, x2)
        if size > cap:
            x1, x2 = x1 * cap / size, x2 * cap / size
        state[S_T1], state[S_T2] = x1, x2
        f1, f2 = stiffness * x1, stiffness * x2
    state[S_OVERLAP] = overlap
    beta_t = params[P_TANGENT_COEF]
    if beta_t > 0.0:
        c = VISCOUS_FACTOR * beta_t * math.sqrt(stiffness * params[P_M])
        f1 += c * u1
        f2 += c * u2
        if params[P_DAMPING_CAPPED] > 0.0:
            size = math.hypot(f1, f2)
            if size > cap:
                f1, f2 = f1 * cap / size, f2 * cap / size
    return total, -f1, -f2


def tangential_energy(state, params, overlap):
    """The elastic energy the tangential springs hold (J): ``sum k_j |s_j|^2/2`` over the
    cells in contact, or ``|F|^2/(2 k_t)`` and ``k_t |xi|^2/2`` for the variants."""
    if overlap <= 0.0:
        return 0.0
    model = int(params[P_MODEL])
    g, r = params[P_G], params[P_R]
    a = math.sqrt(r * overlap)
    stiffness = 8.0 * g * a
    if model == INCREMENTAL or model == SCALED:
        return (state[S_T1] ** 2 + state[S_T2] ** 2) / (2.0 * stiffness)
    if model == TOTAL:
        return 0.5 * stiffness * (state[S_T1] ** 2 + state[S_T2] ** 2)
    cells = int(params[P_CELLS])
    base1, base2 = HEADER + cells + 1, HEADER + 2 * cells + 1
    energy = 0.0
    for j in range(int(state[S_CELLS])):
        lo = state[HEADER + j]
        top = min(state[HEADER + j + 1], a)
        if top > lo:
            energy += 4.0 * g * (top - lo) * (state[base1 + j] ** 2 + state[base2 + j] ** 2)
    return energy
