"""The book's Sphinx extensions, function by function, without a book build (issue 31, item 1).

The full book build reaches every extension, but only as a whole and only for form; these tests
give each function the inputs that tell its branches apart, with Sphinx's objects replaced by
small stand-ins (a namespace with the attributes the function reads).

Oracles: the hand-made input and the result written out by hand; Sphinx's own table of events
for the event names an extension connects to; LaTeX's special characters for the escapes.
"""

from __future__ import annotations

import importlib.util
import itertools
import json
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from types import SimpleNamespace
from typing import ClassVar, NamedTuple

import pytest
from docutils import nodes
from sphinx import addnodes

ROOT = Path(__file__).resolve().parents[1]
EXT = ROOT / "book" / "_ext"


def _load(name: str):
    dotted = f"book._ext.{name}"
    if dotted in sys.modules:
        return sys.modules[dotted]
    spec = importlib.util.spec_from_file_location(dotted, EXT / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[dotted] = module
    spec.loader.exec_module(module)
    return module


api_reference = _load("api_reference")
book_presentation = _load("book_presentation")
glossary_links = _load("glossary_links")
paper_equations = _load("paper_equations")
book_downloads = _load("book_downloads")
build_provenance = _load("build_provenance")
number_text = _load("number_text")
pdf_layout = _load("pdf_layout")
subset_references = _load("subset_references")


# --- setup: what each extension registers ---------------------------------------------------------


class _Recorder:
    """A stand-in Sphinx application that records every registration call."""

    def __init__(self) -> None:
        self.calls: list[tuple] = []

    def __getattr__(self, name: str):
        def record(*args, **kwargs):
            self.calls.append((name, *args, *sorted(kwargs.items())))

        return record


SAFE = {"parallel_read_safe": True, "parallel_write_safe": True}
SETUP = {
    "api_reference": (
        [
            # after numpydoc (priority 500), which writes the References section as citations
            ("connect", "autodoc-process-docstring", api_reference._process_docstring, ("priority", 600)),
            ("connect", "autodoc-skip-member", api_reference._skip_class_data),
            ("connect", "missing-reference", api_reference._field_reference),
        ],
        SAFE,
    ),
    "book_downloads": (
        [
            ("connect", "html-page-context", book_downloads._add_notebook, ("priority", 400)),
            ("connect", "html-page-context", book_downloads._add_notebook, ("priority", 900)),
            ("connect", "html-page-context", book_downloads._add_pdf_button, ("priority", 600)),
            ("connect", "build-finished", book_downloads._copy_pdf),
        ],
        {"version": "1.0", **SAFE},
    ),
    "build_provenance": (
        [
            ("add_directive", "build-provenance", build_provenance.BuildProvenanceDirective),
            ("connect", "builder-inited", build_provenance._title_page),
            ("connect", "html-page-context", build_provenance._ledger_page),
        ],
        {"version": "1.0", **SAFE},
    ),
    "number_text": ([("add_post_transform", number_text.TidyPastedNumbers)], SAFE),
    "book_presentation": (
        [
            ("set_html_assets_policy", "always"),
            ("add_directive", "erratum", book_presentation.ErratumDirective),
            ("connect", "doctree-read", book_presentation._erratum_anchors),
            ("connect", "doctree-read", book_presentation._captions),
            ("connect", "doctree-read", book_presentation._collect_titles),
            ("connect", "env-purge-doc", book_presentation._purge),
            ("connect", "env-merge-info", book_presentation._merge),
            ("connect", "env-get-updated", book_presentation._renumber, ("priority", 900)),
            ("connect", "doctree-resolved", book_presentation._latex_figure_numbers),
            ("connect", "doctree-resolved", book_presentation._print_hidden_inputs),
            ("connect", "doctree-resolved", book_presentation._print_proof_titles),
            ("connect", "doctree-resolved", book_presentation._words_links_in_text_font),
        ],
        {"version": "1.0", **SAFE},
    ),
    "paper_equations": (
        [
            ("connect", "doctree-read", paper_equations._collect),
            ("connect", "env-purge-doc", paper_equations._purge),
            ("connect", "env-merge-info", paper_equations._merge),
            ("connect", "env-get-updated", paper_equations._renumber, ("priority", 900)),
        ],
        {"version": "1.0", **SAFE},
    ),
    "glossary_links": (
        [
            ("add_config_value", "glossary_links_docname", "glossary", "env"),
            ("add_config_value", "glossary_links_exclude", ["reference/"], "env"),
            ("add_config_value", "glossary_links_ignore", [], "env"),
            ("connect", "builder-inited", glossary_links._read_glossary),
            ("connect", "env-get-outdated", glossary_links._outdated),
            ("add_transform", glossary_links.GlossaryLinks),
        ],
        {"version": "1.0", **SAFE, "env_version": 1},
    ),
    "subset_references": (
        [
            ("connect", "missing-reference", subset_references.missing_reference),
            ("add_post_transform", subset_references.MystLinksOutside),
            ("connect", "build-finished", subset_references._report),
        ],
        {"parallel_read_safe": True, "parallel_write_safe": False},
    ),
}
#: events that extensions or builders (not Sphinx's core) define
OTHER_EVENTS = {"html-page-context", "autodoc-skip-member", "autodoc-process-docstring"}


@pytest.mark.parametrize("name", sorted(SETUP))
def test_setup_registers_its_handlers(name):
    from sphinx.events import core_events

    calls, metadata = SETUP[name]
    app = _Recorder()
    assert globals()[name].setup(app) == metadata  # the module these expectations name
    assert app.calls == calls
    if name == "subset_references":  # the counts the build's report reads
        assert app.__dict__["_subset_counts"] == Counter()
    for call in app.calls:
        if call[0] == "connect":
            assert call[1] in set(core_events) | OTHER_EVENTS


def test_paper_equations_setup_patches_the_latex_writer_once():
    """The LaTeX writer's display-math visitor is wrapped once, however often the extension loads."""
    from sphinx.writers.latex import LaTeXTranslator

    paper_equations.setup(_Recorder())
    patched = LaTeXTranslator.visit_math_block
    assert patched._paper_equations is True
    paper_equations.setup(_Recorder())
    assert LaTeXTranslator.visit_math_block is patched


def test_pdf_layout_setup_registers_nodes_and_transforms():
    app = _Recorder()
    assert pdf_layout.setup(app) == SAFE
    assert app.calls == [
        (
            "add_node",
            pdf_layout.in_place_citation,
            ("latex", (pdf_layout._visit_in_place_citation, pdf_layout._depart_in_place_citation)),
        ),
        (
            "add_node",
            nodes.admonition,
            ("latex", (pdf_layout._visit_admonition, pdf_layout._depart_admonition)),
            ("override", True),
        ),
        ("add_post_transform", pdf_layout.CitationUrlsInline),
        ("add_post_transform", pdf_layout.CitationsInPlace),
        ("add_post_transform", pdf_layout.IntroductionHeading),
    ]


# --- number_text ------------------------------------------------------------------------------------


def _pasted(text: str, classes: list[str]) -> nodes.inline:
    return nodes.inline("", "", nodes.Text(text), classes=classes)


def test_pasted_numbers_are_tidied_and_other_text_is_left_alone():
    from navcore.formatting import tidy_numbers

    doc = nodes.paragraph()
    doc += _pasted("9.5e-04 and -0.0", ["pasted-text"])
    doc += _pasted("9.5e-04", ["other"])
    doc += _pasted("12", ["pasted-text"])
    doc += _pasted("1.0e-05", ["pasted-text"])
    transform = SimpleNamespace(document=doc)
    number_text.TidyPastedNumbers.run(transform)
    texts = [n.astext() for n in doc.children]
    assert texts == [tidy_numbers("9.5e-04 and -0.0"), "9.5e-04", "12", tidy_numbers("1.0e-05")]
    assert texts[3] != "1.0e-05"
    assert texts[0] != "9.5e-04 and -0.0"  # the oracle does change it
    assert all(isinstance(c, nodes.Text) for n in doc.children for c in n.children)


# --- build_provenance -------------------------------------------------------------------------------


def test_latex_escape_of_every_special_character():
    for module in (build_provenance, pdf_layout):
        assert module._latex_escape("a&b%c$d#e_f{g}h\\i") == r"a\&b\%c\$d\#e\_f\{g\}h\i"


def test_provenance_table_literals_and_words():
    table = build_provenance.provenance_table([("commit", "abc123"), ("tree", "clean and tidy")])
    assert table["classes"] == ["navcore-provenance"]
    (group,) = table.children
    assert group["cols"] == 2
    assert [c["colwidth"] for c in group.findall(nodes.colspec)] == [30, 70]
    rows = list(group.findall(nodes.row))
    assert [[e.astext() for e in r.children] for r in rows] == [
        ["Built with", "Value"],
        ["commit", "abc123"],
        ["tree", "clean and tidy"],
    ]
    assert isinstance(rows[0].parent, nodes.thead) and isinstance(rows[1].parent, nodes.tbody)
    assert len(list(rows[1].findall(nodes.literal))) == 1  # a hash: a literal
    assert not list(rows[2].findall(nodes.literal))  # words: text


class _Provenance(NamedTuple):
    date: str

    def rows(self):
        return [("commit_sha", "a&b"), ("lock", "f_0")]

    def as_dict(self):
        return {"b": "</script>", "a": 1}


def test_title_page_latex_block():
    text = build_provenance.title_page_latex(_Provenance("2026-01-01"))
    assert text == (
        "\\authoraddress{\\scriptsize\\begin{tabular}{@{}r@{\\enspace}l@{}}\n"
        "\\multicolumn{2}{r}{\\itshape Built from}\\\\\n"
        "commit\\_sha & \\texttt{a\\&b}\\\\\n"
        "lock & \\texttt{f\\_0}\\\\\n"
        "\\end{tabular}}\n"
    )


@pytest.mark.parametrize(
    ("builder", "date", "expected_date"),
    [("latex", "2026-01-01", "2026-01-01"), ("latex", "unknown", "commit date unknown"), ("html", "x", None)],
)
def test_title_page_date_and_preamble(monkeypatch, builder, date, expected_date):
    p = _Provenance(date)
    monkeypatch.setattr(build_provenance, "provenance", lambda: p)
    context = {"preamble": "PRE"}
    app = SimpleNamespace(builder=SimpleNamespace(name=builder, context=context))
    build_provenance._title_page(app)
    if expected_date is None:
        assert context == {"preamble": "PRE"}
    else:
        assert context == {"preamble": "PRE\n" + build_provenance.title_page_latex(p), "date": expected_date}
    context.clear()
    build_provenance._title_page(app)
    if expected_date is not None:
        assert context["preamble"] == "\n" + build_provenance.title_page_latex(p)


@pytest.mark.parametrize(
    ("fmt", "body", "added"),
    [("html", "<div data-ledger-app>", True), ("html", "<p>", False), ("latex", "data-ledger-app", False)],
)
def test_ledger_page_carries_the_provenance(monkeypatch, fmt, body, added):
    monkeypatch.setattr(build_provenance, "provenance", lambda: _Provenance("d"))
    app = SimpleNamespace(builder=SimpleNamespace(format=fmt))
    context = {"body": body, "metatags": "M"}
    build_provenance._ledger_page(app, "ledger", "page.html", context, None)
    script = '<script type="application/json" id="navcore-provenance">{"a": 1, "b": "<\\/script>"}</script>\n'
    assert context["metatags"] == ("M" + script if added else "M")
    if added:
        context = {"body": body}
        build_provenance._ledger_page(app, "ledger", "page.html", context, None)
        assert context["metatags"] == script
        json.loads(script.split(">", 1)[1].rsplit("</script>", 1)[0])  # valid JSON


def test_ledger_page_without_a_body(monkeypatch):
    monkeypatch.setattr(build_provenance, "provenance", lambda: _Provenance("d"))
    context: dict = {}
    build_provenance._ledger_page(
        SimpleNamespace(builder=SimpleNamespace(format="html")), "p", "t", context, None
    )
    assert context == {}


def test_provenance_directive_writes_the_table(monkeypatch):
    monkeypatch.setattr(build_provenance, "provenance", lambda: _Provenance("d"))
    (table,) = build_provenance.BuildProvenanceDirective.run(SimpleNamespace())
    assert table.astext() == build_provenance.provenance_table(_Provenance("d").rows()).astext()


# --- api_reference ----------------------------------------------------------------------------------


@dataclass(frozen=True)
class Sample:
    """A class with fields of each kind."""

    count: int
    label: str = "x"
    LIMIT: ClassVar[int] = 3

    @dataclass
    class Inner:
        depth: int

    def method(self) -> int:
        return self.count

    @property
    def twice(self) -> int:
        return 2 * self.count


class Pair(NamedTuple):
    left: float
    right: float


@pytest.mark.parametrize(
    ("what", "obj", "skip", "expected"),
    [
        ("class", 3, False, True),  # a data attribute: skipped
        ("module", 3, False, None),
        ("class", 3, True, None),  # already skipped: left to Sphinx
        ("class", Sample.method, False, None),
        ("class", Sample.twice, False, None),
        ("class", classmethod(len), False, None),
        ("class", staticmethod(len), False, None),
        ("class", Sample, False, None),
        ("class", __import__("enum").Enum("E", "a").a, False, None),
        ("class", len, False, None),
    ],
)
def test_skip_class_data(what, obj, skip, expected):
    assert api_reference._skip_class_data(None, what, "n", obj, skip, None) is expected


def test_class_fields_of_every_kind(tmp_path, monkeypatch):
    """Inherited dataclass fields, a named tuple without annotations, a plain annotated class;
    and a module reached only by its dotted name (not as an attribute of its package)."""
    (tmp_path / "fieldpkg").mkdir()
    (tmp_path / "fieldpkg" / "__init__.py").write_text("")
    (tmp_path / "fieldpkg" / "sub.py").write_text(
        "import collections\n"
        "from dataclasses import dataclass\n"
        "@dataclass\n"
        "class Base:\n    a: int\n"
        "@dataclass\n"
        "class Child(Base):\n    b: int\n"
        "Point = collections.namedtuple('Point', 'x y')\n"
        "class Plain:\n    z: int\n"
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    import fieldpkg
    import fieldpkg.sub

    monkeypatch.delattr(fieldpkg, "sub")
    assert api_reference._class_fields("fieldpkg.sub.Child") == {"a", "b"}
    assert api_reference._class_fields("fieldpkg.sub.Point") == {"x", "y"}
    assert api_reference._class_fields("fieldpkg.sub.Plain") == {"z"}


def test_class_fields():
    here = __name__
    assert api_reference._class_fields(f"{here}.Sample") == {"count", "label", "LIMIT"}
    assert api_reference._class_fields(f"{here}.Pair") == {"left", "right"}
    assert api_reference._class_fields(f"{here}.test_class_fields") == set()
    assert api_reference._class_fields(f"{here}.Nothing") == set()
    assert api_reference._class_fields("no_such_module_xyz.Thing") == set()
    # a nested class: the module part is found by walking back
    assert api_reference._class_fields(f"{here}.Sample.Inner") == {"depth"}
    assert api_reference._class_fields(f"{here}.Sample.Inner.depth") == set()


def _xref(**attrs) -> addnodes.pending_xref:
    node = addnodes.pending_xref("", refdomain="py", reftype="attr", refdoc="here", **attrs)
    return node


class _Entry(NamedTuple):
    docname: str
    node_id: str
    objtype: str


def _api_env(objects: dict) -> SimpleNamespace:
    return SimpleNamespace(get_domain=lambda name: SimpleNamespace(objects=objects) if name == "py" else None)


def test_field_reference_links_to_the_class(monkeypatch):
    made = []
    monkeypatch.setattr(api_reference, "make_refnode", lambda *a: made.append(a) or "ref")
    here = __name__
    objects = {
        f"{here}.Sample": _Entry("api", "id-sample", "class"),
        "Pair": _Entry("api", "id-pair", "exception"),
        f"{here}.Pair": _Entry("api", "id-pair2", "function"),
    }
    env = _api_env(objects)
    app = SimpleNamespace(builder="B")
    cont = nodes.literal(text="c")
    # Owner.attr with a module: the module-qualified candidate
    assert (
        api_reference._field_reference(app, env, _xref(reftarget="Sample.count", **{"py:module": here}), cont)
        == "ref"
    )
    assert made[-1] == ("B", "here", "api", "id-sample", cont, f"{here}.Sample")
    # a field the class does not have, a method, a bare name without a class: unresolved
    assert (
        api_reference._field_reference(app, env, _xref(reftarget="Sample.nope", **{"py:module": here}), cont)
        is None
    )
    assert api_reference._field_reference(app, env, _xref(reftarget="count"), cont) is None
    # inside a class: the bare name is the class's field
    node = _xref(reftarget="count", **{"py:module": here, "py:class": "Sample"})
    assert api_reference._field_reference(app, env, node, cont) == "ref"
    node = _xref(reftarget="count", **{"py:class": f"{here}.Sample"})
    assert api_reference._field_reference(app, env, node, cont) == "ref"
    # objtype must be a class or an exception
    node = _xref(reftarget="Pair.left", **{"py:module": here})
    assert api_reference._field_reference(app, env, node, cont) is None
    # another domain or role
    other = _xref(reftarget="Sample.count", **{"py:module": here})
    other["reftype"] = "func"
    assert api_reference._field_reference(app, env, other, cont) is None
    other["reftype"], other["refdomain"] = "attr", "std"
    assert api_reference._field_reference(app, env, other, cont) is None
    assert len(made) == 3


def test_field_reference_owner_without_a_module(monkeypatch):
    monkeypatch.setattr(api_reference, "make_refnode", lambda *a: a[-1])
    here = __name__
    env = _api_env({f"{here}.Pair": _Entry("api", "i", "exception")})
    node = _xref(reftarget=f"{here}.Pair.left")
    assert api_reference._field_reference(SimpleNamespace(builder=None), env, node, None) == f"{here}.Pair"


# --- pdf_layout -------------------------------------------------------------------------------------


def _citation(key: str, *children) -> nodes.citation:
    c = nodes.citation("raw-" + key, *children, ids=[key])
    return c


def test_citation_urls_are_printed_as_addresses():
    doc = nodes.section()
    doi = nodes.reference("", "10.1/x", refuri="https://doi.org/10.1/x")
    same = nodes.reference("", "http://a.b", refuri="http://a.b")
    plain_http = nodes.reference("", "a page", refuri="http://e.f/g")
    internal = nodes.reference("", "internal", refid="x")
    local = nodes.reference("", "see", refuri="#x")
    outside = nodes.reference("", "elsewhere", refuri="https://c.d")
    doc += _citation("k", nodes.paragraph("", "", doi, same, plain_http, internal, local))
    doc += nodes.paragraph("", "", outside)
    pdf_layout.CitationUrlsInline.run(SimpleNamespace(document=doc))
    assert [r.astext() for r in doc.findall(nodes.reference)] == [
        "https://doi.org/10.1/x",
        "http://a.b",
        "http://e.f/g",
        "internal",
        "see",
        "elsewhere",
    ]
    assert pdf_layout.CitationUrlsInline.formats == ("latex",)
    assert pdf_layout.CitationUrlsInline.default_priority < 400


def test_citations_in_place_keep_runs_where_they_stand():
    doc = nodes.section()
    doc += nodes.title("", "T")
    doc += _citation("a", nodes.label("", "1"))
    doc += _citation("b", nodes.label("", "2"))
    doc += nodes.paragraph("", "between")
    doc += _citation("c", nodes.label("", "3"))
    inner = nodes.section()
    inner += _citation("d", nodes.label("", "4"))
    doc += inner
    pdf_layout.CitationsInPlace.run(SimpleNamespace(document=doc))
    kinds = [type(c).__name__ for c in doc.children]
    assert kinds == ["title", "thebibliography", "paragraph", "thebibliography", "section"]
    lists = [c for c in doc.children if type(c).__name__ == "thebibliography"]
    assert [[(type(x).__name__, x["ids"], x.rawsource, x.astext()) for x in lst] for lst in lists] == [
        [("in_place_citation", ["a"], "raw-a", "1"), ("in_place_citation", ["b"], "raw-b", "2")],
        [("in_place_citation", ["c"], "raw-c", "3")],
    ]
    assert [type(x).__name__ for x in inner.children] == ["thebibliography"]
    assert not list(doc.findall(nodes.citation))
    assert pdf_layout.CitationsInPlace.default_priority < 750


def _intro(title: str | None, first_title: str = "Book", children: bool = True):
    doc = nodes.document(None, None)
    section = nodes.section()
    if children:
        section += nodes.title("", first_title)
        section += nodes.paragraph("", "text")
    doc += section
    titles = {} if title is None else {"index": nodes.title("", title)}
    return SimpleNamespace(
        document=doc, config=SimpleNamespace(root_doc="index"), env=SimpleNamespace(titles=titles)
    ), section


def test_introduction_heading():
    transform, section = _intro("A & B", "A & B")
    pdf_layout.IntroductionHeading.run(transform)
    raw = section[1]
    assert isinstance(raw, nodes.raw) and raw["format"] == "latex"
    t = r"A \& B"
    assert raw.astext() == (
        rf"\chapter*{{{t}}}\addcontentsline{{toc}}{{chapter}}{{{t}}}\markboth{{{t}}}{{{t}}}" + "\n"
    )
    assert len(section) == 3
    for transform, section in (_intro(None), _intro("Book", "Other"), _intro("Book", children=False)):
        before = len(section)
        pdf_layout.IntroductionHeading.run(transform)
        assert len(section) == before
    # the first section starts with something other than a title
    transform, section = _intro("text", "Book")
    section.children = [nodes.paragraph("", "text")]
    pdf_layout.IntroductionHeading.run(transform)
    assert len(section) == 1
    # no section at all
    transform, _ = _intro("Book")
    transform.document.children = []
    pdf_layout.IntroductionHeading.run(transform)
    assert transform.document.children == []


class _Writer:
    def __init__(self, table=None):
        self.body: list[str] = []
        self.no_latex_floats = 0
        self.table = table
        self.calls: list[str] = []

    def visit_citation(self, node):
        self.calls.append(("visit", node))

    def depart_citation(self, node):
        self.calls.append(("depart", node))


@pytest.mark.parametrize(
    ("classes", "kind"), [(["warning"], "warning"), (["x", "warning"], "warning"), ([], "note")]
)
def test_admonition_boxes(classes, kind):
    table = SimpleNamespace(has_problematic=False)
    writer = _Writer(table)
    node = nodes.admonition(classes=classes)
    pdf_layout._visit_admonition(writer, node)
    assert writer.body == ["\n\\begin{sphinxadmonition}{" + kind + "}"]
    assert writer.no_latex_floats == 1 and table.has_problematic is True
    pdf_layout._depart_admonition(writer, node)
    assert writer.body[-1] == "\\end{sphinxadmonition}\n"
    assert writer.no_latex_floats == 0
    outside = _Writer(None)
    outside.no_latex_floats = 2  # nested in another float-free box
    pdf_layout._visit_admonition(outside, nodes.admonition())
    assert outside.table is None and outside.no_latex_floats == 3


def test_in_place_citation_is_printed_as_a_citation():
    writer = _Writer()
    node = nodes.citation()
    pdf_layout._visit_in_place_citation(writer, node)
    pdf_layout._depart_in_place_citation(writer, node)
    assert writer.calls == [("visit", node), ("depart", node)]


# --- book_downloads ---------------------------------------------------------------------------------


def _app(tmp_path: Path, fmt: str = "html", env=None) -> SimpleNamespace:
    out = tmp_path / "html"
    out.mkdir(exist_ok=True)
    return SimpleNamespace(outdir=str(out), builder=SimpleNamespace(format=fmt), env=env or SimpleNamespace())


def _write_notebook(path: Path, outputs: list) -> None:
    import nbformat

    outputs = [nbformat.from_dict(o) for o in outputs]
    nb = nbformat.v4.new_notebook()
    nb.cells = [
        nbformat.v4.new_markdown_cell("# t"),
        nbformat.v4.new_code_cell("x", outputs=outputs, execution_count=1),
    ]
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)


def test_executed_notebook_ids_addresses_and_provenance(tmp_path, monkeypatch):
    monkeypatch.setattr(book_downloads, "_provenance", lambda: {"commit": "c"})
    out = {
        "output_type": "execute_result",
        "execution_count": 1,
        "metadata": {},
        "data": {"text/plain": "<Thing at 0x7fAB12> and <Other at 0xff>"},
    }
    _write_notebook(tmp_path / "p.ipynb", [out])
    nb = book_downloads.executed_notebook(tmp_path / "p.ipynb", None)
    assert [c["id"] for c in nb.cells] == ["cell-0", "cell-1"]
    assert nb.cells[1].outputs[0]["data"]["text/plain"] == "<Thing> and <Other>"
    assert nb.metadata["navcore_provenance"] == {"commit": "c"}


def test_executed_notebook_merges_outputs_only_when_absent(tmp_path, monkeypatch):
    import jupyter_cache
    import nbformat

    monkeypatch.setattr(book_downloads, "_provenance", lambda: {})
    merged = []

    class Cache:
        def merge_match_into_notebook(self, nb):
            merged.append(nb)
            if len(merged) == 2:
                raise KeyError("not cached")
            nb.cells[1].outputs = [
                nbformat.from_dict({"output_type": "stream", "name": "stdout", "text": "hi"})
            ]
            return 1, nb

    monkeypatch.setattr(jupyter_cache, "get_cache", lambda path: Cache() if path == "C" else None)
    _write_notebook(tmp_path / "empty.ipynb", [])
    nb = book_downloads.executed_notebook(tmp_path / "empty.ipynb", "C")
    assert nb.cells[1].outputs[0]["text"] == "hi" and len(merged) == 1
    nb = book_downloads.executed_notebook(tmp_path / "empty.ipynb", "C")  # KeyError: as written
    assert nb.cells[1].outputs == [] and len(merged) == 2
    nb = book_downloads.executed_notebook(tmp_path / "empty.ipynb", None)
    assert len(merged) == 2
    _write_notebook(tmp_path / "full.ipynb", [{"output_type": "stream", "name": "stdout", "text": "own"}])
    nb = book_downloads.executed_notebook(tmp_path / "full.ipynb", "C")
    assert nb.cells[1].outputs[0]["text"] == "own" and len(merged) == 2


def test_add_notebook_writes_the_download(tmp_path, monkeypatch):
    monkeypatch.setattr(book_downloads, "_provenance", lambda: {"commit": "c"})
    config = SimpleNamespace(execution_mode="off", execution_cache_path="C")
    app = _app(tmp_path, env=SimpleNamespace(mystnb_config=config))
    _write_notebook(tmp_path / "jupyter_execute" / "wf" / "page.ipynb", [])
    context: dict = {}
    book_downloads._add_notebook(app, "wf/page", "page.html", context, object())
    target = tmp_path / "html" / "_sources" / "wf" / "page.ipynb"
    assert context == {"ipynb_source": "wf/page.ipynb"}
    text = target.read_text()
    assert text.endswith("}\n\n") or text.endswith("}\n")
    assert json.loads(text)["metadata"]["navcore_provenance"] == {"commit": "c"}
    # no doctree, another builder, no executed notebook: nothing
    for args in (
        (app, "wf/page", None),
        (_app(tmp_path, "latex"), "wf/page", object()),
        (app, "nope", object()),
    ):
        context = {}
        book_downloads._add_notebook(args[0], args[1], "page.html", context, args[2])
        assert context == {}


@pytest.mark.parametrize(("mode", "expected"), [("cache", "C"), ("force", None)])
def test_add_notebook_uses_the_cache_only_in_cache_mode(tmp_path, monkeypatch, mode, expected):
    seen = []
    monkeypatch.setattr(book_downloads, "executed_notebook", lambda path, cache: seen.append(cache) or {})
    monkeypatch.setitem(sys.modules, "nbformat", SimpleNamespace(writes=lambda nb: "{}"))
    config = SimpleNamespace(execution_mode=mode, execution_cache_path="C")
    app = _app(tmp_path, env=SimpleNamespace(mystnb_config=config))
    (tmp_path / "jupyter_execute").mkdir()
    (tmp_path / "jupyter_execute" / "p.ipynb").write_text("{}")
    book_downloads._add_notebook(app, "p", "t", {}, object())
    book_downloads._add_notebook(_app(tmp_path), "p", "t", {}, object())  # no MyST-NB config
    assert seen == [expected, None]
    assert (tmp_path / "html" / "_sources" / "p.ipynb").read_text() == "{}\n"


def test_pdf_button_and_copy(tmp_path):
    app = _app(tmp_path)
    pdf = tmp_path / "latex" / "book.pdf"
    assert book_downloads._pdf_source(app) == pdf
    assert book_downloads._build_dir(app) == tmp_path

    def context():
        return {
            "header_buttons": [
                {"label": "other", "buttons": []},
                {"label": "download-buttons", "buttons": []},
            ],
            "pathto": lambda name, kind: f"../{name}#{kind}",
        }

    ctx = context()
    book_downloads._add_pdf_button(app, "p", "t", ctx, None)  # no PDF yet
    assert ctx["header_buttons"][1]["buttons"] == []
    book_downloads._copy_pdf(app, None)
    assert not (tmp_path / "html" / "book.pdf").exists()
    pdf.parent.mkdir()
    pdf.write_bytes(b"%PDF")
    ctx = context()
    book_downloads._add_pdf_button(app, "p", "t", ctx, None)
    assert ctx["header_buttons"][0]["buttons"] == []
    assert ctx["header_buttons"][1]["buttons"] == [
        {
            "type": "link",
            "url": "../book.pdf#1",
            "text": "book (PDF)",
            "tooltip": "Download the whole book as a PDF",
            "icon": "fas fa-book",
            "label": "download-book-pdf-button",
        }
    ]
    book_downloads._add_pdf_button(app, "p", "t", {}, None)  # no header buttons: nothing to do
    latex = _app(tmp_path, "latex")
    ctx = context()
    book_downloads._add_pdf_button(latex, "p", "t", ctx, None)
    assert ctx["header_buttons"][1]["buttons"] == []
    book_downloads._copy_pdf(latex, None)
    assert not (tmp_path / "html" / "book.pdf").exists()
    book_downloads._copy_pdf(app, RuntimeError("failed"))
    assert not (tmp_path / "html" / "book.pdf").exists()
    book_downloads._copy_pdf(app, None)
    assert (tmp_path / "html" / "book.pdf").read_bytes() == b"%PDF"


# --- subset_references ------------------------------------------------------------------------------


GLOSSARY = """# Glossary

```{glossary}
:sorted:
CEP
  Circular error probable.
A posteriori
  After the data.
Kalman Filter
  A filter.
%comment
```

Not a term

:::{glossary}
Tightly coupled
  text
:::
After
"""


def test_glossary_terms():
    assert subset_references._glossary_terms(GLOSSARY) == {
        "cep",
        "a posteriori",
        "kalman filter",
        "tightly coupled",
    }
    assert subset_references._glossary_terms("CEP\n") == set()


def _book(tmp_path: Path) -> Path:
    src = tmp_path / "book"
    pages = {
        "intro.md": "# Introduction\n",
        "wf/01-model.md": "(wf-model)=\n# The model\n\n```{math}\n:label: Eq-One\n```\n$$ x $$ (eq-two)\n",
        "kzl/01-page.md": "# KZL page\n",
        "reference/api.rst": "The API\n=======\n\n.. _api-top:\n\n.. automodule:: navcore.frames\n",
        "reference/more.md": "```{automodule} navcore.units\n```\n\n:::{py:module} navcore.ledger\n:::\n",
        "glossary.md": GLOSSARY,
        "notes.txt": "(not-a-page)=\n",
        "_hidden/x.md": "(hidden)=\n",
        ".dot/y.md": "(dot)=\n",
        "bad.md": b"\xff\xfe(bad-label)=\n",
    }
    for name, text in pages.items():
        path = src / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text)
    return src


