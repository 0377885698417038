"""Claims, errata, inputs and the verdict rule: what a paper module declares.

A paper module (``navcore.papers``) states, for each number the paper publishes, a
:class:`~navcore.claims.declarations.Claim` with its tolerance
(:mod:`~navcore.claims.tolerances`) and expected verdict, each erratum as an
:class:`~navcore.claims.declarations.Erratum`, and its inputs in an
:class:`~navcore.claims.inputs.InputSet`; :func:`~navcore.claims.runs.evaluate` derives a
claim's verdict by the rule of :mod:`~navcore.claims.verdict`, into an
:class:`~navcore.claims.evaluation.Evaluation`. The
registry of every paper's claims, its rendering and its summaries are the ledger's
(``navcore.ledger``), which re-exports these names. Typical use from a paper module::

    from navcore.claims import Claim, Erratum, Tolerance, printed

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
"""

from navcore.claims.declarations import (
    ERRATUM_BASES,
    KINDS,
    PAPERS,
    RELATIONS,
    STATUSES,
    TEXT_ONLY_CAVEAT,
    Claim,
    Erratum,
    claim_errata,
)
from navcore.claims.evaluation import Evaluation
from navcore.claims.inputs import Input, InputSet, band_ahead, for_each_band_run, input_cache
from navcore.claims.quotes import claim_quote, quote_policies, with_quotes
from navcore.claims.runs import evaluate
from navcore.claims.tolerances import (
    EXACT,
    POLICIES,
    PROSE_WORDS,
    Tolerance,
    figure_reading,
    monte_carlo,
    printed,
    prose,
)
from navcore.claims.verdict import BAND_FACTOR

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
    "claim_errata",
    "claim_quote",
    "evaluate",
    "figure_reading",
    "for_each_band_run",
    "input_cache",
    "monte_carlo",
    "printed",
    "prose",
    "quote_policies",
    "with_quotes",
]
