"""Eqs. (17)–(23): the AFT residual, the fixed point, Newton and the analytic solution.

Oracles: eq. (23) for the linear law (and the nonlinear laws reduced to it),
the static balance of the mean, exact convolution for polynomial laws,
finite differences for the Jacobian, linear scaling with the load, and the
residual of eq. (17) re-evaluated on a much finer time grid.
"""

import numpy as np
import pytest

from railtrack import (
    BilinearFoundation,
    CubicFoundation,
    LinearFoundation,
    Passage,
    Track,
    Train,
    analytic_coefficients,
    solve,
    sweep_speeds,
)
from railtrack.solvers.fixed_point import automatic_split, contraction_factors
from railtrack.equations.aft_jacobian import residual_jacobian
from railtrack.equations.harmonic_balance import (
    from_real,
    harmonic_system,
    nonlinear_coefficients,
    residual,
    residual_norm,
    to_real,
    two_sided,
)

TRACK = Track.paper()
TRAIN = Train.paper()
PASSAGE = Passage(TRACK, TRAIN)
LINEAR = LinearFoundation.paper()
NONLINEAR = {
    "bilinear 0.5": BilinearFoundation.paper(0.5),
    "tensionless": BilinearFoundation.paper(0.0),
    "cubic 0.8": CubicFoundation.paper(0.8),
}


@pytest.fixture(scope="module")
def analytic():
    return analytic_coefficients(PASSAGE, LINEAR, 15)


def test_mean_displacement_is_static_balance(analytic):
    # mean train weight per sleeper 2QL/H carried by the foundation spring alone
    expected = -2 * TRAIN.wheel_load * TRACK.sleeper_spacing / (TRAIN.wagon_length * LINEAR.stiffness)
    assert analytic[15].real == pytest.approx(expected, rel=1e-13)
    assert analytic[15].imag == 0.0
    assert solve(TRACK, TRAIN, LINEAR, 15).mean_displacement == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize("method", ["newton", "fixed-point"])
def test_iterative_methods_reproduce_eq23(method, analytic):
    solution = solve(TRACK, TRAIN, LINEAR, 15, method=method, max_iterations=400)
    assert solution.converged
    np.testing.assert_allclose(solution.coefficients, analytic, rtol=0, atol=1e-9 * abs(analytic[15]))


@pytest.mark.parametrize(
    "law",
    [
        CubicFoundation(LINEAR.stiffness, 2e13, 0.0, LINEAR.damping),
        BilinearFoundation(LINEAR.stiffness, LINEAR.stiffness, LINEAR.damping),
    ],
    ids=["cubic eps=0", "bilinear e=1"],
)
@pytest.mark.parametrize("method", ["newton", "fixed-point"])
def test_nonlinear_laws_reduce_to_linear(law, method, analytic):
    solution = solve(TRACK, TRAIN, law, 15, method=method, max_iterations=400)
    assert solution.converged
    np.testing.assert_allclose(solution.coefficients, analytic, rtol=0, atol=1e-9 * abs(analytic[15]))


def test_linear_response_scales_with_load_and_cubic_does_not():
    heavy = Train.paper(wheel_load=2 * TRAIN.wheel_load)
    linear = solve(TRACK, TRAIN, LINEAR, 15).coefficients
    np.testing.assert_allclose(solve(TRACK, heavy, LINEAR, 15).coefficients, 2 * linear, rtol=1e-9, atol=1e-15)
    cubic = CubicFoundation.paper(0.8)
    light, double = solve(TRACK, TRAIN, cubic, 15), solve(TRACK, heavy, cubic, 15)
    ratio = double.mean_displacement / light.mean_displacement
    assert 1.2 < ratio < 1.95  # hardening: doubling the load less than doubles the mean


def test_hardening_reduces_the_peak():
    peaks = [solve(TRACK, TRAIN, CubicFoundation.paper(eps), 15).one_period(800)[1].min() for eps in (0, 0.4, 0.8)]
    assert peaks[0] < peaks[1] < peaks[2] < 0


