"""Newton's method for a cell with wheels on Hertz springs (issue 20).

Drives `railtrack.equations.wheel_harmonic_balance.wheel_residual`.  The
unknowns split in two: the sleepers' harmonics c_{j,n}, many, and per
wheel k its contact-force harmonics P_{k,p} (p on the grid G Z) and its
mean height over the rail y_k, few.  For given wheel forces the sleepers
are the constant-force cell with one more load, W P
(`railtrack.solvers.cell_newton.solve_cell`, exact); what remains is the
contact residual B(P, y) = [C_H max(delta, 0)^{3/2}]_p - P_p (- Q_k at p = 0).
Its Jacobian is ``K C - I`` (the book's chapter 14): K the Hertz tangent
1.5 C_H delta^{1/2} on the AFT samples and C the contact's compression per
unit P and y: the wheels' receptance A(omega_p) less the track's (A = -1/(m_w omega_p^2)
for a `Wheel`, 2 D^-1 coupling a `Vehicle`'s wheels, `railtrack.equations.wheel_receptance`),
receptance under the moving wheels, the linear map P -> W P -> c ->
reactions -> rail under the wheels, linearised exactly: each sleeper's mean
tangent, and for the sleepers whose tangent varies (a hanging sleeper that
touches) its variation by Woodbury (`railtrack.solvers.wheel_sleepers`).
Both are applied without forming anything of size (K (2l+1))^2 and the step
is found by preconditioned GMRES (`railtrack.solvers.wheel_krylov`, issue
28): the track is factorised once per support
(`railtrack.solvers.wheel_track.track_operator`, once per solve for linear
laws; on identical sleepers C is kept as its sparse class blocks,
`railtrack.solvers.wheel_blocks`).  The reported
residual is the full one, sleepers and contacts.
"""

from __future__ import annotations

from dataclasses import replace
from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import tangent_spectrum
from ..equations.harmonic_balance import default_samples
from ..equations.wheel_harmonic_balance import (
    compression,
    profile_harmonics,
    wheel_loads,
    wheel_residual,
    wheel_system,
)
from ..model.passage import Passage
from .cell_newton import solve_cell
from .wheel_krylov import ContactJacobian, gmres
from .wheel_track import sleeper_response, track_operator

__all__ = ["WheelNewton", "solve_wheels"]

