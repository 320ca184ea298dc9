"""The train as its own object: validation, the axle factor of eq. (10), presets."""

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.ballast import ZHAI_2004, single_layer, two_layer_stiffness


@pytest.mark.parametrize("changes, message", [
    (dict(axle_positions=(1.0, 3.0)), "start at 0"),
    (dict(axle_positions=(0.0, 3.0, 3.0), axle_loads=(1e3,) * 3), "increase"),
    (dict(axle_positions=(0.0, 18.0)), "within the wagon"),
    (dict(axle_positions=(0.0, 3.0, 5.0)), "one entry per axle"),
    (dict(axle_loads=(75e3, -1.0)), "axle_loads"),
    (dict(speed=0.0), "speed"),
    (dict(wagon_length=np.nan), "wagon_length"),
])
def test_a_wagon_that_cannot_exist_is_refused_by_name(changes, message):
    with pytest.raises(ValueError, match=message):
        rt.Train.paper().replace(**changes)


def test_non_numeric_axles_are_a_type_error():
    with pytest.raises(TypeError, match="axle_positions"):
        rt.Train(18.0, ("front", "back"), (1e3, 1e3), 45.0)


def test_the_papers_wheel_pair_is_the_two_axle_case_of_the_axle_factor():
    passage = rt.Passage.paper()
    omega = np.linspace(-300.0, 300.0, 101)
    q, d, v = 75e3, 3.0, 45.0
    expected = q * (1.0 + np.exp(-1j * omega * d / v))          # eq. (10) as printed
    np.testing.assert_allclose(rt.axle_factor(passage, omega), expected, rtol=1e-14)


def test_the_axle_factor_of_a_coach_is_the_sum_of_its_axles_delayed():
    coach = rt.Train.passenger_coach()
    omega = np.linspace(0.0, 500.0, 7)
    total = rt.axle_factor(rt.Passage(rt.Track.paper(), coach), omega)
    parts = [rt.axle_factor(rt.Passage(rt.Track.paper(), coach.replace(
        axle_positions=(0.0,), axle_loads=(q,))), omega) * np.exp(-1j * omega * d / coach.speed)
        for d, q in zip(coach.axle_positions, coach.axle_loads)]
    np.testing.assert_allclose(total, sum(parts), rtol=1e-13)


def test_the_papers_q_and_d_exist_only_where_they_mean_something():
    assert rt.Train.paper().wheel_spacing == 3.0
    with pytest.raises(AttributeError, match="two-axle"):
        rt.Train.passenger_coach().wheel_spacing
    with pytest.raises(AttributeError, match="equal axle loads"):
        rt.Train(18.0, (0.0, 3.0), (1e3, 2e3), 45.0).wheel_load


def test_presets_fit_the_time_domain_ring_and_carry_their_axle_loads():
    for train, axle_load in [(rt.Train.passenger_coach(), 109.1e3), (rt.Train.freight_wagon(), 245.3e3)]:
        ratio = train.wagon_length / rt.Track.paper().sleeper_spacing
        assert ratio == pytest.approx(round(ratio), abs=1e-9)
        assert 2 * train.axle_loads[0] == pytest.approx(axle_load, rel=1e-3)
        assert train.axle_count == 4


@pytest.mark.parametrize("track, law", [
    (rt.Track.paper(), rt.LinearFoundation.paper()),
    (rt.Track.ballasted(), rt.LinearFoundation.ballasted()),
])
@pytest.mark.parametrize("speed", [10.0, 45.0, 100.0])
def test_a_single_axle_60_m_from_its_neighbours_is_alone(track, law, speed):
    def peaks(length):
        s = rt.solve(track, rt.Train.single_axle(75e3, speed, length), law, method="analytic")
        t = np.linspace(-0.05, 0.05, 801) % s.period
        return np.array([s.sleeper_displacement(t).min(), s.rail_displacement(t).min(),
                         s.rail_seat_load(t).max()])
    alone = peaks(480.0)
    np.testing.assert_allclose(peaks(rt.model.train.SINGLE_AXLE_LENGTH), alone, rtol=1e-3)
    assert not np.allclose(peaks(1.8), alone, rtol=1e-3)     # the test can tell neighbours


def test_the_single_layer_matches_the_two_layer_support_to_second_order():
    z = ZHAI_2004
    args = (z["ballast_mass"], z["ballast_stiffness"], z["ballast_damping"],
            z["subgrade_stiffness"], z["subgrade_damping"])
    layer = single_layer(*args)
    omega = np.array([1e-3, 2.0, 4.0])
    exact = two_layer_stiffness(omega, *args)
    assert exact[0].real == pytest.approx(layer.stiffness, rel=1e-9)
    assert exact[0].imag / omega[0] == pytest.approx(layer.damping, rel=1e-6)
    # Re K = k2 - omega^2 m_add + O(omega^4): the quadratic coefficient from two frequencies
    quadratic = (exact[1].real - exact[2].real) / (omega[2] ** 2 - omega[1] ** 2)
    assert quadratic == pytest.approx(layer.added_mass, rel=2e-3)
    assert 95.0 < layer.ballast_resonance < 105.0


def test_the_ballasted_track_is_the_zhai_set_with_the_ballast_share_on_the_sleeper():
    track = rt.Track.ballasted()
    assert track.sleeper_mass == pytest.approx(125.5 + 217.6, abs=0.1)
    assert track.pad_stiffness == 65e6
    critical = 2.0 * np.sqrt(track.pad_stiffness * track.sleeper_mass)
    assert track.pad_damping / critical < 0.5 < rt.Track.paper().pad_damping / (
        2.0 * np.sqrt(rt.Track.paper().pad_stiffness * rt.Track.paper().sleeper_mass))
