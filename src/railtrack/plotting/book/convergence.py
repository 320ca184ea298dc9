"""Figures and tables of the method chapter (book chapter 5).

* `plot_aft`: alternating frequency/time for eq. (20), from w(t) samples to
  g(t) samples to the harmonics G_n;
* `plot_contraction_factors`: the error factors of the paper's iteration,
  eq. (21), for both of its branches;
* `convergence_histories`, `plot_convergence`, `convergence_table`: the
  relative residual of eq. (17) against the iteration number for the fixed
  point and Newton; `change_and_error_table`: why the change between
  iterates is no measure of the error.

SI inside; axes show millimetres and seconds.  w is positive upward; t = 0
when a front wheel is above the observed sleeper.  Each data series carries
a ``gid`` so that tests can find it.
"""

from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np
from matplotlib.figure import Figure

from ...solvers.fixed_point import contraction_factors
from ...equations.harmonic_balance import HarmonicSystem, harmonic_system, nonlinear_coefficients, synthesize
from ...equations.linear import analytic_coefficients
from ...solvers.solution import Solution
from ...solvers.solve import solve
from ...model.passage import Passage
from ..style import BLACK, BLUE, MM, ORANGE, TIME_LABEL, VERMILLION, new_figure

__all__ = [
    "METHOD_LABELS",
    "plot_aft",
    "plot_contraction_factors",
    "convergence_histories",
    "plot_convergence",
    "convergence_table",
    "change_and_error_table",
]

METHOD_LABELS = {"fixed-point": "fixed point, eq. (21)", "newton": "Newton, AFT Jacobian"}
"""Legend text of each `railtrack.solve` method in `plot_convergence`."""

_METHOD_STYLE = {
    "fixed-point": dict(color=ORANGE, ls="-", lw=1.4),
    "newton": dict(color=BLUE, ls="--", lw=1.4, marker="o", ms=4),
}


# --------------------------------------------------------------------------
# Eq. (20): alternating frequency/time


def plot_aft(solution: Solution, samples: int | None = None) -> Figure:
    """The three steps of the AFT evaluation of eq. (20) for a solved case.

    (a) w(t) synthesised from c_0..c_m on N samples (dots) over the truncated
    Fourier series (line); (b) g(t) = f(w, w') / M at the same samples;
    (c) |G_n| from the FFT of the samples, n = 0..N/2: the harmonics n <= m
    enter eq. (17), the others are discarded.

    Parameters
    ----------
    solution : Solution
        From `railtrack.solve`; its track, foundation, m and coefficients.
    samples : int, optional
        N; default the solution's own (`railtrack.equations.harmonic_balance.default_samples`).

    Returns
    -------
    matplotlib.figure.Figure
        Three axes.  gid ``"w-samples"`` (t in s, w in mm), ``"w-series"``,
        ``"g-samples"`` (t in s, g in m/s^2), ``"G-kept"`` (n = 0..m, |G_n| in
        m/s^2, equal to `railtrack.equations.harmonic_balance.nonlinear_coefficients`)
        and ``"G-dropped"`` (n = m+1..N/2).
    """
    m = solution.harmonics
    system = harmonic_system(solution.passage, solution.foundation, m,
                             samples or solution.samples)
    c = solution.coefficients[m:]
    N, T = system.samples, solution.period
    t = np.arange(N) * T / N
    w, v = synthesize(system, c)
    g = np.asarray(system.foundation.force(w, v), dtype=float) / system.sleeper_mass
    G_all = np.abs(np.fft.rfft(g)) / N
    G_kept = np.abs(nonlinear_coefficients(system, c))

    fig, (ax_w, ax_g, ax_G) = new_figure(3, 1, width=7.0, height=2.3)
    fine = np.linspace(0.0, T, 20 * N + 1)
    ax_w.plot(fine, solution.sleeper_displacement(fine) * MM, "-", color="0.6", lw=1.0,
              label=r"$w_m(t)$, eq. (19)", gid="w-series")
    ax_w.plot(t, w * MM, ".", color=BLUE, ms=3,
              label=f"N = {N} samples (inverse FFT)", gid="w-samples")
    ax_w.set_ylabel("w [mm] (up > 0)")
    ax_g.plot(t, g, ".", color=VERMILLION, ms=3, label=r"$g = f(w, w')/M$ at the samples",
              gid="g-samples")
    ax_g.set_ylabel(r"g [m/s²]")
    for ax in (ax_w, ax_g):
        ax.set_xlabel(TIME_LABEL)
    n_all = np.arange(len(G_all))
    ax_G.semilogy(n_all[m + 1:], G_all[m + 1:], "x", color="0.5", ms=3.5,
                  label=r"$n > m$: dropped by the truncation", gid="G-dropped")
    ax_G.semilogy(np.arange(m + 1), G_kept, "o", color=VERMILLION, ms=4,
                  label=r"$n \leq m$: $\mathcal{F}_n$ of eq. (20)", gid="G-kept")
    ax_G.axvline(m + 0.5, color="0.3", ls=":", lw=0.9)
    ax_G.set_xlabel(r"harmonic number $n$ (FFT of the samples)")
    ax_G.set_ylabel(r"$|G_n|$ [m/s²]")
    for ax in (ax_w, ax_g, ax_G):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="best")
    return fig


