"""The ground's free waves against Rayleigh's closed form and an independent determinant.

Truths: the exact Rayleigh speed for nu = 1/4, sqrt(2 - 2/sqrt(3)) c_s;
Viktorov's approximation (0.862 + 1.14 nu) / (1 + nu) c_s (good to 1 %
at nu = 0.05, 0.1 % near 0.5); the layered ground's fundamental mode tends to the half-space's
Rayleigh speed at long waves and to the top layer's at short waves; and a
layer over a half-space by Knopoff's global matrix (six boundary conditions
on plain potentials, written here from Hooke's law, no stiffness matrices).
"""

import math

import numpy as np
import pytest

from railtrack.equations.ground_waves import fundamental_phase_speed, rayleigh_speed
from railtrack.model.ground import Ground, SoilLayer


def test_rayleigh_speed_for_a_quarter_poisson_ratio_is_exact():
    assert abs(rayleigh_speed(150.0, 0.25) / 150.0 - math.sqrt(2 - 2 / math.sqrt(3))) < 1e-12


@pytest.mark.parametrize("nu, tol", [(0.05, 1.2e-2), (0.1, 8e-3), (0.25, 2.5e-3), (0.3, 2e-3),
                                     (0.4, 1e-3), (0.49, 1e-3)])
def test_rayleigh_speed_meets_viktorovs_approximation(nu, tol):
    # the fit is ~1 % low at nu = 0.05 and within 0.1 % for nearly incompressible soil
    assert abs(rayleigh_speed(1.0, nu) / ((0.862 + 1.14 * nu) / (1 + nu)) - 1) < tol


@pytest.mark.parametrize("nu", [0.15, 0.25, 0.45])
def test_the_stiffness_determinant_of_a_half_space_finds_rayleighs_root(nu):
    ground = Ground.homogeneous(120.0, nu, 1800.0, 0.05)
    got = fundamental_phase_speed(ground, [1.0, 40.0])
    assert np.max(np.abs(got / rayleigh_speed(120.0, nu) - 1)) < 1e-9


SOFT_OVER_STIFF = Ground((SoilLayer(100.0, 0.3, 1800.0, 0.02, thickness=2.0),),
                         SoilLayer(250.0, 0.3, 2000.0, 0.02))


def test_the_fundamental_mode_goes_from_the_half_spaces_rayleigh_speed_to_the_layers():
    low, high = fundamental_phase_speed(SOFT_OVER_STIFF, [0.05, 300.0])
    # wavelength 4.6 km over a 2 m layer: within 0.05 %; 0.3 m waves: exp(-40) from the layer's
    assert abs(low / rayleigh_speed(250.0, 0.3) - 1) < 5e-4
    assert abs(high / rayleigh_speed(100.0, 0.3) - 1) < 1e-9
    speeds = fundamental_phase_speed(SOFT_OVER_STIFF, np.geomspace(0.05, 300.0, 25))
    assert np.all(np.diff(speeds) < 0)                          # normally dispersive


def _global_matrix(layer: SoilLayer, half: SoilLayer, k: float, omega: float) -> complex:
    """Knopoff's 6x6 determinant: free surface, welded interface, decaying half-space."""
    def fields(soil, a, shift):
        # potentials exp(i k x + a (z - shift)), z down; columns (u, w, tau_xz, sigma_zz)
        lam, mu = soil.lame_lambda, soil.shear_modulus
        e = lambda z: np.exp(a * (z - shift))                  # noqa: E731
        p_wave = lambda z: e(z) * np.array([1j * k, a, 2j * mu * k * a,        # noqa: E731
                                            lam * (a * a - k * k) + 2 * mu * a * a])
        s_wave = lambda z: e(z) * np.array([-a, 1j * k, -mu * (a * a + k * k),  # noqa: E731
                                            2j * mu * k * a])
        return p_wave, s_wave

    h = layer.thickness
    a_p = np.sqrt(k * k - (omega / layer.p_wave_speed) ** 2 + 0j)
    a_s = np.sqrt(k * k - (omega / layer.shear_wave_speed) ** 2 + 0j)
    b_p = np.sqrt(k * k - (omega / half.p_wave_speed) ** 2 + 0j)
    b_s = np.sqrt(k * k - (omega / half.shear_wave_speed) ** 2 + 0j)
    layer_fields = [fields(layer, -a_p, 0.0)[0], fields(layer, -a_s, 0.0)[1],
                    fields(layer, a_p, h)[0], fields(layer, a_s, h)[1]]
    half_fields = [fields(half, -b_p, h)[0], fields(half, -b_s, h)[1]]
    matrix = np.zeros((6, 6), dtype=complex)
    for j, field in enumerate(layer_fields):
        matrix[0:2, j] = field(0.0)[2:]                          # no traction at the surface
        matrix[2:6, j] = field(h)                                # continuity at z = h
    for j, field in enumerate(half_fields):
        matrix[2:6, 4 + j] = -field(h)
    return np.linalg.det(matrix)


