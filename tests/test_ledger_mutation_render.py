"""The errata list, the findings table and the counts table, rendered from synthetic errata and
evaluations (issue 31, mutation survivors: rendering the ledger's tests did not read).

Oracle: the layout each class's docstring states (errata grouped by basis, computed first, the
text-only caveat said once under its heading; each entry's basis, kind, printed text, finding,
evidence and claims with their verdicts; the findings counted by paper, basis and kind), written
out by hand for two errata and checked fragment by fragment. The counts table is fed a
hand-written ``counts`` in place of the registry's, so no claim of a paper is evaluated.
"""

from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import pytest

from navcore.claims.declarations import TEXT_ONLY_CAVEAT
from navcore.claims.evaluation import Evaluation
from navcore.ledger import Claim, Erratum, Tolerance, evaluate
from navcore.ledger import tables as tables_module
from navcore.ledger.tables import CountsTable, ErrataList, FindingsTable, _claim_link_html
from navcore.ledger.text import _breakable_heading

#: one claim, a cross-check of a printed 12 that agrees (consistent)
EVALS = [
    evaluate(
        Claim(
            id="SP-test-sum-a",
            paper="SP",
            locator="Table 1",
            quantity="q",
            published=12.0,
            unit="dB",
            compute=lambda: 12.0,
            tolerance=Tolerance(reason="t", abs=0.5, policy="printed-digits"),
            expected_status="consistent",
            kind="cross-check",
            note="n",
        )
    )
]

E1 = Erratum(
    id="SP-E-rend1",
    paper="SP",
    locator="Eq. (1)",
    printed="$a + b$",
    finding="$a - b$",
    evidence="the <derivation>",
    kind="units",
    basis="computed",
    claims=("SP-test-sum-a", "SP-test-sum-zz"),
    discussed_in="sp/ch2",
)
E2 = Erratum(
    id="WF-E-rend2",
    paper="WF",
    locator="Table 2",
    printed="x_1",
    finding="y & z",
    evidence="c",
    kind="typography",
    basis="text-only",
)

LINK_A = (
    '<a href="../ledger.html#sp-test-sum-a"><code>SP-test-sum-a</code></a> '
    '<span class="ledger-badge ledger-status-consistent">consistent</span>'
)


def test_claim_link_and_heading():
    assert _claim_link_html("../", "SP-test-sum-a", "consistent") == LINK_A
    assert _claim_link_html("", "SP-x", None) == '<a href="ledger.html#sp-x"><code>SP-x</code></a>'
    assert _breakable_heading("unstated assumption") == "unstated<br>as&shy;sumption"
    assert _breakable_heading("not-reproducible") == "not-<wbr>repro&shy;ducible"
    assert _breakable_heading("a<b") == "a&lt;b"


def test_errata_list_html():
    out = ErrataList([E2, E1], root="../", titles={"sp/ch2": "Chapter <2>"}, evals=EVALS)._repr_html_()
    computed = out.index("<b>Computed findings</b> (1)")
    text_only = out.index("<b>Text-only findings</b> (1)")
    assert (
        computed < out.index('id="sp-e-rend1"') < text_only < out.index('id="wf-e-rend2"')
    )  # computed first
    assert out.count("transcriptions of the papers") == 1
    assert out.index("ledger-caveat") > text_only
    assert (
        '<div class="erratum erratum-computed" id="sp-e-rend1"><h4>SP-E-rend1 — SP, Eq. (1)</h4>'
        '<p class="erratum-basis"><b>Basis:</b> computed · <b>Kind:</b> units</p>'
        '<p><b>Printed:</b> <span class="math notranslate nohighlight">\\(a + b\\)</span></p>'
        '<p><b>The book finds:</b> <span class="math notranslate nohighlight">\\(a - b\\)</span></p>'
        "<p><b>Evidence:</b> the &lt;derivation&gt;</p>"
        f"<p><b>Claims (its evidence in the ledger):</b> {LINK_A}, "
        '<a href="../ledger.html#sp-test-sum-zz"><code>SP-test-sum-zz</code></a>. '
        'Discussed in <a href="../sp/ch2.html#sp-e-rend1">Chapter &lt;2&gt;</a>.</p></div>'
    ) in out
    assert (
        "<p><b>Printed:</b> x_1</p><p><b>The book finds:</b> y &amp; z</p><p><b>Evidence:</b> c</p>"
        "<p><b>Claims (its evidence in the ledger):</b> none.</p></div>"
    ) in out
    # no caveat when the page said it already; a page without a title says "the chapter"
    quiet = ErrataList([E2, E1], caveat=False)._repr_html_()
    assert "transcriptions" not in quiet
    assert 'Discussed in <a href="sp/ch2.html#sp-e-rend1">the chapter</a>.' in quiet
    assert ErrataList([])._repr_html_() == "<p>No errata registered.</p>"


def test_errata_list_sets_a_long_formula_in_a_box_cut_where_tex_may_break():
    """Oracle: the formula cut by hand after its relation and its outer binary operator, its
    pieces joined by line-break opportunities in a box of their own; a formula of up to 40
    characters stays inline in the sentence (printed, finding and evidence alike)."""
    long = "x_{DL}(k/k) = x_{DL}(k/k-1) + K_{DL}(k)[y_a(k) - x_{DL}(k/k-1)]"
    assert len(long) > 40
    e = Erratum(
        id="WF-E-rend3", paper="WF", locator="Eq. (13)", printed=f"${long}$", finding=f"so ${long}$",
        evidence="$a + b$ and " + "$" + "c" * 40 + "$", kind="typography", basis="text-only",
    )  # fmt: skip
    out = ErrataList([e])._repr_html_()
    m = '<span class="math notranslate nohighlight">'
    boxed = (
        f'<span class="ledger-math-wide">{m}\\(x_{{DL}}(k/k) ={{}}\\)</span><wbr>'
        f"{m}\\(x_{{DL}}(k/k-1) +{{}}\\)</span><wbr>"
        f"{m}\\(K_{{DL}}(k)[y_a(k) - x_{{DL}}(k/k-1)]\\)</span></span>"
    )
    assert f"<p><b>Printed:</b> {boxed}</p>" in out
    assert f"<p><b>The book finds:</b> so {boxed}</p>" in out
    assert f"<p><b>Evidence:</b> {m}\\(a + b\\)</span> and {m}\\({'c' * 40}\\)</span></p>" in out


def test_errata_list_latex_markdown_and_repr():
    el = ErrataList([E2, E1], evals=EVALS)
    assert el.latex().splitlines() == [
        r"\begingroup\sloppy",
        r"\par\medskip\noindent\textit{Computed findings (1)}\par",
        r"\par\medskip\noindent\textbf{SP-\allowbreak{}E-\allowbreak{}rend1} (SP, Eq. (1))\nopagebreak",
        r"\begin{itemize}",
        r"\item \textit{Basis:} computed; \textit{kind:} units",
        r"\item \textit{Printed:} $a + b$",
        r"\item \textit{The book finds:} $a - b$",
        r"\item \textit{Evidence:} the <derivation>",
        r"\item \textit{Claims (its evidence in the ledger):} "
        r"\texttt{SP-\allowbreak{}test-\allowbreak{}sum-\allowbreak{}a} (consistent); "
        r"\texttt{SP-\allowbreak{}test-\allowbreak{}sum-\allowbreak{}zz}",
        r"\end{itemize}",
        r"\par\medskip\noindent\textit{Text-only findings (1)}\par",
        r"\noindent{}" + TEXT_ONLY_CAVEAT + r"\par",
        r"\par\medskip\noindent\textbf{WF-\allowbreak{}E-\allowbreak{}rend2} (WF, Table 2)\nopagebreak",
        r"\begin{itemize}",
        r"\item \textit{Basis:} text-only; \textit{kind:} typography",
        r"\item \textit{Printed:} x\_1",
        r"\item \textit{The book finds:} y \& z",
        r"\item \textit{Evidence:} c",
        r"\item \textit{Claims (its evidence in the ledger):} none",
        r"\end{itemize}",
        r"\endgroup",
    ]
    assert "transcriptions" not in ErrataList([E2], caveat=False).latex()
    assert el._repr_markdown_() == "```{raw} latex\n" + el.latex() + "\n```"
    assert ErrataList([])._repr_markdown_() == "No errata registered."
    assert (
        repr(el)
        == "SP-E-rend1: SP, Eq. (1) (computed, units)\nWF-E-rend2: WF, Table 2 (text-only, typography)"
    )
    assert repr(ErrataList([])) == "No errata registered."


