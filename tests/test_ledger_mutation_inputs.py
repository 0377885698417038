"""The input registry: declarations, reads, overrides, recording and the input cache
(issue 31, mutation survivors). Synthetic input sets only; no paper module is imported.

Oracle in every test: the contract of :mod:`navcore.claims.inputs` as its docstrings state it,
checked on values chosen by hand: which reads a recording holds (only the innermost one), which
value a read returns under nested overrides (the inner one wins), when the input cache calls its
function again (a new argument key, or a changed value of an input it read) and what it replays.
"""

from __future__ import annotations

import numpy as np
import pytest

from navcore.claims.inputs import (
    NOMINAL_LABEL,
    OTHER_LABEL,
    Input,
    InputReadError,
    InputSet,
    _hashable,
    _label_and_unit,
    _same,
    _same_reads,
    all_inputs,
    declaring,
    get_input,
    input_cache,
    is_number,
    overriding,
    recording,
)

IN = InputSet("SP", "mutation_inputs")
IN.published("gain", 2.0, unit="dB", locator="Table 1", quantity="antenna gain")
IN.published("count", 4, unit="1", locator="Table 2")
IN.published("vec", np.array([1.0, 2.0]), locator="Eq. (3)")
IN.assumed("loss", 1.0, low=0.0, high=3.0, unit="dB", reason="typical cables", quantity="cable loss")
IN.convention("sign", 1.0, alternative=-1.0, reason="the sign is not printed")
IN.convention(
    "mode", "a", readings={"the first mode": "a", "the second mode": "b", "the third": "c"}, reason="three"
)
IN.fitted("k", 0.5, fitted_to=("SP-fit-1",), reason="solved from Table 4")

NAME = "SP.mutation_inputs."


# --- declarations -----------------------------------------------------------------------------


def _input(**kw) -> Input:
    base = dict(name="SP.mutation_inputs.tmp", paper="SP", value=1.0)
    base.update(kw)
    return Input(**base)


def test_input_checks_each_provenance():
    with pytest.raises(ValueError, match="provenance must be one of"):
        _input(provenance="guessed", reason="r")
    with pytest.raises(ValueError, match="needs the locator"):
        _input(provenance="published", locator="  ")
    for prov in ("convention", "assumed", "fitted"):
        with pytest.raises(ValueError, match=f"{prov} input .* needs a reason"):
            _input(provenance=prov, reason=" ", low=0.0, high=2.0, alternative=2.0, fitted_to=("x",))
    # a published input needs no reason; the others need no locator
    _input(provenance="published", locator="T1")
    # the assumed range: both ends, and the nominal within (the ends included)
    with pytest.raises(ValueError, match="plausible range"):
        _input(provenance="assumed", reason="r", low=0.0)
    with pytest.raises(ValueError, match="plausible range"):
        _input(provenance="assumed", reason="r", high=0.0)
    _input(provenance="assumed", reason="r", value=0.0, low=0.0, high=2.0)
    _input(provenance="assumed", reason="r", value=2.0, low=0.0, high=2.0)
    with pytest.raises(ValueError, match="must lie in"):
        _input(provenance="assumed", reason="r", value=2.0000001, low=0.0, high=2.0)
    with pytest.raises(ValueError, match="must lie in"):
        _input(provenance="assumed", reason="r", value=-0.0000001, low=0.0, high=2.0)
    # only a convention has readings
    with pytest.raises(ValueError, match="only a convention has readings"):
        _input(provenance="published", locator="T1", alternative=2.0)
    with pytest.raises(ValueError, match="only a convention has readings"):
        _input(provenance="assumed", reason="r", low=0.0, high=2.0, readings=(("x", 1.0), ("y", 2.0)))
    with pytest.raises(ValueError, match="must name the claims"):
        _input(provenance="fitted", reason="r")
    _input(provenance="fitted", reason="r", fitted_to=("SP-x",))


