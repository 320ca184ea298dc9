"""The rail's bending moment under moving wheels: its kinks summed in closed form.

Under a point load the shear force of an Euler–Bernoulli beam jumps by the
load, so the bending moment M = EI w'' has a kink there.  At a fixed point x
the moment therefore has a kink in time each time an axle passes: with the
wheel at x_j(t) = v t - d_j and M locally a function of x - x_j(t), its rate
dM/dt jumps by J_j = -v Q_j at t_j = (x + d_j) / v (the sagging peak under the
wheel is a cusp).  This holds for the dynamic response too: inertia and the
sleeper reactions add no point load at a moving x.

A kink makes the Fourier coefficients fall only like 1/n^2 and the series
converge like 1/m at the kink: 20 % low at the m that makes the displacement
accurate to 1e-3.  The periodic function with one slope jump J at t = 0,

    g(tau) = -J (tau^2 / (2 T) - tau / 2 + T / 12),   0 <= tau < T,

has the coefficients g_n = -J / (T omega_n^2) (n != 0, g_0 = 0).  Subtracting
them from the series and adding g in closed form leaves a remainder without
kinks, which converges fast.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .rail_field import check_positions

__all__ = ["kink_coefficients", "kink_sum"]


def _kinks(passage: Passage, x: np.ndarray):
    """(slope jump J_j [N m/s], time t_j of the kink [s]) for each axle, at each x."""
    speed = float(passage.speed)
    jumps = -speed * np.asarray(passage.axle_loads, dtype=float)
    times = (np.asarray(x, dtype=float)[..., None] + np.asarray(passage.axle_positions)) / speed
    return jumps, times


def kink_coefficients(passage: Passage, omega: ArrayLike, x: ArrayLike) -> np.ndarray:
    """Fourier coefficients of the moment's kinks at each x [N m], shape (X, W).

    ``sum_j -J_j e^{-i omega_n t_j} / (T omega_n^2)``, zero at omega = 0.
    """
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    check_positions(passage, omega, x)
    jumps, times = _kinks(passage, np.atleast_1d(x))
    with np.errstate(divide="ignore"):
        shape = np.where(omega == 0.0, 0.0, -1.0 / (float(passage.period) * omega**2))
    phases = np.exp(-1j * times[..., None] * omega)               # (X, J, W)
    return np.einsum("j,xjw->xw", jumps, phases) * shape


def kink_sum(passage: Passage, t: ArrayLike, x: ArrayLike) -> np.ndarray:
    """The kinks' periodic functions summed in closed form, sum_j g_j(t - t_j) [N m].

    `t` and `x` broadcast together.

    Examples
    --------
    >>> passage = Passage.paper()
    >>> period = passage.period
    >>> t = np.linspace(0.0, period, 4096, endpoint=False)
    >>> g = kink_sum(passage, t, 0.0)
    >>> bool(abs(g.mean()) < 1e-6 * abs(g).max())       # no mean
    True
    """
    t, x = np.broadcast_arrays(np.asarray(t, dtype=float), np.asarray(x, dtype=float))
    # The kinks' phase 2 pi (x / v) / T, as the first harmonic's: refused where it is round-off.
    check_positions(passage, [2.0 * np.pi / float(passage.period)], x)
    jumps, times = _kinks(passage, x)
    period = float(passage.period)
    tau = np.mod(t[..., None] - times, period)
    return (-jumps * (tau**2 / (2.0 * period) - tau / 2.0 + period / 12.0)).sum(axis=-1)
