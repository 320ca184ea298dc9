"""A foundation law given as a Python callable ``f(w, v)``: `CallableFoundation`.

Its force is the callable's, checked to be a real array shaped like w; its
tangent is taken by central differences.  `railtrack.model.foundations.as_foundation`
wraps any callable in one, so a plain function is accepted wherever a
foundation is.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

__all__ = ["CallableFoundation"]


@dataclass(frozen=True)
class CallableFoundation:
    """Any law ``f(w, v)`` given as a Python callable.

    The callable receives arrays w [m] and v = w' [m/s] of one shape and must
    return the force [N] as a real array of that same shape.  The tangent is
    taken by central differences with steps scaled to the displacement and
    velocity amplitudes (1e-7 of them, at least 1e-12 m and 1e-10 m/s).
    """

    law: Callable[[np.ndarray, np.ndarray], np.ndarray]

    def __post_init__(self) -> None:
        if not callable(self.law):
            raise TypeError(f"law must be a callable f(w, v); got {type(self.law).__name__}")

    def force(self, w, v):
        w = np.asarray(w, dtype=float)
        v = np.asarray(v, dtype=float)
        returned = self.law(w, v)
        shape = np.broadcast(w, v).shape
        try:
            force = np.asarray(returned, dtype=float)
        except (TypeError, ValueError):
            force = None
        if force is None or force.shape != shape:
            described = (
                f"shape {np.shape(returned)}" if force is not None else type(returned).__name__
            )
            raise ValueError(
                f"the foundation law f(w, v) must return a real array shaped like w, {shape}; "
                f"it returned {described}: {_preview(returned)}"
            )
        return force

    def tangent(self, w, v):
        w = np.asarray(w, dtype=float)
        v = np.asarray(v, dtype=float)
        dw = max(1e-7 * float(np.max(np.abs(w), initial=0.0)), 1e-12)
        dv = max(1e-7 * float(np.max(np.abs(v), initial=0.0)), 1e-10)
        stiffness = (self.force(w + dw, v) - self.force(w - dw, v)) / (2 * dw)
        damping = (self.force(w, v + dv) - self.force(w, v - dv)) / (2 * dv)
        return stiffness, damping

    def linearization(self) -> tuple[float, float]:
        stiffness, damping = self.tangent(np.zeros(1), np.zeros(1))
        return float(stiffness[0]), float(damping[0])


def _preview(value) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."
