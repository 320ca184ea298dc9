"""The sleepers whose tangent varies over the period, in the track under the wheels (issue 28).

With every law replaced by its mean tangent the track under the wheels is
a quasi-Newton model of a nonlinear cell (the hanging sleeper touching part
of the period): 16 Newton steps at m = 135 where Newton needs a few.  The
exact linearisation adds, for the q sleepers whose tangent varies, the
variation E (real (2m+1) x (2m+1) per sleeper: it couples the harmonics),
as the cell's own Newton step does (`railtrack.solvers.cell_step`):
Woodbury's identity solves ``(B + K2 V^T E V) dc = W dP`` with the
mean-tangent blocks' inverse B^{-1} and one real system of size q (2m+1),

    y = B^{-1} W dP,   s = (I + E Wv)^{-1} E V y,   dc = y - B^{-1} K2 V^T s,

``Wv = V B^{-1} K2 V^T``; and s is the varying part of the pads' forces,
``dp = support dc + V^T s``.  The reduced matrix is factorised once per
Newton step.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.linalg import lu_factor, lu_solve

from ..equations.cell_harmonic_balance import (
    cell_force_jacobian,
    pack_harmonics,
    unpack_harmonics,
)
from .cell_step import _real_blocks, _times_harmonic_map, _to_pack

__all__ = ["VaryingSleepers", "varying_sleepers", "varying_response"]


class VaryingSleepers(NamedTuple):
    """The reduced system of the module docstring; see `varying_sleepers`."""

    index: np.ndarray       # (q,) the sleepers whose tangent varies
    through: np.ndarray     # (m+1, N, q) B^{-1} K2 V^T [m/N]
    variation: np.ndarray   # real (q (2m+1),)*2 E in pack_harmonics order [N/m]
    reduced: tuple          # LU factors of I + E Wv


def varying_sleepers(ops, inverse: np.ndarray, tangent, support: np.ndarray):
    """The reduced system for the sleepers whose tangent varies, or None if none does.

    Parameters
    ----------
    ops : CellOperators
    inverse : ndarray, shape (m+1, N, N)
        B_n^{-1}, the mean-tangent blocks' inverse.
    tangent : (ndarray (2, N, 4m+1), ndarray (2, N, S))
        `railtrack.equations.cell_harmonic_balance.tangent_spectrum`'s output.
    support : ndarray, shape (m+1, N)
        The mean tangents' dynamic stiffness [N/m] (its mean part is not in E).
    """
    harmonics, sampled = tangent
    index = np.flatnonzero((np.ptp(sampled[0], axis=-1) > 0) | (np.ptp(sampled[1], axis=-1) > 0))
    if index.size == 0:
        return None
    m = ops.omega.size - 1
    direct, conjugate = cell_force_jacobian(harmonics[0][index], harmonics[1][index], ops.omega)
    diagonal = np.arange(m + 1)
    direct[:, diagonal, diagonal] -= (harmonics[0][index, 2 * m].real[:, None]
                                      + 1j * ops.omega * harmonics[1][index, 2 * m].real[:, None])
    variation = _to_pack(_real_blocks(direct, conjugate))
    through = inverse @ ops.second[:, :, index]
    # E Wv with Wv block-diagonal over the harmonics: O((q (2m+1))^2 q), not the dense
    # product's cube (0.8 GFLOP a Newton step at m = 458 over a hanging sleeper)
    reduced = _times_harmonic_map(variation, through[:, index, :])
    reduced[np.diag_indices_from(reduced)] += 1.0
    return VaryingSleepers(index, through, variation, lu_factor(reduced))


def varying_response(varying: VaryingSleepers, mean_response: np.ndarray):
    """(dc, s): the sleepers' exact response (m+1, N) and the varying pads' forces (m+1, q).

    ``mean_response`` is y = B^{-1} W dP, the response through the mean tangents.
    """
    q = varying.index.size
    forces = unpack_harmonics(lu_solve(varying.reduced, varying.variation
                                       @ pack_harmonics(mean_response[:, varying.index])), q).T
    response = mean_response - np.einsum("nab,nb->na", varying.through, forces)
    response[0] = response[0].real
    return response, forces
