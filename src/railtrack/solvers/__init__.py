"""The solvers of the harmonic-balance equations and the result they return.

`solve` (the entry point: a method looked up in a table), `sleeper_solve`
(its one sleeper on a rigid ground: the rounds of m, the result), `fixed_point`
(the paper's eq. 21), `newton`, `batch` (Newton on many systems at once),
`truncation` (how many harmonics: the truncation error), `harmonics_needed`
(m = "auto": predicted, then grown), `spectrum` (the linear coefficients
of eq. 17 over n, computed once), `conditioning`, `diagnosis`,
`arguments` (checks of the arguments), `foundation_at_rest`, `solution`
(the `Solution`), `time_histories` (the Fourier series it sums and its
rail at any (t, x)), `energy` (the work
of the pads, the foundation and the loads), `floquet` and `contour`
(stability by Hill's method), `floquet_track` (its multipliers continued
from a neighbouring solution), `floquet_assembly` (the `Floquet` result
judged), `floquet_verdict` and `floquet_bound` (its verdict, and the a-priori
estimate of |mu| it rests on), and for a cell of N sleepers `cell_newton`,
`cell_step` (its structured Newton step), `cell_auto` (m = "auto"),
`cell_truncation` (its truncation estimate, in the Floquet modes),
`cell_static` (the track under its own weight), `cell_solution` and
`cell_floquet` (its Floquet multipliers, Hill's matrix of the cell);
`result_protocol` (the questions every steady-state result answers, alike,
and the `SharedOutputs` mixin), `result_repr` (their short reprs and HTML
tables: the `ShortRepr` mixin) and `export` (the `Exports` mixin); `convergence` (the
errors and warnings of a solve that fell short); `wheel_extremes` (a wheel
solution's contact force over a period) and `wheel_free_rail` (its rail
under the wheels' varying forces, eq. 13.2);
`design_figures` and `design_summary` (the ``summary()`` of every result:
seat load, ballast pressure, rail moment and stress, dynamic factor).

Imports: `railtrack.model` and `railtrack.equations`.
"""
