"""The ledger's mechanisms on synthetic claims and inputs, independent of the registry (issue 31).

Each test builds its own inputs and claims here and never imports a paper module, so a
mechanism that breaks fails here, not only through one registry claim among hundreds.

Oracle in every test: the rule of LEDGER.md (and of the docstrings of :mod:`navcore.claims.verdict`,
:mod:`navcore.claims.runs` and :mod:`navcore.claims.inputs`) written out by hand for claims whose values are
simple closed forms of their inputs, so which runs are made, which band results and which
verdict follows can be counted by hand.

* the band's corners: six assumed inputs where only one off-diagonal corner agrees (every
  corner is run up to six inputs); seven inputs fall back to the documented four corners and
  the two steepest ones, and a printed value those runs miss but the inputs' separate effects
  reach is undecided (not-reproducible);
* the verdict rule with an admissible and a plausible-range input read together;
* the input cache: a cached function reading two inputs of which one is overridden (the
  overridden value is used, and both reads are recorded, on a miss and on a hit); a cached
  read under two override values (two results, each replayed from the cache afterwards);
* the expected-status check: each of the five derived verdicts passes when it is the expected
  one and fails, saying so, for every other;
* the readings: the cap on combinations at its boundary, the band too wide under a reading
  other than the one used, the note's sentence for a statement's other reading.
"""

from __future__ import annotations

import itertools

import pytest

from navcore._validate import ModelDomainError
from navcore.claims.declarations import STATUSES
from navcore.claims.evaluation import left_out_of_band
from navcore.claims.inputs import Input, overriding, recording
from navcore.claims.json_coding import from_jsonable, jsonable
from navcore.claims.runs import MAX_READING_COMBINATIONS
from navcore.claims.verdict import MAX_CORNER_INPUTS
from navcore.ledger import Claim, InputSet, Tolerance, evaluate, input_cache, printed
from navcore.ledger.interactive import InteractiveLedger
from navcore.ledger.text import _band_text

TOL = Tolerance(reason="test", abs=0.5, policy="printed-digits")

IN = InputSet("ATC10", "synthetic_mechanisms")
for _i in range(7):
    IN.assumed(f"x{_i}", 0.5, low=0.0, high=1.0, reason="test range of the corner tests")
IN.assumed("plausible", 0.0, low=-1.0, high=1.0, reason="a plausible range, not every admissible value")
IN.assumed("wall", 0.0, low=-1.0, high=1.0, reason="every admissible value", admissible=True)
IN.assumed("wall2", 0.0, low=-2.0, high=2.0, reason="every admissible value", admissible=True)
IN.published("a", 2.0, locator="Eq. (1)")
IN.published("b", 3.0, locator="Eq. (2)")
IN.convention("sign", 1.0, alternative=-1.0, quantity="sign of the term", reason="the sign is not printed")
for _i in range(5):
    IN.convention(f"c{_i}", 0.0, alternative=1.0, reason="a convention of the cap tests")
IN.convention("scale", 1.0, alternative=10.0, quantity="scale of the band", reason="two readings")

NAME = "ATC10.synthetic_mechanisms."


def make(**kw) -> Claim:
    base = dict(
        id="ATC10-test-mechanisms",
        paper="ATC10",
        locator="Eq. (1)",
        quantity="q",
        published=10.0,
        unit="m",
        compute=lambda: 5.0 * IN.a,
        tolerance=TOL,
        expected_status="reproduced",
        note="a synthetic claim",
    )
    base.update(kw)
    return Claim(**base)


# --- the band's corners ---------------------------------------------------------------------------

#: The one corner of the six-input box at which the claim below agrees: high, low, high, low, ...
PATTERN = (1.0, 0.0, 1.0, 0.0, 1.0, 0.0)


def _corner_indicator(xs: list[float]) -> float:
    """1 at the corner PATTERN, 0 at every other corner, (1/2)^6 at the nominal (all 0.5)."""
    out = 1.0
    for x, p in zip(xs, PATTERN, strict=True):
        out *= x if p == 1.0 else 1.0 - x
    return out