def test_findings_table():
    ft = FindingsTable([E1, E2], EVALS, root="../", list_findings=True)
    assert repr(ft).splitlines() == [
        "Paper  Basis  typography  units  convention  derivation  unstated assumption  inconsistent numbers  "
        "overstatement  Findings",
        "WF  text-only  1  0  0  0  0  0  0  1",
        "SP  computed  0  1  0  0  0  0  0  1",
        "all  computed  0  1  0  0  0  0  0  1",
        "all  text-only  1  0  0  0  0  0  0  1",
        "all  all  1  1  0  0  0  0  0  2",
    ]
    out = ft._repr_html_()
    assert out.startswith(
        '<div class="ledger-counts-wrap"><table class="ledger-counts ledger-findings"><thead><tr>'
        "<th>Paper</th><th>Basis</th><th>typo&shy;graphy</th><th>units</th>"
    )
    assert "<tr><td>SP</td><td>computed</td><td>0</td><td>1</td>" in out
    assert out.count(TEXT_ONLY_CAVEAT) == 1
    assert (
        '<tr><td><a href="../errata.html#sp-e-rend1"><code>SP-E-rend1</code></a><br>'
        '<span class="ledger-locator">SP, Eq. (1)</span></td><td>computed</td><td>units</td>'
        f"<td>{LINK_A}</td></tr>"
    ) in out
    assert (
        "<td>text-only</td><td>typography</td><td>no claim checks it</td></tr></tbody></table></div>" in out
    )
    md = ft._repr_markdown_()
    assert "\n\n" + TEXT_ONLY_CAVEAT + "\n\n" in md
    assert r"SP-\allowbreak{}E-\allowbreak{}rend1 & computed & units & " in md
    assert "(consistent)" in md and "no claim checks it" in md
    assert md.count("\\begin{longtable}") == 2
    # computed findings only, not listed: no caveat, no list
    plain = FindingsTable([E1])
    assert plain._caveat() == ""
    assert "ledger-findings-list" not in plain._repr_html_() and "ledger-caveat" not in plain._repr_html_()
    assert plain._repr_markdown_().count("\\begin{longtable}") == 1
    assert TEXT_ONLY_CAVEAT not in plain._repr_markdown_()


@pytest.fixture
def fake_counts(monkeypatch):
    rows = {
        "SP": {
            "reproduced": 3,
            "consistent": 1,
            "inconsistent": 0,
            "discrepant": 2,
            "not-reproducible": 0,
            "total": 6,
        },
        "WF": {
            "reproduced": 1,
            "consistent": 0,
            "inconsistent": 1,
            "discrepant": 0,
            "not-reproducible": 1,
            "total": 3,
        },
    }
    monkeypatch.setattr(
        tables_module, "counts", lambda paper: {p: r for p, r in rows.items() if paper in (None, p)}
    )
    passes = {"SP": [True, False, False], "WF": [True]}
    monkeypatch.setattr(
        tables_module,
        "evaluations",
        lambda paper: [SimpleNamespace(passes=ok) for ok in passes[paper]],
    )


def test_counts_table(fake_counts):
    t = CountsTable()
    assert t.failing == {"SP": 2, "WF": 0}
    assert repr(t).splitlines() == [
        "Paper  reproduced  consistent  inconsistent  discrepant  not-reproducible  total  failing check",
        "SP  3  1  0  2  0  6  2",
        "WF  1  0  1  0  1  3  0",
        "all  4  1  1  2  1  9  2",
    ]
    out = t._repr_html_()
    assert out.startswith(
        '<div class="ledger-counts-wrap"><table class="ledger-counts"><thead><tr><th>Paper</th>'
    )
    assert "<th>repro&shy;duced</th>" in out and "<th>failing<br>check</th>" in out
    assert (
        "<tr><td>all</td><td>4</td><td>1</td><td>1</td><td>2</td><td>1</td><td>9</td><td>2</td></tr>" in out
    )
    assert out.endswith("</tbody></table></div>")
    assert (
        r"all & \mbox{4} & \mbox{1} & \mbox{1} & \mbox{2} & \mbox{1} & \mbox{9} & \mbox{2} \\"
        in t._repr_markdown_()
    )
    # one paper: no total row
    one = CountsTable("WF")
    assert repr(one).splitlines()[1:] == ["WF  1  0  1  0  1  3  0"]


def test_small_pieces_of_the_ledger_page():
    from navcore.claims.evaluation import _n_runs, left_out_of_band
    from navcore.ledger.interactive import InteractiveLedger, _band_html, _left_out_brief
    from navcore.ledger.tables import LedgerTable
    from navcore.ledger.text import _md_escape, quote_text

    assert (_n_runs(0), _n_runs(1), _n_runs(2)) == ("0 runs", "1 run", "2 runs")
    two = SimpleNamespace(left_out=({"case": "no fix", "runs": 1}, {"case": "a gap", "runs": 3}))
    assert left_out_of_band(two) == "no fix (1 run); a gap (3 runs)"
    assert _left_out_brief(two) == "4 runs left out"
    assert _left_out_brief(SimpleNamespace(left_out=({"case": "x", "runs": 1},))) == "1 run left out"
    assert _md_escape("a|b\nc") == "a\\|b c"
    assert quote_text("so that $$x &= 1 \\quad (3)$$ holds for $p_d$") == "so that $x = 1$ holds for $p_d$"
    assert quote_text("no formula, 5 %") == "no formula, 5 %"
    assert _band_html({"band": None}, "m") == "" and _band_html({}, "m") == ""
    assert _band_html({"band": [0.5, 2.0]}, "m") == "0.5 –&nbsp;2&nbsp;m"
    assert _band_html({"band": [0.5, 2.0]}, "statement") == "0.5 –&nbsp;2"
    assert _band_html({"band": [0.5, 2.0]}, "") == "0.5 –&nbsp;2"
    assert _band_html({"band": [True, True]}, "statement") == "holds throughout"
    assert _band_html({"band": [False, False]}, "statement") == "fails throughout"
    assert _band_html({"band": [True, False]}, "statement") == "holds for some inputs"
    assert _band_html({"band": [0.0, True]}, "statement") == "holds for some inputs"
    # (their text form, text_table, imports every paper module for the errata: not here)
    il = InteractiveLedger(EVALS)
    assert il._repr_markdown_() == "```{raw} latex\n" + LedgerTable(EVALS, show_notes=False).latex() + "\n```"


def test_latex_table_widths_by_hand():
    from navcore.ledger.tables import latex_table

    # one long text column (70 letters, breakable every 7: widest piece 7 x 4 pt = 28 pt) and one
    # number column; 70 characters wide in all, so the columns are proportional (p{...}), not l/r
    block = latex_table(["A", "B"], [["x" * 70, "1"], ["[y]"]])
    lines = block.splitlines()
    # long text: 12 + (mean length of its cells, (70 + 3) / 2) ** 0.75 characters of 4 pt
    need_text = (12.0 + ((70 + 3) / 2) ** 0.75) * 4.0
    need_number = 3 * 4.0  # at least 3 characters
    # the page has room for both (share 1): each column gets its need plus 8 pt of padding
    w0, w1 = need_text + 8.0, need_number + 8.0
    assert (
        lines[1]
        == r"\begingroup\footnotesize\setlength{\tabcolsep}{4pt}\hyphenpenalty=10000\exhyphenpenalty=10000"
    )
    assert lines[2] == (
        r"\begin{longtable}{>{\raggedright\arraybackslash}p{\dimexpr "
        + f"{w0 / (w0 + w1):.4f}"
        + r"\linewidth-2\tabcolsep\relax}>{\raggedleft\arraybackslash}p{\dimexpr "
        + f"{w1 / (w0 + w1):.4f}"
        + r"\linewidth-2\tabcolsep\relax}}"
    )
    assert lines[3] == r"\hline \textbf{A} & \textbf{B} \\ \hline \endfirsthead"
    assert lines[4] == r"\hline \textbf{A} & \textbf{B} \\ \hline \endhead"
    assert lines[5] == r"\hline \endfoot"
    assert lines[6] == r"\allowbreak{}".join(["x" * 7] * 10) + r" & \mbox{1} \\"
    # a short row is padded; a cell starting with "[" is protected from reading as an option
    assert lines[7] == r"{}[y] &  \\"
    assert lines[8:] == [r"\end{longtable}", r"\endgroup", "```"]
    assert lines[0] == "```{raw} latex"


def test_latex_table_narrow_and_crowded():
    from navcore.ledger.tables import latex_table

    # 60 characters or fewer: the natural width, l and r columns
    narrow = latex_table(["Paper", "Claims", "Note"], [["SP", "155", "ok"], ["KZL", "4.5 %", "-"]])
    assert r"\begin{longtable}{lrl}" in narrow
    assert r"KZL & \mbox{4.5 \%} & - \\" in narrow
    # a column with a blank cell is still numeric; an empty column is not
    assert r"\begin{longtable}{rl}" in latex_table(["n", "e"], [["1", ""], ["", ""]])
    # words that cannot break and do not fit the line: one size smaller
    crowded = latex_table([f"H{i}" for i in range(10)], [["abcdefghijkl" * 1] * 10])
    assert r"\begingroup\scriptsize" in crowded
    assert r"\begingroup\footnotesize" in latex_table([f"H{i}" for i in range(5)], [["abcdefghijkl"] * 5])


#: a sentence of 130 characters, long enough to be said once for a group (at least 120)
LONG = (
    "The scenario flies a straight track at "
    + "constant speed " * 5
    + "over a flat earth with four ground stations in view."
)


