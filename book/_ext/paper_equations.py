"""Number the paper's equations as the paper does.

Sphinx numbers the labelled equations of each page 1, 2, 3...  A chapter that
reproduces equations (4)-(8) of the paper would then show them as (1)-(5),
and every {eq} reference would disagree with the paper the reader holds.
This extension gives each equation labelled ``paper-eq-N`` the number N, on
the page and in every reference to it, and an equation of the book's own
labelled ``chC-eq-N`` the number C.N (chapter C), so that the two never look
alike.  It needs ``math_numfig = False`` so
that Sphinx uses the equation's own number rather than a per-page count.
"""

from __future__ import annotations

import re

from docutils import nodes
from sphinx.application import Sphinx

PAPER_LABEL = re.compile(r"^paper-eq-(\d+)$")
CHAPTER_LABEL = re.compile(r"^ch(\d+)-eq-(\d+)$")


def _renumber(app: Sphinx, doctree: nodes.document) -> None:
    domain = app.env.get_domain("math")
    for node in doctree.findall(nodes.math_block):
        label = node.get("label") or ""
        paper, chapter = PAPER_LABEL.match(label), CHAPTER_LABEL.match(label)
        if paper or chapter:
            number = int(paper.group(1)) if paper else f"{chapter.group(1)}.{chapter.group(2)}"
            node["number"] = number
            domain.equations[label] = (app.env.docname, number)


def setup(app: Sphinx) -> dict:
    app.connect("doctree-read", _renumber)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
