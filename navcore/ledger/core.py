"""Claims, tolerances, errata and their evaluation.

A :class:`Claim` is one number (or statement) that a paper publishes, together with a
function that makes navcore compute it. Its published value is typed once, with its
locator; its reproduced value is never typed: it is whatever ``compute()`` returns.

Check rules, by declared status
-------------------------------
``reproduced`` / ``consistent``
    the reproduced value satisfies the published relation within the tolerance:
    ``=``: ``|reproduced - published| <= tol``; ``<``/``<=``/``>``/``>=``: the inequality
    holds (the tolerance widens it); a statement (``published`` is ``True``/``False``) must
    evaluate to the published truth value.
``discrepant``
    the reproduced value violates the published relation beyond the tolerance (the
    disagreement persists), the claim names an erratum, and it agrees with an independent
    ``oracle`` computation within ``oracle_tolerance``, so a regression is still caught
    without typing the book's value in.
``not-reproducible``
    ``compute`` is ``None``; the note says which inputs are missing. There is nothing to
    check and the test is reported as skipped with the note as its reason.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal

__all__ = [
    "PAPERS",
    "RELATIONS",
    "STATUSES",
    "Claim",
    "Erratum",
    "Evaluation",
    "Tolerance",
    "evaluate",
    "printed",
]

PAPERS: dict[str, str] = {
    "WF": "Wu & Fowler, Application of MEMS for Improved Emitter Location Accuracy",
    "SP": "Schmidt & Phillips, INS/GPS Integration Architecture Performance Comparisons",
    "ATC10": "Schneider, Stiglitz & Eckberg, Surveillance Aspects of the AATMS (ATC-10)",
    "KZL": "Knedlik, Zhou & Loffeld, Position and Attitude Estimation for Bistatic SAR",
}
STATUSES = ("reproduced", "consistent", "discrepant", "not-reproducible")
RELATIONS = ("=", "<", "<=", ">", ">=")
Status = Literal["reproduced", "consistent", "discrepant", "not-reproducible"]
Relation = Literal["=", "<", "<=", ">", ">="]

_ID_RE = re.compile(r"^(WF|SP|ATC10|KZL)-[A-Za-z0-9][A-Za-z0-9._+-]*$")


@dataclass(frozen=True)
class Tolerance:
    """An absolute and/or relative tolerance with the reason it has that size.

    The allowed deviation is ``max(abs, rel * |published|)``. ``reason`` is mandatory: a
    tolerance without a written reason is a defect (LEDGER.md, tolerance policy).
    """

    reason: str
    abs: float | None = None
    rel: float | None = None

    def __post_init__(self) -> None:
        if not self.reason or not self.reason.strip():
            raise ValueError("Tolerance.reason must say why the tolerance has its size")
        for name in ("abs", "rel"):
            value = getattr(self, name)
            if value is not None and not (value >= 0 and math.isfinite(value)):
                raise ValueError(f"Tolerance.{name} must be finite and >= 0, got {value!r}")

    def allowed(self, published: float) -> float:
        """Return the allowed absolute deviation around ``published``."""
        a = self.abs or 0.0
        r = (self.rel or 0.0) * abs(published)
        return max(a, r)

    def as_dict(self) -> dict[str, Any]:
        return {"abs": self.abs, "rel": self.rel, "reason": self.reason}

    def describe(self) -> str:
        parts = []
        if self.abs is not None:
            parts.append(f"±{self.abs:.4g}")
        if self.rel is not None:
            parts.append(f"±{100 * self.rel:.3g} %")
        return " or ".join(parts) if parts else "exact"


EXACT = Tolerance(reason="exact: an integer count or a logical statement", abs=0.0)


def printed(text: str, *, extra_abs: float = 0.0, why: str = "") -> tuple[float, Tolerance]:
    """Parse a number as printed and return it with a half-last-digit tolerance.

    ``printed("17.67")`` gives ``(17.67, Tolerance(abs=0.005, ...))``; ``printed("1.2e-3")``
    gives half a unit of the last mantissa digit times the exponent. ``extra_abs`` adds what
    the paper's own rounding of intermediate values can explain; ``why`` says so.

    Examples
    --------
    >>> value, tol = printed("17.67")
    >>> value, tol.abs
    (17.67, 0.005)
    """
    s = text.strip().replace("−", "-")
    m = re.fullmatch(r"([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?", s)
    if not m or (not m.group(2) and not m.group(3)):
        raise ValueError(f"text must be a printed number such as '17.67' or '1.5e-3', got {text!r}")
    decimals = len(m.group(3) or "")
    exponent = int(m.group(4) or 0)
    value = float(s)
    half = 0.5 * 10.0 ** (exponent - decimals)
    reason = f"half a unit in the last printed digit of {text}"
    if extra_abs:
        reason += f", plus {extra_abs:g}" + (f" ({why})" if why else "")
    elif why:
        reason += f"; {why}"
    return value, Tolerance(reason=reason, abs=round(half + extra_abs, 15))


@dataclass(frozen=True)
class Erratum:
    """A suspected error in a paper, with the book's finding and its evidence.

    Parameters
    ----------
    id : str
        Stable identifier such as ``"ATC10-E2-erf-argument"``.
    paper, locator : str
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
    """

    id: str
    paper: str
    locator: str
    printed: str
    finding: str
    evidence: str
    claims: tuple[str, ...] = ()
    discussed_in: str = ""

    def __post_init__(self) -> None:
        if self.paper not in PAPERS:
            raise ValueError(f"Erratum.paper must be one of {list(PAPERS)}, got {self.paper!r}")
        for name in ("id", "locator", "printed", "finding", "evidence"):
            if not str(getattr(self, name)).strip():
                raise ValueError(f"Erratum.{name} must not be empty (erratum {self.id!r})")


@dataclass(frozen=True)
class Claim:
    """One published number or statement and how navcore reproduces it.

    Parameters
    ----------
    id : str
        Stable, unique; starts with the paper key (``"ATC10-tab2.1-K1-pdl0.9"``).
    paper : str
        ``WF``, ``SP``, ``ATC10`` or ``KZL``.
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
        Returns the reproduced value in ``unit`` (``None`` only for ``not-reproducible``).
    tolerance : Tolerance
        The allowed deviation and why.
    status : str
        One of :data:`STATUSES` (the book's verdict; the check enforces it).
    note : str
        The interpretation used, the assumptions made, the erratum if any.
    relation : str
        How the published value relates to the quantity: ``=``, or a bound such as ``>``
        for a printed ``>130``.
    erratum : str
        Id of the erratum (required when ``status == "discrepant"``).
    oracle : callable or None
        Independent computation of the book's value (required for ``discrepant``).
    oracle_tolerance : Tolerance or None
        How closely ``compute()`` must agree with ``oracle()``.
    discussed_in : str
        Book docname where the claim is derived (filled by chapters for cross-links).
    """

    id: str
    paper: str
    locator: str
    quantity: str
    published: float | bool
    unit: str
    compute: Callable[[], Any] | None
    tolerance: Tolerance
    status: Status
    note: str
    relation: Relation = "="
    erratum: str = ""
    oracle: Callable[[], Any] | None = None
    oracle_tolerance: Tolerance | None = None
    discussed_in: str = ""
    _meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not _ID_RE.match(self.id):
            raise ValueError(
                f"Claim.id must start with its paper key and a dash and use [A-Za-z0-9._+-], got {self.id!r}"
            )
        if self.paper not in PAPERS:
            raise ValueError(f"Claim.paper must be one of {list(PAPERS)}, got {self.paper!r}")
        if not self.id.startswith(self.paper + "-"):
            raise ValueError(f"Claim.id must start with '{self.paper}-', got {self.id!r}")
        if self.status not in STATUSES:
            raise ValueError(f"Claim.status must be one of {STATUSES}, got {self.status!r}")
        if self.relation not in RELATIONS:
            raise ValueError(f"Claim.relation must be one of {RELATIONS}, got {self.relation!r}")
        if not isinstance(self.tolerance, Tolerance):
            raise ValueError(f"Claim.tolerance must be a Tolerance (claim {self.id})")
        if not self.note.strip():
            raise ValueError(f"Claim.note must state the interpretation (claim {self.id})")
        if self.status == "not-reproducible":
            if self.compute is not None:
                raise ValueError(f"a not-reproducible claim has no compute (claim {self.id})")
        elif self.compute is None:
            raise ValueError(f"Claim.compute is required unless not-reproducible ({self.id})")
        if self.status == "discrepant":
            if not self.erratum:
                raise ValueError(f"a discrepant claim must name its erratum (claim {self.id})")
            if self.oracle is None or self.oracle_tolerance is None:
                raise ValueError(
                    f"a discrepant claim needs an independent oracle and oracle_tolerance (claim {self.id})"
                )
        if isinstance(self.published, bool) and self.relation != "=":
            raise ValueError(f"a statement claim uses relation '=' (claim {self.id})")

    @property
    def is_statement(self) -> bool:
        return isinstance(self.published, bool)


@dataclass(frozen=True)
class Evaluation:
    """The result of evaluating one claim."""

    claim: Claim
    reproduced: Any
    passes: bool
    detail: str
    oracle_value: Any = None

    def __post_init__(self) -> None:
        # comparisons on numpy scalars give numpy booleans: store a plain bool
        object.__setattr__(self, "passes", bool(self.passes))

    @property
    def deviation(self) -> float | None:
        """``reproduced - published`` for numeric claims, else ``None``."""
        if self.claim.is_statement or self.reproduced is None:
            return None
        return float(self.reproduced) - float(self.claim.published)

    def as_json(self) -> dict[str, Any]:
        """The documented fields of LEDGER.md, and no others."""
        c = self.claim
        rep = self.reproduced
        if rep is not None and not isinstance(rep, bool):
            rep = float(rep)
            if not math.isfinite(rep):
                rep = None if math.isnan(rep) else ("Infinity" if rep > 0 else "-Infinity")
        pub = c.published if isinstance(c.published, bool) else float(c.published)
        return {
            "id": c.id,
            "paper": c.paper,
            "locator": c.locator,
            "quantity": c.quantity,
            "published": pub,
            "relation": c.relation,
            "unit": c.unit,
            "reproduced": rep,
            "tolerance": c.tolerance.as_dict(),
            "status": c.status,
            "note": c.note,
        }


def _satisfies(value: float, relation: str, published: float, allowed: float) -> bool:
    if relation == "=":
        return abs(value - published) <= allowed
    if relation == "<":
        return value < published + allowed
    if relation == "<=":
        return value <= published + allowed
    if relation == ">":
        return value > published - allowed
    if relation == ">=":
        return value >= published - allowed
    raise ValueError(f"relation must be one of {RELATIONS}, got {relation!r}")


def _coerce(value: Any, claim: Claim) -> Any:
    if claim.is_statement:
        if not isinstance(value, bool | int) and not hasattr(value, "__bool__"):
            raise TypeError(f"claim {claim.id}: a statement must compute to a truth value")
        return bool(value)
    out = float(value)
    return out


def evaluate(claim: Claim) -> Evaluation:
    """Compute a claim's reproduced value and check it against its declared status."""
    if claim.status == "not-reproducible":
        return Evaluation(claim, None, True, "not reproducible: " + claim.note)
    assert claim.compute is not None
    try:
        reproduced = _coerce(claim.compute(), claim)
    except Exception as exc:  # a claim whose computation fails is a failing claim
        return Evaluation(claim, None, False, f"compute raised {type(exc).__name__}: {exc}")

    if claim.is_statement:
        agrees = reproduced == claim.published
    else:
        if math.isnan(reproduced):
            return Evaluation(claim, reproduced, False, "reproduced value is NaN")
        allowed = claim.tolerance.allowed(float(claim.published))
        agrees = _satisfies(reproduced, claim.relation, float(claim.published), allowed)

    if claim.status in ("reproduced", "consistent"):
        detail = "agrees with the published value" if agrees else "disagrees with the published value"
        return Evaluation(claim, reproduced, agrees, detail)

    # discrepant: the disagreement must persist and the value must match the oracle
    assert claim.oracle is not None and claim.oracle_tolerance is not None
    try:
        oracle_value = _coerce(claim.oracle(), claim)
    except Exception as exc:
        return Evaluation(claim, reproduced, False, f"oracle raised {type(exc).__name__}: {exc}")
    if claim.is_statement:
        matches = oracle_value == reproduced
    else:
        matches = abs(reproduced - oracle_value) <= claim.oracle_tolerance.allowed(oracle_value)
    if agrees:
        detail = "declared discrepant but now agrees with the published value: re-examine"
    elif not matches:
        detail = f"disagrees with its independent oracle ({oracle_value!r})"
    else:
        detail = "discrepancy confirmed by an independent oracle"
    return Evaluation(claim, reproduced, (not agrees) and matches, detail, oracle_value)
