"""Figures and tables of the load and method chapters (book chapters 4 and 5).

The functions live in `railtrack.plotting.book.spectra` (chapter 4) and
`railtrack.plotting.book.convergence` (chapter 5); this module gathers them.

* `dirichlet_kernel`, `plot_dirichlet_kernel`: the partial sums of the wheel
  comb of eq. (10) growing into a Dirac comb;
* `load_spectrum_table`, `plot_load_spectra`: the coefficients P_n and F_n of
  eq. (16), with the harmonics where the two wheels of a wagon cancel;
* `plot_aft`: alternating frequency/time for eq. (20), from w(t) samples to
  g(t) samples to the harmonics G_n;
* `plot_contraction_factors`: the error factors of the paper's iteration,
  eq. (21), for both of its branches;
* `convergence_histories`, `plot_convergence`: the relative residual of
  eq. (17) against the iteration number for the fixed point and Newton.

Everything is SI inside; the axes show millimetres and seconds (and the
acceleration-like coefficients in m/s^2, 1/s^2).  w is positive upward, so
the train pushes the sleeper to w < 0; t = 0 when a front wheel is above the
observed sleeper.  Each data series carries a ``gid`` so that tests (and
readers) can find it.
"""

from .convergence import (
    METHOD_LABELS,
    change_and_error_table,
    convergence_histories,
    convergence_table,
    plot_aft,
    plot_contraction_factors,
    plot_convergence,
)
from .spectra import (
    dirichlet_kernel,
    load_spectrum_table,
    plot_dirichlet_kernel,
    plot_load_spectra,
    vanishing_harmonics,
)

__all__ = [
    "METHOD_LABELS",
    "dirichlet_kernel",
    "plot_dirichlet_kernel",
    "vanishing_harmonics",
    "load_spectrum_table",
    "plot_load_spectra",
    "plot_aft",
    "plot_contraction_factors",
    "convergence_histories",
    "plot_convergence",
    "convergence_table",
    "change_and_error_table",
]
