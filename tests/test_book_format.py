"""The book's number formatter, its table tidying and the number-format gate.

Oracles: the expected strings are written out by hand from the rule each case states
(significant digits, ×10ⁿ, no signed zero); the gate is run on small HTML pages made here.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from navcore import book
from navcore.formatting import format_number, number_formatter, tidy_numbers
from tests._tools import load_tool

ROOT = Path(__file__).resolve().parents[1]


_tool = load_tool


@pytest.mark.parametrize(
    ("value", "kwargs", "expected"),
    [
        (1.6344416666666666, {}, "1.63"),
        (0.012345, {}, "0.0123"),
        (123.456, {}, "123"),
        (12345.6, {}, "12346"),
        (12345678.0, {}, "1.23×10⁷"),
        (1.0e-4, {}, "1.00×10⁻⁴"),
        (-2.5e-7, {}, "-2.50×10⁻⁷"),
        (-0.0, {}, "0"),
        (-0.0004, {"decimals": 3}, "0.000"),
        (-0.0004, {"decimals": 4}, "-0.0004"),
        (60.0, {"kind": "exact"}, "60"),
        (1e9, {"kind": "exact"}, "1×10⁹"),
        (2.5e-5, {"kind": "exact"}, "2.5×10⁻⁵"),
        (1.67e-13, {"kind": "residual"}, "2×10⁻¹³"),
        (12.3456, {"kind": "percent"}, "12.3"),
        (3.0, {"kind": "count"}, "3"),
        (np.float64(0.5), {}, "0.500"),
        (math.nan, {}, "–"),
        (None, {}, "–"),
        ({180.0: 18.019433953373785, 360.0: 36.01596868057278}, {}, "180: 18.0, 360: 36.0"),
        ([1.0, -0.0], {"digits": 2}, "1.0, 0"),
        (-1.5, {"minus": "−"}, "−1.50"),
    ],
)
def test_format_number(value, kwargs, expected):
    assert format_number(value, **kwargs) == expected


@pytest.mark.parametrize("value", [1e-300, -3.2e-14, 0.001, 999_999.0, 1e6, -7.77e22])
def test_format_number_never_prints_a_program_exponent_or_negative_zero(value):
    text = format_number(value)
    assert "e" not in text and not text.startswith("-0")
    # the digits shown are the value's own: read back, it agrees to the shown precision
    mantissa, _, power = text.partition("×10")
    sup = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
    read = float(mantissa) * (10.0 ** int(power.translate(sup)) if power else 1.0)
    assert read == pytest.approx(value, rel=5e-3)


def test_bad_settings_are_rejected():
    with pytest.raises(ValueError, match="kind must be one of"):
        format_number(1.0, "speed")
    with pytest.raises(ValueError, match="digits must be an integer of at least 1"):
        format_number(1.0, digits=0)
    with pytest.raises(ValueError, match="decimals must be a non-negative integer"):
        number_formatter(decimals=-1)


def test_tidy_numbers_keeps_the_digits_and_drops_signed_zeros():
    assert tidy_numbers("9.40e-02 and 1e5; -0.000 | x1e-3") == "9.40×10⁻² and 1×10⁵; 0.000 | x1e-3"
    assert tidy_numbers("0.000e+00, 2.5e+00, -1.2E+03") == "0.000, 2.5, -1.2×10³"
    assert tidy_numbers("Eq. (2.4.2), 10-0 and -0.5") == "Eq. (2.4.2), 10-0 and -0.5"


def test_book_table_tidies_every_cell_and_prints_a_float_index_exactly():
    frame = pd.DataFrame({"p_f": [1e-4, -1e-9]}, index=pd.Index([60.0, 150.0], name="t (s)"))
    table = book.table(frame.style.format("{:.2e}"))
    _head, body = table.cells()
    assert [row[0] for row in body[1:]] == ["60", "150"]
    assert body[1][1] == "1.00×10⁻⁴" and body[2][1] == "-1.00×10⁻⁹"
    html = table._repr_html_()
    assert "e-04" not in html and "60.000000" not in html and "1.00×10⁻⁴" in html


def test_quantity_table():
    table = book.quantity_table({"attitude error (deg)": 2.2914, "left product (deg)": 1.6e-14})
    assert table.cells()[1] == [["attitude error (deg)", "2.29"], ["left product (deg)", "1.60×10⁻¹⁴"]]


def test_number_gate_finds_each_pattern_and_leaves_code_and_math_alone():
    gate = _tool("check_numbers")
    page = """<html><body><article class="bd-article">
    <p>The gain is 1.00e-04 and the error 1.6344416666666666 m; at rest -0.000.</p>
    <div class="cell_output"><pre>{180.0: 18.02}</pre>
    <table><tr><th>t</th><td>60.000000</td></tr></table></div>
    <div class="cell_input"><pre>x = 1e-9; y = {1.0: 2}</pre></div>
    <span class="math">10^{-4} -0</span>
    <p>doi:10.1115/1.3662552, 0.0000 and 1.00×10⁻⁴.</p>
    </article></body></html>"""
    found = {(name, match) for name, match, _ in gate.hits(page)}
    assert found == {
        ("exponent", "1.00e-04"),
        ("long decimal", "1.6344416666666666"),
        ("negative zero", "-0.000"),
        ("mapping", "{180.0: 1"),
        ("padded", "60.000000"),
    }


def test_number_gate_can_leave_the_ledger_tables_out():
    gate = _tool("check_numbers")
    page = '<article class="bd-article"><table class="ledger-claims"><td>5.8e-14</td></table></article>'
    assert gate.hits(page) and not gate.hits(page, skip_ledger=True)
