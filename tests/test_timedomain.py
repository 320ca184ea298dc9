"""The time-domain FE model (`railtrack.timedomain.simulation`) against the semi-analytical method.

The two share nothing but `Track`, `Train` and the foundation laws: the FE ring is
integrated in time by Newmark's scheme, the semi-analytical solution is a
Fourier series from eq. (23) or Newton on eq. (17).  Tolerances come from
the convergence study of the FE model on the paper's linear case, sleeper 0,
max |w_FE - w_eq.(23)| over one period (analytic reference with 400
harmonics):

    elements_per_span  steps_per_period  max error [m]
    1                  2400              1.3e-7
    2                  2400              1.9e-8
    4                  2400              3.4e-9
    8                  2400              1.7e-9
    16                 2400              1.7e-9
    8                  600               2.8e-8
    8                  1200              7.0e-9
    8                  4800              6.2e-10
    8                  9600              3.5e-10

so at the default mesh (8 per span, 2400 steps, dt = 0.17 ms) the error is
the second-order Newmark time-step error, ~1.7e-9 m against a 1.13e-3 m peak.
"""

from __future__ import annotations

import time
import tracemalloc
import warnings

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from railtrack import (
    BilinearFoundation,
    CubicFoundation,
    LinearFoundation,
    Passage,
    Track,
    Train,
    solve,
)
from railtrack.timedomain.fem import ring_mesh, wheel_load_entries
from railtrack.timedomain.runcost import LongRunWarning, check_run_cost
from railtrack.timedomain.simulation import TimeDomainSolution, simulate_time_domain
from railtrack.timedomain.timestep import TimeStepWarning, estimate_step_error

TRACK = Track.paper()
TRAIN = Train.paper()
SLEEPERS = 30  # H / L for the paper's train
STEPS = 2400  # default, a multiple of H / L: the delay L / v is 80 steps


@pytest.fixture(scope="module")
def tensionless() -> TimeDomainSolution:
    """The strongest nonlinearity of the paper: no tension stiffness, eq. (24)."""
    return simulate_time_domain(TRACK, TRAIN, BilinearFoundation.paper(ratio=0.0))


def test_tiny_speed_reproduces_static_solutions():
    # At v = 1 mm/s a period lasts 5 hours: inertia is negligible and the
    # response is the static one, but for the viscous lag of the dashpots,
    # first order in v; measured 4.5e-6 m per (m/s) of speed (pads and
    # foundation, eta/k ~ 5e-3 and 1e-2 s), so 4.5e-9 m here.  The FE
    # nodal values of a static beam with point loads are exact (Hermite
    # cubics), so one element per span suffices; the 120 steps only sample
    # the load positions.  Tolerance 2e-8 m: 4x the lag, 5e4 times below the
    # 1.1e-3 m peak.
    train = Train.paper(speed=1e-3)
    foundation = LinearFoundation.paper()
    result = simulate_time_domain(TRACK, train, foundation, elements_per_span=1, steps_per_period=120)
    assert result.converged

    # Static FE ring with the wheels frozen at each sampled position.
    mesh = ring_mesh(Passage(TRACK, train), 1)
    springs = sp.csc_matrix(
        (np.full(SLEEPERS, foundation.stiffness), (mesh.sleeper_dofs, mesh.sleeper_dofs)),
        shape=mesh.stiffness.shape,
    )
    factor = spla.splu((mesh.stiffness + springs).tocsc())
    dofs, values = wheel_load_entries(mesh, result.times)
    loads = np.zeros((result.times.size, mesh.n_dofs))
    for row, (where, what) in enumerate(zip(dofs, values)):
        np.add.at(loads[row], where, what)
    static = factor.solve(loads.T).T
    np.testing.assert_allclose(result.sleeper_displacement, static[:, mesh.sleeper_dofs[0]], rtol=0, atol=2e-8)
    np.testing.assert_allclose(result.rail_displacement, static[:, mesh.rail_dofs[0]], rtol=0, atol=2e-8)

    # The semi-analytical eq. (23) at the same speed (the same lag included).
    analytic = solve(TRACK, train, foundation, harmonics=600, method="analytic")
    np.testing.assert_allclose(
        result.sleeper_displacement, analytic.sleeper_displacement(result.times), rtol=0, atol=2e-8
    )
    assert result.sleeper_displacement.min() < -1e-3  # a real deflection was compared


