"""The cell's per-harmonic operators kept in its Floquet modes (issue 28).

`railtrack.equations.cell_harmonic_balance` writes the cell's equations as
``R_n = K1_n c_n + K2_n p_n - g_n`` with ``K1_n = F diag(den) F^H`` and
``K2_n = K1_n diag(1/A) + F diag(num) F^H`` (A_j the pads).  F is the cell's
Floquet basis, ``F[j, s] = e^{-i phi_s j} / sqrt(N)``, ``phi_s = theta + 2 pi s/N``,
``theta = omega_n L / v``, and it is a discrete Fourier transform with a twist:

    F^H x = sqrt(N) ifft(e^{i theta j} x_j),     F z = e^{-i theta j} fft(z) / sqrt(N),

O(N log N) per harmonic instead of a dense N x N product.  A matrix
``F diag(x) F^H`` is theta-circulant, ``[j, j'] = e^{-i theta (j - j')} h[(j - j') mod N]``
with ``h = fft(x) / N``: its dense form (when a caller wants it) costs O(N^2)
per harmonic, not the O(N^3) of the product.  `CellOperators` keeps the modal
factors and builds K1_n and K2_n densely only when they are read.
"""

from __future__ import annotations

import dataclasses
from functools import cached_property

import numpy as np

from ..model.passage import Passage
from .cell_receptance_modes import cell_receptance_modes
from .load import axle_factor
from .receptance import receptance_factors

__all__ = ["CellOperators", "cell_operators"]


def _twisted(twist: np.ndarray, values: np.ndarray, columns=None) -> np.ndarray:
    """Dense ``F diag(values) F^H`` (W, N, N), or its `columns` only (W, N, r).

    `twist` is ``e^{i theta j}`` (W, N).
    """
    n = values.shape[-1]
    h = np.fft.fft(values, axis=-1) / n
    j = np.arange(n)
    columns = j if columns is None else np.asarray(columns)
    return (np.conj(twist)[:, :, None] * h[:, (j[:, None] - columns[None, :]) % n]
            * twist[:, None, columns])


@dataclasses.dataclass(frozen=True, eq=False)
class CellOperators:
    """The matrices of ``R_n = K1_n c_n + K2_n p_n - g_n`` by their Floquet factors.

    Attributes
    ----------
    omega : ndarray, shape (W,)
        omega_n >= 0 [rad/s].
    load : ndarray, shape (W, N)
        g_n [N], real at omega = 0.
    denominator, numerator : ndarray, shape (W, N)
        den_s [N/m] and num_s [-] of each Floquet mode (`cell_receptance_modes`).
    pad : ndarray, shape (W, N)
        ``A_j = k1_j + i omega_n eta1_j`` [N/m].
    theta : ndarray, shape (W,)
        ``omega_n L / v`` [rad], the phase from one sleeper to the next.

    ``first`` (K1_n) and ``second`` (K2_n), shape (W, N, N), are built when
    first read (O(W N^2)); `apply` and `railtrack.equations.cell_blocks` work
    in the modes without them.
    """

    omega: np.ndarray
    load: np.ndarray
    denominator: np.ndarray
    numerator: np.ndarray
    pad: np.ndarray
    theta: np.ndarray

    def _replace(self, **changes) -> CellOperators:
        """A copy with `changes` (as a NamedTuple's); a new load keeps the dense matrices."""
        new = dataclasses.replace(self, **changes)
        if set(changes) <= {"load"}:
            for name in ("first", "second"):
                if name in self.__dict__:
                    new.__dict__[name] = self.__dict__[name]
        return new

    def take(self, rows) -> CellOperators:
        """The operators at the harmonics `rows` (a slice, indices or a mask)."""
        return CellOperators(*(getattr(self, f.name)[rows] for f in dataclasses.fields(self)))

    @cached_property
    def twist(self) -> np.ndarray:
        """``e^{i theta j}`` (W, N), the phase of sleeper j in the modes."""
        return np.exp(1j * self.theta[:, None] * np.arange(self.pad.shape[1]))

    @property
    def rest(self) -> np.ndarray:
        """Where omega_n = 0 (the rows kept real)."""
        return self.omega == 0.0

    @cached_property
    def first(self) -> np.ndarray:
        """K1_n [N/m], (W, N, N), real at omega = 0."""
        out = _twisted(self.twist, self.denominator)
        out[self.rest] = out[self.rest].real
        return out

    @cached_property
    def second(self) -> np.ndarray:
        """K2_n [-], (W, N, N), real at omega = 0."""
        out = self.first / self.pad[:, None, :] + _twisted(self.twist, self.numerator)
        out[self.rest] = out[self.rest].real
        return out

    def columns(self, which) -> tuple[np.ndarray, np.ndarray]:
        """Columns `which` (r,) of K1_n and K2_n, each (W, N, r), in O(W N r)."""
        which = np.asarray(which, dtype=int)
        first = _twisted(self.twist, self.denominator, which)
        second = first / self.pad[:, None, which] + _twisted(self.twist, self.numerator, which)
        return first, second

    def to_modes(self, x: np.ndarray) -> np.ndarray:
        """``F^H x`` for x (W, N) or (W, N, k), by FFT over the sleepers."""
        phase = self.twist.reshape(self.twist.shape + (1,) * (x.ndim - 2))
        return np.sqrt(x.shape[1]) * np.fft.ifft(phase * x, axis=1)

    def from_modes(self, z: np.ndarray) -> np.ndarray:
        """``F z`` for z (W, N) or (W, N, k), by FFT over the modes."""
        phase = np.conj(self.twist).reshape(self.twist.shape + (1,) * (z.ndim - 2))
        return phase * np.fft.fft(z, axis=1) / np.sqrt(z.shape[1])

    def modal(self, values: np.ndarray, z: np.ndarray) -> np.ndarray:
        """``values * z`` for per-mode values (W, N) and z (W, N) or (W, N, k)."""
        return values.reshape(values.shape + (1,) * (z.ndim - 2)) * z

    def apply(self, c: np.ndarray, p: np.ndarray, real_at_rest: bool = True) -> np.ndarray:
        """``K1_n c_n + K2_n p_n`` for c, p (W, N) or (W, N, k), in O(W N log N).

        ``= F [den (F^H (c + p / A)) + num (F^H p)]``; real at omega = 0 unless
        `real_at_rest` is False (then as the matrices would give it for a complex c, p).
        """
        pad = self.pad.reshape(self.pad.shape + (1,) * (np.ndim(p) - 2))
        out = self.from_modes(self.modal(self.denominator, self.to_modes(c + p / pad))
                              + self.modal(self.numerator, self.to_modes(p)))
        if real_at_rest:
            out[self.rest] = out[self.rest].real
        return out


