"""Results as labelled arrays, tables and files: the helpers every export shares.

Every result and study of the package has ``to_xarray()`` (an
`xarray.Dataset`), ``to_dataframe()`` (a `pandas.DataFrame`),
``to_netcdf(path)`` and ``to_csv(path)``; the datasets are built in
`railtrack.solvers.result_export` (the solvers' results),
`railtrack.timedomain.td_export` and `railtrack.studies.study_export`
from the pieces here, so that they all follow the same rules:

* CF conventions (``Conventions = "CF-1.10"``): every variable and
  coordinate carries ``units`` (a UDUNITS string: "m", "N", "s",
  "m s-1", "N m", "1" for a ratio) and ``long_name``; signs are stated in
  the long names (displacements positive upward, forces positive in
  compression, moments positive when sagging).
* Named dimensions: time, sleeper, wheel, harmonic, x, and for studies the
  swept field (speed, ...) or member, point, draw.
* What was solved is recorded in the attributes: the track's, the train's
  and the foundation law's fields (SI units, listed in ``input_units``),
  m, converged, residual, the truncation estimate, the railtrack version.
* Only what netCDF-3 holds: attributes are numbers, strings or 1-D numeric
  arrays (a flag is 0 or 1, a missing value is left out); complex values
  (Fourier coefficients, Floquet multipliers) are split into ``_real``
  and ``_imag`` parts.  Booleans, integers and strings in variables are
  encoded by xarray and read back as written.

netCDF files are written by SciPy's netCDF-3 writer (``engine="scipy"``),
so no further library is needed; ``xarray.open_dataset(path)`` reads them.
CSV files hold ``to_dataframe()``: one row per instant of time (per member,
point or draw of a study), a column per quantity and place, named
``quantity[index]`` (``sleeper_displacement[2]``: sleeper 2).

Examples
--------
>>> import railtrack as rt
>>> s = rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper())
>>> ds = s.to_xarray(samples=64)
>>> ds["rail_seat_load"].dims, ds["rail_seat_load"].attrs["units"]
(('sleeper', 'time'), 'N')
>>> round(float(ds["rail_seat_load"].mean()))        # sum Q L / H over the period
5000
>>> s.to_dataframe(samples=64).columns[:3].tolist()
['time', 'sleeper_displacement[0]', 'sleeper_velocity[0]']
"""

from __future__ import annotations

import dataclasses
import numbers
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .arguments import require_count

if TYPE_CHECKING:     # the results import this module: pandas and xarray load on first export
    import pandas as pd
    import xarray as xr

__all__ = ["CONVENTIONS", "FIELD_UNITS", "variable", "complex_parts", "time_grid",
           "input_attrs", "law_attrs", "base_attrs", "flag", "write_netcdf", "frame",
           "write_csv", "Exports"]

CONVENTIONS = "CF-1.10"

FIELD_UNITS = {
    # Track, Train
    "rail_linear_mass": "kg m-1", "rail_bending_stiffness": "N m2", "sleeper_mass": "kg",
    "sleeper_spacing": "m", "pad_stiffness": "N m-1", "pad_damping": "N s m-1",
    "wagon_length": "m", "axle_positions": "m", "axle_loads": "N", "speed": "m s-1",
    # foundation laws
    "stiffness": "N m-1", "damping": "N s m-1", "compression_stiffness": "N m-1",
    "tension_stiffness": "N m-1", "cubic_stiffness": "N m-3", "epsilon": "1", "gap": "m",
    "ramp": "m", "gravity": "m s-2",
    # wheel, rail-top profile, Timoshenko rail
    "unsprung_mass": "kg", "hertz_constant": "N m-1.5", "primary_stiffness": "N m-1",
    "primary_damping": "N s m-1", "depth": "m", "length": "m", "period": "m", "centre": "m",
    "angle": "rad", "circumference": "m",
    "shear_stiffness": "N", "rotary_inertia": "kg m",
    # vehicle
    "body_mass": "kg", "body_pitch_inertia": "kg m2", "bogie_mass": "kg",
    "bogie_pitch_inertia": "kg m2", "wheelset_mass": "kg", "secondary_stiffness": "N m-1",
    "secondary_damping": "N s m-1", "bogie_spacing": "m", "wheelbase": "m",
}
"""UDUNITS unit of each input field by its name (all inputs are SI inside the package)."""


