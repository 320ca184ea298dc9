"""Finite elements of one wagon length of track closed into a ring.

The verification model of `railtrack.timedomain.simulation` discretises the same track
as the semi-analytical method, but in space and time:

* the rail, an Euler–Bernoulli beam (eq. 1), by Hermite cubic elements with
  the consistent mass matrix, ``elements_per_span`` per sleeper span (or a
  Timoshenko beam); the elements are in `railtrack.timedomain.rail_elements`;
* each sleeper, a point mass M (eq. 4), joined to the rail node above it by
  the pad spring–dashpot k1, eta1 (eqs. 4–5);
* the moving wheels, as consistent nodal loads: each wheel load -Q is spread
  on the four degrees of freedom of the element it stands on with the Hermite
  shape functions evaluated at its position (the work-equivalent loads).

The train repeats every H (eq. 9), and so does the periodic steady state, so
one wagon length H with its two ends identified (a ring) carries that state
exactly; this needs H / L to be an integer, the number of sleepers on the
ring.  The foundation f(w, w') is left to `railtrack.timedomain.simulation`: it is the
only nonlinear part.

Degrees of freedom: rail node j (at x = j h, h = L / elements_per_span) has
deflection ``2 j`` and rotation ``2 j + 1``; sleeper i (at x = i L, under
rail node ``i * elements_per_span``) has ``2 * n_nodes + i``.  w is positive
upward, rotations are dw/dx (the sections' psi for a Timoshenko rail).  All units SI.

Here the assembly (`ring_mesh`); the count of sleepers and `RingMesh` are in
`railtrack.timedomain.ring_layout`, the wheels' positions, shapes and loads
in `railtrack.timedomain.ring_loads`, and both are importable from here.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from numpy.typing import ArrayLike

from ..model.passage import Passage
from ..model.timoshenko import TimoshenkoRail
from .rail_elements import (beam_element_matrices, hermite_shape_functions,
                            timoshenko_element_matrices)
from .ring_layout import RingMesh, sleepers_on_ring
from .ring_loads import (contact_compliance, contact_shapes, rail_shapes, wheel_load_entries,
                         wheel_positions)

__all__ = [
    "RingMesh",
    "sleepers_on_ring",
    "hermite_shape_functions",
    "beam_element_matrices",
    "ring_mesh",
    "wheel_positions",
    "wheel_load_entries",
    "contact_shapes",
    "contact_compliance",
    "rail_shapes",
]


def ring_mesh(passage: Passage, elements_per_span: int,
              sleepers: tuple[ArrayLike, ArrayLike, ArrayLike] | None = None,
              timoshenko: TimoshenkoRail | None = None) -> RingMesh:
    """Assemble M, C, K of the ring of length H (see the module docstring).

    Parameters
    ----------
    passage : Passage
    elements_per_span : int
    sleepers : (mass, pad_stiffness, pad_damping), each of shape (H / L,), optional
        M_i [kg], k1_i [N/m], eta1_i [N s/m] of each ring sleeper and its pad
        (a cell of differing sleepers); default the passage's on every one.
    timoshenko : TimoshenkoRail, optional
        Timoshenko rail elements (`railtrack.timedomain.rail_elements`) with this shear
        stiffness and rotary inertia; default Hermite (Euler–Bernoulli) ones.

    Raises
    ------
    ValueError
        If H / L is not an integer (`sleepers_on_ring`), or `sleepers` has
        arrays of another length.
    TypeError
        If `timoshenko` is not a TimoshenkoRail.
    """
    n_sleepers = sleepers_on_ring(passage)
    if timoshenko is not None and not isinstance(timoshenko, TimoshenkoRail):
        raise TypeError("timoshenko must be a railtrack.model.timoshenko.TimoshenkoRail or None; "
                        f"got {type(timoshenko).__name__}")
    if sleepers is None:
        sleepers = (passage.sleeper_mass, passage.pad_stiffness, passage.pad_damping)
    masses, pad_k, pad_c = (np.array(np.broadcast_to(np.asarray(value, dtype=float), n_sleepers))
                            for value in sleepers)
    n_nodes = n_sleepers * elements_per_span
    n_dofs = 2 * n_nodes + n_sleepers
    h = float(passage.sleeper_spacing) / elements_per_span
    beam = (float(passage.rail_bending_stiffness), float(passage.rail_linear_mass))
    if timoshenko is None:
        k_element, m_element = beam_element_matrices(*beam, h)
    else:
        k_element, m_element = timoshenko_element_matrices(*beam, timoshenko, h)

    # Element e joins node e to node e + 1, and the last element closes the
    # ring on node 0: that identification is the periodic boundary condition.
    first = np.arange(n_nodes)
    second = (first + 1) % n_nodes
    element_dofs = np.stack([2 * first, 2 * first + 1, 2 * second, 2 * second + 1], axis=1)
    rows = np.repeat(element_dofs, 4, axis=1).ravel()
    cols = np.tile(element_dofs, (1, 4)).ravel()
    shape = (n_dofs, n_dofs)
    k_rail = sp.coo_matrix((np.tile(k_element.ravel(), n_nodes), (rows, cols)), shape)
    m_rail = sp.coo_matrix((np.tile(m_element.ravel(), n_nodes), (rows, cols)), shape)

    sleeper_dofs = 2 * n_nodes + np.arange(n_sleepers)
    rail_dofs = 2 * elements_per_span * np.arange(n_sleepers)
    pad_rows = np.concatenate([rail_dofs, sleeper_dofs, rail_dofs, sleeper_dofs])
    pad_cols = np.concatenate([rail_dofs, sleeper_dofs, sleeper_dofs, rail_dofs])
    pad_sign = np.repeat([1.0, 1.0, -1.0, -1.0], n_sleepers)

    def pad(values: np.ndarray) -> sp.coo_matrix:
        # Pad i couples rail node i e and sleeper i with its own k1_i or eta1_i.
        return sp.coo_matrix((pad_sign * np.tile(values, 4), (pad_rows, pad_cols)), shape)

    sleeper_masses = sp.coo_matrix((masses, (sleeper_dofs, sleeper_dofs)), shape)
    return RingMesh(
        passage=passage,
        elements_per_span=elements_per_span,
        n_sleepers=n_sleepers,
        element_length=h,
        mass=(m_rail + sleeper_masses).tocsc(),
        damping=pad(pad_c).tocsc(),
        stiffness=(k_rail + pad(pad_k)).tocsc(),
        sleeper_dofs=sleeper_dofs,
        rail_dofs=rail_dofs,
        sleeper_mass=masses,
        pad_stiffness=pad_k,
        pad_damping=pad_c,
        timoshenko=timoshenko,
    )
