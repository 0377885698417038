"""What the paper printed: a claim's quote, the numbers in it, and the tolerance policy it implies.

What the paper printed
----------------------
A claim's ``printed`` is the paper's words or formula as quoted; by default the text given
to its tolerance (``printed("17.67")`` quotes ``17.67``, ``prose("about")`` quotes the word).
The tolerance policy follows the quote by rule (:func:`quote_policies`), and a number the
paper does not print is not ``published``: a threshold or an encoding of "this equation
holds" is the book's, so such a claim is a ``statement`` whose threshold is a declared
convention (:func:`quote_has_number`).
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Iterable, Mapping
from typing import Any

from navcore.claims.declarations import Claim, resolve_tolerance
from navcore.claims.tolerances import PROSE_WORDS, Tolerance

__all__ = [
    "claim_quote",
    "label_prints_value",
    "quote_has_number",
    "quote_numbers",
    "quote_policies",
    "with_quotes",
]


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
        :func:`~navcore.claims.tolerances.printed`), ``"word"`` (the word given to
        :func:`~navcore.claims.tolerances.prose`, without its number) or ``"none"``.

    Examples
    --------
    >>> from navcore.claims import printed
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


def with_quotes(claims: Iterable[Claim], quotes: Mapping[str, str]) -> list[Claim]:
    """The claims, each with its ``printed`` quote taken from ``quotes`` unless it gives one.

    A paper keeps the words behind its claims in one mapping (``navcore.papers.<paper>_quotes``
    ``QUOTES``: claim id -> the paper's words or formula as transcribed); a paper module applies it
    to its ``CLAIMS`` once, after declaring them. A claim that gives ``printed=`` itself (a
    non-blank quote) keeps it; a claim whose id the mapping lacks is returned unchanged.

    Parameters
    ----------
    claims : iterable of Claim
        The claims of one paper module, in order.
    quotes : mapping of str to str
        Claim id -> the quote to fill in.

    Returns
    -------
    list of Claim
        The claims in the same order; those filled are copies (``dataclasses.replace``).

    Raises
    ------
    TypeError
        If ``quotes`` is not a mapping or an item of ``claims`` is not a
        :class:`~navcore.claims.declarations.Claim`.

    Examples
    --------
    >>> from navcore.claims import Claim
    >>> c = Claim.statement(id="WF-doc-eq1", locator="Eq. (1)", quantity="q", compute=lambda: True, note="n")
    >>> with_quotes([c], {"WF-doc-eq1": "a = b"})[0].printed
    'a = b'
    """
    if not isinstance(quotes, Mapping):
        raise TypeError(f"quotes must be a mapping of claim id to quote, got {type(quotes).__name__}")
    out = []
    for i, c in enumerate(claims):
        if not isinstance(c, Claim):
            raise TypeError(f"claims[{i}] must be a Claim, got {type(c).__name__}")
        out.append(
            c if c.printed.strip() or c.id not in quotes else dataclasses.replace(c, printed=quotes[c.id])
        )
    return out


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
    :data:`~navcore.claims.tolerances.PROSE_WORDS`) is ``prose``; a value the paper says it read from its
    figures ("read from", "from the figures") is ``figure-reading``; otherwise the number is taken as printed:
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
        The admissible policies of :data:`~navcore.claims.tolerances.POLICIES`.

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
