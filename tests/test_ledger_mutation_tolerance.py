"""The ledger's tolerance policies and quote rules, value by value (issue 31, mutation survivors).

Oracle in every test: the policy as LEDGER.md and :mod:`navcore.claims.tolerances` state it, applied by
hand to a printed text: half a unit in the last printed digit (``"17.67"`` -> 0.005, ``"1.2e-3"``
-> 5e-5, ``"2750"`` -> 0.5, or 5 if its trailing zero is not significant), the prose table's
bands, a figure's reading resolution, and the numbers a quote prints. Synthetic, no registry.
"""

from __future__ import annotations

import math

import pytest

from navcore.claims.quotes import label_prints_value, quote_has_number, quote_numbers, quote_policies
from navcore.claims.tolerances import (
    PROSE_WORDS,
    Tolerance,
    _number_math,
    _trailing_zeros,
    figure_reading,
    monte_carlo,
    printed,
    prose,
)

# --- Tolerance --------------------------------------------------------------------------------


def test_allowed_is_the_larger_of_abs_and_rel_times_the_magnitude():
    t = Tolerance(reason="r", abs=0.5, rel=0.1, policy="prose")
    assert t.allowed(2.0) == 0.5  # 0.1 * 2 = 0.2 < 0.5
    assert t.allowed(-20.0) == 2.0  # 0.1 * |-20| = 2 > 0.5
    assert t.allowed(100.0) == 10.0
    assert Tolerance(reason="r", rel=0.1, policy="prose").allowed(-30.0) == pytest.approx(3.0, rel=1e-15)
    assert Tolerance(reason="r", abs=0.25, policy="exact").allowed(1e9) == 0.25
    assert Tolerance(reason="r", policy="exact").allowed(5.0) == 0.0


def test_tolerance_checks_its_fields():
    with pytest.raises(ValueError, match="reason"):
        Tolerance(reason="  ", abs=1.0, policy="exact")
    with pytest.raises(ValueError, match="policy"):
        Tolerance(reason="r", abs=1.0, policy="guess")
    for name in ("abs", "rel", "loose_abs"):
        with pytest.raises(ValueError, match=f"Tolerance.{name}"):
            Tolerance(reason="r", policy="exact", **{name: -1e-9})
        with pytest.raises(ValueError, match=f"Tolerance.{name}"):
            Tolerance(reason="r", policy="exact", **{name: math.inf})
    # zero is allowed; loose_abs equal to abs is allowed, below it is not
    Tolerance(reason="r", abs=0.0, rel=0.0, policy="exact")
    Tolerance(reason="r", abs=0.5, loose_abs=0.5, policy="printed-digits")
    with pytest.raises(ValueError, match="loose_abs must be >= abs"):
        Tolerance(reason="r", abs=0.5, loose_abs=0.4999, policy="printed-digits")
    # with no abs, any non-negative loose_abs is allowed
    Tolerance(reason="r", loose_abs=0.0, policy="printed-digits")


def test_loose_copies_everything_but_abs():
    t = Tolerance(reason="why", abs=0.5, rel=0.01, policy="printed-digits", quote="2750", loose_abs=5.0)
    loose = t.loose()
    assert loose is not None
    assert (loose.abs, loose.rel, loose.policy, loose.reason, loose.quote, loose.loose_abs) == (
        5.0,
        0.01,
        "printed-digits",
        "why",
        "2750",
        None,
    )
    assert Tolerance(reason="r", abs=0.5, policy="printed-digits").loose() is None


def test_absolute_and_as_dict():
    t = Tolerance(reason="why", abs=0.25, rel=0.5, policy="prose", loose_abs=1.0)
    assert t.absolute == 0.25
    assert t.as_dict() == {"abs": 0.25, "rel": 0.5, "reason": "why", "policy": "prose", "loose_abs": 1.0}
    with pytest.raises(ValueError, match="has no absolute part"):
        _ = Tolerance(reason="r", rel=0.1, policy="prose").absolute


@pytest.mark.parametrize(
    ("kw", "text"),
    [
        (dict(abs=0.005), "±0.005"),
        (dict(rel=0.1), "±10 %"),
        (dict(abs=0.5, rel=0.1), "±0.5 or ±10 %"),
        (dict(abs=0.0, rel=0.1), "±10 %"),  # a zero abs beside a rel is not shown
        (dict(abs=0.0), "exact"),
        (dict(), "exact"),
        (dict(abs=1.5e-5), "±$1.5 \\times 10^{-5}$"),
        (dict(abs=0.5, loose_abs=5.0), "±0.5 (±5 if trailing zeros are not significant)"),
        (dict(abs=0.0, loose_abs=50.0), "exact (±50 if trailing zeros are not significant)"),
        (dict(rel=0.125), "±12.5 %"),
    ],
)
def test_describe(kw, text):
    assert Tolerance(reason="r", policy="printed-digits", **kw).describe() == text