def test_common_opening():
    from navcore.ledger.tables import _common_opening

    assert len(LONG) >= 120
    a, b = LONG + " Then a.", LONG + " Then b."
    assert _common_opening([a, b]) == LONG
    # too short a common opening, an empty note, no notes: none
    assert _common_opening(["Short. Then a.", "Short. Then b."]) == ""
    assert _common_opening([a, ""]) == "" and _common_opening([]) == ""
    # a note that is nothing but the opening keeps no text of its own: none
    assert _common_opening([a, LONG + " "]) == ""
    # a full stop after an abbreviation or inside math does not end a sentence
    abbrev = LONG[:-1] + " e.g. more text here. Then a."
    assert _common_opening([abbrev, LONG[:-1] + " e.g. more text here. Then b."]) == (
        LONG[:-1] + " e.g. more text here."
    )
    assert _common_opening([LONG[:-1] + " e.g. x", LONG[:-1] + " e.g. y"]) == ""
    math_note = LONG + " $a. b$ c. Then"
    assert _common_opening([math_note + " a.", math_note + " b."]) == LONG + " $a. b$ c."
    assert _common_opening([LONG + " $a. b", LONG + " $a. c"]) == LONG
    # the notes differ inside the first sentence: none
    assert _common_opening([LONG + " x.", "X" + LONG[1:] + " x."]) == ""


def test_locator_detail_and_shared_label():
    from navcore.ledger.tables import _locator_detail, _shared_label

    assert _locator_detail("Table 2.6", "Table 2.6") == ""
    assert _locator_detail("Table 2.6, column 2", "Table 2.6") == "column 2"
    assert _locator_detail("Table 2.6; row 1", "Table 2.6") == "row 1"
    assert _locator_detail("Eq. (3)", "Eq. (3") == "Eq. (3)"  # the rest is a closing bracket
    assert _locator_detail("Table 2.6,", "Table 2.6") == "Table 2.6,"
    assert _locator_detail("Fig. 3", "Table 2.6") == "Fig. 3"
    assert _shared_label(3, 3) == "note for these 3 claims"
    assert _shared_label(2, 3) == "note shared by 2 of these 3 claims"


def _ev(cid, locator, note, unit="m"):
    return Evaluation(
        Claim(
            id=cid,
            paper="SP",
            locator=locator,
            quantity="q",
            published=1.0,
            unit=unit,
            compute=lambda: 1.0,
            tolerance=Tolerance(reason="t", abs=0.5, policy="printed-digits"),
            expected_status="reproduced",
            note=note,
        ),
        1.0,
        True,
        "d",
        status="reproduced",
        tolerance=Tolerance(reason="t", abs=0.5, policy="printed-digits"),
    )


def test_group_claims_and_what_a_group_shares():
    from navcore.ledger.tables import group_claims

    evs = [
        _ev("SP-g1", "Table 2.6, column 1", LONG + " One."),
        _ev("SP-g2", "Table 2.6, column 2", LONG + " Two."),
        _ev("SP-g3", "Table 2.6, column 2", LONG + " Three."),
        _ev("SP-g4", "Fig. 3", "Alone."),
    ]
    groups = group_claims(evs)
    # g2 and g3 share a locator: a run of their own; g1 is grouped by its table
    assert [(g.label, g.heading, [e.claim.id for e in g.evals]) for g in groups] == [
        ("Table 2.6", "Table 2.6, column 1", ["SP-g1"]),
        ("Table 2.6, column 2", "Table 2.6, column 2", ["SP-g2", "SP-g3"]),
        ("Fig. 3", "Fig. 3", ["SP-g4"]),
    ]
    g = groups[1]
    assert g.shared == {"tolerance": "±0.5: t", "note": LONG}
    assert g.shared_by == 2
    assert [g.own(i) for i in range(2)] == [{"note": "Two."}, {"note": "Three."}]
    # a single claim shares nothing
    assert groups[0].shared == {} and groups[0].shared_by == 0
    assert groups[0].own(0) == {"note": LONG + " One.", "tolerance": "±0.5: t"}
    # three claims, two of them opening alike: the opening is shared by two, their notes go on with "…"
    trio = group_claims(
        [
            _ev("SP-t1", "Eq. (1)", LONG + " One."),
            _ev("SP-t2", "Eq. (1)", "Other. " + LONG),
            _ev("SP-t3", "Eq. (1)", LONG + " Three."),
        ]
    )[0]
    assert trio.shared["note"] == LONG and trio.shared_by == 2
    assert [d["note"] for d in trio.details] == ["… One.", "Other. " + LONG, "… Three."]
    assert trio.own(1)["note"] == "Other. " + LONG
    # identical notes are shared whole
    same = group_claims([_ev("SP-s1", "Eq. (2)", "Same."), _ev("SP-s2", "Eq. (2)", "Same.")])[0]
    assert same.shared == {"note": "Same.", "tolerance": "±0.5: t"} and same.shared_by == 2
    assert same.own(0) == {}


def test_details_html_and_tex():
    from navcore.ledger.tables import _details_html, _details_tex

    d = {"note": "A note", "tolerance": "±0.5: t", "band": "1 to 2 m", "inputs": "x = 1 (published)"}
    assert _details_html(d) == (
        "<p>A note</p><p><i>Tolerance:</i> ±0.5: t</p><p><i>Over the assumed inputs' ranges:</i> 1 to 2 m</p>"
        "<p><i>Inputs:</i> x = 1 (published)</p>"
    )
    assert _details_html({"note": "", "band": "b"}) == "<p><i>Over the assumed inputs' ranges:</i> b</p>"
    assert _details_tex(d) == (
        r"A note. \textit{Tolerance:} ±0.5: t. \textit{Over the assumed inputs' ranges:} 1 to 2 m."
    )
    assert _details_tex({"note": "Done!", "tolerance": "(x)"}) == r"Done! \textit{Tolerance:} (x)"


def test_json_and_csv_exports():
    import csv
    import io
    import json

    from navcore.ledger.tables import csv_export, json_dump, json_export
    from navcore.provenance import BuildProvenance

    build = BuildProvenance("0" * 40, "clean", "2026-01-01T00:00:00+00:00", "f" * 64, "3.11.7", ())
    e = _ev("SP-j1", "Eq. (1)", "Ünïcode note")
    dumped = json_dump([e])
    assert json.loads(dumped) == [e.as_json()]
    assert "Ünïcode" in dumped and '\n  {\n    "id": "SP-j1",' in dumped  # Unicode kept, two-space indent
    exported = json_export([e], build)
    assert json.loads(exported) == {"provenance": build.as_dict(), "claims": [e.as_json()]}
    assert exported.startswith('{\n  "provenance": {') and "Ünïcode" in exported
    text = csv_export([e, e], build)
    table = list(csv.DictReader(io.StringIO(text)))
    assert len(table) == 2 and table[0]["id"] == "SP-j1" and table[0]["note"] == "Ünïcode note"
    assert table[0]["build_commit"] == "0" * 40 and table[1]["build_lock_sha256"] == "f" * 64
    assert text.splitlines()[0].startswith("id,locator,quantity,published,")
    assert text.endswith("\r\n")
    # no claims: a header of the id and the build's columns
    assert csv_export([], build).splitlines() == ["id," + ",".join(build.flat())]


def _table_claims():
    import dataclasses

    a = _ev("SP-g2", "Table 2.6, column 2", LONG + " Two.")
    b = _ev("SP-g3", "Table 2.6, column 2", LONG + " Three.")
    c = _ev("SP-g4", "Fig. 3", "Alone.")
    claim = dataclasses.replace(
        c.claim, erratum="SP-E-x", discussed_in="sp/ch3", kind="cross-check", expected_status="consistent"
    )
    readings = (
        {"reading": {"SP.x.y": "r0"}, "nominal": True, "value": 1.0, "band": None, "agrees": False},
        {"reading": {"SP.x.y": "r1"}, "nominal": False, "value": 1.0, "band": None, "agrees": True},
    )
    c = dataclasses.replace(c, claim=claim, passes=False, status="discrepant", readings=readings)
    return a, b, c


