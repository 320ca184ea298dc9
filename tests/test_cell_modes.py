"""The cell's operators in its Floquet modes against their dense definition (issue 28).

`railtrack.equations.cell_modes` keeps K1_n, K2_n by their per-mode factors and
applies them by FFT; `railtrack.equations.cell_blocks` solves the blocks
``K1 + K2 diag(S)`` in the modes, with Woodbury's identity over the sleepers
that differ.  Here each is checked against the matrices built from their
definition, ``F diag(den) F^H`` with the explicit basis
``F[j, s] = e^{-i phi_s j} / sqrt(N)``, and dense solves, to 1e-10.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.cell_blocks import solve_blocks
from railtrack.equations.cell_harmonic_balance import _forces, _synthesize, cell_operators
from railtrack.equations.cell_receptance_modes import cell_receptance_modes
from railtrack.equations.load import axle_factor
from railtrack.equations.receptance import receptance_factors
from railtrack.model.passage import Passage
from railtrack.solvers.cell_auto import cell_truncation_errors
from railtrack.solvers.cell_newton import solve_cell
from railtrack.solvers.truncation import auto_samples

PASSAGE = Passage.paper()
N = 7
OMEGA = PASSAGE.fundamental_frequency * np.arange(15)


def dense_operators(passage, k1, eta, omega, sleeper_weight=None, rail_weight=0.0):
    """K1, K2 and g from the definition: the explicit Floquet basis and matrix products."""
    n = k1.size
    modes = cell_receptance_modes(passage, omega, n)
    j = np.arange(n)
    basis = np.exp(-1j * j[None, :, None] * modes.phase[:, None, :]) / np.sqrt(n)
    adjoint = np.conj(np.swapaxes(basis, -1, -2))
    first = (basis * modes.denominator[:, None, :]) @ adjoint
    pad = k1 + 1j * omega[:, None] * eta
    second = first / pad[:, None, :] + (basis * modes.numerator[:, None, :]) @ adjoint
    b = (-4.0 * np.sqrt(n) * axle_factor(passage, omega) * receptance_factors(passage, omega).gap
         * passage.sleeper_spacing / passage.wagon_length)
    load = b[:, None] * basis[:, :, 0]
    rest = omega == 0.0
    total = float(passage.train.wagon_load)
    load[rest] *= (total + rail_weight * passage.wagon_length) / total
    if sleeper_weight is not None:
        load[rest] -= second[rest].real @ sleeper_weight
    return first, second, load


def pads(differing=(3,)):
    k1, eta = np.full(N, 1.8e8), np.full(N, 3.0e4)
    for j in differing:
        k1[j], eta[j] = 0.7e8, 1.0e4
    return k1, eta


def relative(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def test_operators_are_their_definition():
    k1, eta = pads()
    weight = np.linspace(900.0, 1100.0, N)
    ops = cell_operators(PASSAGE, k1, eta, OMEGA, sleeper_weight=weight, rail_weight=590.0)
    first, second, load = dense_operators(PASSAGE, k1, eta, OMEGA, weight, 590.0)
    assert relative(ops.first, first) < 1e-12
    assert relative(ops.second, second) < 1e-12
    assert relative(ops.load, load) < 1e-12
    assert np.all(ops.first[0].imag == 0) and np.all(ops.load[0].imag == 0)
    columns = ops.columns([1, 5])
    assert relative(columns[0], first[:, :, [1, 5]]) < 1e-12
    assert relative(columns[1], second[:, :, [1, 5]]) < 1e-12


def test_applied_by_fft_as_the_dense_product():
    k1, eta = pads((0, 4))
    ops = cell_operators(PASSAGE, k1, eta, OMEGA)
    first, second, _ = dense_operators(PASSAGE, k1, eta, OMEGA)
    rng = np.random.default_rng(3)
    c = rng.normal(size=(OMEGA.size, N)) + 1j * rng.normal(size=(OMEGA.size, N))
    p = 1e5 * (rng.normal(size=(OMEGA.size, N)) + 1j * rng.normal(size=(OMEGA.size, N)))
    c[0], p[0] = c[0].real, p[0].real
    dense = np.einsum("nab,nb->na", first, c) + np.einsum("nab,nb->na", second, p)
    assert relative(ops.apply(c, p), dense) < 1e-12


def support(differing, rest_reference=2e7):
    """-M omega^2 + K + i omega C per sleeper, `differing` ones on another law."""
    s = np.full((OMEGA.size, N), 0j) + rest_reference - 250.0 * OMEGA[:, None] ** 2 \
        + 1j * OMEGA[:, None] * 2e5
    for j in differing:
        s[:, j] = 3e6 - 180.0 * OMEGA ** 2 + 1j * OMEGA * 5e4
    return s


@pytest.mark.parametrize("case", ["identical", "one", "two and a pad", "all", "singular"])
def test_blocks_solved_in_the_modes_are_the_dense_solve(case):
    differing, pad_differs, rest_reference = {
        "identical": ((), (), 2e7), "one": ((3,), (), 2e7), "two and a pad": ((1, 4), (6,), 2e7),
        "all": (range(N), (), 2e7),
        # the reference sleepers carry nothing at rest: B0 singular at omega = 0 only
        "singular": ((2,), (), 0.0)}[case]
    k1, eta = pads(pad_differs)
    ops = cell_operators(PASSAGE, k1, eta, OMEGA)
    first, second, _ = dense_operators(PASSAGE, k1, eta, OMEGA)
    s = support(differing, rest_reference)
    rng = np.random.default_rng(5)
    rhs = rng.normal(size=(OMEGA.size, N, 3)) + 1j * rng.normal(size=(OMEGA.size, N, 3))
    dense = np.linalg.solve(first + second * s[:, None, :], rhs)
    assert relative(solve_blocks(ops, s, rhs), dense) < 1e-10
    assert relative(solve_blocks(ops, s, rhs[..., 0]), dense[..., 0]) < 1e-10


def dense_truncation_tail(solution):
    """The tail c_{m+1..8m} of the estimate, solved as it was: every law sampled, dense blocks."""
    passage, cell, m = solution.passage, solution.cell, solution.harmonics
    top, samples = 8 * m, auto_samples(8 * m)
    c = solution.coefficients[:, m:]
    w, v = _synthesize(c, passage.fundamental_frequency * np.arange(m + 1), samples)
    excess = (np.fft.rfft(_forces(cell, w, v), axis=-1) / samples)[:, m + 1:top + 1]
    tangent = _forces(cell, w, v, tangent=True).mean(axis=-1)
    high = passage.fundamental_frequency * np.arange(m + 1, top + 1)
    first, second, load = dense_operators(passage, cell.pad_stiffness, cell.pad_damping, high)
    s = -cell.sleeper_mass * high[:, None] ** 2 + tangent[0] + 1j * high[:, None] * tangent[1]
    rhs = load - np.einsum("nab,bn->na", second, excess)
    return np.linalg.solve(first + second * s[:, None, :], rhs[..., None])[..., 0].T


def test_truncation_estimate_in_the_modes_is_the_dense_one():
    cell = rt.SleeperCell.identical(PASSAGE, rt.LinearFoundation(20e6, 0.2e6), 6).with_sleeper(
        2, foundation=rt.GapFoundation(1e-3, 20e6, 0.2e6))
    solution = solve_cell(PASSAGE, cell, 24)
    assert solution.converged
    _, tail, _ = cell_truncation_errors(solution)
    assert relative(tail, dense_truncation_tail(solution)) < 1e-10


def test_a_nearly_singular_reference_is_solved_densely():
    # the reference sleepers' support puts one Floquet mode of B0 at 1e-11 of the others at
    # harmonic 5: Woodbury's terms grow by 1e11 and cancel; the residual sends that harmonic
    # to the dense solve, where the differing sleeper keeps B well posed
    k1, eta = pads(())
    ops = cell_operators(PASSAGE, k1, eta, OMEGA)
    first, second, _ = dense_operators(PASSAGE, k1, eta, OMEGA)
    s = support((3,))
    n, mode = 5, 2
    den, num, pad = ops.denominator[n, mode], ops.numerator[n, mode], ops.pad[n, 0]
    s[n, [j for j in range(N) if j != 3]] = -den / (den / pad + num) * (1.0 + 1e-11)
    rhs = np.random.default_rng(7).normal(size=(OMEGA.size, N)) + 0j
    dense = np.linalg.solve(first + second * s[:, None, :], rhs[..., None])[..., 0]
    assert relative(solve_blocks(ops, s, rhs)[n], dense[n]) < 1e-9


@pytest.mark.parametrize("differing", [(3,), tuple(range(N))])
def test_blocks_in_groups_of_harmonics_are_the_same_solve(monkeypatch, differing):
    from railtrack.equations import cell_blocks

    k1, eta = pads()
    ops = cell_operators(PASSAGE, k1, eta, OMEGA)
    s = support(differing)
    rhs = np.random.default_rng(9).normal(size=(OMEGA.size, N)) + 0j
    whole = solve_blocks(ops, s, rhs)
    monkeypatch.setattr(cell_blocks, "BLOCK_ENTRIES", 3 * N * N)      # 3 harmonics a group
    assert relative(solve_blocks(ops, s, rhs), whole) < 1e-13