def test_linear_foundation_matches_analytic_eq23():
    foundation = LinearFoundation.paper()
    reference = solve(TRACK, TRAIN, foundation, harmonics=200, method="analytic")
    finer = solve(TRACK, TRAIN, foundation, harmonics=400, method="analytic")
    t = np.linspace(0.0, TRAIN.period, 1200, endpoint=False)
    # The reference is converged in m to 6e-10 m, below the FE error.
    assert np.max(np.abs(reference.sleeper_displacement(t) - finer.sleeper_displacement(t))) < 1e-9

    result = simulate_time_domain(TRACK, TRAIN, foundation)
    assert result.converged and result.periods >= 2
    error = np.max(np.abs(result.sleeper_displacement - reference.sleeper_displacement(result.times)))
    rail_error = np.max(np.abs(result.rail_displacement - reference.rail_displacement(result.times)))
    # Measured 2.0e-9 m (sleeper) and 2.2e-9 m (rail): the Newmark error at
    # dt = T/2400 (table above).  5e-9 m leaves a 2.5x margin.
    assert error < 5e-9
    assert rail_error < 5e-9

    # Second order in time: halving the steps quadruples the error
    # (measured ratio 4.1; the mesh error at 8 per span is far smaller).
    coarse = simulate_time_domain(TRACK, TRAIN, foundation, steps_per_period=STEPS // 2)
    coarse_error = np.max(
        np.abs(coarse.sleeper_displacement - reference.sleeper_displacement(coarse.times))
    )
    assert 3.0 < coarse_error / error < 5.5


def test_neighbouring_sleepers_lag_by_l_over_v(tensionless):
    # The discrete ring is invariant under a shift of one span combined with
    # a delay of L/v = 80 steps, so in the steady state sleeper i at step n
    # equals sleeper 0 at step n - 80 i exactly; what is left is the decayed
    # start-up transient, below the period-to-period tolerance 1e-6 x peak.
    result = tensionless
    displacements = result.sleeper_displacements
    assert displacements.shape == (STEPS, SLEEPERS)
    delay = STEPS // SLEEPERS
    peak = np.max(np.abs(displacements))
    for i in range(SLEEPERS):
        np.testing.assert_allclose(
            displacements[:, i], np.roll(displacements[:, 0], i * delay), rtol=0, atol=1e-6 * peak
        )
    # The opposite delay is wrong by a lot: the check can tell the direction.
    assert np.max(np.abs(displacements[:, 1] - np.roll(displacements[:, 0], -delay))) > 1e-5


def test_tensionless_foundation_matches_newton(tensionless):
    result = tensionless
    assert result.converged
    assert np.all(np.isfinite(result.sleeper_displacements))
    assert result.sleeper_displacement.max() > 2e-4  # the sleeper does lift off
    reference = solve(TRACK, TRAIN, BilinearFoundation.paper(ratio=0.0), harmonics=400)
    assert reference.converged
    error = np.max(np.abs(result.sleeper_displacement - reference.sleeper_displacement(result.times)))
    # Measured 6.9e-9 m.  The kink of eq. (24) makes the harmonic series
    # converge slowly: going from 200 to 400 harmonics still moves it by
    # 1.4e-8 m, so the reference is uncertain at ~1e-8 m; 4e-8 m allows both.
    assert error < 4e-8


def test_cubic_foundation_matches_newton():
    foundation = CubicFoundation.paper(epsilon=0.8)
    result = simulate_time_domain(TRACK, TRAIN, foundation)
    assert result.converged
    reference = solve(TRACK, TRAIN, foundation, harmonics=200)
    assert reference.converged
    error = np.max(np.abs(result.sleeper_displacement - reference.sleeper_displacement(result.times)))
    rail_error = np.max(np.abs(result.rail_displacement - reference.rail_displacement(result.times)))
    # Measured 1.3e-9 m: the same Newmark error as the linear case (the
    # reference moves by 6e-10 m from 200 to 400 harmonics); 5e-9 m as there.
    assert error < 5e-9
    assert rail_error < 5e-9


class _OtherReference:
    """The same law with another linearization (k0, c0) for the factored matrix."""

    def __init__(self, law, stiffness, damping):
        self.law, self.reference = law, (stiffness, damping)

    def force(self, w, v):
        return self.law.force(w, v)

    def tangent(self, w, v):
        return self.law.tangent(w, v)

    def linearization(self):
        return self.reference


@pytest.mark.parametrize(
    "law", [CubicFoundation.paper(epsilon=0.8), BilinearFoundation.paper(ratio=0.0)]
)
def test_result_does_not_depend_on_the_factored_reference_law(law):
    # Each step solves A u + U g(u) = b exactly by Newton on the sleeper
    # block, whatever linear part (k0, c0) was factored into A; only a lagged
    # or unconverged g would make the answer depend on it.  Same discrete
    # model on both sides, so they agree to the Newton tolerance (1e-11 of
    # the static deflection, 3e-15 m) accumulated over the steps: measured
    # 3e-17 m, so 1e-12 m is ample, while stopping Newton after the first
    # evaluation (g lagged by a step) makes them differ by 2e-5 m.
    default = simulate_time_domain(TRACK, TRAIN, law, 2, 600)
    shifted = simulate_time_domain(TRACK, TRAIN, _OtherReference(law, 1e8, 1e6), 2, 600)
    np.testing.assert_allclose(shifted.sleeper_displacement, default.sleeper_displacement, rtol=0, atol=1e-12)


def test_start_from_rest_reaches_the_same_steady_state():
    # A coarse mesh suffices: both runs integrate the same discrete model.
    # Each stops once a period changes by <= 1e-6 x peak (1.1e-9 m) and the
    # transient left then is of that order, so they agree within 3e-9 m.
    foundation = BilinearFoundation.paper(ratio=0.5)
    static = simulate_time_domain(TRACK, TRAIN, foundation, 2, 600)
    rest = simulate_time_domain(TRACK, TRAIN, foundation, 2, 600, start="rest")
    assert static.converged and rest.converged
    np.testing.assert_allclose(rest.sleeper_displacement, static.sleeper_displacement, rtol=0, atol=3e-9)


def test_reports_not_converged_after_max_periods():
    result = simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 1, 120, max_periods=1)
    assert not result.converged
    assert result.periods == 1 and result.period_change.size == 0
    result = simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 1, 120, max_periods=2, tol=1e-3)
    assert result.periods == 2 and result.period_change.size == 1


