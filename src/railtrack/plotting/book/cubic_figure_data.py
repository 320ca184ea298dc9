"""Data of Figures 6 and 7 of Hoang et al. (2015): the cubic foundation, eq. (25).

`figure6_data` runs the paper's fixed point, eq. (21), for several numbers
k of steps; `figure7_data` for several nonlinearity parameters eps.  Each
returns `PanelData` (SI units) with Newton references at the same m;
`railtrack.plotting.book.paper_figure_data` imports them, and
`railtrack.plotting.book.paper_figures` draws them.
"""

from __future__ import annotations

import dataclasses
from typing import Sequence

from ... import CubicFoundation, Passage
from .panels import (
    PAPER_HARMONICS,
    PAPER_ITERATIONS,
    POINTS,
    PanelData,
    paper_iteration,
    make_panel,
    converged_reference,
    reference_label_for,
    period_times,
)

__all__ = ["figure6_data", "figure7_data"]


def figure6_data(
    passage: Passage | None = None,
    foundation: CubicFoundation | None = None,
    *,
    iterations: Sequence[int] = (5, 10, 15, 30, 100),
    harmonics: int = PAPER_HARMONICS,
    points: int = POINTS,
) -> PanelData:
    """Figure 6: cubic foundation, several numbers k of fixed-point steps.

    Parameters
    ----------
    passage : Passage, optional
        Default Table 1.
    foundation : CubicFoundation, optional
        Default `CubicFoundation.paper(0.8)`: k2 = 20 MN/m,
        k3 = 2e13 N/m^3, eps = 0.8, eta2 = 0.2 MN s/m.
    iterations : sequence of int
    harmonics : int
    points : int

    Returns
    -------
    PanelData
        parameter "k"; reference = Newton at the same m.
    """
    passage = Passage.paper() if passage is None else passage
    foundation = CubicFoundation.paper(0.8) if foundation is None else foundation
    times = period_times(passage, points)
    return make_panel(
        "k", iterations, times,
        [paper_iteration(passage, foundation, harmonics, k) for k in iterations],
        [converged_reference(passage, foundation, harmonics)],
        reference_label_for(foundation, harmonics), f"fixed point, m = {harmonics}",
    )


def figure7_data(
    passage: Passage | None = None,
    foundation: CubicFoundation | None = None,
    *,
    epsilons: Sequence[float] = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0),
    harmonics: int = PAPER_HARMONICS,
    iterations: int = PAPER_ITERATIONS,
    points: int = POINTS,
) -> PanelData:
    """Figure 7: cubic foundation for several nonlinearity parameters eps.

    Parameters
    ----------
    passage : Passage, optional
        Default Table 1.
    foundation : CubicFoundation, optional
        Supplies k2, k3 and eta2 (default `CubicFoundation.paper()`); its
        epsilon is replaced by each value.
    epsilons : sequence of float
        eps >= 0; eps = 0 is the linear law.
    harmonics, iterations : int
        m and k of the fixed point (paper: 15, 100).
    points : int

    Returns
    -------
    PanelData
        parameter "epsilon"; one Newton reference per eps.
    """
    passage = Passage.paper() if passage is None else passage
    base = CubicFoundation.paper() if foundation is None else foundation
    laws = [dataclasses.replace(base, epsilon=eps) for eps in epsilons]
    times = period_times(passage, points)
    return make_panel(
        "epsilon", epsilons, times,
        [paper_iteration(passage, law, harmonics, iterations) for law in laws],
        [converged_reference(passage, law, harmonics) for law in laws],
        reference_label_for(base, harmonics), f"fixed point, m = {harmonics}, k = {iterations}",
    )
