"""A claim's note, JSON and table row from hand-made evaluation records (issue 31, mutation
survivors of ``Evaluation.note``, ``_reading_words``, ``_reading_text``, ``as_json``, ``_plain``,
``Tolerance.describe``, and the ledger table's ``format_value`` and ``rows``).

Each test builds an :class:`~navcore.claims.evaluation.Evaluation` directly (its readings, band, inputs
and flags written by hand), so the sentence the note must add is fixed by the record alone.

Oracle: the sentences and formats the docstrings of :meth:`Evaluation.note` and
:func:`~navcore.ledger.text.format_value` describe, written out by hand for each record.
"""

from __future__ import annotations

import math

import pytest

from navcore.claims.evaluation import Evaluation, _plain
from navcore.claims.tolerances import EXACT, PRECISION_LOOSE, PRECISION_READING, PRECISION_STRICT, printed
from navcore.ledger import Claim, Erratum, InputSet, Tolerance
from navcore.ledger.tables import rows
from navcore.ledger.text import format_value, published_text

IN = InputSet("ATC10", "mutation_note")
IN.convention("scale", 1.0, alternative=10.0, unit="m", quantity="scale", reason="two readings")
IN.convention("code", 1.023e6, alternative=10.23e6, unit="Hz", quantity="chip rate", reason="C/A or P")
IN.convention(
    "chip", 1.023e6, readings={"the C/A code, 1.023 Mchip/s": 1.023e6, "the P code": 10.23e6}, unit="Hz",
    quantity="chip rate", reason="which code",
)  # fmt: skip
IN.convention(
    "chip2", 10.23e6, readings={"the P code": 10.23e6, "the C/A code, 1.023 Mchip/s": 1.023e6}, unit="Hz",
    quantity="chip rate", reason="which code",
)  # fmt: skip
IN.convention("pair", (1, 2.5), alternative=(3, 4.0), quantity="pair", reason="a tuple")
IN.convention("bare", 1.0, alternative=2.0, unit="1", reason="no quantity")
NAME = "ATC10.mutation_note."
HALF = Tolerance(reason="t", abs=0.5, policy="printed-digits")


def claim(**kw) -> Claim:
    base = dict(
        id="ATC10-test-note",
        paper="ATC10",
        locator="Table 1",
        quantity="q",
        published=92.0,
        unit="m",
        compute=lambda: 1.0,
        tolerance=HALF,
        expected_status="consistent",
        note="A note",
    )
    base.update(kw)
    return Claim(**base)


def reading(names: dict, value, agrees=False, nominal=False, band=None, too_wide=False, undecided=False):
    return {
        "reading": names,
        "nominal": nominal,
        "value": value,
        "band": band,
        "agrees": agrees,
        "band_too_wide": too_wide,
        "undecided": undecided,
    }


def ev(c=None, **kw) -> Evaluation:
    kw.setdefault("status", "consistent")
    kw.setdefault("tolerance", HALF)
    return Evaluation(c or claim(), 2.0, True, "d", **kw)


USED = {NAME + "scale": "the reading used"}
OTHER = {NAME + "scale": "the other reading"}


def test_other_reading_value_unit_and_agreement():
    e = ev(readings=(reading(USED, 2.0, nominal=True), reading(OTHER, 92.0, agrees=True)))
    assert e.note() == (
        "A note. With the scale read as the other reading (10 m): 92 m, which agrees with the printed value. "
        "The reading used disagrees and another admissible reading agrees: an open reading of the text, "
        "not a discrepancy."
    )
    # a dimensionless claim: no unit after the value; the note already ends its sentence
    c = claim(unit="", note="A note!")
    e = ev(c, readings=(reading(USED, 2.0, nominal=True, agrees=True), reading(OTHER, 20.0)))
    assert e.note() == "A note! With the scale read as the other reading (10 m): 20."
    # a numeric claim whose unit is "statement" prints none either
    e = ev(
        claim(unit="statement"),
        readings=(reading(USED, 2.0, nominal=True, agrees=True), reading(OTHER, 20.0)),
    )
    assert e.note() == "A note. With the scale read as the other reading (10 m): 20."


