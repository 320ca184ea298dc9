"""Self-weight of rail and sleepers in a cell (issue 19, section 2).

Independent truths: statics (the foundations carry the weight of rail and
sleepers, and the train's), superposition for linear laws (the response with
gravity is the response without it plus the state at rest), and a hanging
sleeper that cannot reach its ballast (its pads carry its weight: seat load
-M g).
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.train import STANDARD_GRAVITY as G
from railtrack.solvers.cell_static import cell_at_rest

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)
SOUND = rt.LinearFoundation(20e6, 0.2e6)
BAY = G * (float(PAPER.sleeper_mass) + float(PAPER.rail_linear_mass) * PAPER.sleeper_spacing)


def cell(gravity, gap=None, n=10, at=5):
    sound = rt.SleeperCell.identical(PAPER, SOUND, n, gravity=gravity)
    return sound if gap is None else sound.with_sleeper(
        at, foundation=rt.GapFoundation(gap, 20e6, 0.2e6))


def test_linear_cell_with_gravity_is_the_cell_without_it_plus_its_state_at_rest():
    light = rt.solve(TRACK, TRAIN, cell(0.0), 30)
    heavy = rt.solve(TRACK, TRAIN, cell(G), 30)
    rest = heavy.at_rest()
    assert rest.converged
    np.testing.assert_allclose(rest.foundation_force, BAY, rtol=1e-9)
    shift = heavy.coefficients - light.coefficients
    m = heavy.harmonics
    np.testing.assert_allclose(shift[:, m], rest.sleeper_displacement, rtol=1e-9)
    np.testing.assert_allclose(np.delete(shift, m, axis=1), 0.0, atol=1e-15)


def test_a_hanging_sleeper_hangs_on_its_pads_and_its_neighbours_carry_it():
    rest = rt.solve(TRACK, TRAIN, cell(G, gap=1e-3), 60).at_rest()
    mass = float(PAPER.sleeper_mass)
    assert rest.sleeper_displacement[5] > -1e-3                  # it does not reach the ballast
    assert rest.foundation_force[5] == 0.0
    assert rest.rail_seat_load[5] == pytest.approx(-mass * G, rel=1e-9)   # the pads hold it up
    assert rest.foundation_force[[4, 6]].min() > BAY
    assert rest.foundation_force.sum() == pytest.approx(10 * BAY, rel=1e-9)


def test_the_foundations_carry_the_train_and_the_track():
    heavy = rt.solve(TRACK, TRAIN, cell(G, gap=0.5e-3), 60)
    t = heavy.one_period(4096)[0]
    train = np.sum(TRAIN.axle_loads) * 10 * PAPER.sleeper_spacing / TRAIN.wagon_length
    assert heavy.foundation_force(t).sum(axis=0).mean() == pytest.approx(train + 10 * BAY,
                                                                          rel=1e-6)


def test_gravity_must_not_be_negative():
    with pytest.raises(ValueError, match="gravity"):
        cell(-9.81)


def test_a_tensionless_law_rests_like_its_compression_branch():
    # At w = 0 a bilinear law's kink gave Newton the tension branch (0 N/m for a
    # tensionless ballast): a track on nothing, a singular matrix.  Every sleeper
    # presses under its weight, so the state at rest is the linear law's, whose
    # foundation force is the weight of one sleeper and one span of rail.
    for law in (rt.BilinearFoundation(20e6, 0.0, 2e5), rt.BilinearFoundation(20e6, 5e6, 2e5)):
        rest = cell_at_rest(PAPER, rt.SleeperCell.identical(PAPER, law, 3, gravity=G))
        assert rest.converged
        np.testing.assert_allclose(rest.foundation_force, BAY, rtol=1e-9)
        np.testing.assert_allclose(rest.sleeper_displacement, -BAY / 20e6, rtol=1e-9)
