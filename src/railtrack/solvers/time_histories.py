"""Time histories from Fourier coefficients: the series of eq. (12) and the rail's field.

`fourier_series` sums a two-sided set of harmonics at any times;
`rail_field_series` gives the single-sleeper `railtrack.Solution`'s rail
(displacement or curvature) at any (t, x) from the field coefficients of
`railtrack.equations.rail_field`, with one matrix product on a grid of
times and places; `periodic_peak` reads the extreme of a sampled period.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..equations.moment import kink_coefficients
from ..equations.positions import checked_times
from ..equations.rail_field import rail_field_coefficients

__all__ = ["fourier_series", "periodic_peak", "rail_field_series"]


def fourier_series(coefficients: np.ndarray, omega: np.ndarray, t: ArrayLike) -> np.ndarray:
    """Real sum_n c_n exp(i omega_n t) over a two-sided set, eq. (12), for any shape of t."""
    t = checked_times(omega, t)
    phases = np.exp(1j * np.multiply.outer(t, omega))
    return (phases @ coefficients).real


def rail_field_series(solution, t: ArrayLike, x: ArrayLike, which: int) -> np.ndarray:
    """Re sum_n r_n(x) e^{i omega_n t} of a `Solution`'s rail, shape of ``broadcast(t, x)``.

    ``which``: 0 the displacement [m], 1 the curvature less its kinks
    (`railtrack.equations.moment`), 2 the whole curvature [1/m].
    """
    t = checked_times(solution.frequencies, t)
    t, x = np.broadcast_arrays(t, np.asarray(x, dtype=float))
    xs, x_index = np.unique(x, return_inverse=True)
    ts, t_index = np.unique(t, return_inverse=True)
    omega = solution.frequencies
    coefficients = rail_field_coefficients(solution.passage, omega, solution.coefficients, xs)[min(which, 1)]
    if which == 1:
        ei = solution.passage.rail_bending_stiffness
        coefficients = coefficients - kink_coefficients(solution.passage, omega, xs) / ei
    if ts.size * xs.size <= 4 * max(t.size, 1):   # a grid: one matrix product
        table = (np.exp(1j * np.multiply.outer(ts, omega)) @ coefficients.T).real
        return table[t_index.reshape(t.shape), x_index.reshape(x.shape)]
    phases = np.exp(1j * np.multiply.outer(t, omega))
    return np.einsum("...n,...n->...", coefficients[x_index.reshape(x.shape)], phases).real



def periodic_peak(values: np.ndarray, sign: float) -> np.ndarray:
    """sign * the max over the last (periodic) axis of sign * values, refined by a parabola.

    The parabola through the largest sample and its two neighbours (taken
    around the period's ends) places the peak between the samples.

    A unit cosine sampled 16 times a period, its crest between two samples:

    >>> t = np.linspace(0.0, 1.0, 16, endpoint=False)
    >>> w = np.cos(2 * np.pi * (t - 0.03))
    >>> round(float(w.max()), 3), round(float(periodic_peak(w, 1.0)), 3)
    (0.982, 0.999)
    """
    scaled = sign * values
    i = np.argmax(scaled, axis=-1)[..., None]
    n = values.shape[-1]
    left, middle, right = (np.take_along_axis(scaled, (i + k) % n, axis=-1)[..., 0]
                           for k in (-1, 0, 1))
    curvature = left - 2.0 * middle + right
    with np.errstate(divide="ignore", invalid="ignore"):
        offset = np.where(curvature < 0, 0.5 * (left - right) / curvature, 0.0)
    return sign * (middle - 0.25 * (left - right) * offset)
