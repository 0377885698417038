"""WF's, KZL's and SP's quotes of the papers (issue 27, item 5).

Oracle: the transcriptions of the papers themselves. Every WF and KZL claim quotes its paper, and so
does every SP claim of the modules whose quotes :mod:`navcore.papers.sp_quotes` holds; every piece of
each quote (pieces joined by " [...] ") is a substring of the transcription once whitespace is
collapsed (tables are transcribed with tabs). The check runs wherever the transcriptions are beside
the checkout (``../shared/papers``) and is skipped elsewhere; the quote-policy rule itself is
tests/test_ledger_printed.py's.
"""

from __future__ import annotations

import re

import pytest

from navcore import ledger
from navcore.claims.quotes import claim_quote
from navcore.papers import kzl_quotes, sp_quotes, wf_quotes
from navcore.traceability import paper_text_path

QUOTES = {"WF": wf_quotes.QUOTES, "KZL": kzl_quotes.QUOTES, "SP": sp_quotes.QUOTES}


def _normalise(text: str) -> str:
    """Whitespace collapsed and math delimiters left out: a quote sets the paper's formulas as
    ``$...$`` math where the transcription left them bare, and the words stay the paper's."""
    return re.sub(r"\s+", " ", text.replace("$", "")).strip()


@pytest.mark.parametrize("paper", ["WF", "KZL"])
def test_every_claim_quotes_the_paper(paper):
    unquoted = [c.id for c in ledger.claims(paper) if claim_quote(c)[1] != "claim"]
    assert not unquoted, unquoted


@pytest.mark.parametrize("paper", ["WF", "KZL", "SP"])
def test_no_quote_of_a_claim_that_is_gone(paper):
    stale = sorted(set(QUOTES[paper]) - {c.id for c in ledger.claims(paper)})
    assert not stale, f"quotes of claims that are gone: {stale}"


@pytest.mark.parametrize("paper", ["WF", "KZL", "SP"])
def test_every_quote_is_in_the_transcription(paper):
    path = paper_text_path(paper)
    if not path.exists():
        pytest.skip(f"the {paper} transcription is not beside the checkout")
    text = _normalise(path.read_text(encoding="utf-8"))
    missing = []
    for c in ledger.claims(paper):
        if paper == "SP" and c.id not in QUOTES["SP"]:
            continue  # quoted where it is made (flyby and missions)
        for piece in c.printed.split(" [...] "):
            if _normalise(piece) not in text:
                missing.append(f"{c.id}: {piece[:80]!r}")
    assert not missing, "\n".join(missing)
