"""The book's build tools: paper equation numbers, the internal link check, link prefixes."""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _load(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


paper_equations = _load(ROOT / "book" / "_ext" / "paper_equations.py", "book._ext.paper_equations")
check_links = _load(ROOT / "tools" / "check_links.py", "tools.check_links")


@pytest.mark.parametrize(
    ("label", "number"),
    [
        ("eq-wf-13", "13"),
        ("eq-atc10-2.4.2", "2.4.2"),
        ("eq-atc10-a.18", "A.18"),
        ("eq-sp-2.1", "2.1"),
        ("eq-kzl-7", "7"),
        ("eq-sp-x-residual", None),  # derived by the book: N-numbered
        ("eq-wf-x-2", None),
        ("eq-foo-13", None),  # not one of the four papers
        ("eq-atc10-tab4.3", None),
    ],
)
def test_paper_number_from_label(label, number):
    """Oracle: the label convention written out by hand."""
    assert paper_equations.paper_number(label) == number


def _page(path: Path, body: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"<html><body>{body}</body></html>")


def test_link_check_finds_missing_files_and_anchors(tmp_path):
    """Oracle: a hand-made HTML tree with one good link, one missing file, one missing anchor."""
    _page(tmp_path / "index.html", '<a href="wf/a.html#x">ok</a><a href="https://example.org">ext</a>')
    body = '<p id="x">x</p><a href="b.html">missing</a><a href="../index.html#nope">bad</a>'
    _page(tmp_path / "wf" / "a.html", body)
    broken = check_links.broken_links(tmp_path)
    assert len(broken) == 2
    assert any("b.html (no such file)" in b for b in broken)
    assert any("#nope (no such anchor)" in b for b in broken)


def test_link_check_passes_a_good_tree(tmp_path):
    _page(tmp_path / "index.html", '<a href="#top">top</a><span id="top"></span><a href="sub/">dir</a>')
    _page(tmp_path / "sub" / "index.html", '<a href="../index.html">up</a>')
    assert check_links.broken_links(tmp_path) == []


def test_book_root_prefix_follows_the_page_folder(tmp_path, monkeypatch):
    """Pages execute in their own folder: '' at the book's root, '../' in a chapter folder."""
    from navcore import book

    (tmp_path / "_toc.yml").write_text("root: intro\n")
    (tmp_path / "wf").mkdir()
    monkeypatch.chdir(tmp_path)
    assert book.book_root_prefix() == ""
    monkeypatch.chdir(tmp_path / "wf")
    assert book.book_root_prefix() == "../"


def test_errata_and_ledger_links_use_the_root_prefix(monkeypatch):
    from navcore import book, ledger

    # a chapter page runs in its own folder, so that "../" is the book (whose pages give the
    # errata list its page titles), never the folder above the checkout
    monkeypatch.chdir(ROOT / "book" / "wf")
    errata = book.errata_list("WF", root="../")
    assert 'href="../wf/' in errata._repr_html_()
    first = ledger.claims("WF")[0]
    table = book.claims_table(ids=[first.id], root="", link_pages=True)
    assert f'href="{first.discussed_in}.html#{first.id.lower()}"' in table._repr_html_()


def test_pandas_table_has_a_markdown_twin_for_the_pdf():
    """Oracle: the pipe table written out by hand (formatting and hidden index honoured)."""
    import numpy as np
    import pandas as pd

    from navcore import book

    df = pd.DataFrame({"a": [1.23456, np.nan], "b_c": ["u", "v"]})
    styled = df.style.format(precision=2, na_rep="").hide(axis="index")
    assert book.table(styled).cells() == (["a", "b_c"], [["1.23", "u"], ["", "v"]])
    latex = book.table(styled)._repr_markdown_()
    # a printed table: numbers right-aligned and unbreakable, LaTeX specials escaped
    assert latex.startswith("```{raw} latex") and "\\begin{longtable}{rl}" in latex
    assert "\\mbox{1.23} & u \\\\" in latex and "\\textbf{b\\_c}" in latex
    assert "<table" in book.table(df)._repr_html_()


book_presentation = _load(ROOT / "book" / "_ext" / "book_presentation.py", "book._ext.book_presentation")
check_book = _load(ROOT / "tools" / "check_book.py", "tools.check_book")


def test_pages_gate_finds_helpers_in_shown_cells(tmp_path):
    """Oracle: hand-written pages; a helper in a cell whose source a reader sees is found, one in
    a removed cell or input is not (a folded ``hide-input`` cell is still shown)."""
    page = (
        "# P\n\n"
        "```{code-cell} ipython3\nx = 1\nglue('a', x, display=False)\n```\n\n"  # shown: found
        "```{code-cell} ipython3\n:tags: [remove-cell]\nglue('b', 1, display=False)\n```\n\n"
        "```{code-cell} ipython3\n:tags: [remove-input]\nbook.show_figure('F')\n```\n\n"
        "```{code-cell} ipython3\n:tags: [hide-input]\nimport numpy\n%matplotlib inline\n```\n\n"
        "```{code-cell} ipython3\n:tags: [remove-output]\nfig = book.show_figure('G')\n```\n\n"
        "```{code-cell} ipython3\nfrom navcore.book import glue\n```\n\n"
        "```{code-cell} ipython3\nbook.table(x)  # glue( in a comment, not at a line's start\n```\n\n"
        "A paragraph: glue('c', 2) in prose is not code.\n"
    )
    (tmp_path / "wf").mkdir()
    (tmp_path / "wf" / "a.md").write_text(page)
    (tmp_path / "_build").mkdir()
    (tmp_path / "_build" / "b.md").write_text(page)  # a build's copy is not a page
    problems = check_book.check_pages(tmp_path)
    assert [p.split(": ")[0] for p in problems] == ["wf/a.md:5", "wf/a.md:21", "wf/a.md:26", "wf/a.md:30"]
    assert "'glue('" in problems[0] and "'%matplotlib'" in problems[1]
    assert "'fig = book.show_figure('" in problems[2] and "'from navcore.book import glue'" in problems[3]
    assert check_book.main(["pages", str(tmp_path)]) == 1


def test_pages_gate_passes_the_book():
    """The book's own pages keep every helper in a hidden cell."""
    assert check_book.check_pages(ROOT / "book") == []


@pytest.mark.parametrize(
    ("name", "number"),
    [
        ("fig-atc10-2-1", "2.1"),
        ("fig-kzl-fig4", "4"),
        ("fig-wf-1", "1"),
        ("fig-atc10-3-3-to-3-6", "3.3\u20133.6"),  # one grid redrawing a run of figures
        ("fig-sp-architectures", None),  # the book's own: N-numbered
        ("fig-atc10-ma-tails", None),
    ],
)
def test_paper_figure_number_from_name(name, number):
    assert book_presentation.paper_figure_number(name) == number


def test_html_gate_finds_helpers_and_notebooks_without_outputs(tmp_path):
    cell = (
        '<div class="cell_input docutils container"><div class="highlight-ipython3 notranslate">'
        '<div class="highlight"><pre><span class="n">glue</span><span class="p">(</span>"k", 1)</pre>'
    )
    _page(tmp_path / "wf" / "a.html", cell)
    nb = {
        "cells": [{"cell_type": "code", "execution_count": None, "outputs": [], "source": "1"}],
        "metadata": {"navcore_provenance": {"commit": "0" * 40, "lock_sha256": "f" * 64}},
    }
    (tmp_path / "_sources" / "wf").mkdir(parents=True)
    (tmp_path / "_sources" / "wf" / "a.ipynb").write_text(__import__("json").dumps(nb))
    problems = check_book.check_html(tmp_path)
    assert len(problems) == 2
    assert "shows 'glue('" in problems[0] and "not executed" in problems[1]


def test_html_gate_finds_developer_wording_in_text_data_and_notebook_outputs(tmp_path):
    clean = "<p>The claim is consistent: the reading of c agrees.</p>"
    _page(tmp_path / "wf" / "ok.html", clean)
    _page(tmp_path / "wf" / "a.html", "<p>Verdict changed from reproduced: a cross-check.</p>")
    _page(tmp_path / "ledger.html", '<script>var data = [{"expected_status": "consistent"}];</script>')
    _page(tmp_path / "reference" / "api.html", "<p>Oracle: scipy, in a docstring of the API.</p>")
    nb = {
        "cells": [
            {
                "cell_type": "code",
                "execution_count": 1,
                "source": "x",
                "outputs": [{"output_type": "stream", "name": "stdout", "text": "caught by the oracle"}],
            }
        ]
    }
    (tmp_path / "_sources" / "wf").mkdir(parents=True)
    (tmp_path / "_sources" / "wf" / "a.ipynb").write_text(__import__("json").dumps(nb))
    problems = check_book.check_wording(tmp_path)
    assert [p.split(":")[0] for p in problems] == ["ledger.html", "wf/a.html", "_sources/wf/a.ipynb"]
    assert "'Verdict changed'" in problems[1] and "'expected_status'" in problems[0]


def test_html_gate_finds_numbers_as_a_program_prints_them(tmp_path):
    """Oracle: hand-written pages, one number of each kind the gate must find, and their forms
    as the book prints them, which it must pass."""
    article = '<article class="bd-article">{}</article>'
    _page(tmp_path / "wf" / "ok.html", article.format("<p>1.00×10⁻⁴ m, 1.63 s, 0 and 60 deg</p>"))
    _page(tmp_path / "wf" / "exp.html", article.format("<p>a step of 1.00e-04 m</p>"))
    long_decimal = "<table><tr><td>1.6344416666666666</td></tr></table>"
    _page(tmp_path / "wf" / "long.html", article.format(long_decimal))
    _page(tmp_path / "wf" / "zero.html", article.format("<p>an error of -0.000 m</p>"))
    _page(tmp_path / "wf" / "code.html", article.format('<div class="cell_input"><pre>x = 1e-4</pre></div>'))
    _page(tmp_path / "reference" / "api.html", article.format("<p>tol=1e-12</p>"))
    problems = check_book.check_number_format(tmp_path)
    assert [p.split(":")[0] for p in problems] == ["wf/exp.html", "wf/long.html", "wf/zero.html"]
    assert "'1.00e-04'" in problems[0] and "(exponent)" in problems[0]
    assert check_book.main(["numbers", str(tmp_path)]) == 1


def test_html_gate_finds_formulas_shown_as_latex_source(tmp_path):
    """Oracle: hand-written pages and ledger records, each with one formula shown as LaTeX source
    that the gate must find, beside the forms a reader sees typeset, which it must pass."""
    import json

    article = '<article class="bd-article">{}</article>'
    typeset = (
        r"<p>The error $\mathbf{e}$ and <span class='math'>\(\bar{N}_{FL}\)</span>; "
        r"a table heading $\sigma_0$ (ns); a price of 50 $ more.</p>"
        r'<div class="cell_input"><pre>x = r"\frac{a}{b}"</pre></div>'
    )
    _page(tmp_path / "wf" / "ok.html", article.format(typeset))
    _page(tmp_path / "wf" / "bare.html", article.format(r"<p>the measurement error \mathbf{e} .</p>"))
    _page(tmp_path / "atc10" / "sub.html", article.format("<table><tr><td>a fixed P_{DL}</td></tr></table>"))
    code = '<td><code class="ledger-latex">x</code></td>'
    _page(tmp_path / "kzl" / "code.html", article.format(f"<table><tr>{code}</tr></table>"))
    records = [
        {"id": "WF-a", "printed": r"the error $\mathbf{e}$", "quantity": "q", "note": ""},
        {"id": "WF-b", "printed": r"\gamma_n = 1", "quantity": "q", "note": ""},
    ]
    data = json.dumps(records).replace("</", "<\\/")
    _page(tmp_path / "ledger.html", f'<script type="application/json" class="ledger-data">{data}</script>')
    _page(tmp_path / "reference" / "api.html", article.format(r"<p>\frac{a}{b} in a docstring</p>"))
    problems = check_book.check_plain_math(tmp_path)
    assert [p.split(":")[0] for p in problems] == [
        "atc10/sub.html",
        "kzl/code.html",
        "ledger.html",
        "wf/bare.html",
    ]
    assert "'_{'" in problems[0] and "ledger-latex" in problems[1]
    assert "WF-b (printed)" in problems[2] and "'\\\\mathbf'" in problems[3]
    assert check_book.latex_outside_math(r"$$x_{n-1}$$ and \(y_{2}\), 50 $ and 60 $") == []


def test_html_gate_finds_formulas_shown_as_program_text(tmp_path, monkeypatch):
    """Oracle: hand-written pages, each with formulas written as program text that the gate must
    find (a unit's power, a flat subscript, a spelled-out Greek letter, literal emphasis marks,
    in prose, a table cell of a cell's HTML output and a claim row), beside the forms a reader
    sees typeset, code and a cell's printed output, which it must pass; and an allowlist entry
    that passes its page and fails once its text is gone."""
    article = '<article class="bd-article">{}</article>'
    shown = (
        "<p>GM in m³/s², $\\beta$ and <span class='math'>\\(N\\tau_c/\\alpha\\)</span>, 5 parts in "
        "<span class='math'>\\(10^{8}\\)</span>, the detector <strong>deteriorates</strong>.</p>"
        '<p>The call <code class="docutils literal">exp(mu**2*p/2)</code> in a sentence.</p>'
        '<div class="cell docutils container"><div class="cell_input docutils container">'
        '<div class="highlight-ipython3"><div class="highlight"><pre>x = tau_c ** 2</pre></div></div></div>'
        '<div class="cell_output docutils container">'
        '<div class="output text_plain highlight-myst-ansi"><div class="highlight"><pre>exp(mu**2*p/2)'
        "</pre></div></div>"
        '<div class="output text_html"><table><tr><td>$\\operatorname{tr}\\{(F\'F)^{-1}\\}$</td></tr>'
        "</table></div></div></div>"
    )
    _page(tmp_path / "atc10" / "ok.html", article.format(shown))
    table = (
        '<div class="cell_output docutils container"><div class="output text_html">'
        "<table><tr><td>tr{(F'F)^-1}, all satellites</td><td>3.986×10¹⁴ m^3/s^2</td></tr></table></div></div>"
    )
    _page(tmp_path / "atc10" / "table.html", article.format(table))
    claims = '<table class="ledger-claims"><tr><td class="ledger-value">0.5 N tau_c / alpha</td></tr></table>'
    # identifiers and the words of prose that name a quantity are not formulas
    words = (
        "<table><tr><td>ATC10-tab4.3-exII-s5-alpha, SP-fig2.1-(peak, omega0), ATC10-E4.3-beta-definition</td>"
        "<td>code and delta range, delta pseudoranges, a chi-square quantile, 1 sigma, a psi-angle form</td>"
        "</tr></table>"
    )
    _page(tmp_path / "sp" / "words.html", article.format(words))
    _page(tmp_path / "traceability.html", article.format("<p>test_emitter, test_strapdown</p>"))
    _page(tmp_path / "atc10" / "claims.html", article.format(claims))
    _page(tmp_path / "atc10" / "quote.html", article.format("<p>the detector **deteriorates**</p>"))
    _page(tmp_path / "reference" / "api.html", article.format("<p>a docstring's sigma_0 and m^2</p>"))
    monkeypatch.setattr(check_book, "PLAIN_TEXT_ALLOWED", {})  # the book's own entries aside
    problems = check_book.check_plain_text_math(tmp_path)
    found = sorted(re.match(r"(\S+): plain-text math \((.+?)\) (.+?): \.\.\.", p).groups() for p in problems)
    assert found == [
        ("atc10/claims.html", "Greek name", "'alpha'"),
        ("atc10/claims.html", "Greek name", "'tau_c'"),
        ("atc10/claims.html", "flat subscript", "'tau_c'"),
        ("atc10/quote.html", "power", "'**'"),
        ("atc10/quote.html", "power", "'**'"),
        ("atc10/table.html", "power", "'F)^-'"),
        ("atc10/table.html", "power", "'m^3'"),
        ("atc10/table.html", "power", "'s^2'"),
    ], problems
    assert check_book.main(["html", str(tmp_path)]) == 1
    # an allowed hit passes on its page; an entry whose text is gone fails
    allowed = {("atc10/quo*.html", "**deteriorates**"): "the paper's own asterisks (a synthetic reason)"}
    monkeypatch.setattr(check_book, "PLAIN_TEXT_ALLOWED", allowed)
    assert not [p for p in check_book.check_plain_text_math(tmp_path) if p.startswith("atc10/quote.html")]
    (tmp_path / "atc10" / "quote.html").unlink()
    _page(tmp_path / "atc10" / "quote.html", article.format("<p>the detector <em>deteriorates</em></p>"))
    assert [p for p in check_book.check_plain_text_math(tmp_path) if p.startswith("atc10/quo")] == [
        "atc10/quo*.html: allowed plain-text math '**deteriorates**' no longer occurs: remove it from "
        "PLAIN_TEXT_ALLOWED"
    ]


PROSE_PAGE = """
<nav><p>sidebar: navcore.location.fdoa is navigation, not prose</p></nav>
<article class="bd-article"><section>
<h1>Title with level_arm</h1>
<p>The model is <code class="docutils literal">navcore.inertial.alignment</code>, see
<a href="x.html">federated_fuse</a>; math <span class="math">\\(C/N_0\\) and \\(x_k\\)</span>.</p>
<p>Here navcore.gnss.tracking stands bare, and so does levelling_alignment.</p>
<ul><li><p>Call fuse() to fuse.</p></li></ul>
<div class="admonition note"><p class="admonition-title">Note</p><p>The C/N0 of 41 dB-Hz is fine.</p></div>
<dl><dt>term_name</dt><dd>defined with <kbd>ctrl_c</kbd> and the set_point value.</dd></dl>
<table><thead><tr><th>col_name</th></tr></thead><tbody><tr><td>row_value</td></tr></tbody></table>
<div class="cell_output docutils container"><p>printed_name from a cell</p></div>
<table class="ledger-table"><tr><td>claim_note</td></tr></table>
<figure><img src="a.png"/><figcaption><p>Figure of sigma_a.</p></figcaption></figure>
<pre>code_in_pre()</pre>
</section></article>
"""


def test_prose_gate_finds_identifiers_only_in_running_prose():
    """Oracle: a hand-made page; the identifiers in prose are the ones outside code blocks,
    links, math, headings, header cells, cell outputs and claim tables. A name set in inline
    code type inside a sentence still stands in the prose (issue 20's `levelling_alignment`)."""
    found = [ident for ident, _ in check_book.prose_identifiers(PROSE_PAGE)]
    bare = [
        "navcore.inertial.alignment",
        "navcore.gnss.tracking",
        "levelling_alignment",
        "fuse()",
        "set_point",
        "row_value",
        "sigma_a",
    ]
    assert found == bare


@pytest.mark.parametrize(
    ("text", "identifiers"),
    [
        ("the loosely coupled filter (Section 2)", []),
        ("the C/N_0 ratio and N_0 itself", []),  # math typed as text: no letter after the underscore
        ("navcore.ledger", ["navcore.ledger"]),
        ("call book.setup() first", ["book.setup()"]),
        ("f(x) is a function, g(...) too", ["g(...)"]),
        ("a snake_case name, and x_k", ["snake_case", "x_k"]),
        ("a well-known, built-in word", []),
    ],
)
def test_prose_gate_identifier_patterns(text, identifiers):
    found = [ident for ident, _ in check_book.prose_identifiers(f"<p>{text}</p>")]
    assert found == identifiers


def test_prose_gate_skips_the_reference_and_generated_pages(tmp_path):
    """The API pages are skipped; the how-to guides of the Reference part are prose."""
    body = "<p>bare navcore.units here</p>"
    pages = (
        "reference/units.html",
        "genindex.html",
        "_modules/x.html",
        "search.html",
        "wf/a.html",
        "reference/howto/dop.html",
    )
    for rel in pages:
        _page(tmp_path / rel, body)
    problems = check_book.check_prose(tmp_path)
    assert problems == [
        f"{rel}: identifier 'navcore.units' in prose: ...bare navcore.units here..."
        for rel in ("reference/howto/dop.html", "wf/a.html")
    ]
    assert check_book.check_html(tmp_path) == problems


def test_reference_subset_has_every_page_of_the_reference_part():
    """``build_book.py --only reference`` builds the pages the book's Reference part lists."""
    import yaml

    build_book = _load(ROOT / "tools" / "build_book.py", "build_book")
    toc = yaml.safe_load((ROOT / "book" / "_toc.yml").read_text())
    part = next(p for p in toc["parts"] if p["caption"] == "Reference")

    def files(node):
        if isinstance(node, dict):
            found = [node["file"]] if "file" in node else []
            for key in ("chapters", "sections"):
                for child in node.get(key, []):
                    found += files(child)
            return found
        return []

    subset = yaml.safe_load(build_book.subset_toc("reference"))
    in_subset = [subset["root"], *files({"chapters": subset["parts"][0]["chapters"]})]
    assert sorted(in_subset) == sorted(files(part))


def test_latex_gate_counts_only_wide_overfull_boxes(tmp_path):
    (tmp_path / "book.log").write_text(
        "Overfull \\hbox (1.5pt too wide) in paragraph at lines 1--2\n"
        "Overfull \\hbox (842.0pt too wide) in alignment at lines 9--12\n"
    )
    problems = check_book.check_latex(tmp_path)
    assert len(problems) == 1 and "842.0 pt" in problems[0]


def test_same_gate_ignores_only_pdf_dates_and_the_rebuild_record(tmp_path):
    for run, date in (("a", b"20260101"), ("b", b"20270202")):
        (tmp_path / run).mkdir()
        (tmp_path / run / "book.pdf").write_bytes(b"%PDF /CreationDate (D:" + date + b") body")
        (tmp_path / run / "x.html").write_text("same")
        (tmp_path / run / ".buildinfo").write_text(f"config: {run}")  # Sphinx's, not the book's
    assert check_book.same_trees(tmp_path / "a", tmp_path / "b") == []
    (tmp_path / "b" / "x.html").write_text("other")
    assert check_book.same_trees(tmp_path / "a", tmp_path / "b") == ["differs: x.html"]


def test_interactive_ledger_filters_by_the_fields_present():
    from navcore import ledger
    from navcore.ledger.interactive import InteractiveLedger
    from navcore.ledger.text import STATUS_COLOURS

    assert "inconsistent" in STATUS_COLOURS
    evals = ledger.evaluations("WF")[:3]
    page = InteractiveLedger(evals, root="")._repr_html_()
    for control in ('data-filter="paper"', 'data-filter="status"', 'data-download="csv"', 'type="search"'):
        assert control in page
    assert f'id="{evals[0].claim.id.lower()}"' in page
    # kind and band columns appear exactly when the records carry them
    has_kind = any(e.as_json().get("kind") for e in evals)
    assert ('data-filter="kind"' in page) == has_kind
    assert "\\begin{longtable}" in InteractiveLedger(evals)._repr_markdown_()


def test_styler_html_is_the_same_every_time():
    import pandas as pd

    from navcore import book

    df = pd.DataFrame({"a": [1.0, 2.0]})
    assert book.table(df.style)._repr_html_() == book.table(df.style)._repr_html_()


def test_numbering_papers_numbers_and_the_books_own_per_chapter():
    """Oracle: the numbers written out by hand for a two-chapter toy environment."""
    from types import SimpleNamespace

    env = SimpleNamespace(
        toc_fignumbers={
            "wf/01": {"figure": {"fig-wf-1": (3,), "fig-wf-example": (4,)}, "exercise": {"ex-a": (1,)}},
            "wf/02": {"figure": {"fig-wf-sensitivity": (5,)}, "theorem": {"thm": (1,), "own": (2,)}},
            "kzl/01": {
                "figure": {"fig-kzl-fig4": (6,), "fig-kzl-standalone": (7,)},
                "exercise": {"ex-b": (2,)},
            },
        },
        paper_theorem_numbers={"wf/02": {"thm": "3.1"}},
    )
    book_presentation._renumber(None, env)
    n = env.toc_fignumbers
    assert n["wf/01"]["figure"] == {"fig-wf-1": ("1",), "fig-wf-example": ("N1",)}
    assert n["wf/02"]["figure"] == {"fig-wf-sensitivity": ("N2",)}
    assert n["wf/02"]["theorem"] == {"thm": ("3.1",), "own": ("N1",)}  # its own counter
    assert n["kzl/01"]["figure"] == {"fig-kzl-fig4": ("4",), "fig-kzl-standalone": ("N1",)}
    assert n["wf/01"]["exercise"] == {"ex-a": ("1",)} and n["kzl/01"]["exercise"] == {"ex-b": ("1",)}


def test_printed_chunks_are_merged_exactly():
    """Oracle: the text as printed, whatever the chunking of the kernel's stream messages."""
    import nbformat

    build_book = _load(ROOT / "tools" / "build_book.py", "tools.build_book")
    chunks = ["Example beta:", " [0.07 0.06]\n", " K  gain\n", "\n", "   1   18\n"]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("print()")])
    nb.cells[0].outputs = [nbformat.v4.new_output("stream", name="stdout", text=c) for c in chunks]
    nb.cells[0].outputs.insert(2, nbformat.v4.new_output("stream", name="stderr", text="warn\n"))
    build_book._merge_streams(nb)
    outs = nb.cells[0].outputs
    assert [o["name"] for o in outs] == ["stdout", "stderr"]
    assert outs[0]["text"] == "".join(chunks)


