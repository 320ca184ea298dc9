"""The track engineer's quantities: deflection bowl, rail-seat load, bending moment.

Data functions return arrays, dicts or table rows in SI units; the plotting
functions draw them in mm, kN, kN m, m and s.  The yardstick is the static
Winkler beam (Hetényi 1946): a rail on a bed k = k_s / L per metre, with
k_s = k1 k2 / (k1 + k2) (pad and foundation in series), has under a load P
w(x) = -(P lambda / 2k) exp(-lambda|x|) (cos lambda x + sin lambda|x|) and
EI w'' = (P / 4 lambda) exp(-lambda|x|) (cos lambda x - sin lambda|x|),
lambda = (k / 4 EI)^(1/4); w positive upward.
"""

from __future__ import annotations

from typing import NamedTuple

import re

import numpy as np
from matplotlib import animation
from matplotlib.figure import Figure

from ..solution import draw_bowl
from ..style import MM, new_figure, series_style

__all__ = ["GRAVITY", "support_stiffness", "winkler_parameters", "wheel_positions", "winkler_bowl",
           "winkler_moment", "static_bowl", "bowl_uplift", "LoadHistories", "load_histories",
           "load_peaks", "load_distribution_table", "table_markdown", "pad_damping_ratio",
           "self_weight_per_seat", "wheel_moments", "moment_peaks", "richardson",
           "plot_bowls", "plot_bowl_frame", "animate_bowl", "offline_jshtml",
           "plot_load_histories", "plot_moments"]

GRAVITY = 9.81  # m/s^2, for the self-weight of the track (which the model leaves out)


def support_stiffness(track, foundation) -> float:
    """k_s = k1 k2 / (k1 + k2): pad and foundation in series, per rail seat [N/m].

    k2 is the foundation's stiffness at rest in compression
    (``foundation.linearization()[0]``)."""
    k1, k2 = float(track.pad_stiffness), float(foundation.linearization()[0])
    return k1 * k2 / (k1 + k2)


def winkler_parameters(track, foundation) -> tuple[float, float]:
    """Bed stiffness k = k_s / L [N/m^2] and lambda = (k / 4 EI)^(1/4) [1/m] of the smeared track."""
    k = support_stiffness(track, foundation) / float(track.sleeper_spacing)
    return k, (k / (4.0 * float(track.rail_bending_stiffness))) ** 0.25


