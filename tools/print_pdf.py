"""Print a single-page build of the book to PDF with headless Chromium.

    python tools/print_pdf.py SINGLEHTML_DIR OUT.pdf

`make pdf` builds the book with Sphinx's ``singlehtml`` builder (every chapter
on one page) and prints that page here.  The route was chosen over LaTeX:
Chromium is already the browser test's (Debian's ``chromium`` and
``chromium-driver``), whereas a LaTeX route needs a TeX installation of
several hundred megabytes and renders the book's MathJax, HTML tables and
admonitions through a second, different toolchain.  Printing the page the
reader sees keeps equations, figures, tables and exercise numbers exactly as
in the HTML book; the page's own print style (book/_static/custom.css)
removes the navigation and wraps code instead of cutting it.

The page is served from 127.0.0.1 and Chromium resolves no other host, as in
the browser test, whose set-up (tests/rendered/browser.py) is reused.
"""

from __future__ import annotations

import base64
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

sys.path.insert(0, str(Path(__file__).resolve().parent))  # also when imported by a test
import browser  # noqa: E402  (the local server and headless Chromium, shared with the browser test)

LOAD_TIMEOUT = 300  # s
PRINT_TIMEOUT = 900  # s, for the one printToPDF request
A4 = {"paperWidth": 8.27, "paperHeight": 11.69}  # inches
MARGIN = 0.55  # inches, each side
FOOTER = (
    '<div style="font-size:8px;width:100%;text-align:center;color:#555">'
    '<span class="title"></span> &middot; <span class="pageNumber"></span>'
    ' / <span class="totalPages"></span></div>'
)

# Folded code stays folded on paper: its "Show code" line is dropped (print
# CSS); the outputs are printed.  Figures are waited for, since a lazily
# loaded image would print as an empty box.
_PREPARE_JS = """
document.querySelectorAll('img[loading="lazy"]').forEach(i => i.loading = "eager");
return Array.from(document.images).filter(i => !i.complete).length;
"""


def print_pdf(html_dir: Path, out: Path) -> int:
    """Print ``html_dir``'s single page to ``out``; return the number of pages."""
    from selenium.webdriver.support.ui import WebDriverWait

    chromium, chromedriver = browser.find_browser()
    if not (chromium and chromedriver):
        raise SystemExit("make pdf needs chromium and chromedriver "
                         "(Debian packages chromium and chromium-driver)")
    # The book's root document is book/index, so singlehtml writes the page
    # to book/index.html but links it as if it sat at the top (_static/...,
    # _images/...): it is printed from a copy at the top.
    page = "index.html"
    nested = html_dir / "book" / "index.html"
    if nested.exists():
        page = "book.html"
        (html_dir / page).write_bytes(nested.read_bytes())
    with browser.serve_directory(html_dir) as base, \
            browser.headless_chromium(chromium, chromedriver) as driver:
        # One page holds the whole book: MathJax needs longer than on a chapter.
        driver.set_page_load_timeout(LOAD_TIMEOUT)
        driver.set_script_timeout(LOAD_TIMEOUT)
        # Printing the whole book is one request to chromedriver; selenium's
        # default of 120 s was too short on a busy two-core machine (measured:
        # the print timed out while other notebooks ran).
        driver.command_executor.client_config.timeout = PRINT_TIMEOUT
        state = browser.load_page(driver, base + page)
        if state["mathjax"] != "ok":
            raise SystemExit(f"MathJax did not typeset the page: {state['mathjax']}")
        WebDriverWait(driver, LOAD_TIMEOUT, poll_frequency=0.2).until(
            lambda d: d.execute_script(_PREPARE_JS) == 0)
        pdf = driver.execute_cdp_cmd("Page.printToPDF", {
            **A4,
            "marginTop": MARGIN, "marginBottom": MARGIN,
            "marginLeft": MARGIN, "marginRight": MARGIN,
            "printBackground": True,
            "displayHeaderFooter": True,
            "headerTemplate": "<div></div>",
            "footerTemplate": FOOTER,
        })
    data = base64.b64decode(pdf["data"])
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_bytes(data)
    return data.count(b"/Type /Page") - data.count(b"/Type /Pages")


def main(argv: list[str]) -> int:
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    pages = print_pdf(Path(argv[1]), Path(argv[2]))
    print(f"{argv[2]}: {pages} pages")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
