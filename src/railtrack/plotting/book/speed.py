"""The train speeds up: speed-response curves, critical speeds, folds and scatter.

Data functions return floats, arrays or dicts in SI units; the plotting
functions draw them in mm and m/s.  The yardsticks are two smeared tracks:
the rail on a Winkler bed k = k_s / L, k_s = k1 k2 / (k1 + k2), whose
critical speed is the classical v_cr = (4 k EI / (rho S)^2)^(1/4)
(Fryba 1972), and the same rail on a bed that keeps the sleeper's mass, a
pad k1 / L, a mass M / L and a foundation k2 / L per metre, whose lower wave
branch is bounded by omega^2 = (k1 + k2) / M.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from matplotlib.figure import Figure

from ...equations.dispersion import smeared_phase_speed
from ..style import BLACK, BLUE, MM, VERMILLION, new_figure, series_style

__all__ = ["lowest_over_speed", "peak_speed", "winkler_critical_speed", "lower_branch_bound",
           "smeared_critical_speed", "halved_spacing", "solution_counts", "branch_dips_at",
           "plot_speed_curves", "plot_seat_load_histogram"]


def lowest_over_speed(cases: dict, train, speeds) -> dict:
    """Lowest sleeper displacement over a period [m] for each (track, law), eq. (23).

    Parameters
    ----------
    cases : dict of str -> (Track, LinearFoundation)
    train : Train
        Its own speed is ignored.
    speeds : array_like, shape (S,)
        Train speeds [m/s].

    Returns
    -------
    dict of str -> ndarray, shape (S,)
        min w over the period at each speed [m] (negative: down).
    """
    import railtrack as rt

    return {name: rt.sweep_extremes(track, train, law, speeds)[0]
            for name, (track, law) in cases.items()}


def peak_speed(speeds, lowest) -> tuple[float, float]:
    """Speed of the largest downward response and that response.

    A parabola through the grid's deepest point and its two neighbours
    refines the speed between grid points.

    Parameters
    ----------
    speeds : array_like, shape (S,)
        Increasing speeds [m/s].
    lowest : array_like, shape (S,)
        min w at each speed [m].

    Returns
    -------
    speed : float
        [m/s]
    lowest : float
        min w there [m] (the grid value).
    """
    v, w = np.asarray(speeds, float), np.asarray(lowest, float)
    i = int(np.argmin(w))
    if 0 < i < len(v) - 1:
        a, b, c = w[i - 1], w[i], w[i + 1]
        denominator = a - 2.0 * b + c
        shift = 0.5 * (a - c) / denominator if denominator > 0 else 0.0
        return float(v[i] + shift * (v[i + 1] - v[i - 1]) / 2.0), float(b)
    return float(v[i]), float(w[i])


def winkler_critical_speed(track, foundation) -> float:
    """v_cr = (4 k EI / (rho S)^2)^(1/4), k = k_s / L, k_s = k1 k2 / (k1 + k2) [m/s].

    The massless, undamped continuous support: the least phase speed of
    the free waves of a beam on a Winkler bed.
    """
    k1, k2 = float(track.pad_stiffness), float(foundation.linearization()[0])
    k = k1 * k2 / (k1 + k2) / float(track.sleeper_spacing)
    return float((4.0 * k * float(track.rail_bending_stiffness)
                  / float(track.rail_linear_mass) ** 2) ** 0.25)


def lower_branch_bound(track, foundation) -> float:
    """sqrt((k1 + k2) / M) [rad/s]: the sleeper on its two springs, rail held still.

    The lower branch of the smeared track's free waves approaches it from
    below as the wavenumber grows.
    """
    k1, k2 = float(track.pad_stiffness), float(foundation.linearization()[0])
    return float(np.sqrt((k1 + k2) / float(track.sleeper_mass)))


def smeared_critical_speed(track, foundation, wavenumbers=None) -> float:
    """Critical speed of the smeared track with the sleeper's mass [m/s] (NaN if none).

    A load moving at v excites the free waves with omega = v kappa; resonance
    is where that line touches the lower branch of
    `railtrack.equations.dispersion.smeared_phase_speed`, at the first local minimum of
    its phase speed omega / kappa.  With M -> 0 it is `winkler_critical_speed`.
    The lower branch stays below `lower_branch_bound`, so its phase speed
    falls to 0 at large kappa; if it has no local minimum before that, there
    is no tangency and NaN is returned.

    Parameters
    ----------
    track : Track
    foundation : a law with ``linearization()``
    wavenumbers : array_like, optional
        Increasing kappa to search [rad/m] (default 20000 points from 0.05 to 20).
    """
    kappa = (np.linspace(0.05, 20.0, 20000) if wavenumbers is None
             else np.asarray(wavenumbers, float))
    phase = smeared_phase_speed(track, foundation, kappa)
    minima = np.flatnonzero((phase[1:-1] < phase[:-2]) & (phase[1:-1] < phase[2:]))
    return float(phase[minima[0] + 1]) if len(minima) else float("nan")


def halved_spacing(track, foundation):
    """The same track with sleepers twice as dense, every per-metre value kept.

    L, M, k1, eta1, k2 and eta2 are halved; the rail is unchanged.

    Returns
    -------
    (Track, foundation)
        The foundation via ``dataclasses.replace`` of its stiffness and damping.
    """
    denser = dataclasses.replace(track, sleeper_spacing=track.sleeper_spacing / 2,
                                 sleeper_mass=track.sleeper_mass / 2,
                                 pad_stiffness=track.pad_stiffness / 2,
                                 pad_damping=track.pad_damping / 2)
    law = dataclasses.replace(foundation, stiffness=foundation.stiffness / 2,
                              damping=foundation.damping / 2)
    return denser, law


def solution_counts(branch, speeds) -> np.ndarray:
    """How many points of the branch cross each speed (``len(branch.solutions_at(v))``)."""
    return np.array([len(branch.solutions_at(float(v))) for v in np.atleast_1d(speeds)])


def branch_dips_at(branch, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """Where the branch crosses `speed`: (min w there [m], index of the point before), one per crossing.

    min w is interpolated linearly between the two points of each crossing
    (`Branch.crossings`).
    """
    dip = branch.minimum_displacement()
    before, weight = branch.crossings(speed)
    after = np.minimum(before + 1, len(dip) - 1)
    return dip[before] + weight * (dip[after] - dip[before]), before


def plot_speed_curves(speeds, curves: dict, *, marks: dict | None = None,
                      title: str | None = None) -> Figure:
    """-min w [mm] over speed [m/s], one line per case, peaks ringed.

    Each case has its own colour, line style and marker; the marks are grey
    dotted lines (one dot pattern each), so nothing is told apart by colour alone.

    Parameters
    ----------
    speeds : array_like, shape (S,)
        [m/s]
    curves : dict of str -> array_like, shape (S,)
        Legend label -> min w [m].
    marks : dict of str -> float, optional
        Legend label -> a speed to mark with a vertical line [m/s].
    title : str, optional
    """
    fig, ax = new_figure()
    for n, (label, lowest) in enumerate(curves.items()):
        lowest = np.asarray(lowest)
        line, = ax.plot(speeds, -lowest * MM, label=label, gid=label,
                        **series_style(n, len(curves), points=len(lowest), marker=True))
        _ring_peak(ax, speeds, lowest, line)
    _mark_speeds(ax, marks)
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest sleeper dip −min w [mm]")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return fig


MARK_STYLES = (":", (0, (1, 3)), (0, (3, 1, 1, 1, 1, 1)), (0, (1, 1, 1, 4)))
"""Dot patterns of the grey vertical marks, kept apart from the curves' line styles."""


