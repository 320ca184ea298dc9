"""Plots of the book, one module per part of it, all drawn from library results.

* `railtrack.plotting.style`: units, labels and the shared look;
* `railtrack.plotting.model`: the track schematic, Table 1, eq. (3) spectra;
* `railtrack.plotting.coefficients`: P_n, F_n and convergence of the iterations;
* `railtrack.plotting.paper_figures`: Figures 3–7 of the paper;
* `railtrack.plotting.verification`: harmonic balance against the time-domain model.

Each function returns a `matplotlib.figure.Figure` and uses SI inside,
showing millimetres and seconds on the axes.
"""


def _sharp_notebook_figures() -> None:
    """In a notebook, embed figures at twice their pixel density ("retina").

    They keep their size on the page but stay sharp when a projector or a
    high-density screen enlarges them.  Outside IPython nothing changes.
    """
    try:
        from IPython import get_ipython
        from matplotlib_inline.backend_inline import set_matplotlib_formats
    except ImportError:
        return
    if get_ipython() is not None:
        set_matplotlib_formats("retina")


_sharp_notebook_figures()
