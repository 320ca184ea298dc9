"""Eq. (3), (6) and (16): the receptance, the coupling P and the load F.

Independent truths used here:
* Poisson summation of the free beam's Green function over the supports
  (`rail_receptance_lattice_sum`), which does not use the closed form;
* the printed formulas of eqs. (6) and (16), evaluated literally with that
  lattice sum, away from their 0/0 points;
* the limits P_0 = k1 / M and F_0 = 2 Q L / (M H) stated after eq. (16).
"""

import numpy as np
import pytest

from railtrack import Passage, load_coefficients, rail_coupling, rail_receptance
from railtrack.equations.receptance import (
    bending_wavenumber,
    moving_load_receptance,
    rail_receptance_lattice_sum,
)
from railtrack.equations.sleeper import coupling_and_transfer, load_transfer, pad_stiffness

PASSAGE = Passage.paper()
# omega at which omega / v = k_b: both brackets of the printed Gamma are singular
CRITICAL = PASSAGE.speed**2 * np.sqrt(PASSAGE.rail_linear_mass / PASSAGE.rail_bending_stiffness)


def printed_coupling_and_load(passage, omega):
    """Eq. (16) exactly as printed, with eta_E from the lattice sum."""
    eta = rail_receptance_lattice_sum(passage, omega)
    A = passage.pad_stiffness + 1j * omega * passage.pad_damping
    kb = bending_wavenumber(passage, omega)
    gamma = 1.0 / ((1 + A * eta) * ((omega / passage.speed) ** 4 - kb**4))
    P = A**2 * eta / (passage.sleeper_mass * (1 + A * eta))
    F = (
        passage.wheel_load
        * (1 + np.exp(-1j * omega * passage.wheel_spacing / passage.speed))
        * A
        * gamma
        / (passage.sleeper_mass * passage.wagon_length * passage.rail_bending_stiffness)
    )
    return P, F


@pytest.mark.parametrize(
    "omega", [0.3, 2.0, 6.0, 15.707963, 47.1, 200.0, 1234.5, 2.0e4, -15.707963]
)
def test_closed_form_matches_lattice_sum(omega):
    closed = rail_receptance(PASSAGE, omega)
    lattice = rail_receptance_lattice_sum(PASSAGE, omega)
    assert closed == pytest.approx(lattice, rel=1e-6)


def test_closed_form_matches_lattice_sum_for_other_tracks():
    for passage in (Passage.paper(speed=12.0), Passage.paper(sleeper_spacing=0.75, speed=90.0)):
        omega = np.array([1.0, 30.0, 300.0])
        np.testing.assert_allclose(
            rail_receptance(passage, omega), rail_receptance_lattice_sum(passage, omega), rtol=1e-6
        )


def test_closed_form_matches_lattice_sum_near_a_pole():
    # cos(k_b L) = cos(omega L / v) at omega = CRITICAL, where eta_E blows up
    omega = CRITICAL * np.array([0.99, 0.999, 1.001, 1.01])
    np.testing.assert_allclose(
        rail_receptance(PASSAGE, omega), rail_receptance_lattice_sum(PASSAGE, omega), rtol=1e-6
    )


@pytest.mark.parametrize("omega", [1.0, 15.707963, 31.4, 157.0, 1000.0])
def test_coupling_and_load_match_printed_eq16(omega):
    P, F = printed_coupling_and_load(PASSAGE, omega)
    assert rail_coupling(PASSAGE, omega) == pytest.approx(P, rel=1e-6)
    assert load_coefficients(PASSAGE, omega) == pytest.approx(F, rel=1e-6)


@pytest.mark.parametrize("omega", [0.0, 1e-12, 1e-8, 1e-5, 1e-3])
def test_limits_at_zero_frequency(omega):
    P0 = PASSAGE.pad_stiffness / PASSAGE.sleeper_mass
    F0 = 2 * PASSAGE.wheel_load * PASSAGE.sleeper_spacing / (PASSAGE.sleeper_mass * PASSAGE.wagon_length)
    # P - P0 ~ i omega eta1 / M (relative omega * eta1 / k1 = omega / 220 s^-1), and
    # F / F0 - 1 ~ -i omega D / (2 v) from the second wheel: both bounded by omega * D / v
    bound = 1e-12 + omega * PASSAGE.wheel_spacing / PASSAGE.speed
    assert rail_coupling(PASSAGE, omega) == pytest.approx(P0, rel=bound)
    assert load_coefficients(PASSAGE, omega) == pytest.approx(F0, rel=bound)


