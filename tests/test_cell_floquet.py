"""Floquet multipliers of a cell's periodic solution (issue 27, finding 1).

Independent truths: a cell of N identical sleepers is today's track, so its
multipliers are those `railtrack.floquet` finds for one sleeper (the cell's
own Hill matrix, ``reduce=False``, is an N-fold larger matrix of other
operators); a linear track with damping has every multiplier inside the
unit circle; the ring's linearised period map (`ring_multipliers`) for a
cell of differing sleepers.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.cell import SleeperCell
from railtrack.solvers.cell_floquet import cell_floquet

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)


def _fold(speed):
    train = rt.Train.paper(speed=speed)
    return train, rt.Passage(FOLD_TRACK, train)


def _same_set(a, b, tol):
    """Each member of a has one of b within tol, and the other way round."""
    gap = np.abs(a[:, None] - b[None, :])
    return (
        a.size == b.size
        and gap.min(axis=1).max() < tol
        and gap.min(axis=0).max() < tol
    )


@pytest.mark.parametrize("sleepers", [1, 3])
def test_a_cell_of_identical_sleepers_has_the_multipliers_of_one_sleeper(
    sleepers,
):
    train, passage = _fold(480.0)
    plain = rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    reference = rt.floquet(plain)
    assert abs(reference.dominant) == pytest.approx(2.66, abs=0.01)
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, sleepers),
        19,
        stability="off",
    )
    for result in (rt.floquet(cell), cell_floquet(cell, reduce=False)):
        assert not result.stable
        assert abs(result.dominant) == pytest.approx(
            abs(reference.dominant), rel=1e-6
        )
        assert _same_set(
            result.multipliers[result.resolved],
            reference.multipliers[reference.resolved],
            1e-6,
        )


def test_a_stable_state_of_identical_sleepers_matches_one_sleeper():
    train, passage = _fold(420.0)
    reference = rt.floquet(
        rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    )
    assert reference.stable and abs(reference.dominant) == pytest.approx(
        0.49, abs=0.01
    )
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, 3),
        19,
        stability="off",
    )
    result = cell_floquet(cell, reduce=False)
    assert result.stable
    assert _same_set(
        result.multipliers[result.resolved],
        reference.multipliers[reference.resolved],
        1e-6,
    )


def test_a_linear_cell_of_differing_sleepers_is_stable():
    # lightly damped pads and ballast: every free disturbance of a
    # linear track dies out, slowly enough that the box holds many
    # multipliers close to the unit circle
    train, passage = _fold(480.0)
    cell = (
        SleeperCell.identical(passage, rt.LinearFoundation(20e6, 5000.0), 3)
        .with_sleeper(
            1,
            foundation=rt.LinearFoundation(5e6, 2000.0),
            sleeper_mass=250.0,
        )
        .with_sleeper(2, pad_stiffness=5e8)
    )
    result = rt.floquet(
        rt.solve(FOLD_TRACK, train, cell, 12, stability="off"),
        min_multiplier=1e-3,
    )
    assert result.resolved.sum() >= 10
    assert np.all(np.abs(result.multipliers) < 1.0)
    assert result.stable and abs(result.dominant) > 0.3


def test_solve_warns_for_an_unstable_cell_and_keeps_the_full_result():
    train, passage = _fold(480.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 1)
    with pytest.warns(rt.UnstableSolutionWarning, match="2.66"):
        rt.solve(FOLD_TRACK, train, cell)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.UnstableSolutionWarning)
        full = rt.solve(
            FOLD_TRACK,
            train,
            SleeperCell.identical(passage, FOLD_LAW, 3),
            stability="full",
        )
    assert full.stability is not None and not full.stability.stable
    assert abs(full.stability.dominant) == pytest.approx(2.66, abs=0.01)


def test_random_support_flags_the_unstable_state():
    with pytest.warns(rt.UnstableSolutionWarning, match="1 of 1 draws"):
        sample = rt.random_support(
            FOLD_TRACK,
            rt.Train.paper(speed=480.0),
            FOLD_LAW,
            sleepers=3,
            variation=0.0,
            draws=1,
        )
    assert sample.stability.tolist() == ["unstable"]
    assert sample.stability_counts() == {
        "stable": 0,
        "unstable": 1,
        "unknown": 0,
    }
    assert "1 unstable" in sample.summary()


def test_a_wheel_solution_is_refused_with_the_alternative_named():
    class Wheeled:
        wheel = object()

    with pytest.raises(TypeError, match="simulate_time_domain"):
        rt.floquet(Wheeled())


@pytest.mark.parametrize("stiffness", [19e6, 16e6])
def test_differing_sleepers_match_the_rings_period_map(stiffness):
    # sleeper 1 of 3 on a softer ballast: 19 MN/m leaves the state
    # unstable (|mu| 2.75, not the uniform track's 2.66), 16 MN/m makes
    # it stable (0.62); the ring linearised about the same orbit (a
    # Newmark period map, no Hill matrix) gives the same multiplier
    train, passage = _fold(480.0)
    softer = rt.CubicFoundation(stiffness, 2e13, 0.8, 5000.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 3).with_sleeper(
        1, foundation=softer
    )
    state = rt.solve(FOLD_TRACK, train, cell, 19, stability="off")
    hill = rt.floquet(state)
    ring = rt.ring_multipliers(
        state, elements_per_span=2, steps_per_period=600
    )
    assert hill.stable == ring.stable == (stiffness < 18e6)
    assert abs(hill.dominant) == pytest.approx(abs(ring.dominant), rel=0.02)
    assert abs(hill.dominant - ring.dominant) < 0.03 * abs(ring.dominant)


def test_the_ring_of_an_identical_cell_is_the_ring_of_one_sleeper():
    train, passage = _fold(480.0)
    plain = rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, 3),
        19,
        stability="off",
    )
    options = dict(elements_per_span=2, steps_per_period=300)
    one = rt.ring_multipliers(plain, **options)
    three = rt.ring_multipliers(cell, **options)
    assert abs(three.dominant - one.dominant) < 1e-6 * abs(one.dominant)


def test_the_ring_refuses_a_cell_that_does_not_divide_the_wagon():
    train, passage = _fold(480.0)
    cell = SleeperCell.identical(passage, rt.LinearFoundation.paper(), 4)
    state = rt.solve(FOLD_TRACK, train, cell, 30, stability="off")
    with pytest.raises(ValueError, match="rt.floquet"):
        rt.ring_multipliers(state)


def test_random_support_says_unknown_where_the_quick_look_saw_one_phase():
    # N = 3 of H / L = 30: the quick look sees 1 of the 10 phases per
    # cell, so finding nothing proves nothing; "full" sees all ten
    train = rt.Train.paper(speed=420.0)
    options = dict(sleepers=3, variation=0.0, draws=1)
    quick = rt.random_support(FOLD_TRACK, train, FOLD_LAW, **options)
    full = rt.random_support(
        FOLD_TRACK, train, FOLD_LAW, stability="full", **options
    )
    assert quick.stability.tolist() == ["unknown"]
    assert full.stability.tolist() == ["stable"]
    assert "1 stable, 0 unstable, 0 unknown" in full.summary()
