"""docs/validation.md says what the validation code computes (benchmarks/kharaz.py,
benchmarks/chung_ooi.py), and its statements hold."""

import math
from pathlib import Path

import numpy as np
import pytest
from benchmarks import chung_ooi, kharaz

from spinimpact.core.tangential import integrate_tangential, mindlin_stiffness_ratio

#: Every model over every measured bounce, and the benchmarks in time: run by `make test`.
pytestmark = pytest.mark.slow

DOC = (Path(__file__).resolve().parents[1] / "docs" / "validation.md").read_text()


@pytest.fixture(scope="module")
def rows():
    return kharaz.table()


def test_the_table_is_what_the_code_computes(rows):
    start = DOC.index("<!-- validation table")
    block = DOC[DOC.index("\n", start) + 1 : DOC.index("<!-- end of validation table")]
    assert block.strip() == kharaz.markdown_table(rows).strip()


def test_the_statements_about_the_table(rows):
    e = dict(rows)
    rigid = e["rigid"]
    # the pipeline check: the worst cases as pairs, and the rms measured here
    assert rigid["e_t"][1:] == pytest.approx((5 / 7 - 0.5964, 20.0845), abs=1e-4)
    assert rigid["spin"][1] == pytest.approx(577.0096 - 402.83, abs=0.01)
    assert round(rigid["e_t"][0], 3) == 0.054 and round(rigid["spin"][0]) == 73
    # the goal: met by micro-slip with the oxide's literature parameters, in e_t and spin
    best = "Mindlin-Deresiewicz (micro-slip), nu = 0.23"
    best_et = min(err["e_t"][0] for _, err in rows)
    assert e[best]["e_t"][0] <= 0.013 and e[best]["spin"][0] <= 33
    assert round(e[best]["e_t"][0], 4) == 0.0124 and round(e[best]["spin"][0]) == 23
    assert e[best]["e_t"][1:] == pytest.approx((0.028, 9.6304), abs=5e-4)
    assert best_et == pytest.approx(e[best]["e_t"][0], abs=2e-4)  # the history, alloy: 0.0125
    # the alloy's reference figures (0.0055, 28) are not met by the alloy's parameters
    alloy = e["Mindlin-Deresiewicz (micro-slip), alloy (nu = 0.33)"]
    assert round(alloy["e_t"][0], 3) == 0.027 and round(alloy["spin"][0]) == 23
    assert round(e["Hertz-Mindlin in time, history spring"]["e_t"][0], 3) == 0.022
    # spin: every compliance model below 33 rad/s but the three older Hertz springs (oxide)
    over = {label for label, err in rows if label != "rigid" and err["spin"][0] >= 33}
    assert over == {"Hertz-Mindlin in time, scaled spring",
                    "Hertz-Mindlin in time, incremental spring",
                    "Hertz-Mindlin in time, total spring"}  # fmt: skip
    compliant = [err for label, err in rows if label != "rigid"]
    assert all(0.45 <= round(err["rebound_angle"][0], 2) <= 0.75 for err in compliant)


def test_near_normal_incidence():
    """The figures of 'What decides it': e_t at the 2 and 4 degree points."""
    angles, values = kharaz.measured()["e_t"]
    pick = angles < 5
    assert values[pick].round(3).tolist() == [0.794, 0.745]
    got = {
        "scaled": kharaz.hertz_mindlin(angles[pick])["e_t"],
        "history": kharaz.history(angles[pick])["e_t"],
        "micro-slip": kharaz.mindlin_deresiewicz(angles[pick])["e_t"],
    }
    assert got["scaled"].round(3).tolist() == [0.881, 0.874]
    assert got["history"].round(3).tolist() == [0.799, 0.799]
    assert got["micro-slip"].round(3).tolist() == [0.778, 0.754]


def test_between_9_and_60_degrees():
    angles, values = kharaz.measured()["e_t"]
    keep = angles > 9
    worst = {}
    for label, model, material in kharaz.MODELS:
        worst[label] = np.abs(model(angles, material)["e_t"] - values)[keep].max()
    assert round(worst["Stronge, nu = 0.23"], 3) == 0.018
    assert round(worst["linear spring-dashpot + Mindlin ratio in time"], 3) == 0.012
    assert round(worst["Hertz-Mindlin in time, scaled spring"], 3) == 0.049
    assert round(worst["Hertz-Mindlin in time, scaled spring, alloy (nu = 0.33)"], 3) == 0.025
    assert round(worst["Hertz-Mindlin in time, history spring"], 3) == 0.031
    assert round(worst["Mindlin-Deresiewicz (micro-slip), nu = 0.23"], 3) == 0.028
    assert round(worst["rigid"], 3) == 0.118


