r"""One flight fitted to a camera track: its position, velocity, spin and drag coefficient.

:func:`fit_arc` finds the state of a ball under gravity, drag and Magnus lift (the equations
of :mod:`spinimpact.core.aero`, flown by :func:`spinimpact.model.track.fly_to`) that best
explains the positions of one flight, with standard errors, and says in words how well each
spin component is determined.

Estimation. Weighted least squares on the three coordinates of every sample, in two passes:
a robust pass (SciPy's ``soft_l1`` loss, which down-weights samples far off the path), then
samples whose residual exceeds :data:`OUTLIER_SIGMAS` noise deviations are set aside and the
rest are fitted by plain least squares, from which the covariance ``s^2 (J^T J)^{-1}`` comes
(``s`` the given noise, or estimated from the scatter of the kept samples). The Jacobian is
taken by finite differences, every perturbed flight integrated in one batch.

Identifiability. The spin acts only through the Magnus force ``k (omega x v)``: its
component along the velocity has no effect but through the saturation of the lift
coefficient, and a short arc curves little. Each spin component is therefore reported along
three axes fixed by the fitted velocity, ``topspin`` (about ``up x heading``; negative is
backspin), ``sidespin`` (about the vertical) and ``gyrospin`` (about the heading), with one of
the words of :data:`IDENTIFIABILITY`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .flight import AIR_DENSITY, GRAVITY
from .presets import Ball
from .presets import ball as as_ball
from .track import MIN_SAMPLES, Air, Track, fly_to, frame_rotation, plain, spin_axes

__all__ = ["ArcFit", "fit_arc", "covariance", "identify", "arc_positions", "IDENTIFIABILITY",
           "SPIN_COMPONENTS", "OUTLIER_SIGMAS", "DETERMINED_SPIN_RATIO",
           "MAX_EVALUATIONS"]  # fmt: skip

#: A sample whose residual exceeds this many noise deviations (in any coordinate) is an
#: outlier: it is set aside after the robust pass (at 1-2 mm of noise, 5 deviations is 5-10 mm).
OUTLIER_SIGMAS = 5.0
#: The words for how well the data determine a spin component (its standard error ``se``,
#: in units of the spin ratio ``R se / |v|``): below 0.05 ``determined``; finite but larger
#: ``poorly determined``; infinite ``not determined locally by these data``.
IDENTIFIABILITY = ("determined", "poorly determined", "not determined locally by these data")
#: The spin components' names, in the order of :func:`spin_axes`.
SPIN_COMPONENTS = ("topspin", "sidespin", "gyrospin")
#: The spin ratio ``R se/|v|`` below which a spin component counts as determined.
DETERMINED_SPIN_RATIO = 0.05
#: The most evaluations of each pass of :func:`fit_arc` (a short arc, whose spin the data
#: hardly determine, would otherwise creep along its flat directions for long).
MAX_EVALUATIONS = 40


@dataclass(frozen=True, eq=False)
class ArcFit:
    """One flight fitted to a track (:func:`fit_arc`); vectors in the track's frame.

    Attributes
    ----------
    name : str
        The track's.
    time : float
        s, the time of the fitted state.
    position, velocity, spin : ndarray, shape (3,)
        m, m/s, rad/s at ``time``.
    covariance : ndarray, shape (k, k)
        Of ``(position, velocity, spin)`` and, when fitted, ``C_D`` (``k`` = 9 or 10).
    standard_error : ndarray, shape (k,)
    spin_components : dict
        ``topspin``, ``sidespin``, ``gyrospin``: ``(rad/s, standard error, word)`` along
        :func:`spin_axes` (the word one of :data:`IDENTIFIABILITY`); the standard error and
        the word are the samples' alone, without any ``spin_prior``.
    sigma : float
        m, the noise used (given, or estimated from the kept samples' scatter).
    sigma_given : bool
    rms : float
        m, the rms 3D distance of the kept samples from the fitted path.
    outliers : ndarray of bool
        Samples set aside.
    fitted : ndarray, shape (n, 3)
        The fitted path at every sample (m, track's frame).
    residuals : ndarray, shape (n, 3)
        Measured less fitted, m.
    chi2, dof : float, int
    drag_coefficient : float
        The ``C_D`` flown (fitted, or as given).
    """

    name: str
    time: float
    position: np.ndarray
    velocity: np.ndarray
    spin: np.ndarray
    covariance: np.ndarray
    standard_error: np.ndarray
    spin_components: dict
    sigma: float
    sigma_given: bool
    rms: float
    outliers: np.ndarray
    fitted: np.ndarray
    residuals: np.ndarray
    chi2: float
    dof: int
    drag_coefficient: float
    track: Track = field(repr=False)

    @property
    def state(self) -> np.ndarray:
        """``(position, velocity, spin, C_D)`` as one vector of 10."""
        return np.r_[self.position, self.velocity, self.spin, self.drag_coefficient]

    def summary(self) -> str:
        """The fitted state in words, one line a quantity."""
        se = self.standard_error
        lines = [f"track {self.name}: flight at t = {self.time:.4f} s, rms {1e3 * self.rms:.2f} mm"
                 f" over {len(self.track) - int(self.outliers.sum())} samples "
                 f"({int(self.outliers.sum())} outlier(s) set aside)"]  # fmt: skip
        for k, what, unit in ((0, "position", "m"), (3, "velocity", "m/s"), (6, "spin", "rad/s")):
            vals = ", ".join(f"{x:.4g} +- {e:.2g}" for x, e in zip(
                self.state[k:k + 3], se[k:k + 3], strict=True))  # fmt: skip
            lines.append(f"  {what} ({vals}) {unit}")
        if se.size == 10:
            lines.append(f"  drag coefficient {self.drag_coefficient:.3f} +- {se[9]:.2g}")
        for name, (value, err, word) in self.spin_components.items():
            lines.append(f"  {name} {value * 30 / np.pi:.0f} +- {err * 30 / np.pi:.0f} rpm: {word}")
        return "\n".join(lines)

    def to_dict(self) -> dict[str, Any]:
        """Every field as plain numbers and lists (the track left out)."""
        return plain(self, {"spin_components": lambda c: {
            k: {"value": v, "standard_error": e, "identifiability": w}
            for k, (v, e, w) in c.items()}})  # fmt: skip


def covariance(jac: np.ndarray, s2: float) -> np.ndarray:
    """``s2 (J^T J)^-1``, with an infinite variance for a parameter in a direction the
    residuals do not depend on (a null direction of the column-scaled ``J``)."""
    norms = np.linalg.norm(jac, axis=0)
    known = norms > 1e-12 * max(float(norms.max(initial=0.0)), 1e-300)
    scaled = jac[:, known] / norms[known]
    _, sv, vt = np.linalg.svd(scaled, full_matrices=False)
    null = vt[sv < 1e-9 * sv[0]] if sv.size else vt[:0]
    if null.size:
        idx = np.flatnonzero(known)
        known[idx[np.any(np.abs(null) > 1e-6, axis=0)]] = False
    k = jac.shape[1]
    cov = np.full((k, k), np.nan)
    np.fill_diagonal(cov, np.inf)
    if known.any():
        sub = jac[:, known]
        cov[np.ix_(known, known)] = np.linalg.inv(sub.T @ sub) * s2
    return cov


def identify(spin_cov: np.ndarray, spin: np.ndarray, velocity: np.ndarray, radius: float,
             up: str) -> dict[str, tuple[float, float, str]]:  # fmt: skip
    """Each spin component along :func:`spin_axes`, its standard error and its word."""
    axes = spin_axes(velocity, up)
    speed = float(np.linalg.norm(velocity))
    out = {}
    for name, a in zip(SPIN_COMPONENTS, axes, strict=True):
        used = np.abs(a) > 1e-12
        block = spin_cov[np.ix_(used, used)]
        err = float(np.sqrt(a[used] @ block @ a[used])) if np.all(np.isfinite(block)) else np.inf
        if not np.isfinite(err):
            word = IDENTIFIABILITY[2]
        elif radius * err / max(speed, 1e-9) < DETERMINED_SPIN_RATIO:
            word = IDENTIFIABILITY[0]
        else:
            word = IDENTIFIABILITY[1]
        out[name] = (float(a @ spin), float(err), word)
    return out


def arc_positions(states: np.ndarray, t0: float, times: np.ndarray, air: Air,
                  rot: np.ndarray) -> np.ndarray:  # fmt: skip
    """Positions (track's frame, ``(b, m, 3)``) at ``times`` of ``b`` flights whose states
    ``(b, 10)``, position, velocity, spin (track's frame) and ``C_D``, hold at ``t0``."""
    s = states[:, :9].reshape(-1, 3, 3) @ rot.T
    p, _ = fly_to(np.full(len(s), t0), s[:, 0], s[:, 1], s[:, 2], times, air.per_ball(states[:, 9]))
    return p @ rot


def _prior(spin_prior: Any) -> tuple[np.ndarray, np.ndarray] | None:
    """The prior's mean and ``1 / sd`` along (topspin, sidespin, gyrospin), ``1 / sd`` 0
    where it has none; or ``None`` for no prior."""
    if spin_prior is None:
        return None
    if not isinstance(spin_prior, dict):
        raise TypeError("spin_prior must be a dict such as {'gyrospin': (mean, sd)} (rad/s), "
                        f"got {spin_prior!r}")  # fmt: skip
    mean, inverse_sd = np.zeros(3), np.zeros(3)
    for name, value in spin_prior.items():
        if name not in SPIN_COMPONENTS:
            raise ValueError(f"spin_prior: unknown component {name!r}; the components are "
                             f"{', '.join(SPIN_COMPONENTS)}")  # fmt: skip
        try:
            m, sd = (float(v) for v in value)
        except (TypeError, ValueError):
            raise TypeError(f"spin_prior[{name!r}] must be (mean, sd) in rad/s, got "
                            f"{value!r}") from None  # fmt: skip
        if not (np.isfinite(m) and sd > 0 and not np.isnan(sd)):
            raise ValueError(f"spin_prior[{name!r}] must be a finite mean and an sd > 0 "
                             f"(rad/s), got {value!r}")  # fmt: skip
        j = SPIN_COMPONENTS.index(name)
        mean[j], inverse_sd[j] = m, 1.0 / sd
    return mean, inverse_sd


def _start(track: Track, t0: float, gravity: float) -> np.ndarray:
    """A starting state from a quadratic fit of each coordinate near ``t0``."""
    s = track.time - t0
    coef = np.polyfit(s, track.position, 2)
    return np.concatenate([coef[2], coef[1], np.zeros(3)])


def _jacobian(fun: Any, x: np.ndarray, step: np.ndarray) -> np.ndarray:
    """Forward differences of ``fun`` (which takes a batch ``(b, k)``) in one batch."""
    batch = np.vstack([x, x + np.diag(step)])
    f = fun(batch)
    return ((f[1:] - f[0]) / step[:, None]).T


def fit_arc(track: Track, ball: Ball | str = "table-tennis", *, at: float | None = None,
            sigma: float | None = None, drag_coefficient: float | str = "fit",
            air_density: float = AIR_DENSITY, gravity: float = GRAVITY,
            start: Any = None, spin_prior: Any = None) -> ArcFit:  # fmt: skip
    """Fit one flight (position, velocity and spin at a time) to a track's positions.

    Parameters
    ----------
    track : Track
        The samples of one flight (no contact within them).
    ball : Ball or str
        Its mass, radius, inertia and lift law (a preset name, e.g. ``table-tennis``).
    at : float, optional
        s, the time of the fitted state (default: the first sample). It may lie outside the
        samples: the state at a contact is fitted from the samples after it.
    sigma : float, optional
        m, the noise of each coordinate; by default estimated from the scatter.
    drag_coefficient : float or "fit"
        ``C_D``: fitted with the state (the default; a long arc determines it, a short one
        only loosely), or held at the value given.
    air_density, gravity : float
        kg/m^3, m/s^2.
    start : array_like, shape (9,) or (10,), optional
        A starting state (track's frame), with ``C_D`` last; by default from quadratic fits
        of the positions and the ball's ``C_D``.
    spin_prior : dict, optional
        A Gaussian prior on spin components: ``{"gyrospin": (mean, sd)}`` (rad/s), any of
        ``topspin``, ``sidespin`` and ``gyrospin`` (along :func:`spin_axes` of the fitted
        velocity). Each adds one residual, ``s (component - mean) / sd`` (``s`` the noise),
        so the fit is the posterior mode and the covariance the posterior's (linearized). A
        component the samples hardly determine then stays near what other shots showed
        (:meth:`~spinimpact.model.track_fit.BounceFit.spin_prior`) instead of wherever the
        noise takes it; one they determine well is barely moved. Default: none.

    Returns
    -------
    ArcFit

    Raises
    ------
    TypeError
        ``track`` not a :class:`Track`.
    ValueError
        Too few samples (fewer than :data:`MIN_SAMPLES`, or fewer left than the numbers fitted
        after the outliers are set aside), a ``sigma`` that is not positive.

    Examples
    --------
    A flight without air, 2 mm of noise: the fitted velocity is within its errors.

    >>> import numpy as np
    >>> from spinimpact.model.track import as_track
    >>> t = np.linspace(0.0, 0.3, 40)
    >>> rng = np.random.default_rng(0)
    >>> xyz = np.stack([5 * t, 0 * t, 1 + 2 * t - 9.80665 * t**2 / 2], 1)
    >>> tr = as_track(t, xyz + rng.normal(0, 0.002, xyz.shape))
    >>> f = fit_arc(tr, air_density=0.0, drag_coefficient=0.5, sigma=0.002)
    >>> bool(np.all(np.abs(f.velocity - [5, 0, 2]) < 3 * f.standard_error[3:6]))
    True
    """
    if not isinstance(track, Track):
        raise TypeError(f"track must be a Track (spinimpact.model.track.as_track), got {track!r}")
    from scipy.optimize import least_squares

    ball_ = as_ball(ball)
    if len(track) < MIN_SAMPLES:
        raise ValueError(f"track {track.name}: {len(track)} sample(s); a flight needs at least "
                         f"{MIN_SAMPLES}")  # fmt: skip
    if sigma is not None and not (np.isfinite(sigma) and sigma > 0):
        raise ValueError(f"sigma must be > 0 (m), got {sigma!r}")
    free_drag = isinstance(drag_coefficient, str)
    if free_drag and drag_coefficient != "fit":
        raise ValueError(f"drag_coefficient must be a number or 'fit', got {drag_coefficient!r}")
    cd = ball_.drag_coefficient if free_drag else float(drag_coefficient)
    air = Air(ball_, air_density, gravity)
    rot = frame_rotation(track.up)
    t0 = float(track.time[0] if at is None else at)
    x0 = np.r_[_start(track, t0, gravity), cd] if start is None else np.asarray(start, float)
    if x0.size == 9:
        x0 = np.r_[x0, cd]
    if not free_drag:
        x0[9] = cd
    k = 10 if free_drag else 9
    prior = _prior(spin_prior)
    step = np.r_[np.full(3, 1e-6), np.full(3, 1e-5), np.full(3, 1e-2), 1e-4][:k]
    scale = np.r_[np.full(3, 1e-3), np.full(3, 1e-2), np.full(3, 30.0), 0.05][:k]

    def batch(keep: np.ndarray):
        times, meas = track.time[keep], track.position[keep]

        def fun(y: np.ndarray) -> np.ndarray:
            states = np.column_stack([y[:, :9], y[:, 9] if free_drag else np.full(len(y), cd)])
            r = (arc_positions(states, t0, times, air, rot) - meas).reshape(len(y), -1)
            if prior is None:
                return r
            return np.hstack([r, prior_rows(y)])

        return fun

    prior_noise = [sigma or 2e-3]  # the robust pass's scale; then the noise estimated

    def prior_rows(y: np.ndarray) -> np.ndarray:
        """``s (component - mean) / sd`` for each state of the batch ``y`` (b, 3)."""
        axes = np.stack([spin_axes(v, track.up) for v in y[:, 3:6]])
        parts = np.einsum("bij,bj->bi", axes, y[:, 6:9]) - prior[0]
        return prior_noise[0] * parts * prior[1]

    low = np.r_[np.full(9, -np.inf), 0.0][:k]

    def solve(keep: np.ndarray, x: np.ndarray, loss: str, f_scale: float) -> Any:
        fun = batch(keep)
        return least_squares(lambda y: fun(y[None])[0], x, jac=lambda y: _jacobian(fun, y, step),
                             loss=loss, f_scale=f_scale, x_scale=scale, method="trf",
                             bounds=(low, np.inf), max_nfev=MAX_EVALUATIONS)  # fmt: skip

    everything = np.ones(len(track), dtype=bool)
    robust = solve(everything, x0[:k], "soft_l1", 3.0 * (sigma or 2e-3))
    res = batch(everything)(robust.x[None])[0][: 3 * len(track)].reshape(-1, 3)
    noise = sigma or max(1.4826 * float(np.median(np.abs(res))), 1e-5)
    prior_noise[0] = noise
    outliers = np.any(np.abs(res) > OUTLIER_SIGMAS * noise, axis=1)
    keep = ~outliers
    if 3 * keep.sum() <= k:
        raise ValueError(f"track {track.name}: {int(keep.sum())} sample(s) left after "
                         f"setting aside {int(outliers.sum())} outlier(s); too few for a "
                         "flight")  # fmt: skip
    x = solve(keep, robust.x, "linear", 1.0).x
    resid = -batch(everything)(x[None])[0][: 3 * len(track)].reshape(-1, 3)
    chi = float(np.sum(resid[keep] ** 2))
    dof = int(3 * keep.sum() - k)
    s2 = sigma**2 if sigma is not None else chi / max(dof, 1)
    prior_noise[0] = float(np.sqrt(s2))  # the prior's rows in units of the noise used
    jac = _jacobian(batch(keep), x, step)
    cov = covariance(jac, s2)  # with a prior, the posterior's
    data_cov = cov if prior is None else covariance(jac[: 3 * int(keep.sum())], s2)
    return ArcFit(
        name=track.name, time=t0, position=x[:3], velocity=x[3:6], spin=x[6:9],
        covariance=cov, standard_error=np.sqrt(np.diag(cov)),
        spin_components=identify(data_cov[6:9, 6:9], x[6:9], x[3:6], ball_.radius, track.up),
        sigma=float(np.sqrt(s2)), sigma_given=sigma is not None,
        rms=float(np.sqrt(np.mean(np.sum(resid[keep] ** 2, axis=1)))), outliers=outliers,
        fitted=track.position - resid, residuals=resid, chi2=chi / s2, dof=dof,
        drag_coefficient=float(x[9]) if free_drag else cd, track=track,
    )  # fmt: skip
