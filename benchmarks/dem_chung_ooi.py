"""Chung & Ooi (2011) Tests 1-6 run in time with the DEM contact force (``spinimpact.dem``),
as the DEM codes' benchmark scripts run them, beside the references.

* Tests 1 and 2 (normal impacts of two spheres, of a sphere on a wall): contact duration,
  peak force and largest compression against Hertz's closed form.
* Test 3: the restitution that the viscous damping gives, with the exact ``beta``
  (:func:`spinimpact.dem.viscous_damping`) and with the DEM codes' log-decrement formula.
* Test 4: Kharaz et al. (2001) measured (e_t, spin, rebound angle) against the DEM force
  (micro-slip, Hunt-Crossley damping calibrated to kappa = 0.98 at each impact's normal
  speed) and against the impulse-space micro-slip law.
* Test 5: the recoil ``u+/(mu vn)`` and spin ``R omega+/(mu vn)`` against the incident
  ``u-/(mu vn)``, beside the digitized reference curves (DEM: steel, polyethylene; FEM),
  with the rms difference over each curve's points.
* Test 6: ``beta = -u+/u-`` against ``chi = 3.5 mu (1 + e) vn/u-`` for each tangential
  model and damping choice, beside the digitized DEM reference curve of the aluminium alloy,
  with the rms difference and the largest ``beta`` where ``chi > 1``.

The cases are those of :mod:`benchmarks.chung_ooi` (materials, sizes and speeds as
Kratos's and PySPH's scripts define them; docs/validation.md). Each impact takes 1,000
steps per undamped Hertz contact duration (``STEPS``). The reference points are
``benchmarks/data/chung_ooi_2011`` (third-party digitizations, about 1 % reading error;
its README gives the source).

Run ``python -m benchmarks.dem_chung_ooi [--test N]``; ``--figure PATH`` draws Test 6's
figure (``docs/images/dem_test6.png``).
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from pathlib import Path

import numpy as np

from spinimpact import Body, dem

from . import chung_ooi, kharaz

DATA = Path(__file__).resolve().parent / "data" / "chung_ooi_2011"
#: Steps per undamped Hertz contact duration.
STEPS = 1000


def reference(name):
    """The digitized curves of one file: block name -> ``(x, y)`` arrays."""
    blocks, current = {}, None
    for line in (DATA / name).read_text().splitlines():
        line = line.strip()
        if line.startswith("#"):
            current = line[1:].split("#")[0].strip()
            blocks[current] = []
        elif line and current is not None:
            blocks[current].append([float(v) for v in line.split(",")])
    return {k: np.array(v).T for k, v in blocks.items() if v}


def _wall(case, **options):
    """The DEM force of an oblique case (a sphere on a rigid wall)."""
    return dem.ContactForce.sphere_on_wall(
        youngs_modulus=case.youngs_modulus, poisson_ratio=case.poisson_ratio,
        radius=case.radius, density=case.density, mu=case.mu, restitution=case.kappa,
        speed=case.normal_speed, **options,
    )  # fmt: skip


def normal_tests(cases) -> list[str]:
    """Tests 1 and 2 in time: the DEM loop (two spheres for Test 1, a wall for Test 2)."""
    lines = [f"{'material':18s} {'quantity':16s} {'DEM loop':>14s} {'Hertz theory':>14s} "
             f"{'rel. diff':>10s}"]  # fmt: skip
    for case in cases:
        ref = chung_ooi.hertz_theory(case)
        mass = 4.0 / 3.0 * math.pi * case.radius**3 * case.density
        ball = Body.solid_sphere(mass=mass, radius=case.radius)
        if case.pair:
            force = dem.ContactForce.two_spheres(
                youngs_modulus=case.youngs_modulus, poisson_ratio=case.poisson_ratio,
                radius=case.radius, density=case.density, mu=0.0)  # fmt: skip
            dt = force.time_scale(2.0 * case.speed) / STEPS
            run = dem.pair_impact(force, (ball, ball), ((0.0, case.speed, 0.0),
                                  (0.0, -case.speed, 0.0)), dt=dt, trace=True)  # fmt: skip
        else:
            force = dem.ContactForce.sphere_on_wall(
                youngs_modulus=case.youngs_modulus, poisson_ratio=case.poisson_ratio,
                radius=case.radius, density=case.density, mu=0.0)  # fmt: skip
            dt = force.time_scale(case.speed) / STEPS
            run = dem.wall_impact(force, ball, 0.0, -case.speed, 0.0, dt=dt, trace=True)
        trace = np.asarray(run.trace)
        closed = trace[:, 1] > 0.0
        values = {"duration": dt * closed.sum(), "peak_force": trace[:, 2].max(),
                  "max_compression": trace[:, 1].max()}  # fmt: skip
        for key, value in values.items():
            lines.append(f"{case.name:18s} {key:16s} {value:14.6e} {ref[key]:14.6e} "
                         f"{value / ref[key] - 1:10.1e}")  # fmt: skip
    return lines


def test3() -> list[str]:
    """Test 3: the viscous damping's restitution, exact ``beta`` and log-decrement."""
    lines = [f"{'material':18s} {'target e':>9s} {'beta exact':>11s} {'e (exact)':>10s} "
             f"{'beta log-dec':>13s} {'e (log-dec)':>12s}"]  # fmt: skip
    for case in chung_ooi.TEST3:
        mass = 4.0 / 3.0 * math.pi * case.radius**3 * case.density
        ball = Body.solid_sphere(mass=mass, radius=case.radius)
        for e in chung_ooi.TEST3_RESTITUTION:
            cells = []
            for beta in (dem.viscous_damping(e), dem.log_decrement_damping(e)):
                force = dem.ContactForce.sphere_on_wall(
                    youngs_modulus=case.youngs_modulus, poisson_ratio=case.poisson_ratio,
                    radius=case.radius, density=case.density, mu=0.0)  # fmt: skip
                if beta > 0:
                    force = dem.ContactForce(force.modulus, force.shear_modulus, force.radius,
                                             force.mass, 0.0, damping="viscous",
                                             damping_coefficient=beta)  # fmt: skip
                dt = force.time_scale(case.speed) / STEPS
                run = dem.wall_impact(force, ball, 0.0, -case.speed, 0.0, dt=dt)
                cells.append((beta, float(run.vy) / case.speed))
            lines.append(f"{case.name:18s} {e:9.2f} {cells[0][0]:11.4f} {cells[0][1]:10.4f} "
                         f"{cells[1][0]:13.4f} {cells[1][1]:12.4f}")  # fmt: skip
    return lines


