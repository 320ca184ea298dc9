"""A flat on one wheel of every wagon (issue 32, item 5): `rt.WheelFlat`.

Independent truths: the fresh flat's sagitta (geometry), superposition (a
rail dip felt by every wheel is, to first order in its depth, the sum of a
flat of the same shape on each wheel alone), the massless wheel that
follows any profile and presses with its static load, and the time-domain
ring with the same flat.
"""

import re
import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.plausibility import PlausibilityWarning
from railtrack.model.wheel_flat import felt_by, sagitta


def _peaks(solution, samples):
    t = np.arange(samples) * solution.period / samples
    return solution.contact_force(t)


def test_sagitta_is_the_chord_height_of_the_wheel_circle():
    radius, chord = 0.46, 0.05
    depth = sagitta(chord, radius)
    # the chord's ends lie on the circle: (l/2)^2 + (R - d)^2 = R^2
    assert (0.5 * chord) ** 2 + (radius - depth) ** 2 == pytest.approx(radius**2, rel=1e-14)
    assert depth == pytest.approx(chord**2 / (8 * radius), rel=(chord / radius) ** 2)
    with pytest.raises(ValueError, match="diameter"):
        sagitta(1.0, 0.46)


def test_the_flat_is_felt_by_its_wheel_in_every_wagon_only():
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1)
    np.testing.assert_array_equal(felt_by(flat, 6, 2), [0, 1, 0, 1, 0, 1])
    np.testing.assert_array_equal(felt_by(rt.CosineDip(1e-3, 1.0, 18.0), 3), [1, 1, 1])
    with pytest.raises(ValueError, match="a wagon has 2 wheels"):
        felt_by(rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=2), 2)
    # strikes every circumference, with the flat's depth at its centre
    x = np.array([0.0, 3.0, 6.0, 0.05, 1.5])
    np.testing.assert_allclose(flat(x), [-0.5e-3, -0.5e-3, -0.5e-3, 0.0, 0.0], atol=1e-18)


@pytest.mark.parametrize("wheel", [-1, 1.0, True, "1"])
def test_a_wheel_that_is_not_an_index_is_refused(wheel):
    with pytest.raises(ValueError, match="wheel must be"):
        rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=wheel)


def test_a_depth_typed_in_millimetres_warns():
    with pytest.warns(PlausibilityWarning, match="WheelFlat.depth"):
        rt.WheelFlat(0.5, 0.1, 3.0)
    with pytest.warns(PlausibilityWarning, match="WheelFlat.circumference"):
        rt.WheelFlat(0.5e-3, 0.01, 0.1)  # a radius of 16 mm


def test_a_circumference_off_the_sleeper_pattern_is_refused():
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 2.89, wheel=1)  # 2 pi 0.46 m
    with pytest.raises(ValueError, match="whole number of sleeper spacings"):
        rt.solve(track, train, rt.LinearFoundation.ballasted(), 600,
                 wheel=rt.Wheel(600.0), profile=flat)


def test_a_massless_wheel_rides_over_its_flat_with_its_static_load():
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3)
    with rt.plausibility("ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore")  # its truncation estimate of a flat rail
        s = rt.solve(track, train, rt.LinearFoundation.ballasted(), 300,
                     wheel=rt.Wheel(1e-6), profile=flat)
    p = _peaks(s, 4800)
    q = np.asarray(train.axle_loads)[:, None]
    assert s.converged
    np.testing.assert_allclose(p, np.broadcast_to(q, p.shape), rtol=1e-6)


def test_a_dip_under_every_wheel_is_the_sum_of_a_flat_on_each():
    # to first order in the depth, the rail's dip = the flat on wheel 0 + on wheel 1
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    law, wheel = rt.LinearFoundation.ballasted(), rt.Wheel(600.0)
    depth, length, period, centre = 1e-7, 0.1, 3.0, 0.3
    m = 300

    def change(profile):
        with rt.plausibility("ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")  # 0.1 um: far below any real flat
            s = rt.solve(track, train, law, m, wheel=wheel, profile=profile)
            smooth = rt.solve(track, train, law, m, wheel=wheel,
                              profile=rt.CosineDip(0.0, length, period, centre))
        assert s.converged
        return _peaks(s, 16 * m) - _peaks(smooth, 16 * m)

    with rt.plausibility("ignore"):
        dip = change(rt.CosineDip(depth, length, period, centre))
        flats = sum(change(rt.WheelFlat(depth, length, period, wheel=k, centre=centre))
                    for k in (0, 1))
    scale = float(np.max(np.abs(dip)))
    assert scale > 1.0  # N: the dip is felt
    np.testing.assert_allclose(flats, dip, atol=1e-3 * scale)
    # and each flat alone is not the dip: the wheels feel different things
    with rt.plausibility("ignore"):
        alone = change(rt.WheelFlat(depth, length, period, wheel=1, centre=centre))
    assert np.max(np.abs(alone[0])) < 0.2 * np.max(np.abs(alone[1]))


