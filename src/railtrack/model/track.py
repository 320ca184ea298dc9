"""Parameters of the track: rail, pads, sleepers (Table 1 of Hoang et al. 2015).

All quantities are SI: metres, seconds, kilograms, newtons.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

from .plausibility_check import check_plausible, quantities_to_si
from .validation import as_float64, require_finite, require_non_negative, require_positive

__all__ = ["Track", "require_positive", "require_non_negative", "require_finite", "as_float64"]


@dataclass(frozen=True)
class Track:
    """A periodically supported rail with its pads and sleepers.

    The rail is an infinite Euler–Bernoulli beam resting on identical sleepers
    spaced `sleeper_spacing` apart (Fig. 1 of the paper).  A pad (spring
    `pad_stiffness`, dashpot `pad_damping`) joins the rail to each sleeper;
    the foundation below the sleeper is a separate law
    (`railtrack.model.foundations`) and the train a `railtrack.Train`.

    Parameters
    ----------
    rail_linear_mass : float
        Mass of the rail per unit length, rho*S [kg/m].
    rail_bending_stiffness : float
        Bending stiffness of the rail, E*I [N m^2].
    sleeper_mass : float
        Mass M of one sleeper, the share under the one rail modelled [kg].
    sleeper_spacing : float
        Distance L between neighbouring sleepers [m].
    pad_stiffness : float
        Rail-pad stiffness k1 [N/m].
    pad_damping : float
        Rail-pad viscous damping eta1 [N s/m], may be zero.

    Notes
    -----
    Every field may also be a numpy array: all formulas of the package are
    elementwise, so arrays that broadcast against each other and against the
    frequency axis describe a batch of tracks: give batched fields a trailing
    axis of length one, shape ``(..., 1)``, so that the last axis stays the
    harmonic axis (see `railtrack.sweep_speeds`).

    Examples
    --------
    >>> track = Track.paper()
    >>> track.pad_stiffness / track.sleeper_mass     # omega_0^2 of eq. (8)
    2200000.0
    >>> Track.paper(pad_damping=30e3).pad_damping
    30000.0
    """

    rail_linear_mass: float
    rail_bending_stiffness: float
    sleeper_mass: float
    sleeper_spacing: float
    pad_stiffness: float
    pad_damping: float

    def __post_init__(self) -> None:
        quantities_to_si(self)
        require_positive("rail_linear_mass", self.rail_linear_mass, "kg/m")
        require_positive("rail_bending_stiffness", self.rail_bending_stiffness, "N m^2")
        require_positive("sleeper_mass", self.sleeper_mass, "kg")
        require_positive("sleeper_spacing", self.sleeper_spacing, "m")
        require_positive("pad_stiffness", self.pad_stiffness, "N/m")
        require_non_negative("pad_damping", self.pad_damping, "N s/m")
        as_float64(self)
        check_plausible(self)

    @classmethod
    def paper(cls, **changes: float) -> "Track":
        """The UIC60 rail, pads and sleepers of Table 1, optionally with some fields changed."""
        values = dict(
            rail_linear_mass=60.0,
            rail_bending_stiffness=6.3e6,
            sleeper_mass=100.0,
            sleeper_spacing=0.6,
            pad_stiffness=220e6,
            pad_damping=1.0e6,
        )
        values.update(changes)
        return cls(**values)

    @classmethod
    def ballasted(cls, **changes: float) -> "Track":
        """A ballasted track of Zhai, Wang & Lin (2004), mapped onto this model.

        Rail 60 kg/m, EI = 6.62 MN m^2; pad 65 MN/m and 75 kN s/m (about a
        third of critical, where the paper's is several times critical);
        sleepers 0.6 m apart.  The sleeper mass is the half sleeper
        (125.5 kg) plus the share of the ballast mass that moves with it
        (217.6 kg, `railtrack.model.ballast.single_layer`); use it with
        ``LinearFoundation.ballasted()``.  Values per rail and rail seat,
        as listed in `railtrack.model.ballast.ZHAI_2004`.
        """
        from .ballast import ZHAI_2004 as z, single_layer

        layer = single_layer(z["ballast_mass"], z["ballast_stiffness"], z["ballast_damping"],
                             z["subgrade_stiffness"], z["subgrade_damping"])
        values = dict(
            rail_linear_mass=z["rail_linear_mass"],
            rail_bending_stiffness=z["rail_bending_stiffness"],
            sleeper_mass=z["half_sleeper_mass"] + layer.added_mass,
            sleeper_spacing=z["sleeper_spacing"],
            pad_stiffness=z["pad_stiffness"],
            pad_damping=z["pad_damping"],
        )
        values.update(changes)
        return cls(**values)

    def replace(self, **changes: float) -> "Track":
        """Return a copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)

    @property
    def pad_natural_frequency_squared(self) -> float:
        """omega_0^2 = k1 / M of eq. (8) [rad^2/s^2]."""
        return self.pad_stiffness / self.sleeper_mass

    @property
    def pad_damping_rate(self) -> float:
        """beta = eta1 / M of eq. (8) [1/s]."""
        return self.pad_damping / self.sleeper_mass
