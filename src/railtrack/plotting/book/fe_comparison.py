"""One foundation solved four ways on the time-domain grid (book chapter 12).

`compare_case` solves one of the seven foundations of Sections 4.1–4.3
(`paper_cases`) by Newton (m = 15 and m = 200), the paper's fixed point
(m = 15, k = 100) and `railtrack.simulate_time_domain`, samples every
answer at the FE model's times and times the FE run; `fe_against_harmonics`
asks whether the FE model or the truncated series is the less accurate, and
`newton_solve_time` times one Newton solve for comparison.  The tables and
plots of these results are in `railtrack.plotting.book.verification`.

SI inside.  w is positive upward (the train pushes the sleeper to w < 0);
t = 0 when a front wheel is above sleeper 0.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Sequence

import numpy as np

from ... import BilinearFoundation, CubicFoundation, LinearFoundation, Passage, solve
from ...timedomain.simulation import TimeDomainSolution, simulate_time_domain

__all__ = ["METHODS", "CaseComparison", "paper_cases", "compare_case", "fe_against_harmonics",
           "newton_solve_time"]

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
