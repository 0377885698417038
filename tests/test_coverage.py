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
