"""The ledger's verdict rule at its edges, on synthetic claims (issue 31, mutation survivors).

Each test pins one comparison of the rule (:mod:`navcore.claims.verdict`, "Verdicts", "A band too
wide to decide"; :mod:`navcore.claims.tolerances`, "Trailing zeros") at the value where a
changed operator or constant would give
another answer: a value exactly at the tolerance's edge, a band exactly a factor 3 wide, a band
touching zero. No paper module is imported and nothing is evaluated over the registry.

Oracle in every test: the rule of LEDGER.md written out by hand for numbers that are exact in
binary floating point (10, 0.5, 10.5, 9.5, ...), so each expected truth value and verdict is
read off the rule's text, not computed by the code under test.
"""

from __future__ import annotations

import math

import pytest

from navcore.claims.tolerances import EXACT
from navcore.claims.verdict import (
    BAND_FACTOR,
    _band_satisfies,
    _outcome,
    _satisfies,
    band_spread,
    band_too_wide,
    derive_status,
    precision_status,
)
from navcore.ledger import Claim, Tolerance

HALF = Tolerance(reason="test: half a unit", abs=0.5, policy="printed-digits")
ZERO = Tolerance(reason="test: exact", abs=0.0, policy="exact")


def make(published: float | bool = 10.0, **kw) -> Claim:
    base = dict(
        id="WF-test-mutation-verdict",
        paper="WF",
        locator="Eq. (1)",
        quantity="q",
        published=published,
        unit="m",
        compute=lambda: 10.0,
        tolerance=HALF,
        expected_status="reproduced",
        note="a synthetic claim",
    )
    base.update(kw)
    if isinstance(published, bool):
        base["unit"] = "statement"
    return Claim(**base)


# --- _satisfies and _band_satisfies: each relation at the tolerance's edge -------------------


@pytest.mark.parametrize(
    ("value", "relation", "expected"),
    [
        # "=": |v - 10| <= 0.5, the edges included
        (10.5, "=", True),
        (9.5, "=", True),
        (10.5000001, "=", False),
        (9.4999999, "=", False),
        # "<": v < 10 + 0.5 (the edge excluded), "<=": v <= 10.5 (included)
        (10.5, "<", False),
        (10.4999999, "<", True),
        (10.5, "<=", True),
        (10.5000001, "<=", False),
        # ">": v > 10 - 0.5 (excluded), ">=": v >= 9.5 (included)
        (9.5, ">", False),
        (9.5000001, ">", True),
        (9.5, ">=", True),
        (9.4999999, ">=", False),
        # far on each side
        (-100.0, "<", True),
        (100.0, ">", True),
        (100.0, "<", False),
        (-100.0, ">=", False),
    ],
)
def test_satisfies_at_the_tolerance_edge(value, relation, expected):
    assert _satisfies(value, relation, 10.0, 0.5) is expected


def test_satisfies_rejects_an_unknown_relation():
    with pytest.raises(ValueError, match="relation must be one of"):
        _satisfies(1.0, "==", 1.0, 0.0)


@pytest.mark.parametrize(
    ("lo", "hi", "relation", "expected"),
    [
        # "=": the interval [lo, hi] meets [9.5, 10.5]
        (10.5, 12.0, "=", True),  # touches the upper edge
        (10.5000001, 12.0, "=", False),
        (8.0, 9.5, "=", True),  # touches the lower edge
        (8.0, 9.4999999, "=", False),
        (0.0, 20.0, "=", True),  # straddles it
        # a bound below ("<", "<="): decided by the band's low end
        (9.0, 50.0, "<", True),
        (10.5, 50.0, "<", False),
        (10.5, 50.0, "<=", True),
        # a bound above (">", ">="): decided by the band's high end
        (-50.0, 11.0, ">", True),
        (-50.0, 9.5, ">", False),
        (-50.0, 9.5, ">=", True),
    ],
)
def test_band_satisfies_is_the_interval_meeting_the_accepted_set(lo, hi, relation, expected):
    assert _band_satisfies(lo, hi, relation, 10.0, 0.5) is expected


# --- band_spread and band_too_wide ------------------------------------------------------------