def wheel_positions(train, front: float = 0.0, wagons: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """Positions [m] and loads [N] of the wheels of 2 `wagons` + 1 wagons, one front wheel at `front`."""
    n = np.arange(-wagons, wagons + 1)[:, None]
    positions = front - np.asarray(train.axle_positions)[None, :] - n * float(train.wagon_length)
    return positions.ravel(), np.broadcast_to(np.asarray(train.axle_loads), positions.shape).ravel()


def winkler_bowl(track, foundation, x, positions, loads, moment: bool = False) -> np.ndarray:
    """Static rail deflection [m] (or moment EI w'' [N m]) of the Winkler beam under point loads.

    Parameters
    ----------
    track, foundation : railtrack.Track and a foundation law (its stiffness at rest)
    x : array_like, shape (X,)
        Positions along the rail [m].
    positions, loads : array_like, shape (J,)
        Where the wheels stand [m] and their loads [N] (downward), superposed.
    moment : bool
        Return the bending moment, sagging positive, instead of w.

    Returns
    -------
    ndarray, shape (X,)
        w(x), positive upward, or EI w''(x).
    """
    k, lam = winkler_parameters(track, foundation)
    r = lam * np.abs(np.subtract.outer(np.asarray(x, dtype=float), np.asarray(positions, float)))
    if moment:
        shape = np.exp(-r) * (np.cos(r) - np.sin(r)) / (4.0 * lam)
    else:
        shape = -lam / (2.0 * k) * np.exp(-r) * (np.cos(r) + np.sin(r))
    return shape @ np.asarray(loads, dtype=float)


def winkler_moment(track, foundation, x, positions, loads) -> np.ndarray:
    """Static bending moment EI w'' of the Winkler beam, sagging positive [N m]."""
    return winkler_bowl(track, foundation, x, positions, loads, moment=True)


def static_bowl(track, train, foundation, x, front: float = 0.0) -> np.ndarray:
    """The Winkler bowl [m] of a whole train (five wagons) with a front wheel at `front`."""
    positions, loads = wheel_positions(train, front)
    return winkler_bowl(track, foundation, x, positions, loads)


def bowl_uplift(bowl) -> tuple[float, float]:
    """Largest rail rise [m] ahead of the foremost wheel and behind the rearmost in the window."""
    wheels = np.asarray(bowl.wheel_positions)
    return float(bowl.rail[bowl.x > wheels.max()].max()), float(bowl.rail[bowl.x < wheels.min()].max())


class LoadHistories(NamedTuple):
    """Times [s], rail-seat load and foundation force [N] (compression > 0) over one period."""
    t: np.ndarray
    rail_seat: np.ndarray
    foundation: np.ndarray


def load_histories(solution, samples: int = 2000) -> LoadHistories:
    """Sample `Solution.rail_seat_load` and `Solution.foundation_force` over one period."""
    t = np.linspace(0.0, solution.period, samples, endpoint=False)
    return LoadHistories(t, solution.rail_seat_load(t), solution.foundation_force(t))


def load_peaks(solution, samples: int = 2000) -> dict:
    """Extremes and means of the rail-seat load and the foundation force [N]."""
    h = load_histories(solution, samples)
    return {f"{key}_{stat}": getattr(values, stat)() for key, values in
            (("seat", h.rail_seat), ("foundation", h.foundation)) for stat in ("max", "min", "mean")}


def load_distribution_table(solutions: dict, wheel_load: float, samples: int = 2000) -> list[dict]:
    """Peak loads as a share of the wheel load, one row per solved case.

    Parameters
    ----------
    solutions : dict of (str, str) -> railtrack.Solution
        (parameter set, law) -> solution.
    wheel_load : float
        Q [N], the divisor of the shares.
    samples : int
        Samples over one period.

    Returns
    -------
    list of dict
        One row per case: ``track``, ``law``, ``m`` (harmonics), ``seat_max``
        and ``seat_min`` (rail-seat load / Q), ``foundation_max`` and
        ``foundation_min`` (foundation force / Q), ``lowest`` and ``highest``
        (sleeper displacement [m]).  ``pandas.DataFrame(rows)`` takes it as is.
    """
    rows = []
    for (track_label, law_label), s in solutions.items():
        p = load_peaks(s, samples)
        w = s.sleeper_displacement(np.linspace(0.0, s.period, samples, endpoint=False))
        shares = {key: p[key] / wheel_load for key in p if not key.endswith("mean")}
        rows.append(dict(track=track_label, law=law_label, m=s.harmonics, **shares,
                         lowest=float(w.min()), highest=float(w.max())))
    return rows


def table_markdown(rows: list[dict]) -> str:
    """The rows of `load_distribution_table` as a Markdown table (shares to 3 decimals, mm)."""
    lines = ["| track | law | m | rail seat, max / Q | rail seat, min / Q | foundation, max / Q "
             "| foundation, min / Q | sleeper lowest [mm] | sleeper highest [mm] |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['track']} | {r['law']} | {r['m']} | {r['seat_max']:.3f} | "
                     f"{r['seat_min']:.3f} | {r['foundation_max']:.3f} | {r['foundation_min']:.3f} | "
                     f"{r['lowest'] * MM:.3f} | {r['highest'] * MM:.3f} |")
    return "\n".join(lines)


def pad_damping_ratio(track) -> float:
    """eta1 / (2 sqrt(k1 M)): the pad's damping relative to critical for the sleeper on the pad [-]."""
    return float(track.pad_damping / (2.0 * np.sqrt(track.pad_stiffness * track.sleeper_mass)))


def self_weight_per_seat(track, sleeper_mass: float | None = None) -> float:
    """g (M + rho S L): weight of one sleeper share and one span of rail [N] (not in the model)."""
    mass = track.sleeper_mass if sleeper_mass is None else sleeper_mass
    return float(GRAVITY * (mass + track.rail_linear_mass * track.sleeper_spacing))


def wheel_moments(solution, x: float) -> np.ndarray:
    """Rail bending moment at `x` [N m] at the instants each axle of a wagon is above x, shape (J,)."""
    p = solution.passage
    return solution.rail_bending_moment(np.mod((x + np.asarray(p.axle_positions)) / p.speed, p.period), x)


def moment_peaks(solution, samples: int = 2000) -> dict:
    """Peak sagging moment under a wheel and peak hogging moment, above a sleeper and at mid-span [N m]."""
    t = np.linspace(0.0, solution.period, samples, endpoint=False)
    half = float(solution.passage.sleeper_spacing) / 2.0
    return dict(sleeper_sagging=wheel_moments(solution, 0.0).max(),
                midspan_sagging=wheel_moments(solution, half).max(),
                sleeper_hogging=solution.rail_bending_moment(t, 0.0).min(),
                midspan_hogging=solution.rail_bending_moment(t, half).min())


def richardson(m1: int, value1: float, m2: int, value2: float) -> float:
    """Limit m -> inf of a value whose error falls like 1/m, from its values at m1 and m2."""
    return (m2 * value2 - m1 * value1) / (m2 - m1)


def plot_bowls(panels: dict) -> Figure:
    """One panel per entry: title -> (DeflectionBowl, static Winkler bowl or None)."""
    fig, axes = new_figure(len(panels), 1, height=2.8, sharex=True)
    for ax, (title, (bowl, static)) in zip(np.atleast_1d(axes), panels.items()):
        draw_bowl(ax, bowl.x, bowl.rail, bowl.sleeper_positions, bowl.sleepers,
                  bowl.wheel_positions, static)
        ax.set_title(title, fontsize="medium")
    for ax in np.atleast_1d(axes)[:-1]:
        ax.set_xlabel("")
    np.atleast_1d(axes)[0].legend(fontsize="small", ncol=2, loc="lower right")
    return fig


def _bowl_axes(bowls, index, dpi=None):
    """A figure with frame `index` of a bowl over several instants drawn; its artists."""
    fig, ax = new_figure(height=3.0, dpi=dpi)
    wheels = lambda i: bowls.wheel_positions[i][(bowls.wheel_positions[i] >= bowls.x.min())
                                                 & (bowls.wheel_positions[i] <= bowls.x.max())]
    artists = draw_bowl(ax, bowls.x, bowls.rail[index], bowls.sleeper_positions,
                        bowls.sleepers[index], wheels(index))
    low = min(bowls.rail.min(), bowls.sleepers.min()) * MM
    ax.set(ylim=(1.15 * low, 0.4 - 0.15 * low), xlim=(bowls.x.min(), bowls.x.max()))
    ax.legend(fontsize="small", ncol=3, loc="lower left")
    return fig, ax, artists, wheels


def plot_bowl_frame(bowls, index: int, time: float) -> Figure:
    """The still frame `index` of a DeflectionBowl over several instants (for print)."""
    fig, ax, _, _ = _bowl_axes(bowls, index)
    return ax.set_title(f"t = {time:.3f} s", fontsize="medium").figure


def animate_bowl(bowls, times, interval: float = 80.0, dpi: int = 60) -> animation.FuncAnimation:
    """A FuncAnimation of the rail and sleepers over the instants `times` of `bowls`."""
    fig, ax, (line, dots, marks), wheels = _bowl_axes(bowls, 0, dpi)
    title = ax.set_title("", fontsize="medium")

    def update(i):
        line.set_ydata(bowls.rail[i] * MM)
        dots.set_ydata(bowls.sleepers[i] * MM)
        marks.set_data(wheels(i), np.zeros_like(wheels(i)) + 0.15)
        title.set_text(f"t = {times[i]:.3f} s")
        return line, dots, marks, title

    return animation.FuncAnimation(fig, update, frames=len(times), interval=interval, blit=False)


_ICONS = {"fa-minus": "&minus;", "fa-fast-backward": "|&lt;&lt;", "fa-step-backward": "|&lt;",
          "fa-play fa-flip-horizontal": "&lt;", "fa-pause": "||", "fa-play": "&gt;",
          "fa-step-forward": "&gt;|", "fa-fast-forward": "&gt;&gt;|", "fa-plus": "+"}


def offline_jshtml(anim, **kwargs) -> str:
    """``anim.to_jshtml()`` with nothing fetched from the internet.

    Matplotlib's player links a Font Awesome stylesheet from a CDN for its
    button icons; this drops the link and writes the buttons as text."""
    html = re.sub(r"<link[^>]*font-awesome[^>]*>", "", anim.to_jshtml(**kwargs))
    return re.sub(r'<i class="fa ([^"]+)"></i>', lambda m: _ICONS.get(m.group(1), "?"), html)


def plot_load_histories(histories: dict, wheel_load: float) -> Figure:
    """Rail-seat load (top) and foundation force (bottom) [kN] over one period, one line per case."""
    fig, axes = new_figure(2, 1, height=2.8, sharex=True)
    for n, (label, h) in enumerate(histories.items()):
        axes[0].plot(h.t, h.rail_seat / 1e3, label=label, gid=label, **series_style(n))
        axes[1].plot(h.t, h.foundation / 1e3, label=label, gid=label, **series_style(n))
    for ax, name in zip(axes, ("rail-seat load [kN]", "foundation force [kN]")):
        ax.set_ylabel(f"{name}\n(compression > 0)")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.grid(True, alpha=0.3)
        ax.secondary_yaxis("right", functions=(lambda f: f * 1e3 / wheel_load,
                                               lambda q: q * wheel_load / 1e3)).set_ylabel("share of Q")
    axes[1].set_xlabel("time t [s] (t = 0: front wheel above the sleeper)")
    axes[0].legend(fontsize="small")
    return fig


def plot_moments(solutions: dict, samples: int = 800) -> Figure:
    """Rail bending moment above a sleeper and at mid-span [kN m] over one period, one panel per case."""
    fig, axes = new_figure(len(solutions), 1, height=2.6, sharex=True)
    for ax, (label, s) in zip(np.atleast_1d(axes), solutions.items()):
        t = np.linspace(0.0, s.period, samples, endpoint=False)
        half = float(s.passage.sleeper_spacing) / 2.0
        ax.plot(t, s.rail_bending_moment(t, 0.0) / 1e3, label="above a sleeper (x = 0)", gid="sleeper",
                **series_style(0))
        ax.plot(t, s.rail_bending_moment(t, half) / 1e3, label="mid-span (x = L/2)", gid="midspan",
                **series_style(1))
        ax.set(ylabel="M [kN m]\n(sagging > 0)", title=f"{label}, m = {s.harmonics}")
        ax.grid(True, alpha=0.3)
    np.atleast_1d(axes)[-1].set_xlabel("time t [s] (t = 0: front wheel above the sleeper)")
    np.atleast_1d(axes)[0].legend(fontsize="small")
    return fig
