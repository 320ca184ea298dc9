"""Each failure mode a new user met has one clear outcome (issue 7, section 2).

Every test here failed on the code before the fix: an IndexError from deep
inside, a "converged" answer to an unstable track, a silently ignored
option, a wrong number with a tiny residual.
"""

import warnings

import numpy as np
import pytest

from railtrack import (
    BilinearFoundation,
    ConvergenceError,
    CubicFoundation,
    LinearFoundation,
    Passage,
    Track,
    Train,
    simulate_time_domain,
    solve,
)
from railtrack.solvers.conditioning import roundoff_estimate
from railtrack.equations.harmonic_balance import harmonic_system

PAPER = Track.paper()
TRAIN = Train.paper()
CUBIC = CubicFoundation.paper(0.8)
LINEAR = LinearFoundation.paper()


# --- samples: the rule N > 4m is stated up front --------------------------------------

@pytest.mark.parametrize("samples", [31, 40, 60])
def test_too_few_samples_are_refused_with_the_rule(samples):
    with pytest.raises(ValueError, match=r"samples must be an integer > 4 \* harmonics = 60"):
        solve(PAPER, TRAIN, CUBIC, 15, samples=samples)


def test_the_smallest_allowed_samples_work_for_newton():
    solution = solve(PAPER, TRAIN, CUBIC, 15, samples=61)
    reference = solve(PAPER, TRAIN, CUBIC, 15)
    # N > 4m is exact for the cubic law: same answer as the default N = 256
    np.testing.assert_allclose(solution.coefficients, reference.coefficients, rtol=0, atol=1e-13)


# --- divergence is a result -----------------------------------------------------------

def test_diverging_fixed_point_is_reported_not_raised():
    solution = solve(PAPER, TRAIN, CUBIC, 15, method="fixed-point", split=0)
    assert not solution.converged
    assert "diverged" in solution.message and "iteration" in solution.message


def test_diverging_fixed_point_under_strict_raises_convergence_error():
    with pytest.raises(ConvergenceError, match="diverged") as info:
        solve(PAPER, TRAIN, CUBIC, 15, method="fixed-point", split=0, strict=True)
    assert "Diverging harmonics" in str(info.value)


def test_overflowing_law_during_the_iteration_is_divergence_not_a_bad_law():
    heavy = Train.paper(wheel_load=5e9)
    law = CubicFoundation.paper(epsilon=1e3)
    solution = solve(PAPER, heavy, law, 15, method="fixed-point", split="auto")
    assert not solution.converged and "diverged" in solution.message
    assert "no split N0" in solution.message
    with pytest.raises(ConvergenceError, match="no split N0 in 0..15"):
        solve(PAPER, heavy, law, 15, method="fixed-point", split="auto", strict=True)


def test_slow_fixed_point_is_slow_not_diverging():
    with pytest.raises(ConvergenceError) as info:
        solve(PAPER, TRAIN, CUBIC, 15, method="fixed-point", max_iterations=5, strict=True)
    text = str(info.value)
    assert "Diverging" not in text and "diverged" not in text
    assert "did not converge: not converged" not in text


def test_failed_newton_names_harmonics():
    with pytest.raises(ConvergenceError, match=r"Largest residuals at harmonics n = \[\d"):
        solve(PAPER, TRAIN, CUBIC, 15, max_iterations=1, strict=True)


# --- a law that makes the track unstable ------------------------------------------------

@pytest.mark.parametrize(
    "law, what",
    [
        (lambda w, v: -(20e6 * w + 0.2e6 * v), "negative stiffness"),
        (lambda w, v: 20e6 * w - 0.2e6 * v, "negative damping"),
    ],
)
def test_law_unstable_at_rest_is_refused(law, what):
    with pytest.raises(ValueError, match=what) as info:
        solve(PAPER, TRAIN, law, 15)
    assert "check_foundation=False" in str(info.value)


def test_the_refused_law_is_indeed_unstable_in_the_time_domain():
    # the truth behind the refusal: the same track integrated in time does not settle
    law = lambda w, v: 20e6 * w - 0.2e6 * v  # noqa: E731
    unchecked = solve(PAPER, TRAIN, law, 15, check_foundation=False)
    assert unchecked.converged    # harmonic balance alone would have accepted it
    try:
        result = simulate_time_domain(PAPER, TRAIN, law, 2, 480, max_periods=6)
    except (RuntimeError, ValueError):
        return
    assert not result.converged


def test_softening_law_positive_at_rest_passes():
    softening = lambda w, v: 20e6 * w - 1e12 * w**3 + 0.2e6 * v  # noqa: E731
    assert solve(PAPER, TRAIN, softening, 15).converged


# --- a callable that returns the wrong thing ---------------------------------------------

@pytest.mark.parametrize(
    "law",
    [
        lambda w, v: 5.0,
        lambda w, v: None,
        lambda w, v: (2e7 * w)[:, None],
        lambda w, v: (2e7 * w)[:-1],
    ],
    ids=["scalar", "None", "column", "shorter"],
)
def test_law_with_a_wrong_return_says_what_it_returned(law):
    with pytest.raises(ValueError, match=r"must return a real array shaped like w.*it returned"):
        solve(PAPER, TRAIN, law, 15)


# --- initial, max_iterations, analytic, tol --------------------------------------------

