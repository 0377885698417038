"""The chapters' claim tables (grouping, disclosures, statement wording, anchors), inline
math in notes and errata, and the readable claim ids.

Oracles: the grouping, the wording and the markup written out by hand for synthetic claims
built in the test; for the renamed ids, the map of ``tools/rename_claim_ids.py``.
"""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

from navcore.formatting import math_spans
from navcore.ledger import EXACT, Claim, Erratum, Tolerance, evaluate
from navcore.ledger.tables import ErrataList, LedgerTable, group_claims
from navcore.ledger.text import claim_group, html_text, tex_text

ROOT = Path(__file__).resolve().parents[1]
TOL = Tolerance(reason="half a unit in the last printed digit", abs=0.5, policy="printed-digits")
SHARED_NOTE = "Needs the post-calibration covariance, which the paper does not give."


def make(**kw):
    base = dict(
        id="SP-test-1",
        paper="SP",
        locator="Table 2.6, column 4",
        quantity="natural frequency of the aided loop",
        published=10.0,
        unit="rad/s",
        compute=lambda: 10.2,
        tolerance=TOL,
        expected_status="reproduced",
        note=SHARED_NOTE,
    )
    base.update(kw)
    return Claim(**base)


def statement(**kw):
    base = dict(
        id="SP-test-s",
        locator="Sec. 2.5",
        quantity="the printed matrix is the sensitivity",
        published=True,
        unit="statement",
        compute=lambda: True,
        tolerance=EXACT,
        note="A logical check.",
    )
    base.update(kw)
    return make(**base)


def table_evals():
    return [
        evaluate(make(id="SP-test-1")),
        evaluate(make(id="SP-test-2", compute=lambda: 9.9)),
        evaluate(make(id="SP-test-3", note="Only this one has its own note.")),
        evaluate(statement(id="SP-test-s1")),
        evaluate(statement(id="SP-test-s2", compute=lambda: False, expected_status="inconsistent")),
    ]


# -- grouping ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("locator", "group"),
    [
        ("Table 2.6, column 2", "Table 2.6"),
        ("Table 2.6", "Table 2.6"),
        ("Sec. 3.6, discussion of Fig. 5", "Fig. 5"),
        ("Sec. III, after Eq. (9)", "Eq. (9)"),
        ("Eqs. (16)-(17)", "Eqs. (16)-(17)"),
        ("Theorem, Eqs. (21)-(23)", "Theorem"),
        ("Sec. 2.8", "Sec. 2.8"),
        ("Sec. IV.D", "Sec. IV.D"),
        ("Remark (ii)", "Remark (ii)"),
        ("Appendix H, corollary (H.26)", "Appendix H"),
        ("Sec. 2.6.1 (Figs. 2.2-2.3)", "Figs. 2.2-2.3"),
    ],
)
def test_claim_group_names_what_the_claim_checks(locator, group):
    assert claim_group(locator) == group


def test_consecutive_claims_of_one_group_share_a_header():
    evals = [
        evaluate(make(id="SP-test-a", locator="Table 2.6, column 2")),
        evaluate(make(id="SP-test-b", locator="Table 2.6, column 2")),
        evaluate(make(id="SP-test-c", locator="Table 2.6, row 'No inertial aiding'")),
        evaluate(make(id="SP-test-d", locator="Sec. 2.5, worked example after Table 2.6")),
        evaluate(make(id="SP-test-e", locator="Sec. 2.5")),
        evaluate(make(id="SP-test-f", locator="Table 2.6, column 2")),
    ]
    groups = group_claims(evals)
    # a run of one locator is its own group; the others group by what they check; a group
    # that comes back later (not consecutive) gets a header again
    assert [(g.heading, [e.claim.id[-1] for e in g.evals]) for g in groups] == [
        ("Table 2.6, column 2", ["a", "b"]),
        ("Table 2.6", ["c", "d"]),
        ("Sec. 2.5", ["e"]),
        ("Table 2.6, column 2", ["f"]),
    ]
    html = LedgerTable(evals)._repr_html_()
    assert html.count('class="ledger-group"') == 4
    # the row says what its locator adds to the header
    assert "(row &#x27;No inertial aiding&#x27;)" in html


