"""One way to print a number for a reader: the book's tables, outputs and text.

A program prints ``1.6344416666666666``, ``-0.000``, ``1.00e-04`` (which a browser may break
after the minus sign) or ``{180.0: 18.019433953373785}``. The book prints what the value is:

* a count, or an index that is exact (``kind="exact"``), as it is (``60``, not ``60.000000``);
* a computed quantity with a few significant digits (three by default), in fixed notation
  between 0.001 and 10^6 and otherwise as ``1.23×10⁻⁴``, a form with no place for a line to
  break and no exponent written the way a program writes it;
* zero, and anything that rounds to zero, without a sign (never ``-0`` or ``-0.000``);
* a round-off residual (a difference that is zero in exact arithmetic) with one digit;
* a percentage with a sensible number of decimals;
* a column of like values, where the reader compares digits, with a fixed number of
  decimals (``decimals=2``), still without ``-0.00``;
* a mapping or sequence of numbers element by element (``180: 18.0``).

:func:`format_number` is the function; :func:`number_formatter` makes the one-argument
callable that ``pandas.io.formats.style.Styler.format`` takes. A unit is printed by
:func:`unit_text` (``m³/s²``, not ``m^3/s^2``); :func:`plain_math` finds the plain-text math a
reader should not see outside ``$...$`` (:func:`math_spans` cuts a text at its math).

Examples
--------
>>> format_number(1.6344416666666666)
'1.63'
>>> format_number(-0.0001, decimals=3)
'0.000'
>>> format_number(1.0e-4)
'1.00×10⁻⁴'
>>> format_number(60.0, "exact"), format_number(60.0)
('60', '60.0')
>>> format_number({180.0: 18.019433953373785})
'180: 18.0'
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from typing import Any

__all__ = [
    "KINDS",
    "format_number",
    "math_spans",
    "number_formatter",
    "plain_math",
    "tidy_numbers",
    "unit_text",
]

#: What a value can be; each kind sets its significant digits and notation.
KINDS = ("quantity", "count", "residual", "percent", "exact")

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
_MINUS = "−"  # U+2212, the typographic minus


def _scientific(value: float, digits: int) -> str:
    mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
    return f"{mantissa}×10{str(int(exponent)).translate(_SUPERSCRIPT)}"


def _unsigned_zero(text: str) -> str:
    """``-0``, ``-0.00`` and ``-0.00×10⁻³`` read as zero: drop the sign."""
    body = text.lstrip("-" + _MINUS)
    digits = body.split("×")[0]
    if body != text and not any(c in "123456789" for c in digits):
        return body
    return text


def format_number(
    value: Any,
    kind: str = "quantity",
    *,
    digits: int = 3,
    decimals: int | None = None,
    minus: str = "-",
) -> str:
    """A number as a reader should see it.

    Parameters
    ----------
    value : int, float, numpy scalar, mapping or sequence
        The value; a mapping prints as ``key: value`` pairs and a sequence element by
        element (comma-separated); ``None`` and NaN print as an en dash; text is returned as
        it is.
    kind : {"quantity", "count", "residual", "percent", "exact"}, optional
        What the value is: a computed ``"quantity"`` (``digits`` significant digits), a
        ``"count"`` (an integer), a round-off ``"residual"`` (one significant digit, in
        scientific form unless zero), a ``"percent"`` (``digits`` significant digits, at most
        two decimals) or an ``"exact"`` value such as an input or an index (every digit it
        has: an integer below 10⁶ as an integer, ``1×10⁹`` rather than ``1e+09``).
    digits : int, optional
        Significant digits of a quantity or percentage (at least 1).
    decimals : int or None, optional
        Fixed notation with this many decimals, whatever the size (a column of like values
        that a reader compares digit by digit); overrides ``digits`` for a quantity.
    minus : str, optional
        The minus sign: ``"-"`` (default, plain text) or ``"−"`` (U+2212, typeset text).

    Returns
    -------
    str
        The number as text. Zero, and any value that rounds to zero at the shown digits, has
        no sign; an integer-valued float prints as an integer when its digits allow.

    Raises
    ------
    ValueError
        If ``kind`` is not one of :data:`KINDS`, ``digits`` is less than 1 or ``decimals``
        is negative.

    Examples
    --------
    >>> [format_number(v) for v in (0.012345, 123.456, 12345678.0, -2.5e-7)]
    ['0.0123', '123', '1.23×10⁷', '-2.50×10⁻⁷']
    >>> format_number(1.67e-13, "residual"), format_number(0.0, "residual")
    ('2×10⁻¹³', '0')
    >>> format_number(12.3456, "percent"), format_number(3.0, "count")
    ('12.3', '3')
    >>> format_number(1e9, "exact"), format_number(2.5e-5, "exact"), format_number(0.25, "exact")
    ('1×10⁹', '2.5×10⁻⁵', '0.25')
    >>> format_number(-0.0004, digits=2), format_number(-0.0004, decimals=2)
    ('-4.0×10⁻⁴', '0.00')
    """
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    if int(digits) != digits or digits < 1:
        raise ValueError(f"digits must be an integer of at least 1, got {digits!r}")
    if decimals is not None and (int(decimals) != decimals or decimals < 0):
        raise ValueError(f"decimals must be a non-negative integer or None, got {decimals!r}")
    if isinstance(value, str):
        return value
    if value is None:
        return "–"

    def same(v: Any) -> str:
        return format_number(v, kind, digits=digits, decimals=decimals, minus=minus)

    if isinstance(value, Mapping):
        return ", ".join(f"{format_number(k, 'exact')}: {same(v)}" for k, v in value.items())
    if isinstance(value, list | tuple) or (hasattr(value, "ndim") and getattr(value, "ndim", 0) > 0):
        return ", ".join(same(v) for v in value)
    if isinstance(value, bool):
        return "yes" if value else "no"
    x = float(value)
    if math.isnan(x):
        return "–"
    if math.isinf(x):
        return ("-" if x < 0 else "") + "∞"
    text = _format_float(x, kind, int(digits), decimals)
    text = _unsigned_zero(text)
    return text.replace("-", minus) if minus != "-" else text


def _format_float(x: float, kind: str, digits: int, decimals: int | None) -> str:
    if kind == "count":
        return str(round(x))
    if kind == "exact":
        if x == int(x) and abs(x) < 1e6:
            return str(int(x))
        text = repr(x)
        if "e" in text or abs(x) >= 1e6:
            significant = text.split("e")[0].lstrip("-").replace(".", "").strip("0")
            return _scientific(x, max(len(significant), 1))
        return text
    if decimals is not None and kind in ("quantity", "percent"):
        return f"{x:.{int(decimals)}f}"
    if x == 0:
        return "0"
    if kind == "residual":
        return _scientific(x, 1)
    magnitude = math.floor(math.log10(abs(x)))
    if kind == "percent":
        decimals = min(max(digits - 1 - magnitude, 0), 2)
        return f"{x:.{decimals}f}"
    if -3 <= magnitude < 6:
        if x == int(x) and abs(x) >= 10 ** (digits - 1):
            return str(int(x))
        return f"{x:.{max(digits - 1 - magnitude, 0)}f}"
    return _scientific(x, digits)


def number_formatter(
    kind: str = "quantity", *, digits: int = 3, decimals: int | None = None
) -> Callable[[Any], str]:
    """A one-argument formatter for ``Styler.format`` (or ``map``) with these settings.

    Parameters
    ----------
    kind : str, optional
        As in :func:`format_number`.
    digits : int, optional
        As in :func:`format_number`.
    decimals : int or None, optional
        As in :func:`format_number`.

    Returns
    -------
    callable
        ``value -> str``.

    Raises
    ------
    ValueError
        If ``kind`` or ``digits`` is invalid (checked now, not at the first value).

    Examples
    --------
    >>> import pandas as pd
    >>> frame = pd.DataFrame({"sigma (m)": [1.6344416666666666, -0.0]})
    >>> frame.style.format(number_formatter()).to_string(delimiter=" ").splitlines()[1:]
    ['0 1.63', '1 0']
    """
    format_number(0.0, kind, digits=digits, decimals=decimals)  # validates the settings now

    def fmt(value: Any) -> str:
        return format_number(value, kind, digits=digits, decimals=decimals)

    return fmt


_EXPONENT = re.compile(r"(?<![\w.])([-−]?)(\d+(?:\.\d+)?)[eE]([-+−]?)(\d+)\b")
_NEGATIVE_ZERO = re.compile(r"(?<![\w.\d])[-−](0(?:\.0+)?)(?!\d|\.\d|×)")


def _exponent(m: re.Match[str]) -> str:
    sign, mantissa, exp_sign, exponent = m.groups()
    if not any(c in "123456789" for c in mantissa):
        return mantissa.split(".")[0] if "." not in mantissa else mantissa
    power = int(exponent) * (-1 if exp_sign in ("-", "−") else 1)
    if power == 0:
        return sign + mantissa
    return f"{sign}{mantissa}×10{str(power).translate(_SUPERSCRIPT)}"


def tidy_numbers(text: str) -> str:
    """Rewrite the numbers of a text that a program formatted, keeping their digits.

    A number in exponent notation becomes ``mantissa×10ⁿ`` (the digits the writer chose
    stay; a zero mantissa becomes ``0``), and a negative zero loses its sign. Everything
    else is left alone. The book's tables pass their cells through it, so a column formatted
    with ``"{:.2e}"`` reads ``9.40×10⁻²``.

    Parameters
    ----------
    text : str
        Any text (a table cell, an output line).

    Returns
    -------
    str
        The text with those numbers rewritten.

    Examples
    --------
    >>> tidy_numbers("9.40e-02, 1e5 and -0.000; x1e-3 stays")
    '9.40×10⁻², 1×10⁵ and 0.000; x1e-3 stays'
    >>> tidy_numbers("0.000e+00 and 2.5e+00")
    '0.000 and 2.5'
    """
    return _NEGATIVE_ZERO.sub(r"\1", _EXPONENT.sub(_exponent, text))


def estimate_text(value: float, se: float) -> str:
    """A Monte Carlo estimate with its standard error, each with the digits the error supports.

    The error is shown with two significant digits, the estimate rounded at the place of the
    error's first significant digit (at least one digit), both by :func:`format_number`.

    Parameters
    ----------
    value : float
        The estimate.
    se : float
        Its standard error (positive and finite).

    Returns
    -------
    str
        ``"estimate ± error"``, e.g. ``"3×10⁻⁵ ± 1.2×10⁻⁵"``.

    Raises
    ------
    ValueError
        If ``se`` is not positive and finite, or ``value`` is not finite.

    Examples
    --------
    >>> estimate_text(3.14e-5, 1.17e-5)
    '3×10⁻⁵ ± 1.2×10⁻⁵'
    >>> estimate_text(12.345, 0.26)
    '12.3 ± 0.26'
    """
    if not (math.isfinite(se) and se > 0):
        raise ValueError(f"se must be a positive finite standard error, got {se!r}")
    if not math.isfinite(value):
        raise ValueError(f"value must be finite, got {value!r}")
    place = math.floor(math.log10(se))
    digits = math.floor(math.log10(abs(value))) - place + 1 if value else 1
    return f"{format_number(value, digits=max(digits, 1))} ± {format_number(se, digits=2)}"


# ---------------------------------------------------------------------------------------
# units and plain-text math: what reads as program text outside ``$...$``

_GREEK = (
    "alpha|beta|gamma|delta|epsilon|zeta|eta|theta|kappa|lambda|mu|nu|xi|pi|rho|sigma|tau|phi|chi|"
    "psi|omega|Gamma|Delta|Theta|Lambda|Sigma|Phi|Psi|Omega|dtheta|dphi"
)


#: Plain-text math, by kind: what each pattern finds in text outside ``$...$``. One list for the
#: registry's texts (the tests), the docstrings' prose and the text of the built book's pages
#: (the release gate ``tools/check_book.py``), and for :func:`unit_text`, which sets a unit
#: that holds one of them as math.
PLAIN_MATH_PATTERNS = {
    "e-notation": re.compile(r"(?<![\w.])\d+(?:\.\d+)?[eE][+-]?\d+\b"),
    "flat subscript": re.compile(r"\b[A-Za-z]+_[A-Za-z0-9]+\b"),
    "Greek name": re.compile(rf"\b(?:{_GREEK})(?:\d+|_\w+)?\b"),
    "power": re.compile(r"\w\)?\^[-+(\w]|\*\*"),
    "sqrt(": re.compile(r"\bsqrt\("),
    "cross-product bracket": re.compile(r"\[\s*\w+\s+x\s*\]"),
    "(x) product": re.compile(r"\(x\)"),
    "symbol with a flat 0": re.compile(r"\b[A-Za-z]0\b"),
    "derivative quotient": re.compile(r"\bd[A-Za-z]/d[A-Za-z]\b"),
}


#: A starred symbol (``h1*``, the hypothesis :math:`h_1^*`).
PLAIN_STARRED = re.compile(r"(?<![\w\\*])[A-Za-z]\d?\*(?![\w*])")


#: LaTeX source outside math (``tau_{i+1}``, ``e^{+jnv}``, ``\bar``).
PLAIN_LATEX_SOURCE = re.compile(r"\\[A-Za-z]{2,}(?![A-Za-z])|[_^]\{")


def plain_math(text: str) -> list[tuple[str, str]]:
    r"""The plain-text math outside the ``$...$`` spans of ``text``: each hit of
    ``PLAIN_MATH_PATTERNS``, a starred symbol and LaTeX source, as ``(kind, text found)``.

    Parameters
    ----------
    text : str
        A text a reader sees (a note, a quantity, a unit, a page's words), with its math in
        ``$...$``.

    Returns
    -------
    list of (str, str)
        Each hit as its kind (a key of ``PLAIN_MATH_PATTERNS``, ``"starred symbol"`` or
        ``"LaTeX source"``) and the text it found, in the order of the patterns; empty when
        every formula is set as math.

    Examples
    --------
    >>> plain_math("beyond 10 mm/s^2 at rho = 0.25")
    [('Greek name', 'rho'), ('power', 's^2')]
    >>> plain_math(r"beyond 10 $\mathrm{mm/s}^2$ at $\rho = 0.25$")
    []
    """
    found = []
    for is_math, piece in math_spans(text):
        if not is_math:
            found += [
                (kind, m.group(0)) for kind, pat in PLAIN_MATH_PATTERNS.items() for m in pat.finditer(piece)
            ]
            found += [("starred symbol", m.group(0)) for m in PLAIN_STARRED.finditer(piece)]
            found += [("LaTeX source", m.group(0)) for m in PLAIN_LATEX_SOURCE.finditer(piece)]
    return found


#: One atom of a unit: ``sqrt(...)``, a name with an optional subscript (``tau_c``, ``N_T``) and
#: an optional power (``m^3``, ``deg^2``, ``e^*``), or a number with an optional power (``10^8``).
_UNIT_ATOM = re.compile(
    r"sqrt\((?P<root>[^()]+)\)"
    r"|(?P<name>[A-Za-z]+)(?:_(?P<sub>[A-Za-z0-9]+))?(?:\^(?P<pow>[-+]?\w+|\*))?"
    r"|(?P<num>\d+(?:\.\d+)?)(?:\^(?P<npow>[-+]?\w+))?"
)


_GREEK_NAMES = frozenset(_GREEK.split("|")) - {"dtheta", "dphi"}


def _unit_atom_tex(m: re.Match[str], symbol: bool) -> str:
    if m.group("root"):
        return r"\sqrt{" + _unit_tex(m.group("root"), symbol=False) + "}"
    if m.group("num"):
        return m.group("num") + (f"^{{{m.group('npow')}}}" if m.group("npow") else "")
    name, sub, power = m.group("name"), m.group("sub"), m.group("pow")
    if name in _GREEK_NAMES:
        out = "\\" + name
    elif symbol or sub:  # a symbol of a formula (N, N_T): italic
        out = name
    else:  # a unit's symbol (m, s, deg): upright
        out = rf"\mathrm{{{name}}}"
    if sub:
        out += f"_{{{sub}}}"
    if power:
        out += f"^{{{power}}}"
    return out


def _unit_tex(token: str, *, symbol: bool) -> str:
    """A token of a unit (no spaces) as LaTeX math, atom by atom; other characters as they are."""
    out, pos = [], 0
    for m in _UNIT_ATOM.finditer(token):
        out.append(token[pos : m.start()] + _unit_atom_tex(m, symbol))
        pos = m.end()
    return "".join(out) + token[pos:]


_SUPERSCRIPTS = str.maketrans("0123456789-+", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺")


#: An integer power of a unit's symbol or of a number (``m^3``, ``10^8``), and a root of one.
_UNIT_POWER = re.compile(r"(?<=[A-Za-z0-9)])\^([-+]?\d+)(?![\w^])")


_UNIT_ROOT = re.compile(r"\bsqrt\((\w+)\)")


def unit_text(unit: str) -> str:
    r"""A unit as a reader sees it: a power as a superscript, a root as a radical and a unit
    that is a formula as ``$...$`` math; a plain unit (``m/s``, ``dB-Hz``) as it is.

    The ledger keeps units as plain strings (its JSON and CSV exports carry them so); every
    table and text a reader sees shows them through this function, with
    :func:`~navcore.ledger.text.html_text` or :func:`~navcore.ledger.text.tex_text`. A unit is
    rewritten only when it holds plain-text math (``PLAIN_MATH_PATTERNS``). A unit of symbols
    takes its powers and roots as the registry's own units write them (``m/s²``,
    ``deg/h/√Hz``): superscripts and radicals in the text, which stays upright and breaks
    after its slashes as any unit. A unit that is a formula, with a Greek letter, a subscript
    or a symbol standing alone (the :math:`N` of :math:`N\tau_{c}/\alpha`), is set as math;
    its words (``parts in``) stay text.

    Parameters
    ----------
    unit : str
        A claim's or an input's unit, as the registry holds it.

    Returns
    -------
    str
        The unit as text, with ``$...$`` around what is math.

    Examples
    --------
    >>> unit_text("m/s"), unit_text("m^3/s^2"), unit_text("deg^2"), unit_text("rad/s/sqrt(s)")
    ('m/s', 'm³/s²', 'deg²', 'rad/s/√s')
    >>> unit_text("parts in 10^8")
    'parts in 10⁸'
    >>> print(unit_text("N tau_c / alpha"), unit_text("N_T"))
    $N \tau_{c} / \alpha$ $N_{T}$
    """
    if not plain_math(unit):
        return unit
    text = _UNIT_ROOT.sub(r"√\1", _UNIT_POWER.sub(lambda m: m.group(1).translate(_SUPERSCRIPTS), unit))
    if not plain_math(text):
        return text
    tokens = unit.split()
    # a single letter standing alone is a symbol of a formula (the N of N tau_c / alpha)
    formula = any(len(t) == 1 and t.isalpha() for t in tokens)
    runs: list[tuple[bool, list[str]]] = []
    for t in tokens:
        is_word = t.isalpha() and len(t) > 1 and t not in _GREEK_NAMES
        piece = t if is_word else _unit_tex(t, symbol=formula)
        if runs and runs[-1][0] == (not is_word):
            runs[-1][1].append(piece)
        else:
            runs.append((not is_word, [piece]))
    return " ".join(f"${' '.join(ts)}$" if is_math else " ".join(ts) for is_math, ts in runs)


_MATH = re.compile(r"(?<![\\$])\$(?=[^\s$])([^$]*?[^\s\\$])\$(?!\$)")


def math_spans(text: str) -> list[tuple[bool, str]]:
    """``text`` cut into ``(is_math, piece)``: ``$...$`` is inline math.

    A dollar sign followed by a space (``50,000 $ INS``) or escaped (``\\$``) is not math,
    so prices and lone dollar signs stay text.

    Parameters
    ----------
    text : str
        A note, quantity or erratum text.

    Returns
    -------
    list of tuple of (bool, str)
        The pieces in order, ``True`` for the inside of a ``$...$`` span (without the dollar
        signs), ``False`` for text.

    Examples
    --------
    >>> math_spans("gain $K_1$ costs 50 $ more")
    [(False, 'gain '), (True, 'K_1'), (False, ' costs 50 $ more')]
    """
    out: list[tuple[bool, str]] = []
    pos = 0
    for m in _MATH.finditer(text):
        if m.start() > pos:
            out.append((False, text[pos : m.start()]))
        out.append((True, m.group(1)))
        pos = m.end()
    if pos < len(text):
        out.append((False, text[pos:]))
    return out