def _env(src: Path, found=("intro", "kzl/01-page"), docname="kzl/01-page") -> SimpleNamespace:
    return SimpleNamespace(
        srcdir=str(src), found_docs=set(found), all_docs=dict.fromkeys(found), docname=docname
    )


def test_outside_sources_and_what_they_define(tmp_path):
    src = _book(tmp_path)
    env = _env(src)
    sources = subset_references._outside_sources(env)
    assert sources == {
        "bad": src / "bad.md",
        "glossary": src / "glossary.md",
        "reference/api": src / "reference/api.rst",
        "reference/more": src / "reference/more.md",
        "wf/01-model": src / "wf/01-model.md",
    }
    outside = subset_references._Outside(env)
    assert outside.sources == sources
    assert outside.labels == {"wf-model", "eq-one", "eq-two", "api-top"}
    assert outside.titles == {
        "wf/01-model": "The model",
        "reference/api": "The API",
        "glossary": "Glossary",
    }
    assert outside.terms == {"cep", "a posteriori", "kalman filter", "tightly coupled"}
    assert outside.modules == {"navcore.frames", "navcore.units", "navcore.ledger"}


def test_outside_without_the_glossary_has_no_terms(tmp_path):
    env = _env(_book(tmp_path), found=("intro", "glossary"))
    outside = subset_references._Outside(env)
    assert outside.terms == set()
    app = SimpleNamespace(env=env, _subset_counts=Counter(), _subset_outside=outside)
    assert subset_references.missing_reference(app, env, _ref("std", "term", "CEP"), nodes.Text("x")) is None