def test_six_assumed_inputs_only_an_off_diagonal_corner_agrees():
    """90 + 10 * indicator: the nominal gives 90.16, one input at a time at most 90.31, the two
    diagonal corners (all low, all high) and their mirrors 90, and only the corner
    (high, low, high, low, high, low) gives 100, the printed value. Every one of the 2^6 corners
    is run (six inputs is the limit, MAX_CORNER_INPUTS), so the band reaches 100: consistent.
    A band made of the one-at-a-time runs and the diagonal corners only would be [90, 90.31]:
    inconsistent."""
    assert MAX_CORNER_INPUTS == 6
    runs = []

    def compute():
        xs = [getattr(IN, f"x{i}") for i in range(6)]
        runs.append(tuple(xs))
        return 90.0 + 10.0 * _corner_indicator(xs)

    value, tol = printed("100.0")
    ev = evaluate(make(published=value, tolerance=tol, compute=compute, expected_status="consistent"))
    assert ev.status == "consistent" and ev.passes
    assert ev.reproduced == pytest.approx(90.0 + 10.0 / 64)
    assert ev.band == pytest.approx((90.0, 100.0))
    # the runs: the nominal, each input at its two ends, and the 64 corners
    assert len(runs) == 1 + 6 * 2 + 2**6
    assert set(itertools.product((0.0, 1.0), repeat=6)) <= set(runs)
    # the sensitivity (one input at a time) alone never reaches the printed value
    one_at_a_time = [v for _, row in ev.sensitivity for _, v in row]
    assert max(one_at_a_time) == pytest.approx(90.0 + 10.0 / 32)


def test_seven_assumed_inputs_fall_back_to_four_corners_and_the_steepest_two():
    """Beyond six inputs: each input at its ends, four corners (all low, all high, the first half
    low and the rest high, and its mirror) and the two corners where each input sits at the end
    that raised (lowered) the value one at a time (core._band_runs). Oracle: the run list and the
    band by hand for 10 + x0 - x1 + x2 - x3 + x4 - x5 + x6, whose extremes (14 at high, low, high,
    ..., 7 at its mirror) no diagonal corner reaches (those give 10 or 11)."""
    runs = []
    signs = (1, -1, 1, -1, 1, -1, 1)

    def compute():
        xs = tuple(getattr(IN, f"x{i}") for i in range(7))
        runs.append(xs)
        return 10.0 + sum(s * x for s, x in zip(signs, xs, strict=True))

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert ev.status == "consistent"
    lows, highs = (0.0,) * 7, (1.0,) * 7
    up = tuple(1.0 if s > 0 else 0.0 for s in signs)
    down = tuple(1.0 - x for x in up)
    corners = [lows, highs, lows[:3] + highs[3:], highs[:3] + lows[3:], up, down]
    assert runs[-6:] == corners
    assert len(runs) == 1 + 7 * 2 + 6
    assert ev.band == pytest.approx((7.0, 14.0))


def _capped_sum() -> float:
    """10 plus seven inputs in [0, 1] summed and capped at 5: one at a time each moves the value
    from 13 to 14 (nominal 13.5), so their separate effects add up to 10 to 17, while no run
    exceeds 15."""
    return 10.0 + min(sum(getattr(IN, f"x{i}") for i in range(7)), 5.0)


@pytest.mark.parametrize(
    ("published", "expected", "envelope"),
    [
        (14.5, "consistent", None),  # inside the band the runs reach (10 to 15)
        (16.0, "not-reproducible", (10.0, 17.0)),  # beyond the runs, within the separate effects' sum
        (17.6, "inconsistent", None),  # beyond both (17 + the tolerance 0.5 < 17.6)
    ],
)
def test_beyond_six_inputs_a_value_the_runs_miss_but_the_effects_reach_is_undecided(
    published, expected, envelope
):
    """Beyond six inputs the corners are a sample (core docstring, "Beyond six inputs"). Oracle:
    the rule by hand for 10 + min(x0 + ... + x6, 5): the runs reach 10 to 15 (all low: 10; the
    steepest corner, all high: capped at 15), the envelope is 13.5 - 7 x 0.5 to 13.5 + 7 x 0.5 =
    10 to 17; a printed 16 lies between them (not-reproducible, and the note gives the envelope),
    17.6 beyond both (inconsistent)."""
    ev = evaluate(make(published=published, compute=_capped_sum, expected_status=expected))
    assert ev.status == expected, ev.detail
    assert ev.band == pytest.approx((10.0, 15.0))
    assert ev.envelope == (pytest.approx(envelope) if envelope else None)
    assert not ev.band_too_wide
    assert ("separate effects add up to 10 to 17 m" in ev.note()) is (envelope is not None)


