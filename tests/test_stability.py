"""Which periodic solution the track reaches: the ring started on a solution, stability, ramps.

Truths used: the finite-element ring's own converged state (from the static
start) for the state built from a harmonic-balance solution; harmonic
balance for the response of the first period; the known case of issue 9
(paper's track with pad damping 1e5 N s/m, cubic foundation
(20e6 N/m, 2e13 N/m^3, 0.8, 5000 N s/m), 525 m/s), where Newton and the
static start of the ring disagree (-1.607 mm against -1.507 mm).
"""

from __future__ import annotations

import numpy as np
import pytest

import railtrack as rt
from railtrack import CubicFoundation, LinearFoundation, Passage, Track, Train, continuation, solve
from railtrack.timedomain.fem import ring_mesh
from railtrack.studies.ramp import speed_ramp
from railtrack.timedomain.ring_state import ring_state_from_solution
from railtrack.studies.stability import check_stability, record_spectrum, tiled_train
from railtrack.timedomain.simulation import simulate_time_domain

TRACK, TRAIN = Track.paper(), Train.paper()
SOFT = Track.paper(pad_damping=1e5)
CUBIC = CubicFoundation(20e6, 2e13, 0.8, 5000.0)


def _minimum(solution) -> float:
    return float(solution.sleeper_displacement(np.linspace(0.0, solution.period, 4000)).min())


def test_state_from_a_solution_is_the_rings_converged_state():
    # The ring's own periodic state, reached from the static start, is the
    # truth; the differences are the ring's discretization (and the 200
    # harmonics of the slope's series, whose coefficients decay like n^-3).
    foundation = LinearFoundation.paper()
    solution = solve(TRACK, TRAIN, foundation, harmonics=200, method="analytic")
    result = simulate_time_domain(TRACK, TRAIN, foundation, tol=1e-9, max_periods=10)
    assert result.converged
    mesh = ring_mesh(Passage(TRACK, TRAIN), 8)
    u, v = ring_state_from_solution(mesh, solution)
    ring_u, ring_v = result.final_state
    rail, rotation, sleepers = slice(0, 2 * mesh.n_nodes, 2), slice(1, 2 * mesh.n_nodes, 2), mesh.sleeper_dofs
    # Measured: 5.9e-9 m, 8.1e-8 rad, 1.8e-9 m; 3.4e-5 m/s, 2.4e-6 m/s (peaks
    # 1.2e-3 m, 9.3e-4 rad, 1.1e-3 m, 4.2e-2 m/s, 3.8e-2 m/s).
    for mine, ring, bound in ((u[rail], ring_u[rail], 1.5e-8), (u[rotation], ring_u[rotation], 2e-7),
                              (u[sleepers], ring_u[sleepers], 5e-9), (v[rail], ring_v[rail], 1e-4),
                              (v[sleepers], ring_v[sleepers], 6e-6)):
        assert np.max(np.abs(mine - ring)) < bound
    # The slope's sign and the sleepers' delay direction matter by far more.
    assert np.max(np.abs(-u[rotation] - ring_u[rotation])) > 1e-4
    assert np.max(np.abs(u[sleepers][::-1] - ring_u[sleepers])) > 1e-5


@pytest.mark.parametrize("foundation", [LinearFoundation.paper(), CubicFoundation.paper(epsilon=0.8)])
def test_start_from_a_solution_matches_it_in_the_first_period(foundation):
    solution = solve(TRACK, TRAIN, foundation, harmonics=200)
    result = simulate_time_domain(TRACK, TRAIN, foundation, start=solution)
    # Same bound as the static-start comparisons of test_timedomain.py
    # (measured 2.0e-9 m and 1.6e-9 m in the first period already).
    first = np.max(np.abs(result.sleeper_history[0] - solution.sleeper_displacement(result.times)))
    assert first < 5e-9
    assert result.converged and result.periods == 2
    static = simulate_time_domain(TRACK, TRAIN, foundation)
    static_first = np.max(np.abs(static.sleeper_history[0] - solution.sleeper_displacement(static.times)))
    assert static.periods == 3 and static_first > 1e-5  # measured 7.8e-5 m (linear), 1.9e-5 m (cubic)