def cell_operators(passage: Passage, pad_stiffness, pad_damping, omega, *,
                   sleeper_weight=None, rail_weight: float = 0.0) -> CellOperators:
    """K1_n, K2_n and g_n of the cell's equations, for omega_n >= 0, by their Floquet factors.

    Parameters
    ----------
    passage : Passage
        Scalar-valued rail (EI, rho S), spacing L and train.
    pad_stiffness, pad_damping : array_like, shape (N,)
        k1_j > 0 [N/m] and eta1_j >= 0 [N s/m] of the cell's pads.
    omega : array_like, shape (W,)
        omega_n >= 0 [rad/s].
    sleeper_weight : array_like, shape (N,), optional
        M_j g [N], the sleepers' self-weight (default none, as the paper).
    rail_weight : float
        rho S g [N/m], the rail's self-weight (default 0).

    Self-weight is static: it enters g_0 alone.  The rail's weight is a
    uniform load, as the train's mean is (``sum_k Q_k / H`` per metre), so
    it adds ``rho S g H`` to sum_k Q_k in b_0; the sleepers' weights act on
    the sleepers, ``p_{j,0} + M_j g``, so g_0 loses ``K2_0 (M g)``.

    Returns
    -------
    CellOperators
        K1 and K2 real at omega = 0 (their round-off imaginary part is
        removed there), g real there.  Building it costs O(W N log N); the
        dense K1, K2 cost O(W N^2) when read.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> ops = cell_operators(passage, [1.8e8] * 3, [0.0] * 3, np.array([0.0, 15.7]))
    >>> ops.first.shape, bool(np.all(ops.load[0].imag == 0))
    ((2, 3, 3), True)
    >>> # the statics: sum of the n = 0 rows of K2 times p is the train's weight per sleeper
    >>> q = float(passage.static_load_per_sleeper)
    >>> p = np.full(3, -q)
    >>> bool(np.allclose(ops.second[0] @ p, ops.load[0], rtol=1e-12))
    True
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    k1 = np.asarray(pad_stiffness, dtype=float)
    n = k1.size
    modes = cell_receptance_modes(passage, omega, n)                      # (W, N) each
    theta = omega * passage.sleeper_spacing / passage.speed
    pad = k1 + 1j * omega[:, None] * np.asarray(pad_damping, dtype=float)            # (W, N)
    gap = receptance_factors(passage, omega).gap
    b = (-4.0 * np.sqrt(n) * axle_factor(passage, omega) * gap
         * passage.sleeper_spacing / passage.wagon_length)
    load = np.zeros((omega.size, n), dtype=complex)
    ops = CellOperators(omega, load, modes.denominator, modes.numerator, pad, theta)
    load[:] = b[:, None] * np.conj(ops.twist) / np.sqrt(n)
    rest = ops.rest
    if np.any(rest) and (rail_weight or sleeper_weight is not None):
        total = float(passage.train.wagon_load)
        weight = float(rail_weight) * passage.wagon_length
        load[rest] *= (total + weight) / total
        if sleeper_weight is not None:
            weights = np.broadcast_to(np.asarray(sleeper_weight, dtype=float), load.shape)
            load[rest] -= ops.apply(np.zeros(load.shape, dtype=complex), weights)[rest].real
    load[rest] = load[rest].real
    return ops
