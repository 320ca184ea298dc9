"""The nodal state of the finite-element ring at t = 0, from a harmonic-balance solution.

`railtrack.simulate_time_domain` can start from a periodic solution instead
of the static state, to ask whether the track stays on it
(`railtrack.studies.stability`).  The state is read off the Fourier series at t = 0
(a wagon's first axle above sleeper 0):

* rail deflection at node x_j = j h: ``solution.rail_displacement(0, x_j)``
  (eq. 6 and `railtrack.equations.rail_field`), its velocity the same series with
  coefficients i omega_n r_n(x_j);
* rail rotation dw/dx: the rail field has coefficients of w and w'' only, so
  the slope is a central difference of the series over +-delta and +-2 delta
  combined by Richardson's rule (`SLOPE_STEP`).  w'' is continuous and w'''
  jumps only under a point force (a wheel, a pad), where the symmetric
  difference still cancels the delta^2 term's odd part, so the error is
  O(delta^3) there and O(delta^4) elsewhere: at delta = L / 600 it is below
  1e-12 rad on the paper's track (against slopes of ~1e-3 rad), far under
  the ring's own discretization error;
* sleeper k at x = k L: w(-k L / v) and w'(-k L / v), for sleeper k repeats
  sleeper 0's history k L / v later.

The ring may be several wagons long (a train of n wagons tiled into one
"super-wagon" of length n H): a solution periodic over H is periodic over
n H too, so the series seeds that ring as well.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla

from .fem import RingMesh, wheel_load_entries
from .newmark import evaluate_law
from ..equations.rail_field import rail_field_coefficients

__all__ = [
    "SLOPE_STEP",
    "ring_state_from_solution",
    "check_ring_state",
    "consistent_acceleration",
    "initial_state",
]

SLOPE_STEP = 1.0 / 600.0
"""Step delta of the slope's central difference, as a fraction of the sleeper spacing L [-]."""


def _same_track(mesh: RingMesh, solution) -> None:
    """Refuse a solution of another track, speed or train than the ring's (tiled trains allowed)."""
    ring, solved = mesh.passage, solution.passage
    if ring.track != solved.track or float(ring.speed) != float(solved.speed):
        raise ValueError("the solution must be for the ring's track and speed; got "
                         f"{solved.track} at {float(solved.speed):g} m/s for a ring of "
                         f"{ring.track} at {float(ring.speed):g} m/s")
    n = int(round(float(ring.wagon_length) / float(solved.wagon_length)))
    # n wagons tiled: axles k H + d_j (k-major, so increasing), loads repeated.
    offsets = (float(solved.wagon_length) * np.arange(n)[:, None]
               + np.asarray(solved.axle_positions)[None, :]).ravel()
    tiled = (n >= 1 and np.isclose(float(ring.wagon_length), n * float(solved.wagon_length))
             and len(ring.axle_positions) == offsets.size
             and np.allclose(ring.axle_positions, offsets, rtol=0, atol=1e-9)
             and np.allclose(ring.axle_loads, np.tile(solved.axle_loads, n)))
    if not tiled:
        raise ValueError("the ring's train must be the solution's train, or n of its wagons "
                         f"tiled into one of length n H; got {ring.train} for a solution of {solved.train}")


def ring_state_from_solution(mesh: RingMesh, solution) -> tuple[np.ndarray, np.ndarray]:
    """Displacements u and velocities u' of every ring DOF at t = 0 from a `Solution`.

    Parameters
    ----------
    mesh : RingMesh
        The ring; its track and speed must be the solution's, its train the
        solution's or n of its wagons tiled (`railtrack.studies.stability.tiled_train`).
    solution : railtrack.Solution
        A periodic solution (harmonic balance), any number of harmonics.

    Returns
    -------
    u, v : ndarray, shape (mesh.n_dofs,)
        Deflections [m] and rotations dw/dx [rad]; their rates [m/s], [rad/s].

    Examples
    --------
    >>> from railtrack import Passage, LinearFoundation, solve
    >>> from railtrack.timedomain.fem import ring_mesh
    >>> passage = Passage.paper()
    >>> solution = solve(passage.track, passage.train, LinearFoundation.paper())
    >>> u, v = ring_state_from_solution(ring_mesh(passage, 2), solution)
    >>> round(1e3 * float(u[ring_mesh(passage, 2).sleeper_dofs[0]]), 3)   # w(0) [mm]
    -1.049
    """
    _same_track(mesh, solution)
    passage, omega, c = solution.passage, solution.frequencies, solution.coefficients
    x = mesh.element_length * np.arange(mesh.n_nodes)
    delta = SLOPE_STEP * float(passage.sleeper_spacing)
    shifts = np.array([0.0, -delta, delta, -2.0 * delta, 2.0 * delta])
    # One call for all 5 n_nodes offsets: coefficients r_n(x) of the rail [m].
    r = rail_field_coefficients(passage, omega, c, (x[None, :] + shifts[:, None]).ravel())[0]
    r = r.reshape(shifts.size, x.size, omega.size)
    values = np.stack([r.sum(axis=-1).real, (r * (1j * omega)).sum(axis=-1).real])  # (2, 5, X)
    # Richardson: (4 D(delta) - D(2 delta)) / 3 with D the central difference.
    slope = (4.0 * (values[:, 2] - values[:, 1]) / (2.0 * delta)
             - (values[:, 4] - values[:, 3]) / (4.0 * delta)) / 3.0
    u, v = np.zeros(mesh.n_dofs), np.zeros(mesh.n_dofs)
    for state, k in ((u, 0), (v, 1)):
        state[0:2 * mesh.n_nodes:2] = values[k, 0]
        state[1:2 * mesh.n_nodes:2] = slope[k]
    delays = -float(passage.sleeper_spacing) * np.arange(mesh.n_sleepers) / float(passage.speed)
    u[mesh.sleeper_dofs] = solution.sleeper_displacement(delays)
    v[mesh.sleeper_dofs] = solution.sleeper_velocity(delays)
    return u, v


