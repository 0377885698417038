"""The verdict rule: how a computed value or band, its tolerance and its inputs' provenance give a verdict.

The comparisons (:func:`band_spread`, :func:`band_too_wide`, :func:`additive_envelope`) and
``derive_status``, which :func:`~navcore.claims.runs.evaluate` applies to a claim's runs.

Verdicts, as derived (the ledger page)
--------------------------------------
``not-reproducible``
    nothing is computed (``compute is None``); the note names the missing input. Or the
    band over the assumed inputs is too wide to decide (below): the value and the band are
    shown, and the assumptions are too loose to tell agreement from disagreement.
``reproduced``
    kind ``reproduction`` or ``statement``, every input read is ``published`` or
    ``convention``, and the value under the reading used of every convention satisfies the
    published relation within the tolerance.
``consistent``
    agreement that rests on more than published inputs: some value in the band of the
    ``assumed`` inputs agrees (and the band decides), or the computation reads a ``fitted``
    input, or the kind is ``cross-check`` (arithmetic on printed numbers) or ``fit``; or the
    reading used of a convention disagrees where another admissible reading agrees; or a whole
    number agrees only if its trailing zeros are not significant ("Trailing zeros").
``inconsistent``
    the model under declared assumptions disagrees across the whole band, under every
    admissible reading (or a fit that does not agree).
``discrepant``
    disagreement under every admissible reading of every convention read, with published
    inputs only, or for every admissible input (every assumed input read declares its range
    ``admissible``); the claim names an erratum and an independent oracle with which the
    book's value must agree.

Readings
--------
A ``convention`` input lists every admissible reading of a text that leaves one open, each
labelled in words, the one used included (:meth:`~navcore.claims.inputs.InputSet.convention`).
The ledger runs a claim under every combination of the readings of the conventions it read
(up to :data:`~navcore.claims.runs.MAX_READING_COMBINATIONS`; beyond it, each convention's readings one at a
time, the others at the reading used), across the assumed inputs' ranges too where the claim also
reads assumed inputs, and weighs them:

* the reading used agrees: the verdict is that reading's (``reproduced`` with published
  inputs), and what the other readings give is shown;
* the reading used disagrees and another admissible reading agrees: ``consistent``, and the
  claim names the reading(s) that agree (the paper is not accused of what one of its own
  readings supports);
* every admissible reading disagrees: ``discrepant`` (published inputs only, or an
  admissible assumed range) or ``inconsistent`` (plausible assumed ranges).

A reading other than the one used is run across the assumed ranges only when the verdict
needs it: the other readings are taken in order, and their bands run until one reading (the one
used first) agrees with a band that decides, which settles the verdict; the readings after it
show their values. The bands run over the assumed inputs that the run under the readings used
read (a claim's inputs are those of that run).

A band too wide to decide
-------------------------
Stated before any value is computed: a band decides nothing when its ends are more than a
factor :data:`BAND_FACTOR` (3) apart and the tolerance does not accept all of it (part of
the band agrees with the printed value, part does not). Such a claim is ``not-reproducible``
with its band shown, not ``consistent``. The factor is the span of the loosest word of the
prose table that still names one number, "of the order of" (±50 %, so 0.5 to 1.5 times the
number: a factor 3); a band wider than that says less than the paper's loosest wording. The
ends are compared by :func:`band_spread`: as a ratio of magnitudes for a band of one sign; a
band that reaches zero or changes sign has no finite ratio (it cannot even tell the sign), so
it is too wide unless the tolerance accepts all of it; a band in decibels (a unit starting
with ``dB``) is compared as the power ratio of its ends, 10 log10(3) = 4.77 dB. A printed
bound (``<``, ``>``) is treated alike: a band that straddles it and spans more than a factor 3
is too wide; a band wholly on the bound's side agrees everywhere and decides. A statement's
band is its truth values across the assumed ranges: one that holds somewhere and fails
elsewhere in the ranges accepts both outcomes, so it too decides nothing.

Beyond six inputs
-----------------
Up to :data:`MAX_CORNER_INPUTS` inputs every corner is run, and the band holds the extremes of
any response monotone in each input. Beyond, the corners run are a sample of the box: a
printed value inside the band is still reached by runs on both sides of it, but one outside
the band may lie at a corner not run, and a band from a sample can shrink when an input is
added (another split of the list, other diagonals). So, stated before any value is computed,
such a band shows a printed value out of reach only when the value is also outside what the
inputs' separate effects add up to, :func:`additive_envelope`: the nominal value plus every
input's largest rise in its one-at-a-time run, and minus every largest fall (the extremes of
a response that is a sum of one function of each input). The envelope uses only the
one-at-a-time runs and only widens when an input is added. A printed value outside the band
and inside the envelope is ``not-reproducible``: the search cannot decide, and the note gives
the envelope. Outside both, the verdict is derived as before (``inconsistent``, or
``discrepant`` over admissible ranges). A statement's truth values do not add, so a
statement's band is its runs' truth values alone.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from navcore.claims.declarations import RELATIONS, Claim
from navcore.claims.tolerances import Tolerance

__all__ = [
    "BAND_FACTOR",
    "MAX_CORNER_INPUTS",
    "additive_envelope",
    "band_spread",
    "band_too_wide",
    "precision_status",
]


#: A band whose ends are more than this factor apart decides nothing where the tolerance does
#: not accept all of it (module docstring, "A band too wide to decide").
BAND_FACTOR = 3.0


def band_spread(low: float, high: float, unit: str = "") -> float:
    """How far apart a band's ends are, as a factor (module docstring, "A band too wide").

    Parameters
    ----------
    low, high : float
        The band's ends (in either order).
    unit : str, optional
        The claim's unit; one starting with ``dB`` compares the ends as a power ratio.

    Returns
    -------
    float
        ``max(|low|, |high|) / min(|low|, |high|)`` for a band of one sign; ``10 **
        ((high - low) / 10)`` in decibels; ``inf`` for a band that reaches zero or changes
        sign (1 for the single point 0).

    Examples
    --------
    >>> band_spread(2.0, 8.0), band_spread(-8.0, -2.0), band_spread(-1.0, 1.0)
    (4.0, 4.0, inf)
    >>> round(band_spread(12.0, 19.5, "dB"), 2)
    5.62
    """
    lo, hi = sorted((float(low), float(high)))
    if unit.strip().lower().startswith("db"):
        return 10.0 ** ((hi - lo) / 10.0)
    if lo > 0 or hi < 0:
        return max(abs(lo), abs(hi)) / min(abs(lo), abs(hi))
    return 1.0 if lo == hi == 0 else math.inf


def band_too_wide(claim: Claim, tol: Tolerance, low: Any, high: Any) -> bool:
    """Whether a claim's band is too wide to decide (module docstring, "A band too wide").

    True when the tolerance does not accept the whole band and its ends are more than
    :data:`BAND_FACTOR` apart (:func:`band_spread`); for a statement, when its band holds
    both truth values (the assumptions accept either outcome).

    Parameters
    ----------
    claim : Claim
        The claim (its published value, relation and unit).
    tol : Tolerance
        Its resolved tolerance.
    low, high : float
        The band's ends.

    Returns
    -------
    bool
        Whether the band decides nothing.

    Examples
    --------
    >>> from navcore.claims import EXACT, printed
    >>> value, tol = printed("120")
    >>> c = Claim(id="SP-doc-cep", paper="SP", locator="Sec. 3.3", quantity="CEP",
    ...           published=value, unit="m", compute=lambda: 100.0, tolerance=tol,
    ...           expected_status="consistent", note="a synthetic claim")
    >>> band_too_wide(c, tol, 2.0, 567.0), band_too_wide(c, tol, 100.0, 150.0)
    (True, False)
    >>> s = Claim(id="SP-doc-better", paper="SP", locator="Sec. 3.3", quantity="TC beats LC",
    ...           published=True, unit="statement", compute=lambda: True, tolerance=EXACT,
    ...           expected_status="consistent", note="a synthetic claim")
    >>> band_too_wide(s, EXACT, False, True), band_too_wide(s, EXACT, True, True)
    (True, False)
    """
    if claim.is_statement or _is_truth(low) or _is_truth(high):
        return bool(low) != bool(high)
    pub = float(claim.published)
    allowed = tol.allowed(pub)
    lo, hi = sorted((float(low), float(high)))
    if _satisfies(lo, claim.relation, pub, allowed) and _satisfies(hi, claim.relation, pub, allowed):
        return False  # the tolerance accepts all of it: agreement everywhere decides
    return band_spread(lo, hi, claim.unit) > BAND_FACTOR


def _is_truth(value: Any) -> bool:
    """A Python or numpy boolean (numpy 2 names its scalar type ``bool``, numpy 1 ``bool_``).

    Examples
    --------
    >>> import numpy as np
    >>> _is_truth(True), _is_truth(np.False_), _is_truth(1), _is_truth(np.float64(1.0))
    (True, True, False, False)
    """
    import numpy as np

    return isinstance(value, bool | np.bool_)


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


def _band_satisfies(lo: float, hi: float, relation: str, published: float, allowed: float) -> bool:
    """Whether some value in [lo, hi] satisfies the relation (the band is an interval)."""
    if relation == "=":
        return lo <= published + allowed and hi >= published - allowed
    if relation in ("<", "<="):
        return _satisfies(lo, relation, published, allowed)
    return _satisfies(hi, relation, published, allowed)


#: Up to this many assumed inputs, the band includes every corner of their box (2**6 = 64 runs);
#: beyond it, each input one at a time plus four diagonal corners and, for a numeric value, the
#: two corners where every input sits at the end that raised (lowered) the value one at a time
#: (the extremes of a monotone response, which the diagonals can miss).
MAX_CORNER_INPUTS = 6


def additive_envelope(
    value: Any, sensitivity: Sequence[tuple[str, Sequence[tuple[Any, Any]]]]
) -> tuple[float, float] | None:
    """What the assumed inputs' separate effects add up to (module docstring, "Beyond six inputs").

    The nominal value plus every input's largest rise in its one-at-a-time run, and minus
    every largest fall: the extremes of a response that is the sum of one function of each
    input. It uses only the one-at-a-time runs, and it can only widen when an input is added.

    Parameters
    ----------
    value : float or bool
        The claim's value at the nominal inputs.
    sensitivity : sequence of (str, sequence of (point, value))
        Per assumed input, its one-at-a-time runs (:attr:`~navcore.claims.evaluation.Evaluation.sensitivity`).

    Returns
    -------
    tuple of (float, float) or None
        ``(low, high)``; ``None`` for a truth value, or where a value is not a finite real
        number (effects of a truth value do not add).

    Examples
    --------
    >>> additive_envelope(10.0, [("a", ((0, 9.0), (1, 12.0))), ("b", ((0, 10.5), (1, 11.0)))])
    (9.0, 13.0)
    >>> additive_envelope(True, [("a", ((0, False), (1, True)))]) is None
    True
    """
    if _is_truth(value):
        return None
    try:
        v0 = float(value)
        rows = [[float(v) - v0 for _, v in row if not _is_truth(v)] for _, row in sensitivity]
    except (TypeError, ValueError):
        return None
    if not math.isfinite(v0) or not all(math.isfinite(d) for row in rows for d in row):
        return None
    low = v0 + math.fsum(min(0.0, *row) for row in rows if row)
    high = v0 + math.fsum(max(0.0, *row) for row in rows if row)
    return low, high


@dataclass(frozen=True)
class _Outcome:
    """How one reading's value (and band) compares with the printed value."""

    agrees_at_value: bool
    agrees: bool
    too_wide: bool
    #: the runs do not reach the printed value but the inputs' separate effects add up to it
    #: (more than six assumed inputs: module docstring, "Beyond six inputs")
    undecided: bool = False


