"""A ballasted track's two-layer support reduced to the model's single foundation layer.

Track-dynamics models in the line of Zhai and co-workers put a ballast mass
m_b between the sleeper and the ground, on a ballast spring-dashpot (k_b, c_b)
above and a subgrade spring-dashpot (k_f, c_f) below.  This model has one
layer (k2, eta2) under the sleeper.  Condensing the ballast mass statically
(Guyan) gives, to second order in the frequency:

* k2 = k_b k_f / (k_b + k_f), the two springs in series (exact at rest);
* eta2 = k2^2 (c_b / k_b^2 + c_f / k_f^2), each dashpot weighted by its share
  of the compliance, squared;
* an added sleeper mass r^2 m_b, where r = k_b / (k_b + k_f) is how far the
  ballast mass moves when the sleeper moves by one.

The reduction holds well below the ballast mass's own resonance on its
springs, sqrt((k_b + k_f) / m_b) / (2 pi); above it no single layer can
follow the two-layer support.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .validation import require_non_negative, require_positive

__all__ = ["SingleLayer", "single_layer", "two_layer_stiffness", "ZHAI_2004"]

ZHAI_2004 = dict(
    rail_linear_mass=60.64,                      # kg/m, 60 kg/m rail
    rail_bending_stiffness=2.059e11 * 3.217e-5,  # N m^2, E I
    half_sleeper_mass=125.5,                     # kg, one rail seat
    sleeper_spacing=0.6,                         # m
    pad_stiffness=6.5e7,                         # N/m
    pad_damping=7.5e4,                           # N s/m
    ballast_mass=531.4,                          # kg, per rail seat
    ballast_stiffness=1.3775e8,                  # N/m
    ballast_damping=5.88e4,                      # N s/m
    subgrade_stiffness=7.75e7,                   # N/m
    subgrade_damping=3.115e4,                    # N s/m
)
"""Ballasted track of Zhai, Wang & Lin (2004), per rail and per rail seat.

Values as transcribed (two rails halved) in the open-source train-track tool
TTB-2D of D. Cantero, which states that it takes them from that paper; the
paper's own table was not at hand to check them.
"""


@dataclass(frozen=True)
class SingleLayer:
    """The one-layer equivalent of a ballast-subgrade support (`single_layer`).

    Attributes
    ----------
    stiffness : float
        k2 [N/m].
    damping : float
        eta2 [N s/m].
    added_mass : float
        Share of the ballast mass to add to the sleeper mass [kg].
    ballast_resonance : float
        sqrt((k_b + k_f) / m_b) / (2 pi) [Hz]: the reduction is faithful
        well below it.
    """

    stiffness: float
    damping: float
    added_mass: float
    ballast_resonance: float


def single_layer(ballast_mass: float, ballast_stiffness: float, ballast_damping: float,
                 subgrade_stiffness: float, subgrade_damping: float) -> SingleLayer:
    """Condense a ballast mass on two spring-dashpot layers to one layer plus a mass.

    Examples
    --------
    >>> z = ZHAI_2004
    >>> layer = single_layer(z["ballast_mass"], z["ballast_stiffness"], z["ballast_damping"],
    ...                      z["subgrade_stiffness"], z["subgrade_damping"])
    >>> round(layer.stiffness / 1e6, 2), round(layer.damping / 1e3, 1), round(layer.added_mass, 1)
    (49.6, 20.4, 217.6)
    """
    for name, value, unit in (("ballast_mass", ballast_mass, "kg"),
                              ("ballast_stiffness", ballast_stiffness, "N/m"),
                              ("subgrade_stiffness", subgrade_stiffness, "N/m")):
        require_positive(name, value, unit)
    require_non_negative("ballast_damping", ballast_damping, "N s/m")
    require_non_negative("subgrade_damping", subgrade_damping, "N s/m")
    k_b, k_f = ballast_stiffness, subgrade_stiffness
    stiffness = k_b * k_f / (k_b + k_f)
    damping = stiffness**2 * (ballast_damping / k_b**2 + subgrade_damping / k_f**2)
    share = k_b / (k_b + k_f)
    resonance = np.sqrt((k_b + k_f) / ballast_mass) / (2.0 * np.pi)
    return SingleLayer(stiffness, damping, share**2 * ballast_mass, float(resonance))


def two_layer_stiffness(omega, ballast_mass, ballast_stiffness, ballast_damping,
                        subgrade_stiffness, subgrade_damping):
    """Exact dynamic stiffness that the two-layer support offers the sleeper [N/m].

    K_b - K_b^2 / (K_b + K_f - omega^2 m_b), with K = k + i omega c.
    """
    omega = np.asarray(omega, dtype=float)
    upper = ballast_stiffness + 1j * omega * ballast_damping
    lower = subgrade_stiffness + 1j * omega * subgrade_damping
    return upper - upper**2 / (upper + lower - omega**2 * ballast_mass)