def test_explicit_state_continues_a_run():
    foundation = LinearFoundation.paper()
    first = simulate_time_domain(TRACK, TRAIN, foundation, 2, 600)
    again = simulate_time_domain(TRACK, TRAIN, foundation, 2, 600, start=first.final_state)
    peak = np.max(np.abs(first.sleeper_displacement))
    # The first run stopped when its periods differed by <= 1e-6 x peak.
    np.testing.assert_allclose(again.sleeper_history[0], first.sleeper_displacement, rtol=0, atol=2e-6 * peak)


@pytest.mark.parametrize("start, match", [
    ("moving", "start must be"),
    ((np.zeros(3), np.zeros(3)), r"shape \(150,\)"),
    (solve(TRACK, TRAIN.replace(speed=30.0), LinearFoundation.paper()), "ring's track and speed"),
    (solve(TRACK, Train(18.0, (0.0, 2.0), (75e3, 75e3), 45.0), LinearFoundation.paper()), "tiled"),
])
def test_bad_starts_are_refused(start, match):
    with pytest.raises(ValueError, match=match):
        simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 2, 600, start=start)


def test_tiled_train_is_n_wagons_in_one():
    two = tiled_train(TRAIN, 2)
    assert (two.wagon_length, two.axle_positions, two.axle_loads) == (36.0, (0.0, 3.0, 18.0, 21.0), (75e3,) * 4)
    # Its harmonic-balance response is the one-wagon response: same periodic state.
    one = solve(TRACK, TRAIN, LinearFoundation.paper(), harmonics=60, method="analytic")
    both = solve(TRACK, two, LinearFoundation.paper(), harmonics=120, method="analytic")
    t = np.linspace(0.0, 2 * TRAIN.period, 500)
    np.testing.assert_allclose(both.sleeper_displacement(t), one.sleeper_displacement(t), rtol=0, atol=1e-12)
    with pytest.raises(ValueError, match="wagons"):
        tiled_train(TRAIN, 0)


@pytest.mark.parametrize("wagons", [1, 2])
def test_linear_track_stays(wagons):
    solution = solve(TRACK, TRAIN, LinearFoundation.paper(), harmonics=200, method="analytic")
    check = check_stability(solution, periods=4, elements_per_span=2, steps_per_period=600 * wagons,
                            wagons=wagons)
    assert check.stable and check.verdict == "stays", check.message
    # Measured 2.3e-5 at 2 elements and 600 steps: the ring's discretization.
    assert check.distance.shape == (4,) and check.distance.max() < 1e-4
    assert np.isnan(check.reached_min)


def test_spectrum_tells_periodic_from_quasi_periodic_records():
    steps, period = 200, 0.04
    t = np.arange(10 * steps + 37) * period / steps   # 37 samples of a partial period first
    periodic = 1e-3 * np.cos(2 * np.pi * t / period) + 2e-4 * np.sin(6 * np.pi * t / period)
    spectrum = record_spectrum(periodic, period, steps)
    assert spectrum.frequencies.size == 10 * steps // 2 + 1
    # Not whole periods from t = 0, but the trailing whole periods are taken:
    # the lines are at multiples of 1/T only, up to rounding.
    assert spectrum.interharmonic_fraction < 1e-10
    np.testing.assert_allclose(spectrum.amplitudes[spectrum.harmonic][[1, 3]], [1e-3, 2e-4], rtol=1e-10)
    beating = periodic + 1e-4 * np.cos(2 * np.pi * 2.3 * t / period)
    beat = record_spectrum(beating, period, steps)
    assert beat.interharmonic_fraction > 0.05
    with pytest.raises(ValueError, match="at least 2 periods"):
        record_spectrum(periodic[:steps], period, steps)


