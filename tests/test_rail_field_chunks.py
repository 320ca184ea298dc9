"""The rail field of cells and wheels: in bounded memory, and only where it has digits (issue 27).

#9: `rail_displacement` of a cell or a wheel solution took memory in
proportion to the distinct x times the sleepers times the harmonics (1.9 GB
for 1,024 points on a dip).  Truths: the field in small blocks is the field
in one block; the sum over the sleepers, now separated per harmonic, is the
direct sum of the closed-form kernel `cell_offset_receptance` (eq. 3's
Floquet sum) at each sleeper; peak memory of 20,000 points is measured.
#7: x = 1e18 returned numbers; the phases omega x / v have no digit left
there, so such x is refused (`check_positions`), while far x within the
bound repeats the rail a whole number of wagons behind, delayed.
"""

import tracemalloc

import numpy as np
import pytest

import railtrack as rt
import railtrack.solvers.wheel_free_rail as free_rail_module
from railtrack.equations.cell_rail_field import (cell_offset_receptance,
                                                 cell_rail_field_coefficients)
from railtrack.equations.cell_receptance import cell_moving_load
from railtrack.studies.hanging_sleeper import hanging_cell

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)
SOUND = rt.LinearFoundation(20e6, 0.2e6)
DIP = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3)


@pytest.fixture(scope="module")
def cell():
    with pytest.warns(rt.TruncationWarning):          # the seat load wants m > 400; not read
        return rt.solve(TRACK, TRAIN, hanging_cell(PAPER, SOUND, 1e-3), 60)


@pytest.fixture(scope="module")
def wheels():
    return rt.solve(TRACK, TRAIN, SOUND, 60, wheel=rt.Wheel(600.0), profile=DIP)


def test_the_separated_sum_is_the_direct_sum_over_the_sleepers(cell):
    m, n = cell.harmonics, cell.sleepers
    omega = cell.frequencies[m + 1:]
    seat = cell.seat_harmonics[:, m + 1:]
    span, length = PAPER.sleeper_spacing, n * PAPER.sleeper_spacing
    x = np.array([0.0, 0.1, 5.4, 8.7, 9.0, 9.05, 17.99, 18.0, 25.3, -0.2, -13.1])
    ours = cell_rail_field_coefficients(PAPER, omega, cell.coefficients[:, m + 1:], seat,
                                        cell.cell.pad_stiffness, x)
    wraps = np.floor(x / length)
    inside = x - wraps * length
    theta = omega * length / PAPER.speed
    free = cell_moving_load(PAPER, omega, 1)[:, 0] * np.exp(-1j * np.outer(inside, omega)
                                                            / PAPER.speed)
    for which, derivative in ((0, 0), (1, 2)):
        direct = np.zeros((x.size, omega.size), dtype=complex)
        for j in range(n):
            d = inside - j * span
            behind = d < 0
            kernel = cell_offset_receptance(PAPER, omega, n, d + behind * length, derivative)
            direct -= np.where(behind[:, None], np.exp(1j * theta) * kernel, kernel) * seat[j]
        train = free if derivative == 0 else -((omega / PAPER.speed) ** 2) * free
        expected = np.exp(-1j * np.outer(wraps, theta)) * (direct + train)
        scale = np.abs(expected).max(axis=0)
        np.testing.assert_array_less(np.abs(ours[which] - expected) / scale, 1e-9)


@pytest.mark.parametrize("which", [0, 1, 2])
def test_blocks_give_the_one_shot_field(cell, which):
    t = np.linspace(0.0, cell.period, 37)
    x = np.linspace(-2.0, 20.0, 53)
    for tt, xx in ((t[:, None], x[None, :]),                       # a grid
                   (t[:, None] + 0.001 * x[None, :], x[None, :])):   # all points distinct
        whole = cell._field(tt, xx, which, entries=10**9)
        blocks = cell._field(tt, xx, which, entries=7)             # one position a block
        np.testing.assert_allclose(blocks, whole, rtol=0, atol=1e-13 * np.abs(whole).max())


