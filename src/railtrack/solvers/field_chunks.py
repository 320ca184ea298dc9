"""A rail field's Fourier series at many (t, x), in chunks whose memory is bounded.

``Re sum_n r_n(x) e^{i omega_n t}`` needs the coefficients r_n(x) at each
distinct x (a W-long complex row each) and a phase per (t, n).  Evaluated in
one piece this takes memory in proportion to the number of points times W
(1.9 GB for 1,024 points on a wheel's dip before issue 27).  Here the
distinct positions are taken `CHUNK_ENTRIES` / W at a time, and so are the
points read at them: the largest array holds about `CHUNK_ENTRIES` complex
numbers whatever the number of points.  Where the points are a grid of few
distinct t and x, each block of the table is one matrix product, as
`railtrack.Solution.rail_displacement` does.
"""

from __future__ import annotations

from typing import Callable

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["CHUNK_ENTRIES", "chunk_length", "fourier_field"]

CHUNK_ENTRIES = 1 << 18
"""Complex entries per block of (positions or times) x harmonics: 4 MB an array."""


def chunk_length(harmonics: int, entries: int = CHUNK_ENTRIES) -> int:
    """Positions (or times) per block for `harmonics` coefficients each, at least 1."""
    return max(1, int(entries) // max(1, int(harmonics)))


def fourier_field(t: ArrayLike, x: ArrayLike, coefficients_at: Callable[[np.ndarray], np.ndarray],
                  omega: np.ndarray, *, entries: int = CHUNK_ENTRIES) -> np.ndarray:
    """``Re sum_n r_n(x) e^{i omega_n t}`` at t and x broadcast together.

    Parameters
    ----------
    t, x : array_like
        Times [s] and positions [m], broadcast together.
    coefficients_at : callable
        Maps distinct positions, shape (X,), to r_n(x), shape (X, W), with
        any one-sided weights (2 for n > 0) already applied.
    omega : ndarray, shape (W,)
        omega_n [rad/s].
    entries : int
        Complex entries per block (`CHUNK_ENTRIES`); the result does not
        depend on it beyond round-off.

    Returns
    -------
    ndarray
        Real, shaped as ``np.broadcast(t, x)``.
    """
    t, x = np.broadcast_arrays(np.asarray(t, dtype=float), np.asarray(x, dtype=float))
    shape = t.shape
    flat_t, flat_x = t.ravel(), x.ravel()
    out = np.empty(flat_t.size)
    if out.size == 0:
        return out.reshape(shape)
    omega = np.asarray(omega, dtype=float)
    xs, x_index = np.unique(flat_x, return_inverse=True)
    ts, t_index = np.unique(flat_t, return_inverse=True)
    x_index, t_index = x_index.ravel(), t_index.ravel()
    grid = ts.size * xs.size <= 4 * flat_t.size
    step = chunk_length(omega.size, entries)
    order = np.argsort(x_index, kind="stable")
    bounds = np.searchsorted(x_index[order], np.arange(0, xs.size + step, step))
    for block, first in enumerate(range(0, xs.size, step)):
        coefficients = coefficients_at(xs[first:first + step])
        points = order[bounds[block]:bounds[block + 1]]
        if grid:
            for start in range(0, ts.size, step):
                inner = points[(t_index[points] >= start) & (t_index[points] < start + step)]
                if inner.size:
                    phases = np.exp(1j * np.multiply.outer(ts[start:start + step], omega))
                    table = (phases @ coefficients.T).real
                    out[inner] = table[t_index[inner] - start, x_index[inner] - first]
        else:
            for start in range(0, points.size, step):
                inner = points[start:start + step]
                phases = np.exp(1j * np.multiply.outer(flat_t[inner], omega))
                out[inner] = np.einsum("pw,pw->p", coefficients[x_index[inner] - first],
                                       phases).real
    return out.reshape(shape)
