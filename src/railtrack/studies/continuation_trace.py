"""One branch traced at a fixed number of harmonics m: the pseudo-arclength loop.

From the first solve at ``parameter = start``, `trace` steps along the
branch R(x, p) = 0 of eq. (17) in the scaled unknowns u = (x / X, p / P)
(Keller 1977): a predictor along the tangent, a corrector on the bordered
system (`railtrack.solvers.arclength`), a step that grows after a fast
corrector and shrinks after a failed one or one whose tangent turns too
far; a change of sign of dp/ds locates a fold, and the branch lands
exactly on the end value.  `railtrack.studies.continuation` chooses m and
warns; the steps that stand alone are in
`railtrack.studies.continuation_steps`.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..equations.harmonic_balance import harmonic_system, to_real
from ..model.passage import Passage
from ..solvers.arclength import ArclengthProblem, correct as _correct, tangent_of as _tangent
from ..solvers.progress import PROGRESS_WORK, progress_bar, show_progress
from ..solvers.solution import ConvergenceWarning, TruncationWarning
from ..solvers.solve import solve
from .branch import Fold, hermite_turning_value, replaced
from .continuation_steps import (branch_of as _branch, estimates as _estimates, fold as _fold,
                                 land as _land)

__all__ = ["GROW", "SHRINK", "MIN_COSINE", "ParameterProblem", "trace", "trace_points"]

GROW, SHRINK = 1.5, 0.5
"""Step factors after a fast (<= 3 Newton steps) and after a failed corrector."""
MIN_COSINE = 0.9
"""A step whose new tangent turns by more than ~25 degrees is refused: it may have jumped branch."""


class ParameterProblem(ArclengthProblem):
    """R(u) and its Jacobian in the scaled unknowns u = (x / X, p / P) of one parameter."""

    def __init__(self, track, train, foundation, parameter, harmonics, samples, scales):
        self.parts = (track, train, foundation, parameter)
        self.harmonics, self.samples = harmonics, samples
        super().__init__(self._system, scales)

    def _system(self, p: float):
        track, train, foundation = replaced(*self.parts[:3], self.parts[3], p)
        return harmonic_system(Passage(track, train), foundation, self.harmonics, self.samples)


def trace(track, train, foundation, parameter, start, stop, step, bounds, max_points, tol,
          max_corrector, progress, harmonics, samples, initial):
    """The branch at m = `harmonics`, and `continuation_steps.estimates` of its points.

    A bar counts the points if `progress` says so (`railtrack.solvers.progress`).
    """
    shown = show_progress(progress, max_points * (2 * harmonics + 1) ** 2 >= PROGRESS_WORK)
    with progress_bar(shown, None, f"continuation in {parameter}, m = {harmonics}", "points") as bar:
        traced = trace_points(track, train, foundation, parameter, start, stop, step, bounds,
                              max_points, tol, max_corrector, harmonics, samples, initial, bar)
        bar.to(len(traced[0]), f"{parameter} = {traced[0].values[-1]:.6g}")
        return traced


def trace_points(track, train, foundation, parameter, start, stop, step, bounds, max_points,
                 tol, max_corrector, harmonics, samples, initial, bar):
    """`trace`'s work, `bar` moved at every point."""
    span = abs(stop - start)
    with warnings.catch_warnings():
        # the branch warns for itself (`continuation`'s `_warned`, and its truncation check)
        warnings.simplefilter("ignore", ConvergenceWarning)
        warnings.simplefilter("ignore", TruncationWarning)


        first = solve(*replaced(track, train, foundation, parameter, start), harmonics,
                      method="newton", tol=tol, samples=samples, initial=initial,
                      stability="off")  # a branch has stable and unstable points alike
    c = first.coefficients[harmonics:]
    x_scale = float(np.linalg.norm(to_real(c))) or 1.0
    problem = ParameterProblem(track, train, foundation, parameter, harmonics, first.samples,
                       (x_scale, span))
    u = np.append(to_real(c) / x_scale, start / span)
    points = [(u, first.residual, 0, start)]
    folds, message = [], ""
    if not first.converged:
        message = f"the first solve, at {parameter} = {start!r}, did not converge: {first.message}"
        return (_branch(problem, points, [np.full(len(u), np.nan)], folds, message, tol),
                (float("nan"), start, harmonics))
    direction = np.sign(stop - start)
    tangent = _tangent(problem.jacobian(u))
    tangent *= np.sign(tangent[-1]) * direction or 1.0
    tangents = [tangent]
    ds, (low, high) = step / span, (b / span for b in bounds)
    while len(points) < max_points:
        bar.to(len(points), f"{parameter} = {u[-1] * span:.6g}")
        point = _correct(problem, u + ds * tangent, tangent, tol, max_corrector)
        new_tangent = None if point is None else _tangent(problem.jacobian(point[0]), tangent)
        if point is None or new_tangent @ tangent < MIN_COSINE:
            predicted = u + ds * tangent
            if point is None and (predicted[-1] * span - stop) * direction >= 0:
                # no solution past stop, e.g. stop at the edge of the field's valid
                # range (epsilon = 0): land on stop from the predictor instead
                landed = _land(problem, u, predicted, stop, tol)
                if landed is not None:
                    points.append(landed)
                    tangents.append(_tangent(problem.jacobian(landed[0]), tangent))
                    message = f"reached {parameter} = {stop!r}"
                    break
            if ds <= low * (1 + 1e-12):
                message = (f"the corrector failed, or turned the tangent too far, at the "
                           f"smallest step {bounds[0]:.3g} at {parameter} = {u[-1] * span:.6g}")
                break
            ds = max(low, ds * SHRINK)
            continue
        p_new = point[0][-1] * span
        if new_tangent[-1] * tangent[-1] < 0:
            value = _fold(problem, u, tangent, ds, new_tangent[-1], tol, max_corrector)
            if value is None:
                value = span * hermite_turning_value(u[-1], point[0][-1], tangent[-1],
                                                     new_tangent[-1], ds)
            folds.append(Fold(float(value), len(points) - 1))
        crossed = (p_new - stop) * direction >= 0 or (p_new - start) * direction < 0
        if crossed:
            bound = stop if (p_new - stop) * direction >= 0 else start
            landed = _land(problem, u, point[0], bound, tol)
            if landed is not None:
                points.append(landed)
                tangents.append(_tangent(problem.jacobian(landed[0]), tangent))
            message = (f"reached {parameter} = {bound!r}" if bound == stop else
                       f"the branch turned back and left the range at {parameter} = {bound!r}")
            if landed is None:
                message += " but the final solve there failed"
            break
        points.append(point + (p_new,))
        tangents.append(new_tangent)
        u, tangent = point[0], new_tangent
        ds = min(high, ds * GROW) if point[2] <= 3 else ds
    else:
        message = f"stopped after max_points = {max_points} points at {parameter} = {u[-1] * span:.6g}"
    message += f"; {len(folds)} fold(s)"
    return _branch(problem, points, tangents, folds, message, tol), _estimates(problem, points)
