"""Issue 27's mechanisms on synthetic claims, independent of the registry.

Oracle: the rules of LEDGER.md written out by hand for each case (which readings agree,
which band decides, which policy a quote admits, which number a quote prints), on claims
whose values are simple closed forms of their inputs.

* readings of a convention are weighed: discrepant only when every admissible reading
  disagrees; consistent, naming the reading, when only another one agrees;
* a claim that reads both a convention and assumed inputs runs the other readings across the
  band only when the verdict needs it;
* a band too wide to decide (ends more than a factor 3 apart, partly agreeing) makes the
  claim not-reproducible;
* an erratum's basis is required and flows into the JSON of the claims it rests on;
* the quoted printed text fixes which tolerance policies are admissible, and a number claim's
  quote must print its published number.
"""

from __future__ import annotations

import dataclasses
import math

import pytest

from navcore.claims.declarations import TEXT_ONLY_CAVEAT, Erratum, claim_errata
from navcore.claims.quotes import claim_quote, quote_has_number, quote_numbers, quote_policies
from navcore.claims.runs import MAX_READING_COMBINATIONS, reading_combinations
from navcore.claims.verdict import BAND_FACTOR, band_spread, band_too_wide, derive_status
from navcore.ledger import Claim, InputSet, Tolerance, evaluate, printed, prose
from navcore.ledger.registry import validate_registry

TOL = Tolerance(reason="test", abs=0.5, policy="printed-digits")

IN = InputSet("KZL", "synthetic_readings")
IN.published("gain", 2.0, locator="Eq. (99)")
IN.convention(
    "per_cycle",
    1.0,
    quantity="range per cycle",
    readings={"one foot per cycle": 1.0, "the L1 wavelength": 0.62, "the 300 m code": 300.0},
    reason="the text says one thing, the numbers another",
)
IN.convention("sign", 1.0, alternative=-1.0, quantity="sign of the term", reason="the sign is not printed")
IN.assumed("offset", 0.0, low=-1.0, high=1.0, reason="test range", unit="m")
IN.assumed("scale", 1.0, low=0.5, high=1.5, reason="test range")
IN.assumed("wall", 0.0, low=-1.0, high=1.0, reason="every admissible value", admissible=True)
IN.fitted("fit_gain", 1.0, fitted_to=["KZL-test-elsewhere"], reason="solved from another printed value")

PER_CYCLE = "KZL.synthetic_readings.per_cycle"
SIGN = "KZL.synthetic_readings.sign"


def make(**kw):
    base = dict(
        id="KZL-test-readings",
        paper="KZL",
        locator="Eq. (1)",
        quantity="q",
        published=10.0,
        unit="m",
        compute=lambda: 5.0 * IN.gain,
        tolerance=TOL,
        expected_status="reproduced",
        note="n",
    )
    base.update(kw)
    return Claim(**base)


def labels(ev, name=PER_CYCLE):
    return [r["reading"][name] for r in ev.agreeing_readings]


# --- readings are weighed ---------------------------------------------------------------------


def test_the_reading_used_agrees_reproduced_and_the_others_are_shown():
    ev = evaluate(make(compute=lambda: 10.0 * IN.per_cycle))
    assert ev.status == "reproduced"
    assert [(r["reading"][PER_CYCLE], r["value"], r["agrees"]) for r in ev.readings] == [
        ("one foot per cycle", 10.0, True),
        ("the L1 wavelength", 6.2, False),
        ("the 300 m code", 3000.0, False),
    ]
    note = ev.note()
    assert "With the range per cycle read as the L1 wavelength (0.62): 6.2 m." in note
    # a label that prints its value is not followed by it again
    assert "With the range per cycle read as the 300 m code: 3000 m." in note


