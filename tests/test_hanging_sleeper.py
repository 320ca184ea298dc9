"""Harmonic balance against the time-domain ring on the hanging sleeper (issue 19, section 3).

The paper's track and wagon at 45 m/s, a cell of 30 sound sleepers
(k2 = 20 MN/m, eta2 = 0.2 MN s/m) with sleeper 15 hanging above the same
ballast.  The ring (one wagon, 30 sleepers, `simulate_time_domain` with the
cell) integrates the same laws in time, by finite elements: an independent
method.  Its discretisation error at 4 elements a span and 1200 steps a
period is below 0.1 % on the forces (the finest ring, 32 elements and 9600
steps, as reference); harmonic balance at m = 200 is converged beyond that.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.hanging_sleeper import hanging_cell, moment_extremes, sleeper_extremes

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = rt.Passage(TRACK, TRAIN)
SOUND = rt.LinearFoundation(20e6, 0.2e6)
AROUND = slice(13, 18)


@pytest.fixture(scope="module", params=[0.5e-3, 1e-3, 2e-3])
def both(request):
    cell = hanging_cell(PAPER, SOUND, request.param)
    harmonic = rt.solve(TRACK, TRAIN, cell, 200)
    ring = rt.simulate_time_domain(TRACK, TRAIN, cell, 4, 1200)
    assert harmonic.converged and ring.converged
    return harmonic, ring


def test_loads_and_displacements_around_the_void_agree(both):
    harmonic, ring = (sleeper_extremes(s) for s in both)
    for name in ("peak_seat_load", "peak_foundation_force"):
        hb, td = getattr(harmonic, name)[AROUND], getattr(ring, name)[AROUND]
        np.testing.assert_allclose(td, hb, atol=3e-3 * hb.max(), err_msg=name)
    np.testing.assert_allclose(ring.lowest_displacement[AROUND],
                               harmonic.lowest_displacement[AROUND], rtol=2e-3)
    np.testing.assert_allclose(ring.contact_fraction[AROUND],
                               harmonic.contact_fraction[AROUND], atol=0.01)


def test_the_rail_moment_over_the_void_agrees(both):
    harmonic, ring = (moment_extremes(s, 15) for s in both)
    for key in harmonic:
        np.testing.assert_allclose(ring[key], harmonic[key], atol=0.03 * harmonic[key][0],
                                   err_msg=key)


def test_the_neighbours_carry_more_the_wider_the_gap():
    peaks = [sleeper_extremes(rt.solve(TRACK, TRAIN, hanging_cell(PAPER, SOUND, g), 60))
             for g in (0.0, 0.5e-3, 1e-3, 2e-3)]
    neighbour = [p.peak_foundation_force[14] for p in peaks]
    hanging = [p.peak_foundation_force[15] for p in peaks]
    assert np.all(np.diff(neighbour) > 0) and np.all(np.diff(hanging) < 0)
    assert hanging[-1] == 0.0 and peaks[-1].contact_fraction[15] == 0.0


def test_a_wheel_solution_is_read_like_the_cell_and_a_massless_wheel_is_the_constant_force():
    # the limit m_w -> 0: a wheel without mass presses with its load whatever the rail does,
    # so over a hanging sleeper every sleeper's extremes are the constant-force cell's
    cell = hanging_cell(PAPER, SOUND, 1e-3)
    forces = sleeper_extremes(rt.solve(TRACK, TRAIN, cell, 200))
    with pytest.warns(rt.PlausibilityWarning, match="unsprung"):   # a limit, not a wheel
        massless = rt.Wheel(1e-3)
    wheels = sleeper_extremes(rt.solve(TRACK, TRAIN, cell, 200, wheel=massless))
    for name in ("peak_seat_load", "peak_foundation_force", "lowest_displacement"):
        np.testing.assert_allclose(getattr(wheels, name), getattr(forces, name), rtol=1e-4)
    # a heavy wheel at speed changes the neighbours' loads: the reading sees the wheels
    fast = rt.Train.paper(speed=100.0)
    cell = hanging_cell(rt.Passage(TRACK, fast), SOUND, 1e-3)
    # a 5 % difference is read: 0.5 % accuracy is ample (1e-3 needs more than "auto"'s cap)
    constant = rt.solve(TRACK, fast, cell, accuracy=5e-3)
    heavy = rt.solve(TRACK, fast, cell, wheel=rt.Wheel(900.0))
    assert constant.converged and heavy.converged
    forces, wheels = sleeper_extremes(constant), sleeper_extremes(heavy)
    assert np.max(np.abs(wheels.peak_foundation_force[AROUND] / forces.peak_foundation_force[
        AROUND] - 1)) > 0.05


def test_the_neighbours_rise_is_nothing_without_a_void_and_follows_chapter_13_with_one():
    from railtrack.studies.hanging_sleeper import neighbour_rise
    sound = rt.solve(TRACK, TRAIN, hanging_cell(PAPER, SOUND, 0.0), 200)
    # identical sleepers peak alike, to the sampling of the period (2048 instants)
    assert np.allclose(neighbour_rise(sound, sound, 15), 0.0, atol=1e-4)   # measured: 1.2e-5
    # a sleeper that never touches (5 mm) under a static train carries nothing: its two
    # neighbours share its load, each well under half of it again (the rail spreads it)
    slow = rt.Train.paper(speed=5.0)
    walking = rt.Passage(TRACK, slow)
    force, depth = neighbour_rise(rt.solve(TRACK, slow, hanging_cell(walking, SOUND, 0.0), 200),
                                  rt.solve(TRACK, slow, hanging_cell(walking, SOUND, 5e-3), 200),
                                  15)
    assert 0.0 < force < 0.5 and abs(depth - force) < 0.01   # a weak dashpot at walking pace
