"""The free rail under the wheels' varying forces, eq. (14.2), for a `WheelSolution`.

A `railtrack.WheelSolution`'s rail is the rail field of its sleepers (their
reactions and the wheels' static loads) plus this: the infinite rail, free
of sleepers' reactions, under each wheel's contact-force harmonics, through
the wheel-train receptance (`railtrack.equations.wheel_train_receptance`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..equations.positions import checked_times
from ..equations.wheel_train_receptance import wheel_train_receptance
from .field_chunks import chunk_length

__all__ = ["free_rail"]


def free_rail(solution, t: ArrayLike, x: ArrayLike, derivative: int) -> np.ndarray:
    """The free rail under a `WheelSolution`'s varying wheel forces, eq. (14.2) at (t, x).

    Its displacement [m] (``derivative=0``) or curvature [1/m] (2), shape of
    ``broadcast(t, x)``.

    The points are taken in blocks (`chunk_length`), every wheel's offset
    at once, so that memory stays bounded and each harmonic's roots are
    found once per block.
    """
    t = checked_times(2 * np.pi * solution.grid / solution.period, t)
    t, x = np.broadcast_arrays(t, np.asarray(x, dtype=float))
    flat_t, flat_x = t.ravel(), x.ravel()
    out = np.zeros(flat_t.size)
    omega = 2 * np.pi * solution.grid / solution.period
    speed = float(solution.passage.speed)
    axles = np.asarray(solution.passage.axle_positions, dtype=float)[:, None]
    step = chunk_length(axles.size)
    for start in range(0, flat_t.size, step):
        part = slice(start, start + step)
        offset = flat_x[part] - speed * flat_t[part] + axles                 # (K, P)
        # points that move with the train share their offsets: each once
        offsets, where = np.unique(offset, return_inverse=True)
        for force, w in zip(solution.contact_harmonics.T, omega):
            shape = wheel_train_receptance(solution.passage, float(w), offsets,
                                           derivative)[where.reshape(offset.shape)]
            # P presses down
            out[part] -= 2 * (np.exp(1j * w * flat_t[part]) * (force @ shape)).real
    return out.reshape(t.shape)
