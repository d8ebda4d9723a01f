"""The figures of docs/flight.md: one first serve (side and top views, bounces marked) and
1,000 serves scattered in speed, angle, direction and spin.

Usage: python docs/scripts/flight.py OUTPUT_DIRECTORY
"""

import sys
from pathlib import Path

import numpy as np

from spinimpact.io import atomic_path
from spinimpact.model.flight import flight
from spinimpact.viz.flight import plot_flight


def main(folder: str) -> None:
    out = Path(folder)
    serve = flight("tennis", "hard", speed=50.0, angle=-6.0, height=2.8, spin_rpm=2000.0,
                   spin_axis=[0.0, 0.4, -1.0], max_bounces=3)  # fmt: skip
    with atomic_path(out / "flight_serve.png") as tmp:
        plot_flight(serve).savefig(tmp, format="png", dpi=80)
    rng = np.random.default_rng(2026)
    n = 1000
    serves = flight("tennis", "hard", speed=rng.normal(50.0, 2.0, n),
                    angle=rng.normal(-6.0, 0.4, n), direction=rng.normal(0.0, 1.5, n),
                    height=2.8, spin_rpm=rng.normal(2000.0, 300.0, n), max_bounces=2,
                    path=True)  # fmt: skip
    with atomic_path(out / "flight_serves.png") as tmp:
        plot_flight(serves).savefig(tmp, format="png", dpi=80)


if __name__ == "__main__":
    main(sys.argv[1])
