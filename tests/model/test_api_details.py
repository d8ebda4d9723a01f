"""Core helpers and API details not covered elsewhere: velocity ratios, error
messages for arrays, restitution models, history() arguments."""

import numpy as np
import pytest

import spinimpact.core as core
from spinimpact import Body, ConstantRestitution, TabulatedRestitution, solve

from tests.cases import random_cases


def test_velocity_ratios_match_rebound():
    """The two ratio equations after (4.17) against rebound/incidence from solve()."""
    c = random_cases(5000, seed=3)
    body = Body(mass=c["mass"], radius=c["radius"], gyration=c["gyration"])
    imp = solve(body, c["vx"], c["vy"], c["omega"], mu=c["mu"], kappa=c["kappa"])
    rvx, rom = core.velocity_ratios(
        c["vx"], c["vy"], c["omega"], c["radius"], c["zeta"], c["mu"], c["kappa"]
    )
    # rtol 1e-9: the ratio forms divide by vx- and omega-, which amplifies rounding
    # where those are small next to u-; compare on the velocity scale instead.
    scale = np.abs(c["vx"]) + np.abs(c["vy"]) + np.abs(c["radius"] * c["omega"])
    assert np.all(np.abs(rvx * c["vx"] - imp.after.vx) <= 1e-12 * scale)
    assert np.all(np.abs(rom * c["omega"] - imp.after.omega) * c["radius"] <= 1e-12 * scale)
    assert np.isnan(core.velocity_ratios(0.0, -1.0, 0.0, 0.1, 3.0, 0.2, 0.5)[0])


def test_array_errors_name_the_first_offending_index():
    with pytest.raises(ValueError, match=r"vy must be < 0.*got 0\.5.*index 2"):
        solve(Body.ring(mass=1, radius=1), 1.0, [-1.0, -2.0, 0.5, 3.0], 0.0, mu=0.1, kappa=0.5)
    with pytest.raises(ValueError, match=r"kappa must be in \[0, 1\].*index \(1, 0\)"):
        solve(Body.ring(mass=1, radius=1), 1.0, -1.0, 0.0, mu=0.1, kappa=[[0.5], [1.5]])
    with pytest.raises(ValueError, match=r"mass must be > 0.*index 1"):
        Body(mass=[1.0, -1.0], radius=1.0, gyration=1.0)


def test_shapes_that_do_not_broadcast():
    with pytest.raises(ValueError, match=r"do not broadcast.*vx \(3,\).*omega \(2,\)"):
        solve(Body.ring(mass=1, radius=1), [1.0, 2.0, 3.0], -1.0, [0.0, 1.0], mu=0.1, kappa=0.5)


def test_non_numeric_input():
    with pytest.raises(TypeError, match="vx must be a real number"):
        solve(Body.ring(mass=1, radius=1), "fast", -1.0, 0.0, mu=0.1, kappa=0.5)
    with pytest.raises(TypeError, match="body must be a spinimpact.Body"):
        solve("ring", 1.0, -1.0, 0.0, mu=0.1, kappa=0.5)
    with pytest.raises(ValueError, match="body must be one of"):
        Body.preset("cube", mass=1.0, radius=1.0)


def test_tabulated_restitution_in_solve():
    model = TabulatedRestitution(speeds=[1.0, 3.0], kappas=[0.9, 0.5])
    imp = solve(
        Body.solid_disk(mass=1, radius=0.1), 1.0, [-1.0, -2.0, -5.0], 0.0, mu=0.1, kappa=model
    )
    np.testing.assert_allclose(imp.kappa, [0.9, 0.7, 0.5], rtol=1e-15)  # clipped at the ends
    np.testing.assert_allclose(imp.newton_restitution, [0.9, 0.7, 0.5], rtol=1e-15)
    strict = TabulatedRestitution(speeds=[1.0, 3.0], kappas=[0.9, 0.5], extrapolate="error")
    with pytest.raises(ValueError, match=r"impact speed \|vy\| = 5.0 is outside"):
        solve(Body.solid_disk(mass=1, radius=0.1), 1.0, -5.0, 0.0, mu=0.1, kappa=strict)


def test_drop_test_restitution():
    model = TabulatedRestitution.from_drop_heights([2.0, 0.5], [1.28, 0.405])
    np.testing.assert_allclose(model.kappas, [0.9, 0.8], rtol=1e-14)
    np.testing.assert_allclose(model.speeds, np.sqrt(2 * 9.80665 * np.array([0.5, 2.0])))


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(speeds=[1, 1], kappas=[0.5, 0.6]), "strictly increasing"),
        (dict(speeds=[1, 2], kappas=[0.5, 1.2]), r"kappas must be in \[0, 1\]"),
        (dict(speeds=[-1, 2], kappas=[0.5, 0.6]), "speeds must be >= 0"),
        (dict(speeds=[1, 2], kappas=[0.5]), "equal non-zero length"),
        (dict(speeds=[1, 2], kappas=[0.5, 0.6], extrapolate="linear"), "extrapolate"),
    ],
)
def test_bad_restitution_tables(kwargs, message):
    with pytest.raises(ValueError, match=message):
        TabulatedRestitution(**kwargs)


def test_callable_kappa_out_of_range_is_named():
    with pytest.raises(ValueError, match=r"kappa \(from .*\) must be in \[0, 1\]"):
        solve(Body.ring(mass=1, radius=1), 1.0, -1.0, 0.0, mu=0.1, kappa=lambda v: 2 * v)
    assert float(ConstantRestitution(0.3)(np.array(7.0))) == 0.3
    with pytest.raises(ValueError, match="kappa must be in"):
        ConstantRestitution(-0.1)


def test_history_arguments():
    imp = solve(Body.solid_disk(mass=1, radius=0.1), [1.0, 2.0], -1.0, 0.0, mu=0.1, kappa=0.5)
    with pytest.raises(ValueError, match=r"shape \(2,\).*impact\[i\]"):
        imp.history()
    one = imp[1]
    h = one.history(n=11)
    assert h.tau[0] == 0 and h.tau[-1] == one.tau1
    assert np.all(np.diff(h.tau) > 0)
    assert one.tau0 in h.tau  # the kink at the end of compression is on the grid
    with pytest.raises(ValueError, match="n must be an integer >= 2"):
        one.history(n=1)
    with pytest.raises(ValueError, match=r"tau must be in \[0, tau1"):
        one.history(tau=[0.0, 2 * float(one.tau1)])


@pytest.mark.parametrize(("n", "error"), [("5", TypeError), (2.5, TypeError), (True, TypeError),
                                          (1, ValueError), (-3, ValueError)])  # fmt: skip
def test_history_n_is_a_whole_number(n, error):
    imp = solve(Body.ring(mass=1, radius=1), 1.0, -1.0, 0.0, mu=0.1, kappa=0.5)
    with pytest.raises(error, match=r"^n must be an integer"):
        imp.history(n)


def test_preset_name_of_the_wrong_type():
    with pytest.raises(TypeError, match="body must be one of"):
        Body.preset(["ring"], mass=1.0, radius=1.0)
