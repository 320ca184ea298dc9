"""Newton's method for a cell of N sleepers, each on its own law (issue 19, third block).

The residual is ``R_n = K1_n c_n + K2_n p_n(c) - g_n``, n = 0..m, of
`railtrack.equations.cell_harmonic_balance` [N], with
``p_{j,n} = M_j s^2 c_{j,n} + F_{j,n}(c)`` and F_{j,n} harmonic n of sleeper j's
foundation force by AFT.  The unknowns are packed real,
``[Re c_{.,0}, Re c_{.,1..m}, Im c_{.,1..m}]`` (N (2m+1) of them), and so is
the residual, ``[R_0, Re R_{1..m}, Im R_{1..m}]``: R_0 is real for a real mean
c_{.,0}, so the system is square.  Its exact Jacobian is
``K1_n + K2_n dp_n/dc``, where dp/dc is block-diagonal over the sleepers (each
law's AFT Jacobian plus M_j s^2, `cell_force_jacobian`).  The step uses
that structure (`railtrack.solvers.cell_step`): m + 1 solves of N x N plus one
system the size of the nonlinear sleepers' unknowns, the exact Newton step.
A backtracking line search on the residual norm keeps it robust; the
result says honestly whether it converged.  A law whose force jumps (a
damping force switched on at contact) defeats it: use a continuous one.
"""

from __future__ import annotations

import numpy as np

from ..equations.cell_blocks import solve_blocks
from ..equations.cell_harmonic_balance import cell_operators, cell_residual, two_sided_norm
from ..equations.harmonic_balance import (
    NonFiniteForceError,
    default_samples,
    require_jacobian_samples,
)
from ..model.cell import SleeperCell
from ..model.passage import Passage
from .cell_solution import CellSolution
from .cell_step import newton_step
from .foundation_at_rest import static_deflection

__all__ = ["solve_cell"]


def _linear_guess(passage: Passage, cell: SleeperCell, ops) -> np.ndarray:
    """Each law replaced by its `linearization()`, solved per harmonic, c (N, m+1).

    If that cell is singular (laws with no stiffness at rest, such as a gap law
    on every sleeper), those laws take their tangent at the static deflection
    under the mean load per sleeper instead, as `railtrack.solvers.newton.linear_guess` does.
    """
    pairs = np.array([law.linearization() for law in cell.foundations], dtype=float)
    s = 1j * ops.omega[:, None]
    for attempt in range(2):
        support = cell.sleeper_mass * s**2 + pairs[:, 0] + s * pairs[:, 1]       # (m+1, N)
        try:
            guess = solve_blocks(ops, support, ops.load)
            if np.all(np.isfinite(guess)):
                break
        except np.linalg.LinAlgError:
            pass
        if attempt == 0:
            force = float(passage.static_load_per_sleeper)
            for j, law in enumerate(cell.foundations):
                mean = static_deflection(law, force) if pairs[j, 0] <= 0 else np.nan
                if np.isfinite(mean):
                    pairs[j] = [float(np.ravel(x)[0])
                                for x in law.tangent(np.array([mean]), np.zeros(1))]
    else:
        raise ValueError("the linearised cell is singular (no sleeper's law has stiffness at "
                         "rest, or an undamped resonance); pass an initial guess")
    guess[0] = guess[0].real
    return guess.T


