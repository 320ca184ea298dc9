"""Where the rail can be asked for: positions x whose phases omega x / v double precision carries.

The rail's coefficients at x carry the phase e^{-i omega_n x / v} of each
harmonic; far from the observed sleeper round-off leaves that phase no
digits.  `check_positions` refuses such x (`railtrack.equations.rail_field`,
`railtrack.equations.moment`); `checked_times` does the same for the
phases omega_n t of a time t, and for a t that is not a number.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage

__all__ = ["MAX_PHASE_ROUNDOFF", "check_positions", "checked_times"]

MAX_PHASE_ROUNDOFF = 1e-3
"""Largest round-off of the highest harmonic's phase omega_m |x| / v accepted [rad].

A double carries the phase to eps = 2.2e-16 of itself, so at |x| the phase
of harmonic m is uncertain by eps omega_m |x| / v.  Measured on the paper's
case (m = 24, 45 m/s) at whole wagons ahead, where the rail repeats: the
displacement is off by ~0.05 and the bending moment by ~0.2-0.4 times that
round-off of the peak (9e-5 and 4e-4 at 1.9e-3 rad; 8 % and 51 % at
1.9 rad, |x| = 1e15 m, where the phase has no digit left).  At 1e-3 rad,
|x| = 5.4e11 m there, round-off stays below the accuracy of the truncation.
"""


def check_positions(passage: Passage, omega: ArrayLike, x: ArrayLike) -> None:
    """Refuse positions x at which round-off leaves the phases omega x / v no digits.

    Raises ValueError for a non-finite x, or where ``eps max|omega| max|x| / v``
    exceeds `MAX_PHASE_ROUNDOFF`; the message gives the bound on |x|.
    """
    x = np.asarray(x, dtype=float)
    if x.size == 0:
        return
    if not np.all(np.isfinite(x)):
        raise ValueError(f"positions x must be finite numbers [m]; got {x[~np.isfinite(x)][0]!r}")
    far = float(np.max(np.abs(x)))
    per_metre = float(np.max(np.abs(np.asarray(omega, dtype=float)), initial=0.0)) / float(
        passage.speed)
    roundoff = np.finfo(float).eps * far * per_metre
    if roundoff > MAX_PHASE_ROUNDOFF:
        bound = MAX_PHASE_ROUNDOFF / (np.finfo(float).eps * per_metre)
        spans = float(passage.wagon_length) / float(passage.sleeper_spacing)
        hint = (f" The rail repeats every wagon (H / L = {spans:.0f} spans): ask for x modulo "
                f"H = {float(passage.wagon_length):g} m." if abs(spans - round(spans)) < 1e-9
                else "")
        raise ValueError(
            f"|x| = {far:.3g} m is too far for double precision: the phase omega x / v of the "
            f"highest harmonic ({per_metre * far:.3g} rad) carries a round-off of "
            f"{roundoff:.2g} rad, and the result would be round-off, not the rail "
            f"(MAX_PHASE_ROUNDOFF = {MAX_PHASE_ROUNDOFF:g} rad).  This solution accepts "
            f"|x| <= {bound:.3g} m.{hint}")


def checked_times(omega: ArrayLike, t: ArrayLike) -> np.ndarray:
    """t as a float array [s], refused where it is not finite or its phases have no digits.

    Raises ValueError for a non-finite t, or where ``eps max|omega| max|t|``
    exceeds `MAX_PHASE_ROUNDOFF`; the message gives the bound on |t|.  A
    periodic response repeats every period: ask for t modulo it.

    Examples
    --------
    >>> checked_times([0.0, 100.0], [0.0, 0.5]).tolist()
    [0.0, 0.5]
    >>> checked_times([100.0], [float("nan")])
    Traceback (most recent call last):
    ...
    ValueError: times t must be finite numbers [s]; got nan
    """
    t = np.asarray(t, dtype=float)
    if t.size == 0:
        return t
    if not np.all(np.isfinite(t)):
        raise ValueError(f"times t must be finite numbers [s]; got {float(t[~np.isfinite(t)][0])!r}")
    top = float(np.max(np.abs(np.asarray(omega, dtype=float)), initial=0.0))
    late = float(np.max(np.abs(t)))
    roundoff = np.finfo(float).eps * top * late
    if roundoff > MAX_PHASE_ROUNDOFF:
        bound = MAX_PHASE_ROUNDOFF / (np.finfo(float).eps * top)
        raise ValueError(
            f"|t| = {late:.3g} s is too late for double precision: the phase omega t of the "
            f"highest harmonic carries a round-off of {roundoff:.2g} rad, and the result "
            f"would be round-off (MAX_PHASE_ROUNDOFF = {MAX_PHASE_ROUNDOFF:g} rad).  "
            f"|t| <= {bound:.3g} s is accepted; the response repeats every period, so ask "
            "for t modulo it")
    return t
