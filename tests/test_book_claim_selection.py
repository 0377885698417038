"""Pages select their claims tables by printed item or by table name: the selection, and every
claim on one page.

A claims table names the printed items its claims check (``items=["Table 4.3"]``): every claim
whose locator names one of them is shown, so a new claim of an existing item joins its page with
no change to the page. A table that shows a part of an item's claims has a name on its page
(``table="heading"``), which its claims declare (``Claim(table="heading")``): a new claim joins
it by its declaration. The page scan below reads each table's selection from the pages' source
(literal ``items``, ``table``, ``ids`` and ``prefix`` arguments) without evaluating any claim.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from navcore import book, ledger
from navcore.ledger import Claim, printed

ROOT = Path(__file__).resolve().parents[1]


def _claim(cid: str, locator: str, paper: str = "SP", table: str = "", page: str = "sp/p") -> Claim:
    value, tol = printed("17.67")
    return Claim(
        id=cid, paper=paper, locator=locator, quantity="a number", published=value, unit="",
        compute=lambda: 17.67, tolerance=tol, expected_status="reproduced", note="synthetic",
        discussed_in=page, table=table,
    )  # fmt: skip


def _calls(text: str):
    """Each ``claims_table(...)`` call of a page's source, parsed (the call node)."""
    for m in re.finditer(r"claims_table\(", text):
        i, depth = m.end(), 1
        while depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        yield ast.parse("f(" + text[m.end() : i]).body[0].value


def table_selection(call: ast.Call) -> list[str] | None:
    """The ids a call selects, read from its literal arguments; ``None`` when not literal."""
    try:
        args = [ast.literal_eval(a) for a in call.args]
        kw = {k.arg: ast.literal_eval(k.value) for k in call.keywords}
    except ValueError:
        return None
    paper = kw.get("paper", args[0] if args else None)
    if "items" in kw or "table" in kw or "ids" in kw:
        chosen = book.select_claims(paper, kw["items"]) if "items" in kw else []
        if "table" in kw:
            chosen += [i for i in book.table_claims(paper, kw["table"]) if i not in chosen]
        return chosen + [ledger.claim(i).id for i in kw.get("ids", ()) if ledger.claim(i).id not in chosen]
    return [c.id for c in ledger.claims(paper, kw.get("prefix", args[1] if len(args) > 1 else None))]


def page_selections(folder: Path) -> tuple[dict[str, list[str]], set[str]]:
    """Claim id -> the pages whose tables select it; and the pages with a table not literal."""
    shown: dict[str, list[str]] = {}
    opaque: set[str] = set()
    for path in sorted(folder.rglob("*.md")):
        page = path.relative_to(folder).with_suffix("").as_posix()
        for call in _calls(path.read_text()):
            ids = table_selection(call)
            if ids is None:
                opaque.add(page)
                continue
            for cid in ids:
                shown.setdefault(cid, []).append(page)
    return shown, opaque


@pytest.fixture
def registry(monkeypatch):
    """A synthetic SP ledger (no paper module is read): claims in registry order."""
    claims = [
        _claim("SP-a", "Table 2.6"),
        _claim("SP-b", "Eq. (2.1), Table 2.6", table="sums"),
        _claim("SP-c", "Fig. 2.1"),
        _claim("SP-d", "Sec. 2.5"),
        _claim("SP-e", "Sec. 2.8", table="sums"),
        _claim("SP-f", "Sec. 2.8", table="bounds", page="sp/q"),
        _claim("SP-g", "Sec. 2.4", table="sums"),
    ]

    def fake(paper=None, prefix=None):
        return tuple(c for c in claims if paper in (None, c.paper) and c.id.startswith(prefix or ""))

    def one(cid):
        return next(c for c in claims if c.id == cid)

    monkeypatch.setattr(ledger, "claims", fake)
    monkeypatch.setattr(ledger, "claim", one)
    return claims


def test_an_item_selects_its_claims_in_the_order_of_the_items(registry):
    """Oracle: the synthetic locators read by hand."""
    assert book.select_claims("SP", ["Table 2.6"]) == ["SP-a", "SP-b"]
    assert book.select_claims("SP", ["Fig. 2.1", "Table 2.6"]) == ["SP-c", "SP-a", "SP-b"]
    assert book.select_claims("SP", ["Eq. (2.1)", "Table 2.6"]) == ["SP-b", "SP-a"]  # once only
    assert book.select_claims("SP", ["Sec. 2.5"]) == ["SP-d"]


def test_an_item_that_selects_nothing_or_no_paper_is_an_error(registry):
    with pytest.raises(ValueError, match="names"):
        book.select_claims("SP", ["Table 2.7"])
    with pytest.raises(ValueError, match="paper"):
        book.select_claims(None, ["Table 2.6"])
    with pytest.raises(ValueError, match="not one"):
        book.item_key("Tables 2.6 and 2.7")


def test_typed_ids_follow_the_items_claims(registry):
    call = next(_calls('book.claims_table("SP", items=["Fig. 2.1"], ids=["SP-d", "SP-c"])'))
    assert table_selection(call) == ["SP-c", "SP-d"]


