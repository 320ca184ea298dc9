"""The draws of `random_support` on linear laws, solved as a batch (issue 28).

Every draw is a cell of the same rail, train, sleepers and pads, so the
cell's operators at m (`railtrack.equations.cell_harmonic_balance.cell_operators`),
those of the truncation estimate's tail (harmonics m+1..8m), and the map
from the sleepers' seat forces to the rail's curvature under the wheels
(`moment_map`) are built once per m and shared by every draw.  The draws are
cut into chunks of `DRAW_CHUNK`; `solve_chunk` solves one chunk
(`railtrack.solvers.cell_batch`) and reads its peaks, and the chunks are
mapped by `railtrack.solvers.chunk_map.map_chunks`, in this process or on
the caller's executor, with one BLAS thread per chunk
(`railtrack.solvers.threads`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import CellOperators, cell_operators
from ..equations.cell_rail_field import cell_rail_field_coefficients
from ..equations.harmonic_balance import default_samples
from ..equations.moment import kink_coefficients, kink_sum
from ..model.foundations import LinearFoundation
from ..solvers.auto_harmonics import AUTO_ROUNDS
from ..solvers.cell_auto import MAX_CELL_HARMONICS, cell_grown_harmonics, solve_cell_auto
from ..solvers.cell_batch import batch_state, batch_truncation, linear_cells
from ..solvers.cell_solution import CellSolution
from ..solvers.chunk_map import chunk_bounds, map_chunks
from ..solvers.threads import blas_threads
from ..solvers.truncation import auto_samples

__all__ = ["DRAW_CHUNK", "POINTS_PER_SPAN", "TIMES", "Level", "MomentMap", "moment_map",
           "build_level", "solve_chunk", "linear_draws"]

DRAW_CHUNK = 50
"""Draws per chunk: a chunk's tail solves stay within `TAIL_ENTRIES` a group."""
POINTS_PER_SPAN = 8
TIMES = 512


class MomentMap(NamedTuple):
    """The rail's bending moment at the points of `_peaks`, affine in the seat forces.

    ``M[d, i, k] = Re sum_{n, j} gain[i, k, n, j] p_{d, j, n} + offset[i, k]`` [N m]
    at x_i (8 a span) under wheel k (time (x_i + d_k)/v mod T).
    """

    gain: np.ndarray         # (X, K, m+1, N) [m]
    offset: np.ndarray       # (X, K) [N m]


class Level(NamedTuple):
    """Everything a chunk needs at one m, built once and shared by the draws."""

    passage: object
    cell: object
    harmonics: int
    samples: int
    ops: CellOperators
    tail_ops: CellOperators
    moments: MomentMap
    accuracy: float


def moment_map(passage, cell, omega: np.ndarray) -> MomentMap:
    """The map of `MomentMap`, as `CellSolution.rail_bending_moment` reads the rail.

    The curvature's coefficients at x are ``sum_j A_j(x) p_j + b(x)``
    (`cell_rail_field_coefficients` is affine in the seat forces p), so A_j
    is read by putting p = e_j at every harmonic; the closed-form kinks
    (`railtrack.equations.moment`) do not depend on the draw.
    """
    n, m = cell.sleepers, omega.size - 1
    span, ei = passage.sleeper_spacing, passage.rail_bending_stiffness
    x = np.arange(n * POINTS_PER_SPAN) * span / POINTS_PER_SPAN
    wheels = np.asarray(passage.axle_positions, dtype=float)
    times = np.mod((x[:, None] + wheels[None, :]) / float(passage.speed), passage.period)

    def curvature(seat):
        (field,) = cell_rail_field_coefficients(passage, omega, np.zeros((n, m + 1)), seat,
                                                cell.pad_stiffness, x, derivatives=(2,))
        return field                                                           # (X, W)

    base = curvature(np.zeros((n, m + 1), dtype=complex))
    unit = np.stack([curvature(np.repeat(np.eye(n)[:, [j]], m + 1, axis=1)) - base
                     for j in range(n)], axis=-1)                               # (X, W, N)
    weights = np.where(np.arange(m + 1) == 0, 1.0, 2.0)
    phases = np.exp(1j * times[..., None] * omega) * weights                   # (X, K, W)
    gain = ei * unit[:, None] * phases[..., None]
    free = (base - kink_coefficients(passage, omega, x) / ei)[:, None] * phases
    offset = ei * free.sum(axis=-1).real + kink_sum(passage, times, x[:, None])
    return MomentMap(gain, offset)


