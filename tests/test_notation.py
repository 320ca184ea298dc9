"""One symbol per quantity across the book (issue 16, section 4).

The book's notation is the table `railtrack.plotting.book.tables.notation_table`,
printed in chapter 1.  This test reads the prose of every page under book/
(the markdown cells of the notebooks and the .md pages) and the printed
output of every code cell, and fails where a symbol is used for a quantity
that the notation gives another symbol.  Each rule below names the
convention it protects and shows the kind of text that broke it before.

Truths used: the conventions themselves (stated in the notation table and
in chapters 2 and 5), and, for each rule, a sample of the text it must
reject, checked in `test_each_rule_rejects_what_it_is_written_against`,
so that a rule cannot silently stop matching.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
PAGES = sorted(BOOK.glob("*.ipynb")) + sorted(BOOK.glob("*.md"))

# (name, where, pattern, why, a text that breaks the convention)
# where: "prose" (markdown), "output" (printed by code cells) or "both".
RULES = [
    (
        "contraction factor is rho, not q",
        "both",
        re.compile(r"(?<![\w\\])q_(?:0|n|\{n\})(?![\w])"),
        "q is the phase omega L/v between neighbouring sleepers (chapter 2) "
        "and nothing else; the factor by which the paper's iteration shrinks "
        "the error is rho_0 (the mean) and rho_n (harmonic n), chapter 5.",
        r"the error of the mean after $k$ steps is $-q_0^k$; $q_n^{(1)}$",
    ),
    (
        "beta is the pad damping rate, never a wavenumber",
        "prose",
        re.compile(
            r"\\beta\s*\\?,?\s*x\b|i\(\\beta|\\omega\s*/\s*\\beta"
            r"|v\s*\\beta\b|\\beta\^4|wavenumbers?\s+\$\\beta"
        ),
        "beta = eta_1/M (eq. 8); a wavenumber is kappa (or k_b for the free "
        "bending wave).",
        r"A free wave $e^{i(\beta x-\omega t)}$ with phase speed $\omega/\beta$",
    ),
    (
        "the free bending wavenumber is k_b, not k",
        "prose",
        re.compile(
            r"\bk\s*=\s*k_b\b|(?<![\w\\{])k\^[34]|e\^\{-i?k\s*\|x\|\}"
            r"|\ba\s*=\s*kL\b"
        ),
        "k_b^4 = rho S omega^2 / EI everywhere; a bare k is a stiffness "
        "(chapter 9's bed modulus) or the iteration index.",
        r"$G(x) = -\frac{e^{-k|x|}}{4EI\,k^3}, \qquad k = k_b$; with $a = kL$",
    ),
    (
        "k_b is a wavenumber, never a stiffness",
        "prose",
        re.compile(r"k_b\s*\+\s*k_f|k_b\s*/\s*\(\s*k_b"),
        "k_b is the free bending wavenumber; a ballast or subgrade stiffness "
        "needs a symbol of its own.",
        r"the ratio $r = k_b/(k_b + k_f)$",
    ),
    (
        "lambda is not a travelling wave's wavenumber",
        "prose",
        re.compile(
            r"e\^\{[^}]*i[^}]*\\lambda\s*x|wavenumbers?\s+\$\\lambda"
            r"|\\lambda\s*=\s*k_b"
        ),
        "a travelling wave is written with kappa or k_b; lambda is kept for "
        "the decay parameter (k/4EI)^(1/4) of a rail on a Winkler bed "
        "(chapter 9) and for Newton's step length (chapter 5).",
        r"a wave $e^{-i\lambda x}$ of wavenumber $\lambda$",
    ),
    (
        "kappa is a wavenumber only",
        "prose",
        re.compile(r"\\kappa\s*\(t\)|\\kappa\s*=\s*\\partial"),
        "kappa and kappa_j are wavenumbers (chapter 2's comb, chapter 10's "
        "free waves); the AFT Jacobian's stiffness per mass is gamma(t).",
        r"$\delta g = \kappa(t)\,\delta w$, with $\kappa = \partial f/\partial w / M$",
    ),
    (
        "D is the axle spacing only",
        "prose",
        re.compile(r"(?<!paper's \$)(?<!paper's )\bD_j\b"),
        "a wheel's distance behind the reference wheel is ell_j (chapter 4); "
        "the paper's D_j may only be named as such.",
        r"$\sum_j Q_j\,e^{-i\omega D_j/v}$",
    ),
    (
        "F_0 is an acceleration, not a load",
        "both",
        re.compile(
            r"(?<![M\w])(?<!M )F_0\$?\s*=\s*\$?\s*[\d.]+\s*kN"
            r"|(?<![M\w])(?<!M )F_0 = [\d.]+ m/s\^2\s*=\s*[\d.]+ kN"
        ),
        "F_0 = sum Q L / (M H) in m/s^2 (eq. 16); the load per sleeper is "
        "M F_0, in kN.",
        "F_0 = 50 m/s^2 = 5 kN per sleeper",
    ),
    (
        "secant stiffness means f(w)/w only",
        "prose",
        None,  # sentence rule, see _secant_misuse
        "the secant stiffness of a law is f(w)/w at one displacement "
        "(chapter 8); a stiffness fitted to a whole motion needs another "
        "name (chapter 10 calls it k_eff).",
        "The secant stiffness, the least-squares slope of the force against "
        "w over the period, falls to 17.1 MN/m.",
    ),
]

SENTENCE = re.compile(r"(?:[^.!?]|[.!?](?!\s|$))+(?:[.!?]|$)")
FIT = re.compile(r"least[- ]squares|best fits?|regression|fitted", re.I)


def _secant_misuse(text):
    """Sentences that call a fitted stiffness 'secant' (a function name too)."""
    found = []
    for sentence in SENTENCE.findall(text):
        if ("secant" in sentence.lower() and FIT.search(sentence)
                and "not the secant" not in sentence):
            found.append(sentence.strip())
    return found


def _matches(rule, text):
    name, _, pattern, _, _ = rule
    if pattern is None:
        return _secant_misuse(text)
    return [text[max(0, m.start() - 60):m.end() + 60] for m in pattern.finditer(text)]


def _texts(path):
    """(where, label, text) of every markdown cell and printed output."""
    if path.suffix == ".md":
        yield "prose", path.name, path.read_text()
        return
    cells = json.loads(path.read_text())["cells"]
    for i, cell in enumerate(cells):
        if cell["cell_type"] == "markdown":
            yield "prose", f"{path.name} cell {i}", "".join(cell["source"])
            continue
        for output in cell.get("outputs", []):
            text = "".join(output.get("text", ""))
            data = output.get("data", {})
            for kind in ("text/markdown", "text/plain"):
                if kind in data:
                    text += "".join(data[kind])
                    break
            if text:
                yield "output", f"{path.name} cell {i} output", text


@pytest.mark.parametrize("rule", RULES, ids=[r[0] for r in RULES])
def test_each_rule_rejects_what_it_is_written_against(rule):
    assert _matches(rule, rule[4]), rule[0]


@pytest.mark.parametrize("rule", RULES, ids=[r[0] for r in RULES])
def test_the_book_keeps_the_notation(rule):
    name, where, _, why, _ = rule
    found = []
    for path in PAGES:
        for kind, label, text in _texts(path):
            if where in (kind, "both"):
                found += [f"{label}: ...{hit}..." for hit in _matches(rule, text)]
    assert not found, f"{name} ({why}):\n" + "\n".join(found)


def test_the_notation_table_lists_the_conventions():
    from railtrack.plotting.book.tables import notation_table

    rows = {row.split("|")[1].strip(): row.split("|")[2]
            for row in notation_table().splitlines()[2:]}
    assert r"$\beta$" in rows and "nothing else" in rows[r"$\beta$"]
    assert r"$k_b$" in rows and r"k_b^4 = \rho S\omega^2/EI" in rows[r"$k_b$"]
    assert any(r"\kappa_j" in symbol for symbol in rows)
    assert r"$q$" in rows and r"\omega L/v" in rows[r"$q$"]
    assert any(r"\rho_0" in symbol and r"\rho_n" in symbol for symbol in rows)
