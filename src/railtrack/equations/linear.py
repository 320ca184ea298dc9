"""Section 4.1: the analytic solution for a linear foundation, eqs. (22)–(23).

For f = k2 w + eta2 w' the AFT term of eq. (17) is exactly
``(k2 + i eta2 omega_n) c_n / M``, and each harmonic decouples:

    c_n = F_n / (omega_n^2 + P_n - omega_0^2 - i beta omega_n - (k2 + i eta2 omega_n)/M).   (23)

Every function here is elementwise, so a batch of tracks (array-valued
fields with a trailing axis of length one) is solved in one call: that is
the fast path for parameter sweeps.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.foundations import LinearFoundation
from .sleeper import coupling_and_transfer, sleeper_operator
from ..model.passage import Passage
from ..model.track import Track
from ..model.train import Train
from .load import load_coefficients

__all__ = ["analytic_coefficients", "sweep_speeds", "sweep_extremes"]


def analytic_coefficients(
    passage: Passage, foundation: LinearFoundation, harmonics: int
) -> np.ndarray:
    """Sleeper coefficients c_n, n = -m..m, of eq. (23) [m].

    Parameters
    ----------
    passage : Passage
        Scalar or batched (fields of shape ``(..., 1)``).
    foundation : LinearFoundation
        The law of eq. (22).
    harmonics : int
        m >= 1.

    Returns
    -------
    ndarray, shape (..., 2m+1)
        Complex c_n, harmonic axis last.

    Examples
    --------
    >>> from railtrack import LinearFoundation, Passage
    >>> c = analytic_coefficients(Passage.paper(), LinearFoundation.paper(), 15)
    >>> float(c[15].real)          # the mean, -2 Q L / (H k2)
    -0.00025
    """
    if not isinstance(foundation, LinearFoundation):
        raise TypeError(
            "the analytic solution (eq. 23) needs a LinearFoundation; got "
            f"{type(foundation).__name__}; use method='newton' for other laws"
        )
    if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) or harmonics < 1:
        raise ValueError(f"harmonics must be an integer >= 1; got {harmonics!r}")
    omega = passage.harmonic_frequencies(int(harmonics))
    law = (foundation.stiffness + 1j * foundation.damping * omega) / passage.sleeper_mass
    coupling, transfer = coupling_and_transfer(passage, omega)
    denominator = coupling - sleeper_operator(passage, omega) - law
    return load_coefficients(passage, omega, transfer) / denominator


def sweep_speeds(
    track: Track, train: Train, foundation: LinearFoundation, speeds: ArrayLike,
    harmonics: int = 15,
) -> np.ndarray:
    """Eq. (23) for many train speeds at once.

    Parameters
    ----------
    track : Track
    train : Train
        Its own speed is ignored.
    foundation : LinearFoundation
    speeds : array_like, shape (S,)
        Train speeds [m/s], all > 0.
    harmonics : int

    Returns
    -------
    ndarray, shape (S, 2m+1)
        c_n for each speed [m].  The period T = H / v differs between rows.
    """
    speeds = np.asarray(speeds, dtype=float).reshape(-1, 1)
    return analytic_coefficients(Passage(track, train.replace(speed=speeds)), foundation, harmonics)


def sweep_extremes(
    track: Track, train: Train, foundation: LinearFoundation, speeds: ArrayLike, harmonics: int = 60,
    samples: int = 2048,
) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest sleeper displacement over a period, for many speeds (eq. 23).

    The series of eq. (12) is evaluated at `samples` equally spaced
    fractions of each speed's period, t / T = j / samples; the grid is the
    same for every speed because omega_n t = 2 pi n t / T.

    Parameters
    ----------
    track : Track
    train : Train
        Its own speed is ignored.
    foundation : LinearFoundation
    speeds : array_like, shape (S,)
        Train speeds [m/s].
    harmonics : int
        m; the default 60 leaves a truncation error below 1e-3 of the peak
        for wagons up to about 40 m (`railtrack.solvers.truncation`).
    samples : int
        Points per period, > 2m.

    Returns
    -------
    lowest, highest : ndarray, shape (S,)
        min and max of w over the period [m] (w < 0 is down).

    Examples
    --------
    >>> from railtrack import Track, Train, LinearFoundation
    >>> low, high = sweep_extremes(Track.paper(), Train.paper(), LinearFoundation.paper(), [45.0])
    >>> round(float(low[0]) * 1e3, 2)
    -1.13
    """
    coefficients = sweep_speeds(track, train, foundation, speeds, harmonics)[:, harmonics:]
    spectrum = np.zeros((coefficients.shape[0], samples // 2 + 1), dtype=complex)
    spectrum[:, : harmonics + 1] = coefficients * samples
    w = np.fft.irfft(spectrum, samples, axis=-1)
    return w.min(axis=-1), w.max(axis=-1)