def test_outside_is_computed_once_per_app(tmp_path):
    app = SimpleNamespace(env=_env(_book(tmp_path)))
    first = subset_references._outside(app)
    assert subset_references._outside(app) is first is app._subset_outside


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("navcore.frames.quat_normalize", True),
        ("navcore.frames", True),
        ("navcore.frames._private", False),
        ("navcore.frames.__name__", False),  # exists, but private
        ("navcore.frames.no_such_thing", False),
        ("navcore.estimation.kalman", False),  # not documented outside
        ("numpy.linalg", False),
        ("navcoreish.x", False),
        ("navcore.no_such_module.f", False),
        ("navcore", False),
    ],
)
def test_documented(name, expected):
    modules = {"navcore.frames", "navcore.units"}
    assert subset_references._documented(name, modules) is expected


def test_documented_the_package_itself():
    assert subset_references._documented("navcore", {"navcore"}) is True


def _subset_app(tmp_path: Path, **env) -> SimpleNamespace:
    app = SimpleNamespace(env=_env(_book(tmp_path), **env), _subset_counts=Counter())
    return app


def _ref(domain, reftype, target, **attrs) -> addnodes.pending_xref:
    return addnodes.pending_xref(
        "", nodes.Text("words"), refdomain=domain, reftype=reftype, reftarget=target, **attrs
    )