def test_the_smallest_angles_and_the_spring_rules():
    angles = np.array([2.0275, 3.9282, 20.0845, 30.2218, 49.5459])
    e_t = {label: model(angles, material)["e_t"] for label, model, material in kharaz.MODELS}
    # the springs that give back the stored strain as it is (all but history, micro-slip)
    newer = ("history", "micro-slip")
    springs = [v for label, v in e_t.items()
               if label not in ("rigid", "Walton, beta0 = 0.33") and not any(
                   word in label for word in newer)]  # fmt: skip
    assert all(0.82 <= x <= 1.005 for v in springs for x in v[:2])
    assert min(x for v in springs for x in v[:2]) < 0.83  # Stronge at 4 degrees: 0.827
    assert e_t["Walton, beta0 = 0.33"][:2] == pytest.approx([0.62, 0.62], abs=5e-4)
    rules = np.array([e_t[f"Hertz-Mindlin in time, {rule} spring"][2:]
                      for rule in ("scaled", "incremental", "total", "history")])  # fmt: skip
    assert round(float((rules.max(axis=0) - rules.min(axis=0)).max()), 3) == 0.019


def test_small_angle_spring_rules_and_definitions():
    two_and_four = np.array([2.0275, 3.9282])
    inc = kharaz.incremental(two_and_four)["e_t"]
    tot = kharaz.total(two_and_four)["e_t"]
    assert round(inc.max(), 2) == 0.96 and round(tot.max(), 2) == 1.00
    # the anvil: glass constants move the stiffness ratio from 0.870 to 0.875
    assert round(float(mindlin_stiffness_ratio(0.23)), 3) == 0.870
    assert round(float(mindlin_stiffness_ratio(0.23, 0.22, 3.8e11 / 7e10)), 3) == 0.875
    # rebound angle at 60 degrees: 57.7 for the centre (rigid), 48 for the contact point
    vx, vy = kharaz.incidence(60.0)
    imp = kharaz.solve(kharaz.OXIDE.body, vx, vy, 0.0, mu=kharaz.MU, kappa=kharaz.KAPPA)
    centre = math.degrees(math.atan2(float(imp.after.vx), float(imp.after.vy)))
    u = float(imp.after.vx + kharaz.RADIUS * imp.after.omega)
    assert (
        round(centre, 1) == 57.7 and round(math.degrees(math.atan2(u, float(imp.after.vy)))) == 48
    )


def test_alpha_v_calibration_gives_kappa_at_every_angle():
    body = kharaz.OXIDE.body
    alpha_v = kharaz._hertz_alpha_speed(kharaz.OXIDE)
    for angle in (0.0, 45.0, 80.0):
        vx, vy = kharaz.incidence(angle)
        law = kharaz.HertzContact(3.8e11 / 2, 0.23, kharaz.RADIUS, alpha_v / abs(vy))
        assert law.restitution(float(body.mass), abs(vy)) == pytest.approx(0.98, abs=1e-8)


def test_chung_ooi_normal_tests_against_hertz_theory():
    for case in (*chung_ooi.TEST1, *chung_ooi.TEST2):
        run, ref = chung_ooi.normal_run(case), chung_ooi.hertz_theory(case)
        for key in ("duration", "peak_force", "max_compression"):
            assert float(getattr(run, key)) == pytest.approx(ref[key], rel=1e-8)
    assert chung_ooi.TEST1[0] == chung_ooi.NormalCase("glass", 4.8e10, 0.2, 2800, 0.01, 10, True)
    case = chung_ooi.TEST3[1]
    assert float(chung_ooi.normal_run(case, 0.4).restitution) == pytest.approx(0.4, abs=1e-6)


