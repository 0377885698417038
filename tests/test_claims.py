"""One test per ledger claim, named by its id: the claim must pass its own check.

The check depends on the declared status (see ``navcore.claims.verdict``): a reproduced or
consistent claim must agree with the published value within its tolerance; a discrepant claim
must still disagree and must match its independent oracle; a not-reproducible claim whose band
is too wide to decide must still derive that verdict; a claim that computes nothing is skipped
with its note as the reason.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import pytest

from navcore import ledger

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
import claim_values

CLAIM_IDS = [c.id for c in ledger.claims()]


def _module_group(claim_id: str) -> str:
    """The paper module that defines the claim: its claims share their model runs (one
    flyby, one Monte Carlo, one mission), so they run on one pytest-xdist worker
    (``--dist loadgroup``), which computes each shared run once."""
    from navcore.ledger import registry

    return registry._CLAIM_MODULE[claim_id]


@pytest.mark.parametrize(
    "claim_id", [pytest.param(i, marks=pytest.mark.xdist_group(_module_group(i))) for i in CLAIM_IDS]
)
def test_claim(claim_id: str) -> None:
    result = ledger.evaluate_claim(claim_id)
    if result.claim.compute is None:
        # skipped only where the claim expects it: a claim whose computation went missing
        # (expected reproduced, say) fails here instead of being skipped
        assert result.passes, f"{claim_id}: {result.detail}"
        pytest.skip(f"not reproducible: {result.claim.note}")
    assert result.passes, (
        f"{claim_id} ({result.claim.locator}, {result.claim.quantity}): {result.detail}; "
        f"published {result.claim.relation} {result.claim.published} {result.claim.unit}, "
        f"reproduced {result.reproduced!r}, tolerance {_tolerance_text(result)}"
    )


RECORDED = claim_values.load()


@pytest.mark.parametrize(
    "claim_id", [pytest.param(i, marks=pytest.mark.xdist_group(_module_group(i))) for i in CLAIM_IDS]
)
def test_claim_reproduces_the_recorded_values(claim_id: str) -> None:
    """The claim's value, band, readings, one-at-a-time band runs and oracle value, and what it
    declares (published value, unit, tolerance, locator, kind, expected verdict, computation,
    page), are those recorded (numbers to a relative 1e-6): a change that moves a reproduced
    number, whether or not its verdict moves, fails here until the record is written again, and
    the record's diff shows it in review. A regression check: the record says that a number
    moved, the claim's own check says whether it still agrees."""
    assert claim_id in RECORDED, f"{claim_id} is not recorded: python tools/claim_values.py --update"
    now = claim_values.values(ledger.evaluate_claim(claim_id))
    moved = claim_values.differences(RECORDED[claim_id], now)
    assert not moved, (
        f"{claim_id}: its reproduced numbers moved ({'; '.join(moved)}). If the change is meant, "
        "write the record again (python tools/claim_values.py --update) and review its diff"
    )


def test_the_record_holds_exactly_the_ledger_claims() -> None:
    """No claim left unrecorded, no recorded claim that is gone (renamed or removed)."""
    assert sorted(RECORDED) == sorted(CLAIM_IDS)


def _tolerance_text(result: ledger.Evaluation) -> str:
    """The tolerance in short, as the ledger resolved it (a callable tolerance included).

    ``result.tolerance`` is what the ledger resolved before computing; when resolving failed
    (status ``error``) it is ``None`` and the claim's own tolerance is described if it is a
    :class:`~navcore.ledger.Tolerance`, else said to be unresolved.
    """
    tol = result.tolerance if result.tolerance is not None else result.claim.tolerance
    return tol.describe() if isinstance(tol, ledger.Tolerance) else "not resolved (see the detail)"


def test_registry_is_consistent() -> None:
    """Unique ids, every discrepant claim names a registered erratum, errata name real claims."""
    ledger.validate_registry(list(ledger.claims()), list(ledger.errata()))
    for c in ledger.claims():
        if c.status == "discrepant":
            e = ledger.erratum(c.erratum)
            assert e.paper == c.paper


def test_paper_modules_hold_claims_and_errata_of_the_right_type() -> None:
    """CLAIMS and ERRATA, where a paper module defines them, hold Claim and Erratum objects.

    Modules with only published inputs or scenarios (tables, trajectories) define neither.
    """
    import importlib

    from navcore.ledger import Claim, Erratum

    for name in ledger.paper_modules():
        module = importlib.import_module(name)
        assert all(isinstance(c, Claim) for c in getattr(module, "CLAIMS", [])), name
        assert all(isinstance(e, Erratum) for e in getattr(module, "ERRATA", [])), name


def test_failure_message_describes_a_callable_tolerance() -> None:
    """Issue 31, item 6: a claim whose tolerance is a callable (resolved by the ledger before
    computing) must get a failure message, not an AttributeError that hides its verdict.
    Oracle: the tolerance written out by hand (half a unit of "12.5" is ±0.05)."""
    value, tol = ledger.printed("12.5")
    claim = ledger.Claim(
        id="SP-test-callable-tolerance", paper="SP", locator="Eq. (1)", quantity="q",
        published=value, unit="m", compute=lambda: 13.0, tolerance=lambda: tol,
        expected_status="reproduced", note="a synthetic claim whose tolerance is a callable",
    )  # fmt: skip
    result = ledger.evaluate(claim)
    assert not result.passes and result.status == "discrepant"
    assert _tolerance_text(result) == "±0.05"
    broken = ledger.evaluate(dataclasses.replace(claim, tolerance=lambda: 1.0))
    assert broken.status == "error" and _tolerance_text(broken) == "not resolved (see the detail)"


def test_a_claim_that_lost_its_computation_fails_and_one_that_has_none_is_skipped(monkeypatch) -> None:
    """A claim expected to reproduce whose computation is gone (a mutant set ``compute=None``
    and the test skipped it as "not reproducible") fails; one that expects not-reproducible is
    skipped with its note. Oracle: the two outcomes written out by hand."""
    claim = ledger.Claim(
        id="WF-test-no-computation", paper="WF", locator="Eq. (1)", quantity="q", published=1.0,
        unit="m", compute=None, tolerance=ledger.EXACT, expected_status="reproduced",
        note="a synthetic claim without its computation",
    )  # fmt: skip
    monkeypatch.setattr(ledger, "evaluate_claim", lambda claim_id: ledger.evaluate(claim))

    def outcome() -> str:  # a skip must not escape: it would skip this test, not fail it
        try:
            test_claim(claim.id)
        except AssertionError as exc:
            return f"failed: {exc}"
        except pytest.skip.Exception as exc:
            return f"skipped: {exc}"
        return "passed"

    assert outcome().startswith("failed: WF-test-no-computation")
    claim = dataclasses.replace(claim, expected_status="not-reproducible")
    assert outcome() == "skipped: not reproducible: a synthetic claim without its computation"
