"""The band runs, run by run, on synthetic inputs (issue 31, mutation survivors).

Each claim's computation logs the values of the inputs it read, so a test sees exactly which runs
``_band_runs`` made, in which order and under which overrides. No paper module is imported.

Oracle in every test: the module docstrings of :mod:`navcore.claims.runs` ("Band runs") and
:mod:`navcore.claims.verdict` ("Beyond six inputs", "Readings") written out by hand: each
assumed input one at a time over its band
points (the others nominal), then every corner of the box up to six inputs, beyond that the two
diagonal corners, the two half-and-half corners and the two steepest corners; the additive
envelope is the nominal value plus each input's largest rise and minus each largest fall.
"""

from __future__ import annotations

import itertools
import math

import pytest

from navcore._validate import ModelDomainError
from navcore.claims.inputs import Input, band_ahead, for_each_band_run
from navcore.claims.runs import MAX_READING_COMBINATIONS, _band_runs, _steepest_corners, reading_combinations
from navcore.claims.verdict import additive_envelope
from navcore.ledger import Claim, InputSet, Tolerance

TOL = Tolerance(reason="test", abs=0.5, policy="printed-digits")
IN = InputSet("KZL", "mutation_bands")
IN.assumed("a", 1.0, low=0.0, high=2.0, reason="test range")
IN.assumed("b", 10.0, low=5.0, high=20.0, reason="test range")
IN.assumed("g", 1.0, low=0.0, high=2.0, grid=3, reason="a gridded test range")
IN.assumed("n", 3, low=1, high=5, grid=4, reason="an integer test range")
for _i in range(7):
    IN.assumed(f"x{_i}", 0.5, low=0.0, high=1.0, reason="test range of the seven-input box")
for _i in range(5):
    IN.convention(f"c{_i}", 0.0, alternative=1.0, reason="a convention of the combination tests")
IN.convention("three", 1.0, readings={"one": 1.0, "two": 2.0, "three": 3.0}, reason="three readings")

NAME = "KZL.mutation_bands."


def make(compute) -> Claim:
    return Claim(
        id="KZL-test-mutation-bands",
        paper="KZL",
        locator="Eq. (1)",
        quantity="q",
        published=10.0,
        unit="m",
        compute=compute,
        tolerance=TOL,
        expected_status="consistent",
        note="a synthetic claim",
    )


def inputs(*names: str) -> list[Input]:
    return [IN.input(n) for n in names]


def test_band_points():
    # no grid: the two ends; grid 3: low, middle, high; an integer input: rounded, unique, sorted
    assert IN.input("a").band_points == (0.0, 2.0)
    assert IN.input("g").band_points == (0.0, 1.0, 2.0)
    assert IN.input("n").band_points == (1, 2, 4, 5)  # 1, 2.33, 3.67, 5 rounded
    assert all(isinstance(p, int) for p in IN.input("n").band_points)
    # a grid of 2 (or 1) is the two ends
    two = Input(
        name="KZL.mutation_bands.two",
        paper="KZL",
        value=1.0,
        provenance="assumed",
        low=0.0,
        high=4.0,
        grid=2,
        reason="r",
    )
    assert two.band_points == (0.0, 4.0)
    # a published input has no band
    pub = Input(name="KZL.mutation_bands.p", paper="KZL", value=1.0, provenance="published", locator="T1")
    assert pub.band_points == ()


def test_two_inputs_one_at_a_time_then_every_corner():
    log: list[tuple[float, float]] = []

    def compute():
        a, b = IN.a, IN.b
        log.append((a, b))
        return a * b

    values, sensitivity = _band_runs(make(compute), inputs("a", "b"))
    # one at a time (a over 0, 2 with b nominal; b over 5, 20 with a nominal), then the corners
    expected_runs = [
        (0.0, 10.0),
        (2.0, 10.0),
        (1.0, 5.0),
        (1.0, 20.0),
        (0.0, 5.0),
        (0.0, 20.0),
        (2.0, 5.0),
        (2.0, 20.0),
    ]
    assert log == expected_runs
    assert values == [a * b for a, b in expected_runs]
    assert sensitivity == [(NAME + "a", ((0.0, 0.0), (2.0, 20.0))), (NAME + "b", ((5.0, 5.0), (20.0, 20.0)))]


def test_one_input_has_no_corners_and_a_grid():
    log = []

    def compute():
        log.append(IN.g)
        return 3.0 * IN.g

    values, sensitivity = _band_runs(make(compute), inputs("g"))
    assert log == [0.0, 1.0, 2.0]  # one run per band point; no corner runs
    assert values == [0.0, 3.0, 6.0]
    assert sensitivity == [(NAME + "g", ((0.0, 0.0), (1.0, 3.0), (2.0, 6.0)))]


