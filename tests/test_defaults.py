"""Defaults that cannot be silently wrong (issue 18, sections 4 and 6): `continuation`
chooses m itself and warns when an explicit m falls short; an unconverged `solve`
warns; where Newton stalls, `solve` follows the branch up from a lower speed.

The fold case is chapter 10's: `Track.paper(pad_damping=1e5)`,
`CubicFoundation(20e6, 2e13, 0.8, 5000)`, the paper's wagon, 300-700 m/s.
Its folds converged in m are taken from a branch at m = 40, twice the m
that the solver predicts, against which the defaults are judged.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt

TRACK = rt.Track.paper(pad_damping=1e5)
LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000)


def _branch(harmonics, start=300.0, stop=700.0):
    return rt.continuation(TRACK, rt.Train.paper(speed=start), LAW, "speed", start=start,
                           stop=stop, harmonics=harmonics)


@pytest.fixture(scope="module")
def reference():
    """The branch at m = 40: its folds are converged in m to well below 0.1 m/s."""
    return _branch(40)


@pytest.fixture(scope="module")
def default_branch():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        branch = rt.continuation(TRACK, rt.Train.paper(speed=300.0), LAW, "speed",
                                 start=300.0, stop=700.0)
    return branch, caught


def test_default_continuation_places_the_folds_within_1_m_s(reference, default_branch):
    branch, caught = default_branch
    assert len(reference.folds) == 4
    assert len(branch.folds) == 4
    assert np.abs(branch.fold_values - reference.fold_values).max() < 1.0
    assert not [w for w in caught if issubclass(w.category, rt.TruncationWarning)]


def test_default_continuation_reports_m_and_meets_the_accuracy(default_branch):
    branch, _ = default_branch
    assert f"m = {branch.harmonics}" in branch.message
    worst = max(branch.solution(i).truncation_error for i in range(0, len(branch), 4))
    assert worst <= 1e-3


def test_an_explicit_m_that_falls_short_warns():
    """m = 15 puts the third fold 2 m/s off and its worst point is > 3 % off."""
    with pytest.warns(rt.TruncationWarning, match="harmonics=15"):
        _branch(15, stop=560.0)


def test_continuation_accepts_auto_explicitly():
    branch = rt.continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
                             "speed", start=40.0, stop=60.0, harmonics="auto")
    exact = rt.solve(rt.Track.paper(), rt.Train.paper(speed=60.0), rt.LinearFoundation.paper(),
                     branch.harmonics, method="analytic")
    assert np.allclose(branch.coefficients[-1], exact.coefficients[branch.harmonics:],
                       rtol=0, atol=1e-9 * np.abs(exact.coefficients).max())


def test_continuation_down_from_620_m_s_passes_the_same_folds(reference):
    """Started where Newton from the linear guess fails, going down: not a one-point branch."""
    branch = _branch(40, start=620.0, stop=480.0)
    assert branch.message.startswith("reached speed = 480.0")
    # going down it meets 513.1, then 541.2, and crosses 480 before the fold at 470
    assert np.allclose(branch.fold_values, reference.fold_values[[3, 2]], atol=0.05)


def test_a_branch_that_ends_early_warns():
    with pytest.warns(rt.ConvergenceWarning, match="ended early"):
        branch = rt.continuation(
            TRACK, rt.Train.paper(speed=300.0), LAW, "speed", start=300.0, stop=700.0,
            harmonics=25, max_points=5)
    assert len(branch) == 5


def test_continuation_reaches_the_edge_of_the_valid_range():
    """epsilon = 0 is the smallest valid value; there the law is linear, eq. (23)."""
    law = rt.CubicFoundation.paper()
    branch = rt.continuation(rt.Track.paper(), rt.Train.paper(), law, "epsilon",
                             start=0.8, stop=0.0, harmonics=25)
    assert branch.message.startswith("reached epsilon = 0.0")
    assert branch.values[-1] == 0.0
    exact = rt.analytic_coefficients(rt.Passage(rt.Track.paper(), rt.Train.paper()),
                                     rt.LinearFoundation(law.stiffness, law.damping), 25)
    assert np.abs(branch.coefficients[-1] - exact[25:]).max() < 1e-9 * np.abs(exact).max()


def test_an_unconverged_solve_warns_and_strict_raises():
    args = (TRACK, rt.Train.paper(speed=600.0), LAW, 25)
    with pytest.warns(rt.ConvergenceWarning, match="did not converge"):
        assert not rt.solve(*args, fallback=False).converged
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rt.ConvergenceError):
            rt.solve(*args, fallback=False, strict=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.simplefilter("ignore", rt.ConvergenceWarning)
        rt.solve(*args, fallback=False)            # silenced by the user: no error


def test_an_explicit_budget_of_steps_that_runs_out_is_quiet():
    """The paper's k fixed-point steps: the caller chose the budget; converged=False says it."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        k15 = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper(), 15,
                       method="fixed-point", max_iterations=15)
    assert not k15.converged and k15.iterations == 15


def test_where_newton_stalls_the_warning_names_continuation():
    with pytest.warns(rt.ConvergenceWarning, match=r"rt\.continuation\(.*start=300, stop=600"):
        solution = rt.solve(TRACK, rt.Train.paper(speed=600.0), LAW, 25, fallback=False)
    assert not solution.converged


@pytest.fixture(scope="module")
def branch_25():
    return _branch(25, stop=620.0)


@pytest.mark.parametrize("speed", [545.0, 570.0, 600.0])
def test_solve_reaches_the_single_solution_above_the_folds(branch_25, speed):
    """545-600 m/s: one solution, which Newton from the linear guess misses."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        solution = rt.solve(TRACK, rt.Train.paper(speed=speed), LAW, 25)
    assert solution.converged
    assert "continuation in speed" in solution.message
    (start,) = branch_25.solutions_at(speed)        # the branch crosses this speed once
    polished = rt.solve(TRACK, rt.Train.paper(speed=speed), LAW, 25, initial=start)
    assert polished.converged
    assert np.abs(solution.coefficients - polished.coefficients).max() < 1e-9 * np.abs(
        polished.coefficients).max()


def test_auto_short_of_its_accuracy_fails_and_does_not_advise_auto():
    # 'auto' stopped short is a failure (converged=False), whose advice is not 'auto' again
    with pytest.warns(rt.ConvergenceWarning, match="fell short") as caught:
        result = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
                          method="analytic", accuracy=1e-13)
    assert not result.converged and result.truncation_error > 1e-13
    assert "use 'auto'" not in str(caught[0].message)
