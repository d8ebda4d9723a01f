"""Pictures of fitted tracks: the measured samples, the fitted flights, the bounce and the
residuals; and a predicted bounce with its band.

Nothing here fits: every number drawn is a field of an
:class:`~spinimpact.model.track_arc.ArcFit`, a :class:`~spinimpact.model.track_fit.BounceFit`
or a :class:`~spinimpact.model.track_predict.Prediction`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..model.track import Track, frame_rotation
from ..model.track_arc import ArcFit
from ..model.track_fit import BounceFit
from ..model.track_predict import Prediction

if TYPE_CHECKING:  # pragma: no cover
    from matplotlib.figure import Figure

__all__ = ["plot_track", "plot_prediction"]


def _figure(**kwargs: Any) -> Figure:
    from matplotlib.figure import Figure  # no pyplot: no global state, no GUI backend

    return Figure(layout="constrained", **kwargs)


def _axes(track: Track) -> tuple[np.ndarray, np.ndarray, np.ndarray, tuple[str, str]]:
    """Along, lateral and vertical unit rows of the track's frame, and their names."""
    rot = frame_rotation(track.up)
    names = ("x", "y") if track.up == "z" else ("x", "z")
    lateral = np.array([0.0, 1.0, 0.0]) if track.up == "z" else np.array([0.0, 0.0, 1.0])
    return np.array([1.0, 0.0, 0.0]), lateral, rot[1], names


def plot_track(fit: BounceFit | ArcFit, shot: int = 0) -> Figure:
    """One track: side and top views of the samples and the fitted flights, and the residuals.

    Parameters
    ----------
    fit : BounceFit or ArcFit
        A fit across a bounce (its shot ``shot`` is drawn) or of one flight.
    shot : int
        Which shot of a :class:`BounceFit`.

    Returns
    -------
    matplotlib.figure.Figure
        Top left: height against the distance along the track, samples as dots (outliers set
        aside as crosses), the fitted path as a line, the contact as a red diamond. Bottom left:
        the lateral position (top view). Right: the residuals of each coordinate (mm) over
        time, the contact's time dashed.
    """
    if isinstance(fit, BounceFit):
        if not 0 <= shot < len(fit.shots):
            raise ValueError(f"shot must be in [0, {len(fit.shots)}), got {shot!r}")
        s = fit.shots[shot]
        track, fitted, resid, out = s.track, s.fitted, s.residuals, s.outliers
        contact, tc = s.contact_position, s.contact_time
        title = (f"{s.name}: {fit.law} bounce, rms {1e3 * s.rms_before:.1f} mm before, "
                 f"{1e3 * s.rms_after:.1f} mm after")  # fmt: skip
    elif isinstance(fit, ArcFit):
        track, fitted, resid, out = fit.track, fit.fitted, fit.residuals, fit.outliers
        contact, tc = None, None
        title = f"{fit.name}: one flight, rms {1e3 * fit.rms:.1f} mm"
    else:
        raise TypeError(f"fit must be a BounceFit or an ArcFit, got {type(fit).__name__}")
    along, lateral, up, (xa, ya) = _axes(track)
    za = track.up
    fig = _figure(figsize=(10.0, 5.6))
    grid = fig.add_gridspec(2, 2, width_ratios=(1.3, 1.0))
    side, top, res = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[1, 0]), fig.add_subplot(
        grid[:, 1])  # fmt: skip
    p = track.position
    for ax, axis, label in ((side, up, f"${za}$ (m)"), (top, lateral, f"${ya}$ (m)")):
        ax.plot(p[~out] @ along, p[~out] @ axis, ".", ms=3, color="0.35", label="measured")
        if out.any():
            ax.plot(p[out] @ along, p[out] @ axis, "x", ms=5, color="tab:orange",
                    label="outliers set aside")  # fmt: skip
        ax.plot(fitted @ along, fitted @ axis, "-", lw=1.2, color="tab:blue", label="fitted")
        if contact is not None:
            ax.plot(contact @ along, contact @ axis, "D", ms=6, color="tab:red", label="contact")
        ax.set_ylabel(label)
    top.set_xlabel(f"${xa}$ (m)")
    side.legend(loc="best", fontsize=8)
    side.set_title(title, fontsize=9)
    for k, name in enumerate(("x", "y", "z")):
        res.plot(track.time, 1e3 * resid[:, k], ".", ms=3, label=f"${name}$")
    if tc is not None:
        res.axvline(tc, ls="--", color="tab:red", lw=1.0, label="contact")
    lim = max(5.0, 1e3 * float(np.percentile(np.abs(resid[~out]), 99.5)) * 1.5) if (
        ~out).any() else 10.0  # fmt: skip
    res.set_ylim(-lim, lim)
    res.set_xlabel("$t$ (s)")
    res.set_ylabel("measured $-$ fitted (mm)")
    res.set_title("residuals (outliers beyond the frame)", fontsize=9)
    res.legend(loc="lower left", fontsize=8, ncol=4)
    return fig


def plot_prediction(pred: Prediction, track: Track | None = None) -> Figure:
    """A predicted bounce: the incoming samples used, the prediction with its band, and, if
    ``track`` is given, the samples that came after (not used).

    Returns
    -------
    matplotlib.figure.Figure
        Left: height against the distance along the track. Right: the predicted height with
        its band over time. The band is ``low``-``high`` of the prediction (linearized, at its
        ``confidence``).
    """
    if not isinstance(pred, Prediction):
        raise TypeError(f"pred must be a Prediction, got {type(pred).__name__}")
    inc = pred.incoming.track
    along, _, up, (xa, _) = _axes(inc)
    za = inc.up
    fig = _figure(figsize=(10.0, 4.0))
    side, band = fig.subplots(1, 2)
    side.plot(inc.position @ along, inc.position @ up, ".", ms=3, color="0.35",
              label="incoming samples (used)")  # fmt: skip
    later = np.zeros(0, dtype=bool) if track is None else track.time > inc.time[-1]
    if later.any():
        side.plot(track.position[later] @ along, track.position[later] @ up, "o", ms=3,
                  mfc="none", color="tab:green", label="later samples (not used)")  # fmt: skip
        band.plot(track.time[later], track.position[later] @ up, "o", ms=3, mfc="none",
                  color="tab:green", label="later samples")  # fmt: skip
    side.plot(pred.position @ along, pred.position @ up, "-", color="tab:blue", label="predicted")
    side.plot(pred.contact_position @ along, pred.contact_position @ up, "D", color="tab:red",
              label="predicted contact")  # fmt: skip
    side.set_xlabel(f"${xa}$ (m)")
    side.set_ylabel(f"${za}$ (m)")
    side.legend(loc="best", fontsize=8)
    side.set_title(pred.name, fontsize=9)
    k = int(np.argmax(np.abs(up)))
    band.fill_between(pred.time, pred.low[:, k], pred.high[:, k], color="tab:blue", alpha=0.25,
                      label=f"{100 * pred.confidence:g} % band")  # fmt: skip
    band.plot(pred.time, pred.position @ up, "-", color="tab:blue", label="predicted")
    band.axvline(pred.contact_time, ls="--", color="tab:red", lw=1.0, label="predicted contact")
    band.set_xlabel("$t$ (s)")
    band.set_ylabel(f"${za}$ (m)")
    band.legend(loc="best", fontsize=8)
    return fig