def test_a_reading_that_sets_several_numbers_lists_them_once_as_numbers():
    """A convention whose readings are tuples (a schedule, a pair of values) is named in a note
    with its numbers as a reader writes them: one pair of parentheses, no Python float zeros.
    Oracle: the note text written out by hand."""
    S = InputSet("KZL", "synthetic_tuple_readings")
    S.convention(
        "pair",
        (1.0, 2.0),
        quantity="pair of gains",
        readings={"the printed pair": (1.0, 2.0), "the swapped pair": (2.0, 1.0)},
        reason="the table's columns are not labelled",
    )
    ev = evaluate(make(id="KZL-test-tuple", compute=lambda: 10.0 * S.pair[0]))
    note = ev.note()
    assert "With the pair of gains read as the swapped pair (2, 1): 20 m." in note
    assert "((" not in note and "2.0" not in note
    from navcore.ledger.text import _inputs_text

    inputs = _inputs_text(ev)
    assert "pair of gains = (1, 2) (convention)" in inputs and "1.0" not in inputs


def test_a_reading_whose_label_prints_its_value_shows_it_once():
    """A convention's reading label that says its value (in another SI prefix, or as a
    percentage) is not followed by the value again: "read as the C/A code, 1.023 Mchip/s",
    not "... 1.023 Mchip/s (1.023×10⁶ Hz)"; a label without its value keeps it.
    Oracle: the note text written out by hand."""
    C = InputSet("SP", "synthetic_chip_readings")
    C.convention(
        "chip_rate_hz",
        10.23e6,
        unit="Hz",
        quantity="chip rate",
        readings={"the P(Y) code, 10.23 Mchip/s": 10.23e6, "the C/A code, 1.023 Mchip/s": 1.023e6},
        reason="the code is not named",
    )
    C.convention(
        "slack", 0.1, readings={"within 10 %": 0.1, "within 1 %": 0.01}, quantity="slack", reason="r"
    )
    C.convention(
        "gain", 1.0, readings={"the printed gain": 1.0, "the doubled gain": 2.0}, quantity="gain", reason="r"
    )
    ev = evaluate(make(id="SP-test-chip", paper="SP", compute=lambda: C.chip_rate_hz / 1.023e6 * C.gain))
    note = ev.note()
    assert "the chip rate read as the C/A code, 1.023 Mchip/s:" in note and "×10⁶ Hz" not in note
    assert "the gain read as the doubled gain (2)" in note
    ev = evaluate(make(id="SP-test-slack", paper="SP", compute=lambda: 100.0 * C.slack))
    assert "the slack read as within 1 %:" in ev.note()


def test_only_another_reading_agrees_consistent_and_named():
    ev = evaluate(make(compute=lambda: 16.13 * IN.per_cycle, expected_status="consistent"))
    # 16.13 under the reading used, 10.0006 under the L1 wavelength, 4839 under the code
    assert ev.status == "consistent" and ev.passes
    assert labels(ev) == ["the L1 wavelength"]
    assert "another admissible reading agrees: an open reading" in ev.note()
    assert "which agrees with the printed value" in ev.note()


def test_every_reading_disagrees_discrepant():
    ev = evaluate(make(compute=lambda: 20.0 * IN.per_cycle))
    assert ev.status == "discrepant" and ev.agreeing_readings == ()


def test_readings_weigh_statements_too():
    c = make(published=True, unit="statement", compute=lambda: IN.sign > 0, expected_status="reproduced")
    assert evaluate(c).status == "reproduced"
    c = make(published=True, unit="statement", compute=lambda: IN.sign < 0, expected_status="consistent")
    ev = evaluate(c)
    assert ev.status == "consistent" and labels(ev, SIGN) == ["the other reading"]


def test_a_statement_reading_that_agrees_over_part_of_its_band_says_so():
    c = make(
        published=True,
        unit="statement",
        compute=lambda: (IN.sign < 0) & (IN.offset > 0.5),  # reads both inputs
        expected_status="not-reproducible",
    )
    # false throughout under the sign used; under the other, true for offsets above 0.5 and false
    # below: a band that holds both truth values decides nothing (LEDGER.md, a band too wide)
    ev = evaluate(c)
    assert ev.status == "not-reproducible"
    assert "does not hold at the nominal inputs, but holds over part of the assumed ranges" in ev.note()
    assert "holds for some of the assumed inputs and fails for others" in ev.note()
    # true throughout under the other sign: that reading decides, and agrees
    c = make(
        published=True,
        unit="statement",
        compute=lambda: (IN.sign < 0) | (IN.offset > 0.5),
        expected_status="consistent",
    )
    assert evaluate(c).status == "consistent"


