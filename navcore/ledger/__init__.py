"""The verification ledger: every paper's claims gathered, evaluated, rendered and summarised.

Schema and policy: see the book's introduction and its ledger page. A paper module declares
its claims, errata and inputs with :mod:`navcore.claims` (the types and the verdict rule);
the ledger re-exports those names, so a reader may write ``from navcore.ledger import
Claim`` as well. From anywhere::

    from navcore import ledger
    ledger.evaluations(paper="SP")
"""

from navcore import claims as _claims
from navcore.claims import *  # noqa: F403 (the claim types re-exported; their one list is navcore.claims.__all__)
from navcore.ledger.registry import (
    cache_dir,
    claim,
    claims,
    counts,
    errata,
    erratum,
    evaluate_claim,
    evaluations,
    paper_modules,
    validate_registry,
)

__all__ = [
    *_claims.__all__,
    "cache_dir",
    "claim",
    "claims",
    "counts",
    "errata",
    "erratum",
    "evaluate_claim",
    "evaluations",
    "paper_modules",
    "validate_registry",
]
