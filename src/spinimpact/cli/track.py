"""``spinimpact track tracks.csv``: fit flights and bounces to camera tracks, or predict bounces.

Tracks with a bounce are fitted jointly through the exact bounce law
(:func:`~spinimpact.model.track_fit.fit_bounces`: the surface's and the ball's shared
parameters with their intervals, each shot's state); a track without one is fitted as one
flight (:func:`~spinimpact.model.track_arc.fit_arc`). ``--predict`` then predicts each track's
bounce and outgoing flight from its incoming samples alone
(:func:`~spinimpact.model.track_predict.predict_bounce`). Files are written atomically.
"""

from __future__ import annotations

import json
from typing import Any

import click
import numpy as np

from ..model.presets import BALLS, GROUNDS
from ..model.track_bounce import LAWS
from ._common import image_format, jsonable
from ._vocabulary import help as _help
from .fit import _fixed

__all__ = ["track_command"]

#: Seconds after the contact that ``--predict`` predicts.
HORIZON = 0.25


def _rpm(w: np.ndarray) -> str:
    return "(" + ", ".join(f"{x * 30 / np.pi:.0f}" for x in w) + ") rpm"


def _vec(v: np.ndarray, unit: str, digits: int = 3) -> str:
    return "(" + ", ".join(f"{x:.{digits}f}" for x in v) + f") {unit}"


@click.command("track")
@click.argument("tracks", type=click.Path(dir_okay=False))
@click.option("--ball", type=click.Choice(sorted(BALLS)), default="table-tennis",
              show_default=True, help=_help("ball"))  # fmt: skip
@click.option("--surface", type=click.Choice(sorted(GROUNDS)), default="table",
              show_default=True,
              help=_help("surface", "Starting mu and kappa of the fit."))  # fmt: skip
@click.option("--tangential", type=click.Choice(LAWS), default="walton", show_default=True,
              help=_help("tangential", "The bounce law fitted."))  # fmt: skip
@click.option("--fix", multiple=True, metavar="NAME=VALUE",
              help=_help("fix", "mu, kappa, contact_height (m), beta0 (walton), "
                         "poisson_ratio (mindlin-deresiewicz) or lift_slope; "
                         "repeatable."))  # fmt: skip
@click.option("--free-lift", is_flag=True, help=_help("free-lift"))
@click.option("--up", type=click.Choice(["z", "y"]), default="z", show_default=True,
              help=_help("up"))  # fmt: skip
@click.option("--sigma", type=float, default=None,
              help=_help("sigma", "Default: estimated from the scatter."))  # fmt: skip
@click.option("--confidence", type=click.FloatRange(0.5, 0.999), default=0.95, show_default=True,
              help=_help("confidence"))  # fmt: skip
@click.option("--predict", is_flag=True, help=_help("predict"))
@click.option("--json", "as_json", is_flag=True, help=_help("json", "Every field, in SI units."))
@click.option("--json-file", default=None, help=_help("json-file"))
@click.option("--plot", default=None, help=_help("plot", "The first track's fit or prediction."))
@click.option("--dpi", type=click.IntRange(20, 600), default=150, show_default=True,
              help=_help("dpi"))  # fmt: skip