def test_beyond_six_inputs_another_readings_envelope_leaves_it_undecided():
    """The rule weighs every reading: x scale, read as 1 (used) or 10 (the other). Oracle by
    hand: the used reading's runs and envelope (10 to 15, 10 to 17) miss a printed 160; the other
    reading's runs reach 100 to 150 and its envelope 100 to 170, which holds it: not-reproducible,
    the envelope and the note are the other reading's."""
    ev = evaluate(
        make(published=160.0, compute=lambda: IN.scale * _capped_sum(), expected_status="not-reproducible")
    )
    assert ev.status == "not-reproducible", ev.detail
    assert ev.envelope == pytest.approx((100.0, 170.0))
    assert [r["undecided"] for r in ev.readings] == [False, True]
    assert "With the scale of the band read as the other reading (10), the runs over the 7" in ev.note()


def test_six_inputs_run_every_corner_and_take_no_envelope():
    """Up to six inputs every corner is run, so a value beyond the band is out of reach. Oracle:
    10 + min(x0 + ... + x5, 4) by hand: band 10 to 14, separate effects 10 to 16; a printed 15
    is inconsistent (the envelope is not used)."""
    ev = evaluate(
        make(
            published=15.0,
            compute=lambda: 10.0 + min(sum(getattr(IN, f"x{i}") for i in range(6)), 4.0),
            expected_status="inconsistent",
        )
    )
    assert ev.status == "inconsistent" and ev.envelope is None
    assert ev.band == pytest.approx((10.0, 14.0))


def test_the_additive_envelope_only_widens_when_an_input_is_added():
    """The property that makes the rule stable under new declarations (issue 27): adding an
    input's one-at-a-time row adds a non-negative rise and fall. Oracle: interval inclusion
    over random rows (seeded)."""
    import numpy as np

    from navcore.claims.verdict import additive_envelope

    rng = np.random.default_rng(27)
    for _ in range(200):
        v0 = float(rng.normal())
        rows = [
            (f"x{i}", tuple((p, v0 + float(d)) for p, d in enumerate(rng.normal(size=3)))) for i in range(8)
        ]
        lo7, hi7 = additive_envelope(v0, rows[:7])
        lo8, hi8 = additive_envelope(v0, rows)
        assert lo8 <= lo7 <= v0 <= hi7 <= hi8


def test_the_steepest_corners_are_skipped_for_a_statement():
    """A statement's values are not numbers that order: beyond six inputs only the four corners."""
    runs = []

    def compute():
        xs = tuple(getattr(IN, f"x{i}") for i in range(7))
        runs.append(xs)
        return sum(xs) >= 0.0

    evaluate(
        make(
            published=True,
            unit="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=compute,
            expected_status="consistent",
        )
    )
    assert len(runs) == 1 + 7 * 2 + 4


def test_a_single_assumed_input_runs_no_corner():
    runs = []

    def compute():
        runs.append(IN.x0)
        return 10.0 + IN.x0

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert runs == [0.5, 0.0, 1.0] and ev.band == (10.0, 11.0)


# --- the verdict with an admissible and a plausible-range input ---------------------------------


@pytest.mark.parametrize(
    ("inputs", "status"),
    [
        (("wall",), "discrepant"),  # every input spans all admissible values
        (("wall", "wall2"), "discrepant"),
        (("wall", "plausible"), "inconsistent"),  # one range is only plausible: no accusation
        (("plausible", "wall"), "inconsistent"),
        (("plausible",), "inconsistent"),
    ],
)
def test_disagreement_over_mixed_admissible_and_plausible_ranges(inputs, status):
    """LEDGER.md: a disagreement across the whole band is a discrepancy only when *every* assumed
    input read declares its range admissible; one plausible range makes it inconsistent.
    Oracle: 20 + the inputs' sum spans [18, 22] or narrower, never within 10 +- 0.5."""
    extra = {}
    if status == "discrepant":
        extra = dict(erratum="ATC10-E-none", oracle=lambda: 20.0, oracle_tolerance=TOL)
    claim = make(compute=lambda: 20.0 + sum(getattr(IN, n) for n in inputs), expected_status=status, **extra)
    ev = evaluate(claim)
    assert ev.status == status and ev.passes
    assert {i["name"] for i in ev.inputs} == {NAME + n for n in inputs}


