"""One hanging sleeper: how many sleepers a cell needs to stand for an isolated defect (issue 19).

Independent truths: the sound track (today's N = 1 solve) far from the
defect, and the cell of twice or five times the size (the neighbours' loads
must not move once the defects are far apart).
"""

import numpy as np
import pytest

import railtrack as rt

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)
SOUND = rt.LinearFoundation(20e6, 0.2e6)


def peak_seat_loads(n, gap=1e-3):
    """Largest rail-seat load [N] of the hanging sleeper and two neighbours on each side."""
    at = n // 2
    cell = rt.SleeperCell.identical(PAPER, SOUND, n).with_sleeper(
        at, foundation=rt.GapFoundation(gap, 20e6, 0.2e6))
    result = rt.solve(TRACK, TRAIN, cell, 120)
    loads = result.rail_seat_load(result.one_period(2000)[0]).max(axis=1)
    return loads[at - 2:at + 3], loads[0]


@pytest.fixture(scope="module")
def sound_peak():
    today = rt.solve(TRACK, TRAIN, SOUND, 120, stability="off")
    return today.rail_seat_load(today.one_period(2000)[0]).max()


def test_neighbour_loads_no_longer_move_from_one_defect_in_20_to_one_in_100(sound_peak):
    near20, far20 = peak_seat_loads(20)
    near100, far100 = peak_seat_loads(100)
    np.testing.assert_allclose(near20, near100, rtol=2e-4)
    # ten sleepers from the defect the track is sound again
    assert far20 == pytest.approx(sound_peak, rel=1e-3)
    assert far100 == pytest.approx(sound_peak, rel=1e-4)
    # the neighbours carry what the hanging sleeper does not
    assert near20[1] > 1.15 * sound_peak and near20[3] > 1.15 * sound_peak
    assert near20[2] < 0.6 * sound_peak


def test_one_defect_in_ten_is_not_yet_isolated(sound_peak):
    near10, far10 = peak_seat_loads(10)
    assert abs(far10 / sound_peak - 1.0) > 5e-3
