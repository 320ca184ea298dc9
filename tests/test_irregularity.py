"""Track spectra and the random and measured rails drawn from them (issue 32, item 2).

Truths: adaptive quadrature (scipy.integrate.quad) of the spectra against
their closed-form band integrals; the realisation's mean square, from
samples, against the spectrum's integral over the band, within the
midpoint rule's bound (dOmega^2/24 times the integral of |S''|, S'' by
finite differences) and the band's two edge cells; periodicity, the seed,
finite differences of r for the slope; the spline's interpolation bound
for a measured rail; and today's wheel solver taking a random rail unchanged.
"""

import numpy as np
import pytest
from scipy.integrate import quad

import railtrack as rt
from railtrack.model.irregularity import FRASpectrum, GermanSpectrum
from railtrack.model.random_profile import MeasuredProfile, RandomProfile

BAND = (1.5, 25.0)                                    # wavelengths [m]
LOW, HIGH = 2 * np.pi / BAND[1], 2 * np.pi / BAND[0]  # wavenumbers [rad/m]
SPECTRA = [FRASpectrum(c) for c in range(1, 7)] + [GermanSpectrum("low"),
                                                   GermanSpectrum("high")]


def _quad(spectrum, a, b):
    return quad(spectrum, a, b, limit=400, epsabs=0.0, epsrel=1e-11)[0]


@pytest.mark.parametrize("spectrum", SPECTRA, ids=repr)
@pytest.mark.parametrize("band", [(LOW, HIGH), (0.05, 0.3), (1.0, 40.0)])
def test_the_closed_form_band_integral_is_the_quadrature(spectrum, band):
    assert spectrum.band_variance(*band) == pytest.approx(_quad(spectrum, *band), rel=1e-9)


def test_the_fra_classes_order_by_roughness_class_6_smoothest():
    omega = np.geomspace(LOW, HIGH, 50)
    densities = np.array([FRASpectrum(c)(omega) for c in range(1, 7)])
    assert np.all(np.diff(densities, axis=0) < 0)            # pointwise, class by class
    sigmas = [FRASpectrum(c).band_variance(LOW, HIGH) ** 0.5 for c in range(1, 7)]
    assert np.all(np.diff(sigmas) < 0)
    # 1.5-25 m: 8.58, 7.86, 6.43, 5.71, 3.57, 1.43 mm
    assert sigmas[0] == pytest.approx(8.58e-3, abs=0.01e-3)
    assert sigmas[5] == pytest.approx(1.43e-3, abs=0.01e-3)


def test_the_german_high_disturbance_is_rougher_than_the_low():
    omega = np.geomspace(LOW, HIGH, 50)
    ratio = GermanSpectrum("high")(omega) / GermanSpectrum("low")(omega)
    assert np.allclose(ratio, 10.80 / 4.032, rtol=1e-12)


def _midpoint_bound(spectrum, omega, step):
    """dOmega^2/24 * sum over cells of max|S''| * dOmega, S'' by central differences."""
    points = omega[:, None] + step * np.linspace(-0.5, 0.5, 5)[None, :]
    h = 1e-3 * points
    second = (spectrum(points + h) - 2 * spectrum(points) + spectrum(points - h)) / h ** 2
    return step ** 2 / 24 * np.sum(np.abs(second).max(axis=1)) * step


@pytest.mark.parametrize("spectrum", [FRASpectrum(4), GermanSpectrum("high")], ids=repr)
@pytest.mark.parametrize("wagons", [5, 30])
def test_the_realisation_variance_is_the_band_integral(spectrum, wagons):
    rail = RandomProfile(spectrum, BAND, wagons * 18.0, seed=7)
    step = 2 * np.pi / rail.period
    samples = 4 * int(rail.harmonics[-1])                 # > 2 j_max: exact for the sum
    x = np.arange(samples) * rail.period / samples
    mean_square = float(np.mean(rail(x) ** 2))
    assert mean_square == pytest.approx(rail.variance, rel=1e-10)
    # the cells around the harmonics, by quadrature: the midpoint rule's error
    omega = rail.wavenumbers
    cells = _quad(spectrum, omega[0] - step / 2, omega[-1] + step / 2)
    bound = _midpoint_bound(spectrum, omega, step)
    assert abs(mean_square - cells) <= 1.5 * bound
    assert bound < 0.05 * cells
    # the nominal band differs from the cells by at most half a cell at each end
    edges = step / 2 * (spectrum(LOW - step / 2) + spectrum(HIGH - step / 2))
    assert abs(mean_square - spectrum.band_variance(LOW, HIGH)) <= 1.5 * bound + edges


def test_the_midpoint_error_falls_as_the_period_grows():
    spectrum = FRASpectrum(4)
    errors = []
    for wagons in (5, 10, 20):
        rail = RandomProfile(spectrum, BAND, wagons * 18.0, seed=1)
        step = 2 * np.pi / rail.period
        omega = rail.wavenumbers
        errors.append(abs(rail.variance - _quad(spectrum, omega[0] - step / 2,
                                                omega[-1] + step / 2)))
    assert errors[1] < errors[0] / 3 and errors[2] < errors[1] / 3     # ~ dOmega^2


