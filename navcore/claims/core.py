"""Claims, tolerances, errata, and the verdicts the ledger derives for them.

A :class:`Claim` is one number (or statement) that a paper publishes, with a function that
makes navcore compute it. Its published value is typed once, with its locator; its
reproduced value is never typed: it is whatever ``compute()`` returns. The claim declares
its ``kind``, its tolerance (fixed by how the paper printed the number, through a named
policy) and the verdict it expects; :func:`evaluate` derives the verdict from the
computation, the tolerance and the provenance of every input the computation read
(:mod:`navcore.claims.inputs`), and the ledger fails where the two differ.

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
(up to :data:`MAX_READING_COMBINATIONS`; beyond it, each convention's readings one at a time,
the others at the reading used), across the assumed inputs' ranges too where the claim also
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

Band runs
---------
The band runs each assumed input one at a time over its band points and then the corners of
the box: every corner for up to :data:`MAX_CORNER_INPUTS` inputs; beyond that, the two
diagonal corners (all low, all high), the two half-and-half corners (the first half of the
inputs low and the rest high, and the reverse), and, for a numeric value, the two corners
where each input sits at the end of its range that raised (lowered) the value in its
one-at-a-time run (the extremes of a response monotone in each input, which the diagonals can
miss). A run whose inputs are each in range but together describe a case the model does not
cover (it raises ``ModelDomainError``, for example no four satellites stay above the mask
along the whole flight for fixed channels) gives no value: it is left out of the band, and
the evaluation's ``left_out`` records which case was left out and in how many runs; the note
says it. A statement whose nominal and one-at-a-time runs already hold both truth values
skips its corners: its band is ``(False, True)`` whatever they give; under a reading other
than the one used, whose one-at-a-time runs are not shown, its runs stop as soon as both truth
values are in (``left_out`` counts the runs made). Each batch of runs (the one-at-a-time
runs, then the corners) is announced before it is made (``band_ahead`` in
:mod:`navcore.claims.inputs`), so that a model whose runs batch well can compute the whole
batch in one call when the first run asks, and serve the others from its
:func:`~navcore.claims.inputs.input_cache`; such a model gives each run the result it gives
that run alone (KZL's Monte Carlo does, bit for bit, and its tests check it).

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

Trailing zeros
--------------
The trailing zeros of a whole number printed without a decimal point or an exponent ("2750",
"20", "3300") do not say whether they are significant, so the precision is a reading of the
text, and :func:`printed` gives its tolerance both: strict, half a unit in the last digit
(``abs``), and loose, half a unit in the last non-zero digit (``loose_abs``: ±5 for "2750",
±50 for "3300"). The verdict weighs them like the readings of a convention:

* agreement under the strict one: the verdict as derived with it (the loose one is not run);
* agreement only under the loose one: ``consistent`` (:func:`precision_status`), and the
  claim's ``readings`` name the reading that agrees, "trailing zeros not significant"
  (:data:`PRECISION_READING`);
* agreement under neither: the verdict as derived with the loose tolerance (the claim is not
  accused of a digit its printed number may not carry), both readings shown.

A number printed with a decimal point ("20.0", "20.") or an exponent ("150e1") states its
significant digits.

Findings and their basis
------------------------
An :class:`Erratum` is a finding; its ``basis`` (:data:`ERRATUM_BASES`) is ``computed``
(a number the paper prints is wrong: a recomputation under its stated inputs, or its own
other printed numbers, contradict it) or ``text-only`` (the text of a formula or a word is at
fault, and the paper's printed numbers follow the correct form, or none depends on it). The
book works from transcriptions, so a text-only finding cannot tell a misprint from a
transcription slip (:data:`TEXT_ONLY_CAVEAT`). A claim's ``errata`` are the errata it is
evidence for: the one it names and those that name it.

What the paper printed
----------------------
A claim's ``printed`` is the paper's words or formula as quoted; by default the text given
to its tolerance (``printed("17.67")`` quotes ``17.67``, ``prose("about")`` quotes the word).
The tolerance policy follows the quote by rule (:func:`quote_policies`), and a number the
paper does not print is not ``published``: a threshold or an encoding of "this equation
holds" is the book's, so such a claim is a ``statement`` whose threshold is a declared
convention (:func:`quote_has_number`).

Tolerance policies
------------------
``printed-digits`` (half a unit in the last printed digit, :func:`printed`), ``prose`` (the
band of a word such as "about", :func:`prose`), ``figure-reading`` (the reading resolution
of a figure's axis, :func:`figure_reading`), ``monte-carlo`` (the sampling error of a run
count, :func:`monte_carlo`) and ``exact`` (:data:`EXACT`).
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from navcore._validate import ModelDomainError
from navcore.claims.inputs import (
    Input,
    _label_and_unit,
    band_ahead,
    declaring,
    get_input,
    overriding,
    recording,
)
from navcore.formatting import unit_text

__all__ = [
    "BAND_FACTOR",
    "ERRATUM_BASES",
    "ERRATUM_KINDS",
    "EXACT",
    "KINDS",
    "MAX_CORNER_INPUTS",
    "MAX_READING_COMBINATIONS",
    "PAPERS",
    "POLICIES",
    "PRECISION_LOOSE",
    "PRECISION_READING",
    "PRECISION_STRICT",
    "PROSE_WORDS",
    "RELATIONS",
    "STATUSES",
    "TEXT_ONLY_CAVEAT",
    "Claim",
    "Erratum",
    "Evaluation",
    "Tolerance",
    "additive_envelope",
    "band_spread",
    "band_too_wide",
    "claim_errata",
    "claim_quote",
    "evaluate",
    "figure_reading",
    "label_prints_value",
    "left_out_of_band",
    "monte_carlo",
    "precision_status",
    "printed",
    "prose",
    "quote_has_number",
    "quote_numbers",
    "quote_policies",
]

PAPERS: dict[str, str] = {
    "WF": "Wu & Fowler, Application of MEMS for Improved Emitter Location Accuracy",
    "SP": "Schmidt & Phillips, INS/GPS Integration Architecture Performance Comparisons",
    "ATC10": "Schneider, Stiglitz & Eckberg, Surveillance Aspects of the AATMS (ATC-10)",
    "KZL": "Knedlik, Zhou & Loffeld, Position and Attitude Estimation for Bistatic SAR",
}
STATUSES = ("reproduced", "consistent", "inconsistent", "discrepant", "not-reproducible")
KINDS = ("reproduction", "cross-check", "statement", "fit")
POLICIES = ("printed-digits", "prose", "figure-reading", "monte-carlo", "exact")
RELATIONS = ("=", "<", "<=", ">", ">=")
Status = Literal["reproduced", "consistent", "inconsistent", "discrepant", "not-reproducible"]
Kind = Literal["reproduction", "cross-check", "statement", "fit"]
Policy = Literal["printed-digits", "prose", "figure-reading", "monte-carlo", "exact"]
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


@dataclass(frozen=True)
class Tolerance:
    """An absolute and/or relative tolerance, the policy that fixed it and the reason.

    The allowed deviation is ``max(abs, rel * |published|)``. ``policy`` is one of
    :data:`POLICIES` and ``reason`` says how the printed text gives the size; both are
    mandatory (the ledger's rules, "Tolerance: fixed before the value is computed"). Build one
    through its policy's helper (:func:`printed`, :func:`prose`, :func:`figure_reading`,
    :func:`monte_carlo`, :data:`EXACT`).

    Attributes
    ----------
    reason : str
        How the printed text gives the size (not empty).
    abs : float or None
        Absolute tolerance, in the claim's unit (finite, >= 0); ``None`` for none.
    rel : float or None
        Relative tolerance, a fraction of the published value (finite, >= 0); ``None``
        for none.
    policy : str
        One of :data:`POLICIES`; the ledger refuses a tolerance without one.
    quote : str
        The printed text the tolerance was fixed from (``"17.67"`` for :func:`printed`,
        ``"about"`` for :func:`prose`); a claim quotes it by default (not compared).
    loose_abs : float or None
        The absolute tolerance under the other reading of a whole number printed with
        trailing zeros and no decimal point (``"2750"``): half a unit in its last non-zero
        digit (module docstring, "Trailing zeros"); ``None`` when the printed digits leave no
        such reading. Set by :func:`printed`; at least ``abs``.

    Raises
    ------
    ValueError
        If ``reason`` is empty, ``policy`` is not one of :data:`POLICIES`, ``abs``, ``rel``
        or ``loose_abs`` is negative or not finite, or ``loose_abs`` is below ``abs``.

    Examples
    --------
    >>> tol = Tolerance(reason="3 standard errors of a 25-run mean", rel=0.06, policy="monte-carlo")
    >>> tol.allowed(50.0), tol.describe()
    (3.0, '±6 %')
    """

    reason: str
    abs: float | None = None
    rel: float | None = None
    policy: str = ""
    quote: str = field(default="", compare=False)
    loose_abs: float | None = None

    def __post_init__(self) -> None:
        if not self.reason or not self.reason.strip():
            raise ValueError("Tolerance.reason must say why the tolerance has its size")
        if self.policy and self.policy not in POLICIES:
            raise ValueError(f"Tolerance.policy must be one of {POLICIES}, got {self.policy!r}")
        for name in ("abs", "rel", "loose_abs"):
            value = getattr(self, name)
            if value is not None and not (value >= 0 and math.isfinite(value)):
                raise ValueError(f"Tolerance.{name} must be finite and >= 0, got {value!r}")
        if self.loose_abs is not None and self.loose_abs < (self.abs or 0.0):
            raise ValueError(f"Tolerance.loose_abs must be >= abs, got {self.loose_abs!r} < {self.abs!r}")

    def loose(self) -> Tolerance | None:
        """The tolerance under the reading that a whole number's trailing zeros are not
        significant (``abs`` = :attr:`loose_abs`); ``None`` when there is no such reading."""
        if self.loose_abs is None:
            return None
        return Tolerance(
            reason=self.reason, abs=self.loose_abs, rel=self.rel, policy=self.policy, quote=self.quote
        )

    @property
    def absolute(self) -> float:
        """The absolute part of the tolerance (a printed-digits half unit, say).

        Raises
        ------
        ValueError
            If the tolerance has no absolute part.
        """
        if self.abs is None:
            raise ValueError(f"tolerance {self.describe()!r} has no absolute part")
        return self.abs

    def allowed(self, published: float) -> float:
        """Return the allowed absolute deviation around ``published``."""
        a = self.abs or 0.0
        r = (self.rel or 0.0) * abs(published)
        return max(a, r)

    def as_dict(self) -> dict[str, Any]:
        """The tolerance as the ledger's JSON writes it: ``abs``, ``rel``, ``reason``, ``policy``,
        and ``loose_abs`` (``null`` unless a whole number's trailing zeros leave a second reading)."""
        return {
            "abs": self.abs,
            "rel": self.rel,
            "reason": self.reason,
            "policy": self.policy,
            "loose_abs": self.loose_abs,
        }

    def describe(self) -> str:
        """The size in short: ``"±0.005"``, ``"±10 %"``, both joined by "or", or ``"exact"``; a
        whole number's trailing zeros add the loose reading (``"±0.5 (±5 if trailing zeros are
        not significant)"``)."""
        parts = []
        if self.abs is not None and (self.abs or self.rel is None):
            parts.append("±" + _number_math(f"{self.abs:.4g}"))
        if self.rel is not None:
            parts.append(f"±{100 * self.rel:.3g} %")
        text = " or ".join(parts) if parts and parts != ["±0"] else "exact"
        if self.loose_abs is not None:
            text += f" (±{_number_math(f'{self.loose_abs:.4g}')} if trailing zeros are not significant)"
        return text


EXACT = Tolerance(reason="exact: an integer count or a logical statement", abs=0.0, policy="exact")

#: The one table of prose words and their bands (shown on the ledger page). A claim about a
#: word of this table compares with ``rel`` (relative) or ``abs_log10`` (in decades, for
#: claims published as a base-10 logarithm of a ratio); a word that names a count ("several",
#: "a few") has its ``centre`` and half-width ``abs``, which a statement reads as its range.
PROSE_WORDS: dict[str, dict[str, Any]] = {
    "about": {"rel": 0.10, "meaning": "within ±10 %"},
    "approximately": {"rel": 0.10, "meaning": "within ±10 %"},
    "nearly": {"rel": 0.10, "meaning": "within ±10 %"},
    "close to": {"rel": 0.10, "meaning": "within ±10 %"},
    "around": {"rel": 0.10, "meaning": "within ±10 % (read as 'about')"},
    "roughly": {"rel": 0.20, "meaning": "within ±20 %"},
    "on the order of": {"rel": 0.50, "meaning": "within ±50 %"},
    "of the order of": {"rel": 0.50, "meaning": "within ±50 %"},
    "several": {"abs": 3.0, "centre": 6.0, "meaning": "3 to 9 (published as 6 ± 3)"},
    "a few": {"abs": 1.5, "centre": 3.5, "meaning": "2 to 5 (published as 3.5 ± 1.5)"},
    "an order of magnitude": {
        "abs_log10": 0.5,
        "meaning": "a factor 3.16 either way of 10 (log10 ratio 1 ± 0.5)",
    },
    "orders of magnitude": {"abs_log10": 0.5, "meaning": "±0.5 decade on the log10 ratio"},
    "~": {"rel": 0.10, "meaning": "within ±10 % (read as 'approximately')"},
    "≈": {"rel": 0.10, "meaning": "within ±10 % (read as 'approximately')"},
}


def printed(text: str, *, extra_abs: float = 0.0, why: str = "") -> tuple[float, Tolerance]:
    """Parse a number as printed and return it with a half-last-digit tolerance.

    ``printed("17.67")`` gives ``(17.67, Tolerance(abs=0.005, ...))``; ``printed("1.2e-3")``
    gives half a unit of the last mantissa digit times the exponent. ``extra_abs`` adds what
    the paper's own rounding of intermediate values can explain (the text must show that
    rounding); ``why`` says so. Policy ``printed-digits``.

    The trailing zeros of a whole number printed without a decimal point or an exponent
    (``"2750"``, ``"20"``, ``"3300"``) are ambiguous: the tolerance carries both readings,
    ``abs`` half a unit in the last digit (every digit significant) and ``loose_abs`` half a
    unit in the last non-zero digit (the trailing zeros not significant), and the verdict
    weighs them (module docstring, "Trailing zeros").

    Parameters
    ----------
    text : str
        The number exactly as printed (``"17.67"``, ``"1.2e-3"``, ``"−4"`` with a minus
        sign); its digits fix the tolerance, so trailing zeros matter.
    extra_abs : float, optional
        Added to the half unit, in the number's unit: what the paper's own rounding of
        intermediate values explains.
    why : str, optional
        Appended to the tolerance's reason (why ``extra_abs`` is added, or how the printed
        number applies).

    Returns
    -------
    value : float
        The printed number.
    tolerance : Tolerance
        Policy ``printed-digits`` with ``abs`` half a unit in the last printed digit plus
        ``extra_abs``; for a whole number with trailing zeros also ``loose_abs``, half a unit in
        its last non-zero digit plus ``extra_abs``.

    Raises
    ------
    ValueError
        If ``text`` is not a printed number.

    Examples
    --------
    >>> value, tol = printed("17.67")
    >>> value, tol.abs, tol.policy
    (17.67, 0.005, 'printed-digits')
    >>> printed("1.2e-3")[1].abs
    5e-05
    >>> tol = printed("2750")[1]
    >>> tol.abs, tol.loose_abs, tol.describe()
    (0.5, 5.0, '±0.5 (±5 if trailing zeros are not significant)')
    >>> printed("2751")[1].loose_abs is None, printed("20.0")[1].loose_abs is None
    (True, True)
    """
    s = text.strip().replace("−", "-")
    m = re.fullmatch(r"([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?", s)
    if not m or (not m.group(2) and not m.group(3)):
        raise ValueError(f"text must be a printed number such as '17.67' or '1.5e-3', got {text!r}")
    decimals = len(m.group(3) or "")
    exponent = int(m.group(4) or 0)
    value = float(s)
    half = 0.5 * 10.0 ** (exponent - decimals)
    reason = f"half a unit in the last printed digit of {_number_math(text.strip())}"
    if extra_abs:
        reason += f", plus {_number_math(f'{extra_abs:g}')}" + (f" ({why})" if why else "")
    elif why:
        reason += f"; {why}"
    loose_abs = None
    zeros = _trailing_zeros(m.group(2)) if m.group(3) is None and m.group(4) is None else 0
    if zeros:
        loose_abs = round(0.5 * 10.0**zeros + extra_abs, 15)
        zeros_are = "zeros are" if zeros > 1 else "zero is"
        reason += f", or in its last non-zero digit if its trailing {zeros_are} not significant"
    return value, Tolerance(
        reason=reason,
        abs=round(half + extra_abs, 15),
        policy="printed-digits",
        quote=text.strip(),
        loose_abs=loose_abs,
    )


def _number_math(text: str) -> str:
    r"""A number as a reader sees it: one in e-notation as inline math, any other unchanged.

    Examples
    --------
    >>> _number_math("1.61e-4"), _number_math("184e1"), _number_math("1e-12"), _number_math("0.011")
    ('$1.61 \\times 10^{-4}$', '$184 \\times 10^{1}$', '$10^{-12}$', '0.011')
    """
    m = re.fullmatch(r"([+-]?)(\d*(?:\.\d*)?)[eE]([+-]?\d+)", text.replace("−", "-"))
    if not m:
        return text
    sign, mantissa, exponent = m.group(1), m.group(2), int(m.group(3))
    if mantissa == "1":
        return f"${sign}10^{{{exponent}}}$"
    return f"${sign}{mantissa} \\times 10^{{{exponent}}}$"


def _trailing_zeros(digits: str) -> int:
    """How many trailing zeros a whole number's digits end with after a non-zero digit (0 for
    ``"2751"`` and for ``"0"``)."""
    stripped = digits.rstrip("0")
    return len(digits) - len(stripped) if stripped.strip("0") else 0


def prose(word: str, *, why: str = "") -> Tolerance:
    """The tolerance of a prose word from :data:`PROSE_WORDS` (policy ``prose``).

    Parameters
    ----------
    word : str
        The word or phrase as the paper prints it (``"about"``, ``"on the order of"``); case
        and surrounding spaces are ignored. It must be a key of :data:`PROSE_WORDS`.
    why : str, optional
        Appended to the tolerance's reason (how the word applies to this claim).

    Returns
    -------
    Tolerance
        Policy ``prose``: ``rel`` for a relative band, ``abs`` for an absolute band, or
        ``abs`` in decades for a base-10 logarithm of a ratio (the ledger's rules, "Tolerance: fixed
        before the value is computed").

    Raises
    ------
    ValueError
        If ``word`` is not in :data:`PROSE_WORDS`.

    Examples
    --------
    >>> prose("about").rel
    0.1
    """
    key = word.strip().lower()
    if key not in PROSE_WORDS:
        raise ValueError(f"word must be one of {sorted(PROSE_WORDS)}, got {word!r}")
    band = PROSE_WORDS[key]
    reason = f"'{key}' in prose: {band['meaning']}" + (f"; {why}" if why else "")
    if "rel" in band:
        return Tolerance(reason=reason, rel=band["rel"], policy="prose", quote=key)
    if "abs" in band:
        return Tolerance(reason=reason, abs=band["abs"], policy="prose", quote=key)
    return Tolerance(reason=reason, abs=band["abs_log10"], policy="prose", quote=key)


def figure_reading(resolution: float, *, figure: str, axis: str) -> Tolerance:
    """Tolerance of a value read off ``figure``: the reading resolution of its ``axis``.

    Parameters
    ----------
    resolution : float
        The reading resolution of the axis, in the claim's unit; finite and > 0.
    figure : str
        The figure the value is read off (``"Fig. 2.1"``).
    axis : str
        The axis and how finely it can be read (``"loop bandwidth, 0.5 Hz per minor
        division"``).

    Returns
    -------
    Tolerance
        Policy ``figure-reading`` with ``abs = resolution`` (the ledger's rules, "Tolerance: fixed
        before the value is computed").

    Raises
    ------
    ValueError
        If ``resolution`` is not finite and > 0.

    Examples
    --------
    >>> figure_reading(0.5, figure="Fig. 2.1", axis="loop bandwidth, 0.5 Hz per minor division").abs
    0.5
    """
    if not (resolution > 0 and math.isfinite(resolution)):
        raise ValueError(f"resolution must be finite and > 0, got {resolution!r}")
    return Tolerance(
        reason=f"read off {figure}: {axis} (reading resolution {resolution:g})",
        abs=resolution,
        policy="figure-reading",
    )


def monte_carlo(*, rel: float | None = None, abs: float | None = None, runs: int, why: str) -> Tolerance:
    """Tolerance from the sampling error of ``runs`` Monte Carlo runs (policy ``monte-carlo``).

    The size is computed by the caller from the run count and the published value (never from
    the reproduced one) and ``why`` says how (e.g. "3 standard errors of a 25-run CEP").

    Parameters
    ----------
    rel : float or None, optional
        Relative tolerance (a fraction of the published value).
    abs : float or None, optional
        Absolute tolerance, in the claim's unit.
    runs : int
        The number of Monte Carlo runs behind the published value; >= 1.
    why : str
        How the size follows from ``runs`` and the published value.

    Returns
    -------
    Tolerance
        Policy ``monte-carlo`` (the ledger's rules, "Tolerance: fixed before the value is computed").

    Raises
    ------
    ValueError
        If ``runs < 1``, or (from :class:`Tolerance`) ``rel`` or ``abs`` is negative or not
        finite.

    Examples
    --------
    Three standard errors of a 25-run root-mean-square error (a relative standard error of
    about ``1 / sqrt(2 * 25)``):

    >>> tol = monte_carlo(rel=round(3 / (2 * 25) ** 0.5, 2), runs=25,
    ...                   why="3 standard errors of a 25-run RMS error")
    >>> tol.rel, tol.policy, tol.describe()
    (0.42, 'monte-carlo', '±42 %')
    """
    if runs < 1:
        raise ValueError(f"runs must be >= 1, got {runs!r}")
    return Tolerance(reason=f"Monte Carlo of {runs} runs: {why}", abs=abs, rel=rel, policy="monte-carlo")


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
    aliases : tuple of str
        Former ids that still refer to this claim.
    printed : str
        The paper's words or formula as quoted (``"approximately 1.4"``, ``"P_D >= 1 exp
        -K(...)"``); empty to quote the text given to the tolerance (``printed("17.67")``
        quotes ``17.67``; :func:`claim_quote`). The tolerance policy must follow it
        (:func:`quote_policies`) and a number claim's quote must contain its published
        number (:func:`quote_has_number`).

    Raises
    ------
    ValueError
        If the id does not start with its paper key and a dash, a value is not one of its
        table (:data:`PAPERS`, :data:`STATUSES`, :data:`RELATIONS`, :data:`KINDS`), the
        note is empty, a truth value is a ``reproduction`` or uses a bound, ``printed`` is
        not a string, or a discrepant claim lacks its erratum, oracle or oracle tolerance.
        (A computed claim may expect ``not-reproducible``: a band too wide to decide.)

    Examples
    --------
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
        :data:`EXACT` unless given and its expected verdict ``reproduced`` unless given.
        Every other field is :class:`Claim`'s, by keyword.

        Parameters
        ----------
        id, locator, quantity, compute, note, discussed_in
            As for :class:`Claim`.
        tolerance : Tolerance or callable, optional
            :data:`EXACT` by default (a truth value is met or not).
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
        """The expected verdict (the derived one is on the :class:`Evaluation`)."""
        return self.expected_status


