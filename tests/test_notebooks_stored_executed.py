"""Every notebook under book/ must be stored executed.

nbval only compares cells that have stored outputs: a notebook saved without
outputs (or half run) passes `make test` while testing nothing.  This module
fails on such notebooks.  Rules, for every non-empty code cell of every
notebook under book/:

* it has an ``execution_count``, and the counts run 1, 2, 3, ... in document
  order (one "Restart kernel and run all", which is what nbval replays);
* a cell whose last statement is a bare expression that displays a value
  (a name, attribute, subscript, arithmetic, literal, ...; not a call, and
  not silenced with a trailing ``;``) has stored outputs;
* a cell holds an error output if and only if it is tagged ``raises-exception``.

To store a notebook executed:  .venv/bin/jupyter-execute --inplace book/NAME.ipynb
(or "Restart kernel and run all" then save, in Jupyter).

The self-tests at the bottom show that the checker does fail on bad notebooks.
"""

from __future__ import annotations

import ast
from pathlib import Path

import nbformat
import pytest

REPO_ROOT = Path(__file__).resolve().parents[1]
BOOK_DIR = REPO_ROOT / "book"


def book_notebooks() -> list[Path]:
    """All notebooks under book/ (the same set `make test` gives to nbval)."""
    if not BOOK_DIR.is_dir():
        return []
    return sorted(
        p
        for p in BOOK_DIR.rglob("*.ipynb")
        if ".ipynb_checkpoints" not in p.parts and "_build" not in p.parts
    )


def _python_source(source: str) -> str | None:
    """Cell source as plain Python (IPython magics translated), or None."""
    try:
        from IPython.core.inputtransformer2 import TransformerManager

        return TransformerManager().transform_cell(source)
    except Exception:  # pragma: no cover - IPython is always installed here
        return None


# Expression nodes whose value is displayed as an execute_result when they
# end a cell.  Calls are left out: a call may return None (plt.show()).
_DISPLAYING = (
    ast.Name,
    ast.Attribute,
    ast.Subscript,
    ast.BinOp,
    ast.UnaryOp,
    ast.BoolOp,
    ast.Compare,
    ast.Constant,
    ast.Tuple,
    ast.List,
    ast.Dict,
    ast.Set,
    ast.ListComp,
    ast.DictComp,
    ast.SetComp,
    ast.JoinedStr,
)


def expects_output(source: str) -> bool:
    """True when the cell ends with an expression whose value is displayed."""
    stripped = source.rstrip()
    if not stripped or stripped.endswith(";"):
        return False
    code = _python_source(source)
    if code is None:
        return False
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return False
    if not tree.body:
        return False
    last = tree.body[-1]
    if not isinstance(last, ast.Expr):
        return False
    value = last.value
    if isinstance(value, ast.Constant) and value.value is None:
        return False
    return isinstance(value, _DISPLAYING)


def notebook_problems(nb: nbformat.NotebookNode) -> list[str]:
    """Human-readable list of reasons why `nb` is not stored executed."""
    problems: list[str] = []
    expected_count = 1
    for index, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        source = cell.source if isinstance(cell.source, str) else "".join(cell.source)
        if not source.strip():
            continue
        where = f"cell {index} ({source.strip().splitlines()[0][:60]!r})"
        tags = set(cell.get("metadata", {}).get("tags", []))
        outputs = cell.get("outputs", [])
        count = cell.get("execution_count")

        if count is None:
            problems.append(f"{where}: not executed (execution_count is null)")
        else:
            if count != expected_count:
                problems.append(
                    f"{where}: execution_count {count}, expected {expected_count} "
                    "(notebook not stored from a single top-to-bottom run)"
                )
            expected_count = count + 1

        if expects_output(source) and not outputs:
            problems.append(f"{where}: ends with an expression but has no stored output")

        has_error = any(o.get("output_type") == "error" for o in outputs)
        if has_error and "raises-exception" not in tags:
            problems.append(f"{where}: stored with an error output")
        if "raises-exception" in tags and count is not None and not has_error:
            problems.append(f"{where}: tagged raises-exception but has no stored error")
    return problems