def test_cross_check_fit_and_fitted_use_any_reading():
    assert evaluate(make(compute=lambda: 16.13 * IN.per_cycle, kind="cross-check")).status == "consistent"
    assert evaluate(make(compute=lambda: 20.0 * IN.per_cycle, kind="cross-check")).status == "discrepant"
    assert evaluate(make(compute=lambda: 16.13 * IN.per_cycle, kind="fit")).status == "consistent"


def test_a_fitted_input_read_with_assumed_ones_still_needs_a_band_that_decides():
    """A fit makes agreement at best consistent; its band over assumed inputs is still subject to
    the too-wide rule (LEDGER.md): 10 * scale spans 5-15 (a factor 3: decides), 10 * scale**3
    spans 1.25-33.75 (a factor 27, part agreeing: decides nothing). Oracle: the spans by hand."""
    decides = make(compute=lambda: 10.0 * IN.fit_gain * IN.scale, expected_status="consistent")
    assert evaluate(decides).status == "consistent"
    wide = make(compute=lambda: 10.0 * IN.fit_gain * IN.scale**3, expected_status="not-reproducible")
    ev = evaluate(wide)
    assert ev.band == pytest.approx((1.25, 33.75))
    assert ev.status == "not-reproducible" and ev.passes
    beyond = make(compute=lambda: 30.0 * IN.fit_gain * IN.scale, expected_status="inconsistent")
    assert evaluate(beyond).status == "inconsistent"  # 15-45 misses 10 +- 0.5


def test_every_combination_of_two_conventions_is_run_nominal_first():
    calls = []

    def compute():
        calls.append((IN.per_cycle, IN.sign))
        return 10.0 * IN.per_cycle * IN.sign

    ev = evaluate(make(compute=compute))
    assert len(ev.readings) == 3 * 2 and ev.readings[0]["nominal"]
    assert sorted(set(calls)) == sorted({(p, s) for p in (1.0, 0.62, 300.0) for s in (1.0, -1.0)})
    assert ev.readings[0]["reading"] == {PER_CYCLE: "one foot per cycle", SIGN: "the reading used"}


def test_combinations_beyond_the_cap_are_run_one_convention_at_a_time():
    from navcore.claims.inputs import Input

    conventions = [
        Input(name=f"KZL.doc.c{i}", paper="KZL", value=0, provenance="convention", alternative=1, reason="r")
        for i in range(5)
    ]
    assert 2**5 > MAX_READING_COMBINATIONS
    combos = reading_combinations(conventions)
    assert len(combos) == 1 + 5
    assert all(sum(v != 0 for _, _, v in combo) == (0 if i == 0 else 1) for i, combo in enumerate(combos))
    assert len(reading_combinations(conventions[:4])) == 16  # within the cap: all of them


def test_single_alternative_and_labelled_readings_are_checked():
    S = InputSet("KZL", "synthetic_readings_checks")
    S.convention("a", 1.0, alternative=2.0, reason="r")
    assert S.input("a").readings == (("the reading used", 1.0), ("the other reading", 2.0))
    assert S.input("a").alternative == 2.0
    S.convention("b", 1.0, readings={"x": 1.0, "y": 2.0, "z": 3.0}, reason="r")
    assert S.input("b").nominal_label == "x" and S.input("b").alternative == 2.0
    with pytest.raises(ValueError, match="must be one of its"):
        S.convention("c", 5.0, readings={"x": 1.0, "y": 2.0}, reason="r")
    with pytest.raises(ValueError, match="at least two readings"):
        S.convention("d", 1.0, readings={"x": 1.0}, reason="r")
    with pytest.raises(ValueError, match="not both or neither"):
        S.convention("e", 1.0, readings={"x": 1.0, "y": 2.0}, alternative=2.0, reason="r")
    with pytest.raises(ValueError, match="not both or neither"):
        S.convention("f", 1.0, reason="r")
    with pytest.raises(ValueError, match="two readings have the value"):
        S.convention("g", 1.0, readings={"x": 1.0, "y": 1.0}, reason="r")
    with pytest.raises(ValueError, match="needs a label"):
        S.convention("h", 1.0, readings={"x": 1.0, " ": 2.0}, reason="r")