def test_base_overrides_are_kept_in_every_run():
    seen = []

    def compute():
        seen.append((IN.a, IN.b, IN.c0))
        return IN.a + IN.c0

    _band_runs(make(compute), inputs("a", "b"), base={NAME + "c0": 1.0})
    assert len(seen) == 8
    assert all(c0 == 1.0 for _, _, c0 in seen)


def test_runs_outside_the_models_domain_are_left_out_and_counted():
    def compute():
        if IN.a == 0.0:
            raise ModelDomainError("a is zero", case="no fix with a = 0")
        return IN.a + IN.b

    excluded: list[str] = []
    values, sensitivity = _band_runs(make(compute), inputs("a", "b"), excluded=excluded)
    # a = 0 in its one-at-a-time run and at the two corners with a low: three runs left out
    assert excluded == ["no fix with a = 0"] * 3
    assert sensitivity == [(NAME + "a", ((2.0, 12.0),)), (NAME + "b", ((5.0, 6.0), (20.0, 21.0)))]
    assert values == [12.0, 6.0, 21.0, 7.0, 22.0]
    # without a list to append to, the runs are left out all the same
    values2, _ = _band_runs(make(compute), inputs("a", "b"))
    assert values2 == values


def test_seven_inputs_run_diagonals_half_splits_and_steepest_corners():
    names = [f"x{i}" for i in range(7)]
    # increasing in x0..x3, decreasing in x4..x6: the steepest corners are (1,1,1,1,0,0,0) and its mirror
    weights = (1.0, 2.0, 3.0, 4.0, -5.0, -6.0, -7.0)
    log = []

    def compute():
        xs = [getattr(IN, n) for n in names]
        log.append(tuple(xs))
        return sum(w * x for w, x in zip(weights, xs, strict=True))

    values, _sensitivity = _band_runs(make(compute), inputs(*names))
    assert len(log) == 14 + 6
    corners = log[14:]
    lows, highs = (0.0,) * 7, (1.0,) * 7
    assert corners == [
        lows,
        highs,
        (0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0),  # the first half (7 // 2 = 3) low, the rest high
        (1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0),
        (1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0),  # each at the end that raised the value
        (0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0),  # each at the end that lowered it
    ]
    assert max(values) == 10.0 and min(values) == -18.0


def test_six_inputs_run_every_corner():
    names = [f"x{i}" for i in range(6)]
    log = []

    def compute():
        log.append(tuple(getattr(IN, n) for n in names))
        return 0.0

    _band_runs(make(compute), inputs(*names))
    assert log[12:] == list(itertools.product((0.0, 1.0), repeat=6))


def test_band_runs_are_announced_in_two_batches():
    batches = []

    def compute():
        got = for_each_band_run("mutation-bands", lambda: (IN.a, IN.b))
        if got:
            batches.append([v for _, v in got])
        return IN.a

    _band_runs(make(compute), inputs("a", "b"), base={NAME + "c1": 1.0})
    assert batches == [
        [(0.0, 10.0), (2.0, 10.0), (1.0, 5.0), (1.0, 20.0)],
        [(0.0, 5.0), (0.0, 20.0), (2.0, 5.0), (2.0, 20.0)],
    ]


def test_band_ahead_runs_on_top_of_the_active_overrides():
    from navcore.claims.inputs import overriding

    with overriding({NAME + "b": 7.0}), band_ahead([{NAME + "a": 2.0}]):
        got = for_each_band_run("mutation-bands-outer", lambda: (IN.a, IN.b))
    assert [v for _, v in got] == [(2.0, 7.0)]
    # the reads come back with the values of that run
    reads = got[0][0]
    assert [(i.name, v) for i, v in reads] == [(NAME + "a", 2.0), (NAME + "b", 7.0)]


def test_for_each_band_run_leaves_out_runs_outside_the_domain():
    def params():
        if IN.a > 1.0:
            raise ModelDomainError("too big", case="a above 1")
        return IN.a

    with band_ahead([{NAME + "a": 0.0}, {NAME + "a": 2.0}, {NAME + "a": 0.5}]):
        got = for_each_band_run("mutation-bands-domain", params)
        # the overrides of a run do not leak out of it
        assert IN.a == 1.0
    assert [v for _, v in got] == [0.0, 0.5]


def test_band_ahead_rejects_an_unknown_input():
    with pytest.raises(ValueError, match="not a registered input"):
        with band_ahead([{NAME + "nope": 1.0}]):
            pass


# --- _steepest_corners ------------------------------------------------------------------------


def _row(low_value, high_value, low=0.0, high=1.0):
    return ((low, low_value), (high, high_value))


def test_steepest_corners_directions_and_ties():
    xs = inputs("x0", "x1", "x2")
    sens = [("x0", _row(1.0, 2.0)), ("x1", _row(5.0, 3.0)), ("x2", _row(4.0, 4.0))]
    # rising, falling, flat (a tie goes high for the upper corner and low for the lower)
    assert _steepest_corners(xs, sens) == [[1.0, 0.0, 1.0], [0.0, 1.0, 0.0]]


