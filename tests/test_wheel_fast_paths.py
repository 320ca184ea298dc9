"""Issue 28's fast paths with wheels against the slow ones they replace.

- the contact force and compression at instants evenly over one period (what
  "auto" compares, `one_period`, `extremes`) by an inverse FFT, against the
  direct sum over the harmonics at the same instants given in another order;
- a level of "auto" whose sleepers start from the coarser level's harmonics
  reaches the state the same level reaches with its sleepers starting at rest.
"""

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.profile import smooth_rail
from railtrack.solvers.wheel_newton import solve_wheels


def _hanging(n=3):
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper())
    cell = rt.SleeperCell.identical(passage, rt.LinearFoundation(20e6, 0.2e6), n).with_sleeper(
        1, foundation=rt.GapFoundation(1e-3, 20e6, 0.2e6))
    return passage, cell


@pytest.mark.filterwarnings("ignore:harmonics=60")   # m small on purpose: the test is fast
def test_the_force_over_a_period_by_inverse_fft_is_the_direct_sum():
    passage, cell = _hanging()
    dip = rt.CosineDip(0.3e-3, 0.6, 1.8, centre=0.9)
    solution = rt.solve(rt.Track.paper(), rt.Train.paper(), cell, wheel=rt.Wheel(600.0),
                        profile=dip, harmonics=60)
    t = solution.one_period(1024)[0]
    order = np.random.default_rng(1).permutation(t.size)      # not evenly spaced: the sum
    scale = float(np.max(passage.axle_loads))
    for name, unit in (("contact_force", scale), ("compression", 1e-4),
                       ("wheel_displacement", 1e-4)):
        fast = getattr(solution, name)(t)
        direct = np.empty_like(fast)
        direct[:, order] = getattr(solution, name)(t[order])
        assert np.max(np.abs(fast - direct)) <= 1e-9 * unit, name
        assert np.ptp(fast) > 1e-4 * unit, name                # not trivially flat


def test_a_level_whose_sleepers_start_from_the_coarser_level_reaches_the_same_state():
    passage, cell = _hanging()
    wheel = rt.Wheel(600.0)
    coarse = solve_wheels(passage, cell, wheel, smooth_rail, 30)
    assert coarse.converged
    start = (coarse.contact_harmonics, coarse.lift)
    cold = solve_wheels(passage, cell, wheel, smooth_rail, 45, start=start)
    warm = solve_wheels(passage, cell, wheel, smooth_rail, 45,
                        start=start + (coarse.coefficients[:, 30:],))
    assert cold.converged and warm.converged
    scale = float(np.max(passage.axle_loads))
    assert np.max(np.abs(warm.contact_force - cold.contact_force)) <= 1e-7 * scale
    assert np.max(np.abs(warm.coefficients - cold.coefficients)) <= 1e-7 * np.max(
        np.abs(cold.coefficients))
    # the cell's hanging sleeper makes its inner solve nonlinear: a state that moves
    assert np.ptp(warm.contact_force) > 1e-3 * scale