# --- conventions together with assumed inputs -------------------------------------------------


def test_mixed_other_reading_run_across_the_band_when_the_verdict_needs_it():
    calls = []

    def compute():
        calls.append(IN.per_cycle)
        return 16.13 * IN.per_cycle + IN.offset

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    # the reading used spans [15.13, 17.13]: no agreement; the L1 wavelength spans [9.0, 11.0]
    assert ev.status == "consistent" and labels(ev) == ["the L1 wavelength"]
    assert ev.band == pytest.approx((15.13, 17.13))
    l1 = next(r for r in ev.readings if r["reading"][PER_CYCLE] == "the L1 wavelength")
    assert l1["band"] == pytest.approx((9.0006, 11.0006))
    assert calls.count(0.62) == 1 + len(IN.input("offset").band_points)


def test_mixed_reading_used_decides_and_the_others_are_not_run_across_the_band():
    calls = []

    def compute():
        calls.append(IN.per_cycle)
        return 10.0 * IN.per_cycle + IN.offset

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert ev.status == "consistent"
    assert all(r["band"] is None for r in ev.readings if not r["nominal"])
    assert calls.count(0.62) == 1 and calls.count(300.0) == 1  # their values only, for the note


def test_mixed_every_reading_disagrees_over_its_band():
    ev = evaluate(make(compute=lambda: 30.0 * IN.per_cycle + IN.offset, expected_status="inconsistent"))
    assert ev.status == "inconsistent" and ev.passes
    ev = evaluate(
        make(
            compute=lambda: 30.0 * IN.per_cycle + IN.wall,
            expected_status="discrepant",
            erratum="KZL-E-none",
            oracle=lambda: 30.0,
            oracle_tolerance=TOL,
        )
    )
    assert ev.status == "discrepant"


# --- a band too wide to decide ----------------------------------------------------------------


def test_band_spread_by_sign_and_unit():
    assert band_spread(2.0, 8.0) == 4.0 and band_spread(-8.0, -2.0) == 4.0
    assert math.isinf(band_spread(-1.0, 1.0)) and math.isinf(band_spread(0.0, 1.0))
    assert band_spread(0.0, 0.0) == 1.0
    assert band_spread(10.0, 10.0 + 10 * math.log10(3), "dB") == pytest.approx(3.0)  # a power ratio
    assert band_spread(10.0, 20.0, "dBW") == pytest.approx(10.0)


def test_too_wide_band_that_partly_agrees_is_not_reproducible():
    # 10 * scale over [0.5, 1.5] with offset: the band runs from about 4 to 16 (a factor 4)
    c = make(
        compute=lambda: 10.0 * IN.scale * (1.0 + 0.1 * IN.offset) ** 2, expected_status="not-reproducible"
    )
    ev = evaluate(c)
    lo, hi = ev.band
    assert hi / lo > BAND_FACTOR
    assert ev.status == "not-reproducible" and ev.passes and ev.band_too_wide
    assert ev.reproduced == 10.0  # the value and the band are shown
    assert "too loose to decide" in ev.note()


def test_band_under_the_factor_or_wholly_accepted_still_decides():
    narrow = make(compute=lambda: 10.0 + IN.offset, expected_status="consistent")  # [9, 11]
    assert evaluate(narrow).status == "consistent"
    wide_tol = Tolerance(reason="test", abs=100.0, policy="printed-digits")  # accepts all of [4, 16]
    accepted = make(
        compute=lambda: 10.0 * IN.scale * (1.0 + 0.1 * IN.offset) ** 2,
        tolerance=wide_tol,
        expected_status="consistent",
    )
    assert evaluate(accepted).status == "consistent"


