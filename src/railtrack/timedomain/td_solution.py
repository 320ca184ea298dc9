"""The result of the time-domain check, `railtrack.simulate_time_domain`."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..model.passage import Passage
from ..solvers.export import Exports
from ..solvers.result_repr import ShortRepr
from .td_repr import time_domain_rows

__all__ = ["TimeDomainSolution"]


@dataclass(frozen=True, eq=False, repr=False)
class TimeDomainSolution(ShortRepr, Exports):
    """Periodic steady response of the FE ring found by `simulate_time_domain`.

    Attributes
    ----------
    times : ndarray, shape (steps_per_period,)
        One period, t = 0, dt, ..., T - dt [s]; t = 0 when a wagon's first axle is
        above sleeper 0.
    sleeper_displacement : ndarray, shape (steps_per_period,)
        w(t) of sleeper 0 over the last period [m], positive upward.
    rail_displacement : ndarray, shape (steps_per_period,)
        Rail deflection above sleeper 0 over the last period [m].
    sleeper_displacements : ndarray, shape (steps_per_period, n_sleepers)
        All sleepers over the last period [m]; in the steady state sleeper i
        lags sleeper 0 by i L / v.
    rail_displacement_midspan, bending_moment_above_sleeper, bending_moment_midspan,
    rail_seat_load, foundation_force : ndarray, shape (steps_per_period,)
        Over the last period: rail at x = L / 2 [m]; EI w'' at x = 0 and
        L / 2, sagging positive [N m]; pad force on sleeper 0 and force on
        its foundation, positive in compression [N] (`railtrack.timedomain.ring_outputs`).
    periods : int
        Periods integrated.
    converged : bool
        Whether the last period's sleeper-0 response differed from the one
        before by at most ``tol`` times its peak: the state repeats, which
        says nothing of the mesh or the step (on a Timoshenko rail the
        rail-seat load needs a fine mesh, `simulate_time_domain`'s
        ``timoshenko``); ``False`` comes with a `railtrack.ConvergenceWarning`.
    period_change : ndarray, shape (periods - 1,)
        max |w_k - w_{k-1}| / max |w_k| between consecutive periods k [-].
    elements_per_span : int
    steps_per_period : int
    passage : Passage
    foundation : object
    step_error : float
        Estimated time-step error, max |w - w_exact| of sleeper 0 over its
        peak [-] (`railtrack.timedomain.timestep.estimate_step_error`, for the track
        linearized about its static state); NaN if not estimated.
    sleeper_history : ndarray, shape (periods, steps_per_period)
        Sleeper 0 over every period integrated [m]: row k is period k + 1.
    final_state : (ndarray, ndarray), shape (n_dofs,) each
        Ring displacements and velocities at the end of the last period
        [m, rad], [m/s, rad/s]: the wheels are back at their t = 0 places,
        so this is a valid ``start`` for another run.
    rail_seat_loads, foundation_forces : ndarray, shape (steps_per_period, n_sleepers)
        Over the last period, for every ring sleeper i: the pad force
        k1_i (w_i - w_r) + eta1_i (w_i - w_r)' and the force -f_i(w_i, w_i') on
        its foundation, positive in compression [N]
        (`railtrack.timedomain.ring_fields`); column 0 is `rail_seat_load`,
        `foundation_force`.  The sleepers' own displacements are
        `sleeper_displacements`.
    bending_moments_above_sleepers, bending_moments_midspan : ndarray
        Shape (steps_per_period, n_sleepers).
        Rail moment EI w'' above sleeper i (x = i L) and at the mid-span
        between sleepers i and i + 1 (x = (i + 1/2) L), sagging positive
        [N m]; column 0 is `bending_moment_above_sleeper`, `bending_moment_midspan`.
    wagons : int
        Wagons on the ring; its sleepers number wagons x H / L and `passage`
        holds the tiled train (a period of wagons x H / v).
    contact_forces, wheel_displacements, rail_under_wheels : ndarray or None
        With wheels (``simulate_time_domain(..., wheel=...)``), shape
        (steps_per_period, J) for the J wheels of the ring (the tiled train's
        axles, in order): the Hertz contact force P >= 0 [N], the wheel's
        displacement z and the rail's displacement u_c under it [m], positive
        upward, over the last period; None for constant moving forces.
        `loss_of_contact` gives when P = 0.
    wheel : Wheel, Vehicle or None
        The wheel (or vehicle above the wheels) of the run.

    A `SleeperCell` run keeps the cell in `foundation`; ring sleeper i is its
    sleeper i mod N.  `contact_fraction` gives each sleeper's share of the
    period on its ballast.
    """

    times: np.ndarray
    sleeper_displacement: np.ndarray
    rail_displacement: np.ndarray
    sleeper_displacements: np.ndarray
    periods: int
    converged: bool
    period_change: np.ndarray
    elements_per_span: int
    steps_per_period: int
    passage: Passage | None = None
    foundation: Any = None
    step_error: float = float("nan")
    rail_displacement_midspan: np.ndarray | None = None
    bending_moment_above_sleeper: np.ndarray | None = None
    bending_moment_midspan: np.ndarray | None = None
    rail_seat_load: np.ndarray | None = None
    foundation_force: np.ndarray | None = None
    sleeper_history: np.ndarray | None = None
    final_state: tuple[np.ndarray, np.ndarray] | None = None
    rail_seat_loads: np.ndarray | None = None
    foundation_forces: np.ndarray | None = None
    bending_moments_above_sleepers: np.ndarray | None = None
    bending_moments_midspan: np.ndarray | None = None
    wagons: int = 1
    contact_forces: np.ndarray | None = None
    wheel_displacements: np.ndarray | None = None
    rail_under_wheels: np.ndarray | None = None
    wheel: Any = None

    def contact_fraction(self, threshold: float = 0.0) -> np.ndarray:
        """Share of the last period during which each ring sleeper's foundation pushes [-].

        The fraction of the steps with `foundation_forces` > `threshold` [N]
        (`railtrack.timedomain.ring_cell.contact_fraction`), shape (n_sleepers,):
        1 on the ballast all period, 0 hanging all period.
        """
        from .ring_cell import contact_fraction

        if self.foundation_forces is None:
            raise ValueError("this solution has no per-sleeper foundation forces")
        return contact_fraction(self.foundation_forces, threshold)

    def loss_of_contact(self) -> tuple[np.ndarray, np.ndarray]:
        """Each wheel's share of the last period with P = 0 [-] and its longest such stretch [s].

        Shapes (J,) each (`railtrack.timedomain.ring_contact.loss_of_contact`;
        a stretch over the period's end continues at its start).
        """
        from .ring_contact import loss_of_contact

        if self.contact_forces is None:
            raise ValueError("this solution has no wheels: run simulate_time_domain(..., "
                             "wheel=Wheel(...)) for contact forces")
        return loss_of_contact(self.contact_forces, float(self.times[1] - self.times[0]))

    _rows = time_domain_rows            # __repr__, _repr_html_ (ShortRepr)
    _table_row = "time"                 # to_dataframe: a row per instant

    def to_xarray(self):
        """The last period as an `xarray.Dataset` (CF units; `railtrack.timedomain.td_export`)."""
        from .td_export import time_domain_dataset
        return time_domain_dataset(self)

