"""Finding 12 of issue 27: each unclear error becomes one that names the argument and its value.

Each test passes an input that used to raise an AttributeError, IndexError,
OverflowError or a bare NumPy error, or was taken silently (True as 1 kg, a
NaN dip centre), and checks that a ValueError or TypeError now names the
argument, the value and what is expected.  The truths are the inputs
themselves: a boolean is no mass, NaN is no position, a train needs an axle.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.profile import CosineDip
from railtrack.studies.random_support import RandomSupport

TRACK = rt.Track.paper()
LAW = rt.LinearFoundation(20e6, 0.2e6)


def _cell(sleepers=3):
    return rt.SleeperCell.identical(rt.Passage.paper(), rt.CubicFoundation.paper(), sleepers)


# --- continuation and equivalent_track -------------------------------------------------


def test_continuation_refuses_a_cell_and_names_the_alternatives():
    with pytest.raises(TypeError, match=r"SleeperCell.*solve\(.*sweep") as caught:
        rt.continuation(TRACK, rt.Train.paper(), _cell(), "speed", stop=50.0)
    assert "foundation" in str(caught.value)


def test_equivalent_track_takes_a_callable_law_as_the_same_law_written_as_a_dataclass():
    # f = k w + eta w' is LinearFoundation(k, eta): the fit must not depend on how it is given.
    as_function = rt.equivalent_track(TRACK, lambda w, v: 20e6 * w + 0.2e6 * v)
    as_class = rt.equivalent_track(TRACK, LAW)
    for name in ("mass", "stiffness", "damping"):
        assert getattr(as_function, name) == pytest.approx(getattr(as_class, name), rel=1e-6)


def test_equivalent_track_refuses_a_cell_and_names_one_sleepers_law():
    with pytest.raises(TypeError, match=r"foundation.*SleeperCell.*foundations\["):
        rt.equivalent_track(TRACK, _cell())


@pytest.mark.parametrize("bad", ["track", None, 3.0])
def test_equivalent_track_refuses_what_is_no_track(bad):
    with pytest.raises(TypeError, match="passage"):
        rt.equivalent_track(bad, LAW)


# --- random_support and its quantiles ---------------------------------------------------


@pytest.mark.parametrize("name, bad", [("draws", -1), ("draws", 2.5), ("draws", 0),
                                       ("draws", True), ("draws", "3"), ("seed", -1),
                                       ("seed", 1.5), ("seed", True)])
def test_random_support_names_a_bad_count(name, bad):
    with pytest.raises(ValueError, match=rf"{name} must be an integer >= \d; got {bad!r}"):
        rt.random_support(TRACK, rt.Train.paper(), LAW, sleepers=3, **{name: bad})


@pytest.mark.parametrize("name, bad, error", [("variation", True, TypeError),
                                              ("variation", "0.3", TypeError),
                                              ("sleepers", 2.5, ValueError)])
def test_random_support_names_a_bad_cell_or_scatter(name, bad, error):
    with pytest.raises(error, match=rf"{name} must be .*got {bad!r}"):
        rt.random_support(TRACK, rt.Train.paper(), LAW, draws=1, **{"sleepers": 3, name: bad})


def test_quantiles_without_a_converged_draw_say_so():
    nan = np.full(2, np.nan)
    sample = RandomSupport(0.3, np.ones((2, 3)), nan, nan, np.zeros(2, bool), np.full(2, 40))
    with pytest.raises(ValueError, match="none of the 2 draws converged"):
        sample.quantiles()


def test_quantiles_keep_the_converged_draws_only():
    # Two converged draws, 1 and 3 kN: their median is 2 kN whatever the third holds.
    sample = RandomSupport(0.3, np.ones((3, 3)), np.array([1e3, 5e3, 3e3]),
                           np.array([1.0, 9.0, 3.0]), np.array([True, False, True]),
                           np.full(3, 40))
    assert sample.quantiles((0.5,))["peak_seat_load"] == pytest.approx([2e3])


# --- WheelSolution.extremes -------------------------------------------------------------


@pytest.fixture(scope="module")
def wheel_solution():
    return rt.solve(TRACK, rt.Train.paper(), LAW, 30, wheel=rt.Wheel(600.0))


@pytest.mark.parametrize("bad", [0, -4, 2.5, True])
def test_extremes_names_a_bad_sample_count(wheel_solution, bad):
    with pytest.raises(ValueError, match=rf"samples must be an integer >= 1; got {bad!r}"):
        wheel_solution.extremes(samples=bad)


def test_extremes_with_one_sample_is_the_force_at_time_zero(wheel_solution):
    one = wheel_solution.extremes(samples=1)
    at_zero = wheel_solution.contact_force(np.zeros(1))[:, 0]
    assert one["max"] == pytest.approx(at_zero) and one["min"] == pytest.approx(at_zero)


# --- the law's check at rest ------------------------------------------------------------


def test_a_law_not_finite_at_rest_is_told_in_a_sentence():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        with pytest.raises(ValueError) as caught:
            rt.solve(TRACK, rt.Train.paper(), lambda w, v: 1e6 * np.sqrt(w))
    message = str(caught.value)
    assert message.startswith("the foundation law's linearisation at rest is not finite: "
                              "df/dw = nan N/m, df/dw' = 0 N s/m")
    assert "has its" not in message and "would be unstable" not in message


# --- speed ------------------------------------------------------------------------------


@pytest.mark.parametrize("speed", [1e300, 1.5e154])
def test_a_speed_whose_square_overflows_is_refused_by_name(speed):
    with pytest.raises(ValueError, match=r"speed .*1\.34e\+154 m/s.*overflow"):
        rt.solve(TRACK, rt.Train.paper(speed=speed), LAW)
    with pytest.raises(ValueError, match="speed"):
        rt.Passage.paper().replace(speed=speed)


def test_speeds_far_past_service_stay_allowed():
    # The book studies 700 m/s; the bound is where v^2 leaves double precision.
    for speed in (700.0, 1e8, 1e150):
        train = rt.Train.paper(speed=speed)
        assert np.isfinite(train.period) and np.isfinite(float(train.speed) ** 2)


# --- check_stability --------------------------------------------------------------------


@pytest.fixture(scope="module")
def linear_solution():
    return rt.solve(TRACK, rt.Train.paper(), LAW, 20, stability="off")


@pytest.mark.parametrize("name, bad, error", [
    ("tol", "0.01", TypeError), ("tol", None, TypeError), ("tol", True, TypeError),
    ("tol", -0.01, ValueError), ("kick", "0", TypeError), ("settle_tol", "1e-6", TypeError),
    ("quasi_periodic", np.nan, ValueError), ("max_periods", 2.5, ValueError),
    ("seed", -1, ValueError), ("wagons", 0, ValueError)])
def test_check_stability_names_a_bad_argument(linear_solution, name, bad, error):
    with pytest.raises(error, match=rf"{name} must be .*; got {bad!r}"):
        rt.check_stability(linear_solution, **{name: bad})


# --- the model's dataclasses ------------------------------------------------------------


def test_a_train_without_axles_is_refused_by_name():
    with pytest.raises(ValueError, match=r"axle_positions.*at least one axle.*\(\)"):
        rt.Train(18.0, (), (), 45.0)


@pytest.mark.parametrize("positions, loads", [((0.0, True), (75e3, 75e3)),
                                               ((0.0, 3.0), (75e3, True))])
def test_a_train_refuses_booleans_among_its_axles(positions, loads):
    with pytest.raises(TypeError, match="axle_(positions|loads) must be .*boolean"):
        rt.Train(18.0, positions, loads, 45.0)


def test_a_train_refuses_a_nan_axle_position_by_name():
    with pytest.raises(ValueError, match=r"axle_positions must be a finite number >= 0"):
        rt.Train(18.0, (0.0, np.nan), (75e3, 75e3), 45.0)


@pytest.mark.parametrize("field", ["sleeper_mass", "pad_stiffness", "pad_damping"])
def test_a_cell_refuses_a_boolean_among_its_sleepers(field):
    values = dict(sleeper_mass=[100.0, 100.0], pad_stiffness=[220e6, 220e6],
                  pad_damping=[1e6, 1e6])
    values[field] = [values[field][0], True]
    with pytest.raises(TypeError, match=rf"{field} must be a real number.*True.*boolean"):
        rt.SleeperCell(**values, foundations=[LAW, LAW])


@pytest.mark.parametrize("bad", [np.nan, 2.5, "3", True, None])
def test_a_cell_size_names_a_bad_count(bad):
    with pytest.raises(ValueError, match=rf"sleepers must be an integer >= 1; got {bad!r}"):
        rt.SleeperCell.identical(rt.Passage.paper(), LAW, bad)


@pytest.mark.parametrize("bad, error", [(np.nan, ValueError), (np.inf, ValueError),
                                        (True, TypeError), ("9", TypeError)])
def test_a_dip_refuses_a_centre_that_is_no_position(bad, error):
    with pytest.raises(error, match="centre must be a .*finite|centre must be a real number"):
        CosineDip(0.5e-3, 1.0, 18.0, centre=bad)


@pytest.mark.parametrize("make", [
    lambda: rt.Track.paper(sleeper_mass=[100.0, True]),
    lambda: rt.Wheel([600.0, True]),
    lambda: rt.CubicFoundation(20e6, [2e13, False], 0.8, 5000.0),
    lambda: rt.GapFoundation([1e-3, True], 20e6),
])
def test_other_model_fields_refuse_booleans_in_sequences(make):
    with pytest.raises(TypeError, match="boolean"):
        make()


def test_a_cells_changed_sleeper_refuses_a_boolean():
    cell = rt.SleeperCell.identical(rt.Passage.paper(), LAW, 3)
    with pytest.raises(TypeError, match="sleeper_mass must be a real number; got True"):
        cell.with_sleeper(1, sleeper_mass=True)


def test_a_cell_names_foundations_that_are_no_sequence():
    with pytest.raises(TypeError, match="foundations must be a list or tuple of laws"):
        rt.SleeperCell([100.0], [220e6], [1e6], LAW)


@pytest.mark.parametrize("index, bad", [(0, 0.0), (1, True), (3, np.nan), (2, -1.0)])
def test_the_ballast_reduction_names_a_bad_layer(index, bad):
    from railtrack.model.ballast import single_layer

    names = ["ballast_mass", "ballast_stiffness", "ballast_damping", "subgrade_stiffness",
             "subgrade_damping"]
    values = [500.0, 180e6, 60e3, 65e6, 30e3]
    values[index] = bad
    with pytest.raises((TypeError, ValueError), match=rf"{names[index]} must be"):
        single_layer(*values)


def test_check_stability_refuses_a_cell_and_names_the_alternatives():
    # the ring of check_stability starts from one sleeper's solution: a
    # CellSolution has no .train and once raised a bare AttributeError
    track, train = rt.Track.paper(), rt.Train.paper()
    cell = rt.SleeperCell.identical(
        rt.Passage(track, train), rt.LinearFoundation.paper(), 2
    )
    solution = rt.solve(track, train, cell)
    assert solution.converged
    with pytest.raises(TypeError, match="rt.floquet"):
        rt.check_stability(solution)
