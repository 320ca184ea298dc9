"""Checks on a page of the rendered book, shared by test_pages.py (the real
book) and test_checks_fail.py (tiny pages that prove each check can fail).

Every ``check_*`` function returns a list of human-readable problems; an empty
list means the page passed that check.  The browser side is Selenium 4 driving
headless Chromium through chromedriver (Debian packages ``chromium`` and
``chromium-driver``); nothing here ever downloads a driver or a browser.
"""

from __future__ import annotations

import functools
import html.parser
import json
import os
import re
import urllib.parse
from pathlib import Path
import sys

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools"))
# the server and browser set-up, shared with make pdf; conftest.py and
# test_checks_fail.py reach find_browser, headless_chromium and
# serve_directory through this module
from browser import (  # noqa: E402
    find_browser as find_browser,
    headless_chromium as headless_chromium,
    load_page,
    save_screenshot,
    serve_directory as serve_directory,
)

MAX_REPORTED = 8  # problems of one kind listed per page

# URL schemes a page may use without leaving the machine.
LOCAL_SCHEMES = ("data", "blob", "about")
# Documents of the browser itself, whose requests are not the book's.
BROWSER_UI_SCHEMES = ("chrome", "chrome-untrusted", "chrome-search", "devtools")


# ----------------------------------------------------------- (a) raw TeX ---

# Text of the body outside code (pre, code, .highlight), outside what MathJax
# produced, and outside script/style.  Hidden text is included on purpose:
# MathJax typesets collapsed (toggle, dropdown) content too, so TeX left in it
# is just as wrong once it is opened.
_TEXT_JS = """
const SKIP = 'pre, code, kbd, samp, .highlight, script, style, noscript, template, '
           + 'textarea, mjx-container, mjx-assistive-mml, svg, math';
const out = [];
const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
let node;
while ((node = walker.nextNode())) {
  const parent = node.parentElement;
  if (!parent || parent.closest(SKIP)) continue;
  out.push(node.nodeValue);
}
return out.join('');
"""

# Formulas MathJax could not typeset: an merror node (a TeX syntax error) or,
# with MathJax's noundefined extension, an undefined macro shown as red text.
# Walks MathJax's own list of typeset formulas; returns the TeX source of each.
_MATH_ERRORS_JS = """
const out = [];
const doc = window.MathJax && MathJax.startup && MathJax.startup.document;
if (!doc || !doc.math) return out;
for (const item of doc.math) {
  let why = null;
  try {
    item.root.walkTree((node) => {
      if (why) return;
      if (node.isKind('merror')) {
        why = node.attributes.get('data-mjx-error') || 'merror';
      } else if (node.isKind('mtext') && node.attributes.get('mathcolor') === 'red') {
        why = 'undefined control sequence';
      }
    });
  } catch (e) { why = null; }
  if (why) out.push(why + ': ' + String(item.math).slice(0, 120));
}
return out;
"""

RAW_TEX_PATTERNS = [
    ("display-math delimiter $$", re.compile(r"\$\$")),
    ("math delimiter \\( \\) \\[ \\]", re.compile(r"\\[()\[\]]")),
    ("environment \\begin{...} / \\end{...}", re.compile(r"\\(?:begin|end)\{")),
    ("TeX command", re.compile(r"\\[A-Za-z]{2,}")),
    # $...$ holding something that only makes sense as TeX (\ ^ _ {),
    # so that two prices in one sentence are not a false alarm.
    ("inline math $...$", re.compile(r"\$[^$\n]{0,200}?[\\^_{][^$\n]{0,200}?\$")),
]


def _excerpt(text, start, end, width=40):
    left = max(0, start - width)
    right = min(len(text), end + width)
    snippet = text[left:right].replace("\n", " ")
    return ("…" if left else "") + snippet + ("…" if right < len(text) else "")


def find_raw_tex(text):
    """Raw TeX in ``text`` (the page's prose): list of 'kind: …excerpt…'."""
    problems, seen = [], set()
    for kind, pattern in RAW_TEX_PATTERNS:
        for match in pattern.finditer(text):
            excerpt = _excerpt(text, match.start(), match.end())
            if excerpt in seen:
                continue
            seen.add(excerpt)
            problems.append(f"{kind} {match.group(0)!r} in: {excerpt!r}")
    return problems


