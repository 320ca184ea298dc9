"""Issue 18 section 6: the smaller items of the new surface, each with a test that failed before.

Truths used: the documented minimum of `check_stability` (periods >= 2); a
solve stopped after one Newton step (its own `converged` flag says no); the
slider range of `explore`; the run-cost estimate against the ring's actual
size; the spacing of sleepers against the span of positions asked for; the
digits of a double (an x whose phase x omega / v exceeds 2^53 ulp carries no
digit); the inputs of each message against the cause it names.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack import CubicFoundation, LinearFoundation, Track, Train, solve
from railtrack.studies.stability import check_stability

TRACK, TRAIN = Track.paper(), Train.paper()


# -- 1. check_stability(periods=2), the documented minimum -----------------------------------

def test_check_stability_runs_at_its_documented_minimum_of_two_periods():
    s = solve(TRACK, TRAIN, LinearFoundation.paper(), harmonics=60)
    check = check_stability(s, periods=2, elements_per_span=2, steps_per_period=600)
    # A linear track has one periodic solution, stable: the ring stays on it.
    assert check.verdict == "stays" and check.periods == 2


# -- 2. check_stability refuses an unconverged solution ---------------------------------------

def test_check_stability_refuses_an_unconverged_solution():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = solve(TRACK, TRAIN, CubicFoundation.paper(epsilon=0.8), harmonics=20,
                  max_iterations=1)
    assert not s.converged
    with pytest.raises(ValueError, match="not converged"):
        check_stability(s, periods=2, elements_per_span=2, steps_per_period=600)


# -- 3. explore() takes a setting outside a slider's range as given, never clamped ------------

def test_explore_keeps_a_setting_outside_the_slider_range():
    pytest.importorskip("ipywidgets")
    import matplotlib

    matplotlib.use("Agg")
    from railtrack.plotting import explorer as ex

    asked = {"speed": 900.0, "pad_damping": 5000.0, "foundation_stiffness": 0.5}
    for name, value in asked.items():          # each outside the slider's own range
        assert not ex.CONTROLS[name][1] <= value <= ex.CONTROLS[name][2]
    panel = rt.explore(**asked)
    for name, value in asked.items():
        assert panel.controls[name].value == value
        assert panel.state.values[name] == value
    # What is drawn is the case asked for, solved directly.
    direct = ex.solve_case(**asked)
    assert np.max(np.abs(panel.state.solution.coefficients - direct.coefficients)) < 1e-15


def test_explore_refuses_a_setting_that_is_not_a_finite_number():
    pytest.importorskip("ipywidgets")
    with pytest.raises(ValueError, match="speed must be a finite number"):
        rt.explore(speed=float("inf"))


# -- 5. deflection_bowl over a window of millions of sleepers is refused at once --------------

def test_deflection_bowl_refuses_a_window_of_millions_of_sleepers_at_once():
    import time

    s = solve(TRACK, TRAIN, LinearFoundation.paper())
    span = float(TRACK.sleeper_spacing)
    sleepers = 2 * int(np.floor(1e6 / span)) + 1          # k L within [-1e6, 1e6] m
    start = time.perf_counter()
    with pytest.raises(ValueError, match=f"{sleepers} sleepers"):
        s.deflection_bowl(0.0, [-1e6, 0.0, 1e6])
    assert time.perf_counter() - start < 1.0               # refused before it builds them
    # A long but reasonable window is still drawn (10 km: 16,667 sleepers).
    bowl = s.deflection_bowl(0.0, [-5e3, 0.0, 5e3])
    assert bowl.sleepers.size == 2 * int(np.floor(5e3 / span)) + 1


# -- 4. a ring of 2000 elements per span warns of its run time ---------------------------------

def test_a_ring_of_two_thousand_elements_per_span_warns_of_its_run_time():
    from railtrack.timedomain.fem import sleepers_on_ring
    from railtrack.model.passage import Passage
    from railtrack.timedomain.runcost import LongRunWarning, check_run_cost

    sleepers = sleepers_on_ring(Passage(TRACK, TRAIN))
    # Measured on the 2-core machine: 19.9 s a period, 65 s for the 3 periods of
    # the default run from the static start (294 s in the sweep).
    with pytest.warns(LongRunWarning, match="per period"):
        check_run_cost(sleepers, 2000, 2400, 40)
    with warnings.catch_warnings():
        warnings.simplefilter("error", LongRunWarning)
        check_run_cost(sleepers, 8, 2400, 40)          # the default: ~0.2 s a period


# -- 6. positions so far that round-off leaves no digit are refused ----------------------------

EPS = np.finfo(float).eps
ROUNDOFF_PHASE = 1e-3     # rad: the phase round-off accepted, eps * omega_m |x| / v


def _far(s, wagons: float) -> float:
    """0.25 m plus a whole number of wagons: the same rail by periodicity (H / L = 30)."""
    x = 0.25 + float(s.train.wagon_length) * np.round(wagons)
    assert x - float(s.train.wagon_length) * np.round(wagons) == 0.25   # exact in binary
    return x


def test_rail_far_away_repeats_the_rail_here_up_to_the_roundoff_bound():
    s = solve(TRACK, TRAIN, LinearFoundation.paper())
    t = np.linspace(0.0, s.period, 200, endpoint=False)
    per_metre = s.frequencies.max() / float(s.train.speed)      # rad/m of the highest harmonic
    bound = ROUNDOFF_PHASE / (EPS * per_metre)                    # 5.4e11 m at m = 24, 45 m/s
    near = _far(s, 0.9 * bound / float(s.train.wagon_length))
    here_w, here_m = s.rail_displacement(t, 0.25), s.rail_bending_moment(t, 0.25)
    far_w, far_m = s.rail_displacement(t, near), s.rail_bending_moment(t, near)
    # Measured 9e-5 and 4e-4 of the peak at eps * phase = 1.9e-3 rad.
    assert np.max(np.abs(far_w - here_w)) < 1e-4 * np.max(np.abs(here_w))
    assert np.max(np.abs(far_m - here_m)) < 1e-3 * np.max(np.abs(here_m))


@pytest.mark.parametrize("output", ["rail_displacement", "rail_bending_moment"])
def test_positions_where_roundoff_leaves_no_digit_are_refused(output):
    s = solve(TRACK, TRAIN, LinearFoundation.paper())
    t = np.linspace(0.0, s.period, 50, endpoint=False)
    # At 1e15 m the phase of the highest harmonic, 8.4e15 rad, is known to
    # 1.9 rad: measured 8 % (displacement) and 51 % (moment) off.
    with pytest.raises(ValueError, match="round-off"):
        getattr(s, output)(t, _far(s, 1e15 / float(s.train.wagon_length)))
    with pytest.raises(ValueError, match="round-off"):
        getattr(s, output)(t, -_far(s, 1e15 / float(s.train.wagon_length)))


# -- 7. messages that name the real cause -------------------------------------------------------

def test_overflowing_receptance_is_not_blamed_on_a_missing_pad_damping():
    from railtrack.equations.sleeper import rail_coupling
    from railtrack.model.passage import Passage

    # EI = 1e-300 N m^2 at 1e5 m/s: k_b L = (rho S omega^2 / EI)^(1/4) L reaches 1.4e78,
    # whose fourth power overflows; the pad's damping is the paper's 1e6 N s/m.
    track = Track.paper(rail_bending_stiffness=1e-300)
    assert track.pad_damping == 1e6
    passage = Passage(track, Train.paper(speed=1e5))
    with pytest.raises(ValueError) as info:
        rail_coupling(passage, passage.harmonic_frequencies(20))
    message = str(info.value)
    assert "pad_damping > 0" not in message
    assert "overflow" in message and "rail_bending_stiffness" in message
    with pytest.raises(ValueError, match="overflow"):
        solve(track, Train.paper(speed=1e5), LinearFoundation.paper(), harmonics=20)


def test_a_wagon_length_off_a_whole_number_of_spans_shows_the_digits_that_say_so():
    from railtrack.model.passage import Passage
    from railtrack.timedomain.fem import sleepers_on_ring

    passage = Passage(TRACK, Train(18.0000001, (0.0, 3.0), (100e3, 100e3), 45.0))
    with pytest.raises(ValueError) as info:
        sleepers_on_ring(passage)
    message = str(info.value)
    printed = float(message.split("H/L = ")[-1].split()[0])
    assert printed != 30.0 and abs(printed - 18.0000001 / 0.6) < 1e-7
    assert "H = 18.0000001 m" in message and "L = 0.6 m" in message
