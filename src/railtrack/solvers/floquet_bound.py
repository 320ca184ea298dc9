"""An a-priori estimate of how fast any disturbance of a periodic solution can grow.

`growth_bound` tells a Floquet search how high its box of multipliers must
reach before finding nothing there proves stability
(`railtrack.solvers.floquet_verdict`).

Linearised about the orbit, the track is the rail and pads (constant,
passive) and, under each sleeper of mass m_s, the foundation's tangent
stiffness k(t) and damping d(t).  With any shift
kappa that makes k~ = k + kappa > 0, the energy E_s = 1/2 m_s w'^2 +
1/2 k~ w^2 of one sleeper on its foundation alone obeys

    dE_s/dt <= [ (k~'/k~)_+ + 2 max(-d, 0) / m_s + kappa / sqrt(m_s min k~) ] E_s,

since a positive d dissipates, 1/2 k~' w^2 <= (k~'/k~)_+ 1/2 k~ w^2 and
|kappa w w'| <= kappa E_s / sqrt(m_s min k~), so its amplitude grows per
period T by at most

    log |mu| <= 1/2 (upward variation of log k~ over T)
                + int_0^T max(-d, 0) / m_s dt + T kappa / (2 sqrt(m_s min k~)).

This is a proof for a sleeper that the rail leaves alone, not for the
coupled track: the passive rail and pads move energy between sleepers that
sit at different points of their cycle, and the bound that survives that
exchange (over a wagon's window of sleepers, the largest of their rates at
each instant) is e^16 to e^40 on chapter 10's fold branch, above any useful
box.  So `growth_bound` is an estimate of how large a multiplier can be,
exact in the limit of a soft rail; on the fold branch it lies above the
ring's |mu| (3 to 6,400 against at most 2.7, tests/test_floquet_verdicts.py),
and the default box (1e6) stays far above it.  A verdict of "stable" thus
says: no multiplier up to max_multiplier, and max_multiplier well above what
this estimate allows.  For a cell the estimate is the largest over its
sleepers.  A kinked law (bilinear, gap) gives finite jumps of log k~, so it
stays finite.  Several shifts are tried and the least kept.
"""

from __future__ import annotations

import numpy as np

__all__ = ["growth_bound", "BOUND_SAMPLES", "SHIFT_FRACTIONS"]

BOUND_SAMPLES = 4096
"""Samples of the orbit over one period for the bound (its sampled variation of log k~)."""
SHIFT_FRACTIONS = (1e-3, 1e-2, 1e-1, 1.0)
"""Shifts kappa tried, above -min k, as fractions of the range of k (and kappa = 0 if min k > 0)."""


def growth_bound(solution) -> float:
    """An estimate of the largest |mu| per period T = H / v any disturbance of `solution` can have [-].

    From the energy of the linearised track (module docstring); inf if the
    foundation's tangent along the orbit is not finite.  An estimate: a proof
    for a sleeper the rail leaves alone (module docstring).  For a
    `CellSolution`, the largest of its sleepers' estimates.

    Examples
    --------
    >>> import railtrack as rt
    >>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper())
    >>> growth_bound(s)      # constant k, positive d: no disturbance grows
    1.0
    """
    period, m = float(solution.period), int(solution.harmonics)
    samples = max(BOUND_SAMPLES, 16 * m)
    cell = getattr(solution, "cell", None)
    rows = np.atleast_2d(solution.coefficients)[:, m:]
    laws = [solution.foundation] if cell is None else list(cell.foundations)
    masses = np.broadcast_to(np.asarray(
        solution.passage.sleeper_mass if cell is None else cell.sleeper_mass, float), len(laws))
    omega = np.asarray(solution.frequencies, dtype=float)[-(m + 1):]
    increments = []
    for c, law, mass in zip(rows, laws, masses):
        # w and w' over one period at t_j = j T / N, by an inverse FFT of c_0..c_m
        spectrum = np.zeros(samples // 2 + 1, dtype=complex)
        spectrum[: m + 1] = c
        w = np.fft.irfft(spectrum, samples) * samples
        spectrum[: m + 1] *= 1j * omega
        v = np.fft.irfft(spectrum, samples) * samples
        stiffness, damping = (np.broadcast_to(np.asarray(part, dtype=float), w.shape)
                              for part in law.tangent(w, v))
        if not (np.all(np.isfinite(stiffness)) and np.all(np.isfinite(damping))):
            return float("inf")
        increments.append(_least_increments(stiffness, damping, float(mass), period))
    if any(part is None for part in increments):
        return float("inf")
    return float(np.exp(max(float(np.sum(part)) for part in increments)))


def _least_increments(stiffness: np.ndarray, damping: np.ndarray, mass: float,
                      period: float) -> np.ndarray | None:
    """Per sample, the growth of log E / 2 over the shift kappa with the least total.

    1/2 (rise of log k~)_+ + max(-d, 0) dt / m_s + dt kappa / (2 sqrt(m_s min k~)),
    whose sum over the period is log of the bound (module docstring).
    """
    dt = period / stiffness.size
    low, high = float(stiffness.min()), float(stiffness.max())
    shifts = [0.0] if low > 0 else []
    spread = max(high - low, abs(high), np.finfo(float).tiny)
    shifts += [max(-low, 0.0) + f * spread for f in SHIFT_FRACTIONS]
    best, chosen = float("inf"), None
    for kappa in shifts:
        shifted = stiffness + kappa
        if shifted.min() <= 0:
            continue
        log_k = np.log(np.append(shifted, shifted[0]))
        steps = (0.5 * np.maximum(np.diff(log_k), 0.0) + np.maximum(-damping, 0.0) * dt / mass
                 + 0.5 * dt * kappa / np.sqrt(mass * shifted.min()))
        if steps.sum() < best:
            best, chosen = float(steps.sum()), steps
    return chosen
