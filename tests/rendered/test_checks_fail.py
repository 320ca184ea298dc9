"""Each check of the rendered-book test can fail.

Tiny pages, each with exactly one kind of fault, are served from a temporary
directory and opened in the same headless Chromium as the book; the check
meant to catch the fault must report it, and a clean page must pass them all.
These run in a plain `pytest tests` too (no --book-html needed); they are
skipped only if the browser or selenium is missing.
"""

import json
from pathlib import Path

import checks
import pytest

REPO = Path(__file__).resolve().parents[2]

# A 1x1 transparent PNG.
PIXEL = (
    "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAQAAAC1HAwCAAAAC0lEQVR42mNkYAAAAAYAAjCB0C8AAAAASUVORK5CYII="
)

# <link rel="icon" href="data:,">: no favicon.ico request (and 404) per page.
TEMPLATE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{title}</title>
<link rel="icon" href="data:,">{head}</head>
<body>{body}</body></html>
"""

PAGES = {
    "clean.html": dict(
        body=(
            '<h1 id="top">Clean</h1>'
            "<p>Prices $5 and $10, a path C:/x and an image:</p>"
            f'<img src="{PIXEL}" alt="pixel">'
            '<p><a href="target.html#here">target</a> <a href="#top">top</a> '
            '<a href="target.html">target page</a> <a href="https://example.org/">off-site link</a></p>'
            "<pre>$$ \\frac{a}{b} \\begin{align} $$</pre>"
            "<p><code>\\(\\alpha\\)</code></p>"
            '<div class="highlight"><span>\\mathrm{d}x $$</span></div>'
        )
    ),
    "target.html": dict(body='<h1>Target</h1><p id="here">here</p><a name="named">named</a>'),
    "stale.html": dict(body="<p>left over from an older build</p>"),
    "raw_tex.html": dict(body=("<p>The equation $$x^2 + y^2$$ was not typeset.</p><pre>$$ \\frac{in}{code} $$</pre>")),
    "raw_tex_inline.html": dict(body="<p>Here \\(\\alpha_1\\) and $k_2 = \\mathrm{d}x$ stayed raw.</p>"),
    "missing_image.html": dict(body='<p>A figure:</p><img src="figures/nope.png" alt="missing">'),
    "dead_anchor.html": dict(
        body=(
            '<h2 id="ok">ok</h2>'
            '<p><a href="target.html#nowhere">a missing anchor</a> '
            '<a href="target.html#here">a good anchor</a> '
            '<a href="target.html#named">a good name</a> '
            '<a href="#ok">a good local anchor</a> '
            '<a href="#gone">a missing local anchor</a> '
            '<a href="missing.html">a missing page</a></p>'
        )
    ),
    "stale_link.html": dict(body='<p><a href="stale.html">a page not in the toc</a></p>'),
    "external.html": dict(
        head='<script src="https://example.invalid/x.js"></script>',
        body="<p>This page asks the internet for a script.</p>",
    ),
    "overflow.html": dict(
        head="<style>pre { width: 300px; overflow-x: auto; }</style>",
        body=("<pre>short line</pre>"
              "<pre>print(f'a line of code far wider than the 300 px box that holds it')</pre>"),
    ),
    "console_error.html": dict(body='<script>console.error("boom from the page");</script><p>hi</p>'),
}


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    root = tmp_path_factory.mktemp("tiny-site")
    for name, parts in PAGES.items():
        html = TEMPLATE.format(title=name, head=parts.get("head", ""), body=parts["body"])
        (root / name).write_text(html, encoding="utf-8")
    with checks.serve_directory(root) as base_url:
        yield root, base_url


def inspect(browser, site, page, known_pages=None):
    root, base_url = site
    return checks.inspect_page(browser, base_url + page, base_url, root, known_pages=known_pages)


def joined(problems):
    return "\n".join(problems)


def test_clean_page_passes_every_check(browser, site):
    results = inspect(browser, site, "clean.html", known_pages={"clean.html", "target.html"})
    assert not any(results.values()), checks.format_problems("clean.html", results)


def test_raw_display_math_is_reported(browser, site):
    results = inspect(browser, site, "raw_tex.html")
    text = joined(results["raw TeX"])
    assert "$$" in text and "x^2" in text, text
    assert "code" not in text, "text inside <pre> must not count as raw TeX:\n" + text


def test_raw_inline_math_is_reported(browser, site):
    text = joined(inspect(browser, site, "raw_tex_inline.html")["raw TeX"])
    assert "\\(" in text and "\\mathrm" in text and "k_2" in text, text


def test_missing_image_is_reported(browser, site):
    results = inspect(browser, site, "missing_image.html")
    assert "figures/nope.png" in joined(results["images"]), results
    # The 404 reaches the console too.
    assert "404" in joined(results["console"]), results


def test_dead_links_and_anchors_are_reported(browser, site):
    problems = inspect(browser, site, "dead_anchor.html")["links"]
    text = joined(problems)
    assert "'nowhere'" in text and "'gone'" in text and "missing.html" in text, text
    assert len(problems) == 3, text  # #here, #named and #ok exist


def test_link_to_page_outside_the_toc_is_reported(browser, site):
    problems = inspect(browser, site, "stale_link.html", known_pages={"stale_link.html"})["links"]
    assert len(problems) == 1 and "stale.html" in problems[0] and "_toc.yml" in problems[0], problems


def test_request_leaving_localhost_is_reported(browser, site):
    results = inspect(browser, site, "external.html")
    assert "https://example.invalid/x.js" in joined(results["requests"]), results


def test_code_wider_than_the_page_is_reported(browser, site):
    problems = inspect(browser, site, "overflow.html")["overflow"]
    assert len(problems) == 1 and "far wider" in problems[0], problems


def test_console_error_is_reported(browser, site):
    results = inspect(browser, site, "console_error.html")
    assert "boom from the page" in joined(results["console"]), results
    assert not results["requests"] and not results["links"] and not results["images"], results


def _mathjax_dir():
    for candidate in (REPO / "book" / "_static" / "mathjax", REPO / "_build" / "html" / "_static" / "mathjax"):
        if (candidate / "tex-mml-svg.js").is_file():
            return candidate
    return None


def test_formula_mathjax_rejects_is_reported(browser, tmp_path):
    """An undefined macro and a TeX syntax error, typeset by the book's MathJax."""
    mathjax = _mathjax_dir()
    if mathjax is None:
        pytest.skip("no local MathJax copy (book/_static/mathjax is made by `make venv`)")
    head = (
        '<script>window.MathJax = {"options": {"processHtmlClass": "math"}};</script>'
        '<script defer src="/mathjax/tex-mml-svg.js"></script>'
    )
    body = (
        '<p><span class="math">\\(\\undefinedmacro x\\)</span> and '
        '<span class="math">\\(x^1^2\\)</span> and the good '
        '<span class="math">\\(\\frac{1}{2}\\)</span></p>'
    )
    (tmp_path / "index.html").write_text(TEMPLATE.format(title="math", head=head, body=body))
    (tmp_path / "mathjax").symlink_to(mathjax, target_is_directory=True)
    with checks.serve_directory(tmp_path) as base_url:
        results = checks.inspect_page(browser, base_url + "index.html", base_url, tmp_path)
    text = joined(results["raw TeX"])
    assert "\\undefinedmacro" in text and "x^1^2" in text and "Double exponent" in text, text
    assert len(results["raw TeX"]) == 2, text  # the good formula passes
    assert not results["console"] and not results["requests"], results


