"""C for identical sleepers: sparse blocks between the wheel harmonics of one class (issue 28).

On a cell of identical sleepers under one support the transfer through the
sleepers is diagonal in the Floquet modes: a wheel harmonic p loads mode
s(p), the rail under the wheels reads Fourier index r(p'), and only
r = -s (mod N) answers (r = s for n < 0, through conj).  So C couples p
only to the p' of its class (p' = +-p mod N G): 4 N blocks of
(K l/N)^2 entries, built once per support as products over the sleeper
harmonics n.  A product with C then costs O(K^2 l^2 / N) instead of the
matrix-free O((m+1) l K) of `railtrack.solvers.wheel_track`, which at
m = 687 is what GMRES spends its time on.  For other cells (a hanging
sleeper) the transfer couples every (r, s): `class_blocks` returns None
and C stays matrix-free.
"""

from __future__ import annotations

import numpy as np

from ..equations.wheel_harmonic_balance import wheels_under

__all__ = ["class_blocks", "apply_blocks", "blocks_diagonal", "SPARSE_TOL"]

SPARSE_TOL = 1e-13
"""Transfer below this fraction of its largest entry is round-off (identical sleepers)."""


def class_blocks(system, positive: np.ndarray, negative: np.ndarray):
    """The blocks of C's force part, or None where the transfer is not diagonal in modes.

    Parameters
    ----------
    positive, negative : ndarray, shape (m+1, N, N)
        Q[n, r, s] for n >= 0 and, through conj, n <= 0 (n = 0 once), as in
        `railtrack.solvers.wheel_track`.

    Returns
    -------
    list of (rows, cols, matrix, conjugate) or None
        delta[rows] += matrix @ u[cols] (or conj(u)), flattened (harmonic, wheel).
    """
    m, n_sl = positive.shape[0] - 1, positive.shape[1]
    r, s = np.meshgrid(np.arange(n_sl), np.arange(n_sl), indexing="ij")
    # n >= 0 answers at r = -s, n <= 0 (through conj) at r = s
    largest = max(float(np.max(np.abs(positive))), float(np.max(np.abs(negative))), 1e-300)
    if np.max(np.abs(positive[:, (r + s) % n_sl != 0]), initial=0.0) > SPARSE_TOL * largest \
            or np.max(np.abs(negative[:, r != s]), initial=0.0) > SPARSE_TOL * largest:
        return None
    lmax = system.grid.size
    factor = system.load_gap[..., None] * system.sleeper_shift[:, None] * system.wheel_phase
    plus, minus = factor[:, :lmax], factor[:, lmax:]
    reads = system.mode_of_wheel
    # gathered once by class, so that each block reads contiguous slices: a gather per
    # block from the (m+1, 2l, K) factor was 60 % of the blocks' time at m = 549
    row_order, row_groups = _groups(reads)
    under = (system.under_weight[row_order, :, None] * system.harmonic_phase
             * np.conj(system.wheel_phase[row_order, None]))              # (l, 2m+1, K)
    upper, lower = under[:, m:], under[:, m::-1]
    plus_order, plus_groups = _groups(system.load_mode[:lmax])
    minus_order, minus_groups = _groups(system.load_mode[lmax:])
    plus, minus = plus[:, plus_order], minus[:, minus_order]
    branches = ((upper, positive, plus_order, plus_groups, plus, False, -1),
                (lower, negative, minus_order, minus_groups, np.conj(minus), False, 1),
                (upper, positive, minus_order, minus_groups, minus, True, -1),
                (lower, negative, plus_order, plus_groups, np.conj(plus), True, 1))
    blocks = []
    for below, transfer, col_order, col_groups, load, conjugate, sign in branches:
        for read, rows in row_groups.items():
            mode = (sign * read) % n_sl
            cols = col_groups.get(mode)
            if cols is None:
                continue
            left = below[rows] * transfer[:, read, mode][None, :, None]       # (R, n, K)
            left = np.transpose(left, (0, 2, 1)).reshape(-1, m + 1)
            right = load[:, cols, :].reshape(m + 1, -1)
            blocks.append((row_order[rows], col_order[cols], left @ right, conjugate))
    return blocks


def _groups(keys: np.ndarray):
    """The order that sorts ``keys`` (stable) and, per value, its slice of that order."""
    order = np.argsort(keys, kind="stable")
    values, starts = np.unique(keys[order], return_index=True)
    ends = np.append(starts[1:], keys.size)
    return order, {int(v): slice(int(a), int(b)) for v, a, b in zip(values, starts, ends)}


def apply_blocks(system, blocks, forces: np.ndarray) -> np.ndarray:
    """C's force part by its blocks: delta's harmonics (K, l) [m] under P (K, l) [N]."""
    k_w, lmax = forces.shape
    rail = np.zeros((lmax, k_w), dtype=complex)
    by_harmonic = forces.T                                                # (l, K)
    for rows, cols, matrix, conjugate in blocks:
        load = by_harmonic[cols].ravel()
        rail[rows] += (matrix @ (np.conj(load) if conjugate else load)).reshape(-1, k_w)
    rail = rail - (system.between_wheels @ by_harmonic[..., None])[..., 0]
    return rail.T - wheels_under(system, forces)


def blocks_diagonal(system, blocks) -> np.ndarray:
    """C's p -> p blocks (l, 2K, 2K) real, [Re, Im] x wheels, read off the class blocks."""
    lmax, k_w = system.grid.size, system.between_wheels.shape[1]
    with_u = np.zeros((lmax, k_w, k_w), dtype=complex)
    with_conj = np.zeros_like(with_u)
    for rows, cols, matrix, conjugate in blocks:
        common, at_row, at_col = np.intersect1d(rows, cols, return_indices=True)
        entries = matrix.reshape(rows.size, k_w, cols.size, k_w)[at_row, :, at_col, :]
        (with_conj if conjugate else with_u)[common] += entries
    own = system.between_wheels + system.wheel_receptance
    by_re, by_im = with_u + with_conj - own, 1j * (with_u - with_conj - own)
    return np.concatenate([np.concatenate([by_re.real, by_im.real], axis=2),
                           np.concatenate([by_re.imag, by_im.imag], axis=2)], axis=1)