def test_a_mixed_claim_that_agrees_over_its_band_is_consistent():
    ev = evaluate(make(compute=lambda: 8.5 + IN.wall + IN.plausible, expected_status="consistent"))
    assert ev.status == "consistent" and ev.band == (6.5, 10.5)


# --- the input cache --------------------------------------------------------------------------------


def test_cached_function_reading_two_inputs_one_overridden():
    """A cached function reads a and b; under an override of a alone it recomputes with the new a
    and the declared b, and both reads are recorded in the caller's recording, on the miss and
    on the hit (the overridden read is recorded like any other). Oracle: a * 10 + b by hand."""
    calls = []

    @input_cache
    def combined(k):
        calls.append(k)
        return IN.a * k + IN.b

    with recording() as reads:
        assert combined(10.0) == 23.0
    assert sorted(reads) == [NAME + "a", NAME + "b"] and len(calls) == 1
    for attempt in range(2):  # a miss, then a hit
        with overriding({NAME + "a": 5.0}), recording() as reads:
            assert combined(10.0) == 53.0
        assert sorted(reads) == [NAME + "a", NAME + "b"], attempt
        assert reads[NAME + "a"].value == 2.0  # the record is the declaration, not the override
    assert len(calls) == 2
    with recording() as reads:
        assert combined(10.0) == 23.0  # the declared value again, from the cache
    assert sorted(reads) == [NAME + "a", NAME + "b"] and len(calls) == 2


def test_cached_read_under_two_override_values():
    """Two override values of one input give two results, each kept: the cache is keyed on the
    value each read returned. Oracle: 3 * a by hand; the call count says when it recomputes."""
    calls = []

    @input_cache
    def tripled():
        calls.append(IN.a)
        return 3.0 * IN.a

    results = {}
    for a in (7.0, 11.0, 7.0, 11.0):
        with overriding({NAME + "a": a}):
            results.setdefault(a, []).append(tripled())
    assert results == {7.0: [21.0, 21.0], 11.0: [33.0, 33.0]}
    assert calls == [7.0, 11.0]
    assert tripled() == 6.0 and calls == [7.0, 11.0, 2.0]


def test_claim_reading_through_a_cached_function_follows_its_band_and_lists_its_inputs():
    """Through the ledger: a claim whose value comes from a cached function is evaluated across
    the assumed range (each band point a different override) and lists the inputs the cached
    function read, also when the nominal run is a cache hit. Oracle: 9 + x0 and 10 * a / 2."""

    @input_cache
    def cached_value():
        return 9.0 + IN.x0 + 10.0 * IN.a / 2.0 - 10.0

    cached_value()  # fill the cache outside any recording
    ev = evaluate(make(compute=cached_value, expected_status="consistent"))
    assert ev.reproduced == 9.5 and ev.band == (9.0, 10.0)
    assert [i["name"] for i in ev.inputs] == [NAME + "a", NAME + "x0"]


def test_overrides_nest_and_unknown_names_are_refused():
    with overriding({NAME + "a": 4.0}):
        with overriding({NAME + "b": 5.0}):
            assert (IN.a, IN.b) == (4.0, 5.0)
        with overriding({NAME + "a": 6.0}):
            assert IN.a == 6.0
        assert (IN.a, IN.b) == (4.0, 3.0)
    with pytest.raises(ValueError, match="not a registered input"):
        with overriding({NAME + "nope": 1.0}):
            pass


# --- the expected-status check ---------------------------------------------------------------------


