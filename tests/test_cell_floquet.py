"""Floquet multipliers of a cell's periodic solution (issue 27, finding 1).

Independent truths: a cell of N identical sleepers is today's track, so its
multipliers are those `railtrack.floquet` finds for one sleeper (the cell's
own Hill matrix, ``reduce=False``, is an N-fold larger matrix of other
operators); a linear track with damping has every multiplier inside the
unit circle; the ring's linearised period map (`ring_multipliers`) for a
cell of differing sleepers.
"""

import warnings

import numpy as np
import pytest

import railtrack as rt
from railtrack.model.cell import SleeperCell
from railtrack.solvers.cell_floquet import cell_floquet

FOLD_TRACK = rt.Track.paper(pad_damping=1e5)
FOLD_LAW = rt.CubicFoundation(20e6, 2e13, 0.8, 5000.0)


def _fold(speed):
    train = rt.Train.paper(speed=speed)
    return train, rt.Passage(FOLD_TRACK, train)


def _same_set(a, b, tol):
    """Each member of a has one of b within tol, and the other way round."""
    gap = np.abs(a[:, None] - b[None, :])
    return (
        a.size == b.size
        and gap.min(axis=1).max() < tol
        and gap.min(axis=0).max() < tol
    )


@pytest.mark.parametrize("sleepers", [1, 3])
def test_a_cell_of_identical_sleepers_has_the_multipliers_of_one_sleeper(
    sleepers,
):
    train, passage = _fold(480.0)
    plain = rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    reference = rt.floquet(plain)
    assert abs(reference.dominant) == pytest.approx(2.66, abs=0.01)
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, sleepers),
        19,
        stability="off",
    )
    for result in (rt.floquet(cell), cell_floquet(cell, reduce=False)):
        assert not result.stable
        assert abs(result.dominant) == pytest.approx(
            abs(reference.dominant), rel=1e-6
        )
        assert _same_set(
            result.multipliers[result.resolved],
            reference.multipliers[reference.resolved],
            1e-6,
        )


def test_a_stable_state_of_identical_sleepers_matches_one_sleeper():
    train, passage = _fold(420.0)
    reference = rt.floquet(
        rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    )
    assert reference.stable and abs(reference.dominant) == pytest.approx(
        0.49, abs=0.01
    )
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, 3),
        19,
        stability="off",
    )
    result = cell_floquet(cell, reduce=False)
    assert result.stable
    assert _same_set(
        result.multipliers[result.resolved],
        reference.multipliers[reference.resolved],
        1e-6,
    )


def test_a_linear_cell_of_differing_sleepers_is_stable():
    # lightly damped pads and ballast: every free disturbance of a
    # linear track dies out, slowly enough that the box holds many
    # multipliers close to the unit circle
    train, passage = _fold(480.0)
    cell = (
        SleeperCell.identical(passage, rt.LinearFoundation(20e6, 5000.0), 3)
        .with_sleeper(
            1,
            foundation=rt.LinearFoundation(5e6, 2000.0),
            sleeper_mass=250.0,
        )
        .with_sleeper(2, pad_stiffness=5e8)
    )
    result = rt.floquet(
        rt.solve(FOLD_TRACK, train, cell, 12, stability="off"),
        min_multiplier=1e-3,
    )
    assert result.resolved.sum() >= 10
    assert np.all(np.abs(result.multipliers) < 1.0)
    assert result.stable and abs(result.dominant) > 0.3


def test_solve_warns_for_an_unstable_cell_and_keeps_the_full_result():
    train, passage = _fold(480.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 1)
    with pytest.warns(rt.UnstableSolutionWarning, match="2.66"):
        rt.solve(FOLD_TRACK, train, cell)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rt.UnstableSolutionWarning)
        full = rt.solve(
            FOLD_TRACK,
            train,
            SleeperCell.identical(passage, FOLD_LAW, 3),
            stability="full",
        )
    assert full.stability is not None and not full.stability.stable
    assert abs(full.stability.dominant) == pytest.approx(2.66, abs=0.01)


def test_random_support_flags_the_unstable_state():
    with pytest.warns(rt.UnstableSolutionWarning, match="1 of 1 draws"):
        sample = rt.random_support(
            FOLD_TRACK,
            rt.Train.paper(speed=480.0),
            FOLD_LAW,
            sleepers=3,
            variation=0.0,
            draws=1,
        )
    assert sample.stability.tolist() == ["unstable"]
    assert sample.stability_counts() == {
        "stable": 0,
        "unstable": 1,
        "unknown": 0,
    }
    assert "1 unstable" in sample.summary()


