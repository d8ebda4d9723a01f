"""Predicting a table-tennis ball's bounce from its incoming track: the exact law against two
fitted baselines, cross-validated by shot on the measured tracks.

Run with ``python -m benchmarks.track`` (about 15-25 minutes on two cores; ``--folds``,
``--laws`` to change). Data: ``benchmarks/data/table_tennis_tracks/`` (its README: source,
licence, frame). Every shot with a bounce found by the data's own rule (``bounce_status``
``bounce`` or ``bounce_few_post``) is scored; shots are split into ``k`` folds by shot,
stratified by launch setting (sorted by setting and trajectory, dealt round-robin).

For each fold, on the training shots only:

* **exact law** (:func:`spinimpact.model.track_fit.fit_bounces`): the shared ``mu``,
  ``kappa``, contact height and, for Walton's law, ``beta0``, fitted jointly with every
  training shot's incoming and outgoing flights; once with the rigid law, once with Walton's,
  and ``selected``: whichever of the two has the lower BIC on the training shots;
* **rebound matrix** (Nakashima type): ``(v', w') = M (v, w)``, a 6x6 matrix fitted by least
  squares to the training shots' velocity and spin at the contact, before (from the incoming
  flight's fit) and after (the outgoing flight fitted alone, from the contact, for shots with
  at least 8 samples after it);
* **constant restitution**: ``v_n' = -e v_n``, ``v_t' = c v_t`` (the spin kept), ``e`` and ``c``
  by least squares on the same pairs.

Each test shot is then predicted from its incoming samples alone (those up to the data's
contact time): its incoming flight fitted (:func:`spinimpact.model.track_arc.fit_arc`, position,
velocity, spin and drag coefficient, with the gyrospin prior of the training shots' fit:
:meth:`~spinimpact.model.track_fit.BounceFit.spin_prior`; ``--no-spin-prior`` leaves it out),
flown to the surface and bounced by each model, and flown on (the same flight model and drag
coefficient for every model; the baselines' incoming fits, for training and test shots alike,
take the prior of the exact law selected in that fold). The baselines take the
contact height as the median of the training shots' ``bounce_z``. Scored: the 3D distance
between predicted and measured positions at every measured sample within 0.10 s and within
0.25 s after the data's contact time; the rms over all of them (pooled) and per launch setting.
Every sample counts, outliers included, for every model alike.
"""

from __future__ import annotations

import argparse
import csv
import math
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

from spinimpact.model.presets import ball as as_ball
from spinimpact.model.track import Air, Bounce, as_track, frame_rotation
from spinimpact.model.track_arc import fit_arc
from spinimpact.model.track_bounce import flights
from spinimpact.model.track_fit import fit_bounces
from spinimpact.model.track_predict import predict_bounce

DATA = Path(__file__).resolve().parent / "data" / "table_tennis_tracks"
HORIZONS = (0.10, 0.25)
BASELINES = ("rebound matrix", "constant restitution")
MIN_POST_FOR_PAIRS = 8


def load(data: Path = DATA) -> list[dict]:
    """The scored shots: track, split and the data's contact, in file order."""
    rows = defaultdict(list)
    with open(data / "tracks.csv", newline="") as f:
        for line, r in enumerate(csv.DictReader(f), start=2):
            rows[(r["set"], int(r["trajectory"]))].append(
                (float(r["t"]), float(r["x"]), float(r["y"]), float(r["z"]), line)
            )
    shots = []
    with open(data / "trajectories.csv", newline="") as f:
        for r in csv.DictReader(f):
            if r["bounce_status"] not in ("bounce", "bounce_few_post"):
                continue
            key = (r["set"], int(r["trajectory"]))
            a = np.array(rows[key])
            track = as_track(
                a[:, 0], a[:, 1:4], rows=a[:, 4].astype(int), name=f"{key[0]} {key[1]}"
            )
            shots.append(
                {
                    "set": key[0],
                    "track": track,
                    "split": int(r["n_pre"]),
                    "bounce_t": float(r["bounce_t"]),
                    "bounce": Bounce(
                        index=int(r["n_pre"]),
                        time=float(r["bounce_t"]),
                        height=float(r["bounce_z"]),
                    ),
                }
            )
    shots.sort(key=lambda s: (s["set"], s["track"].name))
    return shots


