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
        "g is the foundation force per sleeper mass, not a gap or gravity",
        "prose",
        re.compile(
            r"w\s*<\s*-g\b|\(w\s*\+\s*g\)|(?:gap|hangs|by a gap|on) \$g\$"
            r"|\\rho\s*S\s*g\b|M_j\s*g\b"
        ),
        "g = f/M (eq. 8); chapter 13's gap under a hanging sleeper is h, "
        "and gravity is written out as 9.81 m/s^2.",
        r"sleeper 15 hangs $g$ above its ballast and touches it when $w < -g$",
    ),
    (
        "r is not an index, a ramp or a fit statistic",
        "both",
        re.compile(
            r"\\varphi_r\b|\\kappa_r\b|\\sum_r\b|(?<![\w\\])r = 0, \\dots"
            r"|(?<![\w\\])r\(\\delta\)|\$r\^2\$|(?<!\w)r²"
            r"|w\^\{\(r\)\}|e\^\{-irq\}|sleeper \$r\$"
        ),
        "r is the height of the rail's top r(x) (chapter 14) and the rail's "
        "harmonics r_n (chapter 3); chapter 13's Floquet modes are counted "
        "by sigma as in chapter 14, its wavenumber sum by j, the dashpot's "
        "ramp is written out, a fit's quality is named in words, and "
        "chapter 11's sleeper is j, as in chapter 13.",
        r"modes $\varphi_r = \varphi_0 + 2\pi r/N$, $r = 0, \dots, N-1$; "
        r"the fit's $r^2$; sleeper $r$ moves as $w^{(r)}(t) = w(t - rL/v)$",
    ),
    (
        "s is a complex frequency, not a squared wavenumber",
        "prose",
        re.compile(
            r"s\s*=\s*\\kappa\^2|s_1,\s*s_2|[YZ]\(s(?:_[12])?\)|s_2\s*<\s*0"
            r"|(?<![\w\\])s\s*=\s*\\pm\s*k_b\^2"
        ),
        "s is the complex frequency of e^{st} (chapter 11, s = i omega on "
        "the axis); the Timoshenko rail's squared wavenumber is psi.",
        r"the two roots $s_1, s_2$ (in $s = \kappa^2$) of its dispersion",
    ),
    (
        "mu is a Floquet multiplier, not an index",
        "prose",
        re.compile(r"_\\mu\b|_\{[^}$]*\\mu\}|\\sum_\\mu|wave \$\\mu\$"),
        "mu is the factor by which a disturbance grows in one period "
        "(chapter 11); the wagon pattern's wavenumbers are xi_l = 2 pi l/H.",
        r"the wavenumbers $\gamma_\mu = 2\pi\mu/H$; harmonic $\omega_{p-\mu}$",
    ),
    (
        "sigma counts a cell's Floquet modes, not a Floquet exponent",
        "prose",
        re.compile(
            r"e\^\{\\sigma\s*[tT]\}|\\sigma\s*\+\s*i\\Omega"
            r"|\\mathbf\{H\}\(\\sigma|exponent \$\\sigma"
        ),
        "sigma numbers the Floquet modes of a cell of N sleepers (chapters "
        "13 and 14); the exponent of a disturbance e^{lambda t} is lambda, "
        "with the multiplier mu = e^{lambda T} (chapter 11).",
        r"grows as $e^{\sigma t}$ (the Floquet exponent $\sigma$; "
        r"$\mu = e^{\sigma T}$), $\mathbf{H}(\sigma + i\Omega;\theta)$",
    ),
    (
        "nu is the tangent damping per mass, not an index",
        "prose",
        re.compile(
            r"\\kappa_\\nu|\\sum_\\nu\b|wave \$\\nu\$|_\{p\s*-\s*\\nu\}"
        ),
        "nu(t) = dg/dw' along the solution, harmonics nu_l (chapter 11); "
        "the wagon pattern's wavenumbers are xi_l = 2 pi l/H (chapter 14).",
        r"wavenumbers $\kappa_\nu = 2\pi\nu/H$; the same wave $\nu$ "
        r"passes at $\omega_{p-\nu}$; $\sum_\nu$",
    ),
    (
        "gamma is the tangent stiffness per mass, not a wavenumber",
        "prose",
        re.compile(r"\\gamma_\\mu|\\gamma_\{p|wavenumbers?\s+\$\\gamma"),
        "gamma(t) = dg/dw along the solution (chapter 11); a wavenumber is "
        "kappa, k_b or (the wagon pattern's) xi_l.",
        r"with weight $e^{i\gamma_{p-n}\ell_j}$, wavenumbers $\gamma_\mu$",
    ),
    (
        "D is the axle spacing, not a stiffness or a dispersion relation",
        "prose",
        re.compile(r"\\mathcal\s*\{?D\b|(?<![\w\\])Z\(s,\s*q\)|force \$Zu\$"),
        "D is the wheel spacing in a bogie (eq. 16); the sleeper's dynamic "
        "stiffness is S(s, q) (calligraphic), the Timoshenko rail's "
        "dispersion relation T(kappa) (calligraphic); Z is chapter 14's "
        "sum over the supports.",
        r"$\mathcal{D}(s, q) = Ms^2 + A/(1 + A\eta)$; "
        r"$Z(s, q) = Ms^2 + \ldots$, a force $Zu$",
    ),
    (
        "K is the number of wheels, not a stiffness harmonic",
        "both",
        re.compile(
            r"(?<![\\\w{])K_(?:l\b|\{[kl]|\{-?\d\}\*)"
            r"|foundation's \$?K\$? and \$?C\b"
        ),
        "K wheels at ell_j (chapter 4); the harmonics of the tangent "
        "stiffness are M gamma_l (and of the tangent damping M nu_l).  "
        "(Chapter 5's K_n = k_2 + i eta_2 omega_n, the linear law's, is "
        "left to a later pass.)",
        r"$M\gamma(t) = \sum_l K_l\,e^{il\Omega t}$; K_{0}*p_{1}",
    ),
    (
        "P is the rail coupling, not the contact force",
        "both",
        re.compile(
            r"P\s*=\s*C_H|P_\{j,\s*p\}|P_j\(t\)|(?<![\w\\])P\s*-\s*Q"
            r"|Q\s*-\s*P\b|P_\{?(?:max|min)|P\s*max\b|P\s*min\b"
            r"|P\^\{[123]/3\}|P\s*\\ge\s*0|\[P_j\]|(?<![\w\\])P_p\b"
        ),
        "P_n is eq. 16's coupling of the rail and the other sleepers; the "
        "wheel-rail contact force is Q_c (Q at rest).",
        r"$m_w\ddot z = P - Q$, $P = C_H\max(\delta, 0)^{3/2}$",
    ),
    (
        "theta is the Bloch phase between sleepers, not between cells",
        "prose",
        re.compile(
            r"\\theta(?:_n)?\s*=\s*[^$]*\\Lambda|\\Lambda[^$]*\\theta\b"
            r"|\\theta\s*\\ell"
        ),
        "theta is the phase a disturbance turns by from one sleeper to the "
        "next (chapter 11); the phase omega Lambda/v from one cell of N "
        "sleepers to the next is Theta (chapter 13).",
        r"$\theta = \frac{\omega\Lambda}{v}$, $e^{-i\theta \ell}$",
    ),
    (
        "lambda is not a wavelength",
        "prose",
        re.compile(r"wavelengths?\s+\$\\lambda|\\lambda\s*=\s*H/n|D/\\lambda"),
        "lambda is a Floquet exponent (chapter 11), as well as Newton's "
        "step (chapter 5) and the Winkler decay (chapter 9); a wavelength "
        "is written H/n.",
        r"a harmonic of wavelength $\lambda = H/n$ gets $|\cos(\pi D/\lambda)|$",
    ),
    (
        "n counts harmonics, not sleepers or time steps",
        "prose",
        re.compile(
            r"sleeper \$n\s*\+\s*N_s\$|e\^\{i\\theta\s*n\}|\\delta w_n"
            r"|_\{n\+1\}|\\mathbf u\}?_n|\(u_n,|e\^\{-inq"
        ),
        "n is a harmonic (omega_n, c_n, P_n, F_n); a sleeper is j (chapters "
        "4 and 13; the paper's own eq. 2 keeps its n) and a time step is "
        "written t + Delta t.",
        r"sleeper $n$ moves as $\delta w_n(t) = e^{i\theta n}\ldots$; "
        r"$\mathbf u_{n+1} = \mathbf u_n + \ldots$",
    ),
    (
        "k counts iterations, not harmonics",
        "prose",
        re.compile(
            r"harmonic \$k\$|(?<![\w\\])[pqs]_k\b|_\{kj\}|\\sum_\{?k\}?\s*p"
            r"|e\^\{ik\\Omega|(?<![\w\\])k\s*=\s*j\s*\+\s*l|_\{k\s*[-+]\s*j\}"
        ),
        "k is the iteration index of eq. 20 (chapter 5); harmonics are n "
        "(and n' for a second one).",
        r"Its harmonic $k$ has $p_k\,e^{s_k t}$; $\mathbf{H}_{kj}$",
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
    # one Floquet exponent book-wide: lambda (chapter 11), sigma a cell's mode
    floquet = next(row for symbol, row in rows.items() if r"\lambda" in symbol)
    assert "Floquet exponent" in floquet and "Floquet mode" in rows[r"$\sigma$"]
    assert r"$q$" in rows and r"\omega L/v" in rows[r"$q$"]
    assert any(r"\rho_0" in symbol and r"\rho_n" in symbol for symbol in rows)
    # issue 30's pass: each meaning moved off a clashing symbol has a row
    for moved in (r"$h$", r"\Theta", r"$\sigma$", r"\xi_l", r"Q_c", r"\gamma(t)",
                  r"\mathcal{S}(s, q)", r"$\psi$"):
        assert any(moved in symbol for symbol in rows), moved
