"""The benchmark tests of Chung & Ooi (2011, Granular Matter 13:643-656) as runnable cases.

Each case prints the benchmark's quantities beside the analytical reference (Hertz
theory; the rigid-body law where the contact slides throughout) or the measured one
(Test 4: Kharaz et al. 2001). The definitions (materials, speeds, radii) are those of
the tests as the DEM codes script them (YADE's Test1-4 scripts, Kratos's Chung_Ooi
benchmark class; docs/validation.md lists them with their sources). The normal-impact
tests integrate :meth:`spinimpact.dynamics.ContactLaw.normal_impact`; Tests 4-6
:func:`spinimpact.dynamics.simulate` with ``tangential=Mindlin()``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from spinimpact import Body
from spinimpact.core.compliance import maw_angles
from spinimpact.core.tangential import mindlin_stiffness_ratio
from spinimpact.dynamics import HertzContact, HuntCrossleyContact, Mindlin, simulate

from . import kharaz


@dataclass(frozen=True)
class NormalCase:
    """A normal impact: two identical spheres (``pair``) or a sphere on a rigid plane."""

    name: str
    youngs_modulus: float  #: Pa
    poisson_ratio: float
    density: float  #: kg/m^3
    radius: float  #: m
    speed: float  #: m/s, approach speed of the sphere (each sphere's, for a pair)
    pair: bool

    def reduced(self) -> tuple[float, float, float, float]:
        """(m*, R*, E*, relative speed) of the equivalent sphere on a rigid plane."""
        m = 4.0 / 3.0 * math.pi * self.radius**3 * self.density
        e_star = self.youngs_modulus / (1.0 - self.poisson_ratio**2)
        if self.pair:  # two bodies: reduced mass and radius, both compliances add
            return m / 2.0, self.radius / 2.0, e_star / 2.0, 2.0 * self.speed
        return m, self.radius, e_star, self.speed


#: Test 1 (two identical spheres, 10 m/s each) and Test 2 (a sphere on a rigid plane at
#: 0.2 m/s), as YADE's Test1.py / Test2.py define them (Test 2's aluminium alloy there has
#: nu = 0.30).
TEST1 = (NormalCase("glass", 4.8e10, 0.20, 2800.0, 0.010, 10.0, True),
         NormalCase("limestone", 2.0e10, 0.25, 2500.0, 0.010, 10.0, True))  # fmt: skip
TEST2 = (NormalCase("aluminium alloy", 7.0e10, 0.30, 2699.0, 0.10, 0.2, False),
         NormalCase("magnesium alloy", 4.0e10, 0.35, 1800.0, 0.10, 0.2, False))  # fmt: skip
#: Test 3: a 2.5 mm sphere on a rigid plane at 3.9 m/s with restitution 0.2 ... 1.0.
TEST3 = (NormalCase("aluminium oxide", 3.8e11, 0.23, 4000.0, 0.0025, 3.9, False),
         NormalCase("cast iron", 1.0e11, 0.25, 7000.0, 0.0025, 3.9, False))  # fmt: skip
TEST3_RESTITUTION = (0.2, 0.4, 0.6, 0.8, 1.0)


def hertz_theory(case: NormalCase) -> dict[str, float]:
    """Hertz's elastic impact in closed form (Johnson 1985, sec. 11.4): largest
    compression ``(15 m v^2/(16 E* sqrt R))^(2/5)``, peak force ``4/3 E* sqrt(R) d^(3/2)``,
    duration ``2.8685 d/v`` (the factor ``(4/5) B(2/5, 1/2)`` by quadrature here)."""
    from scipy.integrate import quad

    m, r, e, v = case.reduced()
    d = (15.0 * m * v**2 / (16.0 * e * math.sqrt(r))) ** 0.4
    factor = 2.0 * quad(lambda x: 1.0 / math.sqrt(1.0 - x**2.5), 0.0, 1.0, limit=200)[0]
    return {"duration": factor * d / v, "peak_force": 4.0 / 3.0 * e * math.sqrt(r) * d**1.5,
            "max_compression": d}  # fmt: skip


def normal_run(case: NormalCase, kappa: float = 1.0):
    """The integrated normal impact of the case (Hertz with Hunt-Crossley damping
    calibrated to ``kappa``)."""
    m, r, e, v = case.reduced()
    k = 4.0 / 3.0 * e * math.sqrt(r)
    if kappa == 1.0:
        return HuntCrossleyContact(k, 1.5).normal_impact(m, v)
    law = HuntCrossleyContact.calibrated(stiffness=k, kappa=kappa, mass=m, speed=v)
    return law.normal_impact(m, v)


def test1(cases=TEST1) -> list[str]:
    """Tests 1 and 2: contact duration, peak force, largest compression vs Hertz."""
    lines = [f"{'material':18s} {'quantity':16s} {'integrated':>14s} {'Hertz theory':>14s}"
             f" {'rel. diff':>10s}"]  # fmt: skip
    for case in cases:
        run, ref = normal_run(case), hertz_theory(case)
        for key, value in (("duration", run.duration), ("peak_force", run.peak_force),
                           ("max_compression", run.max_compression)):  # fmt: skip
            lines.append(f"{case.name:18s} {key:16s} {float(value):14.6e} {ref[key]:14.6e} "
                         f"{float(value) / ref[key] - 1:10.1e}")  # fmt: skip
    return lines


def test3() -> list[str]:
    """Test 3: the restitution each damped law gives against its target."""
    lines = [f"{'material':18s} {'target e':>9s} {'integrated e':>13s}"]
    for case in TEST3:
        for kappa in TEST3_RESTITUTION:
            run = normal_run(case, kappa)
            lines.append(f"{case.name:18s} {kappa:9.2f} {float(run.restitution):13.6f}")
    return lines


def test4() -> list[str]:
    """Test 4: Kharaz et al. (2001); the Hertz models beside the measurement: micro-slip
    (MindlinDeresiewicz), and Hertz-Mindlin in time with the scaled spring, each with the
    oxide's and the alloy's Poisson ratio."""
    data = kharaz.measured()
    lines = []
    for key, (angles, values) in data.items():
        columns = [kharaz.mindlin_deresiewicz(angles, kharaz.OXIDE)[key],
                   kharaz.mindlin_deresiewicz(angles, kharaz.ALLOY)[key],
                   kharaz.hertz_mindlin(angles, kharaz.OXIDE)[key],
                   kharaz.hertz_mindlin(angles, kharaz.ALLOY)[key]]  # fmt: skip
        lines.append(f"{key}: angle, measured, micro-slip (oxide), (alloy), "
                     "Hertz-Mindlin scaled spring (oxide), (alloy)")  # fmt: skip
        lines += ["  " + " ".join([f"{a:6.2f}", f"{m:9.4f}"] + [f"{c[i]:9.4f}" for c in columns])
                  for i, (a, m) in enumerate(zip(angles, values, strict=True))]  # fmt: skip
    return lines


@dataclass(frozen=True)
class ObliqueCase:
    """A sphere on a rigid plane at a constant normal speed (Tests 5 and 6)."""

    name: str
    youngs_modulus: float
    poisson_ratio: float
    density: float
    radius: float
    normal_speed: float
    mu: float
    kappa: float

    def body(self) -> Body:
        m = 4.0 / 3.0 * math.pi * self.radius**3 * self.density
        return Body.solid_sphere(mass=m, radius=self.radius)

    def run(self, vx: float, omega: float):
        law = HertzContact(self.youngs_modulus, self.poisson_ratio, self.radius)
        if self.kappa < 1.0:
            law = HertzContact.calibrated(
                youngs_modulus=self.youngs_modulus, poisson_ratio=self.poisson_ratio,
                radius=self.radius, kappa=self.kappa, mass=float(self.body().mass),
                speed=self.normal_speed,
            )  # fmt: skip
        return simulate(self.body(), vx, -self.normal_speed, omega, mu=self.mu, contact=law,
                        tangential=Mindlin())  # fmt: skip


#: Test 5 (Kratos's benchmark 5 and the PySPH script: vn = 5 m/s, R = 10 um, mu = 0.3, e = 1).
TEST5 = (ObliqueCase("steel", 2.08e11, 0.30, 7850.0, 1e-5, 5.0, 0.3, 1.0),
         ObliqueCase("polyethylene", 1.0e9, 0.40, 1400.0, 1e-5, 5.0, 0.3, 1.0))  # fmt: skip
#: Test 5's normalized incidence angles ``Psi_1 = r u-/(mu vn-)`` (Maw et al.'s, as in
#: docs/validation.md: ``r = 2(1-nu)/(2-nu)``).
TEST5_PSI = (0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 14.0)
#: Test 6 (Kratos's benchmark 6: vn = 0.2 m/s, R = 0.1 m, mu = 0.4, e = 0.5, pure backspin);
#: the aluminium alloy of Test 4 (nylon is left out: its constants could not be confirmed).
TEST6 = (ObliqueCase("aluminium alloy", 7.0e10, 0.33, 2700.0, 0.1, 0.2, 0.4, 0.5),)
TEST6_TAN = (0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0)


def test5_threshold(case: ObliqueCase, zeta: float = 3.5) -> float:
    """``Psi_1`` from which the rigid law slides throughout: ``r zeta (1 + e)`` (5.76 for
    steel, 5.25 for polyethylene, a solid sphere with e = 1)."""
    return float(mindlin_stiffness_ratio(case.poisson_ratio)) * zeta * (1 + case.kappa)


def test5() -> list[str]:
    """Test 5: Maw et al.'s normalized recoil angle ``Psi_2 = r u+/(mu vn+)`` and the
    normalized spin ``R omega+/(mu vn-)`` against the normalized incidence angle
    ``Psi_1 = r u-/(mu vn-)``, ``r = 2(1-nu)/(2-nu)`` (the definition of
    docs/validation.md and :func:`spinimpact.core.compliance.maw_angles`); reference: the
    rigid law, exact where the contact slides throughout (``Psi_1 >= r zeta (1 + e)``,
    :func:`test5_threshold`)."""
    lines = ["Psi1 = r u-/(mu vn-), Psi2 = r u+/(mu vn+), r = 2(1-nu)/(2-nu); "
             "spin = R w+/(mu vn-); model: Hertz-Mindlin in time, scaled spring",
             f"{'material':15s} {'Psi1':>5s} {'Psi2(model)':>12s} {'Psi2(rigid)':>12s} "
             f"{'spin(model)':>12s} {'spin(rigid)':>12s}"]  # fmt: skip
    zeta = 3.5
    for case in TEST5:
        r = float(mindlin_stiffness_ratio(case.poisson_ratio))
        for psi in TEST5_PSI:
            vn, e, mu = case.normal_speed, case.kappa, case.mu
            u0 = psi * mu * vn / r
            sim = case.run(u0, 0.0)
            u1 = float(sim.after.vx + case.radius * sim.after.omega)
            recoil = float(maw_angles(u0, -vn, u1, float(sim.after.vy), mu,
                                      case.poisson_ratio).recoil)  # fmt: skip
            spin = case.radius * float(sim.after.omega) / (mu * vn)
            if psi >= test5_threshold(case, zeta):  # u+ = u- - zeta mu (1 + e) vn, vn+ = e vn
                ref_recoil, ref_spin = (psi - r * zeta * (1 + e)) / e, -(zeta - 1) * (1 + e)
            else:  # sticks: u+ = 0, R omega+ = -(zeta - 1) u-/zeta
                ref_recoil, ref_spin = 0.0, -(zeta - 1) / zeta * psi / r
            lines.append(f"{case.name:15s} {psi:5.1f} {recoil:12.4f} {ref_recoil:12.4f} "
                         f"{spin:12.4f} {ref_spin:12.4f}")  # fmt: skip
    return lines


def test6() -> list[str]:
    """Test 6: pure backspin (``vx- = 0``); ``beta = -u+/u-`` against
    ``chi = zeta mu (1 + e) vn-/u-`` and the recoil tangent ``u+/vn+`` against the
    incidence tangent ``u-/vn-`` (the contact point's, not normalized by ``mu`` or ``r``);
    reference: the rigid law (``beta = chi - 1`` while sliding)."""
    lines = [
        "tangents u-/vn-, u+/vn+ (not normalized); chi = zeta mu (1+e) vn-/u-; beta = -u+/u-; "
        "model: Hertz-Mindlin in time, scaled spring",
        f"{'material':16s} {'u-/vn-':>7s} {'chi':>6s} {'beta(model)':>12s} {'beta(rigid)':>11s} "
        f"{'u+/vn+(model)':>14s} {'u+/vn+(rigid)':>14s}",
    ]
    for case in TEST6:
        for tan_in in TEST6_TAN:
            u0 = tan_in * case.normal_speed
            sim = case.run(0.0, u0 / case.radius)
            u1 = float(sim.after.vx + case.radius * sim.after.omega)
            chi = 3.5 * case.mu * (1 + case.kappa) * case.normal_speed / u0
            ref_beta = min(chi - 1.0, 0.0)
            ref_out = -ref_beta * u0 / (case.kappa * case.normal_speed)
            tan_out = u1 / float(sim.after.vy)
            lines.append(f"{case.name:16s} {tan_in:7.2f} {chi:6.3f} {-u1 / u0:12.4f} "
                         f"{ref_beta:11.4f} {tan_out:14.4f} {ref_out + 0.0:14.4f}")  # fmt: skip
    return lines


TESTS = {1: lambda: test1(TEST1), 2: lambda: test1(TEST2), 3: test3, 4: test4, 5: test5,
         6: test6}  # fmt: skip
