"""The public entry points run BLAS on one thread and their warnings still name the caller (issue 28)."""

import warnings

from threadpoolctl import threadpool_info

import railtrack as rt
import railtrack.equations.harmonic_balance as hb


def _blas_threads():
    return {pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"}


def test_solve_runs_on_one_blas_thread_and_restores_the_callers(monkeypatch):
    seen = []
    original = hb.residual

    def spy(*args, **kwargs):
        seen.append(_blas_threads())
        return original(*args, **kwargs)

    monkeypatch.setattr("railtrack.solvers.solve.residual", spy)
    before = _blas_threads()
    rt.solve(rt.Track.paper(), rt.Train.paper(), rt.LinearFoundation.paper(), 15,
             method="analytic", stability="off")
    assert seen and all(threads <= {1} for threads in seen)
    assert _blas_threads() == before


def test_a_warning_from_solve_names_the_line_that_called_it():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rt.solve(rt.Track.paper(), rt.Train.paper(), rt.CubicFoundation.paper(0.8), 3)
    truncation = [w for w in caught if issubclass(w.category, rt.TruncationWarning)]
    assert truncation, "m = 3 must warn that its truncation error is large"
    assert all(w.filename == __file__ for w in truncation), [w.filename for w in truncation]
