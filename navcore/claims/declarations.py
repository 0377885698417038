"""What a paper module declares: the :class:`Claim`, the :class:`Erratum`, and their vocabularies.

A :class:`Claim` is one number (or statement) that a paper publishes, with a function that
makes navcore compute it. Its published value is typed once, with its locator; its
reproduced value is never typed: it is whatever ``compute()`` returns. The claim declares
its ``kind``, its tolerance (fixed by how the paper printed the number, through a named
policy of :mod:`navcore.claims.tolerances`) and the verdict it expects;
:func:`~navcore.claims.runs.evaluate` derives the verdict from the computation, the tolerance
and the provenance of every input the computation read (:mod:`navcore.claims.inputs`) by the
rule of :mod:`navcore.claims.verdict`, and the ledger fails where the two differ.

The paper keys (:data:`PAPERS`), the verdicts (:data:`STATUSES`), the kinds (:data:`KINDS`),
the printed relations (:data:`RELATIONS`) and the kinds and bases of a finding
(:data:`ERRATUM_KINDS`, :data:`ERRATUM_BASES`) are declared here.

Findings and their basis
------------------------
An :class:`Erratum` is a finding; its ``basis`` (:data:`ERRATUM_BASES`) is ``computed``
(a number the paper prints is wrong: a recomputation under its stated inputs, or its own
other printed numbers, contradict it) or ``text-only`` (the text of a formula or a word is at
fault, and the paper's printed numbers follow the correct form, or none depends on it). The
book works from transcriptions, so a text-only finding cannot tell a misprint from a
transcription slip (:data:`TEXT_ONLY_CAVEAT`). A claim's ``errata`` are the errata it is
evidence for: the one it names and those that name it.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from navcore.claims.inputs import declaring
from navcore.claims.tolerances import EXACT, POLICIES, Tolerance

__all__ = [
    "ERRATUM_BASES",
    "ERRATUM_KINDS",
    "KINDS",
    "PAPERS",
    "RELATIONS",
    "STATUSES",
    "TEXT_ONLY_CAVEAT",
    "Claim",
    "Erratum",
    "claim_errata",
]


PAPERS: dict[str, str] = {
    "WF": "Wu & Fowler, Application of MEMS for Improved Emitter Location Accuracy",
    "SP": "Schmidt & Phillips, INS/GPS Integration Architecture Performance Comparisons",
    "ATC10": "Schneider, Stiglitz & Eckberg, Surveillance Aspects of the AATMS (ATC-10)",
    "KZL": "Knedlik, Zhou & Loffeld, Position and Attitude Estimation for Bistatic SAR",
}


STATUSES = ("reproduced", "consistent", "inconsistent", "discrepant", "not-reproducible")


KINDS = ("reproduction", "cross-check", "statement", "fit")


RELATIONS = ("=", "<", "<=", ">", ">=")


Status = Literal["reproduced", "consistent", "inconsistent", "discrepant", "not-reproducible"]


Kind = Literal["reproduction", "cross-check", "statement", "fit"]


Relation = Literal["=", "<", "<=", ">", ">="]


#: What kind of slip an erratum is, judged from what the paper prints and what the book finds
#: (never from a verdict). Each erratum has exactly one kind: the first that fits, in this order.
ERRATUM_KINDS: dict[str, str] = {
    "typography": "a misprinted digit, sign, symbol, subscript, exponent or cross-reference, "
    "where the paper's own later results or its other equations show the intended form",
    "units": "a unit, scale or quantity confusion: a number in the wrong unit, a factor of two "
    "between one- and two-sided densities, a quantity named as another (variance for mean "
    "square, bandwidth for natural frequency, peak for average power)",
    "convention": "a formula that is right under another sign, frame or ordering convention "
    "than the one the paper states (a skew matrix of the opposite sign, a quaternion product "
    "in the other order, a specific force of the opposite sign)",
    "derivation": "an algebra or derivation error: a step that does not follow, a wrong "
    "exponent or factor carried through, a bound or formula that is wrong as derived",
    "unstated-assumption": "a result that holds only under an assumption the paper does not "
    "state (independence, commuting covariances, a symmetric density, an accelerating flight), "
    "or states but does not meet where it applies it",
    "inconsistent-numbers": "numbers that contradict each other across tables, figures and "
    "text, or that the paper's own stated inputs do not give",
    "overstatement": "a statement in words (always, slightly, tight, about, larger than) "
    "that the paper's own model and numbers do not support",
}


#: The basis of an erratum's evidence (the ledger's rules, "The basis of an erratum").
ERRATUM_BASES: dict[str, str] = {
    "computed": "a number the paper prints is wrong: a recomputation under its stated inputs, or its "
    "own other printed numbers, contradict it",
    "text-only": "the text of a formula or a word is at fault, and the paper's printed numbers follow "
    "the correct form (or none depends on it)",
}


#: Said once wherever text-only findings are listed or counted (not repeated per erratum).
TEXT_ONLY_CAVEAT = (
    "The book works from transcriptions of the papers, so a text-only finding (the text of a "
    "formula or a word, on which the printed numbers do not depend) cannot tell a misprint in "
    "the paper from a slip in its transcription."
)


_ID_RE = re.compile(r"^(WF|SP|ATC10|KZL)-[A-Za-z0-9][A-Za-z0-9._+-]*$")

#: A claims table's name (:attr:`Claim.table`): kebab-case, ``"heading"``, ``"fig5-bounds"``.
_TABLE_RE = re.compile(r"^[a-z0-9]+(-[a-z0-9]+)*$")


@dataclass(frozen=True, kw_only=True)
class Erratum:
    """A suspected error in a paper, with the book's finding and its evidence.

    Parameters
    ----------
    id : str
        Stable identifier such as ``"ATC10-E2-erf-argument"``; starts with the paper key.
    paper : str, optional
        ``WF``, ``SP``, ``ATC10`` or ``KZL``; by default the key the id starts with, and if
        given it must be that key.
    locator : str
        Where it stands (``"Eq. (2.8.1)"``).
    printed : str
        What the paper prints.
    finding : str
        What the book finds instead.
    evidence : str
        How the book knows: the independent derivation, cross-table check or Monte Carlo.
    claims : tuple of str
        Ids of the ledger claims it affects.
    discussed_in : str
        The book page (docname, e.g. ``"atc10/02-jamming"``) where it is discussed.
    no_claim_reason : str
        Why no ledger claim can check it (an erratum of wording with no number, say); every
        erratum has a claim or this reason.
    kind : str
        What kind of slip it is, one of :data:`ERRATUM_KINDS`, judged from ``printed``,
        ``finding`` and ``evidence`` (never from a verdict); required (an erratum without a
        kind raises ``ValueError``). The kinds:

        ``typography``
            a misprinted digit, sign, symbol, subscript, exponent or cross-reference, where
            the paper's own later results or other equations show the intended form.
        ``units``
            a unit, scale or quantity confusion: a number in the wrong unit, a factor of two
            between one- and two-sided densities, a quantity named as another.
        ``convention``
            a formula that is right under another sign, frame or ordering convention than the
            one the paper states.
        ``derivation``
            an algebra or derivation error: a step that does not follow, a wrong exponent or
            factor carried through, a bound that is wrong as derived.
        ``unstated-assumption``
            a result that holds only under an assumption the paper does not state, or states
            but does not meet where it applies it.
        ``inconsistent-numbers``
            numbers that contradict each other across tables, figures and text, or that the
            paper's own stated inputs do not give.
        ``overstatement``
            a statement in words (always, slightly, tight, larger than) that the paper's own
            model and numbers do not support.
    basis : str
        What the evidence rests on, one of :data:`ERRATUM_BASES`; required:

        ``computed``
            a number the paper prints is wrong: a recomputation under its stated inputs, or
            its own other printed numbers, contradict it.
        ``text-only``
            the text of a formula or a word is at fault, and the paper's printed numbers
            follow the correct form (or none depends on it). The book works from
            transcriptions, so such a finding cannot tell a misprint from a transcription
            slip; the pages that list findings say so once (:data:`TEXT_ONLY_CAVEAT`).

    Raises
    ------
    ValueError
        If ``paper`` is unknown or not the id's key, a text field is empty, ``kind`` is not one of
        :data:`ERRATUM_KINDS` or ``basis`` not one of :data:`ERRATUM_BASES`.

    Notes
    -----
    Constructing an erratum indexes it by id for :func:`claim_errata` (the last one
    constructed under an id wins), so a claim's JSON can name the errata it is evidence for.

    Examples
    --------
    >>> e = Erratum(id="SP-E9-doc", paper="SP", locator="Eq. (2.4.2)", printed="a + b",
    ...             finding="a - b", evidence="the derivation in the book", kind="typography",
    ...             basis="text-only", no_claim_reason="a sign with no printed number to check")
    >>> e.kind, e.basis, e.claims
    ('typography', 'text-only', ())
    """

    id: str
    paper: str = ""
    locator: str
    printed: str
    finding: str
    evidence: str
    claims: tuple[str, ...] = ()
    discussed_in: str = ""
    no_claim_reason: str = ""
    kind: str = ""
    basis: str = ""

    def __post_init__(self) -> None:
        if not self.paper:
            object.__setattr__(self, "paper", self.id.split("-", 1)[0])
        if self.paper not in PAPERS:
            raise ValueError(f"Erratum.paper must be one of {list(PAPERS)}, got {self.paper!r}")
        if not self.id.startswith(self.paper + "-"):
            raise ValueError(f"Erratum.id must start with '{self.paper}-', got {self.id!r}")
        if self.kind not in ERRATUM_KINDS:
            raise ValueError(
                f"Erratum.kind must be one of {list(ERRATUM_KINDS)}, got {self.kind!r} (erratum {self.id!r})"
            )
        if self.basis not in ERRATUM_BASES:
            raise ValueError(
                f"Erratum.basis must be one of {list(ERRATUM_BASES)}, got {self.basis!r} "
                f"(erratum {self.id!r})"
            )
        for name in ("id", "locator", "printed", "finding", "evidence"):
            if not str(getattr(self, name)).strip():
                raise ValueError(f"Erratum.{name} must not be empty (erratum {self.id!r})")
        _ERRATA_BY_ID[self.id] = self


#: Every erratum constructed, by id (the last one under an id wins): :func:`claim_errata`.
_ERRATA_BY_ID: dict[str, Erratum] = {}


def claim_errata(claim: Claim, errata: Sequence[Erratum] | None = None) -> list[dict[str, str]]:
    """The errata ``claim`` is evidence for, each ``{"id", "basis"}``, sorted by id.

    An erratum counts when the claim names it (``claim.erratum``) or it names the claim (its
    ``claims`` hold the claim's id or one of its former ids), so a text-only erratum can
    rest on a reproduced claim.

    Parameters
    ----------
    claim : Claim
        The claim.
    errata : sequence of Erratum or None, optional
        The errata to look in; ``None`` for every erratum constructed in the process (those
        of the paper modules imported).

    Returns
    -------
    list of dict of str to str
        ``[{"id": ..., "basis": "computed" | "text-only"}, ...]``; an erratum id the claim
        names that is not among ``errata`` is left out.

    Examples
    --------
    >>> e = Erratum(id="SP-E8-doc", paper="SP", locator="Eq. (2.4.2)", printed="a + b",
    ...             finding="a - b", evidence="the derivation", kind="typography",
    ...             basis="text-only", claims=("SP-doc-sum",))
    >>> c = Claim(id="SP-doc-sum", paper="SP", locator="Eq. (2.4.2)", quantity="a sum",
    ...           published=3.0, unit="", compute=lambda: 3.0, tolerance=EXACT,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> claim_errata(c, [e])
    [{'id': 'SP-E8-doc', 'basis': 'text-only'}]
    """
    pool = list(_ERRATA_BY_ID.values()) if errata is None else list(errata)
    names = {claim.id, *claim.aliases}
    out = {e.id: e.basis for e in pool if e.id == claim.erratum or names.intersection(e.claims)}
    return [{"id": k, "basis": out[k]} for k in sorted(out)]


@dataclass(frozen=True, kw_only=True)
class Claim:
    """One published number or statement and how navcore reproduces it.

    Parameters
    ----------
    id : str
        Stable, unique; starts with the paper key (``"ATC10-tab2.1-K1-pdl0.9"``).
    paper : str, optional
        ``WF``, ``SP``, ``ATC10`` or ``KZL``; by default the key the id starts with (the one
        home of a claim's paper), and if given it must be that key.
    locator : str
        Where it stands in the paper, in the paper's words (``"Table 4.3"``).
    quantity : str
        What it is, in words a reader understands.
    published : float or bool
        The value as printed. A statement ("tight beats loose") is ``True``.
    unit : str
        The published value's unit (``""`` for dimensionless, ``"statement"`` for truth
        values).
    compute : callable or None
        Returns the reproduced value in ``unit``; it reads its inputs from the paper
        module's :class:`~navcore.claims.inputs.InputSet`. ``None`` when nothing can be
        computed (the verdict is then ``not-reproducible``).
    tolerance : Tolerance or callable
        The allowed deviation, its policy and reason; fixed by the printed text. A callable
        is resolved by the ledger before ``compute`` runs, where no input can be read.
    expected_status : str
        The verdict the paper module expects (:data:`STATUSES`); the ledger derives the
        verdict and fails when the two differ.
    note : str
        The interpretation used, the assumptions made, the erratum if any.
    relation : str
        How the published value relates to the quantity: ``=``, or a bound such as ``>``
        for a printed ``>130``.
    kind : str
        :data:`KINDS`; defaults to ``statement`` for a truth value, else ``reproduction``.
    erratum : str
        Id of the erratum (required when the verdict is ``discrepant``).
    oracle : callable or None
        Independent computation of the book's value (required for ``discrepant``).
    oracle_tolerance : Tolerance or None
        How closely ``compute()`` must agree with ``oracle()``.
    discussed_in : str
        Book docname where the claim is derived (for cross-links).
    table : str
        The name of the claims table on its page (``discussed_in``) that shows it, for a claim
        its locator's printed item does not place; a page selects it with
        ``navcore.book.claims_table(paper, table=...)`` (the book pages' helper). Kebab-case
        (``"heading"``, ``"fig5-bounds"``); empty for a claim its printed item places. A table
        name is the page's: the claims that give it are all discussed on one page.
    aliases : tuple of str
        Former ids that still refer to this claim.
    printed : str
        The paper's words or formula as quoted (``"approximately 1.4"``, ``"P_D >= 1 exp
        -K(...)"``); empty to quote the text given to the tolerance (``printed("17.67")``
        quotes ``17.67``; :func:`~navcore.claims.quotes.claim_quote`). The tolerance policy must follow it
        (:func:`~navcore.claims.quotes.quote_policies`) and a number claim's quote must contain its published
        number (:func:`~navcore.claims.quotes.quote_has_number`).

    Raises
    ------
    ValueError
        If the id does not start with its paper key and a dash, a value is not one of its
        table (:data:`PAPERS`, :data:`STATUSES`, :data:`RELATIONS`, :data:`KINDS`), the
        note is empty, a truth value is a ``reproduction`` or uses a bound, ``printed`` is
        not a string, a discrepant claim lacks its erratum, oracle or oracle tolerance, or
        ``table`` is not kebab-case or is given without ``discussed_in``. (A computed claim
        may expect ``not-reproducible``: a band too wide to decide.)

    Examples
    --------
    >>> from navcore.claims import printed
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> c.kind, c.relation, c.is_statement
    ('reproduction', '=', False)
    >>> Claim(id="SP-doc-bad", paper="SP", locator="Fig. 2.1", quantity="q", published=1.0,
    ...       unit="", compute=None, tolerance=EXACT, expected_status="reproduced", note=" ")
    Traceback (most recent call last):
    ...
    ValueError: Claim.note must state the interpretation (claim SP-doc-bad)
    """

    id: str
    paper: str = ""
    locator: str
    quantity: str
    published: float | bool
    unit: str
    compute: Callable[..., Any] | None  # called with no arguments; lambdas bind loop values as defaults
    tolerance: Tolerance | Callable[[], Tolerance]
    expected_status: Status
    note: str
    relation: Relation = "="
    kind: Kind | None = None
    erratum: str = ""
    oracle: Callable[..., Any] | None = None
    oracle_tolerance: Tolerance | None = None
    discussed_in: str = ""
    table: str = ""
    aliases: tuple[str, ...] = ()
    printed: str = ""
    _meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not _ID_RE.match(self.id):
            raise ValueError(
                f"Claim.id must start with its paper key and a dash and use [A-Za-z0-9._+-], got {self.id!r}"
            )
        if not self.paper:
            object.__setattr__(self, "paper", self.id.split("-", 1)[0])
        if self.paper not in PAPERS:
            raise ValueError(f"Claim.paper must be one of {list(PAPERS)}, got {self.paper!r}")
        if not self.id.startswith(self.paper + "-"):
            raise ValueError(f"Claim.id must start with '{self.paper}-', got {self.id!r}")
        if self.expected_status not in STATUSES:
            raise ValueError(f"Claim.expected_status must be one of {STATUSES}, got {self.expected_status!r}")
        if self.relation not in RELATIONS:
            raise ValueError(f"Claim.relation must be one of {RELATIONS}, got {self.relation!r}")
        if self.kind is None:
            object.__setattr__(
                self, "kind", "statement" if isinstance(self.published, bool) else "reproduction"
            )
        if self.kind not in KINDS:
            raise ValueError(f"Claim.kind must be one of {KINDS}, got {self.kind!r} (claim {self.id})")
        if isinstance(self.published, bool) and self.kind == "reproduction":
            raise ValueError(
                f"a truth-valued claim is a statement, cross-check or fit, not a reproduction ({self.id})"
            )
        if not (isinstance(self.tolerance, Tolerance) or callable(self.tolerance)):
            raise ValueError(
                f"Claim.tolerance must be a Tolerance or a callable returning one (claim {self.id})"
            )
        if not self.note.strip():
            raise ValueError(f"Claim.note must state the interpretation (claim {self.id})")
        if not isinstance(self.printed, str):
            raise ValueError(f"Claim.printed must be the quoted text, got {self.printed!r} (claim {self.id})")
        if self.expected_status == "discrepant":
            if not self.erratum:
                raise ValueError(f"a discrepant claim must name its erratum (claim {self.id})")
            if self.oracle is None or self.oracle_tolerance is None:
                raise ValueError(
                    f"a discrepant claim needs an independent oracle and oracle_tolerance (claim {self.id})"
                )
        if self.table and not _TABLE_RE.match(self.table):
            raise ValueError(f"Claim.table must be a kebab-case name, got {self.table!r} (claim {self.id})")
        if self.table and not self.discussed_in:
            raise ValueError(f"Claim.table is a table of the claim's page: needs discussed_in ({self.id})")
        if isinstance(self.published, bool) and self.relation != "=":
            raise ValueError(f"a statement claim uses relation '=' (claim {self.id})")

    @classmethod
    def statement(
        cls,
        *,
        id: str,
        locator: str,
        quantity: str,
        compute: Callable[..., Any] | None,
        note: str,
        discussed_in: str = "",
        tolerance: Tolerance | Callable[[], Tolerance] | None = None,
        expected_status: Status = "reproduced",
        **fields: Any,
    ) -> Claim:
        """A claim that a printed statement holds: published ``True``, unit ``"statement"``.

        The common fields of a statement claim, in one place: its published value is the
        truth value ``True`` (the paper says it holds), its unit ``"statement"``, its tolerance
        :data:`~navcore.claims.tolerances.EXACT` unless given and its expected verdict ``reproduced`` unless
        given. Every other field is :class:`Claim`'s, by keyword.

        Parameters
        ----------
        id, locator, quantity, compute, note, discussed_in
            As for :class:`Claim`.
        tolerance : Tolerance or callable, optional
            :data:`~navcore.claims.tolerances.EXACT` by default (a truth value is met or not).
        expected_status : str
            ``"reproduced"`` by default.
        **fields
            Any other field of :class:`Claim` (``kind``, ``erratum``, ``oracle``, ``printed``, ...).

        Returns
        -------
        Claim

        Raises
        ------
        ValueError
            As :class:`Claim` does; and if ``published`` or ``unit`` is given (a statement's
            are fixed).

        Examples
        --------
        >>> c = Claim.statement(id="SP-doc-tight", locator="Sec. 2.1", quantity="tight beats loose",
        ...                     compute=lambda: True, note="a synthetic claim")
        >>> c.published, c.unit, c.tolerance is EXACT, c.kind, c.expected_status
        (True, 'statement', True, 'statement', 'reproduced')
        """
        fixed = sorted({"published", "unit"} & fields.keys())
        if fixed:
            raise ValueError(f"Claim.statement fixes {', '.join(fixed)}; got it as an argument (claim {id})")
        return cls(
            id=id,
            locator=locator,
            quantity=quantity,
            published=True,
            unit="statement",
            compute=compute,
            tolerance=EXACT if tolerance is None else tolerance,
            expected_status=expected_status,
            note=note,
            discussed_in=discussed_in,
            **fields,
        )

    @property
    def is_statement(self) -> bool:
        """Whether the claim is a statement (its published value is a truth value)."""
        return isinstance(self.published, bool)

    @property
    def status(self) -> str:
        """The expected verdict (the derived one is on the :class:`~navcore.claims.evaluation.Evaluation`)."""
        return self.expected_status


def resolve_tolerance(claim: Claim) -> Tolerance:
    """The claim's tolerance, resolved where no input can be read (before any computation)."""
    with declaring():
        tol = (
            claim.tolerance()
            if callable(claim.tolerance) and not isinstance(claim.tolerance, Tolerance)
            else claim.tolerance
        )
    if not isinstance(tol, Tolerance):
        raise TypeError(f"claim {claim.id}: tolerance must resolve to a Tolerance, got {type(tol).__name__}")
    if tol.policy not in POLICIES:
        raise ValueError(f"claim {claim.id}: the tolerance names no policy of {POLICIES}")
    return tol