@pytest.mark.parametrize(("builder", "kept_inputs"), [("latex", 1), ("html", 2)])
def test_print_drops_the_source_of_cells_the_web_folds_away(builder, kept_inputs):
    """Oracle: a hand-built doctree with one hide-input cell and one plain cell; in print only
    the plain cell keeps its source, and both keep their outputs; HTML is untouched."""
    from types import SimpleNamespace

    from docutils import nodes
    from docutils.frontend import get_default_settings
    from docutils.parsers.rst import Parser
    from docutils.utils import new_document

    doc = new_document("page", get_default_settings(Parser))
    for tags in (["tag_hide-input"], []):
        cell = nodes.container(classes=["cell", *tags])
        cell += nodes.container("", nodes.literal_block("", "bookkeeping()"), classes=["cell_input"])
        cell += nodes.container("", nodes.paragraph("", "result"), classes=["cell_output"])
        doc += cell
    app = SimpleNamespace(builder=SimpleNamespace(format=builder))
    book_presentation._print_hidden_inputs(app, doc, "page")
    inputs = [c for c in doc.findall(nodes.container) if "cell_input" in c["classes"]]
    outputs = [c for c in doc.findall(nodes.container) if "cell_output" in c["classes"]]
    assert len(inputs) == kept_inputs and len(outputs) == 2


