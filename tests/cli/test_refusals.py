"""Impossible or degenerate input on the command line: one line on stderr naming the option
and the value, exit status 2, no traceback."""

import pytest

from tests.cli.test_errors import assert_one_line


@pytest.mark.parametrize("args, option", [
    (("sphere", "--gyration", 0.5), "--gyration must be <= sqrt(2/3) * radius"),
    (("pair", "--gyration2", 0.5), "--gyration2 must be <= sqrt(2/3) * radius"),
])  # fmt: skip
def test_a_gyration_no_sphere_has_is_refused(cli, args, option):
    status, out, err = cli(*args)
    assert_one_line(status, out, err, option)
    assert "0.5" in err and "0.0816497" in err


def test_a_grazing_sphere_is_refused_as_solve_refuses_vy(cli):
    status, out, err = cli("sphere", "--velocity", "1,-1e-300,0")
    assert_one_line(status, out, err, "normal velocity must be <= -1e-50")
    assert "division" not in err


def test_a_map_of_a_tiny_body_is_drawn(cli, tmp_path):
    """The maps are dimensionless: a body of 1e-49 m gets the same map as any other (its
    spins R omega/|vy| = 3 used to overflow a float32 cast)."""
    target = tmp_path / "map.png"
    status, out, err = cli("map", "--radius", 1e-49, "--output", target, "--resolution", 20,
                           "--dpi", 50)  # fmt: skip
    assert status == 0, err
    assert target.stat().st_size > 0
