"""The semi-analytical method against the time-domain FE model (book chapter 9).

* `compare_case`: one of the seven foundations of Sections 4.1–4.3 (`paper_cases`)
  solved by Newton (m = 15 and m = 200), the paper's fixed point (m = 15,
  k = 100) and `railtrack.simulate_time_domain`, on the time-domain grid;
  tables and plots of what agrees with what, and by how much;
* `convergence_study`: the FE error against eq. (23) under mesh and time-step refinement;
* `newton_solve_time`: the median wall time of one Newton solve.

SI inside; tables and axes in mm and s.  w is positive upward (the train
pushes the sleeper to w < 0); t = 0 when a front wheel is above sleeper 0.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from ... import BilinearFoundation, CubicFoundation, LinearFoundation, Passage, solve
from ...timedomain.simulation import TimeDomainSolution, simulate_time_domain
from .model import markdown_table
from ..style import BLUE, DISPLACEMENT_LABEL, GREEN, MM, ORANGE, TIME_LABEL, VERMILLION, new_figure

__all__ = ["METHODS", "CaseComparison", "paper_cases", "compare_case", "fe_against_harmonics",
           "comparison_table", "truncation_table", "distinct_cases", "plot_comparison", "plot_error_budget",
           "ConvergenceStudy", "observed_orders", "convergence_study", "convergence_table",
           "plot_convergence", "newton_solve_time"]

METHODS = {"newton": "Newton, m = 15", "reference": "Newton, m = 200",
           "fe": "time domain (FE)", "paper": "fixed point, m = 15, k = 100"}
"""Curve key -> legend text (for the default m, k of `compare_case`)."""


def paper_cases() -> list[tuple[str, object]]:
    """(label, law) of the seven foundations compared: eq. (22), (24) e = 1, 0.5, 0, (25) eps = 0, 0.4, 0.8."""
    return ([("linear", LinearFoundation.paper())]
            + [(f"bilinear, e = {e:g}", BilinearFoundation.paper(e)) for e in (1.0, 0.5, 0.0)]
            + [(f"cubic, ε = {x:g}", CubicFoundation.paper(x)) for x in (0.0, 0.4, 0.8)])


@dataclass(frozen=True, eq=False)
class CaseComparison:
    """One foundation solved four ways, sampled on the time-domain grid.

    Attributes
    ----------
    label : str
    times : ndarray, shape (N,)
        t = 0, dt, ..., T - dt [s].
    curves : dict of str -> ndarray, shape (N,)
        w(t) [m] keyed as in `METHODS`.
    means : dict of str -> float
        Mean of each curve [m]: c_0 for the series, the sample mean for "fe".
    fe : TimeDomainSolution
    fe_seconds : float
        Wall time of the `simulate_time_domain` call [s].
    """

    label: str
    times: np.ndarray
    curves: dict
    means: dict
    fe: TimeDomainSolution
    fe_seconds: float

    def stats(self, key: str) -> tuple[float, float, float]:
        """(min, max, mean) of curve `key` [m]."""
        return float(self.curves[key].min()), float(self.curves[key].max()), self.means[key]

    def error(self, key: str, against: str = "reference") -> float:
        """max_t |w_key(t) - w_against(t)| [m]."""
        return float(np.max(np.abs(self.curves[key] - self.curves[against])))

    @property
    def peak(self) -> float:
        """max |w| of the reference [m]."""
        return float(np.max(np.abs(self.curves["reference"])))

    def lag_mismatch(self) -> float:
        """max over sleepers i of |w_i(t) - w_0(t - i L / v)|, divided by the peak [-]."""
        record = self.fe.sleeper_displacements
        steps, sleepers = record.shape
        if steps % sleepers:
            raise ValueError(f"steps_per_period ({steps}) must be a multiple of H/L ({sleepers})")
        lagged = [np.roll(record[:, 0], i * (steps // sleepers)) for i in range(sleepers)]
        return float(np.max(np.abs(record - np.array(lagged).T)) / np.max(np.abs(record)))


def compare_case(passage: Passage, foundation, label: str = "", *, harmonics: int = 15,
                 reference_harmonics: int = 200, iterations: int = 100,
                 elements_per_span: int = 8, steps_per_period: int = 2400) -> CaseComparison:
    """Solve one foundation by Newton (m and a large m), the fixed point and the FE model.

    Parameters
    ----------
    passage, foundation, label : Passage, foundation object, str
    harmonics, reference_harmonics : int
        m of the Newton solutions (both to a relative residual of 1e-10).
    iterations : int
        k of the fixed point, eq. (21), run from c = 0 with m = `harmonics`.
    elements_per_span, steps_per_period : int
        Passed to `simulate_time_domain`.

    Returns
    -------
    CaseComparison
        The FE run is timed with `time.perf_counter` (``fe_seconds``).
    """
    start = time.perf_counter()
    fe = simulate_time_domain(passage.track, passage.train, foundation, elements_per_span, steps_per_period)
    seconds = time.perf_counter() - start
    solutions = {
        "newton": solve(passage.track, passage.train, foundation, harmonics, tol=1e-10, strict=True),
        "reference": solve(passage.track, passage.train, foundation, reference_harmonics, tol=1e-10, strict=True),
        "paper": solve(passage.track, passage.train, foundation, harmonics, method="fixed-point",
                       max_iterations=iterations),
    }
    curves = {key: s.sleeper_displacement(fe.times) for key, s in solutions.items()}
    means = {key: s.mean_displacement for key, s in solutions.items()}
    curves["fe"], means["fe"] = fe.sleeper_displacement, float(fe.sleeper_displacement.mean())
    return CaseComparison(label, fe.times, curves, means, fe, seconds)


def fe_against_harmonics(case: CaseComparison, harmonics: Sequence[int]) -> np.ndarray:
    """max_t |w_FE(t) - w_Newton,m(t)| [m] for each m: is the FE or the series the less accurate?"""
    passage, law = case.fe.passage, case.fe.foundation
    return np.array([np.max(np.abs(case.curves["fe"] - solve(passage.track, passage.train, law, m, tol=1e-10, strict=True)
                                   .sleeper_displacement(case.times))) for m in harmonics])


def _difference(value_mm: float) -> str:
    """Signed difference [mm] to two digits; round-off (< 1e-9 mm) shown as such."""
    return "< 1e-9" if abs(value_mm) < 1e-9 else f"{value_mm:+.1e}"


def comparison_table(cases: Sequence[CaseComparison], digits: int = 4) -> str:
    """Markdown table of min, max and mean w [mm] by Newton m = 15, m = 200 and FE, with differences."""
    rows = []
    for case in cases:
        for i, name in enumerate(("min", "max", "mean")):
            n15, ref, fe = (case.stats(k)[i] * MM for k in ("newton", "reference", "fe"))
            rows.append([case.label if i == 0 else "", name, f"{n15:.{digits}f}",
                         f"{ref:.{digits}f}", f"{fe:.{digits}f}", _difference(fe - ref),
                         _difference(n15 - ref)])
    return markdown_table(["case", "w [mm]", METHODS["newton"], METHODS["reference"], "FE",
                           "FE − (m = 200)", "(m = 15) − (m = 200)"], rows)


def truncation_table(cases: Sequence[CaseComparison]) -> str:
    """Markdown table of the m = 15 truncation and k = 100 iteration errors [mm, % of peak]."""
    def both(error, peak):
        return f"{error * MM:.1e} ({100 * error / peak:.2g} %)"
    rows = []
    for c in cases:
        truncation, iteration = c.error("newton"), c.error("paper", "newton")
        rows.append([c.label, f"{c.peak * MM:.4f}", both(truncation, c.peak),
                     both(iteration, c.peak), both(c.error("paper"), c.peak),
                     f"{c.error('fe') * MM:.1e}",
                     _difference((c.means["newton"] - c.means["reference"]) * MM),
                     _difference((c.means["paper"] - c.means["newton"]) * MM),
                     "truncation" if truncation > iteration else "iteration"])
    return markdown_table(["case", "peak abs(w) [mm]", "m = 15 truncation [mm]",
                           "k = 100 iteration [mm]", "paper's total [mm]", "FE − (m = 200) [mm]",
                           "mean: truncation [mm]", "mean: iteration [mm]", "larger"], rows)


def distinct_cases(cases: Sequence[CaseComparison], rtol: float = 1e-12) -> list[list[CaseComparison]]:
    """Group cases whose reference curves coincide (e.g. linear, bilinear e = 1, cubic eps = 0).

    Two cases are grouped when their m = 200 curves differ by at most `rtol`
    times the peak; the groups keep the order of first appearance.
    """
    groups: list[list[CaseComparison]] = []
    for case in cases:
        for group in groups:
            first = group[0]
            if (first.times.shape == case.times.shape and np.max(np.abs(
                    first.curves["reference"] - case.curves["reference"])) <= rtol * first.peak):
                group.append(case)
                break
        else:
            groups.append([case])
    return groups


def plot_comparison(cases: Sequence[CaseComparison], zoom: int = 25) -> Figure:
    """One row per distinct case: the whole period (left) and a zoom on the deepest point (right).

    Cases with the same response (`distinct_cases`) share a row, titled
    with all their labels.  FE: thick grey; Newton m = 200: dashed black;
    Newton m = 15: thin vermillion, dash-dot.

    Parameters
    ----------
    cases : sequence of CaseComparison
    zoom : int
        Half-width of the zoom window, in FE time steps around the deepest point.

    Returns
    -------
    matplotlib.figure.Figure
        Axes in pairs (full, zoom); the full axes' titles are the group labels
        joined by " = "; t in s on x (ms in the zoom), w in mm on y.
    """
    groups = distinct_cases(cases)
    fig, axes = new_figure(len(groups), 2, width=6.5, height=1.5, squeeze=False,
                           gridspec_kw=dict(width_ratios=(1.7, 1.0)))
    styles = {"fe": dict(color="0.7", ls="-", lw=4.0), "reference": dict(color="black", ls="--", lw=1.0),
              "newton": dict(color=VERMILLION, ls="-.", lw=1.1)}
    for (full, detail), group in zip(axes, groups):
        case = group[0]
        trough = int(np.argmin(case.curves["reference"]))
        window = slice(max(trough - zoom, 0), trough + zoom + 1)
        for key, style in styles.items():
            full.plot(case.times, case.curves[key] * MM, label=METHODS[key], **style)
            detail.plot(case.times[window] * 1e3, case.curves[key][window] * MM, **style)
        full.set_title(" = ".join(c.label for c in group), fontsize=9, loc="left")
        full.set_xlim(0.0, case.times[-1])
        detail.set_title("zoom on the deepest point", fontsize=8, loc="left")
        for ax in (full, detail):
            ax.grid(True, alpha=0.3)
            ax.tick_params(labelsize=8)
    axes[-1, 0].set_xlabel(TIME_LABEL, fontsize=8)
    axes[-1, 1].set_xlabel("time t [ms]", fontsize=8)
    fig.supylabel(DISPLACEMENT_LABEL, fontsize=9)
    fig.legend(*axes[0, 0].get_legend_handles_labels(), loc="outside upper center", ncol=3,
               fontsize=8)
    return fig


def plot_error_budget(cases: Sequence[CaseComparison]) -> Figure:
    """max |error| [mm] of each approximation, per case, on a log scale."""
    fig, ax = new_figure(height=3.4)
    errors = {"FE (defaults) − Newton m = 200": ([c.error("fe") for c in cases], "s", BLUE),
              "m = 15 truncation: Newton m = 15 − m = 200":
                  ([c.error("newton") for c in cases], "o", ORANGE),
              "k = 100 iteration: fixed point − Newton m = 15":
                  ([c.error("paper", "newton") for c in cases], "^", GREEN)}
    x = np.arange(len(cases))
    for shift, (label, (values, marker, colour)) in zip((-0.15, 0.0, 0.15), errors.items()):
        ax.semilogy(x + shift, np.array(values) * MM, marker, color=colour, ms=7, label=label)
    ax.set_xticks(x, [c.label for c in cases], rotation=25, ha="right", fontsize=8)
    ax.set_ylabel("max over t of |error| [mm]")
    ax.set_ylim(top=10.0)  # room for the legend above the points
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    return fig


@dataclass(frozen=True)
class ConvergenceStudy:
    """max_t |w_FE - w_eq.(23)| [m] for refined meshes and time steps (linear law)."""

    elements: tuple          # elements_per_span of the mesh study
    element_errors: np.ndarray
    fixed_steps: int         # steps_per_period of the mesh study
    steps: tuple             # steps_per_period of the time-step study
    step_errors: np.ndarray
    fixed_elements: int      # elements_per_span of the time-step study
    reference_harmonics: int
    reference_error: float   # max |eq. (23) with 200 harmonics - the reference| [m]


def observed_orders(sizes: Sequence[float], errors: Sequence[float]) -> np.ndarray:
    """Order p between neighbours, from errors ~ C size^p: log(e_i / e_i+1) / log(s_i / s_i+1)."""
    sizes, errors = np.asarray(sizes, float), np.asarray(errors, float)
    return np.log(errors[:-1] / errors[1:]) / np.log(sizes[:-1] / sizes[1:])


def convergence_study(passage: Passage, foundation: LinearFoundation, *,
                      elements: Sequence[int] = (1, 2, 4, 8),
                      steps: Sequence[int] = (600, 1200, 2400, 4800), fixed_steps: int = 4800,
                      fixed_elements: int = 8, reference_harmonics: int = 800) -> ConvergenceStudy:
    """Refine the mesh at `fixed_steps`, then the time step at `fixed_elements`.

    The reference is eq. (23) with `reference_harmonics` harmonics; runs
    shared by both studies are made once.
    """
    reference = solve(passage.track, passage.train, foundation, reference_harmonics, method="analytic")
    runs = {}

    def error(e, s):
        if (e, s) not in runs:
            fe = simulate_time_domain(passage.track, passage.train, foundation, e, s)
            runs[e, s] = np.max(np.abs(fe.sleeper_displacement - reference.sleeper_displacement(fe.times)))
        return runs[e, s]
    t = np.linspace(0.0, passage.period, 2400, endpoint=False)
    m200 = solve(passage.track, passage.train, foundation, 200, method="analytic").sleeper_displacement(t)
    return ConvergenceStudy(
        tuple(elements), np.array([error(e, fixed_steps) for e in elements]), fixed_steps,
        tuple(steps), np.array([error(fixed_elements, s) for s in steps]), fixed_elements,
        reference_harmonics, float(np.max(np.abs(m200 - reference.sleeper_displacement(t)))))


def convergence_table(study: ConvergenceStudy) -> str:
    """Markdown table of both studies: size, max error [mm], observed order."""
    rows = []
    for name, values, errors in (("elements per span", study.elements, study.element_errors),
                                 ("steps per period", study.steps, study.step_errors)):
        orders = ["–"] + [f"{p:.2f}" for p in observed_orders(1.0 / np.array(values), errors)]
        rows += [[name, v, f"{e * MM:.2e}", p] for v, e, p in zip(values, errors, orders)]
    return markdown_table(["refined", "value", "largest error of the FE model against eq. (23) [mm]", "observed order"], rows)


def plot_convergence(study: ConvergenceStudy) -> Figure:
    """Log–log error against h = L / elements and against dt = T / steps, with slope guides."""
    fig, axes = new_figure(1, 2, height=3.2)
    panels = ((np.array(study.elements), study.element_errors, 3,
               "elements per span (h = L / elements)", f"{study.fixed_steps} steps per period"),
              (np.array(study.steps), study.step_errors, 2,
               "steps per period (dt = T / steps)", f"{study.fixed_elements} elements per span"))
    for ax, (n, errors, order, xlabel, title) in zip(axes, panels):
        ax.loglog(n, errors * MM, "o-", color=BLUE, label="FE error")
        ax.loglog(n, errors[0] * MM * (n / n[0]) ** -order, "k:", label=f"slope −{order}")
        ax.axhline(study.reference_error * MM, color="0.5", lw=0.8, ls="--",
                   label=f"eq. (23) at m = 200 vs m = {study.reference_harmonics}")
        ax.set_xticks(n, [str(v) for v in n])
        ax.minorticks_off()
        ax.set(xlabel=xlabel, title=title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7.5)
    axes[0].set_ylabel("FE error against eq. (23),\nlargest over one period [mm]")
    return fig


def newton_solve_time(passage: Passage, foundation, harmonics: int = 15, repeats: int = 21) -> float:
    """Median wall time of `solve(track, foundation, harmonics)` (Newton) over `repeats` calls [s].

    The method alone: without the look at the solution's stability that `solve`
    adds by default (``stability="off"``).
    """
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        solve(passage.track, passage.train, foundation, harmonics, stability="off")
        times.append(time.perf_counter() - start)
    return float(np.median(times))
