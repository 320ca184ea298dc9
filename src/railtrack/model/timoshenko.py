"""The rail's shear stiffness and rotary inertia, for a Timoshenko rail (issue 20, section 3).

An Euler–Bernoulli rail (the paper's) has only the bending stiffness EI and the
mass per length rho S, both on `railtrack.Track`.  A Timoshenko rail adds the
shear deformation of the section and the inertia of its rotation: the shear
stiffness kappa G A [N] (shear coefficient x shear modulus x area) and the
rotary inertia per length rho I [kg m] (density x second moment of area).
`TimoshenkoRail` holds these two; EI and rho S stay on the track, so that the
same rail can be read with and without shear.  Both matter above roughly
500 Hz, where the rail's bending wavelength is no longer long against its
height; they lower the pinned-pinned frequency of the rail between sleepers
(`railtrack.equations.timoshenko_receptance.pinned_pinned_frequency`).
"""

from __future__ import annotations

from dataclasses import dataclass

from .plausibility_check import check_plausible, quantities_to_si
from .track import as_float64, require_non_negative, require_positive

__all__ = ["TimoshenkoRail"]


@dataclass(frozen=True)
class TimoshenkoRail:
    """Shear stiffness and rotary inertia of the rail, the Timoshenko beam's extra terms.

    The rail's deflection w and the rotation psi of its sections obey, with the
    force per length f(x, t) upward (w positive upward),

        rho S w_tt - kappa G A (w_xx - psi_x) = f,
        rho I psi_tt - EI psi_xx - kappa G A (w_x - psi) = 0;

    ``shear_stiffness -> inf`` and ``rotary_inertia = 0`` give the paper's
    Euler–Bernoulli rail, ``EI w_xxxx + rho S w_tt = f``.

    Parameters
    ----------
    shear_stiffness : float
        kappa G A > 0 [N]: shear coefficient x shear modulus x cross-section area.
    rotary_inertia : float
        rho I >= 0 [kg m]: steel density x second moment of area (per length of rail).

    Examples
    --------
    >>> rail = TimoshenkoRail.uic60()
    >>> round(rail.shear_stiffness / 1e6, 1), round(rail.rotary_inertia, 4)   # MN, kg m
    (248.5, 0.2398)
    >>> TimoshenkoRail.from_section(0.4, 81e9, 76.70e-4, 7850.0, 3055e-8) == rail
    True
    """

    shear_stiffness: float
    rotary_inertia: float

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("shear_stiffness", self.shear_stiffness, "N")
        require_non_negative("rotary_inertia", self.rotary_inertia, "kg m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def from_section(cls, shear_coefficient: float, shear_modulus: float, area: float,
                     density: float, second_moment: float) -> TimoshenkoRail:
        """kappa G A and rho I from the section's properties.

        Parameters
        ----------
        shear_coefficient : float
            kappa > 0 [-], Timoshenko's shear coefficient for the direction of bending.
        shear_modulus : float
            G > 0 [Pa].
        area : float
            A > 0 [m^2], the cross-section's area.
        density : float
            rho >= 0 [kg/m^3].
        second_moment : float
            I >= 0 [m^4], about the axis of bending (horizontal, for vertical bending).
        """
        for name, value, unit in (("shear_coefficient", shear_coefficient, ""),
                                  ("shear_modulus", shear_modulus, "Pa"),
                                  ("area", area, "m^2")):
            require_positive(name, value, unit)
        require_non_negative("density", density, "kg/m^3")
        require_non_negative("second_moment", second_moment, "m^4")
        return cls(shear_coefficient * shear_modulus * area, density * second_moment)

    @classmethod
    def uic60(cls) -> TimoshenkoRail:
        """The UIC60 (60E1) rail in vertical bending: kappa G A = 248.5 MN, rho I = 0.240 kg m.

        From A = 76.70 cm^2, I = 3055 cm^4 (the UIC 60 value; EN 13674-1 lists
        3038.3 cm^4 for 60E1, 0.6 % less), G = 81 GPa, rho = 7850 kg/m^3 and
        kappa = 0.4 for vertical shear.  What we could check in stored sources:
        A = 76.70 cm^2, I_y = 3038.3 cm^4, E = 210 GPa, G = 81 GPa and
        rho = 7850 kg/m^3 in the UIC60 entry of the rolling-noise package
        ``rolland`` (github.com/alex-nehls/rolland, ``rolland/database/rail/db_rail.py``),
        whose later revision gives the vertical shear coefficient 0.393 (and
        0.538 lateral; its commented UIC54 entry gives 0.4 and 0.54).  The value
        0.4 is the one usually quoted for vertical bending of UIC60 (Knothe &
        Grassie, Vehicle System Dynamics 22, 1993, 209-262; Grassie et al.,
        J. Mech. Eng. Sci. 24, 1982, 77-90); we could not open those tables here.
        E I = 6.42 MN m^2 with E = 210 GPa; `railtrack.Track.paper` keeps the
        paper's 6.3 MN m^2 and 60 kg/m.
        """
        return cls.from_section(0.4, 81e9, 76.70e-4, 7850.0, 3055e-8)
