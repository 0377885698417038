"""The traceability index is whole: paper item -> navcore function -> tests -> book pages.

The guard: it fails when a model function claims a paper item that no page of its chapter
shows, when a claim's locator, a decorator or a book label names an item that the paper's
text does not contain (except the items listed, with reasons, in ``OCR_LOST``), or when a
display-equation label follows neither naming rule.
"""

from __future__ import annotations

import pytest

from navcore import trace, traceability


def test_the_index_has_no_broken_link():
    problems = traceability.problems()
    assert problems == [], "\n".join(problems)


def test_every_claim_locator_names_known_items():
    """Each claim's locator names at least one item, and the index knows every item named."""
    from navcore import ledger

    index = traceability.build_index()
    for claim in ledger.claims():
        refs = traceability.claim_refs(claim.locator, claim.paper)
        assert refs, f"{claim.id}: locator {claim.locator!r} names no equation, table, figure or section"
        for ref in refs:
            assert ref in index.entries and claim.id in index.entries[ref].claims


def test_equations_checked_under_a_neighbour_show_the_inventorys_claims():
    """Oracle: the coverage inventory. An equation it counts as checked has claims in the index
    even when the claim is filed under a neighbouring equation (WF Eq. (1), checked by the claim
    on Eq. (8)); claims named by a locator are kept as they are."""
    from navcore import coverage, ledger
    from navcore.trace import Ref

    index = traceability.build_index()
    for item in coverage.items():
        if item.category != "equation" or not item.claims:
            continue
        for ref in traceability.claim_refs(item.locator, item.paper):
            if ref in index.entries:
                assert index.entries[ref].claims, f"{ref}: the inventory names {item.claims}, the index none"
    assert index.entries[Ref("WF", "1")].claims == ["WF-eq8-norm"]
    located = [c.id for c in ledger.claims() if Ref("WF", "8") in traceability.claim_refs(c.locator, c.paper)]
    assert index.entries[Ref("WF", "8")].claims == located


def test_papers_items_are_available_for_the_guard():
    """The guard knows every paper's items: from the texts, or the committed snapshot."""
    missing = [p for p in trace.PAPER_KEYS if traceability.paper_items(p) is None]
    assert missing == []
    assert "2.4.2" in traceability.paper_items("ATC10")
    assert "Table 2.5" in traceability.paper_items("SP")
    assert "Sec. IV.D" in traceability.paper_items("WF")


@pytest.mark.parametrize("paper", trace.PAPER_KEYS)
def test_items_snapshot_matches_the_papers_texts(paper):
    """Oracle: the items extracted from the paper's text now; a stale snapshot fails."""
    import json

    from_text = traceability.paper_items_from_text(paper)
    if from_text is None:
        pytest.skip(f"the text of {paper} is absent at {traceability.paper_text_path(paper)}")
    snapshot = json.loads(traceability.ITEMS_SNAPSHOT.read_text())[paper]
    assert sorted(from_text) == snapshot


def test_ocr_lost_items_are_really_absent():
    """Oracle: each exemption is checked against the paper's text; a stale one fails."""
    for text in traceability.OCR_LOST:
        paper, item = text.split(" ", 1)
        known = traceability.paper_items(paper)
        assert item not in known, f"{text} is in the paper's text: remove it from OCR_LOST"


@pytest.mark.parametrize(
    ("text", "items"),
    [
        ("Eqs. (10)-(11)", {"10", "11"}),
        ("Eqs. (2.4.1)-(2.4.3)", {"2.4.1", "2.4.2", "2.4.3"}),
        ("(A.15)-(A.18)", {"A.15", "A.16", "A.17", "A.18"}),
        ("Table 2.6 and Fig. 2.1, Sec. 2.5, Appendix C", {"Table 2.6", "Fig. 2.1", "Sec. 2.5", "Appendix C"}),
        ("Eq. (13)", {"13"}),
        ("Sec. 4.6, rule (1)", {"Sec. 4.6", "Rule 1"}),
        ("Sec. 4.6 rules (3)-(4)", {"Sec. 4.6", "Rule 3", "Rule 4"}),
        ("Sec. 4.6, Example II", {"Sec. 4.6", "Example II"}),
        ("Examples I and II of Table 4.3", {"Example I", "Example II", "Table 4.3"}),
    ],
)
def test_items_in_text(text, items):
    """Oracle: the items written out by hand."""
    assert traceability.items_in_text(text, dotted=True) == items


@pytest.mark.parametrize("bad", ["13", "XX 13", "WF", "WF thirteen", "WF Table", 13])
def test_bad_refs_raise(bad):
    with pytest.raises(ValueError, match="ref"):
        trace.parse_ref(bad)


def test_decorator_returns_the_same_function_and_registers_it():
    def model(x: float) -> float:
        """A model."""
        return 2 * x

    decorated = trace.implements("WF 13", "ATC10 A18", "SP Table 2.6")(model)
    assert decorated is model and decorated(2.0) == 4.0 and decorated.__doc__ == "A model."
    impl = trace._REGISTRY[f"{model.__module__}.{model.__qualname__}"]
    assert impl.refs == (trace.Ref("WF", "13"), trace.Ref("ATC10", "A.18"), trace.Ref("SP", "Table 2.6"))
    del trace._REGISTRY[impl.name]
    with pytest.raises(ValueError, match="refs"):
        trace.implements()


def test_model_functions_are_decorated():
    """Every model package has decorated functions, and each record points to a real function."""
    import importlib

    impls = traceability.all_implementations()
    packages = {i.module.split(".")[1] for i in impls}
    assert {"estimation", "inertial", "gnss", "detection", "location"} <= packages
    for impl in impls:
        obj = importlib.import_module(impl.module)
        for part in impl.qualname.split("."):
            obj = getattr(obj, part)
        assert callable(obj)
