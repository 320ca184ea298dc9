"""The rail's cross-section: what turns a bending moment into a stress (issue 29).

A `RailSection` holds the vertical-bending properties of a rail profile:
the second moment of area I about the horizontal neutral axis and the
elastic section moduli of the foot and of the head, W = I / e with e the
distance from the neutral axis to the extreme fibre.  A sagging moment M
(positive, as `railtrack.Solution.rail_bending_moment` reports it) puts the
foot in tension, sigma = M / W_foot, and the head in compression.

Presets, from EN 13674-1:2011 (Railway applications - Track - Rail - Part 1:
Vignole railway rails 46 kg/m and above), Annex A, the profiles once called
UIC60 and UIC54 (UIC leaflet 861-3); the same values are tabulated in
Esveld, C. (2001), Modern Railway Track, 2nd ed., MRT-Productions, Delft:

=========  ==========  =============  =============  ===========  ========
profile    I [cm^4]    W_foot [cm^3]  W_head [cm^3]  mass [kg/m]  h [mm]
=========  ==========  =============  =============  ===========  ========
60E1       3038.3      375.5          333.6          60.21        172
54E1       2337.9      311.2          278.7          54.77        159
=========  ==========  =============  =============  ===========  ========

They check themselves: I / W_foot + I / W_head is the height within 0.5 mm
for both (80.9 + 91.1 = 172.0 mm; 75.1 + 83.9 = 159.0 mm), which is what
`RailSection` asks of any section (within 3 %), so that a modulus typed in
cm^3 or mm^3 instead of m^3 is refused, not turned into a stress a million
times off.  E = 210 GPa (steel) gives 60E1 an EI of 6.38 MN m^2, 1.3 %
above the 6.3 MN m^2 of the paper's UIC60 rail (`railtrack.Track.paper`,
Table 1), and a mass per metre of 60.21 kg/m against its 60 kg/m.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from .validation import as_float64, require_positive

__all__ = ["RailSection", "UIC60", "UIC54", "STEEL_YOUNGS_MODULUS"]

STEEL_YOUNGS_MODULUS = 210e9
"""E of rail steel [Pa] (Esveld 2001 uses 2.1e5 N/mm^2)."""

HEIGHT_MISMATCH = 0.03
"""Largest relative gap between I/W_foot + I/W_head and the height that a section may have [-]."""


@dataclass(frozen=True)
class RailSection:
    """The vertical-bending properties of a rail profile.

    Parameters
    ----------
    name : str
        The profile's designation, e.g. "60E1 (UIC60)".
    second_moment : float
        I about the horizontal neutral axis [m^4].
    section_modulus_foot, section_modulus_head : float
        W = I / e to the foot's and to the head's extreme fibre [m^3].
    linear_mass : float
        Mass per metre [kg/m].
    height : float
        Rail height, foot to head [m].
    youngs_modulus : float
        E [Pa], 210 GPa by default.

    Raises
    ------
    ValueError
        If a value is not > 0, or if I / W_foot + I / W_head (the distances of
        the two extreme fibres from the neutral axis) misses the height by
        more than 3 %: a unit slip (cm^3, mm^4) or a swapped field.

    Examples
    --------
    >>> round(UIC60.foot_stress(20e3) / 1e6, 1)         # MPa under 20 kN m, sagging
    53.3
    >>> round(UIC60.bending_stiffness / 1e6, 2)          # EI [MN m^2]
    6.38
    """

    name: str
    second_moment: float
    section_modulus_foot: float
    section_modulus_head: float
    linear_mass: float
    height: float
    youngs_modulus: float = STEEL_YOUNGS_MODULUS

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a string; got {self.name!r}")
        for field, unit in (("second_moment", "m^4"), ("section_modulus_foot", "m^3"),
                            ("section_modulus_head", "m^3"), ("linear_mass", "kg/m"),
                            ("height", "m"), ("youngs_modulus", "Pa")):
            require_positive(field, getattr(self, field), unit)
        as_float64(self)
        for field in ("second_moment", "section_modulus_foot", "section_modulus_head"):
            if not isinstance(getattr(self, field), float):
                raise TypeError(f"{field} must be one number; got {getattr(self, field)!r}")
        fibres = (self.second_moment / self.section_modulus_foot
                  + self.second_moment / self.section_modulus_head)
        if abs(fibres / self.height - 1.0) > HEIGHT_MISMATCH:
            raise ValueError(
                f"section {self.name!r}: I / W_foot + I / W_head = {fibres:.4g} m should be the "
                f"height {self.height:.4g} m (the two extreme fibres' distances from the neutral "
                f"axis); I = {self.second_moment:.4g} m^4, W_foot = "
                f"{self.section_modulus_foot:.4g} m^3, W_head = {self.section_modulus_head:.4g} "
                "m^3: are they in m^4 and m^3 (1 cm^4 = 1e-8 m^4, 1 cm^3 = 1e-6 m^3)?")

    @property
    def bending_stiffness(self) -> float:
        """E I [N m^2], to compare with `railtrack.Track.rail_bending_stiffness`."""
        return self.youngs_modulus * self.second_moment

    def foot_stress(self, moment):
        """Bending stress at the foot's extreme fibre, M / W_foot [Pa]; tension when sagging (M > 0)."""
        return moment / self.section_modulus_foot

    def head_stress(self, moment):
        """Bending stress at the head's extreme fibre, -M / W_head [Pa]; compression when sagging."""
        return -moment / self.section_modulus_head

    def replace(self, **changes) -> "RailSection":
        """A copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)


UIC60 = RailSection("60E1 (UIC60)", 3038.3e-8, 375.5e-6, 333.6e-6, 60.21, 0.172)
"""60E1, formerly UIC60: EN 13674-1:2011, Annex A (module docstring)."""

UIC54 = RailSection("54E1 (UIC54)", 2337.9e-8, 311.2e-6, 278.7e-6, 54.77, 0.159)
"""54E1, formerly UIC54: EN 13674-1:2011, Annex A (module docstring)."""
