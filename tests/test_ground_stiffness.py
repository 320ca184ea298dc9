"""The layered ground's surface flexibility against closed forms and limits (issue 31).

Truths independent of the stiffness-matrix code: Boussinesq's static
half-space in the wavenumber domain, (1 - nu) / (mu k); the 1D column
(k -> 0): a half-space is Lysmer's dashpot i / (omega rho c_p) for
exp(-i omega t), a layer on a rigid base tan(kappa h) / (M kappa); a layer
identical to the half-space below changes nothing; a thin layer on a rigid
base is a Winkler spring M / h per unit area.
"""

import math

import numpy as np
import pytest

from railtrack import plausibility
from railtrack.equations.ground_stiffness import surface_flexibility
from railtrack.model.ground import Ground, SoilLayer

K = np.array([1e-3, 0.05, 1.0, 30.0, 3e3])


@pytest.mark.parametrize("nu", [0.1, 0.25, 0.33, 0.45, 0.49])
def test_static_homogeneous_half_space_is_boussinesq(nu):
    ground = Ground.homogeneous(120.0, nu, 1900.0, 0.03)
    mu = 1900.0 * 120.0**2
    truth = (1 - nu) / (mu * K)
    assert np.max(np.abs(surface_flexibility(ground, K, 0.0) / truth - 1)) < 1e-6
    # as omega -> 0+ (omega / (k c_s) = 1e-5, a shift of ~1e-10) with the complex modulus
    nearly = surface_flexibility(ground, K, 1e-5 * K * 120.0)
    assert np.max(np.abs(nearly * (1 - 0.06j) / truth - 1)) < 1e-6


def test_long_waves_on_a_half_space_meet_lysmers_dashpot():
    layer = SoilLayer(150.0, 0.3, 1800.0)          # undamped: pure radiation
    omega = 2 * math.pi * 20.0
    got = surface_flexibility(Ground((), layer), 1e-7 * omega / layer.p_wave_speed, omega)
    truth = 1j / (omega * layer.density * layer.p_wave_speed)
    assert abs(got / truth - 1) < 1e-6


def test_long_waves_on_a_layer_over_rigid_rock_resonate_as_a_column():
    layer = SoilLayer(150.0, 0.3, 1800.0, 0.02, thickness=4.0)
    with plausibility("ignore"):                         # no rock is this stiff: meant
        rock = SoilLayer(150.0 * 1e8, 0.3, 1800.0)       # impedance 1e8 times the layer's
    omega = np.array([5.0, 40.0, 120.0, 300.0])
    m_star = layer.constrained_modulus * layer.damping_factor(omega)
    kappa = omega * np.sqrt(layer.density / m_star)
    truth = np.tan(kappa * layer.thickness) / (m_star * kappa)
    got = surface_flexibility(Ground((layer,), rock), 1e-6, omega)
    assert np.max(np.abs(got / truth - 1)) < 1e-5


def test_a_layer_like_the_half_space_below_changes_nothing():
    soil = dict(shear_wave_speed=90.0, poisson_ratio=0.35, density=1700.0, damping_ratio=0.04)
    half = SoilLayer(**soil)
    one = Ground((SoilLayer(**soil, thickness=2.5),), half)
    two = Ground((SoilLayer(**soil, thickness=0.3), SoilLayer(**soil, thickness=7.0)), half)
    k = np.geomspace(1e-3, 1e2, 40)
    for omega in (0.0, 30.0, 400.0, -60.0):
        truth = surface_flexibility(Ground((), half), k, omega)
        for ground in (one, two):
            assert np.max(np.abs(surface_flexibility(ground, k, omega) / truth - 1)) < 1e-9


def test_a_thin_stiff_layer_on_rigid_rock_is_a_winkler_spring():
    layer = SoilLayer(200.0, 0.3, 2000.0, thickness=0.1)
    with plausibility("ignore"):                         # no rock is this stiff: meant
        rock = SoilLayer(200.0 * 1e5, 0.3, 2000.0)
    spring = layer.constrained_modulus / layer.thickness          # (lambda + 2 mu) / h [Pa/m]
    got = surface_flexibility(Ground((layer,), rock), 1e-2, 1.0)   # k h = 1e-3
    assert abs(1 / got / spring - 1) < 1e-5


def test_negative_frequency_gives_the_conjugate():
    ground = Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=3.0),),
                    SoilLayer(250.0, 0.25, 2000.0, 0.02))
    k = np.linspace(0.05, 5.0, 30)
    assert np.allclose(surface_flexibility(ground, k, -70.0),
                       np.conj(surface_flexibility(ground, k, 70.0)), rtol=1e-12, atol=0)


def test_damping_makes_the_ground_lose_energy():
    """Im(w/p) > 0 for omega > 0 under exp(-i omega t): the load does work on the ground."""
    ground = Ground((SoilLayer(80.0, 0.3, 1800.0, 0.05, thickness=3.0),),
                    SoilLayer(250.0, 0.25, 2000.0, 0.02))
    assert np.all(surface_flexibility(ground, np.geomspace(0.01, 50, 60), 80.0).imag > 0)


@pytest.mark.parametrize("bad", [0.0, -1.0, np.nan, np.inf])
def test_a_wavenumber_not_positive_is_refused(bad):
    with pytest.raises(ValueError, match="k"):
        surface_flexibility(Ground.homogeneous(100.0, 0.3, 1800.0), bad, 1.0)


@pytest.mark.parametrize("kwargs, match", [
    (dict(poisson_ratio=0.5), "poisson_ratio"), (dict(poisson_ratio=-0.1), "poisson_ratio"),
    (dict(thickness=-1.0), "thickness"), (dict(density=0.0), "density"),
    (dict(shear_wave_speed=-5.0), "shear_wave_speed"), (dict(damping_ratio=2.0), "damping")])
def test_bad_soil_is_refused_by_name(kwargs, match):
    soil = dict(shear_wave_speed=100.0, poisson_ratio=0.3, density=1800.0, thickness=2.0)
    with pytest.raises(ValueError, match=match):
        SoilLayer(**{**soil, **kwargs})


def test_a_half_space_in_the_layers_is_refused():
    with pytest.raises(ValueError, match="layers"):
        Ground((SoilLayer(100.0, 0.3, 1800.0),), SoilLayer(200.0, 0.3, 1800.0))
    with pytest.raises(ValueError, match="halfspace"):
        Ground((), SoilLayer(200.0, 0.3, 1800.0, thickness=3.0))


def test_the_soil_moduli_are_those_of_isotropic_elasticity():
    soil = SoilLayer.from_young_modulus(30e6, 0.25, 1800.0, 0.03, thickness=2.0)
    mu = 30e6 / 2.5                                                  # E / (2 (1 + nu))
    assert soil.shear_modulus == pytest.approx(mu, rel=1e-14)
    assert soil.young_modulus == pytest.approx(30e6, rel=1e-14)
    assert soil.lame_lambda == pytest.approx(mu, rel=1e-14)         # lambda = mu at nu = 1/4
    assert soil.p_wave_speed == pytest.approx(math.sqrt(3 * mu / 1800.0), rel=1e-14)
    assert soil.thickness == 2.0 and soil.damping_ratio == 0.03
    assert soil.damping_factor(-5.0) == pytest.approx(1 + 0.06j)