def test_harmonic_balance_p1_of_a_flat_agrees_with_the_ring():
    # The ring (finite elements, Newmark; its error what halving dt changes)
    # and harmonic balance at m = 1200 (its error its truncation estimate).
    # docs/flat_p1.md has both converged: 164.3 kN.
    track, law = rt.Track.ballasted(), rt.LinearFoundation.ballasted()
    train, wheel = rt.Train.paper(speed=30.0), rt.Wheel(600.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3)
    ring = []
    for steps in (7200, 14400):  # dt = 83 and 42 us; the flat passes in 3.3 ms
        r = rt.simulate_time_domain(track, train, law, 4, steps, wheel=wheel,
                                    profile=flat, tol=1e-3, warn_step_error=None)
        assert r.converged
        ring.append(float(r.contact_forces[:, 1].max()))
    ring_error = abs(ring[1] - ring[0])
    assert ring_error < 0.01 * ring[1]
    m = 1200
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the truncation warning itself
        s = rt.solve(track, train, law, m, wheel=wheel, profile=flat)
    p = _peaks(s, 16 * m)
    q = float(np.max(train.axle_loads))
    assert p[1].max() > 1.8 * q  # the flat's blow, on the flat wheel above all
    assert p[1].max() - q > 5 * (p[0].max() - q)
    assert abs(p[1].max() - ring[1]) < s.truncation_error * q + ring_error


def test_a_circumference_typed_in_cm_or_mm_is_refused_before_any_solve():
    # 300 m would be solved as a train of 17 wagons, 3000 m as 167: memory runs out
    for typed in (300.0, 3000.0):
        with pytest.raises(ValueError, match="cm or mm"), rt.plausibility("ignore"):
            rt.WheelFlat(0.5e-3, 0.1, typed)


def test_a_flat_length_typed_in_mm_is_named_before_the_length_check():
    with pytest.warns(PlausibilityWarning, match="WheelFlat.length"):
        with pytest.raises(ValueError, match="shorter than its period"):
            rt.WheelFlat(0.5e-3, 60.0, 3.0)


def test_the_period_error_names_the_circumferences_that_fit():
    # 920 mm wheel, 0.6 m spacings, 18 m wagon: 3.0 m (5 spacings, 6 a wagon) is nearest
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, np.pi * 0.92, wheel=1)
    with pytest.raises(ValueError, match=r"nearest are 3 m and 3\.6 m"):
        rt.solve(track, train, rt.LinearFoundation.ballasted(), 600,
                 wheel=rt.Wheel(600.0), profile=flat)


def test_extremes_and_the_repr_read_the_flats_blow_as_a_fine_grid_does():
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the truncation estimate at m = 600
        s = rt.solve(track, train, rt.LinearFoundation.ballasted(), 600,
                     wheel=rt.Wheel(600.0), profile=flat)
    fine = float(_peaks(s, 200_000)[1].max())
    assert s.extremes()["max"][1] == pytest.approx(fine, rel=2e-3)
    shown = float(re.search(r"contact force \[kN\]: max ([0-9.]+)", repr(s)).group(1))
    assert shown * 1e3 == pytest.approx(fine, rel=2e-3)  # 4 m samples read 0.6 % low
    assert "WheelFlat on wheel 1" in repr(s)


def test_a_flat_on_every_wheel_is_the_rail_dip_of_the_same_shape_exactly():
    # each wheel of the 2-wheel wagon feels the one flat it carries: the same r(x)
    # as a rail dip under both, so harmonic balance and the ring give the same answer
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    law, wheel = rt.LinearFoundation.ballasted(), rt.Wheel(600.0)
    dip = rt.CosineDip(0.5e-3, 0.1, 3.0, centre=0.3)
    flats = rt.ProfileSum(*(rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=k, centre=0.3)
                            for k in (0, 1)))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the truncation estimate at m = 300
        a, b = (rt.solve(track, train, law, 300, wheel=wheel, profile=p) for p in (dip, flats))
    np.testing.assert_allclose(_peaks(b, 4800), _peaks(a, 4800), rtol=1e-9, atol=1e-6)
    ring = [rt.simulate_time_domain(track, train, law, 2, 1800, wheel=wheel, profile=p,
                                    tol=1e-3, warn_step_error=None).contact_forces
            for p in (dip, flats)]
    np.testing.assert_allclose(ring[1], ring[0], rtol=1e-9, atol=1e-6)


def test_a_flat_on_a_dipped_rail_feels_both_and_the_other_wheel_only_the_dip():
    # the mean rail height each wheel feels, against the cosine's closed-form mean
    # -depth length / (2 period): wheel 0 the weld's, wheel 1 the weld's and the flat's
    weld = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.0)
    both = rt.ProfileSum(weld, rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1))
    assert both.period == 18.0
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = rt.solve(track, train, rt.LinearFoundation.ballasted(), 300,
                     wheel=rt.Wheel(600.0), profile=both)
    assert s.converged
    weld_mean, flat_mean = -0.5e-3 * 1.0 / 36.0, -0.5e-3 * 0.1 / 6.0
    np.testing.assert_allclose(s.profile_harmonics[:, 0].real,
                               [weld_mean, weld_mean + flat_mean], rtol=1e-3)
    with pytest.raises(ValueError, match="repeat together"):
        rt.ProfileSum(rt.WheelFlat(0.5e-3, 0.1, 3.0), rt.WheelFlat(0.5e-3, 0.1, 3.6))
    with pytest.raises(TypeError, match="two or more"):
        rt.ProfileSum(rt.WheelFlat(0.5e-3, 0.1, 3.0))


def test_the_export_records_the_flat_with_its_units():
    track, train = rt.Track.ballasted(), rt.Train.paper(speed=30.0)
    flat = rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1, centre=0.3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = rt.solve(track, train, rt.LinearFoundation.ballasted(), 60,
                     wheel=rt.Wheel(600.0), profile=flat)
    attrs = s.to_xarray(samples=64).attrs
    assert attrs["profile"] == "WheelFlat" and attrs["profile_wheel"] == 1
    units = dict(item.split(": ") for item in attrs["input_units"].split("; "))
    assert units["profile_circumference"] == "m" and units["profile_depth"] == "m"
