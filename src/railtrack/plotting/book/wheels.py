"""Figures of the chapter "The wheel on the rail": contact forces, the dip, the P2 force, Timoshenko.

Each function draws what the library computed; nothing is solved here.
Units on the page: kN, mm, um, m, m/s, Hz; the library's SI values are converted.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from ..style import new_figure, series_style

__all__ = ["plot_contact_along_track", "plot_dip_against_speed", "plot_loss_of_contact",
           "plot_rail_receptances", "plot_sleeper_passing"]

KN = 1e-3


def _shade_dip(ax, dip) -> None:
    """Shade the dip's extent, centre +- length / 2 [m], and mark its lowest point."""
    if dip is None:
        return
    half = 0.5 * float(dip.length)
    ax.axvspan(dip.centre - half, dip.centre + half, color="tab:orange", alpha=0.12, lw=0,
               zorder=0, label="dip")
    ax.axvline(dip.centre, color="tab:orange", lw=0.8, ls="--", zorder=0)


def plot_contact_along_track(solutions: dict, wheel: int = 0, window: tuple[float, float] | None
                             = None, samples: int = 4096, sleepers: bool = True,
                             dip=None) -> Figure:
    """Contact force of wheel `wheel` against its position along the track, one line each.

    `window` (x_min, x_max) [m] limits the abscissa (default: one wagon length);
    thin grey vertical lines mark the sleepers; `dip` (a `CosineDip`) is shaded,
    its lowest point dashed.
    """
    fig, ax = new_figure(1, 1, width=7.0, height=3.0)
    first = next(iter(solutions.values()))
    wagon, span = float(first.passage.wagon_length), float(first.passage.sleeper_spacing)
    lo, hi = (0.0, wagon) if window is None else window
    for i, (label, solution) in enumerate(solutions.items()):
        t = solution.one_period(samples)[0]
        x = np.mod(solution.wheel_position(t)[wheel], wagon)
        order = np.argsort(x)
        force = solution.contact_force(t)[wheel][order] * KN
        keep = (x[order] >= lo) & (x[order] <= hi)
        ax.plot(x[order][keep], force[keep], label=label, **series_style(i))
    if sleepers:
        for xs in np.arange(np.ceil(lo / span), np.floor(hi / span) + 1) * span:
            ax.axvline(xs, color="0.8", lw=0.6, zorder=0)
    _shade_dip(ax, dip)
    ax.set_xlim(lo, hi)
    ax.set_xlabel("wheel position along the track x [m] (grey verticals: sleepers)")
    ax.set_ylabel(r"contact force $Q_c$ [kN]")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_dip_against_speed(speeds: np.ndarray, curves: dict, static_load: float) -> Figure:
    """Largest contact force [N] against speed [m/s], one line per entry of `curves`.

    An entry is an array over `speeds`; NaN leaves a gap (a formula that does not apply).
    """
    fig, ax = new_figure(1, 1, width=6.5, height=3.2)
    for i, (label, values) in enumerate(curves.items()):
        ax.plot(speeds, np.asarray(values) * KN, label=label, marker="o", ms=3,
                **series_style(i))
    ax.axhline(static_load * KN, color="0.5", lw=0.8, ls=":", label="static load Q")
    ax.set_xlabel("speed v [m/s]")
    ax.set_ylabel("largest contact force [kN]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_loss_of_contact(solution, window: tuple[float, float], samples: int = 16384,
                         dip=None) -> Figure:
    """Contact force and compression of every wheel through `window` [m] of its path.

    `dip` (a `CosineDip`) is shaded on both panels, its lowest point dashed.
    """
    fig, axes = new_figure(2, 1, width=7.0, height=4.2, sharex=True)
    wagon = float(solution.passage.wagon_length)
    t = solution.one_period(samples)[0]
    force, compression = solution.contact_force(t) * KN, solution.compression(t) * 1e6
    for k, x in enumerate(np.mod(solution.wheel_position(t), wagon)):
        order = np.argsort(x)
        keep = (x[order] >= window[0]) & (x[order] <= window[1])
        style = series_style(k)
        axes[0].plot(x[order][keep], force[k][order][keep], label=f"wheel {k + 1}", **style)
        axes[1].plot(x[order][keep], compression[k][order][keep], **style)
    axes[1].axhline(0.0, color="k", lw=0.8)
    axes[0].set_ylabel(r"contact force $Q_c$ [kN]")
    axes[1].set_ylabel("compression δ [µm]")
    axes[1].set_xlabel("wheel position along the track x [m]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        _shade_dip(ax, dip)
    axes[1].set_xlim(*window)
    axes[0].legend(fontsize=8)
    return fig


def plot_rail_receptances(frequency: np.ndarray, receptances: dict,
                          marks: dict | None = None) -> Figure:
    """|receptance| [m/N] against frequency [Hz] on a log scale, one line per entry;
    `marks` (label -> frequency [Hz]) draws vertical lines."""
    fig, ax = new_figure(1, 1, width=6.5, height=3.2)
    for i, (label, values) in enumerate(receptances.items()):
        ax.semilogy(frequency, np.abs(values), label=label, **series_style(i))
    for i, (label, f) in enumerate((marks or {}).items()):
        ax.axvline(f, color=series_style(i)["color"], lw=0.8, ls=":", label=label)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("|receptance| [m/N]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_sleeper_passing(curves: dict) -> Figure:
    """Swing of the contact force [N] against the sleeper-passing frequency v / L [Hz].

    `curves` maps a label to ``(frequency, swing, resonance)``: arrays over the
    speeds swept and the wheel-and-track frequency [Hz] of that case (a dotted
    vertical line of the same colour), or None for none.
    """
    fig, ax = new_figure(1, 1, width=6.5, height=3.2)
    for i, (label, (frequency, swing, resonance)) in enumerate(curves.items()):
        style = series_style(i)
        ax.plot(frequency, np.asarray(swing) * KN, label=label, **style)
        if resonance is not None:
            ax.axvline(resonance, color=style["color"], lw=0.8, ls=":")
    ax.set_xlabel("sleeper-passing frequency v / L [Hz] (dotted: wheel and track, one mass)")
    ax.set_ylabel("swing of P, max - min [kN]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig
