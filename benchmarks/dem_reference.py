"""A DEM code's own published curves for the Kharaz et al. (2001) impact (MFiX test case DEM05),
against the measurement and against this package's time-domain model.

MFiX runs the benchmark as its regression case DEM05 and ships the outputs a run must
reproduce; ``benchmarks/data/mfix_dem05`` holds their Part-Wall curves (its README gives the
provenance and MFiX's parameters). This module

* measures each MFiX curve against the Kharaz measurement with the measure of
  :func:`benchmarks.kharaz.errors` (rms and worst absolute error over the measured points),
  the MFiX curve being interpolated linearly onto the measured angles (MFiX's angles are
  0.5 to 65 degrees in steps of 0.5 and 2.5, and cover every measured angle);
* runs this package's time-domain model set up as MFiX set up its runs -- restitution 1 (no
  damping), the same springs (linear: ``k_t/k_n = 1.48/1.72``; Hertzian: the two-material
  Hertz and Mindlin stiffnesses of a sphere with E = 380 GPa, nu = 0.23 on a wall with
  E = 70 GPa, nu = 0.25) -- under each spring rule, at MFiX's angles, and reports the largest
  difference from MFiX's curve;
* splits the difference into MFiX's step and MFiX's contact geometry with a fixed-step
  explicit integration (:mod:`benchmarks.dem_explicit`).

The runs use the benchmark's sphere (radius 2.5 mm, density 4000 kg/m^3) and speed
(3.9 m/s); with restitution 1 the rebound depends only on the incidence angle, the
stiffness ratio and mu (the stiffness, the mass and the speed set the time scale).

Run ``python -m benchmarks.dem_reference`` to print the tables.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from spinimpact.core.tangential import mindlin_stiffness_ratio
from spinimpact.dynamics import HuntCrossleyContact, LinearContact, Mindlin, simulate

from .dem_explicit import explicit_impacts
from .kharaz import MU, OXIDE, RADIUS, SPEED, errors, incidence, markdown_table, quantities

DATA = Path(__file__).resolve().parent / "data" / "mfix_dem05"

#: MFiX's two collision models of DEM05 (the column prefixes of the data files).
MODELS = ("lsd", "hertzian")
LABELS = {
    "lsd": "MFiX DEM05, linear spring-dashpot (k_t/k_n = 1.48/1.72), e = 1",
    "hertzian": "MFiX DEM05, Hertzian (sphere 380 GPa, 0.23; wall 70 GPa, 0.25), e = 1",
}
QUANTITIES = ("e_t", "spin", "rebound_angle")
SPRINGS = ("scaled", "incremental", "total")

LSD_NORMAL = 1.72e7  #: N/m, MFiX's KN_W
LSD_RATIO = 1.48 / 1.72  #: MFiX's KT_W_FAC
SPHERE = (380e9, 0.23)  #: E (Pa), nu of the sphere (MFiX's E_YOUNG, V_POISSON)
WALL = (70e9, 0.25)  #: E (Pa), nu of the wall (MFiX's Ew_YOUNG, Vw_POISSON)
STEP_FACTOR = 50.0  #: MFiX's DTSOLID_FACTOR: the DEM step is the shortest collision time / 50


def curves() -> dict[str, dict[str, tuple[np.ndarray, np.ndarray]]]:
    """MFiX's Part-Wall curves: model -> quantity -> (incidence angle in degrees, value)."""
    files = {"e_t": "tangential_restitution.csv", "spin": "omega.csv",
             "rebound_angle": "rebound_angle.csv"}  # fmt: skip
    out: dict[str, dict[str, tuple[np.ndarray, np.ndarray]]] = {m: {} for m in MODELS}
    for key, name in files.items():
        lines = [s for s in (DATA / name).read_text().splitlines() if s and not s.startswith("#")]
        columns = lines[0].split(",")
        data = np.array([s.split(",") for s in lines[1:]], dtype=float)
        for model in MODELS:
            j = next(i for i, c in enumerate(columns) if c.startswith(model + "_"))
            out[model][key] = (data[:, 0], data[:, j])
    return out


