"""The printed book (make pdf): what its print style rests on.

Truths used: the page that tools/print_pdf.py prints (A4, its margins, at
CSS's 96 px per inch), the notebooks' 76-column code limit (pyproject.toml),
the advance of DejaVu Sans Mono, the monospace font Chromium uses on Debian
(1233 of 2048 units per em; Source Code Pro and Menlo are no wider), the
theme's code-box frame (measured in Chromium: a code cell has a 3 px and a
1 px border, a code or output box 16 px of padding either side), and the
print rules of book/_static/custom.css. Each check is also run on a case made
here that it must reject, so that it can fail.

The real check of the PDFs is a look at every page (make pdf); these tests
keep what that look found from coming back: code that wraps in the middle
of an expression, tables and code boxes that the theme keeps whole (which
left pages half empty, and empty box frames at a page's foot), and
figures drawn in the proportions of the screen's inline size.
"""

import importlib.util
import json
import math
import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
CSS = BOOK / "_static" / "custom.css"

MONO_ADVANCE = 1233 / 2048     # em, DejaVu Sans Mono
CSS_PX_PER_INCH = 96
ROOT_FONT_PX = 16              # the theme's 1rem
CODE_FRAME_PX = 3 + 1 + 2 * 16     # code cell: borders, and the box's padding
OUTPUT_FRAME_PX = 2 * 16           # output box: padding only


