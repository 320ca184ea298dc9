"""An independent check of the semi-analytical method: finite elements in time.

`simulate_time_domain` integrates the ring model of `railtrack.timedomain.fem` (rail,
eq. 1; sleepers, eq. 4; pads, eq. 5; the foundation law f(w, w') of
eqs. 22, 24 or 25 under every sleeper) step by step in time with the
average-acceleration Newmark scheme (Newmark 1959: gamma = 1/2,
beta = 1/4), from the static state, until the sleeper's response over one
period T = H / v repeats the previous period's.  Nothing is shared with the
harmonic-balance solver but the `Track` and the foundation object.

Why average acceleration and not HHT-alpha on the Euler–Bernoulli rail: it
is unconditionally stable, second-order accurate and adds no numerical
damping.  The unresolved high-frequency rail modes it leaves undamped carry
almost no motion at the sleepers, and the pad dashpots damp those that do, so
the sleeper response settles to its period without numerical dissipation
(see the tests).  A Timoshenko rail is different (issue 27): under a moving
load its velocity jumps wherever the load passes (the shear kink Q / kGA
moving at v), at every rail node of the mesh, and the nodes' mass cannot
follow a jump: each node crossing rings the mesh's own modes, which the
undamped step keeps.  The pad's dashpot turns the rail's ringing velocity
into rail-seat load, a spurious 1 to 5 kN on the paper's track
(eta1 = 1e6 N s/m) that neither a finer mesh nor a smaller step removes.
There the step is HHT-alpha (Hilber, Hughes & Taylor 1977) by default.

Besides the static state, a run may start from a harmonic-balance solution
or from an explicit ring state (`railtrack.timedomain.ring_state`): that is how
`railtrack.studies.stability` asks whether the track stays on a periodic solution,
and how `railtrack.studies.ramp.speed_ramp` carries a steady state from speed
to speed.

The arguments are checked and the run built in
`railtrack.timedomain.ring_setup`, the periods stepped in
`railtrack.timedomain.ring_periods`, each step in `railtrack.timedomain.newmark`.
"""

from __future__ import annotations

from typing import Any

from ..model.track import Track
from ..model.train import Train
from ..solvers.threads import blas_threads
from .newmark import NonFiniteLawError
from .ring_periods import GROWTH_LIMIT, run_periods
from .ring_setup import prepare_run
from .runcost import LongRunWarning
from .td_solution import TimeDomainSolution
from .timestep import TimeStepWarning

__all__ = [
    "TimeDomainSolution",
    "simulate_time_domain",
    "TimeStepWarning",
    "LongRunWarning",
    "NonFiniteLawError",
    "GROWTH_LIMIT",
]


