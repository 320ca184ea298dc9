"""The solvers' periodic results as `xarray.Dataset`: Solution, CellSolution, WheelSolution.

The three periodic results share their names and dimensions (a `Solution`
is the cell of one sleeper, ``sleeper = 0``), sampled at ``samples``
instants over one period, t = 0 when a wagon's first axle is above sleeper 0:

* on ``(sleeper, time)``: sleeper_displacement [m], sleeper_velocity
  [m s-1], rail_seat_load [N], foundation_force [N],
  rail_displacement_at_sleeper [m], rail_bending_moment_at_sleeper [N m]
  (not for the sleepers of a wheel solution's cell, whose rail field is the
  wheel solution's);
* on ``(sleeper, harmonic)``: sleeper_displacement_coefficient_real, _imag [m];
* with ``x=`` positions [m]: rail_displacement [m] and rail_bending_moment
  [N m] on ``(x, time)``;
* a cell adds per sleeper its cell_sleeper_mass, cell_pad_stiffness,
  cell_pad_damping, foundation_law and foundation_<field> (NaN where the
  law has no such field), and contact_fraction [1];
* a wheel solution adds on ``(wheel, time)`` contact_force [N],
  compression, wheel_displacement, wheel_position [m]; lift [m] per wheel;
  contact_force_harmonic_real, _imag [N] on ``(wheel, wheel_harmonic)``.

Coordinates: time [s], sleeper and sleeper_position [m], harmonic and
angular_frequency [rad s-1], wheel with axle_position [m] and axle_load
[N].  The rules (units, long names, attributes) are
`railtrack.solvers.export`'s.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from .export import (FIELD_UNITS, base_attrs, complex_parts, flag, input_attrs, time_grid,
                     variable)

__all__ = ["solution_dataset", "cell_dataset", "wheel_dataset"]

SLEEPER_OUTPUTS = {
    "sleeper_displacement": ("m", "vertical displacement of the sleeper, positive upward"),
    "sleeper_velocity": ("m s-1", "vertical velocity of the sleeper, positive upward"),
    "rail_seat_load": ("N", "rail-seat load (pad force on the sleeper), positive in "
                            "compression"),
    "foundation_force": ("N", "force of the sleeper on its foundation, positive in compression"),
    "rail_displacement_at_sleeper": ("m", "vertical displacement of the rail above the "
                                          "sleeper, positive upward"),
    "rail_bending_moment_at_sleeper": ("N m", "bending moment of the rail above the "
                                              "sleeper, positive when sagging"),
}


def _coordinates(t: np.ndarray, harmonics: int, frequencies: np.ndarray,
                 positions: np.ndarray) -> dict:
    return {
        "time": variable("time", t, "s", "time since a wagon's first axle passed sleeper 0"),
        "sleeper": variable("sleeper", np.arange(positions.size), "1",
                            "index of the sleeper in the cell"),
        "sleeper_position": variable("sleeper", positions, "m",
                                     "position of the sleeper along the track"),
        "harmonic": variable("harmonic", np.arange(-harmonics, harmonics + 1), "1",
                             "harmonic number n of the wagon-passing frequency"),
        "angular_frequency": variable("harmonic", frequencies, "rad s-1",
                                      "angular frequency omega_n of the harmonic"),
    }


def _histories(outputs: dict) -> dict:
    return {name: variable(("sleeper", "time"), values, *SLEEPER_OUTPUTS[name])
            for name, values in outputs.items()}


def _coefficients(coefficients: np.ndarray) -> dict:
    return complex_parts("sleeper_displacement_coefficient", ("sleeper", "harmonic"),
                         np.atleast_2d(coefficients), "m",
                         "Fourier coefficient c_n of the sleeper displacement")


def _rail_field(result, t: np.ndarray, x) -> tuple[dict, dict]:
    """The rail along x [m] at every time: displacement and bending moment on (x, time)."""
    if x is None:
        return {}, {}
    x = np.atleast_1d(np.asarray(x, dtype=float))
    if x.ndim != 1:
        raise ValueError(f"x (positions along the rail) must be a 1-D array [m]; got shape "
                         f"{x.shape}")
    grid_t, grid_x = t[None, :], x[:, None]
    data = {
        "rail_displacement": variable(("x", "time"), result.rail_displacement(grid_t, grid_x),
                                      "m", "vertical displacement of the rail, positive upward"),
        "rail_bending_moment": variable(("x", "time"), result.rail_bending_moment(grid_t, grid_x),
                                        "N m", "bending moment of the rail, positive when "
                                               "sagging"),
    }
    return data, {"x": variable("x", x, "m", "position along the rail from sleeper 0")}


def _stability_attrs(stability) -> dict:
    if stability is None:
        return {}
    return {"stability_verdict": stability.verdict,
            "dominant_multiplier_real": float(np.real(stability.dominant)),
            "dominant_multiplier_imag": float(np.imag(stability.dominant))}


def solution_dataset(solution, samples: int = 400, x=None) -> xr.Dataset:
    """A `railtrack.Solution` over one period, as the cell of its one sleeper (sleeper = 0)."""
    t = time_grid(solution.period, samples)
    one = {"sleeper_displacement": solution.sleeper_displacement(t),
           "sleeper_velocity": solution.sleeper_velocity(t),
           "rail_seat_load": solution.rail_seat_load(t),
           "foundation_force": solution.foundation_force(t),
           "rail_displacement_at_sleeper": solution.rail_displacement(t, 0.0),
           "rail_bending_moment_at_sleeper": solution.rail_bending_moment(t, 0.0)}
    data = _histories({name: values[None, :] for name, values in one.items()})
    data.update(_coefficients(solution.coefficients))
    field, coords = _rail_field(solution, t, x)
    data.update(field)
    coords.update(_coordinates(t, solution.harmonics, solution.frequencies, np.zeros(1)))
    errors = {f"truncation_error_{k}": v for k, v in solution.truncation_errors().items()}
    attrs = base_attrs(
        "Solution", "Periodic steady response of a track on one kind of sleeper (railtrack)",
        method=solution.method, harmonics=solution.harmonics, converged=flag(solution.converged),
        residual=solution.residual, iterations=solution.iterations,
        truncation_error=solution.truncation_error, aft_samples=solution.samples,
        split=solution.split, period=solution.period, message=solution.message, **errors)
    attrs.update(_stability_attrs(solution.stability))
    attrs.update(input_attrs(solution.passage, solution.foundation))
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _cell_variables(cell) -> dict:
    """Each sleeper's mass, pad and law, on the sleeper dimension."""
    laws = cell.foundations
    data = {
        "cell_sleeper_mass": variable("sleeper", cell.sleeper_mass, "kg", "mass of the sleeper"),
        "cell_pad_stiffness": variable("sleeper", cell.pad_stiffness, "N m-1",
                                       "stiffness of the rail pad"),
        "cell_pad_damping": variable("sleeper", cell.pad_damping, "N s m-1",
                                     "damping of the rail pad"),
        "foundation_law": variable("sleeper", np.array([type(law).__name__ for law in laws]),
                                   "1", "foundation law of the sleeper"),
    }
    for name, unit in FIELD_UNITS.items():
        values = [getattr(law, name, None) for law in laws]
        if any(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            numbers = [float(v) if isinstance(v, (int, float)) else np.nan for v in values]
            data[f"foundation_{name}"] = variable("sleeper", numbers, unit,
                                                  f"{name.replace('_', ' ')} of the foundation law")
    return data


def _cell_histories(cell, t: np.ndarray, rail) -> dict:
    """The sleepers' histories; `rail` gives the rail's moment (None where it does not hold).

    The rail above each sleeper follows from the pad (`rail_above_sleepers`),
    which equals the cell's rail field there to round-off.
    """
    x = cell.passage.sleeper_spacing * np.arange(cell.sleepers)
    outputs = {"sleeper_displacement": cell.sleeper_displacement(t),
               "sleeper_velocity": cell.sleeper_velocity(t),
               "rail_seat_load": cell.rail_seat_load(t),
               "foundation_force": cell.foundation_force(t),
               "rail_displacement_at_sleeper": cell.rail_above_sleepers(t)}
    if rail is not None:
        outputs["rail_bending_moment_at_sleeper"] = rail.rail_bending_moment(t[None, :],
                                                                             x[:, None])
    return _histories(outputs)


def cell_dataset(cell, samples: int = 400, x=None) -> xr.Dataset:
    """A `railtrack.CellSolution` over one period: every sleeper of the cell."""
    t = time_grid(cell.period, samples)
    data = _cell_histories(cell, t, None if cell.rail_field_note else cell)
    data.update(_coefficients(cell.coefficients))
    data.update(_cell_variables(cell.cell))
    data["contact_fraction"] = variable("sleeper", cell.contact_fraction(), "1",
                                        "share of the period the sleeper presses on its "
                                        "foundation")
    field, coords = _rail_field(cell, t, x)
    data.update(field)
    positions = cell.passage.sleeper_spacing * np.arange(cell.sleepers)
    coords.update(_coordinates(t, cell.harmonics, cell.frequencies, positions))
    attrs = base_attrs(
        "CellSolution", "Periodic steady response of a cell of sleepers (railtrack)",
        harmonics=cell.harmonics, converged=flag(cell.converged), residual=cell.residual,
        iterations=cell.iterations, truncation_error=cell.truncation_error,
        aft_samples=cell.samples, period=cell.period, message=cell.message,
        sleepers=cell.sleepers, gravity=cell.cell.gravity)
    attrs.update(_stability_attrs(cell.stability))
    attrs.update(input_attrs(cell.passage))
    for key in ("track_sleeper_mass", "track_pad_stiffness", "track_pad_damping"):
        attrs.pop(key, None)          # the cell's own, per sleeper, are variables
    return xr.Dataset(data, coords=coords, attrs=attrs)


def wheel_dataset(solution, samples: int = 400, x=None) -> xr.Dataset:
    """A `railtrack.WheelSolution` over one period: every wheel and every sleeper of the cell."""
    t = time_grid(solution.period, samples)
    cell = solution.sleepers
    positions = cell.passage.sleeper_spacing * np.arange(cell.sleepers)
    # the rail at the sleepers takes the wheels' free rail, harmonic by harmonic (about
    # 4 s for 30 sleepers at 400 samples and m = 549, "auto" under a dip); the pads'
    # relation (`rail_above_sleepers`) is cheaper but drifts from it where m is small
    data = _cell_histories(cell, t, solution)
    data["rail_displacement_at_sleeper"] = variable(
        ("sleeper", "time"), solution.rail_displacement(t[None, :], positions[:, None]),
        *SLEEPER_OUTPUTS["rail_displacement_at_sleeper"])
    data.update(_coefficients(cell.coefficients))
    data.update(_cell_variables(cell.cell))
    wheel = ("wheel", "time")
    data.update({
        "contact_force": variable(wheel, solution.contact_force(t), "N",
                                  "wheel-rail contact force, positive in compression"),
        "compression": variable(wheel, solution.compression(t), "m",
                                "compression of the Hertz contact (< 0: wheel off the rail)"),
        "wheel_displacement": variable(wheel, solution.wheel_displacement(t), "m",
                                       "vertical displacement of the wheel, positive upward"),
        "wheel_position": variable(wheel, solution.wheel_position(t), "m",
                                   "position of the wheel along the track from sleeper 0"),
        "lift": variable("wheel", solution.lift, "m",
                         "mean compression less the profile's mean"),
    })
    data.update(complex_parts("contact_force_harmonic", ("wheel", "wheel_harmonic"),
                              solution.contact_harmonics, "N",
                              "one-sided harmonic P_p of the contact force"))
    field, coords = _rail_field(solution, t, x)
    data.update(field)
    coords.update(_coordinates(t, cell.harmonics, cell.frequencies, positions))
    passage = solution.passage
    coords.update({
        "wheel": variable("wheel", np.arange(len(passage.axle_positions)), "1",
                          "index of the wheel (axle) of the wagon"),
        "axle_position": variable("wheel", passage.axle_positions, "m",
                                  "distance of the axle behind the wagon's first axle"),
        "axle_load": variable("wheel", passage.axle_loads, "N", "static wheel load Q"),
        "wheel_harmonic": variable("wheel_harmonic", solution.grid, "1",
                                   "harmonic number p of the wheels' fundamental v / (N L)"),
    })
    attrs = base_attrs(
        "WheelSolution", "Periodic steady response of wheels on Hertz springs, rail and "
                         "sleepers (railtrack)",
        harmonics=solution.harmonics, converged=flag(solution.converged),
        residual=solution.residual, iterations=solution.iterations,
        truncation_error=solution.truncation_error, period=solution.period,
        message=solution.message, sleepers=cell.sleepers)
    attrs.update(input_attrs(passage, wheel=solution.wheel, profile=solution.profile))
    for key in ("track_sleeper_mass", "track_pad_stiffness", "track_pad_damping"):
        attrs.pop(key, None)
    return xr.Dataset(data, coords=coords, attrs=attrs)
