"""Section 2.3: the train as a periodic impulse series, eqs. (9)–(16).

Axle j of wagon k sits at distance k H + d_j behind the train's first axle
(eq. 9, where the paper's wagon has d = (0, D)), so that the load is periodic
with period H in space and T = H / v in time.  By Poisson summation (eq. 10)
its spectrum is a Dirac comb on the harmonics omega_n = 2 pi n v / H
(eq. 11), weighted by the wagon's axle factor sum_j Q_j e^{-i omega d_j / v}
(the paper's Q (1 + e^{-i omega D / v})).  The load that reaches the sleeper
through the rail and pad is the Fourier series ``-sum F_n exp(i omega_n t)``
with F_n from eq. (16).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .sleeper import load_transfer, pad_stiffness

__all__ = ["wheel_offsets", "axle_factor", "load_coefficients", "wheel_passage_times"]


def wheel_offsets(passage: Passage, wagons: range | int) -> np.ndarray:
    """Distances of the axles behind the train's first axle, eq. (9) [m].

    Parameters
    ----------
    passage : Passage
    wagons : int or range
        The wagons k to list; an int n means ``range(n)``.

    Returns
    -------
    ndarray, shape (J * len(wagons),)
        Sorted offsets ``k H + d_j``.

    Examples
    --------
    >>> wheel_offsets(Passage.paper(), 2)
    array([ 0.,  3., 18., 21.])
    """
    wagons = range(wagons) if isinstance(wagons, int) else wagons
    k = np.asarray(list(wagons), dtype=float)
    offsets = k[:, None] * passage.wagon_length + np.asarray(passage.axle_positions)[None, :]
    return np.sort(offsets.ravel())


def wheel_passage_times(passage: Passage) -> np.ndarray:
    """Times within one period [0, T) at which an axle is above the sleeper, d_j / v [s].

    With the convention t = 0 when a wagon's first axle is above the sleeper.
    """
    return passage.axle_times


def axle_factor(passage: Passage, omega: ArrayLike) -> np.ndarray:
    """The wagon's load spectrum sum_j Q_j exp(-i omega d_j / v), eq. (10) generalised [N].

    For the paper's wagon, d = (0, D) and Q_j = Q, it is Q (1 + e^{-i omega D/v}).

    Examples
    --------
    >>> float(axle_factor(Passage.paper(), 0.0).real)      # sum Q_j
    150000.0
    """
    omega = np.asarray(omega, dtype=float)
    factor = np.zeros(np.broadcast_shapes(np.shape(omega), np.shape(passage.speed)), complex)
    for position, load in zip(passage.axle_positions, passage.axle_loads):
        if position == 0.0:
            factor = factor + load
        else:
            factor = factor + load * np.exp(-1j * omega * position / passage.speed)
    return factor


def load_coefficients(
    passage: Passage, omega: ArrayLike, transfer: np.ndarray | None = None
) -> np.ndarray:
    """Load coefficients F(omega) = [sum_j Q_j e^{-i omega d_j/v}] A Gamma / (M H EI), eq. (16) [m/s^2].

    F_n = F(omega_n) is harmonic n of the train's load on the sleeper,
    per unit sleeper mass, after it has passed through the rail and the pad.
    The sleeper's equation (15) has ``-sum F_n exp(i omega_n t)`` on its
    right-hand side: loads push down, and w is positive upward.

    Parameters
    ----------
    passage : Passage
    omega : array_like
        Angular frequency [rad/s]; the method uses the harmonics omega_n.
    transfer : ndarray, optional
        Gamma(omega) if already computed (`railtrack.equations.sleeper.coupling_and_transfer`).

    Returns
    -------
    ndarray
        Complex F, same shape as `omega`.  At omega = 0 it equals the exact
        limit ``sum Q_j L / (M H)``: the train's mean weight per sleeper over
        the sleeper mass.  For the paper's wagon it vanishes where
        ``omega D / v`` is an odd multiple of pi, for then its two axles cancel.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> float(load_coefficients(passage, 0.0).real)   # 2 Q L / (M H)
    50.0
    """
    omega = np.asarray(omega, dtype=float)
    if transfer is None:
        transfer = load_transfer(passage, omega)
    return (
        axle_factor(passage, omega)
        * pad_stiffness(passage, omega)
        * transfer
        / (passage.sleeper_mass * passage.wagon_length * passage.rail_bending_stiffness)
    )
