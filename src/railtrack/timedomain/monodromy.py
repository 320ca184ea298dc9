"""Floquet multipliers of the finite-element ring linearised about a periodic solution.

`railtrack.studies.stability.check_stability` starts the ring of
`railtrack.timedomain.simulation` on a harmonic-balance `Solution` and watches
whether it drifts away.  This module asks the same question of the ring's
linearisation instead: the Newmark step map of the ring, with the
foundation's tangent k(t) = df/dw, c(t) = df/dw' evaluated along the solution,
propagated over a period.  Its eigenvalues, the Floquet multipliers mu, say
how each disturbance that fits the ring grows per period T = H / v.

The linearised step, and the span map G = S^-1 Phi that the symmetry of
the travelling wave reduces it to, are `railtrack.timedomain.span_map`:
the period map of a ring of one wagon (N_s sleepers) is G^N_s, so the
multipliers are mu = nu^N_s, nu the eigenvalues of one dense
2 n_dofs x 2 n_dofs matrix.

A ring of n wagons (the train tiled, as ``check_stability(wagons=n)``) is
also invariant under the shift W = S^N_s by one wagon, which commutes with
G; the period map is W G^N_s.  On the disturbances with wagon j equal to
exp(i theta j) times wagon 0, theta = 2 pi k / n (a Bloch phase), W is
exp(-i theta) and G reduces to a matrix of one wagon's size:
mu = exp(-i theta) nu^N_s.

Which multipliers matter: the rail modes whose deflection vanishes at every
sleeper (pinned-pinned modes) never move a sleeper and are undamped (|mu| = 1),
and the rail modes too fast for the time step are barely damped (|mu| ~
0.9999); `RingMultipliers.dominant` leaves out both by `sleeper_share`.
The map is linearised about the harmonic-balance orbit, not about the ring's
own periodic orbit, which is O(dt^2) away: on the fold track of chapter 10 at
525 m/s the two differ by 5e-3 of the peak at 600 steps per period, and the
map matches central differences of the nonlinear ring to 6e-3 (4e-4 at 2400).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .fem import RingMesh
from .cell_span_map import cell_span_map
from .span_map import RingSpanMap, ring_span_map

__all__ = ["SLEEPER_SHARE", "RingSpanMap", "RingMultipliers", "ring_span_map", "ring_multipliers"]

SLEEPER_SHARE = 1e-3
"""Least `RingMultipliers.sleeper_share` of a multiplier that counts as moving the sleepers [-].