def test_missing_reference_sets_what_lies_outside_as_text(tmp_path):
    app = _subset_app(tmp_path)
    env = app.env
    cont = nodes.literal(text="cont")

    def resolve(node):
        out = subset_references.missing_reference(app, env, node, cont)
        return None if out is None else (out["classes"], out.astext())

    plain = ["xref-outside-subset"]
    # pages: by title, by its own words, unknown, inside the subset
    assert resolve(_ref("std", "doc", "../wf/01-model", refdoc="kzl/01-page")) == (plain, "The model")
    assert resolve(_ref("std", "doc", "../wf/01-model.md", refdoc="kzl/01-page", refexplicit=True)) == (
        plain,
        "cont",
    )
    assert resolve(_ref("std", "doc", "/bad")) == (plain, "/bad")  # no title: the target
    assert resolve(_ref("std", "doc", "../wf/02-none", refdoc="kzl/01-page")) is None
    assert resolve(_ref("std", "doc", "/intro", refdoc="kzl/01-page")) is None
    # labels, of every role, any case
    for domain, reftype in (("std", "ref"), ("std", "numref"), ("math", "eq"), ("prf", "ref")):
        assert resolve(_ref(domain, reftype, "WF-model")) == (plain, "cont")
        assert resolve(_ref(domain, reftype, "nope")) is None
    assert resolve(_ref("std", "label", "wf-model")) is None
    # glossary terms
    assert resolve(_ref("std", "term", "Kalman filter")) == (plain, "cont")
    assert resolve(_ref("std", "term", "nope")) is None
    assert resolve(_ref("std", "keyword", "Kalman filter")) is None  # not a term reference
    assert resolve(_ref("c", "term", "Kalman filter")) is None
    # the API, with and without the current module
    assert resolve(_ref("py", "func", "navcore.frames.quat_normalize")) == (plain, "cont")
    assert resolve(_ref("py", "func", "quat_normalize", **{"py:module": "navcore.frames"})) == (plain, "cont")
    assert resolve(_ref("py", "func", "quat_normalize")) is None
    assert resolve(_ref("py", "func", "navcore.estimation.kalman")) is None
    assert resolve(_ref("c", "func", "wf-model")) is None
    assert resolve(_ref(None, None, None)) is None
    assert app._subset_counts == Counter({"page": 3, "label": 4, "term": 1, "API": 2})


