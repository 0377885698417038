"""The verification ledger: every published number as a claim, checked by navcore.

Schema and policy: see the book's introduction and its ledger page. Typical use
from a paper module::

    from navcore.ledger import Claim, Erratum, Tolerance, printed

    value, tol = printed("17.67")
    CLAIMS = [
        Claim(
            id="SP-fig2.1-omega0",
            paper="SP",
            locator="Fig. 2.1",
            quantity="loop natural frequency for a 90 deg peak error",
            published=value,
            unit="rad/s",
            compute=lambda: natural_frequency_for_peak(...),
            tolerance=tol,
            expected_status="reproduced",
            note="phase converted with ...",
        )
    ]

and from anywhere::

    from navcore import ledger
    ledger.evaluations(paper="SP")
"""

from navcore.ledger.core import (
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
    Tolerance,
    claim_errata,
    claim_quote,
    evaluate,
    figure_reading,
    monte_carlo,
    printed,
    prose,
    quote_policies,
)
from navcore.ledger.inputs import Input, InputSet, band_ahead, for_each_band_run, input_cache
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