@pytest.mark.parametrize("name", sorted(NONLINEAR))
def test_newton_converges_and_fine_grid_residual_is_small(name):
    law = NONLINEAR[name]
    solution = solve(TRACK, TRAIN, law, 15, strict=True)
    assert solution.residual <= 1e-10
    assert solution.iterations <= 10
    # eq. (17) re-evaluated with 16x more AFT samples: only aliasing remains
    fine = harmonic_system(PASSAGE, law, 15, samples=4096)
    assert residual_norm(fine, residual(fine, solution.coefficients[15:])) < 1e-4


@pytest.mark.parametrize("name", sorted(NONLINEAR))
def test_fixed_point_agrees_with_newton(name):
    law = NONLINEAR[name]
    newton = solve(TRACK, TRAIN, law, 15)
    fixed = solve(TRACK, TRAIN, law, 15, method="fixed-point", max_iterations=3000, tol=1e-9)
    assert fixed.converged
    np.testing.assert_allclose(fixed.coefficients, newton.coefficients, rtol=0, atol=1e-8 * 1e-3)


def test_tensionless_foundation_never_pulls():
    solution = solve(TRACK, TRAIN, BilinearFoundation.paper(0.0), 15)
    t = np.linspace(0, TRAIN.period, 2000, endpoint=False)
    w = solution.sleeper_displacement(t)
    assert w.max() > 0  # the sleeper does lift off ...
    spring = solution.foundation.force(w, 0 * w)
    assert np.all(spring[w >= 0] == 0)  # ... and the foundation then carries nothing


def test_aft_of_polynomial_equals_exact_convolution():
    m = 6
    rng = np.random.default_rng(7)
    c = (rng.normal(size=m + 1) + 1j * rng.normal(size=m + 1)) * 1e-4
    c[0] = c[0].real
    mass = TRACK.sleeper_mass
    # g = (a w^2 + b w^3) / M: harmonics up to 3m, so 4m + 1 samples avoid aliasing
    law = lambda w, v: 3e10 * w**2 + 2e13 * w**3  # noqa: E731
    system = harmonic_system(PASSAGE, law, m, samples=4 * m + 1)
    full = two_sided(c)
    square = np.convolve(full, full)
    cube = np.convolve(square, full)
    # two-sided index i holds harmonic i - 2m (square) and i - 3m (cube)
    expected = (3e10 * square[2 * m : 3 * m + 1] + 2e13 * cube[3 * m : 4 * m + 1]) / mass
    got = nonlinear_coefficients(system, c)
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())


@pytest.mark.parametrize(
    "law",
    [CubicFoundation.paper(0.8), BilinearFoundation.paper(0.3), lambda w, v: 2e7 * w + 5e9 * v * np.abs(v)],
    ids=["cubic", "bilinear", "callable quadratic damping"],
)
def test_jacobian_matches_finite_differences(law):
    system = harmonic_system(PASSAGE, law, 8)
    rng = np.random.default_rng(3)
    c = (rng.normal(size=9) + 1j * rng.normal(size=9)) * 1e-4
    c[0] = -3e-4
    x = to_real(c)
    jacobian = residual_jacobian(system, c)
    numeric = np.empty_like(jacobian)
    for k in range(len(x)):
        h = 1e-7 * np.abs(x).max()
        xp, xm = x.copy(), x.copy()
        xp[k] += h
        xm[k] -= h
        numeric[:, k] = (to_real(residual(system, from_real(xp))) - to_real(residual(system, from_real(xm)))) / (2 * h)
    # the bilinear kink may fall inside [x - h, x + h] for a few samples: O(h) error
    np.testing.assert_allclose(jacobian, numeric, rtol=0, atol=1e-4 * np.abs(jacobian).max())


def test_linear_fixed_point_error_shrinks_by_the_predicted_factor(analytic):
    system = harmonic_system(PASSAGE, LINEAR, 15)
    factors = contraction_factors(system, 15)
    errors = []
    for k in (3, 4):  # few steps, so that even the fast harmonics are above round-off
        c = solve(TRACK, TRAIN, LINEAR, 15, method="fixed-point", max_iterations=k).coefficients
        errors.append(np.abs(c[15:] - analytic[15:]))
    measured = errors[1] / errors[0]
    # where the load vanishes (n = 3, 9, 15) the error is zero from the start
    alive = errors[0] > 1e-14 * np.abs(analytic).max()
    np.testing.assert_allclose(measured[alive], factors[alive], rtol=1e-6)
    # and the mean converges slowest: factor 1 - k2/k1 (Section 4.1)
    assert factors[0] == pytest.approx(1 - LINEAR.stiffness / TRACK.pad_stiffness, rel=1e-12)


