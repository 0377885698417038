"""The generated sentences of a claim's note and details, as a reader reads them (readers' round 2):
what agrees (the value, or only part of its band), which readings are named, sentences built from
a noun phrase, numbers at the claim's digits, singular count units, table-valued inputs as text,
the ledger's table of prose words named, and no range whose two ends print the same.

Each test builds an :class:`~navcore.claims.evaluation.Evaluation` by hand (its readings, band and
tolerance written out), so the sentence is fixed by the record alone.
"""

from __future__ import annotations

import math

from navcore.claims.evaluation import Evaluation, _plain, note_digits, reader_label
from navcore.claims.tolerances import EXACT, PRECISION_LOOSE, PRECISION_READING, PRECISION_STRICT, printed
from navcore.ledger import Claim, InputSet, Tolerance
from navcore.ledger.interactive import _band_html
from navcore.ledger.text import _agreeing_reading_text, _band_text, _table_value_text

IN = InputSet("ATC10", "note_text")
IN.convention("scale", 1.0, alternative=10.0, unit="m", quantity="scale", reason="two readings")
IN.convention("sky", 0.0, alternative=15.0, unit="deg", quantity="phasing", reason="read on the way")
IN.convention("gyro", 1.0, alternative=2.0, quantity="gyro numbers", reason="read on the way")
IN.convention(
    "fall", 0.9, readings={"from 90 %": 0.9, "from half": 0.5, "from a tenth": 0.1},
    quantity="start of the fall", reason="three readings",
)  # fmt: skip
IN.convention(
    "step", 0.001, readings={"more than 0.1 %": 0.001, "more than 1 %": 0.01},
    quantity="how much the error must fall to count as a step", reason="a clause",
)  # fmt: skip
IN.convention(
    "near", 0.01, readings={"within 1 %": 0.01, "within 10 %, the prose table's 'nearly'": 0.1},
    quantity="closeness that 'close' allows", reason="a prose word",
)  # fmt: skip
NAME = "ATC10.note_text."
HALF = Tolerance(reason="t", abs=0.5, policy="printed-digits")


def claim(**kw) -> Claim:
    base = dict(
        id="ATC10-test-note-text", paper="ATC10", locator="Table 1", quantity="q", published=11.0,
        unit="m", compute=lambda: 1.0, tolerance=HALF, expected_status="consistent", note="A note",
    )  # fmt: skip
    base.update(kw)
    return Claim(**base)


def reading(names: dict, value, agrees=False, nominal=False, band=None, too_wide=False):
    return {
        "reading": names,
        "nominal": nominal,
        "value": value,
        "band": band,
        "agrees": agrees,
        "band_too_wide": too_wide,
        "undecided": False,
    }


def ev(c=None, **kw) -> Evaluation:
    kw.setdefault("status", "consistent")
    kw.setdefault("tolerance", HALF)
    return Evaluation(c or claim(), 2.0, True, "d", **kw)


USED = {NAME + "scale": "the reading used"}
OTHER = {NAME + "scale": "the other reading"}


