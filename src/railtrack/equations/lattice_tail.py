"""The near-singular branch of the rail's kernels: the lattice sum over j != 0 with its tail.

Where q^4 - a^4 is small the closed form of the offset lattice sum loses
digits to cancellation (`railtrack.equations.rail_field.difference_kernels`);
there the sum over the wavenumbers kappa_j = (q + 2 pi j) / L, j != 0, is
taken term by term for |j| <= `TERMS`, and the rest in closed form: the
first four terms of each summand's expansion in 1/(2 pi j) are sums of
Bernoulli polynomials (`bernoulli_sum`).
"""

from __future__ import annotations

from math import comb, factorial

import numpy as np

__all__ = ["TERMS", "bernoulli_sum", "lattice_kernels"]

_BERNOULLI = (1.0, -0.5, 1.0 / 6.0, 0.0, -1.0 / 30.0, 0.0, 1.0 / 42.0, 0.0)
TERMS = 128
"""Wavenumbers kept on each side by the near-singular branch."""


def bernoulli_sum(p: int, xi: np.ndarray) -> np.ndarray:
    """sum_{j != 0} e^{-2 pi i j xi} / (2 pi j)^p = -(-i)^p B_p(xi) / p!, 0 <= xi <= 1, p >= 2."""
    poly = sum(comb(p, k) * _BERNOULLI[k] * xi ** (p - k) for k in range(p + 1))
    return -((-1j) ** p) * poly / factorial(p)


def lattice_kernels(q: np.ndarray, a: np.ndarray, xi: np.ndarray):
    """sum_{j != 0} (e^{-2 pi i j xi} - 1) f_j and sum_{j != 0} (q^2 f_j - e^{...} u_j'^2 f_j).

    f_j = 1 / ((q + 2 pi j)^4 - a^4).  The first four terms of the expansion
    of f_j (and of (q + 2 pi j)^2 f_j) in powers of 1/(2 pi j) are summed in
    closed form with Bernoulli polynomials; the rest falls like j^-8 (j^-6)
    and is summed over |j| <= 128.  Shapes (X, W) from q, a (W,) and xi (X,).
    """
    j = np.concatenate([np.arange(-TERMS, 0), np.arange(1, TERMS + 1)]).astype(float)
    u = 2.0 * np.pi * j[:, None]                       # (J, 1)
    f = 1.0 / ((q + u) ** 4 - a**4)                    # (J, W)
    g = (q + u) ** 2 * f
    f_series = [(4, 1.0), (5, -4.0 * q), (6, 10.0 * q**2), (7, -20.0 * q**3)]
    g_series = [(2, 1.0), (3, -2.0 * q), (4, 3.0 * q**2), (5, -4.0 * q**3)]
    # complex, so that the products below are one BLAS call each
    f_rest = (f - sum(c * u ** (-p) for p, c in f_series)).astype(complex)
    g_rest = (g - sum(c * u ** (-p) for p, c in g_series)).astype(complex)
    wave = np.exp(-2j * np.pi * np.multiply.outer(xi, j))   # (X, J)
    xi = xi[:, None]
    zero = np.zeros_like(xi)
    f_all = f_rest.sum(axis=0) + sum(c * bernoulli_sum(p, zero) for p, c in f_series)
    f_wave = wave @ f_rest + sum(c * bernoulli_sum(p, xi) for p, c in f_series)
    g_wave = wave @ g_rest + sum(c * bernoulli_sum(p, xi) for p, c in g_series)
    return f_wave - f_all, q**2 * f_all - g_wave