def kharaz_dem(angles, material=kharaz.OXIDE):
    """Kharaz et al.'s impacts with the DEM force: micro-slip, the sphere on a plate of its
    own material (as :func:`benchmarks.kharaz.mindlin_deresiewicz` takes it), Hunt-Crossley
    damping calibrated to kappa = 0.98 at each impact's normal speed."""
    body = material.body
    rows = []
    for a in np.atleast_1d(angles):
        vx, vy = (float(v) for v in kharaz.incidence(float(a)))
        force = dem.ContactForce.sphere_on_wall(
            youngs_modulus=material.youngs_modulus, poisson_ratio=material.poisson_ratio,
            radius=kharaz.RADIUS, mass=float(body.mass), mu=kharaz.MU,
            wall_youngs_modulus=material.youngs_modulus,
            wall_poisson_ratio=material.poisson_ratio, restitution=kharaz.KAPPA,
            damping="hunt-crossley", speed=abs(vy))  # fmt: skip
        run = dem.wall_impact(force, body, vx, vy, 0.0, dt=force.time_scale(abs(vy)) / STEPS)
        rows.append((vx, float(run.vx), float(run.vy), float(run.omega)))
    return kharaz.quantities(*(np.array(c) for c in zip(*rows, strict=True)))


def test4() -> list[str]:
    """Test 4: rms and worst errors against Kharaz et al.'s measurement."""
    lines = ["Kharaz et al. (2001), errors against the measurement (rms, worst at angle)"]
    for label, model in (("DEM force, micro-slip (in time)", kharaz_dem),
                         ("impulse-space micro-slip law", kharaz.mindlin_deresiewicz)):  # fmt: skip
        for material in (kharaz.OXIDE, kharaz.ALLOY):
            e = kharaz.errors(model, material)
            cells = [f"{k} {e[k][0]:.4g} ({e[k][1]:.3g} at {e[k][2]:.0f})" for k in e]
            lines.append(f"  {label}, nu = {material.poisson_ratio}: " + "; ".join(cells))
    return lines