def test_automatic_split_gives_a_convergent_iteration():
    system = harmonic_system(PASSAGE, LINEAR, 15)
    assert contraction_factors(system, automatic_split(system)).max() < 1
    assert contraction_factors(system, 0).max() > 1  # the small-N0 choice diverges
    diverging = solve(TRACK, TRAIN, LINEAR, 15, method="fixed-point", split=0, max_iterations=50)
    assert not diverging.converged
    assert diverging.residual_history[-1] > diverging.residual_history[0]


def test_sweep_equals_individual_solves():
    speeds = np.array([20.0, 45.0, 70.0])
    batch = sweep_speeds(TRACK, TRAIN, LINEAR, speeds, 15)
    for speed, row in zip(speeds, batch):
        single = solve(TRACK, Train.paper(speed=speed), LINEAR, 15, method="analytic").coefficients
        np.testing.assert_allclose(row, single, rtol=1e-12, atol=1e-18)


def test_time_histories_are_consistent():
    solution = solve(TRACK, TRAIN, CubicFoundation.paper(0.8), 15)
    t = np.linspace(0, TRAIN.period, 512, endpoint=False)
    w = solution.sleeper_displacement(t)
    assert w.mean() == pytest.approx(solution.mean_displacement, rel=1e-12)
    assert solution.sleeper_displacement(t + TRAIN.period) == pytest.approx(w, abs=1e-15)
    dt = 1e-6
    velocity = (solution.sleeper_displacement(t + dt) - solution.sleeper_displacement(t - dt)) / (2 * dt)
    np.testing.assert_allclose(solution.sleeper_velocity(t), velocity, atol=1e-6 * np.abs(velocity).max())
    # the mean pad force is the mean train weight per sleeper: rail mean = sleeper mean - 2QL/(H k1)
    rail = solution.rail_displacement(t)
    assert rail.mean() == pytest.approx(
        w.mean() - PASSAGE.static_load_per_sleeper / TRACK.pad_stiffness, rel=1e-10
    )
    assert rail.min() < w.min()  # the rail deflects more than the sleeper under the wheel


def test_peak_is_near_the_wheels():
    solution = solve(TRACK, TRAIN, LINEAR, 15, method="analytic")
    t = np.linspace(0, TRAIN.period, 4000, endpoint=False)
    t_min = t[np.argmin(solution.sleeper_displacement(t))]
    # the deepest point falls between the two wheel passages (0 and D/v), delayed by the dynamics
    assert 0.0 <= t_min <= TRAIN.wheel_spacing / TRAIN.speed + 0.02


@pytest.mark.parametrize("ratio", [0.5, 0.0])
def test_factor_from_the_solution_estimates_the_bilinear_rate_better(ratio):
    law = BilinearFoundation.paper(ratio)
    system = harmonic_system(PASSAGE, law, 15)
    history = solve(TRACK, TRAIN, law, 15, method="fixed-point", max_iterations=300).residual_history
    observed = (history[300] / history[200]) ** (1 / 100)  # asymptotic rate of eq. (21)
    at_rest = contraction_factors(system, 15)[0]
    along_solution = contraction_factors(system, 15, solve(TRACK, TRAIN, law, 15).coefficients[15:])[0]
    assert abs(along_solution - observed) < abs(at_rest - observed)
    assert at_rest < along_solution < observed  # tension is softer: slower than k2+ predicts


def test_sweep_extremes_equal_the_extremes_of_single_solves():
    from railtrack import sweep_extremes
    speeds = [20.0, 45.0, 300.0]
    low, high = sweep_extremes(TRACK, TRAIN, LINEAR, speeds, 60)
    for v, lo, hi in zip(speeds, low, high):
        w = solve(TRACK, Train.paper(speed=v), LINEAR, 60, method="analytic").one_period(2048)[1]
        assert lo == pytest.approx(w.min(), rel=1e-12) and hi == pytest.approx(w.max(), rel=1e-12)
