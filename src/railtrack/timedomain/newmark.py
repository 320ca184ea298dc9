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


class NonFiniteLawError(ValueError):
    """The foundation law returned NaN or infinity; `where` says for which w, w'."""


def describe_law(foundation) -> str:
    """A short name of the law for messages: the callable's name for a wrapped callable."""
    law = getattr(foundation, "law", None)
    if callable(law):
        return f"{type(foundation).__name__}({getattr(law, '__qualname__', repr(law))})"
    text = repr(foundation)
    return text if len(text) <= 100 else text[:97] + "..."


def instability_hint(foundation) -> str:
    """Why a track grows without bound, for messages: the law's linearization at rest."""
    try:
        stiffness, damping = (float(x) for x in foundation.linearization())
        at_rest = f" (at rest k = df/dw = {stiffness:.3g} N/m, c = df/dw' = {damping:.3g} N s/m)"
    except Exception:  # noqa: BLE001 - only decorates a message
        at_rest = ""
    return (
        f"the system is unstable: does the foundation law {describe_law(foundation)}{at_rest} "
        "have a negative stiffness or damping? A stable track needs f(w, w') increasing in w "
        "and in w'"
    )


def evaluate_law(foundation, w: np.ndarray, rate: np.ndarray):
    """f(w, w') [N], df/dw [N/m] and df/dw' [N s/m], refusing non-finite values.

    Raises
    ------
    NonFiniteLawError
        Naming the law, the first sleeper concerned and its w [m], w' [m/s].
    """
    force = np.asarray(foundation.force(w, rate), float)
    slope, viscosity = (np.asarray(value, float) for value in foundation.tangent(w, rate))
    # The common case in one pass; the search for the culprit only on failure
    # (this runs several times per time step).
    if np.isfinite(force).all() and np.isfinite(slope).all() and np.isfinite(viscosity).all():
        return force, slope, viscosity
    for name, value in (("force", force), ("stiffness df/dw", slope), ("damping df/dw'", viscosity)):
        bad = ~np.isfinite(np.broadcast_to(value, np.shape(w)))
        if np.any(bad):
            i = int(np.argmax(bad))
            raise NonFiniteLawError(
                f"the foundation law {describe_law(foundation)} returned a non-finite {name} "
                f"({np.broadcast_to(value, np.shape(w))[i]}) at w = {w[i]:.6g} m, "
                f"w' = {rate[i]:.6g} m/s (sleeper {i}, {int(np.sum(bad))} sleeper(s) in all)"
            )
    return force, slope, viscosity


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
    """Average-acceleration Newmark steps (gamma = 1/2, beta = 1/4; Newmark 1959).

    With u' and u'' at the end of a step linear in u_{n+1}, a step is
    ``A u_{n+1} + U g = b`` with A = K + (2/dt) C + (4/dt^2) M (reference
    foundation included) and b from the state at the start of the step and
    the wheel loads at its end.  The reference (k0, c0) is one pair of
    floats or a pair of arrays, one entry per sleeper (a cell); `constant`,
    loads that do not move (a cell's self-weight, shape (n_dofs,)) [N].
    """

    def __init__(self, mesh, foundation, reference, dt, loads, tol, iterations, constant=None):
        self.k0, self.c0 = reference
        stiffness = mesh.stiffness + _sleeper_projector(mesh, self.k0)
        damping = mesh.damping + _sleeper_projector(mesh, self.c0)
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
        self.constant = constant

    def _remainder(self, offset: np.ndarray):
        """g(w) = f(w, w') - k0 w - c0 w' and dg/dw, with w' = (2/dt) w - offset."""
        gain, foundation = 2.0 / self.dt, self.foundation

        def remainder(w):
            rate = gain * w - offset
            force, slope, viscosity = evaluate_law(foundation, w, rate)
            return (force - self.k0 * w - self.c0 * rate,
                    slope - self.k0 + gain * (viscosity - self.c0))

        return remainder

    def step(self, u, v, a, load_index: int):
        """State (u, u', u'') at the end of a step whose end has loads `load_index`."""
        dt, sleepers = self.dt, self.mesh.sleeper_dofs
        rhs = self.history @ np.concatenate([u, v, a])
        np.add.at(rhs, self.load_dofs[load_index], self.load_values[load_index])
        if self.constant is not None:
            rhs += self.constant
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