# --- printed ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "value", "abs_", "loose"),
    [
        ("17.67", 17.67, 0.005, None),
        ("1.2e-3", 1.2e-3, 5e-5, None),
        ("1.2E+3", 1200.0, 50.0, None),
        ("150e1", 1500.0, 5.0, None),  # an exponent states its digits: no loose reading
        ("−4", -4.0, 0.5, None),  # a Unicode minus
        ("+7", 7.0, 0.5, None),
        ("2750", 2750.0, 0.5, 5.0),
        ("3300", 3300.0, 0.5, 50.0),
        ("-3000", -3000.0, 0.5, 500.0),
        ("20", 20.0, 0.5, 5.0),
        ("20.", 20.0, 0.5, None),  # a decimal point states the zeros are significant
        ("20.0", 20.0, 0.05, None),
        ("0", 0.0, 0.5, None),
        ("2751", 2751.0, 0.5, None),
        (".5", 0.5, 0.05, None),
        (" 12.5 ", 12.5, 0.05, None),
    ],
)
def test_printed_half_a_unit_in_the_last_digit(text, value, abs_, loose):
    v, tol = printed(text)
    assert v == value
    assert tol.abs == pytest.approx(abs_, rel=1e-12)
    assert tol.loose_abs == (None if loose is None else pytest.approx(loose, rel=1e-12))
    assert tol.policy == "printed-digits"
    assert tol.quote == text.strip()
    assert tol.rel is None


def test_printed_reason_and_extra():
    _, tol = printed("17.67")
    assert tol.reason == "half a unit in the last printed digit of 17.67"
    _, tol = printed("17.67", extra_abs=0.01, why="the paper rounds g")
    assert tol.abs == pytest.approx(0.015, rel=1e-12)
    assert tol.reason == "half a unit in the last printed digit of 17.67, plus 0.01 (the paper rounds g)"
    _, tol = printed("17.67", extra_abs=0.01)
    assert tol.reason == "half a unit in the last printed digit of 17.67, plus 0.01"
    _, tol = printed("17.67", why="read as metres")
    assert tol.abs == 0.005
    assert tol.reason == "half a unit in the last printed digit of 17.67; read as metres"
    # the loose reading adds the extra too, and the reason names the zeros
    _, tol = printed("2750", extra_abs=1.0)
    assert (tol.abs, tol.loose_abs) == (1.5, 6.0)
    assert tol.reason.endswith(", or in its last non-zero digit if its trailing zero is not significant")
    _, tol = printed("3300")
    assert tol.reason.endswith("if its trailing zeros are not significant")
    _, tol = printed("1.5e-4")
    assert tol.reason == "half a unit in the last printed digit of $1.5 \\times 10^{-4}$"


@pytest.mark.parametrize("text", ["", "abc", ".", "-", "1.2.3", "e5", "1e", "12 m"])
def test_printed_rejects_what_is_not_a_number(text):
    with pytest.raises(ValueError, match="text must be a printed number"):
        printed(text)


@pytest.mark.parametrize(
    ("digits", "zeros"), [("2750", 1), ("3300", 2), ("100", 2), ("0", 0), ("000", 0), ("2751", 0), ("", 0)]
)
def test_trailing_zeros(digits, zeros):
    assert _trailing_zeros(digits) == zeros


def test_number_math():
    assert _number_math("1.61e-4") == "$1.61 \\times 10^{-4}$"
    assert _number_math("-1e3") == "$-10^{3}$"
    assert _number_math("−2.5E+07") == "$-2.5 \\times 10^{7}$"
    assert _number_math("0.011") == "0.011"
    assert _number_math("12") == "12"


# --- prose, figure_reading, monte_carlo ---------------------------------------------------------


def test_prose_each_kind_of_band():
    t = prose("  About ")
    assert (t.rel, t.abs, t.policy, t.quote) == (0.10, None, "prose", "about")
    assert t.reason == "'about' in prose: within ±10 %"
    t = prose("several", why="satellites in view")
    assert (t.rel, t.abs, t.policy) == (None, 3.0, "prose")
    assert t.reason == "'several' in prose: 3 to 9 (published as 6 ± 3); satellites in view"
    t = prose("an order of magnitude")
    assert (t.rel, t.abs) == (None, 0.5)
    assert prose("roughly").rel == 0.20
    assert prose("of the order of").rel == 0.50
    with pytest.raises(ValueError, match="word must be one of"):
        prose("perhaps")
    # every word of the table gives a tolerance of its own band
    for word, band in PROSE_WORDS.items():
        t = prose(word)
        assert (t.rel, t.abs) == (band.get("rel"), band.get("abs", band.get("abs_log10")))


