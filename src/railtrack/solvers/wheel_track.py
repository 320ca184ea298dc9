"""C, the compression under the wheels per unit wheel force: the Jacobian's linear part.

Used by Newton's method with wheels (`railtrack.solvers.wheel_newton`):
the wheel's own receptance 1/(m_w omega_p^2) less the track's receptance
under the moving wheels, from the linear map P -> W P -> c -> reactions ->
rail under the wheels, each sleeper's law replaced by its mean tangent.
"""

from __future__ import annotations

import numpy as np

__all__ = ["track_under_wheels"]


def track_under_wheels(system, cell, support: np.ndarray) -> np.ndarray:
    """C: the harmonics of delta per unit wheel force and lift, real (K(2l+1), K(2l+1)) [m/N].

    Per wheel the packing is ``[y or delta_0, Re x_1..l, Im x_1..l]``.
    ``support`` (m+1, N) [N/m] is each sleeper's dynamic stiffness
    -M omega^2 + k + i omega eta (the laws' mean tangents).

    A wheel harmonic p loads one Floquet mode s of sleeper harmonic n, and
    the rail under wheel harmonic p_l reads one discrete Fourier index r_l of
    the reactions, so C is a sum over n of products through
    ``Q[n, s, r] = DFT_j(e^{i omega_n x_j/v} (-support_j) (A_n^{-1} basis_s)_j)[r]``,
    computed once (N x N per harmonic).  For identical sleepers Q is zero
    unless r = -s (mod N): only those blocks are summed.
    """
    ops, lmax, m = system.ops, system.grid.size, system.ops.omega.size - 1
    k_w = system.between_wheels.shape[1]
    v_l = system.sleeper_phase                                             # (2m+1, N)
    solved = np.linalg.solve(ops.first + ops.second * support[:, None, :], system.mode_basis)
    reaction = -support[:, :, None] * solved                               # (m+1, N_j, N_s)
    positive = np.fft.fft(v_l[m:, :, None] * reaction, axis=1)             # (m+1, r, s)
    negative = np.fft.fft(v_l[m::-1, :, None] * np.conj(reaction), axis=1)
    factor = system.load_factor                                            # (m+1, 2l, K)
    plus, minus = factor[:, :lmax], factor[:, lmax:]
    s_plus, s_minus = system.load_mode[:lmax], system.load_mode[lmax:]
    upper = system.under_wheel[:, m:]                                      # (l, m+1, K)
    lower = system.under_wheel[:, m::-1]                                   # n = 0, -1, .. -m
    tail = np.ones(m + 1)
    tail[0] = 0.0                                                          # n = 0 counted once
    # coefficients of u and conj(u) for a force u at +p, conj(u) at -p
    with_u = (_through(upper, positive, s_plus, plus, system.mode_of_wheel)
              + _through(lower, negative * tail[:, None, None], s_minus, np.conj(minus),
                         system.mode_of_wheel))
    with_conj = (_through(upper, positive, s_minus, minus, system.mode_of_wheel)
                 + _through(lower, negative * tail[:, None, None], s_plus, np.conj(plus),
                            system.mode_of_wheel))
    by_re, by_im = with_u + with_conj, 1j * (with_u - with_conj)            # (l, K, l', K')
    own = (system.between_wheels[:, :, :, None] * np.eye(lmax)[:, None, None, :]
           + (system.wheel_mobility[:, None, None, None] * np.eye(k_w)[None, :, :, None]
              * np.eye(lmax)[:, None, None, :]))                           # (l, K, K', l')
    own = np.transpose(own, (0, 1, 3, 2))                                  # (l, K, l', K')
    by_re, by_im = by_re - own, by_im - 1j * own
    size = 2 * lmax + 1
    out = np.zeros((k_w, size, k_w, size))
    out[:, 1:lmax + 1, :, 1:lmax + 1] = np.transpose(by_re.real, (1, 0, 3, 2))
    out[:, lmax + 1:, :, 1:lmax + 1] = np.transpose(by_re.imag, (1, 0, 3, 2))
    out[:, 1:lmax + 1, :, lmax + 1:] = np.transpose(by_im.real, (1, 0, 3, 2))
    out[:, lmax + 1:, :, lmax + 1:] = np.transpose(by_im.imag, (1, 0, 3, 2))
    for k in range(k_w):
        out[k, 0, k, 0] = 1.0
    return out.reshape(k_w * size, k_w * size)


def _through(under, transfer, modes, factor, reads):
    """sum_n under[l, n, k] transfer[n, r_l, s_q] factor[n, q, k'], block by block (r, s)."""
    lmax, k_w = under.shape[0], under.shape[2]
    out = np.zeros((lmax, k_w, factor.shape[1], factor.shape[2]), dtype=complex)
    largest = float(np.max(np.abs(transfer))) if transfer.size else 0.0
    for r in np.unique(reads):
        rows = np.flatnonzero(reads == r)
        for s in np.unique(modes):
            line = transfer[:, r, s]
            if not np.any(np.abs(line) > 1e-13 * largest):
                continue                       # round-off: the blocks identical sleepers skip
            cols = np.flatnonzero(modes == s)
            block = line[:, None, None] * factor[:, cols, :]               # (W, q, K')
            out[np.ix_(rows, np.arange(k_w), cols, np.arange(factor.shape[2]))] = \
                np.tensordot(under[rows], block, axes=([1], [0]))
    return out
