"""The ledger's summaries (counts, findings, input tables) on synthetic evaluations
(issue 31, mutation survivors: these functions had no test that reached them in the ledger's run).

Five synthetic claims of two papers read a fitted gain, an assumed loss over [1, 3] dB and a
convention (the loss counted once or halved), plus a cross-check and a claim whose computation
fails; three errata of two papers and both bases.

Oracle: the claims are closed forms, so every count, band end and verdict below is worked out by
hand from the verdict rule: ``a`` = 14 - scale * loss is 12 at the nominal (13 and 11 at the range's
ends) and agrees with its printed 12 under the reading used; ``b`` = 14 - 2 scale loss is 10 (12 to 8)
and its printed 13 agrees only with the other reading (14 - loss: 12, 13 at loss = 1). The text
layouts are those the functions' docstrings show.
"""

from __future__ import annotations

import pandas  # noqa: F401  (the frames import it; loaded once, at collection, not in a test)
import pytest

from navcore.ledger import Claim, Erratum, InputSet, Tolerance, evaluate
from navcore.ledger.summary import (
    _breakable,
    _fmt,
    _label,
    assumed_inputs_frame,
    convention_inputs_frame,
    count_table,
    finding_evidence,
    findings_count_table,
    findings_text,
    fitted_inputs_frame,
    input_readers,
    kind_counts_frame,
    prose_words_frame,
    sensitivity_frame,
    summary_text,
)

IN = InputSet("SP", "mutation_summary")
IN.assumed(
    "loss", 2.0, low=1.0, high=3.0, unit="dB", reason="typical receivers", quantity="implementation loss"
)
IN.fitted("gain", 14.0, fitted_to=("SP-test-sum-a", "SP-test-sum-b"), unit="dB", reason="solved from Table 4")
IN.convention("scale", 1.0, alternative=0.5, quantity="loss scale", reason="once or split")
IN.assumed("flag_x", 1.0, low=0.0, high=2.0, reason="a statement's input")
HALF = Tolerance(reason="t", abs=0.5, policy="printed-digits")
NAME = "SP.mutation_summary."


def _claim(cid: str, paper: str = "SP", **kw) -> Claim:
    base = dict(
        id=cid,
        paper=paper,
        locator="Table 1",
        quantity="q",
        published=12.0,
        unit="dB",
        compute=lambda: IN.gain - IN.scale * IN.loss,
        tolerance=HALF,
        expected_status="consistent",
        note="n",
    )
    base.update(kw)
    return Claim(**base)


def _boom() -> float:
    raise ZeroDivisionError


EVALS = [
    evaluate(_claim("SP-test-sum-a", aliases=("SP-old-a",))),
    evaluate(_claim("SP-test-sum-b", published=13.0, compute=lambda: IN.gain - 2.0 * IN.scale * IN.loss)),
    evaluate(_claim("SP-test-sum-x", kind="cross-check", compute=lambda: 12.0)),
    evaluate(_claim("WF-test-sum-w", paper="WF", compute=lambda: 12.0, expected_status="reproduced")),
    evaluate(_claim("WF-test-sum-e", paper="WF", compute=_boom, expected_status="reproduced")),
]
ERRATA = [
    Erratum(id="SP-E-sum1", paper="SP", locator="Eq. (1)", printed="a", finding="b", evidence="c",
            kind="units", basis="computed", claims=("SP-old-a",)),
    Erratum(id="WF-E-sum2", paper="WF", locator="Eq. (2)", printed="a", finding="b", evidence="c",
            kind="typography", basis="text-only"),
    Erratum(id="SP-E-sum3", paper="SP", locator="Eq. (3)", printed="a", finding="b", evidence="c",
            kind="typography", basis="text-only"),
]  # fmt: skip


def test_the_synthetic_claims_verdicts():
    assert [(e.status, e.passes) for e in EVALS] == [
        ("consistent", True),
        ("consistent", True),
        ("consistent", True),
        ("reproduced", True),
        ("error", False),
    ]


def test_count_table():
    zero = dict.fromkeys(("reproduced", "consistent", "inconsistent", "discrepant", "not-reproducible"), 0)
    assert count_table(EVALS) == [
        {"paper": "WF", "kind": "reproduction", **zero, "reproduced": 1, "error": 1, "total": 2},
        {"paper": "SP", "kind": "reproduction", **zero, "consistent": 2, "error": 0, "total": 2},
        {"paper": "SP", "kind": "cross-check", **zero, "consistent": 1, "error": 0, "total": 1},
        {"paper": "all", "kind": "all", **zero, "reproduced": 1, "consistent": 3, "error": 1, "total": 5},
    ]
    assert count_table([]) == [{"paper": "all", "kind": "all", **zero, "error": 0, "total": 0}]