def test_a_wheel_solution_is_refused_with_the_alternative_named():
    class Wheeled:
        wheel = object()

    with pytest.raises(TypeError, match="simulate_time_domain"):
        rt.floquet(Wheeled())


@pytest.mark.parametrize("stiffness", [19e6, 16e6])
def test_differing_sleepers_match_the_rings_period_map(stiffness):
    # sleeper 1 of 3 on a softer ballast: 19 MN/m leaves the state
    # unstable (|mu| 2.75, not the uniform track's 2.66), 16 MN/m makes
    # it stable (0.62); the ring linearised about the same orbit (a
    # Newmark period map, no Hill matrix) gives the same multiplier
    train, passage = _fold(480.0)
    softer = rt.CubicFoundation(stiffness, 2e13, 0.8, 5000.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 3).with_sleeper(
        1, foundation=softer
    )
    state = rt.solve(FOLD_TRACK, train, cell, 19, stability="off")
    hill = rt.floquet(state)
    ring = rt.ring_multipliers(
        state, elements_per_span=2, steps_per_period=600
    )
    assert hill.stable == ring.stable == (stiffness < 18e6)
    assert abs(hill.dominant) == pytest.approx(abs(ring.dominant), rel=0.02)
    assert abs(hill.dominant - ring.dominant) < 0.03 * abs(ring.dominant)


def test_the_ring_of_an_identical_cell_is_the_ring_of_one_sleeper():
    train, passage = _fold(480.0)
    plain = rt.solve(FOLD_TRACK, train, FOLD_LAW, 19, stability="off")
    cell = rt.solve(
        FOLD_TRACK,
        train,
        SleeperCell.identical(passage, FOLD_LAW, 3),
        19,
        stability="off",
    )
    options = dict(elements_per_span=2, steps_per_period=300)
    one = rt.ring_multipliers(plain, **options)
    three = rt.ring_multipliers(cell, **options)
    assert abs(three.dominant - one.dominant) < 1e-6 * abs(one.dominant)


def test_the_ring_refuses_a_cell_that_does_not_divide_the_wagon():
    train, passage = _fold(480.0)
    cell = SleeperCell.identical(passage, rt.LinearFoundation.paper(), 4)
    state = rt.solve(FOLD_TRACK, train, cell, 30, stability="off")
    with pytest.raises(ValueError, match="rt.floquet"):
        rt.ring_multipliers(state)


def test_random_support_says_unknown_where_the_quick_look_saw_one_phase():
    # N = 3 of H / L = 30: the quick look sees 1 of the 10 phases per
    # cell, so finding nothing proves nothing; "full" sees all ten
    train = rt.Train.paper(speed=420.0)
    options = dict(sleepers=3, variation=0.0, draws=1)
    quick = rt.random_support(FOLD_TRACK, train, FOLD_LAW, **options)
    full = rt.random_support(
        FOLD_TRACK, train, FOLD_LAW, stability="full", **options
    )
    assert quick.stability.tolist() == ["unknown"]
    assert full.stability.tolist() == ["stable"]
    assert "1 stable, 0 unstable, 0 unknown" in full.summary()


def _damped_law(w, v):
    # cubic spring and a damping that grows with |w|: the tangent damping
    # then varies along the orbit, which couples different harmonics
    return 20e6 * w + 2e13 * w**3 + 5e3 * (1.0 + (w / 1e-3) ** 2) * v


