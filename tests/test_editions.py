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
