"""Claims the library has outgrown stay out of the book (issue 29, item 8).

Since chapters 12 and 13 the library carries self-weight (``gravity=9.81``
in a `SleeperCell`) and sleepers that differ, hanging ones included.  A
chapter that solves the paper's model may still say that model leaves
them out, but it must say whose model it means: a bare "the model has no
self-weight" reads as a limit of the library, which it no longer is.
"""

import json
import re
from pathlib import Path

import pytest

BOOK = Path(__file__).resolve().parents[1] / "book"
NOTEBOOKS = sorted(BOOK.glob("*.ipynb"))
OUTGROWN = re.compile(r"no self-weight|every sleeper (?:has|the) same support"
                      r"|there is no hanging sleeper", re.I)


def sentences(path):
    for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
        if cell["cell_type"] == "markdown":
            yield from re.split(r"(?<=[.:;])\s+", "".join(cell["source"]))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_a_limit_the_library_lifted_is_said_to_be_the_papers(path):
    bare = [s for s in sentences(path) if OUTGROWN.search(s) and "paper" not in s]
    assert bare == [], f"{path.name}: say it is the paper's model: {bare}"
