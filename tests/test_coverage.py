"""Every printed item of each paper has a claim or a written reason (issue 17).

Oracle: the inventory of printed items kept in the paper snapshot, swept from the papers'
texts section by section; the test needs neither the texts nor the book.
"""

from __future__ import annotations

import pytest

from navcore import coverage, ledger


@pytest.mark.parametrize("paper", list(ledger.PAPERS))
def test_every_item_has_a_claim_or_a_reason(paper):
    mine = [p for p in coverage.problems() if p.startswith(paper + "-") or p.startswith(f"erratum {paper}-")]
    assert mine == [], "\n".join(mine)


@pytest.mark.parametrize("paper", list(ledger.PAPERS))
def test_at_least_95_percent_of_the_printed_items_are_claims(paper):
    s = coverage.summary(paper)
    assert s["items"] > 0, f"{paper} has no inventory"
    assert s["percent"] >= 95.0, f"{paper}: {s['covered']} of {s['items']} printed items have a claim"


def test_claims_named_by_items_exist_and_items_are_unique():
    assert not [p for p in coverage.problems() if "unknown claim" in p or "duplicate" in p]


@pytest.mark.parametrize("paper", list(ledger.PAPERS))
def test_items_stand_in_sections_of_the_paper(paper):
    """Oracle: the sections and appendices found in the paper's text (or its committed snapshot).

    A number the transcription read as an equation tag ("(0.1)") is not an item: its pseudo-section
    ("Sec. 0.1") is in no heading of the paper."""
    from navcore import traceability

    known = traceability.paper_items(paper)
    lost = {text.split(" ", 1)[1] for text in traceability.OCR_LOST if text.startswith(paper + " ")}
    stray = sorted({i.section for i in coverage.items(paper)} - known - lost - {"Abstract"})
    assert stray == [], f"{paper}: sections not in the paper: {stray}"


def test_reasons_are_one_style():
    """The Coverage page sets each reason in parentheses after the item: a reason starts in lower
    case (or with a name such as "Table 2.4"), ends without a period or a closing parenthesis and
    names no erratum that the ledger lacks."""
    import re

    errata = {e.id for e in ledger.errata()}
    bad = []
    for it in coverage.items():
        r = it.reason
        if not r:
            continue
        if r[0].isupper() and not r.startswith(("Table ", "Fig. ", "Sec. ", "Ref. ", "App")):
            bad.append(f"{it.id}: starts in upper case: {r[:40]!r}")
        if r.endswith((".", ")")):
            bad.append(f"{it.id}: ends with {r[-1]!r}")
        named = re.findall(r"erratum ([A-Z][\w.-]*\w)", r)
        bad += [f"{it.id}: names erratum {e}, which the ledger lacks" for e in named if e not in errata]
        if "OCR" in r or "OCR" in it.printed:
            bad.append(f"{it.id}: 'OCR' in reader text")
    assert bad == [], "\n".join(bad)
