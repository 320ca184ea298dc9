"""The README's code runs, and it tells a newcomer about every capability (issue 29, item 8).

Every ```python block of README.md is run, each in a fresh namespace (each
block stands on its own), except a block preceded by the marker line
``<!-- readme-test: skip ... -->`` (an HTML comment: GitHub does not show
it).  The marker is for a block that needs what the test cannot give (pint,
which is optional) or names that other work delivers; the reason follows
"skip" in the comment.  Warnings a block raises are allowed: the README
says where one is expected.
"""

import inspect
import re
import subprocess
import warnings
from pathlib import Path

import pytest

import railtrack as rt

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
SKIP = "<!-- readme-test: skip"
FENCE = re.compile(r"(?P<before>[^\n]*)\n```python\n(?P<code>.*?)\n```", re.S)


def python_blocks() -> list[tuple[int, str, bool]]:
    """(line, code, skipped) of every ```python block, in order."""
    return [(README.count("\n", 0, m.start("code")) + 1, m["code"],
             m["before"].lstrip().startswith(SKIP)) for m in FENCE.finditer(README)]


BLOCKS = python_blocks()


def test_the_readme_has_python_blocks_and_few_are_skipped():
    # the pattern finds the blocks (else the test below would test nothing)
    assert len(BLOCKS) >= 6
    assert sum(skipped for *_, skipped in BLOCKS) <= 2


@pytest.mark.parametrize("line, code", [(line, code) for line, code, skipped in BLOCKS
                                        if not skipped], ids=lambda v: str(v)[:12])
def test_each_python_block_runs(line, code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a block that writes a file writes it here
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(code, f"README.md, block at line {line}", "exec"), {"__name__": "readme"})


@pytest.mark.parametrize("name", ["SleeperCell", "GapFoundation", "gravity", "Wheel", "CosineDip",
                                  "TimoshenkoRail", "p2_force", "floquet", "check_branch",
                                  "random_support", "continuation", "sweep", "progress",
                                  "PlausibilityWarning", "pint", "summary()", "to_xarray()",
                                  "to_netcdf", "make venv", "LayeredGround",
                                  "surface_displacement", "wheel_load_statistics",
                                  "DippedJoint", "hanging_cell", "neighbour_rise"])
def test_the_readme_names_each_capability(name):
    assert name in README


def test_each_signature_the_prose_writes_names_real_parameters():
    # `rt.CosineDip(depth, length, repeat, ...)` once named a parameter that
    # CosineDip does not have (period); every `rt.name(a, b, c=...)` written in
    # the prose (not the code blocks) names its arguments as the signature does
    prose = re.sub(r"```.*?```", "", README, flags=re.S).replace("\n", " ")
    checked = 0
    for span in re.findall(r"`([^`]+)`", prose):
        for name, arguments in re.findall(r"\brt\.([A-Za-z_]\w*)\(([^()]*)\)", span):
            names = [a.split("=")[0].strip() for a in arguments.split(",")
                     if a.strip() and a.strip() != "..."]
            if not all(re.fullmatch(r"[a-z_]\w*", n) for n in names):
                continue                              # values, not a signature
            parameters = inspect.signature(getattr(rt, name)).parameters
            free = any(p.kind is p.VAR_KEYWORD for p in parameters.values())
            for argument in names:
                assert argument in parameters or free, (name, argument, list(parameters))
            checked += bool(names)
    assert checked >= 10


def test_make_help_lists_venv():
    shown = subprocess.run(["make", "-s", "help"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout
    assert re.search(r"^make venv\s+-", shown, re.M), shown


def test_the_route_without_make_ends_by_starting_jupyterlab_on_the_book():
    # issue 30: it stopped after the build and the tests, leaving a student
    # without make no way to open the chapters
    section = README.split("### Without make", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```(bash|bat)\n(.*?)\n```", section, re.S)
    assert {shell for shell, _ in blocks} == {"bash", "bat"}, blocks
    lab = re.search(r"--ServerApp\.root_dir=\S*?/?book\b",
                    (ROOT / "Makefile").read_text(encoding="utf-8"))
    assert lab, "make lab no longer opens book/: update this test"
    for shell, code in blocks:
        last = code.strip().splitlines()[-1].split("#")[0].split()
        assert last[:2] == ["jupyter", "lab"], (shell, last)
        assert "--ServerApp.root_dir=book" in last, (shell, last)
