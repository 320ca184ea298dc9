"""The recipes of the book's figures and tables, one module per part of the book.

* `model`, `schematic`, `tables`, `rail_span`: the model chapters (1-3);
* `spectra`, `coefficients`, `convergence`, `truncation`: the load and the method (4-5);
* `paper_figures`, `paper_figure_data` (with `bilinear_figure_data`,
  `cubic_figure_data`), `panels`, `passage`: Figures 3-7 of the paper (6-8);
* `track_engineer`: the engineer's quantities (9);
* `speed`, `speed_laws`, `wavelengths`: the train speeding up (10);
* `verification` (with `fe_comparison`, `fe_convergence`): against the
  time-domain ring (11).

Imports: the library's layers and the reusable plots of `railtrack.plotting`;
only the book's notebooks import from here.
"""