def test_convention_readings_are_checked_and_normalised():
    conv = _input(provenance="convention", reason="r", alternative=2.0)
    assert conv.readings == ((NOMINAL_LABEL, 1.0), (OTHER_LABEL, 2.0))
    assert conv.nominal_label == NOMINAL_LABEL and conv.other_readings == ((OTHER_LABEL, 2.0),)
    # readings given: the alternative is the first reading that is not the one used
    conv = _input(
        provenance="convention", reason="r", value=2.0, readings=(("x", 1.0), ("y", 2.0), ("z", 3.0))
    )
    assert conv.alternative == 1.0 and conv.nominal_label == "y"
    assert conv.other_readings == (("x", 1.0), ("z", 3.0))
    # an alternative given beside readings is kept
    conv = _input(
        provenance="convention", reason="r", value=2.0, alternative=3.0, readings=(("x", 2.0), ("z", 3.0))
    )
    assert conv.alternative == 3.0
    with pytest.raises(ValueError, match="needs its readings"):
        _input(provenance="convention", reason="r")
    with pytest.raises(ValueError, match="at least two readings, got 1"):
        _input(provenance="convention", reason="r", readings=(("x", 1.0),))
    with pytest.raises(ValueError, match="a label in words"):
        _input(provenance="convention", reason="r", readings=(("x", 1.0), (" ", 2.0)))
    with pytest.raises(ValueError, match="a label in words"):
        _input(provenance="convention", reason="r", readings=(("x", 1.0), (3, 2.0)))
    with pytest.raises(ValueError, match="labels must be distinct"):
        _input(provenance="convention", reason="r", readings=(("x", 1.0), ("x", 2.0)))
    with pytest.raises(ValueError, match=r"two readings have the value 1\.0"):
        _input(provenance="convention", reason="r", readings=(("x", 1.0), ("y", 2.0), ("z", 1.0)))
    with pytest.raises(ValueError, match="must be one of its readings"):
        _input(provenance="convention", reason="r", value=5.0, readings=(("x", 1.0), ("y", 2.0)))
    # arrays as readings are compared element by element
    conv = _input(
        provenance="convention",
        reason="r",
        value=np.array([1.0, 2.0]),
        readings=(("x", np.array([1.0, 2.0])), ("y", np.array([1.0, 3.0]))),
    )
    assert conv.nominal_label == "x"
    # non-conventions: no label, no other readings
    pub = _input(provenance="published", locator="T1")
    assert pub.nominal_label == "" and pub.other_readings == ()


def test_source_is_the_locator_or_the_reason():
    assert IN.input("gain").source() == "Table 1"
    assert IN.input("loss").source() == "typical cables"
    assert IN.input("k").source() == "solved from Table 4"


def test_input_set_declaration_rules():
    s = InputSet("SP", "mutation_inputs_decl")
    for bad in ("1x", "_x", "a-b", ""):
        with pytest.raises(ValueError, match="public identifier"):
            s.published(bad, 1.0, locator="T1")
    s.published("x", 1.0, locator="T1")
    with pytest.raises(ValueError, match="declared twice"):
        s.published("x", 1.0, locator="T1")
    # the same full name in another set object: the same declaration is accepted, another refused
    again = InputSet("SP", "mutation_inputs_decl")
    again.published("x", 1.0, locator="T1")
    other = InputSet("SP", "mutation_inputs_decl")
    with pytest.raises(ValueError, match="registered twice with different declarations"):
        other.published("x", 2.0, locator="T1")
    with pytest.raises(ValueError, match="give one of readings= and alternative="):
        s.convention("c", 1.0, readings={"a": 1.0, "b": 2.0}, alternative=2.0, reason="r")
    with pytest.raises(AttributeError, match="inputs are declared with"):
        s.x = 3.0
    with pytest.raises(AttributeError, match="has no input 'nope'"):
        s.nope  # noqa: B018
    assert repr(s) == "InputSet('SP', 'mutation_inputs_decl')"