#: The ledger table of three claims as the class docstring lays it out (reviewed line by line):
#: a group of two sharing a locator, whose common note and tolerance are said once in its header,
#: and a failing discrepant cross-check with an erratum and an agreeing other reading.
TABLE_HTML = (
    '<div class="ledger-claims-wrap"><table class="ledger-claims"><thead><tr><th scope="col">Wh'
    'at it checks</th><th scope="col">Printed</th><th scope="col">Reproduced</th><th scope="col'
    '">Verdict</th><th scope="col">Kind</th></tr></thead><tbody><tr class="ledger-group"><th co'
    'lspan="5" scope="rowgroup"><span class="ledger-group-label">Table 2.6, column 2</span><det'
    'ails class="ledger-shared"><summary>note for these 2 claims</summary><p>The scenario flies'
    " a straight track at constant speed constant speed constant speed constant speed constant "
    "speed over a flat earth with four ground stations in view.</p><p><i>Tolerance:</i> ±0.5: t"
    '</p></details></th></tr><tr id="sp-g2" class="ledger-claim" data-status="reproduced"><td c'
    'lass="ledger-what">q<details class="ledger-details"><summary>details</summary><p class="le'
    'dger-id">Claim <code>SP-g2</code></p><p>Two.</p></details></td><td class="ledger-value" da'
    'ta-label="Printed">1&nbsp;m</td><td class="ledger-value" data-label="Reproduced">1&nbsp;m<'
    '/td><td class="ledger-verdict" data-label="Verdict"><span class="ledger-badge ledger-statu'
    's-reproduced">reproduced</span></td><td class="ledger-kind" data-label="Kind"><span class='
    '"ledger-kind-label">reproduction</span></td></tr><tr id="sp-g3" class="ledger-claim" data-'
    'status="reproduced"><td class="ledger-what">q<details class="ledger-details"><summary>deta'
    'ils</summary><p class="ledger-id">Claim <code>SP-g3</code></p><p>Three.</p></details></td>'
    '<td class="ledger-value" data-label="Printed">1&nbsp;m</td><td class="ledger-value" data-l'
    'abel="Reproduced">1&nbsp;m</td><td class="ledger-verdict" data-label="Verdict"><span class'
    '="ledger-badge ledger-status-reproduced">reproduced</span></td><td class="ledger-kind" dat'
    'a-label="Kind"><span class="ledger-kind-label">reproduction</span></td></tr></tbody><tbody'
    '><tr class="ledger-group"><th colspan="5" scope="rowgroup"><span class="ledger-group-label'
    '">Fig. 3</span></th></tr><tr id="sp-g4" class="ledger-claim" data-status="discrepant"><td '
    'class="ledger-what">q<details class="ledger-details"><summary>details</summary><p class="l'
    'edger-id">Claim <a href="../sp/ch3.html#sp-g4" title="where the book derives it"><code>SP-'
    "g4</code></a></p><p>Alone. With the y read as r1: 1 m, which agrees with the printed value"
    '.</p><p><i>Tolerance:</i> ±0.5: t</p></details></td><td class="ledger-value" data-label="P'
    'rinted">1&nbsp;m</td><td class="ledger-value" data-label="Reproduced">1&nbsp;m</td><td cla'
    'ss="ledger-verdict" data-label="Verdict"><span class="ledger-badge ledger-status-discrepan'
    't">discrepant</span> <b class="ledger-fails">check fails</b> <a class="ledger-erratum" hre'
    'f="../errata.html#sp-e-x">SP-E-x</a> <span class="ledger-reading">agrees under: r1</span><'
    '/td><td class="ledger-kind" data-label="Kind"><span class="ledger-kind-label">cross-check<'
    "/span></td></tr></tbody></table></div>"
)
TABLE_LATEX = (
    "\\begingroup\\footnotesize\\setlength{\\tabcolsep}{3pt}\\sloppy\n\\begin{longtable}{>{\\raggedrigh"
    "t\\arraybackslash}p{\\dimexpr 0.49\\linewidth-2\\tabcolsep\\relax}>{\\raggedright\\arraybackslash"
    "}p{\\dimexpr 0.16\\linewidth-2\\tabcolsep\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexpr 0.16\\"
    "linewidth-2\\tabcolsep\\relax}>{\\raggedright\\arraybackslash}p{\\dimexpr 0.19\\linewidth-2\\tabc"
    "olsep\\relax}}\n\\hline \\textbf{What it checks} & \\textbf{Printed} & \\textbf{Reproduced} & \\t"
    "extbf{Verdict} \\\\ \\hline \\endfirsthead\n\\hline \\textbf{What it checks} & \\textbf{Printed} &"
    " \\textbf{Reproduced} & \\textbf{Verdict} \\\\ \\hline \\endhead\n\\hline \\endfoot\n\\rowcolor[HTML]"
    "{F1F3F5}\\multicolumn{4}{>{\\raggedright\\arraybackslash}p{\\dimexpr\\linewidth-2\\tabcolsep\\rel"
    "ax}}{\\textbf{Table 2.6, column 2}\\newline{}{\\scriptsize The scenario flies a straight trac"
    "k at constant speed constant speed constant speed constant speed constant speed over a fla"
    "t earth with four ground stations in view. \\textit{Tolerance:} ±0.5: t.}} \\\\*\nq\\newline{}{"
    "\\scriptsize \\texttt{SP-\\allowbreak{}g2}. Two.} & 1 m & 1 m & \\cellcolor[HTML]{D8F0D8}repro"
    "duced\\newline{}{\\scriptsize\\itshape reproduction} \\\\ \\arrayrulecolor{black!25}\\hline\\array"
    "rulecolor{black}\nq\\newline{}{\\scriptsize \\texttt{SP-\\allowbreak{}g3}. Three.} & 1 m & 1 m "
    "& \\cellcolor[HTML]{D8F0D8}reproduced\\newline{}{\\scriptsize\\itshape reproduction} \\\\ \\hline"
    "\n\\rowcolor[HTML]{F1F3F5}\\multicolumn{4}{>{\\raggedright\\arraybackslash}p{\\dimexpr\\linewidth"
    "-2\\tabcolsep\\relax}}{\\textbf{Fig. 3}} \\\\*\nq\\newline{}{\\scriptsize \\texttt{SP-\\allowbreak{}"
    "g4}. Alone. With the y read as r1: 1 m, which agrees with the printed value. \\textit{Toler"
    "ance:} ±0.5: t.} & 1 m & 1 m & \\cellcolor[HTML]{FBE3D4}discrepant \\textbf{(check fails)}\\n"
    "ewline{}{\\scriptsize SP-\\allowbreak{}E-\\allowbreak{}x}\\newline{}{\\scriptsize agrees under:"
    " r1}\\newline{}{\\scriptsize\\itshape cross-check} \\\\ \\hline\n\\end{longtable}\n\\endgroup"
)
TABLE_HTML_NO_NOTES = (
    '<div class="ledger-claims-wrap"><table class="ledger-claims"><thead><tr><th scope="col">Wh'
    'at it checks</th><th scope="col">Printed</th><th scope="col">Reproduced</th><th scope="col'
    '">Verdict</th><th scope="col">Kind</th></tr></thead><tbody><tr class="ledger-group"><th co'
    'lspan="5" scope="rowgroup"><span class="ledger-group-label">Fig. 3</span></th></tr><tr id='
    '"sp-g4" class="ledger-claim" data-status="discrepant"><td class="ledger-what">q <span clas'
    's="ledger-id"><a href="sp/ch3.html#sp-g4" title="where the book derives it"><code>SP-g4</c'
    'ode></a></span></td><td class="ledger-value" data-label="Printed">1&nbsp;m</td><td class="'
    'ledger-value" data-label="Reproduced">1&nbsp;m</td><td class="ledger-verdict" data-label="'
    'Verdict"><span class="ledger-badge ledger-status-discrepant">discrepant</span> <b class="l'
    'edger-fails">check fails</b> <span class="ledger-reading">agrees under: r1</span></td><td '
    'class="ledger-kind" data-label="Kind"><span class="ledger-kind-label">cross-check</span></'
    "td></tr></tbody></table></div>"
)


def test_ledger_table_html_and_latex():
    from navcore.ledger.tables import LedgerTable

    a, b, c = _table_claims()
    t = LedgerTable([a, b, c], link_pages=True)
    assert t._repr_html_() == TABLE_HTML
    assert t.latex() == TABLE_LATEX
    assert t._repr_markdown_() == "```{raw} latex\n" + TABLE_LATEX + "\n```"
    bare = LedgerTable([c], show_notes=False, link_pages=True, link_errata=False, root="")
    assert bare._repr_html_() == TABLE_HTML_NO_NOTES
    # without page links or notes the claim id is not shown; a group sharing part of its notes says so
    assert "ledger-id" not in LedgerTable([c], show_notes=False)._repr_html_()
    trio = [
        _ev("SP-t1", "Eq. (1)", LONG + " One."),
        _ev("SP-t2", "Eq. (1)", "Other."),
        _ev("SP-t3", "Eq. (1)", LONG + " Three."),
    ]
    tex = LedgerTable(trio).latex()
    assert r"{\scriptsize note shared by 2 of these 3 claims: " in tex
    assert "note shared by 2 of these 3 claims</summary>" in LedgerTable(trio)._repr_html_()
    assert "note shared" not in LedgerTable(trio, show_notes=False).latex()


