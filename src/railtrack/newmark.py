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
from .foundations import Foundation

__all__ = ["reference_law", "CondensedSystem", "static_state", "NewmarkStepper"]


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


def static_state(
    mesh: RingMesh, foundation: Foundation, k0: float, load: np.ndarray, tol: float, iterations: int
) -> np.ndarray:
    """Static equilibrium K u + U f(U^T u, 0) = P with the wheels frozen [m]."""
    system = CondensedSystem(mesh.stiffness + k0 * _sleeper_projector(mesh), mesh.sleeper_dofs)
    free = system.lu.solve(load)
    zero = np.zeros(mesh.n_sleepers)

    def remainder(w):
        slope, _ = foundation.tangent(w, zero)
        return foundation.force(w, zero) - k0 * w, np.asarray(slope, float) - k0

    _, force = system.solve_sleepers(free[mesh.sleeper_dofs], remainder, zero, tol, iterations)
    return free - system.response @ force


class NewmarkStepper:
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
        self.system = CondensedSystem(
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
