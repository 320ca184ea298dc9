"""Figures 3–7 of Hoang et al. (2015), recomputed with `railtrack`.

Each paper figure has a data function, ``figureN_data``, that solves the
cases the figure shows and returns them as `PanelData` (arrays in SI
units, no plotting), and a plotting function, ``figureN``, that draws them
and returns a `matplotlib.figure.Figure` with millimetres and seconds on
the axes.  The defaults are the paper's parameters:

* the track and train of Table 1, `Passage.paper()`;
* linear foundation k2 = 20 MN/m, eta2 = 0.2 MN s/m (eq. 22, Figure 3);
* bilinear foundation k2+ = 20 MN/m, k2- = e k2+, e = 0.5 (eq. 24,
  Figures 4 and 5);
* cubic foundation k2 = 20 MN/m, k3 = 20 kN/mm^3 = 2e13 N/m^3, eps = 0.8
  (eq. 25, Figures 6 and 7);
* m = 15 harmonics and k = 100 iterations unless the figure varies them.

The paper's curves come from its fixed-point iteration, eq. (21), run for
k steps from c = 0 (``method="fixed-point", max_iterations=k``; none of
the paper's cases reaches the tolerance 1e-10 sooner).  Every
figure also carries a reference curve that has converged (Newton's method
to a relative residual of 1e-10, or eq. 23 for the linear law), drawn
dashed black, so that the reader sees what the iteration is tending to.

Conventions: w is positive upward, so the train pushes the sleeper to
w < 0; t = 0 when a front wheel is above the sleeper, the back wheel
follows at D / v, and the plots show one period T = H / v.

Examples
--------
>>> from railtrack.plotting.book.paper_figures import figure3_data
>>> data = figure3_data()
>>> data.values
(15, 100)
>>> bool(data.errors()[1] < 1e-7)      # k = 100 is within 0.1 um of eq. (23)
True
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ... import BilinearFoundation, CubicFoundation, LinearFoundation, Passage
from ...equations.load import wheel_passage_times
from .paper_figure_data import (
    figure3_data,
    figure4_data,
    figure5_data,
    figure6_data,
    figure7_data,
    harmonic_convergence_data,
)
from .panels import PAPER_HARMONICS, PAPER_ITERATIONS, PanelData
from ..style import BLUE, MARKERS, MM, ORANGE, PURPLE, VERMILLION, label_displacement_axes, new_figure

__all__ = [
    "PAPER_HARMONICS",
    "PAPER_ITERATIONS",
    "PanelData",
    "figure3_data",
    "figure4_data",
    "figure5_data",
    "figure6_data",
    "figure7_data",
    "harmonic_convergence_data",
    "figure3",
    "figure4",
    "figure5",
    "figure6",
    "figure7",
]

_SYMBOLS = {"k": "k", "m": "m", "e": "e", "epsilon": "ε"}


def _colours(count: int) -> list:
    return [plt.get_cmap("viridis")(x) for x in np.linspace(0.0, 0.85, count)]


def _markers(index: int, count: int, points: int, per_line: int = 10) -> dict:
    """Marker of curve `index` of `count`, about `per_line` of them, staggered between curves.

    The curves of a panel differ in colour (ordered along viridis) and in
    marker, so that they can be told apart without colour.
    """
    step = max(points // per_line, 1)
    return dict(marker=MARKERS[index % len(MARKERS)], markersize=4.5,
                markevery=((index * step) // max(count, 1) % step, step))


_FIGURE3_COLOURS = (VERMILLION, BLUE, PURPLE, ORANGE)


def _mark_wheels(ax: Axes, passage: Passage) -> None:
    """Dotted verticals where a wheel is above the sleeper (front at 0 and T, back at D/v)."""
    front, back = wheel_passage_times(passage)
    for time, name in ((front, "front wheel"), (back, "back wheel"), (passage.period, None)):
        ax.axvline(time, color="0.6", linestyle=":", linewidth=0.8, zorder=0)
        if name:
            ax.text(time, 0.98, f"{name} ", transform=ax.get_xaxis_transform(),
                    fontsize=7, color="0.4", rotation=90, va="top", ha="left")


def _draw_panel(ax: Axes, data: PanelData, passage: Passage, *, title: str) -> None:
    symbol = _SYMBOLS.get(data.parameter, data.parameter)
    count = len(data.values)
    for n, (colour, value, w) in enumerate(zip(_colours(count), data.values, data.displacements)):
        ax.plot(data.times, w * MM, "-", color=colour, linewidth=1.4, label=f"{symbol} = {value:g}",
                **_markers(n, count, len(data.times)))
    references = np.atleast_2d(data.reference)
    for i, w in enumerate(references):
        ax.plot(data.times, w * MM, color="black", linestyle="--", linewidth=0.9,
                label=f"{data.reference_label} (converged)" if i == 0 else None)
    _mark_wheels(ax, passage)
    label_displacement_axes(ax)
    ax.set_xlim(0.0, passage.period)
    ax.set_title(f"{title}: {data.method}", fontsize=10)
    ax.legend(loc="lower center", bbox_to_anchor=(0.62, 0.02), fontsize=7.5, ncol=2)


def _single_panel(data_function, passage, foundation, title: str, **kwargs) -> Figure:
    """Draw the one panel that `data_function` computes (Figures 5, 6 and 7)."""
    passage = Passage.paper() if passage is None else passage
    fig, ax = new_figure()
    _draw_panel(ax, data_function(passage, foundation, **kwargs), passage, title=title)
    return fig


def figure3(passage: Passage | None = None, foundation: LinearFoundation | None = None,
            **kwargs) -> Figure:
    """Figure 3 of the paper: linear foundation, analytic (eq. 23) against eq. (21).

    Eq. (23) is a thick grey band, each k its own colour and marker, and
    Newton's solution dashed black.  Keyword arguments are those of `figure3_data`.
    """
    passage = Passage.paper() if passage is None else passage
    data = figure3_data(passage, foundation, **kwargs)
    fig, ax = new_figure()
    ax.plot(data.times, data.reference * MM, "-", color="0.75", linewidth=4.0,
            label=data.reference_label)
    count = len(data.values)
    for n, (k, w) in enumerate(zip(data.values, data.displacements)):
        ax.plot(data.times, w * MM, "-", color=_FIGURE3_COLOURS[n % len(_FIGURE3_COLOURS)],
                linewidth=1.4, label=f"fixed point, eq. (21), k = {k}",
                **_markers(n, count, len(data.times)))
    ax.plot(data.times, data.extra["Newton"] * MM, color="black", linestyle="--",
            linewidth=0.9, label="Newton (converged)")
    _mark_wheels(ax, passage)
    label_displacement_axes(ax)
    ax.set_xlim(0.0, passage.period)
    ax.set_title(f"Linear foundation, m = {data.solutions[0].harmonics}", fontsize=10)
    ax.legend(loc="lower center", bbox_to_anchor=(0.62, 0.02), fontsize=8)
    return fig


def figure4(passage: Passage | None = None, foundation: BilinearFoundation | None = None,
            **kwargs) -> Figure:
    """Figure 4 of the paper: bilinear foundation, varying m (upper) and k (lower).

    Keyword arguments are those of `figure4_data`.
    """
    passage = Passage.paper() if passage is None else passage
    upper, lower = figure4_data(passage, foundation, **kwargs)
    fig, axes = new_figure(2, 1, sharex=True)
    _draw_panel(axes[0], upper, passage, title="Number of harmonics m")
    _draw_panel(axes[1], lower, passage, title="Number of iterations k")
    axes[0].set_xlabel("")
    return fig


def figure5(passage: Passage | None = None, foundation: BilinearFoundation | None = None,
            **kwargs) -> Figure:
    """Figure 5 of the paper: bilinear foundation for several e = k2-/k2+.

    Keyword arguments are those of `figure5_data`.
    """
    return _single_panel(figure5_data, passage, foundation, r"Ratio $e = k_2^- / k_2^+$", **kwargs)


def figure6(passage: Passage | None = None, foundation: CubicFoundation | None = None,
            **kwargs) -> Figure:
    """Figure 6 of the paper: cubic foundation, several numbers of iterations k.

    Keyword arguments are those of `figure6_data`.
    """
    return _single_panel(figure6_data, passage, foundation, "Number of iterations k", **kwargs)


def figure7(passage: Passage | None = None, foundation: CubicFoundation | None = None,
            **kwargs) -> Figure:
    """Figure 7 of the paper: cubic foundation for several eps.

    Keyword arguments are those of `figure7_data`.
    """
    return _single_panel(figure7_data, passage, foundation, "Nonlinearity parameter ε", **kwargs)