def test_other_reading_band_and_several_changed_inputs():
    both = {
        NAME + "scale": "the other reading",
        NAME + "code": "the other reading",
        NAME + "bare": "the reading used",
    }
    e = ev(readings=(reading(USED, 2.0, nominal=True, agrees=True), reading(both, 20.0, band=(10.0, 30.5))))
    assert e.note() == (
        "A note. With the scale read as the other reading (10 m) and the chip rate read as the other "
        "reading ($1.023 \\times 10^{7}$ Hz): 20 m (over the assumed ranges 10 to 30.5 m)."
    )


def test_a_label_that_prints_its_value_is_not_repeated():
    # chip's reading used is the C/A code; chip2's is the P code, its other reading the C/A code
    to_ca = {NAME + "chip2": "the C/A code, 1.023 Mchip/s"}
    e = ev(readings=(reading({}, 2.0, nominal=True, agrees=True), reading(to_ca, 5.0)))
    assert e.note() == "A note. With the chip rate read as the C/A code, 1.023 Mchip/s: 5 m."
    to_p = {NAME + "chip": "the P code"}
    e = ev(readings=(reading({}, 2.0, nominal=True, agrees=True), reading(to_p, 5.0)))
    assert e.note() == "A note. With the chip rate read as the P code ($1.023 \\times 10^{7}$ Hz): 5 m."


def test_inputs_at_their_reading_used_are_not_named():
    r = {NAME + "chip": "the C/A code, 1.023 Mchip/s", NAME + "scale": "the other reading"}
    e = ev(readings=(reading({}, 2.0, nominal=True, agrees=True), reading(r, 5.0)))
    assert e.note() == "A note. With the scale read as the other reading (10 m): 5 m."


def test_tuple_values_unknown_inputs_and_unknown_labels():
    e = ev(
        readings=(
            reading({}, 2.0, nominal=True, agrees=True),
            reading({NAME + "pair": "the other reading"}, 5.0),
        )
    )
    assert e.note() == "A note. With the pair read as the other reading (3, 4): 5 m."
    # an input that is not registered: its name spelled out, no value
    e = ev(
        readings=(reading({}, 2.0, nominal=True, agrees=True), reading({"ATC10.nowhere.some_x": "lab"}, 5.0))
    )
    assert e.note() == "A note. With the some x read as lab: 5 m."
    # a label that is none of the input's readings: no value shown
    e = ev(readings=(reading({}, 2.0, nominal=True, agrees=True), reading({NAME + "scale": "half"}, 5.0)))
    assert e.note() == "A note. With the scale read as half: 5 m."
    # an input without a quantity or a unit ("1" is a pure number)
    e = ev(
        readings=(
            reading({}, 2.0, nominal=True, agrees=True),
            reading({NAME + "bare": "the other reading"}, 5.0),
        )
    )
    assert e.note() == "A note. With the bare read as the other reading (2): 5 m."


def test_precision_readings_in_words():
    strict = {PRECISION_READING: PRECISION_STRICT}
    loose = {PRECISION_READING: PRECISION_LOOSE}
    e = ev(readings=(reading(strict, 2753.0, nominal=True), reading(loose, 2753.0, agrees=True)))
    assert e.note() == (
        "A note. With the printed number's trailing zeros not significant: 2753 m, which agrees with the "
        "printed value. The reading used disagrees and another admissible reading agrees: an open reading "
        "of the text, not a discrepancy."
    )
    # with a convention too: the convention is named first, then the precision
    mixed = {NAME + "scale": "the other reading", PRECISION_READING: PRECISION_LOOSE}
    e = ev(readings=(reading({**USED, **strict}, 2.0, nominal=True, agrees=True), reading(mixed, 3.0)))
    assert e.note() == (
        "A note. With the scale read as the other reading (10 m) and the printed number's trailing zeros "
        "not significant: 3 m."
    )


