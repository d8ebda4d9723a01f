"""Kharaz, Gorham & Salman (2001): every model against the measured oblique bounces.

A 5 mm aluminium-oxide sphere (radius 2.5 mm, density 4000 kg/m^3, E = 3.8e11 Pa,
nu = 0.23) strikes a glass anvil at 3.9 m/s without spin; literature parameters
mu = 0.092, kappa = 0.98 (Chung & Ooi 2011, Test 4). The anvil is treated as the
sphere's own material, as the benchmark does; with Hertz-Mindlin contact the rebound
then depends on Poisson's ratio, mu and kappa only (E and the density set the time
scale). Nothing here is fitted to the measured points.

The measured points are in ``benchmarks/data/kharaz2001`` (one public digitization;
its README says where it comes from). :func:`errors` is the measure of the issue's
table: rms and worst absolute error over the measured points of each quantity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from spinimpact import Body, solve
from spinimpact.core.tangential import mindlin_stiffness_ratio
from spinimpact.dynamics import HertzContact, LinearContact, Mindlin, simulate

DATA = Path(__file__).resolve().parent / "data" / "kharaz2001"

SPEED = 3.9  #: m/s
RADIUS = 2.5e-3  #: m
MU = 0.092
KAPPA = 0.98
#: Walton's beta0 from the literature (not fitted here): Foerster, Louge, Chang & Allia
#: (1994), glass spheres, the published beta0 nearest to this pair of materials.
BETA0 = 0.33


@dataclass(frozen=True)
class Material:
    """A sphere material of the benchmark: E in Pa, Poisson's ratio, density in kg/m^3."""

    name: str
    youngs_modulus: float
    poisson_ratio: float
    density: float

    @property
    def body(self) -> Body:
        mass = 4.0 / 3.0 * math.pi * RADIUS**3 * self.density
        return Body.solid_sphere(mass=mass, radius=RADIUS)


OXIDE = Material("aluminium oxide", 3.8e11, 0.23, 4000.0)
ALLOY = Material("aluminium alloy", 7.0e10, 0.33, 2700.0)