def test_the_random_rail_repeats_and_its_slope_is_its_derivative():
    rail = RandomProfile(FRASpectrum(3), BAND, 36.0, seed=11)
    x = np.linspace(-5.0, 41.0, 777)
    assert np.allclose(rail(x + rail.period), rail(x), rtol=0, atol=1e-15)
    assert np.allclose(rail.slope(x + 2 * rail.period), rail.slope(x), rtol=0, atol=1e-13)
    h = 1e-4
    difference = (rail(x + h) - rail(x - h)) / (2 * h)
    assert np.allclose(rail.slope(x), difference, rtol=0,
                       atol=1e-6 * np.max(np.abs(difference)))
    assert rail(np.zeros((3, 4))).shape == (3, 4)


def test_a_seed_gives_the_same_rail_another_seed_another():
    x = np.linspace(0.0, 18.0, 101)
    one = RandomProfile(FRASpectrum(4), BAND, 18.0, seed=5)
    again = RandomProfile(FRASpectrum(4), BAND, 18.0, seed=5)
    other = RandomProfile(FRASpectrum(4), BAND, 18.0, seed=6)
    assert np.array_equal(one(x), again(x)) and one == again
    assert not np.allclose(one(x), other(x))


@pytest.mark.parametrize("arguments, error", [
    ((FRASpectrum(4), (1.5, 25.0), 1.0, 0), ValueError),      # no harmonic in the band
    ((FRASpectrum(4), (25.0, 1.5), 18.0, 0), ValueError),
    ((FRASpectrum(4), (1.5, 25.0), 18.0, -1), TypeError),
    ((FRASpectrum(4), (1.5, 25.0), 18.0, True), TypeError),
    ((FRASpectrum(4), (1.5, 25.0), 0.0, 0), ValueError),
    (("class 4", (1.5, 25.0), 18.0, 0), TypeError),
])
def test_impossible_random_rails_are_refused(arguments, error):
    with pytest.raises(error):
        RandomProfile(*arguments)


def test_unknown_spectra_are_refused():
    with pytest.raises(ValueError, match="1-6"):
        FRASpectrum(7)
    with pytest.raises(ValueError, match="'low' or 'high'"):
        GermanSpectrum("medium")


def test_a_measured_rail_passes_through_its_samples_and_repeats():
    heights = RandomProfile(FRASpectrum(4), BAND, 18.0, seed=3)(np.arange(180) * 0.1)
    rail = MeasuredProfile(heights, 0.1)
    assert rail.period == pytest.approx(18.0)
    assert np.allclose(rail(np.arange(180) * 0.1), heights, rtol=0, atol=1e-15)
    x = np.linspace(-3.0, 20.0, 301)
    assert np.allclose(rail(x + 18.0), rail(x), rtol=0, atol=1e-15)
    h = 1e-5
    assert np.allclose(rail.slope(x), (rail(x + h) - rail(x - h)) / (2 * h), rtol=0,
                       atol=1e-7 * np.max(np.abs(rail.slope(x))))
    # no kink where the record repeats
    seam = rail.slope(np.array([18.0 - 1e-9, 1e-9]))
    assert seam[0] == pytest.approx(seam[1], abs=1e-6 * np.max(np.abs(rail.slope(x))))


def test_a_measured_rail_reproduces_a_smooth_rail_within_the_spline_bound():
    truth = RandomProfile(FRASpectrum(4), BAND, 18.0, seed=3)
    spacing = 0.1
    rail = MeasuredProfile(truth(np.arange(180) * spacing), spacing)
    x = np.linspace(0.0, 18.0, 2001)
    fourth = np.sum(truth.amplitudes * truth.wavenumbers ** 4)    # >= max |r''''|
    bound = 5 / 384 * spacing ** 4 * fourth
    error = np.max(np.abs(rail(x) - truth(x)))
    assert error <= 2 * bound                    # periodic spline: the clamped bound, x2
    assert error < 1e-3 * np.max(np.abs(truth(x)))


def test_a_random_rail_plugs_into_the_wheel_solver_unchanged():
    train = rt.Train.paper(speed=45.0)
    rail = RandomProfile(FRASpectrum(5), BAND, float(train.wagon_length), seed=2)
    result = rt.solve(rt.Track.paper(), train, rt.LinearFoundation(20e6, 0.2e6), 120,
                      wheel=rt.Wheel(600.0), profile=rail)
    assert result.converged
    t = np.linspace(0.0, result.period, 2048, endpoint=False)
    # the wheel's acceleration averages to zero over a period: the mean force is Q
    assert np.mean(result.contact_force(t)) == pytest.approx(
        float(train.axle_loads[0]), rel=1e-6)
