"""Floquet exponents continued from a neighbouring solution by Newton's method.

Along a branch or a speed sweep, the multipliers of one point are close to
those of the next.  `continue_exponents` takes every exponent of a previous
result (`railtrack.floquet`), with its eigenvector, as the start of Newton's
method on Hill's matrix of the new solution (`polish`): a few bordered
solves per exponent, instead of a contour of 16-24 solves per Bloch phase
over the whole box.

What it can and cannot say.  A multiplier it finds outside the unit circle,
resolved and with a small residual, is an eigenpair of Hill's matrix as much
as the contour's are: "unstable" is proved.  "Stable" rests on continuity:
the exponents move continuously with the solution.  A full search found
every multiplier in its box, so those it did not find lay below
min_multiplier (or above the box, which the a-priori estimate rules out).
The `ceiling` bounds the multipliers not continued (those that entered the
box through its bottom): min_multiplier after a full search, then at each
continued point the last ceiling plus the largest move |Delta mu| of a
continued multiplier.  If the spectrum moves no faster than its continued
members, every multiplier not continued lies at |mu| <= ceiling; while that
is below the largest continued one the listed dominant multiplier is the
dominant one, and while it is below 1 the continued ones decide the
verdict; beyond either, the caller searches in full again.  An exponent
lost on the way (not converged, or onto another one: as a rule a complex
pair meeting on the real axis, whose two real multipliers then part fast)
ends the continuation too, and so does one that crossed the strip's edge
|Im lambda T| = pi (it belongs to the next phase of the family now).  All
are continued: on chapter 10's branch, near a fold, a multiplier rose from
under half the dominant |mu| to above it in one step.  So a continued
"stable" means: no multiplier outside the unit circle among those continued
from a full search that proved stability, and the spectrum moved too little
since for another to have reached it.  `Floquet.continued` marks it,
`Floquet.ceiling` holds the ceiling, and its message says so.
"""

from __future__ import annotations


import numpy as np

from ..equations.hill import hill_matrix_slope
from ..model.passage import Passage
from .contour import polish

__all__ = ["continue_exponents", "newton_parts"]

TRACK_RESIDUAL = 1e-6
"""Largest relative residual ||H p|| / ||H|| of a continued exponent (as `RESIDUAL_LIMIT`)."""


def continue_exponents(passage: Passage, toeplitz: np.ndarray, period: float,
                       start: np.ndarray, vectors: np.ndarray, phases: np.ndarray
                       ) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """Newton's method on Hill's matrix from the exponents of a neighbouring solution.

    Parameters
    ----------
    passage : Passage
        The new solution's track and train.
    toeplitz : ndarray, shape (2, 2m+1, 2m+1)
        Its K_{k-j} and C_{k-j} (`railtrack.equations.hill.tangent_toeplitz`).
    period : float
        Its period T = H / v [s].
    start : ndarray of complex, shape (r,)
        The exponents z = lambda T [-] of the neighbouring solution.
    vectors : ndarray of complex, shape (r, 2m+1)
        Their eigenvectors, on the new solution's harmonics.
    phases : ndarray of float, shape (r,)
        Their Bloch phases [rad].

    Returns
    -------
    values : ndarray of complex, shape (r,)
        The continued z [-].
    vectors : ndarray of complex, shape (r, 2m+1)
        Their eigenvectors, unit norm.
    kept : ndarray of bool, shape (r,)
        False for an exponent lost on the way (not converged, or converged
        onto another one): the caller then searches in full.
    move : float
        The largest |Delta mu| of a kept exponent [-].
    """
    matrix, slope = newton_parts(passage, toeplitz, period, phases)
    values, vectors, residuals = polish(matrix, start, vectors, slope)
    same_phase = np.abs(phases[:, None] - phases[None, :]) < 1e-9
    close = np.abs(np.exp(values[:, None]) - np.exp(values[None, :])) < 1e-7 * np.maximum(
        1.0, np.abs(np.exp(values[:, None])))
    kept = (residuals < TRACK_RESIDUAL) & ~np.any(np.triu(same_phase & close, 1), axis=0)
    # on mu, not on z: near the bottom of the box a multiplier moves far in log mu
    move = float(np.max(np.abs(np.exp(values) - np.exp(start))[kept], initial=0.0))
    return values, vectors, kept, move


def newton_parts(passage: Passage, toeplitz: np.ndarray, period: float, phases: np.ndarray):
    """`matrix(z, rows)` and `derivative(z, p, rows)` of Hill's matrix in z = lambda T for `polish`.

    Newton asks for both at the same z in each step: the derivative's
    diagonal is kept from the matrix's evaluation (`hill_matrix_slope`)
    instead of evaluating the rail's functions twice more.
    """
    kept: dict = {}

    def matrix(z, rows):
        values, slope = hill_matrix_slope(passage, toeplitz, z / period, phases[rows])
        kept.update(z=z, rows=rows, slope=slope)
        return values

    def derivative(z, p, rows):
        if kept.get("z") is not z or kept.get("rows") is not rows:
            matrix(z, rows)
        return (kept["slope"] * p + p @ toeplitz[1].T) / period
    return matrix, derivative
