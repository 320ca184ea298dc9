"""Newton's method for a cell of N sleepers on their own laws (issue 19, third block).

Independent truths used here:
* today's N = 1 solver (`railtrack.solve`, its own residual, Jacobian and guess);
* today's travelling wave for N identical nonlinear sleepers: sleeper j is
  sleeper 0 delayed by jL/v.  On the AFT's time grid this holds to round-off
  only if the delay is a whole number of samples (samples a multiple of
  H/L = 30): for a law with a kink the AFT's aliasing differs otherwise;
* the linear cell of the second block (`cell_linear_coefficients`, solved in
  Floquet modes, no AFT);
* the Jacobian against central differences of the residual;
* statics: the foundations carry, on average, the train's mean weight per sleeper.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.cell_harmonic_balance import (
    cell_jacobian,
    cell_operators,
    cell_residual,
    pack_harmonics,
)
from railtrack.equations.cell_linear import LinearCell, cell_linear_coefficients
from railtrack.model.cell import SleeperCell
from railtrack.model.foundations import BilinearFoundation, CubicFoundation, LinearFoundation
from railtrack.model.passage import Passage
from railtrack.solvers.cell_newton import solve_cell
from railtrack.solvers.cell_step import newton_step

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
PAPER = Passage(TRACK, TRAIN)
LAWS = [CubicFoundation.paper(), BilinearFoundation.paper(ratio=0.5)]
K2, ETA2 = 20e6, 0.2e6


def gap_law(gap):
    """A sleeper hanging `gap` [m] above the ballast: it pushes on it only when w < -gap.

    f = min(k2 (w + g) + eta2 w', 0): compression only (f < 0, w positive upward),
    continuous.  (The law k2 min(w + g, 0) + eta2 w' [w + g < 0] jumps by
    eta2 w' at contact; Newton's generalised Jacobian, here and in
    `railtrack.solve` for N = 1, then often stalls.)
    """
    return lambda w, v: np.minimum(K2 * (w + gap) + ETA2 * v, 0.0)


def today(law, m, samples=None):
    solution = rt.solve(TRACK, TRAIN, law, harmonics=m, samples=samples, tol=1e-13,
                        stability="off", fallback=False)
    assert solution.converged
    return solution.coefficients


def delayed(coefficients, n):
    m = (coefficients.size - 1) // 2
    omega = PAPER.harmonic_frequencies(m)
    j = np.arange(n)[:, None]
    return coefficients * np.exp(-1j * omega * j * PAPER.sleeper_spacing / PAPER.speed)


@pytest.mark.parametrize("law", LAWS + [gap_law(0.5e-3)])
def test_one_sleeper_is_todays_solve(law):
    m = 15
    expected = today(law, m)
    result = solve_cell(PAPER, SleeperCell.identical(PAPER, law, 1), m, tol=1e-13)
    assert result.converged and result.residual <= 1e-13, result.message
    np.testing.assert_allclose(result.coefficients[0], expected, rtol=0,
                               atol=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize("n", [3, 30])
def test_identical_nonlinear_sleepers_are_today_delayed(law, n):
    m, samples = 15, 300                       # a delay jL/v = jT/30 is 10 j samples
    expected = delayed(today(law, m, samples), n)
    result = solve_cell(PAPER, SleeperCell.identical(PAPER, law, n), m, tol=1e-12,
                        samples=samples)
    assert result.converged, result.message
    np.testing.assert_allclose(result.coefficients, expected, rtol=0,
                               atol=1e-9 * np.abs(expected).max())


def random_linear_cell(n, seed=19):
    rng = np.random.default_rng(seed)
    return LinearCell(rng.uniform(80, 160, n), rng.uniform(0.5e8, 3e8, n),
                      rng.uniform(0, 2e4, n), rng.uniform(5e6, 6e7, n), rng.uniform(0, 3e5, n))


@pytest.mark.parametrize("passage", [PAPER, Passage.paper(speed=110.0, sleeper_spacing=0.7)])
def test_linear_laws_are_the_linear_cell(passage):
    n, m = 6, 20
    linear = random_linear_cell(n)
    expected = cell_linear_coefficients(passage, linear, m)
    cell = SleeperCell(linear.sleeper_mass, linear.pad_stiffness, linear.pad_damping,
                       [LinearFoundation(k, d) for k, d in zip(linear.stiffness, linear.damping)])
    scale = np.abs(expected).max()
    guessed = solve_cell(passage, cell, m)                  # the linear guess is the answer
    assert guessed.converged and guessed.iterations == 0, guessed.message
    np.testing.assert_allclose(guessed.coefficients, expected, rtol=0, atol=1e-11 * scale)
    # from rest, one step with the exact Jacobian lands on it
    newton = solve_cell(passage, cell, m, tol=1e-11, initial=np.zeros((n, m + 1)))
    assert newton.converged and newton.iterations == 1, newton.message
    np.testing.assert_allclose(newton.coefficients, expected, rtol=0, atol=1e-10 * scale)


def test_jacobian_is_the_derivative_of_the_residual():
    n, m, samples = 4, 6, 64
    linear = random_linear_cell(n, seed=3)
    laws = [CubicFoundation(k, 2e13, 0.8, d) for k, d in zip(linear.stiffness, linear.damping)]
    cell = SleeperCell(linear.sleeper_mass, linear.pad_stiffness, linear.pad_damping, laws)
    omega = PAPER.fundamental_frequency * np.arange(m + 1)
    ops = cell_operators(PAPER, cell.pad_stiffness, cell.pad_damping, omega)
    rng = np.random.default_rng(5)
    c = 1e-3 * (rng.normal(size=(n, m + 1)) + 1j * rng.normal(size=(n, m + 1))) / (1 + np.arange(
        m + 1))
    c[:, 0] = c[:, 0].real
    jacobian = cell_jacobian(cell, c, ops, samples)
    x = np.concatenate([c[:, 0].real, c[:, 1:].T.real.ravel(), c[:, 1:].T.imag.ravel()])
    h = 1e-9
    numeric = np.empty_like(jacobian)
    for i in range(x.size):
        columns = []
        for sign in (1, -1):
            y = x.copy()
            y[i] += sign * h
            trial = np.empty((m + 1, n), dtype=complex)
            trial[0] = y[:n]
            trial[1:] = (y[n:n + m * n] + 1j * y[n + m * n:]).reshape(m, n)
            columns.append(pack_harmonics(cell_residual(cell, trial.T, ops, samples)[0]))
        numeric[:, i] = (columns[0] - columns[1]) / (2 * h)
    np.testing.assert_allclose(jacobian, numeric, rtol=0, atol=1e-6 * np.abs(jacobian).max())


@pytest.mark.parametrize("nonlinear", [(), (2,), (0, 3), (0, 1, 2, 3, 4)])
def test_structured_step_is_the_dense_newton_step(nonlinear):
    """Woodbury on the varying sleepers (cell_step) against the dense Jacobian (cell_jacobian)."""
    n, m, samples = 5, 8, 64
    linear = random_linear_cell(n, seed=4)
    laws = [CubicFoundation(k, 2e13, 0.8, d) if j in nonlinear else LinearFoundation(k, d)
            for j, (k, d) in enumerate(zip(linear.stiffness, linear.damping))]
    cell = SleeperCell(linear.sleeper_mass, linear.pad_stiffness, linear.pad_damping, laws)
    omega = PAPER.fundamental_frequency * np.arange(m + 1)
    ops = cell_operators(PAPER, cell.pad_stiffness, cell.pad_damping, omega)
    rng = np.random.default_rng(6)
    c = 1e-3 * (rng.normal(size=(n, m + 1)) + 1j * rng.normal(size=(n, m + 1)))
    c[:, 0] = c[:, 0].real
    residual = cell_residual(cell, c, ops, samples)[0]
    dense = np.linalg.solve(cell_jacobian(cell, c, ops, samples), -pack_harmonics(residual))
    for limit in (10**6, 0):        # the reduced system solved directly, then by GMRES
        step = newton_step(cell, c, residual, ops, samples, direct_limit=limit)
        np.testing.assert_allclose(pack_harmonics(step.T), dense, rtol=0,
                                   atol=1e-10 * np.abs(dense).max())


@pytest.mark.parametrize("passage", [PAPER, Passage.paper(speed=80.0)])
def test_soft_nonlinear_sleeper_dips_and_the_cell_carries_the_train(passage):
    n, m, soft = 7, 20, 3
    cell = SleeperCell.identical(passage, CubicFoundation.paper(), n).with_sleeper(
        soft, foundation=CubicFoundation(8e6, 2e13, 0.8, 0.2e6))
    result = solve_cell(passage, cell, m)
    assert result.converged, result.message
    weight = passage.static_load_per_sleeper
    mean_force = result.foundation_harmonics[:, m]
    np.testing.assert_allclose(mean_force.imag, 0.0, atol=1e-9 * weight)
    np.testing.assert_allclose(mean_force.real.mean(), -weight, rtol=1e-9)
    # at rest the seat load is the foundation force
    np.testing.assert_allclose(result.seat_harmonics[:, m], mean_force, rtol=1e-12)
    # the soft sleeper carries less than the weight, its neighbours more; it dips most
    assert -mean_force[soft].real < weight < -mean_force[soft - 1].real
    tau = np.linspace(0.0, 1.0, 256, endpoint=False)
    history = (result.coefficients[:, None, :]
               * np.exp(2j * np.pi * tau[:, None] * np.arange(-m, m + 1))).sum(-1).real
    low = history.min(axis=1)
    assert np.argmin(low) == soft and np.argmin(result.coefficients[:, m].real) == soft


def history(coefficients, samples=720):
    m = (coefficients.shape[-1] - 1) // 2
    tau = np.arange(samples) / samples
    return (coefficients[..., None, :]
            * np.exp(2j * np.pi * tau[:, None] * np.arange(-m, m + 1))).sum(-1).real


@pytest.mark.parametrize("gap", [0.5e-3, 1e-3])
def test_hanging_sleeper_loads_its_neighbours(gap):
    n, m, hang, samples = 30, 20, 15, 360         # one hanging sleeper per wagon
    sound_cell = SleeperCell.identical(PAPER, LinearFoundation.paper(), n)
    sound = solve_cell(PAPER, sound_cell, m, samples=samples)
    result = solve_cell(PAPER, sound_cell.with_sleeper(hang, foundation=gap_law(gap)), m,
                        samples=samples)
    assert sound.converged and result.converged, result.message
    weight = PAPER.static_load_per_sleeper
    np.testing.assert_allclose(result.foundation_harmonics[:, m].real.mean(), -weight, rtol=1e-9)
    w = history(result.coefficients)
    velocity = history(result.coefficients * 1j * PAPER.harmonic_frequencies(m))
    contact = np.mean(K2 * (w[hang] + gap) + ETA2 * velocity[hang] < 0)
    assert 0.0 < contact < 1.0
    assert np.argmin(w.min(axis=1)) == hang and w[hang].min() < -gap
    peak = -history(result.seat_harmonics).min(axis=1)          # largest downward rail-seat load
    peak_sound = -history(sound.seat_harmonics).min(axis=1)
    np.testing.assert_allclose(peak_sound, peak_sound[0], rtol=1e-9)     # identical sleepers
    assert peak[hang] < peak_sound[0] < min(peak[hang - 1], peak[hang + 1])
    assert np.argmax(peak) in (hang - 1, hang + 1)


def test_bad_arguments_are_named():
    cell = SleeperCell.identical(PAPER, LAWS[0], 2)
    with pytest.raises(TypeError, match="SleeperCell"):
        solve_cell(PAPER, LAWS[0], 5)
    with pytest.raises(ValueError, match="harmonics"):
        solve_cell(PAPER, cell, 0)
    with pytest.raises(ValueError, match="samples"):
        solve_cell(PAPER, cell, 10, samples=40)
    with pytest.raises(ValueError, match="tol"):
        solve_cell(PAPER, cell, 10, tol=0.0)
    with pytest.raises(ValueError, match="max_iterations"):
        solve_cell(PAPER, cell, 10, max_iterations=-1)
    with pytest.raises(ValueError, match="initial"):
        solve_cell(PAPER, cell, 10, initial=np.zeros((3, 11)))
    with pytest.raises(ValueError, match="one value per sleeper"):
        SleeperCell([100.0, 100.0], [1e8, 1e8], [0.0, 0.0], [LAWS[0]])
    with pytest.raises(TypeError, match="no field"):
        cell.with_sleeper(0, mass=1.0)


def test_a_non_finite_law_names_its_sleeper():
    cell = SleeperCell.identical(PAPER, LinearFoundation.paper(), 3).with_sleeper(
        2, foundation=lambda w, v: np.where(w < -1e-4, np.nan, 20e6 * w))
    with pytest.raises(ValueError, match="sleeper 2"):
        solve_cell(PAPER, cell, 5)


def test_an_unfinished_solve_is_not_marked_converged():
    cell = SleeperCell.identical(PAPER, LinearFoundation.paper(), 3).with_sleeper(
        1, foundation=lambda w, v: 20e6 * w + 0.2e6 * v + 1e9 * np.sign(w) * np.abs(w) ** 0.5)
    result = solve_cell(PAPER, cell, 8, max_iterations=2, tol=1e-14)
    assert not result.converged and result.residual > 1e-14
    assert "tol" in result.message
