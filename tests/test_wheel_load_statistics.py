"""Statistics of the dynamic wheel load (issue 32, item 3).

The Monte Carlo over random rails (`railtrack.studies.wheel_load_statistics`)
against the spectral integral on the linearised track
(`railtrack.equations.track_wheel_load`), the spectral integral against the
rigid track's and the free rail's, the mean against statics, and Eisenmann's
factor against its own statement.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.equations.eisenmann import (eisenmann_dynamic_load, eisenmann_speed_factor,
                                           eisenmann_std_ratio)
from railtrack.equations.track_wheel_load import (moving_wheels_receptance,
                                                  track_wheel_load_std,
                                                  track_wheel_load_transfer)
from railtrack.equations.vehicle_response import spectral_wheel_load_std
from railtrack.equations.wheel_train_receptance import wheel_train_receptance
from railtrack.model.irregularity import FRASpectrum
from railtrack.studies import wheel_load_statistics as study
from railtrack.studies.wheel_load_statistics import wheel_load_statistics

CAR = rt.Vehicle.manchester()
TRACK, LAW = rt.Track.paper(), rt.LinearFoundation.paper()
H, SPEED, BAND = 26.4, 45.0, (1.5, 25.0)


@pytest.fixture(scope="module")
def class_six():
    """12 rails of FRA class 6 (sigma ~ 0.05 Q: Hertz nearly linear), one wagon; ~2 s."""
    return wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(6), SPEED, wagon_length=H,
                                 realisations=12, seed=100, progress=False)


def test_monte_carlo_sigma_matches_the_spectral_sum_on_the_track(class_six):
    found = class_six
    assert found.failed == 0
    # The same harmonics as the rails (period H): the linear counterpart of the
    # Monte Carlo; per wheel on the modelled rail, half the wheelset's.
    spectral = track_wheel_load_std(CAR, TRACK, LAW, FRASpectrum(6), SPEED, BAND, H,
                                    period=H) / 2
    # The MC's own sampling error of sigma from N realisations: the standard
    # error of the mean variance, sd(sigma_i^2) / sqrt(N), over 2 sigma.  For a
    # linear track a rail's variance over time does not depend on its random
    # phases (Parseval: harmonics 2..17 of H never meet the sleepers' 44, 88, ..
    # nor their sidebands), so this error only measures Hertz's curvature.
    n = found.converged.sum()
    sampling = np.std(found.std ** 2, axis=0, ddof=1) / np.sqrt(n) / (2 * spectral)
    # Beyond it, the model's own difference: Hertz linearised ((2/3 sigma/Q)^2 ~ 1e-3
    # at class 6), sleepers smeared, the solver's truncation (measured: 2e-4).
    # Leaving out the sleeper-passing variance would miss by 4.6e-3; a rigid
    # track by 12 %.
    allowance = 3 * sampling + 2e-3
    assert np.all(np.abs(found.rail_std / spectral - 1) <= allowance)
    assert np.all(found.smooth_std > 0)            # the sleepers alone move the load


def test_a_linear_rail_gives_each_realisation_the_same_variance(class_six):
    # Parseval again: random phases, fixed amplitudes, a nearly linear response
    spread = np.std(class_six.std, axis=0, ddof=1) / class_six.std.mean(axis=0)
    assert np.all(spread < 1e-3)


def test_mean_wheel_load_is_the_static_load(class_six):
    # Each body is statically determinate on its supports and no acceleration
    # has a mean over a period: the mean contact force is Q whatever the rail.
    # The solver enforces it to its contact tolerance (1e-9 Q); samples evenly
    # over the period give the mean harmonic up to aliasing (harmonics of 2048).
    assert np.all(np.abs(class_six.mean / class_six.static_load - 1) < 1e-8)
    rough = wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(4), SPEED, wagon_length=H,
                                  realisations=2, progress=False)   # Hertz far from linear
    assert np.all(np.abs(rough.mean / rough.static_load - 1) < 1e-8)
    assert np.all(rough.pooled_std > 3 * class_six.pooled_std)


def test_quantiles_are_ordered_and_beside_the_normal_bounds(class_six):
    found = class_six
    assert np.all(np.diff(found.upper, axis=0) > 0) and np.all(np.diff(found.lower, axis=0) < 0)
    assert np.all(found.lower < found.mean) and np.all(found.mean < found.upper)
    assert np.all(found.peak.max(axis=0) >= found.upper[-1])
    # the 68.3 % interval of a nearly normal load: Q + sigma within a few %
    assert np.allclose(found.upper[0], found.normal_bounds[0], rtol=0.02)


def test_a_very_stiff_track_gives_the_rigid_track_value():
    with pytest.warns(UserWarning):                 # implausible on purpose
        stiff = rt.Track.paper(pad_stiffness=1e15, rail_bending_stiffness=6.3e12)
        law = rt.LinearFoundation(1e15, 1e6)
    rigid = spectral_wheel_load_std(CAR, FRASpectrum(4), SPEED, BAND)
    on_track = track_wheel_load_std(CAR, stiff, law, FRASpectrum(4), SPEED, BAND, H,
                                    contact_stiffness=np.inf)
    assert np.allclose(on_track, rigid, rtol=1e-6)
    soft = track_wheel_load_std(CAR, TRACK, LAW, FRASpectrum(4), SPEED, BAND, H)
    assert np.all(np.abs(soft / rigid - 1) > 0.05)  # the paper's track is no rigid one


def test_the_lattice_sum_on_a_vanishing_support_is_the_free_rails():
    with pytest.warns(UserWarning):
        free = rt.Track.paper(pad_stiffness=1e-3, pad_damping=0.0)
    passage = rt.Passage(free, CAR.train(H, SPEED))
    d = np.asarray(passage.axle_positions)
    offsets = d[None, :] - d[:, None]
    for j in (2, 9):
        wavenumber = 2 * np.pi * j / H
        ours = moving_wheels_receptance(passage, LAW, wavenumber, offsets)
        theirs = wheel_train_receptance(passage, wavenumber * SPEED, offsets)
        assert np.allclose(ours, theirs, rtol=1e-6)


def test_clear_errors_on_bad_input():
    spectrum = FRASpectrum(6)
    for bad in (dict(realisations=1), dict(seed=-1), dict(samples=10), dict(wagons=0)):
        with pytest.raises(ValueError, match=next(iter(bad))):
            wheel_load_statistics(TRACK, LAW, CAR, spectrum, SPEED, wagon_length=H, **bad)
    with pytest.raises(ValueError, match="whole number"):
        wheel_load_statistics(TRACK, LAW, CAR, spectrum, SPEED, wagon_length=26.5,
                              realisations=2)
    with pytest.raises(TypeError, match="Vehicle"):
        wheel_load_statistics(TRACK, LAW, rt.Wheel(900.0), spectrum, SPEED, wagon_length=H)
    with pytest.raises(TypeError, match="progress"):
        wheel_load_statistics(TRACK, LAW, CAR, spectrum, SPEED, wagon_length=H,
                              realisations=2, progress="yes")
    with pytest.raises(TypeError, match="LinearFoundation"):
        track_wheel_load_std(CAR, TRACK, rt.CubicFoundation.paper(0.8), spectrum, SPEED,
                             BAND, H)
    passage = rt.Passage(TRACK, CAR.train(H, SPEED))
    with pytest.raises(ValueError, match="wavenumbers"):
        track_wheel_load_transfer(CAR, passage, LAW, [0.0])
    with pytest.raises(ValueError, match="wavelengths"):
        track_wheel_load_std(CAR, TRACK, LAW, spectrum, SPEED, (25.0, 1.5), H)


def test_progress_bar_follows_the_convention(capsys):
    wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(6), SPEED, wagon_length=H,
                          realisations=2, progress=False)
    assert capsys.readouterr().err == ""
    wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(6), SPEED, wagon_length=H,
                          realisations=2, progress=True)
    assert "random rails" in capsys.readouterr().err


def test_eisenmann_as_stated():
    kmh = 1 / 3.6
    assert eisenmann_speed_factor(30 * kmh) == 1.0
    assert eisenmann_speed_factor(60 * kmh) == pytest.approx(1.0)     # continuous at 60
    assert eisenmann_speed_factor(130 * kmh) == pytest.approx(1.5)    # halfway to 200
    assert eisenmann_speed_factor(200 * kmh) == pytest.approx(2.0)
    ratios = [eisenmann_std_ratio(130 * kmh, c) for c in ("very good", "good", "poor")]
    assert ratios == pytest.approx([0.15, 0.30, 0.45])
    assert eisenmann_dynamic_load(100e3, 130 * kmh, "good", 2) == pytest.approx(160e3)
    for bad in (dict(speed=250 * kmh), dict(speed=-1.0), dict(condition="bad"), dict(t=4)):
        arguments = dict(load=100e3, speed=30.0, condition="good", t=3) | bad
        with pytest.raises(ValueError):
            eisenmann_dynamic_load(**arguments)


def test_a_speed_typed_in_km_per_h_warns_before_any_solve():
    # 160 km/h typed as 160 "m/s": faster than any train in service (350 km/h), and
    # over a rough rail the wheels leave it (the first realisation fails after a
    # minute).  The warning comes first: realisations=1 is refused only after it.
    with pytest.warns(rt.PlausibilityWarning, match=r"km/h\? \(160 km/h = 44.4 m/s\)") as caught:
        with pytest.raises(ValueError, match="realisations"):
            wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(4), 160.0, wagon_length=H,
                                  realisations=1)
    assert caught[0].filename == __file__
    with warnings.catch_warnings():      # a service speed (350 km/h at most) is quiet
        warnings.simplefilter("error", rt.PlausibilityWarning)
        for speed in (SPEED, 350 / 3.6):
            with pytest.raises(ValueError, match="realisations"):
                wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(4), speed,
                                      wagon_length=H, realisations=1)


def test_a_first_realisation_that_fails_is_warned_about_before_the_others(monkeypatch):
    # Every rough ride is made to fail (one Newton step); the smooth one solves.
    real, before = study.solve, []

    def one_step(*args, profile=None, **kwargs):
        if profile is None:
            return real(*args, profile=profile, **kwargs)
        before.append(any("first realisation" in str(w.message) for w in caught))
        return real(*args, profile=profile, max_iterations=1, **kwargs)

    monkeypatch.setattr(study, "solve", one_step)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(RuntimeError, match="none of the 3"):
            wheel_load_statistics(TRACK, LAW, CAR, FRASpectrum(6), SPEED, wagon_length=H,
                                  realisations=3, progress=False)
    assert before == [False, True, True]     # warned after the first, before the second
    early = [w for w in caught if "first realisation" in str(w.message)]
    assert len(early) == 1 and issubclass(early[0].category, rt.ConvergenceWarning)
    assert "the other 2 may fail" in str(early[0].message)
    assert early[0].filename == __file__