def test_statement_readings_in_words():
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)

    def note(value, band):
        return ev(
            s, readings=(reading(USED, True, nominal=True, agrees=True), reading(OTHER, value, band=band))
        ).note()

    head = "A note. With the scale read as the other reading (10 m): "
    assert note(True, None) == head + "holds."
    assert note(False, None) == head + "does not hold."
    assert note(True, (True, True)) == head + "holds across the assumed ranges."
    assert note(False, (False, False)) == head + "does not hold across the assumed ranges."
    assert (
        note(True, (False, True)) == head + "holds at the nominal inputs, not across all the assumed ranges."
    )
    assert note(False, (False, True)) == (
        head + "does not hold at the nominal inputs, but holds over part of the assumed ranges."
    )
    assert note(False, (True, False)) == (
        head + "does not hold at the nominal inputs, but holds over part of the assumed ranges."
    )


def test_consistent_sentence_needs_a_disagreeing_nominal_and_an_agreeing_other():
    both_agree = (reading(USED, 92.0, nominal=True, agrees=True), reading(OTHER, 92.0, agrees=True))
    base = (
        "A note. With the scale read as the other reading (10 m): 92 m, which agrees with the printed value."
    )
    assert ev(readings=both_agree).note() == base
    none_agree = (reading(USED, 2.0, nominal=True), reading(OTHER, 20.0))
    assert ev(readings=none_agree, status="consistent").note().endswith("20 m.")
    one = (reading(USED, 2.0, nominal=True), reading(OTHER, 92.0, agrees=True))
    assert ev(readings=one, status="discrepant").note() == base
    assert ev(readings=(reading(OTHER, 92.0, agrees=True),)).note() == base


def test_band_too_wide_sentences():
    wide = dict(band=(1.0, 100.0), band_too_wide=True, status="not-reproducible")
    text = (
        "Over the assumed inputs' ranges the value spans 1 to 100 m, ends more than a factor 3 apart, "
        "and the printed value agrees with only part of it: the assumptions are too loose to decide."
    )
    assert ev(**wide).note() == "A note. " + text
    assert ev(readings=(reading(USED, 2.0, nominal=True, agrees=True),), **wide).note() == "A note. " + text
    # the unit is left out for a dimensionless claim
    assert "spans 1 to 100, ends" in ev(claim(unit=""), **wide).note()
    # the reading used disagrees: the reading that agrees is too wide
    e = ev(
        readings=(reading(USED, 2.0, nominal=True), reading(OTHER, 20.0, agrees=True, band=(1.0, 100.0))),
        **wide,
    )
    assert e.note().endswith(
        "The reading that agrees does so over only part of a band whose ends are more than a factor 3 "
        "apart: the assumptions are too loose to decide."
    )
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)
    swide = dict(band=(False, True), band_too_wide=True, status="not-reproducible")
    assert ev(s, **swide).note() == (
        "A note. It holds for some of the assumed inputs and fails for others: "
        "the assumptions are too loose to decide."
    )
    e = ev(
        s,
        readings=(reading(USED, False, nominal=True), reading(OTHER, True, agrees=True, band=(False, True))),
        **swide,
    )
    assert e.note().endswith(
        "The reading that agrees holds for some of the assumed inputs and fails for others: the "
        "assumptions are too loose to decide."
    )
    # not too wide, or no band: no sentence
    assert ev(band=(1.0, 100.0)).note() == "A note"
    assert ev(band_too_wide=True).note() == "A note"


