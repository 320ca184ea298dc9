"""Figures, in two parts: plots for your own results, and the book's figure recipes.

Plots a user calls on their own solutions:

* `railtrack.plotting.solution`: one solution, its period and its bowl (`plot_solution`);
* `railtrack.plotting.branch`: a branch with its folds, stability and ramps (`plot_branch`);
* `railtrack.plotting.explorer`: the classroom explorer (`railtrack.explore`);
* `railtrack.plotting.style`: units, labels and the shared, colour-blind-safe look.

`railtrack.plotting.book` holds the recipes of the book's figures and
tables, one module per part of the book; they build on the plots above.

Imports: any layer of the library (`model`, `equations`, `solvers`,
`timedomain`, `studies`); nothing imports from here but the book and the
explorer.  Each function returns a `matplotlib.figure.Figure`, SI inside,
millimetres and seconds on the axes.
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
