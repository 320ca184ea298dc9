"""Stability of a periodic solution from its Floquet multipliers (Hill's method).

A disturbance of the periodic solution grows or dies by the factor
mu = e^{lambda T} per period T = H/v, where lambda is a Floquet exponent:
a zero of det H(lambda; theta), Hill's matrix of
`railtrack.equations.hill`, for some Bloch phase theta per sleeper.  The
solution is stable when every multiplier lies inside the unit circle.

Which exponents to keep.  The shift lambda -> lambda + i Omega of an
exponent (Omega = 2 pi v / H) is the same disturbance with its Bloch phase
shifted by 2 pi L / H.  So the disturbances that repeat every wagon along
the track (the only ones a ring one wagon long carries) are the exponents
with |Im lambda| <= Omega / 2 of the N_s = H/L phases 2 pi j / N_s
(`bloch_phases`), and each appears there once; the textbook rule "keep
|Im lambda| <= Omega / 2" applied at theta = 0 alone would lose all but one
N_s-th of them.  Longer disturbances are the phases theta + 2 pi j / N_s
with 0 < theta <= pi / N_s (``theta="scan"``).

For each phase the exponents in the box ``min_multiplier <= |mu| <=
max_multiplier``, |Im lambda T| <= pi are found by Beyn's contour method and
refined by Newton (`railtrack.solvers.contour`).  Truncation to m harmonics
makes spurious exponents whose eigenvectors sit on the highest harmonics;
each exponent reports the share of its eigenvector on the top fifth of the
harmonics, and those above `TAIL_LIMIT` are "unresolved" and never decide
the verdict.

The verdict is "unstable" when a resolved multiplier lies outside the unit
circle, "stable" only when none does and the search could not have missed
one (its box reaches above the a-priori estimate of |mu|, its contour has
points enough, every phase was searched), and "unknown" otherwise
(`railtrack.solvers.floquet_verdict`).

Along a branch or a sweep, ``guess=`` the previous point's result continues
its exponents by Newton's method instead of searching the box again
(`railtrack.solvers.floquet_track`, which says what its verdicts mean).
"""

from __future__ import annotations

import numbers

import numpy as np

from ..equations.aft_jacobian import tangent_harmonics
from ..equations.harmonic_balance import harmonic_system
from ..equations.hill import bloch_phases, hill_matrix, tangent_toeplitz
from .contour import contour_eigenpairs, polish
from .floquet_assembly import TAIL_LIMIT, _distinct, floquet_result
from .floquet_guess import EDGE, continued_exponents, mirrored_family, with_mirror
from .floquet_track import newton_parts
from .threads import blas_threads
from .floquet_verdict import MIN_POINTS, Floquet
from .solution import Solution

__all__ = ["Floquet", "floquet", "floquet_result", "TAIL_LIMIT"]
MEMORY_BYTES = 256 * 2**20
"""Most memory one stack of Hill's matrices may take (phases are solved in groups) [bytes]."""
RESIDUAL_LIMIT = 1e-6
"""Largest relative residual ||H p|| / ||H|| of an exponent after Newton's refinement."""


def _base_phases(theta, sleepers: int) -> np.ndarray:
    if theta is None:
        return np.zeros(1)
    if isinstance(theta, str):
        if theta != "scan":
            raise ValueError(f"theta must be None, a phase [rad], an array of them or 'scan'; "
                             f"got {theta!r}")
        return np.linspace(0.0, np.pi / sleepers, 9)
    values = np.atleast_1d(np.asarray(theta))
    if values.dtype.kind not in "iuf" or values.ndim != 1 or values.size == 0 \
            or not np.all(np.isfinite(values)):
        raise ValueError(f"theta must be a finite phase [rad] or a 1-D array of them; got {theta!r}")
    return values.astype(float)


