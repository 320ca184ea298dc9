"""The time-domain ring: an independent check of the harmonic-balance results.

One wagon length of track closed into a ring of finite elements (`fem`;
its layout `ring_layout`, the wheels' positions and loads `ring_loads`),
stepped by Newmark's scheme (`newmark`) until each period repeats the last
(`simulation`, whose `simulate_time_domain` is the entry point; its
arguments checked and the run built in `ring_setup`, the periods stepped
in `ring_periods`); the time step and its error (`timestep`), the run's
cost estimated beforehand (`runcost`), the ring started from a
harmonic-balance solution (`ring_state`), its forces and moments
(`ring_outputs`; every sleeper's, `ring_fields`), a cell of differing
sleepers laid along it (`ring_cell`; its linearised map,
`cell_span_map`), wheels of mass on Hertz springs over a rail-top profile
(`ring_wheels`, `ring_contact`), its result (`td_solution`, its short repr
`td_repr`) and the spectrum of a record (`spectrum`).

Imports: `railtrack.model`, `railtrack.equations` and `railtrack.solvers`.
"""
