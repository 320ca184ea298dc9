"""Figures of the chapter "Sleepers that differ": the bowl over a void, the loads, the scatter.

Each function draws what the library computed; nothing is solved here.
Units on the page: mm, kN, kN m, m; the library's SI values are converted.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..style import MM, new_figure, series_style

__all__ = ["plot_bowl", "plot_seat_histories", "plot_random_support"]

KN = 1e-3


def plot_bowl(solutions: dict, at: int, *, wheel_over: tuple[int, ...] = (-1, 0, 1),
              reach: int = 5, points: int = 601) -> Figure:
    """Rail displacement along the track around sleeper `at`, first wheel above sleepers
    ``at + k`` for k in `wheel_over` (one panel each), one line per solution."""
    fig, axes = new_figure(len(wheel_over), 1, height=2.2, sharex=True)
    axes = np.atleast_1d(axes)
    first = next(iter(solutions.values()))
    span, speed = first.passage.sleeper_spacing, float(first.passage.speed)
    x = np.linspace((at - reach) * span, (at + reach) * span, points)
    for ax, k in zip(axes, wheel_over):
        t = (at + k) * span / speed
        for i, (label, solution) in enumerate(solutions.items()):
            ax.plot(x, solution.rail_displacement(t, x) * MM, label=label,
                    **series_style(i))
        ax.axvline(at * span, color="0.6", lw=0.8)
        for d in first.passage.axle_positions:
            ax.plot([(at + k) * span - d], [0.0], marker="v", color="k", ms=6)
        ax.set_ylabel("rail w [mm]")
        ax.set_title(f"first wheel above sleeper {at + k}", fontsize=9)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("position along the track x [m] (grey: the hanging sleeper)")
    axes[0].legend(fontsize=8, loc="lower left")
    return fig


def plot_seat_histories(solutions: dict, sleepers: tuple[int, ...]) -> Figure:
    """Rail-seat load against time of the given sleepers (one panel each)."""
    fig, axes = new_figure(1, len(sleepers), width=7.5, height=2.8, sharey=True)
    axes = np.atleast_1d(axes)
    for ax, j in zip(axes, sleepers):
        for i, (label, solution) in enumerate(solutions.items()):
            t = solution.one_period(1200)[0]
            ax.plot(t * 1e3, solution.rail_seat_load(t)[j] * KN, label=label,
                    **series_style(i))
        ax.set_title(f"sleeper {j}", fontsize=9)
        ax.set_xlabel("time t [ms]")
        ax.grid(True, alpha=0.3)
    axes[0].set_ylabel("rail-seat load [kN]")
    axes[0].legend(fontsize=7)
    return fig


def plot_random_support(samples: dict, sound: tuple[float, float]) -> Figure:
    """Peak rail-seat load and peak sagging moment of each draw against the coefficient of
    variation, with the sound track's values as a line; `sound` is (load [N], moment [N m])."""
    fig, axes = new_figure(1, 2, width=7.5, height=3.0)
    rng = np.random.default_rng(0)   # horizontal jitter only, so that the points do not pile up
    for ax, key, base, unit in ((axes[0], "peak_seat_load", sound[0], "rail-seat load [kN]"),
                                (axes[1], "peak_moment", sound[1], "sagging moment [kN m]")):
        for i, (variation, sample) in enumerate(samples.items()):
            values = getattr(sample, key)[sample.converged] * KN
            jitter = variation + 0.012 * rng.uniform(-1, 1, values.size)
            ax.plot(jitter, values, linestyle="none", marker="o", ms=2.5, alpha=0.5,
                    color=series_style(i)["color"])
            ax.plot([variation], [np.median(values)], marker="_", ms=18, color="k")
        ax.axhline(base * KN, color="0.4", lw=1, ls="--", label="sound track")
        ax.set_xlabel("coefficient of variation of k2 [-]")
        ax.set_ylabel(f"largest {unit}")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    return fig
