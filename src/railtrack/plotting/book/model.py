"""Figures of the model chapters (book chapters 1–3).

* `plot_receptance`, `receptance_check_table`: the receptance eta_E of
  eq. (3) and its check by the lattice sum;
* `plot_rail_coupling`: the coupling P(omega) of eq. (16);
* `plot_rail_and_sleeper`: rail and sleeper displacement over one period, eq. (6).

The schematic and the parameter tables of chapter 1 are in
`railtrack.plotting.book.schematic` and `railtrack.plotting.book.tables`, and are
re-exported here for the notebooks.  Everything is SI inside; axes show
millimetres, seconds, mm/kN.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from ...equations.receptance import (
    critical_frequency,
    rail_receptance,
    rail_receptance_lattice_sum,
    receptance_pole_frequencies,
)
from ...equations.sleeper import rail_coupling
from ...model.passage import Passage
from ...equations.load import wheel_passage_times
from .schematic import draw_track_schematic
from ..style import BLUE, GREEN, MM, ORANGE, PURPLE, VERMILLION, label_displacement_axes, new_figure
from .tables import (
    derived_table,
    foundation_rows,
    foundation_table,
    markdown_table,
    notation_table,
    table1,
    table1_rows,
)

__all__ = [
    "RECEPTANCE_UNIT",
    "draw_track_schematic",
    "table1_rows",
    "table1",
    "foundation_rows",
    "foundation_table",
    "derived_table",
    "notation_table",
    "markdown_table",
    "receptance_pole_frequencies",
    "critical_frequency",
    "plot_receptance",
    "receptance_check_table",
    "plot_rail_coupling",
    "plot_rail_and_sleeper",
]

RECEPTANCE_UNIT = 1e6
"""m/N to mm/kN (1 m/N = 1e3 mm / 1e-3 kN)."""


def plot_receptance(passage: Passage, omega: np.ndarray | None = None,
                    harmonics: int = 15) -> Figure:
    """|eta_E(omega)| of eq. (3) on log axes, with the train's harmonics and the poles.

    Parameters
    ----------
    passage : Passage
    omega : ndarray, optional
        Frequencies to plot [rad/s], default 4000 log-spaced from 0.1 to 5000.
    harmonics : int
        Harmonics omega_n, n = 1..harmonics, of the train to mark.

    Returns
    -------
    matplotlib.figure.Figure
        The curve is the line with gid "eta_E": x in rad/s, y = |eta_E| in
        mm/kN (`RECEPTANCE_UNIT` times m/N).  Harmonics: gid "harmonics".
    """
    if omega is None:
        omega = np.geomspace(0.1, 5000.0, 4000)
    omega = np.asarray(omega, dtype=float)
    eta = rail_receptance(passage, omega)
    fig, ax = new_figure(width=7.5, height=4.2)
    ax.loglog(omega, np.abs(eta) * RECEPTANCE_UNIT, "-", color="0.15", lw=1.0,
              label=r"$|\eta_E(\omega)|$", gid="eta_E")
    low = omega[omega < 0.5 * critical_frequency(passage)]
    ax.loglog(low, RECEPTANCE_UNIT / (passage.rail_linear_mass * passage.sleeper_spacing * low**2),
              color=BLUE, ls="--", lw=1.0, label=r"$1/(\rho S L \omega^2)$: one span as a mass",
              gid="mass-asymptote")
    poles = receptance_pole_frequencies(passage, omega.max())
    poles = poles[poles >= omega.min()]
    star = critical_frequency(passage)
    for k, p in enumerate(poles):
        is_star = np.isclose(p, star)
        ax.axvline(p, color=VERMILLION if is_star else PURPLE, lw=1.2 if is_star else 0.7,
                   ls="-." if is_star else ":", zorder=0,
                   label=(r"$\omega^* = v^2\sqrt{\rho S/EI}$" if is_star else
                          (r"other poles, $\cos k_bL = \cos(\omega L/v)$" if k == 1 else None)))
    wn = passage.fundamental_frequency * np.arange(1, harmonics + 1)
    ax.plot(wn, np.abs(rail_receptance(passage, wn)) * RECEPTANCE_UNIT, "o", ms=4,
            color=ORANGE, mec="0.2", mew=0.5, label=rf"train harmonics $\omega_n$, $n = 1..{harmonics}$",
            gid="harmonics")
    ax.set_xlabel(r"angular frequency $\omega$ [rad/s]")
    ax.set_ylabel(r"$|\eta_E|$ [mm/kN]")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(loc="lower left", fontsize="small")
    return fig


def receptance_check_table(passage: Passage, omega: Sequence[float]) -> str:
    """Markdown table of eta_E by the closed form of eq. (3) and by the lattice sum.

    Values in mm/kN with 9 significant digits and their relative difference
    (written "< 1e-12" below that, so that the printed table is stable).
    """
    omega = np.asarray(omega, dtype=float)
    closed = rail_receptance(passage, omega)
    lattice = rail_receptance_lattice_sum(passage, omega)
    rel = np.abs(closed - lattice) / np.abs(lattice)
    rows = [(f"{w:g}", f"{c * RECEPTANCE_UNIT:.9g}", f"{s * RECEPTANCE_UNIT:.9g}",
             f"{r:.0e}" if r >= 1e-12 else "< 1e-12")
            for w, c, s, r in zip(omega, closed, lattice, rel)]
    return markdown_table([r"$\omega$ [rad/s]", r"$\eta_E$ eq. (3) [mm/kN]",
                           r"$\eta_E$ lattice sum [mm/kN]", "relative difference"], rows)


def plot_rail_coupling(passage: Passage, omega: np.ndarray | None = None,
                       harmonics: int = 15) -> Figure:
    """The rail–sleeper coupling P(omega) of eq. (16): magnitude and phase.

    The magnitude is compared with omega_0^2 = k1/M (its value at omega = 0)
    and with omega^2 (the sleeper's inertia term of eq. 17).

    Parameters
    ----------
    passage : Passage
    omega : ndarray, optional
        Frequencies [rad/s], default 4000 log-spaced from 0.1 to 5000.
    harmonics : int
        Harmonics omega_n, n = 1..harmonics, to mark.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes; the |P| line has gid "P" (y in 1/s^2), the phase line gid
        "phase" (degrees).
    """
    if omega is None:
        omega = np.geomspace(0.1, 5000.0, 4000)
    omega = np.asarray(omega, dtype=float)
    P = rail_coupling(passage, omega)
    fig, (top, bottom) = new_figure(2, 1, width=7.5, height=2.8, sharex=True)
    top.loglog(omega, np.abs(P), "-", color="0.15", lw=1.0, label=r"$|P(\omega)|$", gid="P")
    top.axhline(passage.pad_natural_frequency_squared, color=BLUE, ls="--", lw=1.0,
                label=r"$\omega_0^2 = k_1/M$")
    top.loglog(omega, omega**2, color="0.45", ls=":", lw=1.0, label=r"$\omega^2$")
    wn = passage.fundamental_frequency * np.arange(1, harmonics + 1)
    Pn = rail_coupling(passage, wn)
    top.plot(wn, np.abs(Pn), "o", ms=4, color=ORANGE, mec="0.2", mew=0.5,
             label=r"$P_n$, $n = 1..%d$" % harmonics)
    top.axvline(critical_frequency(passage), color=VERMILLION, ls="-.", lw=1.0, label=r"$\omega^*$")
    top.set_ylim(passage.pad_natural_frequency_squared / 30, None)
    top.set_ylabel(r"$|P|$ [1/s²]")
    top.legend(fontsize="small", loc="upper left")
    bottom.semilogx(omega, np.degrees(np.angle(P)), "-", color="0.15", lw=1.0, gid="phase")
    bottom.plot(wn, np.degrees(np.angle(Pn)), "o", ms=4, color=ORANGE, mec="0.2", mew=0.5)
    bottom.axvline(critical_frequency(passage), color=VERMILLION, ls="-.", lw=1.0)
    bottom.set_ylabel(r"phase of $P$ [°]")
    bottom.set_xlabel(r"angular frequency $\omega$ [rad/s]")
    for ax in (top, bottom):
        ax.grid(True, which="major", alpha=0.3)
    return fig


# --------------------------------------------------------------------------
# Rail and sleeper, eq. (6)


def plot_rail_and_sleeper(solution, samples: int = 400) -> Figure:
    """Rail displacement above the sleeper and sleeper displacement over one period.

    Parameters
    ----------
    solution : railtrack.Solution
        A solved case; uses ``rail_displacement`` (eq. 6) and
        ``sleeper_displacement`` (eq. 12).
    samples : int
        Points over one period [0, T].

    Returns
    -------
    matplotlib.figure.Figure
        Top axes: lines with gid "rail" and "sleeper", t in s, displacement
        in mm (positive upward).  Bottom axes: the pad compression
        w - w_r(0, t) in mm (gid "compression") and its mean 2QL/(H k1)
        (gid "mean-compression").  Dotted verticals at the wheel passages
        t = 0 and D/v.
    """
    t = np.linspace(0.0, solution.period, samples + 1)
    fig, (ax, pad) = new_figure(2, 1, width=7.5, height=2.8, sharex=True,
                                gridspec_kw=dict(height_ratios=(1.6, 1.0)))
    passage = solution.passage
    rail, sleeper = solution.rail_displacement(t), solution.sleeper_displacement(t)
    ax.plot(t, rail * MM, "-", color=BLUE, lw=1.4,
            label=r"rail above the sleeper, $w_r(0,t)$", gid="rail")
    ax.plot(t, sleeper * MM, "--", color=ORANGE, lw=1.6,
            label=r"sleeper, $w(t)$", gid="sleeper")
    pad.plot(t, (sleeper - rail) * MM, "-", color=GREEN, lw=1.4,
             label=r"pad compression $w - w_r(0,t)$", gid="compression")
    mean = passage.static_load_per_sleeper / passage.pad_stiffness
    pad.axhline(mean * MM, color="0.3", ls="--", lw=0.9, label=r"$2QL/(Hk_1)$",
                gid="mean-compression")
    for axes in (ax, pad):
        for k, tw in enumerate(wheel_passage_times(passage)):
            axes.axvline(tw, color="0.5", ls=":", lw=1.2,
                         label="wheel above the sleeper" if k == 0 and axes is ax else None)
    label_displacement_axes(ax, ylabel="displacement [mm]\n(up > 0)")
    ax.set_xlabel("")
    label_displacement_axes(pad, ylabel="compression [mm]")
    ax.set_xlim(0.0, solution.period)
    # Above the axes, so that no legend covers a curve.
    ax.legend(fontsize="small", loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=3, frameon=False)
    pad.legend(fontsize="small", loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=2, frameon=False)
    return fig