def test_zero_frequency_is_exact():
    P0 = PASSAGE.pad_stiffness / PASSAGE.sleeper_mass
    F0 = 2 * PASSAGE.wheel_load * PASSAGE.sleeper_spacing / (PASSAGE.sleeper_mass * PASSAGE.wagon_length)
    assert rail_coupling(PASSAGE, 0.0) == P0
    assert load_coefficients(PASSAGE, 0.0).real == pytest.approx(F0, rel=1e-15)
    assert load_coefficients(PASSAGE, 0.0).imag == 0.0


def test_small_frequencies_approach_limits_continuously():
    omega = np.geomspace(1e-9, 1e-1, 40)
    P = rail_coupling(PASSAGE, omega)
    F = load_coefficients(PASSAGE, omega)
    # the printed form, evaluated where it is still well conditioned (omega = 0.1),
    # agrees with the factored one: the small-omega values are not a different branch
    P_printed, F_printed = printed_coupling_and_load(PASSAGE, 0.1)
    assert P[-1] == pytest.approx(P_printed, rel=1e-6)
    assert F[-1] == pytest.approx(F_printed, rel=1e-6)
    assert np.all(np.diff(np.abs(F - F[0])) >= 0)  # deviation grows monotonically


def test_gamma_is_smooth_where_printed_form_is_singular():
    # (omega/v)^4 - k_b^4 = 0 and eta_E = inf at CRITICAL; their product is finite
    assert np.isinf(moving_load_receptance(PASSAGE, CRITICAL)) or abs(
        moving_load_receptance(PASSAGE, CRITICAL)
    ) > 1e3 * abs(moving_load_receptance(PASSAGE, 1.5 * CRITICAL))
    eps = np.array([-1e-3, -1e-6, 0.0, 1e-6, 1e-3])
    F = load_coefficients(PASSAGE, CRITICAL * (1 + eps))
    assert np.all(np.isfinite(F))
    # a smooth function: the midpoint equals the mean of its neighbours to O(eps^2)
    assert F[2] == pytest.approx(0.5 * (F[1] + F[3]), rel=1e-9)
    P_printed, F_printed = printed_coupling_and_load(PASSAGE, CRITICAL * (1 + 1e-3))
    assert F[4] == pytest.approx(F_printed, rel=1e-6)


def test_no_nan_or_inf_over_a_wide_range():
    omega = np.concatenate([[0.0], np.geomspace(1e-12, 1e8, 2000)])
    omega = np.concatenate([-omega[::-1], omega])
    P, gamma = coupling_and_transfer(PASSAGE, omega)
    F = load_coefficients(PASSAGE, omega)
    for values in (P, gamma, F):
        assert np.all(np.isfinite(values))


def test_conjugate_symmetry():
    omega = np.linspace(0.1, 500, 37)
    np.testing.assert_allclose(rail_coupling(PASSAGE, -omega), np.conj(rail_coupling(PASSAGE, omega)))
    np.testing.assert_allclose(
        load_coefficients(PASSAGE, -omega), np.conj(load_coefficients(PASSAGE, omega))
    )
    np.testing.assert_allclose(rail_receptance(PASSAGE, -omega), rail_receptance(PASSAGE, omega))


def test_load_vanishes_when_the_two_wheels_cancel():
    # omega_n D / v = 2 pi n D / H = pi n / 3: odd multiples of pi at n = 3, 9, 15
    omega = PASSAGE.harmonic_frequencies(15)[15:]
    F = np.abs(load_coefficients(PASSAGE, omega))
    assert np.all(F[[3, 9, 15]] < 1e-12 * F[0])
    assert np.all(np.delete(F, [3, 9, 15]) > 1e-3 * F[0])


def test_pad_stiffness_and_transfer_limit():
    assert pad_stiffness(PASSAGE, 2.0) == PASSAGE.pad_stiffness + 2j * PASSAGE.pad_damping
    # Gamma(0) = EI L / k1 (derived in the book's chapter on the train load)
    expected = PASSAGE.rail_bending_stiffness * PASSAGE.sleeper_spacing / PASSAGE.pad_stiffness
    assert load_transfer(PASSAGE, 0.0) == pytest.approx(expected, rel=1e-14)


def test_undamped_resonance_is_reported_not_returned_as_inf():
    undamped = Passage.paper(pad_damping=0.0)
    # away from the resonance the undamped values are finite and real-coupled
    assert np.isfinite(rail_coupling(undamped, 10.0))
