"""One meaning per symbol inside chapter 14, "The wheel on the rail" (issue 30, item 3).

Issue 30 found symbols of chapters 10-14 that meant two things.  In chapter 14
they were: gamma_mu for the wagon pattern's wavenumbers (gamma is the AFT
Jacobian's stiffness per mass; a wavenumber is kappa), mu for their index
(mu is a Floquet multiplier in chapters 10-13), D(kappa) for the Timoshenko
dispersion relation (D is the axle spacing), K for the Hertz tangent (K is
the number of wheels), kappa_s for the shear coefficient (kappa is a
wavenumber only), R for the wheel's radius (R(t) is the pad force), T for
the force a profile makes above the wheel's bounce (T is the wagon period)
and delta_d beside d for the dip's depth (delta is the contact's
compression).  The truth is the notation table printed in chapter 1,
`railtrack.plotting.book.tables.notation_table`; each rule is checked against
the old text it was written against, so that it cannot silently stop
matching.
"""

import json
import re
from pathlib import Path

import pytest

from railtrack.plotting.book.tables import notation_table

CHAPTER = Path(__file__).resolve().parents[1] / "book" / "14_wheel_on_the_rail.ipynb"

# (what the table gives the symbol, pattern of the second meaning, old text it rejects)
RULES = [
    (r"$\kappa,\ \kappa_j$", r"\\gamma_(?:\\mu|\{p-n\})",
     r"the wagon pattern's wavenumbers $\gamma_\mu = 2\pi\mu/H$"),
    (None, r"\\mu\b", r"the same wave $\mu$ passes at frequency"),
    (r"$D$", r"\\mathcal\{D\}", r"of its dispersion relation $\mathcal{D}(\kappa)$"),
    (r"$\ell_j,\ K$", r"\\mathsf\{K\}", r"the Jacobian $\mathsf{K}\mathsf{C} - \mathsf{I}$"),
    (r"$\kappa,\ \kappa_j$", r"\\kappa_s", r"the shear stiffness $\kappa_sGS$"),
    (r"$R(t)$", r"radius \$R\$|\\sqrt\{R\\delta", r"$2\sqrt{R\delta_0}$ long for a wheel of radius $R$"),
    (r"$\omega_n,\ T$", r"\\approx T\\,", r"the force follows the profile, $P_p \approx T\, r_p$"),
    (None, r"\\delta_d", r"a cosine dip of depth $\delta_d$ = 0.5 mm"),
]


def _prose():
    cells = json.loads(CHAPTER.read_text())["cells"]
    return "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")


@pytest.mark.parametrize("symbol, pattern, old", RULES, ids=[r[1] for r in RULES])
def test_each_symbol_of_chapter_14_means_one_thing(symbol, pattern, old):
    assert re.search(pattern, old), "the rule no longer matches the text it was written against"
    if symbol is not None:
        assert symbol in notation_table(), f"{symbol} left the notation table"
    found = [m.group(0) for m in re.finditer(pattern, _prose())]
    assert not found, found