# -- HTML -------------------------------------------------------------------------------


def _rows(html: str) -> dict[str, str]:
    return dict(re.findall(r'<tr id="([^"]+)" class="ledger-claim"[^>]*>(.*?)</tr>', html))


def test_one_line_per_claim_with_anchor_badge_kind_and_disclosure():
    html = LedgerTable(table_evals(), root="../")._repr_html_()
    rows = _rows(html)
    assert list(rows) == ["sp-test-1", "sp-test-2", "sp-test-3", "sp-test-s1", "sp-test-s2"]
    first = rows["sp-test-1"]
    assert first.count("<td") == 5
    assert "natural frequency of the aided loop" in first
    assert "10&nbsp;rad/s" in first and "10.2&nbsp;rad/s" in first
    assert '<span class="ledger-badge ledger-status-reproduced">reproduced</span>' in first
    assert '<span class="ledger-kind-label">reproduction</span>' in first
    assert "<details" in first and "<summary>" in first and "<code>SP-test-1</code>" in first
    # the three numbers share their tolerance: it is said in their group's header
    header = re.search(r'<tr class="ledger-group">(.*?)</tr>', html).group(1)
    assert "Tolerance:" in header and "half a unit in the last printed digit" in header
    assert "Tolerance:" not in first
    # no full-width note rows any more
    assert "ledger-note" not in html


def test_shared_note_said_once_in_the_group_header():
    evals = [
        evaluate(make(id="SP-test-1")),
        evaluate(make(id="SP-test-2", compute=lambda: 9.9)),
        evaluate(make(id="SP-test-3")),
    ]
    html = LedgerTable(evals)._repr_html_()
    assert html.count(SHARED_NOTE) == 1
    header = re.search(r'<tr class="ledger-group">(.*?)</tr>', html).group(1)
    assert SHARED_NOTE in header and "note for these 3 claims" in header
    # the tolerance is shared as well; each row keeps its id in its own disclosure
    assert html.count("half a unit in the last printed digit") == 1
    for row in _rows(html).values():
        assert SHARED_NOTE not in row and "<details" in row


def test_note_not_shared_stays_with_its_claim():
    html = LedgerTable(table_evals())._repr_html_()
    rows = _rows(html)
    assert "Only this one has its own note." in rows["sp-test-3"]
    assert SHARED_NOTE in rows["sp-test-1"] and SHARED_NOTE in rows["sp-test-2"]
    # a group of one shares nothing with itself: no header disclosure
    assert "note for these 1 claims" not in html


SCENARIO = (
    "Covariance analysis of the sequential-outage mission (Sec. 2.6.1): loosely and tightly "
    "coupled navigators on the assumed trajectory, with the paper's initial errors. "
)


def test_common_opening_of_notes_said_once():
    """Oracle: notes built by hand as a scenario sentence plus a sentence of each claim's own;
    the header holds the scenario once, each row keeps only its own sentence ("…" where the
    scenario covers some of the group), and no sentence is cut (the 'Sec. 2.6.1' full stop
    is not taken for a sentence end)."""
    own = ["84 min is one Schuler period.", "The 10 nmi/h error is random walk.", "Different note."]
    evals = [
        evaluate(make(id="SP-test-1", note=SCENARIO + own[0])),
        evaluate(make(id="SP-test-2", note=SCENARIO + own[1])),
    ]
    html = LedgerTable(evals)._repr_html_()
    header = re.search(r'<tr class="ledger-group">(.*?)</tr>', html).group(1)
    assert html.count("sequential-outage mission") == 1 and "sequential-outage mission" in header
    assert "note for these 2 claims" in header
    rows = _rows(html)
    assert own[0] in rows["sp-test-1"] and own[1] in rows["sp-test-2"]
    assert "…" not in html
    # a third claim with its own note: the scenario is shared by two of three, who continue with "…"
    evals.append(evaluate(make(id="SP-test-3", note=own[2])))
    html = LedgerTable(evals)._repr_html_()
    header = re.search(r'<tr class="ledger-group">(.*?)</tr>', html).group(1)
    assert "note shared by 2 of these 3 claims" in header and html.count("sequential-outage") == 1
    rows = _rows(html)
    assert f"… {own[0]}" in rows["sp-test-1"] and own[2] in rows["sp-test-3"] and "…" not in rows["sp-test-3"]
    tex = LedgerTable(evals).latex()
    assert tex.count("sequential-outage") == 1 and "note shared by 2 of these 3 claims" in tex
    # a short common opening is not worth a header note
    short = [evaluate(make(id=f"SP-test-{i}", note=f"Same start. Own {i}.")) for i in (1, 2)]
    html = LedgerTable(short)._repr_html_()
    header = re.search(r'<tr class="ledger-group">(.*?)</tr>', html).group(1)
    assert "Same start" not in header and html.count("Same start.") == 2