@pytest.mark.parametrize(
    "track, train, arguments, match",
    [
        (TRACK, Train.paper(wagon_length=18.3), {}, "H/L"),
        (Track.paper(sleeper_spacing=0.65), TRAIN, {}, "H/L"),
        (TRACK, TRAIN, {"elements_per_span": 0}, "elements_per_span"),
        (TRACK, TRAIN, {"elements_per_span": 2.5}, "elements_per_span"),
        (TRACK, TRAIN, {"steps_per_period": 0}, "steps_per_period"),
        (TRACK, TRAIN, {"steps_per_period": -10}, "steps_per_period"),
        (TRACK, TRAIN, {"steps_per_period": True}, "steps_per_period"),
        (TRACK, TRAIN, {"steps_per_period": 100}, "multiple of H/L = 30"),
        (TRACK, TRAIN, {"warn_step_error": 0.0}, "warn_step_error"),
        (TRACK, TRAIN, {"max_periods": 0}, "max_periods"),
        (TRACK, TRAIN, {"tol": 0.0}, "tol"),
        (TRACK, TRAIN, {"start": "moving"}, "start"),
    ],
)
def test_bad_input_raises_value_error(track, train, arguments, match):
    with pytest.raises(ValueError, match=match):
        simulate_time_domain(track, train, LinearFoundation.paper(), **arguments)


# --- Failure modes of issue 7, section 2: each test failed before the fix. ---


@pytest.mark.parametrize("steps, match", [(1, "multiple of H/L = 30"), (30, "sleeper-passing"),
                                          (60, "sleeper-passing")])
def test_steps_that_cannot_represent_the_moving_load_are_refused(steps, match):
    # 1 step per period used to return the static state marked converged,
    # 30 (one step per L / v, the sleeper-passing frequency aliased to zero)
    # a 1.2 % error marked converged.
    with pytest.raises(ValueError, match=match) as info:
        simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 8, steps)
    assert "Use" in str(info.value)  # the message says what to pass instead


def test_coarse_steps_warn_with_the_estimated_error():
    # 90 steps (3 per L / v): measured 1.17e-3 of the peak, estimated the same.
    with pytest.warns(TimeStepWarning, match=r"estimated time-step error is 0\.117 % .* >= 120"):
        result = simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 8, 90)
    assert 1.1e-3 < result.step_error < 1.25e-3
    # A deliberate study can ask for a looser bound, or skip the estimate.
    with warnings.catch_warnings():
        warnings.simplefilter("error", TimeStepWarning)
        assert simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 2, 90,
                                    warn_step_error=2e-3).step_error > 1e-3
        assert np.isnan(simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 2, 90,
                                             warn_step_error=None).step_error)


