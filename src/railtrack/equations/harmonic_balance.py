"""Section 3: the harmonic-balance equations (17)–(20) and their Jacobian.

Truncated to m harmonics (eq. 19), the sleeper's equation (15) becomes, for
n = 0..m,

    R_n(c) = (omega_0^2 + i beta omega_n - omega_n^2 - P_n) c_n + G_n(c) + F_n = 0,   (17)

where G_n is harmonic n of g(w, w') = f(w, w') / M (eq. 20).  G_n is
evaluated by alternating frequency/time (AFT): w and w' are synthesised on
a uniform grid of N samples over one period by an inverse FFT, f is
evaluated pointwise, and an FFT returns its harmonics.

This module only evaluates R (its Jacobian is in `railtrack.equations.aft_jacobian`,
re-exported here); `railtrack.solvers.fixed_point` and `railtrack.solvers.newton` drive them
to zero.  Since w is real, c_{-n} = conj(c_n):
only n = 0..m are stored ("one-sided" arrays), and the Jacobian is taken
with respect to the 2m + 1 real unknowns ``[Re c_0, Re c_1..m, Im c_1..m]``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.foundations import Foundation, as_foundation
from .sleeper import coupling_and_transfer, sleeper_operator
from ..model.passage import Passage
from .load import load_coefficients

__all__ = [
    "NonFiniteForceError",
    "HarmonicSystem",
    "harmonic_system",
    "default_samples",
    "synthesize",
    "nonlinear_coefficients",
    "residual",
    "residual_norm",
    "require_jacobian_samples",
    "to_real",
    "from_real",
    "two_sided",
]


class NonFiniteForceError(ValueError):
    """The foundation law returned NaN or inf at some sample of the AFT.

    Attributes
    ----------
    displacement : float
        The w [m] at which it happened; a huge value means the iterate had
        already diverged, a moderate one that the law itself is at fault.
    """

    def __init__(self, message: str, displacement: float):
        super().__init__(message)
        self.displacement = displacement


def default_samples(harmonics: int) -> int:
    """Number N of time samples per period used by the AFT.

    The smallest power of two >= 16 (m + 1), at least 64.  A polynomial law
    of degree p has harmonics up to p m, which alias onto |n| <= m only if
    N <= (p + 1) m, so N > 4m is exact for the cubic law of eq. (25).  A
    law with a kink (eq. 24) has harmonics decaying like n^-2, so the
    aliasing error of harmonic n <= m is of order (m / N)^2 relative to the
    harmonic itself; N = 16 (m + 1) keeps it below 1/256 of the truncation
    error of dropping harmonics above m.
    """
    return max(64, 1 << int(np.ceil(np.log2(16 * (harmonics + 1)))))


@dataclass(frozen=True, eq=False)
class HarmonicSystem:
    """Everything eq. (17) needs for one track, foundation and truncation.

    Attributes
    ----------
    passage : Passage
    foundation : Foundation
    harmonics : int
        m, the highest harmonic kept (eq. 19).
    samples : int
        N, time samples per period for the AFT.
    omega : ndarray, shape (m+1,)
        omega_n, n = 0..m [rad/s].
    coupling : ndarray, shape (m+1,)
        P_n of eq. (16) [1/s^2].
    load : ndarray, shape (m+1,)
        F_n of eq. (16) [m/s^2].
    operator : ndarray, shape (m+1,)
        omega_0^2 + i beta omega_n - omega_n^2 - P_n [1/s^2].
    """

    passage: Passage
    foundation: Foundation
    harmonics: int
    samples: int
    omega: np.ndarray
    coupling: np.ndarray
    load: np.ndarray
    operator: np.ndarray

    @property
    def sleeper_mass(self) -> float:
        return self.passage.sleeper_mass

    @property
    def fundamental(self) -> float:
        """omega_1 = 2 pi v / H [rad/s]."""
        return self.passage.fundamental_frequency

    def load_norm(self) -> float:
        """Two-sided norm of F_n, the scale of the residual [m/s^2]."""
        return float(_two_sided_norm(self.load))


def harmonic_system(
    passage: Passage, foundation, harmonics: int, samples: int | None = None
) -> HarmonicSystem:
    """Precompute the coefficients of eq. (17) for n = 0..m.

    Parameters
    ----------
    passage : Passage
        Scalar-valued track.
    foundation : Foundation or callable
        The law f(w, w'); a callable ``f(w, v)`` is wrapped.
    harmonics : int
        m >= 1.
    samples : int, optional
        AFT samples per period, > 2m for the residual; the Jacobian
        (`railtrack.equations.aft_jacobian.residual_jacobian`, used by Newton) needs > 4m.  Default
        `default_samples`.

    Raises
    ------
    ValueError
        If `harmonics` or `samples` is out of range.
    """
    if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) or harmonics < 1:
        raise ValueError(f"harmonics must be an integer >= 1; got {harmonics!r}")
    harmonics = int(harmonics)
    if samples is None:
        samples = default_samples(harmonics)
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples <= 2 * harmonics:
        raise ValueError(
            f"samples must be an integer > 2 * harmonics = {2 * harmonics}; got {samples!r}"
        )
    omega = passage.fundamental_frequency * np.arange(harmonics + 1)
    coupling, transfer = coupling_and_transfer(passage, omega)
    return HarmonicSystem(
        passage=passage,
        foundation=as_foundation(foundation),
        harmonics=harmonics,
        samples=int(samples),
        omega=omega,
        coupling=coupling,
        load=load_coefficients(passage, omega, transfer),
        operator=sleeper_operator(passage, omega) - coupling,
    )


def require_jacobian_samples(samples: int, harmonics: int) -> None:
    """Raise ``ValueError`` unless N > 4m, the rule for the AFT Jacobian.

    The Jacobian needs the foundation tangent's harmonics up to 2m, which an
    N-point DFT holds only for N > 4m; that is also the rule for an exact
    AFT of the cubic law (see `default_samples`).
    """
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples <= 4 * harmonics:
        raise ValueError(
            f"samples must be an integer > 4 * harmonics = {4 * harmonics} (the AFT Jacobian "
            f"needs the foundation tangent's harmonics up to 2m); got {samples!r}"
        )


def synthesize(system: HarmonicSystem, coefficients: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """w(t_j) and w'(t_j) on t_j = j T / N, j = 0..N-1, from c_0..c_m (eqs. 18, 19).

    Leading axes of `coefficients` are a batch (`railtrack.solvers.batch`): the
    series is synthesised along the last axis.
    """
    coefficients = np.asarray(coefficients)
    spectrum = np.zeros((2,) + coefficients.shape[:-1] + (system.samples // 2 + 1,), dtype=complex)
    spectrum[0, ..., : system.harmonics + 1] = coefficients * system.samples
    spectrum[1, ..., : system.harmonics + 1] = spectrum[0, ..., : system.harmonics + 1] * 1j * system.omega
    w, v = np.fft.irfft(spectrum, system.samples, axis=-1)
    return w, v


def _checked_force(system: HarmonicSystem, w: np.ndarray, v: np.ndarray,
                   strict: bool = True) -> np.ndarray:
    force = np.asarray(system.foundation.force(w, v), dtype=float)
    if force.shape != w.shape:
        force = np.broadcast_to(force, w.shape)
    if strict and not np.all(np.isfinite(force)):
        bad = int(np.flatnonzero(~np.isfinite(force))[0])
        raise NonFiniteForceError(
            f"the foundation law returned a non-finite force {force[bad]!r} at "
            f"w = {w[bad]!r} m, w' = {v[bad]!r} m/s",
            float(w[bad]),
        )
    return force


def nonlinear_coefficients(system: HarmonicSystem, coefficients: np.ndarray,
                           strict: bool = True) -> np.ndarray:
    """G_n = (1/T) int g(w, w') e^{-i omega_n t} dt for n = 0..m by AFT, eq. (20) [m/s^2].

    Parameters
    ----------
    system : HarmonicSystem
    coefficients : ndarray, shape (m+1,)
        c_0..c_m [m].

    strict : bool
        Raise `NonFiniteForceError` where the law is not finite (default);
        False lets NaN through, for a batch to judge member by member.

    Returns
    -------
    ndarray, shape (m+1,)
        The harmonics of f(w, w') / M, exact up to aliasing (see `default_samples`).
    """
    w, v = synthesize(system, coefficients)
    force = _checked_force(system, w, v, strict)
    spectrum = np.fft.rfft(force, axis=-1)[..., : system.harmonics + 1]
    return spectrum / (system.samples * system.sleeper_mass)


def residual(system: HarmonicSystem, coefficients: np.ndarray, strict: bool = True) -> np.ndarray:
    """R_n(c) of eq. (17) for n = 0..m [m/s^2]; zero at a solution.

    Leading axes of `coefficients` are a batch, matching a batched system.
    """
    coefficients = np.asarray(coefficients, dtype=complex)
    return (
        system.operator * coefficients
        + nonlinear_coefficients(system, coefficients, strict)
        + system.load
    )


def _two_sided_norm(values: np.ndarray) -> np.ndarray:
    values = np.asarray(values)
    return np.sqrt(np.abs(values[..., 0]) ** 2 + 2 * np.sum(np.abs(values[..., 1:]) ** 2, axis=-1))


def residual_norm(system: HarmonicSystem, values: np.ndarray) -> float:
    """Two-sided norm of R_n relative to that of F_n (the relative residual).

    For a batch, an array of one relative residual per member.
    """
    relative = _two_sided_norm(values) / _two_sided_norm(system.load)
    return float(relative) if np.ndim(relative) == 0 else relative


def to_real(coefficients: np.ndarray) -> np.ndarray:
    """Pack c_0..c_m into ``[Re c_0, Re c_1..m, Im c_1..m]`` (along the last axis)."""
    coefficients = np.asarray(coefficients, dtype=complex)
    return np.concatenate([coefficients.real, coefficients[..., 1:].imag], axis=-1)


def from_real(x: np.ndarray) -> np.ndarray:
    """Inverse of `to_real`."""
    x = np.asarray(x)
    m = (x.shape[-1] - 1) // 2
    coefficients = np.array(x[..., : m + 1], dtype=complex)
    coefficients[..., 1:] += 1j * x[..., m + 1 :]
    return coefficients


def two_sided(coefficients: np.ndarray) -> np.ndarray:
    """c_{-m}..c_m from c_0..c_m, using c_{-n} = conj(c_n) (along the last axis)."""
    coefficients = np.asarray(coefficients)
    return np.concatenate([np.conj(coefficients[..., :0:-1]), coefficients], axis=-1)