# ---------------------------------------------------------------------------------------
# what the paper printed: the quote, its numbers, and the policy it calls for

#: Words and signs of approximation in a quote: the tolerance is the prose table's band.
_PROSE_MARKERS = re.compile(
    "|".join(
        [re.escape(w) for w in PROSE_WORDS if not w[0].isalpha()]
        + [r"\b" + re.escape(w).replace(r"\ ", r"\s+") + r"\b" for w in PROSE_WORDS if w[0].isalpha()]
        + [r"\bapprox\b\.?"]
    ),
    re.IGNORECASE,
)
#: Words by which a paper says it read a value from its figures.
_FIGURE_MARKERS = re.compile(
    r"\bread\s+(?:from|off)\b|\bfrom\s+(?:the\s+)?(?:figs?\b\.?|figures?|curves?|graphs?|plots?)",
    re.IGNORECASE,
)
_FIGURE_LOCATOR = re.compile(r"\bFigs?\.\s*\d")


def claim_quote(claim: Claim, tol: Tolerance | None = None) -> tuple[str, str]:
    """The paper's text a claim quotes, and where the quote comes from.

    Parameters
    ----------
    claim : Claim
        The claim.
    tol : Tolerance or None, optional
        Its resolved tolerance; ``None`` resolves it (where no input can be read).

    Returns
    -------
    quote : str
        The claim's ``printed`` if given, else the text its tolerance was fixed from; ``""``
        when neither is known.
    source : str
        ``"claim"`` (the claim quotes the paper), ``"digits"`` (the number given to
        :func:`printed`), ``"word"`` (the word given to :func:`prose`, without its number)
        or ``"none"``.

    Examples
    --------
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> claim_quote(c)
    ('17.67', 'digits')
    >>> import dataclasses
    >>> claim_quote(dataclasses.replace(c, printed="omega_0 = 17.67 rad/s"))
    ('omega_0 = 17.67 rad/s', 'claim')
    """
    if claim.printed.strip():
        return claim.printed.strip(), "claim"
    if tol is None:
        try:
            tol = resolve_tolerance(claim)
        except Exception:
            return "", "none"
    quote = tol.quote.strip()
    if not quote:
        return "", "none"
    return quote, ("digits" if tol.policy == "printed-digits" else "word")


