"""A hanging (voided) sleeper: a gap g, then a viscoelastic contact with the ballast.

Sleeper j hangs g above its ballast: it touches it only when w < -g, and the
ballast pushes, never pulls.  With the penetration ``p = -(w + g)``,

    f = min(k2 (w + g) + eta2 w' r(p), 0)   for p > 0,      f = 0 otherwise,

r(p) = min(p / ramp, 1).  The ramp brings the ballast's damping in over the
first ``ramp`` metres of penetration.  Without it (ramp -> 0) the dashpot
would switch on at the instant of contact: a sleeper arriving at speed w'
would meet a force jump of eta2 w', a law whose force is discontinuous in w.
Newton's method on harmonic balance stalls on such a jump, and the
time-domain ring resolves it only with a time step that follows each impact.
With the ramp the law is continuous, and both methods solve the same law.
The "min" keeps the dashpot from pulling the sleeper back as it leaves the
ballast (a Kelvin contact that acts only in compression).

w is positive upward, f negative in compression, as every law of
`railtrack.model.foundations`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .track import as_float64, require_non_negative, require_positive

__all__ = ["GapFoundation", "DEFAULT_RAMP"]

DEFAULT_RAMP = 0.1e-3
"""Penetration [m] over which the ballast's damping comes in (0.1 mm)."""


@dataclass(frozen=True)
class GapFoundation:
    """Foundation of a sleeper hanging `gap` above the ballast (module docstring).

    Parameters
    ----------
    gap : float
        g >= 0 [m]; g = 0 is a tensionless ballast under a sleeper at rest on it.
    stiffness : float
        k2 > 0 [N/m], the ballast once touched.
    damping : float
        eta2 >= 0 [N s/m], reached after `ramp` of penetration.
    ramp : float
        > 0 [m], the penetration over which the damping grows from zero.

    Examples
    --------
    >>> import numpy as np
    >>> law = GapFoundation(1e-3, 20e6, 0.2e6)
    >>> law.force(np.array([0.0, -1e-3, -2e-3]), np.zeros(3))   # free, touching, 1 mm in
    array([     0.,      0., -20000.])
    >>> float(law.force(np.array(-0.5e-3), np.array(-0.1)))     # free: no force at any speed
    0.0
    """

    gap: float
    stiffness: float
    damping: float = 0.0
    ramp: float = DEFAULT_RAMP

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_non_negative("gap", self.gap, "m")
        require_positive("stiffness", self.stiffness, "N/m")
        require_non_negative("damping", self.damping, "N s/m")
        require_positive("ramp", self.ramp, "m")
        as_float64(self)
        check_plausible(self)

    def _parts(self, w, v):
        penetration = -(np.asarray(w, dtype=float) + self.gap)
        share = np.clip(penetration / self.ramp, 0.0, 1.0)
        trial = -self.stiffness * penetration + self.damping * np.asarray(v, dtype=float) * share
        pushing = (penetration > 0) & (trial < 0)
        return penetration, share, trial, pushing

    def force(self, w, v):
        _, _, trial, pushing = self._parts(w, v)
        return np.where(pushing, trial, 0.0)

    def tangent(self, w, v):
        penetration, share, _, pushing = self._parts(w, v)
        ramping = pushing & (penetration < self.ramp)
        velocity = np.asarray(v, dtype=float)
        stiffness = np.where(pushing, self.stiffness, 0.0) \
            - np.where(ramping, self.damping * velocity / self.ramp, 0.0)
        damping = np.where(pushing, self.damping * share, 0.0)
        shape = np.broadcast(penetration, velocity).shape
        return np.broadcast_to(stiffness, shape), np.broadcast_to(damping, shape)

    def linearization(self) -> tuple[float, float]:
        # The ballast once touched: the sound neighbours' law, a good first guess for a cell.
        return float(self.stiffness), float(self.damping)