On the fold track of chapter 10 the shares of modes with |mu| > 0.5 fall in
two groups: 0.18-0.20 (sleeper modes) and below 1e-7 (rail modes).
"""


@dataclass(frozen=True, eq=False)
class RingMultipliers:
    """Floquet multipliers of the ring linearised about a periodic solution (`ring_multipliers`).

    Attributes
    ----------
    multipliers : ndarray of complex, shape (2 n_dofs,)
        mu over one period T = H / v, sorted by |mu| descending [-]: |mu| > 1
        grows, |mu| < 1 decays.
    sleeper_share : ndarray, shape (2 n_dofs,)
        For each mu, sum |du|^2 over the sleepers of its eigenvector divided by
        the same sum over the sleepers and the rail nodes, a rail node's
        |du|^2 being |w|^2 + h^2 |dw/dx|^2 (h the element length, so that
        all terms are in m^2; rates left out) [-]: 0 for a rail mode that
        never moves a sleeper.
    bloch_phase : ndarray, shape (2 n_dofs,)
        theta = 2 pi k / wagons [rad] of each mu's disturbance: wagon j of the
        ring carries exp(i theta j) times wagon 0 (0 on a ring of one wagon).
    dominant : complex
        The mu of largest modulus with `sleeper_share` > `SLEEPER_SHARE`.
    wagons, elements_per_span, steps_per_period : int
        The ring: its wagons, its mesh and its Newmark steps per ring period n H / v.
    """

    multipliers: np.ndarray
    sleeper_share: np.ndarray
    bloch_phase: np.ndarray
    dominant: complex
    wagons: int
    elements_per_span: int
    steps_per_period: int

    @property
    def stable(self) -> bool:
        """|dominant| < 1: every disturbance that moves the sleepers decays."""
        return bool(abs(self.dominant) < 1.0)


def _wagon_dofs(mesh: RingMesh, wagons: int, wagon: int) -> np.ndarray:
    """Indices in (du, du') of wagon `wagon`'s rail nodes and sleepers, in wagon 0's order."""
    per_wagon, e = mesh.n_sleepers // wagons, mesh.elements_per_span
    nodes = wagon * per_wagon * e + np.arange(per_wagon * e)
    rail = np.stack([2 * nodes, 2 * nodes + 1], axis=1).ravel()
    dofs = np.concatenate([rail, 2 * mesh.n_nodes + wagon * per_wagon + np.arange(per_wagon)])
    return np.concatenate([dofs, mesh.n_dofs + dofs])


def ring_multipliers(solution, *, wagons: int = 1, elements_per_span: int = 4,
                     steps_per_period: int | None = None) -> RingMultipliers:
    """Floquet multipliers of the time-domain ring linearised about a periodic solution.

    The ring `railtrack.check_stability` runs (same mesh, Newmark scheme and
    time step for the same arguments), linearised about `solution`: the
    eigenvalues nu of its span map G (`ring_span_map`) give the multipliers
    mu = exp(-i theta) nu^N_s over T = H / v, theta the Bloch phase of each
    wagon-periodic sector (module docstring).  A periodic solution is stable
    to the disturbances the ring carries if |mu| < 1 for every mu that moves
    the sleepers (`RingMultipliers.dominant`).

    Parameters
    ----------
    solution : railtrack.Solution or railtrack.CellSolution
        A converged periodic solution; its track's H / L must be an integer.
        For a cell, the ring carries the cell (`railtrack.timedomain.cell_span_map`)
        and N must divide H / L.
    wagons : int
        Wagons on the ring (the train tiled): Bloch phases 2 pi k / wagons.
    elements_per_span : int
        Hermite elements per sleeper span.
    steps_per_period : int or None
        Newmark steps over the ring's period n H / v, a multiple of its
        n H / L sleepers (as `railtrack.check_stability`); None: 80 per sleeper.

    Returns
    -------
    RingMultipliers

    Raises
    ------
    ValueError
        As `ring_span_map`.

    Examples
    --------
    The solution `railtrack.solve` finds on chapter 10's fold track at 525 m/s
    (the ring leaves it, its distance growing about 1.9-fold per period):

    >>> from railtrack import CubicFoundation, Track, Train, solve
    >>> law = CubicFoundation(20e6, 2e13, 0.8, 5000.0)
    >>> s = solve(Track.paper(pad_damping=1e5), Train.paper(speed=525.0), law, harmonics=25)
    >>> result = ring_multipliers(s, elements_per_span=4, steps_per_period=600)
    >>> result.stable, round(abs(result.dominant), 2)
    (False, 2.01)
    """
    if hasattr(solution, "wheel"):
        raise TypeError("ring_multipliers does not linearise a WheelSolution (the wheels' own "
                        "motion is part of every disturbance); run the ring itself instead: "
                        "rt.simulate_time_domain(track, train, law, ..., wheel=...)")
    # a CellSolution: the map over one cell time, shifted back N sleepers (cell_span_map)
    cell = hasattr(solution, "cell")
    span = (cell_span_map if cell else ring_span_map)(
        solution, wagons=wagons, elements_per_span=elements_per_span,
        steps_per_period=steps_per_period)
    mesh, per_wagon, matrix = span.mesh, span.sleepers_per_wagon, span.matrix
    maps_per_wagon = per_wagon // (solution.sleepers if cell else 1)
    rows = _wagon_dofs(mesh, wagons, 0)
    columns = [_wagon_dofs(mesh, wagons, j) for j in range(wagons)]
    half = rows.size // 2
    sleeper_rows = np.arange(half - per_wagon, half)
    deflection_rows = np.arange(0, half - per_wagon, 2)
    mu, share, phase = [], [], []
    for k in range(wagons):
        theta = 2.0 * np.pi * k / wagons
        block = sum(np.exp(1j * theta * j) * matrix[np.ix_(rows, columns[j])]
                    for j in range(wagons))
        if wagons == 1:
            block = block.real
        nu, vectors = np.linalg.eig(block)
        power = np.abs(vectors) ** 2
        on_sleepers = power[sleeper_rows].sum(axis=0)
        on_rail = (power[deflection_rows].sum(axis=0)
                   + mesh.element_length**2 * power[deflection_rows + 1].sum(axis=0))
        share.append(on_sleepers / (on_sleepers + on_rail))
        mu.append(np.exp(-1j * theta) * nu.astype(complex) ** maps_per_wagon)
        phase.append(np.full(nu.size, theta))
    mu, share, phase = (np.concatenate(x) for x in (mu, share, phase))
    order = np.argsort(-np.abs(mu), kind="stable")
    mu, share, phase = mu[order], share[order], phase[order]
    moving = share > SLEEPER_SHARE
    if not np.any(moving):
        raise RuntimeError("no eigenvector of the ring's span map moves the sleepers: "
                           "the ring has no sleeper motion to judge")
    return RingMultipliers(mu, share, phase, complex(mu[np.argmax(moving)]), int(wagons),
                           int(elements_per_span), span.steps_per_span * mesh.n_sleepers)
