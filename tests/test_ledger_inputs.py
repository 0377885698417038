"""Verdicts derived from evidence: inputs with provenance, bands, kinds, a-priori tolerances.

Two groups of tests:

* the derivation rules of LEDGER.md on synthetic claims and inputs built here (oracle: the
  rules written out by hand for each case);
* the real registry: every published input of each paper, perturbed in turn, moves the
  claims that read it (and makes the ledger fail); a wrong computed value changes the
  derived verdict, never the tolerance; no paper module memoises around the input registry.
"""

from __future__ import annotations

import dataclasses
import functools
import importlib.util
import re
import sys
from pathlib import Path

import pytest

from navcore import ledger
from navcore.claims.inputs import InputReadError, all_inputs, overriding, recording
from navcore.claims.json_coding import jsonable
from navcore.ledger import Claim, Evaluation, InputSet, Tolerance, evaluate, input_cache, printed, prose

ROOT = Path(__file__).resolve().parents[1]
TOL = Tolerance(reason="test", abs=0.5, policy="printed-digits")

# one synthetic input set for the rule tests (a name no paper module uses)
IN = InputSet("WF", "synthetic_test")
IN.published("gain", 2.0, locator="Eq. (99)", unit="")
IN.assumed("offset", 0.0, low=-1.0, high=3.0, reason="test range", unit="m")
IN.assumed("wall", 0.0, low=-1.0, high=1.0, reason="every admissible value", admissible=True)
IN.fitted("k", 5.0, fitted_to=("WF-test",), reason="solved from the printed value")
IN.convention("ft_per_ns", 1.0, alternative=0.9836, reason="the paper's c = 1 ft/ns")


