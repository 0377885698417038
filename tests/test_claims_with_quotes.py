"""Tests of navcore.claims.quotes.with_quotes, the one function that fills the claims' quotes."""

from __future__ import annotations

import pytest

from navcore.claims import Claim, with_quotes


def _statement(claim_id: str, quote: str = "") -> Claim:
    return Claim.statement(
        id=claim_id, locator="Eq. (1)", quantity="q", compute=lambda: True, note="a test claim", printed=quote
    )


def test_fills_only_blank_quotes_of_listed_ids_in_order():
    """Oracle: the expected quotes written out by hand, claim by claim."""
    claims = [
        _statement("WF-a"),
        _statement("WF-b", "its own words"),
        _statement("WF-c"),
        _statement("WF-d", "  "),
    ]
    out = with_quotes(claims, {"WF-a": "a = b", "WF-b": "ignored", "WF-d": "d = e"})
    assert [c.id for c in out] == ["WF-a", "WF-b", "WF-c", "WF-d"]
    assert [c.printed for c in out] == ["a = b", "its own words", "", "d = e"]
    assert out[1] is claims[1] and out[2] is claims[2]  # unchanged claims are the same objects
    assert claims[0].printed == ""  # the claims given are not modified
    assert with_quotes([], {"WF-a": "a"}) == []


def test_rejects_a_non_mapping_and_a_non_claim():
    """Validation: the argument is named as the caller spelled it."""
    with pytest.raises(TypeError, match="quotes"):
        with_quotes([_statement("WF-a")], [("WF-a", "q")])  # type: ignore[arg-type]
    with pytest.raises(TypeError, match=r"claims\[1\]"):
        with_quotes([_statement("WF-a"), "WF-b"], {})  # type: ignore[list-item]
