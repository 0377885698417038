"""``evaluate`` end to end on synthetic claims: its failure paths, the record it keeps (inputs,
band, readings, precision readings, envelope, left-out runs) and the note and JSON it writes
(issue 31, mutation survivors). No paper module is imported; every claim is a closed form.

Oracle in every test: the verdict rule and the record described in :mod:`navcore.claims.verdict`
(module docstring, :class:`~navcore.claims.evaluation.Evaluation`) applied by hand to claims such as
``14 - loss`` with ``loss`` over [1, 3], whose values, bands and verdicts are read off directly.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore._validate import ModelDomainError
from navcore.claims.declarations import resolve_tolerance
from navcore.claims.json_coding import jsonable
from navcore.claims.quotes import claim_quote
from navcore.claims.runs import _coerce
from navcore.claims.tolerances import EXACT, PRECISION_LOOSE, PRECISION_READING, PRECISION_STRICT
from navcore.ledger import Claim, InputSet, Tolerance, evaluate, printed

IN = InputSet("SP", "mutation_evaluate")
IN.published("base", 14.0, unit="dB", locator="Table 1", quantity="base margin")
IN.published("arr", np.array([1.0, 2.0]), locator="Eq. (2)")
IN.assumed("loss", 2.0, low=1.0, high=3.0, unit="dB", reason="typical receivers", quantity="loss")
IN.assumed("wall", 2.0, low=1.0, high=3.0, reason="every admissible value", admissible=True)
IN.assumed("wide", 1.0, low=0.1, high=10.0, reason="a wide range")
IN.convention("scale", 1.0, alternative=10.0, quantity="scale", reason="two readings")
IN.fitted("gain", 1.0, fitted_to=("SP-x",), reason="solved from Table 4")

HALF = Tolerance(reason="test", abs=0.5, policy="printed-digits")
NAME = "SP.mutation_evaluate."


def make(**kw) -> Claim:
    base = dict(
        id="SP-test-mutation-evaluate",
        paper="SP",
        locator="Table 1",
        quantity="margin",
        published=12.0,
        unit="dB",
        compute=lambda: IN.base - IN.loss,
        tolerance=HALF,
        expected_status="consistent",
        note="a synthetic claim",
    )
    base.update(kw)
    return Claim(**base)


# --- failure paths ----------------------------------------------------------------------------


def test_a_tolerance_that_cannot_be_resolved_is_an_error():
    def bad():
        raise RuntimeError("no digits")

    ev = evaluate(make(tolerance=bad))
    assert (ev.status, ev.passes, ev.reproduced) == ("error", False, None)
    assert ev.detail == "tolerance could not be resolved: RuntimeError: no digits"
    ev = evaluate(make(tolerance=lambda: 0.5))
    assert ev.status == "error"
    assert "tolerance must resolve to a Tolerance, got float" in ev.detail
    ev = evaluate(make(tolerance=Tolerance(reason="r", abs=0.5)))  # no policy
    assert ev.status == "error" and "names no policy" in ev.detail
    # a callable tolerance is resolved (where no input can be read)
    assert resolve_tolerance(make(tolerance=lambda: HALF)) is HALF
    ev = evaluate(make(tolerance=lambda: Tolerance(reason="r", abs=IN.base, policy="exact")))
    assert ev.status == "error" and "InputReadError" in ev.detail


def test_nothing_computed():
    ev = evaluate(make(compute=None, expected_status="not-reproducible", note="no input is printed"))
    assert (ev.status, ev.passes, ev.detail) == (
        "not-reproducible",
        True,
        "not reproducible: no input is printed",
    )
    assert ev.tolerance is HALF
    ev = evaluate(make(compute=None, expected_status="reproduced"))
    assert (ev.status, ev.passes) == ("not-reproducible", False)
    assert ev.detail == "nothing is computed: the verdict is not-reproducible"


def test_a_computation_that_raises_or_returns_nan_is_an_error():
    def boom():
        raise KeyError("x")

    ev = evaluate(make(compute=boom))
    assert (ev.status, ev.passes, ev.reproduced, ev.tolerance) == ("error", False, None, HALF)
    assert ev.detail == "compute raised KeyError: 'x'"
    ev = evaluate(make(compute=lambda: float("nan")))
    assert ev.status == "error" and ev.detail == "compute raised ValueError: the computation returned NaN"


def test_a_band_run_that_raises_is_an_error_with_the_inputs_kept():
    def compute():
        if IN.loss != 2.0:
            raise ZeroDivisionError("band")
        return 12.0

    ev = evaluate(make(compute=compute))
    assert (ev.status, ev.passes, ev.reproduced) == ("error", False, 12.0)
    assert ev.detail == "the band or a convention's other reading raised ZeroDivisionError: band"
    assert [i["name"] for i in ev.inputs] == [NAME + "loss"]


def test_coerce():
    s = make(published=True, unit="statement", kind="statement")
    assert _coerce(np.bool_(True), s) is True
    assert _coerce(0, s) is False
    with pytest.raises(TypeError, match="a statement must compute to a truth value"):
        _coerce(object(), s)
    assert _coerce(np.float64(2.5), make()) == 2.5
    assert type(_coerce(3, make())) is float


# --- the record -------------------------------------------------------------------------------


def test_inputs_are_recorded_sorted_with_their_source():
    ev = evaluate(make(compute=lambda: IN.loss * IN.arr[0] + IN.base - 2.0 * IN.loss))
    assert ev.inputs == (
        {"name": NAME + "arr", "provenance": "published", "locator": "Eq. (2)", "value": [1.0, 2.0]},
        {"name": NAME + "base", "provenance": "published", "locator": "Table 1", "value": 14.0},
        {"name": NAME + "loss", "provenance": "assumed", "reason": "typical receivers", "value": 2.0},
    )


def test_band_and_sensitivity_of_one_assumed_input():
    ev = evaluate(make())
    assert (ev.reproduced, ev.band, ev.status, ev.passes) == (12.0, (11.0, 13.0), "consistent", True)
    assert ev.sensitivity == ((NAME + "loss", ((1.0, 13.0), (3.0, 11.0))),)
    assert ev.detail == "derived verdict consistent"
    # no band without an assumed input, and none when bands are off
    ev = evaluate(make(compute=lambda: IN.base - 2.0, expected_status="reproduced"))
    assert (ev.band, ev.sensitivity, ev.status) == (None, (), "reproduced")
    ev = evaluate(make(published=13.0), bands=False)
    assert (ev.band, ev.status) == ((12.0, 12.0), "inconsistent")


def test_admissible_only_when_every_assumed_input_is():
    # 14 - loss - wall over [1, 3] each: at best 12 -> the printed 20 is out of reach
    both = make(published=20.0, compute=lambda: IN.base - IN.loss - IN.wall, expected_status="inconsistent")
    assert evaluate(both).status == "inconsistent"  # loss is plausible only
    only = make(published=20.0, compute=lambda: IN.base - IN.wall, expected_status="inconsistent")
    ev = evaluate(only)
    # every assumed input read spans all admissible values: discrepant (not the expected verdict)
    assert (ev.status, ev.passes) == ("discrepant", False)


def test_expected_status_mismatch_is_reported():
    ev = evaluate(make(expected_status="reproduced"))
    assert (ev.status, ev.passes) == ("consistent", False)
    assert ev.detail == "derived verdict 'consistent' differs from the expected 'reproduced'"


def _discrepant(oracle, compute=lambda: IN.base - 0.0, **kw):
    kw.setdefault("published", 20.0)
    return make(
        compute=compute,
        expected_status="discrepant",
        erratum="SP-E-test",
        oracle=oracle,
        oracle_tolerance=Tolerance(reason="r", abs=0.1, policy="exact"),
        **kw,
    )


def test_discrepant_claims_need_an_agreeing_oracle():
    ev = evaluate(_discrepant(lambda: 14.05))
    assert (ev.status, ev.passes, ev.oracle_value) == ("discrepant", True, 14.05)
    assert ev.detail == "discrepancy confirmed by an independent oracle"
    ev = evaluate(_discrepant(lambda: 14.1000001))
    assert (ev.passes, ev.detail) == (False, "disagrees with its independent oracle (14.1000001)")
    ev = evaluate(_discrepant(lambda: 13.9))  # at the edge below: agrees
    assert ev.passes

    def raises():
        raise ValueError("oracle")

    ev = evaluate(_discrepant(raises))
    assert (ev.passes, ev.detail) == (False, "oracle raised ValueError: oracle")
    # the oracle may read inputs (it runs in a recording of its own): no error
    ev = evaluate(_discrepant(lambda: IN.base))
    assert ev.passes
    # a statement's oracle must give the same truth value
    st = dict(published=True, unit="statement", kind="statement", tolerance=EXACT)
    assert evaluate(_discrepant(lambda: False, compute=lambda: False, **st)).passes
    assert not evaluate(_discrepant(lambda: True, compute=lambda: False, **st)).passes


def test_readings_record_and_note():
    # 10 * scale - 8: 2 under the reading used, 92 under the other; the printed 92 agrees with the other
    c = make(published=92.0, compute=lambda: 10.0 * IN.scale - 8.0, unit="m")
    ev = evaluate(c)
    assert ev.status == "consistent"
    assert ev.readings == (
        {
            "reading": {NAME + "scale": "the reading used"},
            "nominal": True,
            "value": 2.0,
            "band": None,
            "agrees": False,
            "band_too_wide": False,
            "undecided": False,
        },
        {
            "reading": {NAME + "scale": "the other reading"},
            "nominal": False,
            "value": 92.0,
            "band": None,
            "agrees": True,
            "band_too_wide": False,
            "undecided": False,
        },
    )
    assert [r["value"] for r in ev.agreeing_readings] == [92.0]
    assert ev.note() == (
        "a synthetic claim. With the scale read as the other reading (10): 92 m, which agrees with the "
        "printed value. The reading used disagrees and another admissible reading agrees: an open reading "
        "of the text, not a discrepancy."
    )
    js = ev.as_json(errata=[])
    assert js["readings"] == [
        {
            "reading": {NAME + "scale": "the reading used"},
            "nominal": True,
            "value": 2.0,
            "band": None,
            "agrees": False,
            "band_too_wide": False,
        },
        {
            "reading": {NAME + "scale": "the other reading"},
            "nominal": False,
            "value": 92.0,
            "band": None,
            "agrees": True,
            "band_too_wide": False,
        },
    ]


def test_other_readings_get_a_band_only_when_the_verdict_needs_it():
    seen = []

    def compute():
        seen.append((IN.scale, IN.loss))
        return IN.scale * (14.0 - IN.loss)

    # the reading used agrees with a band that decides: the other reading is run at the nominal only
    evaluate(make(compute=compute))
    assert seen == [(1.0, 2.0), (1.0, 1.0), (1.0, 3.0), (10.0, 2.0)]
    seen.clear()
    # the printed 120 agrees only under the other reading: its band is run too
    ev = evaluate(make(published=120.0, compute=compute, unit="m"))
    assert seen == [(1.0, 2.0), (1.0, 1.0), (1.0, 3.0), (10.0, 2.0), (10.0, 1.0), (10.0, 3.0)]
    assert ev.status == "consistent"
    assert [r["band"] for r in ev.readings] == [(11.0, 13.0), (110.0, 130.0)]
    assert ev.note().endswith(
        "With the scale read as the other reading (10): 120 m (over the assumed ranges 110 to 130 m), "
        "which agrees with the printed value. The reading used disagrees and another admissible reading "
        "agrees: an open reading of the text, not a discrepancy."
    )


def test_trailing_zeros_weighed_as_two_readings():
    value, tol = printed("2750")
    # 2753 is outside 2750 +- 0.5 and inside +- 5: consistent under the loose reading
    c = make(published=value, tolerance=tol, compute=lambda: 2753.0, unit="m")
    ev = evaluate(c)
    assert (ev.status, ev.passes) == ("consistent", True)
    assert [r["reading"] for r in ev.readings] == [
        {PRECISION_READING: PRECISION_STRICT},
        {PRECISION_READING: PRECISION_LOOSE},
    ]
    assert [(r["nominal"], r["agrees"]) for r in ev.readings] == [(True, False), (False, True)]
    assert ev.tolerance is tol
    assert "With the printed number's trailing zeros not significant: 2753 m, which agrees" in ev.note()
    # 2750.4 agrees strictly: reproduced, and the loose reading is not run
    ev = evaluate(make(published=value, tolerance=tol, compute=lambda: 2750.4, expected_status="reproduced"))
    assert (ev.status, ev.readings) == ("reproduced", ())
    # 2760: disagrees under both: the loose verdict (discrepant), both readings shown
    ev = evaluate(
        make(published=value, tolerance=tol, compute=lambda: 2760.0, expected_status="inconsistent")
    )
    assert ev.status == "discrepant" and len(ev.readings) == 2
    assert not any(r["agrees"] for r in ev.readings)


def test_a_band_too_wide_to_decide_and_its_note():
    # 10 * wide over [0.1, 10]: band [1, 100], printed 10 agrees only in part
    c = make(published=10.0, compute=lambda: 10.0 * IN.wide, unit="m", expected_status="not-reproducible")
    ev = evaluate(c)
    assert (ev.status, ev.passes, ev.band_too_wide, ev.envelope) == ("not-reproducible", True, True, None)
    assert ev.band == (1.0, 100.0)
    assert ev.note() == (
        "a synthetic claim. Over the assumed inputs' ranges the value spans 1 to 100 m, ends more than a "
        "factor 3 apart, and the printed value agrees with only part of it: the assumptions are too loose "
        "to decide."
    )
    s = make(
        published=True,
        unit="statement",
        kind="statement",
        compute=lambda: IN.wide > 1.0,
        expected_status="not-reproducible",
    )
    ev = evaluate(s)
    assert ev.band_too_wide
    assert ev.note().endswith(
        "It holds for some of the assumed inputs and fails for others: "
        "the assumptions are too loose to decide."
    )


def test_left_out_runs_are_counted_and_noted():
    def compute():
        if IN.loss == 1.0:
            raise ModelDomainError("no fix", case="no four satellites stay above the mask")
        return IN.base - IN.loss

    ev = evaluate(make(compute=compute))
    assert ev.left_out == ({"case": "no four satellites stay above the mask", "runs": 1},)
    assert ev.band == (11.0, 12.0)
    assert ev.note().endswith(
        "The band leaves out, as outside the model's domain, "
        "1 run where no four satellites stay above the mask."
    )


# --- the Evaluation's properties and JSON ------------------------------------------------------------


def test_deviation_kind_printed_and_json():
    ev = evaluate(make(compute=lambda: IN.base - 1.75, expected_status="reproduced"))
    assert ev.deviation == 0.25 and ev.kind == "reproduction"
    value, tol = printed("12.0")
    ev = evaluate(make(published=value, tolerance=tol, compute=lambda: 12.02, expected_status="reproduced"))
    assert ev.printed == "12.0"
    js = ev.as_json(errata=[])
    assert js == {
        "id": "SP-test-mutation-evaluate",
        "paper": "SP",
        "locator": "Table 1",
        "quantity": "margin",
        "published": 12.0,
        "relation": "=",
        "unit": "dB",
        "printed": "12.0",
        "errata": [],
        "kind": "reproduction",
        "inputs": [],
        "reproduced": 12.02,
        "band": None,
        "readings": [],
        "tolerance": tol.as_dict(),
        "status": "reproduced",
        "note": "a synthetic claim",
    }
    s = evaluate(
        make(
            published=True,
            unit="statement",
            kind="statement",
            compute=lambda: True,
            tolerance=EXACT,
            expected_status="reproduced",
        )
    )
    assert s.deviation is None
    assert s.as_json(errata=[])["published"] is True
    assert s.as_json(errata=[])["printed"] is None  # EXACT quotes nothing
    assert evaluate(make(compute=None, expected_status="not-reproducible")).deviation is None
    # the JSON of a band and of an assumed input
    js = evaluate(make()).as_json(errata=[])
    assert js["band"] == [11.0, 13.0] and js["reproduced"] == 12.0


def test_claim_quote_sources():
    value, tol = printed("17.67")
    c = make(published=value, tolerance=tol)
    assert claim_quote(c) == ("17.67", "digits")
    from navcore.claims.tolerances import prose

    assert claim_quote(make(tolerance=prose("about"))) == ("about", "word")
    assert claim_quote(make(tolerance=HALF)) == ("", "none")
    assert claim_quote(make(tolerance=lambda: 1 / 0)) == ("", "none")
    assert claim_quote(make(printed="  margin 12 dB ")) == ("margin 12 dB", "claim")


def test_jsonable():
    assert jsonable(None) is None and jsonable(True) is True and jsonable("a") == "a"
    assert jsonable(3) == 3 and type(jsonable(3)) is int
    assert jsonable(float("inf")) == "Infinity" and jsonable(float("-inf")) == "-Infinity"
    assert jsonable(float("nan")) is None
    assert jsonable({1: (1.5, np.float64(2.0))}) == {"1": [1.5, 2.0]}
    assert jsonable(np.array([[1, 2]])) == [[1, 2]]
    assert jsonable(np.float32(0.5)) == 0.5
    assert jsonable(object).startswith("<class")


def test_every_evaluation_keeps_its_claim_value_and_tolerance():
    def boom():
        raise KeyError("x")

    c = make(compute=boom)
    ev = evaluate(c)
    assert ev.claim is c and ev.tolerance is HALF
    bad_tol = make(tolerance=lambda: 1 / 0)
    assert evaluate(bad_tol).claim is bad_tol

    def band_fails():
        if IN.loss != 2.0:
            raise ZeroDivisionError("band")
        return 12.0

    c = make(compute=band_fails)
    ev = evaluate(c)
    assert ev.claim is c and ev.tolerance is HALF

    def raises():
        raise ValueError("oracle")

    c = _discrepant(raises)
    ev = evaluate(c)
    assert (ev.claim, ev.reproduced, ev.status, ev.tolerance) == (c, 14.0, "discrepant", HALF)
    c = _discrepant(lambda: 14.05)
    ev = evaluate(c)
    assert (ev.claim, ev.reproduced) == (c, 14.0)


def test_oracle_tolerance_edge_is_inclusive():
    # |14 - 14.5| = 0.5 = the oracle tolerance: agrees
    c = make(
        published=20.0,
        compute=lambda: IN.base,
        expected_status="discrepant",
        erratum="SP-E-test",
        oracle=lambda: 14.5,
        oracle_tolerance=Tolerance(reason="r", abs=0.5, policy="exact"),
    )
    assert evaluate(c).passes


def test_trailing_zeros_with_an_admissible_input_stay_discrepant():
    value, tol = printed("2750")
    # 2700 + wall over [1, 3]: at most 2703, outside 2750 +- 5 too; every assumed input admissible
    c = make(published=value, tolerance=tol, compute=lambda: 2700.0 + IN.wall, expected_status="inconsistent")
    ev = evaluate(c)
    assert ev.status == "discrepant" and len(ev.readings) == 2  # strict and loose, no convention


def test_runs_left_out_under_another_reading_are_counted():
    def compute():
        if IN.scale == 10.0 and IN.loss == 1.0:
            raise ModelDomainError("no fix", case="no fix under the other scale")
        return IN.scale * (14.0 - IN.loss)

    # 120 agrees only under the other reading, whose band is run: one of its runs is left out
    ev = evaluate(make(published=120.0, compute=compute, unit="m"))
    assert ev.left_out == ({"case": "no fix under the other scale", "runs": 1},)