def _mark_speeds(ax, marks: dict | None) -> None:
    for (label, v), style in zip((marks or {}).items(), MARK_STYLES):
        ax.axvline(v, color="0.3", ls=style, lw=1, label=label)


def _ring_peak(ax, speeds, lowest, line) -> None:
    """An open ring of the line's colour at the refined peak of -lowest (`peak_speed`)."""
    v, w = peak_speed(speeds, lowest)
    ax.plot([v], [-w * MM], "o", mfc="white", mec=line.get_color(), mew=1.3, ms=6.5, zorder=3)


def plot_seat_load_histogram(ratio, *, bins: int = 60, quantiles=(0.05, 0.95)) -> Figure:
    """Histogram of the peak rail-seat load over the wheel load, with quantiles and the mean.

    Parameters
    ----------
    ratio : array_like, shape (B,)
        Peak rail-seat load / wheel load of each member [-].
    bins : int
    quantiles : tuple of float
        Marked with dashed lines.
    """
    ratio = np.asarray(ratio, float)
    fig, ax = new_figure()
    ax.hist(ratio, bins=bins, color=BLUE, alpha=0.75, gid="histogram")
    ax.axvline(ratio.mean(), color=BLACK, lw=1.2, label=f"mean {ratio.mean():.3f}")
    for q in quantiles:
        ax.axvline(np.quantile(ratio, q), color=VERMILLION, ls="--", lw=1,
                   label=f"{100 * q:g} % quantile {np.quantile(ratio, q):.3f}")
    ax.set_xlabel("peak rail-seat load / wheel load [-]")
    ax.set_ylabel("members")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig
