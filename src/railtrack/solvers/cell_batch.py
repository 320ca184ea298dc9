"""Many cells that differ only in their sleepers' foundation laws, solved together (issue 28).

The cells of a batch share the rail, the train, the sleepers' masses and
the pads, and m: the per-harmonic operators ``K1_n, K2_n, g_n`` of
`railtrack.equations.cell_harmonic_balance` depend on nothing else, so they
are built once (`cell_operators`) and used for every cell.  The laws come as
one batched law whose fields broadcast to shape (D, N, 1), cell d's sleeper j
in row (d, j) (every package law is elementwise), so a force or tangent is
one call for the whole batch.

For linear laws the cell is linear: harmonic n of cell d solves
``[K1_n + K2_n diag(M s^2 + k_dj + s eta_dj)] c_n = g_n`` (s = i omega_n), the
same system as `railtrack.solvers.cell_newton`'s linear guess, which the
Newton iteration then accepts as converged.  `linear_cells` solves it for
all cells and harmonics in one stacked `numpy.linalg.solve`.  `batch_state`
then evaluates each cell as `railtrack.solvers.cell_newton.solve_cell` does:
the foundation's harmonics by AFT, the seat force, and the relative residual
``||R|| / ||g||``, so that "converged" is measured, not assumed; and
`batch_truncation` gives every cell the truncation estimate of
`railtrack.solvers.cell_auto.cell_truncation_errors`, with the tail's
operators (harmonics m+1..8m) built once for the batch; for linear laws the
linearisation it needs is the law itself (no force above m, the tangent
k, eta), for others `linearised_law` gives it by AFT.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import CellOperators, _synthesize
from .truncation import auto_samples

__all__ = ["CellBatch", "linear_cells", "batch_state", "linearised_law", "batch_truncation",
           "TAIL_ENTRIES"]

TAIL_ENTRIES = 2_000_000
"""Matrix entries per stacked solve of the tail (32 MB of complex numbers)."""
SHARE_ENTRIES = 1 << 18
"""Samples per group of cells whose tail is measured together (4 MB)."""


class CellBatch(NamedTuple):
    """D cells' one-sided harmonics n = 0..m and their residuals.

    Attributes
    ----------
    coefficients, force, seat : ndarray, shape (D, N, m+1)
        c_{j,n} [m], the foundation's F_{j,n} by AFT [N] and the seat force
        p_{j,n} plus the sleeper's weight at n = 0 [N], as `CellSolution` keeps them.
    residual : ndarray, shape (D,)
        ``||R|| / ||g||`` [-]; inf where the law's force was not finite.
    """

    coefficients: np.ndarray
    force: np.ndarray
    seat: np.ndarray
    residual: np.ndarray


def linear_cells(ops: CellOperators, sleeper_mass: np.ndarray, stiffness: np.ndarray,
                 damping: np.ndarray) -> np.ndarray:
    """c_{d,j,n} [m] of D linear cells on the shared operators, shape (D, N, m+1).

    Parameters
    ----------
    ops : CellOperators
        K1_n, K2_n, g_n at omega_n = n omega_1, n = 0..m.
    sleeper_mass : ndarray, shape (N,)
        M_j [kg].
    stiffness, damping : ndarray, shape (D, N)
        k_{dj} [N/m] and eta_{dj} [N s/m] of each cell's foundations.
    """
    s = 1j * ops.omega[None, :, None]
    support = (sleeper_mass * s**2 + stiffness[:, None, :]
               + s * damping[:, None, :])                                       # (D, W, N)
    blocks = ops.second * support[:, :, None, :]
    blocks += ops.first
    right = np.broadcast_to(ops.load[..., None], blocks.shape[:-1] + (1,))
    c = np.linalg.solve(blocks, right)[..., 0]
    c[:, 0] = c[:, 0].real
    return np.swapaxes(c, 1, 2)


def _apply(matrices: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``matrices[n] @ values[d, :, n]`` for every cell d and harmonic n: (D, W, N)."""
    return (matrices @ np.swapaxes(values, 1, 2)[..., None])[..., 0]


def _aft(law, coefficients: np.ndarray, omega: np.ndarray, samples: int):
    """The batched law on each cell's AFT samples: w, w' (D, N, samples)."""
    d, n, _ = coefficients.shape
    w, v = _synthesize(coefficients.reshape(d * n, -1), omega, samples)
    return w.reshape(d, n, samples), v.reshape(d, n, samples)


def _two_sided_norms(values: np.ndarray) -> np.ndarray:
    """`two_sided_norm` of each (m+1, N) slice of (D, m+1, N)."""
    return np.sqrt(np.sum(np.abs(values[:, 0]) ** 2, axis=-1)
                   + 2 * np.sum(np.abs(values[:, 1:]) ** 2, axis=(1, 2)))


def batch_state(law, sleeper_mass: np.ndarray, coefficients: np.ndarray, ops: CellOperators,
                samples: int, sleeper_weight: np.ndarray | None = None) -> CellBatch:
    """Each cell's foundation harmonics, seat force and residual at `coefficients` (D, N, m+1).

    As `railtrack.solvers.cell_newton.solve_cell` evaluates its last
    iterate: F by AFT on `samples` points, ``p = -M omega^2 c + F``,
    ``R_n = K1_n c_n + K2_n p_n - g_n``.
    """
    m = ops.omega.size - 1
    with np.errstate(invalid="ignore", over="ignore"):
        w, v = _aft(law, coefficients, ops.omega, samples)
        force = np.fft.rfft(np.broadcast_to(law.force(w, v), w.shape), axis=-1)[..., :m + 1]
        force = force / samples
        p = -sleeper_mass[:, None] * ops.omega**2 * coefficients + force
        res = (_apply(ops.first, coefficients) + _apply(ops.second, p)) - ops.load
        scale = _two_sided_norms(ops.load[None])[0]
        residual = _two_sided_norms(res) / scale
    residual = np.where(np.isfinite(residual), residual, np.inf)
    if sleeper_weight is not None:
        p[..., 0] += sleeper_weight
    return CellBatch(coefficients, force, p, residual)


def _tail_shares(kept: np.ndarray, tail: np.ndarray, samples: int) -> np.ndarray:
    """`railtrack.solvers.cell_auto._tail_share` of each cell, (D,).

    A few cells at a time: their grids of samples stay in cache between the
    two transforms (the whole batch's would be written out and read back).
    """
    m = kept.shape[-1] - 1
    cells = max(1, SHARE_ENTRIES // (kept.shape[1] * samples))
    out = np.empty(kept.shape[0])
    for start in range(0, kept.shape[0], cells):
        part = slice(start, start + cells)
        grid = np.zeros(kept[part].shape[:-1] + (samples // 2 + 1,), dtype=complex)
        grid[..., m + 1:m + 1 + tail.shape[-1]] = tail[part] * samples
        error = np.max(np.abs(np.fft.irfft(grid, samples, axis=-1)), axis=(1, 2))
        grid[..., :m + 1] = kept[part] * samples
        peak = np.max(np.abs(np.fft.irfft(grid, samples, axis=-1)), axis=(1, 2))
        with np.errstate(divide="ignore", invalid="ignore"):
            out[part] = np.where(peak > 0, error / peak, np.inf)
    return out


def linearised_law(law, coefficients: np.ndarray, omega: np.ndarray, samples: int):
    """Each sleeper's force harmonics above m and mean tangent along its orbit, by AFT.

    As `railtrack.solvers.cell_auto.cell_truncation_errors` linearises the law:
    ``excess`` (D, N, 7m) the force's harmonics m+1..8m [N], ``stiffness`` and
    ``damping`` (D, N) the tangent's means over the period [N/m], [N s/m].
    (For a linear law they are 0, k and eta exactly: pass those instead.)
    """
    m = omega.size - 1
    with np.errstate(invalid="ignore", over="ignore"):
        w, v = _aft(law, coefficients, omega, samples)
        spectrum = np.fft.rfft(np.broadcast_to(law.force(w, v), w.shape), axis=-1) / samples
        stiffness, damping = (np.broadcast_to(x, w.shape).mean(axis=-1)
                              for x in law.tangent(w, v))
    return spectrum[..., m + 1:8 * m + 1], stiffness, damping


def batch_truncation(sleeper_mass: np.ndarray, batch: CellBatch, tail_ops: CellOperators,
                     excess, stiffness: np.ndarray, damping: np.ndarray):
    """Each cell's estimated truncation error and its tails, as `cell_truncation_errors`.

    Parameters
    ----------
    sleeper_mass : ndarray, shape (N,)
    batch : CellBatch
        From `batch_state` (its seat force includes the sleepers' weight).
    tail_ops : CellOperators
        `cell_operators` at omega_n, n = m+1..8m (no weights: they are static).
    excess : ndarray, shape (D, N, 7m), or None
        The laws' force harmonics m+1..8m [N] (`linearised_law`); None for none
        (linear laws).
    stiffness, damping : ndarray, shape (D, N)
        The laws' mean tangents [N/m], [N s/m].

    Returns
    -------
    errors : dict of ndarray, shape (D,)
        ``"sleeper_displacement"`` and ``"rail_seat_load"`` [-]; NaN where not finite.
    tail, seat_tail : ndarray, shape (D, N, 7m)
        c_{d,j,m+1..8m} [m] and p_{d,j,m+1..8m} [N].
    """
    c = batch.coefficients
    d, n, width = c.shape
    samples = auto_samples(8 * (width - 1))
    high = tail_ops.omega
    tail = np.empty((d, n, high.size), dtype=complex)
    seat_tail = np.empty_like(tail)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        step = max(1, TAIL_ENTRIES // (d * n * n))
        for start in range(0, high.size, step):
            part = slice(start, start + step)
            h = high[part]
            support = (-sleeper_mass * h[:, None] ** 2 + stiffness[:, None, :]
                       + 1j * h[:, None] * damping[:, None, :])                  # (D, W, N)
            blocks = tail_ops.second[part] * support[:, :, None, :]
            blocks += tail_ops.first[part]
            if excess is None:
                rhs = np.broadcast_to(tail_ops.load[part], blocks.shape[:-1])
            else:
                rhs = tail_ops.load[part] - _apply(tail_ops.second[part], excess[..., part])
            solved = np.linalg.solve(blocks, rhs[..., None])[..., 0]            # (D, W, N)
            tail[..., part] = np.swapaxes(solved, 1, 2)
            seat_tail[..., part] = np.swapaxes(support, 1, 2) * tail[..., part]
            if excess is not None:
                seat_tail[..., part] += excess[..., part]
        errors = {"sleeper_displacement": _tail_shares(c, tail, samples),
                  "rail_seat_load": _tail_shares(batch.seat, seat_tail, samples)}
    finite = np.all(np.isfinite(c), axis=(1, 2))
    errors = {key: np.where(finite & np.isfinite(value), value, np.nan)
              for key, value in errors.items()}
    return errors, tail, seat_tail