def test_statements_read_in_words():
    rows = _rows(LedgerTable(table_evals())._repr_html_())
    assert "stated" in rows["sp-test-s1"] and ">holds<" in rows["sp-test-s1"]
    assert ">does not hold<" in rows["sp-test-s2"]
    for row in (rows["sp-test-s1"], rows["sp-test-s2"]):
        assert "true" not in row and "false" not in row
        assert "statement" in row
    # an exact tolerance says nothing about a truth value: not shown
    assert "logical statement" not in rows["sp-test-s1"]
    text = LedgerTable([evaluate(statement(published=False, compute=lambda: False))])._repr_html_()
    assert "stated not to hold" in text


def test_erratum_link_and_page_link_stay():
    claim = make(
        id="SP-test-d",
        compute=lambda: 20.0,
        expected_status="discrepant",
        erratum="SP-E-test",
        oracle=lambda: 20.0,
        oracle_tolerance=TOL,
        discussed_in="sp/03-residual-acceleration",
    )
    html = LedgerTable([evaluate(claim)], root="../", link_pages=True)._repr_html_()
    assert 'href="../errata.html#sp-e-test"' in html
    assert 'href="../sp/03-residual-acceleration.html#sp-test-d"' in html
    assert 'id="sp-test-d"' in html


def test_without_notes_no_disclosures():
    html = LedgerTable(table_evals(), show_notes=False)._repr_html_()
    assert "<details" not in html and SHARED_NOTE not in html
    assert len(_rows(html)) == 5


# -- LaTeX ------------------------------------------------------------------------------


def test_latex_groups_span_the_width_and_share_notes_once():
    evals = [evaluate(make(id=f"SP-test-{i}")) for i in range(3)] + [evaluate(statement())]
    tex = LedgerTable(evals).latex()
    assert tex.count(r"\multicolumn{4}") == 2  # two groups
    assert tex.count("Needs the post-calibration covariance") == 1
    assert r"\scriptsize" in tex and r"\begin{longtable}" in tex
    # column widths add up to the text width
    widths = [float(w) for w in re.findall(r"p\{\\dimexpr ([0-9.]+)\\linewidth", tex)]
    assert sum(widths) == pytest.approx(1.0)
    assert "stated" in tex and "holds" in tex and "true" not in tex


# -- inline math ------------------------------------------------------------------------


def test_math_spans_and_lone_dollars():
    assert math_spans(r"with $\tau P_N \tau^T$ here") == [
        (False, "with "),
        (True, r"\tau P_N \tau^T"),
        (False, " here"),
    ]
    # a price is not math: a dollar sign followed by a space
    assert math_spans("a 50,000-100,000 $ INS") == [(False, "a 50,000-100,000 $ INS")]


def test_math_in_html_is_marked_up_for_mathjax():
    out = html_text(r"is $O(N^{-3/2})$ & <b>")
    assert out == (r'is <span class="math notranslate nohighlight">\(O(N^{-3/2})\)</span> &amp; &lt;b&gt;')
    assert html_text("x < y") == "x &lt; y"


