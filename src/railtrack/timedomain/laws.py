"""The foundation law as the ring's steps call it: values, tangents, and messages about it.

Split from `railtrack.timedomain.newmark`, which re-exports these names.
"""

from __future__ import annotations

import numpy as np

__all__ = ["NonFiniteLawError", "describe_law", "instability_hint", "evaluate_law"]


class NonFiniteLawError(ValueError):
    """The foundation law returned NaN or infinity; `where` says for which w, w'."""


def describe_law(foundation) -> str:
    """A short name of the law for messages: the callable's name for a wrapped callable."""
    law = getattr(foundation, "law", None)
    if callable(law):
        return f"{type(foundation).__name__}({getattr(law, '__qualname__', repr(law))})"
    text = repr(foundation)
    return text if len(text) <= 100 else text[:97] + "..."


def instability_hint(foundation) -> str:
    """Why a track grows without bound, for messages: the law's linearization at rest."""
    try:
        stiffness, damping = (float(x) for x in foundation.linearization())
        at_rest = f" (at rest k = df/dw = {stiffness:.3g} N/m, c = df/dw' = {damping:.3g} N s/m)"
    except Exception:  # noqa: BLE001 - only decorates a message
        at_rest = ""
    return (
        f"the system is unstable: does the foundation law {describe_law(foundation)}{at_rest} "
        "have a negative stiffness or damping? A stable track needs f(w, w') increasing in w "
        "and in w'"
    )


def evaluate_law(foundation, w: np.ndarray, rate: np.ndarray):
    """f(w, w') [N], df/dw [N/m] and df/dw' [N s/m], refusing non-finite values.

    Raises
    ------
    NonFiniteLawError
        Naming the law, the first sleeper concerned and its w [m], w' [m/s].
    """
    force = np.asarray(foundation.force(w, rate), float)
    slope, viscosity = (np.asarray(value, float) for value in foundation.tangent(w, rate))
    # The common case in one pass; the search for the culprit only on failure
    # (this runs several times per time step).
    if np.isfinite(force).all() and np.isfinite(slope).all() and np.isfinite(viscosity).all():
        return force, slope, viscosity
    for name, value in (("force", force), ("stiffness df/dw", slope), ("damping df/dw'", viscosity)):
        bad = ~np.isfinite(np.broadcast_to(value, np.shape(w)))
        if np.any(bad):
            i = int(np.argmax(bad))
            raise NonFiniteLawError(
                f"the foundation law {describe_law(foundation)} returned a non-finite {name} "
                f"({np.broadcast_to(value, np.shape(w))[i]}) at w = {w[i]:.6g} m, "
                f"w' = {rate[i]:.6g} m/s (sleeper {i}, {int(np.sum(bad))} sleeper(s) in all)"
            )
    return force, slope, viscosity