def variable(dims, values, units: str, long_name: str, **attrs) -> tuple:
    """``(dims, values, attrs)`` for `xarray.Dataset`, with CF ``units`` and ``long_name``."""
    return dims, np.asarray(values), {"units": units, "long_name": long_name, **attrs}


def complex_parts(name: str, dims, values, units: str, long_name: str) -> dict:
    """``{name_real: ..., name_imag: ...}``: netCDF has no complex type."""
    values = np.asarray(values, dtype=complex)
    # a missing value (NaN + 0j, a member never judged) stays missing in both parts
    values = np.where(np.isnan(values), complex(np.nan, np.nan), values)
    return {f"{name}_real": variable(dims, values.real, units, f"real part of {long_name}"),
            f"{name}_imag": variable(dims, values.imag, units, f"imaginary part of {long_name}")}


def time_grid(period: float, samples) -> np.ndarray:
    """``samples`` instants evenly over one period, 0 <= t < T [s]."""
    samples = require_count("samples", samples, 2)
    return np.linspace(0.0, float(period), samples, endpoint=False)


def flag(value) -> int:
    """A bool as 0 or 1: netCDF-3 has no boolean attribute."""
    return int(bool(value))


def _attribute(value):
    """`value` as a netCDF attribute (number, string or 1-D numeric array), or None to drop it."""
    if value is None:
        return None
    if isinstance(value, (bool, np.bool_)):
        return flag(value)
    if isinstance(value, str):
        return value
    if isinstance(value, numbers.Integral):     # netCDF-3 integers have 32 bits
        return int(value) if -2**31 <= int(value) < 2**31 else str(int(value))
    if isinstance(value, numbers.Real):
        return float(value)
    array = np.asarray(value)
    if array.dtype.kind in "iuf" and array.ndim <= 1:
        return array.astype(float) if array.dtype.kind == "f" else array.astype(np.int32)
    return None           # a batched field (a sweep's) or an object: not an attribute


def law_attrs(prefix: str, law) -> dict:
    """``{prefix: class name, prefix_field: value}`` for a dataclass (a law, a wheel, a profile).

    A function is recorded by its name, another object by its type and repr.
    """
    if not dataclasses.is_dataclass(law):
        if hasattr(law, "__qualname__"):        # a function, e.g. a profile r(x)
            return {prefix: law.__qualname__}
        return {prefix: type(law).__name__, f"{prefix}_repr": repr(law)}
    attrs = {prefix: type(law).__name__}
    for item in dataclasses.fields(law):
        value = getattr(law, item.name)
        if callable(value):          # a CallableFoundation's f(w, v): its name
            value = getattr(value, "__qualname__", type(value).__name__)
        value = _attribute(value)
        if value is not None:
            attrs[f"{prefix}_{item.name}"] = value
    return attrs


def input_attrs(passage=None, foundation=None, **others) -> dict:
    """The track's, the train's, the foundation law's (and `others`') fields as attributes.

    ``others`` maps a prefix to an object (``wheel=``, ``profile=``),
    recorded as `law_attrs` does.  Fields that are not scalars or 1-D (a
    sweep's batched fields) are left out: the study records them as
    coordinates.  ``input_units`` lists each recorded field's unit.
    """
    attrs: dict = {}
    if passage is not None:
        attrs.update({k: v for k, v in law_attrs("track", passage.track).items() if k != "track"})
        attrs.update({k: v for k, v in law_attrs("train", passage.train).items() if k != "train"})
    if foundation is not None:
        attrs.update(law_attrs("foundation_law", foundation))
    for prefix, value in others.items():
        if value is not None:
            attrs.update(law_attrs(prefix, value))
    prefixes = ("track_", "train_", "foundation_law_") + tuple(f"{p}_" for p in others)
    units = [f"{key}: {FIELD_UNITS[key[len(p):]]}" for key in attrs for p in prefixes
             if key.startswith(p) and key[len(p):] in FIELD_UNITS]
    if units:
        attrs["input_units"] = "; ".join(units)
    return attrs