@pytest.mark.parametrize("frequency", [3.0, 12.0, 30.0])
def test_the_fundamental_mode_is_a_root_of_knopoffs_global_matrix(frequency):
    layer, half = SOFT_OVER_STIFF.layers[0], SOFT_OVER_STIFF.halfspace
    c = float(fundamental_phase_speed(SOFT_OVER_STIFF, frequency)[0])
    omega = 2 * math.pi * frequency
    below, above = (_global_matrix(layer, half, omega / (c * (1 + s * 1e-6)), omega)
                    for s in (-1, 1))
    # the global determinant changes sign within +-1e-6 c of our root ...
    assert (below * np.conj(above)).real < 0
    # ... and not within 0.5 % of it on either side (so the sign change is the root's)
    far = [_global_matrix(layer, half, omega / (c * (1 + s * 5e-3)), omega) for s in (-1, 1)]
    assert (far[0] * np.conj(below)).real > 0 and (far[1] * np.conj(above)).real > 0


def test_a_stiff_crust_keeps_its_long_waves_and_leaks_its_short_ones():
    crust = Ground((SoilLayer(300.0, 0.3, 2000.0, 0.02, thickness=2.0),),
                   SoilLayer(100.0, 0.3, 1800.0, 0.02))
    # inversely dispersive: long waves see the half-space and travel at its Rayleigh speed,
    # approached linearly in the frequency (halving it halves the excess)
    excess = fundamental_phase_speed(crust, [0.004, 0.002]) / rayleigh_speed(100.0, 0.3) - 1
    assert 0 < excess[1] < 1e-3 and excess[0] / excess[1] == pytest.approx(2.0, rel=0.05)
    # short waves would travel faster than the half-space's shear waves: no guided mode
    with pytest.raises(ValueError, match="no Rayleigh mode .* 20.0 Hz"):
        fundamental_phase_speed(crust, 20.0)


@pytest.mark.parametrize("call, match", [
    (lambda: rayleigh_speed(100.0, 0.5), "poisson_ratio"),
    (lambda: rayleigh_speed(-100.0, 0.3), "shear_wave_speed"),
    (lambda: fundamental_phase_speed(SOFT_OVER_STIFF, [10.0, 0.0]), "frequency")])
def test_bad_wave_questions_are_refused_by_name(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_a_published_layered_profile_has_disbas_fundamental_rayleigh_speeds():
    # an independent code's reference (disba, K. Luu, doi 10.5281/zenodo.3987395: its
    # test/test_dispersion.py, after Herrmann's surf96): four strata of 0.5 km over a
    # half-space, c_p = 1.0-1.4 km/s, c_s = c_p / 1.73, 2 g/cm^3; the fundamental Rayleigh
    # mode's phase velocities at 20 periods from 1 to 10 s sum to 11.788 km/s (Dunkin's
    # algorithm; its fast-delta variant gives 11.782, and disba's own test allows 1e-3)
    p_speed = 1000.0 * (1.0 + 0.1 * np.arange(5))
    ratio = 1.73**2
    nu = (ratio - 2) / (2 * (ratio - 1))
    strata = [SoilLayer(c / 1.73, nu, 2000.0, thickness=500.0) for c in p_speed]
    ground = Ground(tuple(strata[:-1]), SoilLayer(p_speed[-1] / 1.73, nu, 2000.0))
    periods = np.logspace(0.0, 1.0, 20)
    speeds = fundamental_phase_speed(ground, 1.0 / periods, points=2000)
    assert abs(speeds.sum() / 1e3 - 11.788) < 1e-3          # measured: 11.7878
