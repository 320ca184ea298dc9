"""Per-sleeper outputs of the finite-element ring over its last period.

`railtrack.timedomain.ring_outputs` gives sleeper 0's quantities; a cell of
differing sleepers (issue 19) needs them for every ring sleeper i:

* the rail-seat load k1_i (w_i - w_r,i) + eta1_i (w_i - w_r,i)', positive in
  compression, with w_r,i the rail node above sleeper i;
* the force on its foundation -f_i(w_i, w_i'), positive in compression;
* the rail's bending moment EI w'' (EI psi' for a Timoshenko rail) above
  sleeper i (the mean of the two adjacent elements' end curvatures, as
  `ring_outputs`) and at the mid-span between sleepers i and i + 1, sagging
  positive.

Moments and the pad's compression are linear in the nodal state, so they are
rows of two sparse operators applied once per step (`SleeperRecorder`); the
foundation force is evaluated after the period, one law call per law.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from .fem import RingMesh
from .rail_elements import timoshenko_curvature_weights

__all__ = ["moment_operators", "SleeperRecorder"]


def _curvature(xi: float, h: float, phi: float | None = None) -> np.ndarray:
    """d^2/dx^2 of the Hermite cubics at xi: weights of (w_a, theta_a, w_b, theta_b)
    (psi' of a Timoshenko element of shear parameter `phi`)."""
    if phi is not None:
        return timoshenko_curvature_weights(xi, h, phi)
    return np.array([(-6.0 + 12.0 * xi) / h**2, (-4.0 + 6.0 * xi) / h,
                     (6.0 - 12.0 * xi) / h**2, (-2.0 + 6.0 * xi) / h])


def _element_dofs(first: np.ndarray, n_nodes: int) -> np.ndarray:
    """(w_a, theta_a, w_b, theta_b) DOFs of the elements starting at nodes `first`."""
    second = (first + 1) % n_nodes
    return np.stack([2 * first, 2 * first + 1, 2 * second, 2 * second + 1], axis=-1)


def moment_operators(mesh: RingMesh) -> tuple[sp.csr_matrix, sp.csr_matrix]:
    """Sparse rows giving EI w'' above each sleeper and at each mid-span from u [N m / m].

    Returns
    -------
    above, midspan : scipy.sparse.csr_matrix, shape (n_sleepers, n_dofs)
        Row i of `above` is the moment at x = i L (mean of the curvatures at
        the ends of the two elements meeting there); row i of `midspan` the
        moment at x = (i + 1/2) L, inside an element for an odd
        `elements_per_span`, at a node (the same mean) for an even one.
    """
    e, n, h = mesh.elements_per_span, mesh.n_nodes, mesh.element_length
    ei, phi = float(mesh.passage.rail_bending_stiffness), mesh.shear_parameter
    rows = np.arange(mesh.n_sleepers)
    shape = (mesh.n_sleepers, mesh.n_dofs)

    def node_rows(nodes: np.ndarray) -> sp.csr_matrix:
        left = _element_dofs((nodes - 1) % n, n)
        right = _element_dofs(nodes, n)
        cols = np.concatenate([left, right], axis=1)
        values = 0.5 * ei * np.concatenate([_curvature(1.0, h, phi), _curvature(0.0, h, phi)])
        return sp.csr_matrix((np.tile(values, nodes.size), (np.repeat(rows, 8), cols.ravel())),
                             shape)

    above = node_rows(e * rows)
    element, xi = e // 2, 0.5 * e - e // 2
    if xi == 0.0:
        midspan = node_rows(e * rows + element)
    else:
        cols = _element_dofs(e * rows + element, n)
        midspan = sp.csr_matrix((np.tile(ei * _curvature(xi, h, phi), rows.size),
                                 (np.repeat(rows, 4), cols.ravel())), shape)
    return above, midspan


class SleeperRecorder:
    """Records, step by step, what the per-sleeper outputs need; `outputs` finishes them.

    Four floats per sleeper and step: its velocity, its rail-seat load and
    the two moments (`railtrack.timedomain.runcost` counts them).
    """

    def __init__(self, mesh: RingMesh, steps: int):
        self.mesh = mesh
        above, midspan = moment_operators(mesh)
        self.moments = sp.vstack([above, midspan]).tocsr()
        n = mesh.n_sleepers
        self.sleeper_velocity = np.empty((steps, n))
        self.seat = np.empty((steps, n))
        self.moment = np.empty((steps, 2 * n))

    def record(self, n: int, u: np.ndarray, v: np.ndarray) -> None:
        """Store step n's state (u, u') [m, rad], [m/s, rad/s]."""
        mesh = self.mesh
        sleepers, rail = mesh.sleeper_dofs, mesh.rail_dofs
        self.sleeper_velocity[n] = v[sleepers]
        self.seat[n] = (mesh.pad_stiffness * (u[sleepers] - u[rail])
                        + mesh.pad_damping * (v[sleepers] - v[rail]))
        self.moment[n] = self.moments @ u

    def outputs(self, law, displacements: np.ndarray) -> dict[str, np.ndarray]:
        """The per-sleeper arrays, shape (steps, n_sleepers), given the sleepers' w [m].

        `law` is the ring's foundation (`railtrack.timedomain.ring_cell.RingLaw`
        or one law for every sleeper), called once on the whole record.  The
        arrays are the recorder's own (no copies): record no further step.
        """
        n = self.mesh.n_sleepers
        force = np.asarray(law.force(displacements, self.sleeper_velocity), dtype=float)
        return {
            "rail_seat_loads": self.seat,
            "foundation_forces": 0.0 - np.broadcast_to(force, displacements.shape),  # no -0.0
            "bending_moments_above_sleepers": self.moment[:, :n],
            "bending_moments_midspan": self.moment[:, n:],
        }
