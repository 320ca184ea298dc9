"""The track along x at one instant: the deflection bowl that travels with the train.

The sleeper at x = k L repeats the observed sleeper's history k L / v later
(the train moves towards +x), w_k(t) = w(t - k L / v), and the rail between
them comes from `railtrack.equations.rail_field`; so a whole stretch of track at many
instants is post-processing of one periodic solution.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["DeflectionBowl", "deflection_bowl", "MAX_BOWL_ENTRIES"]

MAX_BOWL_ENTRIES = 20_000_000
"""Largest table a bowl builds: sleepers x harmonics, instants x sleepers, or wheels [-].

2e7 complex entries are 320 MB and about a second; the paper's wagon at
m = 60 reaches it with a window of some 100 km of sleepers.
"""


class DeflectionBowl(NamedTuple):
    """The track along x at one instant (`Solution.deflection_bowl`), SI units, w upward.

    Attributes
    ----------
    x : ndarray
        Positions along the rail ahead of the observed sleeper [m].
    rail : ndarray
        Rail displacement at those positions [m].
    sleeper_positions : ndarray
        The sleepers k L that lie within [min x, max x] [m].
    sleepers : ndarray
        Their displacements [m].
    wheel_positions : ndarray
        Where the wheels are at that instant, within [min x, max x] [m].
    """

    x: np.ndarray
    rail: np.ndarray
    sleeper_positions: np.ndarray
    sleepers: np.ndarray
    wheel_positions: np.ndarray


def deflection_bowl(solution, t: ArrayLike, x: ArrayLike) -> DeflectionBowl:
    """The rail and the sleepers along the track at one instant, or at several [m].

    The sleeper at x = k L repeats the observed sleeper's history k L / v
    later (the train moves towards +x): w_k(t) = w(t - k L / v).  The rail
    coefficients are computed once per position and shared by all instants.

    Parameters
    ----------
    t : float or array_like, shape (T,)
        The instant(s) [s]; t = 0 puts a wagon's first axle above the observed sleeper.
    x : array_like, shape (X,)
        Positions along the rail [m], any real values (negative: behind).

    Returns
    -------
    DeflectionBowl
        ``rail`` of shape (X,) for a scalar t, (T, X) otherwise, and
        ``sleepers`` likewise over the sleepers within [min x, max x].
        ``wheel_positions``: for a scalar t the wheels within the window;
        for several instants, shape (T, J), the wheels that are in it at
        some instant (outside it at others).

    Examples
    --------
    >>> from railtrack import Track, Train, LinearFoundation, solve
    >>> solution = solve(Track.paper(), Train.paper(), LinearFoundation.paper())
    >>> bowl = deflection_bowl(solution, 0.0, [-0.6, 0.0, 0.6])
    >>> bowl.sleeper_positions.tolist(), bool(bowl.rail[1] < bowl.sleepers[1] < 0)
    ([-0.6, 0.0, 0.6], True)
    """
    x = np.atleast_1d(np.asarray(x, dtype=float))
    times = np.asarray(t, dtype=float)
    instants = np.atleast_1d(times)
    span, speed = float(solution.passage.sleeper_spacing), float(solution.passage.speed)
    first, last = np.ceil(x.min() / span), np.floor(x.max() / span)
    wagon = float(solution.passage.wagon_length)
    reach = speed * instants
    low, high = (np.floor((reach.min() - x.max()) / wagon),
                 np.ceil((reach.max() - x.min()) / wagon) + 2)
    _check_size(last - first + 1, instants.size, solution.frequencies.size,
                (high - low) * instants.size * len(solution.passage.axle_positions), x)
    positions = span * np.arange(first, last + 1)
    wagons = np.arange(low, high)
    fronts = reach[:, None] - wagon * wagons[None, :]
    offsets = np.asarray(solution.passage.axle_positions, dtype=float)
    wheels = (fronts[:, :, None] - offsets).reshape(len(instants), -1)
    inside = (wheels >= x.min()) & (wheels <= x.max())
    rail = solution.rail_displacement(instants[:, None], x[None, :])
    # w(t - kL/v) = Re sum_n [c_n e^{-i omega_n k L / v}] e^{i omega_n t}: one product
    omega = solution.frequencies
    delayed = solution.coefficients[:, None] * np.exp(-1j * np.multiply.outer(omega, positions / speed))
    sleepers = (np.exp(1j * np.multiply.outer(instants, omega)) @ delayed).real
    if times.ndim == 0:
        return DeflectionBowl(x, rail[0], positions, sleepers[0], np.sort(wheels[0][inside[0]]))
    return DeflectionBowl(x, rail, positions, sleepers, wheels[:, inside.any(axis=0)])


def _check_size(sleepers: float, instants: int, harmonics: int, wheels: float,
                x: np.ndarray) -> None:
    """Refuse a bowl whose tables would exceed `MAX_BOWL_ENTRIES` (before building them)."""
    biggest = max(sleepers * max(harmonics, instants), wheels)
    if biggest > MAX_BOWL_ENTRIES:
        raise ValueError(
            f"the window [{x.min():g}, {x.max():g}] m holds {sleepers:.0f} sleepers "
            f"(and {wheels:.0f} wheel positions over {instants} instant(s)): its tables "
            f"would have {biggest:.3g} entries, above {MAX_BOWL_ENTRIES:.0e} "
            "(railtrack.equations.bowl.MAX_BOWL_ENTRIES).  A bowl draws the sleepers "
            "between the least and the greatest x: ask for a shorter window, or for the "
            "sleepers you need with solution.sleeper_displacement(t - k L / v) and the rail "
            "with solution.rail_displacement(t, x)")
