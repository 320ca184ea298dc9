"""Many nonlinear solves at once: `sweep` over any field of the track, the train or the law.

``sweep(track, train, foundation, speed=values)`` replaces one field (or
several, of equal length) by an array, builds one batched harmonic system
and solves it with `railtrack.solvers.batch.newton_batch`.  The result, `Sweep`,
keeps every member, converged or not, and gives the extremes over a period
of the sleeper displacement, the rail-seat load and the foundation force,
and each member's estimated truncation error.

**Harmonics.**  ``harmonics="auto"`` (default) meets the accuracy of
`railtrack.solve`'s "auto" at every member: m is predicted at up to nine
members spread over the sweep, every member's truncation error is then
estimated (`railtrack.solvers.batch.batch_truncation`), and while the worst
converged member misses the accuracy, m grows to what its spectrum needs
and the sweep is solved again, from the previous solutions.  An explicit m
is kept, and warns (`railtrack.TruncationWarning`) if a member's estimate
exceeds 1 %.

**Size.**  The members are solved in blocks of `BLOCK`, so that the working
memory does not grow with the sweep; the results themselves (2m + 1 complex
coefficients a member) are estimated before anything is allocated, and a
sweep whose results would exceed `MAX_RESULT_BYTES` is refused with the
largest size that fits (`railtrack.studies.sweep_members`; the extremes are
read by `railtrack.studies.period_extremes`).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..equations.harmonic_balance import harmonic_system, require_jacobian_samples
from ..model.foundations import as_foundation
from ..model.passage import Passage
from ..model.track import Track
from ..model.train import Train
from ..solvers.arguments import require_count, require_fraction
from ..solvers.batch import batch_truncation, member
from ..solvers.chunk_map import chunk_bounds, map_chunks, show_progress
from ..solvers.solution import ConvergenceWarning, Solution, TruncationWarning
from ..solvers.solve import AUTO_ROUNDS, DEFAULT_ACCURACY, WARN_TRUNCATION
from ..solvers.truncation import MAX_AUTO_HARMONICS, auto_samples, grown_harmonics
from .sweep_members import (BLOCK, MAX_RESULT_BYTES, check_members_conditioning, warn_members,
                            polynomial_samples, predicted_harmonics, require_fits, rows,
                            solve_block, split_fields)
from .sweep_stability import member_stability, require_whole_sleepers, stability_mode
from ..solvers.export import Exports
from ..solvers.result_repr import ShortRepr
from .study_repr import sweep_rows

__all__ = ["Sweep", "sweep", "BLOCK", "MAX_RESULT_BYTES"]

PROGRESS_MEMBERS = 50_000
"""A sweep of this many members or more shows its progress unless told otherwise."""


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

    _rows = sweep_rows     # __repr__, _repr_html_: ShortRepr

    def to_xarray(self):
        """Every member as an `xarray.Dataset` (CF units; `railtrack.studies.study_export`)."""
        from .study_export import sweep_dataset
        return sweep_dataset(self)


def sweep(track: Track, train: Train, foundation, harmonics: int | str = "auto", *,
          accuracy: float | None = None, tol: float = 1e-10, max_iterations: int = 100,
          samples: int | None = None, stability: str | bool = "quick", progress=None,
          executor=None, **values) -> Sweep:
    """Solve eq. (17) for every value of the swept field(s), all at once.

    Parameters
    ----------
    track, train : Track, Train
    foundation : LinearFoundation, BilinearFoundation or CubicFoundation
        A dataclass law, so that its fields can be swept and evaluated for
        the whole batch at once.
    harmonics : int or "auto"
        m, the same for every member.  "auto" (default): the smallest m for
        which every converged member's estimated truncation error is below
        `accuracy` (module docstring).  An explicit m (the paper's is 15)
        warns with a `railtrack.TruncationWarning` if a member's estimate
        exceeds 1 %.
    accuracy : float, optional
        For ``harmonics="auto"``, as for `railtrack.solve` (default 1e-3).
    tol, max_iterations, samples
        As for `railtrack.solve` with ``method="newton"``; samples needs an
        explicit m.
    stability : {"quick", "full", "off"} or bool
        Judge every converged member as `railtrack.solve` does
        (`Sweep.stable`, `Sweep.dominant_multiplier`; one
        `railtrack.UnstableSolutionWarning` for all unstable members).
        "quick" (default): finds unstable members, proves none stable.
        "full" (or True): `railtrack.floquet` at the sweep's m,
        wagon-periodic disturbances; needs H / L an integer for every
        member.  "off" (or False): nothing.  Either look runs per member, in
        a loop, and costs far more than the batched solve: on a shared
        2-core machine "quick" takes about 9 ms a member of a nonlinear law
        at m = 15 and 35 ms at m = 30; at m = 25 "full" about 70 ms a member on the fold
        track of chapter 10 (480-545 m/s) and 280 ms on the paper's track
        (30-100 m/s), against 0.5-5 ms a member for the sweep itself.
    progress : bool or None
        A ``tqdm`` bar over the blocks of `BLOCK` members: None shows it
        from `PROGRESS_MEMBERS` members (10,000 solve in about a second),
        True or False force it.
    executor : concurrent.futures.Executor, optional
        Runs the blocks (a ``ProcessPoolExecutor``, a Dask ``Client``);
        default: this process.  The results do not depend on it.
    **values : array_like of real numbers, shape (B,)
        The field(s) to sweep by name, e.g. ``speed=...``, ``pad_damping=...``,
        ``stiffness=...``, ``epsilon=...``; several fields sweep together.
        They are copied.

    Returns
    -------
    Sweep
        Members that did not converge are kept, and warn
        (`railtrack.ConvergenceWarning`).

    Raises
    ------
    ValueError
        Bad values (not real, not 1-D, unequal lengths, out of a field's
        range), a member for which eq. (3) loses accuracy (as `railtrack.solve`
        refuses it), results larger than `MAX_RESULT_BYTES`, or
        ``stability="full"`` with a member whose H / L is not an integer.

    Examples
    --------
    >>> import numpy as np
    >>> from railtrack import Track, Train, CubicFoundation
    >>> result = sweep(Track.paper(), Train.paper(), CubicFoundation.paper(), harmonics=15,
    ...                speed=[30.0, 45.0])
    >>> bool(result.converged.all()), np.round(result.lowest * 1e3, 3).tolist()
    (True, [-0.854, -0.853])
    """
    stability = stability_mode(stability)
    if not dataclasses.is_dataclass(foundation):
        raise TypeError(f"sweep takes a dataclass foundation law (Linear, Bilinear, Cubic); "
                        f"got {type(foundation).__name__}")
    automatic = isinstance(harmonics, str) and harmonics == "auto"
    if not automatic:
        harmonics = require_count("harmonics", harmonics, 1)
    elif samples is not None:
        raise ValueError("samples needs an explicit harmonics=m; 'auto' chooses m itself")
    if accuracy is not None and not automatic:
        warnings.warn("accuracy is used by harmonics='auto' only; ignored for an explicit m")
    accuracy = DEFAULT_ACCURACY if accuracy is None else require_fraction("accuracy", accuracy)
    max_iterations = require_count("max_iterations", max_iterations, 0)
    tol = require_fraction("tol", tol)
    track_changes, train_changes, law_changes, size = split_fields(track, train, foundation, values)
    passage = Passage(track.replace(**track_changes), train.replace(**train_changes))
    law = as_foundation(dataclasses.replace(foundation, **law_changes))
    if samples is not None:
        require_jacobian_samples(samples, harmonics)
    require_fits(size, 1 if automatic else harmonics)
    check_members_conditioning(passage, size, values)
    if stability == "full":
        require_whole_sleepers(passage, size, values)
    m = harmonics if not automatic else predicted_harmonics(passage, law, size, accuracy)
    run = dict(passage=passage, law=law, size=size, tol=tol, max_iterations=max_iterations,
               executor=executor, progress=show_progress(progress, size >= PROGRESS_MEMBERS))
    result = _solve(m, samples, None, automatic, **run)
    for _round in range(AUTO_ROUNDS if automatic else 0):
        worst = _worst(result)
        if worst is None or result.truncation_error[worst] <= accuracy or m >= MAX_AUTO_HARMONICS:
            break
        member_system = harmonic_system(Passage(member(passage.track, worst),
                                                member(passage.train, worst)),
                                        member(law, worst), m)
        c = result.coefficients[worst, m:]
        tail = batch_truncation(member_system, c[None, :], 1)[1][0]
        grown = min(MAX_AUTO_HARMONICS,
                    max(math.ceil(1.1 * m), grown_harmonics(c, tail, 0.8 * accuracy)))
        start = np.zeros((size, grown + 1), dtype=complex)
        start[:, : m + 1] = result.coefficients[:, m:]
        m = grown
        result = _solve(m, None, start, automatic, **run)
    warn_members(result, automatic, accuracy, tuple(values))
    verdicts = {} if stability == "off" else dict(zip(
        ("stable", "dominant_multiplier"), member_stability(result, values, stability)))
    return dataclasses.replace(result, values={k: np.array(v, dtype=float)
                                               for k, v in values.items()}, **verdicts)


def _worst(result: Sweep) -> int | None:
    """Index of the converged member with the largest truncation estimate (None if none)."""
    errors = np.where(result.converged & np.isfinite(result.truncation_error),
                      result.truncation_error, -np.inf)
    return int(np.argmax(errors)) if np.isfinite(errors.max()) else None


def _solve(m, samples, initial, automatic, *, passage, law, size, tol, max_iterations,
           executor=None, progress=False) -> Sweep:
    """Every member at m harmonics, `BLOCK` members at a time (on `executor` if given)."""
    require_fits(size, m)
    if samples is None:
        # exact for these laws, and a quarter of solve's default work per member;
        # a kinked law takes what solve takes: its default, or auto's for 'auto'
        samples = polynomial_samples(law, m) or (auto_samples(m) if automatic else None)
    bounds = chunk_bounds(size, BLOCK)
    arguments = []
    for start, stop in bounds:
        index = np.arange(start, stop)
        arguments.append((rows(passage, index, size), rows(law, index, size), len(index), m,
                          samples, tol, max_iterations,
                          None if initial is None else initial[index]))
    parts = map_chunks(solve_block, arguments, [b - a for a, b in bounds], executor=executor,
                       progress=progress, description=f"sweep, m = {m}")
    joined = [np.concatenate(column) for column in list(zip(*parts))[:5]]
    extremes = {k: np.concatenate([p[5][k] for p in parts]) for k in parts[0][5]}
    return Sweep(values={}, harmonics=m, coefficients=joined[0], converged=joined[1],
                 iterations=joined[2], residual=joined[3], truncation_error=joined[4],
                 passage=passage, foundation=law, **extremes)