def floquet(solution: Solution, theta=None, *, harmonics: int | None = None,
            min_multiplier: float = 1e-2, max_multiplier: float = 1e6,
            points: int = 24, shifts: bool = True, guess: Floquet | None = None) -> Floquet:
    """The Floquet multipliers of a periodic solution and its stability, by Hill's method.

    Parameters
    ----------
    solution : Solution or CellSolution
        A converged solution; H / L must be an integer.  For a `CellSolution`
        the multipliers come from Hill's matrix of the cell and its phases
        are per cell (`railtrack.solvers.cell_floquet`).
    theta : None, float, array_like or "scan"
        Bloch phase per sleeper of the disturbances [rad].  None: those that
        repeat every wagon (phase 0 and its N_s shifts), which a ring one
        wagon long carries.  A value or an array: each with its shifts
        (a ring of n wagons carries 2 pi j / (n N_s), j = 0..n-1).  "scan":
        nine phases over [0, pi / N_s], which with their shifts sample every
        wavelength.
    harmonics : int, optional
        m of Hill's matrix, at least the solution's (default).  The
        exponents of a given orbit converge more slowly in m than the orbit
        does: on the fold track at 525 m/s, m = 25 puts the dominant |mu| of
        the m = 25 orbit 3e-3 from its limit, m = 35 within 2e-5.
    min_multiplier, max_multiplier : float
        The multipliers looked for: min <= |mu| <= max [-].  A multiplier
        above the box is not looked for: the verdict is "stable" only if
        max_multiplier reaches twice above the a-priori estimate of |mu| of the
        orbit (`railtrack.solvers.floquet_verdict.growth_bound`, 4.6 on the
        fold track at 600 m/s), else "unknown" when nothing unstable is found.
    points : int
        Quadrature points of the contour per phase (>= 1).  Too few miss
        multipliers inside the box: fewer than 16 never prove stability.
    shifts : bool
        False keeps each base phase alone, without its N_s - 1 shifts: a
        quick look (about a sixteenth of the cost at theta = 0) that sees
        only the disturbances whose exponent lies in that one phase's strip,
        so that it finds "unstable" or "unknown", never "stable"; `solve`
        uses it to warn.
    guess : Floquet, optional
        The result of `floquet` for a neighbouring solution (the next point
        of a branch or a sweep, or the same orbit at fewer harmonics), with
        the same `theta` and box.  Its exponents are continued by Newton's
        method instead of searched for, a few bordered solves per exponent
        (`railtrack.solvers.floquet_track` says when that is trusted and
        what its "stable" means: `Floquet.continued` is then True); where it
        cannot be trusted the box is searched as without a guess.

    Returns
    -------
    Floquet
        With `Floquet.verdict` "stable", "unstable" (a resolved multiplier
        outside the unit circle) or "unknown" (none found, but the search
        could have missed one; `Floquet.message` says how), and
        `Floquet.stable` True, False or None accordingly.

    Raises
    ------
    TypeError
        If `solution` is not a `Solution` (e.g. a `Branch` or a `Sweep`: pass
        one of its points).
    ValueError
        If the solution did not converge, H / L is not an integer, or an
        argument is out of its range.

    Examples
    --------
    >>> import railtrack as rt
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper())
    >>> result = floquet(s)
    >>> result.stable, bool(abs(result.dominant) < 0.1)
    (True, True)
    """
    with blas_threads(1):
        if not isinstance(solution, Solution) and callable(getattr(solution, "solution", None)):
            name = type(solution).__name__
            raise TypeError(f"floquet takes one periodic solution; got a {name}, which holds many: "
                            f"pass {name.lower()}.solution(i) for one of them (rt.check_branch "
                            "judges every point of a Branch, sweep(..., stability='full') every "
                            "member of a sweep)")
        if isinstance(points, bool) or not isinstance(points, (int, np.integer)) or points < 1:
            raise ValueError(f"points must be an integer >= 1 (contour quadrature points; "
                             f"{MIN_POINTS} or more can prove stability); got {points!r}")
        if hasattr(solution, "wheel"):
            raise TypeError(
                "floquet does not compute the multipliers of a WheelSolution (the wheels' own motion "
                "is part of every disturbance); judge it with the time-domain ring instead: "
                "rt.simulate_time_domain(track, train, law, ..., wheel=...)")
        if callable(getattr(solution, "floquet", None)):
            # a CellSolution: Hill's matrix of its cell (railtrack.solvers.cell_floquet)
            return solution.floquet(theta, harmonics=harmonics, min_multiplier=min_multiplier,
                                    max_multiplier=max_multiplier, points=points, shifts=shifts)
        if not all(hasattr(solution, name) for name in ("converged", "passage", "coefficients")):
            raise TypeError("floquet takes a converged railtrack.Solution (from rt.solve); got "
                            f"{type(solution).__name__}")
        if not solution.converged:
            raise ValueError("the Floquet multipliers of an unconverged solution mean nothing: "
                             f"it did not converge ({solution.message})")
        if not all(isinstance(x, numbers.Real) and not isinstance(x, bool)
                   for x in (min_multiplier, max_multiplier)) \
                or not (0 < min_multiplier < 1 < max_multiplier < np.inf):
            raise ValueError("need 0 < min_multiplier < 1 < max_multiplier < inf; got "
                             f"{min_multiplier!r}, {max_multiplier!r}")
        passage = solution.passage
        m = solution.harmonics if harmonics is None else harmonics
        if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < solution.harmonics:
            raise ValueError(f"harmonics must be an integer >= the solution's {solution.harmonics}; "
                             f"got {harmonics!r}")
        sleepers = bloch_phases(passage).size
        bases = _base_phases(theta, sleepers)
        system = harmonic_system(passage, solution.foundation, int(m))
        coefficients = np.zeros(m + 1, dtype=complex)
        coefficients[: solution.harmonics + 1] = solution.coefficients[solution.harmonics:]
        toeplitz = tangent_toeplitz(*tangent_harmonics(system, coefficients))
        period = float(passage.wagon_length / passage.speed)
        low, high = np.log(min_multiplier), np.log(max_multiplier)
        center, semi_axes = 0.5 * (low + high), (0.55 * (high - low) + 0.5, 1.5 * np.pi)
        # A resolved exponent lives on |k| <= band (its tail above is under TAIL_LIMIT), so the
        # contours search Hill's matrix cut to that band, about half the cost; Newton then
        # refines every candidate with all 2m + 1 harmonics.
        band = m - max(1, (2 * m + 1) // 10)
        top = np.abs(np.arange(-m, m + 1)) > band
        search = toeplitz[:, m - band:m + band + 1, m - band:m + band + 1]
        if guess is not None:
            continued = continued_exponents(guess, passage, toeplitz, period, bases, (low, high), top)
            if continued is not None:
                return floquet_result(_distinct(continued[0]), bases, sleepers, m, period,
                                      min_multiplier, solution, max_multiplier=max_multiplier,
                                      points=points, shifts=shifts, guess=guess, ceiling=continued[1])
        candidates, found = [], []
        for base in bases:
            phases = bloch_phases(passage, base) if shifts else np.array([float(base)])
            # Conjugation maps the exponents of phase theta onto those of -theta: where the
            # family holds both, the phases above pi are the mirror images of those below.
            mirrored = mirrored_family(phases)
            solved = phases[phases <= np.pi + 1e-12] if mirrored else phases

            # Phases in groups whose stack of matrices stays under MEMORY_BYTES.
            size = 16 * points * search.shape[-1] ** 2 * 4   # the stack and its working copies
            group = max(1, int(MEMORY_BYTES // size))
            pairs = []
            for start in range(0, solved.size, group):
                def matrix(z, phase=solved[start:start + group, None]):
                    return hill_matrix(passage, search, np.asarray(z) / period, phase)
                pairs += contour_eigenpairs(matrix, center, semi_axes, points)
            for phase, (values, vectors) in zip(solved, pairs):
                near = (np.abs(values.imag) <= np.pi + 0.5) & (values.real >= low - 0.5) \
                    & (values.real <= high + 0.5)
                padded = np.zeros((2 * m + 1, vectors.shape[1]), dtype=complex)
                padded[m - band:m + band + 1] = vectors
                candidates += [(z, p, phase, base, mirrored) for z, p in zip(values[near],
                                                                             padded.T[near])]
        if candidates:
            z0, p0, phase, base, mirrored = (np.array(column) for column in zip(*candidates))

            # Newton on the candidates in groups, so that the bordered matrices stay under
            # MEMORY_BYTES; each candidate's iteration is its own, so grouping changes nothing.
            chunk = max(1, int(MEMORY_BYTES // (16 * 4 * (2 * m + 2) ** 2)))
            parts = []
            for start in range(0, z0.size, chunk):
                rows = np.arange(start, min(start + chunk, z0.size))
                matrix, slope = newton_parts(passage, toeplitz, period, phase[rows])
                parts.append(polish(matrix, z0[rows], p0[rows], slope))
            values, vectors, residuals = (np.concatenate(part) for part in zip(*parts))
            values, inside, tails = strip_roots(values, vectors, residuals, low, high, top)
            for i in np.flatnonzero(inside):
                found += with_mirror(values[i], phase[i], tails[i], base[i], vectors[i], mirrored[i])
        return floquet_result(_distinct(found), bases, sleepers, m, period, min_multiplier, solution,
                              max_multiplier=max_multiplier, points=points, shifts=shifts)


def strip_roots(values: np.ndarray, vectors: np.ndarray, residuals: np.ndarray, low: float,
                high: float, top) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Polished exponents z folded onto the strip, which of them to keep, their tails.

    Kept: inside the search box (low <= Re z <= high), resolved (residual
    below `RESIDUAL_LIMIT`) and on the strip |Im z| <= pi.  A real negative
    multiplier sits on the strip's edge, Im z = +-pi, where round-off decides
    the side: both edges are accepted and folded onto (-pi, pi].  The tail
    is each eigenvector's share in the rows `top` (the highest harmonics).
    """
    inside = (np.abs(values.imag) <= np.pi + EDGE) & (values.real >= low) \
        & (values.real <= high) & (residuals < RESIDUAL_LIMIT)
    folded = values.real + 1j * (np.pi - np.mod(np.pi - values.imag, 2 * np.pi))
    return folded, inside, np.sum(np.abs(vectors[:, top]) ** 2, axis=1)
