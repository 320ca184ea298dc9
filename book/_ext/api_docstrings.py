"""The package's docstrings on the API page (book/api.md) as they read in the source.

The docstrings are numpydoc written to be read as plain text: ``|mu|`` is
the modulus of a multiplier and ``|w - w_exact|`` an error, where
reStructuredText would see substitution references that do not exist.
Before napoleon turns the numpydoc sections into reStructuredText, this
extension escapes each ``|`` outside the docstring's literal parts
(doctest blocks, ``::`` blocks, text in backquotes), so that the page shows what the source
says and the build stays free of warnings.

Autosummary's table gives each name the first sentence of its docstring,
and takes "eq." for the end of one ("Linear viscoelastic foundation
f = k2 w + eta2 w', eq."): the extension adds the book's abbreviations to
the few autosummary knows ("e.g.", "i.e.", "et al.").
"""

from __future__ import annotations

import re

ABBREVIATIONS = ("eq.", "eqs.", "Eq.", "Eqs.", "Fig.", "Sec.", "cf.", "approx.")
"""Abbreviations that do not end a docstring's first sentence."""

_PIPE = re.compile(r"(?<!\\)\|")
# inline literals and interpreted text, where a backslash would be shown as it is
_QUOTED = re.compile(r"(``.+?``|`[^`]+`)")


def _escaped(line: str) -> str:
    """`line` with each ``|`` outside backquotes escaped."""
    parts = _QUOTED.split(line)
    return "".join(part if k % 2 else _PIPE.sub(r"\\|", part) for k, part in enumerate(parts))


def escape_pipes(lines: list[str]) -> None:
    """Escape ``|`` in place, except in doctest and literal (``::``) blocks."""
    literal_indent = None  # the indent a literal block must exceed, while in one
    doctest = False
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if not stripped:
            doctest = False
        elif literal_indent is not None and indent <= literal_indent:
            literal_indent = None
        if stripped.startswith(">>>"):
            doctest = True
        if not doctest and literal_indent is None and stripped:
            lines[i] = _escaped(line)
        if stripped.endswith("::") and literal_indent is None:
            literal_indent = indent


def _process(app, what, name, obj, options, lines) -> None:
    escape_pipes(lines)


def setup(app):
    from sphinx.ext import autosummary

    # read by autosummary's extract_summary at each call
    autosummary.WELL_KNOWN_ABBREVIATIONS = (*autosummary.WELL_KNOWN_ABBREVIATIONS,
                                            *ABBREVIATIONS)
    # before napoleon (priority 500): its output has no "|" of its own
    app.connect("autodoc-process-docstring", _process, priority=400)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
