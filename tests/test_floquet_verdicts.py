"""Floquet verdicts that do not depend on the search box (issue 27, findings 4, 1 and 12).

A search that finds no multiplier outside the unit circle proves stability
only if it could have found one: its box must reach above what the track
can grow by, and its contour must have points enough.  Otherwise the
verdict is "unknown", never "stable".

Independent truths: the time-domain ring's linearised monodromy
(`rt.ring_multipliers`, Newmark, no Hill's matrix) for the multipliers that
a narrow search misses; the linear law, on which no disturbance grows (the
energy bound must give exactly 1); and the ring's multipliers lying under
the a-priori estimate at every speed tried.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)


def _fold_solution(speed):
    return rt.solve(FOLD_TRACK, rt.Train.paper(speed=speed), FOLD_LAW, harmonics=25,
                    stability="off")


@pytest.fixture(scope="module")
def at_600():
    return _fold_solution(600.0)


@pytest.fixture(scope="module")
def at_525():
    return _fold_solution(525.0)


def test_a_box_below_the_dominant_multiplier_does_not_say_stable(at_600):
    # the ring's linearised period map: |mu| = 1.051 > 1.04, outside the asked box
    ring = abs(rt.ring_multipliers(at_600, steps_per_period=300).dominant)
    assert 1.04 < ring < 1.1
    narrow = rt.floquet(at_600, max_multiplier=1.04)
    assert narrow.verdict == "unknown" and narrow.stable is None
    assert "max_multiplier = 1.04" in narrow.message
    full = rt.floquet(at_600)
    assert full.verdict == "unstable" and full.stable is False
    assert abs(abs(full.dominant) - ring) < 2e-3


@pytest.mark.parametrize("points", [1, 2])
def test_too_few_contour_points_do_not_say_stable(at_525, points):
    # the ring: |mu| = 2.0 at 525 m/s; one or two quadrature points miss it
    coarse = rt.floquet(at_525, points=points)
    assert coarse.verdict in ("unstable", "unknown") and coarse.stable is not True
    assert rt.floquet(at_525).verdict == "unstable"


def test_the_quick_look_of_solve_finds_the_instability_at_525(at_525):
    # solve's quick look (one phase, |mu| >= 0.9, 16 points) must find the |mu| = 2.0 pair
    # that the full search finds; where it finds nothing it says "unknown"
    quick = rt.floquet(at_525, shifts=False, min_multiplier=0.9, points=16)
    assert quick.verdict == "unstable"
    assert abs(abs(quick.dominant) - abs(rt.floquet(at_525).dominant)) < 1e-9
    with pytest.warns(rt.UnstableSolutionWarning, match="2.005-fold"):
        rt.solve(FOLD_TRACK, rt.Train.paper(speed=525.0), FOLD_LAW, harmonics=25)


def test_one_phase_alone_never_says_stable(at_600):
    # at 600 m/s the growing disturbance is not in phase 0's strip
    assert rt.floquet(at_600, shifts=False).verdict == "unknown"


def test_the_bound_is_one_on_a_linear_law_and_holds_on_the_fold_track(at_525, at_600):
    from railtrack.solvers.floquet_verdict import growth_bound
    linear = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(), 25)
    assert growth_bound(linear) == 1.0
    for solution in (at_525, at_600):
        ring = abs(rt.ring_multipliers(solution, steps_per_period=300).dominant)
        assert 1.0 < ring < growth_bound(solution)


def test_a_narrow_box_along_a_branch_marks_no_point_stable():
    # from 470 m/s on the fold track: the lower part, stable up to its fold at 527.6 m/s
    # (|mu| 0.59-0.79 there, chapter 10), where a box up to 1.5 once said "stable"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.ConvergenceWarning)   # stops after max_points
        branch = rt.continuation(FOLD_TRACK, rt.Train.paper(speed=470.0), FOLD_LAW, "speed",
                                 start=470.0, stop=520.0, harmonics=25, max_points=5)
    narrow = rt.check_branch(branch, max_multiplier=1.5)
    assert not any(flag is True for flag in narrow.stable)
    assert set(narrow.verdicts) <= {"unstable", "unknown"}
    assert narrow.changes == ()
    full = rt.check_branch(branch)
    assert set(full.verdicts) == {"stable"}
    # every verdict the narrow search gives is one the full search confirms
    for a, b in zip(narrow.verdicts, full.verdicts):
        assert a == "unknown" or a == b


def test_the_default_sweep_reports_unstable_members_as_solve_does():
    with pytest.warns(rt.UnstableSolutionWarning) as plain:
        _ = rt.solve(FOLD_TRACK, rt.Train.paper(speed=480.0), FOLD_LAW, harmonics=25)
    assert "2.661-fold" in str(plain[0].message)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = rt.sweep(FOLD_TRACK, rt.Train.paper(), FOLD_LAW, 25, speed=[480.0, 500.0])
    unstable = [w for w in caught if issubclass(w.category, rt.UnstableSolutionWarning)]
    assert len(unstable) == 1 and "2 of 2 members" in str(unstable[0].message)
    assert "2.661-fold" in str(unstable[0].message)
    assert result.stable.tolist() == [False, False]
    assert result.verdicts.tolist() == ["unstable", "unstable"]
    # the ring's linearised period map agrees at 480 m/s
    ring = rt.ring_multipliers(result.solution(0), steps_per_period=300)
    assert abs(abs(result.dominant_multiplier[0]) - abs(ring.dominant)) < 0.02 * abs(ring.dominant)


def test_a_failed_member_is_unknown_not_unstable():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = rt.sweep(FOLD_TRACK, rt.Train.paper(), FOLD_LAW, 25, speed=[560.0],
                          max_iterations=2)
    assert not result.converged[0]
    assert result.stable[0] is None and result.verdicts[0] == "unknown"
    assert np.isnan(result.dominant_multiplier[0])


def test_the_default_sweep_on_a_linear_law_is_stable():
    result = rt.sweep(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(), 15,
                      speed=[45.0, 60.0])
    assert result.stable.tolist() == [True, True]


def test_floquet_refuses_a_branch_and_bad_points(at_525):
    branch = rt.continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
                             "speed", start=40.0, stop=45.0, harmonics=15)
    with pytest.raises(TypeError, match=r"got a Branch.*branch\.solution\(i\)"):
        rt.floquet(branch)
    for points in (0, -3, 2.5, True):
        with pytest.raises(ValueError, match=rf"points must be an integer >= 1.*{points!r}"):
            rt.floquet(at_525, points=points)
    with pytest.raises(ValueError, match="max_multiplier"):
        rt.floquet(at_525, max_multiplier="big")


def test_check_branch_refuses_a_solution(at_525):
    with pytest.raises(TypeError, match=r"check_branch takes a Branch.*got a Solution"):
        rt.check_branch(at_525)


def test_check_stability_refuses_a_string_tolerance(at_525):
    with pytest.raises(TypeError, match=r"tol must be a real number; got '0.01'"):
        rt.check_stability(at_525, tol="0.01")
