"""Coverage of the track fits' intervals on synthetic tracks with known truth.

Each data set is made by :func:`spinimpact.flight` (tests/model/track_cases.py): a
table-tennis ball with 1.5 mm of noise in each coordinate, two outliers 2-5 cm off the path
and two samples dropped a shot, sampled at about 180 Hz with uneven steps. The nominal 95 %
intervals must cover the truth at about the nominal rate:

* :func:`fit_arc` on the incoming 0.45 s of a flight: the velocity's three components and
  the spin's topspin and sidespin components, each ``estimate -+ 1.96`` standard errors;
* :func:`fit_bounces` of two shots of 0.35 s that slide throughout their bounces (rigid law):
  the profile-likelihood intervals of ``mu``, ``kappa`` and ``contact_height``, and the Wald
  intervals of each shot's spin before the bounce (topspin, sidespin).

Each rate must be at least 95 % less three binomial standard errors at the number of data
sets. ``make test`` runs 30 flights and 10 bounce data sets (a few minutes);
``SPINIMPACT_TRACK_SETS=full`` runs 100 and 40 (about 6 and 10 minutes on two cores): there
the measured rates were 96-98 % (flight) and 92.5-97.5 % (bounce).
"""

from __future__ import annotations

import os

import numpy as np
import pytest

from spinimpact.model.track import find_bounce, spin_axes
from spinimpact.model.track_arc import fit_arc
from spinimpact.model.track_fit import fit_bounces

from .track_cases import CONTACT_HEIGHT, shot

#: Hundreds of fits: run by `make test` only.
pytestmark = pytest.mark.slow

Z95 = 1.959964
#: Data sets of the two tests: (flights, bounce sets).
FULL = os.environ.get("SPINIMPACT_TRACK_SETS", "") == "full"
N_ARC, N_BOUNCE = (100, 40) if FULL else (30, 10)


def _required(n_sets: int) -> float:
    """95 % less three binomial standard errors at ``n_sets``."""
    return 0.95 - 3.0 * (0.95 * 0.05 / n_sets) ** 0.5


def _covered(estimate, se, truth) -> bool:
    return bool(abs(estimate - truth) <= Z95 * se)


def test_arc_intervals_cover_the_truth_at_the_nominal_rate():
    rng = np.random.default_rng(2031)
    n_sets = N_ARC
    hits = np.zeros(5)
    for _ in range(n_sets):
        track, truth = shot(rng, before=0.45, after=0.05)
        split = find_bounce(track)["index"]
        f = fit_arc(track.select(slice(0, split)), sigma=0.0015)
        se = f.standard_error
        for k in range(3):
            hits[k] += _covered(f.velocity[k], se[3 + k], truth["velocity"][k])
        axes = spin_axes(f.velocity, track.up)
        for k, name in enumerate(("topspin", "sidespin")):
            value, err, _ = f.spin_components[name]
            hits[3 + k] += _covered(value, err, float(axes[k] @ truth["spin"]))
    rate = hits / n_sets
    print("arc coverage (vx, vy, vz, topspin, sidespin):", rate)
    assert np.all(rate >= _required(n_sets)), rate


@pytest.mark.timeout(3600)  # 40 joint fits with profile intervals: about 10 minutes
def test_bounce_intervals_cover_the_truth_at_the_nominal_rate():
    rng = np.random.default_rng(2032)
    n_sets = N_BOUNCE
    truth_shared = {"mu": 0.2, "kappa": 0.88, "contact_height": CONTACT_HEIGHT}
    hits = {**{k: 0 for k in truth_shared}, "topspin": 0, "sidespin": 0}
    n_spin = 0
    for _ in range(n_sets):
        made = [shot(rng, mu=0.2, kappa=0.88, before=0.2, after=0.15, name=f"shot {i}")
                for i in range(2)]  # fmt: skip
        fit = fit_bounces([t for t, _ in made], law="rigid", sigma=0.0015)
        for k, v in truth_shared.items():
            hits[k] += fit.interval_low[k] <= v <= fit.interval_high[k]
        for s, (_, truth) in zip(fit.shots, made, strict=True):
            axes = spin_axes(s.state[3:6], "z")
            for k, name in enumerate(("topspin", "sidespin")):
                value, err, _ = s.spin_components_before[name]
                hits[name] += _covered(value, err, float(axes[k] @ truth["spin"]))
            n_spin += 1
    rates = {k: v / (n_spin if k in ("topspin", "sidespin") else n_sets) for k, v in hits.items()}
    print("bounce coverage:", rates)
    assert all(r >= _required(n_sets) for r in rates.values()), rates
