"""The plausibility check of the model's fields, and the pint conversion at its boundary.

Every dataclass of `railtrack.model` (and `railtrack.EquivalentTrack`) calls
`quantities_to_si` first in its ``__post_init__`` (a pint Quantity becomes its
SI magnitude) and `check_plausible` last (a value an order of magnitude
outside its row of `railtrack.model.plausibility.PLAUSIBLE_RANGES` warns
`PlausibilityWarning`).  `FIELDS` says which row, and which SI unit, each
field has.
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys
import warnings
from contextlib import contextmanager

import numpy as np

from .plausibility import ORDER_OF_MAGNITUDE, RANGES, PlausibilityWarning, PlausibleRange
from .validation import to_si

__all__ = ["FIELDS", "quantities_to_si", "check_plausible", "check_value", "likely_slip",
           "warn_implausible", "plausibility"]

_TRACK = dict(rail_linear_mass=("kg/m", "rail_linear_mass"),
              rail_bending_stiffness=("N m^2", "rail_bending_stiffness"),
              sleeper_mass=("kg", "sleeper_mass"), sleeper_spacing=("m", "sleeper_spacing"),
              pad_stiffness=("N/m", "pad_stiffness"), pad_damping=("N s/m", "pad_damping"))
_K2, _ETA2 = ("N/m", "foundation_stiffness"), ("N s/m", "foundation_damping")

FIELDS: dict[str, dict[str, tuple[str, str | None]]] = {
    "Track": _TRACK,
    "Train": dict(wagon_length=("m", "wagon_length"), axle_positions=("m", None),
                  axle_loads=("N", "wheel_load"), speed=("m/s", "speed")),
    "LinearFoundation": dict(stiffness=_K2, damping=_ETA2),
    # a tension stiffness of any size below k2+ is a modelling choice (0: tensionless)
    "BilinearFoundation": dict(compression_stiffness=_K2, tension_stiffness=("N/m", None),
                               damping=_ETA2),
    "CubicFoundation": dict(stiffness=_K2, cubic_stiffness=("N/m^3", "cubic_stiffness"),
                            epsilon=("", None), damping=_ETA2),
    "GapFoundation": dict(gap=("m", "gap"), stiffness=_K2, damping=_ETA2, ramp=("m", None)),
    "Wheel": dict(unsprung_mass=("kg", "unsprung_mass"),
                  hertz_constant=("N/m^1.5", "hertz_constant"),
                  primary_stiffness=("N/m", "primary_stiffness"),
                  primary_damping=("N s/m", "primary_damping")),
    "CosineDip": dict(depth=("m", "dip_depth"), length=("m", "dip_length"),
                      period=("m", None), centre=("m", None)),
    "DippedJoint": dict(angle=("rad", "dip_angle"), length=("m", "dip_length"),
                        period=("m", None), centre=("m", None)),
    "WheelFlat": dict(depth=("m", "flat_depth"), length=("m", "flat_length"),
                      circumference=("m", "wheel_circumference"), centre=("m", None)),
    "Vehicle": dict(body_mass=("kg", None), body_pitch_inertia=("kg m^2", None),
                    bogie_mass=("kg", None), bogie_pitch_inertia=("kg m^2", None),
                    wheelset_mass=("kg", None), secondary_stiffness=("N/m", None),
                    secondary_damping=("N s/m", None), primary_stiffness=("N/m", None),
                    primary_damping=("N s/m", None), bogie_spacing=("m", None),
                    wheelbase=("m", None), hertz_constant=("N/m^1.5", "hertz_constant")),
    "TimoshenkoRail": dict(shear_stiffness=("N", "shear_stiffness"),
                           rotary_inertia=("kg m", "rotary_inertia")),
    "SleeperCell": {**{k: _TRACK[k] for k in ("sleeper_mass", "pad_stiffness", "pad_damping")},
                    "gravity": ("m/s^2", "gravity")},
    "EquivalentTrack": dict(mass=("kg", "track_mass"), stiffness=("N/m", "track_stiffness"),
                            damping=("N s/m", "track_damping")),
    "SoilLayer": dict(shear_wave_speed=("m/s", "soil_shear_wave_speed"),
                      poisson_ratio=("", "poisson_ratio"), density=("kg/m^3", "soil_density"),
                      damping_ratio=("", "soil_damping_ratio"),
                      thickness=("m", "layer_thickness")),     # inf (the half-space): unchecked
    "WinklerGround": dict(modulus=("N/m^2", None), footprint=("m", "footprint"),
                          damping=("N s/m^2", None)),
    "LayeredGround": dict(width=("m", "strip_width"), footprint=("m", "footprint")),
}
"""For each dataclass, each dimensional field's SI unit and its row of the table (or None)."""

