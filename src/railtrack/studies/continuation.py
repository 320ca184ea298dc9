"""Following a branch of periodic solutions in one parameter (pseudo-arclength).

A softening or hardening foundation bends the response curve, so that over a
range of speeds eq. (17) has several periodic solutions, and a sweep of
single solves jumps between them (or misses some).  Pseudo-arclength
continuation (Keller 1977) follows the curve R(x, p) = 0 itself, through
its turning points, with x = to_real(c) (2m + 1 reals) and p the parameter.

**Scaling.**  c is of order a millimetre and p may be 500 m/s, so the
arclength is measured in ``u = (x / X, p / P)``, with X the Euclidean norm of
x at the start and P = |stop - start|: a step ds = 0.02 moves p by at most
2 % of the range, or the solution by 2 % of its size.  The residual is
divided by ||F|| (`residual_norm`), which makes every block of the bordered
Jacobian of order one.

**dR/dp** is a central difference with step h = 1e-6 max(|p|, P).  Its
truncation error, of relative order h^2 / p^2 = 1e-12, and its round-off,
about 1e-16 / 1e-6 = 1e-10 of the terms of R, only enter the Jacobian of
the corrector: they make Newton's convergence linear with a ratio of order
1e-8 instead of quadratic, and do not move the converged point, which is
set by R alone.
"""

from __future__ import annotations

import numpy as np

from ..solvers.arguments import require_count, require_fraction
from .branch import (TRACK_FIELDS, TRAIN_FIELDS, Branch, Fold, check_parameter,
                     hermite_turning_value, replaced, scalar)
from ..equations.aft_jacobian import residual_jacobian
from ..equations.harmonic_balance import (NonFiniteForceError, from_real, harmonic_system,
                                          residual, residual_norm, to_real)
from ..solvers.newton import iterate_newton
from ..model.passage import Passage
from ..solvers.solve import solve

__all__ = ["continuation", "Branch", "Fold"]

GROW, SHRINK = 1.5, 0.5
"""Step factors after a fast (<= 3 Newton steps) and after a failed corrector."""
MIN_COSINE = 0.9
"""A step whose new tangent turns by more than ~25 degrees is refused: it may have jumped branch."""


class _Problem:
    """R(u) and its Jacobian in the scaled unknowns u = (x / X, p / P)."""

    def __init__(self, track, train, foundation, parameter, harmonics, samples, scales):
        self.parts = (track, train, foundation, parameter)
        self.harmonics, self.samples = harmonics, samples
        self.x_scale, self.p_scale = scales

    def system(self, p: float):
        track, train, foundation = replaced(*self.parts[:3], self.parts[3], p)
        return harmonic_system(Passage(track, train), foundation, self.harmonics, self.samples)

    def split(self, u):
        return from_real(u[:-1] * self.x_scale), u[-1] * self.p_scale

    def residual(self, u):
        """(scaled R, relative residual) at u."""
        c, p = self.split(u)
        system = self.system(p)
        r = residual(system, c)
        return to_real(r) / system.load_norm(), residual_norm(system, r)

    def jacobian(self, u):
        """[dR/dx X, dR/dp P] / ||F||, shape (2m+1, 2m+2)."""
        c, p = self.split(u)
        system = self.system(p)
        h = 1e-6 * max(abs(p), self.p_scale)
        try:
            ahead, behind = (to_real(residual(self.system(p + s), c)) for s in (h, -h))
            slope = (ahead - behind) / (2 * h)
        except ValueError:
            # p - h outside the field's range (epsilon = 0): the one-sided
            # difference of the same order, from p, p + h and p + 2h
            r0, r1, r2 = (to_real(residual(self.system(p + k * h), c)) for k in range(3))
            slope = (4 * r1 - 3 * r0 - r2) / (2 * h)
        columns = np.column_stack([residual_jacobian(system, c) * self.x_scale, slope * self.p_scale])
        return columns / system.load_norm()


def _tangent(jacobian, previous=None):
    """Unit null vector of the (2m+1) x (2m+2) `jacobian`, turned to agree with `previous`."""
    if previous is None:
        t = np.linalg.svd(jacobian)[2][-1]
    else:
        t = np.linalg.solve(np.vstack([jacobian, previous]), np.eye(len(previous))[-1])
        t /= np.linalg.norm(t)
        t = t if t @ previous > 0 else -t
    return t


def _correct(problem, guess, tangent, tol, max_steps):
    """Newton on R(u) = 0, tangent . (u - guess) = 0; (u, relative residual, steps) or None."""
    u = guess.copy()
    for steps in range(max_steps + 1):
        try:
            r, norm = problem.residual(u)
            if norm <= tol:
                return u, norm, steps
            if steps == max_steps or not np.isfinite(norm):
                return None
            bordered = np.vstack([problem.jacobian(u), tangent])
            u = u + np.linalg.solve(bordered, -np.append(r, tangent @ (u - guess)))
        except (NonFiniteForceError, ValueError, np.linalg.LinAlgError):
            # a trial p outside the field's range (speed <= 0), or a law overflowing
            return None
    return None


def _fold(problem, u, tangent, ds, slope, tol, max_steps):
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


