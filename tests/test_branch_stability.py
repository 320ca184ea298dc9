"""Stability along a branch (`railtrack.check_branch`), against the ring's own attractors.

The truth is the time-domain ring run without any harmonic-balance input:
started from the static state at one speed, it settles on a stable periodic
state if there is one, and that state must be a point of the branch marked
stable, never one marked unstable.  Theory adds one more: a saddle-node
fold turns a stable part of the branch into an unstable one.  Where Hill's
method and the ring's sampled checks disagree, the ring started on the
point in question decides.
"""

import dataclasses

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.branch_stability import segments

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)
COARSE = dict(elements_per_span=4, steps_per_period=600)


@pytest.fixture(scope="module")
def fold_branch():
    return rt.continuation(FOLD_TRACK, rt.Train.paper(speed=300.0), FOLD_LAW, "speed",
                           start=300.0, stop=660.0, harmonics=25)


@pytest.fixture(scope="module")
def by_ring(fold_branch):
    return rt.check_branch(fold_branch, "time-domain", per_segment=1, periods=20,
                           max_periods=40, confirm=100, **COARSE)


@pytest.fixture(scope="module")
def by_hill(fold_branch):
    return rt.check_branch(fold_branch)


def test_segments_split_the_branch_at_its_folds(fold_branch):
    parts = segments(fold_branch)
    assert len(parts) == len(fold_branch.folds) + 1 == 5
    assert [i for part in parts for i in part] == list(range(len(fold_branch)))
    for fold, before, after in zip(fold_branch.folds, parts[:-1], parts[1:]):
        # d(speed)/ds changes sign across the cut
        assert np.sign(fold_branch.tangents[before[-1], -1]) != np.sign(
            fold_branch.tangents[after[0], -1])


def _ring_attractor_on_branch(marked, speed, solutions, stable):
    # The ring knows nothing of the branch and picks its own attractor.  Its
    # tol 1e-6 (57 and 27 periods; 72 and 30 at 1e-7) moves the minimum it
    # reaches by 1e-9 m: it is 1.17e-6 and 7.3e-7 m off the branch (measured
    # at either tol), against the 5e-6 asserted below.
    ring = rt.simulate_time_domain(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, tol=1e-6,
                                   max_periods=200, **COARSE)
    assert ring.converged
    reached = float(ring.sleeper_displacements.min())
    crossings = np.flatnonzero(np.diff(np.sign(marked.values - speed)) != 0)
    assert len(crossings) == solutions
    dips = marked.minimum_displacement()
    weights = (speed - marked.values[crossings]) / np.diff(marked.values)[crossings]
    at_speed = dips[crossings] + weights * (dips[crossings + 1] - dips[crossings])
    nearest = int(np.argmin(np.abs(at_speed - reached)))
    assert abs(at_speed[nearest] - reached) < 5e-6          # the ring's state is on the branch
    flags = marked.stable[crossings]
    assert flags[nearest] and flags.sum() == stable


@pytest.mark.slow
@pytest.mark.parametrize("speed, solutions, stable_by_ring, stable_by_hill",
                         [(525.0, 5, 2, 2), (540.0, 3, 1, 2)])
def test_the_ring_from_rest_settles_on_a_point_marked_stable(by_ring, by_hill, speed, solutions,
                                                             stable_by_ring, stable_by_hill):
    # at 540 m/s the ring's sample carried an unstable verdict to a stable point
    # (see test_a_stable_stretch_between_folds_that_the_ring_sample_missed)
    _ring_attractor_on_branch(by_ring, speed, solutions, stable_by_ring)
    _ring_attractor_on_branch(by_hill, speed, solutions, stable_by_hill)


@pytest.mark.slow
def test_the_ring_sample_finds_the_torus_on_the_last_part(by_ring):
    parts = segments(by_ring)
    first, *middle, last = parts
    assert by_ring.stable[list(first)].all()                 # 300 m/s up to the first fold
    # every point the ring was run on between the first and the last fold leaves
    assert not any(check.stable for i, check in by_ring.checks.items()
                   if any(i in part for part in middle))
    # On the last part the ring leaves at the high-speed end for a response
    # with lines between the multiples of v/H; the loss of stability, slow
    # there, is located to one step by the 100-period confirmation.
    flags = by_ring.stable[list(last)]
    change = int(np.flatnonzero(np.diff(flags.astype(int)))[0])
    assert flags[: change + 1].all() and not flags[change + 1:].any()
    a, b = last[change], last[change + 1]
    assert a in by_ring.checks and b in by_ring.checks
    assert 580.0 < by_ring.values[a] < by_ring.values[b] < 600.0
    assert by_ring.checks[a].periods == by_ring.checks[b].periods == 100
    assert by_ring.checks[b].change_growth > 1.01 > by_ring.checks[a].change_growth
    assert by_ring.checks[last[-1]].interharmonic_fraction > 0.1   # 660 m/s