#: The interactive ledger of the three claims above, the band of the first with two runs left out
#: (reviewed against the class docstring: controls, the records as JSON, one row per claim).
INTERACTIVE_HTML = (
    '<div class="ledger-app" data-ledger-app><div class="ledger-controls"><input type="search" '
    'placeholder="Search claims" aria-label="Search claims"><label>Paper <select data-filter="p'
    'aper"><option value="">all</option><option value="SP">SP</option></select></label><label>V'
    'erdict <select data-filter="status"><option value="">all</option><option value="reproduced'
    '">reproduced</option><option value="discrepant">discrepant</option></select></label><label'
    '>Kind <select data-filter="kind"><option value="">all</option><option value="cross-check">'
    'cross-check</option><option value="reproduction">reproduction</option></select></label><sp'
    'an class="ledger-sort"><label>Sort by <select data-sort><option value="">the ledger\'s orde'
    'r</option><option value="id">Claim</option><option value="paper">Paper</option><option val'
    'ue="kind">Kind</option><option value="locator">Locator</option><option value="quantity">Qu'
    'antity</option><option value="published">Printed</option><option value="reproduced">Reprod'
    'uced</option><option value="band">Band</option><option value="status">Verdict</option></se'
    'lect></label><button type="button" data-sort-dir title="reverse the order">ascending</butt'
    'on></span><span class="ledger-count" aria-live="polite"></span><span class="ledger-downloa'
    'ds">Download the rows shown: <button type="button" data-download="csv">CSV</button> <butto'
    'n type="button" data-download="json">JSON</button></span></div><script type="application/j'
    'son" class="ledger-data">[{"band": [0.5, 2.0], "errata": [], "id": "SP-g2", "inputs": [], '
    '"kind": "reproduction", "locator": "Table 2.6, column 2", "note": "The scenario flies a st'
    "raight track at constant speed constant speed constant speed constant speed constant speed"
    " over a flat earth with four ground stations in view. Two. The band leaves out, as outside"
    ' the model\'s domain, 2 runs where no fix.", "paper": "SP", "printed": null, "published": 1'
    '.0, "quantity": "q", "readings": [], "relation": "=", "reproduced": 1.0, "status": "reprod'
    'uced", "tolerance": {"abs": 0.5, "loose_abs": null, "policy": "printed-digits", "reason": '
    '"t", "rel": null}, "unit": "m"}, {"band": null, "errata": [], "id": "SP-g3", "inputs": [],'
    ' "kind": "reproduction", "locator": "Table 2.6, column 2", "note": "The scenario flies a s'
    "traight track at constant speed constant speed constant speed constant speed constant spee"
    'd over a flat earth with four ground stations in view. Three.", "paper": "SP", "printed": '
    'null, "published": 1.0, "quantity": "q", "readings": [], "relation": "=", "reproduced": 1.'
    '0, "status": "reproduced", "tolerance": {"abs": 0.5, "loose_abs": null, "policy": "printed'
    '-digits", "reason": "t", "rel": null}, "unit": "m"}, {"band": null, "errata": [], "id": "S'
    'P-g4", "inputs": [], "kind": "cross-check", "locator": "Fig. 3", "note": "Alone. With the '
    'y read as r1: 1 m, which agrees with the printed value.", "paper": "SP", "printed": null, '
    '"published": 1.0, "quantity": "q", "readings": [{"agrees": false, "band": null, "band_too_'
    'wide": false, "nominal": true, "reading": {"SP.x.y": "r0"}, "value": 1.0}, {"agrees": true'
    ', "band": null, "band_too_wide": false, "nominal": false, "reading": {"SP.x.y": "r1"}, "va'
    'lue": 1.0}], "relation": "=", "reproduced": 1.0, "status": "discrepant", "tolerance": {"ab'
    's": 0.5, "loose_abs": null, "policy": "printed-digits", "reason": "t", "rel": null}, "unit'
    '": "m"}]</script><div class="ledger-table-wrap"><table class="ledger-table ledger-interact'
    'ive"><thead><tr><th data-key="id" scope="col"><button type="button" title="sort">Claim</bu'
    'tton></th><th data-key="paper" scope="col"><button type="button" title="sort">Paper</butto'
    'n></th><th data-key="kind" scope="col"><button type="button" title="sort">Kind</button></t'
    'h><th data-key="locator" scope="col"><button type="button" title="sort">Locator</button></'
    'th><th data-key="quantity" scope="col"><button type="button" title="sort">Quantity</button'
    '></th><th data-key="published" scope="col"><button type="button" title="sort">Printed</but'
    'ton></th><th data-key="reproduced" scope="col"><button type="button" title="sort">Reproduc'
    'ed</button></th><th data-key="band" scope="col"><button type="button" title="sort">Band</b'
    'utton></th><th data-key="status" scope="col"><button type="button" title="sort">Verdict</b'
    'utton></th></tr></thead><tbody><tr id="sp-g2" data-index="0" class="ledger-status-reproduc'
    'ed"><td class="ledger-col-id" data-label="Claim"><code>SP-g2</code></td><td class="ledger-'
    'col-paper" data-label="Paper">SP</td><td class="ledger-col-kind" data-label="Kind">reprodu'
    'ction</td><td class="ledger-col-locator" data-label="Locator">Table 2.6, column 2</td><td '
    'class="ledger-col-quantity" data-label="Quantity">q<details><summary>note</summary>The sce'
    "nario flies a straight track at constant speed constant speed constant speed constant spee"
    "d constant speed over a flat earth with four ground stations in view. Two. The band leaves"
    " out, as outside the model&#x27;s domain, 2 runs where no fix.<br><i>Tolerance:</i> ±0.5, "
    't</details></td><td class="ledger-col-published" data-label="Printed">1&nbsp;m</td><td cla'
    'ss="ledger-col-reproduced" data-label="Reproduced">1&nbsp;m</td><td class="ledger-col-band'
    '" data-label="Band">0.5 –&nbsp;2&nbsp;m<br><span class="ledger-reading">2 runs left out</s'
    'pan></td><td class="ledger-col-status" data-label="Verdict">reproduced</td></tr><tr id="sp'
    '-g3" data-index="1" class="ledger-status-reproduced"><td class="ledger-col-id" data-label='
    '"Claim"><code>SP-g3</code></td><td class="ledger-col-paper" data-label="Paper">SP</td><td '
    'class="ledger-col-kind" data-label="Kind">reproduction</td><td class="ledger-col-locator" '
    'data-label="Locator">Table 2.6, column 2</td><td class="ledger-col-quantity" data-label="Q'
    'uantity">q<details><summary>note</summary>The scenario flies a straight track at constant '
    "speed constant speed constant speed constant speed constant speed over a flat earth with f"
    'our ground stations in view. Three.<br><i>Tolerance:</i> ±0.5, t</details></td><td class="'
    'ledger-col-published" data-label="Printed">1&nbsp;m</td><td class="ledger-col-reproduced" '
    'data-label="Reproduced">1&nbsp;m</td><td class="ledger-col-band ledger-empty" data-label="'
    'Band"></td><td class="ledger-col-status" data-label="Verdict">reproduced</td></tr><tr id="'
    'sp-g4" data-index="2" class="ledger-status-discrepant"><td class="ledger-col-id" data-labe'
    'l="Claim"><a href="../sp/ch3.html#sp-g4" title="where the book derives it"><code>SP-g4</co'
    'de></a></td><td class="ledger-col-paper" data-label="Paper">SP</td><td class="ledger-col-k'
    'ind" data-label="Kind">cross-check</td><td class="ledger-col-locator" data-label="Locator"'
    '>Fig. 3</td><td class="ledger-col-quantity" data-label="Quantity">q<details><summary>note<'
    "/summary>Alone. With the y read as r1: 1 m, which agrees with the printed value.<br><i>Tol"
    'erance:</i> ±0.5, t</details></td><td class="ledger-col-published" data-label="Printed">1&'
    'nbsp;m</td><td class="ledger-col-reproduced" data-label="Reproduced">1&nbsp;m</td><td clas'
    's="ledger-col-band ledger-empty" data-label="Band"></td><td class="ledger-col-status" data'
    '-label="Verdict">discrepant <b>(check fails)</b><br><a href="../errata.html#sp-e-x">SP-E-x'
    '</a><br><span class="ledger-reading">agrees under: r1</span></td></tr></tbody></table></di'
    "v><script>"
)


def test_interactive_ledger_html():
    import dataclasses

    from navcore.ledger.interactive import _LEDGER_JS, InteractiveLedger

    a, b, c = _table_claims()
    a = dataclasses.replace(a, band=(0.5, 2.0), left_out=({"case": "no fix", "runs": 2},))
    assert (
        InteractiveLedger([a, b, c], root="../")._repr_html_()
        == INTERACTIVE_HTML + _LEDGER_JS + "</script></div>"
    )
    # without kinds or bands in the records: no kind filter, no kind or band column
    plain = InteractiveLedger([b])
    plain.records = [{**r, "kind": None, "band": None} for r in plain.records]
    assert [k for k, _ in plain._columns()] == [
        "id",
        "paper",
        "locator",
        "quantity",
        "published",
        "reproduced",
        "status",
    ]
    assert 'data-filter="kind"' not in plain._repr_html_()
    # a closing tag in a record cannot end the JSON script element
    d = dataclasses.replace(b, claim=dataclasses.replace(b.claim, note="a </script> note"))
    html = InteractiveLedger([d])._repr_html_()
    assert "a <\\/script> note" in html and "a </script> note" not in html.split("<script>")[0]


def test_quote_math_cases():
    from navcore.ledger.text import quote_math

    # the docstring's cases, then each mechanism alone
    assert quote_math(r"\gamma_n &= \frac{a}{b} \tag{4.5.31}") == r"\gamma_n = \frac{a}{b}"
    assert quote_math(r"\exp \left[(K t + 1) \ln") == r"\exp \left[(K t + 1) \ln\right."
    assert (
        quote_math(r"\sqrt{2 \frac{\partial^2}{\partial r^2}")
        == r"\sqrt{2 \frac{\partial^2}{\partial r^2}\ldots}"
    )
    assert quote_math(r"a & b \\ c & d") == r"\begin{matrix}a & b \\ c & d\end{matrix}"
    assert quote_math("1.61×10^{-4}") == r"1.61\times 10^{-4}"
    assert quote_math(r"x = 1 \quad (3)") == "x = 1"
    assert quote_math(r"x = 1 \qquad 3.2") == "x = 1"
    assert quote_math(r"x = 1 \quad (\text{A.1})") == "x = 1"
    # a closing brace or \right without its partner is opened at the start
    assert quote_math(r"a} + b") == r"{a} + b"
    assert quote_math(r"a \right) + b") == r"\left.a \right) + b"
    assert quote_math(r"\left( a \right) \left[ b") == r"\left( a \right) \left[ b\right."
    # alignment inside an environment is kept; rows inside one are not a matrix
    env = r"\begin{cases} a & b \\ c & d \end{cases}"
    assert quote_math(env) == env
    assert quote_math("a   b") == "a b"
    assert quote_math(" σ ≤ 2 ") == r"\sigma  \leq  2"
    assert quote_math(r"\{a, b") == r"\{a, b"


