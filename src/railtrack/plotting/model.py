"""Figures and tables of the model chapters (book chapters 1–3).

* `draw_track_schematic`: the model of Fig. 1 of the paper, drawn with matplotlib;
* `table1`, `foundation_table`, `derived_table`, `notation_table`: markdown tables
  built from the library's parameter objects (Table 1 and Section 4);
* `receptance_pole_frequencies`, `plot_receptance`, `receptance_check_table`:
  the receptance eta_E of eq. (3) and its check by the lattice sum;
* `plot_rail_coupling`: the coupling P(omega) of eq. (16);
* `plot_rail_and_sleeper`: rail and sleeper displacement over one period, eq. (6).

Everything is SI inside; axes show millimetres, seconds, mm/kN.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch, Rectangle

from ..foundations import BilinearFoundation, CubicFoundation, LinearFoundation
from ..receptance import rail_receptance, rail_receptance_lattice_sum
from ..sleeper import rail_coupling
from ..track import Track
from ..train import wheel_passage_times
from .style import MM, label_displacement_axes, new_figure

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


# --------------------------------------------------------------------------
# Tables


def markdown_table(header: Sequence[str], rows: Sequence[Sequence[object]]) -> str:
    """A GitHub/MyST markdown table from a header and rows of printable cells.

    >>> print(markdown_table(["a", "b"], [[1, 2]]))
    | a | b |
    |---|---|
    | 1 | 2 |
    """
    lines = ["| " + " | ".join(str(h) for h in header) + " |"]
    lines.append("|" + "|".join("---" for _ in header) + "|")
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


# (quantity, symbol, Track field, display unit, SI value of one display unit)
_TABLE1 = (
    ("Rail mass per length", r"$\rho S$", "rail_linear_mass", "kg/m", 1.0),
    ("Rail bending stiffness", r"$EI$", "rail_bending_stiffness", "MN·m²", 1e6),
    ("Train speed", r"$v$", "speed", "m/s", 1.0),
    ("Load of one wheel", r"$Q$", "wheel_load", "kN", 1e3),
    ("Sleeper (block) mass", r"$M$", "sleeper_mass", "kg", 1.0),
    ("Sleeper spacing", r"$L$", "sleeper_spacing", "m", 1.0),
    ("Wheel spacing in a wagon (bogie)", r"$D$", "wheel_spacing", "m", 1.0),
    ("Wagon length", r"$H$", "wagon_length", "m", 1.0),
    ("Pad stiffness", r"$k_1$", "pad_stiffness", "MN/m", 1e6),
    ("Pad damping", r"$\eta_1$", "pad_damping", "MN·s/m", 1e6),
)


def table1_rows(track: Track) -> list[dict]:
    """Rows of Table 1 of the paper, read from `track`.

    Parameters
    ----------
    track : Track
        Usually ``Track.paper()``.

    Returns
    -------
    list of dict
        One dict per parameter with keys ``quantity``, ``symbol`` (LaTeX),
        ``field`` (the `Track` attribute), ``value`` (in ``unit``), ``unit``
        (engineering unit, e.g. "MN/m") and ``scale`` (SI value of one
        ``unit``), so that ``value * scale == getattr(track, field)``.
    """
    rows = []
    for quantity, symbol, field, unit, scale in _TABLE1:
        si = float(getattr(track, field))
        rows.append(dict(quantity=quantity, symbol=symbol, field=field,
                         value=si / scale, unit=unit, scale=scale))
    return rows


def table1(track: Track) -> str:
    """Table 1 of the paper as a markdown table (quantity, symbol, value, unit).

    Parameters
    ----------
    track : Track

    Returns
    -------
    str
        Markdown; show it with ``IPython.display.Markdown``.
    """
    rows = [(r["quantity"], r["symbol"], f"{r['value']:g}", r["unit"]) for r in table1_rows(track)]
    return markdown_table(["Quantity", "Symbol", "Value", "Unit"], rows)


def foundation_rows(linear: LinearFoundation, bilinear: BilinearFoundation,
                    cubic: CubicFoundation) -> list[dict]:
    """Parameters of the three foundation laws of Section 4, in engineering units.

    Returns
    -------
    list of dict
        Keys ``law``, ``equation``, ``symbol``, ``value``, ``unit``, ``scale``
        and ``si`` (``value * scale == si``).
    """
    spec = [
        ("linear", "(22)", r"$k_2$", linear.stiffness, "MN/m", 1e6),
        ("linear", "(22)", r"$\eta_2$", linear.damping, "MN·s/m", 1e6),
        ("bilinear", "(24)", r"$k_2^+$ (compression, $w<0$)", bilinear.compression_stiffness,
         "MN/m", 1e6),
        ("bilinear", "(24)", r"$k_2^-$ (tension, $w\geq 0$)", bilinear.tension_stiffness,
         "MN/m", 1e6),
        ("bilinear", "(24)", r"$\eta_2$", bilinear.damping, "MN·s/m", 1e6),
        ("cubic", "(25)", r"$k_2$", cubic.stiffness, "MN/m", 1e6),
        ("cubic", "(25)", r"$k_3$", cubic.cubic_stiffness, "kN/mm³", 1e3 / 1e-9),
        ("cubic", "(25)", r"$\varepsilon$", cubic.epsilon, "–", 1.0),
        ("cubic", "(25)", r"$\eta_2$", cubic.damping, "MN·s/m", 1e6),
    ]
    return [dict(law=law, equation=eq, symbol=sym, si=float(si), value=float(si) / scale,
                 unit=unit, scale=scale) for law, eq, sym, si, unit, scale in spec]


def foundation_table(linear: LinearFoundation, bilinear: BilinearFoundation,
                     cubic: CubicFoundation) -> str:
    """The foundation parameters of Section 4 as a markdown table."""
    rows = [(r["law"], r["equation"], r["symbol"], f"{r['value']:g}", r["unit"])
            for r in foundation_rows(linear, bilinear, cubic)]
    return markdown_table(["Law", "Eq.", "Symbol", "Value", "Unit"], rows)


def derived_table(track: Track) -> str:
    """Quantities derived from Table 1 that the book uses, as a markdown table.

    Period T = H/v, first harmonic 2 pi v / H, mean load per sleeper 2QL/H,
    omega_0 = sqrt(k1/M), beta = eta1/M, and the frequency
    omega* = v^2 sqrt(rho S / EI) where omega / v = k_b.
    """
    rows = [
        ("Period of the load at one sleeper", r"$T = H/v$", f"{track.period:.4g}", "s"),
        ("First harmonic", r"$\omega_1 = 2\pi v/H$", f"{track.fundamental_frequency:.4g}",
         "rad/s"),
        ("Mean train load per sleeper", r"$2QL/H$",
         f"{track.static_load_per_sleeper / 1e3:.4g}", "kN"),
        ("Pad–sleeper frequency", r"$\omega_0 = \sqrt{k_1/M}$",
         f"{np.sqrt(track.pad_natural_frequency_squared):.4g}", "rad/s"),
        ("Pad damping rate", r"$\beta = \eta_1/M$", f"{track.pad_damping_rate:.5g}", "1/s"),
        ("Frequency where $\\omega/v = k_b$", r"$\omega^* = v^2\sqrt{\rho S/EI}$",
         f"{critical_frequency(track):.4g}", "rad/s"),
    ]
    return markdown_table(["Quantity", "Symbol", "Value", "Unit"], rows)


_NOTATION = (
    (r"$x$", "position along the rail; sleeper 0 at $x = 0$, wheels move toward $+x$", "m"),
    (r"$t$", "time; $t = 0$ when a front wheel is above sleeper 0", "s"),
    (r"$w_r(x,t)$", "rail displacement, positive upward", "m"),
    (r"$w(t)$", "displacement of sleeper 0, positive upward", "m"),
    (r"$\rho S,\ EI$", "rail mass per length, bending stiffness", "kg/m, N·m²"),
    (r"$k_1,\ \eta_1$", "pad stiffness and damping", "N/m, N·s/m"),
    (r"$M$", "mass of one sleeper", "kg"),
    (r"$f(w, w')$", "force of the sleeper on the foundation (its reaction is $-f$)", "N"),
    (r"$R(t)$", "force of sleeper 0 on the rail (pad force)", "N"),
    (r"$Q,\ v$", "load of one wheel (acting downward), train speed", "N, m/s"),
    (r"$L,\ D,\ H$", "sleeper spacing, wheel spacing in a wagon, wagon length", "m"),
    (r"$\omega,\ \hat f(\omega)$", r"angular frequency; $\hat f(\omega)=\int f(t)e^{-i\omega t}dt$",
     "rad/s"),
    (r"$k_b$", r"free bending wavenumber, $k_b^4 = \rho S\omega^2/EI$", "1/m"),
    (r"$\eta_E(\omega)$", "receptance of the periodically supported rail, eq. (3)", "m/N"),
    (r"$A(\omega)$", r"pad dynamic stiffness $k_1 + i\omega\eta_1$", "N/m"),
    (r"$\Gamma(\omega)$", "load transfer of eq. (6)", "m⁴"),
    (r"$\omega_n,\ T$", r"harmonics $2\pi n v/H$, period $H/v$", "rad/s, s"),
    (r"$c_n$", "Fourier coefficients of $w(t)$", "m"),
    (r"$P_n,\ F_n$", "rail coupling and train load of harmonic $n$, eq. (16)", "1/s², m/s²"),
    (r"$m,\ k$", "number of harmonics kept, iteration index", "–"),
)


def notation_table() -> str:
    """The book's notation (symbol, meaning, SI unit) as a markdown table."""
    return markdown_table(["Symbol", "Meaning", "SI unit"], _NOTATION)


