"""The verification ledger: every paper's claims gathered, evaluated, rendered and summarised.

Schema and policy: see the book's introduction and its ledger page. A paper module declares
its claims, errata and inputs with :mod:`navcore.claims` (the types and the verdict rule);
the ledger re-exports those names, so a reader may write ``from navcore.ledger import
Claim`` as well. From anywhere::

    from navcore import ledger
    ledger.evaluations(paper="SP")
"""

from navcore.claims import (
    BAND_FACTOR,
    ERRATUM_BASES,
    EXACT,
    KINDS,
    PAPERS,
    POLICIES,
    PROSE_WORDS,
    RELATIONS,
    STATUSES,
    TEXT_ONLY_CAVEAT,
    Claim,
    Erratum,
    Evaluation,
    Input,
    InputSet,
    Tolerance,
    band_ahead,
    claim_errata,
    claim_quote,
    evaluate,
    figure_reading,
    for_each_band_run,
    input_cache,
    monte_carlo,
    printed,
    prose,
    quote_policies,
)
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
    "BAND_FACTOR",
    "ERRATUM_BASES",
    "EXACT",
    "KINDS",
    "PAPERS",
    "POLICIES",
    "PROSE_WORDS",
    "RELATIONS",
    "STATUSES",
    "TEXT_ONLY_CAVEAT",
    "Claim",
    "Erratum",
    "Evaluation",
    "Input",
    "InputSet",
    "Tolerance",
    "band_ahead",
    "cache_dir",
    "claim",
    "claim_errata",
    "claim_quote",
    "claims",
    "counts",
    "errata",
    "erratum",
    "evaluate",
    "evaluate_claim",
    "evaluations",
    "figure_reading",
    "for_each_band_run",
    "input_cache",
    "monte_carlo",
    "paper_modules",
    "printed",
    "prose",
    "quote_policies",
    "validate_registry",
]