def solve_cell(passage: Passage, cell: SleeperCell, harmonics: int, *, tol: float = 1e-10,
               max_iterations: int = 50, samples: int | None = None,
               initial: np.ndarray | None = None,
               extra_load: np.ndarray | None = None,
               operators=None) -> CellSolution:
    """Periodic response of a cell of N sleepers on their own laws, by Newton [m].

    Parameters
    ----------
    passage : Passage
        Scalar-valued rail, spacing L and train; its sleeper and pad fields
        are not used (the cell's are).
    cell : SleeperCell
    harmonics : int
        m >= 1.
    tol : float
        Converged once ``||R|| / ||g|| <= tol``.
    max_iterations : int
        Newton steps at most.
    samples : int, optional
        AFT samples per period, > 4m; default `default_samples(m)`, as `railtrack.solve`.
    initial : ndarray, shape (N, m+1), optional
        c_{j,0..m} to start from; default: the linear cell with each law's
        ``linearization()``.
    extra_load : ndarray, shape (m+1, N), optional
        A load added to g_n [N], in the same mode-scaled rows (the wheels'
        varying forces, `railtrack.equations.wheel_harmonic_balance.wheel_loads`).

    Returns
    -------
    CellSolution

    Examples
    --------
    >>> from railtrack.model.foundations import CubicFoundation
    >>> passage = Passage.paper()
    >>> cell = SleeperCell.identical(passage, CubicFoundation.paper(), 2)
    >>> result = solve_cell(passage, cell, 10)
    >>> result.converged, result.coefficients.shape
    (True, (2, 21))
    """
    if not isinstance(cell, SleeperCell):
        raise TypeError(f"cell must be a SleeperCell; got {type(cell).__name__}")
    if isinstance(harmonics, bool) or not isinstance(harmonics, (int, np.integer)) or harmonics < 1:
        raise ValueError(f"harmonics must be an integer >= 1; got {harmonics!r}")
    if not 0.0 < tol < 1.0:
        raise ValueError(f"tol must be in (0, 1); got {tol!r}")
    if isinstance(max_iterations, bool) or int(max_iterations) != max_iterations \
            or max_iterations < 0:
        raise ValueError(f"max_iterations must be an integer >= 0; got {max_iterations!r}")
    m, n = int(harmonics), cell.sleepers
    samples = default_samples(m) if samples is None else samples
    require_jacobian_samples(samples, m)
    omega = passage.fundamental_frequency * np.arange(m + 1)
    sleeper_weight, rail_weight = cell.weights(passage)
    if operators is None:
        ops = cell_operators(passage, cell.pad_stiffness, cell.pad_damping, omega,
                             sleeper_weight=sleeper_weight, rail_weight=rail_weight)
    else:
        ops = operators
        if ops.omega.shape != omega.shape or not np.allclose(ops.omega, omega, rtol=1e-12):
            raise ValueError("operators were built for other frequencies than this solve's")
    if extra_load is not None:
        ops = ops._replace(load=ops.load + np.asarray(extra_load))
    if not all(np.all(np.isfinite(x)) for x in (ops.load, ops.denominator, ops.numerator)):
        raise ValueError("the cell's operators are not finite (eq. 3 overflows); check the "
                         "rail's EI, rho S and L")
    scale = two_sided_norm(ops.load)
    c = _linear_guess(passage, cell, ops) if initial is None else np.array(initial, dtype=complex)
    if c.shape != (n, m + 1) or not np.all(np.isfinite(c)):
        raise ValueError(f"initial must be finite, shape {(n, m + 1)}; got {c.shape}")
    c[:, 0] = c[:, 0].real
    current, force = cell_residual(cell, c, ops, samples)
    norm = two_sided_norm(current) / scale
    history, steps, message = [norm], 0, ""
    while norm > tol and steps < max_iterations:
        steps += 1
        try:
            step = newton_step(cell, c, current, ops, samples)
        except np.linalg.LinAlgError:
            message = f"the Jacobian is singular at Newton step {steps}"
            break
        if not np.all(np.isfinite(step)):
            message = f"the Newton step is not finite at Newton step {steps}"
            break
        for _ in range(30):
            trial = c + step
            try:
                trial_current, trial_force = cell_residual(cell, trial, ops, samples)
                trial_norm = two_sided_norm(trial_current) / scale
            except NonFiniteForceError:
                trial_norm = np.inf
            if trial_norm < norm:
                break
            step = 0.5 * step
        else:
            message = f"the line search found no decrease of the residual at Newton step {steps}"
            break
        c, current, force, norm = trial, trial_current, trial_force, trial_norm
        history.append(norm)
    converged = bool(np.isfinite(norm) and norm <= tol)
    summary = f"relative residual {norm:.2e} {'<=' if converged else '>'} tol {tol:.1e} " \
              f"after {steps} Newton steps"
    message = summary if not message else f"{message}; {summary}"

    def two_sided(x):
        return np.concatenate([np.conj(x[:, :0:-1]), x], axis=-1)

    seat = -cell.sleeper_mass[:, None] * omega**2 * c + force
    seat[:, 0] += sleeper_weight
    return CellSolution(passage, cell, two_sided(c), two_sided(force), two_sided(seat), m,
                        int(samples), converged, float(norm), steps, np.array(history), message)
