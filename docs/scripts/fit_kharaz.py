"""Figure for docs/fitting.md: the rigid model fitted to Kharaz et al. (2001).

Usage: python docs/scripts/fit_kharaz.py OUTPUT.png

The measured points (benchmarks/data/kharaz2001: tangential restitution e_t and spin after
impact over the incidence angle, a 5 mm aluminium-oxide sphere at 3.9 m/s without spin)
become bounces: vx = 3.9 sin(theta), vy = -3.9 cos(theta), omega = 0, and after_vx = e_t vx
or after_omega = -|omega|. kappa is held at the literature's 0.98 and one sigma is
estimated from the scatter; all points are fitted, so the picture shows which bounces
the fit finds sliding (filled) and where the rigid law misses the grip of a real ball.
"""

import sys
from pathlib import Path

import numpy as np

from spinimpact import Body, MeasuredBounces, fit
from spinimpact.cli.fit import read_columns
from spinimpact.io import atomic_path
from spinimpact.viz.fit import plot_fit

DATA = Path(__file__).resolve().parents[2] / "benchmarks" / "data" / "kharaz2001"
SPEED, RADIUS = 3.9, 0.0025


def main(output: str) -> None:
    e_t = read_columns(str(DATA / "tangential_restitution.csv"))
    spin = read_columns(str(DATA / "omega.csv"))
    angle = np.radians(np.concatenate([e_t["impact_angle_deg"], spin["impact_angle_deg"]]))
    vx, vy = SPEED * np.sin(angle), -SPEED * np.cos(angle)
    gap = np.full(spin["omega_rad_s"].size, np.nan)  # what each kind of point did not measure
    after_vx = np.concatenate([e_t["e_t"] * vx[: e_t["e_t"].size], gap])
    after_omega = np.concatenate([np.full(e_t["e_t"].size, np.nan), -spin["omega_rad_s"]])
    data = MeasuredBounces(vx, vy, 0.0 * vx, after_vx=after_vx, after_omega=after_omega)
    ball = Body.solid_sphere(mass=4000.0 * 4.0 / 3.0 * np.pi * RADIUS**3, radius=RADIUS)
    res = fit(data, ball, fixed={"kappa": 0.98})
    with atomic_path(output) as tmp:
        plot_fit(res).savefig(tmp, format="png", dpi=80)


if __name__ == "__main__":
    main(sys.argv[1])