def make(**kw):
    base = dict(
        id="WF-test",
        paper="WF",
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


# --- the derivation rules ---------------------------------------------------------------


def test_published_inputs_only_give_reproduced_or_discrepant():
    ev = evaluate(make())
    assert ev.status == "reproduced" and ev.passes
    assert [i["name"] for i in ev.inputs] == ["WF.synthetic_test.gain"]
    assert ev.inputs[0] == {
        "name": "WF.synthetic_test.gain",
        "provenance": "published",
        "locator": "Eq. (99)",
        "value": 2.0,
    }
    assert ev.band is None
    assert evaluate(make(compute=lambda: 6.0 * IN.gain)).status == "discrepant"


def test_assumed_input_band_decides_consistent_or_inconsistent():
    # 8 + offset over [-1, 3] spans [7, 11]: 10 is inside the band, the nominal 8 is not
    c = make(compute=lambda: 8.0 + IN.offset, expected_status="consistent")
    ev = evaluate(c)
    assert ev.band == (7.0, 11.0) and ev.status == "consistent" and ev.passes
    assert ev.reproduced == 8.0  # the value at the nominal is shown whatever the verdict
    assert dict(ev.sensitivity)["WF.synthetic_test.offset"] == ((-1.0, 7.0), (3.0, 11.0))
    far = evaluate(make(compute=lambda: 20.0 + IN.offset, expected_status="inconsistent"))
    assert far.status == "inconsistent" and far.band == (19.0, 23.0) and far.passes
    # agreement at the nominal with an assumed input is consistent, never reproduced
    assert evaluate(make(compute=lambda: 10.0 + IN.offset)).status == "consistent"


def test_disagreement_over_every_admissible_input_is_a_discrepancy():
    ev = evaluate(make(compute=lambda: 20.0 + IN.wall))
    assert ev.status == "discrepant"


def test_corners_of_two_assumed_inputs_enter_the_band():
    ev = evaluate(make(compute=lambda: 10.0 + IN.offset * IN.wall, expected_status="consistent"))
    # one at a time gives 10 only; the corners give -3 and 3 in the product
    assert ev.band == (7.0, 13.0)


def test_fitted_inputs_and_fit_and_cross_check_kinds_are_at_best_consistent():
    assert evaluate(make(compute=lambda: 2.0 * IN.k)).status == "consistent"
    assert evaluate(make(compute=lambda: 3.0 * IN.k)).status == "inconsistent"
    assert evaluate(make(compute=lambda: 10.0, kind="fit")).status == "consistent"
    assert evaluate(make(compute=lambda: 10.0, kind="cross-check")).status == "consistent"
    assert evaluate(make(compute=lambda: 12.0, kind="cross-check")).status == "discrepant"


def test_convention_shows_the_other_reading_in_the_note():
    ev = evaluate(make(compute=lambda: 10.0 * IN.ft_per_ns))
    assert ev.status == "reproduced"
    name = "WF.synthetic_test.ft_per_ns"
    assert [(r["reading"][name], r["nominal"], r["value"], r["agrees"]) for r in ev.readings] == [
        ("the reading used", True, 10.0, True),
        ("the other reading", False, 9.836, True),  # 9.836 is within 10 +- 0.5 too
    ]
    # the note names the input by its quantity (words), or by its last name part if it has none
    assert (
        "With the ft per ns read as the other reading (0.9836): 9.836 m, which agrees with the printed value."
        in ev.as_json()["note"]
    )
    assert "WF.synthetic_test" not in ev.as_json()["note"]


def test_expected_status_that_differs_from_the_derived_one_fails():
    ev = evaluate(make(expected_status="consistent"))
    assert ev.status == "reproduced" and not ev.passes and "differs from the expected" in ev.detail


def test_prose_words_come_from_one_table():
    assert prose("about").rel == 0.10 and prose("about").policy == "prose"
    with pytest.raises(ValueError, match="word must be one of"):
        prose("ish")


# --- tolerances and statuses cannot be computed from the model ---------------------------


def test_tolerance_is_resolved_before_compute_where_no_input_can_be_read():
    calls = []

    def tol_from_the_model():
        calls.append("tol")
        return printed(str(5.0 * IN.gain))[1]  # reads an input: forbidden

    def compute():
        calls.append("compute")
        return 5.0 * IN.gain

    ev = evaluate(make(tolerance=tol_from_the_model, compute=compute))
    assert not ev.passes and "InputReadError" in ev.detail
    assert calls == ["tol"]  # compute never ran


def test_a_paper_module_cannot_read_inputs_at_import(tmp_path):
    src = tmp_path / "guard_probe.py"
    src.write_text(
        "from navcore.ledger import InputSet\n"
        "IN = InputSet('WF', 'guard_probe')\n"
        "IN.published('x', 1.0, locator='Eq. (1)')\n"
        "TOLERANCE_FROM_MODEL = 2 * IN.x\n"
    )
    spec = importlib.util.spec_from_file_location("navcore.papers.guard_probe", src)
    module = importlib.util.module_from_spec(spec)
    try:
        with pytest.raises(InputReadError, match=r"while navcore\.papers\.guard_probe was imported"):
            spec.loader.exec_module(module)
    finally:
        sys.modules.pop("navcore.papers.guard_probe", None)


def test_input_cache_replays_reads_and_follows_overrides():
    runs = []

    @input_cache
    def heavy(scale):
        runs.append(scale)
        return scale * IN.gain

    with recording() as first:
        assert heavy(3.0) == 6.0
    with recording() as second:
        assert heavy(3.0) == 6.0  # from the memo, but the read is still recorded
    assert list(first) == list(second) == ["WF.synthetic_test.gain"] and runs == [3.0]
    with overriding({"WF.synthetic_test.gain": 4.0}):
        assert heavy(3.0) == 12.0
    assert heavy(3.0) == 6.0 and runs == [3.0, 3.0]


def test_input_declarations_are_checked():
    s = InputSet("WF", "synthetic_checks")
    with pytest.raises(ValueError, match="needs the locator"):
        s.published("a", 1.0, locator="")
    with pytest.raises(ValueError, match="plausible range"):
        s.assumed("b", 1.0, low=None, high=2.0, reason="r")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="must lie in"):
        s.assumed("c", 5.0, low=0.0, high=2.0, reason="r")
    with pytest.raises(ValueError, match="must name the claims"):
        s.fitted("d", 1.0, fitted_to=(), reason="r")
    with pytest.raises(ValueError, match="alternative"):
        s.convention("e", 1.0, alternative=None, reason="r")
    with pytest.raises(ValueError, match="not a registered input"):
        with overriding({"WF.nowhere.x": 1.0}):
            pass


# --- the real registry -------------------------------------------------------------------


def test_every_input_says_what_it_is():
    """The ledger, the Assumptions page and every claim's input list name an input by its
    quantity; without one a reader sees the attribute's spelling ("lc carrier bandwidth hz")."""
    ledger.claims()  # loads every paper module, and so declares every input
    modules = set(ledger.paper_modules())  # not the synthetic modules other tests declare
    unnamed = sorted(i.name for i in all_inputs() if i.module in modules and not i.quantity.strip())
    assert not unnamed, f"inputs without a quantity: {unnamed}"


