"""Newmark steps of the finite-element ring, with the nonlinearity condensed on the sleepers.

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

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .fem import RingMesh
from .laws import NonFiniteLawError, describe_law, evaluate_law, instability_hint
from ..model.foundations import Foundation

__all__ = [
    "NonFiniteLawError",
    "describe_law",
    "instability_hint",
    "evaluate_law",
    "reference_law",
    "CondensedSystem",
    "static_state",
    "NewmarkStepper",
]


def reference_law(foundation) -> tuple[float, float]:
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


class CondensedSystem:
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
        Returns (w, g).

        Raises
        ------
        RuntimeError
            If Newton does not converge, its Jacobian is singular, or the
            iterate stops being finite.
        """
        w = free - self.influence @ guess_force
        for _ in range(max_iterations + 1):
            force, slope = remainder(w)
            mismatch = w - free + self.influence @ force
            error = float(np.max(np.abs(mismatch)))
            if error <= tol:
                return w, force
            if not np.isfinite(error):
                raise RuntimeError(
                    "Newton on the sleeper displacements diverged: its mismatch is not finite "
                    f"(the free response reached {np.max(np.abs(free)):.3g} m)"
                )
            jacobian = self.identity + self.influence * slope[None, :]
            try:
                w = w - np.linalg.solve(jacobian, mismatch)
            except np.linalg.LinAlgError:
                raise RuntimeError(
                    "Newton on the sleeper displacements stopped: its Jacobian I + S diag(d) is "
                    "singular, the foundation's tangent d = df/dw + (2/dt) df/dw' - (k0 + (2/dt) c0) "
                    f"reaching {np.min(slope):.3g} N/m cancels the ring's stiffness"
                ) from None
        raise RuntimeError(
            f"Newton on the sleeper displacements did not converge in {max_iterations} "
            f"iterations (mismatch {error:.2e} m > {tol:.2e} m): raise max_newton_iterations, "
            "or check that the foundation law is smooth enough where the sleepers are"
        )


def _sleeper_projector(mesh: RingMesh, weights=1.0) -> sp.csc_matrix:
    """U diag(weights) U^T: the reference law (k0, c0) on the sleeper diagonal.

    `weights` is one value for every sleeper or one per sleeper (a cell,
    `railtrack.timedomain.ring_cell`).
    """
    dofs = mesh.sleeper_dofs
    values = np.array(np.broadcast_to(np.asarray(weights, dtype=float), dofs.shape))
    return sp.csc_matrix((values, (dofs, dofs)), shape=(mesh.n_dofs, mesh.n_dofs))


def static_state(
    mesh: RingMesh, foundation: Foundation, k0: float, load: np.ndarray, tol: float, iterations: int
) -> np.ndarray:
    """Static equilibrium K u + U f(U^T u, 0) = P with the wheels frozen [m].

    `k0` is one reference stiffness [N/m] or one per sleeper (a cell).
    """
    system = CondensedSystem(mesh.stiffness + _sleeper_projector(mesh, k0), mesh.sleeper_dofs)
    free = system.lu.solve(load)
    zero = np.zeros(mesh.n_sleepers)

    def remainder(w):
        force, slope, _ = evaluate_law(foundation, w, zero)
        return force - k0 * w, slope - k0

    _, force = system.solve_sleepers(free[mesh.sleeper_dofs], remainder, zero, tol, iterations)
    return free - system.response @ force


