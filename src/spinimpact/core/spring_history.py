"""The loading history of the "history" spring of :mod:`spinimpact.core.tangential`.

While a Hertz contact sticks and its area shrinks, only the force beyond the loading
history's at the same compression unloads with the stiffness (the exact no-slip elastic
solution, a superposition of flat-punch increments: Mindlin & Deresiewicz 1953). This
module keeps that history: the tangential force ``F_mem(delta)`` at each compression while
the contact was loaded (stuck or sliding), and the energy ``U_mem(delta)``, the integral of
``F dF/k_t`` along it, which the field built by those increments holds.
"""

from __future__ import annotations

import bisect
import math

import numpy as np

__all__ = ["History", "loading_history", "history_energy"]


class History:
    """``F_mem(delta)`` and ``U_mem(delta)`` over the loading, as cubic splines in
    ``s = sqrt(d_max - delta)`` (smooth through the end of compression), one per
    stick or slip phase of the loading (the force has a kink at each switch). The force
    is kept as its ratio to the elastic normal force ``k delta^n``, finite at touch."""

    def __init__(self, d_max, k, n, pieces):
        self.d_max, self.k, self.n = d_max, k, n
        self.pieces = pieces  # [(s_low, F/N_el spline, energy spline)], s_low increasing
        self._lows = [p[0] for p in pieces]

    def ratio(self, d):
        """``F_mem/(k delta^n)``."""
        s, (_low, ratio, _energy) = self._piece(d)
        return float(ratio(s))

    def _piece(self, d):
        s = math.sqrt(max(self.d_max - d, 0.0))
        return s, self.pieces[max(bisect.bisect_right(self._lows, s) - 1, 0)]

    def __call__(self, d):
        if d <= 0.0:
            return 0.0
        return self.ratio(d) * self.k * d**self.n

    def energy(self, d):
        """``U_mem(delta)``, J: the energy of the loading history's traction field."""
        if d <= 0.0:
            return 0.0
        s, (_low, _force, energy) = self._piece(d)
        return float(energy(s))


def loading_history(segments, y_end, k, n, r, force_of, points=1025):
    """:class:`History` of the loading ``segments`` (``(start, end, dense, stick, sigma)``,
    from touch to the end of compression, state ``y_end``); ``force_of(y, stick, sigma)``
    is the tangential force of a state (the spring's while stuck, ``sigma mu N`` while
    sliding)."""
    from scipy.interpolate import CubicSpline

    d_max = float(y_end[0])
    runs, energy = [], 0.0
    for start, end, dense, stick, sigma in segments:
        # Chebyshev points in time, clustered at both ends of the phase
        times = start + (end - start) * 0.5 * (1.0 - np.cos(np.linspace(0.0, math.pi, points)))
        states = dense(times)
        d = states[0]
        force = np.array([force_of(states[:, i], stick, sigma) for i in range(points)])
        stiff = r * n * k * np.maximum(d, 0.0) ** (n - 1.0)
        rate = np.divide(force, stiff, out=np.zeros_like(force), where=stiff > 0)
        cumulative = energy + np.concatenate(([0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1])
                                                                * np.diff(force))))  # fmt: skip
        energy = float(cumulative[-1])
        s = np.sqrt(np.maximum(d_max - d, 0.0))[::-1]
        keep = np.concatenate(([True], np.diff(s) > 0))  # strictly increasing abscissae
        keep &= (d > 0.0)[::-1]  # F/N_el is finite at touch, but 0/0 there
        if keep.sum() >= 2:
            q = (force / (k * np.where(d > 0.0, d, 1.0) ** n))[::-1]
            s, q, u = s[keep], q[keep], cumulative[::-1][keep]
            runs.append((float(s[0]), CubicSpline(s, q), CubicSpline(s, u)))
    runs.sort(key=lambda p: p[0])
    return History(d_max, k, n, runs)


def history_energy(memory, t0, times, delta, force, stiff):
    """The springs' energy under spring="history": the traction field's, ``U_mem`` while
    loading and ``U_mem + F_mem D + k_t D^2/2`` with ``D = (F - F_mem)/k_t`` after."""
    out = np.zeros(times.size)
    for j, (t, d, f, k_t) in enumerate(zip(times, delta, force, stiff, strict=True)):
        if memory is None or d <= 0.0:
            out[j] = f * f / (2.0 * k_t) if k_t > 0 else 0.0
            continue
        held, stored = memory(d), memory.energy(d)
        if t <= t0:
            out[j] = stored
            continue
        gap = (f - held) / k_t if k_t > 0 else 0.0
        out[j] = stored + held * gap + 0.5 * k_t * gap * gap
    return out
