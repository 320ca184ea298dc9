"""The design figures of a solution in the trade's terms, and Eisenmann's dynamic factor (issue 29).

`DesignSummary` is what ``summary()`` of `railtrack.Solution`,
`railtrack.CellSolution` and `railtrack.WheelSolution` returns
(`railtrack.solvers.design_figures` computes it).  Its fields are SI, as
everywhere in the package; its table (`DesignSummary.to_dataframe`) and its
repr give them in the units a track engineer reads: kN, kPa, kN m, MPa,
km/h.

**Eisenmann's factor.**  Design practice multiplies a static wheel load by
a dynamic factor (Eisenmann 1993, as given in Esveld 2001):

    phi = 1 + t s                          for V <= 60 km/h,
    phi = 1 + t s (1 + (V - 60) / 140)     for 60 < V <= 200 km/h,

with s the track's quality (0.1 very good, 0.2 good, 0.3 poor) and t the
multiple of the standard deviation that sets the probability of not being
exceeded (1: 68.3 %, 2: 95.5 %, 3: 99.7 %; t = 3 is the usual choice for
the rail's stress).  It is compared in one place only: beside the dynamic
factor max P / Q of a `railtrack.WheelSolution`, the one result whose
wheel load varies.  The comparison is an order-of-magnitude one: phi is a
statistical envelope of measured wheel loads on real tracks, with their
random unevenness and vehicles, whereas the model's factor is the
deterministic response to the profile it was given (none: 1 at any
speed).  Above 200 km/h the formula is extrapolated, and the summary says
so.

References: J. Eisenmann (1993), "Die Schiene als Träger und Fahrbahn -
theoretische Grundlagen und praktische Beispiele", in Fastenrath (ed.),
Die Eisenbahnschiene, Ernst & Sohn, Berlin; C. Esveld (2001), Modern
Railway Track, 2nd ed., MRT-Productions, Delft.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..model.rail_section import RailSection
from ..model.validation import require_non_negative, require_positive

__all__ = ["DesignSummary", "eisenmann_factor", "TRACK_QUALITY"]

TRACK_QUALITY = {"very good": 0.1, "good": 0.2, "poor": 0.3}
"""Eisenmann's s for each track quality [-]."""

EISENMANN_RANGE_KMH = 200.0
"""Highest speed for which Eisenmann gives his formula [km/h]."""


def eisenmann_factor(speed, track_quality="good", certainty: float = 3.0) -> float:
    """Eisenmann's dynamic factor phi for a wheel load at `speed` (module docstring).

    Parameters
    ----------
    speed : float
        Train speed v [m/s] (V = 3.6 v km/h), >= 0.
    track_quality : {"very good", "good", "poor"} or float
        The track's condition, or s itself (> 0).
    certainty : float
        t, the multiple of the standard deviation: 1, 2 or 3 for 68.3 %,
        95.5 % or 99.7 % of the wheel loads not exceeded (> 0).

    Returns
    -------
    float
        phi [-]; beyond 200 km/h the linear law extrapolated.

    Examples
    --------
    >>> round(eisenmann_factor(160 / 3.6, "good", 3), 4)    # 1 + 3 x 0.2 x (1 + 100/140)
    2.0286
    """
    require_non_negative("speed", speed, "m/s")
    require_positive("certainty", certainty)
    if isinstance(track_quality, str):
        if track_quality not in TRACK_QUALITY:
            raise ValueError(f"track_quality must be one of {sorted(TRACK_QUALITY)} or a number "
                             f"s > 0; got {track_quality!r}")
        s = TRACK_QUALITY[track_quality]
    else:
        require_positive("track_quality", track_quality)
        s = float(track_quality)
    kmh = 3.6 * float(speed)
    return 1.0 + float(certainty) * s * (1.0 + max(kmh - 60.0, 0.0) / 140.0)


