"""Free waves of the smeared track (railtrack.equations.dispersion), against independent truth."""

import numpy as np
import pytest
import scipy.linalg

import railtrack as rt
from railtrack.equations.dispersion import harmonic_resonance_speeds, smeared_phase_speed

TRACK, LAW = rt.Track.paper(), rt.LinearFoundation.paper()


def test_the_lower_branch_is_the_lower_eigenvalue_of_the_two_layer_system():
    # Per metre: rail (rho S) over pad k1/L over sleeper (M/L) over k2/L; a wave
    # exp(i kappa x) adds EI kappa^4 to the rail's stiffness.
    k1, k2, spacing = 220e6, 20e6, 0.6
    for kappa in (0.3, 1.0, 2.5, 8.0):
        stiffness = np.array([[6.3e6 * kappa**4 + k1 / spacing, -k1 / spacing],
                              [-k1 / spacing, (k1 + k2) / spacing]])
        mass = np.diag([60.0, 100.0 / spacing])
        lowest = scipy.linalg.eigh(stiffness, mass, eigvals_only=True)[0]
        expected = np.sqrt(lowest) / kappa
        assert smeared_phase_speed(TRACK, LAW, kappa) == pytest.approx(expected, rel=1e-10)


def test_without_sleeper_mass_the_least_phase_speed_is_winklers():
    # v_cr = (4 k EI / (rho S)^2)^(1/4) with k = k_s / L (Fryba 1972).
    light = TRACK.replace(sleeper_mass=1e-6)
    kappa = np.linspace(0.2, 5.0, 20001)
    k_s = 220e6 * 20e6 / 240e6
    winkler = (4 * k_s / 0.6 * 6.3e6 / 60.0**2) ** 0.25
    assert smeared_phase_speed(light, LAW, kappa).min() == pytest.approx(winkler, rel=1e-5)


def test_short_waves_tend_to_the_sleeper_on_its_two_springs():
    kappa = 200.0
    bound = np.sqrt((220e6 + 20e6) / 100.0)
    assert smeared_phase_speed(TRACK, LAW, kappa) * kappa == pytest.approx(bound, rel=1e-4)


def test_harmonic_n_of_a_wagon_has_wavelength_h_over_n():
    train = rt.Train.paper()
    speeds = harmonic_resonance_speeds(TRACK, LAW, train, [1, 2, 4])
    direct = smeared_phase_speed(TRACK, LAW, 2 * np.pi * np.array([1, 2, 4]) / 18.0)
    np.testing.assert_allclose(speeds, direct, rtol=1e-14)


@pytest.mark.parametrize("bad", [0.0, -1.0, np.nan])
def test_wavenumbers_must_be_positive(bad):
    with pytest.raises(ValueError, match="positive"):
        smeared_phase_speed(TRACK, LAW, [1.0, bad])
