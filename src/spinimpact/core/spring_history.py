"""The loading history of the "history" spring of :mod:`spinimpact.core.tangential`.

While a Hertz contact sticks and its area shrinks, only the force beyond the loading
history's at the same compression unloads with the stiffness (the exact no-slip elastic
solution, a superposition of flat-punch increments: Mindlin & Deresiewicz 1953). This
module keeps that history, ``F_mem(delta)``, and the elastic energy of its traction field,
``U_mem(delta)``: the field of a sliding contact below the compression where it last slid,
the recorded stick phase of loading above it.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["History", "loading_history", "sliding_history", "history_energy"]


def sliding_history(k, n, r, force, delta):
    """:class:`History` of a contact sliding with force ``force`` at compression ``delta``:
    the field ``F/N_el(delta)`` times ``N_el`` below it."""
    return History(k, n, r, force / (k * delta**n) if delta > 0 else 0.0)


class History:
    """The loading history of spring="history" at one time: the force ``F_mem(delta)``
    and the elastic energy ``U_mem(delta)`` of its traction field. Below ``split`` it is the
    field of a sliding contact, ``F_mem = coef k delta^n`` (``coef = F/N_el`` when it last
    slid) with ``U_mem = n F_mem^2/((n + 1) k_t)``; above, the last stick phase of loading, cubic
    splines in ``s = sqrt(d_max - delta)`` (smooth through the end of compression)."""

    def __init__(self, k, n, r, coef, split=math.inf, spline=None, energy=None, d_max=0.0):
        self.k, self.n, self.r, self.coef, self.split = k, n, r, coef, split
        self.spline, self.energy_spline, self.d_max = spline, energy, d_max

    def _sliding(self, d):
        return self.coef * self.k * max(d, 0.0) ** self.n

    def __call__(self, d):
        if self.spline is None or d <= self.split:
            return self._sliding(d)
        return float(self.spline(math.sqrt(max(self.d_max - d, 0.0))))

    def energy(self, d):
        """``U_mem(delta)``, J: the elastic energy of the history's traction field."""
        if self.spline is None or d <= self.split:
            stiff = self.r * self.n * self.k * max(d, 0.0) ** (self.n - 1.0)
            share = self.n / (self.n + 1.0)  # the sliding field's: n F^2/((n + 1) k_t)
            return share * self._sliding(d) ** 2 / stiff if stiff > 0 else 0.0
        return float(self.energy_spline(math.sqrt(max(self.d_max - d, 0.0))))


def loading_history(segment, y_end, k, n, r, points=1025):
    """:class:`History` of a loading ``segment`` (``(start, end, dense, stick, ...)``) at
    its end, state ``y_end``: the sliding field if it slid, else its stick phase recorded."""
    from scipy.interpolate import CubicSpline

    start, end, dense, stick = segment[:4]
    d_max = float(y_end[0])
    if not stick:  # it ended sliding: the field is the sliding one
        return History(k, n, r, y_end[7] / (k * d_max**n))
    y_start = dense(start)
    d_start, f_start = float(y_start[0]), float(y_start[7])
    coef = f_start / (k * d_start**n) if d_start > 0 else 0.0
    below = History(k, n, r, coef)
    # Chebyshev points in time, clustered at both ends of the stick phase
    times = start + (end - start) * 0.5 * (1.0 - np.cos(np.linspace(0.0, math.pi, points)))
    d, force = dense(times)[[0, 7]]
    stiff = r * n * k * np.maximum(d, 0.0) ** (n - 1.0)
    # U = U(start) + integral of F dF / k_t along the phase (trapezoids)
    rate = np.where(stiff > 0, force / np.where(stiff > 0, stiff, 1.0), 0.0)
    steps = 0.5 * (rate[1:] + rate[:-1]) * np.diff(force)
    energy = below.energy(d_start) + np.concatenate(([0.0], np.cumsum(steps)))
    s = np.sqrt(np.maximum(d_max - d, 0.0))[::-1]
    keep = np.concatenate(([True], np.diff(s) > 0))  # strictly increasing abscissae
    s, force, energy = s[keep], force[::-1][keep], energy[::-1][keep]
    return History(k, n, r, coef, d_start, CubicSpline(s, force), CubicSpline(s, energy),
                    d_max)  # fmt: skip


def history_energy(segments, times, delta, force, stiff, stuck, sliding, k, n, r):
    """The springs' energy under spring="history": that of the traction field,
    ``U_mem + F_mem D + k_t D^2/2`` with ``D = (F - F_mem)/k_t`` while it sticks
    (the sliding field's ``n F^2/((n + 1) k_t)`` while it slides; ``sliding`` is
    ``F^2/(2 k_t)``)."""
    out = sliding * (2.0 * n / (n + 1.0))  # sliding: n F^2/((n + 1) k_t)
    for i, segment in enumerate(segments):
        start, end, dense, stick, _sigma, memory = segment
        if not stick:
            continue
        last = i == len(segments) - 1
        rows = np.flatnonzero((times >= start) & ((times < end) | last) & stuck)
        if memory is None:  # loading: the phase's own record
            record = loading_history(segment, dense(end), k, n, r)
            out[rows] = [record.energy(d) for d in delta[rows]]
            continue
        for j in rows:
            held = memory(delta[j])
            d = (force[j] - held) / stiff[j] if stiff[j] > 0 else 0.0
            out[j] = memory.energy(delta[j]) + held * d + 0.5 * stiff[j] * d * d
    return out
