"""Harmonic balance with wheels on Hertz springs, first version (issue 20).

Truths: today's constant-force solve (a wheel of 1 g follows the rail and
presses with Q); the time-domain ring with the same wheels (8 elements a
span, 120 steps per sleeper passage, within 0.05 % of a ring twice as fine);
the refusal of a cell that the wagon length does not hold a whole number of.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.profile import smooth_rail
from railtrack.model.wheel import Wheel
from railtrack.solvers.wheel_newton import solve_wheels

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)
LAW = rt.LinearFoundation(20e6, 0.2e6)
CELL = rt.SleeperCell.identical(PAPER, LAW, 1)


def test_a_massless_wheel_presses_with_its_load_and_leaves_todays_track():
    today = rt.solve(TRACK, TRAIN, LAW, 120, stability="off")
    result = solve_wheels(PAPER, CELL, Wheel(1e-3), smooth_rail, 120)
    assert result.converged
    np.testing.assert_allclose(result.contact_force, 75e3, rtol=1e-6)
    np.testing.assert_allclose(result.coefficients[0], today.coefficients, rtol=0,
                               atol=1e-8 * np.abs(today.coefficients).max())


def test_the_contact_force_at_sleeper_passing_matches_the_ring():
    result = solve_wheels(PAPER, CELL, Wheel(600.0), smooth_rail, 120)
    ring = rt.simulate_time_domain(TRACK, TRAIN, LAW, 8, 3600, wheel=Wheel(600.0), tol=1e-5,
                                   warn_step_error=None)
    assert result.converged and ring.converged
    np.testing.assert_allclose(result.contact_force.mean(axis=1), 75e3, rtol=1e-9)
    swing = ring.contact_forces.max(axis=0) - ring.contact_forces.min(axis=0)
    assert swing.min() > 500.0                      # the sleepers' passing is felt
    np.testing.assert_allclose(result.contact_force.max(axis=1), ring.contact_forces.max(axis=0),
                               atol=0.05 * swing.max())
    np.testing.assert_allclose(result.contact_force.min(axis=1), ring.contact_forces.min(axis=0),
                               atol=0.05 * swing.max())


def test_a_cell_the_wagon_does_not_hold_whole_is_refused():
    with pytest.raises(ValueError, match="whole number of cells"):
        solve_wheels(PAPER, rt.SleeperCell.identical(PAPER, LAW, 7), Wheel(600.0),
                     smooth_rail, 30)