def test_a_band_that_agrees_is_not_said_of_a_value_that_does_not():
    # 72.4315 m misses the printed 11 m; part of its band reaches it
    r = (
        reading(USED, 2.0, nominal=True),
        reading(OTHER, 72.4315, agrees=True, band=(1.86813, 476.476)),
    )
    note = ev(readings=r, band=(1.0, 500.0)).note()
    assert "which agrees" not in note
    assert (
        "With the scale read as the other reading (10 m): 72.43 m (over the assumed ranges 1.868 to "
        "476.5 m); the value does not agree with the printed value, only part of that range does."
    ) in note
    # the value agrees: said of the value
    r = (reading(USED, 2.0, nominal=True), reading(OTHER, 11.2, agrees=True, band=(9.0, 12.0)))
    assert "11.2 m (over the assumed ranges 9 to 12 m), which agrees with the printed value." in (
        ev(readings=r, band=(1.0, 12.0)).note()
    )
    # the value agrees but the band is too wide to decide: said so, not a bare "agrees"
    r = (reading(USED, 2.0, nominal=True), reading(OTHER, 11.2, agrees=True, band=(1.0, 90.0), too_wide=True))
    assert (
        "11.2 m (over the assumed ranges 1 to 90 m); the value agrees with the printed value, but the range "
        "is too wide to decide."
    ) in ev(readings=r, band=(1.0, 90.0)).note()
    # under the loose precision the value is judged with the loose tolerance (±5 around 10: 15.24 misses)
    value, tol = printed("10")
    c = claim(published=value, tolerance=tol, relation="<=")
    strict = {PRECISION_READING: PRECISION_STRICT}
    loose = {PRECISION_READING: PRECISION_LOOSE}
    r = (reading(strict, 15.24, nominal=True), reading(loose, 15.24, agrees=True, band=(3.048, 54.864)))
    note = ev(c, tolerance=tol, readings=r, band=(3.048, 54.864)).note()
    assert "15.24 m (over the assumed ranges 3.048 to 54.86 m); the value does not agree" in note
    # a statement: the part of the ranges agrees
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)
    r = (reading(USED, False, nominal=True), reading(OTHER, False, agrees=True, band=(False, True)))
    note = ev(s, tolerance=EXACT, readings=r, band=(False, True)).note()
    assert note.startswith(
        "A note. With the scale read as the other reading (10 m): does not hold at the nominal inputs, "
        "but holds over part of the assumed ranges; only part of the assumed ranges agrees with the "
        "printed value."
    )


def test_conventions_whose_readings_change_nothing_are_named_once():
    sky, gyro = NAME + "sky", NAME + "gyro"
    used = {NAME + "scale": "the reading used", sky: "the reading used", gyro: "the reading used"}

    def combo(scale, s, g):
        return {
            NAME + "scale": "the other reading" if scale else "the reading used",
            sky: "the other reading" if s else "the reading used",
            gyro: "the other reading" if g else "the reading used",
        }

    r = [reading(used, 2.0, nominal=True)]
    for scale in (0, 1):
        for s in (0, 1):
            for g in (0, 1):
                if scale or s or g:
                    r.append(reading(combo(scale, s, g), 11.0 if scale else 2.0, agrees=bool(scale)))
    e = ev(readings=tuple(r))
    assert set(e.inert_conventions()) == {sky, gyro}
    assert e.note() == (
        "A note. With the scale read as the other reading (10 m): 11 m, which agrees with the printed value. "
        "The other readings, alone or together, leave the result unchanged: the gyro numbers read as the "
        "other reading; the phasing read as the other reading. The reading used disagrees and another "
        "admissible reading agrees: an open reading of the text, not a discrepancy."
    )
    # the verdict cell names what differs from the reading used, and neither inert convention
    assert _agreeing_reading_text(e) == "agrees under: the other reading"
    # readings run one at a time: "each alone"
    r = [
        reading(used, 2.0, nominal=True),
        reading(combo(0, 1, 0), 2.0),
        reading(combo(0, 0, 1), 2.0),
        reading(combo(1, 0, 0), 5.0),
    ]
    assert (
        "The other readings, each alone, leave the result unchanged: the phasing"
        in ev(readings=tuple(r)).note()
    )
    # one convention only: its reading is never folded away
    r = (reading(USED, 11.0, nominal=True, agrees=True), reading(OTHER, 11.0, agrees=True))
    assert ev(readings=r).inert_conventions() == ()


def test_readings_that_all_give_the_same_make_one_sentence():
    fall = NAME + "fall"
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)
    r = (
        reading({fall: "from 90 %"}, True, nominal=True, agrees=True, band=(True, True)),
        reading({fall: "from half"}, True, agrees=True),
        reading({fall: "from a tenth"}, True, agrees=True),
    )
    assert ev(s, tolerance=EXACT, readings=r, band=(True, True)).note() == (
        "A note. The other readings give the same (holds at the nominal inputs, which agrees with the "
        "printed value): the start of the fall read as from half or as from a tenth."
    )
    # different outcomes: one sentence each
    r = (r[0], r[1], reading({fall: "from a tenth"}, False))
    assert ev(s, tolerance=EXACT, readings=r).note().count("With the start of the fall") == 2