def _perturbations(value):
    """Changes of a published scalar, smallest first: a statement may need a large one to flip."""
    if isinstance(value, bool):
        return [not value]
    if isinstance(value, int):
        return [value + 1, 2 * value + 1, 10 * value + 10]
    if isinstance(value, float):
        if not value:  # a zero has no scale of its own: small steps, then one large on any unit's scale
            return [0.1, 1.0, -1.0, 1000.0]
        steps = [value * f for f in (1.1, 2.0, 0.5, 10.0, 0.1, -1.0)]
        if 0.0 < value < 1.0:  # a probability or a fraction near 1 moves by its complement
            steps += [1.0 - (1.0 - value) * f for f in (0.5, 0.1)]
        return steps
    return []


def _moved(a, b) -> bool:
    if a.status != b.status:
        return True
    if isinstance(a.reproduced, bool) or isinstance(b.reproduced, bool) or a.reproduced is None:
        return a.reproduced != b.reproduced
    x, y = float(a.reproduced), float(b.reproduced)
    return abs(x - y) > 1e-12 * max(1.0, abs(x), abs(y))


def _value_moved(cid: str, name: str, new, base: Evaluation) -> bool:
    """Whether claim ``cid``'s value at the readings used moves with input ``name`` changed to
    ``new`` (one run of its model). A computation that raises does not move: a value the model
    refuses (a negative scale factor, a probability above 1) shows that the input is checked,
    not that it matters."""
    c = ledger.claim(cid)
    if c.compute is None or base.reproduced is None:
        return False
    try:
        with overriding({name: new}):
            value = c.compute()
    except Exception:
        return False
    if isinstance(base.reproduced, bool) or isinstance(value, bool):
        return bool(value) != bool(base.reproduced)
    x, y = float(value), float(base.reproduced)
    return abs(x - y) > 1e-12 * max(1.0, abs(x), abs(y))


def _status_moved(cid: str, name: str, new, base: Evaluation) -> bool:
    """Whether claim ``cid``'s evaluation without a band moves (:func:`_moved`) with input
    ``name`` changed to ``new``: its verdict also weighs the other readings' values. An
    evaluation whose computation raised does not move (as in :func:`_value_moved`)."""
    with overriding({name: new}):
        ev = evaluate(ledger.claim(cid), bands=False)
    return ev.reproduced is not None and _moved(ev, base)


def _input_moves(name: str, changes: list, readers: list[str], base: dict[str, Evaluation]) -> bool:
    """Whether some change of input ``name`` moves some reader's value or verdict.

    The values first, for every change and reader (a model run each; the readers share their
    runs through the input cache), then, only if no value moved, the evaluations without a
    band, whose verdicts also weigh the other readings. The order changes only how soon a mover
    is found, never whether.
    """
    for check in (_value_moved, _status_moved):
        for new in changes:
            if any(check(cid, name, new, base[cid]) for cid in readers):
                return True
    return False


@functools.cache
def _nominal(paper: str) -> dict[str, Evaluation]:
    """Every claim of the paper evaluated at its nominal inputs (no band), in this process.

    The base against which a perturbation is compared is the same kind of evaluation as the
    perturbed one, so that a claim moves only because its input changed (a status that
    differs only because the base had its band would count as moved, and a test built on it
    could not fail for that claim). It is also cheap: no band corner is run.
    """
    return {c.id: evaluate(c, bands=False) for c in ledger.claims(paper)}


def _readers(paper: str) -> tuple[dict[str, list[str]], list]:
    """Each published input of the paper that some claim reads, and its readers, cheapest first.

    A claim's input list is recorded from what its nominal computation read. The readers of
    an input are sorted numbers first (a number moves with almost any change of what it reads,
    a statement only when its truth flips), then by how many inputs they read (a closed form
    before a flyby or a Monte Carlo), so that an input's first mover is usually found without
    re-running a mission. The order changes only how soon a mover is found, never whether.
    """
    base = _nominal(paper)
    readers: dict[str, list[str]] = {}
    for e in base.values():
        for i in e.inputs:
            readers.setdefault(i["name"], []).append(e.claim.id)
    for ids in readers.values():
        ids.sort(key=lambda cid: (base[cid].claim.is_statement, len(base[cid].inputs), cid))
    published = [i for i in all_inputs(paper) if i.provenance == "published" and i.name in readers]
    return readers, [i for i in published if _perturbations(i.value)]


