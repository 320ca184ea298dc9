"""The rendered book, page by page, in headless Chromium.

    .venv/bin/python -m pytest tests/rendered --book-html _build/html

Every page that _toc.yml names (plus the root index.html, genindex.html and
search.html) is opened from a local server and fails on
  (a) raw TeX left in its text, or a formula MathJax could not typeset,
  (b) a missing or broken image,
  (c) a SEVERE entry in the browser console,
  (d) any request that leaves the local server,
  (e) a dead internal link or #anchor (or a link to a page not in _toc.yml).
A full-page screenshot of every page is kept under _build/screenshots/.
"""

from pathlib import PurePosixPath

import checks
import pytest


def test_page(page, book_html, book_server, browser, book_pages, screenshot_dir):
    target = book_html / page
    if not target.is_file():
        pytest.fail(f"{page}: named by _toc.yml but not in the build ({book_html})", pytrace=False)
    shot = screenshot_dir / PurePosixPath(page).with_suffix(".png")
    results = checks.inspect_page(
        browser,
        book_server + page,
        base_url=book_server,
        root=book_html,
        known_pages=book_pages,
        screenshot=shot,
    )
    if any(results.values()):
        pytest.fail(checks.format_problems(page, results) + f"\n  (screenshot: {shot})", pytrace=False)
