"""The finite-element ring linearised about a periodic solution, over one span time.

The linearisation behind `railtrack.timedomain.monodromy`: the Newmark step
map of the ring of `railtrack.timedomain.simulation`, with the foundation's
tangent k(t) = df/dw, c(t) = df/dw' evaluated along a harmonic-balance
`Solution`, propagated over one span time L / v and shifted back one sleeper.

The step is the one `railtrack.timedomain.newmark.NewmarkStepper` takes
(average acceleration, gamma = 1/2, beta = 1/4; the same M, C, K, reference
law and time step), differentiated: with u' and u'' at the end of a step
linear in u_{n+1},

    (K + (2/dt) C_{n+1} + (4/dt^2) M + U diag(k_{n+1}) U^T) du_{n+1}
        = [(4/dt^2) M + (2/dt) C_{n+1}] du_n + [(4/dt) M + C_{n+1}] du'_n + M du''_n,

where C_{n+1} = C + U diag(c_{n+1}) U^T and U selects the sleepers; sleeper i
sees k, c of w_i(t) = w_0(t - i L / v), the solution's travelling wave.  The
acceleration is eliminated by the equation of motion at the start, so the
state is (du, du'), of size 2 n_dofs.

Span symmetry: the solution moved on by one span time L / v is itself moved
along the ring by one sleeper, x(t + L/v) = S x(t).  So the map Phi over
[0, L/v] followed by the shift S^-1 back, G = S^-1 Phi, is the same for every
span, and the period map of a ring of one wagon (N_s sleepers) is G^N_s:
the multipliers are mu = nu^N_s, nu the eigenvalues of one dense
2 n_dofs x 2 n_dofs matrix built in steps_per_period / N_s steps.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla

from .fem import RingMesh, ring_mesh, sleepers_on_ring
from .newmark import NewmarkStepper, evaluate_law, reference_law
from .timestep import check_steps_per_period
from ..model.foundations import as_foundation
from ..model.passage import Passage
from ..model.train import Train

__all__ = ["RingSpanMap", "ring_span_map"]


@dataclass(frozen=True, eq=False)
class RingSpanMap:
    """The linearised ring's map over one span time, shifted back one sleeper (`ring_span_map`).

    Attributes
    ----------
    matrix : ndarray, shape (2 n_dofs, 2 n_dofs)
        G = S^-1 Phi acting on the state (du, du') at t = 0 [m, rad; m/s, rad/s].
    mesh : RingMesh
        The ring (its train the solution's, tiled `wagons` times).
    wagons : int
    steps_per_span : int
        Newmark steps per span time L / v.
    dt : float
        Time step [s].
    """

    matrix: np.ndarray
    mesh: RingMesh
    wagons: int
    steps_per_span: int
    dt: float

    @property
    def sleepers_per_wagon(self) -> int:
        """N_s = H / L."""
        return self.mesh.n_sleepers // self.wagons

    def shift(self, state: np.ndarray, sleepers: int) -> np.ndarray:
        """S^sleepers applied to (du, du') (rows): the state moved that many sleepers on [-]."""
        n, e = self.mesh.n_dofs, self.mesh.elements_per_span
        nodes, ring = self.mesh.n_nodes, self.mesh.n_sleepers
        node = np.arange(nodes)
        source = np.empty(n, dtype=int)      # new[i] = old[source[i]]
        source[0:2 * nodes:2] = 2 * ((node - sleepers * e) % nodes)
        source[1:2 * nodes:2] = source[0:2 * nodes:2] + 1
        source[2 * nodes:] = 2 * nodes + (np.arange(ring) - sleepers) % ring
        return state[np.concatenate([source, n + source])]

    def period_map(self) -> np.ndarray:
        """The monodromy matrix W G^N_s over T = H / v, shape (2 n_dofs, 2 n_dofs)."""
        power = np.linalg.matrix_power(self.matrix, self.sleepers_per_wagon)
        return self.shift(power, self.sleepers_per_wagon)


def _ring(solution, wagons: int, elements_per_span: int, steps_per_period: int | None):
    """The ring of `wagons` tiled wagons, its steps per span, and the checked arguments."""
    for name, value in (("wagons", wagons), ("elements_per_span", elements_per_span)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
            raise ValueError(f"{name} must be an integer >= 1; got {value!r}")
    if not getattr(solution, "converged", False):
        raise ValueError("the solution has not converged: its linearisation would be meaningless "
                         f"({getattr(solution, 'message', 'no message')})")
    train, length = solution.train, float(solution.train.wagon_length)
    positions = (length * np.arange(wagons)[:, None] + np.asarray(train.axle_positions)).ravel()
    tiled = Train(wagons * length, positions, np.tile(train.axle_loads, wagons), train.speed)
    passage = Passage(solution.track, tiled)
    ring = sleepers_on_ring(passage)
    steps = 80 * ring if steps_per_period is None else steps_per_period
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)):
        raise ValueError(f"steps_per_period must be an integer; got {steps!r}")
    check_steps_per_period(passage, int(steps))
    return ring_mesh(passage, int(elements_per_span)), int(steps) // ring


def ring_span_map(solution, *, wagons: int = 1, elements_per_span: int = 4,
                  steps_per_period: int | None = None) -> RingSpanMap:
    """The span map G = S^-1 Phi of the ring linearised about `solution` (module docstring).

    Parameters
    ----------
    solution : railtrack.Solution
        A converged periodic solution; its track's H / L must be an integer.
    wagons : int
        Wagons on the ring (the train tiled into one of length n H).
    elements_per_span : int
        Hermite elements per sleeper span.
    steps_per_period : int or None
        Newmark steps over the ring's period n H / v, as for
        `railtrack.check_stability` with the same `wagons` (a multiple of the
        n H / L sleepers on the ring); None: 80 per sleeper on the ring, its default.

    Returns
    -------
    RingSpanMap

    Raises
    ------
    ValueError
        If the solution has not converged, H / L is not an integer or
        `steps_per_period` is not a multiple of the ring's sleepers (or too few).

    Examples
    --------
    >>> from railtrack import LinearFoundation, Track, Train, solve
    >>> s = solve(Track.paper(), Train.paper(), LinearFoundation.paper())
    >>> span = ring_span_map(s, elements_per_span=1, steps_per_period=90)
    >>> span.matrix.shape, span.steps_per_span    # 30 sleepers, 30 rail nodes
    ((180, 180), 3)
    """
    mesh, steps = _ring(solution, wagons, elements_per_span, steps_per_period)
    passage, foundation = mesh.passage, as_foundation(solution.foundation)
    span_time = float(passage.sleeper_spacing) / float(passage.speed)
    dt = span_time / steps
    k0, c0 = reference_law(foundation)
    stepper = NewmarkStepper(mesh, foundation, (k0, c0), dt, (None, None), 0.0, 0)

    # Tangent of the law at every step end along the travelling wave [N/m], [N s/m].
    times = dt * np.arange(steps + 1)[:, None] - span_time * np.arange(mesh.n_sleepers)[None, :]
    w, rate = solution.sleeper_displacement(times), solution.sleeper_velocity(times)
    _, stiffness, damping = evaluate_law(foundation, w.ravel(), rate.ravel())
    stiffness, damping = (np.broadcast_to(x, w.size).reshape(w.shape) for x in (stiffness, damping))

    u, v = tangent_flow(stepper, stiffness, damping, (k0, c0), dt)
    span = RingSpanMap(np.vstack([u, v]), mesh, int(wagons), steps, dt)
    return RingSpanMap(span.shift(span.matrix, -1), mesh, int(wagons), steps, dt)


def tangent_flow(stepper, stiffness: np.ndarray, damping: np.ndarray, reference, dt: float):
    """Unit disturbances carried by Newmark through the tangent law along the orbit.

    `stiffness`, `damping` : (steps + 1, sleepers) tangent of the law at every
    step end [N/m], [N s/m]; `reference` the (k0, c0) the stepper's matrices
    hold.  Starts from the identity in (u, v) and returns (u, v) after the
    steps, each (dofs, 2 dofs): the columns of the map over those steps.
    """
    mesh, system, history = stepper.mesh, stepper.system, stepper.history
    sleepers, (k0, c0) = mesh.sleeper_dofs, reference
    size = mesh.n_dofs
    u = np.hstack([np.eye(size), np.zeros((size, size))])
    v = np.hstack([np.zeros((size, size)), np.eye(size)])
    force = -(mesh.stiffness @ u + mesh.damping @ v)     # M u'' = -C_0 u' - K_0 u at t = 0
    force[sleepers] -= stiffness[0][:, None] * u[sleepers] + damping[0][:, None] * v[sleepers]
    a = spla.splu(mesh.mass.tocsc()).solve(force)
    for step in range(1, stiffness.shape[0]):
        extra = damping[step] - c0
        rhs = history @ np.vstack([u, v, a])
        rhs[sleepers] += extra[:, None] * ((2.0 / dt) * u[sleepers] + v[sleepers])
        free = system.lu.solve(rhs)
        change = stiffness[step] - k0 + (2.0 / dt) * extra
        on_sleepers = np.linalg.solve(system.identity + system.influence * change[None, :],
                                      free[sleepers])
        u_next = free - system.response @ (change[:, None] * on_sleepers)
        increment = u_next - u
        a = (4.0 / dt**2) * increment - (4.0 / dt) * v - a
        v = (2.0 / dt) * increment - v
        u = u_next
    return u, v
