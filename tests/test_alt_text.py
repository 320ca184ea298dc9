"""Every figure of the book says in words what it shows (alt text).

myst-nb writes a figure's image under a hash of its bytes, so without
``mystnb.image.alt`` in the cell's metadata a screen reader announces that
hash.  The alt text must describe the figure, not repeat its caption or
name a file.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb"))


def figure_cells(notebook: dict) -> list[dict]:
    """Code cells that display an image."""
    return [cell for cell in notebook["cells"] if cell["cell_type"] == "code"
            and any("image/png" in o.get("data", {}) for o in cell.get("outputs", []))]


def missing_alt(notebook: dict) -> list[str]:
    """Why each figure of the notebook fails, as messages (empty: none fails)."""
    problems = []
    for cell in figure_cells(notebook):
        meta = cell["metadata"].get("mystnb", {})
        alt = str(meta.get("image", {}).get("alt", "")).strip()
        caption = str(meta.get("figure", {}).get("caption", "")).strip()
        head = "".join(cell["source"])[:60].replace("\n", " ")
        if len(alt) < 40:
            problems.append(f"no alt text (or under 40 characters): {head!r}")
        elif re.fullmatch(r"[0-9a-f]{16,}(\.png)?|\S+\.(png|jpe?g|svg)", alt):
            problems.append(f"alt text is a file name: {head!r}")
        elif caption and alt == caption:
            problems.append(f"alt text repeats the caption: {head!r}")
    return problems


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_figure_has_alt_text(path):
    assert missing_alt(json.loads(path.read_text())) == []


def test_the_check_finds_a_figure_without_alt_text():
    cell = {"cell_type": "code", "source": ["plot()"],
            "metadata": {"mystnb": {"figure": {"caption": "A curve.", "name": "fig-x"}}},
            "outputs": [{"output_type": "display_data", "data": {"image/png": "iVBOR"}}]}
    assert missing_alt({"cells": [cell]})
    cell["metadata"]["mystnb"]["image"] = {"alt": "a1b2c3d4e5f6a7b8c9d0.png"}
    assert missing_alt({"cells": [cell]})
    cell["metadata"]["mystnb"]["image"] = {"alt": "A rising curve of the dip against speed, peaking near 365 m/s."}
    assert missing_alt({"cells": [cell]}) == []