def folds(shots: list[dict], k: int) -> list[int]:
    """Fold of each shot: round-robin within each launch setting."""
    seen: dict[str, int] = defaultdict(int)
    out = []
    for s in shots:
        out.append(seen[s["set"]] % k)
        seen[s["set"]] += 1
    return out


def _bic(fit) -> float:
    n = fit.dof + len(fit.free) + 10 * len(fit.shots)
    rss = fit.chi2 * fit.sigma**2
    return n * math.log(rss / n) + (n - fit.dof) * math.log(n)


def _scored(shot: dict) -> np.ndarray:
    tr, sp = shot["track"], shot["split"]
    return np.flatnonzero(
        (np.arange(len(tr)) >= sp) & (tr.time - shot["bounce_t"] <= max(HORIZONS))
    )


def _incoming(shot: dict, prior: dict | None = None):
    return fit_arc(shot["track"].select(slice(0, shot["split"])), spin_prior=prior)


def _fly(arc, height: float, air: Air, after: np.ndarray, up: str, rebound=None) -> dict:
    """The incoming flight ``arc`` to the surface at ``height``, bounced by ``rebound`` (or the
    rigid law, whose outcome is then unused), and on to the times ``after``."""
    shared = {"mu": np.zeros(1), "kappa": np.zeros(1), "contact_height": np.full(1, height)}
    return flights(np.array([arc.time]), arc.state[None], shared, air, "rigid",
                   np.zeros((1, 0)), after[None], up, rebound=rebound)  # fmt: skip


def _contact_pairs(shots: list[dict], height: float, air: Air, prior: dict | None = None):
    """Velocity and spin before (incoming fit) and after (outgoing fit alone) the contact
    of each training shot with enough samples after it (tracks' frame)."""
    before, after = [], []
    for s in shots:
        tr, sp = s["track"], s["split"]
        if len(tr) - sp < MIN_POST_FOR_PAIRS:
            continue
        arc = _incoming(s, prior)
        fl = _fly(arc, height, air, np.zeros(0), tr.up)
        tc = float(fl["contact_time"][0])
        out = fit_arc(
            tr.select(slice(sp, None)),
            at=tc,
            drag_coefficient=arc.drag_coefficient,
            start=np.r_[fl["contact_position"][0], fl["velocity_before"][0], fl["spin_before"][0]],
        )
        before.append(np.r_[fl["velocity_before"][0], fl["spin_before"][0]])
        after.append(np.r_[out.velocity, out.spin])
    return np.array(before), np.array(after)


def _baseline_maps(before: np.ndarray, after: np.ndarray, up: str) -> dict:
    """The two baselines' rebound maps (tracks' frame), fitted by least squares."""
    m = np.linalg.lstsq(before, after, rcond=None)[0]  # (6, 6): after = before @ m
    vertical = frame_rotation(up)[1]
    vn, vn1 = before[:, :3] @ vertical, after[:, :3] @ vertical
    e = float(-(vn @ vn1) / (vn @ vn))
    t0 = before[:, :3] - vn[:, None] * vertical
    t1 = after[:, :3] - vn1[:, None] * vertical
    c = float(np.sum(t0 * t1) / np.sum(t0 * t0))

    def matrix(v, w):
        y = np.hstack([v, w]) @ m
        return y[:, :3], y[:, 3:]

    def restitution(v, w):
        n = v @ vertical
        return v - n[:, None] * vertical * (1 + e) + (c - 1) * (v - n[:, None] * vertical), w

    return {
        "rebound matrix": matrix,
        "constant restitution": restitution,
        "_numbers": {"e": e, "c": c},
    }


def _baseline_predict(shot: dict, rebound, height: float, air: Air,
                      prior: dict | None = None) -> np.ndarray:  # fmt: skip
    tr = shot["track"]
    fl = _fly(_incoming(shot, prior), height, air, tr.time[_scored(shot)], tr.up, rebound)
    return fl["after"][0]


