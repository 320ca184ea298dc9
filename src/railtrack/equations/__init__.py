"""The paper's equations, eqs. (3)-(23), as pure functions of the parameters.

`receptance` (eq. 3), `rail_field` (eq. 3 at any x), `moment` (the rail's
bending moment and its kinks), `sleeper` (eqs. 4-8, 14: the pad and the
coupling P), `load` (eqs. 9-16: the load F), `harmonic_balance` (eqs.
17-20: the residual, by AFT), `aft_jacobian` (its exact Jacobian), `linear`
(eq. 23, the closed form of the linear law), `bowl` (the deflection bowl)
`dispersion` (the free waves of the smeared track), `hill` (eq. 17
linearised), and for a cell of N differing sleepers `cell_receptance` (eq. 3
generalised), `cell_linear`, `cell_harmonic_balance`, `cell_modes` (its operators
kept in the Floquet modes), `cell_blocks` (their blocks solved there, by
Woodbury over the few sleepers that differ), `cell_rail_field` and
`cell_hill` (Hill's matrix of the cell); for the
wheel on the rail `wheel_train_receptance` (the free rail under wheels whose
forces vary) and `timoshenko_receptance` (eq. 3 with shear and rotary inertia);
for the layered ground beneath (issue 31) `ground_stiffness` (its surface
flexibility, Kausel & Roesset's stiffness matrices), `ground_waves` (the
Rayleigh wave and the fundamental mode's dispersion), `ground_strip` (the
equivalent stiffness under a strip along the track, Dieterman & Metrikine),
`ground_trapped` (the same, undamped, where no ground wave radiates),
`beam_on_ground` (a continuously supported track's dispersion on the ground
and its critical speed), `critical_estimate` (the quick estimate where the
free track's and the ground's dispersion curves cross, Mezher et al. 2016) and
`moving_load_ground` (its steady response to a moving load);
for the vehicle above the wheels `vehicle_matrices` (its M, C, K, natural
frequencies and static wheelset loads) and `vehicle_response` (its dynamic
stiffness at the wheelsets, its steady ride over a rigid irregular track).

Imports: `railtrack.model` only.
"""
