"""CompliantSweep (an alias of ProblemSweep): chunk by chunk, the very numbers of
solve(..., tangential=law)."""

from __future__ import annotations

import numpy as np
import pytest

from spinimpact import Body, Stronge, Walton, solve
from spinimpact.io.compliant_sweep import CompliantSweep, compliant_fields
from spinimpact.io.sweep import parse_axis, run_sweep

pytestmark = pytest.mark.filterwarnings(
    "ignore:(CompliantSweep|compliant_fields) is deprecated:DeprecationWarning"
)

BALL = Body.solid_sphere(mass=0.057, radius=0.033)


@pytest.mark.parametrize("law", [Walton(0.3), Stronge(poisson_ratio=0.3)])
def test_chunks_equal_one_solve(tmp_path, law):
    spec = dict(vx="uniform:-6:6", vy="uniform:-5:-0.5", omega="uniform:-200:200", mu="0.4",
                kappa="uniform:0:1")  # fmt: skip
    sweep = CompliantSweep(BALL, {n: parse_axis(n, v) for n, v in spec.items()}, samples=3000,
                           seed=3, chunk_size=700, tangential=law)  # fmt: skip
    out = tmp_path / "points"
    fields = ("after_vx", "after_omega", "tangential_restitution", "regime")
    result = run_sweep(sweep, output=str(out), fields=fields)
    cols = {n: np.load(out / f"{n}.npy") for n in ("vx", "vy", "omega", "kappa", *fields)}
    imp = solve(BALL, cols["vx"], cols["vy"], cols["omega"], mu=0.4, kappa=cols["kappa"],
                tangential=law)  # fmt: skip
    np.testing.assert_array_equal(cols["after_vx"], imp.after.vx)
    np.testing.assert_array_equal(cols["after_omega"], imp.after.omega)
    np.testing.assert_array_equal(cols["tangential_restitution"], imp.tangential_restitution)
    names = np.asarray(sweep.regimes)[cols["regime"]]
    np.testing.assert_array_equal(names, imp.regime)
    shares = {n: float(np.mean(imp.regime == n)) for n in sweep.regimes}
    assert result.regime_fractions == pytest.approx(shares)
    assert shares["slip-reversal"] > 0 and shares["slip"] > 0


def test_fields_and_bad_input():
    assert "tangential_restitution" in compliant_fields() and "mass" not in compliant_fields()
    axes = {n: parse_axis(n, v) for n, v in dict(vx="1", vy="-1", omega="0", mu="0.2",
                                                  kappa="0.5").items()}  # fmt: skip
    with pytest.raises(TypeError, match="tangential must be a tangential compliance law"):
        CompliantSweep(BALL, axes)
    sweep = CompliantSweep(BALL, axes, tangential=Walton(0.1))
    with pytest.raises(ValueError, match="fields must be among"):
        sweep.field_name("tau_star")
    assert sweep.description()["tangential"] == {"law": "walton", "beta0": 0.1}
