"""Floquet multipliers of a cell's periodic solution, by Hill's matrix of the cell.

As `railtrack.solvers.floquet` does for one sleeper, with Hill's matrix of
the cell (`railtrack.equations.cell_hill`): the exponents of each Bloch phase
theta per cell in the box ``min_multiplier <= |mu| <= max_multiplier``,
|Im lambda T| <= pi, by Beyn's contour method on the harmonics up to a band,
refined by Newton on all of them; those whose eigenvector has more than
`TAIL_LIMIT` of its norm on the top fifth of the harmonics are unresolved.
The phases that one matrix stands for are theta + 2 pi j / b, b = N_s /
gcd(N, N_s) (`cell_bloch_phases`): the disturbances that repeat every
lcm(N, N_s) sleepers, which a ring of that length carries.

The contour is summed one quadrature point at a time, so that a cell of 30
sleepers (matrices of N (2m+1) rows) stays within `MEMORY_BYTES`.  A cell of
identical sleepers (equal laws, one mass and pad) whose solution is the
travelling wave (`travelling_wave`) is today's track; its Hill matrix splits
into N matrices of one sleeper at the phases
(theta + 2 pi r) / N per sleeper, and it is solved so, at the cost of
`railtrack.floquet` on one sleeper (``reduce=False`` keeps the cell's matrix).
"""

from __future__ import annotations

import numpy as np

from ..equations.cell_harmonic_balance import _forces, _synthesize
from ..equations.cell_hill import (cell_bloch_phases, cell_hill_derivative, cell_hill_matrix,
                                   cell_tangent_toeplitz)
from ..equations.harmonic_balance import default_samples
from ..model.cell import SleeperCell
from .contour import RANK_TOLERANCE, polish
from .floquet import MEMORY_BYTES, Floquet, _base_phases, _distinct, floquet_result, strip_roots

__all__ = ["cell_floquet", "uniform_cell", "travelling_wave", "cell_tangent"]


def uniform_cell(cell) -> bool:
    """True if every sleeper of `cell` has the same (or an equal) law, mass and pad."""
    first = cell.foundations[0]
    return (all(law is first or _equal(law, first) for law in cell.foundations)
            and all(np.all(x == x[0]) for x in (cell.sleeper_mass, cell.pad_stiffness,
                                                cell.pad_damping)))


def _equal(law, other) -> bool:
    try:
        return type(law) is type(other) and bool(law == other)
    except (TypeError, ValueError):   # a law with array fields: not compared
        return False


def travelling_wave(solution, tol: float = 1e-6) -> bool:
    """True if sleeper j of the cell moves as sleeper 0 delayed by j L / v (within `tol` of the peak).

    A cell of identical sleepers may also hold solutions that differ from
    sleeper to sleeper (a pattern N sleepers long); only the travelling wave
    is the one-sleeper track's solution.
    """
    c, m = solution.coefficients, solution.harmonics
    omega = solution.passage.fundamental_frequency * np.arange(-m, m + 1)
    delay = np.arange(solution.sleepers)[:, None] * solution.passage.sleeper_spacing \
        / solution.passage.speed
    shifted = c[0] * np.exp(-1j * omega * delay)
    return bool(np.abs(c - shifted).sum(axis=1).max() <= tol * np.abs(c).sum(axis=1).max())


def cell_tangent(solution, m: int) -> np.ndarray:
    """Each sleeper's K_{k-j}, C_{k-j} along the cell's orbit, k, j = -m..m (2, N, 2m+1, 2m+1)."""
    samples = default_samples(2 * m)
    c = np.zeros((solution.sleepers, m + 1), dtype=complex)
    c[:, :solution.harmonics + 1] = solution.coefficients[:, solution.harmonics:]
    omega = solution.passage.fundamental_frequency * np.arange(m + 1)
    w, v = _synthesize(c, omega, samples)
    sampled = _forces(solution.cell, w, v, tangent=True)
    spectrum = np.fft.rfft(sampled, axis=-1)[..., :2 * m + 1] / samples
    full = np.concatenate([np.conj(spectrum[..., :0:-1]), spectrum], axis=-1)
    return cell_tangent_toeplitz(full[0], full[1])


