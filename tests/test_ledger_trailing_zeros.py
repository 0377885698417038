"""The trailing zeros of a whole number printed without a decimal point, on synthetic claims.

Oracle: the rule of the ledger's module docstring ("Trailing zeros") written out by hand for
each case: "2750" is 2750 ± 0.5 if every digit is significant and 2750 ± 5 if its trailing
zero is not; agreement under the strict tolerance keeps the verdict, agreement only under the
loose one gives ``consistent`` and names the reading, agreement under neither gives the verdict
of the loose tolerance. The claims' values are constants or simple closed forms of their
inputs, so which tolerance accepts them is read off by eye.
"""

from __future__ import annotations

import json

import pytest

from navcore.claims.declarations import Erratum
from navcore.claims.tolerances import PRECISION_LOOSE, PRECISION_READING, PRECISION_STRICT
from navcore.claims.verdict import precision_status
from navcore.ledger import Claim, InputSet, Tolerance, evaluate, printed

IN = InputSet("SP", "synthetic_trailing_zeros")
IN.assumed("offset", 0.0, low=-1.0, high=1.0, reason="test range", unit="m")
IN.convention("sign", 1.0, alternative=-1.0, quantity="sign of the term", reason="the sign is not printed")

ERRATUM = Erratum(
    id="SP-E-synthetic-trailing-zeros",
    paper="SP",
    locator="Eq. (1)",
    printed="2750",
    finding="2760",
    evidence="a synthetic erratum",
    kind="inconsistent-numbers",
    basis="computed",
    claims=("SP-test-trailing-zeros",),
)


def make(text: str = "2750", **kw):
    value, tol = printed(text)
    base = dict(
        id="SP-test-trailing-zeros",
        paper="SP",
        locator="Eq. (1)",
        quantity="q",
        published=value,
        unit="m",
        compute=lambda: value,
        tolerance=tol,
        expected_status="reproduced",
        note="a synthetic claim",
    )
    base.update(kw)
    return Claim(**base)


def precision_labels(ev):
    return [(r["reading"].get(PRECISION_READING), r["agrees"]) for r in ev.readings]


# --- the printed digits ---------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "strict", "loose"),
    [
        ("2750", 0.5, 5.0),
        ("3300", 0.5, 50.0),
        ("20", 0.5, 5.0),
        ("100", 0.5, 50.0),
        ("−60", 0.5, 5.0),
        ("2751", 0.5, None),
        ("0", 0.5, None),
        ("20.0", 0.05, None),
        ("20.", 0.5, None),  # a decimal point says the zero is significant
        ("150e1", 5.0, None),  # an exponent states the significant digits
        ("17.60", 0.005, None),
    ],
)
def test_printed_gives_both_readings_of_trailing_zeros(text, strict, loose):
    tol = printed(text)[1]
    assert tol.abs == pytest.approx(strict) and tol.policy == "printed-digits"
    assert tol.loose_abs == (None if loose is None else pytest.approx(loose))
    if loose is not None:
        assert "trailing zero" in tol.reason and tol.loose().abs == pytest.approx(loose)
        assert "if trailing zeros are not significant" in tol.describe()
    else:
        assert tol.loose() is None


def test_extra_abs_widens_both_readings():
    tol = printed("3300", extra_abs=2.0, why="the paper rounds an intermediate value")[1]
    assert (tol.abs, tol.loose_abs) == (2.5, 52.0)


def test_a_loose_tolerance_below_the_strict_one_is_refused():
    with pytest.raises(ValueError, match="loose_abs must be >= abs"):
        Tolerance(reason="r", abs=1.0, loose_abs=0.5, policy="printed-digits")
    with pytest.raises(ValueError, match="loose_abs must be finite"):
        Tolerance(reason="r", abs=1.0, loose_abs=-1.0, policy="printed-digits")


def test_precision_status_by_hand():
    assert [precision_status(s) for s in ("reproduced", "consistent", "inconsistent", "discrepant")] == [
        "consistent",
        "consistent",
        "inconsistent",
        "discrepant",
    ]
    assert precision_status("not-reproducible") == "not-reproducible"


# --- the verdict weighs them ----------------------------------------------------------------


def test_strict_agreement_keeps_the_verdict_and_runs_no_loose_reading():
    ev = evaluate(make(compute=lambda: 2750.3))
    assert ev.status == "reproduced" and ev.passes and ev.readings == ()


def test_only_the_loose_reading_agrees_consistent_and_named():
    ev = evaluate(make(compute=lambda: 2751.66, expected_status="consistent"))
    assert ev.status == "consistent" and ev.passes
    assert precision_labels(ev) == [(PRECISION_STRICT, False), (PRECISION_LOOSE, True)]
    assert ev.readings[0]["nominal"] and not ev.readings[1]["nominal"]
    note = ev.note()
    assert "With the printed number's trailing zeros not significant: 2751.66 m" in note
    assert "another admissible reading agrees: an open reading" in note
    out = json.loads(json.dumps(ev.as_json()))
    assert out["tolerance"]["loose_abs"] == 5.0 and out["tolerance"]["abs"] == 0.5
    assert out["readings"][1]["reading"] == {PRECISION_READING: PRECISION_LOOSE}


def test_neither_agrees_the_loose_verdict_with_both_readings_shown():
    ev = evaluate(
        make(
            compute=lambda: 2760.0,
            expected_status="discrepant",
            erratum=ERRATUM.id,
            oracle=lambda: 2760.0,
            oracle_tolerance=printed("2760.0")[1],
        )
    )
    assert ev.status == "discrepant" and ev.passes
    assert precision_labels(ev) == [(PRECISION_STRICT, False), (PRECISION_LOOSE, False)]


def test_a_band_that_agrees_only_under_the_loose_reading_is_consistent():
    c = make("20", compute=lambda: 18.0 + IN.offset, expected_status="consistent")
    ev = evaluate(c)  # band [17, 19]: outside 20 +- 0.5, inside 20 +- 5
    assert ev.band == (17.0, 19.0) and ev.status == "consistent"
    c = make("20", compute=lambda: 10.0 + IN.offset, expected_status="inconsistent")
    assert evaluate(c).status == "inconsistent"  # [9, 11]: outside 20 +- 5 too


def test_a_band_too_wide_under_the_loose_reading_is_not_reproducible():
    # band [20, 90]: 100 +- 0.5 is not reached; 100 +- 50 accepts part of it, ends a factor 4.5 apart
    c = make("100", compute=lambda: 55.0 + 35.0 * IN.offset, expected_status="not-reproducible")
    ev = evaluate(c)
    assert ev.status == "not-reproducible" and ev.band == (20.0, 90.0)


def test_loose_readings_follow_the_conventions_too():
    ev = evaluate(make(compute=lambda: -2753.0 * IN.sign, expected_status="consistent"))
    # -2753 under the sign used; 2753 under the other: only the other sign with the loose precision agrees
    agreeing = [r["reading"] for r in ev.agreeing_readings]
    assert agreeing == [
        {"SP.synthetic_trailing_zeros.sign": "the other reading", PRECISION_READING: PRECISION_LOOSE}
    ]
    assert len(ev.readings) == 4


def test_cross_check_weighs_the_precision_too():
    assert evaluate(make(compute=lambda: 2752.0, kind="cross-check", expected_status="consistent")).passes
    ev = evaluate(
        make(
            compute=lambda: 2790.0,
            kind="cross-check",
            expected_status="discrepant",
            erratum=ERRATUM.id,
            oracle=lambda: 2790.0,
            oracle_tolerance=printed("1")[1],
        )
    )
    assert ev.status == "discrepant"
