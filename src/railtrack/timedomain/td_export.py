"""The time-domain ring's result, `TimeDomainSolution`, as an `xarray.Dataset`.

The ring's own grid of one period is kept (``time``, the integrator's
steps): nothing is resampled.  Every ring sleeper is on ``sleeper``, the
wheels (with ``wheel=``) on ``wheel``; what the ring gives at sleeper 0
only (the rail there and at mid-span) is named so.

* on ``(sleeper, time)``: sleeper_displacement [m], rail_seat_load [N],
  foundation_force [N], rail_bending_moment_at_sleeper and
  rail_bending_moment_midspan [N m];
* on ``time``: rail_displacement_at_sleeper_0, rail_displacement_midspan_0 [m];
* with wheels, on ``(wheel, time)``: contact_force [N], wheel_displacement
  and rail_under_wheel [m];
* sleeper_0_history [m] on ``(period, time)``; period_change [1] on
  ``period_step``;
* a run on a `SleeperCell`: its laws and fields on ``cell_sleeper``.

Rules as `railtrack.solvers.export`.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import xarray as xr

from ..solvers.export import FIELD_UNITS, base_attrs, flag, input_attrs, variable

__all__ = ["time_domain_dataset"]

RING_SLEEPERS = {
    "sleeper_displacements": ("sleeper_displacement", "m",
                              "vertical displacement of the sleeper, positive upward"),
    "rail_seat_loads": ("rail_seat_load", "N",
                        "rail-seat load (pad force on the sleeper), positive in compression"),
    "foundation_forces": ("foundation_force", "N",
                          "force of the sleeper on its foundation, positive in compression"),
    "bending_moments_above_sleepers": ("rail_bending_moment_at_sleeper", "N m",
                                       "bending moment of the rail above the sleeper, "
                                       "positive when sagging"),
    "bending_moments_midspan": ("rail_bending_moment_midspan", "N m",
                                "bending moment of the rail at mid-span after the sleeper, "
                                "positive when sagging"),
}
SLEEPER_ZERO = {
    "rail_displacement": ("rail_displacement_at_sleeper_0", "m",
                          "vertical displacement of the rail above sleeper 0, positive upward"),
    "rail_displacement_midspan": ("rail_displacement_midspan_0", "m",
                                  "vertical displacement of the rail at x = L / 2, positive "
                                  "upward"),
}
WHEELS = {
    "contact_forces": ("contact_force", "N", "wheel-rail contact force, positive in compression"),
    "wheel_displacements": ("wheel_displacement", "m",
                            "vertical displacement of the wheel, positive upward"),
    "rail_under_wheels": ("rail_under_wheel", "m",
                          "vertical displacement of the rail under the wheel, positive upward"),
}


def _law_input(foundation) -> tuple[dict, dict]:
    """A law as attributes; a `SleeperCell` as its laws' names and fields per cell sleeper."""
    if foundation is None or not hasattr(foundation, "foundations"):
        return input_attrs(foundation=foundation), {}
    laws = foundation.foundations
    names = np.array([type(law).__name__ for law in laws])
    data = {"cell_foundation_law": variable("cell_sleeper", names, "1",
                                            "foundation law of the cell's sleeper")}
    for name in ("sleeper_mass", "pad_stiffness", "pad_damping"):
        data[f"cell_{name}"] = variable("cell_sleeper", getattr(foundation, name),
                                        {"sleeper_mass": "kg", "pad_stiffness": "N m-1",
                                         "pad_damping": "N s m-1"}[name],
                                        f"{name.replace('_', ' ')} of the cell's sleeper")
    fields = {f.name for law in laws if dataclasses.is_dataclass(law)
              for f in dataclasses.fields(law)}
    for name in sorted(fields & set(FIELD_UNITS)):
        values = [float(getattr(law, name, np.nan)) for law in laws]
        data[f"cell_foundation_{name}"] = variable("cell_sleeper", values, FIELD_UNITS[name],
                                                   f"{name.replace('_', ' ')} of the law")
    return {"foundation_law": "SleeperCell", "gravity": float(foundation.gravity)}, data


def time_domain_dataset(result) -> xr.Dataset:
    """A `railtrack.TimeDomainSolution`: the last period on the ring's own time grid."""
    t = np.asarray(result.times, dtype=float)
    n = np.shape(result.sleeper_displacements)[1]
    data = {}
    for field, (name, unit, long_name) in RING_SLEEPERS.items():
        values = getattr(result, field)
        if values is not None:
            data[name] = variable(("sleeper", "time"), np.asarray(values).T, unit, long_name)
    for field, (name, unit, long_name) in SLEEPER_ZERO.items():
        if getattr(result, field) is not None:
            data[name] = variable("time", getattr(result, field), unit, long_name)
    coords = {"time": variable("time", t, "s", "time since a wagon's first axle passed "
                                               "sleeper 0"),
              "sleeper": variable("sleeper", np.arange(n), "1", "index of the ring's sleeper")}
    if result.passage is not None:
        coords["sleeper_position"] = variable(
            "sleeper", float(result.passage.sleeper_spacing) * np.arange(n), "m",
            "position of the sleeper along the ring")
    if result.contact_forces is not None:
        for field, (name, unit, long_name) in WHEELS.items():
            values = getattr(result, field)
            if values is not None:
                data[name] = variable(("wheel", "time"), np.asarray(values).T, unit, long_name)
        coords["wheel"] = variable("wheel", np.arange(np.shape(result.contact_forces)[1]), "1",
                                   "index of the ring's wheel (the tiled train's axles)")
    if result.sleeper_history is not None:
        data["sleeper_0_history"] = variable(
            ("period", "time"), result.sleeper_history, "m",
            "displacement of sleeper 0 in every period integrated, positive upward")
        coords["period"] = variable("period", np.arange(1, len(result.sleeper_history) + 1),
                                    "1", "period integrated")
    if np.size(result.period_change):
        data["period_change"] = variable(
            "period_step", result.period_change, "1",
            "largest change of sleeper 0's response between consecutive periods over its peak")
        coords["period_step"] = variable("period_step", np.arange(2, result.periods + 1), "1",
                                         "period compared with the one before")
    attrs = base_attrs(
        "TimeDomainSolution", "Periodic steady response of the finite-element ring (railtrack)",
        converged=flag(result.converged), periods=result.periods,
        elements_per_span=result.elements_per_span, steps_per_period=result.steps_per_period,
        step_error=result.step_error, wagons=result.wagons,
        period=float(t[1] - t[0]) * len(t) if len(t) > 1 else None)
    law_attrs, law_data = _law_input(result.foundation)
    data.update(law_data)
    attrs.update(input_attrs(result.passage, wheel=result.wheel))
    attrs.update(law_attrs)
    return xr.Dataset(data, coords=coords, attrs=attrs)