# --------------------------------------------------------------------------
# Schematic of the model (Fig. 1 of the paper)


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


def draw_track_schematic(track: Track, *, sleepers: int = 9, observed: int = 6,
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
    track : Track
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
    dark = dict(color="0.15", lw=1.1)

    # rail: an infinite beam (dotted ends)
    ax.add_patch(Rectangle((left, -0.07), right - left, 0.14, color="0.3", zorder=3))
    for x0, x1 in ((left - 0.5, left), (right, right + 0.5)):
        ax.plot([x0, x1], [0, 0], ls=":", color="0.3", lw=2)
    ax.annotate(r"rail $EI,\ \rho S$", (left - 0.5, 0.0), (xs[0] - 0.95, 0.45), ha="right",
                va="center", arrowprops=dict(arrowstyle="-", color="0.4", lw=0.7))

    for i, x in enumerate(xs):
        _spring(ax, x - 0.1, -0.07, y_pad, **dark)
        _dashpot(ax, x + 0.1, -0.07, y_pad, **dark)
        colour = "tab:orange" if i == observed else "0.55"
        ax.add_patch(Rectangle((x - 0.2, y_sl), 0.4, y_pad - y_sl, color=colour, gid="sleeper",
                               zorder=3))
        ax.add_patch(Rectangle((x - 0.2, y_gr), 0.4, y_sl - y_gr, facecolor="0.92",
                               edgecolor="0.3", hatch="...", lw=0.8, gid="foundation"))
    ax.plot([left, right], [y_gr, y_gr], color="0.2", lw=1.5)
    for x in np.arange(left, right, 0.25):
        ax.plot([x, x - 0.15], [y_gr, y_gr - 0.15], color="0.4", lw=0.6)

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
                                 mutation_scale=11, color="tab:orange", lw=1.3))
    ax.text(xo + 0.41, y_pad + 0.02, r"$w$", color="tab:orange", va="center")
    ax.text(xo, y_gr - 0.3, r"observed sleeper, $x = 0$", ha="center", va="top",
            color="tab:orange")

    # sleeper spacing L
    _dimension(ax, xs[1], xs[2], y_gr - 0.45, rf"$L = {track.sleeper_spacing:g}$ m")

    # wheels: back and front wheel of one wagon, front wheel of the next one
    radius, y_wheel = 0.28, 0.07 + 0.28
    wheel_x = (xs[back_wheel], xo)
    for x in wheel_x:
        ax.add_patch(Circle((x, y_wheel), radius, facecolor="white", edgecolor="0.1", lw=1.5,
                            gid="wheel", zorder=4))
        ax.add_patch(FancyArrowPatch((x, 1.55), (x, y_wheel + radius + 0.02), arrowstyle="-|>",
                                     mutation_scale=12, color="tab:red", lw=1.6))
        ax.text(x + 0.08, 1.3, rf"$Q = {track.wheel_load / 1e3:g}$ kN", color="tab:red",
                va="center")
    x_next = -0.35
    ax.add_patch(Circle((x_next, y_wheel), radius, facecolor="white", edgecolor="0.5", lw=1.2,
                        ls="--", gid="next-wheel", zorder=4))
    ax.add_patch(FancyArrowPatch((x_next, 1.55), (x_next, y_wheel + radius + 0.02),
                                 arrowstyle="-|>", mutation_scale=12, color="tab:red", lw=1.0,
                                 ls="--", alpha=0.6))
    ax.text(x_next + 0.08, 1.3, "next wagon", color="0.4", va="center", fontsize="small")
    _dimension(ax, wheel_x[0], wheel_x[1], 1.75, rf"$D = {track.wheel_spacing:g}$ m")
    _dimension(ax, x_next, wheel_x[1], 2.25, rf"$H = {track.wagon_length:g}$ m")

    # speed
    ax.add_patch(FancyArrowPatch((xo + 0.4, 1.85), (xo + 1.7, 1.85), arrowstyle="-|>",
                                 mutation_scale=14, color="tab:blue", lw=1.8))
    ax.text(xo + 1.05, 1.92, rf"$v = {track.speed:g}$ m/s", color="tab:blue", ha="center",
            va="bottom")
    ax.text(right + 0.5, y_gr - 0.75, "not to scale", ha="right", va="bottom", fontsize="small",
            color="0.4", style="italic")
    ax.set_xlim(left - 2.6, right + 0.6)
    ax.set_ylim(y_gr - 0.8, 2.7)
    return fig


