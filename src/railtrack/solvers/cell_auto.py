"""harmonics="auto" for a cell: the rounds that grow m until the truncation estimate meets it.

The estimate is `railtrack.solvers.cell_truncation`'s: the neglected
harmonics n = m+1..8m, solved with each law linearised about its mean
tangent, and the largest share of the tail in the sleepers' displacement
or the rail-seat load (the load converges more slowly).  "auto" starts
from the m that `predict_harmonics` gives the stiffest-to-resolve law of
the cell, and grows m (by at least 10 %) to what both spectra and their
estimated tails need, at most `AUTO_ROUNDS` times and up to
`MAX_CELL_HARMONICS`.  A level that does not converge does not end the
search: m grows by half, from the last converged level where there is one,
up to `FAILED_LEVELS` failures in a row; the message lists each m tried and
what happened there.  Stopped by the cap (a law whose force jumps at
contact: the seat load's error falls about as 1/m), the message says which
m the last two levels' errors, extrapolated, put within the accuracy.
Through `solve_track_cell` (`railtrack.solve`), "auto" that stops short of
the accuracy is a failure, ``converged=False``
(`railtrack.solvers.guards.hold_to_accuracy`); an explicit m converged at
that m warns above 1 %.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import numpy as np

from ..model.passage import Passage
from .arguments import require_count
from .auto_harmonics import AUTO_ROUNDS, DEFAULT_ACCURACY
from .cell_newton import solve_cell
from .cell_solution import CellSolution
from .cell_truncation import (
    cell_grown_harmonics,
    cell_truncation,
    cell_truncation_errors,
    estimate,
)
from .diagnosis import report
from .guards import (
    FAILED_LEVELS,
    check_laws_at_rest,
    checked_accuracy,
    checked_stability,
    checked_tol,
    hold_to_accuracy,
    look_at_stability,
    refuse_unused,
    require_scalar_fields,
    truncation_limit,
)
from .truncation import auto_samples, predict_harmonics

__all__ = ["cell_truncation", "cell_truncation_errors", "cell_grown_harmonics",
           "solve_cell_auto", "solve_track_cell", "MAX_CELL_HARMONICS"]

MAX_CELL_HARMONICS = 400
"""The largest m that harmonics="auto" takes for a cell."""


def _first_harmonics(passage: Passage, cell, accuracy: float) -> int:
    """The largest m that `predict_harmonics` gives any of the cell's laws alone."""
    chosen = 1
    for law in {id(law): law for law in cell.foundations}.values():
        try:
            chosen = max(chosen, predict_harmonics(passage, law, accuracy / 2)[0])
        except (ValueError, ArithmeticError):
            chosen = max(chosen, 15)
    return min(chosen, MAX_CELL_HARMONICS)


def solve_cell_auto(passage: Passage, cell, *, accuracy: float = DEFAULT_ACCURACY,
                    tol: float = 1e-10, max_iterations: int = 50) -> CellSolution:
    """The cell's response at the smallest m whose estimated truncation error meets `accuracy`.

    Examples
    --------
    >>> from railtrack.model.cell import SleeperCell
    >>> from railtrack.model.foundations import CubicFoundation
    >>> passage = Passage.paper()
    >>> cell = SleeperCell.identical(passage, CubicFoundation.paper(), 3)
    >>> result = solve_cell_auto(passage, cell)
    >>> result.converged, bool(result.truncation_error <= 1e-3)
    (True, True)
    """
    return _auto(passage, cell, accuracy, tol, max_iterations)[0]


def _auto(passage: Passage, cell, accuracy: float, tol: float,
          max_iterations: int) -> tuple[CellSolution, int | None]:
    """`solve_cell_auto`, and the m its last estimate needs where the cap stopped it (else None)."""
    if not 0.0 < accuracy < 1.0:
        raise ValueError(f"accuracy must be in (0, 1); got {accuracy!r}")
    m = _first_harmonics(passage, cell, accuracy)
    needed, levels = None, []
    initial, last, tried, failed, rounds = None, None, [], 0, 0
    while True:
        result = solve_cell(passage, cell, m, tol=tol, max_iterations=max_iterations,
                            samples=auto_samples(m), initial=initial)
        if not result.converged:
            # a level that fails does not end the search: a gap law that no m near the
            # prediction resolves converges above it (issue 27); start from the last
            # converged level if there is one
            failed += 1
            tried.append(f"m = {m}: did not converge ({result.message})")
            if failed >= FAILED_LEVELS or m >= MAX_CELL_HARMONICS:
                break
            m = min(MAX_CELL_HARMONICS, math.ceil(1.5 * m))
            initial = None if last is None else np.pad(last, ((0, 0), (0, m + 1 - last.shape[1])))
            continue
        failed, rounds = 0, rounds + 1
        errors, tail, seat_tail, peaks = estimate(result)
        error = max(errors.values())
        result = replace(result, truncation_error=error)
        tried.append(f"m = {m}: converged, estimated truncation error {error:.1e}")
        if error <= accuracy or rounds > AUTO_ROUNDS:
            break
        levels.append((m, error))
        if m >= MAX_CELL_HARMONICS:
            # a law that kinks or jumps converges slowly: say what m it needs
            needed, how = _needed(levels, accuracy, lambda: cell_grown_harmonics(
                result, tail, seat_tail, 0.8 * accuracy, peaks))
            tried.append(f"the largest m that 'auto' takes for a cell is {MAX_CELL_HARMONICS}; "
                         f"about m = {needed} would meet accuracy {accuracy:.1e} ({how})")
            break
        grown = cell_grown_harmonics(result, tail, seat_tail, 0.8 * accuracy, peaks)
        bigger = min(MAX_CELL_HARMONICS, max(math.ceil(1.1 * m), grown))
        last = np.concatenate([result.coefficients[:, m:], tail], axis=1)[:, :bigger + 1]
        initial, m = last, bigger
    return replace(result, message=f"{result.message}; harmonics='auto' tried "
                   + "; ".join(tried)), needed


