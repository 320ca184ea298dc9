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
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from numpy.typing import ArrayLike

from ..model.passage import Passage
from ..model.timoshenko import TimoshenkoRail
from .rail_elements import (beam_element_matrices, hermite_shape_functions, shear_parameter,
                            timoshenko_element_matrices, timoshenko_point_compliance,
                            timoshenko_shape_functions)

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


def wheel_positions(passage: Passage, times: ArrayLike) -> np.ndarray:
    """Positions of the axles of a wagon on the ring, in [0, H) [m], eq. (9).

    The first axle is at x = v t and axle j at d_j behind it, modulo H;
    every other wagon's axles fall on the same ring positions.

    Returns
    -------
    ndarray, shape (len(times), J)
    """
    times = np.atleast_1d(np.asarray(times, dtype=float))
    front = float(passage.speed) * times
    offsets = np.asarray(passage.axle_positions, dtype=float)
    return np.mod(front[:, None] - offsets[None, :], float(passage.wagon_length))


def wheel_load_entries(mesh: RingMesh, times: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Consistent nodal loads of the wheels at each time, as sparse entries.

    Wheel j pushes down with -Q_j; its work-equivalent nodal loads are -Q_j
    times the shape functions (`rail_shapes`) at its position in its element.

    Parameters
    ----------
    mesh : RingMesh
    times : array_like, shape (n_t,)
        [s].

    Returns
    -------
    dofs : ndarray of int, shape (n_t, 4 J)
        Rail DOFs loaded at each time (4 per wheel; may repeat if two wheels
        stand on the same element, so accumulate with ``np.add.at``).
    values : ndarray, shape (n_t, 4 J)
        Nodal forces [N] and moments [N m].
    """
    dofs, shapes = contact_shapes(mesh, times)
    loads = np.asarray(mesh.passage.axle_loads, dtype=float)
    values = -loads[None, :, None] * shapes
    n_t = dofs.shape[0]
    return dofs.reshape(n_t, -1), values.reshape(n_t, -1)


def contact_shapes(mesh: RingMesh, times: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Rail DOFs (n_t, J, 4) and weights N(xi) (n_t, J, 4) under each wheel (`rail_shapes`).

    Shared by `wheel_load_entries` and `railtrack.timedomain.ring_wheels`, so a
    wheel carrying exactly Q loads the rail as the constant force does.
    """
    element, xi = _contact_points(mesh, times)
    following = (element + 1) % mesh.n_nodes
    dofs = np.stack([2 * element, 2 * element + 1, 2 * following, 2 * following + 1], axis=-1)
    return dofs, rail_shapes(mesh, xi)


def _contact_points(mesh: RingMesh, times: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The element under each wheel and the wheel's xi in it, shapes (n_t, J)."""
    x = wheel_positions(mesh.passage, times)
    h = mesh.element_length
    element = np.minimum(np.floor(x / h).astype(int), mesh.n_nodes - 1)
    return element, np.clip(x / h - element, 0.0, 1.0)


def contact_compliance(mesh: RingMesh, times: ArrayLike) -> np.ndarray | None:
    """g(xi) [m/N], shape (n_t, J): a Timoshenko rail's sag under a unit wheel force inside its
    element beyond the element's interpolation (`rail_elements.timoshenko_point_compliance`).

    None for Hermite elements, whose h^3 xi^3 (1 - xi)^3 / (3 EI) is left out.
    """
    if mesh.timoshenko is None:
        return None
    _, xi = _contact_points(mesh, times)
    return timoshenko_point_compliance(xi, mesh.element_length,
                                       mesh.passage.rail_bending_stiffness, mesh.shear_parameter)


def rail_shapes(mesh: RingMesh, xi: ArrayLike) -> np.ndarray:
    """The mesh's element interpolation of w at xi, shape (..., 4): the Hermite cubics, or a
    Timoshenko element's N_w (`rail_elements.timoshenko_shape_functions`, eq. T2)."""
    if mesh.timoshenko is None:
        return hermite_shape_functions(xi, mesh.element_length)
    return timoshenko_shape_functions(xi, mesh.element_length, mesh.shear_parameter)