@pytest.mark.filterwarnings("ignore::railtrack.TruncationWarning")
def test_hill_matrix_at_rest_is_the_jacobian_of_the_harmonic_balance():
    # lambda = 0, theta = 0: Hill's matrix of the cell is the Jacobian of
    # the cell's harmonic balance (cell_jacobian, real packing, other code)
    # up to the invertible K2_n on the left of each harmonic's rows
    from railtrack.equations.cell_harmonic_balance import (
        cell_jacobian,
        cell_operators,
        pack_harmonics,
        unpack_harmonics,
    )
    from railtrack.equations.cell_hill import (
        cell_hill_matrix,
        cell_rail_stiffness,
    )
    from railtrack.equations.harmonic_balance import default_samples
    from railtrack.solvers.cell_floquet import cell_tangent

    train, passage = _fold(300.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 3).with_sleeper(
        1, foundation=_damped_law, sleeper_mass=250.0, pad_stiffness=5e8
    )
    state = rt.solve(FOLD_TRACK, train, cell, 8, stability="off")
    m, n = state.harmonics, 3
    omega = passage.fundamental_frequency * np.arange(m + 1)
    ops = cell_operators(
        passage, cell.pad_stiffness, cell.pad_damping, omega
    )
    c = state.coefficients[:, m:]
    jacobian = cell_jacobian(cell, c, ops, default_samples(2 * m))
    rng = np.random.default_rng(5)
    dc = rng.standard_normal((n, m + 1)) + 1j * rng.standard_normal(
        (n, m + 1)
    )
    dc[:, 0] = dc[:, 0].real
    change = unpack_harmonics(jacobian @ pack_harmonics(dc.T), n)
    expected = np.linalg.solve(ops.second, change.T[..., None])[..., 0]

    two_sided = np.concatenate([np.conj(dc[:, :0:-1]), dc], axis=1)
    hill = cell_hill_matrix(passage, cell, cell_tangent(state, m), 0.0, 0.0)
    rows = (hill @ two_sided.T.ravel()).reshape(2 * m + 1, n)[m:]
    cell_phase = omega * n * passage.sleeper_spacing / passage.speed
    _, second = cell_rail_stiffness(
        passage,
        cell.pad_stiffness,
        cell.pad_damping,
        1j * omega,
        cell_phase,
    )
    found = np.linalg.solve(second, rows[..., None])[..., 0]
    scale = np.abs(expected).max()
    assert np.abs(found - expected).max() < 1e-7 * scale


@pytest.mark.filterwarnings("ignore::railtrack.TruncationWarning")
def test_the_derivative_of_hills_matrix_is_its_slope():
    from railtrack.equations.cell_hill import (
        cell_hill_derivative,
        cell_hill_matrix,
    )
    from railtrack.solvers.cell_floquet import cell_tangent

    train, passage = _fold(300.0)
    cell = SleeperCell.identical(passage, FOLD_LAW, 3).with_sleeper(
        1, foundation=_damped_law, sleeper_mass=250.0
    )
    state = rt.solve(FOLD_TRACK, train, cell, 8, stability="off")
    toeplitz = cell_tangent(state, 8)
    exponent, theta = (
        np.array([-3.0 + 40.0j, 5.0 - 2.0j]),
        np.array([0.3, 2.0]),
    )
    rng = np.random.default_rng(2)
    v = rng.standard_normal((2, 3 * 17)) + 1j * rng.standard_normal(
        (2, 3 * 17)
    )
    slope = cell_hill_derivative(
        passage, cell, toeplitz, exponent, theta, v
    )
    h = 1e-4
    ends = [
        np.einsum(
            "rij,rj->ri",
            cell_hill_matrix(passage, cell, toeplitz, exponent + d, theta),
            v,
        )
        for d in (h, -h, 1j * h, -1j * h)
    ]
    # analytic in lambda: the same slope along the real and imaginary axes
    real = (ends[0] - ends[1]) / (2 * h)
    imaginary = (ends[2] - ends[3]) / (2j * h)
    scale = np.abs(real).max()
    assert np.abs(real - imaginary).max() < 1e-6 * scale
    assert np.abs(slope - real).max() < 1e-6 * scale


def test_the_rails_pinned_pinned_mode_is_neutral_not_unstable():
    # From m = 61 on (420 m/s) the cell's Hill matrix carries the rail's
    # pinned-pinned mode: nodes at every sleeper, so no pad damps it and
    # |mu| = 1.  Its frequency in the fixed frame is the closed form
    # (pi / L)^2 sqrt(EI / rho S); it must not make the state "unstable".
    train = rt.Train.paper(speed=420.0)
    cell = rt.SleeperCell.identical(rt.Passage(FOLD_TRACK, train), FOLD_LAW, 3)
    solution = rt.solve(FOLD_TRACK, train, cell, 85, stability="off")
    result = rt.floquet(solution)
    assert abs(abs(result.dominant) - 1.0) < 1e-8
    track = FOLD_TRACK
    pinned = (np.pi / track.sleeper_spacing) ** 2 * np.sqrt(
        track.rail_bending_stiffness / track.rail_linear_mass
    )
    omega = 2 * np.pi * train.speed / train.wagon_length
    imag = abs(result.exponents[np.argmax(np.abs(result.multipliers))].imag)
    k = np.round((pinned - imag) / omega), np.round((pinned + imag) / omega)
    assert min(abs(pinned - imag - k[0] * omega), abs(pinned + imag - k[1] * omega)) < 1e-3
    assert result.verdict == "stable" and "neutral" in result.message
