"""The semi-analytical method against the time-domain FE model: tables and plots.

The comparison's tables (`comparison_table`, `truncation_table`) and plots
(`plot_comparison`, `plot_error_budget`, with the cases that coincide
grouped by `distinct_cases`).  Book chapter 12 imports everything it uses
from here, so the names of its two other modules are imported here too:

* `railtrack.plotting.book.fe_comparison`: `compare_case`, one of the seven
  foundations of Sections 4.1–4.3 (`paper_cases`) solved by Newton (m = 15
  and m = 200), the paper's fixed point (m = 15, k = 100) and
  `railtrack.simulate_time_domain`, on the time-domain grid; and
  `newton_solve_time`, the median wall time of one Newton solve;
* `railtrack.plotting.book.fe_convergence`: `convergence_study`, the FE
  error against eq. (23) under mesh and time-step refinement.

SI inside; tables and axes in mm and s.  w is positive upward (the train
pushes the sleeper to w < 0); t = 0 when a front wheel is above sleeper 0.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from .fe_comparison import (
    METHODS,
    CaseComparison,
    compare_case,
    fe_against_harmonics,
    newton_solve_time,
    paper_cases,
)
from .fe_convergence import (
    ConvergenceStudy,
    convergence_study,
    convergence_table,
    observed_orders,
    plot_convergence,
)
from .model import markdown_table
from ..style import BLUE, DISPLACEMENT_LABEL, GREEN, MM, ORANGE, TIME_LABEL, VERMILLION, new_figure

__all__ = ["METHODS", "CaseComparison", "paper_cases", "compare_case", "fe_against_harmonics",
           "comparison_table", "truncation_table", "distinct_cases", "plot_comparison", "plot_error_budget",
           "ConvergenceStudy", "observed_orders", "convergence_study", "convergence_table",
           "plot_convergence", "newton_solve_time"]


def _difference(value_mm: float) -> str:
    """Signed difference [mm] to two digits; round-off (< 1e-9 mm) shown as such."""
    return "< 1e-9" if abs(value_mm) < 1e-9 else f"{value_mm:+.1e}"


def comparison_table(cases: Sequence[CaseComparison], digits: int = 4) -> str:
    """Markdown table of min, max and mean w [mm] by Newton m = 15, m = 200 and FE, with differences."""
    rows = []
    for case in cases:
        for i, name in enumerate(("min", "max", "mean")):
            n15, ref, fe = (case.stats(k)[i] * MM for k in ("newton", "reference", "fe"))
            rows.append([case.label if i == 0 else "", name, f"{n15:.{digits}f}",
                         f"{ref:.{digits}f}", f"{fe:.{digits}f}", _difference(fe - ref),
                         _difference(n15 - ref)])
    return markdown_table(["case", "w [mm]", METHODS["newton"], METHODS["reference"], "FE",
                           "FE − (m = 200)", "(m = 15) − (m = 200)"], rows)


def truncation_table(cases: Sequence[CaseComparison]) -> str:
    """Markdown table of the m = 15 truncation and k = 100 iteration errors [mm, % of peak]."""
    def both(error, peak):
        return f"{error * MM:.1e} ({100 * error / peak:.2g} %)"
    rows = []
    for c in cases:
        truncation, iteration = c.error("newton"), c.error("paper", "newton")
        rows.append([c.label, f"{c.peak * MM:.4f}", both(truncation, c.peak),
                     both(iteration, c.peak), both(c.error("paper"), c.peak),
                     f"{c.error('fe') * MM:.1e}",
                     _difference((c.means["newton"] - c.means["reference"]) * MM),
                     _difference((c.means["paper"] - c.means["newton"]) * MM),
                     "truncation" if truncation > iteration else "iteration"])
    return markdown_table(["case", "peak abs(w) [mm]", "m = 15 truncation [mm]",
                           "k = 100 iteration [mm]", "paper's total [mm]", "FE − (m = 200) [mm]",
                           "mean: truncation [mm]", "mean: iteration [mm]", "larger"], rows)


def distinct_cases(cases: Sequence[CaseComparison], rtol: float = 1e-12) -> list[list[CaseComparison]]:
    """Group cases whose reference curves coincide (e.g. linear, bilinear e = 1, cubic eps = 0).

    Two cases are grouped when their m = 200 curves differ by at most `rtol`
    times the peak; the groups keep the order of first appearance.
    """
    groups: list[list[CaseComparison]] = []
    for case in cases:
        for group in groups:
            first = group[0]
            if (first.times.shape == case.times.shape and np.max(np.abs(
                    first.curves["reference"] - case.curves["reference"])) <= rtol * first.peak):
                group.append(case)
                break
        else:
            groups.append([case])
    return groups


def plot_comparison(cases: Sequence[CaseComparison], zoom: int = 25) -> Figure:
    """One row per distinct case: the whole period (left) and a zoom on the deepest point (right).

    Cases with the same response (`distinct_cases`) share a row, titled
    with all their labels.  FE: thick grey; Newton m = 200: dashed black;
    Newton m = 15: thin vermillion, dash-dot.

    Parameters
    ----------
    cases : sequence of CaseComparison
    zoom : int
        Half-width of the zoom window, in FE time steps around the deepest point.

    Returns
    -------
    matplotlib.figure.Figure
        Axes in pairs (full, zoom); the full axes' titles are the group labels
        joined by " = "; t in s on x (ms in the zoom), w in mm on y.
    """
    groups = distinct_cases(cases)
    fig, axes = new_figure(len(groups), 2, width=6.5, height=1.5, squeeze=False,
                           gridspec_kw=dict(width_ratios=(1.7, 1.0)))
    styles = {"fe": dict(color="0.7", ls="-", lw=4.0), "reference": dict(color="black", ls="--", lw=1.0),
              "newton": dict(color=VERMILLION, ls="-.", lw=1.1)}
    for (full, detail), group in zip(axes, groups):
        case = group[0]
        trough = int(np.argmin(case.curves["reference"]))
        window = slice(max(trough - zoom, 0), trough + zoom + 1)
        for key, style in styles.items():
            full.plot(case.times, case.curves[key] * MM, label=METHODS[key], **style)
            detail.plot(case.times[window] * 1e3, case.curves[key][window] * MM, **style)
        full.set_title(" = ".join(c.label for c in group), fontsize=9, loc="left")
        full.set_xlim(0.0, case.times[-1])
        detail.set_title("zoom on the deepest point", fontsize=8, loc="left")
        for ax in (full, detail):
            ax.grid(True, alpha=0.3)
            ax.tick_params(labelsize=8)
    axes[-1, 0].set_xlabel(TIME_LABEL, fontsize=8)
    axes[-1, 1].set_xlabel("time t [ms]", fontsize=8)
    fig.supylabel(DISPLACEMENT_LABEL, fontsize=9)
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside upper center", ncol=3,
               fontsize=8)
    return fig


def plot_error_budget(cases: Sequence[CaseComparison]) -> Figure:
    """max |error| [mm] of each approximation, per case, on a log scale."""
    fig, ax = new_figure(height=3.4)
    errors = {"FE (defaults) − Newton m = 200": ([c.error("fe") for c in cases], "s", BLUE),
              "m = 15 truncation: Newton m = 15 − m = 200":
                  ([c.error("newton") for c in cases], "o", ORANGE),
              "k = 100 iteration: fixed point − Newton m = 15":
                  ([c.error("paper", "newton") for c in cases], "^", GREEN)}
    x = np.arange(len(cases))
    for shift, (label, (values, marker, colour)) in zip((-0.15, 0.0, 0.15), errors.items()):
        ax.semilogy(x + shift, np.array(values) * MM, marker, color=colour, ms=7, label=label)
    ax.set_xticks(x, [c.label for c in cases], rotation=25, ha="right", fontsize=8)
    ax.set_ylabel("max over t of |error| [mm]")
    ax.set_ylim(top=10.0)  # room for the legend above the points
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    return fig
