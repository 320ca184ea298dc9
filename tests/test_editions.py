"""The student edition and the exercises it is made of (tools/editions.py).

Truths used: the notebooks themselves (an exercise has a solution with the
same number, in the chapter that carries that number); the tag ``solution``
on every cell of a solution; and, for the leak check, a page made here that
does contain a solution's printed line, which the check must report.
"""

import importlib.util
import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb"))
spec = importlib.util.spec_from_file_location("editions", ROOT / "tools" / "editions.py")
editions = importlib.util.module_from_spec(spec)
spec.loader.exec_module(editions)

EXERCISE = re.compile(r"^```\{admonition\} Exercise (\d+)\.(\d+)")
LEVEL = re.compile(r"^```\{admonition\} Exercise \d+\.\d+ \((warm-up|predict, then run|core|challenge)\)\n")
SOLUTION = re.compile(r"^:::\{admonition\} Solution to Exercise (\d+)\.(\d+)")


def _cells(path):
    return json.loads(path.read_text())["cells"]


def _text(cell):
    return "".join(cell["source"])


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_exercise_has_a_folded_solution_numbered_by_its_chapter(path):
    number = path.stem.split("_")[0]
    cells = _cells(path)
    exercises = [EXERCISE.match(_text(c)).groups() for c in cells
                 if c["cell_type"] == "markdown" and EXERCISE.match(_text(c))]
    solutions = [SOLUTION.match(_text(c)).groups() for c in cells
                 if c["cell_type"] == "markdown" and SOLUTION.match(_text(c))]
    assert exercises == solutions
    if number.isdigit():                     # a chapter: its exercises carry its number
        assert all(n == str(int(number)) for n, _ in exercises), exercises
    for cell in cells:
        if SOLUTION.match(_text(cell)):
            assert ":class: dropdown" in _text(cell)
        if EXERCISE.match(_text(cell)):                # labelled by difficulty
            assert LEVEL.match(_text(cell)), _text(cell)[:60]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_cell_of_a_solution_is_tagged(path):
    # A solution runs from its text to the next exercise or heading.
    inside = False
    for cell in _cells(path):
        text = _text(cell)
        if cell["cell_type"] == "markdown":
            if SOLUTION.match(text):
                inside = True
            elif EXERCISE.match(text) or text.startswith("#"):
                inside = False
        assert editions.is_solution(cell) == inside, text[:80]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_stripping_removes_the_solutions_and_nothing_else(path):
    notebook = json.loads(path.read_text())
    stripped = editions.strip_solutions(notebook)
    kept = [c for c in notebook["cells"] if not editions.is_solution(c)]
    assert stripped["cells"] == kept
    remaining = json.dumps(stripped)
    assert "Solution to Exercise" not in remaining
    lines, figures = editions.solution_traces(notebook)
    assert not [line for line in lines if json.dumps(line)[1:-1] in remaining]
    assert not figures & editions.solution_traces(
        {"cells": [dict(c, metadata={"tags": ["solution"]}) for c in stripped["cells"]]})[1]


def test_the_leak_check_finds_a_printed_line_of_a_solution(tmp_path):
    source = next(p for p in NOTEBOOKS if editions.solution_traces(json.loads(p.read_text()))[0])
    line = editions.solution_traces(json.loads(source.read_text()))[0][0]
    page = tmp_path / "book" / f"{source.stem}.html"
    page.parent.mkdir()
    page.write_text("<html><body><p>an exercise</p></body></html>")
    assert editions.check_build(tmp_path) == []
    page.write_text(f"<html><body><pre>{line}</pre></body></html>")
    assert editions.check_build(tmp_path)
    page.write_text("<html><body><p>Solution to Exercise 1.1</p></body></html>")
    assert editions.check_build(tmp_path)


def test_the_leak_check_reads_the_chapters_of_a_single_page_build(tmp_path):
    """make pdf checks a singlehtml build: each chapter is a part of one page."""
    source = next(p for p in NOTEBOOKS if editions.solution_traces(json.loads(p.read_text()))[0])
    line = editions.solution_traces(json.loads(source.read_text()))[0][0]
    other = next(p for p in NOTEBOOKS if p != source)
    page = tmp_path / "book" / "index.html"
    page.parent.mkdir()

    def single_page(first, second):
        return (f'<html><body><span id="document-book/{source.stem}"></span>{first}'
                f'<span id="document-book/{other.stem}"></span>{second}</body></html>')

    # The line printed in another chapter is not a leak of this one.
    page.write_text(single_page("<p>an exercise</p>", f"<pre>{line}</pre>"))
    assert not [m for m in editions.check_build(tmp_path) if line in m]
    page.write_text(single_page(f"<pre>{line}</pre>", "<p>another chapter</p>"))
    assert [m for m in editions.check_build(tmp_path) if line in m]


def test_the_appendix_edition_moves_every_solution_and_unfolds_it(tmp_path):
    written = editions.write_sources(tmp_path, "appendix")
    by_name = {path.stem: json.loads(path.read_text()) for path in written}
    appendix = by_name.pop(editions.APPENDIX)
    for name, notebook in by_name.items():
        assert not any(editions.is_solution(c) for c in notebook["cells"]), name
    moved = [c for c in appendix["cells"] if editions.is_solution(c)]
    originals = [c for path in NOTEBOOKS for c in _cells(path) if editions.is_solution(c)]
    assert [c["id"] for c in moved] == [c["id"] for c in originals]
    assert [c.get("outputs") for c in moved] == [c.get("outputs") for c in originals]
    titles = [SOLUTION.match(_text(c)).groups() for c in moved if SOLUTION.match(_text(c))]
    assert titles == sorted(titles, key=lambda t: (int(t[0]), int(t[1])))
    assert not any(":class: dropdown" in _text(c) or "hide-cell" in c["metadata"].get("tags", [])
                   for c in moved)
    # Every chapter with exercises says where their solutions went.
    with_exercises = [n for n, nb in by_name.items()
                      if any(re.search(r"^## Exercises$", _text(c), re.M) for c in nb["cells"])]
    assert len(with_exercises) == 18  # chapters 11 (split from 10), 15, 16 (ground), 17 (vehicle)
    for name in with_exercises:
        assert editions.WHERE_SOLUTIONS_ARE["appendix"] in json.dumps(by_name[name]), name
    toc = (tmp_path / "_toc.yml").read_text()
    assert f"file: book/{editions.APPENDIX}" in toc
    assert toc.index(editions.APPENDIX) < toc.index("book/bibliography")


SKIPPABLE = re.compile(r"^```\{admonition\} Check: skip on a first reading\n:class: skippable\n")
# What the course guide tells a first reading it may skip, chapter by chapter:
# the SymPy checks of the derivations, and these sections (their headings).
SKIPPABLE_SECTIONS = {
    "05_semi_analytical_method": ["How fast the iteration converges"],
    "10_train_speeds_up": ["A time-domain check",
                           "The linear law's second peak, and what the folds sit on"],
    "11_which_solution_the_track_reaches": ["Hill's matrix, derived",
                                            "A third method: the ring linearised"],
    "12_verification": ["Mesh and time-step convergence"],
    "13_sleepers_that_differ": ["Against the time-domain ring",
                                "One defect in how many sleepers?"],
    "14_wheel_on_the_rail": ["How the library solves them",
                             "Checks: the wheel that becomes a constant force"],
    "18_conclusions": ["Misprints"],
}
DERIVATION_CHAPTERS = ["02_rail_receptance", "03_sleeper_dynamics", "04_train_load",
                       "05_semi_analytical_method", "06_linear_foundation",
                       "07_bilinear_foundation", "08_cubic_foundation"]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_what_a_first_reading_may_skip_is_marked_by_a_check_box(path):
    cells = _cells(path)
    boxes = [i for i, c in enumerate(cells) if c["cell_type"] == "markdown"
             and "Check: skip" in _text(c)]
    for i in boxes:
        assert SKIPPABLE.match(_text(cells[i])), _text(cells[i])[:120]
        assert not editions.is_solution(cells[i])
        # The box says what follows: it is not the last cell of its section.
        following = cells[i + 1] if i + 1 < len(cells) else None
        assert following is not None and not _text(following).startswith("## ")
    if path.stem in DERIVATION_CHAPTERS:
        assert boxes, "a derivation chapter whose SymPy checks are not marked"
    for heading in SKIPPABLE_SECTIONS.get(path.stem, []):
        start = next(i for i, c in enumerate(cells)
                     if re.search(rf"^##+ {re.escape(heading)}", _text(c), re.M))
        assert any(start <= i <= start + 1 for i in boxes), f"no box under '{heading}'"


