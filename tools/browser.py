"""Headless Chromium on a local copy of the book: a server on 127.0.0.1 and a browser.

Shared by `make pdf` (tools/print_pdf.py prints pages with it) and the
browser test of the rendered book (tests/rendered/checks.py inspects pages
with it).  Selenium 4 drives Debian's ``chromium`` through its
``chromium-driver``; nothing here ever downloads a driver or a browser, and
nothing but 127.0.0.1 resolves inside the browser.
"""

from __future__ import annotations

import contextlib
import functools
import http.server
import os
import shutil
import tempfile
import threading
import time
from pathlib import Path

PAGE_LOAD_TIMEOUT = 30  # s, driver.get
MATHJAX_TIMEOUT = 30  # s, MathJax.startup.promise
IMAGE_TIMEOUT = 10  # s, until every <img> has finished (loaded or failed)


# ---------------------------------------------------------------- server ---


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format, *args):
        pass


@contextlib.contextmanager
def serve_directory(directory):
    """Serve ``directory`` on 127.0.0.1 and a free port, in a thread.

    Yields the base URL, e.g. ``http://127.0.0.1:40123/`` (with the slash).
    """
    handler = functools.partial(_QuietHandler, directory=os.fspath(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    server.daemon_threads = True
    thread = threading.Thread(target=server.serve_forever, name="book-http", daemon=True)
    thread.start()
    try:
        host, port = server.server_address[:2]
        yield f"http://{host}:{port}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=5)


# --------------------------------------------------------------- browser ---


def find_browser():
    """(chromium, chromedriver) paths, or None for whichever is missing."""
    chromium = os.environ.get("CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
    driver = os.environ.get("CHROMEDRIVER") or shutil.which("chromedriver")
    return chromium, driver


@contextlib.contextmanager
def headless_chromium(chromium, chromedriver):
    """One headless Chromium with browser and performance logging enabled."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    with tempfile.TemporaryDirectory(prefix="book-chromium-") as profile:
        options = webdriver.ChromeOptions()
        options.binary_location = chromium
        for flag in (
            "--headless=new",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-dev-shm-usage",
            "--window-size=1300,1000",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--disable-extensions",
            "--disable-default-apps",
            "--mute-audio",
            f"--user-data-dir={profile}",
            # Nothing but 127.0.0.1 resolves: a request for any other host
            # fails at once (and is still reported by check_requests, which
            # sees it in the performance log) instead of reaching the network.
            "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1",
        ):
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
        options.page_load_strategy = "normal"
        # An explicit chromedriver path: Selenium Manager is never asked to
        # download anything.
        service = Service(executable_path=chromedriver)
        driver = webdriver.Chrome(options=options, service=service)
        try:
            driver.set_page_load_timeout(PAGE_LOAD_TIMEOUT)
            driver.set_script_timeout(MATHJAX_TIMEOUT)
            # The first tab opens on Chromium's new-tab page, whose own
            # chrome:// requests would otherwise land in the first page's log.
            driver.get("about:blank")
            time.sleep(0.5)
            drain_logs(driver)
            yield driver
        finally:
            driver.quit()


def drain_logs(driver):
    """Empty the browser and performance log buffers (they are per session)."""
    driver.get_log("browser")
    driver.get_log("performance")


_WAIT_MATHJAX_JS = """
const done = arguments[arguments.length - 1];
const mj = window.MathJax;
if (!mj) { done("absent"); return; }
if (!(mj.startup && mj.startup.promise)) { done("configured but not loaded"); return; }
mj.startup.promise.then(() => done("ok"), (e) => done("failed: " + e));
"""

_IMAGES_SETTLED_JS = "return Array.from(document.images).every(i => i.complete);"

_HAS_META_REFRESH_JS = "return !!document.querySelector('meta[http-equiv=\"refresh\" i]');"


def load_page(driver, url):
    """Open ``url`` and wait until it has settled; return the logs it produced.

    Waits for the page load, a meta refresh (the root index.html of a Jupyter
    Book is one), MathJax's first typeset and every image.  Returns a dict
    with ``browser`` and ``performance`` log entries and ``mathjax`` (the
    state of MathJax: ok / absent / configured but not loaded / failed / timeout).
    """
    from selenium.common.exceptions import JavascriptException, TimeoutException
    from selenium.webdriver.support.ui import WebDriverWait

    def wait(condition, timeout=PAGE_LOAD_TIMEOUT):
        # A script may hit a document that is being replaced (meta refresh).
        WebDriverWait(driver, timeout, poll_frequency=0.1, ignored_exceptions=[JavascriptException]).until(condition)

    def ready(d):
        return d.execute_script("return document.readyState") == "complete"

    drain_logs(driver)
    driver.get(url)
    try:
        refreshing = driver.execute_script(_HAS_META_REFRESH_JS)
    except JavascriptException:
        refreshing = True
    if refreshing:
        wait(lambda d: d.current_url != url and ready(d))
    wait(ready)
    try:
        mathjax = driver.execute_async_script(_WAIT_MATHJAX_JS)
    except TimeoutException:
        mathjax = f"timeout: not typeset after {MATHJAX_TIMEOUT} s"
    try:
        wait(lambda d: d.execute_script(_IMAGES_SETTLED_JS), IMAGE_TIMEOUT)
    except TimeoutException:
        pass  # check_images reports the images still loading
    time.sleep(0.1)  # let late console messages and requests reach the logs
    return {
        "browser": driver.get_log("browser"),
        "performance": driver.get_log("performance"),
        "mathjax": mathjax,
    }


def save_screenshot(driver, path, max_height=32000):
    """Full-page PNG screenshot through Chrome DevTools.

    The viewport is stretched to the height of the document for the capture
    (as Puppeteer's fullPage does): capturing beyond a 1000 px viewport leaves
    the theme's sticky parts misplaced and unpainted parts blank.
    """
    import base64

    width, height = driver.execute_script(
        "return [window.innerWidth, Math.max(document.documentElement.scrollHeight,"
        " document.body ? document.body.scrollHeight : 0)];"
    )
    height = max(1, min(int(height), max_height))
    driver.execute_cdp_cmd(
        "Emulation.setDeviceMetricsOverride",
        {"width": int(width), "height": height, "deviceScaleFactor": 1, "mobile": False},
    )
    try:
        driver.execute_script("window.scrollTo(0, 0);")
        # Two animation frames: layout and paint at the new size.
        driver.execute_async_script(
            "const done = arguments[arguments.length - 1];"
            "requestAnimationFrame(() => requestAnimationFrame(() => done()));"
        )
        shot = driver.execute_cdp_cmd("Page.captureScreenshot", {"format": "png", "optimizeForSpeed": True})
    finally:
        driver.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(base64.b64decode(shot["data"]))
    return path
