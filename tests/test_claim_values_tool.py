"""The record of what every claim reproduces (``tests/claim_values.json``) and its tool: the
comparison the claim tests make, the writer and the command line, on synthetic claims (the claim
tests themselves compare the registry's claims with the record)."""

from __future__ import annotations

import dataclasses
import json
import sys
from pathlib import Path

from navcore import ledger

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import claim_values


def test_the_record_comparison_catches_each_kind_of_move() -> None:
    """The comparison the claim tests use. Oracle: each case decided by hand (a move of 1e-5 is
    seen, 1e-9 is round-off; a statement that flips, a band end, a reading's value, a reading
    that appears, one band run of one input, an oracle's value; zero against round-off)."""
    cv = claim_values
    base = {
        "reproduced": 2.0, "band": [1.0, 3.0], "readings": [[2.0, [1.0, 3.0]]],
        "sensitivity": [["P.m.x", [[0.5, 1.0], [2.0, 3.0]]], ["P.m.y", [["a", 2.0]]]], "oracle": None,
    }  # fmt: skip
    assert cv.differences(base, base) == []
    assert cv.differences(base, {**base, "reproduced": 2.0 * (1 + 1e-9)}) == []
    assert cv.differences(base, {**base, "reproduced": 2.0 * (1 + 1e-5)}) == [
        f"reproduced: 2.0 -> {2.0 * (1 + 1e-5)!r}"
    ]
    assert cv.differences(base, {**base, "band": [1.0, 3.1]}) == ["band: [1.0, 3.0] -> [1.0, 3.1]"]
    assert cv.differences(base, {**base, "band": None}) == ["band: [1.0, 3.0] -> None"]
    assert len(cv.differences(base, {**base, "readings": [[2.5, [1.0, 3.0]]]})) == 1
    assert len(cv.differences(base, {**base, "readings": [*base["readings"], [2.0, None]]})) == 1
    moved = {**base, "sensitivity": [["P.m.x", [[0.5, 1.0], [2.0, 3.5]]], ["P.m.y", [["a", 2.0]]]]}
    assert cv.differences(base, moved) == [
        "sensitivity to P.m.x: [[0.5, 1.0], [2.0, 3.0]] -> [[0.5, 1.0], [2.0, 3.5]]"
    ]
    other_point = {**base, "sensitivity": [["P.m.x", [[0.5, 1.0], [2.0, 3.0]]], ["P.m.y", [["b", 2.0]]]]}
    assert cv.differences(base, other_point) == ["sensitivity to P.m.y: [['a', 2.0]] -> [['b', 2.0]]"]
    assert cv.differences({**base, "oracle": 4.0}, {**base, "oracle": 4.1}) == ["oracle: 4.0 -> 4.1"]
    assert cv.differences({**base, "unit": "ppm"}, {**base, "unit": "PPM"}) == ["unit: 'ppm' -> 'PPM'"]
    tol = {"rel": 0.0, "abs": 0.05, "reason": "printed", "policy": "printed-digits"}
    assert cv.differences({**base, "tolerance": tol}, {**base, "tolerance": {**tol, "abs": 0.5}}) != []
    statement = {**base, "reproduced": True, "band": [False, True]}
    assert cv.differences(statement, {**statement, "reproduced": False}) == ["reproduced: True -> False"]
    assert cv.differences(statement, {**statement, "reproduced": 1.0}) != []  # a number is no truth value
    assert cv.differences({**base, "reproduced": 0.0}, {**base, "reproduced": 1e-15}) == []
    assert cv.differences({**base, "reproduced": "Infinity"}, {**base, "reproduced": 1e308}) != []