#: Published inputs that no change moves at the nominal inputs, found when the base of the test
#: below became the nominal evaluation (the banded base had let them pass), each with what was
#: found. They stay listed only while they stay silent: one that moves fails the test.
_KNOWN_SILENT = {
    "SP.tables.doppler_scale_factor_vertical_pct": (
        "read (through Table 2.8's Doppler error model) only by the helicopter target-location "
        "claims SP-sec2.6.4-doppler-50pct and -doppler-improves, whose nominal values are "
        "bit-identical for every change of it, x1000 included: open for the SP models (issue 29)"
    ),
    "SP.missions.headon_top_altitude_ft": (
        "Sec. 2.6.3's ingress height of the head-on mission, read only by the same two head-on "
        "statements as the 200 ft below, whose truth no change of it flips; it passed while a "
        "negated height (which the mission refuses) counted as a move"
    ),
    "SP.tables.accel_scale_factor_ppm_0p2": (
        "Table 2.5's 0.2 nmi/h accelerometer scale factor. Its own readers are the column's 1-h "
        "error, computed at rest (the specific force is vertical, so a scale-factor error adds no "
        "horizontal error), and Table 2.7's 0.2 nmi/h cells, whole code-phase intervals that no "
        "change from x0.1 to x10 moves; the other grades' claims list it only because the four "
        "grades (and a mission's systems) are computed in one run. It passed while a negated "
        "scale factor (which the IMU check refuses) counted as a move"
    ),
    "SP.residual.col4_rad_s_0p2": (
        "Table 2.6's natural frequency of the 0.2 nmi/h aided carrier loop, read by the jammer "
        "flyby. Its own readers are Table 2.7's 0.2 nmi/h cells (whole code-phase intervals) and "
        "orderings between systems, which no change from x0.1 to x10 moves (the 0.5, 1 and 10 "
        "nmi/h loops' frequencies do move their cells); the other systems' claims list it only "
        "because the flyby runs every system's loops at once. It passed while a negated "
        "frequency (which the loop refuses) counted as a move"
    ),
    "ATC10.tracking.convergence_fraction": (
        "Sec. 4.5.4's 10 % convergence criterion, read only by the statement that the rule "
        "2.3/psi - 1 counts the steps to within 'approximately' (10 %) in all six Table 4.3 "
        "cases: from a 1 % to a 91 % criterion the rule's count over the recursion's spans 0.1 "
        "to 2.5 and never brings all six within 10 %, so the finding stands for every change "
        "tried; it passed while a negative criterion (which the tolerance refuses) counted as a move"
    ),
    "SP.missions.headon_low_altitude_ft": (
        "Sec. 2.6.3's 200 ft sets how long the head-on mission dives; its only readers are the two "
        "head-on statements (SP-sec2.6.3-tc10-beats-lc1, SP-sec2.8-coupling-short-term), whose "
        "truth no change of it flips (x1.1 and +1 ft change the dive by less than its 1-s step; "
        "negated, the dive is 2 s longer and the orderings stay): the ingress height hardly moves "
        "an inertial error over the 159 s before release"
    ),
}

#: Chunks of each paper's published inputs, each a test of its own (a failure names fewer
#: inputs, and pytest-xdist can spread a paper's many inputs over its workers).
_INPUT_CHUNKS = {"WF": 1, "SP": 8, "ATC10": 3, "KZL": 3}

#: Papers whose nominal evaluation (:func:`_nominal`, cached per process) costs more than their
#: inputs' perturbations: their tests that read it run on one worker, which evaluates it once
#: (KZL's includes its Monte Carlo, about a minute). SP's perturbations (its missions and flyby
#: rerun under each change, minutes) are spread over the workers instead, each evaluating SP's
#: nominal claims once (about 15 s).
_ONE_WORKER = ("WF", "ATC10", "KZL")


def _paper_param(paper: str, *values):
    """``pytest.param(*values)``, on the paper's worker if the paper is one of :data:`_ONE_WORKER`
    (``--dist loadgroup``)."""
    marks = [pytest.mark.xdist_group(f"nominal-{paper}")] if paper in _ONE_WORKER else []
    return pytest.param(*values, marks=marks)


