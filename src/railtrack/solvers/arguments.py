"""Checks of the arguments of `railtrack.solve`: each error names the argument.

Numbers are checked for type as well as range, so that a string, a boolean
or a complex number is refused where it is passed, not deep in a solver.
"""

from __future__ import annotations

import numbers

import numpy as np

__all__ = ["require_count", "require_fraction", "checked_initial"]


def require_count(name: str, value, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}; got {value!r}")
    return int(value)


def require_fraction(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 < value < 1:
        raise ValueError(f"{name} must be a real number with 0 < {name} < 1; got {value!r}")
    return float(value)


def checked_initial(initial, harmonics: int) -> np.ndarray:
    try:
        c = np.array(initial, dtype=complex)
    except (TypeError, ValueError):
        raise ValueError(f"initial must be an array of c_0..c_m; got {initial!r}") from None
    if c.shape != (harmonics + 1,):
        raise ValueError(
            f"initial must have shape ({harmonics + 1},) (c_0..c_m); got {np.shape(initial)}"
        )
    if not np.all(np.isfinite(c)):
        bad = np.flatnonzero(~np.isfinite(c)).tolist()
        raise ValueError(f"initial must be finite; c_n is NaN or inf for n = {bad}")
    if abs(c[0].imag) > 1e-12 * max(float(np.max(np.abs(c))), np.finfo(float).tiny):
        raise ValueError(
            f"initial[0] is c_0, the mean of a real displacement, and must be real; "
            f"got {c[0]!r}"
        )
    c[0] = c[0].real
    return c
