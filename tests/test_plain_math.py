"""No formula left as plain text in what a reader sees of the registry (issue 32, item 7).

Claim quantities, notes and tolerance reasons, errata locators, findings and evidence, and input
quantities and reasons render in the claim rows, the ledger, the errata page and the
Assumptions page, where ``$...$`` is set as math (:func:`navcore.ledger.text.html_text`,
:func:`~navcore.ledger.text.tex_text`). Outside those spans, e-notation (``1e-6``), flat
subscripts (``P_DL``, ``sigma0``), spelled-out Greek letters (``rho =``), powers (``^2``),
``sqrt(`` and ASCII operator notation (``[a x]``, ``(x)``) read as program text: they belong
inside ``$...$`` (``$10^{-6}$``, ``$P_{DL}$``, ``$\\sigma_0$``). Quotes of the paper
(``printed``) are the paper's words and are not scanned.

Oracle: the detector is checked on hand-written strings with and without plain math; the
registry's texts are then scanned with it.
"""

from __future__ import annotations

import re

import pytest

from navcore.formatting import PLAIN_LATEX_SOURCE, PLAIN_MATH_PATTERNS, PLAIN_STARRED, math_spans
from navcore.formatting import plain_math as plain_math

#: Plain-text math, by kind: what each pattern finds outside ``$...$``. The one list that the
#: registry's texts (here), the docstrings' prose (``tests/test_docstring_math.py``) and the text
#: of the built book's pages (the release gate ``tools/check_book.py``) are held to.
PATTERNS = PLAIN_MATH_PATTERNS
#: A starred symbol (``h1*``, the hypothesis :math:`h_1^*`), found in the registry's and the
#: inventory's texts (the docstring gate, which reads ``PATTERNS``, has its own to-do list).
STARRED = PLAIN_STARRED
#: LaTeX source outside math (``tau_{i+1}``, ``e^{+jnv}``, ``\\bar``), found there too.
LATEX_SOURCE = PLAIN_LATEX_SOURCE

#: (who, text found) pairs that are legitimately plain, each with its reason. Keep it short.
ALLOWED: dict[tuple[str, str], str] = {}


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("agrees to 1e-6 relative", ["e-notation"]),
        ("agrees to $10^{-6}$ relative", []),
        ("the design P_DL of Table 2.1", ["flat subscript"]),
        ("the design $P_{DL}$ of Table 2.1", []),
        ("H = df/dp at the estimate", ["derivative quotient"]),
        ("$\\mathbf{H} = \\partial \\mathbf{f}/\\partial \\mathbf{p}$ at the estimate", []),
        ("clock parameter sigma0 = 50 ns", ["Greek name"]),
        ("at rho = 0.25", ["Greek name"]),
        ("at $\\rho = 0.25$, with a price of 50 $ more", []),
        ("beyond 10 mm/s^2", ["power"]),
        ("a label 1/sqrt(3b)", ["sqrt("]),
        ("diag(sf) a + [dtheta x] a", ["Greek name", "cross-product bracket"]),
        ("q' = q (x) [0, w]/2", ["(x) product"]),
        ("the zenith C/N0", ["symbol with a flat 0"]),
        ("a definition of hypothesis h1*", ["starred symbol"]),
        ("hypothesis $h_1^*$, the *a* of a PLL* footnote", []),
        ("Sec. 4 opening (tau_{i+1} - tau_i = 1 s)", ["flat subscript", "Greek name", "LaTeX source"]),
        ("the sign of the exponent (e^{+jnv})", ["LaTeX source"]),
        ("the sign of the exponent ($e^{+jnv}$), Sec. 4 ($\\tau_{i+1} - \\tau_i = 1$ s)", []),
        ("the 1-$\\sigma$ noise, 3 dB, 0.5 s, Eq. (3.8.16), 1,2,3 satellites", []),
    ],
)
def test_detector_finds_plain_math_and_passes_set_math(text, kinds):
    assert sorted({k for k, _ in plain_math(text)}) == sorted(kinds)


