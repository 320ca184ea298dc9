"""The Timoshenko rail's receptance on periodic supports (issue 20, section 3).

Independent truths used here:
* the 2 x 2 system of the coupled deflection/rotation equations for one
  harmonic, solved numerically (dispersion relation and G^ without the formula);
* the Poisson sum over the wavenumbers (no partial fractions) for the closed form;
* the paper's eq. (3) (`rail_receptance`) in the limit kGA -> inf, rho I = 0;
* the simply supported Timoshenko beam: the determinant of the mode
  w = W sin(pi x/L), psi = Psi cos(pi x/L) in the coupled equations, rooted by
  bisection; the poles of eq. (3) listed by `receptance_pole_frequencies`;
* Rayleigh–Timoshenko's first-order estimate of the shear and rotary-inertia
  correction, omega_T^2 ~ omega_EB^2 / (1 + k^2 (EI/kGA + rho I/rho S)).
"""

import numpy as np
import pytest
from scipy.optimize import brentq

from railtrack.equations.receptance import rail_receptance, receptance_pole_frequencies
from railtrack.equations.timoshenko_receptance import (
    pinned_pinned_frequency,
    timoshenko_dispersion,
    timoshenko_green_transform,
    timoshenko_receptance,
    timoshenko_receptance_lattice_sum,
    timoshenko_wavenumbers_squared,
)
from railtrack.model.passage import Passage
from railtrack.model.timoshenko import TimoshenkoRail

PASSAGE = Passage.paper()
RAIL = TimoshenkoRail.uic60()
# below and above the pinned-pinned frequency (6690 rad/s) and the shear cut-off
# sqrt(kGA / rho I) = 32,190 rad/s, and near zero
OMEGA = np.array([1e-4, 0.5, 50.0, 500.0, 3000.0, 6000.0, 8000.0, 12000.0, 30000.0, 40000.0, 1e5])
SPEEDS = [10.0, 45.0, 100.0, 300.0]


def coupled_matrix(passage, rail, kappa, omega):
    """The harmonic e^{i(kappa x - omega t)} in rho S w_tt - kGA(w_xx - psi_x) = f,
    rho I psi_tt - EI psi_xx - kGA(w_x - psi) = 0, term by term."""
    ei, rho_s = passage.rail_bending_stiffness, passage.rail_linear_mass
    kga, rho_i = rail.shear_stiffness, rail.rotary_inertia
    d = 1j * kappa                      # d/dx
    return np.array([
        [-rho_s * omega**2 - kga * d * d, kga * d],
        [-kga * d, -rho_i * omega**2 - ei * d * d + kga],
    ])


def simply_supported_determinant(passage, rail, omega):
    """det of the mode w = W sin(kx), psi = Psi cos(kx), k = pi/L, in the coupled equations."""
    ei, rho_s = passage.rail_bending_stiffness, passage.rail_linear_mass
    kga, rho_i = rail.shear_stiffness, rail.rotary_inertia
    k = np.pi / passage.sleeper_spacing
    # w'' = -k^2 W sin, psi' = -k Psi sin, psi'' = -k^2 Psi cos, w' = k W cos
    matrix = np.array([
        [kga * k**2 - rho_s * omega**2, -kga * k],
        [-kga * k, ei * k**2 + kga - rho_i * omega**2],
    ])
    return np.linalg.det(matrix)


def first_root(f, upper, samples=4000):
    """The first sign change of f on (0, upper], refined by bisection."""
    grid = np.linspace(upper / samples, upper, samples)
    values = np.array([f(w) for w in grid])
    i = np.flatnonzero(np.sign(values[1:]) != np.sign(values[:-1]))[0]
    return brentq(f, grid[i], grid[i + 1], xtol=1e-12, rtol=1e-14)


@pytest.mark.parametrize("kappa, omega", [(0.3, 50.0), (5.0, 6000.0), (12.0, 2e4),
                                          (40.0, 5e4), (2.0, 0.0)])
def test_dispersion_and_green_transform_solve_the_coupled_equations(kappa, omega):
    matrix = coupled_matrix(PASSAGE, RAIL, kappa, omega)
    det = np.linalg.det(matrix).real / RAIL.shear_stiffness
    assert timoshenko_dispersion(PASSAGE, RAIL, kappa, omega) == pytest.approx(det, rel=1e-10)
    w = np.linalg.solve(matrix, np.array([1.0, 0.0]))[0]
    assert abs(w.imag) < 1e-12 * abs(w)
    assert timoshenko_green_transform(PASSAGE, RAIL, kappa, omega) == pytest.approx(
        w.real, rel=1e-10)


def test_wavenumbers_squared_are_the_roots():
    s1, s2 = timoshenko_wavenumbers_squared(PASSAGE, RAIL, OMEGA)
    for s in (s1, s2):
        for root, omega in zip(s, OMEGA):
            # the coupled equations' determinant at kappa = sqrt(s), imaginary for s < 0,
            # against the size of its two products (they cancel)
            m = coupled_matrix(PASSAGE, RAIL, np.sqrt(complex(root)), omega)
            scale = abs(m[0, 0] * m[1, 1]) + abs(m[0, 1] * m[1, 0])
            assert abs(np.linalg.det(m)) < 1e-11 * scale
    cutoff = np.sqrt(RAIL.shear_stiffness / RAIL.rotary_inertia)
    assert np.all(s1 > 0)
    assert np.all((s2 < 0) == (OMEGA < cutoff))


@pytest.mark.parametrize("speed", SPEEDS)
def test_closed_form_matches_lattice_sum(speed):
    passage = PASSAGE.replace(speed=speed)
    closed = timoshenko_receptance(passage, RAIL, OMEGA)
    lattice = timoshenko_receptance_lattice_sum(passage, RAIL, OMEGA)
    assert np.all(np.isfinite(closed))
    np.testing.assert_allclose(closed, lattice, rtol=1e-10)


