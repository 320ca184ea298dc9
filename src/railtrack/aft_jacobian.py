"""The AFT Jacobian of the harmonic-balance residual, eq. (17).

`railtrack.harmonic_balance.residual` evaluates R(c); this module gives its
exact derivative with respect to the 2m + 1 real unknowns
``[Re c_0, Re c_1..m, Im c_1..m]``, for one system or a batch of them.  The
Newton solver, the batched Newton and the continuation use it.
"""

from __future__ import annotations

import numpy as np

from .harmonic_balance import HarmonicSystem, _checked_force, require_jacobian_samples, synthesize

__all__ = ["residual_jacobian"]


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
    require_jacobian_samples(system.samples, m)
    coefficients = np.asarray(coefficients)
    batch = coefficients.shape[:-1]
    w, v = synthesize(system, coefficients)
    _checked_force(system, w, v)
    stiffness, damping = system.foundation.tangent(w, v)
    tangent = np.empty((2,) + batch + (system.samples,))
    tangent[0], tangent[1] = stiffness, damping
    mass = np.asarray(system.sleeper_mass)
    spectrum = np.fft.rfft(tangent, axis=-1)[..., : 2 * m + 1] / (system.samples * mass)
    # Real and imaginary parts of the two-sided harmonics j = -2m..2m, stored
    # at index j + 2m (X_{-j} = conj X_j), with the batch axes last.  The real
    # blocks are then written in place by operations whose inner loops run
    # along the batch (long and contiguous), not along one member's m
    # columns; the complex form, whose real and imaginary parts are taken
    # afterwards, moves twice the memory.  Every entry is the same
    # floating-point expression as in the complex form, bit for bit.
    spectrum = np.moveaxis(spectrum, -1, 1)
    real = np.concatenate([spectrum.real[:, :0:-1], spectrum.real], axis=1)
    imag = np.concatenate([-spectrum.imag[:, :0:-1], spectrum.imag], axis=1)
    # dG_n/dc_k = K_{n-k} + i omega_k D_{n-k}; c_{-k} = conj(c_k) brings in K_{n+k} - i omega_k D_{n+k}.
    # Both are Toeplitz/Hankel in (n, k): windows of the harmonics, views, not gathered.
    (kr_below, kr_above), (dr_below, dr_above) = _lagged(real[0], m), _lagged(real[1], m)
    (ki_below, ki_above), (di_below, di_above) = _lagged(imag[0], m), _lagged(imag[1], m)
    omega_k = np.asarray(system.fundamental) * np.arange(1, m + 1)
    omega_k = np.moveaxis(np.broadcast_to(omega_k, batch + (m,)), -1, 0)       # (m, *batch)
    jacobian = np.empty((2 * m + 1, 2 * m + 1) + batch)
    scratch = np.empty((m + 1, m) + batch)
    lower = scratch[1:]                   # rows n = 1..m, for the Im R_n equations
    # Re R_n by Re c_k: Re K_n for k = 0, then Re(K_{n-k} + K_{n+k}) - omega_k Im(D_{n-k} - D_{n+k})
    jacobian[: m + 1, 0] = real[0, 2 * m : 3 * m + 1]
    block = jacobian[: m + 1, 1 : m + 1]
    np.add(kr_below, kr_above, out=block)
    np.subtract(di_below, di_above, out=scratch)
    block -= np.multiply(omega_k, scratch, out=scratch)
    # Re R_n by Im c_k: -Im(K_{n-k} - K_{n+k}) - omega_k Re(D_{n-k} + D_{n+k})
    block = jacobian[: m + 1, m + 1 :]
    np.subtract(ki_above, ki_below, out=block)
    np.add(dr_below, dr_above, out=scratch)
    block -= np.multiply(omega_k, scratch, out=scratch)
    # Im R_n (n >= 1) by Re c_k: Im K_n for k = 0, then Im(K_{n-k} + K_{n+k}) + omega_k Re(D_{n-k} - D_{n+k})
    jacobian[m + 1 :, 0] = imag[0, 2 * m + 1 : 3 * m + 1]
    block = jacobian[m + 1 :, 1 : m + 1]
    np.add(ki_below[1:], ki_above[1:], out=block)
    np.subtract(dr_below[1:], dr_above[1:], out=lower)
    block += np.multiply(omega_k, lower, out=lower)
    # Im R_n (n >= 1) by Im c_k: Re(K_{n-k} - K_{n+k}) - omega_k Im(D_{n-k} + D_{n+k})
    block = jacobian[m + 1 :, m + 1 :]
    np.subtract(kr_below[1:], kr_above[1:], out=block)
    np.add(di_below[1:], di_above[1:], out=lower)
    block -= np.multiply(omega_k, lower, out=lower)
    # back to (*batch, 2m+1, 2m+1), as a view: np.linalg.solve copies each matrix anyway
    jacobian = np.moveaxis(jacobian, (0, 1), (-2, -1))
    # The linear part, operator_n c_n: on the diagonal of the Re/Re and Im/Im
    # blocks, and (as i operator_n) at Re R_n by Im c_n and Im R_n by Re c_n.
    _add_operator(jacobian, system.operator, m)
    return jacobian


def _add_operator(jacobian: np.ndarray, operator: np.ndarray, m: int) -> None:
    """Add d(operator_n c_n) / d to_real(c) to a stack of real Jacobians, in place."""
    n = np.arange(1, m + 1)
    jacobian[..., 0, 0] += operator.real[..., 0]
    jacobian[..., n, n] += operator.real[..., 1:]
    jacobian[..., n, m + n] -= operator.imag[..., 1:]
    jacobian[..., m + n, n] += operator.imag[..., 1:]
    jacobian[..., m + n, m + n] += operator.real[..., 1:]


def _lagged(harmonics: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """X_{n-k} and X_{n+k}, shape (m+1, m, *batch), n = 0..m, k = 1..m, from X_j stored at j + 2m.

    `harmonics` has shape (4m+1, *batch); the results are views.
    """
    windows = np.moveaxis(np.lib.stride_tricks.sliding_window_view(harmonics, m, axis=0), -1, 1)
    return windows[m : 2 * m + 1, ::-1], windows[2 * m + 1 : 3 * m + 2]