def test_band_spread_closed_forms():
    # ratio of magnitudes for one sign; either order; the negative side too
    assert band_spread(2.0, 8.0) == 4.0
    assert band_spread(8.0, 2.0) == 4.0
    assert band_spread(-8.0, -2.0) == 4.0
    # a band reaching zero (from either side) or changing sign: infinite; the point 0: 1
    assert band_spread(0.0, 5.0) == math.inf
    assert band_spread(-5.0, 0.0) == math.inf
    assert band_spread(-1.0, 1.0) == math.inf
    assert band_spread(0.0, 0.0) == 1.0
    # decibels: the power ratio of the ends, 10 dB -> 10, whatever the case and spaces of "dB"
    assert band_spread(3.0, 13.0, "dB") == pytest.approx(10.0, rel=1e-15)
    assert band_spread(13.0, 3.0, " DBW") == pytest.approx(10.0, rel=1e-15)
    assert band_spread(-5.0, 5.0, "dBm") == pytest.approx(10.0, rel=1e-15)
    # a unit merely containing "db" later is not decibels
    assert band_spread(1.0, 10.0, "m/dB") == 10.0


def test_band_too_wide_at_exactly_the_factor():
    claim = make(published=10.0)
    # the band [4, 12] is 3 wide (factor 3): not more than BAND_FACTOR, so it decides
    assert BAND_FACTOR == 3.0
    assert band_too_wide(claim, ZERO, 4.0, 12.0) is False
    assert band_too_wide(claim, ZERO, 12.0, 4.0) is False
    # a hair wider: too wide (the tolerance accepts 10 only, part of the band)
    assert band_too_wide(claim, ZERO, 4.0, 12.0000001) is True
    assert band_too_wide(claim, ZERO, 3.9999999, 12.0) is True


def test_band_too_wide_not_when_the_tolerance_accepts_all_of_it():
    # published 10 with +-100: the whole band [1, 100] agrees, so it decides though a factor 100 wide
    wide = Tolerance(reason="test", abs=100.0, policy="prose")
    claim = make(published=10.0)
    assert band_too_wide(claim, wide, 1.0, 100.0) is False
    assert band_too_wide(claim, wide, 100.0, 1.0) is False
    # one end just outside the accepted set [-90, 110]: decided by the spread (factor > 3)
    assert band_too_wide(claim, wide, 1.0, 110.0000001) is True
    assert band_too_wide(claim, wide, -90.0000001, 1.0) is True


def test_band_too_wide_uses_the_claims_unit_and_relation():
    # in dB: 4 dB apart is a power ratio 2.5 < 3, decides; 5 dB is 3.16 > 3, too wide
    claim = make(published=20.0, unit="dB")
    assert band_too_wide(claim, ZERO, 16.0, 20.0) is False
    assert band_too_wide(claim, ZERO, 15.0, 20.0) is True
    # a bound "<" 10: the band [1, 9] lies wholly below it, agrees everywhere, decides
    bound = make(published=10.0, relation="<")
    assert band_too_wide(bound, ZERO, 1.0, 9.0) is False
    # [1, 11] straddles it and spans a factor 11: too wide
    assert band_too_wide(bound, ZERO, 1.0, 11.0) is True
    # [8, 11] straddles it but spans less than a factor 3: decides
    assert band_too_wide(bound, ZERO, 8.0, 11.0) is False


def test_band_too_wide_for_truth_values():
    s = make(published=True, kind="statement")
    assert band_too_wide(s, EXACT, False, True) is True
    assert band_too_wide(s, EXACT, True, False) is True
    assert band_too_wide(s, EXACT, True, True) is False
    assert band_too_wide(s, EXACT, False, False) is False
    # a numeric claim handed truth values compares them as truth values too
    n = make(published=1.0)
    assert band_too_wide(n, EXACT, True, False) is True
    assert band_too_wide(n, EXACT, 0.0, True) is True


# --- _outcome ---------------------------------------------------------------------------------


def test_outcome_numeric_at_value_band_and_width():
    c = make(published=10.0)
    # the value agrees, no band
    o = _outcome(c, HALF, 10.5, [])
    assert (o.agrees_at_value, o.agrees, o.too_wide, o.undecided) == (True, True, False, False)
    # the value disagrees, the band [8, 10.2] reaches the printed value: agrees, decides (8 -> 10.2 < 3)
    o = _outcome(c, HALF, 8.0, [8.5, 10.2])
    assert (o.agrees_at_value, o.agrees, o.too_wide, o.undecided) == (False, True, False, False)
    # the value disagrees and the band [1, 20] is too wide (agreeing only in part)
    o = _outcome(c, HALF, 1.0, [20.0])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (False, True, True)
    # the band lies wholly below: no agreement; an envelope reaching 10 makes it undecided
    o = _outcome(c, HALF, 8.0, [9.0], envelope=(7.0, 10.0))
    assert (o.agrees, o.undecided) == (False, True)
    # an envelope that does not reach 9.5: decided (not undecided)
    o = _outcome(c, HALF, 8.0, [9.0], envelope=(7.0, 9.4))
    assert (o.agrees, o.undecided) == (False, False)
    # the union of the band [8, 9] and an envelope [11, 12] covers 10: undecided
    o = _outcome(c, HALF, 8.0, [9.0], envelope=(11.0, 12.0))
    assert (o.agrees, o.undecided) == (False, True)
    # the union of the band [11, 12] and an envelope [8, 9] covers 10 as well
    o = _outcome(c, HALF, 12.0, [11.0], envelope=(8.0, 9.0))
    assert (o.agrees, o.undecided) == (False, True)
    # an agreeing value is never undecided, whatever the envelope
    o = _outcome(c, HALF, 10.0, [10.2], envelope=(0.0, 100.0))
    assert (o.agrees, o.undecided) == (True, False)
    # no envelope: never undecided
    assert _outcome(c, HALF, 8.0, [9.0]).undecided is False