# --------------------------------------------------------------------------
# Eq. (21): contraction factors and convergence


def plot_contraction_factors(system: HarmonicSystem) -> Figure:
    """Error factors of eq. (21) for each harmonic, first and second branch.

    Parameters
    ----------
    system : HarmonicSystem
        From `railtrack.equations.harmonic_balance.harmonic_system`; for a nonlinear law
        the factors use its ``linearization()`` and are an estimate.

    Returns
    -------
    matplotlib.figure.Figure
        gid ``"first-branch"`` (every n treated by the branch |n| <= N0, i.e.
        `contraction_factors(system, m)`) and ``"second-branch"``
        (`contraction_factors(system, -1)`), x = n, y = factor (log axis);
        a line at 1 separates contraction from divergence.
    """
    n = np.arange(system.harmonics + 1)
    first = contraction_factors(system, system.harmonics)
    second = contraction_factors(system, -1)
    fig, ax = new_figure(width=7.0, height=3.2)
    ax.semilogy(n, first, "o-", color=BLUE, ms=4, lw=1.2,
                label=r"first branch ($|n| \leq N_0$)", gid="first-branch")
    ax.semilogy(n, second, "s--", color=ORANGE, ms=4, lw=1.2,
                label=r"second branch ($|n| > N_0$)", gid="second-branch")
    ax.axhline(1.0, color=BLACK, lw=1.0, ls=":", label="1: converges below, diverges above")
    ax.annotate(f"mean (n = 0): {first[0]:.3f} = 1 - k2/k1", (0, first[0]), xytext=(1.5, 0.25),
                arrowprops=dict(arrowstyle="->", lw=0.8), fontsize="small")
    ax.set_xlabel(r"harmonic number $n$")
    ax.set_ylabel("error factor per iteration [-]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize="small", loc="lower left")
    return fig


def convergence_histories(passage: Passage, laws: Mapping[str, object], harmonics: int = 15,
                          *, tol: float = 1e-10, fixed_point_iterations: int = 3000
                          ) -> dict[str, dict[str, Solution]]:
    """Solve each law with the fixed point and with Newton (library defaults otherwise).

    The fixed point starts from c = 0 with N0 = m, as in the paper; Newton
    starts from its default guess, eq. (23) with the law's linearisation.

    Parameters
    ----------
    passage : Passage
    laws : mapping of str to foundation
        Name (for the panel title) to law.
    harmonics : int
        m.
    tol : float
        Relative residual of eq. (17) at which both methods stop.
    fixed_point_iterations : int
        Largest number of fixed-point iterations.

    Returns
    -------
    dict
        ``{name: {"fixed-point": Solution, "newton": Solution}}``.
    """
    return {
        name: {
            "fixed-point": solve(passage.track, passage.train, law, harmonics, method="fixed-point", tol=tol,
                                 max_iterations=fixed_point_iterations),
            "newton": solve(passage.track, passage.train, law, harmonics, method="newton", tol=tol),
        }
        for name, law in laws.items()
    }


def plot_convergence(histories: Mapping[str, Mapping[str, Solution]]) -> Figure:
    """Relative residual of eq. (17) against the iteration for each law and method.

    Parameters
    ----------
    histories : mapping
        ``{name: {method: Solution}}`` as returned by `convergence_histories`.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per law (2 columns), one line per method with gid equal to
        the method name: x = iteration 0, 1, ..., y = ``residual_history``
        (log axis).  A dotted line marks the tolerance 1e-10.
    """
    names = list(histories)
    rows = (len(names) + 1) // 2
    fig, axes = new_figure(rows, 2, width=7.5, height=2.6, sharey=True, squeeze=False)
    for ax, name in zip(axes.flat, names):
        for method, solution in histories[name].items():
            r = solution.residual_history
            label = f"{METHOD_LABELS.get(method, method)}: {solution.iterations} it."
            ax.semilogy(np.arange(len(r)), r, label=label, gid=method,
                        **_METHOD_STYLE.get(method, {}))
        ax.axhline(1e-10, color="0.4", ls=":", lw=0.9)
        ax.set_title(name, fontsize="medium")
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper right")
        ax.set_xlabel("iteration k")
    for ax in axes[:, 0]:
        ax.set_ylabel(r"$\|R\| / \|F\|$ of eq. (17)")
    for ax in axes.flat[len(names):]:
        ax.set_visible(False)
    return fig


def convergence_table(histories: Mapping[str, Mapping[str, Solution]], tail: int = 50) -> str:
    """Markdown table of the iterations taken by each method for each law.

    Columns: law; fixed-point iterations; the fixed point's measured factor
    per iteration, ``(r_K / r_{K - tail}) ** (1 / tail)`` over its last
    `tail` iterations; Newton steps; Newton's relative residuals, rounded
    (those below 1e-12 shown as "< 1e-12", as round-off varies).

    Parameters
    ----------
    histories : mapping
        ``{name: {"fixed-point": Solution, "newton": Solution}}``
        (`convergence_histories`).
    tail : int
        Iterations over which the fixed point's factor is measured.

    Returns
    -------
    str
    """
    lines = [
        "| foundation | fixed point: iterations | measured factor per iteration "
        "| Newton: steps | Newton: relative residuals |",
        "|---|---:|---:|---:|---|",
    ]
    for name, pair in histories.items():
        fixed, newton = pair["fixed-point"], pair["newton"]
        r = fixed.residual_history
        rate = (r[-1] / r[-1 - tail]) ** (1.0 / tail) if len(r) > tail else float("nan")
        steps = ", ".join(f"{x:.0e}" if x > 1e-12 else "< 1e-12" for x in newton.residual_history)
        lines.append(f"| {name} | {fixed.iterations} | {rate:.3f} | {newton.iterations} | {steps} |")
    return "\n".join(lines)


def change_and_error_table(passage: Passage, foundation, iterations: Sequence[int] = (15, 50, 100),
                           harmonics: int = 15) -> str:
    """Markdown table: change of the mean between fixed-point iterates against its error.

    For each k, the mean c_0 after k and k + 1 iterations of eq. (21) from
    c = 0 (`railtrack.solve` with ``method="fixed-point"``) is compared
    with the exact mean of eq. (23).

    Parameters
    ----------
    passage : Passage
    foundation : LinearFoundation
        The exact solution needs the linear law.
    iterations : sequence of int
        The k to list.
    harmonics : int
        m.

    Returns
    -------
    str
        Columns k, |c_0(k+1) - c_0k| [mm], |c_0k - c_0| [mm], their ratio.
    """
    exact = analytic_coefficients(passage, foundation, harmonics)[harmonics].real
    lines = [
        r"| $k$ | change $\lvert c_{0(k+1)} - c_{0k}\rvert$ [mm] "
        r"| error $\lvert c_{0k} - c_0\rvert$ [mm] | change / error |",
        "|---:|---:|---:|---:|",
    ]
    for k in iterations:
        now, then = (
            solve(passage.track, passage.train, foundation, harmonics, method="fixed-point",
                  max_iterations=i).mean_displacement
            for i in (k, k + 1)
        )
        change, error = abs(then - now), abs(now - exact)
        lines.append(f"| {k} | {change * MM:.3e} | {error * MM:.3e} | {change / error:.4f} |")
    return "\n".join(lines)
