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
callable that ``pandas.io.formats.style.Styler.format`` takes.

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

__all__ = ["KINDS", "format_number", "number_formatter", "tidy_numbers"]

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
