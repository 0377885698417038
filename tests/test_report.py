"""The verification report per paper (navcore.report) and ``python -m navcore report``.

Oracles: the ledger's own counts (``navcore.ledger.counts`` and ``count_table``) and its
registered errata, computed from the same evaluations as the report; the WF paper is used,
whose ledger is the fastest to evaluate.
"""

from __future__ import annotations

import re
import shutil

import pytest

from navcore import ledger
from navcore.__main__ import main
from navcore.claims.declarations import STATUSES
from navcore.report import (
    UNRESOLVED,
    FindingsBlock,
    Table,
    build_report,
    check_paper,
    figure_claims,
    to_latex,
    to_markdown,
    to_text,
    write_pdf,
)

PAPER = "WF"


@pytest.fixture(scope="module")
def wf_evals():
    return ledger.evaluations(PAPER)


@pytest.fixture(scope="module")
def wf_report(wf_evals):
    return build_report(PAPER, wf_evals)


def test_verdict_counts_equal_the_ledgers(wf_evals, wf_report):
    table = wf_report.section("verdicts").blocks[1]
    assert isinstance(table, Table)
    col = {h: j for j, h in enumerate(table.head)}
    total = next(r for r in table.rows if r[col["Kind"]] == "all")
    counts = ledger.counts(PAPER)[PAPER]  # the ledger's own count, from the same evaluations
    for s in STATUSES:
        assert int(total[col[s]]) == counts[s], s
    assert int(total[col["Total"]]) == counts["total"] == len(wf_evals)
    for row in table.rows:  # per kind too
        if row[col["Kind"]] == "all":
            continue
        sel = [e for e in wf_evals if e.kind == row[col["Kind"]]]
        assert int(row[col["Total"]]) == len(sel)
        for s in STATUSES:
            assert int(row[col[s]]) == sum(e.status == s for e in sel)


def test_overview_numbers_are_the_ledgers(wf_evals, wf_report):
    text = wf_report.section("overview").blocks[0]
    assert isinstance(text, str)
    counts = ledger.counts(PAPER)[PAPER]
    assert f"The ledger holds {counts['total']} claims" in text
    for s in STATUSES:
        if counts[s]:
            assert f"{counts[s]} {s}" in text
    assert f"{len(ledger.errata(PAPER))} findings" in text


def test_unresolved_claims_are_listed_with_their_notes(wf_evals, wf_report):
    tables = [b for b in wf_report.section("verdicts").blocks if isinstance(b, Table)]
    listed = {r[0]: r for r in tables[1].rows} if len(tables) > 1 else {}
    expected = {e.claim.id: e for e in wf_evals if e.status in UNRESOLVED}
    assert set(listed) == set(expected)
    why = tables[1].head.index("Why")
    shared = {}  # a note several of these claims share is said once, before the table
    for b in wf_report.section("verdicts").blocks:
        if isinstance(b, str) and (m := re.match(r"\*\*Note ([A-Z]+)\*\*, for these (\d+) claims", b)):
            shared[m.group(1)] = (b, int(m.group(2)))
    for cid, row in listed.items():
        note = expected[cid].claim.note
        ref = re.match(r"See note ([A-Z]+)[.;]", row[why])
        if ref:
            text, n = shared[ref.group(1)]
            assert text.endswith(note) and n == sum(
                r[why].startswith(ref.group(0)[:-1]) for r in listed.values()
            )
        else:
            assert row[why].startswith(note.rstrip("."))


def test_long_claim_lists_follow_their_table():
    """No cell of the inputs tables outgrows a page: a long list of claim ids is a number in
    the cell, and the ids follow the table (synthetic: 30 claims read one convention)."""
    from navcore.ledger import Claim, InputSet, evaluate, printed
    from navcore.report import MAX_IDS_CELL, conventions_frame, moved_claims

    inputs = InputSet("WF", "doc_report_lists")
    inputs.convention("scale", 1.0, alternative=0.5, quantity="loss scale", reason="counted once or twice")
    value, tol = printed("2.0")
    evals = [
        evaluate(
            Claim(id=f"WF-doc-long-{i}-list-claim", paper="WF", locator="Sec. 9", quantity="a number",
                  published=value, unit="1", compute=lambda: 2.0 * inputs.scale, tolerance=tol,
                  expected_status="consistent", note="synthetic")
        )
        for i in range(30)
    ]  # fmt: skip
    frame = conventions_frame(evals)
    cell = frame["Claims it moves"].iloc[0]
    assert cell == "30 claims, listed after the table" and len(cell) <= MAX_IDS_CELL
    (listed,) = moved_claims(evals, "convention")
    assert listed.startswith(f"**{frame.iloc[0, 0]}** (30 claims): ")
    assert all(f"WF-doc-long-{i}-list-claim" in listed for i in range(30))


