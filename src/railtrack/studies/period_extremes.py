"""Extremes over a period of a batch of solutions, for `railtrack.studies.sweep`.

Each member's sleeper displacement w, rail-seat load (eq. 5) and foundation
force are sampled on `extremes_grid` points a period by an inverse FFT of
their harmonics, and the largest and smallest sample of each is refined by
the parabola through it and its two neighbours.
"""

from __future__ import annotations

import numpy as np

from ..equations.rail_field import seat_load_coefficients
from ..solvers.time_histories import periodic_peak

__all__ = ["GRID", "extremes_grid", "period_extremes"]

GRID = 256
"""Fewest samples per period at which the extremes are read, each refined by a parabola;
more for m > 31, so that the highest harmonic has at least 8 samples a period."""


def extremes_grid(harmonics: int) -> int:
    """Samples per period for m harmonics: `GRID`, or the power of two >= 8 (m + 1)."""
    return max(GRID, 1 << int(np.ceil(np.log2(8 * (harmonics + 1)))))



def period_extremes(system, coefficients: np.ndarray, size: int) -> dict:
    """Extremes over a period of w, the rail-seat load and the foundation force.

    Parameters
    ----------
    system : HarmonicSystem
        The batched system of the members (`railtrack.equations.harmonic_balance`).
    coefficients : ndarray, shape (B, m+1)
        One-sided c_0..c_m of each member [m].
    size : int
        B.

    Returns
    -------
    dict of str to ndarray, shape (B,)
        ``lowest``, ``highest`` [m]; ``seat_load_peak``, ``seat_load_lowest``,
        ``foundation_force_peak``, ``foundation_force_lowest`` [N], compression
        positive: the extremes fields of `railtrack.Sweep`.
    """
    m = system.harmonics
    grid = extremes_grid(m)
    # omega is (m+1,) unless the passage is swept: seat_load_coefficients is
    # elementwise, so it evaluates the rail's factors once per harmonic, not
    # once per member and harmonic, and broadcasts them over the batch.
    omega = system.omega
    spectrum = np.zeros((3, size, grid // 2 + 1), dtype=complex)
    spectrum[0, :, : m + 1] = coefficients * grid
    spectrum[1, :, : m + 1] = 1j * omega * coefficients * grid
    spectrum[2, :, : m + 1] = seat_load_coefficients(system.passage, omega, coefficients) * grid
    w, rate, seat = np.fft.irfft(spectrum, grid, axis=-1)
    with np.errstate(invalid="ignore", over="ignore"):
        force = -np.broadcast_to(np.asarray(system.foundation.force(w, rate), dtype=float), w.shape)
    return dict(lowest=periodic_peak(w, -1.0), highest=periodic_peak(w, 1.0),
                seat_load_peak=periodic_peak(seat, 1.0),
                seat_load_lowest=periodic_peak(seat, -1.0),
                foundation_force_peak=periodic_peak(force, 1.0),
                foundation_force_lowest=periodic_peak(force, -1.0))
