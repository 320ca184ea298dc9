"""The rail along one span while a wheel crosses it (book chapter 2).

`rail_span_profiles` samples w_r(x, t) of a solved case over 0 <= x <= L
(the observed sleeper at x = 0, the next one ahead at x = L) at the instants
when the front wheel is at given positions; `plot_rail_span` draws them.
SI inside; the figure shows mm against m.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from ..style import MM, new_figure

__all__ = ["rail_span_profiles", "plot_rail_span"]


def rail_span_profiles(solution, wheel_positions: Sequence[float], points: int = 121):
    """Rail displacement along one span with the front wheel at each given position.

    Parameters
    ----------
    solution : railtrack.Solution
    wheel_positions : sequence of float
        Where the front wheel is, ahead of the observed sleeper [m]; the
        instant is ``t = position / v`` (t = 0: wheel above the sleeper).
    points : int
        Samples over 0 <= x <= L.

    Returns
    -------
    x : ndarray, shape (points,)
        Positions [m].
    w : ndarray, shape (len(wheel_positions), points)
        w_r(x, t) [m], positive upward.
    """
    passage = solution.passage
    x = np.linspace(0.0, passage.sleeper_spacing, points)
    t = np.asarray(wheel_positions, dtype=float) / passage.speed
    return x, solution.rail_displacement(t[:, None], x[None, :])


def plot_rail_span(solution, wheel_positions: Sequence[float], points: int = 121) -> Figure:
    """One line of w_r(x) [mm] against x [m] per wheel position, sleepers and wheels marked."""
    x, w = rail_span_profiles(solution, wheel_positions, points)
    span = solution.passage.sleeper_spacing
    fig, ax = new_figure()
    for position, values, marker in zip(wheel_positions, w, "osd^vx"):
        label = f"front wheel at {position:+.2f} m"
        (line,) = ax.plot(x, values * MM, ls="-", marker=marker, markevery=max(points // 8, 1), ms=3,
                          label=label, gid=label)
        if 0.0 <= position <= span:
            ax.axvline(position, color=line.get_color(), ls=":", lw=1)
    for sleeper in (0.0, span):
        ax.axvline(sleeper, color="0.5", lw=2, alpha=0.4)
    ax.set_xlabel("x, ahead of the observed sleeper [m] (sleepers at 0 and L)")
    ax.set_ylabel("rail displacement w_r [mm] (up > 0)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return fig