def test_outcome_band_edges_use_the_min_and_the_max_of_all_runs():
    c = make(published=10.0)
    # value 5, runs [30, 12, 7]: band [5, 30] contains 10, agrees; factor 6 > 3: too wide
    o = _outcome(c, HALF, 5.0, [30.0, 12.0, 7.0])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (False, True, True)
    # value 20, runs [11, 25]: band [11, 25] misses [9.5, 10.5]
    o = _outcome(c, HALF, 20.0, [11.0, 25.0])
    assert (o.agrees, o.too_wide) == (False, False)
    # value 11, runs [9.8]: the low end 9.8 lies within, agrees, band decides
    o = _outcome(c, HALF, 11.0, [9.8])
    assert (o.agrees, o.too_wide) == (True, False)


def test_outcome_statement():
    s = make(published=True, kind="statement")
    o = _outcome(s, EXACT, True, [])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (True, True, False)
    o = _outcome(s, EXACT, False, [])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (False, False, False)
    # false at the nominal, true somewhere in the band: agrees, both outcomes -> too wide
    o = _outcome(s, EXACT, False, [True, False])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (False, True, True)
    # true everywhere: decides
    o = _outcome(s, EXACT, True, [True, True])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (True, True, False)
    # a statement published False: agreement is the value False
    f = make(published=False, kind="statement")
    o = _outcome(f, EXACT, False, [False])
    assert (o.agrees_at_value, o.agrees, o.too_wide) == (True, True, False)


# --- precision_status -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("loose", "expected"),
    [
        ("reproduced", "consistent"),
        ("consistent", "consistent"),
        ("inconsistent", "inconsistent"),
        ("discrepant", "discrepant"),
        ("not-reproducible", "not-reproducible"),
    ],
)
def test_precision_status(loose, expected):
    # the rule: agreement only under the loose reading is "consistent"; else the loose verdict
    assert precision_status(loose) == expected


# --- derive_status: every branch ------------------------------------------------------------


def test_derive_status_published_inputs():
    c = make(published=10.0)
    # the reading used agrees: reproduced, whatever the others give
    assert derive_status(c, HALF, 10.4, [], {"published"}, False) == "reproduced"
    assert derive_status(c, HALF, 10.4, [], {"published", "convention"}, False, [(20.0, [])]) == "reproduced"
    # no input at all: a value that agrees is reproduced, one that does not is discrepant
    assert derive_status(c, HALF, 10.0, [], set(), False) == "reproduced"
    assert derive_status(c, HALF, 11.0, [], set(), False) == "discrepant"
    # the used reading disagrees: consistent if a later reading agrees, discrepant if none does
    assert derive_status(c, HALF, 11.0, [], {"convention"}, False, [(20.0, []), (10.0, [])]) == "consistent"
    assert derive_status(c, HALF, 11.0, [], {"convention"}, False, [(20.0, []), (30.0, [])]) == "discrepant"


def test_derive_status_cross_check_reads_values_only():
    c = make(published=10.0, kind="cross-check")
    assert derive_status(c, HALF, 10.0, [], set(), False) == "consistent"
    assert derive_status(c, HALF, 11.0, [], set(), False) == "discrepant"
    assert derive_status(c, HALF, 11.0, [], set(), False, [(10.2, [])]) == "consistent"
    # a band that reaches the printed value does not count for a cross-check: values only
    assert derive_status(c, HALF, 11.0, [9.0, 12.0], {"assumed"}, False) == "discrepant"


