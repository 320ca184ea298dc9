"""What a cell's solution gives an engineer, and harmonics="auto" for a cell (issue 19).

Independent truths:
* a cell of identical sleepers is today's track: its rail field, moment and
  seat loads equal `railtrack.Solution`'s (eq. 6, `rail_field`, the kinks);
* the rail field at a sleeper is the rail above it from the pad's equation;
* curvature against second differences of the displacement along x;
* the truncation estimate against the solution at twice the harmonics;
* statics: the foundations carry the train's weight.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.passage import Passage
from railtrack.solvers.cell_auto import cell_truncation_errors

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = Passage(TRACK, TRAIN)
SOUND = rt.LinearFoundation(20e6, 0.2e6)


def hanging(gap, n=30, at=15):
    return rt.SleeperCell.identical(PAPER, SOUND, n).with_sleeper(
        at, foundation=rt.GapFoundation(gap, 20e6, 0.2e6))


@pytest.fixture(scope="module")
def identical():
    law = rt.CubicFoundation.paper()
    today = rt.solve(TRACK, TRAIN, law, 20, stability="off", tol=1e-12)
    cell = rt.solve(TRACK, TRAIN, rt.SleeperCell.identical(PAPER, law, 3), 20, tol=1e-12)
    return today, cell


def test_identical_cell_gives_todays_rail_field_and_moment(identical):
    today, cell = identical
    t = np.linspace(0.0, today.period, 97)[:, None]
    x = np.array([0.0, 0.13, 0.3, 0.6, 0.95, 1.5, 1.79, 4.2, -0.7])[None, :]
    w = today.rail_displacement(t, x)
    np.testing.assert_allclose(cell.rail_displacement(t, x), w, atol=1e-8 * np.abs(w).max())
    moment = today.rail_bending_moment(t, x)
    np.testing.assert_allclose(cell.rail_bending_moment(t, x), moment,
                               atol=1e-7 * np.abs(moment).max())
    delay = np.arange(3)[:, None] * PAPER.sleeper_spacing / PAPER.speed
    tt = t[:, 0][None, :] - delay
    np.testing.assert_allclose(cell.rail_seat_load(t[:, 0]), today.rail_seat_load(tt),
                               atol=1e-9 * np.abs(today.rail_seat_load(tt)).max())
    np.testing.assert_allclose(cell.foundation_force(t[:, 0]), today.foundation_force(tt),
                               atol=1e-9 * np.abs(today.foundation_force(tt)).max())


VOID_ACCURACY = 5e-3
"""The seat load of a hanging sleeper converges slowly (its kinks where the sleeper lands):
at 1e-3 it needs m > 400, more than "auto" takes for a cell."""


@pytest.fixture(scope="module")
def void():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return rt.solve(TRACK, TRAIN, hanging(1e-3), accuracy=VOID_ACCURACY)


def test_rail_field_at_each_sleeper_is_the_rail_above_it(void):
    t = void.one_period(64)[0]
    x = np.arange(void.sleepers) * PAPER.sleeper_spacing
    above = void.rail_above_sleepers(t)
    field = void.rail_displacement(t[None, :], x[:, None])
    np.testing.assert_allclose(field, above, atol=1e-9 * np.abs(above).max())


def test_curvature_is_the_second_difference_of_the_rail(void):
    t = void.one_period(16)[0][:, None]
    h = 2e-4
    for x in (8.85, 9.0, 9.3, 12.4):              # beside and above the void, and far
        w = [void.rail_displacement(t, x + s * h) for s in (-1, 0, 1)]
        second = (w[0] - 2 * w[1] + w[2]) / h**2 * PAPER.rail_bending_stiffness
        moment = void.rail_bending_moment(t, x, kinks="series")
        np.testing.assert_allclose(moment, second, atol=2e-5 * np.abs(moment).max())


def test_the_foundations_carry_the_trains_weight(void):
    t = void.one_period(4096)[0]
    weight = np.sum(TRAIN.axle_loads) * void.sleepers * PAPER.sleeper_spacing / TRAIN.wagon_length
    assert void.foundation_force(t).sum(axis=0).mean() == pytest.approx(weight, rel=1e-6)
    assert void.rail_seat_load(t).sum(axis=0).mean() == pytest.approx(weight, rel=1e-6)


def test_the_truncation_estimate_is_the_error_of_keeping_m(void):
    finer = rt.solve(TRACK, TRAIN, void.cell, 2 * void.harmonics)
    t = void.one_period(2048)[0]
    estimates = cell_truncation_errors(void)[0]
    assert void.truncation_error == max(estimates.values()) <= VOID_ACCURACY
    for output in ("sleeper_displacement", "rail_seat_load"):
        truth = getattr(finer, output)(t)
        error = np.abs(truth - getattr(void, output)(t)).max() / np.abs(truth).max()
        assert 0.5 < estimates[output] / error < 2.0, output


def test_a_gap_too_wide_to_close_carries_nothing():
    result = rt.solve(TRACK, TRAIN, hanging(3e-3))
    t = result.one_period(512)[0]
    assert result.sleeper_displacement(t)[15].min() > -3e-3
    assert result.contact_fraction()[15] == 0.0
    assert np.all(result.foundation_force(t)[15] == 0.0)


def test_a_cell_refuses_what_it_cannot_do():
    cell = hanging(1e-3, n=4, at=1)
    with pytest.raises(ValueError, match="newton"):
        rt.solve(TRACK, TRAIN, cell, method="fixed-point")
    # stability="full" is computed for cells now (tests/test_cell_floquet.py)
    with pytest.raises(ValueError, match="stability"):
        rt.solve(TRACK, TRAIN, cell, stability="bogus")
    with pytest.raises(ValueError, match="explicit"):
        rt.solve(TRACK, TRAIN, cell, samples=256)


def test_a_cell_from_another_track_warns_and_a_wrong_index_is_named():
    other = rt.Passage(rt.Track.ballasted(), TRAIN)
    cell = rt.SleeperCell.identical(other, SOUND, 4)
    with pytest.warns(UserWarning, match="sleeper_mass"):
        rt.solve(TRACK, TRAIN, cell, 10)
    with pytest.raises(IndexError, match="0 to 3"):
        cell.with_sleeper(4, foundation=SOUND)
