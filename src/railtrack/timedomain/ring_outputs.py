"""What the finite-element ring gives a track engineer, from its nodal states.

The time-domain check (`railtrack.simulate_time_domain`) records a few
degrees of freedom of the ring at every step; this module turns them into
the quantities that `railtrack.Solution` gives from harmonic balance:

* the rail deflection at mid-span x = L / 2 (the elements' interpolation);
* the rail's bending moment EI w'' (EI psi' for a Timoshenko rail) above
  sleeper 0 and at mid-span, sagging positive.  At a node the curvature of
  a cubic element jumps where a force acts; the mean of the two elements'
  end values is taken, which is exact for a statically loaded beam with no
  load at that node;
* the rail-seat load k1 (w - w_r) + eta1 (w - w_r)' on sleeper 0, positive in
  compression (as `Solution.rail_seat_load`);
* the force on the foundation -f(w, w'), positive in compression (as
  `Solution.foundation_force`).
"""

from __future__ import annotations

import numpy as np

from .fem import RingMesh, rail_shapes
from .rail_elements import timoshenko_curvature_weights

__all__ = ["watched_dofs", "ring_outputs"]


def _curvature_weights(xi: float, length: float, phi: float | None = None) -> np.ndarray:
    """d^2/dx^2 of the Hermite cubics at xi: weights of (w_a, theta_a, w_b, theta_b) [1/m^2, 1/m]
    (psi' of a Timoshenko element of shear parameter `phi`)."""
    if phi is not None:
        return timoshenko_curvature_weights(xi, length, phi)
    h = length
    return np.array([(-6.0 + 12.0 * xi) / h**2, (-4.0 + 6.0 * xi) / h,
                     (6.0 - 12.0 * xi) / h**2, (-2.0 + 6.0 * xi) / h])


def _nodes(mesh: RingMesh) -> tuple[int, float]:
    """Element holding mid-span and the local coordinate there."""
    per_span = mesh.elements_per_span
    return per_span // 2, 0.5 * per_span - per_span // 2


def watched_dofs(mesh: RingMesh) -> np.ndarray:
    """The DOFs to record at every step: rail nodes around x = 0 and L / 2, sleeper 0."""
    n = mesh.n_nodes
    element, _ = _nodes(mesh)
    nodes = np.array([n - 1, 0, 1, element - 1, element, element + 1, element + 2]) % n
    return np.concatenate([2 * nodes, 2 * nodes + 1, [mesh.sleeper_dofs[0]]])


def _node_moment(u, dof, node, n, h, ei, phi=None):
    """EI w'' at a node: the mean of the curvature at the ends of its two elements."""
    before, after = (node - 1) % n, (node + 1) % n
    left = np.stack([u[..., dof[2 * before]], u[..., dof[2 * before + 1]],
                     u[..., dof[2 * node]], u[..., dof[2 * node + 1]]], axis=-1)
    right = np.stack([u[..., dof[2 * node]], u[..., dof[2 * node + 1]],
                      u[..., dof[2 * after]], u[..., dof[2 * after + 1]]], axis=-1)
    return 0.5 * ei * (left @ _curvature_weights(1.0, h, phi)
                       + right @ _curvature_weights(0.0, h, phi))


def _pad(mesh: RingMesh, name: str) -> float:
    """Sleeper 0's pad k1 [N/m] or eta1 [N s/m]: the mesh's own (a cell's), else the passage's."""
    values = getattr(mesh, name)
    return float(getattr(mesh.passage, name) if values is None else values[0])


def ring_outputs(mesh: RingMesh, foundation, displacements: np.ndarray,
                 velocities: np.ndarray) -> dict[str, np.ndarray]:
    """Mid-span rail, moments, rail-seat load and foundation force from recorded states.

    Parameters
    ----------
    mesh : RingMesh
    foundation : foundation object
        Sleeper 0's law.
    displacements, velocities : ndarray, shape (n_t, len(watched_dofs(mesh)))
        u and u' at the watched DOFs [m, rad], [m/s, rad/s].

    Returns
    -------
    dict of ndarray, shape (n_t,)
        ``rail_displacement_midspan`` [m], ``bending_moment_above_sleeper``
        and ``bending_moment_midspan`` [N m], ``rail_seat_load`` and
        ``foundation_force`` [N].
    """
    watched = watched_dofs(mesh)
    dof = {int(d): i for i, d in enumerate(watched)}
    n, h = mesh.n_nodes, mesh.element_length
    ei, phi = float(mesh.passage.rail_bending_stiffness), mesh.shear_parameter
    element, xi = _nodes(mesh)
    u, v = displacements, velocities
    nodal = np.stack([u[:, dof[2 * element]], u[:, dof[2 * element + 1]],
                      u[:, dof[2 * element + 2]], u[:, dof[2 * element + 3]]], axis=-1)
    midspan = nodal @ rail_shapes(mesh, xi)
    if xi == 0.0:
        moment_mid = _node_moment(u, dof, element, n, h, ei, phi)
    else:
        moment_mid = ei * (nodal @ _curvature_weights(xi, h, phi))
    sleeper = dof[int(mesh.sleeper_dofs[0])]
    w, w_rate = u[:, sleeper], v[:, sleeper]
    compression = w - u[:, dof[0]]
    compression_rate = w_rate - v[:, dof[0]]
    return dict(
        rail_displacement_midspan=midspan,
        bending_moment_above_sleeper=_node_moment(u, dof, 0, n, h, ei, phi),
        bending_moment_midspan=moment_mid,
        rail_seat_load=_pad(mesh, "pad_stiffness") * compression
        + _pad(mesh, "pad_damping") * compression_rate,
        foundation_force=-np.asarray(foundation.force(w, w_rate), dtype=float),
    )