# Pure checks on hand-made log entries (no browser needed).


def test_check_requests_on_a_log():
    def entry(method, **params):
        return {"message": json.dumps({"message": {"method": method, "params": params}})}

    base = "http://127.0.0.1:8123/"
    log = [
        entry("Network.requestWillBeSent", request={"url": "http://127.0.0.1:8123/a.css"}),
        entry("Network.requestWillBeSent", request={"url": "data:image/png;base64,xx"}),
        entry("Network.requestWillBeSent", request={"url": "about:blank"}),
        entry("Network.requestWillBeSent", request={"url": "http://127.0.0.1:9999/other-port.js"}),
        entry("Network.requestWillBeSent", request={"url": "http://localhost:8123/by-name.js"}),
        entry("Network.requestWillBeSent", request={"url": "https://cdn.example.org/m.js"}),
        entry("Network.webSocketCreated", url="wss://example.org/socket"),
        entry("Network.responseReceived", response={"url": "https://ignored.example.org/"}),
        # The browser's new-tab page fetching its own parts: not the book's.
        entry(
            "Network.requestWillBeSent",
            documentURL="chrome://new-tab-page/",
            request={"url": "chrome://resources/ntp.js"},
        ),
        # ... but a page of the book asking for a chrome:// URL is reported.
        entry(
            "Network.requestWillBeSent",
            documentURL=base + "page.html",
            request={"url": "chrome://resources/from-page.js"},
        ),
    ]
    problems = joined(checks.check_requests(log, base))
    for bad in ("other-port.js", "by-name.js", "cdn.example.org", "wss://example.org", "from-page.js"):
        assert bad in problems, problems
    for good in ("a.css", "data:", "about:blank", "ignored.example.org", "ntp.js"):
        assert good not in problems, problems


def test_check_console_on_a_log():
    log = [
        {"level": "INFO", "source": "console-api", "message": "fine"},
        {"level": "WARNING", "source": "console-api", "message": "a warning"},
        {"level": "SEVERE", "source": "javascript", "message": "Uncaught ReferenceError: x"},
    ]
    assert checks.check_console(log) == ["console javascript: Uncaught ReferenceError: x"]


@pytest.mark.parametrize(
    "text",
    ["so $$E = mc^2$$", "raw \\(x\\)", "raw \\[x\\]", "a \\frac{1}{2}", "\\begin{align}", "$a_1$", "\\mathrm{d}"],
)
def test_find_raw_tex_finds(text):
    assert checks.find_raw_tex(text), text


@pytest.mark.parametrize("text", ["$5 and $10", "costs $3", "a/b", "C:/temp", "50 % of it", "(x) [y] {z}"])
def test_find_raw_tex_leaves_prose_alone(text):
    assert not checks.find_raw_tex(text), text