@pytest.mark.parametrize("builder", ["latex", "html"])
def test_print_titles_proof_boxes(builder):
    """Oracle: a hand-built doctree in the form sphinx-proof's proof directive returns (an
    untitled admonition of classes proof/proof whose text starts "Proof. "); in print the box
    gets the title "Proof" and the text loses the prefix; HTML keeps sphinx-proof's form."""
    from types import SimpleNamespace

    from docutils import nodes
    from docutils.frontend import get_default_settings
    from docutils.parsers.rst import Parser
    from docutils.utils import new_document

    doc = new_document("page", get_default_settings(Parser))
    box = nodes.admonition(classes=["proof", "proof"])
    box += nodes.paragraph("", "Proof. For any vector y, the inequality holds.")
    doc += box
    app = SimpleNamespace(builder=SimpleNamespace(format=builder))
    book_presentation._print_proof_titles(app, doc, "page")
    titles = [t.astext() for t in doc.findall(nodes.title)]
    text = next(iter(doc.findall(nodes.paragraph))).astext()
    if builder == "latex":
        assert titles == ["Proof"] and text == "For any vector y, the inequality holds."
    else:
        assert titles == [] and text.startswith("Proof. ")


def test_api_links_with_words_read_in_text_font():
    """Oracle: a hand-built doctree of two API cross-references as Sphinx resolves them (a
    reference holding a literal of class xref): the phrase loses the code font, the bare name
    keeps it, and both stay links."""
    from docutils import nodes
    from docutils.frontend import get_default_settings
    from docutils.parsers.rst import Parser
    from docutils.utils import new_document

    doc = new_document("page", get_default_settings(Parser))
    para = nodes.paragraph()
    for text in ("the federated fusion", "federated_fuse"):
        literal = nodes.literal("", text, classes=["xref", "py", "py-func"])
        para += nodes.reference("", "", literal, refuri="#x")
    doc += para
    book_presentation._words_links_in_text_font(None, doc, "page")
    refs = list(doc.findall(nodes.reference))
    assert [type(r.children[0]).__name__ for r in refs] == ["inline", "literal"]
    assert [r.astext() for r in refs] == ["the federated fusion", "federated_fuse"]