def test_printed_cells():
    from navcore.ledger.text import _printed_html, _printed_tex, _printed_text, claim_group

    assert _printed_html("about 10 m") == "about&nbsp;10&nbsp;m"
    assert (
        _printed_html("$$x = 1 \\quad (3)$$")
        == '<span class="math notranslate nohighlight">\\(x = 1\\)</span>'
    )
    wide = "$a + b + c + d + e + f + g + h$"
    # a long formula in its own box, cut after each outer operator (where TeX may break it)
    span = '<span class="math notranslate nohighlight">\\({}\\)</span>'
    pieces = [f"{x} +{{}}" for x in "abcdef"] + ["g + h"]
    assert _printed_html(wide) == (
        '<span class="ledger-math-wide">' + "<wbr>".join(span.format(p) for p in pieces) + "</span>"
    )
    assert _printed_html("costs 50 \\$ per unit, or more") == (
        'costs 50 <span class="tex2jax_ignore mathjax_ignore">$</span> per unit, or more'
    )
    assert _printed_html("\\mathbf{P} = \\sigma^2 I <x>") == (
        '<code class="ledger-latex">\\mathbf{P} = \\sigma^2 I &lt;x&gt;</code>'
    )
    folded = _printed_html("a long sentence the paper printed, word for word", fold=20)
    assert folded == (
        '<details class="ledger-quote"><summary>quote</summary>'
        "a long sentence the paper printed, word for word</details>"
    )
    assert _printed_html("a long sentence the paper printed", fold=40) == "a long sentence the paper printed"
    assert _printed_html("16 chars, ok now") == "16&nbsp;chars,&nbsp;ok&nbsp;now"
    assert _printed_html("17 chars, ok now!") == "17 chars, ok now!"
    assert _printed_tex("about $10^{-6}$ of it") == "about $10^{-6}$ of it"
    assert _printed_tex("costs \\$5 & more") == r"costs \$5 \& more"
    assert (
        _printed_tex("\\mathbf{P}_N = I")
        == r"{\scriptsize\ttfamily \textbackslash{}mathbf\{P\}\_\allowbreak{}N = I}"
    )
    assert _printed_tex("$$a + b + c + d + e + f + g + h \\tag{2}$$") == (
        r"\navcorefitmath{a + b + c + d + e + f + g + h}"
    )
    # the Printed text: the claim's quote, else the number with its relation and unit
    assert _printed_text(_ev("SP-p1", "Eq. (1)", "n")) == "1 m"
    e = _ev("SP-p1", "Eq. (1)", "n")
    import dataclasses

    bound = dataclasses.replace(e, claim=dataclasses.replace(e.claim, relation=">=", unit=""))
    assert _printed_text(bound) == "≥ 1"
    quoted = dataclasses.replace(e, claim=dataclasses.replace(e.claim, printed="about 1 m"))
    assert _printed_text(quoted) == "about 1 m"
    stmt = dataclasses.replace(
        e, claim=dataclasses.replace(e.claim, published=False, unit="statement", kind="statement")
    )
    assert _printed_text(stmt) == "stated not to hold"
    assert claim_group("Sec. III, after Eq. (9)") == "Eq. (9)"
    assert claim_group("Figs. 3 - 4, right") == "Figs. 3 - 4"
    assert claim_group("Theorem 2, proof") == "Theorem 2"
    assert claim_group("Remark (iv)") == "Remark (iv)"
    assert claim_group("App. B, last line") == "App. B"
    assert claim_group("Secs. IV.A and V") == "Secs. IV.A"
    assert claim_group("  abstract ") == "abstract"


def test_tex_breakable_and_widths():
    from navcore.ledger.tables import _min_pt, _text_pieces, _word_pt
    from navcore.ledger.text import tex_breakable

    assert tex_breakable("interpreted") == "interpreted"
    assert tex_breakable("KZLsec36headingX") == r"KZLsec3\allowbreak{}6headin\allowbreak{}gX"
    assert tex_breakable("SP-a.b/c_d") == r"SP-\allowbreak{}a.\allowbreak{}b/\allowbreak{}c\_\allowbreak{}d"
    assert tex_breakable("abcdefghijklmnop") == r"abcdefg\allowbreak{}hijklmn\allowbreak{}op"  # 16 letters
    assert tex_breakable("abcdefghijklmn") == "abcdefghijklmn"  # 14 letters: whole
    assert tex_breakable("a1b2c3d4e5") == "a1b2c3d4e5"  # 10 characters: whole
    # no line ends at a decimal point or after a minus sign (a number would break in two)
    assert tex_breakable("0.0019 g") == "0.0019 g"
    assert tex_breakable("(-3.5 dB)") == "(-3.5 dB)"
    assert tex_breakable("x.5") == r"x.\allowbreak{}5"  # a "." after a letter still may
    assert tex_breakable("5.x") == r"5.\allowbreak{}x"
    assert tex_breakable("L-2") == r"L-\allowbreak{}2"  # a hyphen after a letter still may
    assert _word_pt("ab") == 8.0 and _word_pt("AB") == 10.0 and _word_pt("a%&@") == 19.0
    assert _word_pt("MW") == 10.0 and _word_pt("ab", bold=True) == pytest.approx(8.8)
    assert _text_pieces("x $K_1$ y") == [(False, "x "), (True, "K_1"), (False, " y")]
    assert _text_pieces("a-very-long-hyphenated-word") == [
        (False, "a-\u200bvery-\u200blong-\u200bhyphenated-\u200bword")
    ]
    assert _text_pieces("abcdefghijklmnopq") == [(False, "abcdefg\u200bhijklmn\u200bopq")]
    assert _min_pt("12.5", True) == 16.0
    assert _min_pt("ab abcd", False) == 16.0
    assert _min_pt("ab abcd", False, bold=True) == pytest.approx(17.6)
    # a formula counts as at most 24 characters, at 0.8 of their width, commands as one letter
    assert _min_pt("$\\alpha + b$", False) == pytest.approx(0.8 * 4.0 * 5)
    assert _min_pt("$" + "a" * 40 + "$", False) == pytest.approx(0.8 * 4.0 * 24)
    assert _min_pt("", False) == 0.0


def test_text_table(monkeypatch):
    import navcore.ledger.tables as tables
    from navcore.ledger.tables import text_table

    # the summary below the table reads the registry's errata: replaced by a marker here
    monkeypatch.setattr(tables, "summary_text", lambda evals: f"<summary of {len(evals)}>")
    e = _ev("SP-text-table-claim-with-a-rather-long-identifier", "Eq. (1)", "n")
    lines = text_table([e], width=20).splitlines()
    assert lines == [
        "id                    locator  published  reproduced  unit  tolerance  status      check",
        "--------------------  -------  ---------  ----------  ----  ---------  ----------  -----",
        "SP-text-table-claim…  Eq. (1)  1          1           m     ±0.5       reproduced  ok   ",
        "",
        "<summary of 1>",
    ]
    # a cell exactly as long as the width is kept whole
    assert (
        text_table([e], width=49)
        .splitlines()[2]
        .startswith("SP-text-table-claim-with-a-rather-long-identifier  ")
    )


def test_group_and_opening_edges():
    from navcore.ledger.tables import _common_opening, _details_html, _details_tex, group_claims

    # two identical notes of several sentences are shared whole, not cut at a sentence
    same = group_claims([_ev("SP-i1", "Eq. (5)", LONG + " Tail."), _ev("SP-i2", "Eq. (5)", LONG + " Tail.")])[
        0
    ]
    assert same.shared["note"] == LONG + " Tail." and same.own(0) == {}
    # two different notes, one long: nothing is shared
    two = group_claims([_ev("SP-d1", "Eq. (6)", LONG + " One."), _ev("SP-d2", "Eq. (6)", "Other.")])[0]
    assert "note" not in two.shared and two.shared_by == 2
    assert two.own(0)["note"] == LONG + " One."
    # an escaped dollar sign does not open math: the sentence after it ends where it ends
    cost = LONG + " It costs \\$5 each."
    assert _common_opening([cost + " Then a.", cost + " Then b."]) == cost
    assert _common_opening(["$x$ " + LONG + " Then a.", "$x$ " + LONG + " Then b."]) == "$x$ " + LONG
    # an abbreviation in brackets does not end a sentence
    abbrev = LONG + " Some (e.g. this) text."
    assert _common_opening([abbrev + " Then a.", abbrev + " Then b."]) == abbrev
    # an opening of exactly 120 characters is long enough
    s120 = "A" * 119 + "."
    assert _common_opening([s120 + " x", s120 + " y"]) == s120
    assert _common_opening(["A" * 118 + ". x", "A" * 118 + ". y"]) == ""
    # a formula longer than 24 characters scrolls in its own box in the details
    assert _details_html({"note": "$" + "a" * 25 + "$"}).startswith('<p><span class="ledger-math-wide">')
    assert "ledger-math-wide" not in _details_html({"note": "$" + "a" * 24 + "$"})
    # the parts run on: a full stop is added unless the text ends a sentence or a clause
    assert _details_tex({"note": "Why?", "tolerance": "t:"}) == r"Why? \textit{Tolerance:} t:"
    assert _details_tex({"note": "A note. "}) == "A note. "
    assert _details_tex({"note": " x"}) == " x."


