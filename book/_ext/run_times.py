"""The ``run-times`` directive: each notebook's run time, measured by the build showing it.

A table of run times typed into a page goes stale as soon as a chapter
changes (chapter 1's listed chapter 12 at 17 s when it took 54 s, and had no
row for chapters 13 and 14; the chapters have since been renumbered).  This directive writes the table when the page
is written, from the run times myst-nb recorded while executing each
notebook in the same build (`make book`).  An edition built from the
notebooks' stored outputs (`make test`, `make pdf`, the student edition)
executes nothing, measures nothing, and says so in place of the table.

myst-nb's own ``nb-exec-table`` does the same with five columns (modified,
method, run time, status); this one keeps the two a reader needs, adds the
total and does not leave an empty table in an edition that ran nothing.
"""

from __future__ import annotations

from docutils import nodes
from sphinx.addnodes import pending_xref
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util.docutils import SphinxDirective

from myst_nb.ext.execution_tables import METADATA_KEY
from myst_nb.sphinx_ import NbMetadataCollector

NOT_EXECUTED = (
    "This edition was built from the outputs stored in the notebooks: no "
    "notebook was executed to build it, so it has no run times to show. ",
    "make book",
    " executes every notebook and writes their run times here.")


class run_times_node(nodes.General, nodes.Element):
    """Placeholder, replaced once every notebook has been executed."""


class RunTimes(SphinxDirective):
    """``{run-times}``: the run time of every notebook executed by this build."""

    def run(self):
        # myst-nb re-reads a page that carries this key whenever a notebook
        # is re-executed, so an incremental build refreshes the table too.
        NbMetadataCollector.set_doc_data(self.env, self.env.docname, METADATA_KEY, True)
        return [run_times_node()]


def measured(env) -> list[tuple[str, float]]:
    """(docname, seconds) of every notebook this build executed, in name order."""
    found = []
    for docname, data in sorted(NbMetadataCollector.get_doc_data(env).items()):
        run = data.get("exec_data")
        if run and run.get("runtime") is not None:
            found.append((docname, float(run["runtime"])))
    return found


def _row(*cells: nodes.Node) -> nodes.row:
    row = nodes.row()
    for cell in cells:
        row += nodes.entry("", cell)
    return row


def run_time_table(docname: str, times: list[tuple[str, float]]) -> nodes.table:
    """Notebook (linked by its title) and seconds, with the total."""
    table = nodes.table(classes=["colwidths-auto"])
    group = nodes.tgroup(cols=2)
    table += group
    group += nodes.colspec(colwidth=80)
    group += nodes.colspec(colwidth=20)
    head = nodes.thead()
    head += _row(nodes.paragraph(text="notebook"), nodes.paragraph(text="seconds"))
    group += head
    body = nodes.tbody()
    for target, seconds in times:
        link = pending_xref(refdoc=docname, reftarget="/" + target, reftype="doc",
                            refdomain="std", refexplicit=False, refwarn=True)
        link += nodes.inline(text=target)
        body += _row(nodes.paragraph("", "", link), nodes.paragraph(text=f"{seconds:.0f}"))
    total = sum(seconds for _, seconds in times)
    body += _row(nodes.paragraph(text="all notebooks"), nodes.paragraph(text=f"{total:.0f}"))
    group += body
    return table


class RunTimesTransform(SphinxPostTransform):
    """Fill each placeholder once the run times of the whole build are known."""

    default_priority = 8  # before the references (its links) are resolved

    def run(self, **kwargs) -> None:
        times = measured(self.env)
        for node in list(self.document.findall(run_times_node)):
            if times:
                node.replace_self(run_time_table(self.env.docname, times))
            else:
                before, command, after = NOT_EXECUTED
                node.replace_self(nodes.paragraph(
                    "", "", nodes.Text(before), nodes.literal(text=command), nodes.Text(after)))


def setup(app):
    app.add_node(run_times_node)
    app.add_directive("run-times", RunTimes)
    app.add_post_transform(RunTimesTransform)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