def _registry_texts() -> list[tuple[str, str, str]]:
    from navcore import ledger
    from navcore.claims.inputs import all_inputs

    texts = []
    for c in ledger.claims():
        texts += [(c.id, "quantity", c.quantity), (c.id, "note", c.note)]
        for name, tol in (("tolerance", c.tolerance), ("oracle tolerance", c.oracle_tolerance)):
            if tol is not None and not callable(tol):  # a callable tolerance is made at evaluation
                texts.append((c.id, name, tol.reason))
    for e in ledger.errata():
        texts += [(e.id, f, getattr(e, f)) for f in ("locator", "finding", "evidence", "no_claim_reason")]
    inputs = all_inputs()
    assert len(inputs) > 100  # every paper module's declarations, loaded by ledger.claims()
    texts += [(i.name, f, getattr(i, f) or "") for i in inputs for f in ("quantity", "reason")]
    return texts


def test_registry_texts_set_every_formula_as_math():
    texts = _registry_texts()
    assert len(texts) > 2000
    found = [
        f"{who} ({field}): {kind} {hit!r}"
        for who, field, text in texts
        for kind, hit in plain_math(text)
        if (who, hit) not in ALLOWED
    ]
    assert not found, "\n".join(found)


#: A one-letter symbol given a value (``K = 100``, ``t = 0``, ``n=100``) outside math: in an input's
#: locator, quantity, reason or reading label it is a formula (``$K = 100$``). Scanned in the inputs'
#: texts only, which quote the paper's parameter statements; claim notes and the inventory are not
#: scanned for it.
SYMBOL_VALUE = re.compile(r"(?<![\w.'/-])[A-Za-z]\s*=\s*[-+]?\d")


def input_plain_math(text: str) -> list[tuple[str, str]]:
    """:func:`plain_math` of an input's text, plus a one-letter symbol given a value outside math."""
    found = plain_math(text)
    for is_math, piece in math_spans(text):
        if not is_math:
            found += [("symbol = value", m.group(0)) for m in SYMBOL_VALUE.finditer(piece)]
    return found


@pytest.mark.parametrize(
    ("text", "kinds"),
    [
        ("Sec. 2.7 ('for a P_DL of 0.9 and 0.999')", ["flat subscript"]),
        ("Sec. 2.7 ('for a $P_{DL}$ of 0.9 and 0.999')", []),
        ("Sec. 3.8 ('when N = 10^5, tau/alpha = 10^-5')", ["Greek name", "power", "symbol = value"]),
        ("Sec. 3.8 ('when $N = 10^5$, $\\tau/\\alpha = 10^{-5}$')", []),
        ("Table 1.1's K = 10, 100 and 1000 rows", ["symbol = value"]),
        ("much larger, say, n=100", ["symbol = value"]),
        ("Table 1.1's $K = 10$, 100 and 1000 rows; a 1-s fix, 3-dB beamwidth, Eq. (2.7.3)", []),
    ],
)
def test_input_detector(text, kinds):
    assert sorted({k for k, _ in input_plain_math(text)}) == sorted(kinds)


def test_input_texts_set_every_formula_as_math():
    """Every input's locator, quantity, reason and reading labels (the Assumptions page, the claim
    rows' inputs, the PDF) set a formula as math: ``Sec. 2.7 ('for a $P_{DL}$ of 0.9 and
    0.999')``, not ``P_DL``; ``$\\tau/\\alpha = 10^{-5}$``, not ``tau/alpha = 10^-5``; ``$K = 1$``.
    Words and the paper's quoted words are unchanged; units (``unit``) stay plain."""
    from navcore import ledger
    from navcore.claims.inputs import all_inputs

    ledger.claims()
    # navcore's own inputs: the test modules' synthetic inputs (declared when a worker collects
    # them) are not shown anywhere
    declared = [i for i in all_inputs() if i.module.startswith("navcore.")]
    texts = [(i.name, f, getattr(i, f) or "") for i in declared for f in ("locator", "quantity", "reason")]
    texts += [(i.name, "reading", str(label)) for i in declared for label, _ in i.readings]
    assert len(texts) > 1400  # three texts of each of the 480 inputs, and the readings' labels
    found = [
        f"{who} ({field}): {kind} {hit!r}"
        for who, field, text in texts
        for kind, hit in input_plain_math(text)
        if (who, hit) not in ALLOWED
    ]
    assert not found, "\n".join(found)


