"""The truncation estimate of a cell: its neglected harmonics, solved in the Floquet modes.

The neglected harmonics n = m+1..8m of a cell are estimated as
`railtrack.solvers.truncation` does for one sleeper.  The foundation forces
evaluated on the truncated solution have harmonics above m (the excess
F^+_n); each law is linearised about its mean tangent (Kbar_j, Cbar_j over
the period), and the rail, pads and sleepers answer per harmonic,

    [K1_n + K2_n diag(M s^2 + Kbar + i omega_n Cbar)] c_n = g_n - K2_n F^+_n,

the cell's equations (`railtrack.equations.cell_harmonic_balance`) at n > m,
solved in the cell's Floquet modes with the few differing sleepers by
Woodbury's identity (`railtrack.equations.cell_blocks`): O(N log N) per
harmonic for a cell of identical sleepers but a few.  A sleeper on a
`LinearFoundation` has no excess and a constant tangent: its law is not
sampled.  The error is the largest, over the sleepers, of the tail's max norm
over the period relative to the largest sleeper peak in the cell, for the
sleepers' displacement and for the rail-seat load (the pad's force, whose
tail is ``(-M omega_n^2 + Kbar + i omega_n Cbar) c_n + F^+_n``), whichever is
larger: the load converges more slowly.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from ..equations.cell_blocks import solve_blocks
from ..equations.cell_harmonic_balance import _forces, _synthesize, cell_operators
from ..model.foundations import LinearFoundation
from .cell_solution import CellSolution
from .truncation import _grid, auto_samples, grown_harmonics

__all__ = ["cell_truncation", "cell_truncation_errors", "cell_grown_harmonics", "estimate"]

CHUNK_ENTRIES = 1_000_000
"""Entries per group of harmonics in the tail estimate (16 MB a complex array)."""


def _excess(cell, c: np.ndarray, omega: np.ndarray, samples: int, top: int):
    """F^+_{j, m+1..top} (N, top - m) [N] and each law's mean tangent Kbar, Cbar (N,).

    Only laws that are not a scalar `LinearFoundation` are sampled: a linear
    law's force has no harmonic above m and its tangent is its (k, eta).
    """
    m = omega.size - 1
    n = c.shape[0]
    excess = np.zeros((n, top - m), dtype=complex)
    stiffness, damping = np.empty(n), np.empty(n)
    bent = []
    for j, law in enumerate(cell.foundations):
        if isinstance(law, LinearFoundation) and np.ndim(law.stiffness) == 0 \
                and np.ndim(law.damping) == 0:
            stiffness[j], damping[j] = law.linearization()
        else:
            bent.append(j)
    if bent:
        some = SimpleNamespace(foundations=[cell.foundations[j] for j in bent])
        w, v = _synthesize(c[bent], omega, samples)
        spectrum = np.fft.rfft(_forces(some, w, v), axis=-1) / samples
        excess[bent] = spectrum[:, m + 1:top + 1]
        tangent = _forces(some, w, v, tangent=True)
        stiffness[bent], damping[bent] = tangent[0].mean(axis=-1), tangent[1].mean(axis=-1)
    return excess, stiffness, damping


def cell_truncation(solution: CellSolution) -> tuple[float, np.ndarray]:
    """Estimated truncation error [-] and tail c_{j, m+1..8m} (N, 7m) [m] (module docstring).

    The error is the larger of the sleepers' displacement's and the rail-seat
    load's (`cell_truncation_errors`): the load converges more slowly.
    """
    errors, tail, _ = cell_truncation_errors(solution)
    return max(errors.values()), tail


def cell_truncation_errors(solution: CellSolution) -> tuple[dict[str, float], np.ndarray,
                                                              np.ndarray]:
    """Each output's estimated truncation error [-], and the tails of c and p (N, 7m) [m], [N].

    The tail of the seat force is ``p_n = (-M omega_n^2 + Kbar + i omega_n Cbar) c_n + F^+_n``
    (the law linearised as in the module docstring): the pad passes to the
    sleeper what its inertia and foundation take.  Where a law kinks (a
    sleeper landing on its ballast) the sleeper's acceleration jumps, and the
    pad's force has harmonics falling like 1/n^2 where the displacement's
    fall like 1/n^4: at 300 m/s on a hanging sleeper an m that puts w within
    8e-4 leaves the seat load 5 % of its peak off.

    Returns
    -------
    errors : dict
        ``{"sleeper_displacement", "rail_seat_load"}`` -> max over the cell
        and the period of the neglected part over the largest peak [-].
    tail, seat_tail : ndarray, shape (N, 7m)
        c_{j, m+1..8m} [m] and p_{j, m+1..8m} [N].
    """
    errors, tail, seat_tail, _ = estimate(solution)
    return errors, tail, seat_tail


def estimate(solution: CellSolution):
    """`cell_truncation_errors` and each sleeper's peaks of c and p with their tails (N,) each.

    The peaks are those `cell_grown_harmonics` needs (the same grid): passed
    on, they are not synthesised twice.
    """
    passage, cell, m = solution.passage, solution.cell, solution.harmonics
    top = 8 * m
    samples = auto_samples(top)
    c = solution.coefficients[:, m:]
    omega = passage.fundamental_frequency * np.arange(m + 1)
    excess, stiffness, damping = _excess(cell, c, omega, samples, top)          # (N, 7m)
    high = passage.fundamental_frequency * np.arange(m + 1, top + 1)
    tail = np.empty((c.shape[0], high.size), dtype=complex)
    seat_tail = np.empty_like(tail)
    # harmonics in groups of about CHUNK_ENTRIES entries of (harmonic, sleeper) arrays:
    # memory stays bounded (`solve_blocks` groups its own matrices)
    step = max(1, CHUNK_ENTRIES // c.shape[0])
    for start in range(0, high.size, step):
        part = slice(start, start + step)
        ops = cell_operators(passage, cell.pad_stiffness, cell.pad_damping, high[part])
        support = (-cell.sleeper_mass * high[part, None] ** 2 + stiffness
                   + 1j * high[part, None] * damping)
        rhs = ops.load - ops.apply(np.zeros_like(ops.load), excess[:, part].T)
        tail[:, part] = solve_blocks(ops, support, rhs).T
        seat_tail[:, part] = support.T * tail[:, part] + excess[:, part]
    displacement, peaks = _tail_share(c, tail, samples)
    seat, seat_peaks = _tail_share(solution.seat_harmonics[:, m:], seat_tail, samples)
    errors = {"sleeper_displacement": displacement, "rail_seat_load": seat}
    return errors, tail, seat_tail, (peaks, seat_peaks)


def _tail_share(kept: np.ndarray, tail: np.ndarray, samples: int) -> tuple[float, np.ndarray]:
    """max |sum of the tail| over max |kept + tail|, over every sleeper and the period,
    and each sleeper's peak max_t |kept + tail| (N,).

    The tail's max norm is synthesised sleeper by sleeper in decreasing order
    of its bound ``2 sum_n |tail_n|``, until that bound is below the largest
    found: the same maximum, for the few sleepers whose tail matters.
    """
    m = kept.shape[1] - 1
    grid = np.zeros((kept.shape[0], samples // 2 + 1), dtype=complex)
    grid[:, :m + 1] = kept * samples
    grid[:, m + 1:m + 1 + tail.shape[1]] = tail * samples
    peaks = np.max(np.abs(np.fft.irfft(grid, samples, axis=-1)), axis=-1)
    bound = 2.0 * np.sum(np.abs(tail), axis=1)
    error = 0.0
    for j in np.argsort(-bound):
        if bound[j] <= error:
            break
        row = np.zeros(samples // 2 + 1, dtype=complex)
        row[m + 1:m + 1 + tail.shape[1]] = tail[j] * samples
        error = max(error, float(np.max(np.abs(np.fft.irfft(row, samples)))))
    peak = float(peaks.max())
    return (error / peak if peak > 0 else float("inf")), peaks


def cell_grown_harmonics(solution: CellSolution, tail: np.ndarray, seat_tail: np.ndarray,
                         accuracy: float, peaks=None) -> int:
    """The m that both the sleepers' displacement and the seat force need for `accuracy`.

    Per sleeper j and output, `grown_harmonics` of its spectrum and tail, with
    the budget ``accuracy`` times the largest peak of that output in the cell
    (as `cell_truncation_errors` measures): a sleeper that carries little
    needs no more than the cell's error allows.  `peaks`, the per-sleeper
    peaks of c and p that `estimate` returns, spares synthesising them again.
    """
    m = solution.harmonics
    chosen = 1
    for k, (kept, rest) in enumerate(((solution.coefficients[:, m:], tail),
                                      (solution.seat_harmonics[:, m:], seat_tail))):
        spectrum = np.concatenate([kept, rest], axis=1)
        if peaks is None:
            samples = auto_samples(spectrum.shape[1])
            grid = np.zeros((spectrum.shape[0], samples // 2 + 1), dtype=complex)
            grid[:, :spectrum.shape[1]] = spectrum * samples
            peak = np.max(np.abs(np.fft.irfft(grid, samples, axis=-1)), axis=-1)
        else:
            peak = peaks[k]
        share = np.minimum(accuracy * peak.max() / np.where(peak > 0, peak, np.inf), 0.5)
        high = _first_fitting_bound(spectrum, share)
        # sleepers in decreasing order of the bound on their answer: those whose
        # bound is below the m already chosen cannot raise it
        for j in np.argsort(-high, kind="stable"):
            if high[j] < chosen:
                break
            if peak[j] > 0:
                chosen = max(chosen, grown_harmonics(kept[j], rest[j], share[j]))
    return chosen


def _first_fitting_bound(spectrum: np.ndarray, share: np.ndarray) -> np.ndarray:
    """Per sleeper, an upper bound of `grown_harmonics` (N,): the first m whose neglected part's
    bound ``2 sum_{n > m} |c_n|`` is within ``share`` of the peak, as `grown_harmonics` starts."""
    samples = _grid(spectrum.shape[1] - 1) // 2
    grid = np.zeros((spectrum.shape[0], samples // 2 + 1), dtype=complex)
    count = min(spectrum.shape[1], samples // 2 + 1)
    grid[:, :count] = spectrum[:, :count]
    own = np.max(np.abs(np.fft.irfft(grid * samples, samples, axis=-1)), axis=-1)
    above = 2.0 * np.cumsum(np.abs(spectrum[:, ::-1]), axis=1)[:, ::-1]
    after = np.concatenate([above[:, 1:], np.zeros((spectrum.shape[0], 1))], axis=1)
    fits = after <= (share * own)[:, None]
    return np.where(fits.any(axis=1), np.argmax(fits, axis=1), spectrum.shape[1] - 1)