def test_envelope_sentences():
    inputs = (
        *({"name": f"x{i}", "provenance": "assumed"} for i in range(7)),
        {"name": "p", "provenance": "published"},
    )
    tail = (
        "do not reach the printed value, but the inputs' separate effects add up to 0.5 to 150 m, which "
        "does: beyond 6 inputs the corners run are a sample of the box, so the search cannot show the "
        "printed value out of reach."
    )
    kw = dict(band=(1.0, 90.0), envelope=(0.5, 150.0), inputs=inputs, status="not-reproducible")
    assert ev(**kw).note() == "A note. The runs over the 7 assumed inputs " + tail
    # undecided under the reading used: the plain lead
    r = (reading(USED, 2.0, nominal=True, undecided=True), reading(OTHER, 20.0, undecided=True))
    assert ev(readings=r, **kw).note().endswith(". The runs over the 7 assumed inputs " + tail)
    # undecided only under another reading: the lead names it
    r = (reading(USED, 2.0, nominal=True), reading(OTHER, 20.0, undecided=True))
    assert (
        ev(readings=r, **kw)
        .note()
        .endswith(
            ". With the scale read as the other reading (10 m), the runs over the 7 assumed inputs " + tail
        )
    )
    # no band: no sentence
    assert ev(envelope=(0.5, 150.0), inputs=inputs).note() == "A note"


def test_as_json_uses_the_evaluations_tolerance_and_the_given_errata():
    value, tol = printed("92")
    c = claim(published=value, tolerance=tol, id="ATC10-test-note-json")
    Erratum(
        id="ATC10-E-note-json", paper="ATC10", locator="Eq. 1", printed="a", finding="b", evidence="c",
        kind="units", basis="computed", claims=("ATC10-test-note-json",),
    )  # fmt: skip
    other = printed("92.0")[1]
    r = (
        reading(USED, 2.0, nominal=True),
        reading(OTHER, 92.0, agrees=True, band=(90.0, math.inf), too_wide=True),
    )
    js = Evaluation(c, 92, True, "d", tolerance=other, band=(90, -math.inf), readings=r).as_json(errata=[])
    assert js["printed"] == "92.0" and js["tolerance"] == other.as_dict()
    assert type(js["published"]) is float and type(js["reproduced"]) is float
    assert js["errata"] == []
    assert js["band"] == [90.0, "-Infinity"]
    assert js["readings"][1] == {
        "reading": OTHER,
        "nominal": False,
        "value": 92.0,
        "band": [90.0, "Infinity"],
        "agrees": True,
        "band_too_wide": True,
    }
    # a record without "band_too_wide" is read as False
    r2 = ({"reading": USED, "nominal": 1, "value": 2.0, "agrees": 0},)
    assert Evaluation(c, 92, True, "d", readings=r2).as_json(errata=[])["readings"] == [
        {
            "reading": USED,
            "nominal": True,
            "value": 2.0,
            "band": None,
            "agrees": False,
            "band_too_wide": False,
        }
    ]
    # no evaluated tolerance: the claim's own (a callable: none)
    assert Evaluation(c, None, False, "d").as_json(errata=[])["tolerance"] == tol.as_dict()
    assert Evaluation(claim(tolerance=lambda: HALF), None, False, "d").as_json(errata=[])["tolerance"] is None
    # the errata constructed in the process when none are given
    assert {"id": "ATC10-E-note-json", "basis": "computed"} in Evaluation(c, None, False, "d").as_json()[
        "errata"
    ]


@pytest.mark.parametrize(
    ("value", "text"),
    [
        ((6, 4, 55.0, 0.0), "(6, 4, 55, 0)"),
        ([True, 0.5], "(true, 0.5)"),
        (True, "true"),
        (False, "false"),
        (0.0, "0"),
        (0.01, "0.01"),
        (0.00999, "$9.99 \\times 10^{-3}$"),
        (-0.00353918, "$-3.53918 \\times 10^{-3}$"),
        (1.0e-12, "$10^{-12}$"),
        (1023000.0, "$1.023 \\times 10^{6}$"),
        (2.5, "2.5"),
        (7, "7"),
        ("x", "x"),
    ],
)
def test_plain(value, text):
    assert _plain(value) == text