@pytest.mark.parametrize(
    ("paper", "chunk"),
    [_paper_param(p, p, k) for p in ledger.PAPERS for k in range(_INPUT_CHUNKS[p])],
    ids=lambda v: str(v),
)
def test_each_published_input_moves_the_claims_that_read_it(paper, chunk):
    """Change each published scalar input of the paper in turn (x1.1, +1 or negated; a
    fraction also by its complement).

    At least one claim that read it must move (its nominal value or its nominal verdict,
    against the nominal evaluation without the change). A change the model refuses (it
    raises) moves nothing: it shows that the input is checked, not that it matters. A claim's
    input list is recorded from what its computation read, so a reader that never moves
    points at a read that does not matter, and a claim missing from the readers would not be
    re-run. The inputs are split into chunks (every ``_INPUT_CHUNKS[paper]``-th input from
    the ``chunk``-th on).
    """
    readers, published = _readers(paper)
    if not published:
        pytest.skip(f"{paper} reads no published input yet")
    base = _nominal(paper)
    silent = []
    for inp in published[chunk :: _INPUT_CHUNKS[paper]]:
        moved = _input_moves(inp.name, _perturbations(inp.value), readers[inp.name], base)
        if moved and inp.name in _KNOWN_SILENT:
            pytest.fail(f"{inp.name} now moves a reader: remove it from _KNOWN_SILENT")
        if not moved and inp.name not in _KNOWN_SILENT:
            silent.append(f"{inp.name} (read by {readers[inp.name]})")
    assert not silent, "perturbing these published inputs moves none of their readers: " + "; ".join(silent)


@pytest.mark.parametrize("paper", [_paper_param(p, p) for p in ledger.PAPERS])
def test_a_perturbed_published_input_makes_the_ledger_fail(paper):
    """Some change of one published input of the paper makes a passing claim fail its check.

    The search stops at the first claim that passes at its nominal inputs and fails with one
    published input changed (the perturbations of the test above). It tries the claims
    without a band first, across every input: their nominal evaluation is the ledger's own.
    Only then the claims with a band, where the failure must be confirmed by the ledger's full
    evaluation (with the band) under the same change.
    """
    readers, published = _readers(paper)
    if not published:
        pytest.skip(f"{paper} reads no published input yet")
    base = _nominal(paper)

    def banded(cid: str) -> bool:
        return any(i["provenance"] == "assumed" for i in base[cid].inputs)

    for with_band in (False, True):
        for inp in published:
            for new in _perturbations(inp.value):
                for cid in readers[inp.name]:
                    if banded(cid) != with_band or not base[cid].passes:
                        continue
                    with overriding({inp.name: new}):
                        if evaluate(ledger.claim(cid), bands=False).passes:
                            continue
                        if not with_band or not evaluate(ledger.claim(cid)).passes:
                            return
    pytest.fail(f"no perturbation of a {paper} published input makes the ledger fail")


def _reading_values(readings) -> dict[str, object]:
    """Each convention reading's value, keyed by the readings of the conventions alone (a full
    evaluation adds the printed-precision readings of the tolerance, which change no value)."""
    out = {}
    for r in readings or ():
        conventions = {k: v for k, v in r["reading"].items() if k != "printed precision"}
        out[repr(sorted(conventions.items()))] = r["value"]
    return out


