r"""Tracks across a bounce fitted: the incoming and outgoing flights joined by the exact law.

A track that crosses a level surface holds two flights. :func:`fit_bounces` fits them jointly:
each shot's state before the bounce (position, velocity, spin and drag coefficient at its
first sample) is flown to the surface, bounced by the exact 3D law of
:func:`spinimpact.solve_sphere` (rigid, with Walton's tangential restitution or with
micro-slip) and flown on
(:func:`spinimpact.model.track_bounce.flights`). The spin after the bounce is therefore the
law's prediction, and the outgoing positions test it. Several shots share the surface's
``mu`` and ``kappa``, the law's own parameter (Walton's ``beta0``, micro-slip's Poisson
ratio) and the height of the ball's centre at contact
(``contact_height``, in the tracks' frame): one fit over many shots, with standard errors and
profile-likelihood intervals as :func:`spinimpact.fit` gives them.

:func:`spinimpact.model.track_predict.predict_bounce` then predicts new tracks' bounces from
their incoming samples alone. Every evaluation flies all shots, and all perturbed states of
each, in one batch (:func:`spinimpact.model.track_bounce.flights`, in the least-squares problem
of :mod:`spinimpact.model.track_joint`); the loops run over time steps and iterations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .flight import AIR_DENSITY, GRAVITY
from .presets import Ball, Ground
from .presets import ball as as_ball
from .presets import ground as as_ground
from .track import Air, Bounce, Track, find_bounce, plain
from .track_arc import (
    IDENTIFIABILITY,
    OUTLIER_SIGMAS,
    SPIN_COMPONENTS,
    ArcFit,
    covariance,
    fit_arc,
    identify,
)
from .track_bounce import BOUNDS, CONTACT, LAWS, AtContact, flights, padded, shared_names
from .track_joint import Joint, profile

__all__ = ["BounceFit", "Shot", "fit_bounces", "MIN_CHECK"]


@dataclass(frozen=True, eq=False)
class Shot(AtContact):
    """One track of a bounce fit: its split, its fitted flights and their check.

    Attributes
    ----------
    name : str
    time : float
        s, when ``state`` holds (the first sample).
    state : ndarray, shape (10,)
        Position (m), velocity (m/s), spin (rad/s) and ``C_D`` (track's frame).
    standard_error : ndarray, shape (10,)
    split : int
        The first sample after the contact.
    contact_time : float
        s.
    contact_position, velocity_before, spin_before, velocity_after, spin_after : ndarray
        At the contact, track's frame (m, m/s, rad/s); the spin after is the law's.
    spin_components_before : dict
        As :attr:`ArcFit.spin_components`, for the spin before the bounce.
    outgoing_check : ArcFit or None
        The outgoing samples fitted alone (their state at the contact, ``C_D`` held at the
        shot's): their spin, from the curvature only, beside the law's ``spin_after``.
    fitted, residuals : ndarray, shape (n, 3)
        m.
    outliers : ndarray of bool
    rms_before, rms_after : float
        m, the rms 3D distance of the kept samples before and after the contact.
    """

    name: str
    time: float
    state: np.ndarray
    standard_error: np.ndarray
    split: int
    spin_components_before: dict
    outgoing_check: ArcFit | None
    fitted: np.ndarray
    residuals: np.ndarray
    outliers: np.ndarray
    rms_before: float
    rms_after: float
    track: Track = field(repr=False)

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain numbers and lists (the track left out; of the outgoing
        check its spin, their standard errors and words)."""

        def check(c: ArcFit | None) -> dict | None:
            if c is None:
                return None
            d = c.to_dict()
            return {"spin": d["spin"], "standard_error": d["standard_error"][6:9],
                    "spin_components": d["spin_components"]}  # fmt: skip

        return plain(self, {"outgoing_check": check})


@dataclass(frozen=True, eq=False)
class BounceFit:
    """The shared parameters of a surface and a ball fitted to tracks (:func:`fit_bounces`).

    Attributes
    ----------
    law : str
        ``rigid``, ``walton`` or ``mindlin-deresiewicz``.
    names : tuple of str
        Every shared parameter (``mu``, ``kappa``, ``contact_height``; ``beta0`` for Walton,
        ``poisson_ratio`` for micro-slip).
    values : dict
        Each shared parameter's value (fitted or fixed).
    free : tuple of str
        The fitted ones.
    standard_error, interval_low, interval_high : dict
        Of each fitted parameter: from the curvature, and the profile-likelihood interval at
        ``confidence`` (NaN when intervals were not asked for).
    one_sided : dict
        Which intervals are open to a bound (the profile stays below the threshold there).
    covariance : ndarray
        Of the fitted shared parameters, in the order of ``free``.
    confidence : float
    sigma : float
        m, the noise of a coordinate (given, or estimated from the kept samples).
    sigma_given : bool
    chi2 : float
    dof : int
    shots : tuple of Shot
    ball : Ball
    air_density, gravity : float
    """

    law: str
    names: tuple
    values: dict
    free: tuple
    standard_error: dict
    interval_low: dict
    interval_high: dict
    one_sided: dict
    covariance: np.ndarray
    confidence: float
    sigma: float
    sigma_given: bool
    chi2: float
    dof: int
    shots: tuple
    ball: Ball
    air_density: float
    gravity: float

    def __getitem__(self, name: str) -> float:
        return self.values[name]

    def summary(self) -> str:
        """The shared parameters, one line each, and each shot's residuals."""
        head = (f"bounce law {self.law}: {len(self.shots)} shot(s), noise "
                f"{1e3 * self.sigma:.2f} mm ({'given' if self.sigma_given else 'estimated'}), "
                f"chi2 {self.chi2:.1f} for {self.dof} degrees of freedom")  # fmt: skip
        lines = [head]
        pct = f"{100 * self.confidence:g} %"
        for n in self.names:
            if n not in self.free:
                lines.append(f"  {n} = {self.values[n]:.5g} (fixed)")
                continue
            lo, hi = self.interval_low[n], self.interval_high[n]
            ci = "" if math.isnan(lo) else f" [{lo:.5g}, {hi:.5g}] ({pct} profile)"
            lines.append(f"  {n} = {self.values[n]:.5g} +- {self.standard_error[n]:.2g}{ci}")
        for s in self.shots:
            lines.append(f"  {s.name}: contact at {s.contact_time:.4f} s, rms "
                         f"{1e3 * s.rms_before:.2f} mm before, {1e3 * s.rms_after:.2f} mm after, "
                         f"{int(s.outliers.sum())} outlier(s)")  # fmt: skip
        return "\n".join(lines)

    def spin_prior(self, components: Any = ("gyrospin",)) -> dict[str, tuple[float, float]]:
        """A prior for the spin of new shots like these (empirical Bayes), for
        :func:`~spinimpact.model.track_fit.fit_arc`'s and
        :func:`~spinimpact.model.track_predict.predict_bounce`'s ``spin_prior``.

        For each component named, the median and the robust standard deviation (1.4826
        times the median absolute deviation, at least 1 rad/s) of the shots' spin before
        the bounce, over the shots whose fit determines it (``determined``): there the
        outgoing flight, through the bounce law, shows what the incoming arc alone cannot.
        The gyrospin (about the heading) acts on an incoming flight only through the lift's
        saturation, so an incoming arc leaves it loose, and the bounce law turns it into a
        sideways velocity; the default prior holds it near what the fitted shots showed.

        Parameters
        ----------
        components : sequence of str
            Of ``topspin``, ``sidespin``, ``gyrospin``.

        Returns
        -------
        dict
            ``{component: (mean, sd)}``, rad/s; a component no shot determines is left out.
        """
        out = {}
        for name in components:
            if name not in SPIN_COMPONENTS:
                raise ValueError(f"unknown spin component {name!r}; the components are "
                                 f"{', '.join(SPIN_COMPONENTS)}")  # fmt: skip
            v = np.array([s.spin_components_before[name][0] for s in self.shots
                          if s.spin_components_before[name][2] == IDENTIFIABILITY[0]])  # fmt: skip
            if v.size:
                mid = float(np.median(v))
                out[name] = (mid, max(1.4826 * float(np.median(np.abs(v - mid))), 1.0))
        return out

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain numbers, lists and dicts."""
        return plain(self, {"shots": lambda shots: [x.to_dict() for x in shots],
                            "ball": lambda b: b.to_dict()})  # fmt: skip


#: The fewest samples after a bounce for which the outgoing flight is also fitted alone (the
#: check of the law's spin after the bounce against the outgoing curvature).
MIN_CHECK = 10


def _flown(prob: Any, x: np.ndarray, details: bool = False) -> Any:
    """Every sample of every track flown with the parameters ``x`` (a list of ``(n, 3)``),
    or, with ``details``, a dict with ``position`` (that list) and the contacts."""
    grids = [
        padded([tr.time[:sp] for tr, sp in zip(prob.tracks, prob.splits, strict=True)]),
        padded([tr.time[sp:] for tr, sp in zip(prob.tracks, prob.splits, strict=True)]),
    ]
    fl = flights(prob.t0, prob.states(x), prob.shared(x, len(prob.tracks)), prob.air, prob.law,
                 grids[0], grids[1], prob.up)  # fmt: skip
    pos = [np.concatenate([fl["before"][i, :sp], fl["after"][i, : len(tr) - sp]])
           for i, (tr, sp) in enumerate(zip(prob.tracks, prob.splits, strict=True))]  # fmt: skip
    if not details:
        return pos
    return {"position": pos, **{key: fl[key] for key in ("contact_time", *CONTACT)}}


def _split(track: Track, bounce: Bounce | None, min_after: int) -> int:
    b = find_bounce(track) if bounce is None else bounce
    split = int(b["index"])
    if len(track) - split < min_after:
        raise ValueError(f"track {track.name}: {len(track) - split} sample(s) after the bounce "
                         f"(from row {track.rows[min(split, len(track) - 1)]}); at least "
                         f"{min_after} are needed")  # fmt: skip
    return split


def fit_bounces(tracks: Any, ball: Ball | str = "table-tennis", surface: Ground | str = "table",
                *, law: str = "rigid", fixed: dict[str, float] | None = None,
                free_lift: bool = False, bounces: Any = None, sigma: float | None = None,
                confidence: float = 0.95, intervals: bool = True, air_density: float = AIR_DENSITY,
                gravity: float = GRAVITY, min_after: int = 3) -> BounceFit:  # fmt: skip
    """Fit the incoming and outgoing flights of tracks jointly through the exact bounce.

    Parameters
    ----------
    tracks : Track or sequence of Track
        Each crosses the surface once (:func:`~spinimpact.model.track.find_bounce` splits it).
    ball : Ball or str
        The ball (mass, radius, inertia, lift law; its ``C_D`` only starts each shot's own).
    surface : Ground or str
        Starting ``mu`` and ``kappa`` (or their values, when fixed).
    law : {"rigid", "walton", "mindlin-deresiewicz"}
        The bounce law: rigid contact with Coulomb friction, Walton's tangential
        restitution (``beta0`` shared, starting at 0), or Hertz-Mindlin-Deresiewicz
        micro-slip (``poisson_ratio`` of the ball on a rigid table shared, starting at 0.3;
        ``kappa`` must stay above 0): read from its table
        (:mod:`spinimpact.core.mdr_table`) where ``kappa >= 0.85`` and ``nu <= 1/3`` for a
        thin shell, solved in time elsewhere (tens of milliseconds for each ``kappa`` tried).
    fixed : dict, optional
        Shared parameters held at given values (``{"contact_height": 0.759}``).
    free_lift : bool
        Fit the ball's lift slope ``a`` too (shared; :mod:`spinimpact.core.aero`): the spin
        the law gives after the bounce, seen in the outgoing curvature, determines it. The
        result's ``ball`` then carries the fitted slope, and predictions fly with it.
    bounces : sequence of Bounce, optional
        Where each track is split (default: found from its positions).
    sigma : float, optional
        m, the noise of a coordinate; by default estimated from the scatter.
    confidence : float
        Of the profile-likelihood intervals.
    intervals : bool
        Compute the profile-likelihood intervals (each point a joint re-fit).
    air_density, gravity : float
        kg/m^3, m/s^2.
    min_after : int
        The fewest samples after the bounce a track may have.

    Returns
    -------
    BounceFit

    Raises
    ------
    TypeError
        A track that is not a :class:`~spinimpact.model.track.Track`.
    ValueError
        A track without a bounce, with too few samples before or after it, an unknown law or
        parameter; each names the track (and the row where it applies).
    """
    from scipy.special import chdtri, fdtri

    tracks = [tracks] if isinstance(tracks, Track) else list(tracks)
    if not tracks:
        raise ValueError("no tracks to fit")
    for tr in tracks:
        if not isinstance(tr, Track):
            raise TypeError(f"tracks must be Track objects (spinimpact.model.track.as_track), "
                            f"got {tr!r}")  # fmt: skip
    if law not in LAWS:
        raise ValueError(f"law must be one of {', '.join(LAWS)}, got {law!r}")
    if not 0 < confidence < 1:
        raise ValueError(f"confidence must be in (0, 1), got {confidence!r}")
    ball_, ground_ = as_ball(ball), as_ground(surface)
    names = shared_names(law)
    names += ("lift_slope",) if free_lift or "lift_slope" in (fixed or {}) else ()
    fixed = dict(fixed or {})
    for n, v in fixed.items():
        if n not in names:
            raise ValueError(f"fixed names an unknown parameter {n!r}; this law has "
                             f"{', '.join(names)}")  # fmt: skip
        lo, hi = BOUNDS[n]
        if not (isinstance(v, int | float) and lo <= v <= hi):
            raise ValueError(f"fixed[{n!r}] must be a number in [{lo:g}, {hi:g}], got {v!r}")
    given = [None] * len(tracks) if bounces is None else list(bounces)
    splits = [_split(tr, b, min_after) for tr, b in zip(tracks, given, strict=True)]
    heights = [float(find_bounce(tr)["height"]) if b is None else float(b["height"])
               for tr, b in zip(tracks, given, strict=True)]  # fmt: skip
    air = Air(ball_, air_density, gravity)
    starts = [
        fit_arc(
            tr.select(slice(0, sp)), ball_, sigma=sigma, air_density=air_density, gravity=gravity
        ).state
        for tr, sp in zip(tracks, splits, strict=True)
    ]
    ups = {tr.up for tr in tracks}
    if len(ups) > 1:
        raise ValueError("the tracks' frames differ (up = " + ", ".join(sorted(ups)) + ")")
    init = {"mu": ground_.mu, "kappa": ground_.kappa, "contact_height": float(np.median(heights)),
            "lift_slope": ball_.lift_slope,
            "beta0": 0.0, "poisson_ratio": 0.3}  # fmt: skip
    prob = Joint(tracks, splits, air, law, names, {n: float(v) for n, v in fixed.items()},
                  ups.pop())  # fmt: skip
    x0 = np.r_[[init[n] for n in prob.free], np.concatenate(starts)]
    robust = prob.solve(x0, "soft_l1", 3.0 * (sigma or 2e-3))
    everything = _flown(prob, robust.x)
    res = [np.abs(tr.position - f) for tr, f in zip(tracks, everything, strict=True)]
    noise = sigma or max(1.4826 * float(np.median(np.concatenate(res))), 1e-5)
    prob.set_keep([~np.any(r > OUTLIER_SIGMAS * noise, axis=1) for r in res])
    best = prob.solve(robust.x)
    x = best.x
    chi = 2.0 * float(best.cost)
    dof = prob.n_obs - x.size
    s2 = sigma**2 if sigma is not None else chi / max(dof, 1)
    cov = covariance(prob.jacobian(x).toarray(), s2)
    k = prob.k
    se_all = np.sqrt(np.diag(cov))
    low, high, one = {}, {}, {}
    q = float(chdtri(1, 1.0 - confidence) if sigma is not None else fdtri(1, dof, confidence))
    for j, n in enumerate(prob.free):
        if intervals:
            low[n], high[n], one[n] = profile(prob, x, j, chi, s2, q, se_all[j])
        else:
            low[n], high[n], one[n] = math.nan, math.nan, False
    fl = _flown(prob, x, details=True)
    shots = []
    for i, tr in enumerate(tracks):
        state = prob.states(x)[i]
        at = {key: fl[key][i] for key in CONTACT}
        resid = tr.position - fl["position"][i]
        kp, sp = prob.keep[i], splits[i]
        d2 = np.sum(resid**2, axis=1)
        check = None
        if (len(tr) - sp) >= MIN_CHECK:
            check = fit_arc(tr.select(slice(sp, None)), ball_, at=float(fl["contact_time"][i]),
                            sigma=sigma, drag_coefficient=float(state[9]),
                            air_density=air_density, gravity=gravity,
                            start=np.r_[at["contact_position"], at["velocity_after"],
                                        at["spin_after"]])  # fmt: skip
        rows = slice(k + 10 * i, k + 10 * i + 10)
        shots.append(Shot(
            name=tr.name, time=float(prob.t0[i]), state=state, standard_error=se_all[rows],
            split=sp, contact_time=float(fl["contact_time"][i]), **at,
            spin_components_before=identify(cov[rows, rows][6:9, 6:9], state[6:9], state[3:6],
                                            ball_.radius, tr.up),
            outgoing_check=check, fitted=fl["position"][i], residuals=resid, outliers=~kp,
            rms_before=float(np.sqrt(np.mean(d2[:sp][kp[:sp]]))) if kp[:sp].any() else math.nan,
            rms_after=float(np.sqrt(np.mean(d2[sp:][kp[sp:]]))) if kp[sp:].any() else math.nan,
            track=tr,
        ))  # fmt: skip
    values = dict(prob.fixed)
    values.update({n: float(x[j]) for j, n in enumerate(prob.free)})
    return BounceFit(
        law=law, names=names, values={n: values[n] for n in names}, free=tuple(prob.free),
        standard_error={n: float(se_all[j]) for j, n in enumerate(prob.free)},
        interval_low=low, interval_high=high, one_sided=one, covariance=cov[:k, :k],
        confidence=confidence, sigma=float(np.sqrt(s2)), sigma_given=sigma is not None,
        chi2=chi / s2, dof=dof, shots=tuple(shots),
        ball=ball_.replace(lift_slope=values["lift_slope"]) if "lift_slope" in values else ball_,
        air_density=air_density,
        gravity=gravity,
    )  # fmt: skip