_SCI = re.compile(r"([+-]?\d+(?:\.\d+)?)\s*(?:×|\*|·|x)\s*10\s*(?:\^|\*\*)\s*\{?\s*([+-]?\d+)\s*\}?")
_POW10 = re.compile(r"(?<![\d.])10\s*(?:\^|\*\*)\s*\{?\s*([+-]?\d+)\s*\}?")
_PLAIN = re.compile(r"(?<![\w.])[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?(\s*%)?")
_FRACTION = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)\s*/\s*(\d+(?:\.\d+)?)(?![\w.])")


def quote_numbers(quote: str) -> list[float]:
    """Every number a quote prints, in the forms papers print them.

    Reads plain and signed numbers (a Unicode minus too), thousands separators (``3,300``),
    ``1.5e-3``, ``1.5 × 10^-3`` and ``10^5``, simple fractions (``1/2`` gives 0.5 besides 1
    and 2) and percentages (``50 %`` gives 0.5 besides 50).

    Parameters
    ----------
    quote : str
        The quoted text.

    Returns
    -------
    list of float
        The numbers found (with the extra readings above), in no particular order.

    Examples
    --------
    >>> sorted(quote_numbers("about 3,300 m, i.e. 1.5 × 10^-3 of it, −4 dB, 50 %"))
    [-4.0, 0.0015, 0.5, 50.0, 3300.0]
    """
    text = quote.replace("−", "-").replace("\u2009", " ")
    text = re.sub(r"(?<=\d),(?=\d{3}(?!\d))", "", text)
    out: list[float] = []
    for m in _SCI.finditer(text):
        out.append(float(m.group(1)) * 10.0 ** int(m.group(2)))
    text = _SCI.sub(" ", text)  # a mantissa or an exponent alone is not a printed number
    for m in _POW10.finditer(text):
        out.append(10.0 ** int(m.group(1)))
    text = _POW10.sub(" ", text)
    for m in _FRACTION.finditer(text):
        if float(m.group(2)) != 0:
            out.append(float(m.group(1)) / float(m.group(2)))
    for m in _PLAIN.finditer(text):
        number = m.group(0)[: len(m.group(0)) - len(m.group(1) or "")]
        try:
            value = float(number)
        except ValueError:
            continue
        out.append(value)
        if m.group(1):
            out.append(value / 100.0)
    return out


def quote_has_number(quote: str, published: float) -> bool:
    """Whether ``quote`` prints ``published`` (to a relative 1e-9): what "published" means.

    Parameters
    ----------
    quote : str
        The quoted text (:func:`claim_quote`).
    published : float
        The claim's published value.

    Returns
    -------
    bool
        Whether one of :func:`quote_numbers` equals ``published`` to a relative 1e-9 (an
        absolute 1e-9 below 1).

    Examples
    --------
    >>> quote_has_number("approximately 1.4", 1.4), quote_has_number("nearly uncorrelated", 0.3679)
    (True, False)
    """
    target = float(published)
    scale = 1e-9 * max(1.0, abs(target))
    return any(abs(n - target) <= scale for n in quote_numbers(quote))


