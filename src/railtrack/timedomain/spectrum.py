"""The spectrum of a long time-domain record: is the response periodic?

A response periodic over the wagon's period T = H / v has spectral lines at
the multiples of v / H only.  A record of P whole periods, transformed
without a window, puts a periodic response exactly on every P-th line; what
lies between those lines (the interharmonic fraction) measures how far the
response is from periodic: a quasi-periodic response (a second, unrelated
frequency) or a chaotic one has lines there, a dying transient little.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Spectrum", "record_spectrum"]


@dataclass(frozen=True)
class Spectrum:
    """One-sided amplitude spectrum of a record spanning whole periods T = H / v.

    Attributes
    ----------
    frequencies : ndarray
        f_k = k / (P T) for the P periods recorded [Hz].
    amplitudes : ndarray
        Amplitude of each line [m] (2 |X_k| / N; the mean at k = 0 is |X_0| / N).
    harmonic : ndarray of bool
        Lines at a multiple of v / H: k divisible by P.  A periodic record has
        nothing else, for it spans whole periods (no leakage, no window).
    interharmonic_fraction : float
        RMS of the lines between the multiples of v / H over the RMS of all
        lines but the mean [-]: 0 for a periodic record, of order 1 for a
        quasi-periodic one.
    """

    frequencies: np.ndarray
    amplitudes: np.ndarray
    harmonic: np.ndarray
    interharmonic_fraction: float


def record_spectrum(record, period: float, steps_per_period: int) -> Spectrum:
    """Spectrum of a long record, sampled `steps_per_period` times a period, over whole periods.

    Parameters
    ----------
    record : array_like, shape (N,)
        E.g. sleeper 0 over many periods, ``result.sleeper_history.ravel()`` [m].
    period : float
        T = H / v of the wagon [s]; the record's trailing whole periods are used.
    steps_per_period : int
        Samples per period.

    Examples
    --------
    >>> t = np.arange(4 * 100) / 100                    # 4 periods of T = 1 s
    >>> s = record_spectrum(np.cos(2 * np.pi * t) + 0.1 * np.cos(2 * np.pi * 1.5 * t), 1.0, 100)
    >>> round(s.interharmonic_fraction, 3), s.frequencies[s.amplitudes > 0.05].tolist()
    (0.1, [1.0, 1.5])
    """
    record = np.asarray(record, dtype=float)
    periods = record.size // steps_per_period
    if periods < 2:
        raise ValueError(f"record_spectrum needs at least 2 periods of {steps_per_period} samples; "
                         f"got {record.size} samples")
    record = record[record.size - periods * steps_per_period:]
    lines = np.fft.rfft(record) / record.size
    amplitudes = np.abs(lines) * np.where(np.arange(lines.size) == 0, 1.0, 2.0)
    k = np.arange(lines.size)
    harmonic = k % periods == 0
    power = amplitudes[1:] ** 2
    total = float(np.sum(power))
    fraction = float(np.sqrt(np.sum(power[~harmonic[1:]]) / total)) if total > 0 else 0.0
    return Spectrum(k / (periods * period), amplitudes, harmonic, fraction)
