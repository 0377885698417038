"""A quoted equation too wide for a claim table's Printed column: the rule that sends it to a
line of its own under its claim's row (issue 32), and the HTML of that line.

Oracles: the widths of :func:`math_em` added up by hand from its table of Computer Modern's
widths; the markup written out by hand for synthetic claims built in the test; the stylesheet's
rules read from the file.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from navcore.ledger import EXACT, Claim, evaluate
from navcore.ledger.tables import LedgerTable
from navcore.ledger.text import math_em, quote_below

ROOT = Path(__file__).resolve().parents[1]
#: ATC-10 Eqs. (H.8)-(H.22) as quoted: one product of seven factors, with no operator at its
#: outer level after the first term (it scrolled in its 215 px box at 70 %)
LONG = (
    r"$$P_{\xi_y} = (G'P_n^{-1}G)^{-1} + "
    r"(G'P_n^{-1}G)^{-1}G'P_n^{-1}FP_{\xi_x}F'P_n^{-1}G(G'P_n^{-1}G)^{-1} \quad (H.8)$$"
)
#: a formula as long in characters, but a sum that wraps after each term
SUM = "$$" + " + ".join(f"a_{{{k}}} b_{{{k}}}" for k in range(12)) + "$$"
SHORT = r"$$x = a + b \quad (3)$$"


def statement(cid: str, printed: str) -> Claim:
    return Claim(
        id=cid,
        paper="ATC10",
        locator="App. H, Eqs. (H.8)-(H.22)",
        quantity="the printed covariance is the generalized least-squares one",
        published=True,
        unit="statement",
        compute=lambda: True,
        tolerance=EXACT,
        expected_status="reproduced",
        note="A synthetic claim.",
        printed=printed,
    )


def test_math_em_adds_up_the_symbols_widths():
    """By hand: x (0.52) + a relation with its spaces (1.33) + 1 (0.5); a script at 71 %, 0.05
    from its base; a fraction as wide as its wider part at script size plus 0.24; a 2x2 matrix
    in brackets: two 0.52 columns, 1 em between them, the brackets (0.9) and their spaces (0.33)."""
    assert math_em("x = 1") == pytest.approx(2.35)
    assert math_em("x^{2}") == pytest.approx(0.52 + 0.71 * 0.5 + 0.05)
    assert math_em(r"\frac{ab}{c}") == pytest.approx(0.71 * 1.04 + 0.24)
    assert math_em(r"\begin{bmatrix} a & b \\ c & d \end{bmatrix}") == pytest.approx(3.27)
    # a factor more is wider; the source's spaces do not count
    assert math_em("(G'G)^{-1}G'F") > math_em("(G'G)^{-1}G'")
    assert math_em("a+b") == math_em("a + b")


@pytest.mark.parametrize(
    ("quote", "below"),
    [
        (LONG, True),  # its widest piece is 19 em: wider than 17.5
        (SUM, False),  # as long, but each piece after a "+" is short
        (SHORT, False),
        ("about 10 m", False),  # words alone
        (r"the product \mathbf{P}_N \mathbf{P}_N^T of it", False),  # LaTeX without delimiters
    ],
)
def test_the_rule_takes_the_widest_unbreakable_piece(quote, below):
    assert quote_below(quote) is below


def _tr(html: str, cid: str) -> tuple[str, str]:
    """The claim's row and the row after it."""
    rows = re.findall(r"<tr\b.*?</tr>", html)
    i = next(k for k, r in enumerate(rows) if f'id="{cid}"' in r)
    return rows[i], rows[i + 1] if i + 1 < len(rows) else ""