@pytest.mark.slow
def test_525_newton_solution_leaves_for_the_static_starts_state():
    train = TRAIN.replace(speed=525.0)
    newton = solve(SOFT, train, CUBIC, harmonics=120)
    assert newton.converged and abs(1e3 * _minimum(newton) + 1.607) < 2e-3
    static = simulate_time_domain(SOFT, train, CUBIC, 4, 600, max_periods=100)
    assert static.converged and static.periods > 40          # measured 57
    check = check_stability(newton, periods=20, elements_per_span=4, steps_per_period=600)
    # Measured: the distance grows 1.93-fold per period from 9e-4, and the
    # ring settles after 67 periods between -1.507 and 0.460 mm (the solution
    # -1.607 to 1.359 mm): the static start's state.
    assert check.verdict == "leaves" and not check.stable, check.message
    assert check.growth > 1.5
    assert abs(check.reached_min - static.sleeper_displacements.min()) < 1e-6
    # Newton seeded with that state finds a second periodic solution, and
    # the ring stays on it (distance 1.7e-3 at this mesh, 1e-4 at 8 x 2400).
    w = check.record[-1]
    seeded = solve(SOFT, train, CUBIC, harmonics=120, initial=np.fft.fft(w)[:121] / w.size)
    assert seeded.converged and abs(1e3 * _minimum(seeded) + 1.508) < 2e-3
    stays = check_stability(seeded, periods=20, elements_per_span=4, steps_per_period=600)
    assert stays.verdict == "stays", stays.message
    started = simulate_time_domain(SOFT, train, CUBIC, 4, 600, start=seeded, tol=1e-3)
    assert started.periods <= 3


@pytest.mark.slow
def test_near_critical_speed_the_ring_settles_on_no_periodic_state():
    # 700 m/s: a Newton solution exists (reached falling from 1000 m/s), but
    # the ring leaves it for a response whose periods never repeat, with
    # spectral lines at 2.31 and 2.69 v/H (measured interharmonic fraction
    # 0.39 over periods 75-150 from the static start).
    train = TRAIN.replace(speed=700.0)
    guess = None
    for speed in np.arange(1000.0, 699.0, -25.0):
        step = solve(SOFT, TRAIN.replace(speed=speed), CUBIC, harmonics=120, initial=guess)
        guess = step.coefficients[120:] if step.converged else guess  # 750, 725 fail: go on
    newton = solve(SOFT, train, CUBIC, harmonics=120, initial=guess)
    assert newton.converged
    check = check_stability(newton, periods=10, elements_per_span=4, steps_per_period=600, max_periods=60)
    assert check.verdict == "not periodic", check.message
    assert check.interharmonic_fraction > 0.1 and check.period_change > 0.1
    assert "quasi-periodic" in check.message


@pytest.mark.slow
def test_speed_ramp_shows_two_stable_states_at_900():
    # Falling from 900 m/s (static start there) the ring stays on the small
    # branch, periodic, as harmonic balance continued down from 1000 m/s
    # (-0.837, -0.759, -0.798 mm at 900, 850, 800 m/s), then jumps between
    # 800 and 750 m/s to a large response that repeats no period.  Rising
    # from 500 m/s (a 150-period run per speed) it reached 900 m/s on the
    # large branch, -1.877 mm, as harmonic balance continued up; started on
    # that solution, the ring stays there: two stable states at one speed.
    down = speed_ramp(SOFT, TRAIN, CUBIC, [900.0, 850.0, 800.0, 750.0], 4, 600, max_periods=150)
    np.testing.assert_allclose(1e3 * down.minimum, [-0.837, -0.759, -0.797, -1.707], atol=3e-3)
    assert down.converged.tolist() == [True, True, True, False]
    # the periodic speeds have no lines between the multiples of v/H; 750 m/s has
    assert (down.interharmonic_fraction[:3] < 1e-2).all() and down.interharmonic_fraction[3] > 0.1
    guess = None
    for speed in np.arange(400.0, 901.0, 25.0):   # natural continuation, as measured
        large = solve(SOFT, TRAIN.replace(speed=speed), CUBIC, harmonics=120, initial=guess)
        guess = large.coefficients[120:] if large.converged else guess
    assert large.converged and abs(1e3 * _minimum(large) + 1.877) < 2e-3
    up = speed_ramp(SOFT, TRAIN, CUBIC, [900.0], 4, 600, max_periods=150, start=large)
    assert up.converged[0] and abs(1e3 * up.minimum[0] + 1.877) < 5e-3


