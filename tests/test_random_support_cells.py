"""`random_support` against cells built by hand from its own draws (issue 27).

Independent truth: a draw is a cell whose sleeper j stands on the law with
its stiffness times X_j, once (a `SleeperCell` built here, sleeper by
sleeper, and solved by `railtrack.solve`); its peak rail-seat load is the
largest over the sleepers and the period, and its peak moment the largest
sagging moment under ANY wheel, read here at 32 points a span.  The wagon's
two wheels carry 60 and 90 kN, so that the peak moment is under the second.
"""

import numpy as np
import pytest

import railtrack as rt

TRACK = rt.Track.paper()
TRAIN = rt.Train(18.0, (0.0, 3.0), (60e3, 90e3), 45.0)
PASSAGE = rt.Passage(TRACK, TRAIN)
STIFFNESS, DAMPING = 20e6, 0.2e6


def hand_built(factors):
    cell = rt.SleeperCell.identical(PASSAGE, rt.LinearFoundation(STIFFNESS, DAMPING),
                                    len(factors))
    for j, x in enumerate(factors):
        cell = cell.with_sleeper(j, foundation=rt.LinearFoundation(STIFFNESS * x, DAMPING))
    return cell


def peaks(solution, sleepers, points=32):
    """Largest seat load [N] over 4096 instants, largest moment [N m] under each wheel."""
    t = np.linspace(0.0, solution.period, 4096, endpoint=False)
    seat = solution.rail_seat_load(t).max()
    x = np.arange(sleepers * points) * PASSAGE.sleeper_spacing / points
    under = [solution.rail_bending_moment(np.mod((x + d) / TRAIN.speed, solution.period),
                                          x).max() for d in TRAIN.axle_positions]
    return seat, np.array(under)


@pytest.fixture(scope="module")
def sample():
    return rt.random_support(TRACK, TRAIN, rt.LinearFoundation(STIFFNESS, DAMPING),
                             sleepers=5, variation=0.3, draws=2, seed=4, harmonics=40)


def test_each_draw_is_the_cell_of_its_factors(sample):
    assert sample.converged.all()
    assert np.ptp(sample.factors) > 0.5                     # a real scatter
    for row, seat, moment in zip(sample.factors, sample.peak_seat_load, sample.peak_moment):
        solution = rt.solve(TRACK, TRAIN, hand_built(row), 40)
        assert solution.converged
        own_seat, under = peaks(solution, 5)
        assert seat == pytest.approx(own_seat, rel=1e-3)
        # the heavier second wheel bends the rail most: 30 % more than the first
        assert under[1] > 1.3 * under[0]
        assert moment == pytest.approx(under.max(), rel=2e-3)


def test_scatter_changes_the_answer_by_what_the_factors_say(sample):
    # the cell of the mean factor (1 everywhere) is not the draw: the comparison
    # above sees the factors, not only the track
    sound = rt.solve(TRACK, TRAIN, hand_built(np.ones(5)), 40)
    seat, _ = peaks(sound, 5, points=8)
    assert np.all(np.abs(sample.peak_seat_load / seat - 1) > 0.02)