def simulate_time_domain(
    track: Track,
    train: Train,
    foundation,
    elements_per_span: int = 8,
    steps_per_period: int = 2400,
    *,
    tol: float = 1e-6,
    max_periods: int = 40,
    start: Any = "static",
    min_periods: int = 1,
    newton_tol: float = 1e-11,
    max_newton_iterations: int = 50,
    warn_step_error: float | None = 1e-3,
    wagons: int = 1,
    wheel=None,
    profile=None,
    timoshenko=None,
    hht_alpha: float | None = None,
    progress: bool | None = None,
) -> TimeDomainSolution:
    """Periodic steady response of the track by finite elements and Newmark time stepping.

    The ring of `railtrack.timedomain.fem.ring_mesh` (one wagon length H, or
    `wagons` of them, with periodic ends; rail eq. 1, sleepers eq. 4, pads
    eq. 5) carries the foundation law f(w, w') of eqs. (22), (24) or (25)
    under each sleeper, or the laws of a cell of differing sleepers:

        M u'' + C u' + K u + U f(U^T u, U^T u') = P(t),

    with P(t) the consistent loads of the moving wheels.  It is integrated
    with the average-acceleration Newmark scheme (Newmark 1959), or HHT-alpha
    (`hht_alpha`), and Newton
    iterations on the sleeper DOFs at each step, period after period, until
    sleeper 0's response over a period changes by at most ``tol`` times its
    peak.

    Parameters
    ----------
    passage : Passage
        Track and train; H / L must be an integer (the number of sleepers on
        the ring).  Trains whose H / L is not an integer are not handled (a
        ring of a common multiple of H and L would be).
    foundation : foundation object, callable or SleeperCell
        Any law accepted by `railtrack.as_foundation`, under every sleeper
        with the passage's sleeper mass and pad; or a
        `railtrack.model.cell.SleeperCell` of N sleepers: ring sleeper i is
        cell sleeper i mod N, with that sleeper's mass, pad stiffness, pad
        damping and law (`railtrack.timedomain.ring_cell`).  N must divide
        the ring's wagons x H / L sleepers.  Each distinct law object is
        called once per evaluation, on all the sleepers it carries.  A cell
        with ``gravity > 0`` adds the rail's and sleepers' weight as constant
        loads (w is then measured from the unloaded, weightless track, as in
        `SleeperCell`).
    elements_per_span : int
        Hermite beam elements per sleeper span, >= 1.
    steps_per_period : int
        Time steps per period T = H / v: a multiple of H / L, so that the
        delay L / v between neighbouring sleepers is a whole number of steps,
        and at least 3 H / L, so that the sleeper-passing frequency v / L is
        resolved (`railtrack.timedomain.timestep.check_steps_per_period`).  The error
        falls as dt^2: on the paper's track 1.2e-3 of the peak at 90 steps,
        1.5e-4 at 240 and 1.8e-6 at the default 2400.
    tol : float
        Relative period-to-period change of sleeper 0's response at which the
        state counts as periodic [-]; for a cell whose sleepers differ, of
        every sleeper's response (the largest change over the largest peak).
    max_periods : int
        Periods integrated at most; ``converged=False`` if `tol` is not met.
    start : {"static", "rest"}, Solution or (u, v)
        Initial state: static equilibrium with the wheels at their t = 0
        positions (zero velocity); the undeformed track at rest with the
        wheels suddenly applied; a harmonic-balance `railtrack.Solution` of
        this track and speed (its state at t = 0,
        `railtrack.timedomain.ring_state.ring_state_from_solution`; the train may be n
        of the solution's wagons tiled); or the ring's displacements and
        velocities, two arrays of shape (n_dofs,) such as a previous run's
        ``final_state``.  The acceleration is the one the equation of motion
        gives.
    min_periods : int
        Periods integrated at least, even if the response repeats earlier
        (`railtrack.studies.stability` watches a solution for a while).
    newton_tol : float
        Newton stops when the sleeper equations hold to newton_tol times the
        mean static sleeper deflection [-].
    max_newton_iterations : int
        Newton iterations per step at most.
    warn_step_error : float or None
        Warn (`TimeStepWarning`) when the estimated time-step error exceeds
        this fraction of the peak response [-]; None skips the estimate
        (~0.03 s), e.g. in a deliberate time-step convergence study.  For a
        cell the estimate is that of a uniform track with the cell's mean
        sleeper, pad and linearised foundation.
    wagons : int
        Wagons on the ring, >= 1: the ring is wagons x H long and carries
        wagons x H / L sleepers (the train tiled into one wagon of length
        wagons x H, `railtrack.timedomain.ring_cell.ring_train`), so that it
        can carry a cell longer than one wagon.  The period, the steps per
        period and the result's passage are then the tiled train's.
    wheel : railtrack.model.wheel.Wheel or railtrack.Vehicle, optional
        Each axle of the ring's train becomes a wheel of this unsprung mass on
        a Hertz spring (`railtrack.timedomain.ring_wheels`), started at rest on
        the statically loaded track (start "static" only); the result then has
        `contact_forces` and `wheel_displacements`, and the period counts as
        repeated only when the contact forces repeat too (to `tol` of their
        peak) and balance the wheel loads.  The step should resolve the
        contact's frequency sqrt(k_H / m_w) (k_H = 1.5 C_H delta_0^{1/2}):
        an unresolved stiff contact (a 1 kg wheel on C_H = 1e16) is pumped
        by the average-acceleration step and does not converge.  A
        `railtrack.Vehicle` puts half a vehicle (body, bogies, suspensions) on
        each wagon's wheels (`railtrack.timedomain.ring_vehicle`), the train
        being ``vehicle.train(H, v)``.  Default: constant moving forces.
    profile : callable, optional
        Rail-top profile r(x) [m] fixed on the ring (`railtrack.model.profile`),
        which the wheels roll on; it must repeat with the ring's length
        wagons x H.  Needs `wheel`; default the smooth rail.
    timoshenko : railtrack.model.timoshenko.TimoshenkoRail, optional
        A Timoshenko rail (shear stiffness, rotary inertia) of two-node
        interdependent-interpolation elements (`railtrack.timedomain.rail_elements`),
        whose own interpolation plus the local sag g(xi) P carries the wheels
        (`railtrack.timedomain.ring_wheels`); default the Euler–Bernoulli rail.
        Its slope jumps by R / kGA above each point-supported sleeper, which
        the wheels feel; with ``hht_alpha=0`` its undamped higher modes may
        keep the wheels' period change above 1e-4.  The time-step error estimate and
        a harmonic-balance start stay those of the Euler–Bernoulli rail.

        The rail's velocity jumps wherever a load passes, and the FE ring
        cannot carry a jump: outputs that read the rail's velocity, the
        rail-seat load (through the pad's dashpot) above all, ring with the
        mesh unless `hht_alpha` damps it.  Even then they converge only once
        the elements are short against the shear length sqrt(EI / kGA)
        (0.16 m on UIC60): on the paper's track at 45 m/s (constant loads)
        the peak rail-seat load is 26.6 to 26.9 kN from 32 elements per span
        on (h = 19 mm, 3600 to 14400 steps per period), but 26.8 to 27.6 kN
        at 4 to 16, against 27.1 to 28.7 kN at any mesh with average
        acceleration (Euler–Bernoulli: 25.43 kN at every mesh; with wheels on
        the 0.5 mm dip 27.42, 27.27, 27.21 kN at 8, 16, 32 elements per span;
        issue 27, `tests/test_ring_timoshenko.py`).  The point support itself is a
        limit: on it the rail-seat load jumps when a wheel passes the
        sleeper (the rail's velocity there jumps, the dashpot follows); a
        real pad spreads the load over its width.
    hht_alpha : float or None
        HHT-alpha's alpha in [0, 1/3] (`railtrack.timedomain.newmark.NewmarkStepper`):
        0 is average acceleration; a larger alpha damps the modes the step
        does not resolve (as omega dt -> inf an amplitude falls by
        (1 - alpha) / (1 + alpha) per step), while a resolved one loses about
        alpha (omega dt)^4 / 10 of its amplitude per step.  Default: 0 on the
        Euler–Bernoulli rail, 0.1 on a Timoshenko rail.
    progress : bool or None
        A ``tqdm`` bar counting the periods (`railtrack.solvers.progress`):
        None shows it for a run that also warns `LongRunWarning` (estimated
        past a minute), True or False force it.

    Returns
    -------
    TimeDomainSolution

    Raises
    ------
    ValueError
        If H / L is not an integer, a cell's size N does not divide the ring's
        wagons x H / L sleepers (the message names the wagon counts that
        fit), an argument is out of range,
        `steps_per_period` cannot represent the moving load, or the run would
        need more memory than `railtrack.timedomain.runcost.MEMORY_LIMIT` (checked before
        anything is allocated); `NonFiniteLawError` (a ValueError) if the
        foundation law returns NaN or infinity, naming w, w' and the step.
    RuntimeError
        If the response grows without bound (an unstable track: negative
        stiffness or damping) or Newton fails at some step; the message says
        when.

    Warns
    -----
    TimeStepWarning
        If the estimated time-step error exceeds `warn_step_error`, with the
        estimate and the steps that would meet it.
    LongRunWarning
        If the run is estimated to take more than a minute
        (`railtrack.timedomain.runcost.LONG_RUN_SECONDS`), with the estimate.
    railtrack.ConvergenceWarning
        If the response has not repeated to `tol` within `max_periods`
        (``converged=False``), with the last period's change; not when
        ``min_periods == max_periods``, a run of a fixed length asked for.

    Examples
    --------
    >>> from railtrack import Track, Train, LinearFoundation
    >>> result = simulate_time_domain(Track.paper(), Train.paper(), LinearFoundation.paper(), 2, 480)
    >>> result.converged, round(1e3 * float(result.sleeper_displacement.min()), 2)
    (True, -1.13)

    Sleeper 15 of every 30 hanging 1 mm above its ballast:

    >>> from railtrack import Passage
    >>> from railtrack.model.cell import SleeperCell
    >>> from railtrack.model.gap import GapFoundation
    >>> cell = SleeperCell.identical(Passage.paper(), LinearFoundation.paper(), 30).with_sleeper(
    ...     15, foundation=GapFoundation(1e-3, 20e6, 0.2e6))
    >>> hanging = simulate_time_domain(Track.paper(), Train.paper(), cell, 2, 480)
    >>> hanging.foundation_forces.shape, hanging.contact_fraction()[14:17].round(2)
    ((480, 30), array([0.57, 0.16, 0.59]))
    """
    with blas_threads(1):
        # called from here directly: their warnings point at this function's caller
        run = prepare_run(track, train, foundation, elements_per_span, steps_per_period, tol,
                          max_periods, start, min_periods, newton_tol, max_newton_iterations,
                          warn_step_error, wagons, wheel, profile, timoshenko, hht_alpha,
                          progress)
        return run_periods(run)
