"""Rail-top profiles r(x) fixed on the track: a dipped weld or joint (issues 20, 32).

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

__all__ = ["CosineDip", "DippedJoint", "smooth_rail"]


def smooth_rail(x) -> np.ndarray:
    """The smooth rail: r(x) = 0."""
    return np.zeros(np.shape(x))


def _validate(dip, size: str, unit: str, what: str) -> None:
    """The checks a periodic dip shares: SI, sizes, its length inside its period, plausibility."""
    quantities_to_si(dip)
    require_non_negative(size, getattr(dip, size), unit)
    require_positive("length", dip.length, "m")
    require_positive("period", dip.period, "m")
    require_finite("centre", dip.centre, "m")
    check_plausible(dip)           # first, so that a unit slip is named before the error below
    if dip.length >= dip.period:
        raise ValueError(f"{what} ({dip.length:g} m) must be shorter than its "
                         f"period ({dip.period:g} m)")
    as_float64(dip)


def _from_nearest(dip, x) -> np.ndarray:
    """s: the signed distance of x [m] from the nearest centre + k period."""
    s = np.asarray(x, dtype=float) - dip.centre
    return s - dip.period * np.round(s / dip.period)


def cosine_dip(s, depth: float, length: float) -> np.ndarray:
    """-depth/2 (1 + cos(2 pi s / length)) for |s| < length/2, else 0 [m]; s [m]."""
    inside = np.abs(s) < 0.5 * length
    return np.where(inside, -0.5 * depth * (1.0 + np.cos(2 * np.pi * s / length)), 0.0)


def cosine_slope(s, depth: float, length: float) -> np.ndarray:
    """d/ds of `cosine_dip` [-]."""
    inside = np.abs(s) < 0.5 * length
    return np.where(inside, np.pi * depth / length * np.sin(2 * np.pi * s / length), 0.0)


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
        _validate(self, "depth", "m", "a dip's length")

    def __call__(self, x) -> np.ndarray:
        return cosine_dip(_from_nearest(self, x), self.depth, self.length)

    def slope(self, x) -> np.ndarray:
        """dr/dx [-]."""
        return cosine_slope(_from_nearest(self, x), self.depth, self.length)


@dataclass(frozen=True)
class DippedJoint:
    """A V-shaped dipped joint of total dip angle `angle` ramping over `length`.

        r(x) = -(angle/2) (length/2 - |s|)   for |s| < length/2,   else 0,

    s the distance from the nearest joint ``centre + k period``.  Two
    straight ramps meet at the joint: the rail runs down at slope
    -alpha = -angle/2 and up at +alpha, so its slope jumps by 2 alpha =
    `angle` (the engineer's dip angle) at the joint and by alpha at both
    ends of the ramps, where it meets the level rail.  The depth at the joint
    is angle length / 4.  Its corners are what excite the P1 force.

    Parameters
    ----------
    angle : float
        2 alpha >= 0, the total change of rail slope at the joint [rad].
    length : float
        > 0 [m], < period: the dip's length, from one end of its ramps to
        the other.
    period : float
        > 0 [m], the distance between joints (for a steady state, a whole
        number of sleeper spacings, e.g. the wagon length).
    centre : float
        [m], position of one joint (finite).

    Examples
    --------
    >>> joint = DippedJoint(10e-3, 1.0, 18.0, centre=9.0)
    >>> joint.depth * 1e3
    2.5
    >>> joint(np.array([9.0, 9.25, 9.5, 27.0])) * 1e3
    array([-2.5 , -1.25,  0.  , -2.5 ])
    >>> joint.slope(np.array([8.75, 9.25, 10.0])) * 1e3
    array([-5.,  5.,  0.])
    """

    angle: float
    length: float
    period: float
    centre: float = 0.0

    def __post_init__(self) -> None:
        _validate(self, "angle", "rad", "a joint's dip length")

    @property
    def depth(self) -> float:
        """The dip's depth at the joint, angle length / 4 [m]."""
        return 0.25 * self.angle * self.length

    def __call__(self, x) -> np.ndarray:
        s = _from_nearest(self, x)
        return 0.5 * self.angle * np.minimum(np.abs(s) - 0.5 * self.length, 0.0)

    def slope(self, x) -> np.ndarray:
        """dr/dx [-]: -angle/2 on the way down, +angle/2 up, 0 at the joint itself."""
        s = _from_nearest(self, x)
        inside = np.abs(s) < 0.5 * self.length
        return np.where(inside, 0.5 * self.angle * np.sign(s), 0.0)
