"""`rt.sweep` held to the standard of `rt.solve` (issue 18, sections 4 and 6).

Each test failed on main 15e2612.  Truths: `solve`'s own truncation estimate
and its refusals, the Fourier series of a member evaluated on a fine grid,
and a reference solve at a much larger m.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
CUBIC = rt.CubicFoundation.paper()


def test_each_member_reports_the_truncation_error_solve_gives():
    result = rt.sweep(TRACK, TRAIN, CUBIC, 20, speed=[45.0, 200.0])
    for i, v in enumerate((45.0, 200.0)):
        single = rt.solve(TRACK, TRAIN.replace(speed=v), CUBIC, 20)
        assert result.truncation_error[i] == pytest.approx(single.truncation_error, rel=1e-6)
        assert result.solution(i).truncation_error == pytest.approx(single.truncation_error,
                                                                    rel=1e-6)


def test_the_sweep_keeps_its_own_copy_of_the_values():
    speeds = np.array([45.0, 90.0])
    result = rt.sweep(TRACK, TRAIN, CUBIC, 15, speed=speeds)
    kept = result.coefficients[0].copy()
    speeds[0] = 300.0
    assert result.values["speed"][0] == 45.0
    assert result.solution(0).train.speed == 45.0
    single = rt.solve(TRACK, TRAIN, CUBIC, 15)
    assert np.abs(result.solution(0).coefficients - single.coefficients).max() < 1e-10 * np.abs(
        single.coefficients).max()
    assert np.array_equal(result.coefficients[0], kept)


@pytest.mark.parametrize("harmonics", [100, 130])
def test_extremes_are_read_finely_enough_at_large_m(harmonics):
    """m >= 129 crashed (a fixed 256-point grid); at m = 100 the grid cost 2.5e-4 of the peak."""
    law = rt.BilinearFoundation.paper(0.0)
    result = rt.sweep(TRACK, TRAIN, law, harmonics, speed=[45.0, 300.0])
    for i in range(2):
        t, w = result.solution(i).one_period(2**16)
        assert result.lowest[i] == pytest.approx(w.min(), rel=1e-5)
        assert result.highest[i] == pytest.approx(w.max(), rel=1e-5)


def test_a_member_that_solve_refuses_is_refused():
    with pytest.raises(ValueError, match="member 1 .*rail_linear_mass = 1e-50.*loses accuracy"):
        rt.sweep(TRACK, TRAIN, CUBIC, 15, rail_linear_mass=[60.0, 1e-50])
    with pytest.raises(ValueError, match="loses accuracy"):
        rt.solve(TRACK.replace(rail_linear_mass=1e-50), TRAIN, CUBIC, 15)


def test_a_sweep_too_large_for_memory_is_refused_before_allocating():
    with pytest.raises(ValueError, match=r"2000000 members at m = 15 .* parts of at most \d+"):
        rt.sweep(TRACK, TRAIN, CUBIC, 15, speed=np.full(2_000_000, 45.0))


@pytest.mark.parametrize("values", [dict(speed=["45", "90"]), dict(speed=[True, False]),
                                    dict(epsilon=[True]), dict(damping=[1e5, None])])
def test_strings_and_booleans_are_refused(values):
    with pytest.raises(ValueError, match="real numbers"):
        rt.sweep(TRACK, TRAIN, CUBIC, 15, **values)


def test_an_explicit_m_that_falls_short_warns():
    """The paper's m = 15 on a 60 m wagon misses about a quarter of the peak."""
    with pytest.warns(rt.TruncationWarning, match="harmonics=15"):
        rt.sweep(TRACK, TRAIN.replace(wagon_length=60.0), rt.LinearFoundation.paper(), 15,
                 speed=[45.0, 100.0])


def test_the_default_m_meets_the_accuracy_of_solve_auto():
    """Default ("auto") on a 60 m wagon: within the 1e-3 target of a 400-harmonic solve."""
    train = TRAIN.replace(wagon_length=60.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = rt.sweep(TRACK, train, CUBIC, speed=[45.0, 100.0])
    assert (result.truncation_error <= 1e-3).all()
    for i, v in enumerate((45.0, 100.0)):
        reference = rt.solve(TRACK, train.replace(speed=v), CUBIC, 400)
        t = np.linspace(0.0, reference.period, 8192, endpoint=False)
        w_ref = reference.sleeper_displacement(t)
        error = np.abs(result.solution(i).sleeper_displacement(t) - w_ref).max()
        assert error <= 2e-3 * np.abs(w_ref).max()


def test_unconverged_members_warn():
    with pytest.warns(rt.ConvergenceWarning, match="1 of 2 members"):
        rt.sweep(TRACK, TRAIN, CUBIC, 15, max_iterations=0, epsilon=[0.0, 0.8])