def test_hill_lists_the_folds_and_the_tori(by_hill, fold_branch):
    changes = by_hill.changes
    folds = [c for c in changes if c.kind == "fold"]
    # three folds change stability; at the last one (513.1 m/s) a complex pair is
    # still outside on the part it leads to, and stability comes back 0.2 m/s later
    np.testing.assert_allclose([c.value for c in folds], fold_branch.fold_values[:3],
                               atol=1e-12)
    assert [c.gains for c in folds] == [False, True, False]
    tori = [c for c in changes if c.kind == "complex"]
    assert len(tori) == 4 and len(changes) == 7
    after_fold = tori[2]
    assert fold_branch.fold_values[3] < after_fold.value < fold_branch.fold_values[3] + 0.3
    assert after_fold.gains and abs(after_fold.theta - 2 * np.pi / 30) < 1e-9
    # the ring's sample put the last one between 587.9 and 596.3 m/s
    assert 587.9 < tori[-1].value < 596.3 and not tori[-1].gains
    assert all(0 < c.frequency < 0.5 for c in tori)
    assert by_hill.stable[0] and not by_hill.stable[-1]
    assert np.array_equal(by_hill.stable, np.abs(by_hill.multipliers) < 1)


@pytest.mark.slow
def test_past_the_last_fold_stability_returns_where_check_branch_says(by_hill):
    # Independent check by the linearised ring: on the part that leaves the last
    # fold, a tenth of a metre per second either side of the located change.
    change = [c for c in by_hill.changes if c.kind == "complex"][2]
    after = change.index + 1          # the first point of the part past the fold
    for offset, inside in ((-0.1, False), (0.1, True)):
        solution = rt.solve(FOLD_TRACK, rt.Train.paper(speed=change.value + offset), FOLD_LAW,
                            harmonics=25, initial=by_hill.coefficients[after],
                            stability="off")
        ring = [abs(rt.ring_multipliers(solution, steps_per_period=steps).dominant)
                for steps in (1200, 2400)]
        assert ((4 * ring[1] - ring[0]) / 3 < 1) == inside


@pytest.mark.slow
def test_a_stable_stretch_between_folds_that_the_ring_sample_missed(by_hill, by_ring):
    # Hill finds the part between the second and the third fold stable near both its
    # ends; the ring started on such a point stays, on one in the middle it leaves
    part = segments(by_hill)[2]
    stretch = [i for i in part if by_hill.stable[i]]
    assert stretch and not by_ring.stable[stretch].any()
    # the point farthest from a fold: next to one the coarse ring's own periodic state
    # is more than its tolerance, 1e-2 of the peak, away from harmonic balance
    away = [min(abs(by_hill.values[i] - fold) for fold in by_hill.fold_values) for i in stretch]
    keeps = rt.check_stability(by_hill.solution(stretch[int(np.argmax(away))]), periods=20,
                               max_periods=40, **COARSE)
    assert keeps.verdict == "stays"
    middle = part[len(part) // 2]
    assert not by_hill.stable[middle]
    assert not rt.check_stability(by_hill.solution(middle), periods=20, max_periods=40,
                                  **COARSE).stable


def test_bad_requests_are_refused(fold_branch):
    with pytest.raises(ValueError, match="per_segment"):
        rt.check_branch(fold_branch, "time-domain", per_segment=0)
    with pytest.raises(ValueError, match="confirm"):
        rt.check_branch(fold_branch, "time-domain", confirm=1)
    with pytest.raises(ValueError, match="max_checks"):
        rt.check_branch(fold_branch, "time-domain", per_segment=3, max_checks=16, **COARSE)
    with pytest.raises(ValueError, match="time-domain"):
        rt.check_branch(fold_branch, per_segment=2)
    with pytest.raises(ValueError, match="method"):
        rt.check_branch(fold_branch, "ring")
    broken = dataclasses.replace(fold_branch, converged=np.r_[False, fold_branch.converged[1:]])
    with pytest.raises(ValueError, match="converged"):
        rt.check_branch(broken)


@pytest.mark.slow
def test_the_torus_on_the_last_part_is_located_to_half_a_metre_per_second(by_hill):
    # Independent check by the linearised ring (rt.ring_multipliers): half a metre
    # per second either side of the located Neimark-Sacker speed, its dominant
    # multiplier is inside and outside the unit circle.
    torus = [c for c in by_hill.changes if c.kind == "complex"][-1]
    i = torus.index
    for offset, inside in ((-0.5, True), (0.5, False)):
        speed = torus.value + offset
        weight = (speed - by_hill.values[i]) / (by_hill.values[i + 1] - by_hill.values[i])
        guess = (1 - weight) * by_hill.coefficients[i] + weight * by_hill.coefficients[i + 1]
        solution = rt.solve(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, harmonics=25,
                            initial=guess)
        ring = [abs(rt.ring_multipliers(solution, steps_per_period=steps).dominant)
                for steps in (1200, 2400)]
        assert ((4 * ring[1] - ring[0]) / 3 < 1) == inside
