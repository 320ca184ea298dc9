"""The truncation error of a wheel solve at an explicit m, estimated a posteriori (issue 27).

The solution at m leaves out every harmonic above m: the rail-top profile's
own (a 1 m dip has them up to p ~ 10 H / 1 m), those of the Hertz force on
the truncated compression, and the sleepers' response to the moving loads
above n = m, which reaches the rail under the wheels at the kept p.  The
estimate takes all of them at once: the solution at m, padded with zeros, is
the start of Newton's method on the same balance at M = min(3 m, m + 240)
harmonics (`railtrack.solvers.wheel_newton.solve_wheels`, exact Hertz
tangent, the sleepers solved exactly for those forces), a few steps at
most (`REFINE_STEPS`).  Its steps are the distance to the solution at M, so
the error is

    max over the wheels and the period of |P_M(t) - P_m(t)| / max_k Q_k.

Measured on the 0.5 mm x 1 m dip at 45 m/s against m = 600 (max over the
period): 6.9/2.6/1.2 % of Q estimated at m = 30/60/120 against 7.7/3.1/1.3 %
true; on the smooth rail 0.10/0.027 % against 0.11/0.029 % at m = 60/120.
With M = 2 m (one step) the estimate at
m = 120 fell to 0.99 % and missed the 1 % warning: the harmonics between 2m and 3m
still count.  The cost is a few Newton steps at M, a few times the solve at m.
"""

from __future__ import annotations

import numpy as np

from .result_protocol import period_times
from .wheel_newton import solve_wheels
from .wheel_rounds import wrap

__all__ = ["wheel_truncation", "TAIL_FACTOR", "TAIL_MOST"]

TAIL_FACTOR = 3
"""The refined balance keeps M = TAIL_FACTOR m harmonics ..."""
TAIL_MOST = 240
"""... but never more than TAIL_MOST above m, which bounds the cost at large m
(at m = 300 on the dip: 0.15 % of Q either way)."""
REFINE_STEPS = 4
"""Newton steps at M at most.  One is the first-order estimate; where the contact is
stiff against the wheel's mobility (a 1 g wheel on C_H = 1e16) the first step lands
badly (4 % of Q for a true 1e-8), and the next ones settle it."""
REFINE_TOL = 1e-9
"""... stopping once the contact residual at M is below this, over Q [-]."""
POINTS = 8192
"""Samples a period on which the two contact-force histories are compared."""


def wheel_truncation(solution) -> float:
    """Estimated truncation error of a converged `WheelSolution`'s contact forces over Q [-].

    See the module docstring; NaN if the refining step cannot be taken.
    """
    m, grid = solution.harmonics, solution.grid
    groups = int(grid[0]) if grid.size else 1
    top = max(min(TAIL_FACTOR * m, m + TAIL_MOST) // groups, m // groups + 1) * groups
    refined = solve_wheels(solution.passage, solution.sleepers.cell, solution.wheel,
                           solution.profile, top, tol=REFINE_TOL, max_iterations=REFINE_STEPS,
                           start=(solution.contact_harmonics, solution.lift,
                                  solution.sleepers.coefficients[:, m:]))
    finer = wrap(solution.passage, solution.wheel, solution.profile, refined)
    t = period_times(solution.period, POINTS)
    change = np.abs(finer.contact_force(t) - solution.contact_force(t))
    if not np.all(np.isfinite(change)):
        return float("nan")
    return float(np.max(change) / np.max(solution.passage.axle_loads))
