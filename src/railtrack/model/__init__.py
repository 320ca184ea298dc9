"""The model's parameters: the track, the train, the pair of them, the foundation laws.

`track` (rail, pads, sleepers; Table 1), `train` (wagon length, axles,
loads, speed), `passage` (the train on the track, as the equations take
it), `foundations` (what a foundation law is, and `as_foundation`),
`foundation_laws` (eqs. 22, 24, 25), `callable_foundation` (any callable
law), `gap` (a hanging sleeper's law), `cell` (N sleepers that differ,
repeating along the track), `wheel` and `profile` (the wheel on the rail and the rail-top
profile), `irregularity` (the FRA and German spectra of the rail's
vertical profile) and `random_profile` (a periodic rail drawn from one, or
measured), `vehicle` (a bogie wagon's body, bogies and wheelsets),
`timoshenko` (a rail with shear and rotary inertia), `ballast` (a
ballast-subgrade support reduced to one layer), `rail_section` (a rail
profile's moduli, UIC60 and UIC54, for stresses) and `ground` (soil layers
over a half-space, issue 31).  Frozen, validated
dataclasses in SI units; `validation` holds the checks they share (and the
conversion of pint quantities to SI), `plausibility` the range of each input
on real track and `plausibility_check` the warning for a value far outside it.

Imports: nothing from railtrack outside this folder.  Every other layer
may import from here.
"""