def test_findings_section_lists_every_erratum_with_its_basis(wf_evals, wf_report):
    errata = ledger.errata(PAPER)
    assert errata, "WF has registered errata"
    section = wf_report.section("findings")
    block = next(b for b in section.blocks if isinstance(b, FindingsBlock))
    assert {e.id for e in block.errata} == {e.id for e in errata}
    text = to_text(section)
    md = to_markdown(wf_report)
    status = {e.claim.id: e.status for e in wf_evals}
    for e in errata:
        # in the terminal, under the heading of its basis
        heading = text.index(f"{e.basis} findings (")
        assert text.index(e.id) > heading
        # in the Markdown, with its basis and kind, and its claims with their verdicts
        entry = md[md.index(f"### {e.id}") :]
        assert f"**Basis:** {e.basis}; **kind:** {e.kind}" in entry.split("###")[1]
        for cid in e.claims:
            assert f"{cid} ({status[cid]})" in entry.split("###")[1]
    for line in text.splitlines():
        assert len(line) <= 100, line
    # the counts by kind (rows) and basis (columns): each finding counted once, by hand
    counts = next(b for b in section.blocks if isinstance(b, Table))
    col = {h: j for j, h in enumerate(counts.head)}
    for row in counts.rows:
        kind = row[0].replace(" ", "-")
        for basis in (*{e.basis for e in errata}, "all"):
            sel = [
                e
                for e in errata
                if (basis == "all" or e.basis == basis) and (kind == "all" or e.kind == kind)
            ]
            assert int(row[col[basis]]) == len(sel), (kind, basis)


def test_figures_name_the_claims_that_check_them(wf_evals, wf_report):
    table = wf_report.section("figures").blocks[1]
    assert isinstance(table, Table)
    rows = dict(zip(table.ids, table.rows, strict=True))  # the figure's id -> its row
    assert {"WF-fig1", "WF-fig2"} <= set(rows)
    assert rows["WF-fig1"][0] == "Fig. 1"  # named by its number, as the book numbers it
    own = [r for r in table.rows if r[1] == "not in the paper"]
    assert own and all(re.fullmatch(r"Fig\. N\d+", r[0]) for r in own)
    fig1 = figure_claims("Fig. 1", wf_evals)
    assert fig1 and all("Fig" in e.claim.locator for e in fig1)
    for e in fig1:
        assert f"{e.claim.id} ({e.status})" in rows["WF-fig1"][2]
    # "Fig. 2" is not "Fig. 2.1": the figure numbers are compared whole
    assert not figure_claims("Fig. 2", [e for e in wf_evals if "Fig. 2." in e.claim.locator])


def test_cli_prints_the_findings(capsys):
    assert main(["report", "wf"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Findings\n")
    for e in ledger.errata(PAPER):
        assert e.id in out


def test_cli_refuses_an_unknown_paper(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["report", "XY"])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert "invalid choice" in err and all(p in err for p in ("WF", "SP", "ATC10", "KZL"))
    with pytest.raises(ValueError, match="paper must be one of WF, SP, ATC10, KZL; got 'XY'"):
        check_paper("XY")
    with pytest.raises(ValueError, match="paper must be one of"):
        build_report("XY", [])


def test_latex_is_produced(wf_report):
    tex = to_latex(wf_report)
    assert tex.startswith("\\documentclass") and tex.rstrip().endswith("\\end{document}")
    plain = re.sub(r"\\allowbreak\{\}", "", tex)  # where a long id or hash may break
    p = wf_report.provenance
    for value in (p.commit, p.lock_sha256, p.python):  # the title page carries the provenance
        assert value in plain
    for e in ledger.errata(PAPER):
        assert e.id in plain
    assert "\\begin{longtable}" in tex


@pytest.mark.skipif(shutil.which("xelatex") is None, reason="xelatex is not installed: no PDF to typeset")
def test_pdf_compiles_strictly(wf_report, tmp_path):
    out = write_pdf(wf_report, tmp_path / "WF.pdf")
    assert out.read_bytes().startswith(b"%PDF")


def test_a_note_several_unsettled_claims_share_is_said_once():
    """Synthetic: three inconsistent claims, two with one note; that note is given once, with
    the number and the ids of its claims, and the third claim keeps its own note."""
    from types import SimpleNamespace

    from navcore.report import unresolved_notes

    def stub(cid, note):
        return SimpleNamespace(status="inconsistent", claim=SimpleNamespace(id=cid, note=note))

    evals = [
        stub("SP-x-a", "the long shared note"),
        stub("SP-y", "its own"),
        stub("SP-x-b", "the long shared note"),
    ]
    assert unresolved_notes(evals) == ["**Note A**, for these 2 claims (SP-x-(a, b)): the long shared note"]