def test_chung_ooi_tests_5_and_6_equal_the_rigid_law_where_it_slides():
    """Test 5 uses Maw et al.'s Psi_1 = r u-/(mu vn-) of docs/validation.md (its header
    says so): the rigid law slides throughout from Psi_1 = r zeta (1 + e), 5.76 for steel."""
    header, columns, *lines = chung_ooi.test5()
    assert "Psi1 = r u-/(mu vn-)" in header and "Psi2 = r u+/(mu vn+)" in header
    assert columns.split()[1:] == ["Psi1", "Psi2(model)", "Psi2(rigid)", "spin(model)",
                                   "spin(rigid)"]  # fmt: skip
    steel, poly = chung_ooi.TEST5
    assert chung_ooi.test5_threshold(steel) == pytest.approx(7 * 2 * 0.7 / 1.7)  # 5.765
    assert round(chung_ooi.test5_threshold(steel), 2) == 5.76
    assert "(`Psi_1 >= 5.76` for steel, 5.25 for polyethylene" in " ".join(DOC.split())
    sliding = 0
    for line in lines:
        name = line[:15].strip()
        case = steel if name == "steel" else poly
        psi, recoil, ref_recoil, spin, ref_spin = (float(x) for x in line.split()[-5:])
        if psi >= chung_ooi.test5_threshold(case):
            sliding += 1
            assert recoil == pytest.approx(ref_recoil, abs=1e-4)
            assert spin == pytest.approx(ref_spin, abs=1e-4)
    assert sliding == 12  # Psi_1 = 6, 7, 8, 10, 12, 14 for both materials
    header, _, *lines = chung_ooi.test6()
    assert "u-/vn-, u+/vn+ (not normalized)" in header
    for line in lines:
        parts = line.split()
        chi, beta, ref_beta = (float(x) for x in parts[-5:-2])
        if chi < 1:
            assert beta == pytest.approx(ref_beta, abs=1e-4)
        else:
            assert beta > 0  # grip where the rigid law sticks
    case = chung_ooi.TEST6[0]
    assert (case.normal_speed, case.mu, case.kappa, case.radius) == (0.2, 0.4, 0.5, 0.1)


def test_energy_of_the_variants_as_stated():
    """The doc quotes the variants' energy on the 24 random impacts of tests/core: E rises
    by about 2e-4 of itself at most on the incremental rule, and the total rule returns up
    to 0.4 % more kinetic energy than the ball brought."""
    from spinimpact.core.contact import power_law_time_scale

    from tests.core.test_tangential import K_HERTZ, J, M, R, _cases, _final_gain

    rises, finals = [], []
    for vx, vy, omega, mu, ratio, _ in _cases():
        ts = float(power_law_time_scale(M, abs(vy), K_HERTZ, 1.5))
        kwargs = dict(stiffness=K_HERTZ, exponent=1.5, stiffness_ratio=ratio, time_scale=ts)
        inc = integrate_tangential(M, R, J, mu, vx, vy, omega, spring="incremental", **kwargs)
        tot = integrate_tangential(M, R, J, mu, vx, vy, omega, spring="total", **kwargs)
        rises.append(np.diff(inc.energy).max() / inc.energy[0])
        finals.append(_final_gain(tot))
    assert round(max(rises), 4) == 0.0002
    assert round(max(finals), 3) == 0.004


def test_kharaz_writes_figures_only_into_an_output_directory(monkeypatch, tmp_path, capsys):
    """A plain ``python -m benchmarks.validation kharaz`` prints the table and writes no
    figure (the tracked docs/images stay as they are); ``--output DIR`` writes both there."""
    from benchmarks import validation

    written = []
    monkeypatch.setattr(validation, "_available", lambda models: list(models[:1]))
    monkeypatch.setattr(validation, "kharaz_figure", lambda models, path: written.append(path))
    monkeypatch.setattr(validation, "mbf_figure", lambda path: written.append(path))
    assert validation.main(["kharaz"]) == 0
    assert written == [] and "| rigid |" in capsys.readouterr().out
    assert validation.main(["kharaz", "--output", str(tmp_path / "figs")]) == 0
    assert written == [tmp_path / "figs" / "validation_kharaz.png",
                       tmp_path / "figs" / "validation_mbf.png"]  # fmt: skip
    assert "kharaz --output $(VALIDATION)" in (Path(__file__).parents[1] / "Makefile").read_text()