def test_the_record_is_written_from_evaluations(tmp_path) -> None:
    """The record written from two evaluations reads back as their values, one claim a line in
    the order of their ids. Oracle: the two claims' values written out by hand."""
    cv = claim_values
    a = ledger.Claim(
        id="WF-test-a", paper="WF", locator="Eq. (1)", quantity="q", published=1.5, unit="m",
        compute=lambda: 1.5, tolerance=ledger.EXACT, expected_status="reproduced", note="a synthetic claim",
    )  # fmt: skip
    b = dataclasses.replace(a, id="WF-test-b", compute=lambda: 2.0, published=2.0)
    path = tmp_path / "values.json"
    assert cv.write({c.id: cv.values(ledger.evaluate(c)) for c in (b, a)}, path) == 2
    exact = {"abs": 0.0, "rel": None, "reason": "exact: an integer count or a logical statement",
             "policy": "exact", "loose_abs": None}  # fmt: skip
    plain = {"band": None, "readings": [], "sensitivity": [], "oracle": None, "unit": "m", "tolerance": exact,
             "locator": "Eq. (1)", "kind": "reproduction", "expected_status": "reproduced",
             "computes": True, "discussed_in": ""}  # fmt: skip
    assert cv.load(path) == {
        "WF-test-a": {"reproduced": 1.5, "published": 1.5, **plain},
        "WF-test-b": {"reproduced": 2.0, "published": 2.0, **plain},
    }
    lines = path.read_text().splitlines()
    assert [line.split(":")[0].strip() for line in lines[3:5]] == ['"WF-test-a"', '"WF-test-b"']


def _synthetic(cid: str, value: float):
    return ledger.Claim(
        id=cid, paper="WF", locator="Eq. (1)", quantity="q", published=value, unit="m",
        compute=lambda: value, tolerance=ledger.EXACT, expected_status="reproduced", note="a synthetic claim",
    )  # fmt: skip


def test_the_command_writes_the_record_of_every_evaluation(tmp_path, monkeypatch, capsys) -> None:
    """``--update`` evaluates the ledger (here two synthetic claims in place of the registry's,
    on every core as asked) and writes their values; anything else prints the usage and exits
    with 2. Oracle: the record read back, written out by hand."""
    from navcore.ledger import registry

    asked = {}

    def evaluations(**kw):
        asked.update(kw)
        return [ledger.evaluate(_synthetic("WF-test-b", 2.0)), ledger.evaluate(_synthetic("WF-test-a", 1.5))]

    monkeypatch.setattr(registry, "evaluations", evaluations)
    path = tmp_path / "tests" / "claim_values.json"
    path.parent.mkdir()
    monkeypatch.setattr(claim_values, "RECORD", path)
    monkeypatch.setattr(claim_values, "ROOT", tmp_path)
    assert claim_values.main(["--update"]) == 0
    assert asked == {"n_jobs": -1}
    assert capsys.readouterr().out == "recorded the values of 2 claims in tests/claim_values.json\n"
    assert sorted(json.loads(path.read_text())["claims"]) == ["WF-test-a", "WF-test-b"]
    for argv in ([], ["--update", "x.json"], ["--check"]):
        assert claim_values.main(argv) == 2
        assert capsys.readouterr().err == "usage: python tools/claim_values.py --update\n"


def test_the_tolerances_are_those_documented() -> None:
    """1e-6 relative (no paper prints more than five significant digits) and 1e-12 absolute (the
    smallest value the ledger reproduces is about 1e-5): a move just past either is seen."""
    assert claim_values.RTOL == 1e-6 and claim_values.ATOL == 1e-12
    assert claim_values.same(1.0, 1.0 + 0.9e-6) and not claim_values.same(1.0, 1.0 + 1.1e-6)
    assert claim_values.same(0.0, 0.9e-12) and not claim_values.same(0.0, 1.1e-12)
    assert claim_values.same([1, "a"], [1, "a"]) and not claim_values.same([1, "a"], [1, "b"])
    assert not claim_values.same(None, 0.0) and not claim_values.same([1.0], 1.0)
    long = list(range(200))
    assert claim_values._short(long).endswith("...") and len(claim_values._short(long)) == 300
    assert claim_values._short([1]) == "[1]"
