"""Each script once per page.

Jupyter Book 1.x sets up sphinx-thebe and sphinx-togglebutton so that their
inline configuration scripts reach every page twice, once with the file name
None and once with "" (which Sphinx's own de-duplication tells apart).  A
second ``const THEBE_JS_URL = ...`` is a JavaScript error in the reader's
console on every page; this extension keeps the first copy of each script.
"""

from __future__ import annotations


def _single(app, pagename, templatename, context, doctree) -> None:
    seen, kept = set(), []
    for script in context.get("script_files", []):
        # an inline script has filename None or "" depending on who added it
        key = (getattr(script, "filename", script) or None,
               tuple(sorted(getattr(script, "attributes", {}).items())))
        if key not in seen:
            seen.add(key)
            kept.append(script)
    context["script_files"] = kept


def setup(app):
    app.connect("html-page-context", _single)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