def label_prints_value(label: str, value: Any) -> bool:
    r"""Whether a reading's label already prints its value, in its own unit or with an SI
    prefix (``"the C/A code, 1.023 Mchip/s"`` for :math:`1.023 \times 10^6` Hz, ``"within 1 %"``
    for 0.01), so that a text naming the reading need not show the value again.

    Parameters
    ----------
    label : str
        The reading's label (a convention's ``readings`` key).
    value : Any
        The value it sets; only a real number can be printed.

    Returns
    -------
    bool
        Whether one of the label's numbers (:func:`quote_numbers`) times a power of 1000 equals
        the value to a relative :math:`10^{-9}`.

    Examples
    --------
    >>> label_prints_value("the C/A code, 1.023 Mchip/s", 1.023e6), label_prints_value("within 1 %", 0.01)
    (True, True)
    >>> label_prints_value("the C/A code", 1.023e6), label_prints_value("a factor 3", 2.0)
    (False, False)
    """
    if isinstance(value, bool) or not isinstance(value, int | float) or value == 0:
        return False
    target = float(value)
    return any(
        abs(n * 1000.0**k - target) <= 1e-9 * abs(target) for n in quote_numbers(label) for k in range(-4, 5)
    )


def quote_policies(quote: str, *, published: float | bool, locator: str = "") -> tuple[str, ...]:
    """The tolerance policies the printed words admit (the ledger's rules, "Tolerance").

    The rule: a truth value is ``exact``; a quote with a word or sign of approximation
    ("approximately", "about", "of the order of", "~", "≈", "roughly", "nearly", any word of
    :data:`PROSE_WORDS`) is ``prose``; a value the paper says it read from its figures ("read
    from", "from the figures") is ``figure-reading``; otherwise the number is taken as printed:
    ``printed-digits``, or ``monte-carlo`` (a paper that states a run count), ``exact`` for an
    integer, ``figure-reading`` for a value at a figure's locator.

    Parameters
    ----------
    quote : str
        The claim's quoted text (:func:`claim_quote`).
    published : float or bool
        The claim's published value.
    locator : str, optional
        The claim's locator (a figure admits ``figure-reading``).

    Returns
    -------
    tuple of str
        The admissible policies of :data:`POLICIES`.

    Examples
    --------
    >>> quote_policies("Exp ≈ 9", published=9.0), quote_policies("17.67", published=17.67)
    (('prose',), ('printed-digits', 'monte-carlo'))
    >>> quote_policies("43 dBW, as read from the figures", published=43.0)
    ('figure-reading',)
    """
    if isinstance(published, bool):
        return ("exact",)
    markers = (("prose", _PROSE_MARKERS), ("figure-reading", _FIGURE_MARKERS))
    found = tuple(policy for policy, marker in markers if marker.search(quote))
    if found:
        return found
    out = ["printed-digits", "monte-carlo"]
    if math.isfinite(float(published)) and float(published).is_integer():
        out.append("exact")
    if _FIGURE_LOCATOR.search(locator):
        out.append("figure-reading")
    return tuple(out)


# ---------------------------------------------------------------------------------------
# a band too wide to decide

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


