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

from .style import MM, new_figure

__all__ = ["lowest_over_speed", "peak_speed", "winkler_critical_speed", "lower_branch_bound",
           "smeared_critical_speed", "halved_spacing", "solution_counts", "plot_speed_curves",
           "plot_branch", "plot_seat_load_histogram"]


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

    The rail (rho S, EI) rests on a pad k1 / L, a mass M / L and a
    foundation k2 / L per metre, undamped.  A free wave exp(i(beta x - omega t))
    has x = omega^2 solving
    (EI beta^4 - rho S x)(k1 + k2 - M x) + (k1 / L)(k2 - M x) = 0.
    A load moving at v excites the waves with omega = v beta; resonance is
    where that line touches the lower branch, the first local minimum of its
    phase speed omega / beta.  With M -> 0 it is `winkler_critical_speed`.
    The lower branch stays below `lower_branch_bound`, so its phase speed
    falls to 0 at large beta; if it has no local minimum before that, there
    is no tangency and NaN is returned.

    Parameters
    ----------
    track : Track
    foundation : a law with ``linearization()``
    wavenumbers : array_like, optional
        Increasing beta to search [1/m] (default 20000 points from 0.05 to 20).
    """
    beta = (np.linspace(0.05, 20.0, 20000) if wavenumbers is None
            else np.asarray(wavenumbers, float))
    k1, k2 = float(track.pad_stiffness), float(foundation.linearization()[0])
    rho, ei = float(track.rail_linear_mass), float(track.rail_bending_stiffness)
    m, spacing = float(track.sleeper_mass), float(track.sleeper_spacing)
    a, c = ei * beta ** 4, k1 + k2
    qa, qb, qc = rho * m, a * m + rho * c + k1 * m / spacing, a * c + k1 * k2 / spacing
    phase = np.sqrt((qb - np.sqrt(qb ** 2 - 4.0 * qa * qc)) / (2.0 * qa)) / beta
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


def plot_speed_curves(speeds, curves: dict, *, marks: dict | None = None,
                      title: str | None = None) -> Figure:
    """-min w [mm] over speed [m/s], one line per case, peaks dotted.

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
    for label, lowest in curves.items():
        lowest = np.asarray(lowest)
        line, = ax.plot(speeds, -lowest * MM, label=label, gid=label)
        v, w = peak_speed(speeds, lowest)
        ax.plot([v], [-w * MM], "o", color=line.get_color(), ms=4)
    for (label, v), style in zip((marks or {}).items(), (":", "--", "-.", (0, (1, 3)))):
        ax.axvline(v, color="0.3", ls=style, lw=1, label=label)
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest sleeper dip −min w [mm]")
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    return fig


def plot_branch(branch, *, linear: tuple | None = None) -> Figure:
    """-min w [mm] along a speed branch, its folds marked, optionally the linear law's curve.

    Parameters
    ----------
    branch : Branch
        From ``continuation(..., parameter="speed")``.
    linear : (speeds, lowest), optional
        The linear law's min w [m] over speeds [m/s] for comparison.
    """
    fig, ax = new_figure()
    dip = -branch.minimum_displacement() * MM
    ax.plot(branch.values, dip, "-", lw=1.5, label="cubic law, continued branch", gid="branch")
    indices = [fold.index for fold in branch.folds]
    ax.plot(branch.values[indices], dip[indices], "rv", ms=6, label="folds", gid="folds")
    for n, i in enumerate(indices, 1):
        ax.annotate(f"{n}: {branch.values[i]:.1f}", (branch.values[i], dip[i]), fontsize=7,
                    xytext=(4, 4 if n % 2 else -10), textcoords="offset points")
    if linear is not None:
        ax.plot(linear[0], -np.asarray(linear[1]) * MM, "--", color="0.4",
                label="linear law (same k2, η2)", gid="linear")
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest sleeper dip −min w [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig


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
    ax.hist(ratio, bins=bins, color="C0", alpha=0.75, gid="histogram")
    ax.axvline(ratio.mean(), color="k", lw=1.2, label=f"mean {ratio.mean():.3f}")
    for q in quantiles:
        ax.axvline(np.quantile(ratio, q), color="C3", ls="--", lw=1,
                   label=f"{100 * q:g} % quantile {np.quantile(ratio, q):.3f}")
    ax.set_xlabel("peak rail-seat load / wheel load [-]")
    ax.set_ylabel("members")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig
