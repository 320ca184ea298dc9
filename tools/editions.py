"""Editions of the book built from the notebooks' stored outputs.

`make book` executes every notebook; these editions do not: they copy the
book's sources into a folder of their own and set the copy's configuration
to build from the outputs stored in the notebooks, which `make test`
(nbval) keeps equal to a fresh run.  That takes seconds, not minutes.

- ``stored``: the whole book, as `make test` builds it to find Sphinx
  warnings and broken references and to test the rendered pages.
- ``student``: the book without its solutions.  Every cell of a solution
  (its text, its code and the hidden checks of its answer) carries the
  notebook tag ``solution``; the student edition drops those cells, and
  ``check-student`` reads its built HTML and fails if any solution text,
  printed line or figure reached it.
- ``appendix``: the book for print (`make pdf`): the solutions leave the
  chapters for an appendix of their own, "Solutions to the exercises",
  where they are shown unfolded.

    python tools/editions.py stored TARGET
    python tools/editions.py student TARGET
    python tools/editions.py appendix TARGET
    python tools/editions.py check-student HTML_DIR
"""

from __future__ import annotations

import base64
import copy
import hashlib
import html as entities
import json
import re
import shutil
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TAG = "solution"
MARKER = re.compile(r"Solution to Exercise")


def is_solution(cell: dict) -> bool:
    """Whether a notebook cell belongs to a solution (tagged ``solution``)."""
    return TAG in cell.get("metadata", {}).get("tags", [])


def strip_solutions(notebook: dict) -> dict:
    """A copy of the notebook without its solution cells."""
    stripped = dict(notebook)
    stripped["cells"] = [cell for cell in notebook["cells"] if not is_solution(cell)]
    return stripped


APPENDIX = "solutions"
APPENDIX_TOC = f"""  - caption: Appendix
    chapters:
      - file: book/{APPENDIX}
"""


INSTRUCTOR = "instructor"

# What each edition says under every chapter's "## Exercises" heading about
# where the solutions are.
WHERE_SOLUTIONS_ARE = {
    "student": ("This edition has no solutions: work each exercise on your own, then "
                "compare with your classmates or ask your teacher."),
    "appendix": f"The solutions are gathered in {{doc}}`{APPENDIX}`, at the end of the book.",
}
# A sentence that speaks of the solutions as if the reader had them; the
# student edition drops each from the Exercises sections' introductions.
ABOUT_SOLUTIONS = re.compile(r"\bsolutions?\b", re.I)


def with_note_on_solutions(notebook: dict, note: str, keep_intro: bool = True) -> dict:
    """A copy of the notebook whose Exercises sections say where the solutions are.

    With ``keep_intro=False`` (the student edition) the sentences of the
    section's first paragraph that mention solutions are dropped.
    """
    notebook = copy.deepcopy(notebook)
    for cell in notebook["cells"]:
        if cell["cell_type"] != "markdown":
            continue
        text = "".join(cell["source"])
        match = re.search(r"^## Exercises\n\n([^\n]*)", text, flags=re.M)
        if match is None:
            continue
        intro = match.group(1)
        if not keep_intro:
            intro = " ".join(sentence for sentence in re.split(r"(?<=\.)\s+", intro)
                             if not ABOUT_SOLUTIONS.search(sentence))
        cell["source"] = (text[:match.start()] + f"## Exercises\n\n{note}"
                          + (f" {intro}" if intro else "") + text[match.end():])
    return notebook


def unfolded(cell: dict) -> dict:
    """A solution cell as the appendix shows it: its text and its code unfolded."""
    cell = copy.deepcopy(cell)
    tags = cell.get("metadata", {}).get("tags", [])
    if "hide-cell" in tags:
        tags.remove("hide-cell")
    if cell["cell_type"] == "markdown":
        source = "".join(cell["source"])
        cell["source"] = re.sub(r"^:class: dropdown\n", "", source, flags=re.M)
    return cell


def solutions_appendix(chapters: list[tuple[str, dict]]) -> dict:
    """One notebook holding every chapter's solutions, under the chapter's title."""
    cells = [_markdown(
        "# Solutions to the exercises\n\n"
        "The solutions of every chapter's exercises, in the book's order. "
        "Their numbers and figures are those the library computed when the "
        "book was last executed.")]
    for name, notebook in chapters:
        solutions = [unfolded(cell) for cell in notebook["cells"] if is_solution(cell)]
        if not solutions:
            continue
        title = next(line for cell in notebook["cells"] if cell["cell_type"] == "markdown"
                     for line in "".join(cell["source"]).splitlines() if line.startswith("# "))
        cells += [_markdown(f"## {title[2:]}\n\nThe exercises are in {{doc}}`{name}`.")]
        cells += solutions
    metadata = chapters[0][1].get("metadata", {}) if chapters else {}
    return {"cells": cells, "metadata": metadata, "nbformat": 4, "nbformat_minor": 5}


def _markdown(text: str) -> dict:
    digest = hashlib.sha256(text.encode()).hexdigest()[:8]
    return {"cell_type": "markdown", "id": f"appendix-{digest}", "metadata": {},
            "source": text}


def solution_traces(notebook: dict) -> tuple[list[str], set[str]]:
    """What a solution would leave in a page: its printed lines and its figures' hashes.

    Lines shorter than 12 characters (a bare number, a blank) and lines with
    fewer than six letters or digits (a table's rule) are left out: they may
    occur anywhere in the book.
    """
    lines, images = [], set()
    for cell in notebook["cells"]:
        if not is_solution(cell):
            continue
        for output in cell.get("outputs", []):
            text = output.get("text") or output.get("data", {}).get("text/markdown") or ""
            text = "".join(text) if isinstance(text, list) else text
            lines += [line.strip() for line in text.splitlines()
                      if len(line.strip()) >= 12 and len(re.findall(r"[A-Za-z0-9]", line)) >= 6]
            png = output.get("data", {}).get("image/png")
            if png:
                images.add(hashlib.sha256(base64.b64decode("".join(png))).hexdigest())
    return lines, images