def interpolated(model: str):
    """MFiX's ``model`` curves as a model of :func:`benchmarks.kharaz.errors`: each quantity
    interpolated linearly onto the angles asked for (``nan`` outside MFiX's angles)."""
    table = curves()[model]

    def at(angles, material=OXIDE):
        angles = np.asarray(angles, dtype=float)
        out = {}
        for key, (x, y) in table.items():
            out[key] = np.interp(angles, x, y, left=np.nan, right=np.nan)
        return out

    return at


def errors_table() -> list[tuple[str, dict[str, tuple[float, float, float]]]]:
    """Each MFiX curve's errors against the Kharaz measurement (:func:`kharaz.errors`)."""
    return [(LABELS[m], errors(interpolated(m), OXIDE)) for m in MODELS]


def effective_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """Hertz's ``E*`` of two materials, Pa: ``1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2``."""
    return 1.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)


def hertz_stiffness(radius: float = RADIUS) -> float:
    """``4/3 E* sqrt(R)`` of the sphere on MFiX's wall, N/m^1.5 (MFiX prints 0.41968E+10)."""
    return 4.0 / 3.0 * effective_modulus(*SPHERE, *WALL) * math.sqrt(radius)


def hertz_ratio() -> float:
    """Mindlin's ``k_t/k_n`` of the sphere on MFiX's wall (two materials)."""
    (e1, nu1), (e2, nu2) = SPHERE, WALL
    return float(mindlin_stiffness_ratio(nu1, nu2, e1 / e2))


def setup(model: str):
    """This package's normal law and Mindlin stiffness ratio set up as MFiX's ``model``."""
    if model == "hertzian":
        return HuntCrossleyContact(hertz_stiffness(), 1.5, 0.0), hertz_ratio()
    if model == "lsd":
        return LinearContact(LSD_NORMAL), LSD_RATIO
    raise ValueError(f"model must be one of {MODELS}, got {model!r}")


def ours(angles, model: str, spring: str, rtol: float = 1e-10) -> dict[str, np.ndarray]:
    """This package's time-domain model (:func:`spinimpact.dynamics.simulate` with
    :class:`~spinimpact.dynamics.Mindlin` under ``spring``) set up as MFiX's ``model``."""
    contact, ratio = setup(model)
    tangential = Mindlin(stiffness_ratio=ratio, spring=spring)
    body, rows = OXIDE.body, []
    for a in np.atleast_1d(angles):
        vx, vy = incidence(float(a))
        sim = simulate(body, vx, vy, 0.0, mu=MU, contact=contact, tangential=tangential,
                       rtol=rtol)  # fmt: skip
        rows.append((vx, sim.after.vx, sim.after.vy, sim.after.omega))
    return quantities(*(np.array(c, dtype=float) for c in zip(*rows, strict=True)))


def mfix_step(model: str) -> float:
    """MFiX's DEM step for DEM05, s: the shortest particle-particle collision time MFiX
    estimates, ``pi sqrt(m_eff/k)`` for two spheres of phase 1 (``m_eff = m/2``; for
    Hertzian ``k`` is their ``4/3 E* sqrt(R/2)``), divided by :data:`STEP_FACTOR`."""
    m_eff = float(OXIDE.body.mass) / 2.0
    if model == "hertzian":
        e, nu = SPHERE
        k = 4.0 / 3.0 * effective_modulus(e, nu, e, nu) * math.sqrt(RADIUS / 2.0)
    else:
        k = LSD_NORMAL
    return math.pi * math.sqrt(m_eff / k) / STEP_FACTOR


def explicit(angles, model: str, lever: str = "wall", refine: float = 1.0, offset: float = 0.5):
    """:func:`~benchmarks.dem_explicit.explicit_impacts` set up as MFiX's ``model``, with
    MFiX's step divided by ``refine``."""
    contact, ratio = setup(model)
    body = OXIDE.body
    k_n, n = contact.stiffness, getattr(contact, "exponent", 1.0)
    k_t = ratio * n * k_n  # k_t delta^(n-1) = r times the normal stiffness n k_n delta^(n-1)
    angles = np.asarray(angles, dtype=float)
    vx, vy, omega = explicit_impacts(
        angles, speed=SPEED, mass=float(body.mass), radius=RADIUS, inertia=float(body.inertia),
        mu=MU, normal_stiffness=k_n, tangential_stiffness=k_t, exponent=n,
        dt=mfix_step(model) / refine, lever=lever, offset=offset,
    )  # fmt: skip
    return quantities(incidence(angles)[0], vx, vy, omega)