def _needed(levels: list[tuple[int, float]], accuracy: float, grown) -> tuple[int, str]:
    """The m that meets `accuracy` from the converged levels' (m, error), and how it was found.

    The errors of the last two levels fitted as ``C m^-p`` and extrapolated:
    a kinked law's error steepens with m (the seat load's harmonics fall
    as 1/n^2 only once the kink is resolved), so that the fit errs on the
    safe side.  With one level only, ``grown()``, the spectrum's own
    extrapolation (`cell_grown_harmonics`).
    """
    if len(levels) >= 2 and levels[-2][1] > levels[-1][1] > accuracy:
        (m0, e0), (m1, e1) = levels[-2], levels[-1]
        power = math.log(e0 / e1) / math.log(m1 / m0)
        fitted = math.ceil(m1 * (e1 / accuracy) ** (1.0 / power))
        return fitted, f"its estimate fell as m^-{power:.1f} from m = {m0} to {m1}"
    return grown(), "its estimated spectrum's extrapolation"


def solve_track_cell(track, train, cell, harmonics="auto", method: str = "newton", *,
                     accuracy=None, tol=None, max_iterations=None, samples=None, initial=None,
                     strict: bool = False, check_foundation: bool = True,
                     stability: str = "quick", split=None, fallback=None) -> CellSolution:
    """`railtrack.solve` for a `SleeperCell`: Newton, an explicit m or "auto".

    Arguments as `railtrack.solve`, checked by `railtrack.solvers.guards`
    as for one sleeper.  Stability is judged as for one sleeper, with Hill's
    matrix of the cell (`railtrack.solvers.stability_hint`): "quick" warns,
    "full" keeps the multipliers on the result's `stability`.  `split` and
    `fallback` are refused: there is no fixed point and no speed path here.
    """
    if method != "newton":
        raise ValueError(f"a SleeperCell is solved by method='newton' only; got {method!r}")
    refuse_unused("the SleeperCell path (Newton)",
                  split=(split, "a fixed-point setting"),
                  fallback=(fallback, "no speed path for a cell"))
    stability = checked_stability(stability)
    passage = Passage(track, train)
    _compare_with_track(track, cell)
    require_scalar_fields(track, train)
    check_laws_at_rest(cell.foundations, cell.pad_stiffness, cell.pad_damping, check_foundation)
    tol = checked_tol(tol, 1e-10)
    iterations = 50 if max_iterations is None else require_count("max_iterations",
                                                                 max_iterations, 0)
    automatic = isinstance(harmonics, str) and harmonics == "auto"
    accuracy = checked_accuracy(accuracy, automatic, stacklevel=4)
    if automatic:
        if samples is not None or initial is not None:
            raise ValueError("samples and initial need an explicit harmonics=m; "
                             "'auto' chooses m itself")
        result, needed = _auto(passage, cell, accuracy, tol, iterations)
    else:
        needed = None
        require_count("harmonics", harmonics, 1)
        result = solve_cell(passage, cell, int(harmonics), tol=tol, max_iterations=iterations,
                            samples=samples, initial=initial)
        if result.converged:
            result = replace(result, truncation_error=cell_truncation(result)[0])
    stopped = f"'auto' stopped after {AUTO_ROUNDS + 1} converged levels"
    if needed is not None:
        stopped = (f"'auto' stops at {MAX_CELL_HARMONICS} for a cell (a law that kinks or jumps "
                   f"converges slowly); about harmonics={needed} would meet it")
    result, short = hold_to_accuracy(result, automatic, accuracy, strict, stopped=stopped,
                                     of="the largest sleeper peak")
    if not short:
        result = report(result, strict, truncation_limit(automatic, accuracy),
                        f"harmonics={result.harmonics}: the estimated truncation error is "
                        f"{result.truncation_error:.1%} of the largest sleeper peak; pass a "
                        "larger harmonics")
    judged = look_at_stability(result, stability, stacklevel=5)
    return result if judged is None else replace(result, stability=judged)


def _compare_with_track(track, cell) -> None:
    """Warn when a field of the cell differs from the track's at every sleeper.

    The cell's masses and pads are the ones solved; a cell built from another
    track's `Passage` would replace this track's without a word.
    """
    for name in ("sleeper_mass", "pad_stiffness", "pad_damping"):
        ours, theirs = getattr(cell, name), float(getattr(track, name))
        if not np.any(np.isclose(ours, theirs, rtol=1e-12, atol=0.0)):
            warnings.warn(f"no sleeper of the cell has the track's {name} ({theirs:g}); the "
                          f"cell's values ({np.unique(ours)[:3]}...) are solved. Build the cell "
                          f"from this track's Passage if that was not meant", UserWarning,
                          stacklevel=4)