@dataclass(frozen=True)
class Evaluation:
    """The result of evaluating one claim: its value, band, inputs and derived verdict.

    ``passes`` is true when the derived ``status`` equals the claim's ``expected_status``
    and, for a discrepancy, the erratum is named and the oracle agrees. Built by
    :func:`evaluate`.

    Attributes
    ----------
    claim : Claim
        The claim evaluated.
    reproduced : float, bool or None
        The value computed at the nominal inputs, in the claim's unit (a truth value for a
        statement); ``None`` when nothing was computed or the computation failed.
    passes : bool
        Whether the derived verdict is the expected one (and, for a discrepancy, the
        oracle agrees).
    detail : str
        Why it passes or fails, in words.
    oracle_value : float, bool or None
        The independent oracle's value (discrepant claims only).
    status : str
        The derived verdict, one of :data:`STATUSES`, or ``"error"`` when the tolerance,
        the computation, the band or the oracle raised.
    tolerance : Tolerance or None
        The claim's tolerance as resolved before the computation.
    inputs : tuple of dict
        The inputs the computation read, sorted by name: ``name``, ``provenance``,
        ``locator`` (published) or ``reason`` (the others), and ``value``.
    band : tuple of (float, float) or None
        Lowest and highest value across the assumed inputs' ranges (with the nominal);
        ``None`` when no assumed input was read.
    sensitivity : tuple
        Per assumed input, ``(name, ((point, value), ...))``: the claim's value at each band
        point of that input, the others nominal.
    readings : tuple of dict
        One per combination of the readings of the conventions read (empty when none is
        read), the reading used first: ``reading`` (input name -> label of its reading),
        ``nominal`` (the reading used), ``value`` (at the nominal assumed inputs), ``band``
        (``[low, high]`` over the assumed ranges when the verdict needed it, else ``None``),
        ``agrees`` (whether the printed value is accepted by the value, or by the band when
        one was run) and ``band_too_wide``.
    band_too_wide : bool
        Whether the verdict is ``not-reproducible`` because every band that agrees is too
        wide to decide (:func:`band_too_wide`; each reading's own flag is in ``readings``).
    left_out : tuple of dict
        The band runs left out as outside the model's domain (module docstring, "Band runs"),
        one per case in the order met: ``case`` (the reader's words of the
        :class:`~navcore.ModelDomainError`) and ``runs`` (how many runs met it).
    envelope : tuple of (float, float) or None
        Set when the verdict is ``not-reproducible`` because, with more than
        :data:`MAX_CORNER_INPUTS` assumed inputs, the runs do not reach the printed value
        while the inputs' separate effects add up to it (:func:`additive_envelope`, of the
        reading used if it is the one, else of the first other reading that is; its entry
        in ``readings`` has ``undecided`` true; module docstring, "Beyond six inputs");
        else ``None``.

    Examples
    --------
    >>> value, tol = printed("17.67")
    >>> c = Claim(id="SP-doc-omega", paper="SP", locator="Fig. 2.1", quantity="natural frequency",
    ...           published=value, unit="rad/s", compute=lambda: 17.671, tolerance=tol,
    ...           expected_status="reproduced", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.status, ev.passes, round(ev.deviation, 6), ev.printed
    ('reproduced', True, 0.001, '17.67')
    """

    claim: Claim
    reproduced: Any
    passes: bool
    detail: str
    oracle_value: Any = None
    status: str = "not-reproducible"
    tolerance: Tolerance | None = None
    inputs: tuple[dict[str, Any], ...] = ()
    band: tuple[Any, Any] | None = None
    sensitivity: tuple[tuple[str, tuple[tuple[Any, Any], ...]], ...] = ()
    readings: tuple[dict[str, Any], ...] = ()
    band_too_wide: bool = False
    left_out: tuple[dict[str, Any], ...] = ()
    envelope: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        # comparisons on numpy scalars give numpy booleans: store a plain bool
        object.__setattr__(self, "passes", bool(self.passes))

    @property
    def deviation(self) -> float | None:
        """``reproduced - published`` for numeric claims, else ``None``."""
        if self.claim.is_statement or self.reproduced is None:
            return None
        return float(self.reproduced) - float(self.claim.published)

    @property
    def kind(self) -> str:
        """The claim's kind (:data:`KINDS`)."""
        return str(self.claim.kind)

    @property
    def printed(self) -> str:
        """The paper's text the claim quotes (:func:`claim_quote`); ``""`` when unknown."""
        return claim_quote(self.claim, self.tolerance)[0]

    @property
    def agreeing_readings(self) -> tuple[dict[str, Any], ...]:
        """The readings (of :attr:`readings`) under which the printed value is accepted."""
        return tuple(r for r in self.readings if r["agrees"])

    def _reading_words(self, reading: dict[str, Any]) -> list[str]:
        """What a reading changes from the one used, in words, one phrase per changed input:
        "the chip rate read as the P code (...)", or, for an input described by a clause rather
        than a noun ("how much ... must fall"), "a change of more than 1 % for how much ..."."""
        changed = []
        for name, label in reading["reading"].items():
            if name == PRECISION_READING:
                if label != PRECISION_STRICT:
                    changed.append(f"the printed number's {label}")
                continue
            quantity, in_unit = _label_and_unit(name)
            in_unit = _unit_text(in_unit)
            try:
                inp = get_input(name)
            except ValueError:
                inp = None
            if inp is not None and label == inp.nominal_label:
                continue
            value = next((v for lab, v in (inp.readings if inp else ()) if lab == label), None)
            # a tuple's items go inside the one pair of parentheses below
            items = value if isinstance(value, tuple | list) else () if value is None else (value,)
            shown = ", ".join(_plain(v) for v in items)
            if items and all(_label_prints(label, v) for v in items):
                shown = ""  # "the C/A code, 1.023 Mchip/s" says its value: not again in Hz
            shown = f" ({shown}{' ' + in_unit if in_unit and shown else ''})" if shown else ""
            words = reader_label(label) + shown
            if quantity.lower().startswith(_CLAUSE_WORDS):
                changed.append(f"{words} for {quantity}")
            else:
                changed.append(f"the {quantity} read as {words}")
        return changed

    def _note_digits(self) -> int:
        """Significant digits of the numbers a note's generated sentences print: the printed
        value's, plus two (:func:`note_digits`)."""
        tol = self.tolerance if isinstance(self.tolerance, Tolerance) else None
        return note_digits(self.claim, tol)

    def _num(self, value: Any) -> str:
        """A value of the claim in a generated sentence, at the claim's :meth:`_note_digits`."""
        return _plain(value, self._note_digits())

    def _range(self, lo: Any, hi: Any, unit: str) -> str:
        """``"lo to hi unit"``; ``""`` when the two ends print the same."""
        a, b = self._num(lo), self._num(hi)
        return "" if a == b else f"{a} to {b}{unit}"

    def _unit(self, value: Any = None) -> str:
        """The claim's unit after a number (" m"); a count unit in the singular after one."""
        if self.claim.unit in ("", "statement"):
            return ""
        unit = self.claim.unit
        if unit in COUNT_UNITS and value is not None and not isinstance(value, bool):
            try:
                if float(value) == 1:
                    unit = unit[:-1]
            except (TypeError, ValueError):
                pass
        return f" {_unit_text(unit)}"

    def _reading_outcome(self, reading: dict[str, Any]) -> str:
        """What one reading gives and whether it agrees: the text after "With ...: "."""
        value = reading["value"]
        band = reading.get("band")
        # a claim with assumed inputs whose band this reading did not need (the verdict was settled)
        at_nominal = " at the nominal inputs" if band is None and self.band is not None else ""
        if not _is_truth(value):
            text = self._num(value) + self._unit(value) + at_nominal
            if band is not None:
                spans = self._range(band[0], band[1], self._unit())
                text += f" (over the assumed ranges {spans})" if spans else ""
        elif band is None or bool(band[0]) == bool(band[1]):
            text = ("holds" if value else "does not hold") + (
                " across the assumed ranges" if band else at_nominal
            )
        else:
            text = (
                "holds at the nominal inputs, not across all the assumed ranges"
                if value
                else "does not hold at the nominal inputs, but holds over part of the assumed ranges"
            )
        if reading["agrees"]:
            at_value = band is None or self._agrees_at_value(reading)
            too_wide = band is not None and reading.get("band_too_wide", False)
            if at_value and not too_wide:
                text += ", which agrees with the printed value"
            elif at_value:
                text += "; the value agrees with the printed value, but the range is too wide to decide"
            elif _is_truth(value):
                text += "; only part of the assumed ranges agrees with the printed value"
            else:
                text += "; the value does not agree with the printed value, only part of that range does"
        return text

    def _agrees_at_value(self, reading: dict[str, Any]) -> bool:
        """Whether a reading's value itself (not its band) agrees with the printed value."""
        tol = self.tolerance if isinstance(self.tolerance, Tolerance) else None
        if tol is None:
            return bool(reading["agrees"])
        if reading["reading"].get(PRECISION_READING) == PRECISION_LOOSE:
            tol = tol.loose() or tol
        try:
            return _outcome(self.claim, tol, reading["value"], ()).agrees_at_value
        except (TypeError, ValueError):
            return bool(reading["agrees"])

    def _reading_text(self, reading: dict[str, Any]) -> str:
        """One reading other than the one used, in words: what differs and what it gives."""
        return (
            "With " + " and ".join(self._reading_words(reading)) + ": " + self._reading_outcome(reading) + "."
        )

    def inert_conventions(self) -> tuple[str, ...]:
        """The conventions read whose other readings change nothing, when the claim reads more
        than one (a cross product of readings to thin out): every reading that differs from
        another only in one of them gives the same value, band and agreement (an input the
        claim's computation reads on its way but whose reading does not reach the result).
        ``()`` when there is no reading used to compare with."""
        nominal = next((r for r in self.readings if r["nominal"]), None)
        if nominal is None:
            return ()
        names = list(nominal["reading"])
        if len(names) < 2:
            return ()
        inert = []
        for name in names:
            used = nominal["reading"][name]
            groups: dict[tuple, list[tuple[bool, tuple]]] = {}
            for r in self.readings:
                key = tuple(sorted((k, v) for k, v in r["reading"].items() if k != name))
                groups.setdefault(key, []).append((r["reading"].get(name) == used, _reading_result(r)))
            varied = [g for g in groups.values() if any(not is_used for is_used, _ in g)]
            if varied and all(any(is_used for is_used, _ in g) and _same_results(g) for g in varied):
                inert.append(name)
        return tuple(inert)

    def shown_readings(self) -> tuple[dict[str, Any], ...]:
        """The readings other than the one used that a reader is shown: those whose inert
        conventions (:meth:`inert_conventions`) keep their reading used."""
        nominal = next((r for r in self.readings if r["nominal"]), None)
        inert = self.inert_conventions()
        return tuple(
            r
            for r in self.readings
            if not r["nominal"]
            and all(r["reading"].get(n) == nominal["reading"][n] for n in inert if nominal is not None)
        )

    def _readings_sentences(self) -> list[str]:
        """The sentences on the other readings: one per reading shown, or one for all of them
        when every combination gives the same; then one naming the conventions whose readings
        change nothing (:meth:`inert_conventions`)."""
        shown = self.shown_readings()
        tails = [self._reading_outcome(r) for r in shown]
        nominal = next((r for r in self.readings if r["nominal"]), None)
        extra: list[str] = []
        if nominal is not None and len(shown) > 1 and len(set(tails)) == 1:
            labels = _other_labels(nominal, shown)
            if len(shown) == math.prod(len(ls) + 1 for ls in labels.values()) - 1:
                together = ", alone or together," if len(labels) > 1 else ""
                phrases = "; ".join(_alternatives_phrase(n, ls) for n, ls in labels.items())
                extra.append(f"The other readings{together} give the same ({tails[0]}): {phrases}.")
                shown = ()
        extra += [self._reading_text(r) for r in shown]
        inert = self.inert_conventions()
        if inert and nominal is not None:
            labels = _other_labels(nominal, [r for r in self.readings if not r["nominal"]], only=inert)
            phrases = "; ".join(_alternatives_phrase(n, ls) for n, ls in labels.items())
            # a reading whose band the verdict did not need was compared at the nominal inputs only
            kept = [id(r) for r in self.shown_readings()]
            folded = [r for r in self.readings if not r["nominal"] and id(r) not in kept]
            what = (
                "the result at the nominal inputs"
                if self.band is not None and any(r.get("band") is None for r in folded)
                else "the result"
            )
            if len(labels) > 1 or any(len(ls) > 1 for ls in labels.values()):
                # "together" only where the readings combine them (else each was run alone)
                combined = any(
                    sum(r["reading"].get(n) != nominal["reading"][n] for n in inert) > 1
                    for r in self.readings
                )
                together = (
                    (", alone or together," if combined else ", each alone,") if len(labels) > 1 else ""
                )
                extra.append(f"The other readings{together} leave {what} unchanged: {phrases}.")
            else:
                extra.append(f"The other reading leaves {what} unchanged: {phrases}.")
        return extra

    def note(self) -> str:
        """The claim's note, then what the other readings give and why the verdict is what it is.

        Generated sentences follow the note: one per reading other than the one used (what
        it gives, and whether it agrees); where the reading used disagrees and another
        agrees, that the claim is therefore not discrepant; where the band is too wide, that
        the assumptions are too loose to decide.
        """
        text = self.claim.note.rstrip()
        extra = self._readings_sentences()
        nominal = next((r for r in self.readings if r["nominal"]), None)
        if (
            self.status == "consistent"
            and nominal is not None
            and not nominal["agrees"]
            and any(r["agrees"] for r in self.readings)
        ):
            extra.append(
                "The reading used disagrees and another admissible reading agrees: an open reading "
                "of the text, not a discrepancy."
            )
        if self.band_too_wide and self.band is not None:
            lo, hi = self.band
            unit = self._unit()
            if self.claim.is_statement:
                extra.append(
                    ("It" if nominal is None or nominal["agrees"] else "The reading that agrees")
                    + " holds for some of the assumed inputs and fails for others: the assumptions "
                    "are too loose to decide."
                )
            elif nominal is None or nominal["agrees"]:
                extra.append(
                    "Over the assumed inputs' ranges the value spans "
                    f"{self._num(lo)} to {self._num(hi)}{unit}, "
                    f"ends more than a factor {BAND_FACTOR:g} apart, and the printed value agrees with "
                    "only part of it: the assumptions are too loose to decide."
                )
            else:
                extra.append(
                    "The reading that agrees does so over only part of a band whose ends are more than "
                    f"a factor {BAND_FACTOR:g} apart: the assumptions are too loose to decide."
                )
        if self.envelope is not None and self.band is not None:
            unit = self._unit()
            n = sum(1 for i in self.inputs if i["provenance"] == "assumed")
            other = next((r for r in self.readings if r.get("undecided") and not r["nominal"]), None)
            if other is not None and not any(r.get("undecided") and r["nominal"] for r in self.readings):
                who = " and ".join(self._reading_words(other))
                lead = f"With {who}, the runs over the {n} assumed inputs do not reach the printed value"
            else:
                lead = f"The runs over the {n} assumed inputs do not reach the printed value"
            extra.append(
                f"{lead}, but the inputs' "
                "separate effects add up to "
                f"{self._num(self.envelope[0])} to {self._num(self.envelope[1])}{unit}, "
                f"which does: beyond {MAX_CORNER_INPUTS} inputs the corners run are a sample of the box, "
                "so the search cannot show the printed value out of reach."
            )
        if self.left_out:
            extra.append(
                "The band leaves out, as outside the model's domain, "
                + "; ".join(f"{_n_runs(c['runs'])} where {c['case']}" for c in self.left_out)
                + "."
            )
        if text and extra and not text.endswith((".", "!", "?", ")")):
            text += "."
        return " ".join([text, *extra]).strip()

    def as_json(self, errata: Sequence[Erratum] | None = None) -> dict[str, Any]:
        """The ledger's fields, and no others.

        Parameters
        ----------
        errata : sequence of Erratum or None, optional
            Where to look for the errata the claim is evidence for (:func:`claim_errata`);
            ``None`` for every erratum constructed in the process.
        """
        c = self.claim
        pub = c.published if isinstance(c.published, bool) else float(c.published)
        tol = self.tolerance if self.tolerance is not None else c.tolerance
        quote = claim_quote(c, tol if isinstance(tol, Tolerance) else None)[0]
        return {
            "id": c.id,
            "paper": c.paper,
            "locator": c.locator,
            "quantity": c.quantity,
            "published": pub,
            "relation": c.relation,
            "unit": c.unit,
            "printed": quote or None,
            "errata": claim_errata(c, errata),
            "kind": c.kind,
            "inputs": [dict(i) for i in self.inputs],
            "reproduced": _json_value(self.reproduced),
            "band": None if self.band is None else [_json_value(b) for b in self.band],
            "readings": [
                {
                    "reading": dict(r["reading"]),
                    "nominal": bool(r["nominal"]),
                    "value": _json_value(r["value"]),
                    "band": None if r.get("band") is None else [_json_value(b) for b in r["band"]],
                    "agrees": bool(r["agrees"]),
                    "band_too_wide": bool(r.get("band_too_wide", False)),
                }
                for r in self.readings
            ],
            "tolerance": tol.as_dict() if isinstance(tol, Tolerance) else None,
            "status": self.status,
            "note": self.note(),
        }


