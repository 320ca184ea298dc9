"""A branch of periodic solutions traced by `railtrack.studies.continuation.continuation`.

A `Branch` holds, for each point of a solution curve in (parameter, c)
space, the parameter value and the one-sided coefficients c_0..c_m of
eq. (17), with the turning points (folds) that the curve passed.  It builds
a `railtrack.Solution` for any point on demand (`Branch.solution`), so that
every output of the package (rail, moments, seat loads) is available along
the branch without storing a few hundred solutions.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..equations.harmonic_balance import harmonic_system, two_sided
from ..model.passage import Passage
from ..solvers.solution import Solution
from ..model.track import Track
from ..model.train import Train
from ..solvers.truncation import truncation_error
from ..solvers.export import Exports
from ..solvers.result_repr import ShortRepr
# the parameter's helpers, re-exported: continuation and branch_stability import them from here
from .branch_parameter import (TRACK_FIELDS, TRAIN_FIELDS, check_parameter, hermite_turning_value,
                               replaced, scalar)
from .study_repr import branch_rows

__all__ = ["Branch", "Fold", "StabilityChange", "TRACK_FIELDS", "TRAIN_FIELDS", "replaced", "check_parameter",
           "scalar", "hermite_turning_value"]


@dataclass(frozen=True)
class Fold:
    """A turning point of a branch, where d(parameter)/ds changes sign.

    Attributes
    ----------
    value : float
        The parameter at the fold, located by a local solve of
        d(parameter)/ds = 0 (or, where that failed, by Hermite
        interpolation between the neighbouring points).
    index : int
        The fold lies between points `index` and `index + 1` of the branch.
    """

    value: float
    index: int


@dataclass(frozen=True)
class StabilityChange:
    """Where a branch gains or loses stability (`railtrack.check_branch`).

    Attributes
    ----------
    value : float
        The parameter where the dominant Floquet multiplier crosses the unit
        circle: the fold's value at a fold; elsewhere located by solving
        between the two points.
    index : int
        The change lies between points `index` and `index + 1`.
    kind : {"fold", "real +", "real -", "complex"}
        How stability changes: at a fold (a real multiplier through +1 at
        the solution's own period), or away from folds through +1, through
        -1 (period doubling), or by a complex pair (Neimark–Sacker).
    frequency : float
        arg(mu) / 2 pi of the crossing multiplier, as a fraction of v / H [-].
    theta : float
        Its Bloch phase per sleeper [rad]; 0 for disturbances that repeat
        every wagon.
    gains : bool
        True where the branch becomes stable in the order of its points.
    """

    value: float
    index: int
    kind: str
    frequency: float
    theta: float
    gains: bool


@dataclass(frozen=True, eq=False, repr=False)
class Branch(ShortRepr, Exports):
    """Solutions of eq. (17) along a curve in one scalar parameter.

    Attributes
    ----------
    parameter : str
        The name of the parameter followed (a field of the Track, the Train
        or the foundation), e.g. "speed".
    values : ndarray, shape (K,)
        The parameter at each point, in its own unit (m/s for speed).
    coefficients : ndarray, shape (K, m+1), complex
        One-sided c_0..c_m of the sleeper displacement at each point [m];
        c_{-n} = conj(c_n).  `Solution.coefficients` is two-sided.
    tangents : ndarray, shape (K, 2m+2)
        Unit tangent of the curve at each point, in the scaled unknowns
        ``(to_real(c) / coefficient_scale, p / parameter_scale)``; its last
        entry is d(p / parameter_scale)/ds.
    converged : ndarray of bool, shape (K,)
        Whether the relative residual ||R|| / ||F|| reached `tol` there.
    residuals : ndarray, shape (K,)
        That relative residual.
    folds : tuple of Fold
        The turning points passed, in the order met.
    message : str
        Why the continuation stopped, in words.
    stable : ndarray of object (True, False or None) or None
        Stability of each point, None where its Floquet search could have
        missed a multiplier outside the unit circle (`verdicts`, "unknown");
        None until `railtrack.check_branch` fills it (from every point's
        Floquet multipliers, or from the time-domain ring's verdicts on a
        sample of the points).
    checks : dict or None
        Point index -> `railtrack.Floquet` (or `railtrack.StabilityCheck`)
        of each point judged (`railtrack.check_branch`); None until then.
    multipliers : ndarray of complex or None
        The dominant Floquet multiplier at each point (`railtrack.check_branch`
        with Hill's method); None until then.
    changes : tuple of StabilityChange or None
        Where stability changes along the branch, in the order met.
    track, train, foundation : the problem at the start
    harmonics : int
        m.
    samples : int
        AFT samples per period N.
    coefficient_scale, parameter_scale : float
        The scales of the unknowns used by the continuation [m], [unit of p].

    Examples
    --------
    >>> import railtrack as rt
    >>> from railtrack.studies.continuation import continuation
    >>> branch = continuation(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(),
    ...                       "speed", start=40.0, stop=60.0)
    >>> float(branch.values[0]), float(branch.values[-1]), branch.folds
    (40.0, 60.0, ())
    >>> branch.solution(-1).train.speed
    60.0
    """

    parameter: str
    values: np.ndarray
    coefficients: np.ndarray
    tangents: np.ndarray
    converged: np.ndarray
    residuals: np.ndarray
    folds: tuple[Fold, ...]
    message: str
    track: Track
    train: Train
    foundation: Any
    harmonics: int
    samples: int
    coefficient_scale: float
    parameter_scale: float
    stable: np.ndarray | None = None
    checks: dict | None = None
    multipliers: np.ndarray | None = None
    changes: tuple[StabilityChange, ...] | None = None

    def __len__(self) -> int:
        return len(self.values)

    @property
    def verdicts(self) -> np.ndarray | None:
        """"stable", "unstable" or "unknown" per point (`stable` True, False, None); None until judged."""
        if self.stable is None:
            return None
        return np.array([{True: "stable", False: "unstable"}.get(flag, "unknown")
                         for flag in self.stable])

    @property
    def fold_values(self) -> np.ndarray:
        """The parameter at each fold, in the order met."""
        return np.array([fold.value for fold in self.folds])

    def problem(self, i: int) -> tuple[Track, Train, Any]:
        """(track, train, foundation) with the parameter of point `i`."""
        return replaced(self.track, self.train, self.foundation, self.parameter,
                        float(self.values[i]))

    def solution(self, i: int) -> Solution:
        """The `railtrack.Solution` at point `i` (negative indices count from the end).

        Its truncation error is estimated as `railtrack.solve` does; its
        residual history holds the one final relative residual.
        """
        track, train, foundation = self.problem(i)
        passage = Passage(track, train)
        system = harmonic_system(passage, foundation, self.harmonics, self.samples)
        c = self.coefficients[i]
        return Solution(
            passage=passage, foundation=foundation, harmonics=self.harmonics,
            coefficients=two_sided(c), method="newton", converged=bool(self.converged[i]),
            iterations=0, residual_history=np.array([self.residuals[i]]),
            message=f"point {i} of a branch in {self.parameter}; {self.message}",
            samples=self.samples, truncation_error=truncation_error(system, c),
        )

    @property
    def solutions(self) -> tuple[Solution, ...]:
        """`solution(i)` for every point (built on each access)."""
        return tuple(self.solution(i) for i in range(len(self)))

    def minimum_displacement(self, samples: int = 512) -> np.ndarray:
        """Lowest sleeper displacement over the period at each point [m] (w < 0 is down)."""
        spectrum = np.zeros((len(self), samples // 2 + 1), dtype=complex)
        spectrum[:, : self.harmonics + 1] = self.coefficients * samples
        return np.fft.irfft(spectrum, samples, axis=1).min(axis=1)

    def crossings(self, value: float) -> tuple[np.ndarray, np.ndarray]:
        """Where the branch crosses ``parameter = value``, one entry per crossing.

        Returns (before, weight): the index of the point before each crossing
        and the linear weight 0 <= weight < 1 of the point after it.  A point
        exactly at `value` is a crossing of weight 0, counted once.
        """
        offset = np.asarray(self.values, dtype=float) - value
        before = np.flatnonzero((offset[:-1] == 0) | (offset[:-1] * offset[1:] < 0))
        if len(offset) and offset[-1] == 0:
            before = np.append(before, len(offset) - 1)
        after = np.minimum(before + 1, len(offset) - 1)
        with np.errstate(divide="ignore", invalid="ignore"):
            weight = np.where(offset[before] == 0, 0.0,
                              offset[before] / (offset[before] - offset[after]))
        return before, weight

    def solutions_at(self, value: float) -> np.ndarray:
        """One-sided coefficients interpolated where the branch crosses `value`, shape (J, m+1).

        One row per crossing (`crossings`), linearly interpolated between
        consecutive points.  These are starting points, not solutions:
        polish them with Newton.
        """
        before, weight = self.crossings(value)
        after = np.minimum(before + 1, len(self) - 1)
        c = np.asarray(self.coefficients)
        rows = [(1 - w) * c[i] + w * c[j] for i, j, w in zip(before, after, weight)]
        return np.array(rows).reshape(-1, self.harmonics + 1)

    _rows = branch_rows                 # __repr__, _repr_html_ (ShortRepr)
    _table_row = None                   # to_dataframe: a row per point, converged's dimension

    def to_xarray(self, samples: int = 512):
        """Every point as an `xarray.Dataset` (CF units; `railtrack.studies.study_export`).

        `samples` per period read each point's lowest sleeper displacement.
        """
        from .study_export import branch_dataset
        return branch_dataset(self, samples)