def pinned_pinned_passage(rail):
    """The paper's track with the speed that puts q = pi at the pinned-pinned frequency."""
    omega = 2.0 * np.pi * pinned_pinned_frequency(PASSAGE, rail)
    return PASSAGE.replace(speed=omega * PASSAGE.sleeper_spacing / np.pi), omega


def moving_wave_resonance(passage, rail):
    """The lowest omega where the j = 0 wavenumber omega/v is a free wave, D(omega/v) = 0."""
    return first_root(lambda w: timoshenko_dispersion(passage, rail, w / passage.speed, w),
                      4e4, samples=2000)


@pytest.mark.parametrize("offset", [1e-3, -1e-3, 1e-5, -1e-5])
def test_closed_form_matches_lattice_sum_near_poles(offset):
    passage, pinned = pinned_pinned_passage(RAIL)
    fast = PASSAGE.replace(speed=300.0)
    for p, pole in ((passage, pinned), (fast, moving_wave_resonance(fast, RAIL))):
        omega = np.array([pole * (1.0 + offset)])
        closed = timoshenko_receptance(p, RAIL, omega)
        lattice = timoshenko_receptance_lattice_sum(p, RAIL, omega)
        np.testing.assert_allclose(closed, lattice, rtol=1e-8)


def test_pinned_pinned_frequency_is_a_simple_pole_at_q_pi():
    passage, pole = pinned_pinned_passage(RAIL)
    eta = {e: timoshenko_receptance_lattice_sum(passage, RAIL, np.array([pole * (1 + e)]))[0]
           for e in (1e-4, -1e-4, 1e-6, -1e-6)}
    assert np.sign(eta[1e-6]) == -np.sign(eta[-1e-6])
    assert eta[1e-6] / eta[1e-4] == pytest.approx(100.0, rel=0.02)
    at_pole = timoshenko_receptance(passage, RAIL, np.array([pole]))[0]
    assert abs(at_pole) > 1e3 * abs(eta[1e-4])         # inf, or huge from round-off


@pytest.mark.parametrize("speed", SPEEDS)
def test_euler_bernoulli_limit_is_eq_3(speed):
    passage = PASSAGE.replace(speed=speed)
    stiff = TimoshenkoRail(1e20, 0.0)
    omega = OMEGA[OMEGA <= 4e4]
    np.testing.assert_allclose(timoshenko_receptance(passage, stiff, omega),
                               rail_receptance(passage, omega), rtol=1e-8)


def test_receptance_is_real_and_even_in_omega():
    passage = PASSAGE.replace(speed=100.0)
    eta = timoshenko_receptance(passage, RAIL, OMEGA)
    assert eta.dtype.kind == "f"
    np.testing.assert_array_equal(eta, timoshenko_receptance(passage, RAIL, -OMEGA))


def test_receptance_is_infinite_at_rest():
    assert timoshenko_receptance(PASSAGE, RAIL, np.array([0.0]))[0] == np.inf


@pytest.mark.parametrize("rail", [RAIL, TimoshenkoRail(5e7, 0.5), TimoshenkoRail(2.5e8, 0.0)])
def test_pinned_pinned_matches_simply_supported_beam(rail):
    upper = 2.0 * np.pi * pinned_pinned_frequency(PASSAGE) * 1.01
    root = first_root(lambda w: simply_supported_determinant(PASSAGE, rail, w), upper)
    assert pinned_pinned_frequency(PASSAGE, rail) == pytest.approx(root / (2 * np.pi), rel=1e-10)


def test_euler_bernoulli_pinned_pinned_is_a_pole_of_eq_3():
    passage, pole = pinned_pinned_passage(None)
    poles = receptance_pole_frequencies(passage, 2.0 * pole)
    assert np.min(np.abs(poles - pole)) < 1e-9 * pole
    stiff = TimoshenkoRail(1e20, 0.0)
    assert pinned_pinned_frequency(PASSAGE, stiff) == pytest.approx(
        pinned_pinned_frequency(PASSAGE), rel=1e-10)


@pytest.mark.parametrize("passage", [PASSAGE, PASSAGE.replace(rail_bending_stiffness=6.4155e6,
                                                              rail_linear_mass=60.2)])
def test_uic60_lowers_pinned_pinned_by_shear_and_rotary_inertia(passage):
    ei, rho_s = passage.rail_bending_stiffness, passage.rail_linear_mass
    k2 = (np.pi / passage.sleeper_spacing) ** 2
    estimate = 1.0 / np.sqrt(1.0 + k2 * (ei / RAIL.shear_stiffness
                                         + RAIL.rotary_inertia / rho_s))
    euler, timo = pinned_pinned_frequency(passage), pinned_pinned_frequency(passage, RAIL)
    assert timo < euler
    assert timo / euler == pytest.approx(estimate, rel=0.02)


@pytest.mark.parametrize("args, error", [((0.0, 0.2), ValueError), ((2e8, -0.1), ValueError),
                                         ((np.inf, 0.2), ValueError), ((True, 0.2), TypeError),
                                         ((2e8, 1j), TypeError)])
def test_rail_refuses_bad_values(args, error):
    with pytest.raises(error, match="shear_stiffness|rotary_inertia"):
        TimoshenkoRail(*args)


def test_from_section_refuses_bad_values():
    with pytest.raises(ValueError, match="shear_coefficient"):
        TimoshenkoRail.from_section(0.0, 81e9, 7.67e-3, 7850.0, 3.055e-5)
