"""Stability along a branch (`railtrack.check_branch`), against the ring's own attractors.

The truth is the time-domain ring run without any harmonic-balance input:
started from the static state at one speed, it settles on a stable periodic
state if there is one, and that state must be a point of the branch marked
stable, never one marked unstable.  Theory adds one more: a saddle-node
fold turns a stable part of the branch into an unstable one.
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
def marked(fold_branch):
    return rt.check_branch(fold_branch, per_segment=1, periods=20, max_periods=40, confirm=100,
                           **COARSE)


def test_segments_split_the_branch_at_its_folds(fold_branch):
    parts = segments(fold_branch)
    assert len(parts) == len(fold_branch.folds) + 1 == 5
    assert [i for part in parts for i in part] == list(range(len(fold_branch)))
    for fold, before, after in zip(fold_branch.folds, parts[:-1], parts[1:]):
        # d(speed)/ds changes sign across the cut
        assert np.sign(fold_branch.tangents[before[-1], -1]) != np.sign(
            fold_branch.tangents[after[0], -1])


@pytest.mark.slow
@pytest.mark.parametrize("speed, solutions, stable", [(525.0, 5, 2), (540.0, 3, 1)])
def test_the_ring_from_rest_settles_on_a_point_marked_stable(marked, speed, solutions, stable):
    # The ring knows nothing of the branch and picks its own attractor.
    ring = rt.simulate_time_domain(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, tol=1e-7,
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
def test_folds_separate_stable_from_unstable_and_a_torus_is_located(marked):
    parts = segments(marked)
    first, *middle, last = parts
    assert marked.stable[list(first)].all()                 # 300 m/s up to the first fold
    assert not any(marked.stable[list(part)].any() for part in middle)
    # On the last part the ring leaves at the high-speed end for a response
    # with lines between the multiples of v/H; the loss of stability, slow
    # there, is located to one step by the 100-period confirmation.
    flags = marked.stable[list(last)]
    change = int(np.flatnonzero(np.diff(flags.astype(int)))[0])
    assert flags[: change + 1].all() and not flags[change + 1:].any()
    a, b = last[change], last[change + 1]
    assert a in marked.checks and b in marked.checks
    assert 580.0 < marked.values[a] < marked.values[b] < 600.0
    assert marked.checks[a].periods == marked.checks[b].periods == 100
    assert marked.checks[b].change_growth > 1.01 > marked.checks[a].change_growth
    assert marked.checks[last[-1]].interharmonic_fraction > 0.1   # 660 m/s


def test_bad_requests_are_refused(fold_branch):
    with pytest.raises(ValueError, match="per_segment"):
        rt.check_branch(fold_branch, per_segment=0)
    with pytest.raises(ValueError, match="confirm"):
        rt.check_branch(fold_branch, confirm=1)
    with pytest.raises(ValueError, match="max_checks"):
        rt.check_branch(fold_branch, per_segment=3, max_checks=16, **COARSE)
    broken = dataclasses.replace(fold_branch, converged=np.r_[False, fold_branch.converged[1:]])
    with pytest.raises(ValueError, match="converged"):
        rt.check_branch(broken)
