"""Where Newton fails from the linear guess: reach the speed from a lower one.

On a softening (or hardening) foundation the response curve in speed bends
over, and Newton's method started from eq. (23) about the static mean may
find no decrease of the residual even where a single solution exists: the
linear guess is too far from it.  A train reaches its speed from below;
`speed_path` does the same numerically.  It solves at a lower speed, where
the linear guess is good, and follows the branch of solutions in speed by
pseudo-arclength steps (`railtrack.solvers.arclength`, the steps of
`railtrack.continuation`), through any folds, until the branch first reaches
the speed asked for; Newton then lands on that speed exactly.

The solution found is the first crossing of the branch that starts at the
lower speed.  Where several solutions exist at the target speed it is one
of them, not necessarily the one a ring settles on: `railtrack.continuation`
lists them all.  This module lives in ``solvers`` because `railtrack.solve`
may not import ``studies``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .arclength import ArclengthProblem, correct, tangent_of
from .fixed_point import SolverOutcome
from .newton import iterate_newton
from ..equations.harmonic_balance import HarmonicSystem, from_real, harmonic_system, to_real
from ..model.passage import Passage

__all__ = ["SpeedPath", "speed_path", "START_FRACTIONS", "MAX_POINTS"]

START_FRACTIONS = (0.5, 0.25, 0.1)
"""Starting speeds tried, as fractions of the target speed, until Newton converges there."""
MAX_POINTS = 400
"""Largest number of points along the path (as `railtrack.continuation`'s max_points)."""
FIRST_STEP, SMALLEST_STEP, LARGEST_STEP = 0.02, 2e-5, 0.1
"""Arclength steps in units of (target - start) (those of `railtrack.continuation`)."""
MIN_COSINE = 0.9


class SpeedPath(NamedTuple):
    """What `speed_path` did.

    Attributes
    ----------
    outcome : SolverOutcome or None
        The converged Newton solve at the target speed; None if the path failed.
    start : float
        The speed the path started from [m/s].
    points : int
        Points along the path.
    folds : int
        Turning points passed (where the speed along the branch turned back).
    reason : str
        Why the path failed ("" if it did not).
    """

    outcome: SolverOutcome | None
    start: float
    points: int
    folds: int
    reason: str

    def describe(self, target: float) -> str:
        """The path in words, for the message of the solve."""
        if self.outcome is None:
            return (f"a continuation in speed from a lower speed failed too: {self.reason}")
        return (f"Newton from the linear guess failed; this solution was reached by a "
                f"continuation in speed from {self.start:g} m/s ({self.points} points, "
                f"{self.folds} fold(s) passed), the first solution on that branch at "
                f"{target:g} m/s (rt.continuation lists every solution)")


def speed_path(system: HarmonicSystem, tol: float, max_iterations: int) -> SpeedPath:
    """Solve `system` by following its branch in speed up from a lower speed.

    Parameters
    ----------
    system : HarmonicSystem
        The problem at the target speed v (scalar passage), m harmonics.
    tol, max_iterations
        As for `railtrack.solvers.newton.iterate_newton`, for the first
        solve and the landing; each corrector takes at most 8 steps.

    Returns
    -------
    SpeedPath
    """
    passage, m, samples = system.passage, system.harmonics, system.samples
    target = float(passage.speed)

    def system_at(speed: float) -> HarmonicSystem:
        if speed == target:
            return system
        return harmonic_system(Passage(passage.track, passage.train.replace(speed=speed)),
                               system.foundation, m, samples)

    for fraction in START_FRACTIONS:
        start = fraction * target
        first = iterate_newton(system_at(start), max_iterations, tol)
        if first.converged:
            break
    else:
        return SpeedPath(None, start, 0, 0, f"Newton did not converge at {start:g} m/s either")
    span = target - start
    x = to_real(first.coefficients)
    problem = ArclengthProblem(system_at, (float(np.linalg.norm(x)) or 1.0, span))
    u = np.append(x / problem.x_scale, start / span)
    try:
        tangent = tangent_of(problem.jacobian(u))
    except (ValueError, np.linalg.LinAlgError) as error:
        return SpeedPath(None, start, 1, 0, f"no tangent at {start:g} m/s ({error})")
    tangent *= np.sign(tangent[-1]) or 1.0
    ds, points, folds, end = FIRST_STEP, 1, 0, target / span
    while points < MAX_POINTS:
        point = correct(problem, u + ds * tangent, tangent, tol, 8)
        new = None if point is None else tangent_of(problem.jacobian(point[0]), tangent)
        if point is None or new @ tangent < MIN_COSINE:
            if ds <= SMALLEST_STEP * (1 + 1e-12):
                return SpeedPath(None, start, points, folds, "the corrector failed at "
                                 f"{u[-1] * span:.6g} m/s with the smallest step")
            ds = max(SMALLEST_STEP, ds / 2)
            continue
        points += 1
        folds += int(new[-1] * tangent[-1] < 0)
        if point[0][-1] >= end:                         # crossed the target speed
            weight = (end - u[-1]) / (point[0][-1] - u[-1])
            guess = from_real(((1 - weight) * u[:-1] + weight * point[0][:-1]) * problem.x_scale)
            landed = iterate_newton(system, max_iterations, tol, guess)
            if landed.converged:
                return SpeedPath(landed, start, points, folds, "")
            return SpeedPath(None, start, points, folds,
                             f"Newton at {target:g} m/s from the branch's crossing failed")
        if point[0][-1] < 0.5 * start / span:
            return SpeedPath(None, start, points, folds,
                             f"the branch turned back below {start / 2:g} m/s")
        u, tangent = point[0], new
        ds = min(LARGEST_STEP, ds * 1.5) if point[2] <= 3 else ds
    return SpeedPath(None, start, points, folds, f"not reached within {MAX_POINTS} points")


def not_converged_advice(method: str, message: str, passage: Passage, harmonics: int,
                         stalled: bool) -> str:
    """The text of the `ConvergenceWarning` of an unconverged solve.

    Where Newton stalled (the line search found no decrease, or the speed
    path failed too), a fold of the response curve is likely near this
    speed, and the message gives the `railtrack.continuation` call that
    lists every solution there.
    """
    text = (f"{method} did not converge: {message}. The returned Solution has "
            "converged=False and is not a solution of eq. (17)")
    if method != "newton":
        return text + "; try method='newton'"
    if not stalled:
        return text + "; raise max_iterations, or give a better initial guess"
    v = float(passage.speed)
    return text + (
        ". Newton stalling like this usually means a fold of the response curve is near: "
        "follow the branch through it with "
        f"branch = rt.continuation(track, train, foundation, 'speed', start={v / 2:g}, "
        f"stop={v:g}, harmonics={harmonics}), then branch.solutions_at({v:g}) gives a "
        "starting point (initial=) for each solution at this speed")
