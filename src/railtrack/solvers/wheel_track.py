"""C, the compression under the wheels per unit wheel force, applied matrix-free (issue 28).

Used by Newton's method with wheels (`railtrack.solvers.wheel_newton`):
the wheel's own receptance 1/(m_w omega_p^2) less the track's receptance
under the moving wheels, the linear map P -> W P -> c -> reactions -> rail
under the wheels, each sleeper's law replaced by its mean tangent (its
dynamic stiffness ``support``).  Nothing of size (K (2l+1))^2 is formed: per
sleeper harmonic n the N x N block ``A_n = K1_n + K2_n diag(support_n)`` is
inverted once per support (`track_operator`) and every product C x is then
W P (per Floquet mode), m + 1 products with A_n^{-1}, and the FFT over the
sleepers of `railtrack.equations.wheel_harmonic_balance.rail_under_wheels`:
O((m+1) (N^2 + l K)) a product.

Newton's step is found by GMRES (`railtrack.solvers.wheel_krylov`) with a
preconditioner diagonal in the wheel harmonics: C's blocks p -> p (between
the K wheels), exact, from the transfer through the sleepers read at the
one Floquet mode and Fourier index that harmonic p loads and reads.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.wheel_harmonic_balance import rail_under_wheels, wheel_loads, wheels_under
from .wheel_blocks import apply_blocks, blocks_diagonal, class_blocks
from .wheel_sleepers import varying_response, varying_sleepers

__all__ = ["TrackOperator", "track_operator", "track_response", "sleeper_response"]


class TrackOperator(NamedTuple):
    """The track under the wheels for one support; see `track_operator`."""

    support: np.ndarray     # (m+1, N) [N/m], -M omega^2 + k + i omega eta
    inverse: np.ndarray     # (m+1, N, N) A_n^{-1} [m/N]
    diagonal: np.ndarray    # (l, 2K, 2K) real C restricted to p -> p, [Re, Im] x wheels [m/N]
    varying: object         # VaryingSleepers or None (`railtrack.solvers.wheel_sleepers`)
    blocks: object          # C's class blocks or None (`railtrack.solvers.wheel_blocks`)


def track_operator(system, cell, support: np.ndarray, diagonal: np.ndarray | None = None,
                   tangent=None) -> TrackOperator:
    """A_n^{-1} and C's blocks p -> p for each sleeper's dynamic stiffness ``support``.

    ``support`` (m+1, N) [N/m] is -M omega^2 + k + i omega eta, the laws' mean tangents.
    ``diagonal``: blocks to keep from an earlier support (they only precondition:
    a nonlinear sleeper's mean tangent moving between Newton steps barely changes
    them), instead of building them again.  ``tangent``: the laws' tangent along
    the orbit (`railtrack.equations.cell_harmonic_balance.tangent_spectrum`), for
    the exact linearisation of the sleepers whose tangent varies
    (`railtrack.solvers.wheel_sleepers`); without it, their mean tangent alone.
    """
    ops, lmax, m = system.ops, system.grid.size, system.ops.omega.size - 1
    blocks = ops.first + ops.second * support[:, None, :]
    blocks[0] = blocks[0].real
    inverse = np.linalg.inv(blocks)
    varying = None if tangent is None else varying_sleepers(ops, inverse, tangent, support)
    blocks = None
    if diagonal is None or varying is None:
        positive, negative = _transfer(system, support, inverse, m)
        if varying is None and lmax:
            blocks = class_blocks(system, positive, negative)
        if diagonal is None:
            diagonal = _diagonal(system, positive, negative, lmax, m) if blocks is None \
                else blocks_diagonal(system, blocks)
    return TrackOperator(support, inverse, diagonal, varying, blocks)


def _transfer(system, support, inverse, m):
    """Q[n, r, s] for n = 0..m and, through conj, n = 0..-m (n = 0 counted once)."""
    reaction = -support[:, :, None] * (inverse @ system.mode_basis)       # (m+1, N_j, N_s)
    v_l = system.sleeper_phase
    positive = np.fft.fft(v_l[m:, :, None] * reaction, axis=1)             # (m+1, r, s)
    negative = np.fft.fft(v_l[m::-1, :, None] * np.conj(reaction), axis=1)
    negative[0] = 0.0
    return positive, negative


def _diagonal(system, positive, negative, lmax, m):
    """C's p -> p blocks: harmonic p loads Floquet mode s(+-p), the rail reads index r_p.

    With ``Q[n, r, s] = DFT_j(e^{i omega_n x_j/v} (-support_j) (A_n^{-1} basis_s)_j)[r]``,
    the coefficient of u = P_{k',p} in delta_{k,p} is
    ``sum_n under[p, n, k] Q[n, r_p, s(p)] factor[n, p, k']`` over n = -m..m
    (n < 0 through conj), and likewise for conj(u) through s(-p).
    """
    k_w = system.between_wheels.shape[1]
    if lmax == 0:
        return np.zeros((0, 2 * k_w, 2 * k_w))
    reads = system.mode_of_wheel
    s_plus, s_minus = system.load_mode[:lmax], system.load_mode[lmax:]
    factor = system.load_gap[..., None] * system.sleeper_shift[:, None] * system.wheel_phase
    plus, minus = factor[:, :lmax], factor[:, lmax:]                       # (m+1, l, K)
    under = (system.under_weight[..., None] * system.harmonic_phase
             * np.conj(system.wheel_phase[:lmax, None]))                   # (l, 2m+1, K)
    upper, lower = under[:, m:], under[:, m::-1]

    def through(under, transfer, modes, factor):
        # sum_n under[l, n, k] Q[n, l] factor[n, l, j] as l batched (K x n) @ (n x K)
        # products: the three-operand einsum looped naively (0.1 s a level at m = 458)
        weighted = under * transfer[:, reads, modes].T[:, :, None]          # (l, n, K)
        return np.swapaxes(weighted, 1, 2) @ np.swapaxes(factor, 0, 1)     # (l, K, K)

    with_u = through(upper, positive, s_plus, plus) + through(lower, negative, s_minus,
                                                              np.conj(minus))
    with_conj = through(upper, positive, s_minus, minus) + through(lower, negative, s_plus,
                                                                   np.conj(plus))
    own = system.between_wheels + system.wheel_receptance
    by_re, by_im = with_u + with_conj - own, 1j * (with_u - with_conj - own)
    return np.concatenate([np.concatenate([by_re.real, by_im.real], axis=2),
                           np.concatenate([by_re.imag, by_im.imag], axis=2)], axis=1)


def sleeper_response(system, operator: TrackOperator, forces: np.ndarray):
    """dc = J_c^{-1} W P, the sleepers' harmonics (m+1, N) under wheel forces (K, l) [m].

    Also returns the varying sleepers' force variation (m+1, q), or None.
    """
    response = (operator.inverse @ wheel_loads(system, forces)[..., None])[..., 0]
    response[0] = response[0].real
    if operator.varying is None:
        return response, None
    return varying_response(operator.varying, response)


def track_response(system, operator: TrackOperator, forces: np.ndarray) -> np.ndarray:
    """C's force part: delta's harmonics p = grid (K, l) [m] under P_{k,p} (K, l) [N].

    The rail under the wheel from the sleepers' reactions, less the free
    rail's deflection under the other wheels and the wheel's own mobility.
    """
    if operator.blocks is not None and operator.varying is None:
        return apply_blocks(system, operator.blocks, forces)
    moved, varying = sleeper_response(system, operator, forces)
    pads = operator.support * moved                                        # p = support c
    if varying is not None:
        pads[:, operator.varying.index] += varying                         # ... + E c
    reaction = -np.concatenate([np.conj(pads[:0:-1]), pads], axis=0).T     # (N, 2m+1)
    rail = rail_under_wheels(system, reaction)                             # (l, K)
    rail = rail - (system.between_wheels @ forces.T[..., None])[..., 0]
    return rail.T - wheels_under(system, forces)
