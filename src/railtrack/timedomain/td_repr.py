"""The short repr of a `TimeDomainSolution`: the ring, its convergence and its extremes (issue 29).

A dozen lines: the case, the mesh and step, whether the period repeated,
and the extremes of the last period in mm, kN and kN m, read from the
stored histories (nothing is integrated again; a field the run did not
keep reads "n/a").  Rendered as text or as an HTML table
(`railtrack.solvers.result_repr`).
"""

from __future__ import annotations

import numpy as np

from ..solvers.result_repr import KN, MM, case_text, extent, law_text

__all__ = ["time_domain_rows"]


def _rows_first(values):
    """A (steps, n) history as (n, steps), as the steady-state results order their axes."""
    if values is None:
        return None
    values = np.asarray(values, dtype=float)
    return values.T if values.ndim == 2 else values


def time_domain_rows(s) -> tuple[str, list[tuple[str, str]]]:
    """Title and rows of a `railtrack.TimeDomainSolution`."""
    sleepers = np.shape(s.sleeper_displacements)[-1] if s.sleeper_displacements is not None else 1
    laws = getattr(s.foundation, "foundations", None) or [s.foundation]
    change = np.asarray(s.period_change, dtype=float)
    title = (f"TimeDomainSolution (FE ring of {sleepers} sleepers, {s.wagons} wagon(s)): "
             f"{'converged' if s.converged else 'NOT converged'}")
    seat = s.rail_seat_loads if s.rail_seat_loads is not None else s.rail_seat_load
    force = s.foundation_forces if s.foundation_forces is not None else s.foundation_force
    rows = [("case", "n/a" if s.passage is None else case_text(s.passage)),
            ("foundation", law_text(laws)),
            ("run", f"{int(s.periods)} periods of {int(s.steps_per_period)} steps, "
                    f"{int(s.elements_per_span)} elements a span; step error "
                    f"{float(s.step_error):.1e}"),
            ("last period change", f"{change[-1]:.1e}" if change.size else "n/a"),
            ("sleeper w [mm]", extent(_rows_first(s.sleeper_displacements), MM, 3, "min",
                                      "sleeper")),
            ("rail above sleeper 0 [mm]", extent(s.rail_displacement, MM, 3)),
            ("rail-seat load [kN]", extent(_rows_first(seat), KN, 2, "max", "sleeper")),
            ("foundation force [kN]", extent(_rows_first(force), KN, 2, "max", "sleeper")),
            ("moment above sleeper, midspan [kN m]",
             f"{extent(s.bending_moment_above_sleeper, KN, 2, 'max')}; "
             f"{extent(s.bending_moment_midspan, KN, 2, 'max')}")]
    if s.contact_forces is not None:
        rows.append(("contact force [kN]", extent(_rows_first(s.contact_forces), KN, 2, "max",
                                                  "wheel")))
    return title, rows

