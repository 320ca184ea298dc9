"""No exercise's answer is printed in the body of the book (issue 16, section 3).

For every exercise of chapters 1-6 the table `ANSWERS` names its key
answers: what the exercise asks for, where its solution prints it (a
pattern over the solution's printed output, whose group is the number),
the unit, and how close a number must be to count as the same answer (the
printed resolution, or the step of the grid the answer was found on).

The body is everything a reader sees outside the solutions: the prose of
every page under book/ (the exercise statements included, since a question
must not carry its own answer) and the printed output of every code cell
that is not part of a solution.  A key answer is given away where the body
prints a number with the same unit within the tolerance; answers that are
speeds of a peak count only where the body's sentence or line speaks of a
peak, since speeds are printed everywhere.

Truths used: the solutions' own printed outputs (each key must be found
there, so the table cannot drift from the notebooks), and the case the
issue reported, chapter 1's old output "peaks at 1.01, at 25 m/s", which
gave away exercise 6.2's old answer "at v = 27.5 m/s" and which
`test_the_check_finds_the_old_give_away_of_exercise_6_2` must catch.

A second test checks that the sub-parts (a), (b), ... of every exercise and
solution in the book start a paragraph or a list item of their own, so
that each starts on its own line in print.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
NOTEBOOKS = sorted(BOOK.glob("*.ipynb"))
PAGES = NOTEBOOKS + sorted(BOOK.glob("*.md"))
OWN = [p for p in NOTEBOOKS if p.stem[:2] in ("01", "02", "03", "04", "05", "06")]

EXERCISE = re.compile(r"^```\{admonition\} Exercise (\d+\.\d+)")
SOLUTION = re.compile(r"^:::\{admonition\} Solution to Exercise (\d+\.\d+)")
NUMBER = r"([-−+]?\d+(?:\.\d+)?)"

# How each unit is written after (or, for a ratio, around) a number.
UNITS = {
    "m/s": NUMBER + r"\s*m/s(?![²^\w])",
    "km/h": NUMBER + r"\s*km/h",
    "s": NUMBER + r"\s*s\b(?![⁻\-/])",
    "ms": NUMBER + r"\s*ms\b",
    "rad/s": NUMBER + r"\s*rad/s\b",
    "Hz": NUMBER + r"\s*Hz\b",
    "kN": NUMBER + r"\s*kN\b(?![\s·]*s/m)",
    "kN s/m": NUMBER + r"\s*kN[\s·]*s/m",
    "mm": NUMBER + r"\s*mm\b",
    "m": NUMBER + r"\s*m\b(?![/²³^])",
    "ratio": r"(?:[x×]\s*" + NUMBER + r"(?![\d.])|" + NUMBER + r"\s*(?:×|times\b))",
    "steps": NUMBER + r"\s*(?:steps|iterations)\b",
    "slope": r"slope[^.\n]{0,40}?([-−]\d+(?:\.\d+)?)",
    "samples": r"N\s*[=≥>]\s*" + NUMBER + r"(?![\d.])",
    "list": r"(\[[\d, ]+\])",
}
PEAK = re.compile(r"peak|deepest|largest|max", re.I)

# exercise: [(what it asks, pattern in the solution's output, unit, tolerance)]
ANSWERS = {
    "1.1": [
        ("period of the long wagon", r"T \[s\]\s+by hand\s+([\d.]+)", "s", 0.005),
        ("its first harmonic", r"omega_1 \[rad/s\]\s+by hand\s+([\d.]+)", "rad/s", 0.005),
        ("the same in Hz", r"omega_1 \[Hz\]\s+by hand\s+([\d.]+)", "Hz", 0.005),
        ("mean load per sleeper", r"2QL/H \[kN\]\s+by hand\s+([\d.]+)", "kN", 0.05),
        ("delay between its wheels", r"D/v \[ms\]\s+by hand\s+([\d.]+)", "ms", 0.05),
    ],
    "1.2": [
        ("cubic law: gain of the deepest point",
         r"cubic foundation.*\n\s+deepest w: .*\(x([\d.]+)\)", "ratio", 0.005),
        ("cubic law: gain of the mean", r"cubic foundation.*\n.*\n\s+mean w: .*\(x([\d.]+)\)",
         "ratio", 0.005),
    ],
    "1.3": [
        ("bilinear uplift at 90 m/s", r"\| bilinear \(e = 0\.5\) \| \d+ \| \S+ \| \+([\d.]+) \|",
         "mm", 0.0005),
        ("cubic dip at 90 m/s", r"\| cubic \(eps = 0\.8\) \| \d+ \| (\S+) \|", "mm", 0.0005),
        ("cubic rail-seat load at 90 m/s",
         r"\| cubic \(eps = 0\.8\) \| \d+ \| \S+ \| \S+ \| \S+ \| ([\d.]+) \|", "kN", 0.005),
    ],
    "2.1": [
        ("where the mass model is 1 % off", r"r = 1\.01 at ([\d.]+) rad/s", "rad/s", 0.00005),
    ],
    "2.2": [
        ("speed where omega* meets omega_1", r"omega\* = omega_1 at v = ([\d.]+) m/s", "m/s", 0.05),
        ("the same in km/h", r"omega\* = omega_1 at v = [\d.]+ m/s = (\d+) km/h", "km/h", 0.5),
    ],
    "3.1": [
        ("soft pad's frequency in Hz", r"library:\n\s+omega_0 = \d+ rad/s = ([\d.]+) Hz", "Hz", 0.05),
        ("with the foundation", r"with the foundation (\d+) rad/s", "rad/s", 0.5),
        ("its damped frequency", r"damped frequency (\d+) rad/s", "rad/s", 0.5),
    ],
    "3.2": [
        ("peak rail-seat load, doubled pad",
         r"k1 = 440 MN/m:[\s\S]*?peak rail-seat load ([\d.]+) kN", "kN", 0.005),
        ("deepest rail, doubled pad", r"k1 = 440 MN/m:[\s\S]*?deepest rail (\S+) mm", "mm", 0.0005),
        ("mean pad compression, doubled pad",
         r"k1 = 440 MN/m:[\s\S]*?mean pad compression ([\d.]+) mm", "mm", 0.00005),
    ],
    "3.3": [
        ("gap between the forces at 150 m/s",
         r"v = 150 m/s[\s\S]*?largest difference ([\d.]+) kN", "kN", 0.005),
        ("gap between the forces at 300 m/s",
         r"v = 300 m/s[\s\S]*?largest difference ([\d.]+) kN", "kN", 0.005),
    ],
    "4.1": [
        ("harmonics that vanish when F_1 does",
         r"harmonics n <= 15 with F_n = 0 at this D: (\[[\d, ]+\])", "list", 0),
    ],
    "4.2": [
        ("spacing beyond which the dip is within 1 %", r"for D > ([\d.]+) m", "m", 0.005),
    ],
    "5.1": [
        ("fewest samples that are exact for w^5", r"N =\s+(\d+): exact to round-off", "samples", 0),
    ],
    "5.2": [
        ("fixed point's factor per step, cubic law", r"factor ([\d.]+) per step", "ratio", 0.0005),
    ],
    "5.3": [
        ("slope of the aliasing error", r"fitted slope of log\(error\) against log\(N\): (\S+)",
         "slope", 0.05),
    ],
    "6.1": [
        ("steps taken at k2 = 10 MN/m", r"\| 10 \| [\d.]+ \| n = 0 \| \d+ \| \d+ \| (\d+) \|",
         "steps", 0.5),
        ("steps taken at k2 = 40 MN/m", r"\| 40 \| [\d.]+ \| n = 0 \| \d+ \| \d+ \| (\d+) \|",
         "steps", 0.5),
    ],
    "6.2": [
        # the sweep's grid is 2.5 m/s: a peak is known to one step
        ("deepest dip with eta2 = 200 kN s/m", r"\| 200 \| [\d.]+ \| \S+ \| \S+ \| ([\d.]+) \|",
         "m/s", 2.5),
        ("deepest dip with eta2 = 50 kN s/m", r"\| 50 \| [\d.]+ \| \S+ \| \S+ \| ([\d.]+) \|",
         "m/s", 2.5),
    ],
    "6.3": [
        ("threshold damping on k2 = 20 MN/m", r"\| 20 \| (\d+) \| \d+ \|", "kN s/m", 0.5),
        ("paper's damping over the threshold", r"threshold at k2 = 20 MN/m: ([\d.]+)", "ratio", 0.05),
    ],
}


def _text(cell):
    return "".join(cell["source"])


def _printed(cell):
    out = []
    for output in cell.get("outputs", []):
        out.append("".join(output.get("text", "")))
        data = output.get("data", {})
        for kind in ("text/markdown", "text/plain"):
            if kind in data:
                out.append("".join(data[kind]))
                break
    return "\n".join(out)


def _is_solution(cell):
    return "solution" in cell.get("metadata", {}).get("tags", [])


def solution_outputs(path):
    """{exercise: printed output of its solution's code cells}."""
    found, current = {}, None
    for cell in json.loads(path.read_text())["cells"]:
        match = SOLUTION.match(_text(cell))
        if match:
            current = match.group(1)
            found[current] = ""
        elif _is_solution(cell) and current and cell["cell_type"] == "code":
            found[current] += _printed(cell) + "\n"
    return found


def body_texts():
    """(label, text) of everything outside the solutions, page by page."""
    for path in PAGES:
        if path.suffix == ".md":
            yield path.name, path.read_text()
            continue
        for i, cell in enumerate(json.loads(path.read_text())["cells"]):
            if _is_solution(cell):
                continue
            text = _text(cell) if cell["cell_type"] == "markdown" else _printed(cell)
            if text:
                yield f"{path.name} cell {i}", text


def _value(text):
    return text if text.startswith("[") else abs(float(text.replace("−", "-")))


def give_aways(value, unit, tolerance, texts, peak_only=False):
    """Places among `texts` [(label, text)] that print `value` in `unit`."""
    found = []
    for label, text in texts:
        for match in re.finditer(UNITS[unit], text):
            printed = next(g for g in match.groups() if g is not None)
            other = _value(printed)
            same = other == value if unit == "list" else abs(other - value) <= tolerance
            if not same:
                continue
            # the sentence, or the printed line, around the number
            start = max(text.rfind(". ", 0, match.start()), text.rfind("\n", 0, match.start()))
            ends = [text.find(". ", match.end()), text.find("\n", match.end()), len(text)]
            context = text[start + 1:min(i for i in ends if i >= 0)]
            if peak_only and not PEAK.search(context):
                continue
            found.append(f"{label}: ...{context.strip()[:160]}...")
    return found


def _all_solution_outputs():
    outputs = {}
    for path in NOTEBOOKS:
        outputs.update(solution_outputs(path))
    return outputs


def test_every_exercise_of_chapters_1_to_6_has_its_key_answers():
    exercises = [EXERCISE.match(_text(c)).group(1)
                 for path in OWN for c in json.loads(path.read_text())["cells"]
                 if c["cell_type"] == "markdown" and EXERCISE.match(_text(c))]
    assert sorted(exercises) == sorted(ANSWERS)


@pytest.mark.parametrize("exercise", sorted(ANSWERS))
def test_each_key_answer_is_printed_by_its_solution(exercise):
    printed = _all_solution_outputs()[exercise]
    for what, pattern, _, _ in ANSWERS[exercise]:
        assert re.search(pattern, printed), f"{exercise}: {what} not found in\n{printed}"


@pytest.mark.parametrize("exercise", sorted(ANSWERS))
def test_no_key_answer_is_printed_in_the_body(exercise):
    printed = _all_solution_outputs()[exercise]
    body = list(body_texts())
    found = []
    for what, pattern, unit, tolerance in ANSWERS[exercise]:
        value = _value(re.search(pattern, printed).group(1))
        found += [f"{what} ({value} {unit}) in {place}"
                  for place in give_aways(value, unit, tolerance, body, peak_only=unit == "m/s")]
    assert not found, f"exercise {exercise}'s answer in the body:\n" + "\n".join(found)


def test_the_check_finds_the_old_give_away_of_exercise_6_2():
    # book/06_linear_foundation.ipynb at 7f7eb2f: the solution of 6.2 printed
    old_solution = ("Deepest over the sweep: at v = 27.5 m/s with the paper's damping, "
                    "at v = 150 m/s with η2/10.")
    # and chapter 1's body printed, above it
    old_body = [("01_introduction.ipynb cell 17",
                 "Table 1: deepest / static peaks at 1.01, at 25 m/s\n"
                 "pad 30, foundation 20 kN s/m: deepest / static peaks at 2.48, at 365 m/s\n")]
    answer = re.search(r"at v = ([\d.]+) m/s with the paper's damping", old_solution).group(1)
    # 6.2 swept on a 2.5 m/s grid, so its peak speed is known to one step
    assert give_aways(_value(answer), "m/s", 2.5, old_body, peak_only=True)
    # and a speed that is no peak does not count
    assert not give_aways(25.0, "m/s", 2.5, [("x", "At 25 m/s the solve agrees.")],
                          peak_only=True)


SUB_PART = re.compile(r"\(([a-h])\)\s")


def _misplaced_sub_parts(text):
    """Sub-part labels (a)-(h) that do not start a paragraph or a list item."""
    bad = []
    lines = text.split("\n")
    for n, line in enumerate(lines):
        for match in SUB_PART.finditer(line):
            before = line[:match.start()].strip()
            if before in ("", "-", "*", "**", "- **", "* **"):
                if before == "" and n > 0 and lines[n - 1].strip() and not re.match(
                        r"\s*(?:[-*]|\d+\.)\s", lines[n - 1]):
                    # a label at the start of a line inside a paragraph
                    bad.append(line[:80])
            elif re.search(r"[:;.]\s*\**$", before):
                # a label inside a sentence that lists sub-parts
                bad.append(line[max(0, match.start() - 40):match.end() + 40])
    return bad


def test_the_check_of_sub_parts_finds_run_on_parts():
    assert _misplaced_sub_parts("find:\n(a) the period;\n(b) the number")
    assert _misplaced_sub_parts("predict the change in: (a) the coupling; (b) the mean")
    assert not _misplaced_sub_parts("find:\n\n- (a) the period;\n- (b) the number")
    assert not _misplaced_sub_parts("(a) one.\n\n(b) two, as (a) showed.")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_sub_parts_start_their_own_line(path):
    bad = []
    for i, cell in enumerate(json.loads(path.read_text())["cells"]):
        text = _text(cell)
        if cell["cell_type"] == "markdown" and (EXERCISE.match(text) or SOLUTION.match(text)):
            bad += [f"cell {i}: {b}" for b in _misplaced_sub_parts(text)]
    assert not bad, "\n".join(bad)
