"""The FE model's mesh and time-step convergence against eq. (23) (book chapter 12).

`convergence_study` refines the time-domain ring's mesh at a fixed time
step, then its time step on a fixed mesh, and measures the largest error
of the sleeper's displacement against the analytic solution eq. (23) of a
linear foundation; `observed_orders` reads the order of convergence from
neighbouring errors; `convergence_table` and `plot_convergence` show both
studies.

SI inside; tables and axes in mm.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np
from matplotlib.figure import Figure

from ... import LinearFoundation, Passage, solve
from ...timedomain.simulation import simulate_time_domain
from .model import markdown_table
from ..style import BLUE, MM, new_figure

__all__ = ["ConvergenceStudy", "observed_orders", "convergence_study", "convergence_table",
           "plot_convergence"]


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