def test_the_course_plan_and_chapter_13s_boxes_agree():
    """Issue 30: chapter 13 got skip boxes; the guide's plan must not star them.

    The core path (★) of chapter 13 ends at a heading no later than its first
    boxed section, and the guide's list of what the boxes let a first reading
    skip names every boxed section of the chapter."""
    guide = (ROOT / "book" / "course_guide.md").read_text()
    stem = "13_sleepers_that_differ"
    end = re.search(r'★ chapter 13 up to "([^"]+)"', guide)[1]
    headings = [m[1] for c in _cells(ROOT / "book" / f"{stem}.ipynb")
                for m in re.finditer(r"^##+ (.+)$", _text(c), re.M)]
    boxed = SKIPPABLE_SECTIONS[stem]
    assert all(headings.index(end) <= headings.index(b) for b in boxed), end
    grey = guide.split("The grey boxes let a first reading skip")[1]
    grey = " ".join(grey.split("\n\n")[0].split())
    assert all(f'"{b}"' in grey for b in boxed), grey


def test_the_student_edition_promises_no_solution(tmp_path):
    """Under "this edition has no solutions" nothing may ask the reader to read one."""
    editions.write_sources(tmp_path / "src", "student")
    for path in sorted((tmp_path / "src" / "book").glob("*.ipynb")):
        text = "\n".join(_text(c) for c in _cells(path) if c["cell_type"] == "markdown")
        for match in re.finditer(r"^## Exercises\n\n([^\n]*)", text, flags=re.M):
            intro = match.group(1)
            assert intro.startswith(editions.WHERE_SOLUTIONS_ARE["student"]), path.name
            rest = intro[len(editions.WHERE_SOLUTIONS_ARE["student"]):]
            assert not editions.ABOUT_SOLUTIONS.search(rest), (path.name, rest)


def test_the_leak_check_finds_a_promise_of_a_solution(tmp_path):
    page = tmp_path / "book" / "index.html"
    page.parent.mkdir()
    page.write_text("<html><body><p>Work the exercises.</p></body></html>")
    assert editions.check_build(tmp_path) == []
    page.write_text("<html><body><p>Try each before you read its solution.</p></body></html>")
    assert editions.check_build(tmp_path)


def test_the_student_edition_has_no_instructor_page(tmp_path):
    """Marking notes are for the teacher: the page and every link to it are gone."""
    editions.write_sources(tmp_path / "src", "student")
    book = tmp_path / "src" / "book"
    assert not (book / "instructor.md").exists()
    assert "book/instructor" not in (tmp_path / "src" / "_toc.yml").read_text()
    texts = [p.read_text() for p in book.glob("*.md")]
    texts += ["".join(c["source"]) for p in book.glob("*.ipynb") for c in _cells(p)]
    assert not any("{doc}`instructor`" in text for text in texts)
    assert (ROOT / "book" / "instructor.md").exists()  # the full book keeps it
