"""The moving wheels on the ring's rail: where they stand and what they load.

The axles of a wagon stand at x = v t - d_j on the ring, modulo H (eq. 9).
Each wheel stands inside one rail element, at xi in [0, 1]; the element's
interpolation of w there (the Hermite cubics, or a Timoshenko element's N_w,
eq. T2) gives the rail's deflection under the wheel and, times -Q_j, the
wheel's consistent (work-equivalent) nodal loads on the element's four
degrees of freedom.  A Timoshenko element adds the local sag g(xi) P under a
point force inside it (`contact_compliance`).  These are shared by the
constant moving loads of `railtrack.timedomain.simulation` and the wheels of
mass of `railtrack.timedomain.ring_wheels`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ..model.passage import Passage
from .rail_elements import (hermite_shape_functions, timoshenko_point_compliance,
                            timoshenko_shape_functions)
from .ring_layout import RingMesh

__all__ = [
    "wheel_positions",
    "wheel_load_entries",
    "contact_shapes",
    "contact_compliance",
    "rail_shapes",
]


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