def _claims_deriving_each_status() -> dict[str, dict]:
    """Claim fields that derive each verdict (by the rules of LEDGER.md, by hand)."""
    return {
        "reproduced": dict(compute=lambda: 5.0 * IN.a),  # 10, published inputs only
        "consistent": dict(compute=lambda: 9.0 + IN.x0 * 2.0),  # band [9, 11] holds 10
        "inconsistent": dict(compute=lambda: 20.0 + IN.plausible),  # band [19, 21]
        "discrepant": dict(
            compute=lambda: 6.0 * IN.a,  # 12, published inputs only
            erratum="ATC10-E-none",
            oracle=lambda: 12.0,
            oracle_tolerance=TOL,
        ),
        "not-reproducible": dict(compute=None),
    }


@pytest.mark.parametrize("derived", STATUSES)
@pytest.mark.parametrize("expected", STATUSES)
def test_expected_status_check(derived, expected):
    """A claim passes its check exactly when its derived verdict is the expected one (and, for
    a discrepancy, its oracle agrees); otherwise the detail names both verdicts."""
    fields = dict(_claims_deriving_each_status()[derived])
    if expected == "discrepant":
        fields.setdefault("erratum", "ATC10-E-none")
        fields.setdefault("oracle", lambda: 0.0)
        fields.setdefault("oracle_tolerance", TOL)
    ev = evaluate(make(expected_status=expected, **fields))
    assert ev.status == derived
    if derived == "not-reproducible":  # nothing computed: the check is whether it was expected
        assert ev.passes == (expected == derived)
        return
    assert ev.passes == (expected == derived)
    if expected != derived:
        assert ev.detail == f"derived verdict {derived!r} differs from the expected {expected!r}"


def test_a_discrepancy_passes_only_when_its_oracle_agrees():
    fields = _claims_deriving_each_status()["discrepant"]
    assert evaluate(make(expected_status="discrepant", **fields)).passes
    wrong = evaluate(make(expected_status="discrepant", **{**fields, "oracle": lambda: 13.0}))
    assert wrong.status == "discrepant" and not wrong.passes
    assert wrong.detail == "disagrees with its independent oracle (13.0)" and wrong.oracle_value == 13.0
    # the oracle tolerance is relative to the oracle's value: 12 against 12.4 +- 0.5 agrees
    assert evaluate(make(expected_status="discrepant", **{**fields, "oracle": lambda: 12.4})).passes

    def failing():
        raise RuntimeError("no oracle")

    broken = evaluate(make(expected_status="discrepant", **{**fields, "oracle": failing}))
    assert not broken.passes and broken.detail == "oracle raised RuntimeError: no oracle"


# --- readings: the cap and the other readings' bands ----------------------------------------------


def test_reading_combinations_at_the_cap_are_all_run_and_one_more_convention_is_not():
    """Four two-reading conventions make 16 combinations, the cap: all are run; a fifth makes 32,
    beyond it: the readings used plus each convention's other reading alone (1 + 5 runs)."""
    assert MAX_READING_COMBINATIONS == 16
    seen = []

    def compute_with(n):
        def compute():
            xs = tuple(getattr(IN, f"c{i}") for i in range(n))
            seen.append(xs)
            return 10.0 + 0.01 * sum(xs)

        return compute

    ev = evaluate(make(compute=compute_with(4)))
    assert len(ev.readings) == 16 and len(set(seen)) == 16
    seen.clear()
    ev = evaluate(make(compute=compute_with(5)))
    assert len(ev.readings) == 6
    assert sorted(seen) == sorted([(0.0,) * 5] + [tuple(float(i == j) for i in range(5)) for j in range(5)])


def test_an_other_reading_whose_band_is_too_wide_does_not_make_the_claim_consistent():
    """The reading used (scale 1) gives [1, 3] around 2: no agreement with 20; the other reading
    (scale 10) gives [10, 30]: it holds 20 but its ends are a factor 3 apart... exactly 3, which
    is not more than the factor: it decides, consistent. With a wider range [5, 35] (a factor 7)
    it does not: not-reproducible. Oracle: the band-too-wide rule by hand."""
    value, tol = printed("20.0")
    ev = evaluate(
        make(
            published=value,
            tolerance=tol,
            compute=lambda: IN.scale * (2.0 + IN.plausible),
            expected_status="consistent",
        )
    )
    assert ev.status == "consistent" and not ev.readings[0]["agrees"]
    other = ev.readings[1]
    assert other["band"] == (10.0, 30.0) and other["agrees"] and not other["band_too_wide"]
    wide = evaluate(
        make(
            published=value,
            tolerance=tol,
            compute=lambda: IN.scale * (2.0 + 1.5 * IN.plausible),
            expected_status="not-reproducible",
        )
    )
    assert wide.status == "not-reproducible" and wide.passes and wide.band_too_wide
    assert wide.readings[1]["band"] == (5.0, 35.0) and wide.readings[1]["band_too_wide"]
    assert "The reading that agrees does so over only part of a band" in wide.note()