def build_level(passage, cell, harmonics: int, samples: int, accuracy: float) -> Level:
    """The shared operators of every draw at m = `harmonics`."""
    m = int(harmonics)
    omega = passage.fundamental_frequency * np.arange(m + 1)
    sleeper_weight, rail_weight = cell.weights(passage)
    ops = cell_operators(passage, cell.pad_stiffness, cell.pad_damping, omega,
                         sleeper_weight=sleeper_weight, rail_weight=rail_weight)
    high = passage.fundamental_frequency * np.arange(m + 1, 8 * m + 1)
    tail_ops = cell_operators(passage, cell.pad_stiffness, cell.pad_damping, high)
    return Level(passage, cell, m, int(samples), ops, tail_ops,
                 moment_map(passage, cell, omega), float(accuracy))


def _seat_peaks(seat: np.ndarray) -> np.ndarray:
    """Largest rail-seat load over the sleepers and `TIMES` instants of the period [N]."""
    m = seat.shape[-1] - 1
    if m < TIMES // 2:
        grid = np.zeros(seat.shape[:-1] + (TIMES // 2 + 1,), dtype=complex)
        grid[..., :m + 1] = seat * TIMES
        values = np.fft.irfft(grid, TIMES, axis=-1)
    else:
        phases = np.exp(2j * np.pi * np.outer(np.arange(m + 1), np.arange(TIMES)) / TIMES)
        weights = np.where(np.arange(m + 1) == 0, 1.0, 2.0)[:, None]
        values = (seat @ (phases * weights)).real
    return -values.min(axis=(1, 2))


def solve_chunk(level: Level, law, stiffness: np.ndarray, damping: np.ndarray) -> dict:
    """One chunk of draws at `level`: converged, residual, error, grown m, peaks.

    Parameters
    ----------
    law
        The chunk's batched law, fields broadcasting to (D, N, 1).
    stiffness, damping : ndarray, shape (D, N)
        Its linear foundations' k [N/m] and eta [N s/m].

    Returns
    -------
    dict of ndarray, shape (D,)
        ``converged``, ``residual``, ``error`` (NaN where not converged),
        ``grown`` (the m a draw missing ``level.accuracy`` needs, else 0),
        ``seat`` and ``moment`` (NaN where not converged).
    """
    passage, cell = level.passage, level.cell
    mass = cell.sleeper_mass
    with blas_threads(1):
        c = linear_cells(level.ops, mass, stiffness, damping)
        batch = batch_state(law, mass, c, level.ops, level.samples, cell.weights(passage)[0])
        # a linear law has no force above m and its own tangent: nothing to sample
        errors, tail, seat_tail = batch_truncation(mass, batch, level.tail_ops, None,
                                                   stiffness, damping)
    converged = batch.residual <= TOL
    error = np.fmax(errors["sleeper_displacement"], errors["rail_seat_load"])
    error = np.where(converged, error, np.nan)
    grown = np.zeros(len(c), dtype=int)
    for k in np.flatnonzero(converged & (error > level.accuracy)):
        grown[k] = cell_grown_harmonics(_solution(level, batch, k), tail[k], seat_tail[k],
                                        0.8 * level.accuracy)
    gain, offset = level.moments
    # the seat harmonics as `CellSolution.rail_bending_moment` passes them to the rail
    x, k = offset.shape
    moment = (np.swapaxes(batch.seat, 1, 2).reshape(len(c), -1)
              @ gain.reshape(x * k, -1).T).real.reshape(len(c), x, k) + offset
    seat = _seat_peaks(batch.seat)
    nan = np.full(len(c), np.nan)
    return {"converged": converged, "residual": batch.residual, "error": error,
            "grown": grown, "seat": np.where(converged, seat, nan),
            "moment": np.where(converged, moment.max(axis=(1, 2)), nan)}


TOL = 1e-10
"""The relative residual a draw must meet, `railtrack.solve`'s default for a cell."""


def _solution(level: Level, batch, k: int) -> CellSolution:
    """Draw k as a `CellSolution` (for `cell_grown_harmonics`, which reads its spectra)."""
    def two_sided(x):
        return np.concatenate([np.conj(x[:, :0:-1]), x], axis=-1)

    return CellSolution(level.passage, level.cell, two_sided(batch.coefficients[k]),
                        two_sided(batch.force[k]), two_sided(batch.seat[k]), level.harmonics,
                        level.samples, True, float(batch.residual[k]), 0, np.array([]), "")


def linear_draws(passage, cell, law, factors: np.ndarray, harmonics, *, accuracy: float,
                 executor=None, progress: bool = False) -> dict:
    """Every draw on linear laws (stiffness ``law.stiffness`` times the factors), by levels of m.

    ``harmonics="auto"``: the first level is the m that
    `railtrack.solvers.cell_auto.solve_cell_auto` picks for the cell of the
    mean factor (every X_j = 1); every draw is solved there and given its own
    truncation estimate, and only the draws that miss `accuracy` go on to the
    next level, the largest m that any of them needs
    (`railtrack.solvers.cell_auto.cell_grown_harmonics`, at least 10 % more),
    as "auto" grows m for one cell, at most `AUTO_ROUNDS` + 1 levels and up to
    `MAX_CELL_HARMONICS`.  An explicit m is one level.

    Returns
    -------
    dict of ndarray, shape (D,)
        ``converged``, ``harmonics``, ``error``, ``seat``, ``moment``.
    """
    automatic = isinstance(harmonics, str)
    draws = len(factors)
    if automatic:
        with blas_threads(1):
            m = solve_cell_auto(passage, cell, accuracy=accuracy).harmonics
    else:
        m = int(harmonics)
    stiffness = law.stiffness * factors
    damping = np.broadcast_to(law.damping, factors.shape)
    out = {"converged": np.zeros(draws, bool), "harmonics": np.zeros(draws, int),
           "error": np.full(draws, np.nan), "seat": np.full(draws, np.nan),
           "moment": np.full(draws, np.nan)}
    pending, rounds = np.arange(draws), 0
    while pending.size:
        with blas_threads(1):     # the operators too: stacks of small matrix products
            level = build_level(passage, cell, m, auto_samples(m) if automatic
                                else default_samples(m), accuracy)
        bounds = chunk_bounds(pending.size, DRAW_CHUNK)
        arguments = []
        for start, stop in bounds:
            rows = pending[start:stop]
            arguments.append((level, LinearFoundation(stiffness[rows][..., None],
                                                      damping[rows][..., None]),
                              stiffness[rows], damping[rows]))
        parts = map_chunks(solve_chunk, arguments, [b - a for a, b in bounds],
                           executor=executor, progress=progress,
                           description=f"random_support, m = {m}")
        found = {key: np.concatenate([part[key] for part in parts]) for key in parts[0]}
        for key in ("converged", "error", "seat", "moment"):
            out[key][pending] = found[key]
        out["harmonics"][pending] = m
        rounds += 1
        short = found["converged"] & (found["error"] > accuracy)
        if not automatic or not short.any() or m >= MAX_CELL_HARMONICS or rounds > AUTO_ROUNDS:
            break
        m = min(MAX_CELL_HARMONICS, max(int(np.ceil(1.1 * m)), int(found["grown"][short].max())))
        pending = pending[short]
    return out
