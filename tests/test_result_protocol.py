"""One kind of result (issue 29): Solution, CellSolution and WheelSolution answer alike.

The protocol (`railtrack.solvers.result_protocol.SteadyStateResult`) is the
reference: every class has each shared name with the protocol's signature,
and its arrays have the documented axes (sleepers or wheels first, time
last).  Where the cases coincide the answers agree, checked against an
independent symmetry: a uniform cell of N identical sleepers is the single
sleeper's history shifted by j L / v at sleeper j (two solvers, one answer).
"""

import inspect
import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.solvers.result_protocol import (PER_SLEEPER, PER_WHEEL, SHARED_ATTRIBUTES,
                                               SHARED_METHODS, SteadyStateResult)

TRACK, TRAIN = rt.Track.paper(), rt.Train.paper()
LAW = rt.CubicFoundation.paper()
N = 5                                              # sleepers of the uniform cell
SPACING, SPEED = float(TRACK.sleeper_spacing), float(TRAIN.speed)
SINGLE = rt.solve(TRACK, TRAIN, LAW, 20)
CELL = rt.solve(TRACK, TRAIN, rt.SleeperCell.identical(SINGLE.passage, LAW, N), 20)
with warnings.catch_warnings():
    warnings.simplefilter("ignore", rt.TruncationWarning)
    WHEELS = rt.solve(TRACK, TRAIN, rt.LinearFoundation(20e6, 0.2e6), 60, wheel=rt.Wheel(600.0),
                      profile=rt.CosineDip(1e-3, 1.0, 18.0, centre=9.3))
RESULTS = {"Solution": SINGLE, "CellSolution": CELL, "WheelSolution": WHEELS}
T = np.linspace(0.0, TRAIN.period, 12).reshape(3, 4)      # times of a 2-D shape


def test_the_cases_converged():
    assert all(r.converged for r in RESULTS.values())


@pytest.mark.parametrize("kind", RESULTS)
def test_every_shared_name_has_the_protocol_signature(kind):
    result = RESULTS[kind]
    assert isinstance(result, SteadyStateResult)
    for name in SHARED_ATTRIBUTES:
        assert hasattr(result, name), name
    for name in SHARED_METHODS:
        ours = _parameters(getattr(type(result), name))
        assert ours == _parameters(getattr(SteadyStateResult, name)), (kind, name, ours)


def _parameters(method):
    """Names, kinds and defaults, in order (annotations are spelt differently)."""
    return [(p.name, p.kind, p.default) for p in inspect.signature(method).parameters.values()]


@pytest.mark.parametrize("kind", RESULTS)
def test_sleepers_or_wheels_first_time_last(kind):
    result = RESULTS[kind]
    expected = {"Solution": (), "CellSolution": (N,), "WheelSolution": (30,)}[kind]
    assert result.sleeper_shape == expected
    for name in PER_SLEEPER:
        assert getattr(result, name)(T).shape == expected + T.shape, name
    for name in PER_WHEEL:
        assert getattr(result, name)(T).shape == (2,) + T.shape, name
    x = np.array([0.0, 0.3, 1.1])[:, None]
    t = T[0][None, :]
    assert result.rail_displacement(t, x).shape == (3, 4)
    assert result.rail_bending_moment(t, x, kinks="series").shape == (3, 4)


@pytest.mark.parametrize("kind", RESULTS)
def test_one_period_is_times_and_the_sleepers_there(kind):
    result = RESULTS[kind]
    t, w = result.one_period()
    m = max(result.harmonics, int(np.max(getattr(result, "grid", [0]))))
    assert t.shape == (max(400, 4 * m),)
    np.testing.assert_allclose(np.diff(t), result.period / t.size, rtol=1e-9)
    assert t[0] == 0.0 and t[-1] < result.period
    np.testing.assert_array_equal(w, result.sleeper_displacement(t))
    t7, w7 = result.one_period(7)
    assert t7.shape == (7,) and w7.shape == result.sleeper_shape + (7,)
    with pytest.raises(ValueError, match="samples"):
        result.one_period(0)


@pytest.mark.parametrize("name", PER_SLEEPER)
def test_a_uniform_cell_is_the_single_sleeper_shifted_by_j_l_over_v(name):
    # two solvers (eq. 17 for one sleeper; the cell's N coupled sleepers)
    t = np.linspace(0.0, TRAIN.period, 37)
    cell = getattr(CELL, name)(t)
    single = np.stack([getattr(SINGLE, name)(t - j * SPACING / SPEED) for j in range(N)])
    np.testing.assert_allclose(cell, single, rtol=0, atol=1e-8 * np.abs(single).max())


def test_the_wheels_and_the_rail_agree_between_the_single_sleeper_and_the_cell():
    t = np.linspace(0.0, TRAIN.period, 23)
    for name in PER_WHEEL:
        np.testing.assert_allclose(getattr(CELL, name)(t), getattr(SINGLE, name)(t), rtol=0,
                                   atol=1e-8 * np.abs(getattr(SINGLE, name)(t)).max())
    assert np.all(CELL.contact_force(t) == 75e3)          # a moving load presses with Q
    # 2100 samples: the shift L / v is 70 of them, so each sleeper sees the same instants
    np.testing.assert_array_equal(CELL.contact_fraction(2100),
                                  SINGLE.contact_fraction(2100) * np.ones(N))
    rest = SINGLE.at_rest()
    assert rest.converged and rest.sleeper_displacement == 0.0 == rest.foundation_force


def test_rail_under_wheels_is_the_rail_at_each_wheel_wheels_first():
    # old code: shape t.shape + (K,); each row k is the rail at x = v t - d_k
    t = np.linspace(0.0, TRAIN.period, 9)
    for result in RESULTS.values():
        under = result.rail_under_wheels(t)
        assert under.shape == (2, 9)
        for k, d in enumerate(TRAIN.axle_positions):
            np.testing.assert_allclose(under[k], result.rail_displacement(t, SPEED * t - d),
                                       rtol=1e-12, atol=1e-15)


def test_the_wheels_rail_above_its_sleepers_is_its_rail_field_there():
    # the pad relation (w_j + p_j / pad) against the rail field at x = jL
    # (the sleepers' reactions plus eq. 13.2): apart, they agree to truncation
    t = np.linspace(0.0, TRAIN.period, 11)
    x = np.arange(30)[:, None] * SPACING
    field = WHEELS.rail_displacement(np.broadcast_to(t, (30, 11)), x)
    np.testing.assert_allclose(WHEELS.rail_above_sleepers(t), field, rtol=0,
                               atol=5e-3 * np.abs(field).max())
    np.testing.assert_allclose(WHEELS.foundation_force(t), WHEELS.sleepers.foundation_force(t))
    assert WHEELS.stability is None
    np.testing.assert_array_equal(WHEELS.frequencies, WHEELS.sleepers.frequencies)
    series = WHEELS.rail_bending_moment(t, 9.3, kinks="series")
    closed = WHEELS.rail_bending_moment(t, 9.3)
    assert np.abs(series - closed).max() < 0.05 * np.abs(closed).max()   # mid-span: no kink
