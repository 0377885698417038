"""Coverage of the papers by the ledger: every printed item, its claims or the reason it has none.

The inventory of each paper's printed items lives in the committed paper snapshot
(``navcore/papers/paper_items.json``, key ``"printed"``), so the count is checked on a
machine without the papers' texts. An item is one thing a reader could look up:

``quantity``
    a printed number, a table cell, a figure value stated in the text;
``statement``
    a checkable statement (an ordering, a trend, "at least 15 dB");
``equation``
    a numbered equation (covered by a claim of kind ``statement`` that checks it, or a
    reason such as "a definition");
``input``
    a number the paper gives as an input (parameter tables, scenario values): counted
    apart; covered when a registered input or claim reads it.

Each item names the claims that check it (``claims``) or says why it has none (``reason``).
:func:`problems` lists what breaks that rule, and :func:`summary` gives the percentages the
coverage page shows.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from typing import Any

from navcore.traceability import ITEMS_SNAPSHOT

__all__ = [
    "CATEGORIES",
    "Item",
    "items",
    "problems",
    "section_rows",
    "sections_frame",
    "summary",
    "summary_frame",
]

CATEGORIES = ("quantity", "statement", "equation", "input")
COUNTED = ("quantity", "statement")  # the quantitative items of the coverage percentage


@dataclass(frozen=True)
class Item:
    """One printed item of a paper and how the ledger covers it."""

    id: str
    paper: str
    section: str
    locator: str
    printed: str
    category: str
    claims: tuple[str, ...] = ()
    reason: str = ""

    @property
    def covered(self) -> bool:
        return bool(self.claims)


@cache
def _snapshot() -> dict[str, Any]:
    return json.loads(ITEMS_SNAPSHOT.read_text()) if ITEMS_SNAPSHOT.exists() else {}


def items(paper: str | None = None) -> tuple[Item, ...]:
    """The inventory of printed items (of ``paper`` if given), in the paper's order."""
    printed = _snapshot().get("printed", {})
    out = []
    for p, rows in printed.items():
        if paper is not None and p != paper:
            continue
        for r in rows:
            out.append(
                Item(
                    id=r["id"],
                    paper=p,
                    section=r["section"],
                    locator=r.get("locator", r["section"]),
                    printed=r["printed"],
                    category=r["category"],
                    claims=tuple(r.get("claims", ())),
                    reason=r.get("reason", ""),
                )
            )
    return tuple(out)


def problems() -> list[str]:
    """What breaks the coverage rule: unknown claims, items with neither claim nor reason, duplicates."""
    from navcore import ledger

    known = set()
    for c in ledger.claims():
        known.add(c.id)
        known.update(c.aliases)
    out = []
    seen: set[str] = set()
    for it in items():
        if it.id in seen:
            out.append(f"{it.id}: duplicate item id")
        seen.add(it.id)
        if it.category not in CATEGORIES:
            out.append(f"{it.id}: category {it.category!r} is not one of {CATEGORIES}")
        if not it.claims and not it.reason.strip():
            out.append(f"{it.id} ({it.locator}: {it.printed}): no claim and no reason")
        for cid in it.claims:
            if cid not in known:
                out.append(f"{it.id}: names unknown claim {cid!r}")
    for e in ledger.errata():
        if not e.claims and not getattr(e, "no_claim_reason", ""):
            out.append(f"erratum {e.id}: no claim and no reason")
    return out


def summary(paper: str) -> dict[str, Any]:
    """Counts for ``paper``: quantitative items and covered ones, equations, inputs, errata."""
    from navcore import ledger

    its = items(paper)
    counted = [i for i in its if i.category in COUNTED]
    eqs = [i for i in its if i.category == "equation"]
    inputs = [i for i in its if i.category == "input"]
    errs = ledger.errata(paper)
    return {
        "paper": paper,
        "items": len(counted),
        "covered": sum(i.covered for i in counted),
        "percent": 100.0 * sum(i.covered for i in counted) / len(counted) if counted else 0.0,
        "equations": len(eqs),
        "equations_checked": sum(i.covered for i in eqs),
        "equations_reasoned": sum((not i.covered) and bool(i.reason.strip()) for i in eqs),
        "inputs": len(inputs),
        "errata": len(errs),
        "errata_with_claims": sum(bool(e.claims) for e in errs),
    }


def section_rows(paper: str) -> list[dict[str, Any]]:
    """Per section of ``paper``: quantitative items, covered, equations checked, left without a claim."""
    rows: dict[str, dict[str, Any]] = {}
    for it in items(paper):
        row = rows.setdefault(
            it.section,
            {"section": it.section, "items": 0, "covered": 0, "equations": 0, "checked": 0, "left": []},
        )
        if it.category in COUNTED:
            row["items"] += 1
            row["covered"] += it.covered
        elif it.category == "equation":
            row["equations"] += 1
            row["checked"] += it.covered
        if not it.covered:
            row["left"].append(it)
    return list(rows.values())


def summary_frame() -> Any:
    """One row per paper: quantitative items, covered, percentage, equations, errata (for the book)."""
    import pandas as pd

    from navcore.ledger import PAPERS

    rows = []
    for p in PAPERS:
        s = summary(p)
        rows.append(
            {
                "Paper": p,
                "Printed items": s["items"],
                "With a claim": s["covered"],
                "Covered": f"{s['percent']:.0f} %" if s["items"] else "—",
                "Numbered equations": s["equations"],
                "Checked by a claim": s["equations_checked"],
                "Errata": s["errata"],
                "Errata with a claim": s["errata_with_claims"],
            }
        )
    return pd.DataFrame(rows)


def sections_frame(paper: str) -> Any:
    """Per section of ``paper``: items, covered, and each item left without a claim with its reason."""
    import pandas as pd

    rows = []
    for r in section_rows(paper):
        left = "; ".join(f"{i.printed} ({i.reason})" for i in r["left"]) or "—"
        rows.append(
            {
                "Section": r["section"],
                "Printed items": r["items"],
                "With a claim": r["covered"],
                "Equations": r["equations"],
                "Checked": r["checked"],
                "Left without a claim, and why": left,
            }
        )
    return pd.DataFrame(rows)
