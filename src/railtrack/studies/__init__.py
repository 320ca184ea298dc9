"""Studies of many solutions, built on the solvers and the ring.

`sweep` (many solves over any field, batched; its result in
`sweep_result`), `continuation` and `branch` (a branch of periodic
solutions followed through its folds; the loop that traces it in
`continuation_trace`, the parameter it follows in `branch_parameter`),
`stability` (does the ring stay on a solution? its verdict in
`stability_verdict`), `branch_stability` (the same along a branch), `ramp`
(the ring through rising or falling speeds),
`hanging_sleeper` (the extremes around a void, from either method) and
`random_support` (a Monte Carlo over sleepers' ballast stiffness, its
draws in `random_draws`); `wavelengths` (the smeared, damped track
under a train, and the share of the load each wavelength receives);
`study_repr` (their short reprs and HTML tables).

Imports: any layer below: `railtrack.model`, `railtrack.equations`,
`railtrack.solvers`, `railtrack.timedomain`.
"""