@pytest.mark.parametrize("paper", [_paper_param(p, p) for p in ledger.PAPERS])
def test_every_claims_value_is_the_stored_gates_bit_for_bit(paper):
    """Determinism: every claim's value, evaluated again here, in another process and another
    order (the paper's claims at their nominal inputs, no band run between them), is the value
    the ledger gate stored for this checkout, bit for bit: its reproduced value, the inputs it
    read and their values, and the value under each reading of its conventions.

    Oracle: the gate's own evaluation (``nox -s ledger -- --store``, on every core, one task
    per paper module), which CI hands to the test command in ``NAVCORE_TEST_CACHE_FROM``.
    Without a stored ledger there is nothing to compare with and the test skips; with one that
    was made from another checkout it fails (a stale store proves nothing). The bands are not
    re-run here (they are the same model functions under other inputs); ``nox -s ledger --
    --twice`` compares two whole evaluations, bands included.
    """
    import json
    import os

    from navcore.ledger import registry

    folder = os.environ.get("NAVCORE_TEST_CACHE_FROM")
    if not folder:
        pytest.skip("no stored ledger to compare with (CI passes its gate's in NAVCORE_TEST_CACHE_FROM)")
    stored_dir = Path(folder, "claims")
    differ, stale = [], []
    for cid, ev in _nominal(paper).items():
        try:
            stored = json.loads((stored_dir / f"{cid}.json").read_text())
        except OSError:
            stale.append(f"{cid} (not stored)")
            continue
        if stored.get("key") != registry._claim_key(cid):
            stale.append(f"{cid} (stored from other files)")
            continue
        fresh = {
            "reproduced": jsonable(ev.reproduced, round_trip=True),
            "inputs": jsonable(ev.inputs, round_trip=True),
            "readings": _reading_values(jsonable(ev.readings, round_trip=True)),
        }
        kept = {
            "reproduced": stored["reproduced"],
            "inputs": stored["inputs"],
            "readings": _reading_values(stored["readings"]),
        }
        # compared on the readings both evaluations ran (a full evaluation may run more of them)
        kept["readings"] = {k: v for k, v in kept["readings"].items() if k in fresh["readings"]}
        fresh["readings"] = {k: v for k, v in fresh["readings"].items() if k in kept["readings"]}
        if json.dumps(fresh, sort_keys=True) != json.dumps(kept, sort_keys=True):
            differ.append(f"{cid}: here {fresh['reproduced']!r}, stored {kept['reproduced']!r}")
    assert not stale, f"the stored ledger in {folder} is not this checkout's: " + "; ".join(stale[:10])
    assert not differ, "evaluated again, these claims differ from the stored ledger: " + "; ".join(differ)


def _wrong(claim: Claim, tol: Tolerance, expected: str):
    """A value that reverses the claim's agreement: far off the print if it agrees, the print if not."""
    disagrees = expected in ("discrepant", "inconsistent")
    if claim.is_statement:
        return claim.published if disagrees else not claim.published
    pub = float(claim.published)
    if disagrees:  # a value that satisfies the printed relation with room to spare
        margin = tol.allowed(pub) + abs(pub) + 1.0
        return {"=": pub, "<": pub - margin, "<=": pub - margin, ">": pub + margin, ">=": pub + margin}[
            claim.relation
        ]
    far = 100.0 * tol.allowed(pub) + 10.0 * abs(pub) + 1.0
    return pub - far if claim.relation in (">", ">=") else pub + far


@pytest.mark.parametrize("paper", list(ledger.PAPERS))
def test_a_wrong_value_changes_the_verdict_not_the_tolerance(paper):
    """Substitute a value that reverses the claim's agreement with the print (far outside it when
    the claim agrees, the printed value itself when it does not): the derived verdict changes and
    the ledger fails; the tolerance, fixed before the computation, stays what it was."""
    from navcore.claims.declarations import resolve_tolerance

    for c in ledger.claims(paper):
        if c.compute is None:
            continue
        tol = resolve_tolerance(c)
        wrong = _wrong(c, tol, c.expected_status)
        ev = evaluate(dataclasses.replace(c, compute=lambda w=wrong: w), bands=False)
        assert ev.tolerance == tol, c.id
        assert ev.status != c.expected_status, (c.id, ev.status)
        assert not ev.passes, c.id


def test_every_tolerance_has_a_policy_and_no_cross_check_or_fit_is_reproduced():
    for e in ledger.evaluations():
        assert e.tolerance is not None and e.tolerance.policy in ledger.POLICIES, e.claim.id
        if e.status == "reproduced":
            assert e.kind in ("reproduction", "statement"), e.claim.id
            assert all(i["provenance"] in ("published", "convention") for i in e.inputs), e.claim.id
        if e.status == "not-reproducible":
            # nothing computed, a band too wide to decide, or (beyond six assumed inputs) a printed
            # value the runs miss and the inputs' separate effects reach
            assert (
                (e.reproduced is None and e.claim.compute is None)
                or (e.band is not None and e.band_too_wide and e.envelope is None)
                or (e.band is not None and not e.band_too_wide and e.envelope is not None)
            ), e.claim.id


def test_paper_modules_memoise_only_through_input_cache():
    """functools caches would hide input reads from the ledger and ignore overrides."""
    offenders = []
    for path in sorted((ROOT / "navcore" / "papers").glob("*.py")):
        text = path.read_text()
        if re.search(r"^\s*@(functools\.)?(cache|lru_cache)\b", text, re.M):
            offenders.append(path.name)
    assert not offenders, f"use navcore.ledger.input_cache in {offenders}"