def test_missing_reference_reads_the_current_page_when_the_node_has_none(tmp_path):
    app = _subset_app(tmp_path)
    node = _ref("std", "doc", "../wf/01-model")
    out = subset_references.missing_reference(app, app.env, node, nodes.Text("x"))
    assert out.astext() == "The model"
    # a page name relative to the node's own page, not the page being resolved
    node = _ref("std", "doc", "01-model", refdoc="wf/02-other")
    out = subset_references.missing_reference(app, app.env, node, nodes.Text("x"))
    assert out.astext() == "The model"
    node = _ref("std", "doc", "01-model")
    assert subset_references.missing_reference(app, app.env, node, nodes.Text("x")) is None


def test_myst_links_outside(tmp_path):
    app = _subset_app(tmp_path, docname="kzl/01-page")
    std = SimpleNamespace(labels={"eq-two": 1}, anonlabels={"api-top": 1})
    env = app.env
    env.get_domain = lambda name: {"std": std}[name]
    para = nodes.paragraph()
    other = addnodes.pending_xref(
        "", nodes.Text("o"), refdomain="doc", reftype="doc", reftarget="wf/01-model"
    )
    para.append(other)  # not a MyST link: left alone, and the links after it are still read

    def link(domain, target, **attrs):
        node = addnodes.pending_xref(
            "",
            nodes.inline("", "text " + target),
            refdomain=domain,
            reftype="myst",
            reftarget=target,
            **attrs,
        )
        para.append(node)
        return node

    link("doc", "wf/01-model")  # a page outside: its title
    link("doc", "wf/01-model", refexplicit=True)  # its own words
    link("doc", "intro")  # inside: left to MyST
    link("doc", "wf/none")  # no such page
    link("doc", "bad")  # a page outside without a title: its name
    link(None, "WF-model")  # a label outside
    link(None, "eq-two")  # defined inside too (Sphinx's labels)
    link(None, "api-top")  # an anonymous label inside
    link(None, "nope")
    transform = SimpleNamespace(env=env, app=app, document=para)
    subset_references.MystLinksOutside.run(transform)
    out = [(type(n).__name__, n.astext()) for n in para.children]
    assert out == [
        ("pending_xref", "o"),
        ("inline", "The model"),
        ("inline", "text wf/01-model"),
        ("pending_xref", "text intro"),
        ("pending_xref", "text wf/none"),
        ("inline", "bad"),
        ("inline", "text WF-model"),
        ("pending_xref", "text eq-two"),
        ("pending_xref", "text api-top"),
        ("pending_xref", "text nope"),
    ]
    assert app._subset_counts == Counter({"page": 3, "label": 1})
    assert subset_references.MystLinksOutside.default_priority == 8


def test_plain_text_node(tmp_path):
    app = SimpleNamespace(_subset_counts=Counter())
    cont = nodes.literal(text="c")
    node = subset_references._plain(app, "page", cont)
    assert node["classes"] == ["xref-outside-subset"] and node.astext() == "c"
    assert node.children[0] is not cont
    node = subset_references._plain(app, "page", cont, "Title")
    assert node.astext() == "Title" and isinstance(node.children[0], nodes.Text)
    assert app._subset_counts == Counter({"page": 2})


def test_report_counts(capsys):
    app = SimpleNamespace(_subset_counts=Counter({"page": 2, "API": 1}))
    subset_references._report(app, None)
    assert capsys.readouterr().out == (
        "subset build: 3 references to what lies outside the subset set as plain text (API 1, page 2)\n"
    )
    subset_references._report(SimpleNamespace(_subset_counts=Counter()), None)
    assert (
        capsys.readouterr().out
        == "subset build: 0 references to what lies outside the subset set as plain text\n"
    )


