"""ATC-10's quotes of the paper (issue 27, item 5).

Oracle: the transcription of the paper itself. Every ATC-10 claim quotes it, and every piece of
each quote (pieces joined by " [...] ") is a substring of the transcription once whitespace is
collapsed (tables are transcribed with tabs; quotes give their cells joined by single spaces). The
check runs wherever the transcription is beside the checkout (``../shared/papers``) and is skipped
elsewhere; the quote-policy rule itself is tests/test_ledger_printed.py's.
"""

from __future__ import annotations

import re

import pytest

from navcore import ledger
from navcore.claims.quotes import claim_quote
from navcore.papers.atc10_quotes import QUOTES
from navcore.traceability import paper_text_path


def _normalise(text: str) -> str:
    """Whitespace collapsed and math delimiters left out: a quote sets the paper's formulas as
    ``$...$`` math where the transcription left them bare, and the words stay the paper's."""
    return re.sub(r"\s+", " ", text.replace("$", "")).strip()


def test_every_atc10_claim_quotes_the_paper():
    unquoted = [c.id for c in ledger.claims("ATC10") if claim_quote(c)[1] != "claim"]
    assert not unquoted, unquoted
    stale = sorted(set(QUOTES) - {c.id for c in ledger.claims("ATC10")})
    assert not stale, f"quotes of claims that are gone: {stale}"


def test_every_quote_is_in_the_transcription():
    path = paper_text_path("ATC10")
    if not path.exists():
        pytest.skip("the ATC-10 transcription is not beside the checkout")
    text = _normalise(path.read_text(encoding="utf-8"))
    missing = []
    for c in ledger.claims("ATC10"):
        for piece in c.printed.split(" [...] "):
            if _normalise(piece) not in text:
                missing.append(f"{c.id}: {piece[:80]!r}")
    assert not missing, "\n".join(missing)
