"""Harmonic balance of a cell of N sleepers with their own (nonlinear) laws (issue 19, third block).

Sleeper j of the cell moves as ``w_j(t) = sum_n c_{j,n} e^{i omega_n t}``.
For harmonic n (s = i omega_n) write ``p_{j,n} = M_j s^2 c_{j,n} + F_{j,n}``,
with F_{j,n} harmonic n of the foundation force f_j(w_j, w_j') [N] (by AFT),
the force the sleeper passes to its inertia and its foundation.  The rail and
pad equations of `railtrack.equations.cell_linear` then read

    c + (A^{-1} + eta) p = m,        A_j = k1_j + s eta1_j.

In the Floquet modes (``eta = F diag(num/den) F^H``, F unitary) with row s
multiplied by den_s, and mapped back to sleeper coordinates by F, this is

    R_n = K1_n c_n + K2_n p_n - g_n = 0,
    K1_n = F diag(den) F^H,   K2_n = K1_n diag(1/A) + F diag(num) F^H,
    g_n = b_n F[:, 0],        b_n = -4 sqrt(N) (sum_k Q_k e^{-i omega_n d_k/v}) gap L / H,

every entry finite, also at n = 0 where den_0 = 0 (the rigid translation of
the rail).  At n = 0 the phases 2 pi s/N pair up, den_s = den_{N-s},
num_s = num_{N-s}, so K1_0, K2_0 and g_0 are real: the n = 0 rows are N real
equations (their row sum is the statics, ``num_0 sum_j p_j = N b_0/sqrt(N)``: the
foundations carry the train's mean weight).  For a linear law,
``p = (M s^2 + B) c``, ``F^H R_n = 0`` is exactly the scaled mode system of
`railtrack.equations.cell_linear`.  R_n is in newtons.

The operators are kept by their Floquet factors (`railtrack.equations.cell_modes`):
R_n costs FFTs over the sleepers, O(N log N) a harmonic, and K1_n, K2_n are
built densely only where a caller reads them.
`cell_residual` evaluates R_n with F by AFT on ``samples`` points per period
(each law called once per group of sleepers sharing it), `cell_jacobian` its
exact derivative in the real packing ``[Re c_0, Re c_1..m, Im c_1..m]`` (N (2m+1)
unknowns and equations; `pack_harmonics`).  On the AFT grid a delay jL/v is
a shift of whole samples only if samples L/(v T) is an integer: otherwise the
aliasing of a kinked law differs slightly from sleeper to sleeper (about 1e-5
relative for eq. 24 at m = 15), and N identical sleepers are today's N = 1
answer delayed only up to that.
"""

from __future__ import annotations

import numpy as np

from .cell_modes import CellOperators, cell_operators
from .harmonic_balance import NonFiniteForceError

__all__ = ["CellOperators", "cell_operators", "cell_force_jacobian", "cell_residual",
           "cell_jacobian", "tangent_spectrum", "pack_harmonics", "unpack_harmonics",
           "two_sided_norm"]


def cell_force_jacobian(stiffness: np.ndarray, damping: np.ndarray, omega: np.ndarray):
    """dF_{j,n}/dc_{j,k} and dF_{j,n}/d conj(c_{j,k}) from the tangent's harmonics.

    Linearising f_j about w_j(t) gives ``dF_n = sum_{|k| <= m} (K_{n-k} + i omega_k
    C_{n-k}) dc_k`` (`railtrack.equations.aft_jacobian`); with
    ``c_{-k} = conj(c_k)`` it splits into a part in dc_k (k = 0..m, the
    whole of the real dc_0) and one in conj(dc_k) (k = 1..m; zero at k = 0).

    Parameters
    ----------
    stiffness, damping : ndarray, shape (N, 4m+1)
        K_l [N/m] and C_l [N s/m], l = -2m..2m at index l + 2m
        (`railtrack.equations.aft_jacobian.tangent_harmonics`).
    omega : ndarray, shape (m+1,)
        omega_k [rad/s].

    Returns
    -------
    direct, conjugate : ndarray, shape (N, m+1, m+1)
        Indexed [j, n, k] [N/m].
    """
    m = omega.size - 1
    index = np.arange(m + 1)
    below = index[:, None] - index[None, :] + 2 * m          # n - k + 2m
    above = index[:, None] + index[None, :] + 2 * m          # n + k + 2m
    direct = stiffness[:, below] + 1j * omega * damping[:, below]
    conjugate = stiffness[:, above] - 1j * omega * damping[:, above]
    conjugate[:, :, 0] = 0.0
    return direct, conjugate


def _by_law(cell):
    """Groups of sleepers sharing one law object, so that each law is called once."""
    groups: dict[int, list[int]] = {}
    for j, law in enumerate(cell.foundations):
        groups.setdefault(id(law), []).append(j)
    return [(cell.foundations[idx[0]], np.array(idx)) for idx in groups.values()]


