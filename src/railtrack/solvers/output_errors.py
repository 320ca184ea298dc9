"""The truncation error of each output, not only of the sleeper's displacement.

`Solution.truncation_error` estimates how far the sleeper displacement w(t)
is from its untruncated value (`railtrack.solvers.truncation`).  The outputs
derived from it converge more slowly in m: the rail-seat load R (eq. 5)
holds the pad's velocity term, and the bending moment the rail's curvature,
whose harmonics fall more slowly than the displacement's.  On the paper's
track at 250 m/s with m chosen by ``harmonics="auto"`` (m = 22, w within
4.9e-4), a solve with 8 m harmonics puts R 0.95 % and the moment above the
sleeper 0.69 % of their peaks away.

The estimate here uses the same neglected harmonics c_{m+1}..c_{8m} as
`truncation_error` (the law linearised about the solution) and maps them to
each output through its own linear relation: eq. (6) for the rail, eq. (5)
(`seat_load_coefficients`) for the load, the curvature of
`railtrack.equations.rail_field` less the kinks summed in closed form
(`railtrack.equations.moment`) for the moment.  Each error is the largest
value over the period of the neglected part, over the peak of the output
with that part added.  On a ground (`railtrack.GroundSolution`) the tail
is that of eq. (G2)'s relative displacement d, moved to w = d + u.
"""

from __future__ import annotations

import numpy as np

from ..equations.load import load_coefficients
from ..equations.moment import kink_coefficients, kink_sum
from ..equations.rail_field import rail_field_coefficients, seat_load_coefficients
from ..equations.sleeper import rail_coefficients
from .spectrum import TAIL_FACTOR, _grid, _series, track_spectrum
from .truncation import tail_coefficients

__all__ = ["OUTPUTS", "output_truncation_errors"]

OUTPUTS = ("sleeper_displacement", "rail_displacement", "rail_seat_load", "rail_bending_moment")
"""The outputs whose truncation errors `output_truncation_errors` estimates."""


def _error(coefficients: np.ndarray, kept: int, samples: int,
           closed_form: np.ndarray | float = 0.0) -> float:
    """max_t |sum_{n > kept}| / max_t |whole|, one-sided coefficients n = 0..upto."""
    neglected = _series(coefficients[kept + 1:], kept + 1, samples)
    whole = _series(coefficients, 0, samples) + closed_form
    peak = float(np.max(np.abs(whole)))
    return float(np.max(np.abs(neglected))) / peak if peak > 0 else float("inf")


def output_truncation_errors(solution, x: float = 0.0) -> dict[str, float]:
    """Estimated truncation error of each output of `solution`, relative to its peak [-].

    Parameters
    ----------
    solution : railtrack.Solution
        A solution with finite coefficients.
    x : float
        Position of the rail ahead of the observed sleeper for the rail's
        displacement and bending moment [m] (0: above the sleeper).

    Returns
    -------
    dict
        ``{"sleeper_displacement", "rail_displacement", "rail_seat_load",
        "rail_bending_moment"}`` -> max over the period of the neglected
        harmonics' share over the output's peak (module docstring).  The first
        is `Solution.truncation_error`'s estimate.  NaN for all if the
        coefficients are not finite.
    """
    x = float(x)
    if not np.all(np.isfinite(solution.coefficients)):
        return dict.fromkeys(OUTPUTS, float("nan"))
    passage, m = solution.passage, solution.harmonics
    upto = TAIL_FACTOR * m
    ground = getattr(solution, "ground", None)
    spectrum = track_spectrum(passage, upto, ground)
    system = spectrum.system(passage, solution.foundation, m, solution.samples)
    kept = np.asarray(solution.coefficients[m:], dtype=complex)          # c_0..c_m
    # on a ground the law sees d (eq. G2); w = d + u, u = -R_g M (op' d + F') beyond m
    relative = kept if ground is None else solution.relative_coefficients[m:]
    with np.errstate(over="ignore", invalid="ignore"):
        tail = tail_coefficients(system, relative, spectrum)[: upto - m]
    if ground is not None:
        tail = tail - (spectrum.receptance[m + 1:] * float(passage.sleeper_mass)
                       * (spectrum.operator[m + 1:] * tail + spectrum.load[m + 1:]))
    sleeper = np.concatenate([kept, tail])                                # c_0..c_8m
    omega = spectrum.omega
    samples = _grid(upto)
    if x == 0.0:
        rail = rail_coefficients(passage, omega, sleeper, load_coefficients(passage, omega))
    else:
        rail = rail_field_coefficients(passage, omega, sleeper, [x])[0][0]
    curvature = rail_field_coefficients(passage, omega, sleeper, [x])[1][0]
    moment = (float(passage.rail_bending_stiffness) * curvature
              - kink_coefficients(passage, omega, [x])[0])
    kinks = kink_sum(passage, float(passage.period) * np.arange(samples) / samples, x)
    return {
        "sleeper_displacement": _error(sleeper, m, samples),
        "rail_displacement": _error(rail, m, samples),
        "rail_seat_load": _error(seat_load_coefficients(passage, omega, sleeper), m, samples),
        "rail_bending_moment": _error(moment, m, samples, kinks),
    }
