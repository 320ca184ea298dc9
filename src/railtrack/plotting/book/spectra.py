"""Figures and tables of the load chapter (book chapter 4).

* `dirichlet_kernel`, `plot_dirichlet_kernel`: the partial sums of the wheel
  comb of eq. (10) growing into a Dirac comb;
* `load_spectrum_table`, `plot_load_spectra`: the coefficients P_n and F_n of
  eq. (16), with the harmonics where the two wheels of a wagon cancel
  (`vanishing_harmonics`).

SI inside; each data series carries a ``gid`` so that tests can find it.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from ...equations.sleeper import rail_coupling
from ...model.passage import Passage
from ...equations.load import load_coefficients
from ..style import BLUE, ORANGE, VERMILLION, new_figure, series_style

__all__ = [
    "dirichlet_kernel",
    "plot_dirichlet_kernel",
    "vanishing_harmonics",
    "load_spectrum_table",
    "plot_load_spectra",
]


# --------------------------------------------------------------------------
# Eq. (10): the comb of the wheels


def dirichlet_kernel(x: np.ndarray, order: int) -> np.ndarray:
    """Partial sum sum_{j=-J..J} exp(-i j x) of the wheel comb, eq. (10) [-].

    Evaluated as the plain sum of 2J + 1 exponentials (not by the closed form
    sin((2J+1)x/2) / sin(x/2), which the book derives), so that it can be
    checked against that form.  With x = omega T it is the spectrum of 2J + 1
    front wheels T = H / v apart in time.

    Parameters
    ----------
    x : ndarray
        Phase omega T [rad].
    order : int
        J >= 0.

    Returns
    -------
    ndarray
        Real values (the sum is symmetric in j), shape of `x`.

    Examples
    --------
    >>> float(dirichlet_kernel(np.array([0.0]), 3)[0])     # 2J + 1 at x = 0
    7.0
    """
    x = np.asarray(x, dtype=float)
    j = np.arange(-order, order + 1)
    return np.exp(-1j * np.multiply.outer(x, j)).sum(axis=-1).real


def plot_dirichlet_kernel(orders: Sequence[int] = (2, 5, 20), periods: float = 1.5,
                          points: int = 6001) -> Figure:
    """The partial sums D_J(omega T) of the wheel comb of eq. (10) for several J.

    Each tooth is 2J + 1 high and about 2 pi / (2J + 1) wide in omega T, so
    its area stays 2 pi while it narrows: the sums tend to a Dirac comb.

    Parameters
    ----------
    orders : sequence of int
        The J to draw (2J + 1 wagons).
    periods : float
        The x axis spans omega T / (2 pi) in [-periods, periods].
    points : int
        Samples along x.

    Returns
    -------
    matplotlib.figure.Figure
        One line per J, gid ``"kernel-J"``: x data omega T / (2 pi), y data
        `dirichlet_kernel` (2 pi x, J).
    """
    u = np.linspace(-periods, periods, points)
    fig, ax = new_figure(width=7.0, height=3.2)
    for n, order in enumerate(orders):
        # the last (narrowest, most ragged) sum solid and behind, the smooth first ones dashed
        ax.plot(u, dirichlet_kernel(2 * np.pi * u, order), lw=1.2, zorder=2.0 + 0.1 * (len(orders) - n),
                **series_style(len(orders) - 1 - n),
                label=f"J = {order} ({2 * order + 1} wagons)", gid=f"kernel-{order}")
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.set_xlabel(r"$\omega T / 2\pi$ (the teeth sit at the harmonic numbers $n$)")
    ax.set_ylabel(r"partial sum $\Pi_J(\omega T)$ [-]")
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(True, alpha=0.3)
    return fig


# --------------------------------------------------------------------------
# Eq. (16): P_n and F_n


def vanishing_harmonics(passage: Passage, harmonics: int, rtol: float = 1e-9) -> np.ndarray:
    """Harmonics n in 0..m where the library's F_n is zero to round-off.

    These are the n for which omega_n D / v = 2 pi n D / H is an odd multiple
    of pi: the back wheel's load then arrives in antiphase with the front
    wheel's and the two cancel (n = 3, 9, 15 for D / H = 1/6).

    Parameters
    ----------
    passage : Passage
    harmonics : int
        m.
    rtol : float
        |F_n| <= rtol |F_0| counts as zero.

    Returns
    -------
    ndarray of int
    """
    omega = passage.fundamental_frequency * np.arange(harmonics + 1)
    F = load_coefficients(passage, omega)
    return np.flatnonzero(np.abs(F) <= rtol * np.abs(F[0]))


def load_spectrum_table(passage: Passage, harmonics: int = 15) -> str:
    """Markdown table of omega_n, P_n and F_n (eq. 16) for n = 0..m.

    Columns: n, f_n = omega_n / 2 pi [Hz], Re P_n and Im P_n [10^6 1/s^2],
    |F_n| [m/s^2] and arg F_n [degrees].  Rounded for print; where F_n
    vanishes (the wheels cancel) the table says so instead of showing the
    round-off.

    Parameters
    ----------
    passage : Passage
    harmonics : int
        m.

    Returns
    -------
    str
    """
    n = np.arange(harmonics + 1)
    omega = passage.fundamental_frequency * n
    P = rail_coupling(passage, omega)
    F = load_coefficients(passage, omega)
    zero = set(vanishing_harmonics(passage, harmonics).tolist())
    lines = [
        r"| $n$ | $f_n$ [Hz] | Re $P_n$ [$10^6$ s$^{-2}$] | Im $P_n$ [$10^6$ s$^{-2}$] "
        r"| $\lvert F_n\rvert$ [m/s²] | arg $F_n$ [°] |",
        "|---:|---:|---:|---:|---:|---:|",
    ]
    for k in n:
        if k in zero:
            load = "0 | (wheels cancel)"
        else:
            load = f"{abs(F[k]):.4g} | {np.degrees(np.angle(F[k])):.1f}"
        lines.append(
            f"| {k} | {omega[k] / (2 * np.pi):.1f} | {P[k].real / 1e6:.4f} | "
            f"{P[k].imag / 1e6:.4f} | {load} |"
        )
    return "\n".join(lines)


def plot_load_spectra(passage: Passage, harmonics: int = 15, points: int = 800) -> Figure:
    """|P_n| and |F_n| of eq. (16) at the harmonics, over the continuous |P(omega)|, |F(omega)|.

    Parameters
    ----------
    passage : Passage
    harmonics : int
        m: harmonics n = 0..m are marked.
    points : int
        Samples of the continuous curves.

    Returns
    -------
    matplotlib.figure.Figure
        Two axes sharing the harmonic number n (bottom; frequency in Hz on
        top).  Top: gid ``"P-harmonics"`` (y = |P_n| in 10^6 1/s^2) and
        ``"P-curve"``.  Bottom: gid ``"F-harmonics"`` (y = |F_n| in m/s^2),
        ``"F-curve"`` and ``"F-vanishing"`` (the n where F_n = 0, y = 0).
    """
    n = np.arange(harmonics + 1)
    omega1 = passage.fundamental_frequency
    nu = np.linspace(0.0, harmonics + 0.5, points)
    P_n, F_n = rail_coupling(passage, omega1 * n), load_coefficients(passage, omega1 * n)
    P_c, F_c = rail_coupling(passage, omega1 * nu), load_coefficients(passage, omega1 * nu)
    zero = vanishing_harmonics(passage, harmonics)

    fig, (top, bottom) = new_figure(2, 1, width=7.0, height=2.7, sharex=True)
    top.plot(nu, np.abs(P_c) / 1e6, "-", color="0.6", lw=1.0, label=r"$|P(\omega)|$", gid="P-curve")
    top.plot(n, np.abs(P_n) / 1e6, "o", color=BLUE, ms=5, label=r"$|P_n|$",
             gid="P-harmonics")
    top.axhline(passage.pad_natural_frequency_squared / 1e6, color=ORANGE, ls="--", lw=1.0,
                label=r"$\omega_0^2 = k_1/M$")
    top.set_ylabel(r"$|P_n|$ [$10^6$ s$^{-2}$]")
    top.set_ylim(bottom=0.0)

    bottom.plot(nu, np.abs(F_c), "-", color="0.6", lw=1.0, label=r"$|F(\omega)|$", gid="F-curve")
    bottom.plot(n, np.abs(F_n), "o", color=BLUE, ms=5, label=r"$|F_n|$",
                gid="F-harmonics")
    bottom.axhline(passage.static_load_per_sleeper / passage.sleeper_mass, color=ORANGE,
                   ls="--", lw=1.0, label=r"$F_0 = 2QL/(MH)$")
    bottom.plot(zero, np.zeros(len(zero)), "x", color=VERMILLION, ms=9, mew=2,
                label=r"$F_n = 0$: wheels cancel (n = " + ", ".join(map(str, zero)) + ")",
                gid="F-vanishing")
    for k in zero:
        bottom.axvline(k, color=VERMILLION, ls=":", lw=0.8)
    bottom.set_ylabel(r"$|F_n|$ [m/s²]")
    bottom.set_xlabel(r"harmonic number $n$ ($\omega_n = 2\pi n v/H$)")
    bottom.set_ylim(bottom=-2.0)
    f1 = omega1 / (2 * np.pi)
    top.secondary_xaxis("top", functions=(lambda x: x * f1, lambda f: f / f1)).set_xlabel(
        "frequency [Hz]")
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="upper right")
    return fig