def test_non_finite_initial_is_blamed_on_initial():
    start = np.zeros(16, dtype=complex)
    start[3] = np.nan
    with pytest.raises(ValueError, match=r"initial must be finite.*\[3\]"):
        solve(PAPER, TRAIN, CUBIC, 15, initial=start)


def test_imaginary_mean_in_initial_is_refused():
    start = np.zeros(16, dtype=complex)
    start[0] = -2e-4 + 1e-5j
    with pytest.raises(ValueError, match="initial.*real"):
        solve(PAPER, TRAIN, CUBIC, 15, initial=start)


@pytest.mark.parametrize("method", ["newton", "fixed-point"])
def test_zero_iterations_means_zero(method):
    solution = solve(PAPER, TRAIN, CUBIC, 15, method=method, max_iterations=0)
    assert solution.iterations == 0 and len(solution.residual_history) == 1
    assert not solution.converged


def test_analytic_warns_about_what_it_ignores():
    with pytest.warns(UserWarning, match="tol, max_iterations, initial not used"):
        solve(PAPER, TRAIN, LINEAR, 15, method="analytic", tol=1e-5, max_iterations=3,
              initial=np.zeros(16))


def test_analytic_is_not_converged_when_its_residual_is_not_finite(monkeypatch):
    import sys
    monkeypatch.setattr(sys.modules["railtrack.solvers.solve"], "residual_norm",
                        lambda system, values: float("nan"))
    assert not solve(PAPER, TRAIN, LINEAR, 15, method="analytic").converged


@pytest.mark.parametrize("tol", [0, 0.0, 1, 1.5, -1e-3, float("nan"), "1e-3", True, 1e-3j])
def test_tol_must_be_between_zero_and_one(tol):
    with pytest.raises(ValueError, match="tol"):
        solve(PAPER, TRAIN, LINEAR, 15, tol=tol)


# --- types of the parameters -------------------------------------------------------------

@pytest.mark.parametrize("value", ["45", 45 + 0j, True, None, [45.0, "x"]])
def test_train_refuses_non_real_values_naming_the_field(value):
    with pytest.raises((TypeError, ValueError), match="speed"):
        Train.paper(speed=value)


@pytest.mark.parametrize(
    "make", [lambda: LinearFoundation("2e7"), lambda: BilinearFoundation(2e7, True),
             lambda: CubicFoundation(2e7, 2e13, 0.8 + 0j)],
)
def test_foundations_refuse_non_real_values(make):
    with pytest.raises(TypeError, match="must be a real number"):
        make()


def test_single_precision_fields_are_computed_in_double():
    single = Train.paper(speed=np.float32(45.1), wheel_load=np.float32(75e3))
    assert type(single.speed) is float
    assert all(type(load) is float for load in single.axle_loads)
    double = Train.paper(speed=float(np.float32(45.1)))
    np.testing.assert_array_equal(solve(PAPER, single, CUBIC, 15).coefficients,
                                  solve(PAPER, double, CUBIC, 15).coefficients)


# --- a pure cubic law: no stiffness at rest ------------------------------------------------

def test_pure_cubic_law_starts_from_the_static_mean():
    pure = lambda w, v: 2e13 * w**3 + 0.2e6 * v  # noqa: E731
    system = harmonic_system(Passage(PAPER, TRAIN), pure, 15)
    from railtrack.solvers.newton import linear_guess
    mean = linear_guess(system)[0].real
    # the foundation alone carries 2 Q L / H = 5 kN at the mean: 2e13 w^3 = -5e3
    assert mean == pytest.approx(-(5e3 / 2e13) ** (1 / 3), rel=1e-12)
    solution = solve(PAPER, TRAIN, pure, 15)
    assert solution.converged and solution.iterations <= 10


# --- round-off: formulas outside the range where they are accurate --------------------------

@pytest.mark.parametrize("changes", [{"rail_linear_mass": 1e-50}, {"speed": 1e-12},
                                     {"rail_linear_mass": 1e-25}, {"speed": 1e-9}])
def test_nearly_massless_rail_or_still_train_is_refused(changes):
    passage = Passage.paper(**changes)
    with pytest.raises(ValueError, match="loses accuracy.*speed >=.*rail_linear_mass >="):
        solve(passage.track, passage.train, LINEAR, 15)


@pytest.mark.parametrize(
    "changes, reference",
    [({"speed": 1e-7}, {"speed": 1e-5}), ({"speed": 3e-8}, {"speed": 1e-5}),
     ({"rail_linear_mass": 1e-14}, {"rail_linear_mass": 1e-9}),
     ({"rail_linear_mass": 1e-16}, {"rail_linear_mass": 1e-9})],
)
def test_roundoff_estimate_bounds_the_actual_error(changes, reference):
    # the references are physically the same quasi-static (or massless) track,
    # computed where eq. (3) loses nothing
    passage, exact = Passage.paper(**changes), Passage.paper(**reference)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        w = solve(passage.track, passage.train, LINEAR, 15, method="analytic").one_period(2000)[1]
        w_exact = solve(exact.track, exact.train, LINEAR, 15, method="analytic").one_period(2000)[1]
    actual = np.max(np.abs(w - w_exact)) / np.max(np.abs(w_exact))
    assert actual <= roundoff_estimate(passage) <= 5 * actual, (actual, roundoff_estimate(passage))
