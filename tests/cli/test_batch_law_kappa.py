"""spinimpact batch --tangential mindlin-deresiewicz with a row of kappa = 0: with
--on-error skip the row is written with its error and the others solved; with
--on-error stop, one line naming the row and exit status 2, the old output kept."""

import csv

from tests.cli.test_errors import _keep_sigterm  # noqa: F401 (an autouse fixture)

LAW = ["--tangential", "mindlin-deresiewicz", "--poisson-ratio", "0.23"]


def test_a_row_of_kappa_0_is_reported_in_its_row(cli, tmp_path):
    src, out = tmp_path / "k0.csv", tmp_path / "o.csv"
    src.write_text("vx,vy,omega,mu,kappa\n1,-3,0,0.1,0.9\n1,-3,0,0.1,0.0\n")
    status, stdout, err = cli("batch", src, "--output", out, *LAW, "--on-error", "skip")
    assert status == 0, err
    assert "wrote 2 rows" in stdout and "1 with errors" in stdout
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    assert rows[0]["error"] == "" and float(rows[0]["after_vy"]) > 0
    assert rows[1]["error"].startswith("row 2 (line 3), column kappa: kappa must be > 0 under")
    assert rows[1]["after_vy"] == ""
    out.write_text("kept\n")
    status, stdout, err = cli("batch", src, "--output", out, *LAW, "--on-error", "stop")
    assert status == 2 and stdout == "" and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith("spinimpact: error: row 2 (line 3), column kappa: kappa must be > 0")
    assert out.read_text() == "kept\n"