def test5_curves(case, x, model="micro-slip"):
    """``(u+/(mu vn), R omega+/(mu vn))`` at the incident ``x = u-/(mu vn)``."""
    force = _wall(case, model=model)
    ball = Body.solid_sphere(mass=force.mass, radius=case.radius)
    dt = force.time_scale(case.normal_speed) / STEPS
    recoil, spin = [], []
    scale = case.mu * case.normal_speed
    for value in x:
        run = dem.wall_impact(force, ball, value * scale, -case.normal_speed, 0.0, dt=dt)
        recoil.append((float(run.vx) + case.radius * float(run.omega)) / scale)
        spin.append(case.radius * float(run.omega) / scale)
    return np.array(recoil), np.array(spin)


def _rms(a, b):
    return float(np.sqrt(np.mean((np.asarray(a) - np.asarray(b)) ** 2)))


def test5() -> list[str]:
    """Test 5: recoil and spin of each model beside the digitized curves, rms."""
    graph1, graph2 = reference("benchmark5_graph1.dat"), reference("benchmark5_graph2.dat")
    lines = ["y1 = u+/(mu vn), y2 = R omega+/(mu vn) against x = u-/(mu vn); rms of the DEM "
             "force's curve against each reference curve at its points"]  # fmt: skip
    pairs = {"Steel": chung_ooi.TEST5[0], "Polyethylene": chung_ooi.TEST5[1],
             "FEM": chung_ooi.TEST5[0]}  # fmt: skip
    for model in ("micro-slip", "scaled", "total"):
        for name, case in pairs.items():
            x1, y1 = graph1[name]
            x2, y2 = graph2[name]
            recoil, _ = test5_curves(case, x1, model)
            _, spin = test5_curves(case, x2, model)
            lines.append(f"  {model:11s} vs {name:12s} (nu = {case.poisson_ratio}): recoil rms "
                         f"{_rms(recoil, y1):.3f} over {x1.size} points, spin rms "
                         f"{_rms(spin, y2):.3f} over {x2.size}")  # fmt: skip
    return lines


#: Test 6's configurations: label -> ContactForce options (the damping ratio ``beta_t`` of
#: the tangential damper, where there is one, is the normal one's, as the DEM codes take it).
TEST6_MODELS = {
    "micro-slip, Hunt-Crossley, limit mu N_el": {
        "model": "micro-slip",
        "damping": "hunt-crossley",
        "friction_limit": "elastic",
    },
    "micro-slip, Hunt-Crossley, limit mu N": {"model": "micro-slip", "damping": "hunt-crossley"},
    "micro-slip, viscous, limit mu N_el": {"model": "micro-slip", "friction_limit": "elastic"},
    "micro-slip, viscous, limit mu N": {"model": "micro-slip", "friction_limit": "total"},
    "micro-slip, viscous, limit mu N, tangential damper": {
        "model": "micro-slip",
        "friction_limit": "total",
        "tangential": True,
    },
    "history, viscous, limit mu N": {"model": "history", "friction_limit": "total"},
    "scaled, viscous, limit mu N": {"model": "scaled", "friction_limit": "total"},
    "scaled, viscous, limit mu N, tangential damper (Kratos-like)": {
        "model": "scaled",
        "friction_limit": "total",
        "tangential": True,
    },
    "total, viscous, limit mu N (LIGGGHTS-like, no damper)": {
        "model": "total",
        "friction_limit": "total",
    },
    "total, viscous, limit mu N, tangential damper (LIGGGHTS-like)": {
        "model": "total",
        "friction_limit": "total",
        "tangential": True,
    },
}


