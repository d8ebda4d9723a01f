"""Camera tracks to physics: one import for fitting flights and bounces to measured positions.

>>> from spinimpact.track import read_tracks, fit_bounces, predict_bounce

* :func:`read_tracks` -- tracks from a CSV file (:mod:`spinimpact.io.tracks`);
* :func:`as_track`, :func:`fit_arc`, :func:`find_bounce` -- one flight fitted to a track
  (:mod:`spinimpact.model.track`, :mod:`spinimpact.model.track_arc`);
* :func:`fit_bounces`, :func:`predict_bounce` -- flights joined by the exact bounce law, and
  the bounce predicted from the incoming samples (:mod:`spinimpact.model.track_fit`,
  :mod:`spinimpact.model.track_predict`);
* :func:`plot_track`, :func:`plot_prediction` -- their figures (:mod:`spinimpact.viz.track`).
"""

from .io.tracks import read_tracks
from .model.track import Track, as_track, find_bounce
from .model.track_arc import ArcFit, fit_arc
from .model.track_fit import BounceFit, Shot, fit_bounces
from .model.track_predict import Prediction, predict_bounce
from .viz.track import plot_prediction, plot_track

__all__ = ["read_tracks", "Track", "ArcFit", "as_track", "find_bounce", "fit_arc", "BounceFit",
           "Prediction", "Shot", "fit_bounces", "predict_bounce", "plot_track",
           "plot_prediction"]  # fmt: skip
