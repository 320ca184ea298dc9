"""What a wheel solution's contact force says over a period: extremes, flights, the anchor's sag.

Functions of a `railtrack.WheelSolution` (its methods call them), kept apart
to keep `railtrack.solvers.wheel_solution` short.
"""

from __future__ import annotations

import numpy as np

from .arguments import require_count
from .result_protocol import period_times, top_harmonic

__all__ = ["anchor_sag", "extremes", "loss_of_contact", "peak_samples", "PEAK_SAMPLING"]

PEAK_SAMPLING = 16
"""Samples per period of the highest harmonic m that read a peak of P: a short
blow (a wheel flat's, a joint's P1) lies between two of 4 m samples and reads up
to 5 % low (394 against 414 kN under a flat at m = 600); 16 m samples read it within
a few tenths of a percent."""


def anchor_sag(solution) -> float:
    """The static sag at sleeper 0 of the wheels' uneven mean load [m].

    The rail field of `sleepers` anchors its mean at sleeper 0 under a
    uniform mean load; where the wheels' force varies along the track
    their mean load is not uniform, q(x) = sum_k P_k(x) / H, and the free
    rail of the cell's period sags under its varying part by
    ``sum_k mean_t[(P_k - mean P_k) Lambda^3 B4(x_k / Lambda)] / (24 EI)`` at
    sleeper 0 (Bernoulli's B4, `railtrack.equations.cell_rail_field`).
    Computed once per solution: it takes the contact force over a finely
    sampled period.
    """
    cell = solution.sleepers.cell.sleepers * float(solution.passage.sleeper_spacing)
    t = period_times(solution.period, 4 * solution.sleepers.samples)   # kinks want samples
    force = solution.contact_force(t)
    u = np.mod(solution.wheel_position(t) / cell, 1.0)
    shape = u**4 - 2 * u**3 + u**2 - 1.0 / 30.0
    varying = force - force.mean(axis=1, keepdims=True)
    return float(np.sum(np.mean(varying * shape, axis=1)) * cell**3
                 / (24 * float(solution.passage.rail_bending_stiffness)))


def peak_samples(solution, least: int = 4096) -> int:
    """max(`least`, 16 m) instants over a period: enough to read P's peaks (`PEAK_SAMPLING`)."""
    return max(int(least), PEAK_SAMPLING * top_harmonic(solution))


def extremes(solution, samples: int = 4096) -> dict[str, np.ndarray]:
    """Per wheel: largest and smallest P [N], where they occur [m], mean P [N].

    Positions are the wheel's distance from sleeper 0 along the track,
    within one wagon length (0 <= x < H); ``dynamic_factor`` is max P / Q.
    `samples` >= 1 times over the period.
    """
    t = period_times(solution.period, require_count("samples", samples, 1))
    force = solution.contact_force(t)
    where = np.mod(solution.wheel_position(t), float(solution.passage.wagon_length))
    rows = np.arange(force.shape[0])
    top, bottom = force.argmax(axis=1), force.argmin(axis=1)
    return {"max": force[rows, top], "where_max": where[rows, top],
            "min": force[rows, bottom], "where_min": where[rows, bottom],
            "mean": force.mean(axis=1),
            "dynamic_factor": force[rows, top] / np.asarray(solution.passage.axle_loads)}


def loss_of_contact(solution, samples: int = 8192) -> tuple[np.ndarray, np.ndarray]:
    """Per wheel: the share of the period off the rail, and the longest spell off it [s]."""
    off = solution.compression(period_times(solution.period, samples)) <= 0.0
    dt = solution.period / samples
    longest = np.zeros(off.shape[0])
    for k, row in enumerate(off):
        if row.all():
            longest[k] = solution.period
            continue
        rolled = np.roll(row, -int(np.argmin(row)))        # start on the rail
        runs = np.diff(np.flatnonzero(np.diff(np.r_[0, rolled.astype(int), 0])))[::2]
        longest[k] = runs.max() * dt if runs.size else 0.0
    return off.mean(axis=1), longest