def test_too_wide_band_that_disagrees_everywhere_stays_inconsistent():
    c = make(compute=lambda: 100.0 * IN.scale * (1.0 + 0.1 * IN.offset) ** 2, expected_status="inconsistent")
    assert evaluate(c).status == "inconsistent"


def test_a_bound_straddled_by_a_wide_band_is_too_wide_one_wholly_on_its_side_decides():
    straddles = make(
        relation="<=",
        compute=lambda: 10.0 * IN.scale * (1.0 + 0.1 * IN.offset) ** 2,
        expected_status="not-reproducible",
    )
    assert evaluate(straddles).status == "not-reproducible"
    below = make(
        relation="<=",
        published=20.0,
        compute=lambda: 10.0 * IN.scale * (1.0 + 0.1 * IN.offset) ** 2,
        expected_status="consistent",
    )
    assert evaluate(below).status == "consistent"


def test_band_too_wide_rule_on_signed_and_decibel_bands():
    value, tol = printed("0.0")  # +- 0.05
    signed = make(published=value, tolerance=tol, unit="")
    assert band_too_wide(signed, tol, -0.5, 0.5)  # crosses zero, only partly accepted
    assert not band_too_wide(signed, tol, -0.01, 0.04)  # wholly accepted
    value, tol = printed("15")
    db = make(published=value, tolerance=tol, unit="dB")
    assert band_too_wide(db, tol, 12.4, 19.9)  # 7.5 dB: a power ratio of 5.6
    assert not band_too_wide(db, tol, 13.0, 17.0)  # 4 dB: 2.5
    # a statement's band is its truth values: both in it decide nothing, one alone decides
    assert band_too_wide(make(published=True, unit="statement"), tol, False, True)
    assert not band_too_wide(make(published=True, unit="statement"), tol, True, True)


def test_derive_status_weighs_wide_and_narrow_readings():
    value, tol = printed("10")
    c = make(published=value, tolerance=tol)
    # the reading used agrees only over a too-wide band, another reading over a narrow one
    assert (
        derive_status(c, tol, 3.0, [30.0], {"assumed", "convention"}, False, [(10.2, [9.8])]) == "consistent"
    )
    assert derive_status(c, tol, 3.0, [30.0], {"assumed", "convention"}, False, [(50.0, [60.0])]) == (
        "not-reproducible"
    )


# --- the basis of an erratum and the claims it rests on ---------------------------------------


def erratum(**kw):
    base = dict(
        id="KZL-E-doc",
        paper="KZL",
        locator="Eq. (1)",
        printed="p",
        finding="f",
        evidence="e",
        kind="typography",
        basis="text-only",
    )
    base.update(kw)
    return Erratum(**base)


def test_basis_is_required_and_from_its_table():
    with pytest.raises(ValueError, match=r"Erratum\.basis must be one of"):
        erratum(basis="")
    with pytest.raises(ValueError, match=r"Erratum\.basis must be one of"):
        erratum(basis="transcription")
    assert erratum(basis="computed").basis == "computed"
    assert "transcription" in TEXT_ONLY_CAVEAT


def test_claim_json_names_its_errata_with_their_basis():
    reproduced = make(id="KZL-test-errata")
    named_by = erratum(id="KZL-E-doc-text", claims=("KZL-test-errata",))
    names = erratum(id="KZL-E-doc-computed", basis="computed")
    other = erratum(id="KZL-E-doc-other", claims=("KZL-test-elsewhere",))
    pool = [named_by, names, other]
    assert claim_errata(reproduced, pool) == [{"id": "KZL-E-doc-text", "basis": "text-only"}]
    c = dataclasses.replace(reproduced, erratum="KZL-E-doc-computed")
    assert claim_errata(c, pool) == [
        {"id": "KZL-E-doc-computed", "basis": "computed"},
        {"id": "KZL-E-doc-text", "basis": "text-only"},
    ]
    # an alias of the claim counts too, and the JSON carries the field
    aliased = erratum(id="KZL-E-doc-alias", claims=("KZL-test-old-id",))
    c = dataclasses.replace(reproduced, aliases=("KZL-test-old-id",))
    assert [e["id"] for e in claim_errata(c, [aliased])] == ["KZL-E-doc-alias"]
    ev = evaluate(reproduced)
    assert ev.status == "reproduced"
    assert ev.as_json(errata=pool)["errata"] == [{"id": "KZL-E-doc-text", "basis": "text-only"}]


