"""Units, axis labels and the shared look of the book's figures.

The look is meant to be read without colour: the palette is the
colour-blind-safe one of Okabe and Ito (2008), and any two series in one
axes also differ in line style or marker (`series_style`), so that a
reader with a red-green deficiency, or a grey-scale print, tells them
apart.  Every axes made by `new_figure` cycles through `BOOK_CYCLE`.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
from cycler import cycler
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__all__ = [
    "MM",
    "DISPLACEMENT_LABEL",
    "TIME_LABEL",
    "BLACK",
    "ORANGE",
    "SKY_BLUE",
    "GREEN",
    "BLUE",
    "VERMILLION",
    "PURPLE",
    "PALETTE",
    "LINESTYLES",
    "MARKERS",
    "BOOK_CYCLE",
    "series_style",
    "new_figure",
    "label_displacement_axes",
    "plot_sweep",
]

MM = 1e3
"""Metres to millimetres."""

DISPLACEMENT_LABEL = "sleeper displacement w [mm] (up > 0)"
TIME_LABEL = "time t [s] (t = 0: front wheel above the sleeper)"

# The Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design"); its
# yellow (#F0E442) is left out, too pale for a line on white.
BLACK = "#000000"
ORANGE = "#E69F00"
SKY_BLUE = "#56B4E9"
GREEN = "#009E73"       # bluish green
BLUE = "#0072B2"
VERMILLION = "#D55E00"
PURPLE = "#CC79A7"      # reddish purple

PALETTE = (BLUE, ORANGE, GREEN, VERMILLION, PURPLE, SKY_BLUE, BLACK)
"""The book's colours for series, in the order used."""

LINESTYLES = ("-", "--", "-.", (0, (4, 1.5, 1, 1.5, 1, 1.5)), (0, (7, 2)), (0, (1, 1.2)),
              (0, (7, 1.5, 1, 1.5)))
"""Solid, dashed, dash-dot, dash-dot-dot, long dash, dense dots, long dash-dot."""

MARKERS = ("o", "s", "^", "D", "v", "P", "X")
"""Circle, square, triangle up, diamond, triangle down, plus, cross (filled)."""

BOOK_CYCLE = cycler(color=PALETTE) + cycler(linestyle=LINESTYLES)
"""The property cycle of the book's axes: each series a new colour and a new line style."""


def series_style(index: int, count: int | None = None, *, points: int | None = None,
                 linestyle: bool = True, marker: bool = False, markers_per_line: int = 9) -> dict:
    """Keyword arguments for ``ax.plot`` of series `index` of several in one axes.

    Colour, line style and (optionally) marker all change from one series to
    the next, so that no two series differ by colour alone.

    Parameters
    ----------
    index : int
        Which series (0, 1, ...).
    count : int, optional
        How many series share the axes; staggers the markers of different
        series so that they do not sit on top of one another.
    points : int, optional
        Samples of the line; with `marker`, only about `markers_per_line`
        of them carry a marker.
    linestyle : bool
        Vary the line style (else solid).
    marker : bool
        Add a marker.
    markers_per_line : int

    Examples
    --------
    >>> series_style(1)
    {'color': '#E69F00', 'linestyle': '--'}
    >>> series_style(0, 2, points=100, linestyle=False, marker=True)["markevery"]
    (0, 11)
    """
    style = dict(color=PALETTE[index % len(PALETTE)],
                 linestyle=LINESTYLES[index % len(LINESTYLES)] if linestyle else "-")
    if marker:
        style.update(marker=MARKERS[index % len(MARKERS)], markersize=4)
        if points is not None:
            step = max(points // markers_per_line, 1)
            style["markevery"] = ((index * step) // max(count or 1, 1) % step, step)
    return style


def new_figure(rows: int = 1, cols: int = 1, *, width: float = 7.0, height: float = 3.6,
               **kwargs) -> tuple[Figure, Axes]:
    """A figure of the book's size with `rows` x `cols` axes (constrained layout).

    The axes cycle through `BOOK_CYCLE` (colour and line style together).
    """
    with plt.rc_context({"axes.prop_cycle": BOOK_CYCLE}):
        fig, axes = plt.subplots(rows, cols, figsize=(width, height * rows),
                                 layout="constrained", **kwargs)
    return fig, axes


def label_displacement_axes(ax: Axes, *, ylabel: str = DISPLACEMENT_LABEL) -> None:
    """Time on x in seconds, displacement on y in mm, a light grid."""
    ax.set_xlabel(TIME_LABEL)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)


def plot_sweep(x, curves: dict, *, xlabel: str, ylabel: str, marks: dict | None = None,
               ylim_bottom: float | None = None) -> Figure:
    """One line per entry of `curves` against a swept parameter `x`, with labelled marks.

    Parameters
    ----------
    x : array_like
        The swept values (already in the unit of `xlabel`).
    curves : dict of str -> array_like
        Legend label -> values over `x` (already in the unit of `ylabel`).
    xlabel, ylabel : str
        Axis labels, with units.
    marks : dict of str -> float, optional
        Legend label -> x position of a vertical reference line.
    ylim_bottom : float, optional
        Lower limit of the y axis.
    """
    fig, ax = new_figure()
    for (label, values), marker in zip(curves.items(), "osd^v"):
        ax.plot(x, values, marker=marker, ms=3, label=label, gid=label)
    for (label, position), style in zip((marks or {}).items(), (":", "--", "-.")):
        ax.axvline(position, color="0.3", ls=style, lw=0.9, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if ylim_bottom is not None:
        ax.set_ylim(bottom=ylim_bottom)
    ax.grid(True, alpha=0.3)
    ax.legend()
    return fig
