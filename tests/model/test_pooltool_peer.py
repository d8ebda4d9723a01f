"""pooltool's sphere laws beside solve_sphere and solve_pair (docs/sphere3d.md, "Peer check").

The peer's equations are written out in ``benchmarks/pooltool_compare.py``; these tests pin
where they agree with ours to rounding and the two rules by which they differ. Where pooltool
itself is installed, the last test checks the transcriptions against its own functions.
"""

import numpy as np
import pytest
from benchmarks import pooltool_compare as peer

# Both sides evaluate the same closed forms in a different order: a few roundings of the
# speed scale (the largest measured over 100,000 cases is about 1e-15).
ROUNDING = 1e-13


def _norm(a):
    return np.sqrt(np.sum(a * a, axis=-1))


def test_sphere_half_space_law_is_solve_sphere_for_solid_spheres():
    c = peer.sphere_plane_cases(4000, np.random.default_rng(61))
    v, w, imp = peer.ours_sphere_plane(c)
    pv, pw = peer.peer_sphere_plane(c["v"], c["w"], c["normal"], c["radius"], c["mu"], c["e"])
    scale = _norm(c["v"]) + c["radius"] * _norm(c["w"])
    assert np.max(_norm(pv - v) / scale) < ROUNDING
    assert np.max(c["radius"] * _norm(pw - w) / scale) < ROUNDING
    assert 0.2 < np.mean(imp.grips) < 0.8  # both regimes are exercised


def test_han_2005_is_the_sphere_on_the_noses_plane_less_the_vertical_velocity():
    c = peer.cushion_cases(4000, np.random.default_rng(62))
    v, w, imp = peer.ours_cushion(c)
    pv, pw, sticks = peer.peer_han2005(
        c["v"], c["w"], peer.BALL_RADIUS, peer.BALL_MASS, c["height"], c["mu"], c["e"]
    )
    scale = _norm(c["v"]) + peer.BALL_RADIUS * _norm(c["w"])
    assert np.array_equal(sticks, imp.grips)
    assert np.max(_norm((pv - v)[:, :2]) / scale) < ROUNDING
    assert np.max(peer.BALL_RADIUS * _norm(pw - w) / scale) < ROUNDING
    # the one difference: pooltool leaves the vertical velocity at 0, the free sphere does not
    assert np.all(pv[:, 2] == 0)
    assert np.median(np.abs(v[:, 2]) / scale) > 0.01


def test_frictional_inelastic_with_coulombs_impulse_is_solve_pair():
    c = peer.ball_ball_cases(4000, np.random.default_rng(63))
    imp = peer.ours_ball_ball(c)
    p1, q1, p2, q2 = peer.peer_cases_ball_ball(c, published=False)
    scale = _norm(c["v1"]) + _norm(c["v2"]) + peer.BALL_RADIUS * (_norm(c["w1"]) + _norm(c["w2"]))
    pairs = [
        (p1, imp.after1.velocity, 1.0),
        (p2, imp.after2.velocity, 1.0),
        (q1, imp.after1.spin, peer.BALL_RADIUS),
        (q2, imp.after2.spin, peer.BALL_RADIUS),
    ]
    for mine, ours, size in pairs:
        assert np.max(size * _norm(mine - ours) / scale) < ROUNDING


def test_frictional_inelastic_as_published_takes_2e_over_1_plus_e_of_coulombs_friction():
    c = peer.ball_ball_cases(4000, np.random.default_rng(64))
    imp = peer.ours_ball_ball(c)
    p1, _, p2, _ = peer.peer_cases_ball_ball(c, published=True)
    assert np.all(p1[:, 1] == 0) and np.all(p2[:, 1] == 0)  # vertical velocities set to 0
    # the friction impulse per unit mass: ball 2's velocity change along the table, less the normal
    n = c["normal"]
    dv2 = peer._flat(p2 - c["v2"])
    theirs = _norm(dv2 - np.sum(dv2 * n, -1)[:, None] * n)
    ours = _norm(imp.friction_impulse.array) / peer.BALL_MASS
    slip_t = _norm(imp.slip_before.array)
    vrel_n = np.abs(np.sum((c["v1"] - c["v2"]) * n, -1))
    both_slide = (slip_t / 7 > c["mu"] * c["e"] * vrel_n) & ~imp.grips
    assert both_slide.mean() > 0.8
    # pooltool keeps the friction's part in the table: the slip's horizontal share of it
    horizontal = np.sqrt(imp.slip_before.x**2 + imp.slip_before.z**2) / slip_t
    assert np.any(horizontal[both_slide] < 0.9)  # the slip often has a vertical part
    ratio = theirs[both_slide] / (ours * horizontal)[both_slide]
    expected = (2 * c["e"] / (1 + c["e"]))[both_slide]
    # a quotient of closed forms (measured to 2.4e-14 over 100,000 cases)
    np.testing.assert_allclose(ratio, expected, rtol=1e-10)
    assert np.all(expected < 1)  # below e = 1 it is always less friction


def test_frictional_inelastic_as_published_is_solve_pair_in_the_table_when_e_is_1():
    c = peer.ball_ball_cases(4000, np.random.default_rng(65))
    c["e"] = np.ones_like(c["e"])
    imp = peer.ours_ball_ball(c)
    p1, q1, p2, q2 = peer.peer_cases_ball_ball(c, published=True)
    scale = _norm(c["v1"]) + _norm(c["v2"]) + peer.BALL_RADIUS * (_norm(c["w1"]) + _norm(c["w2"]))
    assert np.max(_norm(peer._flat(p1 - imp.after1.velocity)) / scale) < ROUNDING
    assert np.max(_norm(peer._flat(p2 - imp.after2.velocity)) / scale) < ROUNDING
    assert np.max(peer.BALL_RADIUS * _norm(q1 - imp.after1.spin) / scale) < ROUNDING
    assert np.max(peer.BALL_RADIUS * _norm(q2 - imp.after2.spin) / scale) < ROUNDING


def test_the_transcriptions_are_pooltools_own_functions():
    pytest.importorskip("pooltool", exc_type=ImportError)
    rng = np.random.default_rng(66)
    c = peer.sphere_plane_cases(200, rng)
    pv, pw = peer.pooltool_sphere_plane(c)
    tv, tw = peer.peer_sphere_plane(c["v"], c["w"], c["normal"], c["radius"], c["mu"], c["e"])
    scale = _norm(c["v"]) + c["radius"] * _norm(c["w"])
    assert np.max(np.maximum(_norm(pv - tv), c["radius"] * _norm(pw - tw)) / scale) < ROUNDING
    c = peer.cushion_cases(200, rng)
    pv, pw = peer.pooltool_han2005(c)
    tv, tw, _ = peer.peer_han2005(
        c["v"], c["w"], peer.BALL_RADIUS, peer.BALL_MASS, c["height"], c["mu"], c["e"]
    )
    scale = _norm(c["v"]) + peer.BALL_RADIUS * _norm(c["w"])
    assert np.max(np.maximum(_norm(pv - tv), peer.BALL_RADIUS * _norm(pw - tw)) / scale) < ROUNDING
    c = peer.ball_ball_cases(200, rng)
    scale = _norm(c["v1"]) + _norm(c["v2"]) + peer.BALL_RADIUS * (_norm(c["w1"]) + _norm(c["w2"]))
    for k, (a, b) in enumerate(
        zip(peer.pooltool_ball_ball(c), peer.peer_cases_ball_ball(c, True), strict=True)
    ):
        size = 1.0 if k % 2 == 0 else peer.BALL_RADIUS
        assert np.max(size * _norm(a - b) / scale) < ROUNDING
