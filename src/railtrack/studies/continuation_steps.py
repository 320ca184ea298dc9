"""The steps of `railtrack.continuation` that stand alone: a fold located, a point landed, the branch.

`railtrack.studies.continuation` traces the branch; these helpers locate a
turning point between two corrected points (`fold`), land on the end value
of the parameter (`land`), estimate the truncation error of every point
(`estimates`) and pack the points into a `railtrack.studies.branch.Branch`
(`branch_of`).
"""

from __future__ import annotations

import numpy as np

from ..equations.harmonic_balance import from_real, to_real
from ..solvers.arclength import correct as _correct, tangent_of as _tangent
from ..solvers.newton import iterate_newton
from ..solvers.solve import DEFAULT_ACCURACY
from ..solvers.truncation import TAIL_FACTOR, estimate_of, grown_harmonics, track_spectrum
from .branch import Branch

__all__ = ["fold", "land", "estimates", "branch_of"]


def fold(problem, u, tangent, ds, slope, tol, max_steps):
    """Parameter at the turning point between u and the next point, ``ds`` ahead along `tangent`.

    dp/ds is `tangent[-1]` at u and `slope` at the next point, of opposite
    signs; the Illinois variant of regula falsi on the step length finds
    the corrected point where dp/ds = 0.  None if a corrector fails.
    """
    lo, hi, f_lo, f_hi = 0.0, ds, tangent[-1], slope
    found, side = None, 0
    for _ in range(40):
        trial = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        point = _correct(problem, u + trial * tangent, tangent, tol, max_steps)
        if point is None:
            return None
        f = _tangent(problem.jacobian(point[0]), tangent)[-1]
        found = point[0][-1] * problem.p_scale
        if abs(f) < 1e-10 or hi - lo < 1e-12 * ds:
            break
        if np.sign(f) == np.sign(f_hi):
            hi, f_hi = trial, f
            f_lo, side = (f_lo / 2, side) if side == 1 else (f_lo, 1)
        else:
            lo, f_lo = trial, f
            f_hi, side = (f_hi / 2, side) if side == -1 else (f_hi, -1)
    return found


def estimates(problem, points) -> tuple[float, float, int]:
    """(worst estimated truncation error, its parameter value, the m it needs) over the points."""
    worst = (0.0, float(points[0][3]), problem.harmonics)
    for u, _residual, _steps, value in points:
        system = problem.system(value)
        c = problem.split(u)[0]
        estimate, tail = estimate_of(system, c, track_spectrum(system.passage,
                                                               TAIL_FACTOR * problem.harmonics))
        if tail is not None and estimate > worst[0]:
            worst = (estimate, float(value), grown_harmonics(c, tail, 0.8 * DEFAULT_ACCURACY))
    return worst


def land(problem, before, after, value, tol):
    """Solve at p = value from c interpolated between the points on either side of it."""
    weight = (value / problem.p_scale - before[-1]) / (after[-1] - before[-1])
    x = (1 - weight) * before[:-1] + weight * after[:-1]
    system = problem.system(value)
    outcome = iterate_newton(system, 50, tol, initial=from_real(x * problem.x_scale))
    if not outcome.converged:
        return None
    return (np.append(to_real(outcome.coefficients) / problem.x_scale, value / problem.p_scale),
            float(outcome.residual_history[-1]), outcome.iterations, value)


def branch_of(problem, points, tangents, folds, message, tol):
    track, train, foundation, parameter = problem.parts
    residuals = np.array([point[1] for point in points])
    return Branch(
        parameter=parameter, values=np.array([point[3] for point in points]),
        coefficients=np.array([problem.split(point[0])[0] for point in points]),
        tangents=np.array(tangents), converged=residuals <= tol, residuals=residuals,
        folds=tuple(folds), message=message, track=track, train=train, foundation=foundation,
        harmonics=problem.harmonics, samples=problem.samples,
        coefficient_scale=problem.x_scale, parameter_scale=problem.p_scale,
    )
