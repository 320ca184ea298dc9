"""Chunks of a study mapped in order, on any executor, with an optional progress bar.

A many-case study (the draws of `railtrack.random_support`) cuts its cases
into chunks, each a call of one top-level function on plain arrays, and
`map_chunks` runs them: in this process by default, or on any
`concurrent.futures.Executor` the caller passes (a `ThreadPoolExecutor`, a
`ProcessPoolExecutor`, a Dask ``Client``: they share ``submit``).  The
results come back in the chunks' order whatever order they finish in, and
each chunk computes the same numbers wherever it runs, so the study's
answer does not depend on the executor.

The progress bar (``tqdm.auto``: a widget in a notebook, a line on stderr
in a terminal) counts cases, not chunks.  ``progress=None`` shows it when
the study is large (the caller decides what large is), True or False force
it; with False nothing is written anywhere.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from concurrent.futures import Executor

__all__ = ["map_chunks", "show_progress", "chunk_bounds"]


def show_progress(progress, large: bool) -> bool:
    """Whether to show the bar: `progress` True/False, or None for `large`.

    >>> show_progress(None, False), show_progress(True, False)
    (False, True)
    """
    if progress is None:
        return bool(large)
    if not isinstance(progress, bool):
        raise TypeError(f"progress must be True, False or None (shown when the work is "
                        f"large); got {progress!r}")
    return progress


def chunk_bounds(size: int, chunk: int) -> list[tuple[int, int]]:
    """[start, stop) of consecutive chunks of at most `chunk` cases covering `size`.

    >>> chunk_bounds(5, 2)
    [(0, 2), (2, 4), (4, 5)]
    """
    return [(start, min(start + chunk, size)) for start in range(0, size, max(1, chunk))]


def map_chunks(function: Callable, arguments: Sequence[tuple], sizes: Sequence[int], *,
               executor: Executor | None = None, progress: bool = False,
               description: str = "") -> list:
    """``[function(*a) for a in arguments]``, on `executor` if given, in the arguments' order.

    Parameters
    ----------
    function : callable
        A top-level function (a process pool pickles it and its arguments).
    arguments : sequence of tuple
        One tuple of positional arguments per chunk.
    sizes : sequence of int
        Cases in each chunk, for the progress bar.
    executor : concurrent.futures.Executor, optional
        Anything with ``submit(function, *args)`` returning a future (a Dask
        ``Client`` too); default: this process, one chunk after another.
    progress : bool
        Show a ``tqdm.auto`` bar counting the cases.
    description : str
        The bar's label.
    """
    if executor is not None and not callable(getattr(executor, "submit", None)):
        raise TypeError(f"executor must have a submit method (a concurrent.futures.Executor "
                        f"or a Dask Client); got {type(executor).__name__}")
    bar = None
    if progress:
        from tqdm.auto import tqdm

        bar = tqdm(total=int(sum(sizes)), desc=description, unit="case")
    try:
        if executor is None:
            results = []
            for args, size in zip(arguments, sizes):
                results.append(function(*args))
                if bar is not None:
                    bar.update(size)
            return results
        # every chunk submitted first, then read in order: a Dask future has
        # .result() but is not a concurrent.futures one (no as_completed)
        futures = [executor.submit(function, *args) for args in arguments]
        results = []
        for future, size in zip(futures, sizes):
            results.append(future.result())
            if bar is not None:
                bar.update(size)
        return results
    finally:
        if bar is not None:
            bar.close()
