"""The `Floquet` result of a set of exponents: sorted, its dominant multiplier, judged.

Shared by one sleeper (`railtrack.solvers.floquet`), a cell
(`railtrack.solvers.cell_floquet`) and the continuation from a neighbouring
solution (`railtrack.solvers.floquet_track`).
"""

from __future__ import annotations

import numpy as np

from .floquet_verdict import NEUTRAL, Floquet, growth_bound, neutral_note, search_verdict

__all__ = ["floquet_result", "TAIL_LIMIT"]

TAIL_LIMIT = 0.05
"""Largest share of an eigenvector's norm on the top fifth of the harmonics for a resolved exponent."""


def _kind(multiplier: complex, tol: float = 1e-6) -> tuple[str, float]:
    angle = abs(float(np.angle(multiplier)))
    if multiplier == 0:
        return "none", float("nan")
    if angle < tol:
        return "real +", 0.0
    if angle > np.pi - tol:
        return "real -", 0.5
    return "complex", angle / (2.0 * np.pi)


def floquet_result(found: list, bases: np.ndarray, count: int, m: int, period: float,
                   min_multiplier: float, solution, *, max_multiplier: float, points: int,
                   shifts: bool, per: str = "sleeper", guess: Floquet | None = None,
                   ceiling: float | None = None) -> Floquet:
    """The `Floquet` of the exponents `found` (z = lambda T, phase, tail, base[, vector]), judged.

    Shared by one sleeper (`floquet`, phases per sleeper) and a cell
    (`railtrack.solvers.cell_floquet`, ``per="cell"``): `count` phases of
    the family per base phase.  Eigenvectors, where `found` carries them,
    are kept (`Floquet.vectors`).  `guess`: the exponents were continued from
    that result (`railtrack.solvers.floquet_track`), not searched; a
    "stable" then needs `guess` "stable" too.
    """
    z = np.array([f[0] for f in found], dtype=complex)
    # By decreasing |mu|; a conjugate pair (equal |mu|) lists the member with the
    # smaller phase, then the one turning forward, first, whatever the round-off.
    found_phases = np.array([f[1] for f in found])
    order = np.lexsort((-z.imag, np.round(found_phases, 9), -np.round(z.real, 9)))
    z = z[order]
    phases = np.array([found[i][1] for i in order])
    tail = np.array([found[i][2] for i in order])
    resolved = tail <= TAIL_LIMIT
    multipliers = np.exp(z)
    dominant = complex(multipliers[resolved][0]) if resolved.any() else 0j
    kind, frequency = _kind(dominant)
    theta_dominant = float(phases[resolved][0]) if resolved.any() else float("nan")
    bases_of = np.array([found[i][3] for i in order])
    worst = float(bases_of[resolved][0]) if resolved.any() else float(bases[0])
    # the bound matters only where it could turn a "stable" into "unknown"
    bound = growth_bound(solution) if abs(dominant) <= 1 + NEUTRAL and shifts else float("nan")
    verdict, gaps = search_verdict(dominant, max_multiplier=max_multiplier, bound=bound,
                                   points=int(points), shifts=shifts)
    if guess is not None and verdict == "stable" and guess.verdict != "stable":
        verdict, gaps = "unknown", f"it was continued from a result that was {guess.verdict}"
    family = f"{bases.size} x {count} phases" + (" per cell" if per == "cell" else "")
    message = (f"{verdict}: largest multiplier |mu| = "
               f"{abs(dominant):.4g} ({kind}"
               + (f", frequency {frequency:.3g} v/H" if kind == "complex" else "")
               + f") at Bloch phase {theta_dominant:.3g} rad per {per}; {int(resolved.sum())} "
               f"resolved multipliers with |mu| >= {min_multiplier:g} over {family}, m = {m}"
               + neutral_note(dominant)
               + (f"; none outside the unit circle, but {gaps}" if gaps else "")
               + (f"; continued by Newton from a neighbouring solution's, the box not "
                  f"searched again: any others lie at |mu| <= {ceiling:.3g} if the spectrum "
                  "moved as these did (railtrack.solvers.floquet_track)"
                  if guess is not None else ""))
    vectors = np.array([found[i][4] for i in order]) if found and all(
        len(f) > 4 for f in found) else None
    return Floquet(multipliers, z / period, phases, tail, resolved, dominant, verdict == "stable",
                   kind, frequency, theta_dominant, bases, worst, period, m, message, verdict,
                   bound, vectors, guess is not None,
                   min_multiplier if ceiling is None else ceiling)


def _distinct(found: list) -> list:
    """Drop repeats: one multiplier found twice at one phase (z and z + 2 pi i at the edges)."""
    if not found:
        return []
    mu = np.exp(np.array([item[0] for item in found], dtype=complex))
    phase = np.array([item[1] for item in found], dtype=float)
    same = (np.abs(mu[:, None] - mu[None, :]) < 1e-7 * np.maximum(1.0, np.abs(mu))[:, None]) \
        & (np.abs(phase[:, None] - phase[None, :]) < 1e-9)
    kept: list = []
    for i in range(len(found)):
        # a repeat of one kept before it (the first of each group is kept)
        if not any(same[i, j] for j in kept):
            kept.append(i)
    return [found[i] for i in kept]