def _outcome(
    claim: Claim,
    tol: Tolerance,
    value: Any,
    values: Sequence[Any],
    envelope: tuple[float, float] | None = None,
) -> _Outcome:
    if claim.is_statement:
        at_value = value == claim.published
        outcomes = {bool(v) for v in (value, *values)}
        return _Outcome(at_value, claim.published in outcomes, bool(values) and len(outcomes) == 2)
    pub = float(claim.published)
    allowed = tol.allowed(pub)
    at_value = _satisfies(value, claim.relation, pub, allowed)
    lo, hi = min([value, *values]), max([value, *values])
    agrees = at_value or _band_satisfies(lo, hi, claim.relation, pub, allowed)
    undecided = (
        not agrees
        and envelope is not None
        and _band_satisfies(min(lo, envelope[0]), max(hi, envelope[1]), claim.relation, pub, allowed)
    )
    return _Outcome(at_value, agrees, bool(values) and band_too_wide(claim, tol, lo, hi), undecided)


#: The verdicts that agree with the printed value.
_AGREEMENT = ("reproduced", "consistent")


def precision_status(loose_status: str) -> str:
    """The verdict of a claim whose printed value disagrees when every printed digit is
    significant, from its verdict when a whole number's trailing zeros are not
    (:mod:`navcore.claims.tolerances`, "Trailing zeros").

    Parameters
    ----------
    loose_status : str
        The verdict derived with the loose tolerance (:meth:`~navcore.claims.tolerances.Tolerance.loose`).

    Returns
    -------
    str
        ``consistent`` when the loose reading agrees (``reproduced`` or ``consistent``): an
        open reading of the printed precision, not a reproduction; else ``loose_status``.

    Examples
    --------
    >>> precision_status("reproduced"), precision_status("discrepant")
    ('consistent', 'discrepant')
    """
    return "consistent" if loose_status in _AGREEMENT else loose_status


