"""Chapter 1's run times are measured by the build that shows them (issue 30).

A hand-typed table of run times went stale (chapter 12 listed at 17 s when
it took 54 s; chapters 13 and 14 missing; the chapters have since been renumbered).  Chapter 1 now carries the
``{run-times}`` directive of book/_ext/run_times.py, which writes the run
time myst-nb measured for each notebook in the same build.  These tests
build a two-notebook Sphinx project with it: executed, the table holds each
notebook's time (one notebook sleeps, so its time has a floor that does not
come from the code under test); built from stored outputs, as `make test`
does, the page says no notebook ran instead of showing an empty table.
"""

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
EXT = ROOT / "book" / "_ext"
SLEEP = 1.0


def markdown(name):
    path = ROOT / "book" / name
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return "\n".join("".join(c["source"]) for c in cells
                     if c["cell_type"] == "markdown")


def test_chapter_1_types_no_run_time_and_asks_the_build_for_them():
    text = markdown("01_introduction.ipynb")
    assert "```{run-times}" in text
    typed = re.findall(r"^\|\s*seconds\s*\|.*$|\(\d+ s\)", text, re.M)
    assert typed == [], f"run times typed by hand: {typed}"


def build(tmp_path, mode):
    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text(
        f"import sys\nsys.path.insert(0, {str(EXT)!r})\n"
        "extensions = ['myst_nb', 'run_times']\n"
        f"nb_execution_mode = {mode!r}\n")
    (src / "index.md").write_text(
        "# Home\n\n```{run-times}\n```\n\n```{toctree}\nslow\nquick\n```\n")
    for name, code in [("slow", f"import time\ntime.sleep({SLEEP})"),
                       ("quick", "1 + 1")]:
        nb = nbformat.v4.new_notebook()
        nb.cells = [nbformat.v4.new_markdown_cell(f"# Notebook {name}"),
                    nbformat.v4.new_code_cell(code)]
        nb.metadata["kernelspec"] = {"name": "python3", "language": "python",
                                     "display_name": "Python 3"}
        nbformat.write(nb, src / f"{name}.ipynb")
    out = tmp_path / "out"
    # a process of its own: Sphinx registers its nodes once per process
    env = {**os.environ, "JUPYTER_PREFER_ENV_PATH": "1",
           "PATH": f"{Path(sys.executable).parent}{os.pathsep}"
                   f"{os.environ.get('PATH', '')}"}
    subprocess.run([sys.executable, "-m", "sphinx", "-W", "-n", "-q", "-E",
                    "-b", "html", str(src), str(out)],
                   check=True, env=env, capture_output=True)
    return (out / "index.html").read_text(encoding="utf-8")


def rows(page):
    table = page[page.index("<table"):page.index("</table>")]
    cells = re.findall(r"<td><p>(.*?)</p></td>", table, re.S)
    text = [re.sub(r"<[^>]+>", "", c).strip() for c in cells]
    return dict(zip(text[::2], (float(s) for s in text[1::2])))


def test_an_executed_build_shows_the_times_it_measured(tmp_path):
    times = rows(build(tmp_path, "force"))
    assert set(times) == {"Notebook slow", "Notebook quick", "all notebooks"}
    assert times["Notebook slow"] >= SLEEP
    # whole seconds, so the total may differ from the sum by the rounding
    parts = times["Notebook slow"] + times["Notebook quick"]
    assert abs(times["all notebooks"] - parts) <= 1


def test_a_build_from_stored_outputs_says_nothing_was_measured(tmp_path):
    page = build(tmp_path, "off")
    assert "<table" not in page
    assert "no notebook was executed to build it" in page