build_tool = _load(ROOT / "tools" / "build_book.py", "tools.build_book")


def test_the_build_log_keeps_warnings_and_drops_jupyter_books_banners(capsys):
    """Oracle: jupyter-book's banners as it prints them, and a warning the strict build fails on."""
    import io

    printed = (
        "\x1b[92m===============================================================================\x1b[0m\n"
        "\n"
        "Running Jupyter-Book v1.0.4.post1\n"
        "Source Folder: /repo/book\n"
        "Config Path: /repo/_build/jupyter_cache/_config_cached.yml\n"
        "Output Path: /repo/_build/html\n"
        "/repo/book/wf/01-location-error.md:12: WARNING: undefined label: 'sec-missing'\n"
        "Finished generating HTML for book.\n"
        "Your book's HTML pages are here:\n"
        "    _build/html/\n"
        "You can look at your book by opening this file in a browser:\n"
        "    _build/html/index.html\n"
        "Or paste this line directly into your browser bar:\n"
        "    file:///repo/_build/html/index.html            \n"
        "Building your book, returns a non-zero exit code (1). Look above for the cause.\n"
    )
    build_tool._relay_quietly(io.StringIO(printed))
    assert capsys.readouterr().out == (
        "/repo/book/wf/01-location-error.md:12: WARNING: undefined label: 'sec-missing'\n"
    )


