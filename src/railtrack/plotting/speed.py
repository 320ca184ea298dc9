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

from ..dispersion import smeared_phase_speed
from ..solve import solve
from .style import BLACK, BLUE, MM, ORANGE, PURPLE, VERMILLION, new_figure, series_style

__all__ = ["lowest_over_speed", "peak_speed", "winkler_critical_speed", "lower_branch_bound",
           "smeared_critical_speed", "halved_spacing", "solution_counts", "branch_dips_at",
           "ramp_on_branch", "plot_speed_curves", "plot_branch", "plot_seat_load_histogram"]


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
    `railtrack.dispersion.smeared_phase_speed`, at the first local minimum of
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

    min w is interpolated linearly between the two points of each crossing.
    """
    dip = branch.minimum_displacement()
    offset = np.asarray(branch.values) - speed
    before = np.flatnonzero((offset[:-1] == 0) | (offset[:-1] * offset[1:] < 0))
    weight = offset[before] / (offset[before] - offset[before + 1])
    return dip[before] + weight * (dip[before + 1] - dip[before]), before


def ramp_on_branch(ramp, branch, samples: int = 4096) -> list[tuple[int, float] | None]:
    """For each speed of a ramp, the branch point its steady state lies on.

    The branch's crossings of each speed are polished by `railtrack.solve`
    (`Branch.solutions_at` as starting points), and the ring's least sleeper
    displacement is compared with theirs.

    Returns, per speed, None where the ring found no periodic state, else
    (index of the branch point just before the nearest crossing, |min w of
    the ring - min w of that solution| [m]).
    """
    out = []
    track, train, foundation = branch.problem(0)
    for speed, low, periodic in zip(ramp.speeds, ramp.minimum, ramp.converged):
        if not periodic:
            out.append(None)
            continue
        _, before = branch_dips_at(branch, float(speed))
        at = train.replace(speed=float(speed))
        dips = []
        for guess in branch.solutions_at(float(speed)):
            s = solve(track, at, foundation, harmonics=branch.harmonics, initial=guess)
            t = np.linspace(0.0, float(s.period), samples, endpoint=False)
            dips.append(float(s.sleeper_displacement(t).min()) if s.converged else np.nan)
        gaps = np.abs(np.array(dips) - low)
        k = int(np.nanargmin(gaps))
        out.append((int(before[k]), float(gaps[k])))
    return out


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


def plot_branch(branch, *, linear: tuple | None = None, ramps: dict | None = None) -> Figure:
    """-min w [mm] along a speed branch, its folds marked, optionally the linear law's curve.

    Where ``branch.stable`` is set (`railtrack.check_branch`), stable parts
    are drawn solid and unstable parts dotted, and the points the ring was
    run on are marked.

    Parameters
    ----------
    branch : Branch
        From ``continuation(..., parameter="speed")``.
    linear : (speeds, lowest), optional
        The linear law's min w [m] over speeds [m/s] for comparison.
    ramps : dict, optional
        Label -> `railtrack.SpeedRamp`: the ring's steady dips along rising or
        falling speeds, joined in the order run, each ramp in its own colour,
        line style and marker (the first, ▶, for a rising ramp, the second,
        ◀, for a falling one); a cross (x for the first, + for the second)
        where the response did not repeat (its dip over the last period run).

    Folds are black diamonds; the linear law is grey and dashed.
    """
    fig, ax = new_figure()
    dip = -branch.minimum_displacement() * MM
    if branch.stable is None:
        ax.plot(branch.values, dip, "-", color=BLUE, lw=1.5, label="cubic law, continued branch",
                gid="branch")
    else:
        for flag, style, label in ((True, "-", "stable"), (False, ":", "unstable")):
            drawn = branch.stable == flag
            drawn[1:] |= drawn[:-1].copy()   # one point on, so that the pieces meet
            shown = np.where(drawn, dip, np.nan)
            ax.plot(branch.values, shown, style, color=BLUE, lw=1.5,
                    label=f"branch, {label} (ring)", gid=f"branch-{label}")
        checked = np.array(sorted(branch.checks))
        ax.plot(branch.values[checked], dip[checked], "o", mfc="none", color=BLUE, ms=5,
                label="checked by the ring", gid="checked")
    indices = [fold.index for fold in branch.folds]
    ax.plot(branch.values[indices], dip[indices], "D", color=BLACK, ms=5, label="folds",
            gid="folds", zorder=4)
    for n, i in enumerate(indices, 1):
        ax.annotate(f"{n}: {branch.values[i]:.1f}", (branch.values[i], dip[i]), fontsize=7,
                    xytext=(4, 4 if n % 2 else -10), textcoords="offset points")
    if linear is not None:
        ax.plot(linear[0], -np.asarray(linear[1]) * MM, "--", color="0.4",
                label="linear law (same k2, η2)", gid="linear")
    for n, (label, ramp) in enumerate((ramps or {}).items()):
        colour, marker, cross, style = _RAMP_STYLES[n % len(_RAMP_STYLES)]
        ramp_dip, periodic = -ramp.minimum * MM, np.asarray(ramp.converged, bool)
        ax.plot(ramp.speeds, ramp_dip, ls=style, color=colour, lw=0.9, marker=marker, ms=5,
                markevery=list(periodic), label=label, gid=f"ramp-{n}")
        if not periodic.all():
            ax.plot(ramp.speeds[~periodic], ramp_dip[~periodic], cross, color=colour, ms=7,
                    mew=1.5, label=f"{label}: no periodic state (last period)",
                    gid=f"ramp-{n}-aperiodic")
    ax.set_xlabel("train speed v [m/s]")
    ax.set_ylabel("largest sleeper dip −min w [mm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return fig


_RAMP_STYLES = ((ORANGE, ">", "x", "-"), (PURPLE, "<", "+", "--"),
                (VERMILLION, "^", "1", "-."), (BLACK, "v", "2", (0, (6, 2))))
"""Colour, marker of a periodic state, marker of an aperiodic one and line style of each ramp:
a rising ramp (the first) points right, a falling one left."""


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