def test_each_declaration_sets_its_fields():
    a = IN.input("loss")
    assert (a.name, a.paper, a.value, a.provenance, a.unit, a.quantity) == (
        NAME + "loss",
        "SP",
        1.0,
        "assumed",
        "dB",
        "cable loss",
    )
    assert (a.low, a.high, a.grid, a.admissible, a.reason) == (0.0, 3.0, 0, False, "typical cables")
    s = InputSet("SP", "mutation_inputs_fields")
    s.assumed("w", 2, low=1, high=3, reason="r", unit="m", quantity="q", grid=5, admissible=True)
    w = s.input("w")
    assert (w.grid, w.admissible, w.unit, w.quantity) == (5, True, "m", "q")
    s.fitted("f", 1.0, fitted_to=["SP-a", "SP-b"], reason="r", unit="s", quantity="fq")
    f = s.input("f")
    assert (f.fitted_to, f.unit, f.quantity, f.provenance) == (("SP-a", "SP-b"), "s", "fq", "fitted")
    s.convention("c", 1.0, readings={"one": 1.0, "two": 2.0}, reason="r", unit="ft", quantity="cq")
    c = s.input("c")
    assert (c.readings, c.unit, c.quantity) == ((("one", 1.0), ("two", 2.0)), "ft", "cq")
    s.convention("d", 1.0, alternative=3.0, reason="r")
    assert s.input("d").readings == ((NOMINAL_LABEL, 1.0), (OTHER_LABEL, 3.0))
    s.published("p", 5.0, locator="T9", unit="Hz", quantity="pq")
    p = s.input("p")
    assert (p.locator, p.unit, p.quantity) == ("T9", "Hz", "pq")
    assert [i.name.rsplit(".", 1)[1] for i in s] == ["w", "f", "c", "d", "p"]
    assert s.nominal("p") == 5.0


def test_all_inputs_filters_by_paper_and_get_input():
    names = [i.name for i in all_inputs("SP")]
    assert NAME + "gain" in names
    assert all(i.paper == "SP" for i in all_inputs("SP"))
    assert NAME + "gain" not in [i.name for i in all_inputs("WF")]
    assert NAME + "gain" in [i.name for i in all_inputs()]
    assert get_input(NAME + "gain") is IN.input("gain")
    with pytest.raises(ValueError, match=r"'SP\.nowhere\.x' is not a registered input"):
        get_input("SP.nowhere.x")


def test_label_and_unit():
    assert _label_and_unit(NAME + "gain") == ("antenna gain", "dB")
    assert _label_and_unit(NAME + "count") == ("count", "")  # unit "1": a pure number
    assert _label_and_unit(NAME + "sign") == ("sign", "")
    assert _label_and_unit("SP.nowhere.some_thing") == ("some thing", "")


# --- reads, recording, overrides, declaring -------------------------------------------------------


def test_recordings_nest_and_only_the_innermost_receives():
    with recording() as outer:
        _ = IN.gain
        with recording() as inner:
            _ = IN.loss
        _ = IN.sign
    assert sorted(outer) == [NAME + "gain", NAME + "sign"]
    assert list(inner) == [NAME + "loss"]
    assert outer[NAME + "gain"] is IN.input("gain")
    # a read outside any recording is not recorded, and works
    assert IN.gain == 2.0


def test_overrides_nest_inner_wins_and_are_undone():
    with overriding({NAME + "gain": 3.0, NAME + "loss": 2.0}):
        assert (IN.gain, IN.loss) == (3.0, 2.0)
        with overriding({NAME + "gain": 5.0}):
            assert (IN.gain, IN.loss) == (5.0, 2.0)
        assert (IN.gain, IN.loss) == (3.0, 2.0)
    assert (IN.gain, IN.loss) == (2.0, 1.0)
    with pytest.raises(ValueError, match="not a registered input"), overriding({"SP.nowhere.x": 1.0}):
        pass
    # an override undone after an exception
    with pytest.raises(RuntimeError), overriding({NAME + "gain": 9.0}):
        raise RuntimeError
    assert IN.gain == 2.0


def test_declaring_forbids_reads_and_ends():
    with (
        declaring(),
        pytest.raises(InputReadError, match=r"input SP.mutation_inputs.gain read while a tolerance"),
    ):
        IN.gain  # noqa: B018
    assert IN.gain == 2.0
    with pytest.raises(RuntimeError), declaring():
        raise RuntimeError
    assert IN.gain == 2.0


def test_same_and_hashable_and_is_number():
    assert _same(1.0, 1.0) and not _same(1.0, 2.0)
    assert _same(np.array([1.0, 2.0]), np.array([1.0, 2.0]))
    assert not _same(np.array([1.0, 2.0]), np.array([1.0, 3.0]))
    x = object()
    assert _same(x, x)
    # a comparison that raises falls back to the repr
    assert _same(np.array([1.0, 2.0]), np.array([1.0, 2.0, 3.0])) is False
    assert _same([1, 2], [1, 2])
    assert _hashable((1, 2)) == (1, 2)
    assert _hashable([1, 2]) == ("list", (1, 2))
    assert _hashable(([1], 2)) == ("tuple", (("list", (1,)), 2))
    assert _hashable({"a": 1}) == "{'a': 1}"
    key = _hashable(np.zeros((2, 3)))
    assert key[:3] == ("ndarray", "<f8", (2, 3)) and len(key[3]) == 32
    assert _hashable(np.zeros(3)) != _hashable(np.zeros(3, dtype=np.float32))
    assert _hashable(np.zeros(6)) != _hashable(np.zeros((2, 3)))
    assert _hashable(np.array([1, "a"], dtype=object)) == repr(np.array([1, "a"], dtype=object))
    assert is_number(1) and is_number(2.5)
    assert not is_number(True) and not is_number(float("inf")) and not is_number("1")


def test_same_reads():
    g, s = IN.input("gain"), IN.input("sign")
    assert _same_reads(((g, 2.0), (s, 1.0)), ((g, 2.0), (s, 1.0)))
    assert not _same_reads(((g, 2.0),), ((g, 2.0), (s, 1.0)))
    assert not _same_reads(((g, 2.0),), ((g, 3.0),))
    assert not _same_reads(((g, 2.0),), ((s, 2.0),))
    assert _same_reads((), ())


# --- the input cache --------------------------------------------------------------------------


def test_input_cache_keys_on_bound_arguments_with_defaults():
    calls = []

    @input_cache
    def f(x, flag=True):
        calls.append((x, flag))
        return IN.gain

    assert f(1) == 2.0
    assert f(x=1) == 2.0
    assert f(1, flag=True) == 2.0
    assert f(1, True) == 2.0
    assert calls == [(1, True)]
    assert f(1, flag=False) == 2.0
    assert calls == [(1, True), (1, False)]
    # unhashable arguments are keyed by their contents
    assert f([1]) == 2.0
    assert f([1]) == 2.0
    assert len(calls) == 3
    # a bad call reaches the function, which reports it
    with pytest.raises(TypeError):
        f(1, 2, 3)
    assert f.__name__ == "f"
    f.cache_clear()
    f(1)
    assert len(calls) == 4


def test_input_cache_two_inputs_one_overridden_miss_and_hit():
    calls = []

    @input_cache
    def g():
        calls.append(1)
        return IN.gain + 10.0 * IN.loss

    with overriding({NAME + "loss": 2.0}):
        with recording() as miss:
            assert g() == 22.0
        with recording() as hit:
            assert g() == 22.0
    assert len(calls) == 1
    assert sorted(miss) == sorted(hit) == [NAME + "gain", NAME + "loss"]
    # the nominal loss: a miss (the stored read had loss 2), then a hit; the override again: a hit
    assert g() == 12.0 and len(calls) == 2
    assert g() == 12.0 and len(calls) == 2
    with overriding({NAME + "loss": 2.0}):
        assert g() == 22.0
    assert len(calls) == 2
    # overriding the other input: a miss
    with overriding({NAME + "gain": 0.0}):
        assert g() == 10.0
    assert len(calls) == 3


def test_input_cache_keeps_at_most_256_variants_per_key():
    calls = []

    @input_cache
    def h():
        calls.append(1)
        return IN.loss

    values = [i / 100.0 for i in range(258)]
    for v in values:
        with overriding({NAME + "loss": v}):
            h()
    assert len(calls) == 258
    # the two oldest variants were dropped, the 256 newest kept
    with overriding({NAME + "loss": values[2]}):
        h()
    assert len(calls) == 258
    with overriding({NAME + "loss": values[0]}):
        h()
    assert len(calls) == 259


def test_input_cache_keys_an_array_argument_on_all_its_elements():
    """Oracle: the sums by hand. Two 2000-element arrays that differ only in the middle share
    their repr (numpy elides it), so a repr key would return the first array's result for the
    second; the key of the bytes tells them apart, and an equal array (another object) hits."""
    calls = []

    @input_cache
    def total(a):
        calls.append(1)
        return float(a.sum()) + IN.gain

    a, b = np.zeros(2000), np.zeros(2000)
    b[1000] = 1.0
    assert repr(a) == repr(b)
    with recording():
        assert total(a) == 2.0
        assert total(b) == 3.0
        assert total(b.copy()) == 3.0
    assert len(calls) == 2


