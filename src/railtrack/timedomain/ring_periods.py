"""The ring stepped period after period until its response repeats.

`run_periods` takes a `railtrack.timedomain.ring_setup.RingRun` and steps
it, one period T = H / v at a time, recording every sleeper, the rail above
sleeper 0 and the watched degrees of freedom at every step, until sleeper
0's response over a period (every sleeper's, for a cell whose sleepers
differ; and the wheels' contact forces, if any) changes by at most ``tol``
of its peak from the period before.  A response that grows past
`GROWTH_LIMIT` times the static deflection, a failed Newton step or a law
that returns NaN ends the run with a message saying when.  The records
become the `railtrack.timedomain.td_solution.TimeDomainSolution` of
`railtrack.timedomain.simulation.simulate_time_domain`.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..model.passage import Passage
from ..solvers.progress import progress_bar
from ..solvers.solution import ConvergenceWarning
from .newmark import NonFiniteLawError, instability_hint
from .ring_fields import SleeperRecorder
from .ring_outputs import ring_outputs, watched_dofs
from .ring_setup import FINITE_HINT as _FINITE, RingRun
from .td_solution import TimeDomainSolution

__all__ = ["GROWTH_LIMIT", "run_periods"]

GROWTH_LIMIT = 1e4
"""A sleeper deflection this many times the static one means the track is unstable."""


def _when(passage: Passage, steps: int, n: int, periods: int) -> str:
    """Where step n + 1 of period `periods` ends, for messages."""
    t = (periods - 1 + (n + 1) / steps) * float(passage.period)
    return f"at step {n + 1} of {steps} in period {periods} (t = {t:.6g} s)"


def run_periods(run: RingRun) -> TimeDomainSolution:
    """Step `run` until a period repeats the last (or `run.max_periods`); its result.

    Its `ConvergenceWarning` points at the caller of `simulate_time_domain`,
    which must call this directly.
    """
    passage, mesh, law, stepper, wheel = run.passage, run.mesh, run.law, run.stepper, run.wheel
    u, v, a, scale, every_sleeper = run.u, run.v, run.a, run.scale, run.every_sleeper
    tol, min_periods, max_periods = run.tol, run.min_periods, run.max_periods
    n_steps = run.steps_per_period
    recorder = SleeperRecorder(mesh, n_steps)

    # Far beyond any track's deflection, and far below overflow in a cubic law.
    bound = GROWTH_LIMIT * max(scale, float(np.max(np.abs(u[mesh.sleeper_dofs]))))
    record = np.empty((n_steps, mesh.n_sleepers))
    rail = np.empty(n_steps)
    watched = watched_dofs(mesh)
    states, rates = np.empty((n_steps, watched.size)), np.empty((n_steps, watched.size))
    history = np.empty((max_periods, n_steps))
    previous: np.ndarray | None = None
    previous_all = np.empty_like(record)
    changes: list[float] = []
    converged = False
    with progress_bar(run.shown, max_periods, f"ring, {n_steps} steps a period", "periods") as bar:
        for periods in range(1, max_periods + 1):
            for n in range(n_steps):
                record[n] = u[mesh.sleeper_dofs]
                rail[n] = u[mesh.rail_dofs[0]]
                states[n], rates[n] = u[watched], v[watched]
                recorder.record(n, u, v)
                try:
                    u, v, a = stepper.step(u, v, a, (n + 1) % n_steps)
                except NonFiniteLawError as error:
                    raise NonFiniteLawError(f"{error}, {_when(passage, n_steps, n, periods)}{_FINITE}") from None
                except RuntimeError as error:
                    grown = float(np.max(np.abs(u[mesh.sleeper_dofs]))) / scale
                    hint = f"; {instability_hint(law)}" if grown > 100.0 else ""
                    raise RuntimeError(f"{error}, {_when(passage, n_steps, n, periods)}, the sleepers having "
                                       f"reached {grown:.3g} times the static deflection{hint}") from None
                reached = float(np.max(np.abs(u[mesh.sleeper_dofs])))
                if not reached <= bound:  # also catches NaN
                    raise RuntimeError(
                        f"the response grew without bound in period {periods}: a sleeper reached "
                        f"|w| = {reached:.3g} m, {reached / scale:.3g} times the static deflection scale "
                        f"{scale:.3g} m, {_when(passage, n_steps, n, periods)}; {instability_hint(law)}"
                    )
            history[periods - 1] = record[:, 0]
            current = history[periods - 1]
            wheels_change = None if wheel is None else stepper.period_change()
            if previous is not None:
                if every_sleeper:  # the differing sleepers may settle at different rates
                    peak = max(float(np.max(np.abs(record))), np.finfo(float).tiny)
                    changes.append(float(np.max(np.abs(record - previous_all))) / peak)
                else:
                    peak = max(float(np.max(np.abs(current))), np.finfo(float).tiny)
                    changes.append(float(np.max(np.abs(current - previous))) / peak)
                if wheels_change is not None:
                    changes[-1] = max(changes[-1], wheels_change)
                converged = changes[-1] <= tol
            bar.to(periods, f"change {changes[-1]:.1e}, tol {tol:g}" if changes else None)
            if converged and periods >= min_periods:
                break
            previous = current
            if every_sleeper:
                previous_all[:] = record

    if not converged and max_periods > min_periods:
        last = f"{changes[-1]:.3g}" if changes else "not measured (one period)"
        warnings.warn(ConvergenceWarning(
            f"the ring's response did not repeat to tol = {tol:g} within max_periods = "
            f"{max_periods} (last period's change {last}): raise max_periods, or check the "
            "track's damping; the result has converged=False"), stacklevel=3)
    return TimeDomainSolution(
        times=run.times,
        sleeper_displacement=record[:, 0].copy(),
        rail_displacement=rail.copy(),
        sleeper_displacements=record.copy(),
        periods=periods,
        converged=converged,
        period_change=np.array(changes),
        elements_per_span=run.elements_per_span,
        steps_per_period=run.steps_per_period,
        passage=passage,
        foundation=run.foundation,
        step_error=run.step_error,
        **ring_outputs(mesh, run.first_law, states, rates),
        sleeper_history=history[:periods].copy(),
        final_state=(u.copy(), v.copy()),
        **recorder.outputs(law, record),
        wagons=int(run.wagons),
        **({} if wheel is None else stepper.outputs()),
    )
