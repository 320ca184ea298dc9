"""Floquet multipliers of the linearised finite-element ring (`railtrack.timedomain.monodromy`).

Truths used:
* the ring itself (`simulate_time_domain`, Newton on the nonlinear law at
  every step, nothing linearised): for a linear law the difference of two
  runs one period long is the period map applied to the difference of their
  starts, exactly; for the cubic law it is so to first order (central
  differences), up to the ring's own O(dt^2) drift from the harmonic-balance
  orbit the map is linearised about;
* `check_stability`, which watches the nonlinear ring started on each of the
  five solutions at 525 m/s on chapter 10's fold track, for the verdicts and
  for the growth of the unstable solution `solve` finds;
* the dense monodromy matrix of a ring of three wagons, for the reduction to
  Bloch sectors; the time step's dt^2 law, for convergence.
"""

from __future__ import annotations

import numpy as np
import pytest

from railtrack import CubicFoundation, LinearFoundation, Track, Train, continuation, solve
from railtrack.studies.stability import check_stability
from railtrack.timedomain.monodromy import SLEEPER_SHARE, ring_multipliers, ring_span_map
from railtrack.timedomain.ring_state import ring_state_from_solution
from railtrack.timedomain.simulation import simulate_time_domain

FOLD_TRACK = Track.paper(pad_damping=1e5)
FOLD_LAW = CubicFoundation(20e6, 2e13, 0.8, 5000.0)
FOLD_TRAIN = Train.paper(speed=525.0)


@pytest.fixture(scope="module")
def at_525():
    """The five periodic solutions at 525 m/s, in the branch's order (~1 s)."""
    branch = continuation(FOLD_TRACK, Train.paper(speed=300.0), FOLD_LAW, parameter="speed",
                          start=300.0, stop=700.0, harmonics=25)
    return [solve(FOLD_TRACK, FOLD_TRAIN, FOLD_LAW, harmonics=25, initial=c)
            for c in branch.solutions_at(525.0)]


@pytest.fixture(scope="module")
def default_525():
    """The solution `solve` finds from its default start: min w = -1.607 mm, unstable."""
    return solve(FOLD_TRACK, FOLD_TRAIN, FOLD_LAW, harmonics=25)


def _one_period(solution, start, elements, steps):
    """The nonlinear ring's state (u, u') after one period from `start`."""
    run = simulate_time_domain(solution.track, solution.train, solution.foundation, elements,
                               steps, start=start, max_periods=1, warn_step_error=None)
    return np.concatenate(run.final_state)


def test_linear_ring_period_map_is_the_rings_own_map():
    # A linear law makes the ring linear: two runs differ after a period by
    # the period map applied to the difference of their starts, to round-off.
    law = LinearFoundation.paper()
    solution = solve(Track.paper(), Train.paper(), law, harmonics=60)
    span = ring_span_map(solution, elements_per_span=2, steps_per_period=240)
    mesh, n = span.mesh, span.mesh.n_dofs
    u, v = ring_state_from_solution(mesh, solution)
    change = np.random.default_rng(1).standard_normal(2 * n) * np.repeat([1e-3, 1e-2], n)
    after = _one_period(solution, (u + change[:n], v + change[n:]), 2, 240)
    before = _one_period(solution, (u, v), 2, 240)
    predicted = span.period_map() @ change
    # Measured 2.5e-14 of the largest entry.
    assert np.max(np.abs(after - before - predicted)) < 1e-10 * np.max(np.abs(predicted))


def test_cubic_ring_period_map_is_the_rings_derivative(default_525):
    # Central differences of the nonlinear ring over one period, sleepers
    # pushed by ~1e-7 m.  The map is linearised about the harmonic-balance
    # orbit, the ring runs about its own, which is O(dt^2) away: measured
    # 6.3e-3 at 600 steps (the ring drifts 5.0e-3 of the peak from the
    # solution in that period) and 3.9e-4 at 2400 (drift 3.7e-4).  Shifting
    # the span map the wrong way, or delaying the sleepers the wrong way,
    # gives errors of order 1.
    steps = 2400
    span = ring_span_map(default_525, elements_per_span=4, steps_per_period=steps)
    mesh, n, sleepers = span.mesh, span.mesh.n_dofs, span.mesh.sleeper_dofs
    u, v = ring_state_from_solution(mesh, default_525)
    change = np.zeros(2 * n)
    change[sleepers] = 1e-7 * np.random.default_rng(5).standard_normal(sleepers.size)
    plus = _one_period(default_525, (u + change[:n], v), 4, steps)
    minus = _one_period(default_525, (u - change[:n], v), 4, steps)
    derivative = (plus - minus)[sleepers] / 2.0
    predicted = (span.period_map() @ change)[sleepers]
    assert np.max(np.abs(derivative - predicted)) < 1e-3 * np.max(np.abs(derivative))


@pytest.mark.parametrize("index", range(5))
def test_multipliers_agree_with_the_rings_verdict(at_525, index):
    # The nonlinear ring watched for 20 periods (the book's coarse ring)
    # tells stable from unstable; exactly three of the five are unstable
    # (the three parts of the branch between its first and last folds).
    # tol = 0.05: near the resonance the 600-step ring's own periodic state
    # is 1.2e-2 of the peak from the -2.538 mm solution (at 2400 steps
    # 1.7e-3), above the default tol 1e-2, so the check would call it
    # "leaves" for a state with the same extremes; the unstable ones leave
    # to 0.58-1.3 of the peak within the 20 periods.
    solution = at_525[index]
    check = check_stability(solution, periods=20, tol=0.05, elements_per_span=4,
                            steps_per_period=600, max_periods=20)
    result = ring_multipliers(solution, elements_per_span=4, steps_per_period=600)
    assert check.stable == result.stable
    assert result.stable == (index in (0, 4))
    # Measured |dominant| 0.804, 2.368, 2.008, 2.149, 0.811: far from 1.
    assert abs(abs(result.dominant) - 1.0) > 0.15