# --------------------------------------------------------------------------
# The real check: every notebook under book/.

_NOTEBOOKS = book_notebooks()


@pytest.mark.parametrize(
    "path", _NOTEBOOKS, ids=[str(p.relative_to(REPO_ROOT)) for p in _NOTEBOOKS]
)
def test_book_notebook_stored_executed(path: Path) -> None:
    nb = nbformat.read(path, as_version=4)
    problems = notebook_problems(nb)
    assert not problems, (
        f"{path.relative_to(REPO_ROOT)} is not stored executed "
        "(nbval would silently skip these cells):\n  "
        + "\n  ".join(problems)
        + f"\nFix: .venv/bin/jupyter-execute --inplace {path.relative_to(REPO_ROOT)}"
    )


# --------------------------------------------------------------------------
# Self-tests: the checker must be able to fail.

def _nb(*cells: nbformat.NotebookNode) -> nbformat.NotebookNode:
    nb = nbformat.v4.new_notebook()
    nb.cells = list(cells)
    return nb


def _code(source: str, count: int | None, outputs=(), tags=()) -> nbformat.NotebookNode:
    cell = nbformat.v4.new_code_cell(source, execution_count=count)
    cell.outputs = [nbformat.v4.new_output(**o) for o in outputs]
    if tags:
        cell.metadata["tags"] = list(tags)
    return cell


_RESULT = {"output_type": "execute_result", "data": {"text/plain": "2"}, "execution_count": 2}
_ERROR = {"output_type": "error", "ename": "ValueError", "evalue": "boom", "traceback": []}


def test_checker_accepts_executed_notebook() -> None:
    nb = _nb(
        nbformat.v4.new_markdown_cell("# Title"),
        _code("import math\nx = 1", 1),
        _code("", None),
        _code("x + 1", 2, [_RESULT]),
        _code("print(x);", 3, [{"output_type": "stream", "name": "stdout", "text": "1\n"}]),
        _code("%%time\ny = x", 4, [{"output_type": "stream", "name": "stdout", "text": "CPU times: ...\n"}]),
        _code("raise ValueError('boom')", 5, [_ERROR], tags=["raises-exception"]),
    )
    assert notebook_problems(nb) == []


def test_checker_rejects_unexecuted_notebook() -> None:
    nb = _nb(_code("x = 1", None), _code("x", None))
    problems = notebook_problems(nb)
    assert any("not executed" in p for p in problems)
    assert any("no stored output" in p for p in problems)


def test_checker_rejects_partly_executed_notebook() -> None:
    nb = _nb(_code("x = 1", 1), _code("y = 2", None), _code("x + y", 3, [_RESULT]))
    assert any("not executed" in p for p in notebook_problems(nb))


def test_checker_rejects_out_of_order_execution() -> None:
    nb = _nb(_code("x = 1", 4), _code("x + 1", 2, [_RESULT]))
    assert any("execution_count" in p for p in notebook_problems(nb))


def test_checker_rejects_missing_expression_output() -> None:
    nb = _nb(_code("x = 1", 1, [{"output_type": "stream", "name": "stdout", "text": "a\n"}]), _code("x", 2))
    assert any("no stored output" in p for p in notebook_problems(nb))


def test_checker_rejects_stored_error() -> None:
    nb = _nb(_code("1 / 0", 1, [_ERROR]))
    assert any("error output" in p for p in notebook_problems(nb))


def test_expects_output_heuristic() -> None:
    assert expects_output("a = 1\na")
    assert expects_output("df.shape")
    assert expects_output("x[0] * 2")
    assert not expects_output("x[0] * 2;")
    assert not expects_output("plt.show()")
    assert not expects_output("a = 1")
    assert not expects_output("for i in range(3):\n    pass")
    assert not expects_output("%matplotlib inline")
