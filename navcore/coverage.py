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
    apart; covered when a registered input or claim reads it;
``context``
    printed text with nothing a computation could check (a quotation of another report, a
    judgement of cost or practicality, a remark on the analysis's scope, a modelling
    assumption stated as such): counted apart, each with its reason.

Each item names the claims that check it (``claims``) or says why it has none (``reason``).
:func:`problems` lists what breaks that rule, and :func:`summary` gives the percentages the
coverage page shows.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

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

CATEGORIES = ("quantity", "statement", "equation", "input", "context")
COUNTED = ("quantity", "statement")  # the quantitative items of the coverage percentage

#: Snapshot of every paper's items (:func:`navcore.traceability.paper_items_from_text`) and of
#: the printed-item inventory (key ``"printed"``), committed so that the guard also runs where
#: the papers' texts are not beside the checkout (a clean CI machine).
#: ``tests/test_traceability.py`` fails when it differs from the texts; rewrite it with
#: ``python -c "from navcore import traceability; traceability.write_items_snapshot()"``.
ITEMS_SNAPSHOT = Path(__file__).resolve().parent / "papers" / "paper_items.json"


@dataclass(frozen=True)
class Item:
    """One printed item of a paper and how the ledger covers it.

    Attributes
    ----------
    id : str
        Stable item id, starting with the paper key (``"KZL-p001"``).
    paper : str
        Paper key.
    section : str
        The paper's section the item stands in (``"Sec. 1"``).
    locator : str
        Where exactly, in the paper's words (the section when nothing finer applies).
    printed : str
        What the paper prints, in short.
    category : str
        One of :data:`CATEGORIES` (module docstring).
    claims : tuple of str
        Ids of the ledger claims that check it; empty when it has none.
    reason : str
        Why it has no claim (required then).

    Examples
    --------
    >>> it = Item(id="KZL-p999", paper="KZL", section="Sec. 1", locator="Sec. 1",
    ...           printed="a speed ratio of 76", category="quantity")
    >>> it.covered
    False
    """

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
    """The inventory of printed items (of ``paper`` if given), in the paper's order.

    Read from the committed paper snapshot; nothing is computed.

    Parameters
    ----------
    paper : str or None, optional
        Paper key (``"KZL"``); ``None`` for every paper.

    Returns
    -------
    tuple of Item
        The items, paper by paper in the snapshot's order; empty when the snapshot is
        absent or has no such paper.

    Examples
    --------
    >>> its = items("KZL")
    >>> all(i.paper == "KZL" for i in its), {i.category for i in its} <= set(CATEGORIES)
    (True, True)
    """
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
    """What breaks the coverage rule: unknown claims, items with neither claim nor reason, duplicates.

    Loads every paper's claims and errata (importing the paper modules; nothing is
    evaluated).

    Returns
    -------
    list of str
        One message per problem: a duplicate item id, an unknown category, an item with
        neither claim nor reason, an item naming an unknown claim, an erratum with neither
        claim nor ``no_claim_reason``. Empty when the coverage is complete.

    Examples
    --------
    >>> problems()
    []
    """
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
    """Counts for ``paper``: quantitative items and covered ones, equations, inputs, errata.

    Parameters
    ----------
    paper : str
        Paper key (``"KZL"``).

    Returns
    -------
    dict of str to Any
        ``paper``; ``items`` (quantities and statements), ``covered`` (those with a claim)
        and ``percent`` (covered share, 0-100 %); ``equations``, ``equations_checked`` and
        ``equations_reasoned`` (without a claim, with a reason); ``inputs``; ``context``;
        ``errata`` and ``errata_with_claims``.

    Examples
    --------
    >>> s = summary("KZL")
    >>> s["covered"] <= s["items"], 0.0 <= s["percent"] <= 100.0
    (True, True)
    """
    from navcore import ledger

    its = items(paper)
    counted = [i for i in its if i.category in COUNTED]
    eqs = [i for i in its if i.category == "equation"]
    inputs = [i for i in its if i.category == "input"]
    context = [i for i in its if i.category == "context"]
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
        "context": len(context),
        "errata": len(errs),
        "errata_with_claims": sum(bool(e.claims) for e in errs),
    }


def section_rows(paper: str) -> list[dict[str, Any]]:
    """Per section of ``paper``: quantitative items, covered, equations checked, left without a claim.

    Parameters
    ----------
    paper : str
        Paper key (``"KZL"``).

    Returns
    -------
    list of dict of str to Any
        One row per section, in the paper's order: ``section``, ``items`` (quantities and
        statements), ``covered``, ``equations``, ``checked`` (equations with a claim) and
        ``left`` (the :class:`Item` objects of the section without a claim).

    Examples
    --------
    >>> rows = section_rows("KZL")
    >>> sum(r["items"] for r in rows) == summary("KZL")["items"]
    True
    """
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
    """One row per paper: quantitative items, covered, percentage, equations, errata (for the book).

    Returns
    -------
    pandas.DataFrame
        One row per paper of :data:`~navcore.claims.declarations.PAPERS` (from :func:`summary`),
        columns ``Paper``, ``Printed items``, ``With a claim``, ``Covered`` (a percentage as
        text), ``Numbered equations``, ``Checked by a claim``, ``Errata`` and ``Errata with
        a claim``.

    Examples
    --------
    >>> summary_frame()["Paper"].tolist()
    ['WF', 'SP', 'ATC10', 'KZL']
    """
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
    """Per section of ``paper``: items, covered, and each item left without a claim with its reason.

    Parameters
    ----------
    paper : str
        Paper key (``"KZL"``).

    Returns
    -------
    pandas.DataFrame
        The rows of :func:`section_rows`, columns ``Section``, ``Printed items``, ``With a
        claim``, ``Equations``, ``Checked`` and ``Left without a claim, and why`` (each item
        left with its reason, or a dash).

    Examples
    --------
    >>> sections_frame("KZL").columns.tolist()[:3]
    ['Section', 'Printed items', 'With a claim']
    """
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
