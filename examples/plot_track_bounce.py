"""
From a camera track to the bounce: measured table-tennis shots
==============================================================

Camera tracks of a table-tennis ball shot by a launcher across a table (about 180 Hz,
millimetre noise; the data and their licence ship in ``benchmarks/data/table_tennis_tracks``).
Eight shots are fitted jointly through the exact bounce law with Walton's tangential
restitution (:func:`spinimpact.track.fit_bounces`): each shot's position, velocity, spin and
drag coefficient before the bounce, and the table's ``mu``, ``kappa``, ``beta0`` and the
height of the ball's centre at contact, shared. Then a ninth shot, not among them, is
predicted from its incoming samples alone (:func:`spinimpact.track.predict_bounce`), as a
robot would, and compared with the samples that came after.
"""

from pathlib import Path

import numpy as np

from spinimpact.track import (
    find_bounce,
    fit_bounces,
    plot_prediction,
    plot_track,
    predict_bounce,
    read_tracks,
)

try:
    examples = Path(__file__).resolve().parent
except NameError:  # Sphinx-Gallery runs the examples from their own folder
    examples = Path.cwd()
data = examples.parent / "benchmarks" / "data" / "table_tennis_tracks" / "tracks.csv"
tracks = {t.name.split(" (")[0]: t for t in read_tracks(data)}

names = [f"robot_no_spin {k}" for k in (0, 1, 3, 4, 5, 7)] + ["no_spin 0", "no_spin 3"]
fit = fit_bounces([tracks[n] for n in names], "table-tennis", "table", law="walton",
                  intervals=False)  # fmt: skip
print(fit.summary())

# %%
# One shot's fit (no_spin 0): the samples, the fitted flights joined at the contact, and the
# residuals (outliers set aside as crosses).

fig = plot_track(fit, shot=6)

# %%
# A shot that was not fitted, predicted from the samples before its bounce. The band is the
# linearized 95 % band of the prediction (the incoming flight's uncertainty and the shared
# parameters' covariance carried through).

new = tracks["no_spin 4"]
split = find_bounce(new)["index"]
pred = predict_bounce(new.select(slice(0, split)), fit, horizon=0.25)
later = predict_bounce(new.select(slice(0, split)), fit, times=new.time[split:])
near = new.time[split:] - pred.contact_time <= 0.25
err = np.linalg.norm(later.position - new.position[split:], axis=1)[near]
print(f"predicted contact at {pred.contact_time:.4f} s; rms error over the next 0.25 s: "
      f"{1e3 * np.sqrt(np.mean(err**2)):.1f} mm over {near.sum()} samples")  # fmt: skip
fig2 = plot_prediction(pred, new)
