"""The number a claim compares is set in bold in its quote (the Printed cell of the claim tables).

A claim that quotes a whole printed table row ("10 nmi/h 1880 0.011 g 0.77") compares one of
its numbers; the tables mark that number, where the quote names it once in its words, so that
a reader sees which printed number the reproduced value stands beside. The oracle is the quote
itself: the marked text, with its marks removed, is the quote, and the marked number is the one
the claim's tolerance was given as printed.
"""

from __future__ import annotations

import re

import pytest

from navcore import ledger
from navcore.claims import Claim, evaluate, printed
from navcore.claims.declarations import resolve_tolerance
from navcore.claims.quotes import claim_quote
from navcore.ledger.text import _printed_html, _printed_tex, _printed_text, mark_compared_number


@pytest.mark.parametrize(
    ("quote", "digits", "marked"),
    [
        ("10 nmi/h 1880 0.011 g 0.77", "0.011", "10 nmi/h 1880 **0.011** g 0.77"),
        ("I 50 nsec 5 nsec .10 282 ft", ".10", "I 50 nsec 5 nsec **.10** 282 ft"),
        ("about 1840 ft, and $x_{1840}$", "1840", "about 1840 ft, and $x_{1840}$"),  # also in math
        ("1840 ft of 18400 ft", "1840", "**1840** ft of 18400 ft"),  # 18400 is another number
        ("0.5 and 0.50", "0.5", "**0.5** and 0.50"),
        ("a 1.5 m error", "1.5e0", "a 1.5 m error"),  # not digits as printed
        ("the \\alpha of 3 dB", "3", "the \\alpha of 3 dB"),  # LaTeX shown as source
        ("it *deteriorates* by 3 dB", "3", "it *deteriorates* by 3 dB"),  # the paper's emphasis
        ("$$x = 3 \\quad (3)$$ with 3", "3", "$$x = 3 \\quad (3)$$ with 3"),  # a display formula
        ("3 dB", "", "3 dB"),
    ],
)
def test_the_compared_number_is_marked_only_where_it_stands_once_in_the_words(quote, digits, marked):
    assert mark_compared_number(quote, digits) == marked
    assert mark_compared_number(quote, digits).replace("**", "") == quote


def _row_claim(quote: str, digits: str) -> Claim:
    value, tol = printed(digits)
    return Claim(
        id="SP-doc-row",
        paper="SP",
        locator="Table 2.6, column 3",
        quantity="a synthetic table cell",
        published=value,
        unit="g",
        compute=lambda: value,
        tolerance=tol,
        expected_status="reproduced",
        note="a synthetic claim",
        printed=quote,
    )


def test_the_tables_set_the_marked_number_in_bold_in_html_and_in_the_pdf():
    e = evaluate(_row_claim("10 nmi/h 1880 0.011 g 0.77", "0.011"))
    text = _printed_text(e)
    assert text == "10 nmi/h 1880 **0.011** g 0.77"
    assert "<strong>0.011</strong>" in _printed_html(text)
    assert r"\textbf{0.011}" in _printed_tex(text).replace(r"\allowbreak{}", "")  # breakable in the PDF
    # the interactive ledger folds a quote by its length and words; the marks are not counted
    assert not _printed_html("1 nmi/h 431 0.0026 g 0.37", fold=40).startswith("<details")
    assert not _printed_html("1 nmi/h 431 **0.0026** g 0.37", fold=40).startswith("<details")


def test_a_short_marked_quote_stays_on_one_line():
    assert _printed_html("18 and **0.77**") == "18&nbsp;and&nbsp;<strong>0.77</strong>"


def test_every_marked_quote_of_the_registry_marks_its_tolerance_digits_once():
    """Over the registry: a mark is added only to a claim quote, around the tolerance's digits,
    and removing it gives the quote back."""
    marked = set()
    for c in ledger.claims():
        quote, source = claim_quote(c)
        if source != "claim":
            continue
        tol = resolve_tolerance(c)
        out = mark_compared_number(quote, tol.quote)
        assert out.replace("**", "") == quote.replace("**", ""), c.id
        if out != quote:
            marked.add(c.id)
            assert re.findall(r"\*\*([^*]+)\*\*", out) == [tol.quote.strip()], c.id
    # printed table rows, each quoted whole: SP's Table 2.6 and ATC-10's Table 4.3
    assert {"SP-tab2.6-col3-10", "SP-tab2.6-col4-1", "ATC10-tab4.3-exI-s5-sdN1"} <= marked
