"""The batched Newton of `railtrack.sweep` against single solves, member by member."""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.sweep import sweep

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()


def single(track, train, law, m=15):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.TruncationWarning)
        return rt.solve(track, train, law, m, tol=1e-10)


@pytest.mark.parametrize("law", [rt.CubicFoundation.paper(0.8), rt.BilinearFoundation.paper(0.0),
                                 rt.LinearFoundation.paper()])
def test_a_speed_sweep_equals_single_solves(law):
    speeds = np.array([10.0, 45.0, 120.0, 300.0])
    result = sweep(TRACK, TRAIN, law, 15, speed=speeds)        # single() is at m = 15
    assert result.converged.all() and (result.residual <= 1e-10).all()
    for i, v in enumerate(speeds):
        reference = single(TRACK, TRAIN.replace(speed=v), law)
        scale = np.abs(reference.coefficients).max()
        assert np.abs(result.coefficients[i] - reference.coefficients).max() < 1e-10 * scale
        t = np.linspace(0.0, reference.period, 20000, endpoint=False)
        assert result.lowest[i] == pytest.approx(reference.sleeper_displacement(t).min(), rel=1e-4)
        assert result.seat_load_peak[i] == pytest.approx(reference.rail_seat_load(t).max(), rel=1e-4)
        assert result.foundation_force_peak[i] == pytest.approx(reference.foundation_force(t).max(), rel=1e-4)


def test_sweeping_two_law_fields_together_equals_single_solves():
    k2, eta = np.array([15e6, 20e6, 30e6]), np.array([1e5, 2e5, 5e4])
    result = sweep(TRACK, TRAIN, rt.CubicFoundation.paper(), 15, stiffness=k2, damping=eta)
    for i in range(3):
        reference = single(TRACK, TRAIN, rt.CubicFoundation(k2[i], 2e13, 0.8, eta[i]))
        assert np.abs(result.coefficients[i] - reference.coefficients).max() < 1e-10 * np.abs(
            reference.coefficients).max()
    member = result.solution(1)
    assert member.converged and member.foundation.stiffness == 20e6
    # the member's own rail and forces come with it: the mean balance holds
    t = np.linspace(0.0, member.period, 4096, endpoint=False)
    assert member.rail_seat_load(t).mean() == pytest.approx(TRACK.sleeper_spacing * 150e3 / 18.0)


def test_a_member_that_fails_is_reported_not_dropped():
    # zero Newton steps: only the linear law's start (exact) is converged
    result = sweep(TRACK, TRAIN, rt.CubicFoundation.paper(), max_iterations=0, epsilon=[0.0, 0.8])
    assert result.converged.tolist() == [True, False]
    assert len(result) == 2 and np.isfinite(result.coefficients).all()
    assert "did not converge" in result.solution(1).message


@pytest.mark.parametrize("values, error, match", [
    (dict(), TypeError, "at least one field"),
    (dict(wheel_load=[1.0]), TypeError, "cannot sweep 'wheel_load'"),
    (dict(speed=[[1.0, 2.0]]), ValueError, "1-D"),
    (dict(speed=[10.0, 20.0], damping=[1.0]), ValueError, "equal lengths"),
    (dict(speed=[10.0, -1.0]), ValueError, "speed"),
])
def test_bad_sweeps_say_what_is_wrong(values, error, match):
    with pytest.raises(error, match=match):
        sweep(TRACK, TRAIN, rt.CubicFoundation.paper(), **values)


def test_a_callable_law_is_refused_with_the_reason():
    with pytest.raises(TypeError, match="dataclass foundation"):
        sweep(TRACK, TRAIN, lambda w, v: 2e7 * w, speed=[45.0])