class NewmarkStepper:
    """Newmark steps of the ring: average acceleration, or HHT-alpha with ``hht_alpha``.

    With u' and u'' at the end of a step linear in u_{n+1}, a step is
    ``A u_{n+1} + U g = b``.  For average acceleration (gamma = 1/2,
    beta = 1/4; Newmark 1959), A = K + (2/dt) C + (4/dt^2) M (reference
    foundation included) and b from the state at the start of the step and
    the wheel loads at its end.  With ``hht_alpha`` = alpha in (0, 1/3] the
    step is Hilber, Hughes & Taylor's (1977): the equation of motion holds
    at t_{n+1} - alpha dt for the stiffness, damping, foundation and load
    terms, gamma = 1/2 + alpha, beta = (1 + alpha)^2 / 4; it stays
    unconditionally stable and second-order accurate, and damps the modes
    the step does not resolve (spectral radius (1 - alpha) / (1 + alpha) as
    omega dt -> inf) while a resolved mode loses about alpha (omega dt)^4 / 10
    of its amplitude per step (1e-6 at alpha = 0.1, omega dt = 0.1).  The reference (k0, c0)
    is one pair of floats or a pair of arrays, one entry per sleeper (a
    cell); `constant`, loads that do not move (a cell's self-weight, shape
    (n_dofs,)) [N].
    """

    def __init__(self, mesh, foundation, reference, dt, loads, tol, iterations, constant=None,
                 hht_alpha=0.0):
        self.k0, self.c0 = reference
        alpha = float(hht_alpha)
        if not 0.0 <= alpha <= 1.0 / 3.0:
            raise ValueError("hht_alpha must be a number in [0, 1/3] (HHT-alpha's alpha); "
                             f"got {hht_alpha!r}")
        gamma, beta = 0.5 + alpha, 0.25 * (1.0 + alpha) ** 2
        # u' at the end of a step is gain u_{n+1} - (the `offset` of the state at its start).
        self.gain, self.alpha = gamma / (beta * dt), alpha
        self.rates = (gamma / beta - 1.0, dt * (0.5 * gamma / beta - 1.0))
        self.newmark = (gamma, beta)
        stiffness = mesh.stiffness + _sleeper_projector(mesh, self.k0)
        damping = mesh.damping + _sleeper_projector(mesh, self.c0)
        mass = mesh.mass
        inertia = 1.0 / ((1.0 - alpha) * beta * dt**2)   # A's mass factor, 4/dt^2 at alpha = 0
        self.system = CondensedSystem(
            stiffness + self.gain * damping + inertia * mass, mesh.sleeper_dofs
        )
        # One sparse product of [u; u'; u''] gives b without the loads.  At
        # alpha = 0 the blocks are those of average acceleration exactly.
        if alpha == 0.0:
            blocks = [(4.0 / dt**2) * mass + (2.0 / dt) * damping, (4.0 / dt) * mass + damping, mass]
        else:
            ratio = alpha / (1.0 - alpha)   # the start of the step's share, over the end's
            blocks = [inertia * mass + self.gain * damping - ratio * stiffness,
                      inertia * dt * mass + (self.gain * dt - 1.0 - ratio) * damping,
                      inertia * dt**2 * (0.5 - beta) * mass
                      + (self.gain * dt**2 * (0.5 - beta) - dt * (1.0 - gamma)) * damping]
        self.history = sp.hstack(blocks).tocsr()
        self.mesh, self.foundation, self.dt = mesh, foundation, dt
        self.load_dofs, self.load_values = loads
        self.tol, self.iterations = tol, iterations
        self.force = np.zeros(mesh.n_sleepers)
        self.constant = constant

    def start(self, u, v) -> None:
        """Take the foundation's remainder g of the initial state (u, u') [N] for HHT, whose first
        step needs it; average acceleration keeps g = 0 as Newton's first guess."""
        if self.alpha == 0.0:
            return
        w, rate = u[self.mesh.sleeper_dofs], v[self.mesh.sleeper_dofs]
        force, _, _ = evaluate_law(self.foundation, w, rate)
        self.force = force - self.k0 * w - self.c0 * rate

    def _remainder(self, offset: np.ndarray):
        """g(w) = f(w, w') - k0 w - c0 w' and dg/dw, with w' = gain w - offset."""
        gain, foundation = self.gain, self.foundation

        def remainder(w):
            rate = gain * w - offset
            force, slope, viscosity = evaluate_law(foundation, w, rate)
            return (force - self.k0 * w - self.c0 * rate,
                    slope - self.k0 + gain * (viscosity - self.c0))

        return remainder

    def offset(self, u, v, a, dofs):
        """gain u_n - u'_{n+1} + gain u_{n+1} at `dofs`: what the end's rate needs of the start."""
        if self.alpha == 0.0:
            return (2.0 / self.dt) * u[dofs] + v[dofs]
        return self.gain * u[dofs] + self.rates[0] * v[dofs] + self.rates[1] * a[dofs]

    def right_hand_side(self, u, v, a) -> np.ndarray:
        """b without the moving loads: the history, the constant loads and, for HHT, the
        foundation's remainder g at the start of the step [N]."""
        rhs = self.history @ np.concatenate([u, v, a])
        if self.alpha != 0.0:
            ratio = self.alpha / (1.0 - self.alpha)
            rhs[self.mesh.sleeper_dofs] -= ratio * self.force
            if self.constant is not None:
                rhs += ratio * self.constant
        if self.constant is not None:
            rhs += self.constant
        return rhs

    def finish(self, u, v, a, u_next):
        """(u, u', u'') at the end of the step from u_{n+1}."""
        dt = self.dt
        if self.alpha == 0.0:
            increment = u_next - u
            a_next = (4.0 / dt**2) * increment - (4.0 / dt) * v - a
            return u_next, (2.0 / dt) * increment - v, a_next
        gamma, beta = self.newmark
        a_next = (u_next - u - dt * v - dt**2 * (0.5 - beta) * a) / (beta * dt**2)
        return u_next, v + dt * ((1.0 - gamma) * a + gamma * a_next), a_next

    def step(self, u, v, a, load_index: int):
        """State (u, u', u'') at the end of a step whose end has loads `load_index`."""
        sleepers = self.mesh.sleeper_dofs
        rhs = self.right_hand_side(u, v, a)
        np.add.at(rhs, self.load_dofs[load_index], self.load_values[load_index])
        if self.alpha != 0.0:
            before = (load_index - 1) % len(self.load_dofs)
            ratio = self.alpha / (1.0 - self.alpha)
            np.add.at(rhs, self.load_dofs[before], ratio * self.load_values[before])
        free = self.system.lu.solve(rhs)
        remainder = self._remainder(self.offset(u, v, a, sleepers))
        _, self.force = self.system.solve_sleepers(
            free[sleepers], remainder, self.force, self.tol, self.iterations
        )
        return self.finish(u, v, a, free - self.system.response @ self.force)
