"""A chapter's own equations are numbered with its chapter number.

book/_ext/paper_equations.py shows an equation labelled ``chC-eq-N`` as
(C.N).  When chapters were renumbered (issue 30), the labels of chapters 13
and 14 kept their old chapter numbers, so chapter 14 showed its contact law
as eq. (13.1) while its code printed "eq. (14.6)".  Truth used: the chapter
number in each notebook's file name.
"""

import re
from pathlib import Path

import pytest

BOOK = Path(__file__).resolve().parents[1] / "book"
DEFINED = re.compile(r"\$\$\s*\((ch(\d+)-eq-\d+)\)")
CHAPTERS = sorted(BOOK.glob("[0-9][0-9]_*.ipynb"))


def defined_labels(text):
    """(label, chapter number) of each equation a page labels itself."""
    return [(m.group(1), int(m.group(2))) for m in DEFINED.finditer(text)]


@pytest.mark.parametrize("path", CHAPTERS, ids=[p.stem for p in CHAPTERS])
def test_a_chapters_equations_carry_its_number(path):
    chapter = int(path.name[:2])
    text = path.read_text(encoding="utf-8").replace('\\n",\n    "', "\n")
    wrong = [label for label, number in defined_labels(text) if number != chapter]
    assert not wrong, f"{path.name} labels its equations {wrong}"


def test_the_rule_reads_a_label_after_the_closing_dollars():
    assert defined_labels("$$\nQ_c = C_H\\delta^{3/2}\n$$ (ch13-eq-1)") == [("ch13-eq-1", 13)]


def test_every_chapter_label_cited_is_defined_somewhere():
    pages = list(BOOK.glob("*.ipynb")) + list(BOOK.glob("*.md"))
    texts = {p: p.read_text(encoding="utf-8").replace('\\n",\n    "', "\n") for p in pages}
    defined = {label for t in texts.values() for label, _ in defined_labels(t)}
    cited = {m.group(0) for t in texts.values() for m in re.finditer(r"ch\d+-eq-\d+", t)}
    assert cited <= defined, sorted(cited - defined)