def _unit_text(unit: str) -> str:
    """A unit as a reader sees it in a note (:func:`navcore.formatting.unit_text`: ``m³/s²``,
    not ``m^3/s^2``)."""
    return unit_text(unit) if unit else unit


def _plain(value: Any, digits: int = 6) -> str:
    r"""A value in a note's text: ``digits`` significant digits (six unless a claim's note asks
    for its own, :func:`note_digits`), a very large or small number as inline math (never a
    program's ``1.023e+06`` or a string of zeros such as ``0.00094007``), an infinite one as
    the symbol.

    Examples
    --------
    >>> _plain(1023000.0), _plain(0.00094007), _plain(0.0226556), _plain(2.5), _plain(True)
    ('$1.023 \\times 10^{6}$', '$9.4007 \\times 10^{-4}$', '0.0226556', '2.5', 'true')
    >>> _plain(0.00353918)
    '$3.53918 \\times 10^{-3}$'
    >>> _plain(72.4315, 4), _plain(476.476, 4), _plain(float("inf")), _plain(-float("inf"))
    ('72.43', '476.5', '∞', '−∞')

    A tuple (a reading that sets several numbers) lists its items, each written the same way:

    >>> _plain((6, 4, 55.0, 0.0))
    '(6, 4, 55, 0)'
    """
    if isinstance(value, tuple | list):
        return "(" + ", ".join(_plain(v, digits) for v in value) + ")"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isinf(value):
            return "∞" if value > 0 else "−∞"
        if 1 <= abs(value) < 1e6:  # every digit before the point, never 1.2e+03 for 1234.5
            digits = max(digits, math.floor(math.log10(abs(value))) + 1)
        text = f"{value:.{digits}g}"
        if value != 0 and abs(value) < 1e-2 and "e" not in text:  # else eight decimals or more
            mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
            text = mantissa.rstrip("0").rstrip(".") + "e" + exponent
        return _number_math(text)
    return str(value)


def note_digits(claim: Claim, tol: Tolerance | None = None) -> int:
    """Significant digits of the numbers in a claim's generated sentences: those of the
    printed number plus two, between 3 and 6 (4 for a statement). The printed number's digits
    are counted as printed when its tolerance was fixed from them; else they are those its
    tolerance resolves (an absolute half unit, or a relative one: 10 % is one digit); else
    those of the published value.

    Examples
    --------
    >>> value, tol = printed("11")
    >>> c = Claim(id="SP-doc-digits", paper="SP", locator="T", quantity="q", published=value,
    ...           unit="m", compute=lambda: 1.0, tolerance=tol, expected_status="reproduced", note="n")
    >>> note_digits(c, tol), note_digits(c, printed("5.250")[1]), note_digits(c, printed("0.5")[1])
    (4, 6, 3)
    """
    if claim.is_statement or isinstance(claim.published, bool):
        return 4
    pub = abs(float(claim.published))
    source = claim_quote(claim, tol)[1] if tol is not None else "none"
    if source == "digits" and tol is not None:
        number = re.search(r"\d[\d.]*", tol.quote.replace(" ", ""))
        sig = len((number.group(0) if number else "").replace(".", "").lstrip("0"))
    elif tol is not None and tol.abs and pub > 0:
        sig = math.floor(math.log10(pub)) - math.floor(math.log10(2 * tol.abs)) + 1
    elif tol is not None and tol.rel:
        sig = max(1, -math.floor(math.log10(tol.rel)))
    else:
        sig = len(f"{pub:.6g}".split("e")[0].replace(".", "").lstrip("0").rstrip("0"))
    return min(6, max(3, sig + 2))


#: Plural count units that read in the singular after exactly one ("1 interval").
COUNT_UNITS = ("states", "channels", "satellites", "entries", "cases", "intervals", "lists", "units", "runs")

#: Words that open a clause rather than a noun phrase: an input described so ("how much the
#: velocity error must fall ...") is named after its reading, not after "the".
_CLAUSE_WORDS = ("how ", "what ", "whether ", "which ", "when ", "where ", "why ", "who ")


def reader_label(label: str) -> str:
    """A reading's label as a generated sentence shows it: "the prose table" named for a
    reader, as the ledger page names it.

    Examples
    --------
    >>> reader_label("within 10 %, the prose table's 'nearly'")
    "within 10 % ('nearly' in the ledger's table of prose words)"
    >>> reader_label("2 to 5 s, the prose table's reading")
    "2 to 5 s, the reading of the ledger's table of prose words"
    """
    label = re.sub(r",? the prose table's ('[^']*')", r" (\1 in the ledger's table of prose words)", label)
    label = label.replace("the prose table's reading", "the reading of the ledger's table of prose words")
    return label.replace("the prose table", "the ledger's table of prose words")


def _input_or_none(name: str) -> Any:
    try:
        return get_input(name)
    except ValueError:
        return None


def _quantity_phrase(name: str) -> str:
    """An input named in a sentence: "the chip rate", or its clause as it stands."""
    quantity = _label_and_unit(name)[0]
    return quantity if quantity.lower().startswith(_CLAUSE_WORDS) else f"the {quantity}"


def _other_labels(
    nominal: dict[str, Any], readings: Sequence[dict[str, Any]], only: Sequence[str] | None = None
) -> dict[str, list[str]]:
    """Per input, the labels other than the one used that the readings give it, in order."""
    labels: dict[str, list[str]] = {}
    for r in readings:
        for name, label in r["reading"].items():
            if (only is None or name in only) and label != nominal["reading"].get(name, PRECISION_STRICT):
                labels.setdefault(name, [])
                if label not in labels[name]:
                    labels[name].append(label)
    return labels


def _alternatives_phrase(name: str, labels: Sequence[str]) -> str:
    """An input and its other readings in words: "the chip rate read as the P code or as ...",
    or "x or y for how much ..." for an input described by a clause."""
    if name == PRECISION_READING:  # "trailing zeros not significant": taken so
        return "the printed number's " + " or ".join(
            lab.replace("trailing zeros ", "trailing zeros taken as ", 1) for lab in labels
        )
    words = [reader_label(lab) for lab in labels]
    quantity = _label_and_unit(name)[0]
    if quantity.lower().startswith(_CLAUSE_WORDS):
        return " or ".join(words) + f" for {quantity}"
    return f"the {quantity} read as " + " or as ".join(words)


def _label_prints(label: str, value: Any) -> bool:
    """Whether a reading's label prints this one of its values, as far as a reader can tell:
    :func:`label_prints_value`, or one of the label's numbers (times a power of 1000) within
    its last printed digits of the value (0.98357 ft/ns for 0.983571), or a zero the label
    prints; a code word (a string) is never shown, so it counts as printed."""
    if isinstance(value, str):
        return True
    if isinstance(value, bool) or not isinstance(value, int | float):
        return False
    if value == 0:
        return 0.0 in quote_numbers(label)
    target = float(value)
    return label_prints_value(label, value) or any(
        abs(n * 1000.0**k - target) <= 5e-6 * abs(target) for n in quote_numbers(label) for k in range(-4, 5)
    )


def _same_results(group: list[tuple[bool, tuple]]) -> bool:
    """Whether readings give the same (:func:`_reading_result`): the same value and agreement,
    and the same band and band flag among those that ran one (a reading whose band the verdict
    did not need has none)."""
    results = [res for _, res in group]
    banded = [r for r in results if r[1] is not None]
    return (
        len({(r[0], r[2]) for r in results}) == 1
        and len({r[1] for r in banded}) <= 1
        and len({r[3] for r in banded}) <= 1
    )


def _reading_result(reading: dict[str, Any]) -> tuple:
    """What a reading gives, comparable: value, band, agreement and band flag."""

    def key(v: Any) -> Any:
        try:
            return _json_value(v)
        except (TypeError, ValueError):
            return repr(v)

    band = reading.get("band")
    return (
        key(reading["value"]),
        None if band is None else tuple(key(b) for b in band),
        bool(reading["agrees"]),
        bool(reading.get("band_too_wide", False)),
    )


def _json_number(value: Any, *, round_trip: bool = False) -> Any:
    """A number as JSON: a float; a non-finite one as text (``"Infinity"``, ``"-Infinity"``,
    ``None`` for NaN) or, for a round trip, as ``{"float": "inf"}`` (:func:`from_jsonable`)."""
    v = float(value)
    if math.isfinite(v):
        return v
    if round_trip:
        return {"float": repr(v)}
    return None if math.isnan(v) else ("Infinity" if v > 0 else "-Infinity")


def _json_value(value: Any) -> Any:
    """A claim's value as its JSON record holds it: a truth value or ``None`` as it is, any
    other value as a float (:func:`_json_number`)."""
    if value is None or isinstance(value, bool):
        return value
    return _json_number(value)


