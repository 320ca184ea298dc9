"""The finite-element ring of a cell linearised about a cell's periodic solution.

`railtrack.timedomain.span_map` for a `railtrack.CellSolution`: ring sleeper
i is cell sleeper i mod N (`railtrack.timedomain.ring_cell`), with that
sleeper's mass, pad and law, and it moves as ``w_{i mod N}(t - p N L / v)``,
p = i div N.  The solution moved on by one cell time N L / v is itself moved
along the ring by N sleepers, so the map over [0, N L / v] followed by the
shift back by N sleepers, G = S^-N Phi, is the same for every cell, and the
period map of a ring one wagon long is G^(N_s / N).  The Newmark step and
its linearisation are those of `ring_span_map`.
"""

from __future__ import annotations

import numpy as np

from ..model.passage import Passage
from .fem import ring_mesh, sleepers_on_ring
from .newmark import NewmarkStepper, evaluate_law
from .ring_cell import ring_cell, ring_train
from .span_map import RingSpanMap, tangent_flow
from .timestep import check_steps_per_period

__all__ = ["cell_span_map"]


def cell_span_map(solution, *, wagons: int = 1, elements_per_span: int = 4,
                  steps_per_period: int | None = None) -> RingSpanMap:
    """G = S^-N Phi over one cell time N L / v of the ring linearised about a cell's solution.

    Parameters
    ----------
    solution : CellSolution
        Converged; N must divide the H / L sleepers of a wagon.
    wagons, elements_per_span, steps_per_period
        As `railtrack.timedomain.span_map.ring_span_map`.

    Returns
    -------
    RingSpanMap
        Its `matrix` is G over N spans (`steps_per_span` steps per span).

    Raises
    ------
    ValueError
        If the solution has not converged, or N does not divide H / L.
    """
    if isinstance(elements_per_span, bool) or not isinstance(elements_per_span, (int, np.integer)) \
            or elements_per_span < 1:
        raise ValueError(f"elements_per_span must be an integer >= 1; got {elements_per_span!r}")
    if not getattr(solution, "converged", False):
        raise ValueError("the solution has not converged: its linearisation would be meaningless "
                         f"({getattr(solution, 'message', 'no message')})")
    n = solution.sleepers
    per_wagon = sleepers_on_ring(solution.passage)
    if per_wagon % n:
        raise ValueError(
            f"the ring's multipliers of a cell need N = {n} to divide the H / L = {per_wagon} "
            "sleepers of a wagon (the ring's symmetry is one wagon); use rt.floquet(solution), "
            "Hill's matrix of the cell, which takes any N")
    passage = Passage(solution.passage.track, ring_train(solution.passage.train, wagons))
    ring = sleepers_on_ring(passage)
    steps = 80 * ring if steps_per_period is None else steps_per_period
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)):
        raise ValueError(f"steps_per_period must be an integer; got {steps!r}")
    check_steps_per_period(passage, int(steps))
    per_span = int(steps) // ring
    cell = ring_cell(solution.cell, ring, wagons, per_wagon)
    mesh = ring_mesh(passage, int(elements_per_span), cell.sleepers)
    law, (k0, c0) = cell.law, cell.law.reference()
    span_time = float(passage.sleeper_spacing) / float(passage.speed)
    dt = span_time / per_span
    count = n * per_span
    stepper = NewmarkStepper(mesh, law, (k0, c0), dt, (None, None), 0.0, 0)

    # ring sleeper i is cell sleeper i mod N, delayed by (i div N) cell times
    index = np.arange(ring)
    times = dt * np.arange(count + 1)[:, None] - n * span_time * (index // n)[None, :]
    w = solution.sleeper_displacement(times)[index % n, :, index].T          # (steps+1, ring)
    rate = solution.sleeper_velocity(times)[index % n, :, index].T
    _, stiffness, damping = evaluate_law(law, w, rate)
    stiffness, damping = (np.broadcast_to(x, w.shape) for x in (stiffness, damping))

    u, v = tangent_flow(stepper, stiffness, damping, (k0, c0), dt)
    span = RingSpanMap(np.vstack([u, v]), mesh, int(wagons), per_span, dt)
    return RingSpanMap(span.shift(span.matrix, -n), mesh, int(wagons), per_span, dt)
