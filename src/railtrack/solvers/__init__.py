"""The solvers of the harmonic-balance equations and the result they return.

`solve` (the entry point: a method looked up in a table), `fixed_point`
(the paper's eq. 21), `newton`, `batch` (Newton on many systems at once),
`truncation` (how many harmonics: m = "auto"), `conditioning`, `diagnosis`,
`arguments` (checks of the arguments), `foundation_at_rest`, `solution`
(the `Solution` and the time histories it defines) and `energy` (the work
of the pads, the foundation and the loads).

Imports: `railtrack.model` and `railtrack.equations`.
"""
