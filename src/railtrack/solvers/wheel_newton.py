"""Newton's method for a cell with wheels on Hertz springs (issue 20).

Drives `railtrack.equations.wheel_harmonic_balance.wheel_residual`.  The
unknowns split in two: the sleepers' harmonics c_{j,n}, many, and per
wheel k its contact-force harmonics P_{k,p} (p on the grid G Z) and its
mean height over the rail y_k, few.  For given wheel forces the sleepers
are the constant-force cell with one more load, W P
(`railtrack.solvers.cell_newton.solve_cell`, exact); what remains is the
contact residual B(P, y) = [C_H max(delta, 0)^{3/2}]_p - P_p (- Q_k at p = 0).
Its Jacobian is ``K C - I`` (the book's chapter 13): K the Hertz tangent
1.5 C_H delta^{1/2} by AFT (analysis, times the samples, times synthesis)
and C the contact's compression per unit P and y (`track_under_wheels`):
the wheel's own receptance 1/(m_w omega_p^2) less the track's receptance
under the moving wheels, built once per step from the linear map
P -> W P -> c -> reactions -> rail under the wheels (each sleeper's law
replaced by its mean tangent: exact for linear laws, a quasi-Newton step
for the others).  The residual reported is the
full one, sleepers and contacts.
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import tangent_spectrum
from ..equations.harmonic_balance import default_samples
from ..equations.wheel_harmonic_balance import (
    compression,
    wheel_loads,
    wheel_residual,
    wheel_system,
)
from ..model.passage import Passage
from .cell_newton import solve_cell
from .wheel_track import track_under_wheels

__all__ = ["WheelNewton", "solve_wheels", "track_under_wheels"]

SLEEPERS_TOL = 1e-13
"""The sleepers' inner solve stops at this relative residual: at 1e-10 a warm start passed
without a step once the wheel forces changed by less than 1e-10 of the load, and the
contact residual, which the rail's near-rigid response amplifies at low speed, stalled
above 1e-9 at 1-3 m/s."""
SLEEPERS_SETTLED = 1e-10
"""... and counts as solved at this one (the cell path's tol) where round-off stops it."""
FLOOR_RESIDUAL = 1e-6
"""A stalled contact residual is taken as a round-off floor only below this [-]."""


class WheelNewton(NamedTuple):
    """A cell's periodic response with wheels; ``converged`` only if the residual <= tol."""

    coefficients: np.ndarray   # (N, 2m+1) c_{j,n}, n = -m..m [m]
    grid: np.ndarray           # wheel harmonics p
    contact_harmonics: np.ndarray  # (K, lmax) P_{k,p} [N]
    lift: np.ndarray           # (K,) y_k [m]
    compression_harmonics: np.ndarray  # (K, lmax) delta_{k,p} at p = grid [m]
    times: np.ndarray          # (S,) [s]
    compression: np.ndarray    # (K, S) delta_k(t) [m]
    contact_force: np.ndarray  # (K, S) C_H max(delta, 0)^{3/2} [N]
    converged: bool
    residual: float
    iterations: int
    message: str
    sleepers: object           # CellSolution of the sleepers under the final wheel forces


def _correction(step: np.ndarray, wheels: int, lmax: int, stiffness: np.ndarray,
                scale: float) -> float:
    """Newton's step as a force over Q: max |dP_p| / Q and, for the lift, kbar |dy| / Q [-]."""
    forces, lift = _unpack(step, wheels, lmax)
    return float(max(np.max(np.abs(forces), initial=0.0),
                     np.max(np.abs(stiffness * lift), initial=0.0)) / scale)


def _hertz_tangent(wheel, delta: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """d[C_H max(delta, 0)^{3/2}]_packed / d delta_packed per wheel, (K, 2l+1, 2l+1) [N/m].

    With the tangent's harmonics k_n (two-sided, k_{-n} = conj k_n), harmonic
    p of k delta is ``sum_q k_{p-q} delta_q``: for delta_q = a_q + i b_q it
    takes ``k_{p-q} + k_{p+q}`` per a_q and ``i (k_{p-q} - k_{p+q})`` per b_q.
    """
    spectrum = np.fft.rfft(wheel.contact_stiffness(delta), axis=-1) / delta.shape[-1]
    lmax = grid.size
    step = int(grid[0]) if lmax else 1
    index = np.arange(-2 * lmax, 2 * lmax + 1)
    one_sided = spectrum[:, np.abs(index) * step]
    k = np.where(index >= 0, one_sided, np.conj(one_sided))              # (K, 4l+1)
    p = np.arange(1, lmax + 1)
    minus = k[:, 2 * lmax + p[:, None] - p[None, :]]                      # k_{p-q}
    plus = k[:, 2 * lmax + p[:, None] + p[None, :]]                       # k_{p+q}
    by_a, by_b = minus + plus, 1j * (minus - plus)
    at_p = k[:, 2 * lmax + p]
    out = np.empty((delta.shape[0], 2 * lmax + 1, 2 * lmax + 1))
    out[:, 0, 0] = k[:, 2 * lmax].real
    out[:, 0, 1:lmax + 1] = 2 * at_p.real
    out[:, 0, lmax + 1:] = 2 * at_p.imag
    out[:, 1:lmax + 1, 0], out[:, lmax + 1:, 0] = at_p.real, at_p.imag
    out[:, 1:lmax + 1, 1:lmax + 1], out[:, lmax + 1:, 1:lmax + 1] = by_a.real, by_a.imag
    out[:, 1:lmax + 1, lmax + 1:], out[:, lmax + 1:, lmax + 1:] = by_b.real, by_b.imag
    return out


def _packed_harmonics(samples: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """(K, S) samples -> (K, 2l+1) ``[mean, Re x_p, Im x_p]`` at p = grid."""
    spectrum = np.fft.rfft(samples, axis=-1) / samples.shape[-1]
    return np.concatenate([spectrum[:, :1].real, spectrum[:, grid].real,
                           spectrum[:, grid].imag], axis=1)


def _pack(forces: np.ndarray, lift: np.ndarray) -> np.ndarray:
    return np.concatenate([lift[:, None], forces.real, forces.imag], axis=1).ravel()


def _unpack(x: np.ndarray, wheels: int, lmax: int):
    rows = x.reshape(wheels, 2 * lmax + 1)
    return rows[:, 1:lmax + 1] + 1j * rows[:, lmax + 1:], rows[:, 0].copy()


def solve_wheels(passage: Passage, cell, wheel, profile, harmonics: int, *,
                 samples: int | None = None, tol: float = 1e-9,
                 max_iterations: int = 40, start=None) -> WheelNewton:
    """Periodic response of a cell of sleepers under wheels on Hertz springs, by Newton.

    Parameters
    ----------
    passage : Passage
        Rail, spacing, train (its axle loads Q_k are the wheels' static loads).
    cell : SleeperCell
        H must be a whole number of cells.
    wheel : Wheel
    profile : callable
        r(x) [m], repeating with the cell.
    harmonics : int
        m, the sleepers'; the wheels' harmonics are the multiples of H / (N L) up to m.
    tol : float
        Converged once the contact residual over the largest Q is <= tol and
        the sleepers' residual over the train's load <= `SLEEPERS_SETTLED`;
        or, where the contact residual stops falling above tol (its round-off
        floor: at 1-3 m/s the rail's near-rigid response amplifies the
        sleepers' round-off, 1e-9 of Q), once Newton's correction there, the
        distance to the solution it predicts, is <= tol Q.
    start : (ndarray (K, l'), ndarray (K,)), optional
        P_{k,p} at the first l' wheel harmonics and y_k to start from (a
        coarser m's solution); default: the static contact.
    """
    m = int(harmonics)
    samples = default_samples(m) if samples is None else int(samples)
    system = wheel_system(passage, cell, wheel, m, samples)
    k_w, lmax = len(passage.axle_positions), system.grid.size
    loads = np.asarray(passage.axle_loads, dtype=float)
    scale = float(np.max(loads))
    period = float(passage.period)
    lift = np.array([wheel.static_compression(q) for q in loads]) - float(np.mean(
        profile(np.linspace(0, float(passage.wagon_length), 4096, endpoint=False))))
    forces = np.zeros((k_w, lmax), dtype=complex)
    if start is not None:
        kept = min(lmax, start[0].shape[1])
        forces[:, :kept] = start[0][:, :kept]
        lift = np.array(start[1], dtype=float)
    x = _pack(forces, lift)
    sleepers = None

    def evaluate(vector, start):
        forces, y = _unpack(vector, k_w, lmax)
        inner = solve_cell(passage, cell, m, samples=samples, operators=system.ops,
                           extra_load=wheel_loads(system, forces),
                           initial=start, tol=SLEEPERS_TOL)
        c = inner.coefficients[:, m:]
        _, contacts, delta, hertz = wheel_residual(passage, cell, wheel, profile, system,
                                                   c, forces, y)
        packed = np.concatenate([contacts[:, :1].real, contacts[:, 1:].real,
                                 contacts[:, 1:].imag], axis=1).ravel() / scale
        return packed, delta, hertz, inner

    current, delta, hertz, sleepers = evaluate(x, None)
    norm, steps, message = float(np.linalg.norm(current)), 0, ""
    cached = None

    def forces_of(vector):
        return _unpack(vector, k_w, lmax)[0]

    def settled(inner):
        return bool(inner.converged or inner.residual <= SLEEPERS_SETTLED)

    correction = np.inf
    while (norm > tol or not settled(sleepers)) and steps < max_iterations:
        steps += 1
        c = sleepers.coefficients[:, m:]
        tangents, _ = tangent_spectrum(cell, c, system.ops, samples)
        mean = tangents[:, :, 2 * m]                                       # (2, N)
        s = 1j * system.ops.omega[:, None]
        support = (cell.sleeper_mass * s**2 + mean[0].real + s * mean[1].real)
        if cached is None or not np.array_equal(cached[0], support):
            cached = (support, track_under_wheels(system, cell, support))
        receptance = cached[1]
        # the first step solves the contact linearised at the static compression,
        # k_H (delta - delta_0) = P: from the constant forces the wheel does not
        # yet follow the profile, and Hertz's tangent there would be zero in a dip
        linear_start = steps == 1 and start is None
        if linear_start:
            static = np.array([wheel.static_compression(q) for q in loads])
            hertz_tangent = _hertz_tangent(wheel, np.broadcast_to(static[:, None], delta.shape),
                                           system.grid)
        else:
            hertz_tangent = _hertz_tangent(wheel, delta, system.grid)
        size = 2 * lmax + 1
        jacobian = np.zeros((k_w * size, k_w * size))
        for k in range(k_w):
            rows = slice(k * size, (k + 1) * size)
            jacobian[rows] = hertz_tangent[k] @ receptance[rows]
            own = slice(k * size + 1, (k + 1) * size)
            jacobian[own, own] -= np.eye(2 * lmax)
        target = current
        if linear_start:
            stiffness = hertz_tangent[:, 0, 0]
            linear = stiffness[:, None] * (delta - static[:, None])
            target = (np.concatenate([_packed_harmonics(linear, system.grid) - np.concatenate(
                [loads[:, None] * 0.0, forces_of(x).real, forces_of(x).imag], axis=1)],
                axis=1).ravel() / scale)
        step = np.linalg.solve(jacobian / scale, -target)
        correction = _correction(step, k_w, lmax, hertz_tangent[:, 0, 0], scale)
        for _ in range(30):
            trial = evaluate(x + step, c)
            trial_norm = float(np.linalg.norm(trial[0]))
            if trial_norm < norm or linear_start:
                break
            step = 0.5 * step
        else:
            message = f"no decrease of the contact residual at Newton step {steps}"
            break
        x = x + step
        current, delta, hertz, sleepers = trial
        norm = trial_norm
    floor = bool(message and correction <= tol and norm <= FLOOR_RESIDUAL)
    converged = bool((norm <= tol or floor) and settled(sleepers))
    if settled(sleepers) and not sleepers.converged:
        sleepers = replace(sleepers, converged=True)
    if floor:
        message = (f"the contact residual stops falling at {norm:.1e} (its round-off floor), "
                   f"where Newton's correction is {correction:.1e} Q <= tol")
    forces, y = _unpack(x, k_w, lmax)
    times = np.arange(samples) * period / samples
    summary = (f"contact residual {norm:.2e} {'<=' if norm <= tol else '>'} tol {tol:.1e} "
               f"after {steps} steps; sleepers: {sleepers.message}")
    # delta's own harmonics, without the profile and the lift: rail under the wheel - z
    moving = delta - compression(passage, profile, system, np.zeros_like(forces), y)
    harmonics = (np.fft.rfft(moving, axis=-1) / samples)[:, system.grid]
    return WheelNewton(sleepers.coefficients, system.grid, forces, y, harmonics, times, delta,
                       hertz, converged, norm, steps,
                       summary if not message else f"{message}; {summary}", sleepers)

