r"""A bounce predicted from the incoming samples of a track alone, with its uncertainty.

:func:`predict_bounce` does what a robot must: it fits the incoming flight
(:func:`spinimpact.model.track_arc.fit_arc`), then predicts the contact, the bounce and the
outgoing flight (:func:`spinimpact.model.track_bounce.flights`) with the shared parameters of
an earlier :func:`spinimpact.model.track_fit.fit_bounces`, and a band: the covariance of the
incoming state and of the shared parameters carried through by finite differences
(linearized), all perturbed flights in one batch.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .flight import AIR_DENSITY, GRAVITY
from .presets import Ball
from .presets import ball as as_ball
from .track import Air, Track, plain
from .track_arc import ArcFit, fit_arc
from .track_bounce import (
    BOUNDS,
    CONTACT,
    LAWS,
    SHARED_STEP,
    STEP,
    AtContact,
    flights,
    shared_names,
)
from .track_fit import BounceFit

__all__ = ["Prediction", "predict_bounce"]


@dataclass(frozen=True, eq=False)
class Prediction(AtContact):
    """A bounce and the outgoing flight predicted from an incoming track
    (:func:`predict_bounce`); track's frame.

    Attributes
    ----------
    name : str
    incoming : ArcFit
        The incoming samples' fit.
    time : ndarray, shape (m,)
        s, the times predicted.
    position : ndarray, shape (m, 3)
        m, the predicted centre.
    standard_error : ndarray, shape (m, 3)
        m, of each coordinate (linearized).
    low, high : ndarray, shape (m, 3)
        The band at ``confidence``: ``position -+ z standard_error``.
    contact_time : float
        s.
    contact_position, velocity_before, spin_before, velocity_after, spin_after : ndarray
        At the predicted contact (m, m/s, rad/s).
    contact_standard_error : dict
        The standard error of each of the above (and ``contact_time``).
    confidence : float
    """

    name: str
    incoming: ArcFit
    time: np.ndarray
    position: np.ndarray
    standard_error: np.ndarray
    low: np.ndarray
    high: np.ndarray
    contact_standard_error: dict
    confidence: float

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain numbers, lists and dicts."""
        return plain(self, {"incoming": lambda arc: arc.to_dict(),
                            "contact_standard_error": lambda d: {
                                a: np.asarray(b).tolist() for a, b in d.items()}})  # fmt: skip