def base_attrs(result_type: str, title: str, **fields) -> dict:
    """Conventions, title, source and version, and `fields` made netCDF-safe."""
    from .. import __version__       # the package is imported by the time a result exists

    attrs = {"Conventions": CONVENTIONS, "title": title,
             "source": f"railtrack {__version__}", "railtrack_version": __version__,
             "result_type": result_type}
    for key, value in fields.items():
        value = _attribute(value)
        if value is not None:
            attrs[key] = value
    return attrs


def write_netcdf(dataset: xr.Dataset, path) -> Path:
    """Write `dataset` as a netCDF-3 file with SciPy (no further library needed); its path."""
    path = Path(path)
    dataset.to_netcdf(path, engine="scipy")
    return path


def frame(dataset: xr.Dataset, row: str) -> pd.DataFrame:
    """One row per entry of dimension `row`, a column per quantity and place.

    The coordinates along `row` come first; then each variable along `row`
    (and at most one other dimension, spread into columns ``name[index]``);
    variables along a harmonic dimension stay in the dataset only.  The
    units of each column are in ``frame.attrs["units"]``.
    """
    import pandas as pd

    columns: dict = {}
    units: dict = {}
    for name, array in list(dataset.coords.items()) + list(dataset.data_vars.items()):
        if row not in array.dims or array.ndim > 2 or "harmonic" in "".join(array.dims):
            continue
        if array.ndim == 1:
            columns[name] = _column(array.values)
            units[name] = array.attrs.get("units", "")
            continue
        other = next(d for d in array.dims if d != row)
        labels = dataset[other].values if other in dataset.coords else range(dataset.sizes[other])
        values = array.transpose(row, other).values
        for k, label in enumerate(labels):
            columns[f"{name}[{label}]"] = _column(values[:, k])
            units[f"{name}[{label}]"] = array.attrs.get("units", "")
    table = pd.DataFrame(columns)
    table.attrs["units"] = units
    return table


def _column(values: np.ndarray) -> np.ndarray:
    """Integers as int64, as a CSV reads them back."""
    return values.astype(np.int64) if values.dtype.kind in "iu" else values


def write_csv(table: pd.DataFrame, path) -> Path:
    """Write `table` as CSV (no index column; floats written to round-trip exactly); its path."""
    path = Path(path)
    table.to_csv(path, index=False)
    return path


class Exports:
    """``to_dataframe``, ``to_netcdf`` and ``to_csv`` from the class's ``to_xarray``.

    A result or study defines ``to_xarray`` and sets ``_table_row``, the
    dimension whose entries are the table's rows ("time", "multiplier"); a
    study leaves it None: a row per entry of the dimension of its
    ``converged`` (the swept field, member, point or draw).  Each method
    passes its remaining arguments on to ``to_xarray``.
    """

    _table_row: str | None = None

    def to_dataframe(self, *args, **kwargs) -> pd.DataFrame:
        """`to_xarray` as a `pandas.DataFrame`: a row per instant (member, point, draw, multiplier).

        A column per output and place (`railtrack.solvers.export.frame`); the
        arguments are those of ``to_xarray``.
        """
        dataset = self.to_xarray(*args, **kwargs)
        return frame(dataset, self._table_row or dataset["converged"].dims[0])

    def to_netcdf(self, path, *args, **kwargs) -> Path:
        """Write `to_xarray` to a netCDF file at `path` (SciPy's netCDF-3); the path.

        The arguments after `path` are those of ``to_xarray``.
        """
        return write_netcdf(self.to_xarray(*args, **kwargs), path)

    def to_csv(self, path, *args, **kwargs) -> Path:
        """Write `to_dataframe` to a CSV file at `path`; the path.

        The arguments after `path` are those of ``to_xarray``.
        """
        return write_csv(self.to_dataframe(*args, **kwargs), path)