def without_instructor_links(text: str) -> str:
    """Links to the instructor's page, which the student edition lacks, as plain words."""
    return re.sub(r"\{doc\}`instructor`", "the instructor's page (in the teacher's edition)", text)


def write_sources(target: Path, edition: str) -> list[Path]:
    """Copy the book's sources to `target` as `edition` makes them; return the notebooks.

    `edition` is ``stored`` (as they are), ``student`` (without solutions)
    or ``appendix`` (the solutions moved to an appendix).
    """
    if target.exists():
        shutil.rmtree(target)
    shutil.copytree(ROOT / "book", target / "book",
                    ignore=shutil.ignore_patterns("*.ipynb", ".ipynb_checkpoints"))
    toc = (ROOT / "_toc.yml").read_text()
    if edition == "appendix":
        toc, count = re.subn(r"^  - caption: References$", APPENDIX_TOC + r"\g<0>", toc,
                             flags=re.M)
        assert count == 1, "_toc.yml must have one References part"
    (target / "_toc.yml").write_text(toc)
    config = (ROOT / "_config.yml").read_text()
    config, count = re.subn(r"execute_notebooks: \w+", "execute_notebooks: \"off\"", config)
    assert count == 1, "_config.yml must set execute_notebooks once"
    if edition == "student":
        config = re.sub(r'^title: "(.*)"$', r'title: "\1 (student edition)"', config, count=1,
                        flags=re.M)
        # The instructor's page (marking notes) stays out of the students' hands.
        toc, count = re.subn(rf"^\s*- file: book/{INSTRUCTOR}\n", "", toc, flags=re.M)
        assert count == 1, f"_toc.yml must list book/{INSTRUCTOR} once"
        (target / "_toc.yml").write_text(toc)
        (target / "book" / f"{INSTRUCTOR}.md").unlink()
        for page in (target / "book").glob("*.md"):
            page.write_text(without_instructor_links(page.read_text()))
    (target / "_config.yml").write_text(config)
    notebooks = {source.stem: json.loads(source.read_text())
                 for source in sorted((ROOT / "book").glob("*.ipynb"))}
    if edition == "appendix":
        notebooks[APPENDIX] = solutions_appendix(list(notebooks.items()))
    written = []
    for name, notebook in notebooks.items():
        if edition in ("student", "appendix") and name != APPENDIX:
            notebook = with_note_on_solutions(strip_solutions(notebook),
                                              WHERE_SOLUTIONS_ARE[edition],
                                              keep_intro=edition != "student")
        if edition == "student":
            for cell in notebook["cells"]:
                if cell["cell_type"] == "markdown":
                    cell["source"] = without_instructor_links("".join(cell["source"]))
        path = target / "book" / f"{name}.ipynb"
        path.write_text(json.dumps(notebook, indent=1, ensure_ascii=False) + "\n")
        written.append(path)
    return written


def chapter_of_single_page(text: str, stem: str) -> str:
    """The part of a single-page build (make pdf) that holds notebook `stem`.

    Sphinx's singlehtml builder opens every document with an empty
    ``<span id="document-book/STEM">``; the part runs to the next one.
    """
    start = text.find(f'id="document-book/{stem}"')
    if start < 0:
        return ""
    end = text.find('id="document-', start + 1)
    return text[start:end if end >= 0 else len(text)]


# Phrases that promise a solution to the reader (absent from the student edition).
PROMISES = re.compile(r"before you read its solution|solutions? (?:is|are) folded|folded solutions?"
                      r"|open (?:the|its) solution", re.I)


def check_build(html: Path) -> list[str]:
    """Every trace of a solution found in the built pages, as messages (empty: none)."""
    pages = {path: entities.unescape(path.read_text(errors="replace"))
             for path in html.rglob("*.html")}
    images = {hashlib.sha256(path.read_bytes()).hexdigest(): path
              for path in html.rglob("*.png")}
    found = [f"{path.relative_to(html)}: 'Solution to Exercise'"
             for path, text in pages.items() if MARKER.search(text)]
    found += [f"{path.relative_to(html)}: speaks of a solution the edition lacks: {m.group(0)!r}"
              for path, text in pages.items() for m in PROMISES.finditer(text)]
    for source in sorted((ROOT / "book").glob("*.ipynb")):
        lines, figures = solution_traces(json.loads(source.read_text()))
        page = html / "book" / (source.stem + ".html")
        text = pages.get(page)
        if text is None:
            text = chapter_of_single_page(pages.get(html / "book" / "index.html", ""),
                                          source.stem)
        found += [f"{page.name}: printed by a solution: {line!r}" for line in lines
                  if line in text]
        found += [f"{images[h].relative_to(html)}: a figure of a solution of {source.name}"
                  for h in figures if h in images]
    return found


def main(argv: list[str]) -> int:
    if len(argv) != 3 or argv[1] not in ("stored", "student", "appendix", "check-student"):
        print(__doc__, file=sys.stderr)
        return 2
    if argv[1] != "check-student":
        written = write_sources(Path(argv[2]), argv[1])
        kind = {"stored": "with their stored outputs", "student": "without solutions",
                "appendix": "with the solutions in an appendix"}[argv[1]]
        print(f"{argv[1]} edition: {len(written)} notebooks {kind} in {argv[2]}")
        return 0
    found = check_build(Path(argv[2]))
    for message in found:
        print(f"solution leaked: {message}", file=sys.stderr)
    print(f"student edition: {'no' if not found else len(found)} solution traces in {argv[2]}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
