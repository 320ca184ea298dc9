"""Bad input gets a clear error; an unconverged iteration says so."""

import doctest
import importlib
import pkgutil

import numpy as np
import pytest

import railtrack
from railtrack import (
    BilinearFoundation,
    ConvergenceError,
    CubicFoundation,
    LinearFoundation,
    Track,
    Train,
    solve,
)

PAPER = Track.paper()
TRAIN = Train.paper()


@pytest.mark.parametrize(
    "field, value",
    [
        ("rail_linear_mass", 0.0),
        ("rail_bending_stiffness", -6.3e6),
        ("sleeper_mass", 0.0),
        ("sleeper_spacing", -0.6),
        ("pad_stiffness", 0.0),
        ("pad_damping", -1.0),
    ],
)
def test_bad_track_field_is_named(field, value):
    with pytest.raises(ValueError, match=field):
        Track.paper(**{field: value})


@pytest.mark.parametrize(
    "changes, match",
    [
        ({"speed": 0.0}, "speed"),
        ({"speed": float("nan")}, "speed"),
        ({"wheel_load": -1.0}, "axle_loads"),
        ({"wheel_spacing": 0.0}, "axle_positions"),
        ({"wagon_length": 0.0}, "wagon_length"),
        ({"wheel_spacing": 20.0}, "wagon_length"),  # D >= H: an axle beyond the wagon
        ({"wheel_spacing": 18.0}, "wagon_length"),  # D = H: an axle at the next wagon's first
    ],
)
def test_bad_train_field_is_named(changes, match):
    with pytest.raises(ValueError, match=match):
        Train.paper(**changes)


@pytest.mark.parametrize(
    "make, name",
    [
        (lambda: LinearFoundation(0.0, 1.0), "stiffness"),
        (lambda: LinearFoundation(1e7, -1.0), "damping"),
        (lambda: BilinearFoundation(0.0, 1e7), "compression_stiffness"),
        (lambda: BilinearFoundation(2e7, -1e7), "tension_stiffness"),
        (lambda: CubicFoundation(2e7, -1.0, 0.5), "cubic_stiffness"),
        (lambda: CubicFoundation(2e7, 2e13, -0.5), "epsilon"),
        (lambda: CubicFoundation(2e7, 2e13, 0.5, -2.0), "damping"),
    ],
)
def test_bad_foundation_parameter_is_named(make, name):
    with pytest.raises(ValueError, match=name):
        make()


@pytest.mark.parametrize("harmonics", [0, -3, 2.5, True])
def test_bad_harmonics(harmonics):
    with pytest.raises(ValueError, match="harmonics"):
        solve(PAPER, TRAIN, LinearFoundation.paper(), harmonics=harmonics)


def test_bad_method_lists_the_valid_ones():
    with pytest.raises(ValueError, match="fixed-point"):
        solve(PAPER, TRAIN, LinearFoundation.paper(), 15, method="secant")


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"samples": 20}, "samples"),
        ({"tol": -1.0}, "tol"),
        ({"max_iterations": -1}, "max_iterations"),
        ({"method": "fixed-point", "split": 16}, "split"),
        ({"initial": np.zeros(3)}, "initial"),
    ],
)
def test_bad_solver_options(kwargs, name):
    with pytest.raises(ValueError, match=name):
        solve(PAPER, TRAIN, LinearFoundation.paper(), 15, **kwargs)


def test_analytic_method_needs_a_linear_law():
    with pytest.raises(TypeError, match="LinearFoundation"):
        solve(PAPER, TRAIN, CubicFoundation.paper(), 15, method="analytic")


def test_non_finite_foundation_law_is_reported():
    law = lambda w, v: np.where(w < -5e-4, np.nan, 2e7 * w)  # noqa: E731
    with pytest.raises(ValueError, match="non-finite"):
        solve(PAPER, TRAIN, law, 15)


def test_not_a_foundation():
    with pytest.raises(TypeError, match="foundation"):
        solve(PAPER, TRAIN, 42, 15)


def test_split_warns_when_ignored():
    with pytest.warns(UserWarning, match="split"):
        solve(PAPER, TRAIN, LinearFoundation.paper(), 15, split=3)


def test_early_stop_is_reported_as_not_converged():
    solution = solve(PAPER, TRAIN, LinearFoundation.paper(), 15, method="fixed-point", max_iterations=15)
    assert not solution.converged
    assert solution.iterations == 15
    assert "> tol" in solution.message
    assert solution.residual > 1e-3  # the mean is still ~24 % off after 15 steps


def test_strict_raises_and_names_the_slow_harmonics():
    with pytest.raises(ConvergenceError) as info:
        solve(PAPER, TRAIN, LinearFoundation.paper(), 15, method="fixed-point", max_iterations=15, strict=True)
    error = info.value
    # n = 0, 1, 2 contract by ~0.91 per step: the slowest of eq. (21)
    assert {0, 1, 2} <= set(error.slow_harmonics)
    assert "newton" in str(error)
    assert not error.solution.converged


def test_strict_names_diverging_harmonics():
    with pytest.raises(ConvergenceError) as info:
        solve(PAPER, TRAIN, LinearFoundation.paper(), 15, method="fixed-point", split=0, max_iterations=30,
              strict=True)
    assert "diverging harmonics" in str(info.value).lower()
    assert len(info.value.slow_harmonics) > 0


def test_callable_law_gives_the_same_answer_as_the_object():
    cubic = CubicFoundation.paper(0.8)
    by_callable = solve(PAPER, TRAIN, lambda w, v: cubic.force(w, v), 15)
    np.testing.assert_allclose(by_callable.coefficients, solve(PAPER, TRAIN, cubic, 15).coefficients,
                               rtol=0, atol=1e-12)


def _modules():
    for info in pkgutil.walk_packages(railtrack.__path__, "railtrack."):
        yield info.name


@pytest.mark.parametrize("name", sorted(_modules()))
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0