def test_a_reading_described_by_a_clause_and_the_prose_table():
    r = (
        reading({NAME + "step": "more than 0.1 %"}, True, nominal=True, agrees=True),
        reading({NAME + "step": "more than 1 %"}, True, agrees=True),
    )
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)
    assert ev(s, tolerance=EXACT, readings=r).note() == (
        "A note. With more than 1 % for how much the error must fall to count as a step: holds, which "
        "agrees with the printed value."
    )
    r = (
        reading({NAME + "near": "within 1 %"}, False, nominal=True),
        reading({NAME + "near": "within 10 %, the prose table's 'nearly'"}, True, agrees=True),
    )
    e = ev(s, tolerance=EXACT, readings=r)
    assert (
        "With the closeness that 'close' allows read as within 10 % ('nearly' in the ledger's table of prose "
        "words): holds, which agrees with the printed value."
    ) in e.note()
    assert (
        _agreeing_reading_text(e)
        == "agrees under: within 10 % ('nearly' in the ledger's table of prose words)"
    )
    assert reader_label("2 to 5 s, the prose table's reading") == (
        "2 to 5 s, the reading of the ledger's table of prose words"
    )
    assert reader_label("within 1 %") == "within 1 %"


def test_agrees_under_names_only_what_differs_and_only_the_smallest_readings():
    sky = NAME + "sky"
    used = {NAME + "scale": "the reading used", sky: "the reading used", PRECISION_READING: PRECISION_STRICT}
    a = {NAME + "scale": "the other reading", sky: "the reading used", PRECISION_READING: PRECISION_STRICT}
    ab = {NAME + "scale": "the other reading", sky: "the other reading", PRECISION_READING: PRECISION_STRICT}
    b = {NAME + "scale": "the reading used", sky: "the other reading", PRECISION_READING: PRECISION_STRICT}
    loose = {**used, PRECISION_READING: PRECISION_LOOSE}
    r = (
        reading(used, 2.0, nominal=True),
        reading(a, 11.0, agrees=True),
        reading(ab, 11.2, agrees=True),
        reading(b, 3.0),
        reading(loose, 2.0, agrees=True),
    )
    assert (
        _agreeing_reading_text(ev(readings=r))
        == "agrees under: the other reading / trailing zeros not significant"
    )


def test_numbers_at_the_claims_digits_and_infinity():
    assert note_digits(claim(published=11.0, tolerance=printed("11")[1]), printed("11")[1]) == 4
    assert note_digits(claim(published=48.9), None) == 5
    assert note_digits(claim(published=True, unit="statement", kind="statement", tolerance=EXACT)) == 4
    assert _plain(53.3935, 4) == "53.39" and _plain(1176.06, 3) == "1176" and _plain(0.550607, 4) == "0.5506"
    assert _plain(math.inf) == "∞" and _plain(-math.inf) == "−∞"
    r = (reading(USED, 2.0, nominal=True), reading(OTHER, math.inf))
    assert ev(readings=r).note() == "A note. With the scale read as the other reading (10 m): ∞ m."
    # the sentences after the readings use the same digits
    wide = dict(band=(1.86813, 476.476), band_too_wide=True, status="not-reproducible")
    assert "spans 1.868 to 476.5 m, ends" in ev(**wide).note()


def test_a_count_unit_after_one_is_singular():
    c = claim(unit="intervals", published=2.0)
    r = (reading(USED, 2.0, nominal=True, agrees=True), reading(OTHER, 1.0))
    assert ev(c, readings=r).note().endswith(": 1 interval.")
    r = (reading(USED, 2.0, nominal=True, agrees=True), reading(OTHER, 3.0))
    assert ev(c, readings=r).note().endswith(": 3 intervals.")


