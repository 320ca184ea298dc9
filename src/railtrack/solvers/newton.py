"""Newton's method on the harmonic-balance equations (17).

Not in the paper: where eq. (21) multiplies the error by a fixed factor at
each step (about 1 - k2/k1 = 0.91 for the mean on the paper's track),
Newton's method with the AFT Jacobian of
`railtrack.equations.aft_jacobian.residual_jacobian` converges quadratically for
smooth laws and superlinearly for the kinked bilinear law, where the
Jacobian is a generalised one.  A backtracking line search on the residual
norm keeps it robust far from the solution.
"""

from __future__ import annotations

import numpy as np

from .fixed_point import SolverOutcome
from .foundation_at_rest import static_deflection
from ..equations.aft_jacobian import residual_jacobian
from ..equations.harmonic_balance import (
    HarmonicSystem,
    NonFiniteForceError,
    from_real,
    residual,
    residual_norm,
    to_real,
)

__all__ = ["linear_guess", "guess_about_mean", "iterate_newton"]


def linear_guess(system: HarmonicSystem) -> np.ndarray:
    """The starting point: the static mean, and eq. (23) about it for n >= 1.

    The mean c_0 solves the static balance of eq. (17) for n = 0, where the
    pad and rail terms cancel: f(c_0, 0) = -2 Q L / H
    (`railtrack.solvers.foundation_at_rest.static_deflection`).  The harmonics n >= 1 are
    eq. (23) with the law's tangent at (c_0, 0), which is exact for a linear
    law.  Starting the mean from the static balance rather than from the
    tangent at rest matters for a law with (almost) no stiffness at rest,
    such as a pure cubic: there -F_0 / (k/M) is astronomically large.
    Harmonics whose linearised denominator vanishes start at zero.
    """
    force = float(system.passage.static_load_per_sleeper)
    mean = static_deflection(system.foundation, force)
    if np.isfinite(mean):
        stiffness, damping = (
            float(np.ravel(x)[0]) for x in system.foundation.tangent(np.array([mean]), np.zeros(1))
        )
    else:
        stiffness, damping = system.foundation.linearization()
    return guess_about_mean(system, mean, stiffness, damping)


def guess_about_mean(system: HarmonicSystem, mean, stiffness, damping) -> np.ndarray:
    """c_0 = mean, and eq. (23) with the tangent (stiffness, damping) for n >= 1.

    Scalars give one guess, shape (m+1,); arrays of shape (B, 1) give one per
    member of a batch, shape (B, m+1) (`railtrack.solvers.batch.batch_guess`).
    Where the mean is not finite, c_0 is eq. (23)'s too.
    """
    law = (stiffness + 1j * system.omega * damping) / np.asarray(system.sleeper_mass)
    denominator = np.broadcast_to(system.operator + law,
                                  np.shape(mean)[:-1] + (system.harmonics + 1,))
    load = np.broadcast_to(system.load, denominator.shape)
    usable = np.isfinite(denominator) & (np.abs(denominator) > 0)
    guess = np.zeros(denominator.shape, dtype=complex)
    guess[usable] = -load[usable] / denominator[usable]
    mean = np.asarray(mean, dtype=float)[..., 0] if np.ndim(mean) else float(mean)
    guess[..., 0] = np.where(np.isfinite(mean), mean, guess[..., 0].real)
    return guess


def iterate_newton(
    system: HarmonicSystem,
    max_iterations: int,
    tol: float,
    initial: np.ndarray | None = None,
) -> SolverOutcome:
    """Solve eq. (17) by damped Newton iterations on the 2m + 1 real unknowns.

    Parameters
    ----------
    system : HarmonicSystem
    max_iterations : int
        Largest number of Newton steps.
    tol : float
        Converged once ``||R|| / ||F|| <= tol``.
    initial : ndarray, optional
        c_0..c_m to start from; default `linear_guess`.
    """
    c = linear_guess(system) if initial is None else np.array(initial, dtype=complex)
    current = residual(system, c)
    norm = residual_norm(system, current)
    history, harmonic_residuals = [norm], [np.abs(current)]
    converged, steps, message = norm <= tol, 0, ""
    while not converged and steps < max_iterations:
        steps += 1
        jacobian = residual_jacobian(system, c)
        if not np.all(np.isfinite(jacobian)):
            message = f"the Jacobian is not finite at Newton step {steps}"
            break
        try:
            step = from_real(np.linalg.solve(jacobian, -to_real(current)))
        except np.linalg.LinAlgError:
            # A singular Jacobian happens for instance at w = 0 on a tensionless
            # law, where the mean has no stiffness; the least-squares step still
            # points downhill for the residual norm.
            step = from_real(np.linalg.lstsq(jacobian, -to_real(current), rcond=None)[0])
        step[0] = step[0].real
        # Backtracking: halve the step until the residual decreases.  A trial
        # so far out that the law overflows counts as no decrease.
        for _ in range(30):
            trial = c + step
            try:
                trial_residual = residual(system, trial)
                trial_norm = residual_norm(system, trial_residual)
            except NonFiniteForceError:
                trial_norm = np.inf
            if trial_norm < norm:
                break
            step *= 0.5
        else:
            message = f"the line search found no decrease of the residual at Newton step {steps}"
            break
        c, current, norm = trial, trial_residual, trial_norm
        history.append(norm)
        harmonic_residuals.append(np.abs(current))
        converged = norm <= tol
    if converged:
        message = f"relative residual {norm:.2e} <= tol {tol:.1e} after {steps} Newton steps"
    elif not message:
        message = f"relative residual {norm:.2e} > tol {tol:.1e} after {steps} Newton steps"
    else:
        message += f"; relative residual {norm:.2e} > tol {tol:.1e}"
    return SolverOutcome(
        c, bool(converged), steps, np.array(history), message, np.array(harmonic_residuals[-20:])
    )