def differences(reference, candidate, angles) -> dict[str, tuple[float, float]]:
    """quantity -> (largest absolute difference, its angle in degrees)."""
    out = {}
    for key in QUANTITIES:
        diff = np.abs(np.asarray(candidate[key]) - np.asarray(reference[key]))
        worst = int(np.argmax(diff))
        out[key] = (float(diff[worst]), float(angles[worst]))
    return out


#: The explicit runs of :func:`cross_check`: label -> (lever, step divisor, compared with).
EXPLICIT = {
    "explicit step as MFiX (arm R - delta, step t_c/50)": ("wall", 1.0, "MFiX"),
    "explicit step, arm R, step t_c/1000": ("radius", 20.0, "total"),
    "explicit step, arm R, step t_c/50 (the step alone)": ("radius", 1.0, "total"),
    "explicit step, arm R - delta, step t_c/1000 (the arm alone)": ("wall", 20.0, "total"),
}


def cross_check() -> list[tuple[str, dict[str, tuple[float, float]]]]:
    """rows ``(label, differences)`` at MFiX's angles 0.5 to 65 degrees: this package's
    model under each spring rule against MFiX's curves (``"<model>: <spring> - MFiX"``),
    then the explicit runs of :data:`EXPLICIT` against MFiX or against this package's
    ``"total"`` rule (``"<model>: <explicit label> - MFiX"`` or ``"... - total"``)."""
    rows = []
    for model in MODELS:
        angles, _ = curves()[model]["e_t"]
        mfix = interpolated(model)(angles)
        runs = {spring: ours(angles, model, spring) for spring in SPRINGS}
        for spring in SPRINGS:
            rows.append((f"{model}: {spring} - MFiX", differences(mfix, runs[spring], angles)))
        for label, (lever, refine, against) in EXPLICIT.items():
            run = explicit(angles, model, lever=lever, refine=refine)
            reference = mfix if against == "MFiX" else runs["total"]
            rows.append((f"{model}: {label} - {against}", differences(reference, run, angles)))
    return rows


def touch_spread(model: str, offsets=(0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0)):
    """How much MFiX's step alone makes the result depend on where the touch falls within a
    step: quantity -> (largest spread over ``offsets`` of :func:`explicit` with MFiX's
    conventions, its angle in degrees), at MFiX's angles."""
    angles, _ = curves()[model]["e_t"]
    runs = [explicit(angles, model, offset=o) for o in offsets]
    out = {}
    for key in QUANTITIES:
        values = np.array([r[key] for r in runs])
        spread = values.max(axis=0) - values.min(axis=0)
        worst = int(np.argmax(spread))
        out[key] = (float(spread[worst]), float(angles[worst]))
    return out


def cross_check_markdown(rows) -> str:
    """The cross-check as a Markdown table."""
    head = ("| comparison | e_t, largest difference (deg) | spin, rad/s (deg) "
            "| rebound angle, deg (deg) |\n|---|---|---|---|")  # fmt: skip
    lines = [head]
    for label, d in rows:
        cells = [label] + [f"{d[k][0]:.{p}f} ({d[k][1]:g})"
                           for k, p in (("e_t", 4), ("spin", 2), ("rebound_angle", 4))]  # fmt: skip
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main() -> None:
    print("MFiX DEM05 curves against the Kharaz measurement (benchmarks.kharaz.errors):\n")
    print(markdown_table(errors_table()))
    print("\nThis package's time-domain model and MFiX's curves (e = 1, MFiX's springs):\n")
    print(cross_check_markdown(cross_check()))
    print("\nWhere the touch falls within MFiX's step (the explicit step, offsets 1/8..1):\n")
    print(cross_check_markdown([(f"{m}: spread", touch_spread(m)) for m in MODELS]))


if __name__ == "__main__":
    main()