def test_allowlist_entries_still_occur():
    """An allowlist entry whose text is gone is removed, so the list stays short and true."""
    present = {(who, hit) for who, _, text in _registry_texts() for _, hit in plain_math(text)}
    assert set(ALLOWED) <= present


def _inventory_texts() -> list[tuple[str, str, str]]:
    """The Coverage page's inventory of printed items (``paper_items.json``, key ``printed``):
    each item's description, reason, locator and section, which the page shows in its tables.
    Claim ids a reason names are identifiers, not formulas, and are left out of the scan."""
    from navcore import coverage, ledger

    ids = sorted((c.id for c in ledger.claims()), key=len, reverse=True)
    texts = []
    for item in coverage.items():
        for field in ("printed", "reason", "locator", "section"):
            text = getattr(item, field) or ""
            for cid in ids:
                if cid in text:
                    text = text.replace(cid, "")
            texts.append((item.id, field, text))
    return texts


def test_coverage_inventory_sets_every_formula_as_math():
    texts = _inventory_texts()
    assert len(texts) > 3000  # four fields of every printed item of the four papers
    found = [
        f"{who} ({field}): {kind} {hit!r}" for who, field, text in texts for kind, hit in plain_math(text)
    ]
    assert not found, "\n".join(found)


#: LaTeX source outside math: a command (``\frac``, ``\mathbf``), a braced sub- or superscript
#: (``_{n-1}``) or a matrix's alignment. A quote's formulas are the paper's: each one is set as
#: ``$...$`` (or ``$$...$$``) math, never shown as source.
_LATEX_SOURCE = re.compile(r"\\[A-Za-z]{2,}(?![A-Za-z])|[_^]\{|&=|\\\\")
_OPEN_DOLLAR = re.compile(r"(?<!\\)\$(?=\S)")


def quote_problems(quote: str) -> list[str]:
    """What keeps a quote's formulas from being set as math: an odd number of dollar signs, LaTeX
    source or a flat subscript (``p_d``, ``x_D``) outside its ``$...$`` and ``$$...$$``."""
    from navcore.ledger.text import _DISPLAY

    if quote.count("$$") % 2:
        return ["an unbalanced $$"]
    found = []
    for is_math, piece in math_spans(_DISPLAY.sub(lambda m: "$" + m.group(1).strip() + "$", quote)):
        if not is_math:
            if _OPEN_DOLLAR.search(piece):  # a dollar sign that opens math no other one closes
                found.append("an unbalanced $")
            found += [f"LaTeX {m.group(0)!r}" for m in _LATEX_SOURCE.finditer(piece)]
            found += [f"flat subscript {m.group(0)!r}" for m in PATTERNS["flat subscript"].finditer(piece)]
    return found


@pytest.mark.parametrize(
    ("quote", "problems"),
    [
        ("the measurement error \\mathbf{e} .", ["LaTeX '\\\\mathbf'"]),
        ("the measurement error $\\mathbf{e}$ .", []),
        ("a fixed P_{DL}", ["LaTeX '_{'"]),
        ("As t decreases p_d must decrease", ["flat subscript 'p_d'"]),
        (
            "\\gamma_n &= \\frac{a}{b}",
            ["LaTeX '\\\\gamma'", "LaTeX '&='", "LaTeX '\\\\frac'", "flat subscript 'gamma_n'"],
        ),
        ("$\\gamma_n &= \\frac{a}{b}$", []),
        ("= \\frac{2\\pi}{\\lambda} x $$", ["an unbalanced $$"]),
        ("the bound $x_1 + y", ["an unbalanced $", "flat subscript 'x_1'"]),
        ("$$= \\frac{2\\pi}{\\lambda} x $$", []),
        ("a price of 50 $ and $x_1$ and 1.61×10^{-4}", ["LaTeX '^{'"]),
    ],
)
def test_quote_detector(quote, problems):
    assert quote_problems(quote) == problems


def test_every_quote_sets_its_formulas_as_math():
    """Every claim's quote of the paper (the ledger's Printed column, the claim rows, the reports,
    the JSON and CSV exports) sets each formula as math: the transcription left many bare
    (``\\mathbf{H}``, ``p_d``, ``P_{DL}``, a displayed equation cut at one of its ``$$``)."""
    from navcore import ledger
    from navcore.claims.quotes import claim_quote

    quotes = [(c.id, claim_quote(c)) for c in ledger.claims()]
    assert sum(src == "claim" for _, (_, src) in quotes) > 400
    found = [f"{cid}: {p}" for cid, (q, src) in quotes if src == "claim" for p in quote_problems(q)]
    assert not found, "\n".join(found)