def test_the_wheels_free_rail_in_blocks_is_the_one_shot(wheels, monkeypatch):
    t = np.linspace(0.0, wheels.period, 29)[:, None]
    x = np.linspace(7.0, 11.0, 31)[None, :]            # 899 points: three blocks
    whole = wheels.rail_displacement(t, x), wheels.rail_bending_moment(t, x)
    monkeypatch.setattr(free_rail_module, "chunk_length", lambda *args, **kwargs: 400)
    blocks = wheels.rail_displacement(t, x), wheels.rail_bending_moment(t, x)
    for one, other in zip(whole, blocks):
        np.testing.assert_allclose(other, one, rtol=0, atol=1e-13 * np.abs(one).max())


@pytest.mark.parametrize("which", ["cell", "wheels"])
def test_twenty_thousand_points_take_bounded_memory(cell, wheels, which):
    solution = cell if which == "cell" else wheels
    solution.rail_displacement(0.0, 0.3)          # one-off work (the wheels' anchor) first
    x = np.linspace(-3.0, 21.0, 20_000)
    tracemalloc.start()
    try:
        w = solution.rail_displacement(0.05, x)
        moment = solution.rail_bending_moment(0.05, x)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    # before issue 27 one temporary alone was 20,000 x 30 sleepers x 61 harmonics x 16 B
    assert peak < 128e6
    assert np.all(np.isfinite(w)) and np.all(np.isfinite(moment))
    np.testing.assert_allclose(w[::997], solution.rail_displacement(0.05, x[::997]),
                               rtol=0, atol=1e-12 * np.abs(w).max())


@pytest.mark.parametrize("which", ["cell", "wheels"])
@pytest.mark.parametrize("method", ["rail_displacement", "rail_bending_moment"])
def test_positions_without_digits_are_refused(cell, wheels, which, method):
    read = getattr(cell if which == "cell" else wheels, method)
    for far in (1e18, -1e18, np.nan, np.inf):
        with pytest.raises(ValueError, match="x"):
            read(0.0, np.array([0.0, far]))


def test_far_positions_within_the_bound_repeat_the_rail_wagons_behind(cell):
    wagons = 1e6                                   # 18,000 km ahead, within the bound
    ahead = wagons * PAPER.wagon_length
    t = np.linspace(0.0, cell.period, 16)
    x = 9.2
    np.testing.assert_allclose(cell.rail_displacement(t, x + ahead),
                               cell.rail_displacement(t - ahead / PAPER.speed, x),
                               rtol=0, atol=1e-3 * np.abs(cell.rail_displacement(t, x)).max())


def test_times_without_digits_or_not_numbers_are_refused():
    # t = 1e18 s leaves the phases omega t no digits and NaN is no time: the
    # histories of one sleeper, a cell and the wheels refuse both, as x is;
    # a time one million periods on is still the same response
    track, train = rt.Track.paper(), rt.Train.paper()
    law = rt.LinearFoundation.paper()
    plain = rt.solve(track, train, law, 15)
    cell = rt.solve(
        track, train, rt.SleeperCell.identical(rt.Passage(track, train), law, 2)
    )
    for history in (
        plain.sleeper_displacement,
        cell.sleeper_displacement,
        lambda t: cell.rail_displacement(t, 0.3),
        lambda t: plain.rail_displacement(t, 0.3),
    ):
        for bad in (1e18, float("nan"), float("inf")):
            with pytest.raises(ValueError, match="times t|too late"):
                history(np.array([0.0, bad]))
    period = float(plain.period)
    later = plain.sleeper_displacement(1e6 * period + 0.1 * period)
    now = plain.sleeper_displacement(0.1 * period)
    peak = np.abs(plain.sleeper_displacement(np.linspace(0, period, 64))).max()
    assert abs(later - now) < 1e-6 * peak