def _print_pdf():
    spec = importlib.util.spec_from_file_location(
        "print_pdf", ROOT / "tools" / "print_pdf.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def print_block(css):
    """The body of the first ``@media print { ... }`` block of `css`."""
    start = css.index("@media print")
    opening = css.index("{", start)
    depth = 0
    for i in range(opening, len(css)):
        depth += {"{": 1, "}": -1}.get(css[i], 0)
        if depth == 0:
            return css[opening + 1:i]
    raise ValueError("unclosed @media print block")


def rules(block):
    """[(selectors, {property: value})] of a CSS block, comments removed."""
    block = re.sub(r"/\*.*?\*/", "", block, flags=re.S)
    found = []
    for selectors, body in re.findall(r"([^{}]+)\{([^{}]*)\}", block):
        props = {}
        for declaration in body.split(";"):
            if ":" in declaration:
                name, value = declaration.split(":", 1)
                props[name.strip()] = value.replace("!important", "").strip()
        found.append(([s.strip() for s in selectors.split(",")], props))
    return found


def declared(block, selector, prop):
    """The last value `block` gives `prop` for exactly `selector`, or None."""
    value = None
    for selectors, props in rules(block):
        if selector in selectors and prop in props:
            value = props[prop]
    return value


def column_px(print_pdf):
    """Width of the printed text column, CSS px."""
    return (print_pdf.A4["paperWidth"] - 2 * print_pdf.MARGIN) * CSS_PX_PER_INCH


def code_font_px(block):
    size = declared(block, "div.highlight pre", "font-size")
    assert size and size.endswith("rem"), f"print code font-size: {size}"
    return float(size[:-3]) * ROOT_FONT_PX


def columns(width_px, font_px):
    """Monospace characters that fit in `width_px` at `font_px`."""
    return math.floor(width_px / (MONO_ADVANCE * font_px) + 1e-9)


def printed_output_lines(notebook):
    """(cell index, line) of every output line that the page shows as text.

    A cell tagged remove-cell or remove-output prints no output; an
    execute_result or display_data prints its text/plain only when it has no
    richer form (an image, HTML, Markdown, LaTeX, a widget)."""
    richer = ("image/png", "image/svg+xml", "text/html", "text/markdown",
              "text/latex", "application/vnd.jupyter.widget-view+json",
              "application/javascript")
    for index, cell in enumerate(notebook["cells"]):
        tags = cell.get("metadata", {}).get("tags", [])
        if cell["cell_type"] != "code" or {"remove-cell", "remove-output"} & set(tags):
            continue
        for output in cell.get("outputs", []):
            if output["output_type"] == "stream":
                text = "".join(output["text"])
            elif output["output_type"] == "error":
                text = "\n".join(output["traceback"])
            else:
                data = output.get("data", {})
                if any(kind in data for kind in richer):
                    continue
                text = "".join(data.get("text/plain", ""))
            for line in text.splitlines():
                yield index, line


def too_long(notebook, limit):
    return [(i, len(line), line) for i, line in printed_output_lines(notebook)
            if len(line) > limit]


# ------------------------------------------------------------------ code ---


def test_code_lines_fit_the_printed_column_without_wrapping():
    limit = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["ruff"]["line-length"]
    block = print_block(CSS.read_text())
    fit = columns(column_px(_print_pdf()) - CODE_FRAME_PX, code_font_px(block))
    assert fit >= limit, (
        f"a printed code box holds {fit} columns, the notebooks' code has up to {limit}")
    # The screen's 14 px would not fit on A4 with the theme's 64 px of side
    # margins (the print style removes them): the arithmetic can fail.
    assert columns(column_px(_print_pdf()) - 64 - CODE_FRAME_PX, 14) < limit


def test_printed_output_lines_fit_the_printed_column():
    block = print_block(CSS.read_text())
    limit = columns(column_px(_print_pdf()) - OUTPUT_FRAME_PX, code_font_px(block))
    problems = []
    for path in sorted(BOOK.glob("*.ipynb")):
        notebook = json.loads(path.read_text())
        problems += [f"{path.name} cell {i}: {n} characters: {line[:60]}..."
                     for i, n, line in too_long(notebook, limit)]
    assert not problems, (
        f"output lines longer than the {limit} characters a printed output box "
        "holds (they wrap in the PDF):\n" + "\n".join(problems))


def test_output_check_rejects_a_long_printed_line_only():
    long_line = "x" * 90
    made_up = {"cells": [
        {"cell_type": "code", "metadata": {}, "source": "",
         "outputs": [{"output_type": "stream", "name": "stdout", "text": [long_line]}]},
        {"cell_type": "code", "metadata": {"tags": ["remove-output"]}, "source": "",
         "outputs": [{"output_type": "stream", "name": "stdout", "text": [long_line]}]},
        {"cell_type": "code", "metadata": {}, "source": "",
         "outputs": [{"output_type": "execute_result", "execution_count": 1, "metadata": {},
                      "data": {"text/plain": long_line, "text/latex": "$x$"}}]},
    ]}
    assert [i for i, _, _ in too_long(made_up, 83)] == [0]


# ------------------------------------------------------ pages and boxes ---


def test_print_style_undoes_the_themes_unbreakable_boxes():
    block = print_block(CSS.read_text())
    # sphinx-book-theme keeps every table whole, pydata-sphinx-theme every
    # code block: before a long one the page was left half empty, and a code
    # cell's frame was left empty at a page's foot.
    assert declared(block, ".bd-main .bd-content table", "break-inside") == "auto"
    assert declared(block, ".bd-main .bd-content tr", "break-inside") == "avoid"
    for selector in ("div.cell_input", "div.highlight", 'div[class*="highlight-"]'):
        assert declared(block, selector, "break-inside") == "auto", selector
        assert declared(block, selector, "display") == "block", selector
    # A code box splits only between lines, a few on either side.
    assert int(declared(block, "div.highlight pre", "orphans")) >= 2
    assert int(declared(block, "div.highlight pre", "widows")) >= 2
    assert declared(block, "div.highlight > pre", "break-before") == "avoid"
    # Headings stay with what follows them.  Chapters start a page, the
    # break before the empty anchor that singlehtml puts before each
    # chapter (a break after it, before the chapter, printed blank pages).
    assert declared(block, "h2", "break-after") == "avoid"
    assert declared(block, 'span[id^="document-"]', "break-before") == "page"
    assert declared(block, 'span[id^="document-"]', "display") == "block"
    assert declared(block, 'span[id^="document-"] + section', "break-before") is None


def test_printed_figures_keep_their_proportions_and_the_column_width():
    block = print_block(CSS.read_text())
    for selector in ("div.cell_output img", "figure img"):
        assert declared(block, selector, "height") == "auto", selector
        assert declared(block, selector, "width") == "100%", selector
        assert declared(block, selector, "object-fit") == "contain", selector


def test_css_reader_rejects_a_style_without_the_rules():
    made_up = """
    @media print {
      /* div.highlight { break-inside: auto; } is only a comment here */
      .bd-main .bd-content table { break-inside: avoid; }
      div.cell_output img { max-width: 100%; }
    }
    div.highlight { break-inside: auto; display: block; }
    """
    block = print_block(made_up)
    assert declared(block, ".bd-main .bd-content table", "break-inside") == "avoid"
    assert declared(block, "div.highlight", "break-inside") is None
    assert declared(block, "div.cell_output img", "height") is None


# ----------------------------------------- near-empty pages, split boxes ---

MM_PER_INCH = 25.4
CAPTION_MM = 3 * 1.5 * ROOT_FONT_PX / CSS_PX_PER_INCH * MM_PER_INCH  # 3 lines


def column_height_mm(print_pdf):
    """Height of the printed text column (A4 less the margins), mm."""
    return (print_pdf.A4["paperHeight"] - 2 * print_pdf.MARGIN) * MM_PER_INCH


def figure_fits_under_text(block, text_share=0.4):
    """Whether the tallest printed figure, with a three-line caption, fits on
    the page under `text_share` of a page of text (a heading, a paragraph and
    a short code cell).  A figure is kept whole (break-inside: avoid): one
    that did not fit went to the next page and left the rest of this one
    empty (the explorer's snapshot, Fig. 5.2, Sec. 7.4's figure, the loss of
    contact in the wheel chapter; at 200 mm, three pages of the PDF)."""
    height = declared(block, "div.cell_output img", "max-height")
    assert height and height.endswith("mm"), f"print figure max-height: {height}"
    room = (1 - text_share) * column_height_mm(_print_pdf())
    return float(height[:-2]) + CAPTION_MM <= room


def short_outputs_move_whole(block):
    """Whether a printed output box is kept whole rather than split.

    Chromium split a five-line box four lines on one page, one on the next,
    although widows and orphans (4) forbid it; break-inside: avoid on the
    box's text keeps it whole, and it needs a break allowed before the box:
    no break-before: avoid at the output (which kept it with its code), nor
    at its inner blocks, whose avoid passes up to the box's start (the
    code boxes' rule, div.highlight > pre, is undone for outputs)."""
    inner = ("div.cell_output div.output > div.highlight", "div.cell_output div.highlight > pre")
    return (declared(block, "div.output pre", "break-inside") == "avoid"
            and declared(block, "div.cell_output > div.output", "break-before") != "avoid"
            and all(declared(block, s, "break-before") == "auto" for s in inner))


def test_a_tall_figure_fits_under_some_text():
    assert figure_fits_under_text(print_block(CSS.read_text()))
    # The rule it replaced (200 mm) fails the check.
    assert not figure_fits_under_text(print_block(
        "@media print { div.cell_output img { max-height: 200mm; } }"))


def test_a_short_output_box_is_not_split_across_pages():
    assert short_outputs_move_whole(print_block(CSS.read_text()))
    old = """@media print {
      div.output pre { orphans: 4; widows: 4; }
      div.cell_input > div, div.cell_output > div.output { break-before: avoid; }
    }"""
    assert not short_outputs_move_whole(print_block(old))
    assert not short_outputs_move_whole(print_block(
        "@media print { div.output pre { break-inside: avoid; }"
        " div.cell_output > div.output { break-before: avoid; } }"))
    # Kept whole but with no break allowed before it (this commit's first
    # try): a folded cell's box pulled the figure above it to the next page.
    assert not short_outputs_move_whole(print_block(
        "@media print { div.output pre { break-inside: avoid; }"
        " div.highlight > pre { break-before: avoid; } }"))


MAX_OUTPUT_LINES = 20  # about a third of a printed page at 13 px


def long_outputs(notebook, limit=MAX_OUTPUT_LINES):
    """(cell, lines) of every printed text output longer than `limit` lines."""
    counts = {}
    for index, _ in printed_output_lines(notebook):
        counts[index] = counts.get(index, 0) + 1
    return [(i, n) for i, n in counts.items() if n > limit]


def test_output_boxes_kept_whole_are_short():
    # An output box is kept whole on paper (print rules): a long one moved
    # to the next page would leave most of a page empty before it.
    problems = []
    for path in sorted(BOOK.glob("*.ipynb")):
        problems += [f"{path.name} cell {i}: {n} lines"
                     for i, n in long_outputs(json.loads(path.read_text()))]
    assert not problems, (f"printed outputs over {MAX_OUTPUT_LINES} lines:\n"
                          + "\n".join(problems))
    made_up = {"cells": [
        {"cell_type": "code", "metadata": {}, "source": "", "outputs": [
            {"output_type": "stream", "name": "stdout", "text": ["x\n"] * 21}]},
        {"cell_type": "code", "metadata": {}, "source": "", "outputs": [
            {"output_type": "stream", "name": "stdout", "text": ["x\n"] * 20}]},
    ]}
    assert long_outputs(made_up) == [(0, 21)]


def test_folded_code_does_not_print():
    # A cell tagged hide-input is rendered as a closed <details class="hide">
    # holding the code; on paper it is dropped whole (its outputs print).
    block = print_block(CSS.read_text())
    assert declared(block, "details.hide:not([open])", "display") == "none"
    assert declared(print_block(
        "@media print { details.hide { display: block; } }"),
        "details.hide:not([open])", "display") is None


# ------------------------------------------------- folded table-building ---

HIDDEN = {"hide-input", "remove-input", "remove-cell", "hide-cell"}
LONG_CELL = 15  # lines: issue 30's "longer than about 15 lines"
_TABLE_ROW = re.compile(r"""^\s*(f?["']\|)""", re.M)  # a Markdown table row


def unfolded_table_cells(notebook):
    """Indices of visible code cells over LONG_CELL lines that build a
    Markdown table row by row: their printed code is scaffolding (column
    headers, f-string formats), not the computation, and fills pages."""
    found = []
    for index, cell in enumerate(notebook["cells"]):
        source = "".join(cell["source"])
        tags = set(cell.get("metadata", {}).get("tags", []))
        if (cell["cell_type"] == "code" and not tags & HIDDEN
                and len(source.splitlines()) > LONG_CELL and _TABLE_ROW.search(source)):
            found.append(index)
    return found


def test_long_table_building_cells_of_chapters_1_to_9_are_folded():
    problems = []
    for path in sorted(BOOK.glob("0*.ipynb")):
        cells = unfolded_table_cells(json.loads(path.read_text()))
        problems += [f"{path.name} cell {i}" for i in cells]
    assert not problems, ("long table-building code printed (tag the cell "
                          "hide-input):\n" + "\n".join(problems))
    rows = ["rows = [\n", '    "| a | b |",\n', "]\n"] + [f"x{i} = {i}\n" for i in range(13)]
    made_up = {"cells": [
        {"cell_type": "code", "metadata": {}, "source": rows},
        {"cell_type": "code", "metadata": {"tags": ["hide-input"]}, "source": rows},
        {"cell_type": "code", "metadata": {}, "source": rows[:10]},
        {"cell_type": "code", "metadata": {}, "source": ["rows = []\n"] + rows[2:] + ["y = 1"]},
    ]}
    assert unfolded_table_cells(made_up) == [0]