@pytest.mark.parametrize(
    ("value", "text"),
    [
        (None, "—"),
        (True, "true"),
        (False, "false"),
        (math.inf, "∞"),
        (-math.inf, "−∞"),
        (3.0, "3"),
        (-999999.0, "-999999"),
        (1e6, "1×10⁶"),
        (17.6712345, "17.671"),
        (0.001, "0.001"),
        (0.000999, "9.99×10⁻⁴"),
        (123456.7, "123457"),
        (999999.5, "1000000"),  # rounds up to a million: the fixed form of format_number
        (2.5e-7, "2.5×10⁻⁷"),
    ],
)
def test_format_value(value, text):
    assert format_value(value) == text


def test_format_value_digits():
    assert format_value(3.14159265, digits=3) == "3.14"
    assert format_value(1.23456e-5, digits=2) == "1.2×10⁻⁵"


def test_published_and_rows():
    for relation, text in (("=", "92"), ("<", "< 92"), ("<=", "≤ 92"), (">", "> 92"), (">=", "≥ 92")):
        assert published_text(ev(claim(relation=relation))) == text
    e = Evaluation(
        claim(erratum="ATC10-E-x", discussed_in="atc10/ch1"),
        2.0,
        False,
        "d",
        status="inconsistent",
        tolerance=HALF,
        band=(1.0, 3.5),
    )
    assert rows([e]) == [
        {
            "id": "ATC10-test-note",
            "locator": "Table 1",
            "quantity": "q",
            "published": "92",
            "reproduced": "2",
            "band": "1 to 3.5",
            "unit": "m",
            "kind": "reproduction",
            "tolerance": "±0.5",
            "policy": "printed-digits",
            "status": "inconsistent",
            "check": "FAIL",
            "note": "A note",
            "tolerance_reason": "t",
            "erratum": "ATC10-E-x",
            "discussed_in": "atc10/ch1",
        }
    ]
    # no evaluated tolerance: the claim's; a callable one has no description
    row = rows([Evaluation(claim(tolerance=lambda: HALF), None, True, "d")])[0]
    assert (row["tolerance"], row["policy"], row["tolerance_reason"], row["band"], row["check"]) == (
        "",
        "",
        "",
        "",
        "ok",
    )
    assert rows([Evaluation(claim(), None, True, "d")])[0]["tolerance"] == "±0.5"


def test_table_cell_texts():
    from navcore.ledger.text import (
        _band_text,
        _inputs_text,
        _nowrap,
        _plain_with_unit,
        _reproduced_text,
        _status_class,
        _status_colour,
        _tolerance_text,
    )

    assert _status_class("not-reproducible") == "ledger-status-not-reproducible"
    assert _status_class("a b/c") == "ledger-status-a-b-c"
    assert _status_colour("unknown") == "#ffffff"
    assert _nowrap("12 m") == "12&nbsp;m"
    assert _nowrap("does not hold") == "does not hold"
    assert _nowrap("a <b> 1") == "a&nbsp;&lt;b&gt;&nbsp;1"
    assert _nowrap("12345678901234567 m") == "12345678901234567 m"  # longer than 16: may wrap
    assert _plain_with_unit("1", "states") == "1 state"
    assert _plain_with_unit("2", "states") == "2 states"
    assert _plain_with_unit("1", "m") == "1 m"
    assert _plain_with_unit("—", "m") == "—" and _plain_with_unit("", "m") == ""
    assert _plain_with_unit("3", "statement") == "3" and _plain_with_unit("3", "") == "3"
    assert _reproduced_text(ev()) == "2 m"
    # tolerances: size and reason; a reason that starts with the size is the whole text
    assert _tolerance_text(ev()) == "±0.5: t"
    assert _tolerance_text(ev(tolerance=Tolerance(reason="±0.5 by rounding", abs=0.5, policy="exact"))) == (
        "±0.5 by rounding"
    )
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)
    assert _tolerance_text(ev(s, tolerance=EXACT)) == ""
    assert _tolerance_text(ev(tolerance=EXACT)) == "exact: an integer count or a logical statement"
    assert _tolerance_text(Evaluation(claim(tolerance=lambda: HALF), None, True, "d")) == ""
    assert _tolerance_text(Evaluation(claim(), None, True, "d")) == "±0.5: t"
    # the band with its unit and the runs left out
    left = ({"case": "no fix", "runs": 2},)
    assert _band_text(ev(band=(1.0, 2.5), left_out=left)) == (
        "1 to 2.5 m (left out, outside the model's domain: no fix (2 runs))"
    )
    assert _band_text(ev(claim(unit=""), band=(1.0, 2.5))) == "1 to 2.5"
    assert _band_text(ev()) == "" and _band_text(ev(s, band=(False, True))) == ""
    # the inputs read
    inputs = (
        {"name": NAME + "scale", "provenance": "convention", "value": 1.0},
        {"name": NAME + "pair", "provenance": "convention", "value": [1, 2.5]},
        {"name": "ATC10.nowhere.n_states", "provenance": "published", "locator": "T2", "value": 1},
        {"name": "ATC10.nowhere.mode", "provenance": "assumed", "value": "tracking"},
        {"name": "ATC10.nowhere.flag", "provenance": "assumed", "value": True},
        {"name": "ATC10.nowhere.long", "provenance": "assumed", "value": "x" * 45},
    )
    assert _inputs_text(ev(inputs=inputs)) == (
        "scale = 1 m (convention); pair = (1, 2.5) (convention); n states = 1 (published, T2); "
        "mode = tracking (assumed); flag = true (assumed); long = " + "x" * 39 + "… (assumed)"
    )