def test_other_readings_bands_stop_at_the_first_reading_that_decides():
    """Conventions c0, c1 (readings 0 and 1 each) and one assumed input: the value is
    10 * (1 + c0 + c1) + plausible. The reading used (0, 0) gives [9, 11] against 20: no
    agreement. The combinations after it, in order: (0, 1) gives [19, 21], which agrees and
    decides, so the verdict is settled and the bands of (1, 0) and (1, 1) are not run; their
    values (20 and 30) are, and the note says they are at the nominal inputs. Oracle: the rule of the
    module docstring ("the readings after it show their values") by hand, and the runs counted."""
    runs = []

    def compute():
        runs.append((IN.c0, IN.c1, IN.plausible))
        return 10.0 * (1.0 + IN.c0 + IN.c1) + IN.plausible

    value, tol = printed("20.0")
    ev = evaluate(make(published=value, tolerance=tol, compute=compute, expected_status="consistent"))
    assert ev.status == "consistent" and ev.passes
    bands = {(r["reading"][NAME + "c0"], r["reading"][NAME + "c1"]): r["band"] for r in ev.readings}
    used = ev.readings[0]["reading"][NAME + "c0"]
    other = next(k[0] for k in bands if k[0] != used)
    assert bands[(used, used)] == (9.0, 11.0) and bands[(used, other)] == (19.0, 21.0)
    assert bands[(other, used)] is None and bands[(other, other)] is None
    # the band's points (one input, its low and high ends) for two readings; values for four
    assert sorted(r for r in runs if r[2] != 0.0) == [
        (0.0, 0.0, -1.0),
        (0.0, 0.0, 1.0),
        (0.0, 1.0, -1.0),
        (0.0, 1.0, 1.0),
    ]
    assert sorted({r[:2] for r in runs}) == [(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0)]
    assert "20 m at the nominal inputs" in ev.note() and "30 m at the nominal inputs" in ev.note()


def test_a_statement_whose_one_at_a_time_runs_hold_both_truth_values_runs_no_corner():
    """x0 > 0.7 or x1 > 0.7 at the nominal (0.5, 0.5) is False; x0 alone at its high end makes it
    True: after the one-at-a-time runs the band already holds both truth values, so the four
    corners of the two-input box (which could only repeat them) are not run, and the band is
    (False, True) as with them. x0 + x1 > 1.5 holds at none of the one-at-a-time runs (each
    input alone reaches 1.5 only at its end, not beyond): its corners are run, and the corner
    (1, 1) is the only one that makes it True. Oracle: the truth tables by hand, runs counted."""
    runs = []

    def either():
        runs.append((IN.x0, IN.x1))
        return bool(IN.x0 > 0.7 or IN.x1 > 0.7)

    ev = evaluate(
        make(
            published=True,
            unit="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=either,
            expected_status="not-reproducible",
        )
    )
    assert ev.band == (False, True) and ev.status == "not-reproducible"
    assert (1.0, 1.0) not in runs and (0.0, 0.0) not in runs  # no corner was run
    runs.clear()

    def both():
        runs.append((IN.x0, IN.x1))
        return bool(IN.x0 + IN.x1 > 1.5)

    ev = evaluate(
        make(
            published=False,
            unit="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=both,
            expected_status="not-reproducible",
        )
    )
    assert set(itertools.product((0.0, 1.0), repeat=2)) <= set(runs)
    assert ev.band == (False, True)


