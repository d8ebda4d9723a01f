"""Events inside the integrator's steps (core.events): dips that solve_ivp misses,
crossings as solve_ivp finds them, the state at a terminal event integrated, not
interpolated."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from spinimpact.core.events import Event, integrate_events


def test_a_dip_inside_one_step_is_found_where_solve_ivp_misses_it():
    """g = (t - c)^2 - w^2 is below zero on (c - w, c + w) only; with y' = 0 the
    integrator takes long steps, and solve_ivp compares signs at their ends alone."""
    for c, w in ((0.3, 1e-2), (0.61, 1e-4), (0.8, 3e-3)):

        def g(t, y, c=c, w=w):
            return (t - c) ** 2 - w**2

        g.terminal, g.direction = True, -1
        ivp = solve_ivp(lambda t, y: [0.0], (0.0, 1.0), [1.0], method="DOP853", events=g)
        assert ivp.t_events[0].size == 0  # the miss this module exists for
        run = integrate_events(lambda t, y: [0.0], 0.0, np.array([1.0]), 1.0, [Event(g, -1)],
                               rtol=1e-10, atol=1e-12, max_step=0.25)  # fmt: skip
        assert run.status == 1
        assert run.t == pytest.approx(c - w, abs=1e-13)


def test_a_dip_that_stays_above_zero_is_no_event():
    def g(t, y):
        return (t - 0.3) ** 2 + 1e-6

    run = integrate_events(lambda t, y: [0.0], 0.0, np.array([1.0]), 1.0, [Event(g, -1)],
                           rtol=1e-10, atol=1e-12, max_step=0.25)  # fmt: skip
    assert run.status == 0 and run.t == 1.0 and run.t_events[0].size == 0


def test_crossings_and_directions_agree_with_solve_ivp():
    """A harmonic oscillator: its rising and falling zeros, non-terminal, then a terminal
    one; the same roots as solve_ivp's to the polishing tolerance."""

    def fun(t, y):
        return [y[1], -4.0 * y[0]]

    def rising(t, y):
        return y[0]

    def stop(t, y):
        return 2.9 - t

    run = integrate_events(fun, 0.0, np.array([1.0, 0.0]), 10.0,
                           [Event(rising, 1, False), Event(lambda t, y: y[0], -1, False),
                            Event(stop, -1)], rtol=1e-12, atol=1e-14, max_step=0.1)  # fmt: skip
    rising.direction = 1
    falling = lambda t, y: y[0]  # noqa: E731
    falling.direction = -1
    ivp = solve_ivp(fun, (0.0, 2.9), [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=[rising, falling])  # fmt: skip
    assert run.t == pytest.approx(2.9, abs=1e-14)
    for mine, theirs in zip(run.t_events[:2], ivp.t_events, strict=True):
        assert mine.size == theirs.size > 0
        np.testing.assert_allclose(mine, theirs, atol=1e-12)
    quarter = math.pi / 4.0  # zeros of cos(2t): falling at pi/4, rising at 3 pi/4, ...
    np.testing.assert_allclose(run.t_events[1][:1], [quarter], atol=1e-12)
    np.testing.assert_allclose(run.y[0], math.cos(2 * 2.9), atol=1e-10)
    assert run.sol(1.0)[0] == pytest.approx(math.cos(2.0), abs=1e-10)


def test_the_state_at_a_terminal_event_is_integrated_up_to_it():
    """A spring that only pushes (y'' = -max(y, 0)) from y = 0, y' = 1: it leaves at
    t = pi with y' = -1. The force ends at the event, so the step holding it is integrated
    anew up to the event (the interpolant of a step across such a change can be off by
    more than the tolerance: tests/model/test_mindlin_stronge.py has a case); the dense
    solution ends where the state does."""

    def fun(t, y):
        return [y[1], -max(y[0], 0.0)]

    def sep(t, y):
        return y[0]

    run = integrate_events(fun, 0.0, np.array([0.0, 1.0]), 10.0,
                           [Event(lambda t, y: y[1], -1, False), Event(sep, -1, integrate_to=True)],
                           rtol=1e-12, atol=1e-14, max_step=1.0)  # fmt: skip
    assert run.status == 1
    assert run.t == pytest.approx(math.pi, abs=1e-11)
    assert run.y[1] == pytest.approx(-1.0, abs=1e-11)
    assert run.t_events[0] == pytest.approx([math.pi / 2], abs=1e-12)
    np.testing.assert_allclose(run.sol(run.t), run.y, rtol=0, atol=1e-15)


def test_an_event_needs_a_direction():
    with pytest.raises(ValueError, match="direction"):
        integrate_events(lambda t, y: [0.0], 0.0, np.array([1.0]), 1.0,
                         [Event(lambda t, y: y[0], 0)], rtol=1e-8, atol=1e-10)  # fmt: skip