def check_ring_state(mesh: RingMesh, state) -> tuple[np.ndarray, np.ndarray]:
    """An explicit start (u, v) as two finite float arrays of shape (n_dofs,), or ValueError."""
    try:
        u, v = (np.array(part, dtype=float) for part in state)
    except (TypeError, ValueError):
        raise ValueError("start must be 'static', 'rest', a railtrack.Solution or a pair (u, v) of "
                         f"arrays; got {type(state).__name__}") from None
    for name, part in (("u", u), ("v", v)):
        if part.shape != (mesh.n_dofs,) or not np.all(np.isfinite(part)):
            raise ValueError(f"start {name} must be a finite array of shape ({mesh.n_dofs},) "
                             f"(the ring's DOFs); got shape {part.shape}")
    return u, v


def _loads_at_rest(mesh: RingMesh, constant: np.ndarray | None) -> np.ndarray:
    """P(0): the wheels at their t = 0 places, plus the constant loads (self-weight) if any [N]."""
    dofs, values = wheel_load_entries(mesh, [0.0])
    load = np.zeros(mesh.n_dofs)
    np.add.at(load, dofs[0], values[0])
    if constant is not None:
        load += constant
    return load


def consistent_acceleration(mesh: RingMesh, foundation, u: np.ndarray, v: np.ndarray,
                            constant: np.ndarray | None = None) -> np.ndarray:
    """u'' at t = 0 from the equation of motion M u'' = P(0) - C u' - K u - U f [m/s^2].

    Newmark's average-acceleration step uses u'' at the start of the step;
    an acceleration inconsistent with (u, u') would be a spurious impulse.
    `constant` adds loads that do not move (a cell's self-weight) [N].
    """
    load = _loads_at_rest(mesh, constant)
    sleepers = mesh.sleeper_dofs
    force, _, _ = evaluate_law(foundation, u[sleepers], v[sleepers])
    load[sleepers] -= force
    load -= mesh.damping @ v + mesh.stiffness @ u
    return spla.splu(mesh.mass.tocsc()).solve(load)


def initial_state(mesh: RingMesh, foundation, start, k0: float, tol: float, iterations: int,
                  constant: np.ndarray | None = None):
    """(u, u', u'') of the ring at t = 0 for a `start` of `simulate_time_domain`.

    ``"static"``: static equilibrium under the wheels at t = 0, at rest;
    ``"rest"``: the undeformed track with the wheels suddenly applied;
    a `Solution`: its state at t = 0 (`ring_state_from_solution`); a pair
    (u, v): that state.  The acceleration is the one the equation of motion
    gives (zero for the static state).  `constant` adds loads that do not
    move (a cell's self-weight) [N]; `k0` may be one value per sleeper.
    """
    from .newmark import NonFiniteLawError, static_state

    if isinstance(start, str):
        if start not in ("static", "rest"):
            raise ValueError(f"start must be 'static', 'rest', a Solution or (u, v); got {start!r}")
        load = _loads_at_rest(mesh, constant)
        zero = np.zeros(mesh.n_dofs)
        if start == "rest":
            # The wheels are put on the track at rest: it starts accelerating.
            return zero, zero.copy(), spla.splu(mesh.mass.tocsc()).solve(load)
        where = ", in the static state with the wheels at t = 0"
        try:
            u = static_state(mesh, foundation, k0, load, tol, iterations)
        except NonFiniteLawError as error:
            raise NonFiniteLawError(f"{error}{where}") from None
        except RuntimeError as error:
            raise RuntimeError(f"{error}{where}") from None
        return u, zero.copy(), zero.copy()
    if hasattr(start, "coefficients") and hasattr(start, "passage"):
        u, v = ring_state_from_solution(mesh, start)
    else:
        u, v = check_ring_state(mesh, start)
    return u, v, consistent_acceleration(mesh, foundation, u, v, constant)
