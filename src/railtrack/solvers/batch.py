"""Many harmonic-balance solves at once: a batched Newton on eq. (17).

A batch is a `Passage` and a foundation whose fields are arrays of shape
(B, 1): every function of the package is elementwise, so
`railtrack.equations.harmonic_balance` evaluates the residual (17) and its AFT
Jacobian for all B members in one pass (FFTs along the last axis, a stack of
B Jacobians).  `newton_batch` then runs the same damped Newton as
`railtrack.solvers.newton` on all members together: one stacked linear solve per
step, a backtracking line search member by member, and each member's own
convergence flag, step count and residual.  A member that fails is reported
as failed (``converged`` False, its last iterate kept), never dropped.
"""

from __future__ import annotations

import dataclasses
from typing import NamedTuple

import numpy as np

from .foundation_at_rest import static_deflection
from .newton import guess_about_mean
from .truncation import TAIL_FACTOR, track_spectrum
from ..equations.aft_jacobian import residual_jacobian
from ..equations.harmonic_balance import (HarmonicSystem, from_real, residual, residual_norm,
                                          synthesize, to_real)

__all__ = ["BatchOutcome", "member", "static_means", "batch_guess", "newton_batch",
           "batch_truncation"]


class BatchOutcome(NamedTuple):
    """What `newton_batch` found for each of the B members.

    Attributes
    ----------
    coefficients : ndarray, shape (B, m+1)
        c_0..c_m of each member's last iterate [m].
    converged : ndarray of bool, shape (B,)
    iterations : ndarray of int, shape (B,)
        Newton steps each member took.
    residual : ndarray, shape (B,)
        Final relative residual ||R|| / ||F|| of eq. (17); inf where the law
        was not finite.
    """

    coefficients: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual: np.ndarray


def member(value, index: int):
    """Member `index` of a batched dataclass (fields of shape (B, 1) become scalars)."""
    changes = {}
    for field in dataclasses.fields(value):
        item = getattr(value, field.name)
        if isinstance(item, np.ndarray) and item.ndim > 0:
            flat = item.reshape(-1)
            changes[field.name] = float(flat[index] if flat.size > 1 else flat[0])
    return dataclasses.replace(value, **changes) if changes else value


def static_means(foundation, force: np.ndarray, size: int) -> np.ndarray:
    """The static deflection of each member, f(w, 0) = -force (`static_deflection`) [m].

    Newton on all members at once from the linear estimate; a member it does
    not settle is solved on its own by `railtrack.solvers.foundation_at_rest`.
    """
    force = np.broadcast_to(np.asarray(force, dtype=float).reshape(-1, 1), (size, 1))
    stiffness = np.broadcast_to(np.asarray(foundation.tangent(np.zeros((size, 1)), np.zeros((size, 1)))[0]),
                                (size, 1))
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(stiffness > 0, -force / stiffness, -1e-3)
        for _ in range(12):
            value = np.asarray(foundation.force(w, np.zeros_like(w))) + force
            tangent = np.asarray(foundation.tangent(w, np.zeros_like(w))[0])
            w = np.minimum(w - value / tangent, -1e-12)
        settled = np.abs(np.asarray(foundation.force(w, np.zeros_like(w))) + force) <= 1e-10 * force
    w, settled = w[:, 0], settled[:, 0] & np.isfinite(w[:, 0])
    for i in np.flatnonzero(~settled):
        w[i] = static_deflection(member(foundation, i), float(force[i, 0]))
    return w


def batch_guess(system: HarmonicSystem, size: int) -> np.ndarray:
    """Newton's starting point for every member: `railtrack.solvers.newton.linear_guess`, batched."""
    mean = static_means(system.foundation, system.passage.static_load_per_sleeper, size)
    w = mean[:, None]
    stiffness, damping = (np.broadcast_to(np.asarray(x), (size, 1))
                          for x in system.foundation.tangent(w, np.zeros_like(w)))
    return guess_about_mean(system, w, stiffness, damping)


