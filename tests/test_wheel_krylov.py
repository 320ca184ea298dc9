"""Newton's step with wheels, matrix-free by GMRES (issue 28), against the dense step.

Truth: the Jacobian of the contact residual by central finite differences,
column by column, through the whole residual pipeline (the sleepers solved
exactly for the wheel forces, `solve_cell`, then `wheel_residual`): a linear
cell, so that the track is exactly linear and the differences see only
Hertz's curvature.  The dense Newton step is its solve.
"""

import numpy as np

import railtrack as rt
from railtrack.equations.cell_harmonic_balance import tangent_spectrum
from railtrack.equations.wheel_harmonic_balance import wheel_loads, wheel_residual, wheel_system
from railtrack.solvers.cell_newton import solve_cell
from railtrack.solvers.wheel_krylov import ContactJacobian, gmres
from railtrack.solvers.wheel_track import _diagonal, _transfer, track_operator, track_response

M, SAMPLES = 40, 256


def _case():
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper(speed=45.0))
    law = rt.LinearFoundation(20e6, 0.2e6)
    cell = rt.SleeperCell.identical(passage, law, 3).with_sleeper(
        1, foundation=rt.LinearFoundation(5e6, 0.05e6), pad_stiffness=9e7)
    wheel = rt.Wheel(600.0)
    profile = rt.CosineDip(0.3e-3, 0.6, 1.8, centre=0.9)      # repeats with the cell
    return passage, cell, wheel, profile, wheel_system(passage, cell, wheel, M, SAMPLES)


def _residual(passage, cell, wheel, profile, system, x):
    k_w, lmax = len(passage.axle_positions), system.grid.size
    rows = x.reshape(k_w, 2 * lmax + 1)
    forces = rows[:, 1:lmax + 1] + 1j * rows[:, lmax + 1:]
    c = solve_cell(passage, cell, M, samples=SAMPLES, tol=1e-14,
                   extra_load=wheel_loads(system, forces)).coefficients[:, M:]
    _, contacts, delta, _ = wheel_residual(passage, cell, wheel, profile, system, c, forces,
                                           rows[:, 0])
    packed = np.concatenate([contacts[:, :1].real, contacts[:, 1:].real,
                             contacts[:, 1:].imag], axis=1).ravel()
    return packed / max(passage.axle_loads), delta


def test_the_gmres_step_is_the_dense_newton_step():
    passage, cell, wheel, profile, system = _case()
    k_w, lmax = len(passage.axle_positions), system.grid.size
    rng = np.random.default_rng(3)
    rows = np.zeros((k_w, 2 * lmax + 1))
    rows[:, 0] = wheel.static_compression(75e3) + 0.1e-3          # a mean lift in the dip
    rows[:, 1:] = rng.normal(size=(k_w, 2 * lmax)) * 2e3           # wheel forces [N]
    x = rows.ravel()
    current, delta = _residual(passage, cell, wheel, profile, system, x)
    assert np.ptp(wheel.contact_stiffness(delta)) > 0.1 * np.mean(wheel.contact_stiffness(delta))
    steps = np.where(np.arange(x.size) % (2 * lmax + 1) == 0, 1e-9, 1.0)   # [m], [N]
    dense = np.empty((x.size, x.size))
    for i in range(x.size):
        e = np.zeros_like(x)
        e[i] = steps[i]
        ahead = _residual(passage, cell, wheel, profile, system, x + e)[0]
        behind = _residual(passage, cell, wheel, profile, system, x - e)[0]
        dense[:, i] = (ahead - behind) / (2 * steps[i])
    s = 1j * system.ops.omega[:, None]
    pairs = np.array([law.linearization() for law in cell.foundations])
    support = cell.sleeper_mass * s**2 + pairs[:, 0] + s * pairs[:, 1]
    jacobian = ContactJacobian(system, track_operator(system, cell, support),
                               wheel.contact_stiffness(delta), max(passage.axle_loads))
    applied = np.stack([jacobian.apply(e) for e in np.eye(x.size)], axis=1)
    for i in range(x.size):
        np.testing.assert_allclose(applied[:, i], dense[:, i], rtol=0,
                                   atol=1e-6 * np.abs(dense[:, i]).max())
    step, relative, _ = gmres(jacobian.apply, jacobian.precondition, -current, 1e-12)
    assert relative <= 1e-12
    truth = np.linalg.solve(dense, -current)
    np.testing.assert_allclose(step, truth, rtol=0, atol=1e-5 * np.abs(truth).max())
    # against the matrix-free operator's own dense form: the Krylov solve itself
    np.testing.assert_allclose(step, np.linalg.solve(applied, -current), rtol=0,
                               atol=1e-10 * np.abs(truth).max())


def test_the_preconditioners_blocks_are_the_tracks_response_at_the_harmonic_loaded():
    # the blocks p -> p are built from the transfer through the sleepers, not by applying C:
    # a unit force at one harmonic of one wheel, read at that harmonic, is the block's column
    passage, cell, wheel, profile, system = _case()
    k_w, lmax = len(passage.axle_positions), system.grid.size
    s = 1j * system.ops.omega[:, None]
    pairs = np.array([law.linearization() for law in cell.foundations])
    support = cell.sleeper_mass * s**2 + pairs[:, 0] + s * pairs[:, 1]
    operator = track_operator(system, cell, support)
    for harmonic in range(lmax):
        for part in (1.0, 1j):
            forces = np.zeros((k_w, lmax), dtype=complex)
            forces[0, harmonic] = part
            moved = track_response(system, operator, forces)[:, harmonic]
            column = 0 if part == 1.0 else k_w
            block = operator.diagonal[harmonic][:, column]
            np.testing.assert_allclose(np.concatenate([moved.real, moved.imag]), block,
                                       rtol=1e-12, atol=1e-12 * np.abs(block).max())