def track_command(**o: Any) -> None:
    """Fit a ball's flights and bounces to camera tracks (positions over time), or predict
    each track's bounce from its incoming samples.

    \b
    The file: columns t (s), x, y, z (m) and optionally set and trajectory (one track per
    pair); z up by default (--up). Example:
      spinimpact track tracks.csv --ball table-tennis --surface table --predict --plot p.png
    """
    from ..io.tracks import read_tracks
    from ..model.track import find_bounce
    from ..model.track_arc import fit_arc
    from ..model.track_fit import fit_bounces
    from ..model.track_predict import predict_bounce

    for path in (o["plot"], o["json_file"]):
        if path is not None and path == o["tracks"]:
            raise click.BadParameter("an output may not overwrite the tracks file")
    if o["plot"] is not None:
        image_format(o["plot"], "--plot")
    if o["sigma"] is not None and not o["sigma"] > 0:
        raise click.BadParameter(f"must be > 0 (m), got {o['sigma']!r}", param_hint="--sigma")
    fixed = _fixed(o["fix"])
    tracks = read_tracks(o["tracks"], up=o["up"])
    splits: dict[int, int] = {}
    for i, tr in enumerate(tracks):
        try:
            b = find_bounce(tr)
        except ValueError:
            continue
        if len(tr) - b["index"] >= 3:
            splits[i] = b["index"]
    echo = (lambda text: None) if o["as_json"] else click.echo

    def stage(text: str) -> None:  # what runs now, on stderr (stdout may carry JSON)
        click.echo(f"spinimpact track: {text}", err=True)

    out: dict[str, Any] = {"bounce_fit": None, "flights": [], "predictions": []}
    fit = None
    if splits:
        stage(f"fitting the {len(splits)} track(s) that cross the surface jointly, with "
              "profile-likelihood intervals (about 6 s a track on 2 cores: the 65 shipped "
              "tracks took 6 min 16 s with --predict)")  # fmt: skip
        fit = fit_bounces([tracks[i] for i in splits], o["ball"], o["surface"],
                          law=o["tangential"], fixed=fixed, sigma=o["sigma"],
                          free_lift=o["free_lift"],
                          confidence=o["confidence"])  # fmt: skip
        out["bounce_fit"] = fit.to_dict()
        echo(fit.summary())
    elif o["predict"]:
        raise ValueError(f"{o['tracks']}: no track crosses the surface with at least 3 samples "
                         "after it: --predict has no surface parameters to use")  # fmt: skip
    arcs = []
    if len(tracks) > len(splits):
        stage(f"fitting the {len(tracks) - len(splits)} track(s) without a bounce as flights")
    for i, tr in enumerate(tracks):
        if i not in splits:
            arc = fit_arc(tr, o["ball"], sigma=o["sigma"])
            arcs.append(arc)
            out["flights"].append(arc.to_dict())
            echo(arc.summary())
    predictions = []
    if o["predict"]:
        stage(f"predicting the bounces of {len(tracks)} track(s) from their incoming samples")
        held = "".join(f"; the {name} of each incoming fit held near {m:.0f} +- {sd:.0f} "
                       "rad/s, as the fitted tracks showed"
                       for name, (m, sd) in fit.spin_prior().items())  # fmt: skip
        echo(f"predicted from the incoming samples alone ({o['tangential']} law, parameters "
             f"fitted to the tracks with a bounce above{held}):")  # fmt: skip
        for i, tr in enumerate(tracks):
            sp = splits.get(i)
            if sp is None:
                try:
                    sp = find_bounce(tr)["index"]
                except ValueError:
                    sp = len(tr)
            incoming = tr.select(slice(0, sp))
            later = tr.time[sp:]
            p = predict_bounce(incoming, fit, horizon=HORIZON)
            predictions.append((p, tr))
            d = p.to_dict()
            line = (f"  {p.name}: contact at {p.contact_time:.4f} s, "
                    f"{_vec(p.contact_position, 'm')}; after it "
                    f"{_vec(p.velocity_after, 'm/s', 2)}, spin {_rpm(p.spin_after)}")  # fmt: skip
            if later.size:
                q = predict_bounce(incoming, fit, times=later)
                err = np.linalg.norm(q.position - tr.position[sp:], axis=1)
                near = later - p.contact_time <= HORIZON
                if near.any():
                    rms = 1e3 * float(np.sqrt(np.mean(err[near] ** 2)))
                    line += f"; rms {rms:.1f} mm over {int(near.sum())} later samples (in-sample)"
                    d["later_rms"] = rms / 1e3
            echo(line)
            out["predictions"].append(d)
    if o["as_json"]:
        click.echo(json.dumps(jsonable(out), indent=2))
    _write(out, o, fit, arcs, predictions)


def _write(out: dict, o: dict, fit: Any, arcs: list, predictions: list) -> None:
    from ..io import atomic_path

    if o["json_file"] is not None:
        with atomic_path(o["json_file"]) as tmp:
            tmp.write_text(json.dumps(jsonable(out), indent=2))
    if o["plot"] is not None:
        from ..viz.track import plot_prediction, plot_track

        if predictions:
            fig = plot_prediction(*predictions[0])
        else:
            fig = plot_track(fit if fit is not None else arcs[0])
        with atomic_path(o["plot"]) as tmp:
            fig.savefig(tmp, format=image_format(o["plot"], "--plot"), dpi=o["dpi"])
    if not o["as_json"]:
        for path in (o["plot"], o["json_file"]):
            if path is not None:
                click.echo(f"wrote {path}")
