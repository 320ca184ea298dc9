"""Printed pages of each chapter of the book's PDF, and its near-empty pages.

    python tools/chapter_pages.py PDF [--limit 25] [--sparse-lines 12]

`make pdf` runs this on the book it has printed and fails if a chapter is
longer than ``--limit`` pages (issue 30: a chapter a lecturer can teach is
at most 25 printed pages).  A chapter starts on the page whose text begins
with its numbered heading ("10. The train speeds up"; every document starts
a page, see the print rules of book/_static/custom.css) and ends on the
page before the next chapter, the solutions appendix or the back matter
(the glossary, the API reference, the bibliography), which are no
chapter's pages.

A page whose text is a few lines only, with no figure on it, is listed as
near-empty: the last page of a document may be short, but one in the
middle of a document is a page break that left most of a page white
(a box or figure kept whole that did not fit under the text before it).

The text is read with pypdf (pinned in environment.txt).
"""

from __future__ import annotations

import argparse
import re
import sys
from dataclasses import dataclass
from pathlib import Path

LIMIT = 25  # printed pages per chapter (issue 30)
SPARSE_LINES = 12  # a page with at most this many lines of text is near-empty
# The headings that end the last chapter: what follows the chapters.
BACK_MATTER = ("Solutions to the exercises", "Glossary", "API reference", "Bibliography")
# "10. The train speeds up"; a section ("10.1. Overview") has a second number.
_HEADING = re.compile(r"^(\d{1,2})\.\s+(\S.*)$")


@dataclass(frozen=True)
class Chapter:
    """A chapter of the printed book: its number, heading and pages (1-based)."""

    number: int
    title: str
    first: int
    last: int

    @property
    def pages(self) -> int:
        return self.last - self.first + 1


def _lines(text: str) -> list[str]:
    return [" ".join(line.split()) for line in text.splitlines() if line.strip()]


def body_lines(text: str, footer: str | None = None) -> list[str]:
    """The page's lines of text without its running footer (title, page numbers)."""
    lines = _lines(text)
    if footer is not None and lines and lines[-1].startswith(footer):
        lines = lines[:-1]
    return lines


def running_footer(texts: list[str]) -> str | None:
    """The start of the footer line that every page ends with, if any.

    Chromium prints the page's title and "n / N" at every page's foot; pypdf
    reads it as the page's last line.  Its common start (the title) is
    returned, or None if the pages share no last line."""
    last = [_lines(t)[-1] for t in texts if _lines(t)]
    if len(last) < 2:
        return None
    common = last[0]
    for line in last[1:]:
        n = 0
        while n < min(len(common), len(line)) and common[n] == line[n]:
            n += 1
        common = common[:n]
    common = common.rstrip(" 0123456789/·")
    return common or None


def chapters(texts: list[str], back_matter=BACK_MATTER) -> list[Chapter]:
    """The chapters found in the pages' texts (one string per page).

    Chapters are numbered 1, 2, 3, ... in the book's order, so a page is a
    chapter's first only if its first line is the heading of the chapter
    after the last one found: a numbered list item at a page's top in the
    front matter ("2. The rail and the load" in the project page) or the
    table of contents ("11. Verification") is not taken for one.  The last
    chapter ends before the first page headed by one of `back_matter`.
    """
    starts: list[tuple[int, str, int]] = []
    end = None
    for index, text in enumerate(texts):
        lines = _lines(text)
        if not lines:
            continue
        if starts and lines[0] in back_matter:
            end = index
            break
        match = _HEADING.match(lines[0])
        if match and int(match.group(1)) == (starts[-1][0] + 1 if starts else 1):
            starts.append((int(match.group(1)), match.group(2), index))
    if not starts:
        raise ValueError("no chapter heading ('1. ...') begins any page of the PDF")
    if end is None:
        raise ValueError(f"no page after chapter {starts[-1][0]} begins with one of "
                         f"{back_matter}: where the last chapter ends is unknown")
    found = []
    for k, (number, title, first) in enumerate(starts):
        after = starts[k + 1][2] if k + 1 < len(starts) else end
        found.append(Chapter(number, title, first + 1, after))
    return found


def sparse_pages(texts: list[str], has_figure: list[bool] | None = None,
                 max_lines: int = SPARSE_LINES) -> list[tuple[int, int]]:
    """(page, lines) of every page with at most `max_lines` lines of text
    and no figure (1-based page numbers; the running footer not counted)."""
    footer = running_footer(texts)
    has_figure = has_figure or [False] * len(texts)
    return [(i + 1, len(body_lines(t, footer)))
            for i, (t, figure) in enumerate(zip(texts, has_figure))
            if not figure and len(body_lines(t, footer)) <= max_lines]


def read_pdf(path: Path) -> tuple[list[str], list[bool]]:
    """Each page's text, and whether it draws an image (a figure)."""
    from pypdf import PdfReader

    reader = PdfReader(path)
    texts, figures = [], []
    for page in reader.pages:
        texts.append(page.extract_text() or "")
        xobjects = page.get("/Resources", {}).get("/XObject", {})
        figures.append(any(x.get_object().get("/Subtype") == "/Image"
                           for x in xobjects.values()))
    return texts, figures


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pdf", type=Path)
    parser.add_argument("--limit", type=int, default=LIMIT,
                        help=f"most printed pages a chapter may have (default {LIMIT})")
    parser.add_argument("--sparse-lines", type=int, default=SPARSE_LINES,
                        help="a page with at most this many lines of text (and no "
                             f"figure) is listed as near-empty (default {SPARSE_LINES})")
    args = parser.parse_args(argv)
    texts, figures = read_pdf(args.pdf)
    found = chapters(texts)
    print(f"{args.pdf}: {len(texts)} pages")
    print(" ch  pages  first-last  heading")
    for c in found:
        flag = "  OVER THE LIMIT" if c.pages > args.limit else ""
        print(f"{c.number:3d}  {c.pages:5d}  {c.first:4d}-{c.last:<4d}  "
              f"{c.title[:50]}{flag}")
    sparse = sparse_pages(texts, figures, args.sparse_lines)
    print("near-empty pages (page: lines of text): "
          + (", ".join(f"{p}: {n}" for p, n in sparse) or "none"))
    over = [c for c in found if c.pages > args.limit]
    if over:
        print(f"error: over {args.limit} printed pages: "
              + ", ".join(f"chapter {c.number} ({c.pages})" for c in over), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
