"""Section 2.3: the train as a periodic impulse series, eqs. (9)–(16).

Wheel j sits at distance D_j behind the reference wheel (eq. 9): ``j H`` for
front wheels and ``j H + D`` for back wheels, so that the train is periodic
with period H in space and T = H / v in time.  By Poisson summation (eq. 10)
its spectrum is a Dirac comb on the harmonics omega_n = 2 pi n v / H
(eq. 11), and the load that reaches the sleeper through the rail and pad is
the Fourier series ``-sum F_n exp(i omega_n t)`` with F_n from eq. (16).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from .sleeper import load_transfer, pad_stiffness
from .track import Track

__all__ = ["wheel_offsets", "load_coefficients", "wheel_passage_times"]


def wheel_offsets(track: Track, wagons: range | int) -> np.ndarray:
    """Distances D_j of the wheels behind the reference wheel, eq. (9) [m].

    Parameters
    ----------
    track : Track
    wagons : int or range
        The wagons j to list; an int n means ``range(n)``.

    Returns
    -------
    ndarray, shape (2 * len(wagons),)
        Sorted offsets ``j H`` (front wheels) and ``j H + D`` (back wheels).

    Examples
    --------
    >>> wheel_offsets(Track.paper(), 2)
    array([ 0.,  3., 18., 21.])
    """
    wagons = range(wagons) if isinstance(wagons, int) else wagons
    j = np.asarray(list(wagons), dtype=float)
    front = j * track.wagon_length
    return np.sort(np.concatenate([front, front + track.wheel_spacing]))


def wheel_passage_times(track: Track) -> np.ndarray:
    """Times within one period [0, T) at which a wheel is above the sleeper [s].

    With the convention t = 0 when a front wheel is above the sleeper, the
    back wheel follows at D / v.
    """
    return np.array([0.0, track.wheel_spacing / track.speed])


def load_coefficients(
    track: Track, omega: ArrayLike, transfer: np.ndarray | None = None
) -> np.ndarray:
    """Load coefficients F(omega) = Q (1 + e^{-i omega D/v}) A Gamma / (M H EI), eq. (16) [m/s^2].

    F_n = F(omega_n) is harmonic n of the train's load on the sleeper,
    per unit sleeper mass, after it has passed through the rail and the pad.
    The sleeper's equation (15) has ``-sum F_n exp(i omega_n t)`` on its
    right-hand side: loads push down, and w is positive upward.

    Parameters
    ----------
    track : Track
    omega : array_like
        Angular frequency [rad/s]; the method uses the harmonics omega_n.
    transfer : ndarray, optional
        Gamma(omega) if already computed (`railtrack.sleeper.coupling_and_transfer`).

    Returns
    -------
    ndarray
        Complex F, same shape as `omega`.  At omega = 0 it equals the exact
        limit ``2 Q L / (M H)``: the train's mean weight per sleeper over the
        sleeper mass.  It vanishes where ``omega D / v`` is an odd multiple of
        pi, for then the two wheels of a wagon cancel.

    Examples
    --------
    >>> track = Track.paper()
    >>> float(load_coefficients(track, 0.0).real)   # 2 Q L / (M H)
    50.0
    """
    omega = np.asarray(omega, dtype=float)
    if transfer is None:
        transfer = load_transfer(track, omega)
    wheel_pair = 1.0 + np.exp(-1j * omega * track.wheel_spacing / track.speed)
    return (
        track.wheel_load
        * wheel_pair
        * pad_stiffness(track, omega)
        * transfer
        / (track.sleeper_mass * track.wagon_length * track.rail_bending_stiffness)
    )