def test_finding_evidence_by_the_claims_id_alias_or_erratum():
    named = evaluate(_claim("SP-test-sum-n", compute=lambda: 14.0 - IN.loss, erratum="SP-E-sum3"))
    pairs = finding_evidence(ERRATA, [*EVALS, named])
    assert [(e.id, [ev.claim.id for ev in evs]) for e, evs in pairs] == [
        ("SP-E-sum1", ["SP-test-sum-a"]),  # names the claim's former id
        ("WF-E-sum2", []),
        ("SP-E-sum3", ["SP-test-sum-n"]),  # named by the claim
    ]


def test_findings_count_table():
    kinds0 = dict.fromkeys(
        (
            "typography",
            "units",
            "convention",
            "derivation",
            "unstated-assumption",
            "inconsistent-numbers",
            "overstatement",
        ),
        0,
    )
    assert findings_count_table(ERRATA) == [
        {"paper": "WF", "basis": "text-only", **kinds0, "typography": 1, "total": 1},
        {"paper": "SP", "basis": "computed", **kinds0, "units": 1, "total": 1},
        {"paper": "SP", "basis": "text-only", **kinds0, "typography": 1, "total": 1},
        {"paper": "all", "basis": "computed", **kinds0, "units": 1, "total": 1},
        {"paper": "all", "basis": "text-only", **kinds0, "typography": 2, "total": 2},
        {"paper": "all", "basis": "all", **kinds0, "typography": 2, "units": 1, "total": 3},
    ]
    # one paper: no per-basis total rows
    one = findings_count_table(ERRATA[:1])
    assert [(r["paper"], r["basis"], r["total"]) for r in one] == [("SP", "computed", 1), ("all", "all", 1)]


SUMMARY = """\
findings (errata): 3, by paper, basis and kind
paper   basis      typo  units  conv  deriv  unstated  numbers  overstate  total
WF      text-only  1     0      0     0      0         0        0          1
SP      computed   0     1      0     0      0         0        0          1
SP      text-only  1     0      0     0      0         0        0          1
all     computed   0     1      0     0      0         0        0          1
all     text-only  2     0      0     0      0         0        0          2
all     all        2     1      0     0      0         0        0          3
The book works from transcriptions of the papers, so a text-only finding (the text of a formula or a
word, on which the printed numbers do not depend) cannot tell a misprint in the paper from a slip in
its transcription.

computed findings and the claims that are their evidence:
  SP-E-sum1 (units; Eq. (1)): SP-test-sum-a consistent

text-only findings and the claims that are their evidence:
  WF-E-sum2 (typography; Eq. (2)): no claim checks it
  SP-E-sum3 (typography; Eq. (3)): no claim checks it

claims by paper, kind and verdict:
paper   kind           reproduced  consistent  inconsistent  discrepant  not-reproducible  total
WF      reproduction   1           0           0             0           0                 2
SP      reproduction   0           2           0             0           0                 2
SP      cross-check    0           1           0             0           0                 1
all     all            1           3           0             0           0                 5
5 claims, 1 failing their check

fitted parameters (the claims they were fitted to are not evidence):
  SP.mutation_summary.gain = 14.0: fitted to SP-test-sum-a, SP-test-sum-b; read by 2 claims

assumed inputs (nominal, range) and the claims each moves:
  SP.mutation_summary.loss = 2.0 [1.0, 3.0] dB: 2 claims"""


def test_summary_text():
    text = summary_text(EVALS, ERRATA)
    assert [line.rstrip() for line in text.splitlines()] == SUMMARY.splitlines()
    # the claim counts' columns are padded to their width, the last (total) too
    assert (
        "\nWF      reproduction   1           0           0             0           0                 2    \n"
        in text
    )


def test_findings_text_without_text_only_findings_has_no_caveat():
    text = findings_text(EVALS, ERRATA[:1])
    assert "transcriptions" not in text
    assert text.splitlines()[-1] == "  SP-E-sum1 (units; Eq. (1)): SP-test-sum-a consistent"
    assert "text-only findings" not in text
    # no errata at all: the header, the column heads and the total row only
    assert findings_text(EVALS, []).splitlines() == [
        "findings (errata): 0, by paper, basis and kind",
        "paper   basis      typo  units  conv  deriv  unstated  numbers  overstate  total",
        "all     all        0     0      0     0      0         0        0          0",
    ]


