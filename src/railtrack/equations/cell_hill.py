"""Hill's matrix of a cell of N differing sleepers: the linearised equations of the cell.

A periodic solution of a cell (`railtrack.equations.cell_harmonic_balance`)
repeats every N sleepers, Lambda = N L: sleeper j + pN moves as sleeper j
delayed by p Lambda / v.  A small disturbance of it has the Floquet–Bloch form

    dy_{j + pN}(t) = e^{lambda t} e^{i theta p} sum_k P_{j,k} e^{i k Omega (t - p Lambda / v)},

with the Floquet exponent lambda, the Bloch phase theta per cell and
Omega = 2 pi v / H.  Harmonic k is the complex frequency s_k = lambda + i k Omega
with the phase Q_k = k Omega Lambda / v - theta from one cell to the next, and
the rail answers it with the cell's receptance matrix (`cell_receptance`)
continued to that s and Q.  In the cell's Floquet modes
``F_{jr} = e^{-i phi_r j} / sqrt(N)``, ``phi_r = (Q + 2 pi r) / N``, it is
diagonal, and its eigenvalue r is eq. (3) at s and the phase phi_r per
sleeper, ``num_r / den_r`` with the entire factors of
`railtrack.equations.hill.complex_receptance`.  As in the harmonic balance
of the cell the rail and pad equation ``c + (A^{-1} + eta) p = 0`` is
multiplied by ``K1 = F diag(den) F^H``, so that nothing is infinite:

    K1(s, Q) dc_k + K2(s, Q) dp_k = 0,   K2 = K1 diag(1/A) + F diag(num) F^H,
    dp_k = M s_k^2 dc_k + sum_j (K_{k-j} + s_j C_{k-j}) dc_j,

with A_j = k1_j + eta1_j s and K_l, C_l the harmonics of each sleeper's
tangent df_j/dw, df_j/dw' along its orbit.  The disturbance exists where the
matrix of these equations, Hill's matrix of the cell, is singular.  It is K2
times Hill's matrix with the rail condensed (`railtrack.equations.hill`), so
it has the same zeros and eigenvectors; for N = 1 its entry is
``K2 (D(s, q) + K + s C)`` exactly.  At lambda = 0, theta = 0 it is the
Jacobian of the cell's harmonic balance.

Unknowns are ordered harmonic-major: index (k + m) N + j for harmonic k and
sleeper j.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .hill import _receptance_parts

__all__ = ["cell_rail_stiffness", "cell_tangent_toeplitz", "cell_hill_matrix",
           "cell_hill_derivative", "cell_bloch_phases"]


def cell_rail_stiffness(passage: Passage, pad_stiffness: ArrayLike, pad_damping: ArrayLike,
                        s: ArrayLike, q: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """K1(s, Q) [N/m] and K2(s, Q) [-] of the module docstring, at complex s and real phase Q.

    Parameters
    ----------
    passage : Passage
        Scalar-valued rail (EI, rho S), spacing L.
    pad_stiffness, pad_damping : array_like, shape (N,)
        k1_j [N/m] and eta1_j [N s/m].
    s : array_like
        Complex frequency [1/s].
    q : array_like
        Phase from one cell to the next [rad], broadcast with `s`.

    Returns
    -------
    first, second : ndarray, shape broadcast(s, q).shape + (N, N)
        At s = i omega, Q = omega N L / v they are K1_n, K2_n of
        `railtrack.equations.cell_harmonic_balance.cell_operators` (up to a
        common factor of each Floquet mode, which leaves K1^{-1} K2 unchanged).
    """
    k1 = np.asarray(pad_stiffness, dtype=float)
    n = k1.size
    s, q = np.broadcast_arrays(np.asarray(s, dtype=complex), np.asarray(q, dtype=float))
    phase = (q[..., None] + 2.0 * np.pi * np.arange(n)) / n                     # (..., N)
    parts, gaps = _receptance_parts(passage, s[..., None], phase)
    denominator = 4.0 * passage.rail_bending_stiffness * gaps / passage.sleeper_spacing**3
    j = np.arange(n)
    basis = np.exp(-1j * j[:, None] * phase[..., None, :]) / np.sqrt(n)        # (..., j, r)
    adjoint = np.conj(np.swapaxes(basis, -1, -2))
    first = (basis * denominator[..., None, :]) @ adjoint
    pad = k1 + s[..., None] * np.asarray(pad_damping, dtype=float)              # (..., N)
    second = first / pad[..., None, :] + (basis * parts[..., None, :]) @ adjoint
    return first, second


def cell_tangent_toeplitz(stiffness: np.ndarray, damping: np.ndarray) -> np.ndarray:
    """Each sleeper's K_{k-j} and C_{k-j}, k, j = -m..m: shape (2, N, 2m+1, 2m+1).

    Parameters
    ----------
    stiffness, damping : ndarray, shape (N, 4m+1)
        K_l [N/m] and C_l [N s/m] of each sleeper, l = -2m..2m at index l + 2m
        (`railtrack.equations.cell_harmonic_balance.tangent_spectrum`).
    """
    m = (np.shape(stiffness)[-1] - 1) // 4
    k = np.arange(-m, m + 1)
    lag = (k[:, None] - k[None, :]) + 2 * m
    return np.stack([np.asarray(stiffness)[:, lag], np.asarray(damping)[:, lag]])


def _frequencies(passage: Passage, m: int, n: int, exponent, theta):
    """s_k and Q_k, k = -m..m, broadcast over the exponents and phases: shape (..., 2m+1)."""
    k = np.arange(-m, m + 1)
    omega = passage.fundamental_frequency
    s = np.asarray(exponent, dtype=complex)[..., None] + 1j * omega * k
    q = k * omega * n * passage.sleeper_spacing / passage.speed - np.asarray(theta)[..., None]
    shape = np.broadcast_shapes(s.shape, q.shape)
    return np.broadcast_to(s, shape), np.broadcast_to(q, shape)


def cell_hill_matrix(passage: Passage, cell, toeplitz: np.ndarray, exponent: ArrayLike,
                     theta: ArrayLike) -> np.ndarray:
    """Hill's matrix of a cell at Floquet exponent lambda and Bloch phase theta per cell [N/m].

    Parameters
    ----------
    passage : Passage
        Scalar-valued rail, spacing and train.
    cell : SleeperCell-like
        ``sleeper_mass``, ``pad_stiffness``, ``pad_damping``, each (N,).
    toeplitz : ndarray, shape (2, N, 2m+1, 2m+1)
        `cell_tangent_toeplitz`.
    exponent : array_like
        lambda [1/s], complex.
    theta : array_like
        Bloch phase per cell [rad], broadcast with `exponent`.

    Returns
    -------
    ndarray, shape broadcast(exponent, theta).shape + (N (2m+1), N (2m+1))
        Harmonic-major (module docstring).
    """
    n, size = toeplitz.shape[1], toeplitz.shape[-1]
    s, q = _frequencies(passage, (size - 1) // 2, n, exponent, theta)
    first, second = cell_rail_stiffness(passage, cell.pad_stiffness, cell.pad_damping, s, q)
    # coupling[..., b, k, l] = K_{b, k-l} + s_l C_{b, k-l}: sleeper b's tangent on harmonic l
    coupling = toeplitz[0] + s[..., None, None, :] * toeplitz[1]
    matrix = np.einsum("...kab,...bkl->...kalb", second, coupling)
    inertia = np.asarray(cell.sleeper_mass, dtype=float) * s[..., None] ** 2    # (..., K, N)
    block = first + second * inertia[..., None, :]
    for k in range(size):
        matrix[..., k, :, k, :] += block[..., k, :, :]
    return matrix.reshape(matrix.shape[:-4] + (size * n, size * n))


def cell_hill_derivative(passage: Passage, cell, toeplitz: np.ndarray, exponent: ArrayLike,
                         theta: ArrayLike, vector: np.ndarray, step: float = 1e-6) -> np.ndarray:
    """dH/dlambda times vectors [N s/m]: the tangent's C exactly, K1' and K2' by central differences.

    `exponent` and `theta` of shape (r,) and `vector` of shape (r, N (2m+1))
    give r products.  K1 and K2 are analytic in s, so the difference of width
    `step` (relative to 1 + |s_k|) has an error of order step^2.
    """
    n, size = toeplitz.shape[1], toeplitz.shape[-1]
    s, q = _frequencies(passage, (size - 1) // 2, n, exponent, theta)
    h = step * (1.0 + np.abs(s))
    ends = [cell_rail_stiffness(passage, cell.pad_stiffness, cell.pad_damping, s + d * h, q)
            for d in (1.0, -1.0)]
    first, second = cell_rail_stiffness(passage, cell.pad_stiffness, cell.pad_damping, s, q)
    slope_first, slope_second = ((ends[0][i] - ends[1][i]) / (2.0 * h[..., None, None])
                                 for i in range(2))
    mass = np.asarray(cell.sleeper_mass, dtype=float)
    v = np.asarray(vector).reshape(vector.shape[:-1] + (size, n))               # (r, K, N)
    coupled = np.einsum("bkl,...lb->...kb", toeplitz[0], v) \
        + np.einsum("bkl,...l,...lb->...kb", toeplitz[1], s, v)
    damped = np.einsum("bkl,...lb->...kb", toeplitz[1], v)
    inertia = mass * s[..., None] ** 2 * v
    out = (np.einsum("...kab,...kb->...ka", slope_first, v)
           + np.einsum("...kab,...kb->...ka", slope_second, inertia + coupled)
           + np.einsum("...kab,...kb->...ka", second, 2.0 * mass * s[..., None] * v + damped))
    return out.reshape(vector.shape)


def cell_bloch_phases(passage: Passage, sleepers: int, theta: float = 0.0) -> np.ndarray:
    """The phases per cell theta + 2 pi j / b, j = 0..b-1, that one Hill matrix of the cell stands for [rad].

    The shift lambda -> lambda + i Omega of an exponent shifts its phase per
    cell by 2 pi N L / H; with H / L = N_s sleepers per wagon these shifts
    close after b = N_s / gcd(N, N_s) steps (b = N_s / N when N divides N_s,
    and 1 for a cell as long as the wagon).  H / L must be an integer.
    """
    per_wagon = float(passage.wagon_length) / float(passage.sleeper_spacing)
    count = int(round(per_wagon))
    if count < 1 or abs(per_wagon - count) > 1e-9 * max(1.0, per_wagon):
        raise ValueError(
            "Floquet multipliers need a whole number of sleepers per wagon, H/L an integer; "
            f"got H/L = {per_wagon!r} (H = {float(passage.wagon_length)!r} m, "
            f"L = {float(passage.sleeper_spacing)!r} m)")
    b = count // int(np.gcd(count, int(sleepers)))
    return np.mod(theta + 2.0 * np.pi * np.arange(b) / b, 2.0 * np.pi)