@pytest.mark.parametrize(
    "row",
    [
        ((0.0, 1.0),),  # one point: no direction
        ((0.0, True), (1.0, 2.0)),  # a truth value at the low end
        ((0.0, 1.0), (1.0, False)),  # ... or at the high end
        ((0.5, 1.0), (1.0, 2.0)),  # the low end was left out of the domain
        ((0.0, 1.0), (0.5, 2.0)),  # the high end was left out
        ((0.0, "x"), (1.0, 2.0)),  # not a number
        ((0.0, None), (1.0, 2.0)),  # not a number (TypeError)
        ((0.0, math.inf), (1.0, 2.0)),
        ((0.0, 1.0), (1.0, math.nan)),
    ],
)
def test_steepest_corners_none_without_a_direction(row):
    xs = inputs("x0", "x1")
    sens = [("x0", _row(1.0, 2.0)), ("x1", row)]
    assert _steepest_corners(xs, sens) == []


# --- additive_envelope ------------------------------------------------------------------------


def test_additive_envelope_closed_form():
    # 10 + (max rise 2 of a) + (max rise 1 of b), 10 - (fall 1 of a) - (fall 0.5 of b)
    sens = [("a", ((0, 9.0), (1, 12.0), (2, 11.0))), ("b", ((0, 9.5), (1, 11.0)))]
    assert additive_envelope(10.0, sens) == (8.5, 13.0)
    # an input that only raises contributes no fall (min with 0), one that only lowers no rise
    assert additive_envelope(10.0, [("a", ((0, 11.0), (1, 12.0))), ("b", ((0, 8.0), (1, 9.0)))]) == (
        8.0,
        12.0,
    )
    # an input whose runs were all left out contributes nothing
    assert additive_envelope(10.0, [("a", ()), ("b", ((0, 9.0), (1, 13.0)))]) == (9.0, 13.0)
    assert additive_envelope(10.0, []) == (10.0, 10.0)
    # truth values in a row are skipped, a truth value at the nominal gives none
    assert additive_envelope(10.0, [("a", ((0, True), (1, 12.0)))]) == (10.0, 12.0)
    assert additive_envelope(True, [("a", ((0, 1.0), (1, 2.0)))]) is None


@pytest.mark.parametrize(
    ("value", "sens"),
    [
        (math.inf, [("a", ((0, 1.0), (1, 2.0)))]),
        (math.nan, []),
        (1.0, [("a", ((0, math.inf), (1, 2.0)))]),
        (1.0, [("a", ((0, 1.0), (1, math.nan)))]),
        ("ten", []),
        (None, []),
        (1.0, [("a", ((0, "x"), (1, 2.0)))]),
    ],
)
def test_additive_envelope_none_for_non_finite_or_non_numbers(value, sens):
    assert additive_envelope(value, sens) is None


# --- reading_combinations ---------------------------------------------------------------------


def _labels(combos):
    return [[label for _, label, _ in combo] for combo in combos]


def test_reading_combinations_all_of_them_up_to_the_cap():
    assert MAX_READING_COMBINATIONS == 16
    convs = inputs("c0", "three")
    combos = reading_combinations(convs)
    # the product, the readings used first, in declared order
    assert _labels(combos) == [
        ["the reading used", "one"],
        ["the reading used", "two"],
        ["the reading used", "three"],
        ["the other reading", "one"],
        ["the other reading", "two"],
        ["the other reading", "three"],
    ]
    assert [[v for _, _, v in c] for c in combos][4] == [1.0, 2.0]
    # four conventions of two readings: 16 combinations, all of them
    assert len(reading_combinations(inputs("c0", "c1", "c2", "c3"))) == 16


def test_reading_combinations_one_at_a_time_beyond_the_cap():
    convs = inputs("c0", "c1", "c2", "c3", "three")  # 2**4 * 3 = 48 > 16
    combos = reading_combinations(convs)
    used = ["the reading used"] * 4 + ["one"]
    expected = [used]
    for i in range(4):
        expected.append([*used[:i], "the other reading", *used[i + 1 :]])
    expected += [[*used[:4], "two"], [*used[:4], "three"]]
    assert _labels(combos) == expected
    # five conventions of two readings: 32 > 16, so 1 + 5 runs
    assert len(reading_combinations(inputs("c0", "c1", "c2", "c3", "c4"))) == 6
    assert reading_combinations([]) == [()]


def test_steepest_corners_read_the_ends_of_a_gridded_row():
    # a row of three points: the direction is from its first to its last point, not the middle
    xs = inputs("x0", "x1")
    sens = [("x0", ((0.0, 1.0), (0.5, 9.0), (1.0, 2.0))), ("x1", _row(5.0, 3.0))]
    assert _steepest_corners(xs, sens) == [[1.0, 0.0], [0.0, 1.0]]
