"""The receptance matrix of a cell of N sleepers (issue 19).

Independent truths used here:
* eq. (3) for N = 1 (`rail_receptance`, a different closed form);
* the Poisson sum over the cell's wavenumbers, entry by entry, with no twist;
* the offset lattice sum of `rail_field` for a track whose spacing is the cell;
* the Bernoulli polynomial B_4 for the finite part at omega = 0;
* physics: Toeplitz structure, reciprocity, Hermitian symmetry (no damping in
  the rail), and today's travelling-wave solution for identical sleepers
  (eq. 6, `rail_coefficients`).
"""

import numpy as np
import pytest
from scipy.optimize import brentq

from railtrack.equations.cell_receptance import (
    cell_moving_load,
    cell_receptance,
    cell_receptance_lattice_sum,
)
from railtrack.equations.cell_receptance_modes import cell_receptance_modes
from railtrack.equations.load import load_coefficients
from railtrack.equations.rail_field import offset_receptance
from railtrack.equations.receptance import bending_wavenumber, rail_receptance
from railtrack.equations.sleeper import pad_stiffness, rail_coefficients
from railtrack.model.passage import Passage

PASSAGE = Passage.paper()
OMEGA = np.array([1e-3, 0.5, 15.7, 80.0, 500.0, 3000.0, -40.0])


def rebuild(modes, n):
    """(1/N) sum_s lambda_s e^{-i phi_s (j - j')}."""
    lam = modes.numerator / modes.denominator
    m = np.subtract.outer(np.arange(n), np.arange(n))
    return (lam[..., None, None, :]
            * np.exp(-1j * m[..., None] * modes.phase[..., None, None, :])).mean(-1)


def test_one_sleeper_is_eq_3():
    omega = np.array([1e-4, 0.3, 15.707963, 200.0, 1234.5, 2.0e4, -15.707963])
    np.testing.assert_allclose(cell_receptance(PASSAGE, omega, 1)[:, 0, 0],
                               rail_receptance(PASSAGE, omega), rtol=1e-12, atol=0)


@pytest.mark.parametrize("n", [2, 3, 5])
def test_closed_form_matches_lattice_sum(n):
    np.testing.assert_allclose(cell_receptance(PASSAGE, OMEGA, n),
                               cell_receptance_lattice_sum(PASSAGE, OMEGA, n), rtol=1e-10)


@pytest.mark.parametrize("n", [2, 5])
def test_closed_form_matches_offset_receptance_of_the_cell_lattice(n):
    wide = PASSAGE.replace(sleeper_spacing=n * PASSAGE.sleeper_spacing)
    column = offset_receptance(wide, OMEGA, np.arange(n) * PASSAGE.sleeper_spacing).T
    np.testing.assert_allclose(cell_receptance(PASSAGE, OMEGA, n)[:, :, 0], column, rtol=1e-12)


def test_other_track_and_large_frequency_do_not_overflow():
    passage = Passage.paper(speed=90.0, sleeper_spacing=0.75)
    omega = np.array([3.0, 300.0, 5.0e4])
    closed = cell_receptance(passage, omega, 30)
    assert np.all(np.isfinite(closed))
    np.testing.assert_allclose(closed, cell_receptance_lattice_sum(passage, omega, 30),
                               rtol=1e-9)


@pytest.mark.parametrize("n", [3, 4])
def test_modes_rebuild_the_matrix(n):
    np.testing.assert_allclose(rebuild(cell_receptance_modes(PASSAGE, OMEGA, n), n),
                               cell_receptance(PASSAGE, OMEGA, n), rtol=1e-10)


def test_mode_eigenvalues_match_their_lattice_sum_across_the_series_switch():
    # k_b L = 1 is where the modes switch from the series to the direct form
    one = (1.0 / PASSAGE.sleeper_spacing) ** 4 * PASSAGE.rail_bending_stiffness
    omega = np.sqrt(one / PASSAGE.rail_linear_mass) * np.array([1e-6, 0.3, 0.999, 1.001, 3.0])
    modes = cell_receptance_modes(PASSAGE, omega, 6)
    span, ei = PASSAGE.sleeper_spacing, PASSAGE.rail_bending_stiffness
    t = np.arange(-20_000, 20_001)
    kappa = (modes.phase[..., None] + 2 * np.pi * t) / span
    kb4 = bending_wavenumber(PASSAGE, omega)[:, None, None] ** 4
    lattice = np.sum(1.0 / (kappa**4 - kb4), axis=-1) / (ei * span)
    lam = modes.numerator / modes.denominator
    np.testing.assert_allclose(lam[:, 1:], lattice[:, 1:], rtol=1e-10)


