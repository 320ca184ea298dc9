"""A neighbour's Floquet exponents continued to this solution (``floquet(..., guess=)``).

Along a branch or a sweep, the exponents of the previous point are followed
by Newton's method (`railtrack.solvers.floquet_track`) instead of searching
the whole box again.  `continued_exponents` says when that cannot be
trusted (an exponent lost, one across the strip's edge, the ceiling of the
ones not followed too close to the dominant one): then `floquet` searches
in full.  `with_mirror` and `mirrored_family` give the conjugate exponents
of a family of Bloch phases that holds -theta for each theta.
"""

from __future__ import annotations

import numpy as np

from ..equations.hill import bloch_phases
from .floquet_assembly import TAIL_LIMIT
from .floquet_track import continue_exponents
from .floquet_verdict import NEUTRAL, Floquet

__all__ = ["EDGE", "NEAR_DOUBLE", "continued_exponents", "mirrored_family", "with_mirror"]

EDGE = 1e-6
"""Tolerance on |Im lambda T| <= pi at the edges of the strip [rad]."""
NEAR_DOUBLE = 1e-3
"""Two multipliers of one phase closer than this (times max(1, |mu|)) at a guess are a near-double
pair: continuing both may land both on one (`continued_exponents`) [-]."""


def with_mirror(z, phase, tail, base, vector, mirrored) -> list:
    """The exponent, and where the family holds -phase, its conjugate there.

    H(conj z; -theta) is the conjugate of H(z; theta) with the harmonics
    reversed, so the mirror's eigenvector is conj(p_{-k}).
    """
    found = [(z, phase, tail, base, vector)]
    if mirrored and 1e-12 < phase < np.pi - 1e-12:
        found.append((np.conj(z), 2 * np.pi - phase, tail, base, np.conj(vector[::-1])))
    return found


def continued_exponents(guess: Floquet, passage, toeplitz: np.ndarray, period: float, bases: np.ndarray,
               box: tuple[float, float], top: np.ndarray) -> tuple[list, float] | None:
    """The exponents of `guess` continued to this solution and their ceiling, or None.

    `railtrack.solvers.floquet_track`; None where that cannot be trusted.
    """
    if not isinstance(guess, Floquet) or guess.vectors is None:
        raise TypeError("guess must be a Floquet from rt.floquet of a neighbouring Solution (with "
                        f"its eigenvectors); got {type(guess).__name__}")
    if guess.base_phases.shape != bases.shape or not np.allclose(guess.base_phases, bases):
        raise ValueError(f"guess was computed for the base phases {guess.base_phases!r}, this "
                         f"search asks for {bases!r}: pass the same theta")
    n, count = toeplitz.shape[-1], guess.vectors.shape[1]
    m, m_guess = (n - 1) // 2, (count - 1) // 2
    vectors = np.zeros((guess.vectors.shape[0], n), dtype=complex)
    cut = min(m, m_guess)
    vectors[:, m - cut:m + cut + 1] = guess.vectors[:, m_guess - cut:m_guess + cut + 1]
    # each exponent's base phase and whether its family is mirrored (then only the
    # phases up to pi are continued; the others are their conjugates).  All are
    # continued: one left out may rise fast (near a fold, on chapter 10's branch, from
    # under half the dominant |mu| to above it in one step).
    families = [(base, bloch_phases(passage, base)) for base in bases]
    families = [(base, family, mirrored_family(family)) for base, family in families]
    keep, base_of, mirror_of = [], [], []
    for i, phase in enumerate(guess.phases):
        for base, family, mirrored in families:
            if np.min(np.abs(np.mod(phase - family + np.pi, 2 * np.pi) - np.pi)) < 1e-9:
                if not mirrored or phase <= np.pi + 1e-12:
                    keep.append(i), base_of.append(base), mirror_of.append(mirrored)
                break
    keep = np.array(keep, dtype=int)
    if keep.size == 0:
        return None
    values, vectors, kept, move = continue_exponents(
        passage, toeplitz, period, guess.exponents[keep] * guess.period, vectors[keep],
        guess.phases[keep])
    # One lost on the way (not converged, or two onto one) is as a rule a pair meeting
    # on the real axis, whose two real multipliers then part fast: search in full.
    # Only the twin of a near-double pair off the real axis (1e-3 apart already at the
    # guess, as on chapter 10's branch at 575 m/s) stays with its twin, under the ceiling.
    start = np.exp(guess.exponents[keep] * guess.period)
    phases = guess.phases[keep]
    for j in np.flatnonzero(~kept):
        near = NEAR_DOUBLE * max(1.0, abs(start[j]))
        twins = kept & (np.abs(phases - phases[j]) < 1e-9) & (np.abs(start - start[j]) < near)
        # near the real axis the twin is the conjugate, about to meet it there
        if not twins.any() or abs(start[j].imag) < near:
            return None
    ceiling = max(guess.ceiling, float(np.max(np.abs(start[~kept]), initial=0.0))) + move
    low, high = box
    # One that crossed the strip's edge, |Im z| = pi, is a disturbance of the next phase
    # of the family now, where its own exponent lies inside the strip: search in full.
    if np.any(np.abs(values.imag) > np.pi + EDGE):
        return None
    tails = np.sum(np.abs(vectors[:, top]) ** 2, axis=1)
    # The ceiling bounds the multipliers not continued; it matters only for a "stable":
    # a resolved multiplier found outside proves "unstable" whatever the others do.
    outside = np.any(kept & (tails <= TAIL_LIMIT) & (values.real > np.log1p(NEUTRAL)))
    # the dominant multiplier must be among those continued: none not continued may
    # reach it (a pair colliding on the real axis loses one, whose partner then leads)
    top_listed = np.max(np.abs(np.exp(values[kept & (tails <= TAIL_LIMIT)])), initial=0.0)
    if np.any(values.real > high) or (ceiling >= 1.0 and not outside) or ceiling >= top_listed:
        return None
    found: list = []
    for i in np.flatnonzero(kept & (values.real >= low)):   # below: left through the bottom
        found += with_mirror(values[i], guess.phases[keep[i]], tails[i], base_of[i],
                              vectors[i], mirror_of[i])
    return found, ceiling


def mirrored_family(phases: np.ndarray) -> bool:
    """Whether the family of phases holds -theta for each theta (conjugate exponents)."""
    return bool(np.all(np.min(np.abs(np.mod(-phases[:, None] - phases[None, :] + np.pi,
                                              2 * np.pi) - np.pi), axis=1) < 1e-9))