def _contour(matrix, count: int, center: float, semi_axes, points: int, size: int,
             columns: int = 8, seed: int = 0):
    """Beyn's moments summed point by point (`railtrack.solvers.contour.contour_eigenpairs`).

    ``matrix(z, rows)`` gives the matrices of the phases `rows` at the point z.
    """
    angle = 2.0 * np.pi * np.arange(points) / points
    z = center + semi_axes[0] * np.cos(angle) + 1j * semi_axes[1] * np.sin(angle)
    weights = (-semi_axes[0] * np.sin(angle) + 1j * semi_axes[1] * np.cos(angle)) / (1j * points)
    rng = np.random.default_rng(seed)
    columns = min(columns, size)
    group = max(1, int(MEMORY_BYTES // (16 * 3 * size**2)))
    while True:
        probe = rng.standard_normal((size, columns)) + 1j * rng.standard_normal((size, columns))
        first = np.zeros((count, size, columns), dtype=complex)
        second = np.zeros_like(first)
        scale = np.zeros(count)
        for start in range(0, count, group):
            rows = np.arange(start, min(start + group, count))
            for zi, wi in zip(z, weights):
                solved = np.linalg.solve(matrix(zi, rows), np.broadcast_to(
                    probe, (rows.size, size, columns)))
                first[rows] += wi * solved
                second[rows] += wi * zi * solved
                scale[rows] = np.maximum(scale[rows], np.max(np.abs(solved), axis=(1, 2)))
        u, sigma, wh = np.linalg.svd(first, full_matrices=False)
        ranks = np.sum(sigma > RANK_TOLERANCE * scale[:, None], axis=1)
        if np.all(ranks < columns) or columns == size:
            break
        columns = min(2 * columns, size)
    pairs = []
    for b, rank in enumerate(ranks):
        if rank == 0:
            pairs.append((np.empty(0, complex), np.empty((size, 0), complex)))
            continue
        left, right = u[b, :, :rank], wh[b, :rank].conj().T
        values, vectors = np.linalg.eig(left.conj().T @ second[b] @ right / sigma[b, :rank])
        pairs.append((values, left @ vectors))
    return pairs


def _reduced(solution):
    """Sleeper 0 of a uniform cell as a cell of one sleeper (its orbit is a travelling wave)."""
    cell = solution.cell
    one = SleeperCell(cell.sleeper_mass[:1], cell.pad_stiffness[:1], cell.pad_damping[:1],
                      cell.foundations[:1], cell.gravity)
    return _View(solution.passage, one, solution.coefficients[:1], solution.harmonics)


class _View:
    """The fields of a `CellSolution` that the multipliers need."""

    def __init__(self, passage, cell, coefficients, harmonics):
        self.passage, self.cell, self.coefficients = passage, cell, coefficients
        self.harmonics, self.sleepers = harmonics, coefficients.shape[0]


def cell_floquet(solution, theta=None, *, harmonics: int | None = None,
                 min_multiplier: float = 1e-2, max_multiplier: float = 1e6, points: int = 24,
                 shifts: bool = True, reduce: bool = True) -> Floquet:
    """The Floquet multipliers of a cell's periodic solution (`railtrack.floquet` of a `CellSolution`).

    Parameters
    ----------
    solution : CellSolution
        A converged solution of `railtrack.solve` with a `SleeperCell`; H / L
        must be an integer.
    theta : None, float, array_like or "scan"
        Bloch phase per cell [rad].  None: the phases that repeat every
        lcm(N, N_s) sleepers (phase 0 and its b shifts, `cell_bloch_phases`).
        A value or an array: each with its shifts.  "scan": nine phases over
        [0, 2 pi / b], which with their shifts sample every wavelength.
    harmonics, min_multiplier, max_multiplier, points, shifts
        As `railtrack.floquet`; ``shifts=False`` searches the one phase
        alone (the quick look of `railtrack.solve`).
    reduce : bool
        Solve a cell of identical sleepers as the one sleeper it repeats
        (module docstring); False keeps the cell's matrix (a check).

    Returns
    -------
    Floquet
        Phases (`phases`, `theta`, `base_phases`, `most_unstable`) are per
        cell, N L [rad].

    Raises
    ------
    ValueError
        If the solution did not converge, or H / L is not an integer.
    NotImplementedError
        For the sleepers of a `railtrack.WheelSolution`.
    """
    if getattr(solution, "rail_field_note", ""):
        raise NotImplementedError(
            "the Floquet multipliers of a WheelSolution's sleepers are not computed (the wheels' "
            "own motion is part of every disturbance); judge it with the time-domain ring "
            "instead: rt.simulate_time_domain(track, train, law, ..., wheel=...)")
    if not solution.converged:
        raise ValueError("the Floquet multipliers of an unconverged solution mean nothing: "
                         f"it did not converge ({solution.message})")
    if not (0 < min_multiplier < 1 < max_multiplier < np.inf):
        raise ValueError("need 0 < min_multiplier < 1 < max_multiplier < inf; got "
                         f"{min_multiplier!r}, {max_multiplier!r}")
    m = solution.harmonics if harmonics is None else harmonics
    if isinstance(m, bool) or not isinstance(m, (int, np.integer)) or m < solution.harmonics:
        raise ValueError(f"harmonics must be an integer >= the solution's {solution.harmonics}; "
                         f"got {harmonics!r}")
    passage, n = solution.passage, solution.sleepers
    b = cell_bloch_phases(passage, n).size
    bases = _base_phases(theta, b)
    view = _View(passage, solution.cell, solution.coefficients, solution.harmonics)
    if reduce and n > 1 and uniform_cell(solution.cell) and travelling_wave(solution):
        # phase theta per cell is the N phases (theta - 2 pi r) / N per sleeper of one
        # sleeper's matrix, with the same exponents; with its b shifts it is theta / N and
        # its shifts by 2 pi / lcm(N, N_s), which the one sleeper's shifts by 2 pi / N_s
        # reach from theta / N + 2 pi t / lcm, t < N / gcd(N, N_s)
        view, ratio = _reduced(solution), n
        per_wagon = cell_bloch_phases(passage, 1).size
        if shifts:
            steps = n // int(np.gcd(n, per_wagon))
            sleeper_bases = np.concatenate([base / n + 2.0 * np.pi * np.arange(steps)
                                            / (steps * per_wagon) for base in bases])
        else:
            sleeper_bases = np.concatenate([(base - 2.0 * np.pi * np.arange(n)) / n
                                            for base in bases])
        found = _search(view, sleeper_bases, int(m), min_multiplier, max_multiplier, points,
                        shifts)
        found = [(z, np.mod(ratio * phase, 2.0 * np.pi), tail, base)
                 for z, phase, tail, base in found]
        found = [(z, phase, tail, _nearest(bases, phase, b)) for z, phase, tail, _ in found]
    else:
        found = _search(view, bases, int(m), min_multiplier, max_multiplier, points, shifts)
    return floquet_result(_distinct(found), bases, b, int(m),
                          float(passage.wagon_length / passage.speed), min_multiplier, solution,
                          max_multiplier=max_multiplier, points=points, shifts=shifts, per="cell")


def _nearest(bases: np.ndarray, phase: float, b: int) -> float:
    """The base phase whose shifts by 2 pi / b hold `phase`."""
    gap = np.abs(np.mod(phase - bases + np.pi / b, 2.0 * np.pi / b) - np.pi / b)
    return float(bases[np.argmin(gap)])


def _search(view, bases, m, min_multiplier, max_multiplier, points, shifts) -> list:
    """(z = lambda T, phase, tail, base) of every exponent found in the box."""
    passage, cell, n = view.passage, view.cell, view.sleepers
    toeplitz = cell_tangent(view, m)
    period = float(passage.wagon_length / passage.speed)
    low, high = np.log(min_multiplier), np.log(max_multiplier)
    center, semi_axes = 0.5 * (low + high), (0.55 * (high - low) + 0.5, 1.5 * np.pi)
    band = m - max(1, (2 * m + 1) // 10)
    top = np.repeat(np.abs(np.arange(-m, m + 1)) > band, n)
    search = toeplitz[..., m - band:m + band + 1, m - band:m + band + 1]
    candidates = []
    # each base with its shifts, or (shifts=False) all the bases alone as one group
    groups = [(cell_bloch_phases(passage, n, base), np.full(cell_bloch_phases(
        passage, n).size, float(base))) for base in bases] if shifts \
        else [(np.mod(bases, 2.0 * np.pi), np.asarray(bases, dtype=float))]
    for phases, labels in groups:
        # conjugation maps the exponents of phase theta onto those of -theta
        mirrored = bool(np.all(np.min(np.abs(np.mod(-phases[:, None] - phases[None, :] + np.pi,
                                                      2 * np.pi) - np.pi), axis=1) < 1e-9))
        keep = phases <= np.pi + 1e-12 if mirrored else np.ones(phases.size, bool)
        solved, labels = phases[keep], labels[keep]

        def matrix(z, rows, solved=solved):
            return cell_hill_matrix(passage, cell, search, z / period, solved[rows])
        pairs = _contour(matrix, solved.size, center, semi_axes, points, n * (2 * band + 1))
        for phase, base, (values, vectors) in zip(solved, labels, pairs):
            near = (np.abs(values.imag) <= np.pi + 0.5) & (values.real >= low - 0.5) \
                & (values.real <= high + 0.5)
            padded = np.zeros((n * (2 * m + 1), vectors.shape[1]), dtype=complex)
            padded[n * (m - band):n * (m + band + 1)] = vectors
            candidates += [(z, p, phase, base, mirrored) for z, p in zip(values[near],
                                                                         padded.T[near])]
    found: list = []
    if not candidates:
        return found
    z0, p0, phase, base, mirrored = (np.array(column) for column in zip(*candidates))
    chunk = max(1, int(MEMORY_BYTES // (16 * 4 * (n * (2 * m + 1) + 1) ** 2)))
    parts = []
    for start in range(0, z0.size, chunk):
        rows = np.arange(start, min(start + chunk, z0.size))

        def local(z, which, rows=rows):
            return cell_hill_matrix(passage, cell, toeplitz, z / period, phase[rows[which]])

        def local_slope(z, p, which, rows=rows):
            return cell_hill_derivative(passage, cell, toeplitz, z / period,
                                        phase[rows[which]], p) / period
        parts.append(polish(local, z0[rows], p0[rows], local_slope))
    values, vectors, residuals = (np.concatenate(part) for part in zip(*parts))
    values, inside, tails = strip_roots(values, vectors, residuals, low, high, top)
    for i in np.flatnonzero(inside):
        found.append((values[i], phase[i], tails[i], base[i]))
        if mirrored[i] and 1e-12 < phase[i] < np.pi - 1e-12:
            found.append((np.conj(values[i]), 2 * np.pi - phase[i], tails[i], base[i]))
    return found
