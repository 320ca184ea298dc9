"""The model of Fig. 1 of the paper, drawn with matplotlib (not to scale)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle

from ...model.passage import Passage
from ..style import BLUE, ORANGE, VERMILLION, new_figure

__all__ = ["draw_track_schematic"]


def _spring(ax, x, y_top, y_bottom, width=0.08, turns=5, **kw):
    """A zigzag spring between two heights at abscissa x."""
    lead = 0.15 * (y_top - y_bottom)
    ys = np.linspace(y_top - lead, y_bottom + lead, 2 * turns + 1)
    xs = x + width * np.array([0] + [(-1) ** i for i in range(1, 2 * turns)] + [0])
    ax.plot([x, *xs, x], [y_top, *ys, y_bottom], **kw)


def _dashpot(ax, x, y_top, y_bottom, width=0.07, **kw):
    """A dashpot (piston in a cylinder) between two heights at abscissa x."""
    mid = 0.5 * (y_top + y_bottom)
    h = 0.18 * (y_top - y_bottom)
    ax.plot([x, x], [y_top, mid + 0.3 * h], **kw)
    ax.plot([x - 0.7 * width, x + 0.7 * width], [mid + 0.3 * h] * 2, **kw)   # piston
    ax.plot([x - width, x - width, x + width, x + width],
            [mid + h, mid - h, mid - h, mid + h], **kw)                     # cylinder
    ax.plot([x, x], [mid - h, y_bottom], **kw)


def _dimension(ax, x0, x1, y, text, color="0.25"):
    """A double arrow from x0 to x1 at height y with a label above it."""
    ax.add_patch(FancyArrowPatch((x0, y), (x1, y), arrowstyle="<->", mutation_scale=10,
                                 color=color, lw=0.9, shrinkA=0, shrinkB=0))
    ax.text(0.5 * (x0 + x1), y + 0.06, text, ha="center", va="bottom", color=color)


def draw_track_schematic(passage: Passage, *, sleepers: int = 9, observed: int = 6,
                         back_wheel: int = 3) -> Figure:
    """Schematic of the model of Fig. 1: rail, pads, sleepers, foundation, one wagon.

    Drawn at t = 0 (the front wheel above the observed sleeper 0) and not to
    scale.  The rail is a beam (rho S, EI); each pad a spring k1 beside a
    dashpot eta1; each sleeper a mass M; each foundation a box f(w, w').
    The two wheels of one wagon push down with Q, D apart; the front wheel
    of the following wagon (dashed) is H behind.  The train moves toward +x
    at speed v, and w is positive upward.

    Parameters
    ----------
    passage : Passage
        Its values of L, D, H, v, Q are written on the labels.
    sleepers : int
        Number of sleepers drawn (>= 3).
    observed : int
        Index of the observed sleeper (x = 0), under the front wheel.
    back_wheel : int
        Index of the sleeper above which the back wheel is drawn (< observed).

    Returns
    -------
    matplotlib.figure.Figure
        Sleepers are `Rectangle` patches with gid "sleeper", foundation
        boxes gid "foundation", the wagon's wheels `Circle` patches with gid
        "wheel" and the following wagon's wheel gid "next-wheel".
    """
    if sleepers < 3 or not 0 <= back_wheel < observed < sleepers:
        raise ValueError("need sleepers >= 3 and 0 <= back_wheel < observed < sleepers; got "
                         f"sleepers={sleepers}, observed={observed}, back_wheel={back_wheel}")
    fig, ax = new_figure(width=8.0, height=4.2)
    ax.set_aspect("equal")
    ax.axis("off")
    xs = np.arange(sleepers, dtype=float)
    left, right = -0.9, sleepers - 0.1
    y_pad, y_sl, y_gr = -0.85, -1.2, -1.9
    dark = dict(color="0.15", ls="-", lw=1.1)

    # rail: an infinite beam (dotted ends)
    ax.add_patch(Rectangle((left, -0.07), right - left, 0.14, color="0.3", zorder=3))
    for x0, x1 in ((left - 0.5, left), (right, right + 0.5)):
        ax.plot([x0, x1], [0, 0], ls=":", color="0.3", lw=2)
    ax.annotate(r"rail $EI,\ \rho S$", (left - 0.5, 0.0), (xs[0] - 0.95, 0.45), ha="right",
                va="center", arrowprops=dict(arrowstyle="-", color="0.4", lw=0.7))

    for i, x in enumerate(xs):
        _spring(ax, x - 0.1, -0.07, y_pad, **dark)
        _dashpot(ax, x + 0.1, -0.07, y_pad, **dark)
        colour = ORANGE if i == observed else "0.55"
        ax.add_patch(Rectangle((x - 0.2, y_sl), 0.4, y_pad - y_sl, color=colour, gid="sleeper",
                               zorder=3))
        ax.add_patch(Rectangle((x - 0.2, y_gr), 0.4, y_sl - y_gr, facecolor="0.92",
                               edgecolor="0.3", hatch="...", lw=0.8, gid="foundation"))
    ax.plot([left, right], [y_gr, y_gr], "-", color="0.2", lw=1.5)
    for x in np.arange(left, right, 0.25):
        ax.plot([x, x - 0.15], [y_gr, y_gr - 0.15], "-", color="0.4", lw=0.6)

    # labels of one pad, sleeper and foundation
    x0 = xs[0]
    ax.annotate(r"pad $k_1,\ \eta_1$", (x0 - 0.12, 0.5 * y_pad), (x0 - 0.95, 0.5 * y_pad - 0.05),
                ha="right", va="center", arrowprops=dict(arrowstyle="-", color="0.4", lw=0.7))
    ax.annotate(r"sleeper $M$", (x0 - 0.2, 0.5 * (y_pad + y_sl)),
                (x0 - 0.95, 0.5 * (y_pad + y_sl) - 0.1), ha="right", va="center",
                arrowprops=dict(arrowstyle="-", color="0.4", lw=0.7))
    ax.annotate(r"foundation $f(w, w')$", (x0 - 0.2, 0.5 * (y_sl + y_gr)),
                (x0 - 0.95, 0.5 * (y_sl + y_gr) - 0.15), ha="right", va="center",
                arrowprops=dict(arrowstyle="-", color="0.4", lw=0.7))

    # observed sleeper: x = 0 and w positive upward
    xo = xs[observed]
    ax.add_patch(FancyArrowPatch((xo + 0.36, y_gr + 0.1), (xo + 0.36, y_pad), arrowstyle="-|>",
                                 mutation_scale=11, color=ORANGE, lw=1.3))
    ax.text(xo + 0.41, y_pad + 0.02, r"$w$", color="0.1", va="center")
    ax.text(xo, y_gr - 0.3, r"observed sleeper, $x = 0$", ha="center", va="top",
            color="0.1")

    # sleeper spacing L
    _dimension(ax, xs[1], xs[2], y_gr - 0.45, rf"$L = {passage.sleeper_spacing:g}$ m")

    # wheels: back and front wheel of one wagon, front wheel of the next one
    radius, y_wheel = 0.28, 0.07 + 0.28
    wheel_x = (xs[back_wheel], xo)
    for x in wheel_x:
        ax.add_patch(Circle((x, y_wheel), radius, facecolor="white", edgecolor="0.1", lw=1.5,
                            gid="wheel", zorder=4))
        ax.add_patch(FancyArrowPatch((x, 1.55), (x, y_wheel + radius + 0.02), arrowstyle="-|>",
                                     mutation_scale=12, color=VERMILLION, lw=1.6))
        ax.text(x + 0.08, 1.3, rf"$Q = {passage.wheel_load / 1e3:g}$ kN", color=VERMILLION,
                va="center")
    x_next = -0.35
    ax.add_patch(Circle((x_next, y_wheel), radius, facecolor="white", edgecolor="0.5", lw=1.2,
                        ls="--", gid="next-wheel", zorder=4))
    ax.add_patch(FancyArrowPatch((x_next, 1.55), (x_next, y_wheel + radius + 0.02),
                                 arrowstyle="-|>", mutation_scale=12, color=VERMILLION, lw=1.0,
                                 ls="--", alpha=0.6))
    ax.text(x_next + 0.08, 1.3, "next wagon", color="0.4", va="center", fontsize="small")
    _dimension(ax, wheel_x[0], wheel_x[1], 1.75, rf"$D = {passage.wheel_spacing:g}$ m")
    _dimension(ax, x_next, wheel_x[1], 2.25, rf"$H = {passage.wagon_length:g}$ m")

    # speed
    ax.add_patch(FancyArrowPatch((xo + 0.4, 1.85), (xo + 1.7, 1.85), arrowstyle="-|>",
                                 mutation_scale=14, color=BLUE, lw=1.8))
    ax.text(xo + 1.05, 1.92, rf"$v = {passage.speed:g}$ m/s", color=BLUE, ha="center",
            va="bottom")
    ax.text(right + 0.5, y_gr - 0.75, "not to scale", ha="right", va="bottom", fontsize="small",
            color="0.4", style="italic")
    ax.set_xlim(left - 2.6, right + 0.6)
    ax.set_ylim(y_gr - 0.8, 2.7)
    return fig