def test_another_readings_statement_band_stops_once_it_holds_both_truth_values():
    """Under the reading used (sign 1) the statement is x0 + x1 > 0.8: True at the nominal
    (0.5, 0.5), False with x0 at 0, so its band is too wide and the other reading's band is run.
    Under the other reading (sign -1) it is x0 > 0.7: False at the nominal, True with x0 at 1.
    After x0's two runs that band holds both truth values: it is (False, True) whatever else is
    run, so neither x1's runs nor the corners are made under it, while the reading used makes
    all its one-at-a-time runs (they are shown). Oracle: the truth tables by hand, runs counted."""
    runs = []

    def compute():
        runs.append((IN.sign, IN.x0, IN.x1))
        return bool(IN.x0 + IN.x1 > 0.8) if IN.sign > 0 else bool(IN.x0 > 0.7)

    ev = evaluate(
        make(
            published=True,
            unit="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=compute,
            expected_status="not-reproducible",
        )
    )
    assert ev.status == "not-reproducible" and ev.band == (False, True)
    other = [r[1:] for r in runs if r[0] < 0]
    assert other == [(0.5, 0.5), (0.0, 0.5), (1.0, 0.5)]  # its value, then x0 at its two ends
    used = [r[1:] for r in runs if r[0] > 0]
    assert {(0.5, 0.0), (0.5, 1.0)} <= set(used)  # x1's runs under the reading used are made
    assert [row for name, row in ev.sensitivity if name == NAME + "x1"] == [((0.0, False), (1.0, True))]
    assert ev.readings[1]["band"] == (False, True)


def test_a_statements_other_reading_is_said_in_words():
    ev = evaluate(
        make(
            published=True,
            unit="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=lambda: IN.sign > 0,
            expected_status="reproduced",
        )
    )
    assert ev.status == "reproduced"
    assert ev.note().endswith("With the sign of the term read as the other reading (-1): does not hold.")


def test_inputs_are_recorded_once_with_their_provenance_and_source():
    ev = evaluate(make(compute=lambda: IN.a + IN.a + IN.b + IN.x0 * 0.0 + 5.0, expected_status="consistent"))
    assert [(i["name"], i["provenance"]) for i in ev.inputs] == [
        (NAME + "a", "published"),
        (NAME + "b", "published"),
        (NAME + "x0", "assumed"),
    ]
    assert ev.inputs[0]["locator"] == "Eq. (1)" and ev.inputs[2]["reason"].startswith("test range")


def test_input_records_are_the_declarations():
    inp = IN.input("x0")
    assert isinstance(inp, Input) and inp.band_points == (0.0, 1.0) and inp.provenance == "assumed"


def test_a_band_run_outside_the_models_domain_is_left_out_and_said():
    """A run the model does not cover (ModelDomainError) gives no band value and does not fail
    the claim; the evaluation's ``left_out`` names the case in the reader's words and the
    count, and the note, the ledger page's band text, the interactive table and the stored
    evaluation carry it (core._band_runs, render._band_text, registry's cache fields). Oracle:
    the band of 10 + x0 by hand over the runs left, the one corner x0 = x1 = 1 raising."""

    def compute():
        x0, x1 = IN.x0, IN.x1
        if x0 == 1.0 and x1 == 1.0:
            raise ModelDomainError(
                "x0=1.0 with x1=1.0: no fixed channels", case="no fixed channels for this flight"
            )
        return 10.0 + x0

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert ev.status == "consistent" and ev.passes
    assert ev.band == pytest.approx((10.0, 11.0))  # x0 = 1 still reached at x1 = 0
    assert ev.left_out == ({"case": "no fixed channels for this flight", "runs": 1},)
    assert left_out_of_band(ev) == "no fixed channels for this flight (1 run)"
    assert "x0=1.0" not in ev.detail + ev.note() + _band_text(ev)  # the caller's words stay out
    assert "left out, outside the model's domain: no fixed channels for this flight" in _band_text(ev)
    assert ev.note().endswith(
        "The band leaves out, as outside the model's domain, 1 run where no fixed channels for this flight."
    )
    page = InteractiveLedger([ev])._repr_html_()
    assert "1 run left out" in page
    # the stored record round-trips the field (the cache and the parallel workers use these fields)
    from navcore.ledger import registry

    stored = {k: from_jsonable(jsonable(getattr(ev, k), round_trip=True)) for k in registry._RECORD_FIELDS}
    assert stored["left_out"] == ({"case": "no fixed channels for this flight", "runs": 1},)