def test_table_valued_inputs_read_as_text():
    assert _table_value_text([["Position", 3], ["Velocity", 3], ["User clock bias", 1]]) == (
        "Position 3, Velocity 3, User clock bias 1"
    )
    assert _table_value_text([[1, 0, 0, 0, -1, 1], [0, 1, 0, 1, 0, -1], [0, 0, 1, -1, 1, 0]]) == (
        "a $3 \\times 6$ matrix"
    )
    long = _table_value_text([[f"State block number {i}", 3] for i in range(9)])
    assert long.endswith(", … (9 rows)") and "[" not in long and len(long) <= 100
    assert _table_value_text({"a": 1}) == "a 1"
    assert _table_value_text([1.0, 2.0]) is None and _table_value_text("x") is None


def test_a_range_whose_ends_print_the_same_is_left_out():
    assert _band_text(ev(band=(2.0, 2.0000001))) == ""
    assert _band_html({"band": [2.0, 2.0000001]}, "m") == ""
    r = (reading(USED, 2.0, nominal=True, agrees=True), reading(OTHER, 3.0, band=(3.0, 3.0000001)))
    assert (
        ev(readings=r, band=(2.0, 3.0)).note()
        == "A note. With the scale read as the other reading (10 m): 3 m."
    )


def test_a_reading_whose_band_was_not_run_is_folded_at_the_nominal_inputs_only():
    # the reading used and "a factor 2" agree over bands too wide; with both changed it decides; the
    # phasing's readings ran no band (the verdict was settled) and change nothing at the nominal inputs
    sky, scale = NAME + "sky", NAME + "scale"
    s = claim(published=True, unit="statement", kind="statement", tolerance=EXACT)

    def r(a, b, band, too_wide):
        names = {
            scale: "the other reading" if a else "the reading used",
            sky: "the other reading" if b else "x",
        }
        return reading(names, True, agrees=True, band=band, too_wide=too_wide, nominal=not (a or b))

    sky_used = {sky: "x"}
    rs = (
        {**r(0, 0, (False, True), True), "reading": {scale: "the reading used", **sky_used}},
        r(1, 0, (True, True), False),
        r(0, 1, None, False),
        r(1, 1, None, False),
    )
    e = ev(s, tolerance=EXACT, readings=rs, band=(False, True))
    assert e.inert_conventions() == (sky,)
    assert e.note().endswith(
        "The other reading leaves the result at the nominal inputs unchanged: the phasing read as the other "
        "reading."
    )
    assert _agreeing_reading_text(e) == "agrees under: the other reading"
    # a reading that agrees only over a band too wide is not revived by a folded one that ran none
    rs = (rs[0], {**rs[1], "band": (False, True), "band_too_wide": True}, rs[2], rs[3])
    assert _agreeing_reading_text(ev(s, tolerance=EXACT, readings=rs, band=(False, True))) == ""


def test_a_folded_precision_reading_reads_as_a_sentence():
    strict = {NAME + "scale": "the reading used", PRECISION_READING: PRECISION_STRICT}
    loose = {NAME + "scale": "the reading used", PRECISION_READING: PRECISION_LOOSE}
    other = {NAME + "scale": "the other reading", PRECISION_READING: PRECISION_STRICT}
    both = {NAME + "scale": "the other reading", PRECISION_READING: PRECISION_LOOSE}
    rs = (reading(strict, 2.0, nominal=True), reading(other, 5.0), reading(loose, 2.0), reading(both, 5.0))
    assert ev(readings=rs).note() == (
        "A note. With the scale read as the other reading (10 m): 5 m. The other reading leaves the result "
        "unchanged: the printed number's trailing zeros taken as not significant."
    )


def test_the_band_line_uses_the_notes_digits():
    # printed 11 (two digits): four in the note's sentences and in the band line alike
    value, tol = printed("11")
    e = ev(claim(published=value, tolerance=tol), tolerance=tol, band=(1.86813, 476.476))
    assert _band_text(e) == "1.868 to 476.5 m"