@pytest.mark.parametrize("how", ["fit-kind", "fitted-input"])
def test_derive_status_fit(how):
    kind = "fit" if how == "fit-kind" else "reproduction"
    prov = {"published"} if how == "fit-kind" else {"fitted"}
    c = make(published=10.0, kind=kind)
    assert derive_status(c, HALF, 10.0, [], prov, False) == "consistent"
    assert derive_status(c, HALF, 12.0, [], prov, False) == "inconsistent"
    # admissible does not make a fit discrepant
    assert derive_status(c, HALF, 12.0, [], prov, True) == "inconsistent"
    # an agreeing band too wide to decide: not-reproducible
    assert derive_status(c, HALF, 1.0, [20.0], prov, False) == "not-reproducible"
    # another reading agrees with a band that decides: consistent
    assert derive_status(c, HALF, 1.0, [20.0], prov, False, [(10.0, [10.2])]) == "consistent"
    # undecided (an envelope reaches the printed value): not-reproducible
    assert derive_status(c, HALF, 8.0, [9.0], prov, False, envelope=(7.0, 11.0)) == "not-reproducible"
    # another reading undecided only
    assert derive_status(c, HALF, 8.0, [9.0], prov, False, [(8.0, [9.0], (0.0, 20.0))]) == "not-reproducible"


def test_derive_status_assumed_inputs():
    c = make(published=10.0)
    prov = {"published", "assumed"}
    # the band [9, 11] decides and agrees: consistent (not reproduced, even where the value agrees)
    assert derive_status(c, HALF, 10.0, [9.0, 11.0], prov, False) == "consistent"
    assert derive_status(c, HALF, 9.0, [11.0], prov, True) == "consistent"
    # disagreement across the band: inconsistent for a plausible range, discrepant if admissible
    assert derive_status(c, HALF, 12.0, [13.0], prov, False) == "inconsistent"
    assert derive_status(c, HALF, 12.0, [13.0], prov, True) == "discrepant"
    # an agreeing band too wide to decide: not-reproducible (admissible or not)
    assert derive_status(c, HALF, 1.0, [20.0], prov, False) == "not-reproducible"
    assert derive_status(c, HALF, 1.0, [20.0], prov, True) == "not-reproducible"
    # the reading used too wide, another reading agrees and decides: consistent
    assert derive_status(c, HALF, 1.0, [20.0], prov, False, [(10.0, [10.1])]) == "consistent"
    # the reading used disagrees, another agrees but too wide: not-reproducible
    assert derive_status(c, HALF, 12.0, [13.0], prov, True, [(1.0, [20.0])]) == "not-reproducible"
    # undecided by the envelope of the reading used / of another reading
    assert derive_status(c, HALF, 12.0, [13.0], prov, True, envelope=(9.0, 14.0)) == "not-reproducible"
    assert (
        derive_status(c, HALF, 12.0, [13.0], prov, False, [(12.0, [13.0], (0.0, 14.0))]) == "not-reproducible"
    )
    # fitted and assumed together: the fit's rule (inconsistent, never discrepant)
    assert derive_status(c, HALF, 12.0, [13.0], {"assumed", "fitted"}, True) == "inconsistent"


def test_derive_status_statement():
    s = make(published=True, kind="statement")
    assert derive_status(s, EXACT, True, [], {"published"}, False) == "reproduced"
    assert derive_status(s, EXACT, False, [], {"published"}, False) == "discrepant"
    assert derive_status(s, EXACT, False, [], {"convention"}, False, [(True, [])]) == "consistent"
    assert derive_status(s, EXACT, True, [True], {"assumed"}, False) == "consistent"
    assert derive_status(s, EXACT, True, [False], {"assumed"}, False) == "not-reproducible"
    assert derive_status(s, EXACT, False, [False], {"assumed"}, False) == "inconsistent"
    assert derive_status(s, EXACT, False, [False], {"assumed"}, True) == "discrepant"


def test_numpy_booleans_are_truth_values():
    """numpy 2 names its boolean scalar type 'bool', not 'bool_': a test of the type's name took
    a numpy boolean for a number (found by mutation testing)."""
    import numpy as np

    from navcore.claims.verdict import _is_truth, additive_envelope
    from navcore.ledger import text

    # oracle: the docstrings ("a Python or numpy boolean"; the envelope is None for a truth value)
    assert _is_truth(np.True_) and text._is_truth(np.False_)
    assert additive_envelope(np.True_, [("a", ((0, np.False_), (1, np.True_)))]) is None


def test_band_too_wide_takes_a_truth_valued_end_as_a_statements_band():
    # oracle: a band with a truth value at either end is compared as truth values (both the same:
    # decides), never as the numbers 1 and 5 (a factor 5 apart, which would be too wide)
    n = make(published=5.0)
    assert band_too_wide(n, ZERO, True, 5.0) is False
    assert band_too_wide(n, ZERO, 5.0, True) is False
    # the same ends as numbers: too wide
    assert band_too_wide(n, ZERO, 1.0, 5.0) is True
