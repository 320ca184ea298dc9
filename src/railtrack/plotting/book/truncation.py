"""How many harmonics the wagon length needs: data, table and figure for chapter 5.

For a list of wagon lengths H (everything else as in Table 1), `truncation_study`
solves the same law at the paper's m = 15, with ``harmonics="auto"``, and at
a reference m of six harmonics per sleeper-passing frequency (6 H / L, about
seven times what an accuracy of 1e-3 needs), and measures each error
against the reference in max norm over the period relative to the peak.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter

from ...solvers.solution import TruncationWarning
from ...solvers.solve import solve
from ...model.passage import Passage
from ..style import BLUE, ORANGE, new_figure
from .tables import markdown_table

__all__ = ["TruncationStudy", "truncation_study", "truncation_table", "plot_truncation"]


@dataclass(frozen=True)
class TruncationStudy:
    """Errors of m = 15 and of harmonics="auto" against a reference, per wagon length.

    Attributes
    ----------
    wagon_lengths : ndarray, shape (K,)
        H [m].
    spans : ndarray, shape (K,)
        H / L, harmonics per sleeper-passing frequency v / L [-].
    error_15, estimate_15 : ndarray, shape (K,)
        True and estimated relative truncation error at m = 15 [-].
    auto_harmonics : ndarray of int, shape (K,)
        The m that harmonics="auto" chose for `accuracy`.
    error_auto, estimate_auto : ndarray, shape (K,)
        True and estimated relative error of that solve [-].
    reference_harmonics : ndarray of int, shape (K,)
        m of the reference solves.
    accuracy : float
        The accuracy asked of "auto" [-].
    """

    wagon_lengths: np.ndarray
    spans: np.ndarray
    error_15: np.ndarray
    estimate_15: np.ndarray
    auto_harmonics: np.ndarray
    error_auto: np.ndarray
    estimate_auto: np.ndarray
    reference_harmonics: np.ndarray
    accuracy: float


def _relative_error(solution, reference) -> float:
    t = np.linspace(0.0, reference.period, 8 * reference.harmonics, endpoint=False)
    exact = reference.sleeper_displacement(t)
    return float(np.max(np.abs(solution.sleeper_displacement(t) - exact)) / np.max(np.abs(exact)))


def truncation_study(passage: Passage, foundation, wagon_lengths, accuracy: float = 1e-3) -> TruncationStudy:
    """Solve at m = 15, "auto" and a reference m for each wagon length H [m]."""
    rows = []
    for length in wagon_lengths:
        case = passage.replace(wagon_length=float(length))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", TruncationWarning)   # m = 15 is the point here
            paper = solve(case.track, case.train, foundation, 15, strict=True)
            auto = solve(case.track, case.train, foundation, accuracy=accuracy, strict=True)
            m_ref = int(round(6 * case.wagon_length / case.sleeper_spacing))
            start = np.zeros(m_ref + 1, dtype=complex)
            start[: auto.harmonics + 1] = auto.coefficients[auto.harmonics :]
            reference = solve(case.track, case.train, foundation, m_ref, initial=start, strict=True)
        rows.append((case.wagon_length / case.sleeper_spacing,
                     _relative_error(paper, reference), paper.truncation_error,
                     auto.harmonics, _relative_error(auto, reference), auto.truncation_error, m_ref))
    spans, e15, s15, m_auto, e_auto, s_auto, m_ref = (np.array(column) for column in zip(*rows))
    return TruncationStudy(np.asarray(wagon_lengths, dtype=float), spans, e15, s15,
                           m_auto.astype(int), e_auto, s_auto, m_ref.astype(int), float(accuracy))


def truncation_table(study: TruncationStudy) -> str:
    """Markdown table: per H, the errors at m = 15 and the m that "auto" picks."""
    header = ["wagon H [m]", "H / L", "error at m = 15", "estimate at m = 15",
              f"m for {study.accuracy:.0e}", "its error", "its estimate", "reference m"]
    rows = [
        [f"{h:g}", f"{s:.0f}", f"{e:.2%}", f"{se:.2%}", m, f"{ea:.2%}", f"{sa:.2%}", mr]
        for h, s, e, se, m, ea, sa, mr in zip(
            study.wagon_lengths, study.spans, study.error_15, study.estimate_15,
            study.auto_harmonics, study.error_auto, study.estimate_auto, study.reference_harmonics)
    ]
    return markdown_table(header, rows)


def plot_truncation(study: TruncationStudy) -> Figure:
    """Left: error at m = 15 (true and estimated) against H; right: the m that "auto" picks."""
    fig, (left, right) = new_figure(1, 2, width=8.0, height=3.4)
    left.loglog(study.wagon_lengths, 100 * study.error_15, "o-", color=BLUE,
                label="true (against reference)")
    left.loglog(study.wagon_lengths, 100 * study.estimate_15, "x--", color=ORANGE, label="estimated")
    left.set_xticks(study.wagon_lengths, [f"{h:g}" for h in study.wagon_lengths])
    left.xaxis.set_minor_formatter(NullFormatter())
    left.set_xlabel("wagon length H [m]")
    left.set_ylabel("error of w at m = 15 [% of peak]")
    left.legend()
    right.plot(study.spans, study.auto_harmonics, "o-", color=BLUE,
               label=f"m for accuracy {study.accuracy:.0e}")
    right.plot(study.spans, np.full_like(study.spans, 15.0), "k:", label="the paper's m = 15")
    right.set_xlabel("harmonics per sleeper passing, H / L")
    right.set_ylabel("harmonics m")
    right.legend()
    for ax in (left, right):
        ax.grid(True, alpha=0.3, which="both")
    return fig
