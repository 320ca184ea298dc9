"""The Newton step of a cell, by the cell's structure (issue 19, section 5).

The Jacobian of the cell's residual (`railtrack.equations.cell_harmonic_balance`),

    dR_n = (K1_n + K2_n M s_n^2) dc_n + K2_n dF_n,

couples the N sleepers within a harmonic (through the rail, K1_n and K2_n) and
the harmonics within a sleeper (through its law, dF).  Split each sleeper's
tangent into its mean over the period and the rest:
``dF_{j,n} = (Kbar_j + i omega_n Cbar_j) dc_{j,n} + E_j dc_j``.  The mean part
joins the rail's blocks, ``B_n = K1_n + K2_n diag(M s_n^2 + Kbar + i omega_n Cbar)``,
one N x N complex matrix per harmonic, solved in the cell's Floquet modes
where few sleepers differ (`railtrack.equations.cell_blocks`).  The rest E is non-zero only for
sleepers whose tangent varies over the period (the nonlinear ones, q of them);
for a linear law, or a gap law that is never touched, it is exactly zero.
Woodbury's identity then solves ``(B + K2 V^T E V) dx = -R`` with m + 1
solves of N x N and one real system of size q (2m + 1):

    y = -B^{-1} R,   s = (I + E W)^{-1} E V y,   dx = y - B^{-1} K2 V^T s,

``W = V B^{-1} K2 V^T`` (the nonlinear sleepers' displacement per unit force
through rail, pads and every mean tangent).  One hanging sleeper in 30 at
m = 40: a system of 81 unknowns instead of 2430.  The step is the exact
Newton step: the same numbers as the dense Jacobian's, up to round-off.
"""

from __future__ import annotations

import numpy as np

from ..equations.cell_blocks import solve_blocks
from ..equations.cell_harmonic_balance import (
    CellOperators,
    cell_force_jacobian,
    pack_harmonics,
    tangent_spectrum,
    unpack_harmonics,
)

__all__ = ["newton_step", "varying_sleepers", "DIRECT_LIMIT"]

DIRECT_LIMIT = 1500
"""Unknowns of the reduced system up to which it is solved directly (a dense LU).

Beyond, GMRES on the reduced operator ``I + E W``: every sleeper nonlinear
(a cell on the cubic law) makes it as large as the whole system, whose
dense solve costs (N (2m+1))^3 / 3 and (N (2m+1))^2 floats (30 sleepers at
m = 90: 16 s and 240 MB a step); its operator is applied in
O((m+1) q^2 + q (2m+1)^2) and is the identity plus the tangent's variation
seen through the mean-tangent track, so that GMRES needs few iterations
unless a law's stiffness swings far from its mean.
"""
GMRES_TOL = 1e-13
"""Relative residual to which GMRES solves the reduced system (the step is then exact
to far below Newton's own tolerance)."""


def _unpack(x: np.ndarray, q: int) -> np.ndarray:
    """`unpack_harmonics`, harmonic-major: (m+1, q)."""
    return unpack_harmonics(x, q).T


def varying_sleepers(samples_stiffness: np.ndarray, samples_damping: np.ndarray) -> np.ndarray:
    """Indices of the sleepers whose tangent (N, S) varies over the period."""
    varies = (np.ptp(samples_stiffness, axis=-1) > 0) | (np.ptp(samples_damping, axis=-1) > 0)
    return np.flatnonzero(varies)


def _real_blocks(direct: np.ndarray, conjugate: np.ndarray) -> np.ndarray:
    """Per sleeper, the real (2m+1) x (2m+1) matrix of dF = D dc + C conj(dc), packed
    ``[Re n = 0..m, Im n = 1..m]`` in rows and columns; shapes (q, m+1, m+1) -> (q, 2m+1, 2m+1)."""
    on_real = direct + conjugate
    on_imag = 1j * (direct - conjugate)[:, :, 1:]
    top = np.concatenate([on_real.real, on_imag.real], axis=2)
    bottom = np.concatenate([on_real[:, 1:].imag, on_imag[:, 1:].imag], axis=2)
    return np.concatenate([top, bottom], axis=1)


def _to_pack(blocks: np.ndarray) -> np.ndarray:
    """Block-diagonal (q sleepers) real matrix in `pack_harmonics` order (part, n, sleeper)."""
    q, size, _ = blocks.shape
    out = np.zeros((size, q, size, q))
    out[:, np.arange(q), :, np.arange(q)] = blocks
    return out.reshape(size * q, size * q)