@pytest.mark.parametrize(
    ("unit", "shown"),
    [
        ("m/s", "m/s"),
        ("deg/h/√Hz", "deg/h/√Hz"),
        ("m^3/s^2", "m³/s²"),
        ("deg^2", "deg²"),
        ("rad/s/sqrt(s)", "rad/s/√s"),
        ("parts in 10^8", "parts in 10⁸"),
        ("N_T", "$N_{T}$"),
        ("N tau_c / alpha", "$N \\tau_{c} / \\alpha$"),
    ],
)
def test_unit_text_sets_powers_and_formulas(unit, shown):
    """Oracle: each unit as a reader should see it, written out by hand."""
    from navcore.formatting import unit_text

    assert unit_text(unit) == shown


def test_every_unit_is_shown_without_plain_math():
    """Every claim's and input's unit as the book's tables show it (a claim's printed and
    reproduced value, its band, an input's value in a claim's details, the Assumptions page's
    unit column) has no formula left as program text (``m^3/s^2``, ``N tau_c / alpha``); the
    registry keeps the plain unit, which the JSON and CSV exports carry."""
    from navcore import ledger
    from navcore.claims.inputs import all_inputs
    from navcore.formatting import unit_text

    units = {c.unit for c in ledger.claims()} | {i.unit for i in all_inputs()}
    assert len(units) > 50
    assert any(plain_math(u) for u in units)  # the registry still holds some that need setting
    found = [
        f"{u!r} shown as {unit_text(u)!r}: {plain_math(unit_text(u))}"
        for u in units
        if plain_math(unit_text(u))
    ]
    assert not found, "\n".join(found)


def _shown_text(cell_html: str) -> str:
    """The text of an HTML cell a reader sees outside its math and code."""
    import html

    text = re.sub(r'<span class="math[^"]*">.*?</span>|<code[^>]*>.*?</code>', " ", cell_html, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", "", text))


#: Quotes whose words hold what reads as plain math but is the paper's own text, each with why.
QUOTE_ALLOWED = {("KZL-eq17-rank", "A0"): "the paper's name of its master antenna, a label, not a formula"}


def test_quote_markup_is_rendered_not_shown():
    """A quote's markup (a power ``10^8``, emphasis ``**deteriorates**``, ``*a priori*``) is
    rendered in a claim row, HTML and PDF, and its words are kept: no quote shows plain math or
    literal asterisks. Oracle: hand-written cells, then every claim's quote."""
    from navcore import ledger
    from navcore.claims.quotes import claim_quote
    from navcore.ledger.text import _printed_html, _printed_tex

    cell = _printed_html("the performance of the matched filter detector **deteriorates**")
    assert cell == "the performance of the matched filter detector <strong>deteriorates</strong>"
    cell = _printed_html("requires a short-term oscillator stability better than 5 parts in 10^8")
    assert cell.endswith('5 parts in <span class="math notranslate nohighlight">\\(10^{8}\\)</span>')
    assert _printed_html("the correction of the *a priori* quaternion").count("<em>a priori</em>") == 1
    assert _printed_tex("a detector **deteriorates** as $x^2$ grows, 5 parts in 10^8") == (
        "a detector \\textbf{deteriorates} as $x^2$ grows, 5 parts in $10^{8}$"
    )
    assert _printed_html("a PLL* footnote and h1* stay") == "a PLL* footnote and h1* stay"
    quotes = [(c.id, claim_quote(c)) for c in ledger.claims()]
    quotes = [(cid, q) for cid, (q, src) in quotes if src == "claim"]
    assert len(quotes) > 400
    found = [
        f"{cid}: {kind} {hit!r}"
        for cid, q in quotes
        for kind, hit in plain_math(_shown_text(_printed_html(q)))
        if kind != "LaTeX source" and (cid, hit) not in QUOTE_ALLOWED
    ]
    assert not found, "\n".join(found)
