"""A progress bar for a study that runs step by step, or nothing at all.

`railtrack.continuation`, `railtrack.check_branch`, the time-domain ring
(`railtrack.simulate_time_domain`) and `railtrack.speed_ramp` advance one
point, period or speed at a time; each takes ``progress=None|True|False``
as `railtrack.sweep` and `railtrack.random_support` do
(`railtrack.solvers.chunk_map.show_progress`): None shows the bar only when
the study is large by the caller's own measure, True or False force it.
The bar is ``tqdm.auto``'s (a widget in a notebook, a line on stderr in a
terminal); with False nothing is written anywhere.

The thresholds of "large" lie above every call the book makes: a bar is
output, and nbval would read it as a changed cell.
"""

from __future__ import annotations

from contextlib import contextmanager

from .chunk_map import show_progress

__all__ = ["Progress", "progress_bar", "show_progress", "PROGRESS_WORK"]

PROGRESS_WORK = 4e6
"""Points x (2m + 1)^2 from which a branch shows its progress by default.

`railtrack.continuation` (counted with its `max_points`) and
`railtrack.check_branch` (its points): 400 points at m = 50 and more.
Chapter 10's branch, 173 points at m = 25 (4.5e5; 9 s for `check_branch`),
and the book's largest, 400 points at m = 30 (1.5e6), stay below it.
"""


class Progress:
    """A ``tqdm`` bar moved to a count, or a stand-in that does nothing (`bar` None)."""

    def __init__(self, bar=None):
        self.bar = bar

    def to(self, count: int, note: str | None = None) -> None:
        """Show `count` done (points, periods, speeds), and `note` beside the bar."""
        if self.bar is None:
            return
        if note is not None:
            self.bar.set_postfix_str(note, refresh=False)
        self.bar.update(int(count) - self.bar.n)


@contextmanager
def progress_bar(shown: bool, total: int | None, description: str, unit: str):
    """A `Progress` for a ``with`` block: a bar of `total` `unit` if `shown`, closed at the end.

    ``total=None`` counts without a bar's end (a branch's points are not known
    before it is traced).

    >>> with progress_bar(False, 10, "quiet", "points") as progress:
    ...     progress.to(3)
    >>> progress.bar is None
    True
    """
    if not shown:
        yield Progress()
        return
    from tqdm.auto import tqdm

    bar = tqdm(total=total, desc=description, unit=f" {unit}")
    try:
        yield Progress(bar)
    finally:
        bar.close()
