"""The design figures of a solution: what ``summary()`` of every result computes (issue 29).

One function serves `railtrack.Solution` (a cell of one sleeper),
`railtrack.CellSolution` and `railtrack.WheelSolution`; it reads them
through their methods and fields, so that it imports none of their modules.

Where the extremes are looked for:

* rail-seat load and foundation force: every sleeper of the cell at ``n``
  instants a period (a power of two, >= 2048 and >= 4 per period of the
  highest harmonic; a cell's by an inverse FFT of its harmonics), each
  peak refined by the parabola through its neighbours;
* sagging moment: under every wheel, with the wheel at `points_per_span`
  points of each span of the cell (16 by default), since the sagging peak
  of a span is a cusp under a wheel (`railtrack.equations.moment`) that a
  grid fixed in x and t would cut off; and on the grid below;
* hogging moment: at 4 points a span (the sleepers among them) at 8
  instants for every span the train moves in a period (>= 128), refined in
  time by a parabola; for a `WheelSolution`, whose free rail costs one
  receptance per harmonic and point, at 2 points a span and 4 instants (a
  30-sleeper cell with m = 1057: 6 s).  Between point forces the static
  moment of a beam is linear, so its hogging extreme sits at a sleeper,
  where this grid has a point.  At walking pace every figure is within
  0.1 % of the exact static beam on discrete supports
  (tests/test_design_summary.py).

For the single-sleeper `Solution` the cell is one span: every sleeper is the
observed one, delayed.
"""

from __future__ import annotations

import numpy as np

from ..model.rail_section import UIC60, RailSection
from ..model.validation import require_positive
from .arguments import require_count
from .design_summary import DesignSummary, eisenmann_factor, EISENMANN_RANGE_KMH, TRACK_QUALITY
from .time_histories import periodic_peak

__all__ = ["DesignFigures", "design_summary"]

SECTION_MISMATCH = 0.1
"""Relative gap between the section's EI and the modelled rail's above which the summary says so."""



def _on_grid(coefficients: np.ndarray, samples: int) -> np.ndarray:
    """Re sum_n c_n e^{2 pi i n k / samples}, k < samples, for two-sided c_n, n = -m..m (rows).

    An inverse FFT: exact at the samples for any m < samples / 2, where the
    direct sum would cost samples x (2m + 1) phases (seconds at m = 1000).
    """
    m = (coefficients.shape[-1] - 1) // 2
    spectrum = np.zeros(coefficients.shape[:-1] + (samples,), dtype=complex)
    spectrum[..., np.arange(-m, m + 1) % samples] = coefficients
    return samples * np.fft.ifft(spectrum, axis=-1).real