def _times_harmonic_map(left: np.ndarray, matrices: np.ndarray) -> np.ndarray:
    """``left @ H`` with H the real packed matrix of ``z_n -> T_n z_n`` (complex T (m+1, q, q),
    T_0 real), in O(rows (m+1) q^2): H is block-diagonal over the harmonics, each block
    the real 2 x 2 form of T_n, so that the dense product's O(rows ((2m+1) q)^2) is not needed.
    """
    m, q = matrices.shape[0] - 1, matrices.shape[1]
    rows = left.shape[0]
    on_real = left[:, q:q * (m + 1)].reshape(rows, m, q)
    on_imag = left[:, q * (m + 1):].reshape(rows, m, q)
    re, im = matrices[1:].real, matrices[1:].imag
    out = np.empty_like(left)
    out[:, :q] = left[:, :q] @ matrices[0].real
    out[:, q:q * (m + 1)] = (np.einsum("rna,nab->rnb", on_real, re)
                             + np.einsum("rna,nab->rnb", on_imag, im)).reshape(rows, m * q)
    out[:, q * (m + 1):] = (np.einsum("rna,nab->rnb", on_imag, re)
                            - np.einsum("rna,nab->rnb", on_real, im)).reshape(rows, m * q)
    return out


def newton_step(cell, coefficients: np.ndarray, residual: np.ndarray, ops: CellOperators,
                samples: int, *, direct_limit: int = DIRECT_LIMIT) -> np.ndarray:
    """The exact Newton step dc (N, m+1) for the residual R (m+1, N) at c (N, m+1) [m].

    Parameters as `railtrack.equations.cell_harmonic_balance.cell_jacobian`;
    `residual` is `cell_residual`'s first output at `coefficients`.  The
    reduced system is solved directly up to `direct_limit` unknowns, beyond
    that by GMRES (`_iterative`).

    Raises
    ------
    numpy.linalg.LinAlgError
        If a block or the reduced system is singular.
    """
    m = ops.omega.size - 1
    tangent, samples_tangent = tangent_spectrum(cell, coefficients, ops, samples)
    mean_stiffness, mean_damping = tangent[0][:, 2 * m].real, tangent[1][:, 2 * m].real
    support = (-cell.sleeper_mass * ops.omega[:, None] ** 2 + mean_stiffness
               + 1j * ops.omega[:, None] * mean_damping)                        # (m+1, N)
    y = -solve_blocks(ops, support, residual)
    y[0] = y[0].real
    varying = varying_sleepers(*samples_tangent)
    if varying.size == 0:
        return y.T
    direct, conjugate = cell_force_jacobian(tangent[0][varying], tangent[1][varying], ops.omega)
    diagonal = np.arange(m + 1)
    direct[:, diagonal, diagonal] -= (mean_stiffness[varying, None]
                                      + 1j * ops.omega * mean_damping[varying, None])
    per_sleeper = _real_blocks(direct, conjugate)                             # (q, 2m+1, 2m+1)
    through_rail = solve_blocks(ops, support, ops.columns(varying)[1])          # (m+1, N, q)
    q = varying.size
    if q * (2 * m + 1) <= direct_limit:
        rest = _to_pack(per_sleeper)
        reduced = _times_harmonic_map(rest, through_rail[:, varying, :])
        reduced[np.diag_indices_from(reduced)] += 1.0
        forces = _unpack(np.linalg.solve(reduced, rest @ pack_harmonics(y[:, varying])), q)
    else:
        forces = _unpack(_iterative(per_sleeper, through_rail[:, varying, :],
                                    pack_harmonics(y[:, varying]), q), q)
    correction = np.einsum("nab,nb->na", through_rail, forces)
    step = y - correction
    step[0] = step[0].real
    return step.T


def _iterative(per_sleeper: np.ndarray, response: np.ndarray, target: np.ndarray, q: int):
    """s of ``(I + E W) s = E target`` by GMRES, matrix-free; dense if GMRES fails.

    `per_sleeper` holds E's real blocks (q, 2m+1, 2m+1), `response` W's
    complex blocks per harmonic (m+1, q, q); vectors in `pack_harmonics`
    order, whose reshape to (2m+1, q) has each sleeper's packed harmonics as
    a column.
    """
    from scipy.sparse.linalg import LinearOperator, gmres

    size = per_sleeper.shape[1]

    def tangent_part(x):
        return np.einsum("jab,bj->aj", per_sleeper, x.reshape(size, q)).ravel()

    def through_rail(x):
        return pack_harmonics(np.einsum("nab,nb->na", response, _unpack(x, q)))

    operator = LinearOperator((size * q, size * q), dtype=float,
                              matvec=lambda x: x + tangent_part(through_rail(x)))
    rhs = tangent_part(target)
    solution, info = gmres(operator, rhs, rtol=GMRES_TOL, atol=0.0, restart=60, maxiter=20)
    if info != 0:
        dense = np.eye(size * q) + _times_harmonic_map(_to_pack(per_sleeper), response)
        solution = np.linalg.solve(dense, _to_pack(per_sleeper) @ target)
    return solution