def test_finite_part_at_rest_is_the_bernoulli_polynomial():
    # at omega = 0, eta(mL) = (Lambda^3/EI) sum_r e^{-2 pi i r m/N} / (2 pi r)^4; mode 0
    # holds the terms r = tN, whose t != 0 part is (L^3/(N EI))/720; B4 sums r != 0
    n = 5
    span, ei = PASSAGE.sleeper_spacing, PASSAGE.rail_bending_stiffness
    cell = n * span
    modes = cell_receptance_modes(PASSAGE, np.array([0.0, 1e-7]), n)
    lam = modes.numerator[:, 1:] / modes.denominator[:, 1:]
    m = np.arange(n)
    finite = (lam[:, None, :] * np.exp(-1j * m[:, None] * modes.phase[:, None, 1:])).sum(-1) / n
    x = m / n
    b4 = x**4 - 2 * x**3 + x**2 - 1.0 / 30.0
    expected = cell**3 / ei * (-b4 / 24.0) - span**3 / (n * ei) / 720.0
    np.testing.assert_allclose(finite[0], expected, rtol=1e-12)
    np.testing.assert_allclose(finite[1], expected, rtol=1e-6)


def test_toeplitz_and_twisted_circulant():
    n = 4
    theta = OMEGA * n * PASSAGE.sleeper_spacing / PASSAGE.speed
    for eta in (cell_receptance_lattice_sum(PASSAGE, OMEGA, n),
                rebuild(cell_receptance_modes(PASSAGE, OMEGA, n), n)):
        # depends on j - j' only
        np.testing.assert_allclose(eta[:, 1:, 1:], eta[:, :-1, :-1], rtol=1e-10)
        # eta(d + N L) = e^{-i theta} eta(d): eta_{j,0} = e^{-i theta} eta_{0, N-j}
        for j in range(1, n):
            np.testing.assert_allclose(eta[:, j, 0], np.exp(-1j * theta) * eta[:, 0, n - j],
                                       rtol=1e-10)


@pytest.mark.parametrize("n", [2, 3, 5])
def test_reciprocity_and_hermitian(n):
    omega = OMEGA[OMEGA > 0]
    eta = cell_receptance(PASSAGE, omega, n)
    np.testing.assert_allclose(cell_receptance(PASSAGE, -omega, n),
                               np.swapaxes(eta, -1, -2), rtol=1e-12)
    np.testing.assert_allclose(eta, np.conj(np.swapaxes(eta, -1, -2)), rtol=1e-12)


@pytest.mark.parametrize("n", [2, 3, 5])
def test_travelling_pattern_sees_eq_3(n):
    q = OMEGA * PASSAGE.sleeper_spacing / PASSAGE.speed
    wave = np.exp(-1j * q[:, None] * np.arange(n))
    pushed = np.einsum("wjk,wk->wj", cell_receptance(PASSAGE, OMEGA, n), wave)
    np.testing.assert_allclose(pushed, rail_receptance(PASSAGE, OMEGA)[:, None] * wave,
                               rtol=1e-10)


def test_identical_sleepers_reproduce_eq_6():
    # rail above sleeper j: r = eta R + m with R = A (c - r); today's answer for
    # the sleeper motion c e^{-i q j} is r_n(0) e^{-i q j} of eq. (6).
    n = 3
    omega = 2 * np.pi * PASSAGE.speed / PASSAGE.wagon_length * np.arange(1, 6)
    q = omega * PASSAGE.sleeper_spacing / PASSAGE.speed
    wave = np.exp(-1j * q[:, None] * np.arange(n))
    c = 1e-4 * np.exp(0.7j * np.arange(1, 6))
    stiffness = pad_stiffness(PASSAGE, omega)[:, None, None]
    eta = cell_receptance(PASSAGE, omega, n)
    system = np.eye(n) + eta * stiffness
    right = np.einsum("wjk,wk->wj", eta * stiffness, c[:, None] * wave) + cell_moving_load(
        PASSAGE, omega, n)
    rail = np.linalg.solve(system, right[..., None])[..., 0]
    today = rail_coefficients(PASSAGE, omega, c, load_coefficients(PASSAGE, omega))
    np.testing.assert_allclose(rail, today[:, None] * wave, rtol=1e-10)


def test_singular_exactly_at_the_free_waves():
    n = 3
    cell = n * PASSAGE.sleeper_spacing

    def gap(w):
        return np.cos(bending_wavenumber(PASSAGE, w) * cell) - np.cos(w * cell / PASSAGE.speed)

    grid = np.linspace(100.0, 2000.0, 2000)
    change = np.flatnonzero(np.diff(np.sign(gap(grid))))
    assert change.size > 0
    pole = brentq(gap, grid[change[0]], grid[change[0] + 1], xtol=1e-13)
    near = cell_receptance(PASSAGE, np.array([200.0, pole * (1 + 1e-9)]), n)
    assert np.max(np.abs(near[1])) > 1e6 * np.max(np.abs(near[0]))
    modes = cell_receptance_modes(PASSAGE, pole, n)
    scale = 4 * PASSAGE.rail_bending_stiffness / PASSAGE.sleeper_spacing**3
    assert np.min(np.abs(modes.denominator)) < 1e-8 * scale
    rest = cell_receptance(PASSAGE, 0.0, n)
    assert np.all(np.isinf(rest.real)) and np.all(rest.imag == 0)


@pytest.mark.parametrize("bad", [0, -2, 1.5, True])
def test_sleeper_count_must_be_a_positive_integer(bad):
    with pytest.raises(ValueError, match="sleepers"):
        cell_receptance(PASSAGE, 10.0, bad)