_SLIPS: dict[str, tuple[tuple[float, str], ...]] = {
    # (what one typed unit is in SI, the typed unit): a typed value x is x * factor in SI
    "N/m": ((1e3, "kN/m"), (1e6, "MN/m"), (1e9, "GN/m")),
    "N s/m": ((1e3, "kN s/m"), (1e6, "MN s/m")),
    "N": ((1e3, "kN"), (9.81e3, "tonnes-force"), (1e6, "MN"), (9.81, "kgf")),
    "kg": ((1e3, "tonnes"), (1e-3, "grams")),
    "kg/m": ((1e-3, "g/m"),),
    "m": ((1e-3, "mm"), (1e-2, "cm"), (1e3, "km")),
    "m/s": ((1e-3, "mm/s"), (1e-2, "cm/s"), (1e3, "km/s"), (1 / 3.6, "km/h")),
    "rad": ((1e-3, "mrad"), (math.pi / 180, "degrees")),
    "N m^2": ((1e3, "kN m^2"), (1e6, "MN m^2"), (1e-6, "N mm^2")),
    "N/m^1.5": ((1e3, "kN/m^1.5"), (1e6, "MN/m^1.5"), (1e9, "GN/m^1.5"),
                (1e3**1.5, "N/mm^1.5")),
    "N/m^3": ((1e3, "kN/m^3"), (1e6, "MN/m^3"), (1e9, "N/mm^3"), (1e12, "kN/mm^3")),
    "kg/m^3": ((1e3, "g/cm^3"), (1e3 / 9.81, "kN/m^3")),     # kN/m^3: a unit weight
}


def _number(x: float) -> str:
    """2.2e5 rather than 2.2e+05; 600 rather than 6e+02."""
    text = f"{x:.3g}"
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def likely_slip(value: float, row: PlausibleRange) -> str:
    """The unit `value` was probably typed in, with what it would be in SI; or a question.

    Of the usual slips of `row.unit` (kN for N, mm for m, mrad for rad...),
    the one that brings `value` inside the range, nearest its geometric middle.
    """
    middle = math.sqrt(row.low * row.high)
    fits = [(abs(math.log(value * factor / middle)), factor, unit)
            for factor, unit in _SLIPS.get(row.unit, ())
            if row.low <= value * factor <= row.high]
    if not fits:
        return "is it in SI units?" if row.unit != "-" else "a slipped decimal point?"
    _, factor, unit = min(fits)
    return f"{unit}? ({_number(value)} {unit} = {_number(value * factor)} {row.unit})"


def _internal(code) -> bool:
    """A frame of railtrack, of dataclasses, or a dataclass's generated ``__init__``."""
    name = code.co_filename
    return (name.startswith(_PACKAGE) or name == dataclasses.__file__
            or (name == "<string>" and code.co_name == "__init__"))


_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def warn_implausible(message: str) -> None:
    """Warn `PlausibilityWarning` with `message`, pointing at the first line outside railtrack.

    The user's ``Track(...)`` goes through the dataclass's generated
    ``__init__`` and the package's own frames: the warning names the user's line.
    """
    frame, level = sys._getframe(0), 1
    while frame is not None and _internal(frame.f_code):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, PlausibilityWarning, stacklevel=level if frame is not None else 2)


def check_value(label: str, value, row_field: str) -> None:
    """Warn if an element of `value` (SI) is an order of magnitude outside its row.

    Zeros (no damping, no gap, no weight) and non-finite values (refused
    elsewhere) are not checked; of an array the worst element is named.
    """
    row = RANGES[row_field]
    array = np.asarray(value, dtype=float).ravel()
    array = array[np.isfinite(array) & (array > 0)]
    if array.size == 0:
        return
    factors = np.maximum(row.low / array, array / row.high)
    worst = int(np.argmax(factors))
    if factors[worst] < ORDER_OF_MAGNITUDE:
        return
    x = float(array[worst])
    more = int(np.sum(factors >= ORDER_OF_MAGNITUDE)) - 1
    others = f" (and {more} more)" if more else ""
    unit = "" if row.unit == "-" else f" {row.unit}"     # "-": a ratio, no unit
    warn_implausible(f"{label} = {_number(x)}{unit}{others}; {row.what} "
                     f"{_number(row.low)}-{_number(row.high)}{unit}: "
                     f"{likely_slip(x, row)}")


def quantities_to_si(instance) -> None:
    """Replace each pint Quantity among `instance`'s fields by its SI magnitude (`to_si`)."""
    owner = type(instance).__name__
    for name, (unit, _) in FIELDS[owner].items():
        value = getattr(instance, name)
        converted = to_si(f"{owner}.{name}", value, unit)
        if converted is not value:
            object.__setattr__(instance, name, converted)


def check_plausible(instance) -> None:
    """`check_value` for each field of `instance` that has a row in the table."""
    owner = type(instance).__name__
    for name, (_, row) in FIELDS[owner].items():
        if row is not None:
            check_value(f"{owner}.{name}", getattr(instance, name), row)


@contextmanager
def plausibility(action: str = "warn"):
    """Within the block, implausible inputs and results warn, raise, or pass silently.

    Parameters
    ----------
    action : {"warn", "error", "ignore"}
        "error" raises `PlausibilityWarning` as an exception; "ignore" is for
        a deliberate limit study (a 1 g wheel).  The same as
        ``warnings.simplefilter(action, PlausibilityWarning)`` inside
        ``warnings.catch_warnings()``.

    Examples
    --------
    >>> from railtrack import Track
    >>> with plausibility("error"):
    ...     Track.paper(pad_stiffness=220e3)
    Traceback (most recent call last):
    ...
    railtrack.model.plausibility.PlausibilityWarning: Track.pad_stiffness = 2.2e5 N/m; \
pads are 5e7-2e9 N/m: kN/m? (2.2e5 kN/m = 2.2e8 N/m)
    """
    actions = {"warn": "default", "error": "error", "ignore": "ignore"}
    if action not in actions:
        raise ValueError(f"action must be one of {sorted(actions)}; got {action!r}")
    with warnings.catch_warnings():
        warnings.simplefilter(actions[action], PlausibilityWarning)
        yield
