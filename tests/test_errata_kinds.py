"""Every registered erratum declares what kind of slip it is, from a small vocabulary."""

from __future__ import annotations

import pytest

from navcore import ledger
from navcore.claims.declarations import ERRATUM_KINDS, Erratum


def test_every_erratum_has_a_kind_in_the_vocabulary():
    errata = ledger.errata()
    assert errata, "the registry holds no errata"
    missing = [e.id for e in errata if e.kind not in ERRATUM_KINDS]
    assert not missing, f"errata without a kind of {list(ERRATUM_KINDS)}: {missing}"


def test_every_kind_is_documented_on_the_erratum():
    doc = Erratum.__doc__ or ""
    for kind, meaning in ERRATUM_KINDS.items():
        assert f"``{kind}``" in doc, kind
        assert meaning.strip(), kind


def test_unknown_kind_raises_naming_kind():
    with pytest.raises(ValueError, match=r"Erratum\.kind must be one of"):
        Erratum(
            id="WF-E9",
            paper="WF",
            locator="Eq. (1)",
            printed="p",
            finding="f",
            evidence="e",
            kind="misprint",
            basis="computed",
        )


def test_known_kind_is_accepted():
    e = Erratum(
        id="WF-E9",
        paper="WF",
        locator="Eq. (1)",
        printed="p",
        finding="f",
        evidence="e",
        kind="typography",
        basis="computed",
    )
    assert e.kind == "typography"


def test_missing_kind_raises():
    """Every erratum says what kind of slip it is: leaving the kind out is an error."""
    with pytest.raises(ValueError, match=r"Erratum\.kind must be one of"):
        Erratum(
            id="WF-E9",
            paper="WF",
            locator="Eq. (1)",
            printed="p",
            finding="f",
            evidence="e",
            basis="computed",
        )