def test_the_track_under_the_wheels_is_exact_over_a_sleeper_whose_tangent_varies():
    # one sleeper of three on a cubic law: its tangent swings over the period, so the
    # mean-tangent track is only a quasi-Newton model; with the sleeper's variation
    # (Woodbury) C is the derivative of the residual pipeline, the sleepers solved exactly
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper(speed=45.0))
    law = rt.LinearFoundation(20e6, 0.2e6)
    cubic = rt.CubicFoundation(20e6, 2e14, 0.8, 5000.0)
    cell = rt.SleeperCell.identical(passage, law, 3).with_sleeper(1, foundation=cubic)
    wheel, profile = rt.Wheel(600.0), rt.CosineDip(0.3e-3, 0.6, 1.8, centre=0.9)
    system = wheel_system(passage, cell, wheel, M, SAMPLES)
    k_w, lmax = len(passage.axle_positions), system.grid.size
    rng = np.random.default_rng(5)
    forces = rng.normal(size=(k_w, lmax)) * 2e3 + 1j * rng.normal(size=(k_w, lmax)) * 2e3

    def sleepers(f):
        return solve_cell(passage, cell, M, samples=SAMPLES, tol=1e-14,
                          extra_load=wheel_loads(system, f))

    def rail(f):
        c = sleepers(f).coefficients[:, M:]
        _, _, delta, _ = wheel_residual(passage, cell, wheel, profile, system, c, f,
                                        np.zeros(k_w))
        return (np.fft.rfft(delta, axis=-1) / SAMPLES)[:, system.grid]

    c = sleepers(forces).coefficients[:, M:]
    tangent = tangent_spectrum(cell, c, system.ops, SAMPLES)
    assert np.ptp(tangent[1][0, 1]) > 0.2 * np.mean(tangent[1][0, 1])    # it swings
    mean = tangent[0][:, :, 2 * M].real
    s = 1j * system.ops.omega[:, None]
    support = cell.sleeper_mass * s**2 + mean[0] + s * mean[1]
    exact = track_operator(system, cell, support, tangent=tangent)
    quasi = track_operator(system, cell, support)
    for _ in range(3):
        push = rng.normal(size=(k_w, lmax)) * 5.0 + 1j * rng.normal(size=(k_w, lmax)) * 5.0
        difference = (rail(forces + push) - rail(forces - push)) / 2.0
        applied = track_response(system, exact, push)
        np.testing.assert_allclose(applied, difference, rtol=0,
                                   atol=1e-6 * np.abs(difference).max())
        # the mean tangent alone misses by far more: the test can tell them apart
        assert np.abs(track_response(system, quasi, push) - difference).max() \
            > 1e-3 * np.abs(difference).max()


def test_identical_sleepers_give_c_by_class_blocks_equal_to_the_matrix_free_product():
    # identical sleepers: C couples p only to p' = +-p mod N G; the blocks and the
    # matrix-free chain (W P, the sleepers' solve, the rail read by FFT) agree
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper(speed=45.0))
    law = rt.LinearFoundation(20e6, 0.2e6)
    for sleepers, m in ((3, 40), (30, 75)):
        cell = rt.SleeperCell.identical(passage, law, sleepers)
        system = wheel_system(passage, cell, rt.Wheel(600.0), m, 512)
        s = 1j * system.ops.omega[:, None]
        support = np.broadcast_to(cell.sleeper_mass * s**2 + 20e6 + s * 0.2e6,
                                  (m + 1, sleepers)).copy()
        operator = track_operator(system, cell, support)
        assert operator.blocks is not None
        rng = np.random.default_rng(sleepers)
        shape = (2, system.grid.size)
        forces = rng.normal(size=shape) + 1j * rng.normal(size=shape)
        blocks = track_response(system, operator, forces)
        chain = track_response(system, operator._replace(blocks=None), forces)
        np.testing.assert_allclose(blocks, chain, rtol=0, atol=1e-10 * np.abs(chain).max())
    # a cell whose sleepers differ couples every class: no blocks
    cell = rt.SleeperCell.identical(passage, law, 3).with_sleeper(
        1, foundation=rt.LinearFoundation(5e6, 0.05e6))
    system = wheel_system(passage, cell, rt.Wheel(600.0), 40, 512)
    s = 1j * system.ops.omega[:, None]
    support = cell.sleeper_mass * s**2 + np.array([20e6, 5e6, 20e6]) + s * np.array(
        [0.2e6, 0.05e6, 0.2e6])
    assert track_operator(system, cell, support).blocks is None


def test_the_preconditioners_blocks_read_off_the_class_blocks_are_the_built_ones():
    passage = rt.Passage(rt.Track.paper(), rt.Train.paper(speed=45.0))
    cell = rt.SleeperCell.identical(passage, rt.LinearFoundation(20e6, 0.2e6), 30)
    system = wheel_system(passage, cell, rt.Wheel(600.0), 75, 512)
    s = 1j * system.ops.omega[:, None]
    support = np.broadcast_to(cell.sleeper_mass * s**2 + 20e6 + s * 0.2e6, (76, 30)).copy()
    operator = track_operator(system, cell, support)
    built = _diagonal(system, *_transfer(system, support, operator.inverse, 75), 75, 75)
    np.testing.assert_allclose(operator.diagonal, built, rtol=0, atol=1e-12 * np.abs(built).max())