def derive_status(
    claim: Claim,
    tol: Tolerance,
    value: Any,
    values: list[Any],
    provenances: set[str],
    admissible: bool,
    readings: Sequence[tuple[Any, ...]] = (),
    envelope: tuple[float, float] | None = None,
) -> str:
    """The ledger's verdict from every reading's value and band and the provenances read.

    Parameters
    ----------
    claim : Claim
        The claim.
    tol : Tolerance
        Its resolved tolerance.
    value : float or bool
        The value under the readings used, at the nominal inputs.
    values : list
        The values across the assumed inputs' ranges under the readings used (empty when
        none is assumed).
    provenances : set of str
        The provenances of the inputs read.
    admissible : bool
        Every assumed input read spans all admissible values.
    readings : sequence of (value, values) or (value, values, envelope), optional
        The same for each other combination of readings (``values`` empty where no band
        was run).
    envelope : tuple of (float, float) or None, optional
        With more than :data:`MAX_CORNER_INPUTS` assumed inputs, what their separate effects
        add up to (:func:`additive_envelope`): a printed value the runs do not reach but the
        envelope does is not shown out of reach (module docstring, "Beyond six inputs").

    Returns
    -------
    str
        One of :data:`~navcore.claims.declarations.STATUSES` (module docstring, "Verdicts, as
        derived" and "Readings").

    Examples
    --------
    The reading used disagrees (10.5 against 10 +- 0.05), the other reading agrees:

    >>> from navcore.claims import printed
    >>> value, tol = printed("10.0")
    >>> c = Claim(id="SP-doc-r", paper="SP", locator="Eq. (1)", quantity="q", published=value,
    ...           unit="m", compute=lambda: 10.5, tolerance=tol, expected_status="consistent",
    ...           note="a synthetic claim")
    >>> derive_status(c, tol, 10.5, [], {"convention"}, False, [(10.0, [])])
    'consistent'
    >>> derive_status(c, tol, 10.5, [], {"convention"}, False, [(11.0, [])])
    'discrepant'
    """
    outcomes = [_outcome(claim, tol, value, values, envelope)] + [_outcome(claim, tol, *r) for r in readings]
    if claim.kind == "cross-check":
        return "consistent" if any(o.agrees_at_value for o in outcomes) else "discrepant"
    if claim.kind == "fit" or "fitted" in provenances:
        if any(o.agrees and not o.too_wide for o in outcomes):
            return "consistent"
        if any(o.agrees or o.undecided for o in outcomes):
            return "not-reproducible"  # a band too wide to decide, or a search that cannot
        return "inconsistent"
    if "assumed" in provenances:
        if any(o.agrees and not o.too_wide for o in outcomes):
            return "consistent"
        if any(o.agrees or o.undecided for o in outcomes):
            return "not-reproducible"  # a band too wide to decide, or a search that cannot
        return "discrepant" if admissible else "inconsistent"
    if outcomes[0].agrees_at_value:
        return "reproduced"
    return "consistent" if any(o.agrees_at_value for o in outcomes[1:]) else "discrepant"
