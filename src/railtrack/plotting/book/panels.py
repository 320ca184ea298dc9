"""The curves of one panel of a paper figure, and how they are computed.

`PanelData` holds arrays in SI units; `railtrack.plotting.book.paper_figure_data`
fills it for each of Figures 3–7 and `railtrack.plotting.book.paper_figures`
draws it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ... import LinearFoundation, Solution, Passage, solve
from ..style import MM

__all__ = [
    "PAPER_HARMONICS",
    "PAPER_ITERATIONS",
    "REFERENCE_TOL",
    "POINTS",
    "PanelData",
    "period_times",
    "paper_iteration",
    "converged_reference",
    "reference_label_for",
    "make_panel",
]

PAPER_HARMONICS = 15
"""m used by the paper unless a figure varies it."""
PAPER_ITERATIONS = 100
"""k used by the paper unless a figure varies it."""
REFERENCE_TOL = 1e-10
"""Relative residual of eq. (17) reached by the reference (Newton) curves."""
POINTS = 801
"""Default number of time samples over one period, t = 0 .. T inclusive."""


@dataclass(frozen=True, eq=False)
class PanelData:
    """The curves of one panel of a paper figure, in SI units.

    Attributes
    ----------
    parameter : str
        Name of the quantity varied from curve to curve: "k" (iterations),
        "m" (harmonics), "e" (k2-/k2+) or "epsilon".
    values : tuple
        Its values, one per curve, in the order drawn.
    times : ndarray, shape (N,)
        One period, t = 0 .. T inclusive [s].
    displacements : ndarray, shape (V, N)
        Sleeper displacement w(t) of each curve [m], positive upward.
    means : ndarray, shape (V,)
        Mean displacement c_0 of each curve [m].
    residuals : ndarray, shape (V,)
        Final relative residual ||R|| / ||F|| of eq. (17) of each curve.
    reference : ndarray, shape (N,) or (V, N)
        The converged curve(s) [m]: one shared by all curves, or one per curve.
    reference_means : ndarray, shape () or (V,)
        c_0 of the reference(s) [m].
    reference_label : str
        How the reference was computed, for legends.
    method : str
        How the curves were computed, for legends.
    extra : dict of str -> ndarray, shape (N,)
        Further curves drawn with the panel (Figure 3: Newton's solution) [m].
    solutions, reference_solutions : tuple of Solution
        The full results, for anything not summarised here.
    """

    parameter: str
    values: tuple
    times: np.ndarray
    displacements: np.ndarray
    means: np.ndarray
    residuals: np.ndarray
    reference: np.ndarray
    reference_means: np.ndarray
    reference_label: str
    method: str
    extra: dict = field(default_factory=dict)
    solutions: tuple = ()
    reference_solutions: tuple = ()

    def minima(self) -> np.ndarray:
        """Lowest displacement of each curve (the peak deflection) [m], shape (V,)."""
        return self.displacements.min(axis=-1)

    def maxima(self) -> np.ndarray:
        """Highest displacement of each curve (the uplift if > 0) [m], shape (V,)."""
        return self.displacements.max(axis=-1)

    def errors(self) -> np.ndarray:
        """max_t |w(t) - reference(t)| of each curve [m], shape (V,)."""
        return np.abs(self.displacements - self.reference).max(axis=-1)

    def mean_errors(self) -> np.ndarray:
        """(c_0 - c_0 of the reference) / |c_0 of the reference| of each curve, shape (V,)."""
        return (self.means - self.reference_means) / np.abs(self.reference_means)

    def table(self, *, digits: int = 4, errors: bool = True) -> str:
        """Markdown table of min, max and mean of each curve in mm (and the error).

        Numbers are rounded to `digits` decimals of a millimetre, and
        residuals below 1e-12 are shown as "< 1e-12", so that the text is
        identical from run to run.
        """
        header = f"| {self.parameter} | min w [mm] | max w [mm] | mean w [mm] |"
        rule = "|---|---|---|---|"
        if errors:
            header += " max abs(w - reference) [mm] | relative residual |"
            rule += "---|---|"
        rows = [header, rule]
        columns = zip(
            self.values, self.minima() * MM, self.maxima() * MM, self.means * MM,
            self.errors() * MM, self.residuals,
        )
        for value, low, high, mean, error, res in columns:
            row = f"| {value:g} | {low:.{digits}f} | {high:.{digits}f} | {mean:.{digits}f} |"
            if errors:
                residual = "< 1e-12" if res < 1e-12 else f"{res:.1e}"
                row += f" {error:.2e} | {residual} |"
            rows.append(row)
        return "\n".join(rows)

    def reference_table(self, *, digits: int = 4) -> str:
        """Markdown table of min, max and mean of each converged reference in mm.

        Needs one reference per curve (Figures 5 and 7).  The last column is
        how far each curve (the paper's fixed point) is from its reference.
        """
        if np.ndim(self.reference) != 2:
            raise ValueError("reference_table needs one reference per curve (shape (V, N)); "
                             f"got reference of shape {np.shape(self.reference)}")
        rows = [
            f"| {self.parameter} | min w [mm] | max w [mm] | mean w [mm] | "
            "max abs(curve - reference) [mm] |",
            "|---|---|---|---|---|",
        ]
        columns = zip(self.values, self.reference.min(axis=-1) * MM,
                      self.reference.max(axis=-1) * MM, self.reference_means * MM,
                      self.errors() * MM)
        for value, low, high, mean, error in columns:
            rows.append(f"| {value:g} | {low:.{digits}f} | {high:.{digits}f} | {mean:.{digits}f} |"
                        f" {error:.2e} |")
        return "\n".join(rows)



def period_times(passage: Passage, points: int) -> np.ndarray:
    if isinstance(points, bool) or not isinstance(points, (int, np.integer)) or points < 2:
        raise ValueError(f"points must be an integer >= 2; got {points!r}")
    return np.linspace(0.0, passage.period, int(points))


def paper_iteration(passage, foundation, harmonics, iterations) -> Solution:
    """`iterations` steps of eq. (21) from c = 0, as in the paper.

    Fewer only if the relative residual reaches 1e-10 first, which none of
    the paper's cases does within its k = 100.
    """
    return solve(passage.track, passage.train, foundation, harmonics, method="fixed-point",
                 max_iterations=int(iterations))


def converged_reference(passage, foundation, harmonics) -> Solution:
    """Converged solution: eq. (23) for a linear law, Newton to 1e-10 otherwise."""
    if isinstance(foundation, LinearFoundation):
        return solve(passage.track, passage.train, foundation, harmonics, method="analytic")
    return solve(passage.track, passage.train, foundation, harmonics, method="newton", tol=REFERENCE_TOL, strict=True)


def reference_label_for(foundation, harmonics) -> str:
    if isinstance(foundation, LinearFoundation):
        return f"analytic, eq. (23), m = {harmonics}"
    return f"Newton, m = {harmonics}"


def make_panel(parameter, values, times, solutions, references, reference_label, method,
           extra=None) -> PanelData:
    displacements = np.array([s.sleeper_displacement(times) for s in solutions])
    reference = np.array([r.sleeper_displacement(times) for r in references])
    reference_means = np.array([r.mean_displacement for r in references])
    if len(references) == 1:
        reference, reference_means = reference[0], reference_means[0]
    return PanelData(
        parameter=parameter,
        values=tuple(values),
        times=times,
        displacements=displacements,
        means=np.array([s.mean_displacement for s in solutions]),
        residuals=np.array([s.residual for s in solutions]),
        reference=reference,
        reference_means=reference_means,
        reference_label=reference_label,
        method=method,
        extra=dict(extra or {}),
        solutions=tuple(solutions),
        reference_solutions=tuple(references),
    )
