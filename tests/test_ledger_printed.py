"""The registry's quotes of the papers, read by rule (issue 27, items 5 and 7).

Nothing is evaluated here: the claims are loaded and their quoted printed text is read.

* every claim that quotes the paper has a tolerance policy its words admit
  (:func:`~navcore.claims.quotes.quote_policies`: "approximately", "about", "~", "of the order
  of", "roughly", "nearly" -> prose; "read from the figures" -> figure-reading; otherwise the
  printed digits, exact for integers and truth values, a run count's Monte Carlo);
* a claim with no quote of the paper yet is listed in ``printed_quote_todo.txt`` (a new claim
  without a quote fails), and a listed claim that now has one must leave the list;
* the reasoned exceptions to "published means printed" are each still needed.
"""

from __future__ import annotations

from pathlib import Path

from navcore import ledger
from navcore.claims.declarations import resolve_tolerance
from navcore.claims.quotes import claim_quote, quote_has_number, quote_policies
from navcore.ledger.allowlists import PUBLISHED_NOT_IN_QUOTE

TODO = Path(__file__).with_name("printed_quote_todo.txt")


def _todo() -> list[str]:
    return [
        line.strip() for line in TODO.read_text().splitlines() if line.strip() and not line.startswith("#")
    ]


def test_every_quoted_claim_has_the_policy_its_words_admit():
    wrong = []
    for c in ledger.claims():
        tol = resolve_tolerance(c)
        quote, source = claim_quote(c, tol)
        if source == "none":
            continue
        allowed = quote_policies(quote, published=c.published, locator=c.locator)
        if tol.policy not in allowed:
            wrong.append(f"{c.id}: {quote!r} admits {allowed}, the tolerance is {tol.policy}")
    assert not wrong, "\n".join(wrong)


def test_claims_without_a_quote_are_the_listed_to_do_and_no_more():
    todo = _todo()
    assert len(todo) == len(set(todo)), "a claim is listed twice"
    unquoted = {c.id for c in ledger.claims() if claim_quote(c)[1] in ("none", "word")}
    missing = sorted(unquoted - set(todo))
    stale = sorted(set(todo) - unquoted)
    assert not missing, f"claims without a quote of the paper (give them printed=...): {missing}"
    assert not stale, f"listed as to-do but quoted now, or gone (remove from {TODO.name}): {stale}"


def test_every_exception_to_published_means_printed_is_still_needed():
    by_id = {c.id: c for c in ledger.claims()}
    for claim_id, reason in PUBLISHED_NOT_IN_QUOTE.items():
        assert reason.strip(), claim_id
        c = by_id.get(claim_id)
        assert c is not None, f"{claim_id} is not in the ledger"
        quote, source = claim_quote(c)
        assert not c.is_statement and source in ("claim", "digits"), claim_id
        assert not quote_has_number(quote, float(c.published)), f"{claim_id}: its quote prints it now"
