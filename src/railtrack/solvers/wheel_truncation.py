"""The truncation error of a wheel solve at an explicit m, estimated a posteriori (issue 27).

As `railtrack.solvers.cell_auto.cell_truncation` does for the sleepers: the
solution at m leaves out every wheel harmonic p > m.  Two things excite them:

* the rail-top profile's own harmonics r_p above m (a 1 m dip has them up to
  p ~ 10 H / 1 m), which the truncated solve does not see at all;
* the Hertz force evaluated on the truncated compression, whose harmonics
  above m (the excess e_p) the truncated balance drops.

Both are answered by the wheel-track system linearised about the solution,
at the harmonics m < p <= `TAIL_FACTOR` m: the Hertz spring by its mean
tangent kbar_k = mean over the period of 1.5 C_H delta_k^{1/2}, the track
and the wheel by their receptance under the moving wheels C
(`railtrack.solvers.wheel_newton.track_under_wheels`, each sleeper's law by
its mean tangent), so that the neglected contact-force harmonics solve

    (I - kbar C_tail) dP = kbar r_tail + e_tail.

The error is the largest, over the wheels and the period, of |dP(t)| over
the largest static wheel load Q.  The tail's feedback into the kept
harmonics is left out (second order), as in the sleepers' estimate.
"""

from __future__ import annotations

import numpy as np

from ..equations.cell_harmonic_balance import _forces, _synthesize
from ..equations.harmonic_balance import default_samples
from ..equations.wheel_harmonic_balance import profile_harmonics, wheel_system
from .wheel_newton import track_under_wheels

__all__ = ["wheel_truncation", "TAIL_FACTOR"]

TAIL_FACTOR = 3
"""The tail is solved up to p = TAIL_FACTOR m (the profile's and the excess's harmonics
fall off with p: those just above m carry most of the error) ..."""
TAIL_MOST = 240
"""... but never more than TAIL_MOST harmonics above m, which bounds the cost at large m
(at m = 300 on a dipped weld the estimate moves from 0.17 % to 0.15 % of Q)."""


def wheel_truncation(solution) -> float:
    """Estimated truncation error of a `WheelSolution`'s contact forces over Q [-].

    Parameters
    ----------
    solution : WheelSolution
        Converged, at m harmonics.

    Returns
    -------
    float
        max_{k,t} |dP_k(t)| / max_k Q_k (module docstring).
    """
    passage, cell, wheel = solution.passage, solution.sleepers.cell, solution.wheel
    m = solution.harmonics
    groups = int(solution.grid[0]) if solution.grid.size else int(
        round(float(passage.wagon_length) / (cell.sleepers * float(passage.sleeper_spacing))))
    top = max(min(TAIL_FACTOR * m, m + TAIL_MOST) // groups, m // groups + 1) * groups
    samples = default_samples(top)
    system = wheel_system(passage, cell, wheel, top, samples)
    tail = np.flatnonzero(system.grid > m)
    if tail.size == 0:
        return 0.0
    delta = _compression_samples(solution, samples)                         # (K, S)
    loads = np.asarray(passage.axle_loads, dtype=float)
    stiffness = wheel.contact_stiffness(delta).mean(axis=1)               # kbar_k (K,)
    excess = (np.fft.rfft(wheel.contact_force(delta), axis=-1) / samples)[:, system.grid[tail]]
    rail_top = profile_harmonics(passage, profile=solution.profile, grid=system.grid[tail],
                                 samples=samples)[:, 1:]
    # each sleeper's law by its mean tangent along the truncated orbit
    c = solution.sleepers.coefficients[:, m:]
    w, v = _synthesize(c, passage.fundamental_frequency * np.arange(m + 1), default_samples(m))
    tangent = _forces(cell, w, v, tangent=True).mean(axis=-1)             # (2, N)
    s = 1j * system.ops.omega[:, None]
    support = cell.sleeper_mass * s**2 + tangent[0] + s * tangent[1]
    receptance = track_under_wheels(system, cell, support)
    k_w, lmax = loads.size, system.grid.size
    size = 2 * lmax + 1
    # packed per wheel as [y, Re x_1..l, Im x_1..l]: the tail's rows and columns
    picked = np.concatenate([k * size + 1 + np.concatenate([tail, lmax + tail])
                             for k in range(k_w)])
    kbar = np.repeat(stiffness, 2 * tail.size)
    block = receptance[np.ix_(picked, picked)]
    right = (kbar * np.concatenate([np.concatenate([r.real, r.imag]) for r in rail_top])
             + np.concatenate([np.concatenate([e.real, e.imag]) for e in excess]))
    packed = np.linalg.solve(np.eye(picked.size) - kbar[:, None] * block, right)
    forces = packed.reshape(k_w, 2, tail.size)
    spectrum = np.zeros((k_w, samples // 2 + 1), dtype=complex)
    spectrum[:, system.grid[tail]] = (forces[:, 0] + 1j * forces[:, 1]) * samples
    history = np.fft.irfft(spectrum, samples, axis=-1)
    return float(np.max(np.abs(history)) / np.max(loads))


def _compression_samples(solution, samples: int) -> np.ndarray:
    """delta_k(t) on `samples` points a period by one inverse FFT, (K, samples) [m]."""
    spectrum = np.zeros((solution.lift.size, samples // 2 + 1), dtype=complex)
    spectrum[:, solution.grid] = (solution.compression_harmonics
                                  + solution.profile_harmonics[:, 1:]) * samples
    mean = solution.lift + solution.profile_harmonics[:, 0].real
    return np.fft.irfft(spectrum, samples, axis=-1) + mean[:, None]
