"""Units, axis labels and the shared look of the book's figures."""

from __future__ import annotations

import matplotlib.pyplot as plt
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__all__ = [
    "MM",
    "DISPLACEMENT_LABEL",
    "TIME_LABEL",
    "new_figure",
    "label_displacement_axes",
    "plot_sweep",
]

MM = 1e3
"""Metres to millimetres."""

DISPLACEMENT_LABEL = "sleeper displacement w [mm] (up > 0)"
TIME_LABEL = "time t [s] (t = 0: front wheel above the sleeper)"


def new_figure(rows: int = 1, cols: int = 1, *, width: float = 7.0, height: float = 3.6,
               **kwargs) -> tuple[Figure, Axes]:
    """A figure of the book's size with `rows` x `cols` axes (constrained layout)."""
    fig, axes = plt.subplots(rows, cols, figsize=(width, height * rows), layout="constrained",
                             **kwargs)
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