def run(k: int = 5, laws: tuple[str, ...] = ("rigid", "walton"), spin_prior: bool = True) -> dict:
    shots = load()
    fold = folds(shots, k)
    air = Air(as_ball("table-tennis"))
    names = [
        *(f"exact, {law}" for law in laws),
        *(["exact, selected"] if len(laws) > 1 else []),
        *BASELINES,
    ]
    errors = {n: [np.zeros(0)] * len(shots) for n in names}
    notes = []
    for f in range(k):
        t_start = time.time()
        train = [
            s
            for s, g in zip(shots, fold, strict=True)
            if g != f and len(s["track"]) - s["split"] >= 3
        ]
        test = [i for i, g in enumerate(fold) if g == f]
        fits = {
            law: fit_bounces(
                [s["track"] for s in train],
                law=law.split("+")[0],
                free_lift=law.endswith("+lift"),
                bounces=[s["bounce"] for s in train],
                intervals=False,
            )
            for law in laws
        }
        best = min(laws, key=lambda law: _bic(fits[law]))
        prior = fits[best].spin_prior() if spin_prior else None
        height = float(np.median([s["bounce"]["height"] for s in train]))
        before, after = _contact_pairs(train, height, air, prior)
        maps = _baseline_maps(before, after, train[0]["track"].up)
        for i in test:
            s = shots[i]
            idx = _scored(s)
            if idx.size == 0:
                continue
            measured = s["track"].position[idx]
            incoming = s["track"].select(slice(0, s["split"]))
            for law in laws:
                p = predict_bounce(incoming, fits[law], times=s["track"].time[idx],
                                   spin_prior="fit" if spin_prior else None)  # fmt: skip
                errors[f"exact, {law}"][i] = np.linalg.norm(p.position - measured, axis=1)
            if len(laws) > 1:
                errors["exact, selected"][i] = errors[f"exact, {best}"][i]
            for b in BASELINES:
                pos = _baseline_predict(s, maps[b], height, air, prior)
                errors[b][i] = np.linalg.norm(pos - measured, axis=1)
        values = ", ".join(
            f"{law}: " + ", ".join(f"{n} {v:.4g}" for n, v in fits[law].values.items())
            for law in laws
        )
        notes.append(
            f"fold {f + 1}: {len(train)} training shots, {len(test)} scored; {values}; "
            f"selected {best}; gyrospin prior {prior}; e {maps['_numbers']['e']:.3f}, c "
            f"{maps['_numbers']['c']:.3f} ({len(before)} pairs); "
            f"{time.time() - t_start:.0f} s"
        )
        print(notes[-1], flush=True)
    return {"shots": shots, "errors": errors, "names": names, "notes": notes}


def table(result: dict) -> str:
    shots, errors = result["shots"], result["errors"]
    groups = [("all", [True] * len(shots))] + [
        (name, [s["set"] == name for s in shots]) for name in sorted({s["set"] for s in shots})
    ]
    lines = [
        f"{'rms 3D error, mm':<24}"
        + "".join(f"{g + f' {int(h * 1000)} ms':>24}" for g, _ in groups for h in HORIZONS)
    ]
    counts = []
    for _, sel in groups:
        for h in HORIZONS:
            n = sum(
                int(np.sum(shots[i]["track"].time[_scored(shots[i])] - shots[i]["bounce_t"] <= h))
                for i in range(len(shots))
                if sel[i]
            )
            counts.append(n)
    lines.append(f"{'samples':<24}" + "".join(f"{n:>24d}" for n in counts))
    for name in result["names"]:
        row = f"{name:<24}"
        for _, sel in groups:
            for h in HORIZONS:
                e = [
                    errors[name][i][
                        shots[i]["track"].time[_scored(shots[i])] - shots[i]["bounce_t"] <= h
                    ]
                    for i in range(len(shots))
                    if sel[i]
                ]
                e = np.concatenate(e) if e else np.zeros(0)
                row += f"{1e3 * math.sqrt(np.mean(e**2)) if e.size else math.nan:>24.2f}"
        lines.append(row)
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--folds", type=int, default=5)
    parser.add_argument("--laws", default="rigid,walton")
    parser.add_argument("--no-spin-prior", action="store_true",
                        help="fit the incoming arcs without a prior on the gyrospin")  # fmt: skip
    args = parser.parse_args()
    t = time.time()
    result = run(args.folds, tuple(args.laws.split(",")), not args.no_spin_prior)
    print(table(result))
    print(f"{len(result['shots'])} shots, {args.folds}-fold by shot; {time.time() - t:.0f} s")


if __name__ == "__main__":
    main()
