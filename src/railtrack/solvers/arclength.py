"""Pseudo-arclength steps on eq. (17) in one parameter: the predictor-corrector's parts.

`railtrack.continuation` (layer ``studies``) follows a branch with them, and
`railtrack.solvers.speed_path` (the fallback of `railtrack.solve` where Newton
fails) reaches a speed through the folds below it.  A problem is R(x, p) = 0
with x = to_real(c) (2m + 1 reals) and p the parameter.

**Scaling.**  c is of order a millimetre and p may be 500 m/s, so the
arclength is measured in ``u = (x / X, p / P)``, with X the Euclidean norm of
x at the start and P a parameter range: a step ds = 0.02 moves p by at most
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

from typing import Callable

import numpy as np

from ..equations.aft_jacobian import residual_jacobian
from ..equations.harmonic_balance import (HarmonicSystem, NonFiniteForceError, from_real,
                                          residual, residual_norm, to_real)

__all__ = ["ArclengthProblem", "tangent_of", "correct"]


class ArclengthProblem:
    """R(u) and its Jacobian in the scaled unknowns u = (x / X, p / P).

    Parameters
    ----------
    system_at : callable
        p -> the `HarmonicSystem` at parameter p (raises ValueError outside
        the parameter's valid range).
    scales : (float, float)
        X [m] and P [unit of p].
    """

    def __init__(self, system_at: Callable[[float], HarmonicSystem], scales):
        self.system = system_at
        self.x_scale, self.p_scale = scales

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
            # p - h outside the field's range (epsilon = 0), or p + h: the
            # one-sided difference of the same order, on the side that exists
            try:
                r0, r1, r2 = (to_real(residual(self.system(p + k * h), c)) for k in range(3))
                slope = (4 * r1 - 3 * r0 - r2) / (2 * h)
            except ValueError:
                r0, r1, r2 = (to_real(residual(self.system(p - k * h), c)) for k in range(3))
                slope = -(4 * r1 - 3 * r0 - r2) / (2 * h)
        columns = np.column_stack([residual_jacobian(system, c) * self.x_scale, slope * self.p_scale])
        return columns / system.load_norm()


def tangent_of(jacobian, previous=None):
    """Unit null vector of the (2m+1) x (2m+2) `jacobian`, turned to agree with `previous`."""
    if previous is None:
        t = np.linalg.svd(jacobian)[2][-1]
    else:
        t = np.linalg.solve(np.vstack([jacobian, previous]), np.eye(len(previous))[-1])
        t /= np.linalg.norm(t)
        t = t if t @ previous > 0 else -t
    return t


def correct(problem: ArclengthProblem, guess, tangent, tol, max_steps):
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