def test_pages_that_read_every_papers_claims_run_after_the_paper_chapters(tmp_path):
    """Oracle: the grouping written out by hand (paper chapters heaviest ledger first, then the rest)."""
    pages = [tmp_path / p for p in ("intro.md", "wf/01-a.md", "across/01-b.md", "kzl/01-c.md", "wf/02-d.md")]
    papers, later = build_tool._group_pages(pages, tmp_path)
    assert papers == [
        ("KZL", [str(tmp_path / "kzl/01-c.md")]),
        ("WF", [str(tmp_path / "wf/01-a.md"), str(tmp_path / "wf/02-d.md")]),
    ]
    assert later == [("ACROSS", [str(tmp_path / "across/01-b.md")]), ("", [str(tmp_path / "intro.md")])]


def test_registry_texts_carry_no_developer_wording():
    """What the exports and claim rows show (quantities, notes, quotes, errata, input reasons)
    carries no change history, regression pin or test bookkeeping: that lives in git and tests."""
    from navcore import ledger
    from navcore.claims.inputs import all_inputs

    texts = []
    for c in ledger.claims():
        texts += [(c.id, t) for t in (c.quantity, c.note, c.printed or "", c.locator)]
    for e in ledger.errata():
        texts += [(e.id, t) for t in (e.printed, e.finding, e.evidence, e.no_claim_reason or "")]
    inputs = all_inputs()
    assert len(inputs) > 100  # every paper module's declarations, loaded by ledger.claims()
    texts += [(i.name, t) for i in inputs for t in (i.reason or "", i.quantity or "")]
    found = [f"{who}: {m.group(0)!r}" for who, t in texts if (m := check_book.DEVELOPER_WORDING.search(t))]
    assert not found, found


def test_no_control_characters_in_sources():
    """A control character in a docstring or page (a ``\\b`` of ``\\big`` read by Python as a
    backspace in a non-raw string) passes the HTML build and stops the PDF's LaTeX run."""
    import re

    bad = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]")
    found = []
    for folder, pattern in (("navcore", "*.py"), ("book", "*.md"), ("book", "*.rst"), ("tools", "*.py")):
        for path in sorted((ROOT / folder).rglob(pattern)):
            text = path.read_text(encoding="utf-8", errors="replace")
            for m in bad.finditer(text):
                line = text.count("\n", 0, m.start()) + 1
                found.append(f"{path.relative_to(ROOT)}:{line}: {m.group(0)!r}")
    assert not found, found