def test6_beta(options, chi, case=chung_ooi.TEST6[0], steps=STEPS):
    """``beta = -u+/u-`` at each ``chi`` for one configuration of :data:`TEST6_MODELS`."""
    options = dict(options)
    damper = options.pop("tangential", False)
    force = _wall(case, **options)
    if damper:
        force = dataclasses.replace(force, tangential_damping=force.damping_coefficient)
    ball = Body.solid_sphere(mass=force.mass, radius=case.radius)
    dt = force.time_scale(case.normal_speed) / steps
    out = []
    for c in np.atleast_1d(chi):
        u0 = 3.5 * case.mu * (1 + case.kappa) * case.normal_speed / c
        run = dem.wall_impact(force, ball, 0.0, -case.normal_speed, u0 / case.radius, dt=dt)
        out.append(-(float(run.vx) + case.radius * float(run.omega)) / u0)
    return np.array(out)


def test6() -> list[str]:
    """Test 6: each configuration's beta against the aluminium alloy's reference curve."""
    chi, ref = reference("benchmark6_graph1.dat")["Al. alloy"]
    lines = ["beta = -u+/u- against chi = 3.5 mu (1+e) vn/u- (backspin only, e = 0.5, "
             "mu = 0.4); rms against the Al. alloy DEM curve over its 17 points",
             "chi:       " + " ".join(f"{c:6.2f}" for c in chi),
             "reference: " + " ".join(f"{b:6.3f}" for b in ref)]  # fmt: skip
    for label, options in TEST6_MODELS.items():
        beta = test6_beta(options, chi)
        lines.append(f"{label}: rms {_rms(beta, ref):.3f}, largest beta at chi > 1 "
                     f"{beta[chi > 1].max():.3f} (reference {ref[chi > 1].max():.3f})")  # fmt: skip
        lines.append("           " + " ".join(f"{b:6.3f}" for b in beta))
    return lines


#: The configurations the figure draws (label in the legend -> TEST6_MODELS key).
FIGURE_MODELS = {
    "micro-slip (Hunt-Crossley, limit mu N)": "micro-slip, Hunt-Crossley, limit mu N",
    "micro-slip (limit mu N_el)": "micro-slip, Hunt-Crossley, limit mu N_el",
    "micro-slip + tangential damper": "micro-slip, viscous, limit mu N, tangential damper",
    "scaled spring (no damper)": "scaled, viscous, limit mu N",
    "scaled spring + damper (Kratos-like)": (
        "scaled, viscous, limit mu N, tangential damper (Kratos-like)"
    ),
}


def test6_figure(path) -> None:
    """beta against chi: the reference curves and the configurations of FIGURE_MODELS."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curves = reference("benchmark6_graph1.dat")
    chi = np.geomspace(0.15, 25.0, 60)
    fig, ax = plt.subplots(figsize=(10.0, 4.6))
    for name, marker in (("Al. alloy", "o"), ("Nylon", "s")):
        x, y = curves[name]
        ax.plot(x, y, marker, mfc="none", color="k", label=f"Chung & Ooi DEM, {name.lower()}")
    ax.plot(chi, np.minimum(chi - 1.0, 0.0), color="0.6", lw=1.0, label="rigid law")
    for label, key in FIGURE_MODELS.items():
        ax.plot(chi, test6_beta(TEST6_MODELS[key], chi, steps=400), label=label)
    ax.set_xscale("log")
    ax.set_xlabel(r"$\chi = 3.5\,\mu (1 + e)\, v_n / u^-$")
    ax.set_ylabel(r"$\beta = -u^+/u^-$")
    ax.axhline(0.0, color="0.85", lw=0.8, zorder=0)
    ax.set_title("Chung & Ooi Test 6 (e = 0.5, mu = 0.4, backspin), DEM force in time")
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


TESTS = {1: lambda: normal_tests(chung_ooi.TEST1), 2: lambda: normal_tests(chung_ooi.TEST2),
         3: test3, 4: test4, 5: test5, 6: test6}  # fmt: skip


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks.dem_chung_ooi")
    parser.add_argument("--test", type=int, choices=sorted(TESTS), action="append")
    parser.add_argument("--figure", type=Path, help="draw Test 6's figure into this PNG file")
    args = parser.parse_args(argv)
    if args.figure is not None:
        test6_figure(args.figure)
        return 0
    for n in args.test or sorted(TESTS):
        print(f"Chung & Ooi (2011), Test {n}, with the DEM force ({STEPS} steps a contact)")
        print("\n".join(TESTS[n]()))
        print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