def check_raw_tex(driver, mathjax_state="ok"):
    """(a) Raw TeX in the page's text, formulas MathJax rejected, MathJax not run."""
    problems = find_raw_tex(driver.execute_script(_TEXT_JS))
    problems += [f"MathJax error: {msg.strip()!r}" for msg in driver.execute_script(_MATH_ERRORS_JS)]
    if mathjax_state not in ("ok", "absent"):
        problems.append(f"MathJax {mathjax_state}")
    return problems


# ------------------------------------------------------------ (b) images ---

_BROKEN_IMAGES_JS = """
return Array.from(document.images)
  .filter(i => !i.complete || i.naturalWidth === 0)
  .map(i => ({src: i.currentSrc || i.getAttribute('src') || '', complete: i.complete,
              html: i.outerHTML.slice(0, 160)}));
"""


def check_images(driver):
    """(b) Every <img> has loaded and has a non-zero natural width."""
    problems = []
    for img in driver.execute_script(_BROKEN_IMAGES_JS):
        what = img["src"] or img["html"]
        if len(what) > 160:
            what = what[:160] + "…"
        state = "still loading" if not img["complete"] else "missing or broken"
        problems.append(f"image {state}: {what}")
    return problems


_OVERFLOWING_JS = """
const boxes = document.querySelectorAll(
  'pre, .pst-scrollable-table-container, mjx-container[display="true"]');
return Array.from(boxes)
  .filter(b => b.scrollWidth > b.clientWidth + 1)
  .map(b => ({tag: b.tagName.toLowerCase(), over: b.scrollWidth - b.clientWidth,
              text: (b.innerText || "").trim().split("\\n")
                      .reduce((a, l) => l.length > a.length ? l : a, "").slice(0, 100)}));
"""


def check_overflow(driver):
    """(f) No code, output, table or displayed equation wider than the page.

    Such a box scrolls sideways on screen and is cut on paper.  Reports each
    box with how many pixels it overflows and its longest line.
    """
    return [f"{box['tag']} {box['over']} px wider than the page: {box['text']!r}"
            for box in driver.execute_script(_OVERFLOWING_JS)]


# ----------------------------------------------------------- (c) console ---


def check_console(browser_log):
    """(c) Any SEVERE entry in the browser console log."""
    return [
        f"console {entry.get('source', '')}: {entry.get('message', '')}".strip()
        for entry in browser_log
        if entry.get("level") == "SEVERE"
    ]


# ---------------------------------------------------------- (d) requests ---


def requested_urls(performance_log):
    """URLs of every request (and websocket) in a Chrome performance log."""
    urls = []
    for entry in performance_log:
        try:
            message = json.loads(entry["message"])["message"]
        except (KeyError, TypeError, ValueError):
            continue
        method, params = message.get("method"), message.get("params", {})
        # Requests made by the browser's own pages (new-tab page and the
        # like), not by a page of the book.
        if urllib.parse.urlsplit(params.get("documentURL", "")).scheme in BROWSER_UI_SCHEMES:
            continue
        if method == "Network.requestWillBeSent":
            urls.append(params.get("request", {}).get("url", ""))
        elif method == "Network.webSocketCreated":
            urls.append(params.get("url", ""))
    return urls


def is_local_url(url, base_url):
    parts = urllib.parse.urlsplit(url)
    if parts.scheme in LOCAL_SCHEMES:
        return True
    base = urllib.parse.urlsplit(base_url)
    return parts.scheme in ("http", "https", "ws", "wss") and parts.netloc == base.netloc


def check_requests(performance_log, base_url):
    """(d) Every request stays on the local server (or is data:/blob:/about:)."""
    problems = []
    for url in dict.fromkeys(requested_urls(performance_log)):
        if not is_local_url(url, base_url):
            problems.append(f"request leaves {urllib.parse.urlsplit(base_url).netloc}: {url[:200]}")
    return problems


# ------------------------------------------------------------- (e) links ---


