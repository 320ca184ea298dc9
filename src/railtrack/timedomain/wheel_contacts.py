"""One solve of the ring with its wheels condensed in, the step of `railtrack.timedomain.ring_wheels`.

Split from `railtrack.timedomain.ring_wheels`, which re-exports it; the
equations are in that module's docstring.
"""

from __future__ import annotations

import numpy as np

__all__ = ["solve_contacts"]


def solve_contacts(system, rhs, contacts, wheel, offset, gain, remainder, guess, tol, iterations,
                   compliance=None):
    """One solve of ``A u + U g(w) + B P(delta) = rhs`` with the wheels condensed in.

    Parameters
    ----------
    system : CondensedSystem
        A factored, with A^-1 U and S = U^T A^-1 U.
    rhs : ndarray, shape (n_dofs,)
        b [N, N m].
    contacts : (dofs, shapes), shapes (J, 4)
        The contact points' element DOFs and Hermite weights.
    wheel : Wheel
    offset : ndarray, shape (J,)
        r(x_c) - (h_w - Q) / a_w [m]: with it delta = u_c - P / a_w + offset.
    gain : float or ndarray, shape (J, J)
        a_w [N/m] (k_p in a static solve); or the wheels' compliance G [m/N]
        when they are coupled (a vehicle, `railtrack.timedomain.ring_vehicle`):
        the wheels then move by G P where a lone wheel moves by P / a_w.
    remainder : callable
        w -> (g, dg/dw) of the sleepers' laws beyond the factored reference [N, N/m].
    guess : (g, P)
        Starting forces [N].
    tol : float
        Newton's tolerance on w and delta [m] (plus a round-off floor).
    iterations : int
    compliance : ndarray, shape (J,), optional
        g [m/N]: the rail's local sag under each wheel per unit force.

    Returns
    -------
    u : ndarray, shape (n_dofs,)
    g, P : ndarray
        The converged sleeper remainders and contact forces [N].
    u_c : ndarray, shape (J,)
        The rail's displacement under each wheel [m].
    """
    dofs, shapes = contacts
    sleepers = system.sleeper_dofs
    count, n_s = shapes.shape[0], sleepers.size
    columns = np.zeros((rhs.size, 1 + count))
    columns[:, 0] = rhs
    for j in range(count):
        np.add.at(columns[:, 1 + j], dofs[j], shapes[j])
    solved = system.lu.solve(columns)
    free, contact = solved[:, 0], solved[:, 1:]   # A^-1 b [m], A^-1 B [m/N]

    def at_contacts(field):
        return np.einsum("jk,jk...->j...", shapes, field[dofs])

    influence = np.empty((n_s + count, n_s + count))
    influence[:n_s, :n_s] = system.influence
    influence[:n_s, n_s:] = contact[sleepers]
    influence[n_s:, :n_s] = at_contacts(system.response)
    own = np.eye(count) / gain if np.ndim(gain) == 0 else np.asarray(gain, dtype=float)
    influence[n_s:, n_s:] = at_contacts(contact) + own
    if compliance is not None:
        influence[n_s:, n_s:] += np.diag(compliance)
    target = np.concatenate([free[sleepers], at_contacts(free) + offset])

    def forces(y):
        g, dg = remainder(y[:n_s])
        delta = y[n_s:]
        return (np.concatenate([g, wheel.contact_force(delta)]),
                np.concatenate([dg, wheel.contact_stiffness(delta)]))

    y = target - influence @ np.concatenate(guess)
    for _ in range(iterations + 1):
        force, slope = forces(y)
        coupled = influence @ force
        mismatch = y - target + coupled
        # Round-off floor: the contact rows hold P / a_w, metres for a light wheel.
        floor = tol + 16 * np.finfo(float).eps * (np.abs(target) + np.abs(coupled))
        if np.all(np.abs(mismatch) <= floor):
            break
        if not np.all(np.isfinite(mismatch)):
            raise RuntimeError("Newton on the sleepers and wheel contacts diverged: its "
                               "mismatch is not finite")
        y = y - np.linalg.solve(np.eye(y.size) + influence * slope[None, :], mismatch)
    else:
        raise RuntimeError(
            f"Newton on the sleepers and wheel contacts did not converge in {iterations} "
            f"iterations (mismatch {float(np.max(np.abs(mismatch))):.2e} m): raise "
            "max_newton_iterations, or check the foundation law and the profile's smoothness")
    g, p = force[:n_s], force[n_s:]
    u = free - system.response @ g - contact @ p
    return u, g, p, at_contacts(u) if compliance is None else at_contacts(u) - compliance * p