def test_a_table_selects_the_claims_that_name_it_in_the_ledgers_order(registry):
    """Oracle: the synthetic claims' ``table`` fields read by hand, in the registry's order."""
    assert book.table_claims("SP", "sums") == ["SP-b", "SP-e", "SP-g"]
    assert book.table_claims("SP", "bounds") == ["SP-f"]


def _selected(monkeypatch, **kw):
    """The ids ``claims_table`` selects, in order, with the evaluation and the table replaced."""
    monkeypatch.setattr(ledger, "evaluate_claim", lambda cid: cid)
    monkeypatch.setattr(book, "LedgerTable", lambda evals, **_: list(evals))
    return book.claims_table(root="", **kw)


def test_a_table_follows_the_items_claims_once_each(registry, monkeypatch):
    """Items' claims first, then the table's not among them (``SP-b`` checks Table 2.6 and names
    the table: shown once, with the item); then typed ids not among them. Oracle: by hand."""
    sums = ["SP-b", "SP-e", "SP-g"]
    assert _selected(monkeypatch, paper="SP", table="sums") == sums
    assert _selected(monkeypatch, paper="SP", items=["Table 2.6"], table="sums") == ["SP-a", *sums]
    both = _selected(monkeypatch, paper="SP", items=["Fig. 2.1"], table="bounds", ids=["SP-f", "SP-d"])
    assert both == ["SP-c", "SP-f", "SP-d"]
    call = next(_calls('book.claims_table("SP", items=["Table 2.6"], table="sums")'))
    assert table_selection(call) == ["SP-a", "SP-b", "SP-e", "SP-g"]


def test_a_table_that_selects_nothing_or_no_paper_is_an_error(registry, monkeypatch):
    with pytest.raises(ValueError, match="table='sum' selects no claim of SP"):
        book.table_claims("SP", "sum")
    with pytest.raises(ValueError, match="table='sum' selects no claim of SP"):
        _selected(monkeypatch, paper="SP", items=["Table 2.6"], table="sum")
    with pytest.raises(ValueError, match="paper"):
        book.table_claims(None, "sums")


def test_a_table_name_is_one_pages(registry):
    """A table is one page's: the same name on claims of two pages is refused, not merged."""
    registry.append(_claim("SP-h", "Sec. 2.9", table="bounds", page="sp/p"))
    with pytest.raises(ValueError, match="several pages"):
        book.table_claims("SP", "bounds")


def test_a_claim_names_its_table_in_kebab_case_on_its_page():
    with pytest.raises(ValueError, match="kebab-case"):
        _claim("SP-x", "Sec. 2.9", table="Fig 5")
    with pytest.raises(ValueError, match="discussed_in"):
        _claim("SP-x", "Sec. 2.9", table="fig5-bounds", page="")
    assert _claim("SP-x", "Sec. 2.9").table == ""


def test_no_page_types_the_claims_of_a_table():
    """No page's ``claims_table`` call names claims by ``ids`` (by keyword or as the third
    positional argument): a table selects its claims by printed item, id prefix or table name,
    so that adding a claim to an existing table touches its paper module only, never the page
    (issue 33). ``ids`` remains for notebooks outside the book. Oracle: the pages' sources."""
    typed = []
    for path in sorted((ROOT / "book").rglob("*.md")):
        for call in _calls(path.read_text()):
            if len(call.args) > 2 or any(k.arg == "ids" for k in call.keywords):
                typed.append(f"{path.relative_to(ROOT)}: {ast.unparse(call)[:80]}")
    assert not typed, "tables that type claim ids:\n" + "\n".join(typed)


def test_a_new_claim_of_an_existing_item_lands_on_the_page_that_selects_the_item(registry, tmp_path):
    (tmp_path / "sp").mkdir()
    (tmp_path / "sp" / "p.md").write_text('book.claims_table("SP", items=["Table 2.6"])\n')
    (tmp_path / "sp" / "q.md").write_text('book.claims_table("SP", items=["Fig. 2.1", "Sec. 2.5"])\n')
    registry.append(_claim("SP-new", "Table 2.6, last row"))
    shown, opaque = page_selections(tmp_path)
    assert shown == {
        "SP-a": ["sp/p"],
        "SP-b": ["sp/p"],
        "SP-new": ["sp/p"],
        "SP-c": ["sp/q"],
        "SP-d": ["sp/q"],
    }
    assert not opaque


def test_every_claim_is_shown_on_one_page_its_own():
    """No claim is shown by two tables; one a literal table shows is shown on the page its record
    names (``discussed_in``); one that no literal table shows is on a page whose table selects
    in code (a list built from a paper module; for a claim that names no page, a page of its
    paper's chapter)."""
    shown, opaque = page_selections(ROOT / "book")
    twice = {c: p for c, p in shown.items() if len(p) > 1}
    assert not twice, f"claims shown by two tables: {twice}"
    elsewhere = {c.id: (c.discussed_in, shown[c.id][0]) for c in ledger.claims()
                 if c.id in shown and c.discussed_in and c.discussed_in not in shown[c.id]}  # fmt: skip
    assert not elsewhere, f"claims shown on another page than their own: {elsewhere}"
    chapters = {page.split("/")[0] for page in opaque}
    lost = [
        c.id
        for c in ledger.claims()
        if c.id not in shown
        and (c.discussed_in not in opaque if c.discussed_in else c.paper.lower() not in chapters)
    ]
    assert not lost, f"claims no table shows: {lost}"
