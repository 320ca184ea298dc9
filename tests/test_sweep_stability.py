"""`rt.sweep(..., stability=True)`: every converged member's Floquet verdict.

The independent truth is the linearised time-domain ring (`rt.ring_multipliers`,
a Newmark monodromy matrix, no harmonic balance in the linearisation): on the
fold track of chapter 10 the solutions `sweep` finds at 470 and 540 m/s are
stable and the one at 500 m/s is not (a complex pair at |mu| ~ 2.85).
"""

import warnings

import numpy as np
import pytest

import railtrack as rt

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)
TRAIN = rt.Train.paper()


@pytest.fixture(scope="module")
def fold_sweep():
    # 560 m/s: Newton from the linear guess does not converge there (a fold region)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.ConvergenceWarning)
        return rt.sweep(FOLD_TRACK, TRAIN, FOLD_LAW, speed=[470.0, 500.0, 540.0, 560.0],
                        stability=True)   # "auto": m = 25


@pytest.mark.parametrize("index", [0, 1, 2])
def test_each_verdict_agrees_with_the_linearised_ring(fold_sweep, index):
    ring = rt.ring_multipliers(fold_sweep.solution(index), steps_per_period=1200)
    mu = fold_sweep.dominant_multiplier[index]
    assert fold_sweep.stable[index] == ring.stable
    # a complex pair: either member of it may come first
    assert min(abs(mu - ring.dominant), abs(mu - np.conj(ring.dominant))) \
        < 3e-3 * abs(ring.dominant)


def test_the_sweep_holds_stable_and_unstable_members(fold_sweep):
    """The test above would pass on a verdict that is always True: not so here."""
    assert fold_sweep.stable[:3].tolist() == [True, False, True]


def test_an_unconverged_member_has_no_verdict(fold_sweep):
    # unknown, not unstable: there is no periodic solution to judge
    assert not fold_sweep.converged[3]
    assert fold_sweep.stable[3] is None and fold_sweep.verdicts[3] == "unknown"
    assert np.isnan(fold_sweep.dominant_multiplier[3])


def test_without_stability_there_is_no_verdict():
    result = rt.sweep(rt.Track.paper(), TRAIN, rt.LinearFoundation.paper(), 15, speed=[45.0],
                      stability="off")
    assert result.stable is None and result.dominant_multiplier is None


@pytest.mark.parametrize("train, swept, member", [
    (TRAIN.replace(wagon_length=18.3), dict(speed=[45.0, 60.0]), 0),
    (TRAIN, dict(wagon_length=[18.0, 18.3]), 1),
])
def test_stability_needs_a_whole_number_of_sleepers_per_wagon(train, swept, member):
    with pytest.raises(ValueError, match=rf"stability=True: member {member} .*H/L"):
        rt.sweep(rt.Track.paper(), train, rt.LinearFoundation.paper(), 15, stability=True,
                 **swept)


def test_stability_must_be_a_bool():
    with pytest.raises(TypeError, match="stability must be one of .* got 'yes'"):
        rt.sweep(rt.Track.paper(), TRAIN, rt.LinearFoundation.paper(), 15, stability="yes",
                 speed=[45.0])
