"""The ring's layout: how many sleepers it carries, and its assembled linear part.

A ring one wagon length H long is periodic in the sleepers only if H / L is
an integer (eq. 9 repeats every H, the track every L); `sleepers_on_ring`
checks that and counts them.  `RingMesh` holds what
`railtrack.timedomain.fem.ring_mesh` assembles: the rail (eq. 1), pads
(eq. 5) and sleeper masses (eq. 4) as sparse M, C, K, and the numbering of
the degrees of freedom (rail node j: deflection ``2 j``, rotation
``2 j + 1``; sleeper i: ``2 * n_nodes + i``; `railtrack.timedomain.fem`).
The foundation is not part of it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..model.passage import Passage
from ..model.timoshenko import TimoshenkoRail
from .rail_elements import shear_parameter

__all__ = ["RING_TOLERANCE", "sleepers_on_ring", "RingMesh"]

RING_TOLERANCE = 1e-9
"""Largest |H/L - round(H/L)| accepted as an integer number of sleepers."""


def sleepers_on_ring(passage: Passage) -> int:
    """Number of sleepers H / L on a ring one wagon long.

    Raises
    ------
    ValueError
        If H / L is not an integer within `RING_TOLERANCE`: a ring of length H
        would then not be periodic in the sleepers.
    """
    ratio = float(passage.wagon_length) / float(passage.sleeper_spacing)
    count = int(round(ratio))
    if count < 1 or abs(ratio - count) > RING_TOLERANCE:
        raise ValueError(
            "the time-domain ring model needs H/L (wagon_length / sleeper_spacing) "
            f"to be an integer; got H/L = {_not_integer(ratio)} "
            f"(H = {float(passage.wagon_length)!r} m, L = {float(passage.sleeper_spacing)!r} m)"
        )
    return count


def _not_integer(ratio: float) -> str:
    """`ratio` with the fewest digits (6 at least) that show it is not an integer."""
    for digits in range(6, 18):
        text = f"{ratio:.{digits}g}"
        if float(text) != round(ratio):
            return text
    return repr(ratio)


@dataclass(frozen=True, eq=False)
class RingMesh:
    """Linear part of the ring: rail, pads and sleeper masses, without the foundation.

    Attributes
    ----------
    passage : Passage
    elements_per_span : int
        Rail elements between neighbouring sleepers.
    n_sleepers : int
        H / L.
    element_length : float
        h = L / elements_per_span [m].
    mass, damping, stiffness : scipy.sparse.csc_matrix, shape (n_dofs, n_dofs)
        Global M, C, K of the rail (eq. 1), pads (eq. 5) and sleepers (eq. 4)
        [kg], [N s/m], [N/m] (rotational entries in the matching units).
    sleeper_dofs : ndarray of int, shape (n_sleepers,)
        DOF of sleeper i.
    rail_dofs : ndarray of int, shape (n_sleepers,)
        Deflection DOF of the rail node above sleeper i.
    sleeper_mass, pad_stiffness, pad_damping : ndarray, shape (n_sleepers,)
        M_i [kg], k1_i [N/m], eta1_i [N s/m] of ring sleeper i and its pad:
        the passage's on every sleeper, or a cell's (`railtrack.timedomain.ring_cell`).
    timoshenko : TimoshenkoRail or None
        The rail's shear stiffness and rotary inertia if its elements are
        Timoshenko's; None for Hermite (Euler–Bernoulli) elements.
    """

    passage: Passage
    elements_per_span: int
    n_sleepers: int
    element_length: float
    mass: sp.csc_matrix
    damping: sp.csc_matrix
    stiffness: sp.csc_matrix
    sleeper_dofs: np.ndarray
    rail_dofs: np.ndarray
    sleeper_mass: np.ndarray | None = None
    pad_stiffness: np.ndarray | None = None
    pad_damping: np.ndarray | None = None
    timoshenko: TimoshenkoRail | None = None

    @property
    def shear_parameter(self) -> float | None:
        """Phi = 12 EI / (kappa G A h^2) of the Timoshenko elements [-]; None for Hermite ones."""
        if self.timoshenko is None:
            return None
        return shear_parameter(self.passage.rail_bending_stiffness,
                               self.timoshenko.shear_stiffness, self.element_length)

    @property
    def n_nodes(self) -> int:
        """Rail nodes on the ring (the node at x = H is node 0)."""
        return self.n_sleepers * self.elements_per_span

    @property
    def n_dofs(self) -> int:
        return 2 * self.n_nodes + self.n_sleepers