def test_agreeing_reading_text():
    from navcore.ledger.text import _agreeing_reading_text

    assert _agreeing_reading_text(ev()) == ""
    # the reading used disagrees: the agreeing readings' labels
    r = (
        reading(USED, 2.0, nominal=True),
        reading(OTHER, 92.0, agrees=True),
        reading({NAME + "scale": "x", NAME + "code": "y"}, 92.0, agrees=True),
        reading({NAME + "scale": "z"}, 9.0),
    )
    assert _agreeing_reading_text(ev(readings=r)) == "agrees under: the other reading / x; y"
    # the reading used agrees and decides: nothing to say
    r = (reading(USED, 92.0, nominal=True, agrees=True), reading(OTHER, 92.0, agrees=True))
    assert _agreeing_reading_text(ev(readings=r)) == ""
    # the reading used agrees over a band too wide, another decides: consistent, named
    r = (
        reading(USED, 92.0, nominal=True, agrees=True, too_wide=True),
        reading(OTHER, 92.0, agrees=True),
        reading({NAME + "scale": "w"}, 92.0, agrees=True, too_wide=True),
    )
    assert _agreeing_reading_text(ev(readings=r)) == "agrees under: the other reading"
    assert _agreeing_reading_text(ev(readings=r, status="not-reproducible")) == ""
    r = (reading(USED, 2.0, nominal=True), reading(OTHER, 9.0))
    assert _agreeing_reading_text(ev(readings=r)) == ""


def test_plain_drops_a_bare_decimal_point_and_json_writes_floats():
    # 0.001 and 0.005 in six significant digits are "1.00000e-03", "5.00000e-03": zeros and the point go
    assert _plain(0.001) == "$10^{-3}$"
    assert _plain(0.005) == "$5 \\times 10^{-3}$"
    # a published integer is written as a float
    js = Evaluation(claim(published=92), 92, True, "d", tolerance=HALF).as_json(errata=[])
    assert type(js["published"]) is float and js["published"] == 92.0


def test_label_and_unit_of_any_name():
    from navcore.claims.inputs import _label_and_unit

    s = InputSet("ATC10", "mutation_note_units")
    s.published("dash", 1.0, locator="T1", unit="-")
    s.published("truth", True, locator="T1", unit="statement")
    s.published("metres", 1.0, locator="T1", unit="m")
    assert _label_and_unit("ATC10.mutation_note_units.dash") == ("dash", "")
    assert _label_and_unit("ATC10.mutation_note_units.truth") == ("truth", "")
    assert _label_and_unit("ATC10.mutation_note_units.metres") == ("metres", "m")
    assert _label_and_unit("nodot") == ("nodot", "")
