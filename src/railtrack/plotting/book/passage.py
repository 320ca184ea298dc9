"""Where and when the sleeper moves most while a wagon passes (book chapter 6).

A wagon's two wheels pass the observed sleeper at t = 0 (front) and t = D/v
(back).  `passage_extremes` reads, from a solved case, the dip under each
wheel, the uplift right behind the wagon and right ahead of the next one,
and how far behind each wheel its dip comes.  `passage_study` repeats this
over train speeds, so that the speed dependence of these features (the
viscous lag of the dashpots) can be shown; `plot_passage_study` draws it.

Everything is evaluated at the front wheel's position x = v t in [0, H),
where all speeds share one grid.  SI inside; the figure shows mm and m/s.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from ...solvers.solve import solve
from ...model.passage import Passage
from ..style import MARKERS, MM, PALETTE, new_figure

__all__ = ["PassageExtremes", "passage_extremes", "passage_study", "plot_passage_study"]


@dataclass(frozen=True)
class PassageExtremes:
    """Extremes of the sleeper displacement over one wagon passage.

    Attributes
    ----------
    front_dip, back_dip : float
        Lowest w [m] within D/2 of the front wheel and of the back wheel.
    rear_uplift, front_uplift : float
        Highest w [m] between the back wheel and the midpoint of the gap to
        the next wagon (behind the wagon), and between that midpoint and the
        next front wheel (ahead of the next wagon).
    front_lag, back_lag : float
        Time from each wheel's passage to its dip [s].
    """

    front_dip: float
    back_dip: float
    rear_uplift: float
    front_uplift: float
    front_lag: float
    back_lag: float


def passage_extremes(solution, samples: int = 36000) -> PassageExtremes:
    """The dips and uplifts of one solved case.

    Parameters
    ----------
    solution : railtrack.Solution
        Any solved case; uses ``sleeper_displacement`` (eq. 12).
    samples : int
        Points per wagon length H at which w is evaluated.

    Returns
    -------
    PassageExtremes
    """
    passage = solution.passage
    spacing, length, speed = passage.wheel_spacing, passage.wagon_length, passage.speed
    if not 0 < spacing < length / 2:
        raise ValueError(f"wheel spacing D = {spacing} m must lie in (0, H/2) = (0, {length / 2}) m")
    x = np.linspace(-spacing / 2, length - spacing / 2, samples, endpoint=False)
    w = solution.sleeper_displacement(np.mod(x, length) / speed)
    front = x < spacing / 2
    back = (x >= spacing / 2) & (x < 1.5 * spacing)
    middle = (spacing + length) / 2
    behind = (x > spacing) & (x < middle)
    ahead = (x >= middle)
    i_front, i_back = np.argmin(np.where(front, w, np.inf)), np.argmin(np.where(back, w, np.inf))
    return PassageExtremes(
        front_dip=float(w[i_front]), back_dip=float(w[i_back]),
        rear_uplift=float(w[behind].max()), front_uplift=float(w[ahead].max()),
        front_lag=float(x[i_front] / speed), back_lag=float((x[i_back] - spacing) / speed),
    )


def passage_study(passage: Passage, laws: Mapping[str, object], speeds: Sequence[float],
                  harmonics: int | str = "auto", **track_changes) -> dict:
    """`passage_extremes` for each law at each speed.

    Parameters
    ----------
    passage : Passage
    laws : dict of str -> foundation
        Label -> foundation law.  A `LinearFoundation` is solved by eq. (23),
        any other law by Newton.
    speeds : sequence of float
        Train speeds v [m/s].
    harmonics : int or "auto"
        m of every solve; by default each solve picks its own m
        (truncation error below 1e-3 of the peak), since the differences
        studied here are a few tenths of a per cent.
    **track_changes
        Optional per-label overrides of Track or Train fields: ``label=dict(pad_damping=...)``.

    Returns
    -------
    dict of str -> list of PassageExtremes
        One entry per speed, in the order of `speeds`.
    """
    from ...model.foundations import LinearFoundation

    study = {}
    for label, law in laws.items():
        base = passage.replace(**track_changes.get(label, {}))
        method = "analytic" if isinstance(law, LinearFoundation) else "newton"
        study[label] = [passage_extremes(solve(base.track, base.train.replace(speed=float(v)), law, harmonics,
                                               method=method))
                        for v in speeds]
    return study


def plot_passage_study(speeds: Sequence[float], study: Mapping[str, Sequence[PassageExtremes]]) -> Figure:
    """Dips (top) and uplifts (bottom) against the train speed, one colour and marker per law.

    Parameters
    ----------
    speeds : sequence of float
        Train speeds v [m/s], as given to `passage_study`.
    study : dict of str -> list of PassageExtremes
        From `passage_study`.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes sharing v [m/s]; top: front-wheel dip (solid, gid
        "<label>: front dip") and back-wheel dip (dashed, gid
        "<label>: back dip") in mm; bottom: uplift ahead of the next wagon
        (solid) and behind the wagon (dashed) in mm.  Each law has its own
        colour and marker (circles, squares, triangles, ...).
    """
    fig, (dips, lifts) = new_figure(2, 1, height=2.8, sharex=True)
    speeds = np.asarray(speeds, float)
    for n, (label, rows) in enumerate(study.items()):
        get = lambda name: np.array([getattr(r, name) for r in rows]) * MM  # noqa: E731
        style = dict(color=PALETTE[n % len(PALETTE)], marker=MARKERS[n % len(MARKERS)], ms=3.5)
        dips.plot(speeds, get("front_dip"), "-", gid=f"{label}: front dip",
                  label=f"{label}: front wheel", **style)
        dips.plot(speeds, get("back_dip"), "--", mfc="white", gid=f"{label}: back dip",
                  label=f"{label}: back wheel", **style)
        lifts.plot(speeds, get("front_uplift"), "-", gid=f"{label}: front uplift",
                   label=f"{label}: ahead of the next wagon", **style)
        lifts.plot(speeds, get("rear_uplift"), "--", mfc="white", gid=f"{label}: rear uplift",
                   label=f"{label}: behind the wagon", **style)
    dips.set_ylabel("dip, min w [mm]")
    lifts.set_ylabel("uplift, max w [mm]")
    lifts.set_xlabel("train speed v [m/s]")
    for ax in (dips, lifts):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.01, 0.5))
    return fig
