"""The book's API reference (book/api.md) covers every public name (issue 29, item 8).

The page is generated from the docstrings by Sphinx autodoc and
autosummary (napoleon parses the numpydoc sections); `make test` builds it
with warnings as errors.  Here: every name of ``railtrack.__all__`` has an
entry, the page is in the table of contents, and the docstring filter of
book/_ext/api_docstrings.py escapes what reStructuredText would misread
(``|mu|``) and nothing it would show as a stray backslash.
"""

import re
import sys
from pathlib import Path

import yaml

import railtrack

ROOT = Path(__file__).resolve().parents[1]
PAGE = (ROOT / "book" / "api.md").read_text(encoding="utf-8")
sys.path.insert(0, str(ROOT / "book" / "_ext"))
from api_docstrings import escape_pipes  # noqa: E402


def test_every_public_name_has_an_entry():
    documented = set(re.findall(r"^\.\. (?:auto\w+|py:data):: (?:railtrack\.)?(\S+)", PAGE, re.M))
    assert set(railtrack.__all__) - documented == set()


def test_each_entry_is_in_its_layers_summary_too():
    entries = re.findall(r"^\.\. auto\w+:: (\S+)", PAGE, re.M)
    listed = re.findall(r"^   (railtrack\.\S+)$", PAGE, re.M)
    assert entries == listed  # the same names, in the same order


def test_the_page_is_listed_under_references_with_the_extensions():
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    parts = {p["caption"]: [c["file"] for c in p["chapters"]] for p in toc["parts"]}
    assert "book/api" in parts["References"]
    sphinx = yaml.safe_load((ROOT / "_config.yml").read_text())["sphinx"]
    assert {"sphinx.ext.autodoc", "sphinx.ext.autosummary",
            "sphinx.ext.napoleon"} <= set(sphinx["extra_extensions"])
    assert "api_docstrings" in sphinx["local_extensions"]


def test_pipes_are_escaped_in_prose_only():
    lines = ["The dominant |mu| per period, ``|j| = terms`` and `|x|`.",
             "",
             ">>> abs(-1) | 2",
             "3",
             "",
             "A block::",
             "",
             "    a | b",
             "",
             "Back in |prose|."]
    escape_pipes(lines)
    assert lines[0] == r"The dominant \|mu\| per period, ``|j| = terms`` and `|x|`."
    assert lines[2:5] == [">>> abs(-1) | 2", "3", ""]
    assert lines[7] == "    a | b"
    assert lines[9] == r"Back in \|prose\|."
