"""A batch under a tangential law that refuses some kappa (MindlinDeresiewicz: kappa > 0):
the refused rows are bad rows like any other, named by row, line and column in the
law's words; the good rows are solved; ``on_error="stop"`` names the first."""

import numpy as np
import pytest

from spinimpact import Body, MindlinDeresiewicz, Walton, solve
from spinimpact.io.batch import BatchError, run_batch

from tests.io.test_batch import DEFAULTS, read_csv, write_csv

LAW = MindlinDeresiewicz(poisson_ratio=0.23)
RULE = "kappa must be > 0 under MindlinDeresiewicz"


def _defaults(**changes):
    return {**DEFAULTS, "tangential": LAW, **changes}


def test_a_kappa_the_law_refuses_is_a_bad_row_and_the_others_are_solved(tmp_path):
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    write_csv(src, ["vx", "vy", "omega", "mu", "kappa"],
              [[1, -3, 0, 0.1, 0.9], [1, -3, 0, 0.1, 0.0], [2, -1, 5, 0.3, ""],
               [1, -3, 0, 0.1, -0.5]])  # fmt: skip
    summary = run_batch(src, out, defaults=_defaults(), on_error="skip")
    assert (summary.rows, summary.skipped) == (4, 2)
    got = read_csv(out)
    assert got[1]["error"].startswith(f"row 2 (line 3), column kappa: {RULE} (")
    assert got[1]["error"].endswith("got 0.0") and got[1]["after_vx"] == ""
    assert got[3]["error"] == "row 4 (line 5), column kappa: kappa must be in [0, 1], got -0.5"
    body = Body.solid_sphere(mass=1.0, radius=0.1)
    for line, (vx, vy, omega, mu, kappa) in ((got[0], (1, -3, 0, 0.1, 0.9)),
                                             (got[2], (2, -1, 5, 0.3, 0.8))):  # fmt: skip
        assert line["error"] == ""
        want = solve(body, vx, vy, omega, mu=mu, kappa=kappa, tangential=LAW)
        assert float(line["after_vx"]) == float(want.after.vx)
        assert float(line["after_omega"]) == float(want.after.omega)
    with pytest.raises(BatchError, match=r"^row 2 \(line 3\), column kappa: kappa must be > 0"):
        run_batch(src, tmp_path / "stop.csv", defaults=_defaults())
    assert not (tmp_path / "stop.csv").exists()


def test_a_refused_default_kappa_says_it_is_the_default(tmp_path):
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    write_csv(src, ["vx", "vy", "omega", "kappa"], [[1, -3, 0, ""], [1, -3, 0, 0.5]])
    run_batch(src, out, defaults=_defaults(kappa=0.0), on_error="skip")
    got = read_csv(out)
    assert got[0]["error"].startswith("row 1 (line 2), column kappa: kappa (the default) must be")
    assert got[1]["error"] == "" and np.isfinite(float(got[1]["after_vx"]))
    write_csv(src, ["vx", "vy", "omega"], [[1, -3, 0]])  # no kappa column: no column named
    with pytest.raises(BatchError, match=r"^row 1 \(line 2\): kappa \(the default\) must be > 0"):
        run_batch(src, out, defaults=_defaults(kappa=0.0))


def test_parquet_rows_are_checked_alike_and_other_laws_take_kappa_0(tmp_path):
    pa = pytest.importorskip("pyarrow")
    pq = pytest.importorskip("pyarrow.parquet")
    src = tmp_path / "in.parquet"
    table = {"vx": [1.0, 1.0, 1.0], "vy": [-3.0, -3.0, -3.0], "omega": [0.0, 0.0, 0.0],
             "kappa": [0.9, 0.0, None]}  # fmt: skip
    pq.write_table(pa.table(table), src)
    run_batch(src, tmp_path / "out.csv", defaults=_defaults(), on_error="skip")
    errors = [line["error"] for line in read_csv(tmp_path / "out.csv")]
    assert errors[0] == errors[2] == "" and errors[1].startswith(f"row 2, column kappa: {RULE}")
    summary = run_batch(src, tmp_path / "w.csv", defaults=_defaults(tangential=Walton(0.3)))
    assert summary.skipped == 0  # Walton takes kappa = 0
