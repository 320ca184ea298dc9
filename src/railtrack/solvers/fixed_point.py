"""The paper's iteration, eq. (21), its convergence factors and the split N0.

Starting from c_{n1} = 0, each step solves eq. (17) for c_n, using the
previous iterate in every term but one:

    |n| <= N0:  c_{n,k+1} = [(omega_n^2 + P_n) c_nk - F_n - G_nk] / (omega_0^2 + i beta omega_n)
    |n| >  N0:  c_{n,k+1} = [(omega_0^2 + i beta omega_n) c_nk + F_n + G_nk] / (omega_n^2 + P_n)

with G_nk the AFT harmonics of g(w_mk, w'_mk) (eq. 20).  The printed eq. (21)
writes a calligraphic F_n where the load F_n of eq. (16) is meant.

For a linear law f = k w + eta w' the error of harmonic n is multiplied at
every step by the factor of Section 4.1 (`contraction_factors`); the
iteration converges if and only if every factor is below one.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.harmonic_balance import (
    HarmonicSystem,
    NonFiniteForceError,
    nonlinear_coefficients,
    residual_norm,
    synthesize,
)

__all__ = [
    "SolverOutcome",
    "contraction_factors",
    "automatic_split",
    "iterate_fixed_point",
    "DIVERGENCE_FACTOR",
]

DIVERGENCE_FACTOR = 1e6
"""The iteration is stopped as diverged once its residual exceeds this many times its smallest."""


class SolverOutcome(NamedTuple):
    """What a solver hands back to `railtrack.solve`."""

    coefficients: np.ndarray  # c_0..c_m [m]
    converged: bool
    iterations: int
    residual_history: np.ndarray  # relative residual of each iterate, the start included
    message: str
    harmonic_residuals: np.ndarray  # |R_n| of the last few iterates, shape (k, m+1)


def contraction_factors(
    system: HarmonicSystem, split: int, coefficients: np.ndarray | None = None
) -> np.ndarray:
    """Factor by which eq. (21) multiplies the error of each harmonic, n = 0..m.

    Exact for a linear law (Section 4.1):

        |n| <= N0:  |omega_n^2 + P_n - K_n/M| / |omega_0^2 + i beta omega_n|
        |n| >  N0:  |omega_0^2 + i beta omega_n + K_n/M| / |omega_n^2 + P_n|

    with K_n = k + i omega_n eta.  For a nonlinear law the factors are an
    estimate: (k, eta) is the foundation's `linearization()`, or, if
    `coefficients` are given, its tangent averaged over one period of that
    response (closer to the rate observed near a solution).

    Parameters
    ----------
    system : HarmonicSystem
    split : int
        N0, between -1 and m; -1 puts every harmonic, the mean included, in
        the second branch.
    coefficients : ndarray, shape (m+1,), optional
        c_0..c_m of a response (e.g. a converged one) to average the tangent over.

    Returns
    -------
    ndarray, shape (m+1,)
    """
    if coefficients is None:
        stiffness, damping = system.foundation.linearization()
    else:
        w, v = synthesize(system, np.asarray(coefficients, dtype=complex))
        tangent = system.foundation.tangent(w, v)
        stiffness, damping = (float(np.mean(np.broadcast_to(x, w.shape))) for x in tangent)
    omega = system.omega
    foundation = (stiffness + 1j * omega * damping) / system.sleeper_mass
    pad = system.passage.pad_natural_frequency_squared + 1j * system.passage.pad_damping_rate * omega
    rail = omega**2 + system.coupling
    low = np.abs(rail - foundation) / np.abs(pad)
    with np.errstate(divide="ignore"):
        high = np.abs(pad + foundation) / np.abs(rail)
    return np.where(np.arange(system.harmonics + 1) <= split, low, high)


def automatic_split(system: HarmonicSystem, coefficients: np.ndarray | None = None) -> int:
    """The N0 in 0..m that minimises the largest contraction factor.

    With `coefficients`, the factors use the tangent averaged over that
    response (see `contraction_factors`), which matters for a strongly
    nonlinear law whose stiffness at rest says little about the solution.
    """
    worst = [contraction_factors(system, n0, coefficients).max() for n0 in range(system.harmonics + 1)]
    return int(np.argmin(worst))


def iterate_fixed_point(
    system: HarmonicSystem,
    split: int,
    max_iterations: int,
    tol: float,
    initial: np.ndarray | None = None,
) -> SolverOutcome:
    """Run eq. (21) from c = 0 (or `initial`) for at most `max_iterations` steps.

    Convergence is judged by the relative residual of eq. (17),
    ``||R(c_k)|| / ||F||``, never by the change between iterates: for a
    factor close to one the change is small while the error is large.

    Parameters
    ----------
    system : HarmonicSystem
    split : int
        N0 of eq. (21), 0 <= N0 <= m.
    max_iterations : int
        Number of updates k.
    tol : float
        Stop once the relative residual is <= tol (converged); ``tol = 0``
        runs all k steps, as in the paper's figures.
    initial : ndarray, optional
        c_0..c_m to start from; zero as in the paper by default.
    """
    m = system.harmonics
    low = np.arange(m + 1) <= split
    omega = system.omega
    pad = system.passage.pad_natural_frequency_squared + 1j * system.passage.pad_damping_rate * omega
    rail = omega**2 + system.coupling
    load = system.load
    c = np.zeros(m + 1, dtype=complex) if initial is None else np.array(initial, dtype=complex)
    history, harmonic_residuals = [], []
    converged, diverged, steps = False, "", 0
    for steps in range(max_iterations + 1):
        try:
            nonlinear = nonlinear_coefficients(system, c)
        except NonFiniteForceError as error:
            if steps == 0:
                raise  # the law fails at the start: the law's fault, not the iteration's
            diverged = f"the foundation law overflowed at w = {error.displacement:.3g} m"
            steps -= 1
            break
        current = system.operator * c + nonlinear + load
        norm = residual_norm(system, current)
        if not np.isfinite(norm) or norm > DIVERGENCE_FACTOR * min(history, default=np.inf):
            diverged = f"the relative residual grew to {norm:.3g}"
            history.append(norm)
            harmonic_residuals.append(np.abs(current))
            break
        history.append(norm)
        harmonic_residuals.append(np.abs(current))
        if norm <= tol:
            converged = True
            break
        if steps == max_iterations:
            break
        c = np.where(
            low,
            (rail * c - load - nonlinear) / pad,
            (pad * c + load + nonlinear) / rail,
        )
        c[0] = c[0].real  # w is real; guards against round-off in Im c_0
    if converged:
        message = f"relative residual {history[-1]:.2e} <= tol {tol:.1e} after {steps} iterations"
    elif diverged:
        best = int(np.argmin(history))
        message = (
            f"diverged: {diverged} by iteration {steps + 1}; the residual was smallest "
            f"({history[best]:.2e}) at iteration {best} and grew from then on"
        )
    else:
        message = f"relative residual {history[-1]:.2e} > tol {tol:.1e} after {steps} iterations"
    return SolverOutcome(
        c, converged, steps, np.array(history), message, np.array(harmonic_residuals[-20:])
    )