def test_math_in_latex_passes_unescaped():
    assert tex_text(r"50 % of $e^{FT}$ and $x_1$") == r"50 \% of $e^{FT}$ and $x_1$"
    assert tex_text("a 5 $ thing") == r"a 5 \$ thing"


def test_math_in_notes_and_errata():
    claim = make(note=r"Reads $\sigma_{DN} = \sqrt{\sigma_N^2 + \sigma_T^2}$.")
    html = LedgerTable([evaluate(claim)])._repr_html_()
    assert r'<span class="math notranslate nohighlight">\(\sigma_{DN}' in html
    tex = LedgerTable([evaluate(claim)]).latex()
    assert r"$\sigma_{DN} = \sqrt{\sigma_N^2 + \sigma_T^2}$" in tex
    erratum = Erratum(
        id="SP-E-test",
        paper="SP",
        kind="typography",
        basis="text-only",
        locator="Eq. (1)",
        printed=r"$e^{-\omega_0 t^2}$",
        finding=r"$e^{-\omega_0 t/2}$",
        evidence="sympy",
    )
    html = ErrataList([erratum])._repr_html_()
    assert r'<span class="math notranslate nohighlight">\(e^{-\omega_0 t^2}\)</span>' in html
    assert r"$e^{-\omega_0 t/2}$" in ErrataList([erratum])._repr_markdown_()


def test_registered_texts_have_balanced_math():
    """Every ``$`` of a registered note, quantity or erratum text opens or closes math, except
    a lone dollar sign before a space (a price)."""
    from navcore import ledger

    texts = [t for c in ledger.claims() for t in (c.note, c.quantity)]
    texts += [t for e in ledger.errata() for t in (e.printed, e.finding, e.evidence)]
    for t in texts:
        for is_math, piece in math_spans(t):
            assert is_math or not re.search(r"\$(?!\s|$)", piece), t


# -- readable ids -----------------------------------------------------------------------


