"""Markdown tables of the model's parameters: Table 1, the foundations, notation.

Built from the library's parameter objects, so the book's tables always show
the values the solver uses.  Values are shown in engineering units (MN/m,
kN, ...); the objects hold SI.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np

from ...model.foundations import BilinearFoundation, CubicFoundation, LinearFoundation
from ...equations.receptance import critical_frequency
from ...model.passage import Passage

__all__ = [
    "markdown_table",
    "table1_rows",
    "table1",
    "foundation_rows",
    "foundation_table",
    "derived_table",
    "notation_table",
]


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


# (quantity, symbol, field read from the Passage, display unit, SI value of one display unit)
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


def table1_rows(passage: Passage) -> list[dict]:
    """Rows of Table 1 of the paper, read from `passage`.

    Parameters
    ----------
    passage : Passage
        Usually ``Passage.paper()``.

    Returns
    -------
    list of dict
        One dict per parameter with keys ``quantity``, ``symbol`` (LaTeX),
        ``field`` (the `Track` or `Train` attribute), ``value`` (in ``unit``), ``unit``
        (engineering unit, e.g. "MN/m") and ``scale`` (SI value of one
        ``unit``), so that ``value * scale == getattr(passage, field)``.
    """
    rows = []
    for quantity, symbol, field, unit, scale in _TABLE1:
        si = float(getattr(passage, field))
        rows.append(dict(quantity=quantity, symbol=symbol, field=field,
                         value=si / scale, unit=unit, scale=scale))
    return rows


def table1(passage: Passage) -> str:
    """Table 1 of the paper as a markdown table (quantity, symbol, value, unit).

    Parameters
    ----------
    passage : Passage

    Returns
    -------
    str
        Markdown; show it with ``IPython.display.Markdown``.
    """
    rows = [(r["quantity"], r["symbol"], f"{r['value']:g}", r["unit"]) for r in table1_rows(passage)]
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


def derived_table(passage: Passage) -> str:
    """Quantities derived from Table 1 that the book uses, as a markdown table.

    Period T = H/v, first harmonic 2 pi v / H, mean load per sleeper 2QL/H,
    omega_0 = sqrt(k1/M), beta = eta1/M, and the frequency
    omega* = v^2 sqrt(rho S / EI) where omega / v = k_b.
    """
    rows = [
        ("Period of the load at one sleeper", r"$T = H/v$", f"{passage.period:.4g}", "s"),
        ("First harmonic", r"$\omega_1 = 2\pi v/H$", f"{passage.fundamental_frequency:.4g}",
         "rad/s"),
        ("Mean train load per sleeper", r"$2QL/H$",
         f"{passage.static_load_per_sleeper / 1e3:.4g}", "kN"),
        ("Pad–sleeper frequency", r"$\omega_0 = \sqrt{k_1/M}$",
         f"{np.sqrt(passage.pad_natural_frequency_squared):.4g}", "rad/s"),
        ("Pad damping rate", r"$\beta = \eta_1/M$", f"{passage.pad_damping_rate:.5g}", "1/s"),
        ("Frequency where $\\omega/v = k_b$", r"$\omega^* = v^2\sqrt{\rho S/EI}$",
         f"{critical_frequency(passage):.4g}", "rad/s"),
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
    (r"$\omega_0$", r"pad–sleeper frequency, $\omega_0^2 = k_1/M$, eq. (8)", "rad/s"),
    (r"$\beta$", r"pad damping rate $\eta_1/M$, eq. (8) (used for nothing else)", "1/s"),
    (r"$f(w, w')$", "force of the sleeper on the foundation (its reaction is $-f$)", "N"),
    (r"$g(w, w')$", r"foundation force per sleeper mass, $f/M$, eq. (8) (used for nothing else)",
     "m/s²"),
    (r"$k_2,\ \eta_2$", "foundation stiffness and damping, eqs. (22) and (25)", "N/m, N·s/m"),
    (r"$k_2^+,\ k_2^-$", r"bilinear foundation stiffness in compression ($w < 0$) and in "
     r"tension ($w \ge 0$), eq. (24)", "N/m"),
    (r"$e$", r"tension-to-compression ratio $k_2^-/k_2^+$ of eq. (24)", "–"),
    (r"$k_3,\ \varepsilon$", r"cubic stiffness and its dimensionless weight in "
     r"$\varepsilon k_3 w^3$, eq. (25)", "N/m³, –"),
    (r"$R(t)$", "force of sleeper 0 on the rail (pad force)", "N"),
    (r"$Q,\ v$", "load of one wheel (acting downward), train speed", "N, m/s"),
    (r"$L,\ H$", "sleeper spacing, wagon length", "m"),
    (r"$D$", "wheel (axle) spacing within the bogie of a wagon; nothing else", "m"),
    (r"$\ell_j,\ K$", r"distance of wheel $j$ behind the reference wheel (the paper's $D_j$), "
     "number of wheels", "m, –"),
    (r"$\omega,\ \hat f(\omega)$", r"angular frequency; $\hat f(\omega)=\int f(t)e^{-i\omega t}dt$",
     "rad/s"),
    (r"$k_b$", r"free bending wavenumber of the rail at frequency $\omega$, $k_b^4 = \rho S\omega^2/EI$, "
     "eq. (3)", "1/m"),
    (r"$\kappa,\ \kappa_j$", r"a wavenumber; $\kappa_j = \omega/v + 2\pi j/L$, the wavenumbers of the "
     "comb of sleeper forces (used for nothing else)", "1/m"),
    (r"$q$", r"phase $\omega L/v$ between neighbouring sleepers, eq. (3) (used for nothing else)", "rad"),
    (r"$\rho_0,\ \rho_n$", r"factor by which one step of eq. (21) multiplies the error of the mean, "
     "of harmonic $n$", "–"),
    (r"$\eta_E(\omega)$", "receptance of the periodically supported rail, eq. (3)", "m/N"),
    (r"$A(\omega)$", r"pad dynamic stiffness $k_1 + i\omega\eta_1$", "N/m"),
    (r"$\Gamma(\omega)$", "load transfer of eq. (6)", "m⁴"),
    (r"$\omega_n,\ T$", r"harmonics $2\pi n v/H$, period $H/v$", "rad/s, s"),
    (r"$c_n$", "Fourier coefficients of $w(t)$", "m"),
    (r"$P_n,\ F_n$", "rail coupling and train load of harmonic $n$, eq. (16)", "1/s², m/s²"),
    (r"$\mathcal{F}_{nk}$", r"harmonic $n$ of $g$ at iterate $k$, eq. (20) ($\mathcal{F}_n$ at the "
     "solution); not the load $F_n$", "m/s²"),
    (r"$m,\ k$", "number of harmonics kept, iteration index (a harmonic is $n$, or $n'$; "
     "never $k$)", "–"),
    (r"$\gamma(t),\ \nu(t)$", r"tangent stiffness and damping per sleeper mass along a "
     r"solution, $\partial g/\partial w$ and $\partial g/\partial w'$; harmonics "
     r"$\gamma_l,\ \nu_l$ (ch. 11)", "1/s², 1/s"),
    (r"$\lambda,\ \mu,\ \theta$", r"Floquet exponent, multiplier $\mu = e^{\lambda T}$ and "
     r"Bloch phase from one sleeper to the next of a disturbance (ch. 11); $\lambda$ is also "
     r"Newton's step (ch. 5) and the Winkler decay (ch. 9), never a wavelength ($H/n$)",
     "1/s, –, rad"),
    (r"$s$", r"complex frequency of a disturbance $e^{st}$ ($s = i\omega$ on the axis), ch. 11",
     "1/s"),
    (r"$\mathcal{S}(s, q)$", r"dynamic stiffness of one sleeper with its pad and the rail, "
     r"all moving as $e^{st}e^{-ijq}$ at sleeper $j$ (ch. 11)", "N/m"),
    (r"$N,\ \Lambda,\ \Theta$", r"sleepers in a cell, its length $NL$, the phase "
     r"$\omega\Lambda/v = Nq$ from one cell to the next (ch. 13)", "–, m, rad"),
    (r"$\sigma$", "Floquet mode of a cell of $N$ sleepers, $0 \\le \\sigma < N$ (ch. 13, 14)",
     "–"),
    (r"$h$", "gap between a hanging sleeper and its ballast (ch. 13)", "m"),
    (r"$r(x),\ Q_c$", r"height of the rail's top above its nominal line; wheel–rail contact "
     r"force, $Q_c = Q$ at rest (ch. 14)", "m, N"),
    (r"$\xi_l$", r"wavenumbers $2\pi l/H$ of the wagon pattern (ch. 14)", "1/m"),
    (r"$\psi$", r"squared wavenumber $\kappa^2$ of the Timoshenko rail; $\psi_1,\ \psi_2$ the "
     "roots of its dispersion relation (ch. 14)", "1/m²"),
    (r"$N_0$", r"split of eq. (21): harmonics $\lvert n\rvert \le N_0$ use its first branch, the others "
     "its second", "–"),
)


def notation_table() -> str:
    """The book's notation (symbol, meaning, SI unit) as a markdown table."""
    return markdown_table(["Symbol", "Meaning", "SI unit"], _NOTATION)
