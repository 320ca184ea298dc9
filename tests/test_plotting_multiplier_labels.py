"""Issue 30 (print): the labels of the changes of stability in the multiplier
figure (Fig. 11.1, Fig. 10.4 before the split) must not print over each other.

Truth: the rendered boxes of the labels themselves; the case is the fold
track's, two complex pairs coming in 24.6 m/s apart (513.3 and 537.9 m/s),
whose labels the old placement printed on the same line, on top of each other.
"""

import itertools
import types

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from railtrack.plotting.branch import plot_multipliers  # noqa: E402


def _branch():
    values = np.linspace(440.0, 700.0, 131)
    size = np.where((values > 513.3) & (values < 590.7), 0.8, 1.3)
    changes = [types.SimpleNamespace(value=v, kind=k, gains=g) for v, k, g in (
        (527.6, "fold", False), (470.0, "fold", True), (470.4, "complex", False),
        (537.9, "complex", True), (541.2, "fold", False), (513.3, "complex", True),
        (590.7, "complex", False))]
    return types.SimpleNamespace(values=values, multipliers=size.astype(complex),
                                 stable=size < 1, changes=changes)


def _label_boxes(fig):
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    return {t.get_text(): t.get_window_extent(renderer) for t in ax.texts}


@pytest.mark.parametrize("xlim", [None, (440.0, 700.0), (300.0, 700.0)])
def test_no_two_labels_of_the_changes_overlap(xlim):
    fig = plot_multipliers(_branch(), xlim=xlim) if xlim else plot_multipliers(_branch())
    boxes = _label_boxes(fig)
    assert len(boxes) == 4  # one per change away from a fold
    clashes = [(a, b) for (a, ba), (b, bb) in itertools.combinations(boxes.items(), 2)
               if ba.overlaps(bb)]
    assert not clashes, clashes
    if xlim:
        assert fig.axes[0].get_xlim() == pytest.approx(xlim)


def test_each_label_still_names_its_crossing_and_speed():
    boxes = _label_boxes(plot_multipliers(_branch()))
    assert set(boxes) == {f"complex pair, {v} m/s" for v in ("470.4", "537.9", "513.3", "590.7")}