SLEEPERS_TOL = 1e-13
"""The sleepers' inner solve stops at this relative residual: at 1e-10 a warm start passed
without a step once the wheel forces changed by less than 1e-10 of the load, and the
contact residual, which the rail's near-rigid response amplifies at low speed, stalled
above 1e-9 at 1-3 m/s."""
SLEEPERS_SETTLED = 1e-10
"""... and counts as solved at this one (the cell path's tol) where round-off stops it."""
STEP_TOL = 1e-4
"""GMRES solves Newton's step to this relative residual at most (tighter near tol)."""
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
        or, where the contact residual stays above tol at its round-off floor
        (at 1-3 m/s the rail's near-rigid response amplifies the sleepers'
        round-off, 1e-9 of Q), once Newton's correction there, the distance
        to the solution it predicts, is <= tol Q: whether the line search
        stopped or the steps ran out (issue 28: a residual wandering at its
        floor used the whole budget and was reported not converged).
    start : (ndarray (K, l'), ndarray (K,)[, ndarray (N, m'+1)]), optional
        P_{k,p} at the first l' wheel harmonics and y_k to start from (a
        coarser m's solution), and optionally the sleepers' harmonics
        n = 0..m' there, from which their first inner solve starts (from rest it
        took 5 Newton steps at every level of "auto", 0.7 s of 1.8 at m = 458
        over a hanging sleeper); default: the static contact.
    """
    m = int(harmonics)
    samples = default_samples(m) if samples is None else int(samples)
    system = wheel_system(passage, cell, wheel, m, samples)
    seen = profile_harmonics(passage, profile, system.grid, samples)   # read once a solve
    k_w, lmax = len(passage.axle_positions), system.grid.size
    loads = np.asarray(passage.axle_loads, dtype=float)
    scale = float(np.max(loads))
    period = float(passage.period)
    lift = np.array([wheel.static_compression(q) for q in loads]) - float(np.mean(
        profile(np.linspace(0, float(passage.wagon_length), 4096, endpoint=False))))
    forces = np.zeros((k_w, lmax), dtype=complex)
    resting = None
    if start is not None:
        kept = min(lmax, start[0].shape[1])
        forces[:, :kept] = start[0][:, :kept]
        lift = np.array(start[1], dtype=float)
        if len(start) > 2 and start[2] is not None:
            kept = min(m + 1, start[2].shape[1])
            resting = np.zeros((cell.sleepers, m + 1), dtype=complex)
            resting[:, :kept] = start[2][:, :kept]
    x = _pack(forces, lift)
    sleepers = None

    def evaluate(vector, start):
        forces, y = _unpack(vector, k_w, lmax)
        inner = solve_cell(passage, cell, m, samples=samples, operators=system.ops,
                           extra_load=wheel_loads(system, forces),
                           initial=start, tol=SLEEPERS_TOL)
        c = inner.coefficients[:, m:]
        _, contacts, delta, hertz = wheel_residual(passage, cell, wheel, seen, system,
                                                   c, forces, y,
                                                   inner.foundation_harmonics[:, m:])
        packed = np.concatenate([contacts[:, :1].real, contacts[:, 1:].real,
                                 contacts[:, 1:].imag], axis=1).ravel() / scale
        return packed, delta, hertz, inner

    current, delta, hertz, sleepers = evaluate(x, resting)
    norm, steps, message = float(np.linalg.norm(current)), 0, ""
    products, operator = 0, None

    def forces_of(vector):
        return _unpack(vector, k_w, lmax)[0]

    def settled(inner):
        return bool(inner.converged or inner.residual <= SLEEPERS_SETTLED)

    def direction(linear_start):
        """Newton's step at x (GMRES), the sleepers' predicted move, and the step over Q."""
        nonlocal operator, products
        c = sleepers.coefficients[:, m:]
        tangents, sampled = tangent_spectrum(cell, c, system.ops, samples)
        mean = tangents[:, :, 2 * m]                                       # (2, N)
        s = 1j * system.ops.omega[:, None]
        support = (cell.sleeper_mass * s**2 + mean[0].real + s * mean[1].real)
        if operator is None:
            operator = track_operator(system, cell, support, tangent=(tangents, sampled))
        elif operator.varying is not None or not np.array_equal(operator.support, support):
            operator = track_operator(system, cell, support, operator.diagonal,
                                      (tangents, sampled))
        # the first step solves the contact linearised at the static compression,
        # k_H (delta - delta_0) = P: from the constant forces the wheel does not
        # yet follow the profile, and Hertz's tangent there would be zero in a dip
        target = current
        if linear_start:
            static = np.array([wheel.static_compression(q) for q in loads])
            tangent = np.broadcast_to(wheel.contact_stiffness(static)[:, None], delta.shape)
            linear = tangent * (delta - static[:, None])
            target = (np.concatenate([_packed_harmonics(linear, system.grid) - np.concatenate(
                [loads[:, None] * 0.0, forces_of(x).real, forces_of(x).imag], axis=1)],
                axis=1).ravel() / scale)
        else:
            tangent = wheel.contact_stiffness(delta)
        jacobian = ContactJacobian(system, operator, tangent, scale)
        # inexact Newton: the step's own residual well below the next one's aim
        rtol = min(STEP_TOL, max(1e-12, 0.1 * tol / max(norm, 1e-300)))
        step, _, used = gmres(jacobian.apply, jacobian.precondition, -target, rtol)
        products += used
        # the sleepers under the new forces, predicted through the mean-tangent track:
        # exact for linear laws, so that their inner solve only checks its residual
        moved = sleeper_response(system, operator, forces_of(step))[0].T
        return step, moved, _correction(step, k_w, lmax, np.mean(tangent, axis=1), scale)

    correction, fresh = np.inf, False
    while (norm > tol or not settled(sleepers)) and steps < max_iterations:
        steps += 1
        linear_start = steps == 1 and start is None
        step, moved, correction = direction(linear_start)
        c = sleepers.coefficients[:, m:]
        fresh = True                     # correction is Newton's at the current x ...
        for _ in range(30):
            trial = evaluate(x + step, c + moved)
            trial_norm = float(np.linalg.norm(trial[0]))
            if trial_norm < norm or linear_start:
                break
            step, moved = 0.5 * step, 0.5 * moved
        else:
            message = f"no decrease of the contact residual at Newton step {steps}"
            break
        x = x + step
        current, delta, hertz, sleepers = trial
        norm, fresh = trial_norm, False  # ... until a step is taken
    # a residual above tol that stopped falling, or whose budget ran out, at its round-off
    # floor: Newton's correction there, the distance to the solution it predicts, decides
    if tol < norm <= FLOOR_RESIDUAL and settled(sleepers) and not fresh:
        correction = direction(False)[2]
    floor = bool(tol < norm <= FLOOR_RESIDUAL and correction <= tol)
    converged = bool((norm <= tol or floor) and settled(sleepers))
    if settled(sleepers) and not sleepers.converged:
        sleepers = replace(sleepers, converged=True)
    if floor:
        message = (f"converged at the contact residual's round-off floor: it stays at "
                   f"{norm:.1e}, where Newton's correction is {correction:.1e} Q <= tol")
    forces, y = _unpack(x, k_w, lmax)
    times = np.arange(samples) * period / samples
    summary = (f"contact residual {norm:.2e} {'<=' if norm <= tol else '>'} tol {tol:.1e} "
               f"after {steps} steps ({products} GMRES products); "
               f"sleepers: {sleepers.message}")
    # delta's own harmonics, without the profile and the lift: rail under the wheel - z
    moving = delta - compression(passage, seen, system, np.zeros_like(forces), y)
    harmonics = (np.fft.rfft(moving, axis=-1) / samples)[:, system.grid]
    return WheelNewton(sleepers.coefficients, system.grid, forces, y, harmonics, times, delta,
                       hertz, converged, norm, steps,
                       summary if not message else f"{message}; {summary}", sleepers)

