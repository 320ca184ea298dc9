"""Section 4: the foundation laws f(w, w') of eqs. (22), (24) and (25).

A foundation is any object with

* ``force(w, v)``: the force f(w, w') the sleeper puts on the foundation [N],
  for displacement w [m] and velocity v = w' [m/s], elementwise on arrays;
* ``tangent(w, v)``: the pair (df/dw [N/m], df/dw' [N s/m]) used by Newton's
  method and by the convergence factors of the fixed point;
* ``linearization()``: a representative (stiffness, damping) pair used for a
  starting guess and for the automatic split N0 of eq. (21).

w is positive upward: the train pushes the sleeper to w < 0, which
compresses the foundation.  A plain callable ``f(w, v)`` is accepted
wherever a foundation is, through `as_foundation`.

This module holds that interface (`Foundation`) and `as_foundation`; the
laws live beside it, the paper's in `railtrack.model.foundation_laws`
(eqs. 22, 24, 25) and any callable's in
`railtrack.model.callable_foundation`, and are imported from here too.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from .callable_foundation import CallableFoundation
from .foundation_laws import (
    PAPER_DAMPING as PAPER_DAMPING,
    PAPER_STIFFNESS as PAPER_STIFFNESS,
    BilinearFoundation,
    CubicFoundation,
    LinearFoundation,
)

__all__ = [
    "Foundation",
    "LinearFoundation",
    "BilinearFoundation",
    "CubicFoundation",
    "CallableFoundation",
    "as_foundation",
]


class Foundation(Protocol):
    """What the solvers need of a foundation law."""

    def force(self, w: np.ndarray, v: np.ndarray) -> np.ndarray: ...

    def tangent(self, w: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]: ...

    def linearization(self) -> tuple[float, float]: ...


def as_foundation(law) -> Foundation:
    """Return `law` if it is a foundation object, wrap it if it is a callable.

    Raises
    ------
    TypeError
        If `law` is neither.
    """
    if all(hasattr(law, name) for name in ("force", "tangent", "linearization")):
        return law
    if callable(law):
        return CallableFoundation(law)
    raise TypeError(
        "foundation must have force/tangent/linearization methods or be a "
        f"callable f(w, v); got {type(law).__name__}"
    )
