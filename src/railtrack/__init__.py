"""railtrack: periodic response of a railway track on a nonlinear foundation.

A reproduction of T. Hoang, D. Duhamel, G. Foret, H.P. Yin, G. Cumunel,
"A fast semi-analytical method for computing the response of railway
tracks on nonlinear foundations", COMPDYN 2015.  Modules follow the paper:

=====================  ==============================================
`railtrack.track`      the track: rail, pads, sleepers (Table 1)
`railtrack.train`      the train: wagon length, axles, loads, speed
`railtrack.passage`    the train on the track, as the equations take it
`railtrack.receptance` Section 2.1, eq. (3): the rail's receptance
`railtrack.rail_field` eq. (3) at any offset x: the rail between sleepers
`railtrack.moment`     the rail's bending moment: its kinks in closed form
`railtrack.bowl`       the deflection bowl along the track
`railtrack.energy`     work of the pads, the foundation and the loads
`railtrack.dispersion` free waves of the smeared track; harmonics' resonance speeds
`railtrack.ballast`    a ballast-subgrade support reduced to one layer
`railtrack.sleeper`    Section 2.2, eqs. (4)–(8), (14): pad, coupling P
`railtrack.load`       Section 2.3, eqs. (9)–(16): the load F
`railtrack.harmonic_balance`  Section 3, eqs. (17)–(20): residual, AFT
`railtrack.aft_jacobian`      the exact Jacobian of that residual
`railtrack.fixed_point`       eq. (21): the paper's iteration
`railtrack.newton`     Newton's method on eq. (17)
`railtrack.foundations`  eqs. (22), (24), (25): foundation laws
`railtrack.linear`     Section 4.1, eq. (23): analytic linear solution
`railtrack.truncation` how many harmonics: the truncation error, m = "auto"
`railtrack.solve`      the entry point `solve`
`railtrack.batch`      Newton on a batch of systems at once
`railtrack.sweep`      `sweep`: many solves over any field, at once
`railtrack.continuation` `continuation`: a branch followed through its folds
`railtrack.branch`     the `Branch` it returns, and its folds
`railtrack.fem`        finite-element ring of the same track (check)
`railtrack.timedomain` Newmark time integration of that ring (check)
`railtrack.ring_outputs` the ring's moments and forces, from its nodal states
`railtrack.timestep`   the time steps it needs and its time-step error
`railtrack.runcost`    its memory and run time, estimated before it starts
`railtrack.ring_state` the ring started from a harmonic-balance solution
`railtrack.spectrum`   the spectrum of a record: periodic or not?
`railtrack.stability`  `check_stability`: does the ring stay on a solution?
`railtrack.branch_stability` `check_branch`: the same along a branch, sampled
`railtrack.ramp`       `speed_ramp`: the ring through rising or falling speeds
`railtrack.explorer`   `explore`: sliders for the classroom (JupyterLab)
=====================  ==============================================

SI units throughout.  w is positive upward (the train pushes it negative);
t = 0 when a wagon's first axle is above the observed sleeper.

>>> import railtrack
>>> solution = railtrack.solve(railtrack.Track.paper(), railtrack.Train.paper(),
...                            railtrack.BilinearFoundation.paper(ratio=0.5))
>>> solution.converged
True
"""

from .foundations import (
    BilinearFoundation,
    CallableFoundation,
    CubicFoundation,
    LinearFoundation,
    as_foundation,
)
from .energy import Dissipation, dissipation, load_work
from .linear import analytic_coefficients, sweep_extremes, sweep_speeds
from .rail_field import offset_receptance
from .receptance import rail_receptance, rail_receptance_lattice_sum
from .sleeper import rail_coupling
from .solution import ConvergenceError, Solution, TruncationWarning
from .solve import METHODS, solve
from .sweep import Sweep, sweep
from .continuation import continuation
from .branch import Branch, Fold
from .stability import StabilityCheck, check_stability
from .branch_stability import check_branch
from .ramp import SpeedRamp, speed_ramp
from .newmark import NonFiniteLawError
from .runcost import LongRunWarning
from .timedomain import TimeDomainSolution, simulate_time_domain
from .timestep import TimeStepWarning, estimate_step_error
from .load import axle_factor, load_coefficients
from .passage import Passage
from .track import Track
from .train import Train


def explore(**initial):
    """The classroom explorer: sliders redrawing the response (`railtrack.explorer`).

    Imported on call, so that ``import railtrack`` does not load matplotlib
    and ipywidgets.
    """
    from .explorer import explore as _explore

    return _explore(**initial)


__version__ = "0.1.0"

__all__ = [
    "Track",
    "Train",
    "Passage",
    "LinearFoundation",
    "BilinearFoundation",
    "CubicFoundation",
    "CallableFoundation",
    "as_foundation",
    "solve",
    "METHODS",
    "sweep",
    "Sweep",
    "continuation",
    "Branch",
    "Fold",
    "check_stability",
    "StabilityCheck",
    "check_branch",
    "speed_ramp",
    "SpeedRamp",
    "Solution",
    "ConvergenceError",
    "TruncationWarning",
    "analytic_coefficients",
    "sweep_speeds",
    "sweep_extremes",
    "rail_receptance",
    "rail_receptance_lattice_sum",
    "offset_receptance",
    "rail_coupling",
    "load_coefficients",
    "axle_factor",
    "simulate_time_domain",
    "TimeDomainSolution",
    "TimeStepWarning",
    "LongRunWarning",
    "NonFiniteLawError",
    "estimate_step_error",
    "explore",
    "dissipation",
    "Dissipation",
    "load_work",
]
