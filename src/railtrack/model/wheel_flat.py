"""A flat on one wheel of every wagon, and which wheels feel a profile (issue 32).

A wheel flat rides with the wheel, not the rail: it strikes the rail once
every wheel turn, at the contact positions ``centre + k circumference``,
and only under its own wheel.  To the contact it is a dip felt by that
wheel alone, of the flat's depth: the harmonic balance and the time-domain
ring read it through `felt_by`, which zeroes it under every other wheel.

A fresh flat is a chord of the wheel's circle; wear rounds its edges.  It
is modelled here as a cosine dip of the flat's depth and length, the
rounded shape with no kink (`railtrack.model.profile.CosineDip`); the
depth of a fresh flat of chord length l on a wheel of radius R is its
sagitta, ``sagitta(l, R)`` = l^2 / (8 R) to first order.

The steady state stays periodic only if every wagon length H holds a whole
number of wheel turns and the turn holds a whole number of sleeper
spacings: a circumference of 3.0 m (R = 0.477 m, a new 955 mm wheel) on
0.6 m spacings and 18 m or 24 m wagons.  A wheel of another size is
represented by the nearest circumference that does (see chapter 17).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .profile import _from_nearest, _validate, cosine_dip, cosine_slope

__all__ = ["WheelFlat", "sagitta", "felt_by", "LARGEST_CIRCUMFERENCE"]

LARGEST_CIRCUMFERENCE = 10.0
"""Largest wheel circumference accepted [m]: larger than any railway wheel's
(steam locomotives' driving wheels reach about 2.3 m across, 7.2 m around)."""


def sagitta(chord: float, radius: float) -> float:
    """Depth [m] of a fresh flat of chord length `chord` [m] on a wheel of `radius` [m].

    R - sqrt(R^2 - (l/2)^2), about l^2 / (8 R) for a short flat.

    Examples
    --------
    >>> round(sagitta(0.05, 0.46) * 1e3, 3)      # mm, a 50 mm flat
    0.68
    """
    if not 0.0 < chord < 2.0 * radius:
        raise ValueError(f"a flat's chord ({chord} m) must lie between 0 and the wheel's "
                         f"diameter ({2.0 * radius} m)")
    return float(radius - np.sqrt(radius**2 - 0.25 * chord**2))


@dataclass(frozen=True)
class WheelFlat:
    """A rounded flat of `depth` and `length` on wheel `wheel` of every wagon.

        r_k(x) = -depth/2 (1 + cos(2 pi s / length))   for |s| < length/2,  else 0,

    for wheel k = `wheel` (0 for the leading wheel of a wagon, in the train's
    order), s the distance of the contact point x from the nearest
    ``centre + j circumference``; r_k = 0 for every other wheel.

    Parameters
    ----------
    depth : float
        >= 0 [m], the flat's depth (`sagitta` for a fresh flat).
    length : float
        > 0 [m], < circumference: the rounded flat's length along the tread.
    circumference : float
        2 pi R [m], the distance between two strikes.  For a steady state a
        whole number of sleeper spacings that divides the wagon length.
    wheel : int
        >= 0, which wheel of each wagon carries the flat.
    centre : float
        [m], a contact position where the flat's middle meets the rail.

    Examples
    --------
    >>> flat = WheelFlat(0.5e-3, 0.1, 3.0, wheel=1)
    >>> flat.period
    3.0
    >>> flat(np.array([0.0, 0.025, 3.0])) * 1e3            # under wheel 1
    array([-0.5 , -0.25, -0.5 ])
    >>> felt_by(flat, 4)
    array([0., 1., 0., 0.])
    """

    depth: float
    length: float
    circumference: float
    wheel: int = 0
    centre: float = 0.0

    def __post_init__(self) -> None:
        if isinstance(self.wheel, bool) or not isinstance(self.wheel, (int, np.integer)) \
                or self.wheel < 0:
            raise ValueError(f"wheel must be a wheel's index in its wagon (0, 1, ...); "
                             f"got {self.wheel!r}")
        wheel = int(self.wheel)
        _validate(self, "depth", "m", "a flat's length")
        if self.circumference > LARGEST_CIRCUMFERENCE:
            # a period of many wagons would be solved as one long train: refuse the slip
            raise ValueError(f"a wheel's circumference of {self.circumference:g} m is no "
                             f"railway wheel's (at most {LARGEST_CIRCUMFERENCE:g} m, a wheel "
                             f"3 m across): cm or mm? The circumference is 2 pi R in metres, "
                             f"e.g. 3.0 for R = 0.477 m")
        object.__setattr__(self, "wheel", wheel)       # kept an index, not a float

    @property
    def period(self) -> float:
        """The distance between two strikes, the circumference [m]."""
        return self.circumference

    def __call__(self, x) -> np.ndarray:
        return cosine_dip(_from_nearest(self, x), self.depth, self.length)

    def slope(self, x) -> np.ndarray:
        """dr/dx [-] under the flat wheel."""
        return cosine_slope(_from_nearest(self, x), self.depth, self.length)


def felt_by(profile, wheels: int, per_wagon: int | None = None) -> np.ndarray:
    """1 for each of `wheels` wheels that feels `profile`, else 0, shape (wheels,).

    A rail profile is felt by every wheel; a `WheelFlat` by its own wheel in
    each wagon of `per_wagon` wheels (default: one wagon of `wheels`).

    Raises
    ------
    ValueError
        A flat on a wheel the wagon does not have.
    """
    wheel = getattr(profile, "wheel", None)
    if wheel is None:
        return np.ones(wheels)
    per_wagon = wheels if per_wagon is None else int(per_wagon)
    if wheel >= per_wagon:
        raise ValueError(f"the flat is on wheel {wheel}, but a wagon has {per_wagon} wheels "
                         f"(0 to {per_wagon - 1})")
    return (np.arange(wheels) % per_wagon == wheel).astype(float)
