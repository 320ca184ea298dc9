"""Data of Figures 3–7 of Hoang et al. (2015): the curves, computed, not drawn.

Each ``figureN_data`` solves the cases Figure N shows and returns them as
`PanelData` (SI units).  The paper's curves come from its fixed-point
iteration, eq. (21), run for exactly k steps from c = 0; each panel also
carries a converged reference (eq. 23 for the linear law, Newton to a
relative residual of 1e-10 otherwise).

Figure 3 (the linear foundation, eq. 22) is computed here.  The bilinear
foundation's Figures 4 and 5, with `harmonic_convergence_data` (Figure 4's
convergence in m by Newton), are computed in
`railtrack.plotting.book.bilinear_figure_data`, the cubic foundation's
Figures 6 and 7 in `railtrack.plotting.book.cubic_figure_data`; their names
are imported here, so that the data of all five figures import from this
module.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np

from ... import LinearFoundation, Passage, solve
from .bilinear_figure_data import figure4_data, figure5_data, harmonic_convergence_data
from .cubic_figure_data import figure6_data, figure7_data
from .panels import (
    PAPER_HARMONICS,
    POINTS,
    REFERENCE_TOL,
    PanelData,
    paper_iteration,
    make_panel,
    converged_reference,
    period_times,
)

__all__ = [
    "figure3_data",
    "figure4_data",
    "figure5_data",
    "figure6_data",
    "figure7_data",
    "harmonic_convergence_data",
]


def figure3_data(
    passage: Passage | None = None,
    foundation: LinearFoundation | None = None,
    *,
    iterations: Sequence[int] = (15, 100),
    harmonics: int = PAPER_HARMONICS,
    points: int = POINTS,
) -> PanelData:
    """Figure 3: linear foundation, eq. (23) against k steps of eq. (21).

    Parameters
    ----------
    passage : Passage, optional
        Default `Passage.paper()` (Table 1).
    foundation : LinearFoundation, optional
        Default `LinearFoundation.paper()`: k2 = 20 MN/m, eta2 = 0.2 MN s/m.
    iterations : sequence of int
        Numbers k of fixed-point steps, one curve each.
    harmonics : int
        m.
    points : int
        Time samples over one period.

    Returns
    -------
    PanelData
        parameter "k"; reference = the analytic solution eq. (23);
        ``extra["Newton"]`` = Newton's solution of eq. (17), started from
        c = 0.
    """
    passage = Passage.paper() if passage is None else passage
    foundation = LinearFoundation.paper() if foundation is None else foundation
    times = period_times(passage, points)
    solutions = [paper_iteration(passage, foundation, harmonics, k) for k in iterations]
    analytic = converged_reference(passage, foundation, harmonics)
    # Newton from c = 0, not from its default start (eq. 23 itself for a linear law),
    # so that its agreement with eq. (23) is an independent check.
    newton = solve(passage.track, passage.train, foundation, harmonics, method="newton", tol=REFERENCE_TOL,
                   strict=True, initial=np.zeros(harmonics + 1))
    return make_panel("k", iterations, times, solutions, [analytic], "analytic, eq. (23)",
                  f"fixed point, eq. (21), m = {harmonics}",
                  extra={"Newton": newton.sleeper_displacement(times)})
