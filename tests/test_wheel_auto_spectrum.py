"""harmonics="auto" with wheels reads m off the contact force's spectrum (issue 28).

Truths: a much finer solve, computed here (the dipped weld at m = 687, whose
own truncation is some 5e-4 Q; the coach at m = 600); Fourier's decay of a
profile's harmonics (a jump in r'' gives p^-3, a kink p^-2, a step p^-1);
the triangle inequality (the estimate bounds the time-domain tail of a force
that follows the profile); and the x1.5 rule of issues 20 and 27 where the
fit is refused.
"""

import numpy as np
import pytest

import railtrack as rt
import railtrack.solvers.wheel_rounds as rounds
from railtrack.solvers.wheel_auto import wheel_cell
from railtrack.solvers.wheel_newton import solve_wheels
from railtrack.solvers.wheel_tail import profile_tail, tail_estimate, transfer

TRACK = rt.Track.paper()
LAW = rt.LinearFoundation(20e6, 0.2e6)
WHEEL = rt.Wheel(600.0)
DIP = rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.3)


@pytest.fixture
def levels(monkeypatch):
    """Every m "auto" solves at, in order."""
    calls = []
    real = rounds.solve_wheels

    def spy(passage, cell, wheel, profile, m, **options):
        calls.append(m)
        return real(passage, cell, wheel, profile, m, **options)

    monkeypatch.setattr(rounds, "solve_wheels", spy)
    return calls


def finer(train, profile, m):
    passage = rt.Passage(TRACK, train)
    raw = solve_wheels(passage, wheel_cell(passage, LAW, profile), WHEEL, profile, m)
    assert raw.converged
    return rounds.wrap(passage, WHEEL, profile, raw)


def gap(result, fine):
    t = fine.one_period(4096)[0]
    load = float(np.max(fine.passage.axle_loads))
    return float(np.abs(result.contact_force(t) - fine.contact_force(t)).max()) / load


def test_auto_on_the_dipped_weld_solves_twice_and_meets_its_accuracy(levels):
    # the x1.5 growth took 60, 90, 135, 203, 305, 458 (and 687 at the default accuracy)
    accuracy = 3e-3
    result = rt.solve(TRACK, rt.Train.paper(), LAW, wheel=WHEEL, profile=DIP,
                      accuracy=accuracy)
    assert result.converged and len(levels) == 2 and levels[1] == result.harmonics
    error = gap(result, finer(rt.Train.paper(), DIP, 687))
    assert error <= result.truncation_error <= accuracy      # met, and not optimistic
    # the message states m, the fitted decay and the estimate
    assert f"m = {result.harmonics}: converged" in result.message
    assert "falling as p^-3.0" in result.message            # a jump in r'' at the dip's ends
    assert f"estimated tail {result.truncation_error:.1e} Q" in result.message


def test_the_estimate_on_the_coach_is_not_optimistic():
    coach = rt.Train.passenger_coach(45.0)
    dip = rt.CosineDip(0.5e-3, 1.0, coach.wagon_length, centre=9.3)
    result = rt.solve(TRACK, coach, LAW, wheel=WHEEL, profile=dip, accuracy=1e-2)
    error = gap(result, finer(coach, dip, 600))
    assert result.converged and error > 1e-3                 # a real error ...
    assert error <= result.truncation_error <= 1e-2          # ... estimated from above


def test_the_profiles_decay_is_fouriers():
    passage = rt.Passage(TRACK, rt.Train.paper())

    def shaped(depth):
        def profile(x):
            s = np.mod(np.asarray(x, float) - 9.3 + 9.0, 18.0) - 9.0
            return depth(np.abs(s))
        profile.period = 18.0
        return profile

    kink = shaped(lambda s: np.where(s < 0.5, -1e-4 * (1 - 2 * s), 0.0))     # a V dip
    step = shaped(lambda s: np.where(s < 0.5, -1e-4, 0.0))                   # a box dip
    assert profile_tail(passage, WHEEL, DIP, 1, 1200).decay == pytest.approx(-3.0, abs=0.15)
    assert profile_tail(passage, WHEEL, kink, 1, 1200).decay == pytest.approx(-2.0, abs=0.15)
    assert "cannot be summed" in profile_tail(passage, WHEEL, step, 1, 1200)


def test_the_estimate_bounds_the_tail_of_a_force_that_follows_the_profile():
    passage = rt.Passage(TRACK, rt.Train.paper())
    tail = profile_tail(passage, WHEEL, DIP, 1, 1200)
    m, stiffness = 300, 1.3e9
    x = np.arange(1 << 16) * 18.0 / (1 << 16)
    r = np.fft.rfft(DIP(x)) / x.size
    grid = np.arange(1, m + 1)
    fit = transfer(tail, grid, np.tile(stiffness * r[grid], (2, 1)))
    assert fit.stiffness == pytest.approx(stiffness, rel=1e-12)
    beyond = r.copy()
    beyond[:m + 1] = 0.0
    force_tail = stiffness * np.fft.irfft(beyond, x.size) * x.size     # T_P (r - r_m)(x)
    true = np.abs(force_tail).max() / 75e3
    estimate = tail_estimate(tail, fit, m)
    assert true <= estimate <= 3 * true


def test_a_flat_rail_keeps_the_growth_by_one_and_a_half(levels):
    # chapter 14 prints m for the smooth rail: the same levels as issue 27's rule
    result = rt.solve(TRACK, rt.Train.paper(), LAW, wheel=WHEEL)
    assert levels == [120, 180] and result.harmonics == 180
    assert "m grows by 1.5 (the rail-top profile is flat" in result.message


def test_a_slow_train_whose_bounce_is_beyond_the_fit_keeps_the_growth(levels):
    # at 10 m/s the wheel's bounce (235 Hz) is harmonic 423 of the wagon: 3 x 423 > 600
    result = rt.solve(TRACK, rt.Train.paper(speed=10.0), LAW, wheel=WHEEL, profile=DIP,
                      accuracy=1e-2)
    assert levels[:2] == [60, 90] and result.converged
    assert "m grows by 1.5 (the wheel's bounce" in result.message