def jsonable(value: Any, *, round_trip: bool = False) -> Any:
    """A value as plain JSON (numbers, strings, lists, objects): the ledger's one JSON encoder.

    For a reader (the export, the input records, the tools' records): a numpy value or array
    as the Python value or list it holds, a key as text, a non-finite number as text, anything
    else as its ``repr``. For a round trip (``round_trip=True``, the registry's stored
    evaluations, read back by :func:`from_jsonable`): keys, integers and truth values as they
    are, every other number as a float with a non-finite one kept exactly; a value that is no
    number raises.
    """
    if value is None or isinstance(value, bool | str | int):
        return value
    if isinstance(value, dict):
        return {(k if round_trip else str(k)): jsonable(v, round_trip=round_trip) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [jsonable(v, round_trip=round_trip) for v in value]
    if round_trip:
        return _json_number(value, round_trip=True)
    if not isinstance(value, float) and hasattr(value, "tolist"):
        return jsonable(value.tolist())
    try:
        return _json_number(value)
    except (TypeError, ValueError):
        return repr(value)


def from_jsonable(value: Any, sequence: type = tuple) -> Any:
    """Undo :func:`jsonable` with ``round_trip=True``; JSON arrays become ``sequence`` (tuples,
    as the evaluation fields hold them; the recorded input values are plain JSON with lists)."""
    if isinstance(value, dict):
        if set(value) == {"float"}:
            return float(value["float"])
        return {k: from_jsonable(v, sequence) for k, v in value.items()}
    if isinstance(value, list):
        return sequence(from_jsonable(v, sequence) for v in value)
    return value


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


def _coerce(value: Any, claim: Claim) -> Any:
    if claim.is_statement:
        if not isinstance(value, bool | int) and not hasattr(value, "__bool__"):
            raise TypeError(f"claim {claim.id}: a statement must compute to a truth value")
        return bool(value)
    out = float(value)
    return out


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


def _run(claim: Claim, overrides: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
    assert claim.compute is not None
    with recording() as reads:
        if overrides:
            with overriding(overrides):
                value = _coerce(claim.compute(), claim)
        else:
            value = _coerce(claim.compute(), claim)
    if not claim.is_statement and math.isnan(value):
        raise ValueError("the computation returned NaN")
    return value, reads


def _n_runs(n: int) -> str:
    """``"1 run"``, ``"3 runs"``: a count of band runs in words.

    Examples
    --------
    >>> _n_runs(1), _n_runs(3)
    ('1 run', '3 runs')
    """
    return f"{n} run{'' if n == 1 else 's'}"


def left_out_of_band(ev: Evaluation) -> str:
    """The band runs an evaluation left out as outside the model's domain, in words ("" if none).

    Parameters
    ----------
    ev : Evaluation
        An evaluation (its ``left_out`` field).

    Returns
    -------
    str
        Each case left out and how many runs met it, ``"; "``-separated.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> left_out_of_band(SimpleNamespace(left_out=()))
    ''
    >>> left_out_of_band(SimpleNamespace(left_out=({"case": "no fix", "runs": 2},)))
    'no fix (2 runs)'
    """
    return "; ".join(f"{c['case']} ({_n_runs(c['runs'])})" for c in ev.left_out)


#: Up to this many assumed inputs, the band includes every corner of their box (2**6 = 64 runs);
#: beyond it, each input one at a time plus four diagonal corners and, for a numeric value, the
#: two corners where every input sits at the end that raised (lowered) the value one at a time
#: (the extremes of a monotone response, which the diagonals can miss).
MAX_CORNER_INPUTS = 6

#: Up to this many combinations of the readings of the conventions a claim reads are run (all
#: of them); beyond it, each convention's readings one at a time, the others at the reading used.
MAX_READING_COMBINATIONS = 16


def _band_runs(
    claim: Claim,
    assumed: list[Any],
    base: dict[str, Any] | None = None,
    excluded: list[str] | None = None,
    nominal: Any = None,
) -> tuple[list[Any], list[tuple[str, tuple[tuple[Any, Any], ...]]]]:
    """Values across the assumed inputs' ranges: one at a time, and every corner of the box for up
    to :data:`MAX_CORNER_INPUTS` inputs (extremes of a monotone response lie at corners).

    ``base`` holds the overrides of a reading other than the one used (every run keeps them).
    ``nominal`` is the value at the nominal inputs of that reading: a statement whose nominal and
    one-at-a-time runs already hold both truth values has the band ``(False, True)`` whatever the
    corners give, so its corners are not run; under another reading (``base``), whose
    one-at-a-time runs are not shown, its runs stop there (module docstring, "Band runs").
    A run the model does not cover (it raises :class:`~navcore.ModelDomainError`)
    gives no value: its case in a reader's words is appended to ``excluded`` (module docstring,
    "Band runs").
    """
    base = base or {}
    values: list[Any] = []
    sensitivity = []

    def run(overrides: dict[str, Any]) -> tuple[bool, Any]:
        try:
            return True, _run(claim, overrides)[0]
        except ModelDomainError as exc:
            if excluded is not None:
                excluded.append(exc.case)
            return False, None

    # each batch of runs is announced first, so that a model can run it in one call (band_ahead)
    def both_truth_values() -> bool:
        return claim.is_statement and {bool(v) for v in (nominal, *values) if v is not None} == {False, True}

    with band_ahead([{**base, inp.name: point} for inp in assumed for point in inp.band_points]):
        for inp in assumed:
            row = []
            for point in inp.band_points:
                if base and both_truth_values():
                    break  # another reading's statement: its band is settled, its runs are not shown
                ok, v = run({**base, inp.name: point})
                if ok:
                    values.append(v)
                    row.append((point, v))
            sensitivity.append((inp.name, tuple(row)))

    if both_truth_values():
        corners: Any = []  # the band already holds both truth values
    elif 2 <= len(assumed) <= MAX_CORNER_INPUTS:
        corners = itertools.product(*[(inp.low, inp.high) for inp in assumed])
    elif len(assumed) > MAX_CORNER_INPUTS:  # the diagonal and the two half-and-half corners
        lows, highs = [inp.low for inp in assumed], [inp.high for inp in assumed]
        half = len(assumed) // 2
        corners = [lows, highs, lows[:half] + highs[half:], highs[:half] + lows[half:]]
        corners += _steepest_corners(assumed, sensitivity)
    else:
        corners = []
    corner_runs = [
        {**base, **{inp.name: p for inp, p in zip(assumed, corner, strict=True)}} for corner in corners
    ]
    with band_ahead(corner_runs):
        for overrides in corner_runs:
            ok, v = run(overrides)
            if ok:
                values.append(v)
    return values, sensitivity


def _steepest_corners(
    assumed: list[Any], sensitivity: list[tuple[str, tuple[tuple[Any, Any], ...]]]
) -> list[list[Any]]:
    """The corners at which a monotone numeric response is largest and smallest.

    Each input goes to the end of its range where the one-at-a-time run gave the larger value
    (and, for the other corner, the smaller); none when a value is not a finite real number.
    """
    up, down = [], []
    for inp, (_, row) in zip(assumed, sensitivity, strict=True):
        if len(row) < 2 or isinstance(row[0][1], bool) or isinstance(row[-1][1], bool):
            return []
        if row[0][0] != inp.low or row[-1][0] != inp.high:
            return []  # an end of the range lies outside the model's domain: no direction to take
        try:  # the first and last band points are the ends of the range
            v_low, v_high = float(row[0][1]), float(row[-1][1])
        except (TypeError, ValueError):
            return []
        if not (math.isfinite(v_low) and math.isfinite(v_high)):
            return []
        up.append(inp.high if v_high >= v_low else inp.low)
        down.append(inp.low if v_high >= v_low else inp.high)
    return [up, down]


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
        Per assumed input, its one-at-a-time runs (:attr:`Evaluation.sensitivity`).

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


def reading_combinations(conventions: Sequence[Input]) -> list[tuple[tuple[Input, str, Any], ...]]:
    """The combinations of readings a claim is run under, the readings used first.

    Parameters
    ----------
    conventions : sequence of Input
        The convention inputs the claim read.

    Returns
    -------
    list of tuple of (Input, str, Any)
        Each combination as ``(input, label, value)`` per convention; the first is every
        reading used. Every combination when there are at most
        :data:`MAX_READING_COMBINATIONS`; else each convention's other readings one at a
        time, the others at the reading used.

    Examples
    --------
    >>> from navcore.claims.inputs import Input
    >>> a = Input(name="WF.doc.a", paper="WF", value=1.0, provenance="convention",
    ...           alternative=2.0, reason="two readings")
    >>> [[label for _, label, _ in combo] for combo in reading_combinations([a])]
    [['the reading used'], ['the other reading']]
    """
    per = [
        [(inp, inp.nominal_label, inp.value), *((inp, lab, v) for lab, v in inp.other_readings)]
        for inp in conventions
    ]
    if math.prod(len(p) for p in per) <= MAX_READING_COMBINATIONS:
        return [tuple(combo) for combo in itertools.product(*per)]
    nominal = tuple(p[0] for p in per)
    return [nominal, *((*nominal[:i], r, *nominal[i + 1 :]) for i, p in enumerate(per) for r in p[1:])]


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

#: The key and the labels of the two readings of a whole number's trailing zeros in a claim's
#: ``readings`` (module docstring, "Trailing zeros").
PRECISION_READING = "printed precision"
PRECISION_STRICT = "every printed digit significant"
PRECISION_LOOSE = "trailing zeros not significant"


def precision_status(loose_status: str) -> str:
    """The verdict of a claim whose printed value disagrees when every printed digit is
    significant, from its verdict when a whole number's trailing zeros are not
    (module docstring, "Trailing zeros").

    Parameters
    ----------
    loose_status : str
        The verdict derived with the loose tolerance (:meth:`Tolerance.loose`).

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
        One of :data:`STATUSES` (module docstring, "Verdicts" and "Readings").

    Examples
    --------
    The reading used disagrees (10.5 against 10 +- 0.05), the other reading agrees:

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


def evaluate(claim: Claim, *, bands: bool = True) -> Evaluation:
    """Compute a claim, its band and inputs, derive its verdict and check it against the expected one.

    The tolerance is resolved first, where no input can be read; then ``compute`` runs at the
    nominal inputs with every read recorded; then across each assumed input's range (the
    band, unless ``bands`` is false) and under every other admissible reading of each
    convention read (across the assumed ranges too, where the verdict needs it). The
    verdict follows the ledger's rules (module docstring); a discrepant claim's value
    must also agree with its independent oracle.

    Parameters
    ----------
    claim : Claim
        The claim to evaluate (registered or not).
    bands : bool, optional
        Evaluate across the assumed inputs' ranges (one at a time and at the corners of
        their box). ``False`` computes the nominal value only, so a claim that needs the band
        to agree gets a stricter verdict; the ledger always uses ``True``.

    Returns
    -------
    Evaluation
        The value, inputs, band, readings, derived verdict and whether it is the expected
        one. A failure of the tolerance, the computation, the band or the oracle does not
        raise: it is an evaluation with status ``"error"`` (or a failing check) whose
        ``detail`` says what raised.

    Examples
    --------
    >>> from navcore.ledger import InputSet
    >>> IN = InputSet("SP", "doc_evaluate")
    >>> IN.assumed("loss_db", 2.0, low=1.0, high=3.0, unit="dB", reason="typical receivers")
    >>> value, tol = printed("12.5")
    >>> c = Claim(id="SP-doc-margin", paper="SP", locator="Table 1", quantity="margin",
    ...           published=value, unit="dB", compute=lambda: 14.0 - IN.loss_db, tolerance=tol,
    ...           expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.reproduced, ev.band, ev.status, ev.passes
    (12.0, (11.0, 13.0), 'consistent', True)
    >>> evaluate(c, bands=False).status  # 12 is outside 12.5 +- 0.05 at the nominal
    'inconsistent'

    A convention with two readings, of which only the other one agrees:

    >>> IN.convention("per_cycle_ft", 1.0, quantity="range per carrier cycle",
    ...               readings={"one foot per cycle": 1.0, "the L1 wavelength": 0.62},
    ...               reason="the text says both")
    >>> value, tol = printed("6.2")
    >>> c = Claim(id="SP-doc-peak", paper="SP", locator="Fig. 2.1", quantity="peak error",
    ...           published=value, unit="ft", compute=lambda: 10.0 * IN.per_cycle_ft,
    ...           tolerance=tol, expected_status="consistent", note="a synthetic claim")
    >>> ev = evaluate(c)
    >>> ev.status, [r["reading"]["SP.doc_evaluate.per_cycle_ft"] for r in ev.agreeing_readings]
    ('consistent', ['the L1 wavelength'])
    """
    try:
        tol = resolve_tolerance(claim)
    except Exception as exc:
        return Evaluation(
            claim,
            None,
            False,
            f"tolerance could not be resolved: {type(exc).__name__}: {exc}",
            status="error",
        )
    if claim.compute is None:
        ok = claim.expected_status == "not-reproducible"
        detail = (
            "not reproducible: " + claim.note
            if ok
            else "nothing is computed: the verdict is not-reproducible"
        )
        return Evaluation(claim, None, ok, detail, status="not-reproducible", tolerance=tol)
    try:
        value, reads = _run(claim)
    except Exception as exc:  # a claim whose computation fails is a failing claim
        return Evaluation(
            claim, None, False, f"compute raised {type(exc).__name__}: {exc}", status="error", tolerance=tol
        )

    read: list[Input] = [reads[k] for k in sorted(reads)]
    inputs = tuple(
        {
            "name": i.name,
            "provenance": i.provenance,
            ("locator" if i.provenance == "published" else "reason"): i.source(),
            "value": jsonable(i.value),
        }
        for i in read
    )
    assumed = [i for i in read if i.provenance == "assumed"]
    conventions = [i for i in read if i.provenance == "convention"]
    provenances: set[str] = {str(i.provenance) for i in read}
    admissible = bool(assumed) and all(i.admissible for i in assumed)
    run_bands = bool(assumed) and bands
    try:
        excluded: list[str] = []
        values, sensitivity = (
            _band_runs(claim, assumed, excluded=excluded, nominal=value) if run_bands else ([], [])
        )
        # beyond six inputs the corners are a sample of the box: what the inputs' separate
        # effects add up to bounds what the runs cannot rule out ("Beyond six inputs")
        sampled = run_bands and len(assumed) > MAX_CORNER_INPUTS
        envelope = additive_envelope(value, sensitivity) if sampled else None
        first = _outcome(claim, tol, value, values, envelope)
        # the other readings: their values always (they are shown); their bands only where the
        # readings used do not already agree with a band that decides
        combos = reading_combinations(conventions)[1:] if conventions else []
        others = []
        for combo in combos:
            overrides = {inp.name: v for inp, _, v in combo}
            others.append([combo, overrides, _run(claim, overrides)[0], [], None])
        # in order, until one agrees with a band that decides (the verdict is then settled)
        decided = first.agrees and not first.too_wide
        for other in others if run_bands else []:
            if decided:
                break
            other[3], other_sensitivity = _band_runs(
                claim, assumed, base=other[1], excluded=excluded, nominal=other[2]
            )
            other[4] = additive_envelope(other[2], other_sensitivity) if sampled else None
            o = _outcome(claim, tol, other[2], other[3], other[4])
            decided = o.agrees and not o.too_wide
    except Exception as exc:
        return Evaluation(
            claim,
            value,
            False,
            f"the band or a convention's other reading raised {type(exc).__name__}: {exc}",
            status="error",
            tolerance=tol,
            inputs=inputs,
        )
    band = (min([value, *values]), max([value, *values])) if assumed else None
    other_runs = [(v, vs, env) for _, _, v, vs, env in others]
    status = derive_status(claim, tol, value, values, provenances, admissible, other_runs, envelope)
    # a whole number's trailing zeros: the loose precision is weighed where the strict one does not agree
    loose = tol.loose() if status not in _AGREEMENT else None
    final_tol = tol
    if loose is not None:
        status = precision_status(
            derive_status(claim, loose, value, values, provenances, admissible, other_runs, envelope)
        )
        final_tol = loose
    readings: list[dict[str, Any]] = []
    if conventions or loose is not None:
        nominal_combo = tuple((inp, inp.nominal_label, inp.value) for inp in conventions)
        runs = [(nominal_combo, value, values, envelope, True)] + [
            (c, v, vs, env, False) for c, _, v, vs, env in others
        ]
        precisions = [(None, tol)] if loose is None else [(PRECISION_STRICT, tol), (PRECISION_LOOSE, loose)]
        for precision, t in precisions:
            for combo, v, vs, env, nominal in runs:
                o = first if nominal and t is tol else _outcome(claim, t, v, vs, env)
                reading = {inp.name: label for inp, label, _ in combo}
                if precision is not None:
                    reading[PRECISION_READING] = precision
                readings.append(
                    {
                        "reading": reading,
                        "nominal": nominal and t is tol,
                        "value": v,
                        "band": (min([v, *vs]), max([v, *vs])) if vs else None,
                        "agrees": o.agrees,
                        "band_too_wide": o.too_wide,
                        "undecided": o.undecided,
                    }
                )

    # not-reproducible: a band too wide to decide, or (beyond six inputs) a printed value the runs
    # do not reach and the inputs' separate effects add up to
    final = [
        (env, _outcome(claim, final_tol, v, vs, env))
        for v, vs, env in [(value, values, envelope), *other_runs]
    ]
    undecided = status == "not-reproducible" and not any(o.agrees for _, o in final)
    # the envelope that leaves it undecided: the reading used's, else the first other reading's
    undecided_envelope = next((env for env, o in final if o.undecided), None) if undecided else None
    left_out = tuple({"case": m, "runs": excluded.count(m)} for m in dict.fromkeys(excluded))
    common: dict[str, Any] = dict(
        status=status,
        tolerance=tol,
        inputs=inputs,
        band=band,
        sensitivity=tuple(sensitivity),
        readings=tuple(readings),
        band_too_wide=status == "not-reproducible" and not undecided,
        envelope=undecided_envelope,
        left_out=left_out,
    )
    if status != claim.expected_status:
        return Evaluation(
            claim,
            value,
            False,
            f"derived verdict {status!r} differs from the expected {claim.expected_status!r}",
            **common,
        )
    if status != "discrepant":
        return Evaluation(claim, value, True, f"derived verdict {status}", **common)
    # discrepant: an erratum, and the book's value must agree with its independent oracle
    if not claim.erratum or claim.oracle is None or claim.oracle_tolerance is None:
        return Evaluation(
            claim, value, False, "a discrepancy needs its erratum and an independent oracle", **common
        )
    try:
        with recording():
            oracle_value = _coerce(claim.oracle(), claim)
    except Exception as exc:
        return Evaluation(claim, value, False, f"oracle raised {type(exc).__name__}: {exc}", **common)
    if claim.is_statement:
        matches = oracle_value == value
    else:
        matches = abs(value - oracle_value) <= claim.oracle_tolerance.allowed(oracle_value)
    detail = (
        "discrepancy confirmed by an independent oracle"
        if matches
        else f"disagrees with its independent oracle ({oracle_value!r})"
    )
    return Evaluation(claim, value, matches, detail, oracle_value, **common)