@pytest.mark.parametrize("law", [LinearFoundation.paper(), CubicFoundation.paper(epsilon=0.8)])
@pytest.mark.parametrize("steps", [90, 120, 240, 480, 960])
def test_step_error_estimate_matches_the_measured_error(law, steps):
    # Measured against harmonic balance with 200 harmonics (its own error
    # < 1e-9 of the peak here): estimate / measured = 0.99 to 1.07 for both
    # laws; the issue asks for a factor 3.  (For the kinked tensionless law
    # the linearization underestimates by 1.3-3x; not tested.)
    reference = solve(TRACK, TRAIN, law, 200, method="analytic" if isinstance(law, LinearFoundation) else "newton")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TimeStepWarning)
        result = simulate_time_domain(TRACK, TRAIN, law, 8, steps, max_periods=60)
    exact = reference.sleeper_displacement(result.times)
    measured = np.max(np.abs(result.sleeper_displacement - exact)) / np.max(np.abs(exact))
    assert 1 / 3 < result.step_error / measured < 3


def test_step_error_estimate_is_second_order_and_vanishes_when_quasi_static():
    errors = [estimate_step_error(Passage(TRACK, TRAIN), 20e6, 0.2e6, n)[0] for n in (600, 1200, 2400, 4800, 48000)]
    orders = np.log2(np.array(errors[:3]) / np.array(errors[1:4]))
    np.testing.assert_allclose(orders, 2.0, atol=0.1)
    assert errors[4] == pytest.approx(errors[3] / 100, rel=0.05)
    # At 1 mm/s inertia is negligible: only the dashpots' lag is left to err.
    assert estimate_step_error(Passage.paper(speed=1e-3), 20e6, 0.2e6, 120)[0] < 1e-7


def _nan_below_a_millimetre(w, v):
    return np.where(w < -1e-3, np.nan, 20e6 * w + 0.2e6 * v)


def _nan_when_fast(w, v):
    return np.where(v < -0.02, np.nan, 20e6 * w + 0.2e6 * v)


@pytest.mark.parametrize("law, start, match", [
    (_nan_below_a_millimetre, "static", r"_nan_below_a_millimetre\) returned a non-finite force \(nan\) "
     r"at w = -0\.00112797 m, w' = 0 m/s .* in the static state"),
    (_nan_below_a_millimetre, "rest", r"non-finite force \(nan\) at w = -0\.001000.* at step 141 of "
     r"2400 in period 1 \(t = 0\.0235 s\)"),
    (_nan_when_fast, "static", r"w' = -0\.0203994 m/s \(sleeper 26.* at step 15 of 2400 in period 1"),
])
def test_law_returning_nan_is_named_with_where_it_happened(law, start, match):
    # Used to end in "RuntimeError: Newton ... did not converge (mismatch nan ...)".
    with pytest.raises(ValueError, match=match) as info:
        simulate_time_domain(TRACK, TRAIN, law, start=start)
    assert "must return finite forces" in str(info.value)


@pytest.mark.parametrize("law, at_rest", [
    (lambda w, v: -(20e6 * w + 0.2e6 * v), r"k = df/dw = -2e\+07 N/m, c = df/dw' = -2e\+05"),
    (lambda w, v: 20e6 * w - 0.2e6 * v, r"k = df/dw = 2e\+07 N/m, c = df/dw' = -2e\+05"),
])
def test_unstable_track_says_it_grew_without_bound(law, at_rest):
    # Used to end in "RuntimeError: Newton ... did not converge (mismatch nan ...)".
    with pytest.raises(RuntimeError, match=r"grew without bound in period 1: .* at step \d+ of 2400 .*"
                       r"the system is unstable.*" + at_rest) as info:
        simulate_time_domain(TRACK, TRAIN, law)
    assert "negative stiffness or damping" in str(info.value)


@pytest.mark.parametrize("elements, steps", [(8, 10**8), (10**5, 2400)])
def test_huge_runs_are_refused_before_allocating(elements, steps):
    tracemalloc.start()
    began = time.perf_counter()
    try:
        with pytest.raises(ValueError, match=r"would need about [\d.]+ GB of memory.*above the 4 GB "
                           r"limit.*per period\. Use fewer steps or elements"):
            simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), elements, steps)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert time.perf_counter() - began < 1.0
    assert peak < 1e6  # bytes: nothing of the run's size was allocated


def test_long_runs_warn_with_the_estimated_time():
    # 1.2 million steps fit in memory (2.7 GB with every sleeper's outputs)
    # but take ~4 min a period.
    with pytest.warns(LongRunWarning, match=r"estimated to take \d+ min per period"):
        check_run_cost(SLEEPERS, 8, 1_200_000, 40)
    began = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("error", LongRunWarning)  # stop the call at the warning
        with pytest.raises(LongRunWarning):
            simulate_time_domain(TRACK, TRAIN, LinearFoundation.paper(), 8, 1_200_000)
    assert time.perf_counter() - began < 1.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", LongRunWarning)
        check_run_cost(SLEEPERS, 8, STEPS, 40)  # the default: no warning