@pytest.mark.slow
def test_a_slow_instability_is_caught_before_the_distance_shows_it():
    # Above the last fold of the issue-9 branch, 605 m/s lies past a torus
    # bifurcation: watched 100 periods, the ring leaves the solution (the
    # truth); after 20 periods its distance has hardly grown (6.0e-4 to
    # 6.8e-4 of the peak, measured), but its period-to-period change has.
    branch = continuation(SOFT, TRAIN.replace(speed=300.0), CUBIC, "speed", start=300.0,
                          stop=700.0, harmonics=25)

    def on_last_part(speed):
        return solve(SOFT, TRAIN.replace(speed=speed), CUBIC, harmonics=25,
                     initial=branch.solutions_at(speed)[-1])

    solution = on_last_part(605.0)
    long = check_stability(solution, periods=100, max_periods=100, elements_per_span=4,
                           steps_per_period=600)
    assert long.distance.max() > 1e-2 and not long.stable
    short = check_stability(solution, periods=20, max_periods=40, elements_per_span=4,
                            steps_per_period=600)
    assert short.distance[:20].max() < 1e-3
    assert short.verdict in ("grows", "not periodic") and short.change_growth > 1.03
    # a stable point of the same part is still called stable
    assert check_stability(on_last_part(560.0), periods=20, max_periods=40, elements_per_span=4,
                           steps_per_period=600).verdict == "stays"


@pytest.mark.slow
def test_below_the_last_fold_the_falling_ramp_finds_no_periodic_state():
    # Chapter 10's falling ramp leaves the small branch at the last fold
    # (513.1 m/s) and, within its 80 periods per speed, settles on nothing
    # down to 495 m/s.  Watched 300 periods at 510 m/s the response still
    # does not repeat, and most of its spectrum lies between the multiples
    # of v/H: not a slow transient (measured: 500 periods, fraction 0.68).
    branch = continuation(SOFT, TRAIN.replace(speed=300.0), CUBIC, "speed", start=300.0,
                          stop=560.0, harmonics=25)
    small = solve(SOFT, TRAIN.replace(speed=520.0), CUBIC, harmonics=25,
                  initial=branch.solutions_at(520.0)[-1])
    ramp = speed_ramp(SOFT, TRAIN, CUBIC, [520.0, 514.0, 510.0], 4, 600, tol=1e-5,
                      max_periods=300, start=small)
    assert ramp.converged.tolist() == [True, True, False]
    assert ramp.periods[-1] == 300 and ramp.interharmonic_fraction[-1] > 0.5


def test_a_solution_truncated_beyond_the_tolerance_is_refused_and_hill_still_judges_it():
    # Issue 18: at m = 15 on the fold track near 450 m/s the truncation error is
    # about 3e-2, the ring leaves the solution for the state it approximates,
    # and the check called every point of the branch unstable (0 of 14); at
    # m = 25 all 14 stay.  Hill's multipliers agree at both m.
    track, law = rt.Track.paper(pad_damping=1e5), rt.CubicFoundation(20e6, 2e13, 0.8, 5000)
    coarse = rt.solve(track, rt.Train.paper(speed=450.0), law, harmonics=15)
    assert coarse.converged and coarse.truncation_error > 0.02
    with pytest.raises(ValueError, match="truncation error"):
        rt.check_stability(coarse, elements_per_span=4, steps_per_period=600)
    fine = rt.solve(track, rt.Train.paper(speed=450.0), law, harmonics=25)
    assert rt.floquet(coarse).stable and rt.floquet(fine).stable
    assert abs(abs(rt.floquet(coarse).dominant) - abs(rt.floquet(fine).dominant)) < 5e-3