def test_figure_reading():
    t = figure_reading(0.5, figure="Fig. 2.1", axis="loop bandwidth, 0.5 Hz per division")
    assert (t.abs, t.rel, t.policy) == (0.5, None, "figure-reading")
    assert t.reason == "read off Fig. 2.1: loop bandwidth, 0.5 Hz per division (reading resolution 0.5)"
    for bad in (0.0, -1.0, math.inf, math.nan):
        with pytest.raises(ValueError, match="resolution must be finite and > 0"):
            figure_reading(bad, figure="Fig. 1", axis="x")


def test_monte_carlo():
    t = monte_carlo(rel=0.3, runs=25, why="3 standard errors")
    assert (t.rel, t.abs, t.policy, t.reason) == (
        0.3,
        None,
        "monte-carlo",
        "Monte Carlo of 25 runs: 3 standard errors",
    )
    t = monte_carlo(abs=2.0, runs=1, why="one run")
    assert (t.rel, t.abs, t.reason) == (None, 2.0, "Monte Carlo of 1 runs: one run")
    with pytest.raises(ValueError, match="runs"):
        monte_carlo(rel=0.3, runs=0, why="none")


# --- the quote's numbers and policies --------------------------------------------------------------


@pytest.mark.parametrize(
    ("quote", "numbers"),
    [
        ("about 3,300 m", [3300.0]),
        ("1.5 × 10^-3", [0.0015]),
        ("1.5 x 10^{-3}", [0.0015]),
        ("2 * 10**4", [20000.0]),
        ("10^5 runs", [100000.0]),
        ("1/2 of it", [0.5, 1.0, 2.0]),
        ("1/0", [1.0, 0.0]),
        ("50 %", [50.0, 0.5]),
        ("−4 dB", [-4.0]),
        ("1.5e-3 s", [0.0015]),
        ("x2 and a1", []),
        ("a 1,000,000 m run", [1000000.0]),
        ("0.5", [0.5]),
        (".25", [0.25]),
    ],
)
def test_quote_numbers(quote, numbers):
    assert sorted(quote_numbers(quote)) == pytest.approx(sorted(numbers), rel=1e-12)


def test_quote_has_number_relative_above_one_absolute_below():
    assert quote_has_number("1000", 1000.0 + 0.9e-6)  # within 1e-9 * 1000
    assert not quote_has_number("1000", 1000.0 + 1.1e-6)
    assert quote_has_number("0.001", 0.001 + 0.9e-9)  # below 1: within an absolute 1e-9
    assert not quote_has_number("0.001", 0.001 + 1.1e-9)
    assert quote_has_number("-2000", -2000.0 - 1.9e-6)
    assert not quote_has_number("no number", 0.0)


def test_label_prints_value():
    assert label_prints_value("the C/A code, 1.023 Mchip/s", 1.023e6)
    assert label_prints_value("1 ps", 1e-12)  # 1000**-4
    assert label_prints_value("1 Tm", 1e12)  # 1000**4
    assert not label_prints_value("1 fm", 1e-15)  # beyond the prefixes tried
    assert label_prints_value("within 1 %", 0.01)
    assert label_prints_value("3", 3)
    assert not label_prints_value("3", 3.0000001)
    assert not label_prints_value("1", True)
    assert not label_prints_value("0", 0.0)
    assert not label_prints_value("the value 2", "2")
    assert label_prints_value("-2 dB", -2.0)


def test_quote_policies():
    assert quote_policies("anything", published=True) == ("exact",)
    assert quote_policies("approximately 1.4", published=1.4) == ("prose",)
    assert quote_policies("approx. 1.4", published=1.4) == ("prose",)
    assert quote_policies("on  the order\nof 5", published=5.0) == ("prose",)
    assert quote_policies("~5", published=5.0) == ("prose",)
    assert quote_policies("43 dBW, as read from the figures", published=43.0) == ("figure-reading",)
    assert quote_policies("about 43, from Fig. 3", published=43.0) == ("prose", "figure-reading")
    assert quote_policies("17.67", published=17.67) == ("printed-digits", "monte-carlo")
    assert quote_policies("17", published=17.0) == ("printed-digits", "monte-carlo", "exact")
    assert quote_policies("17", published=17.0, locator="Figs. 3-4") == (
        "printed-digits",
        "monte-carlo",
        "exact",
        "figure-reading",
    )
    assert quote_policies("17.5", published=17.5, locator="Fig. 3") == (
        "printed-digits",
        "monte-carlo",
        "figure-reading",
    )
    assert quote_policies("inf", published=math.inf) == ("printed-digits", "monte-carlo")
    # "about" inside a word is not the prose word
    assert quote_policies("roundabout 17.5", published=17.5) == ("printed-digits", "monte-carlo")


def test_label_prints_value_powers_of_a_thousand_up_to_four():
    # oracle: the SI prefixes from pico to tera, 1000 ** -4 to 1000 ** 4, and no further
    assert label_prints_value("1 P", 1e12)
    assert not label_prints_value("1 P", 1e15)
    assert not label_prints_value("1", 1e-15)