def test_a_long_quote_gets_a_line_of_its_own_and_a_short_one_stays():
    long_ev = evaluate(statement("ATC10-test-long", LONG))
    short_ev = evaluate(statement("ATC10-test-short", SHORT))
    html = LedgerTable([long_ev, short_ev])._repr_html_()
    row, after = _tr(html, "atc10-test-long")
    # the claim's row keeps its id (links point there); its Printed cell points below
    assert row.startswith('<tr id="atc10-test-long" class="ledger-claim ledger-claim-quoted" data-status=')
    below = '<span class="ledger-quote-below">the equation below</span>'
    assert f'<td class="ledger-value" data-label="Printed">{below}</td>' in row
    assert r"\(" not in row.split('data-label="Printed"')[1]
    # the next row holds the quote across the five columns
    # (its own id names it, for the layout gate; links point to the claim's row)
    assert after.startswith(
        '<tr id="atc10-test-long-quote" class="ledger-claim-quote" data-status="reproduced">'
        '<td colspan="5" data-label="Printed">'
    )
    assert r"G&#x27;P_n^{-1}FP_{\xi_x}F&#x27;P_n^{-1}G" in after and "(H.8)" not in after
    # the short quote stays in its cell, inline, and no line follows it
    row, after = _tr(html, "atc10-test-short")
    assert 'class="ledger-claim" data-status=' in row and "ledger-claim-quoted" not in row
    assert r'data-label="Printed"><span class="math notranslate nohighlight">\(x = a + b\)</span></td>' in row
    assert "ledger-claim-quote" not in after
    # deterministic
    assert LedgerTable([long_ev, short_ev])._repr_html_() == html


def test_words_around_a_long_formula_are_the_quote_below():
    ev = evaluate(statement("ATC10-test-words", "so that " + LONG))
    row, after = _tr(LedgerTable([ev])._repr_html_(), "atc10-test-words")
    assert "the quote below" in row and 'class="ledger-claim-quote"' in after
    assert "so that" in after


def test_the_stylesheet_lays_out_the_quote_line_at_both_widths():
    """The line is styled wide (the table's width, no border between it and its claim's row,
    highlighted with its row when the row is opened by its link) and on a phone, where the
    claim's cells become a card that the line closes."""
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")
    narrow = css[css.index("phone width: each claim stacks") :]
    narrow = narrow[: narrow.index("\n}\n")]
    wide = css.replace(narrow, "")
    assert "tr.ledger-claim.ledger-claim-quoted td { border-bottom: 0; }" in wide
    assert "tr.ledger-claim-quote .ledger-math-wide { max-width: 100%;" in wide
    assert "tr.ledger-claim:target + tr.ledger-claim-quote td { background: var(--ledger-target); }" in wide
    assert "tr.ledger-claim.ledger-claim-quoted { border-bottom: 0;" in narrow
    assert "tr.ledger-claim-quote { display: block; border-bottom: 1px solid var(--ledger-rule);" in narrow
    assert "tr.ledger-claim-quote td { display: block;" in narrow


def test_the_pdf_table_sets_a_long_quote_on_a_line_of_its_own():
    """By hand, for synthetic claims: in the PDF's claim table a long quote's Printed cell says
    where the quote is, the row is kept with the next line (``\\\\*``), and that line spans the
    four columns, centred, with the formula scaled to the table's width only when wider; a short
    quote stays in its cell."""
    long_ev = evaluate(statement("ATC10-test-long", LONG))
    short_ev = evaluate(statement("ATC10-test-short", SHORT))
    lines = LedgerTable([long_ev, short_ev]).latex().splitlines()
    at = next(i for i, line in enumerate(lines) if "test-\\allowbreak{}long" in line)
    assert r"& \textit{the equation below} &" in lines[at] and lines[at].endswith(r"\\*")
    quote = lines[at + 1]
    assert quote.startswith(
        r"\multicolumn{4}{>{\centering\arraybackslash}p{\dimexpr\linewidth-2\tabcolsep\relax}}"
    )
    assert r"{\navcorefitmath{P_{\xi_y} = (G'P_n^{-1}G)^{-1} + " in quote and "(H.8)" not in quote
    short = next(line for line in lines if "test-\\allowbreak{}short" in line)
    assert r"& $x = a + b$ &" in short and r"\centering" not in short
    assert sum(r"\centering" in line for line in lines) == 1
