"""Newton's method on the harmonic-balance equations (17).

Not in the paper: where eq. (21) multiplies the error by a fixed factor at
each step (about 1 - k2/k1 = 0.91 for the mean on the paper's track),
Newton's method with the AFT Jacobian of
`railtrack.harmonic_balance.residual_jacobian` converges quadratically for
smooth laws and superlinearly for the kinked bilinear law, where the
Jacobian is a generalised one.  A backtracking line search on the residual
norm keeps it robust far from the solution.
"""

from __future__ import annotations

import numpy as np

from .fixed_point import SolverOutcome
from .harmonic_balance import (
    HarmonicSystem,
    from_real,
    residual,
    residual_jacobian,
    residual_norm,
    to_real,
)

__all__ = ["linear_guess", "iterate_newton"]


def linear_guess(system: HarmonicSystem) -> np.ndarray:
    """Eq. (23) with the foundation's `linearization()`: the starting point.

    Returns zeros if the linearised problem is singular (a law with no
    stiffness at rest, for instance).
    """
    stiffness, damping = system.foundation.linearization()
    foundation = (stiffness + 1j * system.omega * damping) / system.sleeper_mass
    denominator = system.operator + foundation
    if not np.all(np.isfinite(denominator)) or np.any(np.abs(denominator) == 0):
        return np.zeros(system.harmonics + 1, dtype=complex)
    guess = -system.load / denominator
    guess[0] = guess[0].real
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
            message = f"Newton step failed at iteration {steps}: non-finite Jacobian"
            break
        try:
            step = from_real(np.linalg.solve(jacobian, -to_real(current)))
        except np.linalg.LinAlgError:
            # A singular Jacobian happens for instance at w = 0 on a tensionless
            # law, where the mean has no stiffness; the least-squares step still
            # points downhill for the residual norm.
            step = from_real(np.linalg.lstsq(jacobian, -to_real(current), rcond=None)[0])
        step[0] = step[0].real
        # Backtracking: halve the step until the residual decreases.
        for _ in range(30):
            trial = c + step
            trial_residual = residual(system, trial)
            trial_norm = residual_norm(system, trial_residual)
            if trial_norm < norm:
                break
            step *= 0.5
        else:
            message = f"line search found no decrease at iteration {steps}"
            break
        c, current, norm = trial, trial_residual, trial_norm
        history.append(norm)
        harmonic_residuals.append(np.abs(current))
        converged = norm <= tol
    if converged:
        message = f"relative residual {norm:.2e} <= tol {tol:.1e} after {steps} Newton steps"
    elif not message:
        message = (
            f"not converged: relative residual {norm:.2e} > tol {tol:.1e} "
            f"after {steps} Newton steps"
        )
    return SolverOutcome(
        c, bool(converged), steps, np.array(history), message, np.array(harmonic_residuals[-20:])
    )
