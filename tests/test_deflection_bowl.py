"""The track along x at an instant, and the rail under the wheels, against independent truths."""

import numpy as np
import pytest

from railtrack import LinearFoundation, Track, Train, simulate_time_domain, solve

TRACK = Track.paper()
TRAIN = Train.paper()
LINEAR = LinearFoundation.paper()
SOLUTION = solve(TRACK, TRAIN, LINEAR, 200, method="analytic")


def test_bowl_sleepers_match_the_time_domain_ring():
    # the finite-element ring integrates every sleeper: the delay kL/v and its
    # sign come out of the physics there, not out of the formula tested here
    ring = simulate_time_domain(TRACK, TRAIN, LINEAR, 4, 600)
    step = 137
    bowl = SOLUTION.deflection_bowl(ring.times[step], TRACK.sleeper_spacing * np.arange(30))
    peak = np.max(np.abs(ring.sleeper_displacements))
    np.testing.assert_allclose(bowl.sleepers, ring.sleeper_displacements[step], rtol=0,
                               atol=2e-3 * peak)
    # the opposite delay would be far off
    wrong = SOLUTION.sleeper_displacement(ring.times[step] + np.arange(30) * TRACK.sleeper_spacing
                                          / TRAIN.speed)
    assert np.max(np.abs(wrong - ring.sleeper_displacements[step])) > 0.1 * peak


def test_rail_above_each_sleeper_repeats_eq6_later():
    t = 0.0123
    positions = TRACK.sleeper_spacing * np.arange(-5, 6)
    bowl = SOLUTION.deflection_bowl(t, positions)
    above = SOLUTION.rail_displacement(t - positions / TRAIN.speed)      # eq. (6) at x = 0
    np.testing.assert_allclose(bowl.rail, above, rtol=0, atol=1e-12 * np.max(np.abs(above)))


def test_many_instants_equal_single_instants_and_wheels_are_in_the_window():
    x = np.linspace(-9.0, 9.0, 181)
    times = np.array([0.0, 0.05, 0.2])
    many = SOLUTION.deflection_bowl(times, x)
    for i, t in enumerate(times):
        one = SOLUTION.deflection_bowl(t, x)
        np.testing.assert_allclose(many.rail[i], one.rail, rtol=0, atol=1e-15)
        assert np.all((one.wheel_positions >= -9.0) & (one.wheel_positions <= 9.0))
    assert SOLUTION.deflection_bowl(0.0, x).wheel_positions.tolist() == [-3.0, 0.0]


def test_rail_under_a_wheel_repeats_every_sleeper_passing():
    # a wheel meets the same supports every L: its contact point is L/v-periodic
    t = np.linspace(0.0, TRAIN.period, 97)
    under = SOLUTION.rail_under_wheels(t)
    later = SOLUTION.rail_under_wheels(t + TRACK.sleeper_spacing / TRAIN.speed)
    np.testing.assert_allclose(later, under, rtol=0, atol=1e-12 * np.max(np.abs(under)))
    assert under[0, 0] == pytest.approx(SOLUTION.rail_displacement(0.0), rel=1e-12)
    # the deepest contact point is under a wheel, deeper than any sleeper
    assert under.min() < SOLUTION.one_period(4000)[1].min()
