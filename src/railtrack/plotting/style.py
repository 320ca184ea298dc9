"""Units, axis labels and the shared look of the book's figures."""

from __future__ import annotations

import matplotlib.pyplot as plt
from matplotlib.axes import Axes
from matplotlib.figure import Figure

__all__ = ["MM", "DISPLACEMENT_LABEL", "TIME_LABEL", "new_figure", "label_displacement_axes"]

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