def test_cells_with_strings_and_bounds():
    import dataclasses

    from navcore.ledger.text import _inputs_text, _printed_text

    e = _ev("SP-c1", "Eq. (1)", "n")
    assert _printed_text(dataclasses.replace(e, claim=dataclasses.replace(e.claim, relation="<="))) == "≤ 1 m"
    inputs = (
        {"name": "SP.nowhere.labels", "provenance": "convention", "value": ["a", "b"]},
        {"name": "SP.nowhere.flags", "provenance": "convention", "value": [True, 1]},
        {"name": "SP.nowhere.s40", "provenance": "assumed", "value": "x" * 40},
        {"name": "SP.nowhere.s41", "provenance": "assumed", "value": "y" * 41},
    )
    assert _inputs_text(dataclasses.replace(e, inputs=inputs)) == (
        "labels = ['a', 'b'] (convention); flags = [True, 1] (convention); "
        f"s40 = {'x' * 40} (assumed); s41 = {'y' * 39}… (assumed)"
    )
    s = _word_input()
    words = ({"name": s, "provenance": "published", "locator": "T1", "value": "tracking"},)
    assert _inputs_text(dataclasses.replace(e, inputs=words)) == "mode = tracking (published, T1)"


def test_a_long_formula_is_never_cut_inside_a_matrix_or_cases_environment():
    """A cut inside an environment leaves MathJax two halves it refuses ("Missing
    \\begin{cases}"); the formula may still be cut outside it. Oracle: ATC-10's Eq. (4.5.23)
    as printed, cut by hand after its relation only."""
    from navcore.ledger.text import _printed_html

    cases = r"\begin{cases} 2\sigma_0^2, & i=0 \\ \sigma_0^2, & 1 \leq i \end{cases}"
    formula = r"E[\Delta_n \Delta_{n-i}] = " + cases
    out = _printed_html(f"${formula}$")
    assert out.count("<wbr>") == 1
    assert "\\(E[\\Delta_n \\Delta_{n-i}] ={}\\)" in out and "\\(\\begin{cases}" in out


def test_a_conventions_code_word_shows_as_its_readings_words():
    """A convention's value that is a code word ("C/N0", "loop") shows as the words of its
    reading, as the conventions table shows it: "$C/N_0$ in dB-Hz", set as math, never cut.
    Oracle: the readings SP's flyby declares for its signal-to-noise measure."""
    import dataclasses

    from navcore.claims.inputs import get_input
    from navcore.ledger.text import _inputs_text
    from navcore.papers import sp_flyby  # noqa: F401  (declares the input)

    name = "SP.flyby.snr_measure"
    readings = dict((v, label) for label, v in get_input(name).readings)
    e = _ev("SP-c1", "Eq. (1)", "n")
    for code in ("C/N0", "loop"):
        inputs = ({"name": name, "provenance": "convention", "value": code},)
        text = _inputs_text(dataclasses.replace(e, inputs=inputs))
        assert text.endswith(f" = {readings[code]} (convention)") and f"= {code} (" not in text
    assert readings["C/N0"] == "$C/N_0$ in dB-Hz"


def _word_input() -> str:
    """A registered input with a unit whose value is a word (the unit is not appended to words)."""
    from navcore.claims.inputs import get_input
    from navcore.ledger import InputSet

    name = "SP.mutation_render_cells.mode"
    try:
        get_input(name)
    except ValueError:
        InputSet("SP", "mutation_render_cells").published("mode", "tracking", locator="T1", unit="m")
    return name


#: The findings table, the counts table and the errata list above as whole strings (reviewed
#: against the classes' docstrings; the fragments tested above are their parts).
FINDINGS_HTML = (
    '<div class="ledger-counts-wrap"><table class="ledger-counts ledger-findings"><thead><tr><t'
    "h>Paper</th><th>Basis</th><th>typo&shy;graphy</th><th>units</th><th>con&shy;vention</th><t"
    "h>deri&shy;vation</th><th>unstated<br>as&shy;sumption</th><th>incon&shy;sistent<br>numbers"
    "</th><th>over&shy;statement</th><th>Findings</th></tr></thead><tbody><tr><td>WF</td><td>te"
    "xt-only</td><td>1</td><td>0</td><td>0</td><td>0</td><td>0</td><td>0</td><td>0</td><td>1</t"
    "d></tr><tr><td>SP</td><td>computed</td><td>0</td><td>1</td><td>0</td><td>0</td><td>0</td><"
    "td>0</td><td>0</td><td>1</td></tr><tr><td>all</td><td>computed</td><td>0</td><td>1</td><td"
    ">0</td><td>0</td><td>0</td><td>0</td><td>0</td><td>1</td></tr><tr><td>all</td><td>text-onl"
    "y</td><td>1</td><td>0</td><td>0</td><td>0</td><td>0</td><td>0</td><td>0</td><td>1</td></tr"
    "><tr><td>all</td><td>all</td><td>1</td><td>1</td><td>0</td><td>0</td><td>0</td><td>0</td><"
    'td>0</td><td>2</td></tr></tbody></table></div><p class="ledger-caveat">The book works from'
    " transcriptions of the papers, so a text-only finding (the text of a formula or a word, on"
    " which the printed numbers do not depend) cannot tell a misprint in the paper from a slip "
    'in its transcription.</p><div class="ledger-table-wrap"><table class="ledger-findings-list'
    '"><thead><tr><th scope="col">Finding</th><th scope="col">Basis</th><th scope="col">Kind</t'
    'h><th scope="col">Its evidence: claims and verdicts</th></tr></thead><tbody><tr><td><a hre'
    'f="../errata.html#sp-e-rend1"><code>SP-E-rend1</code></a><br><span class="ledger-locator">'
    'SP, Eq. (1)</span></td><td>computed</td><td>units</td><td><a href="../ledger.html#sp-test-'
    'sum-a"><code>SP-test-sum-a</code></a> <span class="ledger-badge ledger-status-consistent">'
    'consistent</span></td></tr><tr><td><a href="../errata.html#wf-e-rend2"><code>WF-E-rend2</c'
    'ode></a><br><span class="ledger-locator">WF, Table 2</span></td><td>text-only</td><td>typo'
    "graphy</td><td>no claim checks it</td></tr></tbody></table></div>"
)
FINDINGS_MD = (
    "```{raw} latex\n\\begingroup\\scriptsize\\setlength{\\tabcolsep}{4pt}\\hyphenpenalty=10000\\exhyp"
    "henpenalty=10000\n\\begin{longtable}{>{\\raggedright\\arraybackslash}p{\\dimexpr 0.0668\\linewid"
    "th-2\\tabcolsep\\relax}>{\\raggedright\\arraybackslash}p{\\dimexpr 0.0786\\linewidth-2\\tabcolsep"
    "\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexpr 0.1089\\linewidth-2\\tabcolsep\\relax}>{\\ragge"
    "dleft\\arraybackslash}p{\\dimexpr 0.0668\\linewidth-2\\tabcolsep\\relax}>{\\raggedleft\\arrayback"
    "slash}p{\\dimexpr 0.1089\\linewidth-2\\tabcolsep\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexp"
    "r 0.1089\\linewidth-2\\tabcolsep\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexpr 0.1089\\linewi"
    "dth-2\\tabcolsep\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexpr 0.1258\\linewidth-2\\tabcolsep"
    "\\relax}>{\\raggedleft\\arraybackslash}p{\\dimexpr 0.1342\\linewidth-2\\tabcolsep\\relax}>{\\ragge"
    "dleft\\arraybackslash}p{\\dimexpr 0.0921\\linewidth-2\\tabcolsep\\relax}}\n\\hline \\textbf{Paper}"
    " & \\textbf{Basis} & \\textbf{typography} & \\textbf{units} & \\textbf{convention} & \\textbf{d"
    "erivation} & \\textbf{unstated assumption} & \\textbf{inconsistent numbers} & \\textbf{overst"
    "atement} & \\textbf{Findings} \\\\ \\hline \\endfirsthead\n\\hline \\textbf{Paper} & \\textbf{Basis"
    "} & \\textbf{typography} & \\textbf{units} & \\textbf{convention} & \\textbf{derivation} & \\te"
    "xtbf{unstated assumption} & \\textbf{inconsistent numbers} & \\textbf{overstatement} & \\text"
    "bf{Findings} \\\\ \\hline \\endhead\n\\hline \\endfoot\nWF & text-only & \\mbox{1} & \\mbox{0} & \\mb"
    "ox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{1} \\\\\nSP & computed & \\mbox{0} &"
    " \\mbox{1} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{1} \\\\\nall & compu"
    "ted & \\mbox{0} & \\mbox{1} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{1"
    "} \\\\\nall & text-only & \\mbox{1} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\"
    "mbox{0} & \\mbox{1} \\\\\nall & all & \\mbox{1} & \\mbox{1} & \\mbox{0} & \\mbox{0} & \\mbox{0} & \\"
    "mbox{0} & \\mbox{0} & \\mbox{2} \\\\\n\\end{longtable}\n\\endgroup\n```\n\nThe book works from transc"
    "riptions of the papers, so a text-only finding (the text of a formula or a word, on which "
    "the printed numbers do not depend) cannot tell a misprint in the paper from a slip in its "
    "transcription.\n\n```{raw} latex\n\\begingroup\\footnotesize\\setlength{\\tabcolsep}{4pt}\\hyphenp"
    "enalty=10000\\exhyphenpenalty=10000\n\\begin{longtable}{>{\\raggedright\\arraybackslash}p{\\dime"
    "xpr 0.2270\\linewidth-2\\tabcolsep\\relax}>{\\raggedright\\arraybackslash}p{\\dimexpr 0.1784\\lin"
    "ewidth-2\\tabcolsep\\relax}>{\\raggedright\\arraybackslash}p{\\dimexpr 0.1946\\linewidth-2\\tabco"
    "lsep\\relax}>{\\raggedright\\arraybackslash}p{\\dimexpr 0.4001\\linewidth-2\\tabcolsep\\relax}}\n\\"
    "hline \\textbf{Finding} & \\textbf{Basis} & \\textbf{Kind} & \\textbf{Its evidence: claims and"
    " verdicts} \\\\ \\hline \\endfirsthead\n\\hline \\textbf{Finding} & \\textbf{Basis} & \\textbf{Kind"
    "} & \\textbf{Its evidence: claims and verdicts} \\\\ \\hline \\endhead\n\\hline \\endfoot\nSP-\\allo"
    "wbreak{}E-\\allowbreak{}rend1 & computed & units & SP-\\allowbreak{}test-\\allowbreak{}sum-\\a"
    "llowbreak{}a (consistent) \\\\\nWF-\\allowbreak{}E-\\allowbreak{}rend2 & text-only & typography"
    " & no claim checks it \\\\\n\\end{longtable}\n\\endgroup\n```"
)
COUNTS_HTML = (
    '<div class="ledger-counts-wrap"><table class="ledger-counts"><thead><tr><th>Paper</th><th>'
    "repro&shy;duced</th><th>consis&shy;tent</th><th>incon&shy;sistent</th><th>discrep&shy;ant<"
    "/th><th>not-<wbr>repro&shy;ducible</th><th>total</th><th>failing<br>check</th></tr></thead"
    "><tbody><tr><td>SP</td><td>3</td><td>1</td><td>0</td><td>2</td><td>0</td><td>6</td><td>2</"
    "td></tr><tr><td>WF</td><td>1</td><td>0</td><td>1</td><td>0</td><td>1</td><td>3</td><td>0</"
    "td></tr><tr><td>all</td><td>4</td><td>1</td><td>1</td><td>2</td><td>1</td><td>9</td><td>2<"
    "/td></tr></tbody></table></div>"
)
ERRATA_HTML = (
    '<p class="errata-group"><b>Computed findings</b> (1)</p><div class="erratum erratum-comput'
    'ed" id="sp-e-rend1"><h4>SP-E-rend1 — SP, Eq. (1)</h4><p class="erratum-basis"><b>Basis:</b'
    '> computed · <b>Kind:</b> units</p><p><b>Printed:</b> <span class="math notranslate nohigh'
    'light">\\(a + b\\)</span></p><p><b>The book finds:</b> <span class="math notranslate nohighl'
    'ight">\\(a - b\\)</span></p><p><b>Evidence:</b> the &lt;derivation&gt;</p><p><b>Claims (its '
    'evidence in the ledger):</b> <a href="../ledger.html#sp-test-sum-a"><code>SP-test-sum-a</c'
    'ode></a> <span class="ledger-badge ledger-status-consistent">consistent</span>, <a href=".'
    './ledger.html#sp-test-sum-zz"><code>SP-test-sum-zz</code></a>. Discussed in <a href="../sp'
    '/ch2.html#sp-e-rend1">Chapter &lt;2&gt;</a>.</p></div><p class="errata-group"><b>Text-only'
    ' findings</b> (1)</p><p class="ledger-caveat">The book works from transcriptions of the pa'
    "pers, so a text-only finding (the text of a formula or a word, on which the printed number"
    "s do not depend) cannot tell a misprint in the paper from a slip in its transcription.</p>"
    '<div class="erratum erratum-text-only" id="wf-e-rend2"><h4>WF-E-rend2 — WF, Table 2</h4><p'
    ' class="erratum-basis"><b>Basis:</b> text-only · <b>Kind:</b> typography</p><p><b>Printed:'
    "</b> x_1</p><p><b>The book finds:</b> y &amp; z</p><p><b>Evidence:</b> c</p><p><b>Claims ("
    "its evidence in the ledger):</b> none.</p></div>"
)