# --------------------------------------------------------------------------
# Receptance of the rail, eq. (3)


def critical_frequency(track: Track) -> float:
    """omega* = v^2 sqrt(rho S / EI), where omega / v equals k_b [rad/s]."""
    return float(track.speed**2 * np.sqrt(track.rail_linear_mass / track.rail_bending_stiffness))


def receptance_pole_frequencies(track: Track, omega_max: float) -> np.ndarray:
    """Frequencies 0 < omega <= omega_max where cos(k_b L) = cos(omega L / v) [rad/s].

    There eta_E of eq. (3) is infinite: a free bending wave of the rail
    (wavenumber k_b) matches a spatial harmonic omega/v + 2 pi j / L of the
    sleeper forces.  With s = sqrt(omega) and c = (rho S/EI)^(1/4) the
    conditions ``omega L / v - 2 pi m = -+ k_b L`` are quadratics in s:
    ``s = v [+-c + sqrt(c^2 + 8 pi m / (v L))] / 2``, m = 0, 1, 2, ...
    (m = 0 with the + sign is omega* of `critical_frequency`).

    Returns
    -------
    ndarray
        Sorted pole frequencies (omega = 0 itself is not listed).
    """
    c = (track.rail_linear_mass / track.rail_bending_stiffness) ** 0.25
    v, span = track.speed, track.sleeper_spacing
    poles = [critical_frequency(track)]
    m = 1
    while True:
        root = np.sqrt(c * c + 8.0 * np.pi * m / (v * span))
        pair = [(0.5 * v * (sign * c + root)) ** 2 for sign in (-1.0, 1.0)]
        if min(pair) > omega_max:
            break
        poles += pair
        m += 1
    poles = np.sort(np.array(poles))
    return poles[poles <= omega_max]


