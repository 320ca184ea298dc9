"""The physically plausible range of every input, and the warning for a value far outside it.

One table, `PLAUSIBLE_RANGES`: for each kind of input (a pad's stiffness, a
wheel load, a dip's depth...) the range found on real railway track, in SI
units, and where that range comes from.  A value an order of magnitude or
more outside its range (below low / 10 or above 10 high) is almost always a
unit slip: a pad stiffness typed in kN/m, a wheel load in kN, a dip angle in
mrad.  `railtrack.model.plausibility_check` warns `PlausibilityWarning` for
it, naming the field, the value, the range and the likely slip.  Inside a
range's factor of ten nothing is said: studies past service speeds or with
unusual tracks stay quiet.

What cannot be caught: a slip by less than ten.  A speed typed in km/h is
3.6 times too large (160 "m/s" for 160 km/h is a plausible speed; only
`railtrack.studies.wheel_load_statistics`, a study of trains in service,
warns above their 350 km/h), a load in kilogram-force 9.81 times too small,
a mass per axle instead of per wheel twice too large.  State the unit
instead: pass a pint Quantity
(``220 * ureg("MN/m")``), which is converted to SI at the boundary.

Sources are cited by the keys of the book's bibliography (book/references.bib)
where they are in it.  "As commonly quoted" marks a value taken as the literature
quotes it, from a text that could not be opened while writing this table: the ranges are
deliberately generous (a warning needs a factor of ten beyond them), so that
such a value being off by a few tens of percent changes nothing.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["PlausibilityWarning", "PlausibleRange", "PLAUSIBLE_RANGES", "RANGES",
           "ORDER_OF_MAGNITUDE", "plausible_ranges"]

ORDER_OF_MAGNITUDE = 10.0
"""How far outside its range a value must be to warn [-]: a factor of ten."""


class PlausibilityWarning(UserWarning):
    """An input (or a result) an order of magnitude outside what railway track shows.

    Usually a unit slip.  To raise instead of warning::

        warnings.simplefilter("error", railtrack.PlausibilityWarning)

    or, for a block of code, ``with railtrack.plausibility("error"): ...``
    (``"ignore"`` for a deliberate limit study).
    """


@dataclass(frozen=True)
class PlausibleRange:
    """One row of the table: the range of one kind of input, in SI units.

    Attributes
    ----------
    field : str
        The kind of input (the name of the field that usually carries it).
    unit : str
        Its SI unit, as the model's docstrings write it.
    low, high : float
        The range found on real track; zero, where a field allows it
        (no damping, no gap), is never checked.
    what : str
        What the value is, as the warning says it ("pads are").
    source : str
        Where the range comes from.
    """

    field: str
    unit: str
    low: float
    high: float
    what: str
    source: str


_K93 = "Knothe & Grassie 1993 [knothe1993], as commonly quoted"
_TABLE1 = "Hoang et al. 2015, Table 1 [hoang2015fast]"
_MPE = ("Table 1 of 'Study on transmission characteristics of vertical rail vibrations in "
        "ballast track', Math. Probl. Eng. 2017, 5872419")
_EC8 = "EN 1998-1:2004 (Eurocode 8), Table 3.1, ground types by v_s,30"

PLAUSIBLE_RANGES: tuple[PlausibleRange, ...] = (
    PlausibleRange(
        "rail_linear_mass", "kg/m", 30.0, 80.0, "rails weigh",
        "EN 13674-1 profiles: 49E1 49.4, 60E1 60.2 kg/m; 136RE 67.6 kg/m; light 30 kg/m "
        "rails; " + _TABLE1 + ": 60 kg/m; Zhai et al. 2004 [zhai2004ballast]: 60.64 kg/m"),
    PlausibleRange(
        "rail_bending_stiffness", "N m^2", 1e6, 1.5e7, "rails bend with EI",
        "E = 210 GPa times I: 49E1 1819 cm^4 (3.8 MN m^2), 60E1 3038 cm^4 (6.4 MN m^2), "
        "136RE 3950 cm^4 (8.3 MN m^2); " + _TABLE1 + ": 6.3 MN m^2"),
    PlausibleRange(
        "sleeper_mass", "kg", 30.0, 400.0, "half sleepers (one rail seat) weigh",
        "half a timber sleeper about 40 kg, half a concrete monoblock 120-170 kg "
        "(Esveld 2001, Modern Railway Track, as commonly quoted; 170 kg in " + _MPE + "); up "
        "to 343 kg with the ballast share of Zhai et al. 2004 [zhai2004ballast]; "
        + _TABLE1 + ": 100 kg"),
    PlausibleRange(
        "sleeper_spacing", "m", 0.5, 0.75, "sleepers lie",
        "0.6 m on main lines, 0.55-0.75 m elsewhere (Esveld 2001, as commonly quoted; 0.55 m in "
        + _MPE + "); " + _TABLE1 + ": 0.6 m"),
    PlausibleRange(
        "pad_stiffness", "N/m", 5e7, 2e9, "pads are",
        "soft pads 50-100 MN/m to stiff (HDPE) pads of 1-2 GN/m (" + _K93 + "; Thompson "
        "2009, Railway Noise and Vibration, as commonly quoted); 225 MN/m in " + _MPE + "; "
        "65 MN/m in Zhai et al. 2004 [zhai2004ballast]; " + _TABLE1 + ": 220 MN/m"),
    PlausibleRange(
        "pad_damping", "N s/m", 1e4, 1e6, "pad dashpots are",
        "tens of kN s/m for real pads (" + _K93 + "; 75 kN s/m in Zhai et al. 2004 "
        "[zhai2004ballast]); up to the 1 MN s/m of " + _TABLE1 + ", several times critical"),
    PlausibleRange(
        "foundation_stiffness", "N/m", 5e6, 3e8, "ballast and subgrade under one rail seat are",
        "20 MN/m per half sleeper in " + _MPE + "; 49.6 MN/m for "
        "Zhai et al. 2004 [zhai2004ballast] in series; 5 MN/m for the soft ground of the "
        "book's chapter 6, a few hundred MN/m for ballast on rock (" + _K93 + "); "
        + _TABLE1 + ": 20 MN/m"),
    PlausibleRange(
        "foundation_damping", "N s/m", 1e4, 5e5, "ballast dashpots under one rail seat are",
        "ballast 58.8 and subgrade 31.2 kN s/m in Zhai et al. 2004 [zhai2004ballast]; "
        "tens of kN s/m (" + _K93 + "); " + _TABLE1 + " (section 4.1): 0.2 MN s/m"),
    PlausibleRange(
        "cubic_stiffness", "N/m^3", 1e12, 1e14, "cubic ballast stiffnesses k3 are",
        "Hoang et al. 2015, section 4.3 [hoang2015fast]: 20 kN/mm^3 = 2e13 N/m^3, so that "
        "k3 w^2 matches k2 = 20 MN/m near w = 1 mm; a decade either side"),
    PlausibleRange(
        "speed", "m/s", 1.0, 700.0, "this book's trains run at",
        "walking pace to the 159.7 m/s (574.8 km/h) world record [tgvrecord2007], and on to "
        "the 700 m/s of the book's speed sweeps (critical speeds, chapter 10); only absurd "
        "speeds warn"),
    PlausibleRange(
        "wheel_load", "N", 2e4, 2.5e5, "wheel loads (half an axle load) are",
        "4 t axles (light vehicles, 20 kN per wheel) to 40 t heavy haul (196 kN); 54.5 kN "
        "for the Manchester benchmark coach [iwnicki1998manchester]; 122.6 kN for a 25 t "
        "C80 wagon; " + _TABLE1 + ": 75 kN"),
    PlausibleRange(
        "wagon_length", "m", 5.0, 60.0, "wagons (the load's period) are",
        "12 m (C80 coal wagon) to 26.4 m (UIC type Z coach, UIC leaflet 567); 60 m is the "
        "package's lone axle (Train.single_axle); " + _TABLE1 + ": 18 m"),
    PlausibleRange(
        "unsprung_mass", "kg", 200.0, 2000.0, "unsprung masses per wheel are",
        "half a wheelset: 906 kg for the Manchester benchmark [iwnicki1998manchester]; "
        "light-rail wheels a few hundred kg, axle-hung motors to about 2 t; 600 kg in "
        "the book's chapter 14"),
    PlausibleRange(
        "hertz_constant", "N/m^1.5", 6e10, 1.5e11, "Hertz constants C_H are",
        "C_H = 2 E sqrt(R) / (3 (1 - nu^2)) for steel (E = 210 GPa, nu = 0.3) and wheel "
        "radii 0.2-0.6 m gives 6.9e10-1.2e11; 9.4e10 for a 0.46 m wheel on UIC60 "
        "(the book's chapter 14; Thompson 2009, as commonly quoted)"),
    PlausibleRange(
        "primary_stiffness", "N/m", 2e5, 1e7, "primary suspensions per wheel are",
        "about 1 MN/m per axlebox for passenger bogies (Manchester benchmark "
        "[iwnicki1998manchester], as commonly quoted); stiffer in freight bogies"),
    PlausibleRange(
        "primary_damping", "N s/m", 1e3, 1e5, "primary dampers per wheel are",
        "a few kN s/m per axlebox (Manchester benchmark [iwnicki1998manchester], as "
        "commonly quoted)"),
    PlausibleRange(
        "dip_depth", "m", 1e-4, 5e-3, "dipped welds and joints are",
        "0.1-1 mm at welds, a few mm at dipped joints (Jenkins et al. 1974 [jenkins1974] "
        "and Esveld 2001, both as commonly quoted); the book's 0.5-2 mm dips"),
    PlausibleRange(
        "dip_length", "m", 0.2, 3.0, "dips are",
        "a weld's dip is 0.5-1 m long, a joint's up to a few metres (Esveld 2001, as "
        "commonly quoted); the book's 0.5 and 1 m dips"),
    PlausibleRange(
        "dip_angle", "rad", 1e-3, 3e-2, "total dip angles 2 alpha are",
        "a few to 20 mrad at dipped joints and welds (Jenkins et al. 1974 [jenkins1974], as "
        "commonly quoted); "
        "3.1-12.6 mrad for the book's dips (2 pi depth / length)"),
    PlausibleRange(
        "flat_depth", "m", 5e-5, 3e-3, "wheel flats are",
        "a fresh flat's depth is its sagitta l^2 / (8 R): 0.17-1.7 mm for flats 25-80 mm "
        "long on 0.46 m wheels; out-of-round wheels and when they are removed are surveyed "
        "by Nielsen & Johansson 2000 [nielsen2000oor]"),
    PlausibleRange(
        "flat_length", "m", 0.02, 0.3, "wheel flats are",
        "a few centimetres fresh, longer once worn round; the book's 100 mm rounded flat"),
    PlausibleRange(
        "wheel_circumference", "m", 2.0, 4.0, "wheel circumferences 2 pi R are",
        "2.0-3.9 m for wheel diameters of 0.64-1.25 m, freight and passenger wheels "
        "0.84-0.92 m new (2.6-2.9 m); 3.0 m in the book, a whole number of sleeper "
        "spacings"),
    PlausibleRange(
        "gap", "m", 1e-4, 5e-3, "gaps under hanging sleepers are",
        "0.5-2 mm voids studied by Lundqvist & Dahlberg 2005 [lundqvist2005] and in the book; "
        "voids of a few mm under unsupported sleepers (Sysyn et al. 2021 [sysyn2021], as "
        "commonly quoted)"),
    PlausibleRange(
        "gravity", "m/s^2", 9.78, 9.84, "gravity is",
        "9.78 m/s^2 at the equator to 9.83 at the poles; 9.81 (STANDARD_GRAVITY); 0 (no "
        "weight, the paper's choice) is never checked"),
    PlausibleRange(
        "shear_stiffness", "N", 1e8, 5e8, "rails' kappa G A are",
        "kappa = 0.4, G = 81 GPa times A: 49E1 (62.9 cm^2) 204 MN, 60E1 (76.7 cm^2) 248.5 MN, "
        "136RE (86.1 cm^2) 279 MN (TimoshenkoRail.uic60; " + _K93 + ")"),
    PlausibleRange(
        "rotary_inertia", "kg m", 0.1, 0.5, "rails' rho I are",
        "7850 kg/m^3 times I: 49E1 0.14, 60E1 0.24, 136RE 0.31 kg m (TimoshenkoRail.uic60)"),
    PlausibleRange(
        "track_mass", "kg", 30.0, 600.0, "equivalent track masses per wheel are",
        "245 kg for British track (Jenkins et al. 1974 [jenkins1974], as p2_force "
        "quotes them); 49.7 kg fitted to the paper's track (equivalent_track)"),
    PlausibleRange(
        "track_stiffness", "N/m", 2e7, 5e8, "equivalent track stiffnesses per wheel are",
        "150 MN/m for British track (Jenkins et al. 1974 [jenkins1974], as p2_force quotes "
        "them); 58.3 MN/m fitted to the paper's track (equivalent_track)"),
    PlausibleRange(
        "track_damping", "N s/m", 1e4, 5e5, "equivalent track dampings per wheel are",
        "55.4 kN s/m for British track (Jenkins et al. 1974 [jenkins1974], as p2_force quotes "
        "them); 340 kN s/m fitted to the paper's track (equivalent_track)"),
    # the ground beneath (SoilLayer, LayeredGround, WinklerGround)
    PlausibleRange(
        "soil_shear_wave_speed", "m/s", 30.0, 3000.0, "soils and rocks carry shear waves at",
        _EC8 + ": soft clays and silts (S1) below 100 m/s, D below 180, C 180-360, B 360-800, "
        "rock (A) above 800 m/s; soft clay of 40-70 m/s under the track at Ledsgard "
        "(Madshus & Kaynia 2000 [madshus2000], as commonly quoted); hard rock a few km/s "
        "(as commonly quoted); the book's chapter 16: 45-810 m/s"),
    PlausibleRange(
        "soil_density", "kg/m^3", 1200.0, 2800.0, "soils and rocks have densities",
        "unit weights of about 12 kN/m^3 (organic clay, peat) to 21-22 kN/m^3 (dense gravel, "
        "glacial till), rock about 26-27 kN/m^3 (Das, Principles of Geotechnical "
        "Engineering, as commonly quoted); the book's chapter 16: 1300-2000 kg/m^3"),
    PlausibleRange(
        "poisson_ratio", "-", 0.1, 0.5, "soils' Poisson's ratios are",
        "0.15-0.45 drained, sands, silts and clays (Das, as commonly quoted), near 0.5 for a "
        "saturated soil that cannot drain (the book's 0.49 clay); 0.5 and above are refused"),
    PlausibleRange(
        "soil_damping_ratio", "-", 0.005, 0.1, "soils' hysteretic damping ratios are",
        "0.5-5 % at the small strains of traffic (Kramer 1996, Geotechnical Earthquake "
        "Engineering, as commonly quoted); 3-10 % in EN 1998-5:2004 (Eurocode 8 part 5), "
        "Table 4.1, for strong shaking; the book's chapter 16: 1.5-6 %"),
    PlausibleRange(
        "layer_thickness", "m", 0.1, 100.0, "soil layers are",
        "a 0.3 m ballast or sub-ballast layer (Esveld 2001 [esveld2001], as commonly quoted) "
        "to deposits of several tens of metres, " + _EC8 + " (ground types B, C, S1; "
        "surface alluvium 5-20 m in type E); the book's chapter 16: 4-6 m, and 500 m strata "
        "of a wave-speed test"),
    PlausibleRange(
        "strip_width", "m", 1.5, 5.0, "loaded strips across the track are",
        "sleepers 2.3-2.8 m long: 2.6 m for standard-gauge concrete monoblocks and timber, "
        "2.59 m (8.5 ft) ties in North America (Esveld 2001 [esveld2001], as commonly "
        "quoted), shorter for metre gauge; wider at the ballast's base; the book's chapter "
        "16: 3 m"),
    PlausibleRange(
        "footprint", "m", 0.15, 0.4, "sleepers' widths along the track are",
        "0.22-0.30 m at the base of timber and concrete sleepers (Esveld 2001 [esveld2001], "
        "as commonly quoted); the book's chapter 16: 0.25 m"),
)
"""The plausible range of every input with a physical range (module docstring)."""

RANGES: dict[str, PlausibleRange] = {row.field: row for row in PLAUSIBLE_RANGES}
"""`PLAUSIBLE_RANGES` by field."""


def plausible_ranges():
    """The table of plausible ranges as a pandas DataFrame.

    Returns
    -------
    pandas.DataFrame
        One row per kind of input: field, unit (SI), low, high, what, source.
        A value below low / 10 or above 10 high warns `PlausibilityWarning`.

    Examples
    --------
    >>> table = plausible_ranges()
    >>> row = table.set_index("field").loc["pad_stiffness"]
    >>> row["unit"], float(row["low"]), float(row["high"])
    ('N/m', 50000000.0, 2000000000.0)
    """
    import pandas  # a dependency, imported on call to keep ``import railtrack`` light

    return pandas.DataFrame(
        [(r.field, r.unit, r.low, r.high, r.what, r.source) for r in PLAUSIBLE_RANGES],
        columns=["field", "unit", "low", "high", "what", "source"])