def test_tables_as_whole_strings(fake_counts):
    from navcore.ledger.tables import CountsTable, ErrataList, FindingsTable

    ft = FindingsTable([E1, E2], EVALS, root="../", list_findings=True)
    assert ft._repr_html_() == FINDINGS_HTML
    assert ft._repr_markdown_() == FINDINGS_MD
    assert CountsTable()._repr_html_() == COUNTS_HTML
    errata = ErrataList([E2, E1], root="../", titles={"sp/ch2": "Chapter <2>"}, evals=EVALS)
    assert errata._repr_html_() == ERRATA_HTML
    # an erratum of an unknown basis sorts last
    odd = Erratum(id="SP-E-odd", paper="SP", locator="x", printed="a", finding="b", evidence="c",
                  kind="units", basis="computed")  # fmt: skip
    object.__setattr__(odd, "basis", "other")
    assert [e.id for e in ErrataList([odd, E2, E1]).items] == ["SP-E-rend1", "WF-E-rend2", "SP-E-odd"]


def test_ledger_table_locator_details_and_wide_quantities():
    import dataclasses

    from navcore.ledger.tables import LedgerTable

    a = _ev("SP-l1", "Table 2.6, column 2", "n one")
    b = _ev("SP-l2", "Table 2.6, column 3", "n two")
    wide = "$" + "q" * 25 + "$ and more"
    b = dataclasses.replace(b, claim=dataclasses.replace(b.claim, quantity=wide))
    t = LedgerTable([a, b], show_notes=False)
    html = t._repr_html_()
    assert '<span class="ledger-group-label">Table 2.6</span>' in html
    assert '<td class="ledger-what">q <span class="ledger-locator">(column 2)</span></td>' in html
    assert '<td class="ledger-what"><span class="ledger-math-wide">' in html
    assert "(column 3)</span></td>" in html
    tex = t.latex()
    assert "\nq (column 2) & 1 m & 1 m & " in tex
    # a claim whose own details are empty adds no ". " after its id
    same = [_ev("SP-s1", "Eq. (2)", "Same."), _ev("SP-s2", "Eq. (2)", "Same.")]
    assert r"\texttt{SP-\allowbreak{}s1}} & " in LedgerTable(same).latex()


def test_exports_default_to_this_checkouts_provenance():
    import json

    from navcore.ledger.tables import csv_export, json_export
    from navcore.provenance import build_provenance

    e = _ev("SP-j2", "Eq. (1)", "n")
    assert json.loads(json_export([e]))["provenance"] == build_provenance().as_dict()
    assert csv_export([e]).splitlines()[0].endswith(",".join(build_provenance().flat()))
    # the header is the first row's keys: two rows give one header
    assert csv_export([e, e]).count("id,locator") == 1


def test_locator_words_break_at_syllables_and_stay_searchable():
    """The interactive ledger's locator column is narrower than "Appendix" at 1400 px: a long
    locator word carries soft hyphens at its syllables (a browser breaks it there, with a hyphen,
    instead of at the column's edge), and the table's search ignores them. Oracle: the
    hyphenations written out by hand; every locator of the registry comes back unchanged once the
    soft hyphens are removed."""
    from navcore import ledger
    from navcore.ledger.interactive import InteractiveLedger
    from navcore.ledger.text import soft_hyphens

    assert soft_hyphens("Appendix E, (E.1)") == "Ap&shy;pen&shy;dix E, (E.1)"
    assert soft_hyphens("Sec. 3.8, approximation") == "Sec. 3.8, ap&shy;prox&shy;i&shy;ma&shy;tion"
    assert soft_hyphens("Sec. II, after Eq. (6)") == "Sec. II, after Eq. (6)"
    assert soft_hyphens("Table 2.7, residual") == "Table 2.7, resid&shy;ual"
    for c in ledger.claims():
        assert soft_hyphens(c.locator).replace("&shy;", "") == c.locator
    claim = dataclasses.replace(EVALS[0].claim, locator="Appendix E")
    page = InteractiveLedger([evaluate(claim)])._repr_html_()
    assert '<td class="ledger-col-locator" data-label="Locator">Ap&shy;pen&shy;dix E</td>' in page
    assert 'tr.textContent.replace(/\\u00ad/g, "").toLowerCase().indexOf(q)' in page
