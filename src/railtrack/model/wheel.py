"""The wheel on the rail: unsprung mass, Hertz contact and primary suspension (issue 20).

Each axle of the train carries, on the modelled rail, one wheel: an unsprung
mass m_w [kg] loaded by the static wheel load Q of `railtrack.Train`
through the vehicle above.  By default the primary suspension is
infinitely soft (the wheel carries Q whatever it does); `primary_stiffness`
and `primary_damping` (k_p, c_p) join it to a body that does not move
vertically.  The wheel meets the rail through a Hertz spring

    P = C_H max(delta, 0)^{3/2},     delta = u_r(x_c, t) + r(x_c) - z(t),

with P >= 0 the contact force (pressing rail and wheel apart), u_r the
rail's displacement at the contact point x_c = vt - d_j, r the rail-top
profile (`railtrack.model.profile`), z the wheel's displacement, all
positive upward.  The wheel's equation is ``m_w z'' = P - Q - k_p z - c_p z'``.
Loss of contact is P = 0: part of the solution, not an error.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .plausibility_check import check_plausible, quantities_to_si
from .track import as_float64, require_non_negative, require_positive

__all__ = ["Wheel", "HERTZ_UIC60"]

HERTZ_UIC60 = 9.4e10
"""C_H [N/m^1.5] of a 0.46 m radius wheel on a UIC60 rail head (issue 20's value)."""


@dataclass(frozen=True)
class Wheel:
    """One wheel per axle on the modelled rail.

    Parameters
    ----------
    unsprung_mass : float
        m_w > 0 [kg], the wheel's share of the wheelset and what moves with it.
    hertz_constant : float
        C_H > 0 [N/m^1.5].
    primary_stiffness, primary_damping : float
        k_p >= 0 [N/m], c_p >= 0 [N s/m] to a body fixed vertically (default 0:
        infinitely soft).

    Examples
    --------
    >>> wheel = Wheel(600.0)
    >>> round(wheel.static_compression(75e3) * 1e6, 1)     # micrometres under Q = 75 kN
    86.0
    """

    unsprung_mass: float
    hertz_constant: float = HERTZ_UIC60
    primary_stiffness: float = 0.0
    primary_damping: float = 0.0

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("unsprung_mass", self.unsprung_mass, "kg")
        require_positive("hertz_constant", self.hertz_constant, "N/m^1.5")
        require_non_negative("primary_stiffness", self.primary_stiffness, "N/m")
        require_non_negative("primary_damping", self.primary_damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    def contact_force(self, compression) -> np.ndarray:
        """P = C_H max(delta, 0)^{3/2} [N] for the compression delta [m]."""
        return self.hertz_constant * np.maximum(np.asarray(compression, dtype=float), 0.0) ** 1.5

    def contact_stiffness(self, compression) -> np.ndarray:
        """dP/d delta = 1.5 C_H max(delta, 0)^{1/2} [N/m]."""
        return 1.5 * self.hertz_constant * np.sqrt(
            np.maximum(np.asarray(compression, dtype=float), 0.0))

    def static_compression(self, load: float) -> float:
        """delta_0 = (Q / C_H)^{2/3} [m], the compression that carries the wheel load Q [N]."""
        require_positive("load", load, "N")
        return float((load / self.hertz_constant) ** (2.0 / 3.0))
