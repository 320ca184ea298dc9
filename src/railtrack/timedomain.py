"""An independent check of the semi-analytical method: finite elements in time.

`simulate_time_domain` integrates the ring model of `railtrack.fem` (rail,
eq. 1; sleepers, eq. 4; pads, eq. 5; the foundation law f(w, w') of
eqs. 22, 24 or 25 under every sleeper) step by step in time with the
average-acceleration Newmark scheme (Newmark 1959: gamma = 1/2,
beta = 1/4), from the static state, until the sleeper's response over one
period T = H / v repeats the previous period's.  Nothing is shared with the
harmonic-balance solver but the `Track` and the foundation object.

Why average acceleration and not HHT-alpha: it is unconditionally stable,
second-order accurate and adds no numerical damping.  The unresolved
high-frequency rail modes it leaves undamped carry almost no motion at the
sleepers, and the pad dashpots damp those that do, so the sleeper response
settles to its period without numerical dissipation (see the tests).

Why it is fast: the foundation is the only nonlinearity and it acts on one
DOF per sleeper.  The foundation's linearization (k0, c0) goes into the
linear effective matrix, which is factored once.  With Z = A^-1 U, where U
selects the sleeper DOFs, every step is one sparse back-substitution for the
"free" response u_free = A^-1 b plus a Newton iteration on the sleepers
alone, whose Jacobian ``I + S diag(d)`` (S = U^T Z, d the change of the
tangent from k0 + (2/dt) c0) is n_sleepers x n_sleepers: the Schur
complement of the sleeper block, equivalently the Woodbury update of A^-1.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .fem import RingMesh, ring_mesh, wheel_load_entries
from .foundations import Foundation, as_foundation
from .track import Track

__all__ = ["TimeDomainSolution", "simulate_time_domain"]


@dataclass(frozen=True, eq=False)
class TimeDomainSolution:
    """Periodic steady response of the FE ring found by `simulate_time_domain`.

    Attributes
    ----------
    times : ndarray, shape (steps_per_period,)
        One period, t = 0, dt, ..., T - dt [s]; t = 0 when a front wheel is
        above sleeper 0.
    sleeper_displacement : ndarray, shape (steps_per_period,)
        w(t) of sleeper 0 over the last period [m], positive upward.
    rail_displacement : ndarray, shape (steps_per_period,)
        Rail deflection above sleeper 0 over the last period [m].
    sleeper_displacements : ndarray, shape (steps_per_period, n_sleepers)
        All sleepers over the last period [m]; in the steady state sleeper i
        lags sleeper 0 by i L / v.
    periods : int
        Periods integrated.
    converged : bool
        Whether the last period's sleeper-0 response differed from the one
        before by at most ``tol`` times its peak.
    period_change : ndarray, shape (periods - 1,)
        max |w_k - w_{k-1}| / max |w_k| between consecutive periods k [-].
    elements_per_span : int
    steps_per_period : int
    track : Track
    foundation : object
    """

    times: np.ndarray
    sleeper_displacement: np.ndarray
    rail_displacement: np.ndarray
    sleeper_displacements: np.ndarray
    periods: int
    converged: bool
    period_change: np.ndarray
    elements_per_span: int
    steps_per_period: int
    track: Track | None = None
    foundation: Any = None


def _require_count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValueError(f"{name} must be an integer >= 1; got {value!r}")
    return int(value)


def _reference_law(foundation) -> tuple[float, float]:
    """(k0, c0) put into the factored matrix: the foundation's linearization.

    Any value is exact (the Newton step on the sleepers corrects for the
    difference); k0 > 0 only keeps the static matrix of a free-floating ring
    non-singular, hence the fallback for laws with no stiffness at rest.
    """
    stiffness, damping = (float(value) for value in foundation.linearization())
    if not np.isfinite(stiffness) or stiffness <= 0.0:
        stiffness = 1e6  # 1 MN/m, 5 % of the paper's k2
    if not np.isfinite(damping) or damping < 0.0:
        damping = 0.0
    return stiffness, damping


class _CondensedSystem:
    """A factored linear matrix A and its Schur complement S = U^T A^-1 U on the sleepers."""

    def __init__(self, matrix: sp.spmatrix, sleeper_dofs: np.ndarray):
        # A is symmetric positive definite (mass, and pads + reference
        # foundation holding the ring), so a symmetric fill-reducing order
        # without pivoting is safe, and solves ~2x faster than the default.
        self.lu = spla.splu(
            sp.csc_matrix(matrix),
            permc_spec="MMD_AT_PLUS_A",
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
        selector = np.zeros((matrix.shape[0], sleeper_dofs.size))
        selector[sleeper_dofs, np.arange(sleeper_dofs.size)] = 1.0
        self.response = self.lu.solve(selector)  # Z = A^-1 U [m/N]
        self.influence = self.response[sleeper_dofs]  # S = U^T Z [m/N]
        self.sleeper_dofs = sleeper_dofs
        self.identity = np.eye(sleeper_dofs.size)

    def solve_sleepers(
        self,
        free: np.ndarray,
        remainder,
        guess_force: np.ndarray,
        tol: float,
        max_iterations: int,
    ) -> tuple[np.ndarray, np.ndarray]:
        """Newton on w = free - S g(w) for the sleeper displacements w [m].

        `remainder(w)` returns g (the foundation force beyond the reference
        law, N) and its derivative d (N/m); `guess_force` starts the iteration
        (the previous step's g, which changes little over one step).
        Returns (w, g).  Raises RuntimeError if Newton does not converge.
        """
        w = free - self.influence @ guess_force
        for _ in range(max_iterations + 1):
            force, slope = remainder(w)
            mismatch = w - free + self.influence @ force
            if np.max(np.abs(mismatch)) <= tol:
                return w, force
            jacobian = self.identity + self.influence * slope[None, :]
            w = w - np.linalg.solve(jacobian, mismatch)
        raise RuntimeError(
            f"Newton on the sleeper displacements did not converge in {max_iterations} "
            f"iterations (mismatch {np.max(np.abs(mismatch)):.2e} m > {tol:.2e} m)"
        )


def _sleeper_projector(mesh: RingMesh) -> sp.csc_matrix:
    """U U^T: ones on the sleeper diagonal, where the reference law (k0, c0) goes."""
    dofs = mesh.sleeper_dofs
    return sp.csc_matrix((np.ones(dofs.size), (dofs, dofs)), shape=(mesh.n_dofs, mesh.n_dofs))


def _static_state(
    mesh: RingMesh, foundation: Foundation, k0: float, load: np.ndarray, tol: float, iterations: int
) -> np.ndarray:
    """Static equilibrium K u + U f(U^T u, 0) = P with the wheels frozen [m]."""
    system = _CondensedSystem(mesh.stiffness + k0 * _sleeper_projector(mesh), mesh.sleeper_dofs)
    free = system.lu.solve(load)
    zero = np.zeros(mesh.n_sleepers)

    def remainder(w):
        slope, _ = foundation.tangent(w, zero)
        return foundation.force(w, zero) - k0 * w, np.asarray(slope, float) - k0

    _, force = system.solve_sleepers(free[mesh.sleeper_dofs], remainder, zero, tol, iterations)
    return free - system.response @ force


class _NewmarkStepper:
    """Average-acceleration Newmark steps (gamma = 1/2, beta = 1/4; Newmark 1959).

    With u' and u'' at the end of a step linear in u_{n+1}, a step is
    ``A u_{n+1} + U g = b`` with A = K + (2/dt) C + (4/dt^2) M (reference
    foundation included) and b from the state at the start of the step and
    the wheel loads at its end.
    """

    def __init__(self, mesh, foundation, reference, dt, loads, tol, iterations):
        self.k0, self.c0 = reference
        projector = _sleeper_projector(mesh)
        stiffness = mesh.stiffness + self.k0 * projector
        damping = mesh.damping + self.c0 * projector
        mass = mesh.mass
        self.system = _CondensedSystem(
            stiffness + (2.0 / dt) * damping + (4.0 / dt**2) * mass, mesh.sleeper_dofs
        )
        # One sparse product of [u; u'; u''] gives b without the loads.
        self.history = sp.hstack(
            [(4.0 / dt**2) * mass + (2.0 / dt) * damping, (4.0 / dt) * mass + damping, mass]
        ).tocsr()
        self.mesh, self.foundation, self.dt = mesh, foundation, dt
        self.load_dofs, self.load_values = loads
        self.tol, self.iterations = tol, iterations
        self.force = np.zeros(mesh.n_sleepers)

    def _remainder(self, offset: np.ndarray):
        """g(w) = f(w, w') - k0 w - c0 w' and dg/dw, with w' = (2/dt) w - offset."""
        gain, foundation = 2.0 / self.dt, self.foundation

        def remainder(w):
            rate = gain * w - offset
            slope, viscosity = foundation.tangent(w, rate)
            force = foundation.force(w, rate) - self.k0 * w - self.c0 * rate
            derivative = np.asarray(slope, float) - self.k0 + gain * (np.asarray(viscosity, float) - self.c0)
            return force, derivative

        return remainder

    def step(self, u, v, a, load_index: int):
        """State (u, u', u'') at the end of a step whose end has loads `load_index`."""
        dt, sleepers = self.dt, self.mesh.sleeper_dofs
        rhs = self.history @ np.concatenate([u, v, a])
        np.add.at(rhs, self.load_dofs[load_index], self.load_values[load_index])
        free = self.system.lu.solve(rhs)
        remainder = self._remainder((2.0 / dt) * u[sleepers] + v[sleepers])
        _, self.force = self.system.solve_sleepers(
            free[sleepers], remainder, self.force, self.tol, self.iterations
        )
        u_next = free - self.system.response @ self.force
        increment = u_next - u
        a_next = (4.0 / dt**2) * increment - (4.0 / dt) * v - a
        v_next = (2.0 / dt) * increment - v
        return u_next, v_next, a_next


def simulate_time_domain(
    track: Track,
    foundation,
    elements_per_span: int = 8,
    steps_per_period: int = 2400,
    *,
    tol: float = 1e-6,
    max_periods: int = 40,
    start: str = "static",
    newton_tol: float = 1e-11,
    max_newton_iterations: int = 50,
) -> TimeDomainSolution:
    """Periodic steady response of the track by finite elements and Newmark time stepping.

    The ring of `railtrack.fem.ring_mesh` (one wagon length H with periodic
    ends; rail eq. 1, sleepers eq. 4, pads eq. 5) carries the foundation law
    f(w, w') of eqs. (22), (24) or (25) under each sleeper:

        M u'' + C u' + K u + U f(U^T u, U^T u') = P(t),

    with P(t) the consistent loads of the moving wheels.  It is integrated
    with the average-acceleration Newmark scheme (Newmark 1959) and Newton
    iterations on the sleeper DOFs at each step, period after period, until
    sleeper 0's response over a period changes by at most ``tol`` times its
    peak.

    Parameters
    ----------
    track : Track
        Track and train; H / L must be an integer (the number of sleepers on
        the ring).  Trains whose H / L is not an integer are not handled (a
        ring of a common multiple of H and L would be).
    foundation : foundation object or callable
        Any law accepted by `railtrack.as_foundation`.
    elements_per_span : int
        Hermite beam elements per sleeper span, >= 1.
    steps_per_period : int
        Time steps per period T = H / v, >= 1.  A multiple of H / L makes
        the delay L / v between neighbouring sleepers a whole number of steps.
    tol : float
        Relative period-to-period change of sleeper 0's response at which the
        state counts as periodic [-].
    max_periods : int
        Periods integrated at most; ``converged=False`` if `tol` is not met.
    start : {"static", "rest"}
        Initial state: static equilibrium with the wheels at their t = 0
        positions (zero velocity), or the undeformed track at rest with the
        wheels suddenly applied.
    newton_tol : float
        Newton stops when the sleeper equations hold to newton_tol times the
        mean static sleeper deflection [-].
    max_newton_iterations : int
        Newton iterations per step at most.

    Returns
    -------
    TimeDomainSolution

    Raises
    ------
    ValueError
        If H / L is not an integer, or an argument is out of range.
    RuntimeError
        If Newton fails at some step.

    Examples
    --------
    >>> from railtrack import Track, LinearFoundation
    >>> result = simulate_time_domain(Track.paper(), LinearFoundation.paper(), 2, 480)
    >>> result.converged, round(1e3 * float(result.sleeper_displacement.min()), 2)
    (True, -1.13)
    """
    elements_per_span = _require_count("elements_per_span", elements_per_span)
    steps_per_period = _require_count("steps_per_period", steps_per_period)
    max_periods = _require_count("max_periods", max_periods)
    max_newton_iterations = _require_count("max_newton_iterations", max_newton_iterations)
    for name, value in (("tol", tol), ("newton_tol", newton_tol)):
        if not np.isfinite(value) or value <= 0:
            raise ValueError(f"{name} must be a finite number > 0; got {value!r}")
    if start not in ("static", "rest"):
        raise ValueError(f"start must be 'static' or 'rest'; got {start!r}")
    foundation = as_foundation(foundation)
    mesh = ring_mesh(track, elements_per_span)
    reference = k0, _ = _reference_law(foundation)
    n_steps, dt = steps_per_period, float(track.period) / steps_per_period
    times = dt * np.arange(n_steps)
    loads = wheel_load_entries(mesh, times)

    # Newton's tolerance is relative to the mean static deflection: the load
    # per sleeper 2 Q L / H on the pad and the reference foundation in series.
    scale = float(track.static_load_per_sleeper) * (1.0 / k0 + 1.0 / float(track.pad_stiffness))
    newton_abs = newton_tol * scale

    load = np.zeros(mesh.n_dofs)
    np.add.at(load, loads[0][0], loads[1][0])
    v = np.zeros(mesh.n_dofs)
    if start == "static":
        u = _static_state(mesh, foundation, k0, load, newton_abs, max_newton_iterations)
        a = np.zeros(mesh.n_dofs)
    else:
        # The wheels are put on the track at rest: it starts accelerating.
        u = np.zeros(mesh.n_dofs)
        a = spla.splu(mesh.mass.tocsc()).solve(load)
    stepper = _NewmarkStepper(mesh, foundation, reference, dt, loads, newton_abs, max_newton_iterations)

    record = np.empty((n_steps, mesh.n_sleepers))
    rail = np.empty(n_steps)
    previous: np.ndarray | None = None
    changes: list[float] = []
    converged = False
    for periods in range(1, max_periods + 1):
        for n in range(n_steps):
            record[n] = u[mesh.sleeper_dofs]
            rail[n] = u[mesh.rail_dofs[0]]
            u, v, a = stepper.step(u, v, a, (n + 1) % n_steps)
        current = record[:, 0].copy()
        if previous is not None:
            peak = max(float(np.max(np.abs(current))), np.finfo(float).tiny)
            changes.append(float(np.max(np.abs(current - previous))) / peak)
            if changes[-1] <= tol:
                converged = True
                break
        previous = current

    return TimeDomainSolution(
        times=times,
        sleeper_displacement=record[:, 0].copy(),
        rail_displacement=rail.copy(),
        sleeper_displacements=record.copy(),
        periods=periods,
        converged=converged,
        period_change=np.array(changes),
        elements_per_span=elements_per_span,
        steps_per_period=steps_per_period,
        track=track,
        foundation=foundation,
    )
