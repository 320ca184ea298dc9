"""The AFT Jacobian of the harmonic-balance residual, eq. (17).

`railtrack.equations.harmonic_balance.residual` evaluates R(c); this module gives its
exact derivative with respect to the 2m + 1 real unknowns
``[Re c_0, Re c_1..m, Im c_1..m]``, for one system or a batch of them.  The
Newton solver, the batched Newton and the continuation use it.
"""

from __future__ import annotations

import numpy as np

from .harmonic_balance import HarmonicSystem, _checked_force, require_jacobian_samples, synthesize

__all__ = ["residual_jacobian", "tangent_harmonics"]


def residual_jacobian(system: HarmonicSystem, coefficients: np.ndarray) -> np.ndarray:
    """Jacobian of `to_real(residual)` with respect to `to_real(c)`, shape (2m+1, 2m+1).

    Linearising g about w(t) gives ``dg = k(t) dw + d(t) dw'`` with the
    foundation's tangent stiffness k and damping d divided by M.  Their
    harmonics K_j, D_j (|j| <= 2m, by the same N-point DFT as the AFT) give

        dG_n / dc_k = K_{n-k} + i omega_k D_{n-k},   n, k = -m..m,

    the exact derivative of eq. (20) as evaluated by AFT.  With
    ``c_{-k} = conj(c_k)`` this becomes a real (2m+1) x (2m+1) matrix; the
    linear part of eq. (17) is diagonal in n.  For a law with a kink the
    one-sided tangent is used, which makes this a generalised (semismooth)
    Jacobian.  Leading axes of `coefficients` are a batch: a stack of
    Jacobians is returned.
    """
    m = system.harmonics
    coefficients = np.asarray(coefficients)
    batch = coefficients.shape[:-1]
    mass = np.asarray(system.sleeper_mass)  # scalar, or (B, 1) for a batch
    stiff, damp = (part / mass for part in tangent_harmonics(system, coefficients))
    omega_k = (np.asarray(system.fundamental) * np.arange(1, m + 1))[..., None, :]
    # dG_n/dc_k = K_{n-k} + i omega_k D_{n-k}; c_{-k} = conj(c_k) brings in K_{n+k} - i omega_k D_{n+k}.
    # Both are Toeplitz in (n, k): windows of the harmonics, taken as views, not gathered.
    k_below, k_above, d_below, d_above = (part for values in (stiff, damp) for part in _lagged(values, m))
    by_real = np.empty(batch + (m + 1, m + 1), dtype=complex)
    by_real[..., 0] = stiff[..., 2 * m: 3 * m + 1]                  # dG_n/dc_0 = K_n
    by_real[..., 1:] = k_below + k_above + 1j * omega_k * (d_below - d_above)
    by_imag = 1j * (k_below - k_above) - omega_k * (d_below + d_above)
    index = np.arange(m + 1)
    operator = np.broadcast_to(system.operator, batch + (m + 1,))
    by_real[..., index, index] += operator
    by_imag[..., index[1:], index[1:] - 1] += 1j * operator[..., 1:]
    jacobian = np.empty(batch + (2 * m + 1, 2 * m + 1))
    jacobian[..., : m + 1, : m + 1] = by_real.real
    jacobian[..., : m + 1, m + 1 :] = by_imag.real
    jacobian[..., m + 1 :, : m + 1] = by_real[..., 1:, :].imag
    jacobian[..., m + 1 :, m + 1 :] = by_imag[..., 1:, :].imag
    return jacobian


def tangent_harmonics(system: HarmonicSystem,
                      coefficients: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Harmonics K_l, C_l (l = -2m..2m) of df/dw [N/m] and df/dw' [N s/m] along w(t).

    The foundation's tangent stiffness and damping along the periodic
    response of coefficients c_0..c_m, by the AFT's N-point DFT (N > 4m),
    stored at index l + 2m.  They make the linearised foundation force
    ``sum_l (K_l + i omega C_l)`` of the Jacobian and of Hill's matrix
    (`railtrack.equations.hill`).  Leading axes of `coefficients` are a batch.
    """
    m = system.harmonics
    require_jacobian_samples(system.samples, m)
    coefficients = np.asarray(coefficients)
    w, v = synthesize(system, coefficients)
    _checked_force(system, w, v)
    stiffness, damping = system.foundation.tangent(w, v)
    tangent = np.empty((2,) + coefficients.shape[:-1] + (system.samples,))
    tangent[0], tangent[1] = stiffness, damping
    spectrum = np.fft.rfft(tangent, axis=-1)[..., : 2 * m + 1] / system.samples
    full = np.concatenate([np.conj(spectrum[..., :0:-1]), spectrum], axis=-1)
    return full[0], full[1]


def _lagged(harmonics: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """X_{n-k} and X_{n+k} for n = 0..m, k = 1..m, from X_j stored at j + 2m (views)."""
    windows = np.lib.stride_tricks.sliding_window_view(harmonics, m, axis=-1)
    return windows[..., m : 2 * m + 1, ::-1], windows[..., 2 * m + 1 : 3 * m + 2, :]