# --- glossary_links: the parts a toy build does not tell apart --------------------------------------


def test_glossary_entries_edges():
    source = (
        "```{glossary}\n"
        ":sorted:\n"
        "A posteriori\n"
        "  definition\n"
        "term : index key : more\n"
        "synonym\n"
        "\n"
        "next\n"
        "```\n"
        "After the glossary\n"
        "\n"
        ":::{glossary}\n"
        "second\n"
        "  text\n"
        ":::\n"
        "Outside\n"
    )
    assert glossary_links.glossary_entries(source) == [
        ["A posteriori"],
        ["term", "synonym"],
        ["next"],
        ["second"],
    ]
    assert glossary_links.glossary_entries("no glossary\n") == []


@pytest.mark.parametrize(
    ("term", "text", "match"),
    [("dB", "DB here", "DB"), ("dB", "dB here", "dB"), ("x", "X here", "X"), ("X", "x here", None)],
)
def test_term_pattern_capital_first_letter(term, text, match):
    m = glossary_links.term_pattern(term).search(text)
    assert (m.group(0) if m else None) == match


def test_matcher_ignores_terms_in_either_case_and_sorts_longest_first():
    m = glossary_links.Matcher([["coupled"], ["tightly coupled"], ["Consistent", "fine"]], {"consistent"})
    assert [(i, t) for i, t, _ in m.patterns] == [(1, "tightly coupled"), (0, "coupled"), (2, "fine")]
    m = glossary_links.Matcher([["Consistent"]], {"Consistent"})
    assert m.patterns == []


@pytest.mark.parametrize(
    ("entries", "text", "done", "expected"),
    [
        ([["Kalman filter"], ["Kalman"]], "a Kalman filter", set(), (2, 15, 0, "Kalman filter")),
        ([["Kalman filter"], ["filter bank"]], "Kalman filter bank", set(), (0, 13, 0, "Kalman filter")),
        ([["CEP"], ["CEP"]], "the CEP", set(), (4, 7, 0, "CEP")),
        ([["CEP"], ["fix"]], "CEP fix CEP", {0}, (4, 7, 1, "fix")),
        ([["CEP"], ["fix"]], "CEP fix CEP", {0, 1}, None),
        ([["tightly coupled"], ["coupled"]], "tightly coupled, then coupled", {0}, (22, 29, 1, "coupled")),
        ([["CEP"]], "nothing", set(), None),
    ],
)
def test_matcher_first(entries, text, done, expected):
    assert glossary_links.Matcher(entries, set()).first(text, done) == expected


def _in(*parents: nodes.Element) -> nodes.Text:
    """A Text node inside the given chain of elements (outermost first)."""
    for outer, inner in itertools.pairwise(parents):
        outer += inner
    text = nodes.Text("CEP")
    parents[-1].append(text)
    return text


@pytest.mark.parametrize(
    ("chain", "skipped"),
    [
        (lambda: (nodes.section(), nodes.paragraph()), False),
        (lambda: (nodes.container(classes=["cell_output"]), nodes.paragraph()), True),
        (lambda: (nodes.container(classes=["x", "output"]), nodes.paragraph()), True),
        (lambda: (nodes.container(classes=["glossary"]),), True),
        (lambda: (nodes.container(classes=["other"]), nodes.paragraph()), False),
        (lambda: (nodes.section(), nodes.title()), True),
        (lambda: (nodes.paragraph(), nodes.literal()), True),
        (
            lambda: (
                nodes.table(),
                nodes.tgroup(),
                nodes.thead(),
                nodes.row(),
                nodes.entry(),
                nodes.paragraph(),
            ),
            True,
        ),
        (
            lambda: (
                nodes.table(),
                nodes.tgroup(),
                nodes.tbody(),
                nodes.row(),
                nodes.entry(),
                nodes.paragraph(),
            ),
            False,
        ),
    ],
)
def test_skipped(chain, skipped):
    assert glossary_links._skipped(_in(*chain())) is skipped


def test_skipped_header_cell_outside_a_table_group():
    """A header row's cell is skipped by its row's parent (thead) even without the SKIP_NODES match."""
    head = nodes.thead()
    row = nodes.row()
    entry = nodes.entry()
    head += row
    row += entry
    text = nodes.Text("CEP")
    entry += text
    saved = glossary_links.SKIP_NODES
    try:
        glossary_links.SKIP_NODES = tuple(n for n in saved if n is not nodes.thead)
        assert glossary_links._skipped(text) is True
    finally:
        glossary_links.SKIP_NODES = saved


class _GlossEnv:
    def __init__(self, docname="page", found=("page", "glossary", "reference/api")):
        self.docname = docname
        self.serials: list[str] = []
        self.found_docs = set(found)
        self.config = SimpleNamespace(
            glossary_links_docname="glossary", glossary_links_exclude=["reference/"]
        )

    def new_serialno(self, category):
        self.serials.append(category)
        return len(self.serials) - 1


def _transform(paragraph_text: str, matcher, docname="page"):
    doc = nodes.section()
    para = nodes.paragraph()
    para += nodes.Text(paragraph_text)
    doc += para
    noted = []
    document = SimpleNamespace(findall=doc.findall, note_explicit_target=noted.append)
    app = SimpleNamespace() if matcher is None else SimpleNamespace(_glossary_links_matcher=matcher)
    t = SimpleNamespace(env=_GlossEnv(docname), app=app, document=document)
    t._link_in = lambda *a: glossary_links.GlossaryLinks._link_in(t, *a)
    t._link = lambda *a: glossary_links.GlossaryLinks._link(t, *a)
    return t, para, noted


def test_glossary_links_nodes():
    matcher = glossary_links.Matcher([["CEP"], ["fix"]], set())
    t, para, noted = _transform("The CEP of a fix, the CEP.", matcher)
    glossary_links.GlossaryLinks.apply(t)
    kinds = [type(n).__name__ for n in para.children]
    assert kinds == [
        "Text",
        "index",
        "target",
        "pending_xref",
        "Text",
        "index",
        "target",
        "pending_xref",
        "Text",
    ]
    assert [para[0].astext(), para[4].astext(), para[8].astext()] == ["The ", " of a ", ", the CEP."]
    index, target, xref = para[1], para[2], para[3]
    assert index["entries"] == [("single", "CEP", "index-0", "", None)] and index["inline"] is True
    assert target["ids"] == ["index-0"] and target.rawsource == "" and target.astext() == ""
    assert noted == [target, para[6]]
    assert xref.attributes | {} == {
        **xref.attributes,
        "refdomain": "std",
        "reftype": "term",
        "reftarget": "CEP",
        "refexplicit": True,
        "refwarn": True,
        "refdoc": "page",
    }
    (inline,) = xref.children
    assert inline.rawsource == "CEP" and inline.astext() == "CEP"
    assert inline["classes"] == ["xref", "std", "std-term", "glossary-link"]
    assert t.env.serials == ["index", "index"]
    assert para[7]["reftarget"] == "fix" and para[5]["entries"][0][2] == "index-1"


def test_glossary_links_only_where_they_should():
    matcher = glossary_links.Matcher([["CEP"]], set())
    for t, para, _ in (
        _transform("The CEP.", None),  # no glossary read
        _transform("The CEP.", glossary_links.Matcher([], set())),  # an empty glossary
        _transform("The CEP.", matcher, docname="glossary"),  # the glossary itself
        _transform("The CEP.", matcher, docname="reference/api"),  # an excluded part
    ):
        glossary_links.GlossaryLinks.apply(t)
        assert [type(n).__name__ for n in para.children] == ["Text"]
    t, para, _ = _transform("CEP", matcher)
    glossary_links.GlossaryLinks.apply(t)
    assert [type(n).__name__ for n in para.children] == ["index", "target", "pending_xref"]


def test_glossary_links_not_without_a_glossary_page():
    env = _GlossEnv(found=("page",))
    assert glossary_links._is_excluded("page", env) is True
    assert glossary_links._is_excluded("page", _GlossEnv()) is False
    assert glossary_links._is_excluded("reference/x", _GlossEnv()) is True


