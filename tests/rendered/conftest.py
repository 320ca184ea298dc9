"""Fixtures for the browser tests of the rendered book.

    .venv/bin/python -m pytest tests/rendered --book-html _build/html

Without --book-html the page tests are skipped (test_checks_fail.py still
runs if a browser is installed).  The pages are the ones _toc.yml names, plus
the root index.html and, if built, genindex.html and search.html.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import checks
import pytest

REPO = Path(__file__).resolve().parents[2]
OPTIONAL_PAGES = ("genindex.html", "search.html")


def pytest_addoption(parser):
    group = parser.getgroup("rendered book")
    group.addoption(
        "--book-html",
        metavar="DIR",
        default=None,
        help="test the HTML book built in DIR (e.g. _build/html) in headless Chromium",
    )
    group.addoption(
        "--book-toc",
        metavar="FILE",
        default=str(REPO / "_toc.yml"),
        help="the _toc.yml whose pages are tested (default: the repository's)",
    )
    group.addoption(
        "--screenshot-dir",
        metavar="DIR",
        default=str(REPO / "_build" / "screenshots"),
        help="where a full-page PNG of every tested page is kept (default: _build/screenshots)",
    )


def _option(config, name):
    # The option exists only when this conftest was loaded at start-up
    # (pytest tests/rendered ...); under a plain `pytest tests` it is absent.
    return config.getoption(name, default=None)


def toc_pages(toc_file):
    """HTML pages (relative paths) of the book described by ``toc_file``."""
    import yaml

    toc = yaml.safe_load(Path(toc_file).read_text(encoding="utf-8"))
    files = []

    def walk(node):
        if isinstance(node, dict):
            for key in ("root", "file"):
                if isinstance(node.get(key), str):
                    files.append(node[key])
            for value in node.values():
                if isinstance(value, (list, dict)):
                    walk(value)
        elif isinstance(node, list):
            for item in node:
                walk(item)

    walk(toc)
    pages = ["index.html"]
    for name in files:
        stem = name
        for suffix in (".ipynb", ".md", ".rst"):
            stem = stem.removesuffix(suffix)
        page = stem.lstrip("/") + ".html"
        if page not in pages:
            pages.append(page)
    return pages


def _pages_for(config):
    toc = _option(config, "book_toc") or str(REPO / "_toc.yml")
    pages = toc_pages(toc)
    html_dir = _option(config, "book_html")
    if html_dir:
        pages += [p for p in OPTIONAL_PAGES if (Path(html_dir) / p).is_file()]
    return pages


def pytest_generate_tests(metafunc):
    if "page" in metafunc.fixturenames:
        metafunc.parametrize("page", _pages_for(metafunc.config))


@pytest.fixture(scope="session")
def book_pages(pytestconfig):
    """Every page of the book, as paths relative to the HTML directory."""
    return frozenset(_pages_for(pytestconfig))


@pytest.fixture(scope="session")
def book_html(pytestconfig):
    html_dir = _option(pytestconfig, "book_html")
    if not html_dir:
        pytest.skip("the rendered book is tested only with --book-html DIR (e.g. --book-html _build/html)")
    path = Path(html_dir).resolve()
    if not (path / "index.html").is_file():
        pytest.fail(f"--book-html {html_dir}: no index.html there; build the book first (make book)")
    return path


@pytest.fixture(scope="session")
def book_server(book_html):
    """Base URL of the book served from 127.0.0.1 on a free port."""
    with checks.serve_directory(book_html) as base_url:
        yield base_url


@pytest.fixture(scope="session")
def screenshot_dir(pytestconfig):
    return Path(_option(pytestconfig, "screenshot_dir") or REPO / "_build" / "screenshots")


@pytest.fixture(scope="session")
def browser(pytestconfig):
    """One headless Chromium for the whole session.

    Missing browser pieces skip the tests, unless --book-html was given:
    then the book was meant to be tested and they are an error.
    """
    problem = None
    chromium, chromedriver = checks.find_browser()
    if importlib.util.find_spec("selenium") is None:
        problem = "selenium is not installed in this environment (it is pinned in environment.txt)"
    elif not chromium or not chromedriver:
        problem = (
            "headless Chromium is not installed "
            f"(chromium: {chromium or 'missing'}, chromedriver: {chromedriver or 'missing'}); "
            "apt-get install chromium chromium-driver"
        )
    if problem:
        if _option(pytestconfig, "book_html"):
            pytest.fail(problem)
        pytest.skip(problem)
    with checks.headless_chromium(chromium, chromedriver) as driver:
        yield driver
