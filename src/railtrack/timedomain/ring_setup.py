"""A run of the ring made ready: its arguments checked, the model built, the state started.

`railtrack.timedomain.simulation.simulate_time_domain` checks its arguments
here (counts, tolerances, the run's memory and time beforehand, the steps
per period, the wheels), builds the ring (`railtrack.timedomain.fem`, rail
eq. 1, sleepers eq. 4, pads eq. 5) with the foundation law of eqs. (22),
(24) or (25) under every sleeper or a cell's laws, starts it from the
static state, a harmonic-balance solution or a given state
(`railtrack.timedomain.ring_state`), estimates the time-step error, and
makes the Newmark or HHT-alpha stepper (`railtrack.timedomain.newmark`),
with wheels of mass or a vehicle on it if asked.  The result, a `RingRun`,
is what `railtrack.timedomain.ring_periods` steps period after period.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..model.cell import SleeperCell
from ..model.foundations import as_foundation
from ..model.passage import Passage
from ..model.vehicle import Vehicle
from ..solvers.progress import show_progress
from .fem import RingMesh, ring_mesh, sleepers_on_ring, wheel_load_entries
from .newmark import NewmarkStepper, NonFiniteLawError, reference_law
from .ring_cell import ring_cell, ring_train
from .ring_state import initial_state
from .ring_vehicle import attach_vehicle
from .ring_wheels import attach_wheels, check_wheel_arguments
from .runcost import LONG_RUN_SECONDS, TYPICAL_PERIODS, check_run_cost
from .timestep import check_step_error, check_steps_per_period

__all__ = ["DEFAULT_TIMOSHENKO_ALPHA", "FINITE_HINT", "RingRun", "prepare_run"]

DEFAULT_TIMOSHENKO_ALPHA = 0.1
"""HHT's alpha on a Timoshenko rail unless told (`simulate_time_domain`, issue 27)."""

FINITE_HINT = (
    ": the law must return finite forces and tangents for every w, w' the sleepers reach "
    "(check its domain: a division, square root or logarithm of w?)"
)
"""Appended to a `NonFiniteLawError`'s message."""


def _require_count(name: str, value: Any) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise ValueError(f"{name} must be an integer >= 1; got {value!r}")
    return int(value)


@dataclass(eq=False)
class RingRun:
    """What `prepare_run` made: the ring, its law and stepper, the started state, the limits.

    `foundation` is the law as given to the result (a `SleeperCell` as
    given, any other law through `as_foundation`); `law` the one the
    stepper evaluates (a cell's law per sleeper), `first_law` the one of
    sleeper 0.  `scale` is the mean static sleeper deflection [m], `shown`
    whether a progress bar counts the periods.
    """

    passage: Passage
    foundation: Any
    law: Any
    first_law: Any
    mesh: RingMesh
    stepper: Any
    u: np.ndarray
    v: np.ndarray
    a: np.ndarray
    times: np.ndarray
    scale: float
    step_error: float
    every_sleeper: bool
    shown: bool
    wheel: Any
    tol: float
    min_periods: int
    max_periods: int
    elements_per_span: int
    steps_per_period: int
    wagons: int


def prepare_run(track, train, foundation, elements_per_span, steps_per_period, tol, max_periods,
                start, min_periods, newton_tol, max_newton_iterations, warn_step_error, wagons,
                wheel, profile, timoshenko, hht_alpha, progress) -> RingRun:
    """The arguments of `simulate_time_domain` checked, in its order, and its run built.

    Its warnings (`LongRunWarning`, `TimeStepWarning`) point at the caller
    of `simulate_time_domain`, which must call this directly.
    """
    passage = Passage(track, ring_train(train, wagons))
    elements_per_span = _require_count("elements_per_span", elements_per_span)
    steps_per_period = _require_count("steps_per_period", steps_per_period)
    max_periods = _require_count("max_periods", max_periods)
    min_periods = min(_require_count("min_periods", min_periods), max_periods)
    max_newton_iterations = _require_count("max_newton_iterations", max_newton_iterations)
    for name, value in (("tol", tol), ("newton_tol", newton_tol)):
        if not np.isfinite(value) or value <= 0:
            raise ValueError(f"{name} must be a finite number > 0; got {value!r}")
    if warn_step_error is not None and not (np.isfinite(warn_step_error) and warn_step_error > 0):
        raise ValueError(f"warn_step_error must be a finite number > 0 or None; got {warn_step_error!r}")
    cost = check_run_cost(sleepers_on_ring(passage), elements_per_span, steps_per_period,
                          max_periods, stacklevel=4)
    # a bar exactly where LongRunWarning speaks (none in the book, which has no such run)
    shown = show_progress(progress, cost.seconds(min(TYPICAL_PERIODS, max_periods))
                          > LONG_RUN_SECONDS)
    check_steps_per_period(passage, steps_per_period)
    check_wheel_arguments(wheel, profile, start, train)
    cell = None
    if isinstance(foundation, SleeperCell):
        n_ring = sleepers_on_ring(passage)
        cell = ring_cell(foundation, n_ring, wagons, n_ring // wagons)
        mesh = ring_mesh(passage, elements_per_span, cell.sleepers, timoshenko)
        law, first_law = cell.law, foundation.foundations[0]
        reference = cell.law.reference()
        k0, pad = float(np.mean(reference[0])), float(np.mean(cell.pad_stiffness))
    else:
        law = first_law = foundation = as_foundation(foundation)
        mesh = ring_mesh(passage, elements_per_span, timoshenko=timoshenko)
        reference = k0, _ = reference_law(foundation)
        pad = float(passage.pad_stiffness)
    n_steps, dt = steps_per_period, float(passage.period) / steps_per_period
    times = dt * np.arange(n_steps)
    loads = wheel_load_entries(mesh, times)

    # Newton's tolerance is relative to the mean static deflection: the load
    # per sleeper 2 Q L / H on the pad and the reference foundation in series.
    scale = float(passage.static_load_per_sleeper) * (1.0 / k0 + 1.0 / pad)
    newton_abs = newton_tol * scale
    weight = None if cell is None else cell.self_weight(mesh)

    try:
        u, v, a = initial_state(mesh, law, start, reference[0], newton_abs, max_newton_iterations,
                                weight)
    except NonFiniteLawError as error:
        raise NonFiniteLawError(f"{error}{FINITE_HINT}") from None
    if cell is None:
        estimated, linearized_at = (passage, foundation), float(np.mean(u[mesh.sleeper_dofs]))
    else:  # a linear stand-in: its tangent is the same at any w
        estimated, linearized_at = cell.stand_in(passage, u[mesh.sleeper_dofs]), 0.0
    step_error = check_step_error(*estimated, linearized_at, steps_per_period,
                                  elements_per_span, warn_step_error, stacklevel=4)
    if hht_alpha is None:
        hht_alpha = 0.0 if timoshenko is None else DEFAULT_TIMOSHENKO_ALPHA
    stepper = NewmarkStepper(mesh, law, reference, dt, loads, newton_abs, max_newton_iterations,
                             weight, hht_alpha)
    if wheel is not None:
        attach = attach_vehicle if isinstance(wheel, Vehicle) else attach_wheels
        u, stepper = attach(stepper, wheel, profile, u, times, reference[0], wagons)
    (stepper if wheel is None else stepper.stepper).start(u, v)
    every_sleeper = cell is not None and not cell.uniform
    return RingRun(passage, foundation, law, first_law, mesh, stepper, u, v, a, times, scale,
                   step_error, every_sleeper, shown, wheel, tol, min_periods, max_periods,
                   elements_per_span, steps_per_period, wagons)