def test_input_cache_finds_an_unhashable_value_equal_to_a_stored_one():
    """Oracle: equality of the values read, by hand. An array input is indexed by its repr; an
    override by an equal array (another object, another repr: -0.0) still finds the stored
    result, and a different array does not."""
    calls = []

    @input_cache
    def v():
        calls.append(1)
        return float(np.sum(IN.vec))

    with overriding({NAME + "vec": np.array([0.0, 1.0])}):
        assert v() == 1.0
    with overriding({NAME + "vec": np.array([-0.0, 1.0])}):
        assert v() == 1.0
    assert len(calls) == 1
    with overriding({NAME + "vec": np.array([0.0, 2.0])}):
        assert v() == 2.0
    assert len(calls) == 2


def test_input_cache_with_reads_that_depend_on_a_value():
    """Oracle: the branch taken, by hand. A computation that reads a second input only on one
    branch stores variants with two sets of inputs; each call finds the variant of its branch,
    and an override of the input read on one branch only misses that branch's variant."""
    calls = []

    @input_cache
    def b():
        calls.append(1)
        return IN.gain if IN.sign > 0 else IN.gain + IN.loss

    assert b() == 2.0
    with overriding({NAME + "sign": -1.0}):
        assert b() == 3.0
        assert b() == 3.0
    assert b() == 2.0
    assert len(calls) == 2
    with overriding({NAME + "loss": 2.0}):
        assert b() == 2.0  # the positive branch does not read the loss
        with overriding({NAME + "sign": -1.0}):
            assert b() == 4.0
    assert len(calls) == 3


def test_input_cache_prime_stores_batched_results():
    calls = []

    @input_cache
    def m(scale):
        calls.append(scale)
        return scale * IN.loss

    loss = IN.input("loss")
    m.prime([(((loss, 2.0),), "two"), (((loss, 3.0),), "three")], 1.0)
    # an entry already stored is kept (not replaced by a second prime)
    m.prime([(((loss, 2.0),), "other")], scale=1.0)
    with overriding({NAME + "loss": 2.0}), recording() as reads:
        assert m(1.0) == "two"
    assert list(reads) == [NAME + "loss"]
    with overriding({NAME + "loss": 3.0}):
        assert m(scale=1.0) == "three"
    assert calls == []
    # another argument key is not primed
    with overriding({NAME + "loss": 2.0}):
        assert m(2.0) == 4.0
    assert calls == [2.0]


def test_input_cache_prime_keeps_at_most_256_variants():
    calls = []

    @input_cache
    def m():
        calls.append(1)
        return IN.loss

    loss = IN.input("loss")
    m.prime([(((loss, i / 100.0),), f"r{i}") for i in range(258)])
    with overriding({NAME + "loss": 0.0}):
        assert m() == 0.0  # the oldest entry was dropped: computed
    with overriding({NAME + "loss": 0.05}):
        assert m() == "r5"
    assert len(calls) == 1


def test_input_cache_guard_inside_declaring():
    @input_cache
    def d():
        return 1.0

    with declaring(), pytest.raises(InputReadError, match="read while a tolerance"):
        d()


def test_an_input_set_records_the_module_that_made_it_through_a_mutation_wrapper():
    """Oracle: two modules made by hand: ``declarer`` makes an input set directly and through a
    function of a module named ``mutmut.trampoline_stand_in`` (as mutmut's trampoline calls a
    mutated ``__init__``); both sets name ``declarer``, never the wrapper."""
    from navcore.claims.inputs import InputSet

    wrapper = {"__name__": "mutmut.trampoline_stand_in", "InputSet": InputSet}
    exec("def make(paper, section):\n    return InputSet(paper, section)\n", wrapper)
    declarer = {"__name__": "declarer", "InputSet": InputSet, "make": wrapper["make"]}
    exec("direct = InputSet('WF', 'frame_direct')\nwrapped = make('WF', 'frame_wrapped')\n", declarer)
    assert declarer["direct"]._module == "declarer"
    assert declarer["wrapped"]._module == "declarer"
