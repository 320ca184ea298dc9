"""tools/chapter_pages.py: the printed pages of each chapter (issue 30's page
budget, at most 25 a chapter) and the near-empty pages of the PDF.

The tool's logic works on the pages' texts; these tests give it the texts of
a made-up book whose chapters' pages are known by construction (the front
matter with a numbered list and a table of contents, chapters, the
solutions appendix and the back matter), so no PDF is printed here.
"""

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
FOOTER = "Railway track on a nonlinear foundation · "


def _tool():
    spec = importlib.util.spec_from_file_location(
        "chapter_pages", ROOT / "tools" / "chapter_pages.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclass looks itself up there
    spec.loader.exec_module(module)
    return module


def _book(lengths, body_lines=30):
    """Page texts of a book whose chapter k has lengths[k-1] pages, with
    the Chromium footer on every page; the expected (number, first, last)."""
    pages, expected = [], []

    def page(first_line, lines=body_lines):
        text = [first_line] + [f"prose line {i}" for i in range(lines - 1)]
        pages.append("\n".join(text + [f"{FOOTER}{len(pages) + 1} / N"]))

    page("Railway track on a nonlinear foundation")
    page("11. Verification: an independent time-domain model")  # contents
    page("Project: your own track and train")
    page("2. The rail and the load (a numbered list at a page's top)")
    for number, length in enumerate(lengths, start=1):
        expected.append((number, len(pages) + 1, len(pages) + length))
        page(f"{number}. Chapter {number}")
        for _ in range(length - 1):
            page(f"{number}.3. A section, or prose")
    page("Solutions to the exercises")
    page("1. The answer to Exercise 1.1 at the top of a page")
    page("Glossary")
    page("Bibliography")
    return pages, expected


def test_chapters_are_counted_from_their_heading_to_the_back_matter():
    tool = _tool()
    lengths = [13, 18, 10, 38, 2, 1]
    pages, expected = _book(lengths)
    found = tool.chapters(pages)
    assert [(c.number, c.first, c.last) for c in found] == expected
    assert [c.pages for c in found] == lengths


def test_a_list_item_or_the_contents_is_no_chapter_start():
    tool = _tool()
    pages, _ = _book([3, 4])
    # The contents page ("11. ...") and the project's numbered list ("2.
    # ...") come before chapter 1: taken for chapters they would start the
    # count there and give chapter 2 the whole front matter.
    found = tool.chapters(pages)
    assert found[0].first == 5 and found[1].first == 8
    # A page of chapter 1 that begins with "2. " (a list item) is not
    # chapter 2's start only if chapter 2 really follows; the count
    # follows the book's numbering 1, 2, 3, ...
    assert [c.number for c in found] == [1, 2]


def test_the_budget_fails_the_run_over_the_limit_only(tmp_path, monkeypatch, capsys):
    tool = _tool()
    for lengths, limit, code in (([25, 3], 25, 0), ([26, 3], 25, 1), ([26, 3], 26, 0)):
        pages, _ = _book(lengths)
        monkeypatch.setattr(tool, "read_pdf", lambda path, p=pages: (p, [False] * len(p)))
        assert tool.main([str(tmp_path / "book.pdf"), "--limit", str(limit)]) == code
    assert "chapter 1 (26)" in capsys.readouterr().err


def test_without_back_matter_the_last_chapter_is_an_error():
    tool = _tool()
    pages, _ = _book([3, 4])
    with pytest.raises(ValueError, match="last chapter"):
        tool.chapters(pages[:-4])


def test_near_empty_pages_are_the_short_ones_without_a_figure():
    tool = _tool()
    pages, _ = _book([3, 4])
    pages[6] = f"1.2. A heading\nOne line of text.\n{FOOTER}7 / N"
    pages[9] = f"Fig. 2.1 A caption\n{FOOTER}10 / N"
    figures = [False] * len(pages)
    figures[9] = True
    assert tool.running_footer(pages) == FOOTER.rstrip(" ·")
    # The footer is not a line of text: page 7 has two.
    assert tool.sparse_pages(pages, figures) == [(7, 2)]
    # A page with a figure and a caption only is not empty; without the
    # figure it would be.
    assert tool.sparse_pages(pages) == [(7, 2), (10, 1)]
    assert tool.sparse_pages(pages, figures, max_lines=1) == []