def predict_bounce(track: Track, shared: BounceFit | dict[str, float], *,
                   ball: Ball | str | None = None, law: str | None = None, times: Any = None,
                   horizon: float = 0.25, until: float | None = None, sigma: float | None = None,
                   confidence: float = 0.95, air_density: float | None = None,
                   gravity: float | None = None,
                   spin_prior: Any = "fit") -> Prediction:  # fmt: skip
    """Predict the bounce and the outgoing flight from a track's incoming samples alone.

    Parameters
    ----------
    track : Track
        The incoming samples (those after ``until``, if given, are left out).
    shared : BounceFit or dict
        The surface's and ball's shared parameters (``mu``, ``kappa``, ``contact_height``,
        the law's own: ``beta0`` for Walton, ``poisson_ratio`` for micro-slip): a
        :func:`fit_bounces` result (its covariance then widens the
        band) or plain values.
    ball, law, air_density, gravity
        Taken from ``shared`` when it is a :class:`BounceFit`; otherwise ``table-tennis``,
        ``rigid``, sea-level air and standard gravity unless given.
    times : array_like, optional
        s, the times to predict (any, before or after the contact); by default 51 times from
        the predicted contact to ``horizon`` after it.
    horizon : float
        s.
    until : float, optional
        s: only samples before it are used (a prefix of the track).
    sigma : float, optional
        m, the noise of a coordinate of the incoming samples (default: estimated).
    confidence : float
        Of the band.
    spin_prior : dict, "fit" or None
        The incoming fit's prior on spin components (:func:`fit_arc`'s ``spin_prior``,
        ``{"gyrospin": (mean, sd)}`` in rad/s). ``"fit"`` (the default): the gyrospin of
        the shots ``shared`` was fitted to (:meth:`BounceFit.spin_prior`), when ``shared``
        is a :class:`BounceFit`, and none otherwise; ``None``: none. The incoming arc alone
        leaves the gyrospin loose, and the law turns it into a sideways velocity after the
        bounce (``docs/track.md`` measures what the prior changes).

    Returns
    -------
    Prediction

    Raises
    ------
    ValueError
        Too few incoming samples, an incoming flight that never reaches the surface, or shared
        values missing; each names the track.
    """
    from scipy.special import ndtri

    if not isinstance(track, Track):
        raise TypeError(f"track must be a Track (spinimpact.model.track.as_track), got {track!r}")
    if isinstance(shared, BounceFit):
        ball_, law_ = shared.ball, shared.law
        density, g = shared.air_density, shared.gravity
        values, cov_names, cov_shared = shared.values, list(shared.free), shared.covariance
    elif isinstance(shared, dict):
        ball_, law_ = as_ball(ball or "table-tennis"), law or "rigid"
        density = AIR_DENSITY if air_density is None else air_density
        g = GRAVITY if gravity is None else gravity
        values, cov_names, cov_shared = dict(shared), [], np.zeros((0, 0))
    else:
        raise TypeError(f"shared must be a BounceFit or a dict of values, got {shared!r}")
    if law_ not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, got {law_!r}")
    names = shared_names(law_)
    missing = [n for n in names if n not in values]
    if missing:
        raise ValueError(f"shared values missing: {', '.join(missing)}")
    for n in (*names, "lift_slope"):
        if n not in values:
            continue
        v, (lo, hi) = values[n], BOUNDS[n]
        if isinstance(v, bool) or not isinstance(v, int | float | np.floating | np.integer):
            raise TypeError(f"shared[{n!r}] must be a number, got {v!r}")
        if not lo <= v <= hi:  # NaN too
            raise ValueError(f"shared[{n!r}] must be in [{lo:g}, {hi:g}], got {v!r}")
    if "lift_slope" in values:  # the ball's lift slope, fitted or given: flown throughout
        names += ("lift_slope",)
        ball_ = ball_.replace(lift_slope=float(values["lift_slope"]))
    if isinstance(spin_prior, str):
        if spin_prior != "fit":
            raise ValueError(f"spin_prior must be a dict, 'fit' or None, got {spin_prior!r}")
        spin_prior = shared.spin_prior() if isinstance(shared, BounceFit) else None
    incoming = track if until is None else track.select(track.time < until)
    arc = fit_arc(incoming, ball_, sigma=sigma, air_density=density, gravity=g,
                  spin_prior=spin_prior)  # fmt: skip
    air = Air(ball_, density, g)
    t0 = arc.time
    base = arc.state
    k = len(cov_names)
    steps = np.r_[STEP, [SHARED_STEP[n] for n in cov_names]]
    batch = np.vstack([base, base + np.diag(STEP), np.repeat(base[None], k, 0)])
    sh = {n: np.full(len(batch), float(values[n])) for n in names}
    for j, n in enumerate(cov_names):
        sh[n][11 + j] += SHARED_STEP[n]
    empty = np.zeros((1, 0))
    first = flights(np.array([t0]), batch[:1], {n: v[:1] for n, v in sh.items()}, air, law_,
                    empty, empty, track.up)  # fmt: skip
    if not np.isfinite(first["contact_time"][0]):
        raise ValueError(f"track {track.name}: the incoming flight does not reach the surface")
    tc = float(first["contact_time"][0])
    when = (tc + np.linspace(0.0, horizon, 51) if times is None
            else np.sort(np.asarray(times, dtype=float)))  # fmt: skip
    split = int(np.searchsorted(when, tc, side="right"))
    b = len(batch)
    fl = flights(np.full(b, t0), batch, sh, air, law_, np.repeat(when[None, :split], b, 0),
                 np.repeat(when[None, split:], b, 0), track.up)  # fmt: skip
    fl["position"] = np.concatenate([fl["before"], fl["after"]], axis=1)
    cov = np.zeros((10 + k, 10 + k))
    cov[:10, :10] = np.where(np.isfinite(arc.covariance), arc.covariance, 0.0)
    cov[10:, 10:] = cov_shared
    z = float(ndtri(0.5 + confidence / 2))

    def spread(a: np.ndarray) -> np.ndarray:
        d = (a[1:] - a[0]) / steps.reshape((-1,) + (1,) * (a.ndim - 1))
        d = d.reshape(len(steps), -1)
        return np.sqrt(np.einsum("ij,ik,kj->j", d, cov, d)).reshape(a.shape[1:])

    se = spread(fl["position"])
    ckeys = CONTACT
    return Prediction(
        name=track.name, incoming=arc, time=when, position=fl["position"][0],
        standard_error=se, low=fl["position"][0] - z * se, high=fl["position"][0] + z * se,
        contact_time=tc, **{c: fl[c][0] for c in ckeys},
        contact_standard_error={"contact_time": float(spread(fl["contact_time"])),
                                **{c: spread(fl[c]) for c in ckeys}},
        confidence=confidence,
    )  # fmt: skip