def continuation(track, train, foundation, parameter: str = "speed", start=None, stop=None,
                 harmonics: int = 15, step: float | None = None, max_points: int = 400,
                 tol: float = 1e-10, *, min_step: float | None = None,
                 max_step: float | None = None, samples: int | None = None,
                 initial=None, max_corrector: int = 8) -> Branch:
    """Follow the periodic solution of eq. (17) from ``parameter = start`` to `stop`.

    Parameters
    ----------
    track, train, foundation
        The problem, as for `railtrack.solve`; the foundation must be a
        dataclass (one of the package's laws) if `parameter` is one of its fields.
    parameter : str
        A scalar field of the Track (e.g. "pad_damping"), of the Train
        ("speed", "wagon_length") or of the foundation ("epsilon",
        "damping", "tension_stiffness", ...), in that field's unit.
    start : float, optional
        First value (default: the value in the given objects).
    stop : float
        The branch ends when it reaches this value, landing exactly on it.
    harmonics : int
        m (default 15).  Check `branch.solution(i).truncation_error`.
    step : float, optional
        First arclength step, in the unit of the parameter: on a flat stretch
        the change of p per step (default (stop - start) / 50).
    max_points : int
        Largest number of points, the start included.
    tol : float
        Every point solves eq. (17) to ||R|| / ||F|| <= tol.
    min_step, max_step : float, optional
        Bounds of the step, same unit as `step` (default step / 1000 and
        (stop - start) / 10).  A corrector failing at `min_step` ends the branch.
    samples : int, optional
        AFT samples per period, > 4m.
    initial : ndarray, optional
        Starting c_0..c_m for the first solve.
    max_corrector : int
        Newton steps allowed to each corrector.

    Returns
    -------
    Branch
        With the points, their coefficients (one-sided), the folds and a message.

    Raises
    ------
    ValueError
        Unknown or non-scalar parameter, start or stop not real scalars,
        start == stop, bad harmonics, tol or step.

    Examples
    --------
    >>> import railtrack as rt
    >>> branch = continuation(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper(),
    ...                       "epsilon", start=0.0, stop=1.0)
    >>> bool(branch.converged.all()), float(branch.values[-1]), len(branch.folds)
    (True, 1.0, 0)
    """
    if not isinstance(parameter, str):
        raise ValueError(f"parameter must be the name of a field; got {parameter!r}")
    check_parameter(track, train, foundation, parameter)
    if start is None:
        start = getattr(track if parameter in TRACK_FIELDS else train if parameter in TRAIN_FIELDS
                        else foundation, parameter)
    start, stop = scalar("start", parameter, start), scalar("stop", parameter, stop)
    if start == stop:
        raise ValueError(f"start and stop of {parameter!r} must differ; both are {start!r}")
    require_count("harmonics", harmonics, 1)
    require_count("max_points", max_points, 2)
    tol = require_fraction("tol", tol)
    span = abs(stop - start)
    step = span / 50 if step is None else scalar("step", parameter, step)
    bounds = (step / 1000 if min_step is None else min_step, span / 10 if max_step is None else max_step)
    if not 0 < bounds[0] <= step <= bounds[1] or step > span:
        raise ValueError(f"need 0 < min_step <= step <= max_step and step <= |stop - start| for "
                         f"{parameter!r}; got {bounds[0]!r}, {step!r}, {bounds[1]!r}")

    first = solve(*replaced(track, train, foundation, parameter, start), harmonics,
                  method="newton", tol=tol, samples=samples, initial=initial)
    c = first.coefficients[harmonics:]
    x_scale = float(np.linalg.norm(to_real(c))) or 1.0
    problem = _Problem(track, train, foundation, parameter, harmonics, first.samples,
                       (x_scale, span))
    u = np.append(to_real(c) / x_scale, start / span)
    points = [(u, first.residual, 0, start)]
    folds, message = [], ""
    if not first.converged:
        message = f"the first solve, at {parameter} = {start!r}, did not converge: {first.message}"
        return _branch(problem, points, [np.full(len(u), np.nan)], folds, message, tol)
    direction = np.sign(stop - start)
    tangent = _tangent(problem.jacobian(u))
    tangent *= np.sign(tangent[-1]) * direction or 1.0
    tangents = [tangent]
    ds, (low, high) = step / span, (b / span for b in bounds)
    while len(points) < max_points:
        point = _correct(problem, u + ds * tangent, tangent, tol, max_corrector)
        new_tangent = None if point is None else _tangent(problem.jacobian(point[0]), tangent)
        if point is None or new_tangent @ tangent < MIN_COSINE:
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
    return _branch(problem, points, tangents, folds, message, tol)


def _land(problem, before, after, value, tol):
    """Solve at p = value from c interpolated between the points on either side of it."""
    weight = (value / problem.p_scale - before[-1]) / (after[-1] - before[-1])
    x = (1 - weight) * before[:-1] + weight * after[:-1]
    system = problem.system(value)
    outcome = iterate_newton(system, 50, tol, initial=from_real(x * problem.x_scale))
    if not outcome.converged:
        return None
    return (np.append(to_real(outcome.coefficients) / problem.x_scale, value / problem.p_scale),
            float(outcome.residual_history[-1]), outcome.iterations, value)


def _branch(problem, points, tangents, folds, message, tol):
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