def _rename_tool():
    spec = importlib.util.spec_from_file_location("rename_claim_ids", ROOT / "tools" / "rename_claim_ids.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_old_ids_resolve_to_the_renamed_claims():
    from navcore import ledger

    renames = _rename_tool().RENAMES
    assert len(renames) >= 45
    ids = {c.id for c in ledger.claims()}
    for old, new in renames.items():
        assert new in ids and old not in ids
        c = ledger.claim(old)
        assert c.id == new and old in c.aliases
    assert not [i for i in ids if re.search(r"-c\d+(-|$)", i)]


def test_evaluating_an_old_id_gives_the_new_one(monkeypatch):
    from navcore import ledger

    monkeypatch.setenv("NAVCORE_CACHE", "off")
    old = "WF-c21-50Hz"
    ev = ledger.evaluate_claim(old)
    assert ev.claim.id == "WF-fig1-update-rate-50hz"
    assert ev.as_json()["id"] == "WF-fig1-update-rate-50hz"
    assert ledger.evaluate_claim("WF-fig1-update-rate-50hz") is ev


def test_rename_rewrites_whole_ids_only_and_is_idempotent():
    tool = _rename_tool()
    text = (
        'claims=("KZL-c16", "KZL-c16-covariance"),\n'
        "see KZL-c16. and KZL-c23-c24; not KZL-c160 nor XKZL-c16\n"
        '        aliases=("KZL-c16",),\n'
    )
    once = tool.rewrite_text(text)
    assert once == (
        'claims=("KZL-sec3.6-heading-with-init", "KZL-sec3.6-heading-with-init-covariance"),\n'
        "see KZL-sec3.6-heading-with-init. and KZL-fig5-tight-three-bounded; not KZL-c160 nor XKZL-c16\n"
        '        aliases=("KZL-c16",),\n'
    )
    assert tool.rewrite_text(once) == once
    module = '    Claim(\n        id="KZL-c7",\n        paper="KZL",\n'
    renamed = tool.rewrite_text(module, add_aliases=True)
    assert renamed == (
        '    Claim(\n        id="KZL-sec2.1-four-measurements",\n'
        '        aliases=("KZL-c7",),\n        paper="KZL",\n'
    )
    assert tool.rewrite_text(renamed, add_aliases=True) == renamed


def test_no_old_id_left_in_the_repository():
    proc = subprocess.run(
        [sys.executable, str(ROOT / "tools" / "rename_claim_ids.py"), "--check"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert proc.returncode == 0, proc.stdout


@pytest.mark.parametrize(
    ("piece", "made_whole"),
    [
        # an alignment point of the paper's display, and its equation number, left out
        (r"\gamma_n &= \frac{a}{b} \tag{4.5.31}", r"\gamma_n = \frac{a}{b}"),
        (r"\leq K \left(x\right) \quad (\text{A.7})", r"\leq K \left(x\right)"),
        # a quote that stops inside \left[ ... or inside a brace
        (r"\exp \left[(K t + 1) \ln", r"\exp \left[(K t + 1) \ln\right."),
        (r"\sqrt{2 \frac{\partial^2}{\partial r^2}", r"\sqrt{2 \frac{\partial^2}{\partial r^2}\ldots}"),
        (r"x \right) - 1", r"\left.x \right) - 1"),
        # rows of a matrix cut from its environment; an environment's own & and \\ untouched
        (r"a & b \\ c & d", r"\begin{matrix}a & b \\ c & d\end{matrix}"),
        (
            r"P &= \begin{bmatrix} a & b \\ c & d \end{bmatrix}",
            r"P = \begin{bmatrix} a & b \\ c & d \end{bmatrix}",
        ),
        # escaped braces are not groups; Unicode letters and operators as commands
        (r"\{ \rho = 1 \}", r"\{ \rho = 1 \}"),
        ("1.61×10^{-4}, σ_a", r"1.61\times 10^{-4}, \sigma _a"),
    ],
)
def test_quote_math_makes_a_cut_formula_whole(piece, made_whole):
    """Oracle: each fragment closed by hand (a quote may stop inside the paper's display)."""
    from navcore.ledger.text import quote_math

    assert quote_math(piece) == made_whole


def _claim_quotes() -> list[tuple[str, str]]:
    from navcore import ledger
    from navcore.claims.quotes import claim_quote

    quotes = [(c.id, claim_quote(c)) for c in ledger.claims()]
    return [(cid, q) for cid, (q, src) in quotes if src == "claim"]


def test_no_quote_is_shown_as_latex_source():
    """Every claim's quote is typeset: its words as text and its formulas as math, in the HTML
    claim rows and ledger (MathJax) and in the PDF tables; none falls back to LaTeX source in
    code type (which it did for 84 quotes whose formulas the transcription left bare)."""
    from navcore.ledger.text import _printed_html, _printed_tex

    quotes = _claim_quotes()
    assert len(quotes) > 400
    source = [cid for cid, q in quotes if "ledger-latex" in _printed_html(q) or "ttfamily" in _printed_tex(q)]
    assert not source, source


def test_every_quote_typesets_in_latex(tmp_path):
    """Oracle: XeLaTeX itself. Every claim's quote as the PDF's Printed cell sets it compiles
    without an error, cut formulas (an open brace, a lone \\left, rows of a matrix) included."""
    import shutil

    from navcore.ledger.text import FIT_MATH_PREAMBLE, _printed_tex

    if shutil.which("xelatex") is None:
        pytest.skip("xelatex is not installed")
    cells = "\n".join(
        rf"\noindent\parbox{{6cm}}{{{_printed_tex(q)}}}\par % {cid}" for cid, q in _claim_quotes()
    )
    doc = (
        "\\documentclass{article}\\usepackage{fontspec}\\usepackage{amsmath,amssymb,graphicx}\n"
        + FIT_MATH_PREAMBLE
        + "\n\\begin{document}\n"
        + cells
        + "\n\\end{document}\n"
    )
    (tmp_path / "q.tex").write_text(doc, encoding="utf-8")
    run = subprocess.run(
        ["xelatex", "-interaction=nonstopmode", "-halt-on-error", "q.tex"],
        cwd=tmp_path, capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert run.returncode == 0, run.stdout[-3000:]