def plot_receptance(track: Track, omega: np.ndarray | None = None,
                    harmonics: int = 15) -> Figure:
    """|eta_E(omega)| of eq. (3) on log axes, with the train's harmonics and the poles.

    Parameters
    ----------
    track : Track
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
    eta = rail_receptance(track, omega)
    fig, ax = new_figure(width=7.5, height=4.2)
    ax.loglog(omega, np.abs(eta) * RECEPTANCE_UNIT, color="0.15", lw=1.0,
              label=r"$|\eta_E(\omega)|$", gid="eta_E")
    low = omega[omega < 0.5 * critical_frequency(track)]
    ax.loglog(low, RECEPTANCE_UNIT / (track.rail_linear_mass * track.sleeper_spacing * low**2),
              color="tab:blue", ls="--", lw=0.9, label=r"$1/(\rho S L \omega^2)$: one span as a mass",
              gid="mass-asymptote")
    poles = receptance_pole_frequencies(track, omega.max())
    poles = poles[poles >= omega.min()]
    star = critical_frequency(track)
    for k, p in enumerate(poles):
        is_star = np.isclose(p, star)
        ax.axvline(p, color="tab:red" if is_star else "tab:purple", lw=1.2 if is_star else 0.6,
                   ls="-" if is_star else ":", zorder=0,
                   label=(r"$\omega^* = v^2\sqrt{\rho S/EI}$" if is_star else
                          (r"other poles, $\cos k_bL = \cos(\omega L/v)$" if k == 1 else None)))
    wn = track.fundamental_frequency * np.arange(1, harmonics + 1)
    ax.plot(wn, np.abs(rail_receptance(track, wn)) * RECEPTANCE_UNIT, "o", ms=4,
            color="tab:green", label=rf"train harmonics $\omega_n$, $n = 1..{harmonics}$",
            gid="harmonics")
    ax.set_xlabel(r"angular frequency $\omega$ [rad/s]")
    ax.set_ylabel(r"$|\eta_E|$ [mm/kN]")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(loc="lower left", fontsize="small")
    return fig


def receptance_check_table(track: Track, omega: Sequence[float]) -> str:
    """Markdown table of eta_E by the closed form of eq. (3) and by the lattice sum.

    Values in mm/kN with 9 significant digits and their relative difference
    (written "< 1e-12" below that, so that the printed table is stable).
    """
    omega = np.asarray(omega, dtype=float)
    closed = rail_receptance(track, omega)
    lattice = rail_receptance_lattice_sum(track, omega)
    rel = np.abs(closed - lattice) / np.abs(lattice)
    rows = [(f"{w:g}", f"{c * RECEPTANCE_UNIT:.9g}", f"{s * RECEPTANCE_UNIT:.9g}",
             f"{r:.0e}" if r >= 1e-12 else "< 1e-12")
            for w, c, s, r in zip(omega, closed, lattice, rel)]
    return markdown_table([r"$\omega$ [rad/s]", r"$\eta_E$ eq. (3) [mm/kN]",
                           r"$\eta_E$ lattice sum [mm/kN]", "relative difference"], rows)


def plot_rail_coupling(track: Track, omega: np.ndarray | None = None,
                       harmonics: int = 15) -> Figure:
    """The rail–sleeper coupling P(omega) of eq. (16): magnitude and phase.

    The magnitude is compared with omega_0^2 = k1/M (its value at omega = 0)
    and with omega^2 (the sleeper's inertia term of eq. 17).

    Parameters
    ----------
    track : Track
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
    P = rail_coupling(track, omega)
    fig, (top, bottom) = new_figure(2, 1, width=7.5, height=2.8, sharex=True)
    top.loglog(omega, np.abs(P), color="0.15", lw=1.0, label=r"$|P(\omega)|$", gid="P")
    top.axhline(track.pad_natural_frequency_squared, color="tab:blue", ls="--", lw=0.9,
                label=r"$\omega_0^2 = k_1/M$")
    top.loglog(omega, omega**2, color="tab:gray", ls=":", lw=0.9, label=r"$\omega^2$")
    wn = track.fundamental_frequency * np.arange(1, harmonics + 1)
    Pn = rail_coupling(track, wn)
    top.plot(wn, np.abs(Pn), "o", ms=4, color="tab:green", label=r"$P_n$, $n = 1..%d$" % harmonics)
    top.axvline(critical_frequency(track), color="tab:red", lw=0.8, label=r"$\omega^*$")
    top.set_ylim(track.pad_natural_frequency_squared / 30, None)
    top.set_ylabel(r"$|P|$ [1/s²]")
    top.legend(fontsize="small", loc="upper left")
    bottom.semilogx(omega, np.degrees(np.angle(P)), color="0.15", lw=1.0, gid="phase")
    bottom.plot(wn, np.degrees(np.angle(Pn)), "o", ms=4, color="tab:green")
    bottom.axvline(critical_frequency(track), color="tab:red", lw=0.8)
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
    track = solution.track
    rail, sleeper = solution.rail_displacement(t), solution.sleeper_displacement(t)
    ax.plot(t, rail * MM, color="tab:blue", lw=1.4,
            label=r"rail above the sleeper, $w_r(0,t)$", gid="rail")
    ax.plot(t, sleeper * MM, color="tab:orange", lw=1.4,
            label=r"sleeper, $w(t)$", gid="sleeper")
    pad.plot(t, (sleeper - rail) * MM, color="tab:green", lw=1.4,
             label=r"pad compression $w - w_r(0,t)$", gid="compression")
    mean = track.static_load_per_sleeper / track.pad_stiffness
    pad.axhline(mean * MM, color="0.3", ls="--", lw=0.9, label=r"$2QL/(Hk_1)$",
                gid="mean-compression")
    for axes in (ax, pad):
        for k, tw in enumerate(wheel_passage_times(track)):
            axes.axvline(tw, color="0.5", ls=":", lw=1.2,
                         label="wheel above the sleeper" if k == 0 and axes is ax else None)
    label_displacement_axes(ax, ylabel="displacement [mm]\n(up > 0)")
    ax.set_xlabel("")
    label_displacement_axes(pad, ylabel="compression [mm]")
    ax.set_xlim(0.0, solution.period)
    ax.legend(fontsize="small", loc="lower right")
    pad.legend(fontsize="small", loc="upper right")
    return fig
