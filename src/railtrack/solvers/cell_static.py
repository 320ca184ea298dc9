"""The cell at rest before the train arrives: self-weight alone (issue 19, section 2).

At omega = 0 the cell's equations (`railtrack.equations.cell_harmonic_balance`)
without the train read ``K1_0 c + K2_0 (f(c, 0) + M g) = g_0``, with g_0 the
rail's weight only: N real equations, solved by Newton on each law's
stiffness ``df/dw(c, 0)``.  Without gravity the answer is c = 0.  A hanging
sleeper (`railtrack.GapFoundation`) finds no ballast under it and hangs on
its pads: its weight goes to its neighbours through the rail.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import _forces, cell_operators
from ..model.passage import Passage

__all__ = ["AtRest", "cell_at_rest"]

_COMPRESSION_SIDE = 1e-12    # [m], far below any static deflection


class AtRest(NamedTuple):
    """Static state of a cell under its own weight, per sleeper (N,)."""

    sleeper_displacement: np.ndarray     # [m], positive upward
    rail_seat_load: np.ndarray           # [N], positive in compression
    foundation_force: np.ndarray         # [N], positive in compression
    converged: bool


def cell_at_rest(passage: Passage, cell, *, tol: float = 1e-12,
                 max_iterations: int = 50) -> AtRest:
    """Static displacement and forces of the cell under the self-weight of rail and sleepers.

    Examples
    --------
    >>> from railtrack.model.cell import SleeperCell
    >>> from railtrack.model.foundations import LinearFoundation
    >>> passage = Passage.paper()
    >>> cell = SleeperCell.identical(passage, LinearFoundation(20e6), 2, gravity=9.81)
    >>> rest = cell_at_rest(passage, cell)
    >>> weight = 9.81 * (float(passage.sleeper_mass) + 60.0 * 0.6)   # one sleeper, one span
    >>> bool(np.allclose(rest.foundation_force, weight, rtol=1e-9))
    True
    """
    sleeper_weight, rail_weight = cell.weights(passage)
    zero = np.zeros(1)
    args = (passage, cell.pad_stiffness, cell.pad_damping, zero)
    loaded = cell_operators(*args, sleeper_weight=sleeper_weight, rail_weight=rail_weight)
    first, second = loaded.first[0].real, loaded.second[0].real
    load = (loaded.load[0] - cell_operators(*args).load[0]).real      # the weight alone
    c = np.zeros(cell.sleepers)
    scale = max(float(np.abs(load).max()), 1.0)
    converged = False
    for _ in range(max_iterations + 1):
        still = np.zeros((cell.sleepers, 1))
        force = _forces(cell, c[:, None], still)[:, 0]
        residual = first @ c + second @ force - load
        if np.abs(residual).max() <= tol * scale:
            converged = True
            break
        # the tangent a hair on the compression side (w < 0): at w = 0 a law with a
        # kink there (bilinear, tensionless) may give its tension branch, 0 N/m for a
        # tensionless one, and a track resting on nothing has no static solution
        stiffness = _forces(cell, c[:, None] - _COMPRESSION_SIDE, still, tangent=True)[0, :, 0]
        c = c - np.linalg.solve(first + second * stiffness, residual)
    force = _forces(cell, c[:, None], np.zeros((cell.sleepers, 1)))[:, 0]
    return AtRest(c, -(force + sleeper_weight) + 0.0, -force + 0.0, converged)
