"""Several irregularities at once: a rough rail and wheel flats, each felt by its wheels.

A flat on a wheel that also rolls over a dipped weld or a random rail: the
contact of wheel k reads the sum of the parts that wheel k feels, a rail
profile under every wheel and a `railtrack.WheelFlat` under its own
(`felt_profile`).  The parts must repeat together: the sum's period is the
longest part's, and every other period must divide it.
"""

from __future__ import annotations

import numpy as np

from .wheel_flat import felt_by

__all__ = ["ProfileSum", "felt_profile"]


class ProfileSum:
    """The sum of rail-top profiles and wheel flats, r_k(x) = sum of the parts wheel k feels.

    Parameters
    ----------
    *parts : callable
        Profiles r(x) [m] (`railtrack.CosineDip`, `railtrack.DippedJoint`, a
        random rail...) and `railtrack.WheelFlat`s; at least two.  Each part
        with a `period` must divide the longest such period.

    Examples
    --------
    >>> import railtrack as rt
    >>> both = ProfileSum(rt.CosineDip(0.5e-3, 1.0, 18.0, centre=9.0),
    ...                   rt.WheelFlat(0.5e-3, 0.1, 3.0, wheel=1))
    >>> both.period
    18.0
    >>> x = np.array([[9.0, 3.0], [9.0, 3.0]])   # wheels 0 and 1 at x = 9 and 3 m
    >>> felt_profile(both, x, 2) * 1e3           # the weld under both; the flat on wheel 1
    array([[-0.5,  0. ],
           [-1. , -0.5]])
    """

    __slots__ = ("parts", "period")

    def __init__(self, *parts) -> None:
        if len(parts) < 2 or not all(callable(p) for p in parts):
            raise TypeError("ProfileSum takes two or more profiles r(x) or wheel flats, e.g. "
                            "ProfileSum(rt.CosineDip(...), rt.WheelFlat(...))")
        periods = [float(p.period) for p in parts if getattr(p, "period", None) is not None]
        period = max(periods) if periods else None
        for other in periods:
            ratio = period / other
            if abs(ratio - round(ratio)) > 1e-9 * ratio:
                raise ValueError(f"the parts must repeat together: a period of {other:g} m "
                                 f"does not divide the longest, {period:g} m")
        object.__setattr__(self, "parts", tuple(parts))
        object.__setattr__(self, "period", period)

    def __setattr__(self, name, value):
        raise AttributeError("a ProfileSum is immutable")

    def __call__(self, x) -> np.ndarray:
        """The sum of every part at x [m], as one wheel carrying every flat would feel it."""
        return sum(np.asarray(p(x), dtype=float) for p in self.parts)

    def __repr__(self) -> str:
        return f"ProfileSum({', '.join(repr(p) for p in self.parts)})"

    def __eq__(self, other) -> bool:
        return isinstance(other, ProfileSum) and self.parts == other.parts

    def __hash__(self) -> int:
        return hash(self.parts)


def felt_profile(profile, x, per_wagon: int, axis: int = 0) -> np.ndarray:
    """r_k at the contact points x [m] of each wheel, the wheels along `axis` of x.

    A rail profile is felt by every wheel; a `WheelFlat` by its own wheel of
    each wagon of `per_wagon` wheels; a `ProfileSum` is the sum of its parts'.
    """
    x = np.asarray(x, dtype=float)
    if isinstance(profile, ProfileSum):
        return sum(felt_profile(p, x, per_wagon, axis) for p in profile.parts)
    mask = felt_by(profile, x.shape[axis], per_wagon)
    shape = [1] * x.ndim
    shape[axis] = x.shape[axis]
    return np.asarray(profile(x), dtype=float) * mask.reshape(shape)