@dataclass(frozen=True)
class DesignSummary:
    """The design figures of one solution, SI fields; `to_dataframe` in kN, kPa, kN m, MPa.

    Attributes
    ----------
    case : str
        What was solved, in words.
    converged : bool
        The solution's flag: figures of an unconverged solve are not the track's.
    speed : float
        v [m/s].
    wheel_load : float
        The largest static wheel load Q of the train on the modelled rail [N].
    rail_seat_loads : ndarray, shape (N,)
        Each sleeper's largest rail-seat load over the period [N].
    mean_rail_seat_load : float
        The rail-seat load averaged over the period and the cell's sleepers,
        from statics: sum_j Q_j L / H, plus the rail's weight rho S g L when
        the cell has gravity [N].
    foundation_forces : ndarray, shape (N,)
        Each sleeper's largest force on its foundation (ballast) [N].
    bearing_area : float or None
        The effective ballast bearing area under one rail seat [m^2], if given.
    sagging_moment, hogging_moment : float
        Largest sagging (> 0) and hogging (< 0) rail bending moment over the
        period and along the rail [N m].
    section : RailSection
        The section whose moduli give the stresses.
    contact_force_max, contact_force_min, dynamic_factor : ndarray or None
        Per wheel, largest and smallest wheel-rail force P [N] and max P / Q [-]
        (a `WheelSolution` only).
    contact_loss_share, contact_loss_longest : ndarray or None
        Per wheel, the share of the period off the rail [-] and the longest spell [s].
    eisenmann : float or None
        Eisenmann's phi at this speed, beside the dynamic factor (module docstring).
    eisenmann_basis : str
        s, t and the speed range behind `eisenmann`.
    notes : tuple of str
        Caveats (a section that is not the modelled rail, an unconverged solve).
    """

    case: str
    converged: bool
    speed: float
    wheel_load: float
    rail_seat_loads: np.ndarray
    mean_rail_seat_load: float
    foundation_forces: np.ndarray
    bearing_area: float | None
    sagging_moment: float
    hogging_moment: float
    section: RailSection
    contact_force_max: Any = None
    contact_force_min: Any = None
    dynamic_factor: Any = None
    contact_loss_share: Any = None
    contact_loss_longest: Any = None
    eisenmann: float | None = None
    eisenmann_basis: str = ""
    notes: tuple = ()

    @property
    def max_rail_seat_load(self) -> float:
        """The largest rail-seat load over the sleepers and the period [N]."""
        return float(np.max(self.rail_seat_loads))

    @property
    def max_foundation_force(self) -> float:
        """The largest foundation (ballast) force over the sleepers and the period [N]."""
        return float(np.max(self.foundation_forces))

    @property
    def ballast_pressure(self) -> float | None:
        """Largest foundation force over the bearing area [Pa]; None without an area."""
        if self.bearing_area is None:
            return None
        return self.max_foundation_force / self.bearing_area

    @property
    def rail_foot_stress(self) -> float:
        """Sagging moment over W_foot: the foot's largest tension [Pa]."""
        return float(self.section.foot_stress(self.sagging_moment))

    @property
    def rail_foot_stress_hogging(self) -> float:
        """Hogging moment over W_foot: the foot's largest compression, negative [Pa]."""
        return float(self.section.foot_stress(self.hogging_moment))

    def rows(self, details: bool = True) -> list[tuple[str, float, str]]:
        """(quantity, value, unit) in the trade's units, the rows of `to_dataframe`.

        With `details`, also each sleeper's and each wheel's largest values
        (where the cell has more than one sleeper, the wagon more than one wheel).
        """
        kilo = 1e-3
        rows = [("speed", 3.6 * self.speed, "km/h"),
                ("wheel load Q (static, largest)", kilo * self.wheel_load, "kN"),
                ("rail-seat load, largest", kilo * self.max_rail_seat_load, "kN"),
                ("rail-seat load, mean (statics)", kilo * self.mean_rail_seat_load, "kN"),
                ("foundation force, largest", kilo * self.max_foundation_force, "kN")]
        if self.bearing_area is not None:
            rows += [("ballast bearing area per rail seat", self.bearing_area, "m^2"),
                     ("ballast pressure, largest", kilo * self.ballast_pressure, "kPa")]
        rows += [("rail bending moment, sagging", kilo * self.sagging_moment, "kN m"),
                 ("rail bending moment, hogging", kilo * self.hogging_moment, "kN m"),
                 (f"rail-foot stress, sagging ({self.section.name})",
                  1e-6 * self.rail_foot_stress, "MPa"),
                 (f"rail-foot stress, hogging ({self.section.name})",
                  1e-6 * self.rail_foot_stress_hogging, "MPa")]
        if self.dynamic_factor is not None:
            rows += [("wheel-rail force, largest", kilo * np.max(self.contact_force_max), "kN"),
                     ("wheel-rail force, smallest", kilo * np.min(self.contact_force_min), "kN"),
                     ("dynamic factor max P/Q", float(np.max(self.dynamic_factor)), "-"),
                     (f"Eisenmann factor ({self.eisenmann_basis})", self.eisenmann, "-"),
                     ("loss of contact, share of the period",
                      100 * float(np.max(self.contact_loss_share)), "%"),
                     ("loss of contact, longest spell",
                      1e3 * float(np.max(self.contact_loss_longest)), "ms")]
        many = details and self.rail_seat_loads.size > 1
        for j in range(self.rail_seat_loads.size if many else 0):
            rows += [(f"rail-seat load, largest, sleeper {j}", kilo * self.rail_seat_loads[j], "kN"),
                     (f"foundation force, largest, sleeper {j}",
                      kilo * self.foundation_forces[j], "kN")]
        wheels = 0 if self.dynamic_factor is None or not details else np.size(self.dynamic_factor)
        for k in range(wheels if wheels > 1 else 0):
            rows += [(f"wheel-rail force, largest, wheel {k}",
                      kilo * self.contact_force_max[k], "kN"),
                     (f"dynamic factor max P/Q, wheel {k}", self.dynamic_factor[k], "-")]
        return [(name, float(value), unit) for name, value, unit in rows]

    def to_dataframe(self, details: bool = True):
        """The figures as a pandas DataFrame: columns quantity, value, unit (trade units).

        `details` as `rows`: per sleeper and per wheel too.
        """
        import pandas as pd

        return pd.DataFrame(self.rows(details), columns=["quantity", "value", "unit"])

    def _repr_html_(self) -> str:
        """The overall figures as a table, for notebooks (per sleeper: `to_dataframe`)."""
        import html

        head = f"<p><b>DesignSummary</b>: {html.escape(self.case)}"
        head += "" if self.converged else " <b>(NOT converged)</b>"
        notes = "".join(f"<br><i>note: {html.escape(note)}</i>" for note in self.notes)
        table = self.to_dataframe(details=False).to_html(index=False, float_format="{:.4g}".format)
        return f"{head}{notes}</p>{table}"

    def __repr__(self) -> str:
        lines = [f"DesignSummary: {self.case}{'' if self.converged else ' (NOT converged)'}"]
        seat = f"{self.max_rail_seat_load / 1e3:.1f} kN"
        if self.rail_seat_loads.size > 1:
            seat += f" (sleeper {int(np.argmax(self.rail_seat_loads))})"
        lines += [f"  wheel load Q            {self.wheel_load / 1e3:.1f} kN at "
                  f"{3.6 * self.speed:.0f} km/h",
                  f"  rail-seat load          {seat}, mean {self.mean_rail_seat_load / 1e3:.1f} kN",
                  f"  foundation force        {self.max_foundation_force / 1e3:.1f} kN"]
        if self.bearing_area is not None:
            lines.append(f"  ballast pressure        {self.ballast_pressure / 1e3:.0f} kPa "
                         f"on {self.bearing_area:g} m^2")
        lines += [f"  rail moment             {self.sagging_moment / 1e3:.2f} / "
                  f"{self.hogging_moment / 1e3:.2f} kN m (sagging / hogging)",
                  f"  rail-foot stress        {self.rail_foot_stress / 1e6:.1f} / "
                  f"{self.rail_foot_stress_hogging / 1e6:.1f} MPa ({self.section.name})"]
        if self.dynamic_factor is not None:
            lines += [f"  wheel-rail force        {np.max(self.contact_force_max) / 1e3:.1f} / "
                      f"{np.min(self.contact_force_min) / 1e3:.1f} kN (max / min)",
                      f"  dynamic factor max P/Q  {np.max(self.dynamic_factor):.3f}; Eisenmann "
                      f"{self.eisenmann:.2f} ({self.eisenmann_basis}; an order of magnitude)",
                      f"  loss of contact         {100 * np.max(self.contact_loss_share):.1f} % "
                      f"of the period, longest {1e3 * np.max(self.contact_loss_longest):.1f} ms"]
        lines += [f"  note: {note}" for note in self.notes[:2]]
        return "\n".join(lines)
