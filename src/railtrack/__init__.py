"""railtrack: periodic response of a railway track on a nonlinear foundation.

A reproduction of T. Hoang, D. Duhamel, G. Foret, H.P. Yin, G. Cumunel,
"A fast semi-analytical method for computing the response of railway
tracks on nonlinear foundations", COMPDYN 2015.  The package is layered;
each subpackage imports only from its own layer or those above it in this
list:

======================  ==============================================
`railtrack.model`       the parameters: track, train, their passage, foundation laws
`railtrack.equations`   the paper's equations (3)-(23): receptance, rail field,
                        sleeper, load, harmonic-balance residual and Jacobian,
                        the linear closed form; free waves of the smeared track
`railtrack.solvers`     `solve` and its methods (fixed point, Newton, batch),
                        truncation, the `Solution` and its outputs, energy
`railtrack.timedomain`  the independent check: the finite-element ring in time
`railtrack.studies`     many solutions: `sweep`, `continuation`, stability, ramps
`railtrack.plotting`    figures: plots of your own results, and the book's recipes
======================  ==============================================

The names below are the public interface, ``import railtrack as rt``.
SI units throughout.  w is positive upward (the train pushes it negative);
t = 0 when a wagon's first axle is above the observed sleeper.

>>> import railtrack
>>> solution = railtrack.solve(railtrack.Track.paper(), railtrack.Train.paper(),
...                            railtrack.BilinearFoundation.paper(ratio=0.5))
>>> solution.converged
True
"""

from .model.foundations import (
    BilinearFoundation,
    CallableFoundation,
    CubicFoundation,
    LinearFoundation,
    as_foundation,
)
from .solvers.energy import Dissipation, dissipation, load_work
from .equations.linear import analytic_coefficients, sweep_extremes, sweep_speeds
from .equations.rail_field import offset_receptance
from .equations.receptance import rail_receptance, rail_receptance_lattice_sum
from .equations.sleeper import rail_coupling
from .solvers.solution import ConvergenceError, ConvergenceWarning, Solution, TruncationWarning
from .solvers.solve import METHODS, solve
from .studies.sweep import Sweep, sweep
from .studies.continuation import continuation
from .studies.branch import Branch, Fold, StabilityChange
from .solvers.floquet import Floquet, floquet
from .solvers.stability_hint import UnstableSolutionWarning
from .studies.stability import StabilityCheck, check_stability
from .studies.branch_stability import check_branch
from .studies.ramp import SpeedRamp, speed_ramp
from .timedomain.newmark import NonFiniteLawError
from .timedomain.runcost import LongRunWarning
from .timedomain.simulation import TimeDomainSolution, simulate_time_domain
from .timedomain.monodromy import RingMultipliers, ring_multipliers
from .timedomain.timestep import TimeStepWarning, estimate_step_error
from .equations.load import axle_factor, load_coefficients
from .model.passage import Passage
from .model.ground_protocol import WinklerGround
from .model.ground import Ground, SoilLayer
from .equations.ground_layered import LayeredGround
from .solvers.ground_solution import GroundSolution
from .model.cell import SleeperCell
from .model.gap import GapFoundation
from .solvers.cell_solution import CellSolution
from .studies.random_support import RandomSupport, random_support
from .model.wheel import Wheel
from .model.vehicle import Vehicle
from .model.profile import CosineDip, DippedJoint
from .model.wheel_flat import WheelFlat
from .model.profile_sum import ProfileSum
from .solvers.wheel_solution import WheelSolution
from .model.timoshenko import TimoshenkoRail
from .studies.p2_force import EquivalentTrack, equivalent_track, p2_force
from .model.track import Track
from .model.train import Train
from .model.plausibility import PlausibilityWarning, plausible_ranges
from .model.plausibility_check import plausibility
from .model.rail_section import RailSection, UIC54, UIC60
from .solvers.design_summary import DesignSummary, eisenmann_factor


def explore(**initial):
    """The classroom explorer: sliders redrawing the response (`railtrack.plotting.explorer`).

    Imported on call, so that ``import railtrack`` does not load matplotlib
    and ipywidgets.
    """
    from .plotting.explorer import explore as _explore

    return _explore(**initial)


__version__ = "0.1.0"

__all__ = [
    "Track",
    "Train",
    "Passage",
    "WinklerGround",
    "SoilLayer",
    "Ground",
    "LayeredGround",
    "GroundSolution",
    "LinearFoundation",
    "BilinearFoundation",
    "CubicFoundation",
    "CallableFoundation",
    "GapFoundation",
    "SleeperCell",
    "CellSolution",
    "random_support",
    "RandomSupport",
    "Wheel",
    "Vehicle",
    "CosineDip",
    "DippedJoint",
    "WheelFlat",
    "ProfileSum",
    "WheelSolution",
    "TimoshenkoRail",
    "p2_force",
    "EquivalentTrack",
    "equivalent_track",
    "as_foundation",
    "solve",
    "METHODS",
    "sweep",
    "Sweep",
    "continuation",
    "Branch",
    "Fold",
    "StabilityChange",
    "floquet",
    "Floquet",
    "UnstableSolutionWarning",
    "check_stability",
    "StabilityCheck",
    "check_branch",
    "speed_ramp",
    "SpeedRamp",
    "Solution",
    "ConvergenceError",
    "ConvergenceWarning",
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
    "ring_multipliers",
    "RingMultipliers",
    "TimeStepWarning",
    "LongRunWarning",
    "NonFiniteLawError",
    "estimate_step_error",
    "explore",
    "dissipation",
    "Dissipation",
    "load_work",
    "PlausibilityWarning",
    "plausible_ranges",
    "plausibility",
    "RailSection",
    "UIC60",
    "UIC54",
    "DesignSummary",
    "eisenmann_factor",
]
