"""One test per ledger claim, named by its id: the claim must pass its own check.

The check depends on the declared status (see ``navcore.ledger.core``): a reproduced or
consistent claim must agree with the published value within its tolerance; a discrepant claim
must still disagree and must match its independent oracle; a not-reproducible claim whose band
is too wide to decide must still derive that verdict; a claim that computes nothing is skipped
with its note as the reason.
"""

from __future__ import annotations

import pytest

from navcore import ledger

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
        pytest.skip(f"not reproducible: {result.claim.note}")
    assert result.passes, (
        f"{claim_id} ({result.claim.locator}, {result.claim.quantity}): {result.detail}; "
        f"published {result.claim.relation} {result.claim.published} {result.claim.unit}, "
        f"reproduced {result.reproduced!r}, tolerance {result.claim.tolerance.describe()}"
    )


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