class _AnchorParser(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.anchors = set()

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if value and (name == "id" or (name == "name" and tag in ("a", "map", "iframe", "img", "form"))):
                self.anchors.add(value)

    handle_startendtag = handle_starttag


@functools.cache
def _anchors_cached(path, mtime_ns, size):
    parser = _AnchorParser()
    parser.feed(Path(path).read_text(encoding="utf-8", errors="replace"))
    parser.close()
    return frozenset(parser.anchors)


def anchors_in(path):
    """Element ids (and a/img/... names) in the HTML file ``path`` (cached)."""
    st = os.stat(path)
    return _anchors_cached(os.fspath(path), st.st_mtime_ns, st.st_size)


def url_to_file(url, base_url, root):
    """The file under ``root`` that a same-site ``url`` names, or None if off-site."""
    parts, base = urllib.parse.urlsplit(url), urllib.parse.urlsplit(base_url)
    if parts.scheme not in ("http", "https") or parts.netloc != base.netloc:
        return None
    rel = urllib.parse.unquote(parts.path).lstrip("/")
    target = Path(root) / rel
    if rel == "" or rel.endswith("/") or target.is_dir():
        target = target / "index.html"
    return target


_LINKS_JS = """
return {
  links: Array.from(document.querySelectorAll('a[href], area[href]'))
           .map(a => [a.getAttribute('href'), a.href]),
  ids: Array.from(document.querySelectorAll('[id]')).map(e => e.id)
         .concat(Array.from(document.querySelectorAll('a[name]')).map(e => e.name)),
  url: location.href,
};
"""


def check_links(driver, base_url, root, known_pages=None):
    """(e) Every same-site <a href> names an existing file under ``root`` and,
    if it has a #fragment, an element id (or name) in that file.

    ``known_pages`` (paths relative to ``root``, e.g. ``book/01_x.html``), if
    given, is the set of pages the book is made of: an internal link to any
    other .html page is reported too, so a stale page left over from an older
    build cannot hide a dead link.
    """
    info = driver.execute_script(_LINKS_JS)
    here = url_to_file(info["url"], base_url, root)
    live_ids = set(info["ids"])
    root = Path(root).resolve()
    problems, seen = [], set()
    for raw, absolute in info["links"]:
        if absolute in seen:
            continue
        seen.add(absolute)
        target = url_to_file(absolute, base_url, root)
        if target is None:
            continue  # off-site or mailto: etc.; following it is the reader's choice
        label = f"link {raw!r}"
        try:
            rel = target.resolve().relative_to(root).as_posix()
        except ValueError:
            problems.append(f"{label} points outside the book: {absolute}")
            continue
        if not target.is_file():
            problems.append(f"dead {label}: no file {rel}")
            continue
        if known_pages is not None and rel.endswith(".html") and rel not in known_pages:
            problems.append(f"{label} goes to {rel}, which is not a page of this book (_toc.yml); stale build?")
        fragment = urllib.parse.unquote(urllib.parse.urlsplit(absolute).fragment)
        if not fragment or not rel.endswith((".html", ".htm")):
            continue
        anchors = anchors_in(target)
        if here is not None and target.resolve() == here.resolve():
            anchors = anchors | live_ids  # ids created by scripts count on their own page
        if fragment not in anchors:
            problems.append(f"dead anchor {label}: no id {fragment!r} in {rel}")
    return problems


# ------------------------------------------------------------ everything ---


def inspect_page(driver, url, base_url, root, known_pages=None, screenshot=None):
    """Load ``url`` and run every check; return {check name: [problems]}."""
    logs = load_page(driver, url)
    results = {
        "raw TeX": check_raw_tex(driver, logs["mathjax"]),
        "images": check_images(driver),
        "console": check_console(logs["browser"]),
        "requests": check_requests(logs["performance"], base_url),
        "links": check_links(driver, base_url, root, known_pages),
        "overflow": check_overflow(driver),
    }
    if screenshot is not None:
        save_screenshot(driver, screenshot)
    return results


def format_problems(page, results):
    """A failure message naming the page and listing what is wrong with it."""
    lines = [f"{page}: {sum(map(len, results.values()))} problem(s)"]
    for check, problems in results.items():
        for problem in problems[:MAX_REPORTED]:
            lines.append(f"  [{check}] {problem}")
        if len(problems) > MAX_REPORTED:
            lines.append(f"  [{check}] … and {len(problems) - MAX_REPORTED} more")
    return "\n".join(lines)