def test_summary_text_without_fitted_or_assumed_inputs():
    text = summary_text(EVALS[2:4], [])
    assert "fitted parameters" not in text and "assumed inputs" not in text
    assert text.endswith("2 claims, 0 failing their check")


def test_input_readers():
    assert [(i.name, ids) for i, ids in input_readers(EVALS, "assumed")] == [
        (NAME + "loss", ["SP-test-sum-a", "SP-test-sum-b"])
    ]
    assert [(i.name, ids) for i, ids in input_readers(EVALS, "convention")] == [
        (NAME + "scale", ["SP-test-sum-a", "SP-test-sum-b"])
    ]
    assert input_readers(EVALS, "published") == []


def test_breakable_fmt_and_label():
    # a word longer than 14 characters gets a zero-width space after each of - . _ , /
    assert _breakable("SP-test-summary-a, x") == "SP-\u200btest-\u200bsummary-\u200ba,\u200b x"
    assert _breakable("a.b_c/d,e-f.g_hi") == "a.\u200bb_\u200bc/\u200bd,\u200be-\u200bf.\u200bg_\u200bhi"
    assert _breakable("SP-test-sum-a,") == "SP-test-sum-a,"  # 14 characters: left alone
    assert _breakable(12) == "12"
    assert _fmt((1.0, [2.5, "x"])) == "(1, (2.5, x))"
    assert _fmt("text") == "text"
    assert _fmt(2.0) == "2"
    assert _label(IN.input("loss")) == "implementation loss"
    assert _label(IN.input("flag_x")) == "flag x"


def test_kind_counts_frame():
    frame = kind_counts_frame(EVALS)
    assert list(frame.columns) == [
        "Paper",
        "Kind",
        "reproduced",
        "consistent",
        "inconsistent",
        "discrepant",
        "not-reproducible",
        "Total",
    ]
    assert frame.values.tolist() == [
        ["WF", "reproduction", 1, 0, 0, 0, 0, 2],
        ["SP", "reproduction", 0, 2, 0, 0, 0, 2],
        ["SP", "cross-check", 0, 1, 0, 0, 0, 1],
        ["all", "all", 1, 3, 0, 0, 0, 5],
    ]


def test_prose_words_frame():
    frame = prose_words_frame()
    assert list(frame.columns) == ["Word in the paper", "Band the ledger uses"]
    assert frame.values.tolist()[0] == ["about", "within ±10 %"]
    assert frame.values.tolist()[5] == ["roughly", "within ±20 %"]


def test_input_frames():
    frame = assumed_inputs_frame(EVALS)
    assert list(frame.columns) == ["Paper", "Input", "Nominal", "Range", "Unit", "Reason", "Claims"]
    assert frame.values.tolist() == [
        ["SP", "implementation loss", "2", "1 to 3", "dB", "typical receivers", 2]
    ]
    frame = fitted_inputs_frame(EVALS)
    assert list(frame.columns) == [
        "Paper",
        "Parameter",
        "Value",
        "Unit",
        "Fitted to",
        "Reason",
        "Claims reading it",
    ]
    assert frame.values.tolist() == [
        ["SP", "gain", "14", "dB", "SP-test-sum-a, SP-test-sum-b", "solved from Table 4", 2]
    ]
    frame = convention_inputs_frame(EVALS)
    assert list(frame.columns) == [
        "Paper",
        "Convention",
        "Reading used",
        "Other readings",
        "Unit",
        "Reason",
        "Claims",
        "Agree only under another reading",
    ]
    assert frame.values.tolist() == [
        [
            "SP",
            "loss scale",
            "the reading used (1)",
            "the other reading (0.5)",
            "",
            "once or split",
            2,
            "SP-test-sum-b",
        ]
    ]
    # empty: the columns all the same
    assert len(assumed_inputs_frame([]).columns) == 7 and len(assumed_inputs_frame([])) == 0
    assert len(fitted_inputs_frame([])) == 0 and len(convention_inputs_frame([])) == 0