def _synthesize(coefficients: np.ndarray, omega: np.ndarray, samples: int):
    """w_j(t_i), w_j'(t_i) on t_i = i T/samples from c_{j,0..m}, shapes (N, samples)."""
    m = omega.size - 1
    spectrum = np.zeros((2, coefficients.shape[0], samples // 2 + 1), dtype=complex)
    spectrum[0, :, :m + 1] = coefficients * samples
    spectrum[1, :, :m + 1] = spectrum[0, :, :m + 1] * 1j * omega
    return np.fft.irfft(spectrum, samples, axis=-1)


def _forces(cell, w: np.ndarray, v: np.ndarray, tangent: bool = False):
    """Each sleeper's law on its samples: f [N] (N, S), or (df/dw, df/dw') (2, N, S)."""
    out = np.empty((2,) + w.shape) if tangent else np.empty(w.shape)
    for law, idx in _by_law(cell):
        if tangent:
            stiffness, damping = law.tangent(w[idx], v[idx])
            out[0, idx], out[1, idx] = stiffness, damping
        else:
            out[idx] = np.asarray(law.force(w[idx], v[idx]), dtype=float)
    if not np.all(np.isfinite(out)):
        j, i = np.argwhere((~np.isfinite(out.reshape(-1, *w.shape))).any(0))[0]
        raise NonFiniteForceError(f"the foundation law of sleeper {j} returned a non-finite "
                                  f"{'tangent' if tangent else 'force'} at w = {w[j, i]!r} m, "
                                  f"w' = {v[j, i]!r} m/s", float(w[j, i]))
    return out


def cell_residual(cell, coefficients: np.ndarray, ops: CellOperators, samples: int):
    """R_n of the module docstring [N] and the foundation harmonics F_{j,n} [N], by AFT.

    Parameters
    ----------
    cell : SleeperCell-like
        Has ``sleeper_mass`` (N,) [kg] and ``foundations`` (N laws with
        ``force`` and ``tangent``, `railtrack.model.foundations`).
    coefficients : ndarray, shape (N, m+1)
        c_{j,0..m} [m], c_{j,0} real.
    ops : CellOperators
        From `cell_operators` at omega_n = n omega_1, n = 0..m.
    samples : int
        AFT samples per period, > 2m.

    Returns
    -------
    residual : ndarray, shape (m+1, N)
        R_n [N] (real at n = 0 up to round-off for a real c_{.,0}).
    force : ndarray, shape (N, m+1)
        F_{j,n} [N], negative in compression.

    Raises
    ------
    NonFiniteForceError
        Naming the sleeper whose law returned NaN or inf.
    """
    m = ops.omega.size - 1
    w, v = _synthesize(coefficients, ops.omega, samples)
    force = np.fft.rfft(_forces(cell, w, v), axis=-1)[:, :m + 1] / samples
    p = -cell.sleeper_mass[:, None] * ops.omega**2 * coefficients + force
    return ops.apply(coefficients.T, p.T) - ops.load, force


def tangent_spectrum(cell, coefficients: np.ndarray, ops: CellOperators, samples: int):
    """Each sleeper's tangent (df/dw, df/dw') along its orbit: harmonics and samples.

    Returns
    -------
    harmonics : ndarray, shape (2, N, 4m+1)
        K_l [N/m] and C_l [N s/m], l = -2m..2m at index l + 2m.
    sampled : ndarray, shape (2, N, samples)
        The tangent at the AFT samples.
    """
    m = ops.omega.size - 1
    w, v = _synthesize(coefficients, ops.omega, samples)
    sampled = _forces(cell, w, v, tangent=True)
    spectrum = np.fft.rfft(sampled, axis=-1)[..., :2 * m + 1] / samples
    return np.concatenate([np.conj(spectrum[..., :0:-1]), spectrum], axis=-1), sampled


def cell_jacobian(cell, coefficients: np.ndarray, ops: CellOperators,
                  samples: int) -> np.ndarray:
    """Exact Jacobian of `pack_harmonics(R)` with respect to `pack_harmonics(c.T)` [N/m].

    ``dR_n = (K1_n + K2_n M s_n^2) dc_n + K2_n dF_n``, with dF the AFT
    derivative of each sleeper's law (`cell_force_jacobian`): block-diagonal
    over the sleepers.  R_0 is real for a real c_{.,0}, so its real part alone
    is kept: the matrix is square, N (2m+1).  Arguments as `cell_residual`;
    samples > 4m (the tangent's harmonics up to 2m).  For a law with a kink
    it is a generalised (one-sided or central-difference) Jacobian.
    """
    m, n = ops.omega.size - 1, len(cell.foundations)
    full, _ = tangent_spectrum(cell, coefficients, ops, samples)
    direct, conjugate = cell_force_jacobian(full[0], full[1], ops.omega)
    by_direct = np.einsum("nab,bnk->nakb", ops.second, direct)
    by_conj = np.einsum("nab,bnk->nakb", ops.second, conjugate)
    inertia = -cell.sleeper_mass * ops.omega[:, None] ** 2                   # (m+1, N)
    harmonic = np.arange(m + 1)
    by_direct[harmonic, :, harmonic, :] += ops.first + ops.second * inertia[:, None, :]
    real_part = (by_direct + by_conj).reshape((m + 1) * n, (m + 1) * n)
    imag_part = (1j * (by_direct - by_conj)[:, :, 1:, :]).reshape((m + 1) * n, m * n)
    return np.block([[real_part.real, imag_part.real],
                     [real_part[n:].imag, imag_part[n:].imag]])


def pack_harmonics(values: np.ndarray) -> np.ndarray:
    """One-sided harmonics (m+1, N) -> real ``[Re v_0, Re v_1..m, Im v_1..m]``, n-major."""
    return np.concatenate([values[0].real, values[1:].real.ravel(), values[1:].imag.ravel()])


def unpack_harmonics(x: np.ndarray, n: int) -> np.ndarray:
    """Inverse of `pack_harmonics` for N sleepers, returned sleeper-major, shape (N, m+1)."""
    m = (x.size // n - 1) // 2
    out = np.empty((m + 1, n), dtype=complex)
    out[0] = x[:n]
    out[1:] = (x[n:n + m * n] + 1j * x[n + m * n:]).reshape(m, n)
    return out.T


def two_sided_norm(values: np.ndarray) -> float:
    """Two-sided norm ``sqrt(|v_0|^2 + 2 sum_{n>=1} |v_n|^2)`` of one-sided (m+1, N)."""
    return float(np.sqrt(np.sum(np.abs(values[0]) ** 2) + 2 * np.sum(np.abs(values[1:]) ** 2)))
