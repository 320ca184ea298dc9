"""Rail-top profiles r(x) fixed on the track: a dipped weld or joint (issue 20).

A profile is any callable ``r(x)`` [m] of the position along the track x [m],
positive upward (a dip is negative), vectorised over numpy arrays.  For the
steady state to be periodic the profile must repeat with the track's
pattern: every ``period`` metres, a whole number of sleeper spacings.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .validation import as_float64, require_finite, require_non_negative, require_positive

__all__ = ["CosineDip", "smooth_rail"]


def smooth_rail(x) -> np.ndarray:
    """The smooth rail: r(x) = 0."""
    return np.zeros(np.shape(x))


@dataclass(frozen=True)
class CosineDip:
    """A dip of `depth` and `length`, centred at `centre`, repeating every `period`.

        r(x) = -depth/2 (1 + cos(2 pi s / length))   for |s| < length/2,   else 0,

    s the distance from the nearest centre ``centre + k period``.

    Parameters
    ----------
    depth : float
        >= 0 [m].
    length : float
        > 0 [m], < period.
    period : float
        > 0 [m], the distance between dips (for a steady state, a whole
        number of sleeper spacings, e.g. the wagon length).
    centre : float
        [m], position of one dip's lowest point (finite).

    Examples
    --------
    >>> dip = CosineDip(0.5e-3, 1.0, 18.0, centre=9.0)
    >>> dip(np.array([9.0, 9.25, 9.5, 27.0])) * 1e3
    array([-0.5 , -0.25,  0.  , -0.5 ])
    """

    depth: float
    length: float
    period: float
    centre: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_non_negative("depth", self.depth, "m")
        require_positive("length", self.length, "m")
        require_positive("period", self.period, "m")
        require_finite("centre", self.centre, "m")
        if self.length >= self.period:
            raise ValueError(f"a dip's length ({self.length} m) must be shorter than its "
                             f"period ({self.period} m)")
        as_float64(self)
        check_plausible(self)

    def __call__(self, x) -> np.ndarray:
        s = np.asarray(x, dtype=float) - self.centre
        s = s - self.period * np.round(s / self.period)
        inside = np.abs(s) < 0.5 * self.length
        return np.where(inside, -0.5 * self.depth * (1.0 + np.cos(2 * np.pi * s / self.length)),
                        0.0)

    def slope(self, x) -> np.ndarray:
        """dr/dx [-]."""
        s = np.asarray(x, dtype=float) - self.centre
        s = s - self.period * np.round(s / self.period)
        inside = np.abs(s) < 0.5 * self.length
        return np.where(inside, np.pi * self.depth / self.length
                        * np.sin(2 * np.pi * s / self.length), 0.0)
