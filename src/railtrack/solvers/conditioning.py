"""Where eq. (3), as evaluated here, stays accurate: a guard against round-off.

`railtrack.equations.receptance.receptance_factors` is exact algebra, but for a nearly
still train or a nearly massless rail it subtracts two large numbers.
`roundoff_estimate` says how much is lost, and `check_conditioning` (called by
`railtrack.solve`) refuses a track where it would show in the answer.
"""

from __future__ import annotations

import numpy as np

from ..model.passage import Passage

__all__ = ["ROUNDOFF_LIMIT", "roundoff_estimate", "check_conditioning"]

ROUNDOFF_LIMIT = 1e-6
"""Largest estimated round-off (relative) of eq. (3) that `check_conditioning` accepts."""


def roundoff_estimate(passage: Passage) -> float:
    """Estimated relative round-off in the response computed from eq. (3) [-].

    The numerator of `receptance_factors` is the difference of two terms of
    size r^2, r = sqrt(omega) (EI/rho S)^(1/4) / v, whose difference is of
    order one: it keeps about 1e-16 r^2 of relative error.  r is large
    when the rail is nearly massless or the train nearly still, where the
    response is the static one.  Measured on Table 1 with rho S or v made
    small, eps r_1^2, with r_1 at the first harmonic omega_1 = 2 pi v / H,
    is between 1 and 4 times the actual error of the sleeper displacement
    (tests/test_failure_modes.py): a cautious estimate.
    """
    omega_1 = 2.0 * np.pi * passage.speed / passage.wagon_length
    r_squared = omega_1 * np.sqrt(passage.rail_bending_stiffness / passage.rail_linear_mass) / passage.speed**2
    return float(np.finfo(float).eps * r_squared)


def check_conditioning(passage: Passage) -> None:
    """Refuse a track for which eq. (3), as evaluated here, would lose accuracy.

    Raises
    ------
    ValueError
        If `roundoff_estimate` exceeds 1e-6, naming the speed and rail mass
        below which this happens.

    Examples
    --------
    >>> check_conditioning(Passage.paper())            # 45 m/s, 60 kg/m: fine
    >>> check_conditioning(Passage.paper(speed=1e-12))
    Traceback (most recent call last):
    ...
    ValueError: eq. (3) loses accuracy for this track: ...
    """
    estimate = roundoff_estimate(passage)
    if estimate <= ROUNDOFF_LIMIT:
        return
    scale = np.finfo(float).eps / ROUNDOFF_LIMIT * 2.0 * np.pi / passage.wagon_length
    slowest = scale * np.sqrt(passage.rail_bending_stiffness / passage.rail_linear_mass)
    lightest = passage.rail_bending_stiffness * (scale / passage.speed) ** 2
    raise ValueError(
        f"eq. (3) loses accuracy for this track: its estimated round-off is {estimate:.1e} "
        f"of the response (limit {ROUNDOFF_LIMIT:.0e}), because the train is nearly still or "
        f"the rail nearly massless. Use speed >= {slowest:.1e} m/s with this rail, or "
        f"rail_linear_mass >= {lightest:.1e} kg/m at this speed"
    )
