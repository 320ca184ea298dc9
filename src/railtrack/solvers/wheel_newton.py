"""Newton's method for a cell with wheels on Hertz springs (issue 20, first version).

Drives `railtrack.equations.wheel_harmonic_balance.wheel_residual`.  The
Jacobian is taken by forward differences of the packed residual: good for
small cells (N = 1, a few hundred unknowns); the exact, structured Jacobian
is the next step.  Starts from today's constant-force solution of the cell,
the wheels at their static compression.

Limit of this version: the rail under a wheel is the sum of the free rail
under the wheels and the sleepers' reactions, and a pair (sleeper harmonic
n, wheel harmonic p) whose wavenumber meets a free bending wave of the rail
makes both parts large and opposite.  Where such a pair falls inside the
truncation the residual cannot be driven below about 1e-6 and the result is
reported ``converged=False`` (the paper's track at 45 m/s with m = 180: the
pair n = 127, p = 120); m = 120 there converges to 1e-10 and matches the
time-domain ring (tests/test_wheel_newton.py).  A finite form of the rail
under the wheel, as `railtrack.equations.cell_rail_field` has for a fixed
point, is the next step.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..equations.cell_harmonic_balance import pack_harmonics, two_sided_norm, unpack_harmonics
from ..equations.harmonic_balance import default_samples
from ..equations.wheel_harmonic_balance import wheel_residual, wheel_system
from ..model.passage import Passage
from .cell_newton import solve_cell

__all__ = ["WheelSolution", "solve_wheels"]


class WheelSolution(NamedTuple):
    """A cell's periodic response with wheels; ``converged`` only if the residual <= tol."""

    coefficients: np.ndarray   # (N, 2m+1) c_{j,n}, n = -m..m [m]
    grid: np.ndarray           # wheel harmonics p
    contact_harmonics: np.ndarray  # (K, lmax) P_{k,p} [N]
    lift: np.ndarray           # (K,) y_k [m]
    times: np.ndarray          # (S,) [s]
    compression: np.ndarray    # (K, S) delta_k(t) [m]
    contact_force: np.ndarray  # (K, S) C_H max(delta, 0)^{3/2} [N]
    converged: bool
    residual: float
    iterations: int
    message: str
    final_residual: np.ndarray  # the packed, scaled residual (sleepers, then contacts)


def _pack(coefficients, forces, lift):
    return np.concatenate([pack_harmonics(coefficients.T), forces.real.ravel(),
                           forces.imag.ravel(), lift])


def _unpack(x, n_sleepers, m, wheels, lmax):
    size = n_sleepers * (2 * m + 1)
    c = unpack_harmonics(x[:size], n_sleepers)
    rest = x[size:]
    forces = (rest[:wheels * lmax] + 1j * rest[wheels * lmax:2 * wheels * lmax]).reshape(
        wheels, lmax)
    return c, forces, rest[2 * wheels * lmax:]


def solve_wheels(passage: Passage, cell, wheel, profile, harmonics: int, *,
                 samples: int | None = None, tol: float = 1e-9,
                 max_iterations: int = 30) -> WheelSolution:
    """Periodic response of a cell of sleepers under wheels on Hertz springs, by Newton.

    Parameters
    ----------
    passage : Passage
        Rail, spacing, train (its axle loads Q_k are the wheels' static loads).
    cell : SleeperCell
        H must be a whole number of cells.
    wheel : Wheel
    profile : callable
        r(x) [m], repeating with the cell.
    harmonics : int
        m, the sleepers'; the wheels' harmonics are the multiples of H / (N L) up to m.
    """
    m = int(harmonics)
    samples = default_samples(m) if samples is None else int(samples)
    system = wheel_system(passage, cell, wheel, m, samples)
    n_sl, k_w, lmax = cell.sleepers, len(passage.axle_positions), system.grid.size
    start = solve_cell(passage, cell, m, samples=samples)
    c0 = start.coefficients[:, m:]
    x = _pack(c0, np.zeros((k_w, lmax), dtype=complex),
              np.array([wheel.static_compression(q) for q in passage.axle_loads])
              - float(np.mean(profile(np.linspace(0, float(passage.wagon_length), 4096,
                                                  endpoint=False)))))
    load_scale = two_sided_norm(system.ops.load)
    force_scale = float(np.max(passage.axle_loads))

    def residual(vector):
        c, forces, lift = _unpack(vector, n_sl, m, k_w, lmax)
        sleepers, contacts, delta, hertz = wheel_residual(
            passage, cell, wheel, profile, system, c, forces, lift)
        packed = np.concatenate([pack_harmonics(sleepers) / load_scale,
                                 contacts[:, 0].real / force_scale,
                                 contacts[:, 1:].real.ravel() / force_scale,
                                 contacts[:, 1:].imag.ravel() / force_scale])
        return packed, delta, hertz

    current, delta, hertz = residual(x)
    norm, steps, message = float(np.linalg.norm(current)), 0, ""
    # difference steps by kind of unknown: a share of the largest sleeper
    # coefficient, 1 mN of contact force, 1e-13 m of compression
    size = n_sl * (2 * m + 1)
    steps_by_kind = np.concatenate([np.full(size, 1e-8 * float(np.abs(x[:size]).max())),
                                    np.full(2 * k_w * lmax, 1e-3), np.full(k_w, 1e-13)])
    while norm > tol and steps < max_iterations:
        steps += 1
        h = steps_by_kind
        jacobian = np.empty((current.size, x.size))
        for i in range(x.size):
            trial = x.copy()
            trial[i] += h[i]
            jacobian[:, i] = (residual(trial)[0] - current) / h[i]
        step = np.linalg.lstsq(jacobian, -current, rcond=None)[0]
        for _ in range(30):
            new, new_delta, new_hertz = residual(x + step)
            new_norm = float(np.linalg.norm(new))
            if new_norm < norm:
                break
            step = 0.5 * step
        else:
            message = f"no decrease of the residual at Newton step {steps}"
            break
        x, current, delta, hertz, norm = x + step, new, new_delta, new_hertz, new_norm
    converged = bool(norm <= tol)
    c, forces, lift = _unpack(x, n_sl, m, k_w, lmax)
    times = np.arange(samples) * float(passage.period) / samples
    summary = f"residual {norm:.2e} {'<=' if converged else '>'} tol {tol:.1e} after {steps} steps"
    two_sided = np.concatenate([np.conj(c[:, :0:-1]), c], axis=1)
    return WheelSolution(two_sided, system.grid, forces, lift, times, delta, hertz, converged, norm,
                         steps, summary if not message else f"{message}; {summary}", current)
