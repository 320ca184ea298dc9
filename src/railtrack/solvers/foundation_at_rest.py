"""The foundation law at rest: the static deflection it settles to, and its stability.

Both are needed before any harmonic-balance solve: the static deflection is
the mean of Newton's starting guess (`railtrack.solvers.newton.linear_guess`) and of
the prediction of m (`railtrack.solvers.truncation`); a law with negative stiffness
or damping at rest describes an unstable track, which `railtrack.solve`
refuses (`check_foundation_at_rest`).
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from ..model.foundations import Foundation

__all__ = ["static_deflection", "check_foundation_at_rest"]


def static_deflection(foundation: Foundation, force: float) -> float:
    """The displacement w at which the foundation alone carries `force`: f(w, 0) = -force [m].

    Used for the mean of the starting guess: in the mean of eq. (17) the pad
    and rail terms cancel (P_0 = omega_0^2), so the foundation carries the
    whole static load 2 Q L / H whatever the law.  Solved by Newton's
    method from the linear estimate, and if that fails by bracketing and
    Brent's method, so it also works for a law with no stiffness at rest
    (a pure cubic).

    Parameters
    ----------
    foundation : Foundation
    force : float
        Downward static load on the foundation [N], > 0.

    Returns
    -------
    float
        w < 0 [m]; NaN if the law cannot carry the load (it never reaches it).

    Examples
    --------
    >>> from railtrack import LinearFoundation
    >>> round(static_deflection(LinearFoundation(20e6), 5000.0), 9)
    -0.00025
    """
    def balance(w: float) -> float:
        return float(np.asarray(foundation.force(np.array([w]), np.zeros(1)))[0]) + force

    stiffness, _ = foundation.linearization()
    guess = force / stiffness if stiffness > 0 else np.inf
    # Newton from the linear estimate settles the usual laws in a step or
    # a few (exactly in one for a linear law); brackets are the fallback.
    w = -guess if guess < 1.0 else -1e-3
    for _ in range(8):
        value = balance(w)
        tangent = float(np.ravel(foundation.tangent(np.array([w]), np.zeros(1))[0])[0])
        if not (np.isfinite(value) and np.isfinite(tangent)) or tangent <= 0:
            break
        if abs(value) <= 1e-13 * force:
            return w
        w -= value / tangent
        if w >= 0:
            break
    # The linear estimate brackets the root unless the law has (almost) no
    # stiffness at rest; then start from a millimetre, the scale of a track.
    low = -guess if guess < 1.0 else -1e-3
    for _ in range(200):
        value = balance(low)
        if not np.isfinite(value):
            return float("nan")
        if value <= 0:
            return float(brentq(balance, low, 0.0, xtol=1e-300, rtol=4 * np.finfo(float).eps))
        low *= 2.0
    return float("nan")


def check_foundation_at_rest(foundation: Foundation, pad_stiffness: float, pad_damping: float) -> None:
    """Refuse a law whose stiffness or damping at rest is negative.

    The harmonic-balance equations (17) can have solutions for such a law,
    but the track they describe is unstable: the time-domain model of the
    same track grows without bound.  A softening law (stiffness falling with
    |w|) passes as long as its stiffness at rest is >= 0.  Tolerances are
    1e-9 of the pad's k1 and eta1 (or sqrt(k1 M)-free 1e-9 N s/m) to forgive
    the round-off of a numerical tangent.

    Raises
    ------
    ValueError
        Naming the negative stiffness or damping, and how to proceed; or
        saying that the stiffness or damping at rest is not finite.
    """
    stiffness, damping = foundation.linearization()
    if not (np.isfinite(stiffness) and np.isfinite(damping)):
        raise ValueError(
            f"the foundation law's linearisation at rest is not finite: df/dw = {stiffness:.4g} "
            f"N/m, df/dw' = {damping:.4g} N s/m at w = w' = 0.  The law must give finite "
            "forces and slopes near rest: look for a division by w, a root or a log of w, "
            "or an overflow")
    problems = []
    if stiffness < -1e-9 * pad_stiffness:
        problems.append(f"negative stiffness at rest, df/dw = {stiffness:.4g} N/m")
    if damping < -1e-9 * max(pad_damping, 1.0):
        problems.append(f"negative damping at rest, df/dw' = {damping:.4g} N s/m")
    if problems:
        raise ValueError(
            "the foundation law has " + " and ".join(problems) + ": the track would be "
            "unstable (the sign convention is f > 0 when the foundation is stretched, "
            "f = k w + eta w' for a spring and dashpot). If this is deliberate, "
            "pass check_foundation=False and confirm the answer with "
            "railtrack.simulate_time_domain"
        )