def test_read_glossary_and_outdated(tmp_path):
    (tmp_path / "glossary.md").write_text(
        "% glossary-links ignore: b\n```{glossary}\nA1\n  x\nb\n  y\nc\n  z\n```\n"
    )
    config = SimpleNamespace(glossary_links_docname="glossary", glossary_links_ignore=["c"])
    app = SimpleNamespace(config=config, srcdir=str(tmp_path))
    glossary_links._read_glossary(app)
    import hashlib

    digest = hashlib.sha256((tmp_path / "glossary.md").read_bytes()).hexdigest()
    assert app._glossary_links_source_hash == digest
    assert [(i, t) for i, t, _ in app._glossary_links_matcher.patterns] == [(0, "A1")]
    env = SimpleNamespace(found_docs={"a", "b", "c", "glossary"})
    assert sorted(glossary_links._outdated(app, env, {"a"}, {"b"}, set())) == ["c", "glossary"]
    assert env.glossary_links_source_hash == digest
    assert glossary_links._outdated(app, env, set(), set(), set()) == []
    # an rst glossary, and none at all
    (tmp_path / "glossary.md").unlink()
    (tmp_path / "glossary.rst").write_text(".. glossary::\n")
    glossary_links._read_glossary(app)
    assert app._glossary_links_source_hash == hashlib.sha256(b".. glossary::\n").hexdigest()
    (tmp_path / "glossary.rst").unlink()
    glossary_links._read_glossary(app)
    assert app._glossary_links_source_hash == hashlib.sha256(b"").hexdigest()
    assert app._glossary_links_matcher.patterns == []


# --- book_presentation and paper_equations: the parts the toy builds leave open ---------------------


@pytest.mark.parametrize(("docname", "chapter"), [("wf/01-page", "wf"), ("intro", ""), ("a/b/c", "a")])
def test_chapter_of_a_page(docname, chapter):
    assert book_presentation._chapter(docname) == chapter


def test_renumber_leaves_equations_code_tables_and_solutions():
    env = SimpleNamespace(
        toc_fignumbers={
            "intro": {
                "displaymath": {"eq": (7,)},
                "code-block": {"c": (8,)},
                "table": {"t": (9,)},
                "figure": {"fig-own": (1,)},
            },
            "wf/01": {
                "solution": {"sol": (5,)},
                "theorem": {"thm": (1,)},
                "exercise": {"ex1": (2,), "ex2": (3,)},
            },
        }
    )
    book_presentation._renumber(None, env)  # no paper theorem numbers recorded at all
    n = env.toc_fignumbers
    assert n["intro"] == {
        "displaymath": {"eq": (7,)},
        "code-block": {"c": (8,)},
        "table": {"t": (9,)},
        "figure": {"fig-own": ("N1",)},
    }
    assert n["wf/01"] == {
        "solution": {"sol": (5,)},
        "theorem": {"thm": ("N1",)},
        "exercise": {"ex1": ("1",), "ex2": ("2",)},
    }
    env = SimpleNamespace(
        toc_fignumbers={"kzl/01": {"theorem": {"a": (1,), "b": (2,)}}},
        paper_theorem_numbers={"wf/01": {"a": "9.9"}},
    )
    book_presentation._renumber(None, env)  # numbers of another page do not apply
    assert env.toc_fignumbers["kzl/01"]["theorem"] == {"a": ("N1",), "b": ("N2",)}


def _latex_app(fmt: str = "latex") -> SimpleNamespace:
    return SimpleNamespace(builder=SimpleNamespace(format=fmt))


def _proof_box(classes: list[str], text: str, title: str | None = None) -> nodes.admonition:
    box = nodes.admonition(classes=classes)
    if title is not None:
        box += nodes.title("", title)
    box += nodes.paragraph("", text)
    return box


def test_print_proof_titles():
    doc = nodes.section()
    doc += _proof_box(["theorem"], "Theorem. Not a proof box.")
    doc += _proof_box(["proof"], "Proof. It follows.", title="Proof")  # titled already
    doc += _proof_box(["proof"], "Proof. It follows.")
    doc += _proof_box(["proof", "lemma"], "Lemma. A lemma's proof.")
    doc += _proof_box(["proof"], "No prefix here.")
    book_presentation._print_proof_titles(_latex_app(), doc, "p")
    shown = [[(type(c).__name__, c.astext(), c.rawsource) for c in box.children] for box in doc.children]
    assert shown == [
        [("paragraph", "Theorem. Not a proof box.", "")],
        [("title", "Proof", ""), ("paragraph", "Proof. It follows.", "")],
        [("title", "Proof", ""), ("paragraph", "It follows.", "")],
        [("title", "Lemma", ""), ("paragraph", "A lemma's proof.", "")],
        [("title", "Proof", ""), ("paragraph", "No prefix here.", "")],
    ]
    empty = nodes.section()
    empty += nodes.admonition(classes=["proof"])  # no text at all
    book_presentation._print_proof_titles(_latex_app(), empty, "p")
    assert [type(c).__name__ for c in empty[0].children] == ["title"]
    html = nodes.section()
    html += _proof_box(["proof"], "Proof. x")
    book_presentation._print_proof_titles(_latex_app("html"), html, "p")
    assert [type(c).__name__ for c in html[0].children] == ["paragraph"]


def test_print_hidden_inputs_drops_only_folded_sources():
    def cell(classes):
        c = nodes.container(classes=classes)
        c += nodes.container("", nodes.Text("src"), classes=["cell_input"])
        c += nodes.container("", nodes.Text("out"), classes=["cell_output"])
        return c

    doc = nodes.section()
    doc += cell(["cell", "tag_hide-input"])
    doc += cell(["cell"])
    doc += cell(["other", "tag_hide-input"])
    book_presentation._print_hidden_inputs(_latex_app(), doc, "p")
    assert [c.astext() for c in doc.children] == ["out", "src\n\nout", "src\n\nout"]


def test_words_links_in_text_font():
    para = nodes.paragraph()
    para += nodes.literal("", "the federated fusion", classes=["xref", "py"])
    para += nodes.literal("", "federated_fuse", classes=["xref", "py"])
    para += nodes.literal("", "a b", classes=["code"])
    book_presentation._words_links_in_text_font(None, para, "p")
    first = para[0]
    assert isinstance(first, nodes.inline) and first["classes"] == ["api-link", "xref", "py"]
    assert first.astext() == "the federated fusion" and first.rawsource == ""
    assert [type(c).__name__ for c in para.children] == ["inline", "literal", "literal"]


def test_paper_equation_tags_per_page_merge_and_renumber():
    def doc_with(label, node_id):
        doc = nodes.section()
        doc += nodes.math_block("", "x", label=label, ids=[node_id])
        return doc

    env = SimpleNamespace(docname="wf/01")
    app = SimpleNamespace(env=env)
    paper_equations._collect(app, doc_with("own", "eq-own"))
    env.docname = "wf/02"
    paper_equations._collect(app, doc_with("own2", "eq-own2"))
    assert env.paper_equation_tags == {"wf/01": {"eq-own": "N1"}, "wf/02": {"eq-own2": "N1"}}
    paper_equations._merge(app, env, set(), SimpleNamespace())  # a worker that collected nothing
    assert set(env.paper_equation_tags) == {"wf/01", "wf/02"}
    fresh = SimpleNamespace()
    paper_equations._merge(app, fresh, set(), env)
    assert fresh.paper_equation_tags == env.paper_equation_tags
    bare = SimpleNamespace(toc_fignumbers={"p": {}})
    assert paper_equations._renumber(None, bare) == [] and bare.toc_fignumbers == {"p": {}}
    paper_equations._purge(None, SimpleNamespace(), "p")  # nothing collected: nothing to purge


def test_paper_equations_setup_patches_an_unpatched_writer(monkeypatch):
    from sphinx.writers.latex import LaTeXTranslator

    def plain(self, node):
        self.body.append("plain")

    monkeypatch.setattr(LaTeXTranslator, "visit_math_block", plain)
    paper_equations.setup(_Recorder())
    patched = LaTeXTranslator.visit_math_block
    assert patched is not plain and patched._paper_equations is True
    writer = SimpleNamespace(body=[])
    patched(writer, nodes.math_block("", "x"))
    assert writer.body == ["plain"]