def measured() -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The measured points: quantity -> (incidence angle in degrees, value)."""
    files = {"e_t": "tangential_restitution.csv", "spin": "omega.csv",
             "rebound_angle": "rebound_angle.csv"}  # fmt: skip
    out = {}
    for key, name in files.items():
        rows = [
            line.split(",")
            for line in (DATA / name).read_text().splitlines()
            if line and not line.startswith("#")
        ][1:]  # after the column names
        data = np.array(rows, dtype=float)
        out[key] = (data[:, 0], data[:, 1])
    return out


def incidence(angle_deg):
    """``(vx, vy)`` in m/s of the 3.9 m/s impact at ``angle_deg`` from the normal."""
    a = np.radians(angle_deg)
    return SPEED * np.sin(a), -SPEED * np.cos(a)


def quantities(vx, after_vx, after_vy, after_omega) -> dict[str, np.ndarray]:
    """e_t = vx+/vx-, the spin's magnitude (rad/s), the centre's rebound angle (deg)."""
    return {
        "e_t": np.asarray(after_vx) / vx,
        "spin": np.abs(after_omega),
        "rebound_angle": np.degrees(np.arctan2(after_vx, after_vy)),
    }


def rigid(angles, material=OXIDE):
    """The rigid-body closed form (the paper's law) with mu and kappa."""
    vx, vy = incidence(np.asarray(angles, dtype=float))
    imp = solve(material.body, vx, vy, 0.0, mu=MU, kappa=KAPPA)
    return quantities(vx, imp.after.vx, imp.after.vy, imp.after.omega)


def impulse_law(angles, law, material=OXIDE):
    """An impulse-space compliance law of :func:`spinimpact.solve` (``tangential=``)."""
    vx, vy = incidence(np.asarray(angles, dtype=float))
    imp = solve(material.body, vx, vy, 0.0, mu=MU, kappa=KAPPA, tangential=law)
    return quantities(vx, imp.after.vx, imp.after.vy, imp.after.omega)


def walton(angles, material=OXIDE):
    from spinimpact.model.compliance import Walton

    return impulse_law(angles, Walton(BETA0), material)


def stronge(angles, material=OXIDE):
    from spinimpact.model.compliance import Stronge

    return impulse_law(angles, Stronge(poisson_ratio=material.poisson_ratio), material)


def _hertz_alpha_speed(material: Material) -> float:
    """Hunt-Crossley ``alpha v`` giving kappa = 0.98 (it depends on ``alpha v`` alone)."""
    mass = float(material.body.mass)
    law = HertzContact.calibrated(youngs_modulus=material.youngs_modulus / 2,
                                  poisson_ratio=material.poisson_ratio, radius=RADIUS,
                                  kappa=KAPPA, mass=mass, speed=SPEED)  # fmt: skip
    return law.alpha * SPEED


def hertz_mindlin(angles, material=OXIDE, rtol=1e-10, spring="scaled"):
    """Time-domain Hertz normal contact (Hunt-Crossley damping giving kappa = 0.98 at
    each impact's normal speed) with Mindlin's no-slip tangential stiffness; ``spring``
    is the rule of :class:`~spinimpact.model.mindlin.Mindlin`."""
    body, alpha_v = material.body, _hertz_alpha_speed(material)
    rows = []
    for a in np.atleast_1d(angles):
        vx, vy = incidence(float(a))
        law = HertzContact(material.youngs_modulus / 2, material.poisson_ratio, RADIUS,
                           alpha_v / abs(vy))  # fmt: skip
        sim = simulate(
            body, vx, vy, 0.0, mu=MU, contact=law, tangential=Mindlin(spring=spring), rtol=rtol
        )
        rows.append((vx, sim.after.vx, sim.after.vy, sim.after.omega))
    return quantities(*(np.array(c, dtype=float) for c in zip(*rows, strict=True)))


def linear_mindlin(angles, material=OXIDE, rtol=1e-10):
    """Time-domain linear spring-dashpot (damping giving kappa = 0.98) with a constant
    tangential spring ``k_t = r k``, ``r = 2(1 - nu)/(2 - nu)`` (the linear DEM model;
    the stiffness itself only sets the time scale)."""
    body = material.body
    stiffness = 1e7  # N/m; any value gives the same rebound (it scales time only)
    law = LinearContact.calibrated(stiffness=stiffness, kappa=KAPPA, mass=float(body.mass))
    tangential = Mindlin(stiffness_ratio=float(mindlin_stiffness_ratio(material.poisson_ratio)))
    rows = []
    for a in np.atleast_1d(angles):
        vx, vy = incidence(float(a))
        sim = simulate(body, vx, vy, 0.0, mu=MU, contact=law, tangential=tangential, rtol=rtol)
        rows.append((vx, sim.after.vx, sim.after.vy, sim.after.omega))
    return quantities(*(np.array(c, dtype=float) for c in zip(*rows, strict=True)))


def mindlin_deresiewicz(angles, material=OXIDE):
    """Hertz normal and Mindlin-Deresiewicz tangential contact with micro-slip
    (:class:`spinimpact.MindlinDeresiewicz`, the method of dimensionality reduction), the
    material's Poisson ratio; Hunt-Crossley damping giving kappa = 0.98."""
    from spinimpact.model.compliance import MindlinDeresiewicz

    law = MindlinDeresiewicz(poisson_ratio=material.poisson_ratio)
    return impulse_law(angles, law, material)


def history(angles, material=OXIDE):
    """:func:`hertz_mindlin` with the history spring (no micro-slip; the force unloads
    along its loading history, the exact no-slip elastic solution)."""
    return hertz_mindlin(angles, material, spring="history")


def incremental(angles, material=OXIDE):
    """:func:`hertz_mindlin` with the plain incremental spring."""
    return hertz_mindlin(angles, material, spring="incremental")


def total(angles, material=OXIDE):
    """:func:`hertz_mindlin` with the total-displacement spring."""
    return hertz_mindlin(angles, material, spring="total")


#: The models compared, in the order of the table: (label, function, material).
MODELS = (
    ("rigid", rigid, OXIDE),
    ("Walton, beta0 = 0.33", walton, OXIDE),
    ("Stronge, nu = 0.23", stronge, OXIDE),
    ("Hertz-Mindlin in time, scaled spring", hertz_mindlin, OXIDE),
    ("Hertz-Mindlin in time, scaled spring, alloy (nu = 0.33)", hertz_mindlin, ALLOY),
    ("Hertz-Mindlin in time, incremental spring", incremental, OXIDE),
    ("Hertz-Mindlin in time, total spring", total, OXIDE),
    ("linear spring-dashpot + Mindlin ratio in time", linear_mindlin, OXIDE),
    ("Hertz-Mindlin in time, history spring", history, OXIDE),
    ("Hertz-Mindlin in time, history spring, alloy (nu = 0.33)", history, ALLOY),
    ("Mindlin-Deresiewicz (micro-slip), nu = 0.23", mindlin_deresiewicz, OXIDE),
    ("Mindlin-Deresiewicz (micro-slip), alloy (nu = 0.33)", mindlin_deresiewicz, ALLOY),
)

#: The models drawn in the figure (the table has them all).
FIGURE_MODELS = tuple(m for m in MODELS if m[0] in (
    "rigid", "Walton, beta0 = 0.33", "Stronge, nu = 0.23",
    "Hertz-Mindlin in time, scaled spring", "Hertz-Mindlin in time, history spring",
    "linear spring-dashpot + Mindlin ratio in time",
    "Mindlin-Deresiewicz (micro-slip), nu = 0.23",
    "Mindlin-Deresiewicz (micro-slip), alloy (nu = 0.33)"))  # fmt: skip

#: The issue's DEM reference figures (Chung & Ooi 2011 curves against the measurement).
DEM_REFERENCE = {"oxide": {"e_t": 0.013, "spin": 33.0}, "alloy": {"e_t": 0.0055, "spin": 28.0}}


def errors(model, material=OXIDE) -> dict[str, tuple[float, float, float]]:
    """quantity -> (rms error, worst absolute error, angle of the worst in degrees)."""
    out = {}
    for key, (angles, values) in measured().items():
        predicted = model(angles, material)[key]
        err = predicted - values
        worst = int(np.argmax(np.abs(err)))
        out[key] = (float(np.sqrt(np.mean(err**2))), float(abs(err[worst])), float(angles[worst]))
    return out


def table() -> list[tuple[str, dict[str, tuple[float, float, float]]]]:
    """Every model's errors, in the order of :data:`MODELS`."""
    return [(label, errors(model, material)) for label, model, material in MODELS]


def markdown_table(rows) -> str:
    """The errors as the Markdown table of ``docs/validation.md``."""
    head = ("| model | e_t rms | e_t worst (deg) | spin rms, rad/s | spin worst (deg) "
            "| rebound angle rms, deg | rebound angle worst (deg) |\n"
            "|---|---|---|---|---|---|---|")  # fmt: skip
    lines = [head]
    for label, e in rows:
        cells = [label]
        for key, digits in (("e_t", 3), ("spin", 0), ("rebound_angle", 2)):
            rms, worst, at = e[key]
            cells += [f"{rms:.{digits}f}", f"{worst:.{digits}f} ({at:.0f})"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)
