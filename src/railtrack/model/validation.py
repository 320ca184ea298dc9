"""Checks of the model's numeric fields, shared by every dataclass of `railtrack.model`.

Each names the field, its value and what is expected: a ``TypeError`` for a
value that is no real number (a boolean, also inside a list, a string, a
complex number), a ``ValueError`` for one out of range or not finite.
"""

from __future__ import annotations

import dataclasses

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["require_positive", "require_non_negative", "require_finite", "as_float64", "to_si"]


def _is_quantity(value) -> bool:
    """True for a pint Quantity, known by its attributes: pint is never imported here."""
    return all(hasattr(value, name) for name in ("magnitude", "units", "to", "dimensionality"))


def to_si(name: str, value, unit: str):
    """`value` in the SI `unit`, its magnitude, if it is a pint Quantity; else `value` as given.

    A sequence holding quantities is converted element by element.  Every
    dimensional field of the model passes through here, so that
    ``220 * ureg("MN/m")`` becomes 2.2e8 N/m at the boundary and the library
    works in SI inside.  pint stays optional: a Quantity is recognised by its
    attributes and converted by its own registry.

    Raises
    ------
    TypeError
        Naming `name`, the quantity and the unit expected, when the dimension
        is wrong (a force given for a stiffness).
    """
    if isinstance(value, (list, tuple)) and any(_is_quantity(v) for v in value):
        return type(value)(to_si(name, v, unit) for v in value)
    if not _is_quantity(value):
        return value
    try:
        magnitude = value.to(unit.replace("^", "**") or "dimensionless").magnitude
    except Exception as error:  # pint's DimensionalityError, or a unit it cannot parse
        raise TypeError(f"{name} must be a quantity in {unit or 'no unit'}; got {value} "
                        f"[{value.dimensionality}], which cannot be converted to {unit}"
                        ) from error
    return magnitude


def _holds_boolean(value) -> bool:
    """True if `value` is a boolean or a (nested) list or tuple holding one.

    NumPy turns ``[100, True]`` into the integers ``[100, 1]``: the boolean
    must be looked for before the conversion.
    """
    if isinstance(value, (bool, np.bool_)):
        return True
    return isinstance(value, (list, tuple)) and any(_holds_boolean(v) for v in value)


def _as_real(name: str, value: ArrayLike, unit: str) -> np.ndarray:
    """`value` as float64, or a ``TypeError`` naming `name` if it is not a real number."""
    array = np.asarray(value)
    boolean = _holds_boolean(value)
    if array.dtype.kind not in "iuf" or boolean:
        kind = {"b": "a boolean", "c": "a complex number", "U": "a string", "S": "a string"}.get(
            array.dtype.kind, f"of type {type(value).__name__}"
        )
        if boolean and array.dtype.kind != "b":
            kind = "which holds a boolean (True is no number here)"
        raise TypeError(
            f"{name} must be a real number{' in ' + unit if unit else ''}; got {value!r}, {kind}"
        )
    return array.astype(np.float64)


def require_positive(name: str, value: ArrayLike, unit: str = "") -> None:
    """Raise unless every element of `value` is a finite real number > 0.

    ``TypeError`` for booleans, complex numbers, strings and other non-real
    values; ``ValueError`` for values that are not finite or not > 0.
    """
    array = _as_real(name, value, unit)
    if not np.all(np.isfinite(array)) or not np.all(array > 0):
        raise ValueError(
            f"{name} must be a finite number > 0{' ' + unit if unit else ''}; got {value!r}"
        )


def require_non_negative(name: str, value: ArrayLike, unit: str = "") -> None:
    """Raise unless every element of `value` is a finite real number >= 0 (see `require_positive`)."""
    array = _as_real(name, value, unit)
    if not np.all(np.isfinite(array)) or not np.all(array >= 0):
        raise ValueError(
            f"{name} must be a finite number >= 0{' ' + unit if unit else ''}; got {value!r}"
        )


def require_finite(name: str, value: ArrayLike, unit: str = "") -> None:
    """Raise unless every element of `value` is a finite real number (see `require_positive`)."""
    if not np.all(np.isfinite(_as_real(name, value, unit))):
        raise ValueError(
            f"{name} must be a finite number{' in ' + unit if unit else ''}; got {value!r}"
        )


def as_float64(instance) -> None:
    """Store every field of a frozen dataclass as float64 (a float, or an array for batches).

    Single precision or integer input would otherwise leak into the sums of
    eq. (3), which lose digits in float32.
    """
    for field in dataclasses.fields(instance):
        value = getattr(instance, field.name)
        if not isinstance(value, (int, float, np.number, np.ndarray)) or isinstance(value, bool):
            continue
        array = np.asarray(value, dtype=np.float64)
        object.__setattr__(instance, field.name, float(array) if array.ndim == 0 else array)
