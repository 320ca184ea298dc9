"""Data of Figures 4 and 5 of Hoang et al. (2015): the bilinear foundation, eq. (24).

`figure4_data` runs the paper's fixed point, eq. (21), for several numbers
m of harmonics and k of steps (its convergence in m and in k);
`figure5_data` for several ratios e = k2- / k2+ of tension to compression
stiffness; `harmonic_convergence_data` solves Figure 4's foundation by
Newton for several m, so that the truncation error is seen without the
fixed point's iteration error.  Each returns `PanelData` (SI units) with
converged references; `railtrack.plotting.book.paper_figure_data` imports
them, and `railtrack.plotting.book.paper_figures` draws them.
"""

from __future__ import annotations

import dataclasses
import warnings
from typing import Sequence

from ... import BilinearFoundation, Passage, TruncationWarning, solve
from .panels import (
    PAPER_HARMONICS,
    PAPER_ITERATIONS,
    POINTS,
    REFERENCE_TOL,
    PanelData,
    paper_iteration,
    make_panel,
    converged_reference,
    reference_label_for,
    period_times,
)

__all__ = ["figure4_data", "figure5_data", "harmonic_convergence_data"]


def figure4_data(
    passage: Passage | None = None,
    foundation: BilinearFoundation | None = None,
    *,
    harmonics: Sequence[int] = (1, 3, 5, 10, 15, 20),
    iterations: Sequence[int] = (5, 15, 30, 100),
    fixed_harmonics: int = PAPER_HARMONICS,
    fixed_iterations: int = PAPER_ITERATIONS,
    reference_harmonics: int = 40,
    points: int = POINTS,
) -> tuple[PanelData, PanelData]:
    """Figure 4: bilinear foundation, convergence in m (upper) and in k (lower).

    Parameters
    ----------
    passage : Passage, optional
        Default Table 1.
    foundation : BilinearFoundation, optional
        Default `BilinearFoundation.paper(0.5)`: k2+ = 20 MN/m, k2- = 10 MN/m,
        eta2 = 0.2 MN s/m.
    harmonics : sequence of int
        Numbers m of harmonics of the upper panel, each run for
        `fixed_iterations` steps.
    iterations : sequence of int
        Numbers k of steps of the lower panel, each with `fixed_harmonics`.
    fixed_harmonics, fixed_iterations : int
        The m of the lower panel and the k of the upper one (paper: 15, 100).
    reference_harmonics : int
        m of the converged Newton reference of the upper panel (the lower
        panel's reference is Newton at `fixed_harmonics`).
    points : int

    Returns
    -------
    (PanelData, PanelData)
        The upper (parameter "m") and the lower (parameter "k") panel.
    """
    passage = Passage.paper() if passage is None else passage
    foundation = BilinearFoundation.paper(0.5) if foundation is None else foundation
    times = period_times(passage, points)
    by_m = [paper_iteration(passage, foundation, m, fixed_iterations) for m in harmonics]
    by_k = [paper_iteration(passage, foundation, fixed_harmonics, k) for k in iterations]
    upper = make_panel(
        "m", harmonics, times, by_m, [converged_reference(passage, foundation, reference_harmonics)],
        reference_label_for(foundation, reference_harmonics), f"fixed point, k = {fixed_iterations}",
    )
    lower = make_panel(
        "k", iterations, times, by_k, [converged_reference(passage, foundation, fixed_harmonics)],
        reference_label_for(foundation, fixed_harmonics), f"fixed point, m = {fixed_harmonics}",
    )
    return upper, lower


def figure5_data(
    passage: Passage | None = None,
    foundation: BilinearFoundation | None = None,
    *,
    ratios: Sequence[float] = (1.0, 0.75, 0.5, 0.25, 0.0),
    harmonics: int = PAPER_HARMONICS,
    iterations: int = PAPER_ITERATIONS,
    points: int = POINTS,
) -> PanelData:
    """Figure 5: bilinear foundation for several ratios e = k2- / k2+.

    Parameters
    ----------
    passage : Passage, optional
        Default Table 1.
    foundation : BilinearFoundation, optional
        Supplies k2+ and eta2 (default `BilinearFoundation.paper()`); its
        tension stiffness is replaced by e k2+ for each e.
    ratios : sequence of float
        e, each >= 0; e = 1 is the linear law, e = 0 a tensionless foundation.
    harmonics, iterations : int
        m and k of the fixed point (paper: 15, 100).
    points : int

    Returns
    -------
    PanelData
        parameter "e"; one Newton reference per ratio.
    """
    passage = Passage.paper() if passage is None else passage
    base = BilinearFoundation.paper() if foundation is None else foundation
    laws = [
        dataclasses.replace(base, tension_stiffness=e * base.compression_stiffness)
        for e in ratios
    ]
    times = period_times(passage, points)
    return make_panel(
        "e", ratios, times,
        [paper_iteration(passage, law, harmonics, iterations) for law in laws],
        [converged_reference(passage, law, harmonics) for law in laws],
        reference_label_for(base, harmonics), f"fixed point, m = {harmonics}, k = {iterations}",
    )


def harmonic_convergence_data(
    passage: Passage | None = None,
    foundation=None,
    *,
    harmonics: Sequence[int] = (5, 10, 15, 20, 40),
    reference_harmonics: int = 80,
    points: int = POINTS,
) -> PanelData:
    """Converged (Newton) responses for several m, against a much larger m.

    Separates the truncation error of eq. (19) from the iteration error
    that the fixed point adds in Figure 4.

    Parameters
    ----------
    passage : Passage, optional
        Default Table 1.
    foundation : optional
        Any law; default `BilinearFoundation.paper(0.5)`.
    harmonics : sequence of int
        m of each curve.
    reference_harmonics : int
        m of the reference curve.
    points : int

    Returns
    -------
    PanelData
        parameter "m"; every curve solved by Newton to a relative residual
        of 1e-10; the reference likewise (eq. 23 for a linear law).
    """
    passage = Passage.paper() if passage is None else passage
    foundation = BilinearFoundation.paper(0.5) if foundation is None else foundation
    times = period_times(passage, points)
    with warnings.catch_warnings():
        # small m on purpose: the figure shows what truncation costs
        warnings.simplefilter("ignore", TruncationWarning)
        solutions = [
            solve(passage.track, passage.train, foundation, m, method="newton", tol=REFERENCE_TOL, strict=True)
            for m in harmonics
        ]
    return make_panel("m", harmonics, times, solutions,
                  [converged_reference(passage, foundation, reference_harmonics)],
                  reference_label_for(foundation, reference_harmonics), "Newton")
