"""The result of a `railtrack.sweep`: every member, its flags, extremes and verdict.

`Sweep` keeps what the batched solve found for each swept value (the
coefficients, convergence, the truncation estimate, the extremes over a
period and, where judged, the Floquet verdict) and rebuilds any member as
a `railtrack.Solution` on demand (`Sweep.solution`).  The sweep itself is
run by `railtrack.studies.sweep.sweep`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..model.passage import Passage
from ..solvers.batch import member
from ..solvers.export import Exports
from ..solvers.result_repr import ShortRepr
from ..solvers.solution import Solution
from .study_repr import sweep_rows

__all__ = ["Sweep"]


@dataclass(frozen=True, eq=False, repr=False)
class Sweep(ShortRepr, Exports):
    """The members of a `sweep`, in the order of the swept values.

    Attributes
    ----------
    values : dict of str to ndarray, shape (B,)
        The swept field(s) [SI units of the field].
    harmonics : int
        m, the same for every member.
    coefficients : ndarray, shape (B, 2m+1)
        Two-sided c_n, n = -m..m, of each member [m].
    converged : ndarray of bool, shape (B,)
    iterations : ndarray of int, shape (B,)
    residual : ndarray, shape (B,)
        Final relative residual of eq. (17) (inf where the law was not finite).
    truncation_error : ndarray, shape (B,)
        Estimated truncation error of each member, as `railtrack.Solution`'s
        (NaN where a member diverged).
    lowest, highest : ndarray, shape (B,)
        Extremes of the sleeper displacement over a period [m] (w < 0 is down).
    seat_load_peak, seat_load_lowest : ndarray, shape (B,)
        Extremes of the rail-seat load, compression positive [N].
    foundation_force_peak, foundation_force_lowest : ndarray, shape (B,)
        Extremes of the force on the foundation, compression positive [N].
    passage, foundation
        The batched passage and law (fields of shape (B, 1) where swept).
    stable : ndarray of object, shape (B,), or None
        Each member judged as `railtrack.solve` judges a solution
        (`railtrack.studies.sweep_stability`): True (stable), False
        (unstable) or None (unknown: not converged, or the look could have
        missed a multiplier outside the unit circle; the default quick look
        finds unstable members and proves none stable).  None with
        ``stability="off"``.  `verdicts` says it in words.
    dominant_multiplier : ndarray of complex, shape (B,), or None
        Each member's dominant multiplier mu per period H / v
        (`railtrack.Floquet.dominant`) [-] where its verdict is known from a
        Floquet search, else NaN.  None with ``stability="off"``.
    """

    values: dict
    harmonics: int
    coefficients: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray
    truncation_error: np.ndarray
    lowest: np.ndarray
    highest: np.ndarray
    seat_load_peak: np.ndarray
    seat_load_lowest: np.ndarray
    foundation_force_peak: np.ndarray
    foundation_force_lowest: np.ndarray
    passage: Passage
    foundation: Any
    stable: np.ndarray | None = None
    dominant_multiplier: np.ndarray | None = None

    def __len__(self) -> int:
        return len(self.converged)

    @property
    def verdicts(self) -> np.ndarray | None:
        """"stable", "unstable" or "unknown" per member (`stable` True, False, None)."""
        return None if self.stable is None else np.array(
            [{True: "stable", False: "unstable"}.get(flag, "unknown") for flag in self.stable])

    def solution(self, index: int) -> Solution:
        """Member `index` as a `railtrack.Solution` (for its rail, moments, bowl ...)."""
        passage = Passage(member(self.passage.track, index), member(self.passage.train, index))
        state = "converged" if self.converged[index] else "did not converge"
        return Solution(
            passage=passage, foundation=member(self.foundation, index), harmonics=self.harmonics,
            coefficients=self.coefficients[index], method="newton (batch)",
            converged=bool(self.converged[index]), iterations=int(self.iterations[index]),
            residual_history=np.array([self.residual[index]]),
            truncation_error=float(self.truncation_error[index]),
            message=f"member {index} of a sweep: {state}, relative residual "
                    f"{self.residual[index]:.2e} after {self.iterations[index]} Newton steps")

    _rows = sweep_rows                  # __repr__, _repr_html_ (ShortRepr)
    _table_row = None                   # to_dataframe: a row per swept value, converged's dimension

    def to_xarray(self):
        """Every member as an `xarray.Dataset` (CF units; `railtrack.studies.study_export`)."""
        from .study_export import sweep_dataset
        return sweep_dataset(self)