def test_dominant_multiplier_is_the_growth_the_ring_watches(default_525):
    # check.growth is a least-squares fit of log(distance) over the ~7 periods
    # before the distance reaches 0.1 of the peak; the dominant multipliers
    # are a complex pair turning 2.06 rad per period, so the distance (a
    # maximum over each period) beats from period to period (ratios 0.46 to
    # 7.9), and it starts from the ring's offset from the solution, which
    # does not grow.  Measured: growth 1.925 against |mu| = 2.008, 4 % apart;
    # allowed 10 %.
    check = check_stability(default_525, periods=20, elements_per_span=4, steps_per_period=600,
                            max_periods=20)
    result = ring_multipliers(default_525, elements_per_span=4, steps_per_period=600)
    assert not check.stable and not result.stable
    assert abs(abs(result.dominant) / check.growth - 1.0) < 0.10
    assert abs(result.dominant.imag) > 0.5 * abs(result.dominant)      # a complex pair
    assert np.isclose(result.multipliers[1], np.conj(result.dominant))


def test_dominant_multiplier_converges_as_dt_squared(default_525):
    # Average acceleration is second order: halving dt should cut the change
    # by 4.  Measured |mu(600) - mu(1200)| = 2.6e-3, |mu(1200) - mu(2400)| =
    # 6.4e-4 (ratio 0.25); 8 elements per span instead of 4 change mu by < 1e-5.
    mu = [ring_multipliers(default_525, elements_per_span=4, steps_per_period=steps).dominant
          for steps in (600, 1200, 2400)]
    first, second = abs(mu[0] - mu[1]), abs(mu[1] - mu[2])
    assert first < 3e-3 * abs(mu[2])
    assert 0.2 < second / first < 0.3
    finer = ring_multipliers(default_525, elements_per_span=8, steps_per_period=600).dominant
    assert abs(finer - mu[0]) < 1e-4 * abs(mu[0])


def test_bloch_sectors_are_the_three_wagon_rings_monodromy(default_525):
    # A ring of three wagons, reduced to the sectors theta = 0, 2 pi/3 and
    # 4 pi/3, against the eigenvalues of its full period map W G^N_s; sector
    # 0 is the ring of one wagon.  Three wagons, not two: exp(-i theta) and
    # exp(+i theta) differ only if theta is not pi.  A coarse ring keeps it
    # fast: the identity is algebraic.
    run = dict(elements_per_span=1)
    three = ring_multipliers(default_525, wagons=3, steps_per_period=270, **run)
    one = ring_multipliers(default_525, wagons=1, steps_per_period=90, **run)
    full = np.linalg.eigvals(ring_span_map(default_525, wagons=3, steps_per_period=270,
                                           **run).period_map())
    moving = (three.sleeper_share > SLEEPER_SHARE) & (np.abs(three.multipliers) > 0.05)
    assert np.count_nonzero(moving & (three.bloch_phase > 0.0)) > 20
    for mu in three.multipliers[moving]:
        assert np.min(np.abs(full - mu)) < 1e-6 * abs(mu)
    in_phase = three.multipliers[three.bloch_phase == 0.0]
    moving_one = (one.sleeper_share > SLEEPER_SHARE) & (np.abs(one.multipliers) > 0.05)
    for mu in one.multipliers[moving_one]:
        assert np.min(np.abs(in_phase - mu)) < 1e-8 * abs(mu)
    # The other sectors are not copies of sector 0.
    out_of_phase = three.multipliers[moving & (three.bloch_phase > 0.0)]
    assert not np.isclose(np.max(np.abs(out_of_phase)), abs(one.dominant), rtol=1e-3)


def test_rail_modes_that_never_move_a_sleeper_are_flagged():
    # Pinned-pinned rail modes (deflection zero at every sleeper) are
    # undamped: |mu| = 1, sleeper share 0; every mode that moves the sleepers
    # of the heavily damped paper's track dies within a period.
    solution = solve(Track.paper(), Train.paper(), LinearFoundation.paper(), harmonics=60)
    result = ring_multipliers(solution, elements_per_span=4, steps_per_period=600)
    on_circle = np.abs(np.abs(result.multipliers) - 1.0) < 1e-9
    assert np.count_nonzero(on_circle) >= 8
    assert np.all(result.sleeper_share[on_circle] < 1e-20)
    assert abs(result.dominant) < 1e-2 and result.stable
    assert np.all(np.diff(np.abs(result.multipliers)) <= 0.0)


def test_refuses_what_it_cannot_linearise(default_525):
    with pytest.raises(ValueError, match="multiple of H/L = 30"):
        ring_multipliers(default_525, steps_per_period=601)
    with pytest.raises(ValueError, match="wagons must be an integer"):
        ring_multipliers(default_525, wagons=0)
    # an explicit max_iterations that runs out is quiet (the caller's budget, 7d66463)
    unconverged = solve(FOLD_TRACK, FOLD_TRAIN, FOLD_LAW, harmonics=25, max_iterations=1)
    assert not unconverged.converged
    with pytest.raises(ValueError, match="has not converged"):
        ring_multipliers(unconverged)