def test_latex_visit_tags_the_last_label_once():
    seen = []

    def original(self, node):
        seen.append(node)
        self.body += ["\\begin{equation}", "\\label{b}\\label{c}x"]

    visit = paper_equations._latex_visit_math_block(original)
    writer = SimpleNamespace(body=["start"])
    node = nodes.math_block("", "x", paper_tag="2.1")
    visit(writer, node)
    assert seen == [node]
    assert writer.body == ["start", "\\begin{equation}", "\\tag{2.1}\\label{b}\\label{c}x"]


# --- book_presentation: the doctree passes a build runs (here on hand-made doctrees) ----------------


def _figure(ids: list[str], caption: str | None) -> nodes.figure:
    figure = nodes.figure(ids=ids)
    if caption is not None:
        figure += nodes.caption("", caption)
    return figure


@pytest.mark.parametrize(
    ("ids", "caption", "expected"),
    [
        (["fig-atc10-2-1"], "Fig. 2.1: redrawn from the model.", "Redrawn from the model."),
        (["x", "fig-wf-3"], "Figure 3 redrawn", "Redrawn"),
        (["fig-atc10-2-1"], "Fig. 2.10 is another figure", "Fig. 2.10 is another figure"),
        (["fig-atc10-2-1"], "The figure", "The figure"),
        (["fig-own"], "Fig. 2.1: not a paper figure", "Fig. 2.1: not a paper figure"),
        (["fig-atc10-3-3-to-3-6"], "Fig. 3.3\u20133.6. four panels", "Four panels"),
    ],
)
def test_captions_drop_the_repeated_number(ids, caption, expected):
    doc = nodes.section()
    doc += _figure(["fig-own"], "Fig. 1: first, not a paper figure")  # passed over, the next still read
    doc += _figure(["fig-wf-5"], None)
    doc += nodes.figure("", nodes.caption(), ids=["fig-wf-6"])  # a caption without text
    doc += _figure(ids, caption)
    book_presentation._captions(None, doc)
    assert doc[0][0].astext() == "Fig. 1: first, not a paper figure"
    assert isinstance(doc[3][0], nodes.caption) and doc[3][0].astext() == expected


def test_captions_without_caption_or_text():
    doc = nodes.section()
    doc += _figure(["fig-wf-3"], None)
    doc += nodes.figure("", nodes.caption(), ids=["fig-wf-4"])
    book_presentation._captions(None, doc)
    assert [f.astext() for f in doc.children] == ["", ""]


def test_erratum_anchors():
    doc = nodes.section()
    box = nodes.admonition()
    box += nodes.title("", "Erratum WF-E2-sign-flip")
    box += nodes.paragraph("", "The sign of WF-E2-sign-flip is wrong; see also SP-E1-units.")
    doc += box
    other = nodes.admonition()
    other += nodes.title("", "Note on KZL-E3-scale")  # not titled Erratum
    doc += other
    doc += nodes.paragraph("", "SP-E1-units again, and KZL-E3-scale, and ATC10-E4.1-x.")
    again = nodes.admonition()
    again += nodes.title("", "Erratum WF-E2-sign-flip")  # the same erratum again: no second anchor
    doc += again
    doc += nodes.admonition("", nodes.paragraph("", "untitled"))
    plain = nodes.admonition()
    plain += nodes.title("", "Erratum note")  # no id in the title: the id in its text is a paragraph's
    plain += nodes.paragraph("", "about SP-E9-x")
    doc += plain
    spaced = nodes.admonition()
    spaced += nodes.title("", "  Erratum WF-E5-y")
    doc += spaced
    book_presentation._erratum_anchors(None, doc)
    assert box["ids"] == ["wf-e2-sign-flip"]
    assert other["ids"] == [] and again["ids"] == []
    assert box[1]["ids"] == ["sp-e1-units"]
    assert doc[2]["ids"] == ["kzl-e3-scale", "atc10-e4.1-x"]
    assert plain["ids"] == [] and plain[1]["ids"] == ["sp-e9-x"]
    assert spaced["ids"] == ["wf-e5-y"]


def test_collect_titles_and_their_bookkeeping():
    def theorem(title: str, ids: list[str], **attrs) -> nodes.Element:
        node = nodes.container(ids=ids, **attrs)
        node += nodes.title("", title)
        node += nodes.paragraph("", "The statement (with a remark).")
        return node

    doc = nodes.section()
    doc += theorem("Theorem 5 of KZL", [], countertype="theorem")  # no id: passed over
    doc += theorem("Theorem #1 (Theorem 3.1 of ATC-10)", ["thm-a"], countertype="theorem")
    doc += theorem("Theorem #2 (Theorem 2.4 of WF (Eq. 7))", ["thm-b"], realtype="theorem")
    doc += theorem("Theorem #3 (Our own)", ["thm-c"], countertype="theorem")
    doc += theorem("Theorem 2.5 of WF", ["thm-e"], countertype="theorem")
    doc += theorem("Theorem #4 (Theorem 1.2\nof SP)", ["thm-f"], countertype="theorem")
    doc += theorem("Theorem 6 of KZL", ["x"], countertype="lemma")
    doc += nodes.container("", ids=["thm-d"], countertype="theorem")  # no title
    env = SimpleNamespace(docname="atc10/01")
    book_presentation._collect_titles(SimpleNamespace(env=env), doc)
    found = {"thm-a": "3.1", "thm-b": "2.4", "thm-e": "2.5", "thm-f": "1.2"}
    assert env.paper_theorem_numbers == {"atc10/01": found}
    assert [n[0].astext() for n in doc.children[:7]] == [
        "Theorem 5 of KZL",
        "Theorem #1 (ATC-10)",
        "Theorem #2 (WF, Eq. 7)",
        "Theorem #3 (Our own)",
        "WF",
        "Theorem #4 (SP)",
        "Theorem 6 of KZL",
    ]
    assert all(isinstance(n[0], nodes.title) for n in doc.children[:7])
    env.docname = "kzl/01"
    book_presentation._collect_titles(SimpleNamespace(env=env), nodes.section())
    assert env.paper_theorem_numbers == {"atc10/01": found, "kzl/01": {}}
    book_presentation._merge(None, env, set(), SimpleNamespace())
    fresh = SimpleNamespace()
    book_presentation._merge(None, fresh, set(), env)
    assert fresh.paper_theorem_numbers == env.paper_theorem_numbers
    book_presentation._purge(None, fresh, "kzl/01")
    assert set(fresh.paper_theorem_numbers) == {"atc10/01"}
    book_presentation._purge(None, SimpleNamespace(), "kzl/01")


def test_latex_figure_numbers():
    section = nodes.section()
    section += nodes.paragraph("", "text between figures")
    for ids, docname in (
        (["fig-a"], None),
        (["fig-b"], "other"),
        ([], None),
        (["fig-c"], None),
        (["fig-z"], None),
    ):
        figure = nodes.figure(ids=ids)
        if docname:
            figure["docname"] = docname
        section += figure
    env = SimpleNamespace(
        toc_fignumbers={
            "earlier": {"figure": {"fig-a": (9,), "fig-b": (8,)}},  # the same ids on another page
            "page": {"figure": {"fig-a": (2, 1)}},
            "other": {"figure": {"fig-b": (3,)}},
            "tables only": {"table": {"t": (1,)}},
            "third": {"table": {}, "figure": {"fig-c": ("N1",)}},
        }
    )
    app = SimpleNamespace(builder=SimpleNamespace(format="latex"), env=env)
    book_presentation._latex_figure_numbers(app, section, "page")
    out = [(type(n).__name__, n.astext() if isinstance(n, nodes.raw) else n["ids"]) for n in section.children]
    assert out == [
        ("paragraph", []),
        ("raw", "\\renewcommand{\\thefigure}{2.1}\n"),
        ("figure", ["fig-a"]),
        ("raw", "\\renewcommand{\\thefigure}{3}\n"),
        ("figure", ["fig-b"]),
        ("figure", []),
        ("raw", "\\renewcommand{\\thefigure}{N1}\n"),
        ("figure", ["fig-c"]),
        ("figure", ["fig-z"]),
    ]
    assert all(n["format"] == "latex" for n in section.findall(nodes.raw))
    html = nodes.section()
    html += nodes.figure(ids=["fig-a"])
    book_presentation._latex_figure_numbers(
        SimpleNamespace(builder=SimpleNamespace(format="html"), env=env), html, "page"
    )
    assert len(html) == 1