CHUNK = 512
"""Members whose Jacobians are assembled and solved together in a Newton step.

A stack of B Jacobians (77 MB for B = 10,000 at m = 15) is written to main
memory by the assembly and read back by the LU; a few hundred (4 MB) stay
in cache in between.  The steps are the same, bit for bit: each member's
LU is its own.  (Measured at m = 15: 128 to 1024 are equally good.)
"""


def _steps(jacobian: np.ndarray, right: np.ndarray) -> np.ndarray:
    """Solve the stack J x = right; a singular member takes a least-squares step."""
    try:
        return np.linalg.solve(jacobian, right[..., None])[..., 0]
    except np.linalg.LinAlgError:
        steps = np.empty_like(right)
        for i in range(len(right)):
            try:
                steps[i] = np.linalg.solve(jacobian[i], right[i])
            except np.linalg.LinAlgError:
                steps[i] = np.linalg.lstsq(jacobian[i], right[i], rcond=None)[0]
        return steps


def _newton_steps(rows: HarmonicSystem, c: np.ndarray, current: np.ndarray) -> np.ndarray:
    """The full Newton step -J^{-1} R of every member of `rows`, `CHUNK` members at a time."""
    size = len(c)
    step = np.empty_like(current)
    for start in range(0, size, CHUNK):
        part = slice(start, min(start + CHUNK, size))
        chunk = rows if size <= CHUNK else _rows(rows, np.arange(part.start, part.stop))
        with np.errstate(invalid="ignore", over="ignore"):
            jacobian = residual_jacobian(chunk, c[part])
        step[part] = from_real(_steps(jacobian, -to_real(current[part])))
    step[:, 0] = step[:, 0].real
    return step


def newton_batch(system: HarmonicSystem, size: int, max_iterations: int = 100, tol: float = 1e-10,
                 initial: np.ndarray | None = None) -> BatchOutcome:
    """Damped Newton on eq. (17) for a batch of B = `size` members at once.

    Parameters
    ----------
    system : HarmonicSystem
        Built by `railtrack.equations.harmonic_balance.harmonic_system` from a batched
        passage and foundation (fields of shape (B, 1) or scalars).
    size : int
        B.
    max_iterations, tol
        As for `railtrack.solvers.newton.iterate_newton`, for every member.
    initial : ndarray, shape (B, m+1), optional
        Starting points; default `batch_guess`.
    """
    c = batch_guess(system, size) if initial is None else np.array(initial, dtype=complex)
    with np.errstate(invalid="ignore", over="ignore"):
        current = residual(system, c, strict=False)
        norm = np.asarray(residual_norm(system, current), dtype=float)
    norm = np.where(np.isfinite(norm), norm, np.inf)
    steps = np.zeros(size, dtype=int)
    active = norm > tol
    stuck = ~np.isfinite(norm)          # a law not finite at the start cannot be helped
    active &= ~stuck
    for _ in range(max_iterations):
        if not active.any():
            break
        index = np.flatnonzero(active)
        # once per step: the line search reuses it (no copy while all are active)
        rows = system if len(index) == size else _rows(system, index)
        step = _newton_steps(rows, c[index], current[index])
        scale = np.ones(len(index))
        pending = np.ones(len(index), dtype=bool)
        for _ in range(30):
            trial = c[index] + scale[:, None] * step
            with np.errstate(invalid="ignore", over="ignore"):
                trial_residual = residual(rows, trial, strict=False)
                trial_norm = np.asarray(residual_norm(rows, trial_residual), dtype=float)
            better = pending & np.isfinite(trial_norm) & (trial_norm < norm[index])
            accepted = index[better]
            c[accepted], current[accepted], norm[accepted] = trial[better], trial_residual[better], trial_norm[better]
            steps[accepted] += 1
            pending &= ~better
            if not pending.any():
                break
            scale[pending] *= 0.5
        stuck[index[pending]] = True     # no decrease within 30 halvings: give up on them
        active = (norm > tol) & ~stuck
    converged = norm <= tol
    return BatchOutcome(c, converged, steps, norm)


