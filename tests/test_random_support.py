"""The random-support Monte Carlo (issue 19, section 4).

Independent truths: with no scatter every draw is today's sound track
(`railtrack.Solution`'s seat load and moment under the wheel); the factors'
mean and coefficient of variation; the same seed gives the same draws.
Each draw against a cell built by hand from its factors, and the moment
under every wheel: tests/test_random_support_cells.py.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.studies.random_support import lognormal_factors, scaled_law

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
SOUND = rt.LinearFoundation(20e6, 0.2e6)


def test_without_scatter_every_draw_is_todays_track():
    sample = rt.random_support(TRACK, TRAIN, SOUND, sleepers=5, variation=0.0, draws=2,
                               harmonics=40)
    today = rt.solve(TRACK, TRAIN, SOUND, 40, stability="off")
    t, _ = today.one_period(4096)
    speed = TRAIN.speed
    under = np.linspace(0.0, 0.6, 9)
    moment = today.rail_bending_moment(under / speed, under).max()
    np.testing.assert_allclose(sample.peak_seat_load, today.rail_seat_load(t).max(), rtol=1e-4)
    np.testing.assert_allclose(sample.peak_moment, moment, rtol=1e-6)


def test_the_factors_have_mean_one_and_the_asked_variation():
    x = lognormal_factors(0.3, 200_000, np.random.default_rng(7))
    assert x.mean() == pytest.approx(1.0, abs=3e-3)
    assert x.std() / x.mean() == pytest.approx(0.3, rel=1e-2)
    assert x.min() > 0


def test_a_seed_gives_the_same_draws_and_more_scatter_loads_the_track_more():
    low = rt.random_support(TRACK, TRAIN, SOUND, sleepers=10, variation=0.1, draws=12, seed=3)
    again = rt.random_support(TRACK, TRAIN, SOUND, sleepers=10, variation=0.1, draws=12, seed=3)
    high = rt.random_support(TRACK, TRAIN, SOUND, sleepers=10, variation=0.4, draws=12, seed=3)
    np.testing.assert_array_equal(low.factors, again.factors)
    np.testing.assert_array_equal(low.peak_seat_load, again.peak_seat_load)
    assert low.converged.all() and high.converged.all()
    assert np.median(high.peak_seat_load) > 1.1 * np.median(low.peak_seat_load)


def test_only_stiffness_is_scaled_and_bad_input_is_named():
    law = scaled_law(rt.BilinearFoundation(20e6, 10e6, 2e5), 2.0)
    assert (law.compression_stiffness, law.tension_stiffness, law.damping) == (40e6, 20e6, 2e5)
    with pytest.raises(TypeError, match="stiffness"):
        scaled_law(lambda w, v: -w, 2.0)
    with pytest.raises(ValueError, match="variation"):
        lognormal_factors(-0.1, 3, np.random.default_rng(0))