# --- what the paper printed -------------------------------------------------------------------


def test_the_quote_flows_from_the_tolerance_and_a_claim_may_give_a_longer_one():
    value, tol = printed("17.67")
    c = make(published=value, tolerance=tol)
    assert claim_quote(c) == ("17.67", "digits") and evaluate(c).as_json()["printed"] == "17.67"
    c = make(tolerance=prose("about"))
    assert claim_quote(c) == ("about", "word")
    c = make(tolerance=prose("about"), printed="about 10 m")
    assert claim_quote(c) == ("about 10 m", "claim") and evaluate(c).printed == "about 10 m"
    assert claim_quote(make()) == ("", "none") and evaluate(make()).as_json()["printed"] is None


@pytest.mark.parametrize(
    ("quote", "published", "locator", "policies"),
    [
        ("approximately 1.4", 1.4, "Sec. 3.8", ("prose",)),
        ("Exp ≈ 9", 9.0, "Sec. 3.8", ("prose",)),
        ("~ 50 %", 50.0, "Sec. 2", ("prose",)),
        ("of the order of 1 m", 1.0, "Sec. 1", ("prose",)),
        ("roughly 3", 3.0, "Sec. 1", ("prose",)),
        ("nearly 20 deg", 20.0, "Sec. 1", ("prose",)),
        ("43 dBW (values read from the figures)", 43.0, "Table 2.1", ("figure-reading",)),
        ("17.67", 17.67, "Sec. 2.5", ("printed-digits", "monte-carlo")),
        ("15 states", 15.0, "Table 2.1", ("printed-digits", "monte-carlo", "exact")),
        ("0.3 m", 0.3, "Fig. 5", ("printed-digits", "monte-carlo", "figure-reading")),
        ("nearly uncorrelated", True, "Sec. 2.2", ("exact",)),
    ],
)
def test_the_policy_follows_the_printed_words(quote, published, locator, policies):
    assert quote_policies(quote, published=published, locator=locator) == policies


def test_numbers_a_quote_prints():
    assert quote_has_number("3,300 m", 3300.0) and quote_has_number("1.5 × 10^-3", 0.0015)
    assert quote_has_number("−4 dB", -4.0) and quote_has_number("50 %", 0.5)
    assert quote_has_number("1/e", 1.0) and not quote_has_number("1/e", math.exp(-1))
    assert not quote_has_number("this equation holds", 0.0)
    assert 10.0 not in quote_numbers("1.5 × 10^-3")  # the base of a power is not printed alone


def test_published_means_printed_registry_check(monkeypatch):
    ok = make(id="KZL-test-printed", tolerance=TOL, printed="the error is 10 m")
    validate_registry([ok], [])
    encoded = make(id="KZL-test-encoded", published=0.0, relation="<=", printed="Eq. (9) holds")
    with pytest.raises(ValueError, match="is not printed in its quote"):
        validate_registry([encoded], [])
    # a statement holds the printed truth; its threshold is a convention, not a published number
    validate_registry(
        [make(id="KZL-test-stmt", published=True, unit="statement", printed="Eq. (9) holds")], []
    )
    # a reasoned exception (a unit conversion) passes
    converted = make(id="KZL-test-km", published=3300.0, printed="3.3 km")
    with pytest.raises(ValueError, match="is not printed"):
        validate_registry([converted], [])
    monkeypatch.setitem(
        __import__("navcore.ledger.allowlists", fromlist=["x"]).PUBLISHED_NOT_IN_QUOTE,
        "KZL-test-km",
        "3.3 km booked in m",
    )
    validate_registry([converted], [])