def test_sensitivity_frame():
    frame = sensitivity_frame(EVALS)
    assert list(frame.columns) == [
        "Assumed input / claim",
        "Low end",
        "Nominal",
        "High end",
        "Printed",
        "Verdict",
    ]
    assert frame.values.tolist() == [
        ["implementation loss: SP-test-sum-a", "13", "12", "11", "12 dB", "consistent"],
        ["implementation loss: SP-test-sum-b", "12", "10", "8", "13 dB", "consistent"],
    ]
    # a statement's unit is not printed; an input missing from a claim's sensitivity is skipped
    s = evaluate(
        _claim(
            "SP-test-sum-s",
            published=True,
            unit="statement",
            kind="statement",
            tolerance=Tolerance(reason="exact", abs=0.0, policy="exact"),
            compute=lambda: IN.flag_x >= 0.0,
        )
    )
    frame = sensitivity_frame([s])
    assert frame.values.tolist() == [["flag x: SP-test-sum-s", "true", "true", "true", "true", "consistent"]]
    no_band = evaluate(_claim("SP-test-sum-nb", compute=lambda: 14.0 - IN.loss), bands=False)
    assert len(sensitivity_frame([no_band])) == 0


@pytest.mark.parametrize("evals", [[], EVALS[3:4]])
def test_frames_of_claims_without_inputs_are_empty(evals):
    assert len(sensitivity_frame(evals)) == 0
    assert len(assumed_inputs_frame(evals)) == 0


def test_summary_edges():
    from navcore.claims.inputs import Input

    # a paper with a reproduction and a fit, no cross-check or statement in between: both rows
    fit = evaluate(_claim("WF-test-sum-f", paper="WF", kind="fit", compute=lambda: 12.0))
    rep = evaluate(_claim("WF-test-sum-r", paper="WF", compute=lambda: 12.0, expected_status="reproduced"))
    assert [(r["paper"], r["kind"]) for r in count_table([rep, fit])] == [
        ("WF", "reproduction"),
        ("WF", "fit"),
        ("all", "all"),
    ]
    # a finding with two claims as its evidence: both listed, comma-separated
    e = Erratum(id="WF-E-sum4", paper="WF", locator="Eq. (4)", printed="a", finding="b", evidence="c",
                kind="units", basis="computed", claims=("WF-test-sum-f", "WF-test-sum-r"))  # fmt: skip
    assert findings_text([rep, fit], [e]).splitlines()[-1] == (
        "  WF-E-sum4 (units; Eq. (4)): WF-test-sum-r reproduced, WF-test-sum-f consistent"
    )
    # breakable words: runs of spaces kept, 15 characters broken, only - . _ , / broken after
    assert _breakable("a  b") == "a  b"
    assert _breakable("abcdefghij-klmn") == "abcdefghij-\u200bklmn"
    assert _breakable("SP-TEST-XXXXXXXXX") == "SP-\u200bTEST-\u200bXXXXXXXXX"
    # an input's name without a dot is its own label
    bare = Input(name="nodot_name", paper="SP", value=1.0, provenance="published", locator="T1")
    assert _label(bare) == "nodot name"
    # empty frames keep their columns
    assert len(fitted_inputs_frame([]).columns) == 7
    assert len(convention_inputs_frame([]).columns) == 8
    assert len(sensitivity_frame([]).columns) == 6


def test_convention_frame_with_three_readings_and_two_claims_agreeing_elsewhere():
    s = InputSet("SP", "mutation_summary_three")
    s.convention("k", 1.0, readings={"one": 1.0, "two": 2.0, "three": 3.0}, reason="three readings")
    # 4 k: 4 under the reading used, 8 and 12 under the others; printed 8 agrees only under "two"
    evs = [
        evaluate(_claim("SP-test-sum-k1", published=8.0, compute=lambda: 4.0 * s.k)),
        evaluate(_claim("SP-test-sum-k2", published=12.0, compute=lambda: 4.0 * s.k)),
    ]
    frame = convention_inputs_frame(evs)
    assert frame.values.tolist()[0][3] == "two (2); three (3)"
    # the first id, with its comma, is longer than 14 characters: it may break after - and ,
    assert frame.values.tolist()[0][7] == "SP-\u200btest-\u200bsum-\u200bk1,\u200b SP-test-sum-k2"


def test_sensitivity_frame_reads_the_ends_of_a_grid_and_skips_claims_without_a_band():
    s = InputSet("SP", "mutation_summary_grid")
    s.assumed("g", 1.0, low=0.0, high=2.0, grid=3, reason="a gridded range", quantity="g")
    no_band = evaluate(_claim("SP-test-sum-g0", compute=lambda: 11.0 + s.g), bands=False)
    banded = evaluate(_claim("SP-test-sum-g1", compute=lambda: 11.0 + s.g))
    frame = sensitivity_frame([no_band, banded])
    assert frame.values.tolist() == [["g: SP-test-sum-g1", "11", "12", "13", "12 dB", "consistent"]]
