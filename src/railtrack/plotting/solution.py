"""One solution drawn: the sleeper and the rail seat over a period, the bowl along the track.

For any `railtrack.Solution`: ``plot_solution(rt.solve(...))``.  The
classroom explorer (`railtrack.plotting.explorer`) draws its panels with
`draw_solution`, and the book's deflection bowls with `draw_bowl`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from .style import BLUE, MM, ORANGE, VERMILLION, new_figure

__all__ = ["plot_solution", "draw_solution", "draw_bowl"]

PANEL_LABELS = ("time t [ms] (t = 0: front wheel above the sleeper)", "sleeper w [mm] (up > 0)",
                "time t [ms]", "rail-seat load [kN]\n(compression > 0)",
                "x along the track [m] (train moving towards +x), at t = 0",
                "rail, sleepers w [mm]\n(up > 0)")


def draw_bowl(ax, x, rail, sleeper_positions, sleepers, wheels, static=None):
    """Draw one instant of the bowl on `ax` in mm against m; return the artists (rail, sleepers, wheels)."""
    (line,) = ax.plot(x, rail * MM, "-", color=BLUE, lw=1.6, label="rail", gid="rail")
    (dots,) = ax.plot(sleeper_positions, sleepers * MM, "s", color="0.45", ms=3.5,
                      label="sleepers", gid="sleepers")
    (marks,) = ax.plot(wheels, np.zeros_like(wheels) + 0.15, "v", color=VERMILLION, ms=8,
                       label="wheels", gid="wheels")
    if static is not None:
        ax.plot(x, static * MM, "k--", lw=1, label="static Winkler beam", gid="winkler")
    ax.axhline(0.0, color="0.7", lw=0.6)
    ax.set(xlabel="x along the track [m] (train moving towards +x)", ylabel="w [mm] (up > 0)")
    ax.grid(True, alpha=0.3)
    return line, dots, marks



def draw_solution(axes, s, samples: int = 600) -> None:
    """Sleeper displacement and rail-seat load over one period, and the bowl at t = 0, on 3 axes."""
    t = np.linspace(0.0, s.period, samples, endpoint=False)
    axles = np.asarray(s.passage.axle_positions) / float(s.passage.speed)
    for ax, k in ((ax, k) for ax in axes[:2] for k in range(len(axles))):
        ax.axvline(axles[k] * 1e3, color="0.6", ls=":", lw=0.8,
                   label=None if k else "an axle above the sleeper")
    axes[0].plot(t * 1e3, s.sleeper_displacement(t) * MM, color=BLUE, gid="sleeper")
    axes[1].plot(t * 1e3, s.rail_seat_load(t) / 1e3, color=ORANGE, gid="rail_seat")
    x = np.arange(-(max(s.passage.axle_positions) + 6.0), 6.0 + 1e-9, 0.03)
    draw_bowl(axes[2], *s.deflection_bowl(0.0, x))  # x, rail, sleeper positions, sleepers, wheels
    axes[0].legend(fontsize="x-small", loc="best")
    axes[2].legend(fontsize="x-small", ncol=3, loc="lower right")


def plot_solution(solution, samples: int = 600) -> Figure:
    """Three panels of one solution: sleeper w [mm] and rail-seat load [kN] against t [ms]
    over one period, and rail and sleepers [mm] along x [m] at t = 0.

    Examples
    --------
    >>> import railtrack as rt
    >>> fig = plot_solution(rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper()))
    >>> len(fig.axes)
    3
    """
    fig, axes = new_figure(3, 1, height=2.3)
    draw_solution(axes, solution, samples)
    for ax, xlabel, ylabel in zip(axes, PANEL_LABELS[::2], PANEL_LABELS[1::2]):
        ax.set(xlabel=xlabel, ylabel=ylabel)
        ax.grid(True, alpha=0.3)
    return fig