# --- findings counted once, and shown ---------------------------------------------------------


def _finding_fixture():
    claim_a = make(id="KZL-test-find-a", compute=lambda: 10.0)
    claim_b = make(
        id="KZL-test-find-b",
        compute=lambda: 20.0 * IN.per_cycle,
        erratum="KZL-E-find-computed",
        expected_status="discrepant",
        oracle=lambda: 20.0,
        oracle_tolerance=TOL,
    )
    text_only = erratum(id="KZL-E-find-text", claims=("KZL-test-find-a",), kind="units")
    computed = erratum(
        id="KZL-E-find-computed", basis="computed", kind="inconsistent-numbers", claims=("KZL-test-find-b",)
    )
    return [evaluate(claim_a), evaluate(claim_b)], [text_only, computed]


def test_the_terminal_summary_leads_with_findings_then_claims_by_verdict():
    from navcore.ledger.summary import summary_text

    evals, found = _finding_fixture()
    text = summary_text(evals, errata=found)
    lines = text.splitlines()
    assert lines[0].startswith("findings (errata): 2")
    assert text.index("findings (errata)") < text.index("claims by paper, kind and verdict")
    assert text.count("misprint") == 1  # the caveat once, not per finding
    assert "  KZL-E-find-computed (inconsistent-numbers; Eq. (1)): KZL-test-find-b discrepant" in lines
    assert "  KZL-E-find-text (units; Eq. (1)): KZL-test-find-a reproduced" in lines
    assert text.index("computed findings") < text.index("text-only findings")


def test_findings_table_and_errata_list_group_by_basis_and_say_the_caveat_once():
    from navcore.ledger.tables import ErrataList, FindingsTable

    evals, found = _finding_fixture()
    table = FindingsTable(found, evals, list_findings=True)
    page = table._repr_html_()
    assert page.count("misprint") == 1
    assert [(r["paper"], r["basis"], r["total"]) for r in table.rows] == [
        ("KZL", "computed", 1),
        ("KZL", "text-only", 1),
        ("all", "all", 2),
    ]
    assert "KZL-test-find-b" in page and "ledger-status-discrepant" in page
    listing = ErrataList(found, evals=evals)
    html = listing._repr_html_()
    assert html.count("misprint") == 1  # once, under the text-only heading, not per erratum
    assert "misprint" not in ErrataList(found, caveat=False)._repr_html_()  # the page said it
    assert (
        html.index("Computed findings") < html.index("KZL-E-find-computed") < html.index("Text-only findings")
    )
    assert "<b>Basis:</b> text-only" in html and "ledger-status-reproduced" in html
    assert "Basis:} computed" in listing.latex()


def test_printed_column_quotes_the_paper_and_says_stated_for_a_statement():
    from navcore.ledger.interactive import InteractiveLedger
    from navcore.ledger.tables import LedgerTable

    quoted = evaluate(make(id="KZL-test-quoted", tolerance=prose("about"), printed="about 10 m"))
    stated = evaluate(make(id="KZL-test-stated", published=True, unit="statement", compute=lambda: True))
    html = LedgerTable([quoted, stated])._repr_html_()
    assert 'data-label="Printed">about&nbsp;10&nbsp;m</td>' in html
    assert 'data-label="Printed">stated</td>' in html
    assert '<button type="button" title="sort">Printed</button>' in InteractiveLedger([quoted])._repr_html_()


def test_json_carries_the_new_fields_and_is_deterministic():
    import json

    from navcore.ledger.tables import json_dump

    evals = [evaluate(make(compute=lambda: 16.13 * IN.per_cycle + IN.offset, expected_status="consistent"))]
    first, second = json_dump(evals), json_dump([evaluate(evals[0].claim)])
    assert first == second
    record = json.loads(first)[0]
    assert [r["agrees"] for r in record["readings"]] == [False, True, False]
    assert record["readings"][1]["band"] is not None and record["band"] is not None
