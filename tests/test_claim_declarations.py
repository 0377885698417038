"""What every claim declares beside its computation is what the record holds, read without
evaluating a claim (a second): published value, unit, tolerance, locator, kind, expected
verdict, whether it computes, and the page that derives it. The paper modules build their claims
when imported, so this is the test that their claim helpers' mutants meet first
(``tools/mutation.py``'s papers package runs it first: mutmut gives the code that runs at import
to the first test it runs)."""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import pytest

from navcore import ledger

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import claim_values


def test_every_claim_declares_what_the_record_holds() -> None:
    """Oracle: the record (``tests/claim_values.json``), written from the claims' evaluations."""
    recorded = claim_values.load()
    moved = []
    for claim in ledger.claims():
        if claim.id not in recorded:
            moved.append(f"{claim.id}: not recorded")
            continue
        was = {k: recorded[claim.id][k] for k in claim_values.DECLARED}
        moved += [f"{claim.id}: {d}" for d in claim_values.differences(was, claim_values.declared(claim))]
    assert not moved, "\n".join(moved[:20]) + "\n(python tools/claim_values.py --update after a meant change)"


@pytest.mark.parametrize("field", claim_values.DECLARED)
def test_a_declared_field_that_moves_is_seen(field: str) -> None:
    """A claim whose declaration changes in any one field fails the check above. Oracle: a
    synthetic claim declared twice, the second time with the field changed by hand."""
    base = ledger.Claim(
        id="WF-test-declared", paper="WF", locator="Eq. (1)", quantity="q", published=1.5, unit="m",
        compute=lambda: 1.5, tolerance=ledger.EXACT, expected_status="reproduced", note="n",
    )  # fmt: skip
    change = {
        "published": {"published": 1.6},
        "unit": {"unit": "M"},
        "tolerance": {"tolerance": ledger.Tolerance(reason="r", abs=0.05, policy="printed-digits")},
        "locator": {"locator": "Eq. (2)"},
        "kind": {"kind": "cross-check"},
        "expected_status": {"expected_status": "consistent"},
        "computes": {"compute": None, "expected_status": "not-reproducible"},
        "discussed_in": {"discussed_in": "wf/01-emitter-location"},
    }[field]
    other = dataclasses.replace(base, **change)
    moved = claim_values.differences(claim_values.declared(base), claim_values.declared(other))
    assert [m.split(":")[0] for m in moved if m.startswith(field)] == [field]
