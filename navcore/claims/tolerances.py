"""How far a computed value may stand from a printed one: tolerances and the printed-text policies.

A claim's :class:`Tolerance` is fixed by how the paper printed the number, through a named
policy (:data:`POLICIES`): the printed digits (:func:`printed`), a word of the prose table
(:data:`PROSE_WORDS`, :func:`prose`), the reading resolution of a figure
(:func:`figure_reading`), a Monte Carlo run count (:func:`monte_carlo`) or :data:`EXACT`.
The verdict that weighs a tolerance is :mod:`navcore.claims.verdict`'s.

Tolerance policies
------------------
``printed-digits`` (half a unit in the last printed digit, :func:`printed`), ``prose`` (the
band of a word such as "about", :func:`prose`), ``figure-reading`` (the reading resolution
of a figure's axis, :func:`figure_reading`), ``monte-carlo`` (the sampling error of a run
count, :func:`monte_carlo`) and ``exact`` (:data:`EXACT`).


Trailing zeros
--------------
The trailing zeros of a whole number printed without a decimal point or an exponent ("2750",
"20", "3300") do not say whether they are significant, so the precision is a reading of the
text, and :func:`printed` gives its tolerance both: strict, half a unit in the last digit
(``abs``), and loose, half a unit in the last non-zero digit (``loose_abs``: ±5 for "2750",
±50 for "3300"). The verdict weighs them like the readings of a convention:

* agreement under the strict one: the verdict as derived with it (the loose one is not run);
* agreement only under the loose one: ``consistent`` (:func:`~navcore.claims.verdict.precision_status`), and
  the claim's ``readings`` name the reading that agrees, "trailing zeros not significant"
  (:data:`PRECISION_READING`);
* agreement under neither: the verdict as derived with the loose tolerance (the claim is not
  accused of a digit its printed number may not carry), both readings shown.

A number printed with a decimal point ("20.0", "20.") or an exponent ("150e1") states its
significant digits.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any, Literal

__all__ = [
    "EXACT",
    "POLICIES",
    "PRECISION_LOOSE",
    "PRECISION_READING",
    "PRECISION_STRICT",
    "PROSE_WORDS",
    "Tolerance",
    "figure_reading",
    "monte_carlo",
    "printed",
    "prose",
]


POLICIES = ("printed-digits", "prose", "figure-reading", "monte-carlo", "exact")


Policy = Literal["printed-digits", "prose", "figure-reading", "monte-carlo", "exact"]


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


#: The key and the labels of the two readings of a whole number's trailing zeros in a claim's
#: ``readings`` (module docstring, "Trailing zeros").
PRECISION_READING = "printed precision"


PRECISION_STRICT = "every printed digit significant"


PRECISION_LOOSE = "trailing zeros not significant"