def _histories(solution, cell_solution, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Rail-seat load and foundation force of every sleeper at `samples` instants a period [N]."""
    if cell_solution is None:                       # the single-sleeper Solution
        t = np.arange(samples) * float(solution.period) / samples
        return (np.asarray(solution.rail_seat_load(t), dtype=float)[None],
                np.asarray(solution.foundation_force(t), dtype=float)[None])
    c = cell_solution.coefficients
    w = _on_grid(c, samples)
    rate = _on_grid(1j * cell_solution.frequencies * c, samples)
    force = np.stack([-np.asarray(law.force(w[j], rate[j]), dtype=float)
                      for j, law in enumerate(cell_solution.cell.foundations)])
    return -_on_grid(cell_solution.seat_harmonics, samples), force + 0.0


def _moments(solution, sleepers: int, points_per_span: int,
             hogging_grid: tuple[int, int]) -> tuple[float, float]:
    """(largest sagging, most hogging) rail bending moment over the period and the cell [N m].

    `hogging_grid` is (points a span, instants for every span the train moves).
    """
    passage = solution.passage
    span, speed = float(passage.sleeper_spacing), float(passage.speed)
    period = float(solution.period)
    x = np.arange(sleepers * points_per_span) * span / points_per_span
    axles = np.asarray(passage.axle_positions, dtype=float)
    under = np.mod((x[:, None] + axles[None, :]) / speed, period)      # wheel j above x
    sagging = float(np.max(solution.rail_bending_moment(under, x[:, None])))
    points, per_span = hogging_grid
    count = max(128, per_span * int(np.ceil(float(passage.wagon_length) / span)))
    times = np.arange(count) * period / count
    at = np.arange(sleepers * points) * span / points                  # the sleepers among them
    grid = solution.rail_bending_moment(times[None, :], at[:, None])   # (x, t)
    hogging = float(np.min(periodic_peak(grid, -1.0)))
    return max(sagging, float(grid.max())), min(hogging, 0.0)


def _top_harmonic(solution) -> int:
    """The highest harmonic of the period in `solution`: the wheels' grid or the sleepers' m."""
    if hasattr(solution, "contact_harmonics"):
        top = int(np.max(solution.grid)) if solution.grid.size else 0
        return max(top, int(solution.sleepers.harmonics))
    return int(solution.harmonics)


def design_summary(solution, *, section: RailSection | None = None, bearing_area: float | None = None,
                   track_quality="good", certainty: float = 3.0,
                   points_per_span: int = 16) -> DesignSummary:
    """The design figures of `solution` (`railtrack.solvers.design_summary.DesignSummary`).

    Parameters
    ----------
    solution : Solution, CellSolution or WheelSolution
    section : RailSection, optional
        The rail's section for the stresses (default `railtrack.model.rail_section.UIC60`).
    bearing_area : float, optional
        Effective ballast bearing area under one rail seat (half a sleeper's) [m^2],
        for the ballast pressure.
    track_quality, certainty
        Eisenmann's s and t (`eisenmann_factor`), for a `WheelSolution`.
    points_per_span : int
        Positions of the wheel in each span for the sagging moment (>= 2).

    Returns
    -------
    DesignSummary
    """
    section = UIC60 if section is None else section
    if not isinstance(section, RailSection):
        raise TypeError(f"section must be a railtrack RailSection (e.g. UIC60); got "
                        f"{type(section).__name__}")
    if bearing_area is not None:
        require_positive("bearing_area", bearing_area, "m^2")
        bearing_area = float(bearing_area)
    points_per_span = require_count("points_per_span", points_per_span, 2)
    passage = solution.passage
    wheels = hasattr(solution, "contact_harmonics")
    cell_solution = solution.sleepers if wheels else solution
    if not hasattr(cell_solution, "seat_harmonics"):    # the single-sleeper Solution
        cell_solution = None
    sleepers = 1 if cell_solution is None else int(cell_solution.coefficients.shape[0])
    n = max(2048, 1 << int(np.ceil(np.log2(4 * (_top_harmonic(solution) + 1)))))
    histories = _histories(solution, cell_solution, n)
    seat, foundation = (periodic_peak(history, 1.0) for history in histories)
    # the free rail under the wheels costs a receptance per harmonic and point: fewer points
    sagging, hogging = _moments(solution, sleepers, points_per_span,
                                (2, 4) if wheels else (4, 8))

    span, loads = float(passage.sleeper_spacing), np.asarray(passage.axle_loads, dtype=float)
    gravity = float(getattr(getattr(cell_solution, "cell", None), "gravity", 0.0))
    mean_seat = float(loads.sum()) * span / float(passage.wagon_length) \
        + float(passage.rail_linear_mass) * gravity * span
    kind = type(solution).__name__
    case = (f"{kind}, {len(loads)} axle{'s' if len(loads) > 1 else ''} a wagon, "
            f"{sleepers} sleeper{'s' if sleepers > 1 else ''} a cell")
    notes = [] if solution.converged else [
        "the solve did not converge: these are not the track's figures"]
    stiffness = float(passage.rail_bending_stiffness)
    if abs(section.bending_stiffness / stiffness - 1.0) > SECTION_MISMATCH:
        notes.append(f"section {section.name} has EI = {section.bending_stiffness / 1e6:.2f} "
                     f"MN m^2, the modelled rail {stiffness / 1e6:.2f}: pass its own section")
    extra = {}
    if wheels:
        e = solution.extremes(n)
        share, longest = solution.loss_of_contact(max(8192, n))
        phi = eisenmann_factor(passage.speed, track_quality, certainty)
        s = TRACK_QUALITY.get(track_quality, track_quality)
        basis = f"s = {float(s):g}, t = {float(certainty):g}"
        if 3.6 * float(passage.speed) > EISENMANN_RANGE_KMH:
            basis += ", extrapolated beyond 200 km/h"
        extra = dict(contact_force_max=e["max"], contact_force_min=e["min"],
                     dynamic_factor=e["dynamic_factor"], contact_loss_share=share,
                     contact_loss_longest=longest, eisenmann=phi, eisenmann_basis=basis)
    return DesignSummary(case=case, converged=bool(solution.converged),
                         speed=float(passage.speed), wheel_load=float(loads.max()),
                         rail_seat_loads=seat, mean_rail_seat_load=mean_seat,
                         foundation_forces=foundation, bearing_area=bearing_area,
                         sagging_moment=sagging, hogging_moment=hogging, section=section,
                         notes=tuple(notes), **extra)


class DesignFigures:
    """``summary()`` of a steady-state result: `design_summary` of it."""

    def summary(self, **options) -> DesignSummary:
        """Design figures in kN, kPa, kN m, MPa (`railtrack.solvers.design_figures`).

        Per sleeper of a cell; with wheels, max P / Q beside Eisenmann's factor.
        Options: ``section`` (UIC60), ``bearing_area`` [m^2] for the ballast pressure,
        ``track_quality`` and ``certainty`` (Eisenmann's s and t), ``points_per_span``.
        """
        return design_summary(self, **options)
