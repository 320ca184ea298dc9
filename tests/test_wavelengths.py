"""The smeared, damped track under a train, and the axle pattern's weights.

Truths independent of the code: the static Winkler beam (Hetenyi), the mean
load per sleeper, the two-axle factor |cos(pi D / lambda)|, and the discrete
track of eq. (23) whose sleepers the smeared track replaces.
"""

import dataclasses

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.wavelengths import (
    axle_pattern_weight,
    smeared_sleeper_extremes,
)


def test_slow_single_axle_is_the_static_winkler_beam():
    # A lone axle, slowly: w_rail = P beta / (2 k), beta = (k / 4 EI)^(1/4),
    # k = k_s / L; the sleeper takes k1 / (k1 + k2) of it.
    track, law = rt.Track.paper(), rt.LinearFoundation.paper()
    train = rt.Train.single_axle(wagon_length=120.0)
    k1, k2 = track.pad_stiffness, law.stiffness
    k = k1 * k2 / (k1 + k2) / track.sleeper_spacing
    beta = (k / (4 * track.rail_bending_stiffness)) ** 0.25
    expected = -75e3 * beta / (2 * k) * k1 / (k1 + k2)
    low, _ = smeared_sleeper_extremes(
        track, train, law, [0.5], harmonics=800, samples=8192
    )
    assert low[0] == pytest.approx(expected, rel=2e-3)


def test_mean_is_the_weight_per_sleeper_on_the_foundation():
    # Averaged over a period the foundation carries sum Q L / H per sleeper.
    track, law, train = (
        rt.Track.paper(),
        rt.LinearFoundation.paper(),
        rt.Train.paper(),
    )
    low, high = smeared_sleeper_extremes(
        track, train, law, [0.5], harmonics=0, samples=16
    )
    assert low[0] == pytest.approx(-150e3 * 0.6 / 18.0 / 20e6, rel=1e-12)
    assert high[0] == pytest.approx(low[0], rel=1e-12)


def test_smeared_track_peaks_with_the_discrete_one_under_the_wagon():
    # The paper's sleepers are dense enough: the discrete track of eq. (23)
    # peaks at the speed and depth of its smeared counterpart.
    track, law = (
        rt.Track.paper(pad_damping=30e3),
        rt.LinearFoundation(20e6, 20e3),
    )
    speeds = np.arange(330.0, 400.0, 0.5)
    for train in (
        rt.Train.paper(),
        rt.Train.single_axle(wagon_length=18.0),
    ):
        discrete = rt.sweep_extremes(track, train, law, speeds)[0]
        smeared = smeared_sleeper_extremes(track, train, law, speeds)[0]
        assert (
            abs(speeds[discrete.argmin()] - speeds[smeared.argmin()]) <= 1.0
        )
        assert smeared.min() == pytest.approx(discrete.min(), rel=5e-3)


def test_axle_pattern_weight_of_two_axles_is_a_cosine():
    lam = np.array([4.5, 3.6, 6.0, 18.0])
    assert axle_pattern_weight(rt.Train.paper(), lam) == pytest.approx(
        np.abs(np.cos(np.pi * 3.0 / lam)), abs=1e-12
    )
    assert axle_pattern_weight(
        rt.Train.single_axle(), lam
    ) == pytest.approx(1.0)


def test_bad_arguments_are_named():
    track, law = rt.Track.paper(), rt.LinearFoundation.paper()
    with pytest.raises(ValueError, match="speeds"):
        smeared_sleeper_extremes(track, rt.Train.paper(), law, [0.0])
    with pytest.raises(ValueError, match="samples"):
        smeared_sleeper_extremes(
            track, rt.Train.paper(), law, [1.0], harmonics=60, samples=64
        )
    with pytest.raises(ValueError, match="wavelengths"):
        axle_pattern_weight(rt.Train.paper(), [-1.0])
    assert dataclasses.is_dataclass(track)


def test_book_recipes():
    from railtrack.plotting.book.wavelengths import (
        harmonic_table,
        peaks_by_train,
    )

    track, law = (
        rt.Track.paper(pad_damping=30e3),
        rt.LinearFoundation(20e6, 20e3),
    )
    one = {"one axle": rt.Train.single_axle(wagon_length=18.0)}
    speeds = np.arange(340.0, 380.0, 0.5)
    ((discrete, smeared),) = peaks_by_train(
        track, law, one, speeds
    ).values()
    # one axle per 18 m: both peak within 1 % of the undamped tangency
    from railtrack.plotting.book.speed import smeared_critical_speed

    tangency = smeared_critical_speed(track, law)
    assert discrete == pytest.approx(tangency, rel=0.01)
    assert smeared == pytest.approx(tangency, rel=0.01)
    rows = harmonic_table(track, law, rt.Train.paper(), [3, 6])
    assert [r[3] for r in rows] == ["0.00", "1.00"]  # cos(pi n / 6)
    assert [r[1] for r in rows] == ["6.00", "3.00"]