def test_a_band_run_outside_the_model_with_no_reader_words_says_its_message():
    """A ModelDomainError without ``case`` is left out under its message (its default case)."""

    def compute():
        if IN.x0 == 1.0:
            raise ModelDomainError("outside")
        return 10.0 + IN.x1

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert (
        ev.left_out == ({"case": "outside", "runs": ev.left_out[0]["runs"]},) and ev.left_out[0]["runs"] >= 2
    )


def test_a_plain_value_error_in_a_band_run_still_fails_the_claim():
    """Only ModelDomainError is left out: any other ValueError of a band run is an error."""

    def compute():
        if IN.x0 == 1.0:
            raise ValueError("a bug")
        return 10.0

    ev = evaluate(make(compute=compute, expected_status="consistent"))
    assert ev.status == "error" and not ev.passes


# --- a band's runs announced ahead, so that a model can batch them ------------------------------


def _batched_model(calls: list[int]):
    """A model of x0..x6 cached on its inputs, which runs a whole announced batch in one call."""
    from navcore.ledger import for_each_band_run

    def params() -> tuple[float, ...]:
        return tuple(getattr(IN, f"x{i}") for i in range(7))

    def model(ps: list[tuple[float, ...]]) -> list[float]:  # one call, any number of runs
        calls.append(len(ps))
        return [sum((-1) ** k * (k + 1) * x for k, x in enumerate(p)) for p in ps]

    @input_cache
    def run() -> float:
        return model([params()])[0]

    def value() -> float:
        ahead = for_each_band_run("test model", params)
        if ahead:
            run.prime([(reads, v) for (reads, _), v in zip(ahead, model([p for _, p in ahead]), strict=True)])
        return run()

    return value


def test_band_batches_reach_the_model_in_one_call_and_give_the_unbatched_values():
    # oracle: the same claim with the model called once per run (no batching), and the count of
    # runs the module docstring gives for seven inputs (two band points each: 14 one at a time;
    # the four diagonal corners and the two steepest ones)
    batched_calls: list[int] = []
    batched = evaluate(make(compute=_batched_model(batched_calls)))
    plain_calls: list[int] = []
    plain_model = _batched_model(plain_calls)

    def unbatched() -> float:
        from navcore.claims.inputs import band_ahead

        with band_ahead([]):  # nothing announced: one call per run
            return plain_model()

    plain = evaluate(make(compute=unbatched))
    assert (batched.reproduced, batched.band, batched.status) == (plain.reproduced, plain.band, plain.status)
    assert batched.band is not None and batched.band[0] < batched.band[1]
    n_points = sum(len(get_band_points(i)) for i in range(7))
    assert plain_calls == [1] * len(plain_calls) and len(plain_calls) == 1 + n_points + 6
    # the nominal run alone, the one-at-a-time runs in one call, the six corners in one call
    assert batched_calls == [1, n_points, 6]


def get_band_points(i: int) -> tuple[float, ...]:
    from navcore.claims.inputs import get_input

    return get_input(f"{NAME}x{i}").band_points


def test_for_each_band_run_reads_stay_out_of_the_callers_recording_and_use_the_outer_overrides():
    from navcore.claims.inputs import band_ahead, for_each_band_run

    with overriding({NAME + "x1": 0.25}), band_ahead([{NAME + "x0": 1.0}, {NAME + "x0": 0.0}]):
        with overriding({NAME + "x0": 0.75}), recording() as reads:  # inside the first run
            ahead = for_each_band_run("xs", lambda: (IN.x0, IN.x1))
            assert IN.x0 == 0.75
    assert [v for _, v in ahead] == [(1.0, 0.25), (0.0, 0.25)]
    assert [(i.name, v) for i, v in ahead[0][0]] == [(NAME + "x0", 1.0), (NAME + "x1", 0.25)]
    assert sorted(reads) == [NAME + "x0"]
    assert for_each_band_run("x0", lambda: IN.x0) == []  # nothing announced here
