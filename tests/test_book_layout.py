"""The layout gate's bookkeeping and the book's Sphinx extensions for the API reference and the PDF.

The Chromium measurement itself runs in ``nox -s book``; here it is replaced by fixed
measurements, so that what the gate does with them (the allowlist, which only shrinks) is
checked on any machine. The extensions are run on small doctrees built here.
"""

from __future__ import annotations

import enum
import importlib.util
import json
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest
from docutils import nodes

ROOT = Path(__file__).resolve().parents[1]


def _load(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def layout(monkeypatch, tmp_path):
    module = _load(ROOT / "tools" / "check_layout.py", "check_layout")
    allow = tmp_path / "allow.json"
    monkeypatch.setattr(module, "ALLOWLIST", allow)
    return module, allow


def _item(name: str) -> tuple[str, dict]:
    return name, {"name": name, "scroll": 500, "client": 388, "text": "x"}


def test_layout_gate_fails_on_an_overflow_not_in_the_allowlist(layout, monkeypatch):
    module, allow = layout
    allow.write_text(json.dumps({"420": {"math": {"a.html#eq-1": "a 17-column matrix"}}}))
    found = {
        1400: {"math": [], "table": []},
        420: {"math": [_item("a.html#eq-1"), _item("b.html#eq-2")], "table": []},
    }
    monkeypatch.setattr(module, "measure", lambda root, widths, **kw: found)
    problems = module.check(Path("."), (1400, 420))
    assert len(problems) == 1 and "b.html#eq-2" in problems[0]


def test_layout_gate_fails_on_an_allowlist_entry_that_no_longer_overflows(layout, monkeypatch):
    module, allow = layout
    allow.write_text(json.dumps({"420": {"table": {"c.html#T_1": "nine columns of numbers"}}}))
    found = {420: {"math": [], "table": []}}
    monkeypatch.setattr(module, "measure", lambda root, widths, **kw: found)
    problems = module.check(Path("."), (420,))
    assert problems == ["420 px: table c.html#T_1 is in the allowlist but no longer overflows: remove it"]


def test_layout_gate_skips_pages_that_only_redirect(layout, tmp_path):
    module, _ = layout
    (tmp_path / "index.html").write_text('<meta http-equiv="Refresh" content="0; url=intro.html" />')
    (tmp_path / "intro.html").write_text("<p>text</p>")
    (tmp_path / "_static").mkdir()
    (tmp_path / "_static" / "x.html").write_text("<p>asset</p>")
    assert [p.name for p in module.pages(tmp_path)] == ["intro.html"]


def test_layout_gate_measures_each_page_once_in_several_tabs_and_reports_in_page_order(layout, tmp_path):
    """Pages measured at once in several tabs finish in any order; the report follows the pages'
    order, each page is loaded once and measured at every width. Oracle: a stand-in browser
    whose tabs finish in the reverse order of the pages."""
    import asyncio

    module, _ = layout
    for name in ("a", "b", "c", "d", "e"):
        (tmp_path / f"{name}.html").write_text("<p>text</p>")
    loads: list[tuple[str, str, tuple[int, ...]]] = []

    class StandIn:
        def __init__(self, executable):
            self.tabs = 0

        async def connect(self):
            pass

        async def open_tab(self):
            self.tabs += 1
            return f"tab-{self.tabs}"

        async def measure(self, session, url, widths):
            name = url.rsplit("/", 1)[1]
            loads.append((session, name, widths))
            await asyncio.sleep(0.01 * (ord("f") - ord(name[0])))  # the first page finishes last
            return {w: {"math": [{"name": f"eq-{w}", "scroll": 9, "client": 1, "text": ""}]} for w in widths}

        def close(self):
            pass

    module.Browser = StandIn
    module.find_browser = lambda: "chromium"
    found = module.measure(tmp_path, (1400, 420), tabs=3)
    assert sorted(name for _, name, _ in loads) == ["a.html", "b.html", "c.html", "d.html", "e.html"]
    assert {widths for _, _, widths in loads} == {(1400, 420)}
    assert len({session for session, _, _ in loads}) == 3
    for width in (1400, 420):
        assert [name for name, _ in found[width]["math"]] == [f"{p}.html#eq-{width}" for p in "abcde"]


@pytest.mark.skipif(
    not any(__import__("shutil").which(b) for b in ("chromium", "chromium-browser", "google-chrome")),
    reason="no Chromium",
)
def test_layout_gate_finds_a_word_broken_in_a_text_tables_first_column(layout, tmp_path):
    """Oracle: Chromium laying out two tiny pages, one whose first column is narrower than
    "Appendix" and breaks anywhere, one whose first column keeps its words; a claim id broken
    after a hyphen is not a broken word."""
    module, _ = layout

    def page(name: str, style: str) -> None:
        (tmp_path / name).write_text(
            '<article class="bd-article"><div class="cell_output"><table class="navcore-text-table">'
            f'<tbody><tr><td style="{style}">Appendix D</td><td>text</td></tr>'
            '<tr><td style="width:4em">WF-eq3-normal</td><td>x</td></tr></tbody></table></div></article>'
        )

    page("broken.html", "overflow-wrap:anywhere; width:30px")
    page("whole.html", "overflow-wrap:normal")
    found = module.measure(tmp_path, (1400,), tabs=1)[1400]["word"]
    assert [name for name, _ in found] == ["broken.html#text-table-1"]
    assert 'inside "Appendix"' in found[0][1]["text"]


def test_layout_gate_finds_a_word_broken_in_any_column_of_a_whole_words_table(layout, tmp_path):
    """Oracle: Chromium laying out two tiny pages whose tables keep their words whole
    (``navcore-whole-words``, the Assumptions page's), one of them with a second column that
    breaks "deterministic" anywhere; in a plain text table only the first column is measured."""
    module, _ = layout

    def page(name: str, classes: str, style: str) -> None:
        (tmp_path / name).write_text(
            f'<article class="bd-article"><div class="cell_output"><table class="{classes}">'
            f'<tbody><tr><td>Sec. 2</td><td style="{style}">deterministic input</td></tr></tbody>'
            "</table></div></article>"
        )

    narrow = "overflow-wrap:anywhere; width:40px"
    page("broken.html", "navcore-text-table navcore-whole-words", narrow)
    page("whole.html", "navcore-text-table navcore-whole-words", "overflow-wrap:normal")
    page("plain.html", "navcore-text-table", narrow)
    found = module.measure(tmp_path, (1400,), tabs=1)[1400]["word"]
    assert [name for name, _ in found] == ["broken.html#text-table-1"]
    assert 'column 2 breaks inside "deterministic"' in found[0][1]["text"]


def test_text_tables_lay_out_for_a_phone_as_cards_or_with_upright_headings(layout, tmp_path):
    """Oracle: Chromium laying out, at 420 px with the book's style sheet, two text tables too
    wide for a phone as tables (six columns of long whole words; eleven count columns with
    word headings): as cards, and with their headings on their side, both fit the column,
    while the same tables without their phone layout run past it."""
    import pandas as pd

    from navcore import book

    module, _ = layout
    words = pd.DataFrame({f"Heading{i}": [f"deterministic{i} and more"] for i in range(6)})
    counts = pd.DataFrame({"Section": ["Appendix D"], **{f"heading{i}": [i] for i in range(10)}})
    cards, upright = book.text_table(words, "navcore-whole-words"), book.text_table(counts)
    assert 'class="navcore-text-table navcore-cards navcore-whole-words"' in cards._repr_html_()
    assert 'data-label="Heading5"' in cards._repr_html_()
    assert "navcore-counts-phone" in upright._repr_html_() and "data-label" not in upright._repr_html_()
    three = book.text_table(pd.DataFrame({"a": ["x"], "b": ["y"], "c": ["z"]}))._repr_html_()
    assert "navcore-cards" not in three and "navcore-counts-phone" not in three
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")
    for name, table in (("cards", cards), ("upright", upright)):
        for variant, html in (("", table._repr_html_()), ("-as-table", table._repr_html_())):
            if variant:  # the same table without its phone layout
                html = html.replace(" navcore-cards", "").replace(" navcore-counts-phone", "")
            (tmp_path / f"{name}{variant}.html").write_text(
                f'<html><head><style>{css}</style></head><body><main class="bd-content">'
                '<article class="bd-article" style="width:100%">'
                f'<div class="cell_output"><div class="output">{html}</div></div>'
                "</article></main></body></html>"
            )
    measured = module.measure(tmp_path, (420,), tabs=1)[420]["table"]
    assert [name for name, _ in measured] == ["cards-as-table.html#table-1", "upright-as-table.html#table-1"]


def _mathjax() -> Path | None:
    """MathJax's CHTML bundle as the book ships it (sphinx-mathjax-offline), if installed."""
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or spec.origin is None:
        return None
    bundle = Path(spec.origin).parent / "static" / "mathjax" / "tex-chtml.js"
    return bundle if bundle.exists() else None


def test_a_text_tables_long_formula_breaks_after_its_relation_in_html_only():
    """Oracle: the formula cut by hand where TeX may break it (after ``=`` and the binary
    ``-``, not inside the bars); a numeric table and the printed (LaTeX) table keep it whole."""
    import pandas as pd

    from navcore import book

    frame = pd.DataFrame(
        {
            "reading": ["so $\\mathrm{Exp}_g = a^2/(2p)$"],
            "reason": ["$|x - y|$ and $C/N_0 - 10\\log_{10} B_L$"],
        }
    )
    html_text = book.text_table(frame)._repr_html_()
    assert "\\(\\mathrm{Exp}_g ={}\\)</span><wbr><span" in html_text
    assert "\\(a^2/(2p)\\)" in html_text and "\\(|x - y|\\)" in html_text
    assert "\\(C/N_0 -{}\\)</span><wbr><span" in html_text
    assert "<wbr>" not in book.table(frame)._repr_html_()
    printed = book.text_table(frame)._repr_markdown_()
    assert "<wbr>" not in printed and "{}" not in printed
    assert "\\mathrm{Exp}_g = a^2/(2p)" in printed and "$C/N_0 - 10\\log_{10} B_L$" in printed


@pytest.mark.skipif(_mathjax() is None, reason="no MathJax bundle (sphinx-mathjax-offline)")
def test_a_text_table_with_long_formulas_fits_a_column_that_the_whole_formulas_overflow(layout, tmp_path):
    """Oracle: Chromium and MathJax laying out, in a 330-px column with the book's style sheet,
    a text table of four formulas set side by side in two columns (each formula about 150 px
    wide): with the formulas cut where TeX may break them it fits; the same table with every
    formula whole runs past the column."""
    import shutil

    import pandas as pd

    from navcore import book

    module, _ = layout
    shutil.copy(_mathjax(), tmp_path / "tex-chtml.js")
    formula = "$\\mathrm{Exp}_g = a^2/(2p) + b^2/(2q)$"
    frame = pd.DataFrame({"first": [f"a {formula}"], "second": [f"b {formula}"]})
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")
    broken = book.text_table(frame)._repr_html_()
    for name, table in (
        ("broken", broken),
        ("whole", broken.replace('{}\\)</span><wbr><span class="math notranslate nohighlight">\\(', " ")),
    ):
        (tmp_path / f"{name}.html").write_text(
            f'<html><head><style>{css}</style><script src="tex-chtml.js"></script></head><body>'
            '<main class="bd-content"><article class="bd-article" style="width:330px">'
            f'<div class="cell_output"><div class="output">{table}</div></div>'
            "</article></main></body></html>"
        )
    assert "<wbr>" in broken and "<wbr>" not in (tmp_path / "whole.html").read_text()
    measured = module.measure(tmp_path, (1400,), tabs=1)[1400]["table"]
    assert [name for name, _ in measured] == ["whole.html#table-1"]


#: WF's Eq. (6) as a claim row quotes it (the Printed cell of claim WF-eq6-montecarlo)
_EQ6 = (
    r"$$\hat{\mathbf{p}}^e - \mathbf{p}^e = (\mathbf{H}^T \mathbf{W} \mathbf{H})^{-1} "
    r"\mathbf{H}^T \mathbf{W}[\mathbf{e} + \tilde{\mathbf{f}}_\theta], \quad (6)$$"
)


def _claim_row_page(path: Path, cells: str, width: str, *, fitting: bool = True) -> None:
    """A page of one claim row (``table.ledger-claims``) with the book's style sheet, MathJax
    and (``fitting``) its equation fitting, in a text column of ``width``."""
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")
    fit = '<script src="navcore-math.js"></script>' if fitting else ""
    path.write_text(
        f'<html><head><style>{css}</style><script src="tex-chtml.js"></script>'
        f'{fit}</head><body><main class="bd-content">'
        f'<article class="bd-article" style="width:100%; max-width:{width}">'
        '<div class="cell_output"><div class="output text_html"><table class="ledger-claims"><tbody>'
        f'<tr id="x-eq6" class="ledger-claim">{cells}</tr></tbody></table></div></div>'
        "</article></main></body></html>"
    )


def _boxed(tex: str) -> str:
    """A formula in a claim row's box of its own, as the ledger sets a long one."""
    span = f'<span class="math notranslate nohighlight">\\({tex}\\)</span>'
    return f'<span class="ledger-math-wide">{span}</span>'


@pytest.mark.skipif(_mathjax() is None, reason="no MathJax bundle (sphinx-mathjax-offline)")
def test_layout_gate_finds_a_formula_cut_in_its_own_box_in_a_claim_row_or_folded_details(layout, tmp_path):
    """A long formula of a claim row scrolls inside its own box (``ledger-math-wide``), which
    the measurement of display blocks never sees. Oracle: Chromium and MathJax laying out three
    one-row claim tables with the book's style sheet: a formula wider than its box, the same
    formula in a folded "details" (measured opened), and a short one; only the first two are
    cut, each named by its row. A formula with no place to break, a fifth wider than its box,
    is set smaller to fit by the book's equation fitting; without the fitting it is cut. The
    first page's formula in a narrow paragraph, not in a claim table, is only counted."""
    import shutil

    module, _ = layout
    shutil.copy(_mathjax(), tmp_path / "tex-chtml.js")
    shutil.copy(ROOT / "book" / "_static" / "navcore-math.js", tmp_path / "navcore-math.js")
    long = r"\hat{\mathbf{p}}^e - \mathbf{p}^e = (\mathbf{H}^T \mathbf{W} \mathbf{H})^{-1} \mathbf{H}^T"
    boxed = _boxed(long * 2)
    _claim_row_page(tmp_path / "cut.html", f'<td class="ledger-value">{boxed}</td>', "772px")
    folded = f'<details class="ledger-details"><summary>details</summary><p>{boxed}</p></details>'
    _claim_row_page(tmp_path / "folded.html", f'<td class="ledger-what">text {folded}</td>', "772px")
    short = '<span class="math notranslate nohighlight">\\(K_1 &lt; 2\\)</span>'
    _claim_row_page(tmp_path / "fits.html", f'<td class="ledger-value">{short}</td>', "772px")
    # 17 upright m's: about 1.2 times the 16-em box of a claim table at MathJax's size
    unbroken = _boxed("\\mathrm{" + "m" * 17 + "}")
    _claim_row_page(tmp_path / "fitted.html", f'<td class="ledger-value">{unbroken}</td>', "772px")
    _claim_row_page(
        tmp_path / "not-fitted.html", f'<td class="ledger-value">{unbroken}</td>', "772px", fitting=False
    )
    # the same cut formula outside a chapter's claim table (in a narrow paragraph) is counted
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")
    (tmp_path / "prose.html").write_text(
        f'<html><head><style>{css}</style><script src="tex-chtml.js"></script></head><body>'
        f'<article class="bd-article"><p id="x-eq6" style="width:150px">{boxed}</p></article></body></html>'
    )
    measured = module.measure(tmp_path, (1400,), tabs=1)[1400]
    found = measured["math"]
    assert [name for name, _ in found] == [
        "cut.html#x-eq6-inline-math-1",
        "folded.html#x-eq6-inline-math-1",
        "not-fitted.html#x-eq6-inline-math-1",
    ]
    assert all(item["scroll"] > item["client"] for _, item in found)
    assert [name for name, _ in measured["inline"]] == ["prose.html#x-eq6-inline-math-1"]


@pytest.mark.skipif(_mathjax() is None, reason="no MathJax bundle (sphinx-mathjax-offline)")
def test_an_inline_formula_a_little_wider_than_its_line_is_set_smaller_to_fit(layout, tmp_path):
    """An inline formula of running text up to 1/0.7 times wider than its line is set smaller
    by the book's equation fitting and no longer cut; one twice as wide keeps its size and is
    counted. Oracle: Chromium and MathJax laying out two paragraphs in 250-px boxes that
    scroll, with the book's style sheet, measured by the layout gate, with and without the
    fitting (without it, both are cut)."""
    import shutil

    module, _ = layout
    shutil.copy(_mathjax(), tmp_path / "tex-chtml.js")
    shutil.copy(ROOT / "book" / "_static" / "navcore-math.js", tmp_path / "navcore-math.js")
    css = (ROOT / "book" / "_static" / "navcore.css").read_text(encoding="utf-8")

    def formula(n: int) -> str:  # n upright m's, about 18 px each at MathJax's size
        return '<span class="math notranslate nohighlight">\\(\\mathrm{' + "m" * n + "}\\)</span>"

    for name, fitting in (("fitted.html", True), ("not-fitted.html", False)):
        script = '<script src="navcore-math.js"></script>' if fitting else ""
        (tmp_path / name).write_text(
            f'<html><head><style>{css}</style><script src="tex-chtml.js"></script>{script}</head>'
            '<body><article class="bd-article">'
            f'<div id="little" style="width:250px; overflow-x:auto"><p>text {formula(16)}</p></div>'
            f'<div id="twice" style="width:250px; overflow-x:auto"><p>text {formula(28)}</p></div>'
            "</article></body></html>"
        )
    inline = [name for name, _ in module.measure(tmp_path, (1400,), tabs=1)[1400]["inline"]]
    assert sorted(inline) == [
        "fitted.html#twice-inline-math-1",
        "not-fitted.html#little-inline-math-1",
        "not-fitted.html#twice-inline-math-1",
    ]


@pytest.mark.skipif(_mathjax() is None, reason="no MathJax bundle (sphinx-mathjax-offline)")
def test_a_claim_rows_quoted_display_equation_fits_its_column_on_a_screen_and_a_phone(layout, tmp_path):
    """WF's Eq. (6) quoted in a claim row's Printed cell (a displayed equation set inline) is
    not cut at 1400 px nor at 420 px. Oracle: Chromium and MathJax laying out the row as the
    ledger renders it, with the book's style sheet and equation fitting, in the book's text
    column at 1400 px (772 px) and in a phone's full width, measured by the layout gate."""
    import shutil

    from navcore.ledger import EXACT, Claim, evaluate
    from navcore.ledger.tables import LedgerTable

    module, _ = layout
    shutil.copy(_mathjax(), tmp_path / "tex-chtml.js")
    shutil.copy(ROOT / "book" / "_static" / "navcore-math.js", tmp_path / "navcore-math.js")
    claim = Claim(
        id="WF-x-eq6", paper="WF", locator="Eq. (6)", quantity="Eq. (6) predicts the spread",
        published=True, unit="statement", compute=lambda: True, tolerance=EXACT, printed=_EQ6,
        expected_status="consistent", note="a synthetic claim",
    )  # fmt: skip
    table = LedgerTable([evaluate(claim)])._repr_html_()
    assert "\\hat{\\mathbf{p}}^e" in table
    row = table[table.index('<tr id="wf-x-eq6"') :]
    cells = row[row.index(">") + 1 : row.index("</tr>")]
    _claim_row_page(tmp_path / "row.html", cells, "772px")
    measured = module.measure(tmp_path, (1400, 420), tabs=1)
    assert measured[1400]["math"] == [] and measured[420]["math"] == []


@pytest.mark.skipif(
    not any(__import__("shutil").which(b) for b in ("chromium", "chromium-browser", "google-chrome")),
    reason="no Chromium",
)
def test_layout_gate_leaves_no_socket_open(layout, tmp_path, monkeypatch):
    """The gate's DevTools connection is closed when the measurement ends: an unclosed socket is
    reported only when it is collected, and then fails whatever test runs next (a CI run failed
    so). Oracle: Python's own report of an unclosed socket at collection."""
    import gc

    module, _ = layout
    (tmp_path / "a.html").write_text('<article class="bd-article"><p>x</p></article>')
    reported = []
    monkeypatch.setattr("sys.unraisablehook", lambda u: reported.append(repr(u.exc_value)))
    for _ in range(2):  # the first run's connection is collected by the second at the latest
        module.measure(tmp_path, (1400,), tabs=1)
    gc.collect()
    assert not [r for r in reported if "socket" in r]


def test_the_committed_allowlist_gives_a_reason_for_every_entry():
    allow = json.loads((ROOT / "tools" / "layout_allowlist.json").read_text(encoding="utf-8"))
    for width, kinds in allow.items():
        if width.startswith("_"):
            continue
        for kind, entries in kinds.items():
            assert kind in ("math", "table", "cell")
            for name, reason in entries.items():
                assert "#" in name and len(reason.split()) >= 4, (width, kind, name)


# --- API reference: a class's fields documented once ---------------------------------------


def test_class_data_attributes_are_skipped_but_methods_and_enum_members_stay():
    ext = _load(ROOT / "book" / "_ext" / "api_reference.py", "api_reference")

    @dataclass(frozen=True)
    class Result:
        t: float
        n: int = 3

        def rms(self) -> float:
            return self.t

    class Kind(enum.Enum):
        A = "a"

    skip = ext._skip_class_data
    assert skip(None, "class", "n", Result.n, False, {}) is True
    assert skip(None, "class", "rms", Result.rms, False, {}) is None
    assert skip(None, "class", "A", Kind.A, False, {}) is None
    assert skip(None, "module", "CONSTANT", 3, False, {}) is None  # module data stays


# --- PDF: citations where they stand ----------------------------------------------------------


def test_runs_of_citations_become_reference_lists_in_place():
    ext = _load(ROOT / "book" / "_ext" / "pdf_layout.py", "pdf_layout")
    from sphinx.builders.latex.nodes import thebibliography

    doc = nodes.document(None, None)
    section = nodes.section()
    section += nodes.paragraph(text="before")
    for label in ("1", "2"):
        citation = nodes.citation(ids=[f"c{label}"], docname="reference/x")
        citation += nodes.label(text=label)
        citation += nodes.paragraph(text=f"reference {label}")
        section += citation
    section += nodes.paragraph(text="after")
    doc += section
    transform = ext.CitationsInPlace.__new__(ext.CitationsInPlace)
    transform.document = doc
    transform.run()
    kinds = [type(child).__name__ for child in section.children]
    assert kinds == ["paragraph", "thebibliography", "paragraph"]
    listing = section[1]
    assert isinstance(listing, thebibliography)
    assert [c["ids"] for c in listing.children] == [["c1"], ["c2"]]
    assert not list(doc.findall(nodes.citation))  # nothing left for Sphinx to move to the end


def test_a_reference_to_a_class_field_links_to_the_class():
    from types import SimpleNamespace

    ext = _load(ROOT / "book" / "_ext" / "api_reference.py", "api_reference")
    entry = SimpleNamespace(
        objtype="class", docname="reference/estimation", node_id="navcore.estimation.kalman.KalmanUpdate"
    )
    env = SimpleNamespace(get_domain=lambda name: SimpleNamespace(objects={entry.node_id: entry}))
    made = []
    ext.make_refnode = lambda builder, fromdoc, todoc, target, child, title: (
        made.append((todoc, target)) or child
    )
    node = {
        "refdomain": "py",
        "reftype": "attr",
        "reftarget": "innovation",
        "refdoc": "x",
        "py:module": "navcore.estimation.kalman",
        "py:class": "KalmanUpdate",
    }
    app = SimpleNamespace(builder=None)
    assert ext._field_reference(app, env, node, nodes.literal()) is not None
    assert made == [("reference/estimation", "navcore.estimation.kalman.KalmanUpdate")]
    node["reftarget"] = "not_a_field"
    assert ext._field_reference(app, env, node, nodes.literal()) is None