def _rows(system: HarmonicSystem, index: np.ndarray) -> HarmonicSystem:
    """The members `index` of a batched system (its per-member arrays indexed)."""
    def take(value):
        return value[index] if isinstance(value, np.ndarray) and value.ndim == 2 and value.shape[0] > 1 else value

    def rows_of(obj):
        changes = {f.name: take(getattr(obj, f.name)) for f in dataclasses.fields(obj)
                   if isinstance(getattr(obj, f.name), np.ndarray)}
        return dataclasses.replace(obj, **changes) if changes else obj

    passage = dataclasses.replace(system.passage, track=rows_of(system.passage.track),
                                  train=rows_of(system.passage.train))
    return dataclasses.replace(system, passage=passage, foundation=rows_of(system.foundation),
                               omega=take(system.omega), coupling=take(system.coupling),
                               load=take(system.load), operator=take(system.operator))



def _periodic_series(coefficients: np.ndarray, first: int, samples: int) -> np.ndarray:
    """sum over n >= first of c_n e^{i omega_n t} + conj at `samples` times, row by row."""
    spectrum = np.zeros(coefficients.shape[:-1] + (samples // 2 + 1,), dtype=complex)
    count = min(coefficients.shape[-1], samples // 2 + 1 - first)
    spectrum[..., first : first + count] = coefficients[..., :count] * samples
    return np.fft.irfft(spectrum, samples, axis=-1)


def batch_truncation(system: HarmonicSystem, coefficients: np.ndarray,
                     size: int) -> tuple[np.ndarray, np.ndarray]:
    """`railtrack.solvers.truncation.truncation_error` of every member, and the tails.

    The same estimate as for a single solve (the neglected harmonics
    m+1..8m linearised about each member's solution, their largest value
    over the period relative to the peak of the completed response), with
    every step elementwise over the batch.

    Returns
    -------
    errors : ndarray, shape (B,)
        NaN where a member's coefficients or law are not finite.
    tails : ndarray, shape (B, 7m)
        Estimated c_{m+1}..c_{8m} of each member [m].
    """
    m, samples = system.harmonics, system.samples
    upto = TAIL_FACTOR * m
    spectrum = track_spectrum(system.passage, upto)
    c = np.asarray(coefficients, dtype=complex)
    with np.errstate(invalid="ignore", over="ignore", divide="ignore"):
        w, v = synthesize(system, c)
        force = np.broadcast_to(np.asarray(system.foundation.force(w, v), dtype=float), w.shape)
        stiffness, damping = (np.mean(np.broadcast_to(x, w.shape), axis=-1, keepdims=True)
                              for x in system.foundation.tangent(w, v))
        excess = np.zeros((size, upto + 1), dtype=complex)
        generated = np.fft.rfft(force, axis=-1) / (samples * np.asarray(system.sleeper_mass))
        top = min(generated.shape[-1], upto + 1)
        excess[:, m + 1 : top] = generated[:, m + 1 : top]
        law = (stiffness + 1j * spectrum.omega * damping) / np.asarray(system.sleeper_mass)
        tails = (-(spectrum.load + excess) / (spectrum.operator + law))[:, m + 1 :]
        grid = 1 << int(np.ceil(np.log2(4 * (upto + 1))))
        neglected = _periodic_series(tails, m + 1, grid)
        whole = _periodic_series(c, 0, grid) + neglected
        errors = np.max(np.abs(neglected), axis=-1) / np.max(np.abs(whole), axis=-1)
    finite = np.all(np.isfinite(c), axis=-1) & np.isfinite(errors)
    return np.where(finite, errors, np.nan), tails
