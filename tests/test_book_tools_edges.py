"""The book tools' one-sided cases (issue 31, item 5): each gate given the input that only one of
its conditions catches, so that a condition dropped or turned around fails a test.

* the notebook gate: a notebook whose code cells all ran but print nothing, and one that has
  outputs but an unrun cell (each alone is a problem; the old test gave both at once, so an
  ``and`` for the ``or`` passed it);
* the build comparison: a file present in only one of the two trees, either way;
* the link check: a broken anchor on the same page (``href="#nope"``), and a good one;
* the equation numbering: the book's own equations after the paper's on one page are N1, N2
  in page order, whatever paper equations stand between them; the numbers reach Sphinx's
  table, and the LaTeX writer tags the equation with them.

Oracle in each test: the hand-made input and the result written out by hand.
"""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest
from docutils import nodes
from docutils.frontend import get_default_settings
from docutils.parsers.rst import Parser
from docutils.utils import new_document

ROOT = Path(__file__).resolve().parents[1]


def _load(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


check_book = _load(ROOT / "tools" / "check_book.py", "tools.check_book")
check_links = _load(ROOT / "tools" / "check_links.py", "tools.check_links")
paper_equations = _load(ROOT / "book" / "_ext" / "paper_equations.py", "book._ext.paper_equations")


# --- the notebook gate ------------------------------------------------------------------------


BUILD = {"commit": "0" * 40, "tree": "clean", "lock_sha256": "f" * 64}


def _notebook(tmp_path: Path, name: str, cells: list[dict], metadata: dict | None = None) -> None:
    folder = tmp_path / "_sources" / "wf"
    folder.mkdir(parents=True, exist_ok=True)
    meta = {"navcore_provenance": BUILD} if metadata is None else metadata
    (folder / name).write_text(json.dumps({"cells": cells, "metadata": meta}))


def _code(count: int | None, outputs: list | None = None) -> dict:
    return {"cell_type": "code", "execution_count": count, "outputs": outputs or [], "source": "x"}


PRINTED = [{"output_type": "stream", "name": "stdout", "text": "1\n"}]


def test_notebook_gate_all_cells_run_but_no_output(tmp_path):
    _notebook(tmp_path, "silent.ipynb", [_code(1), _code(2)])
    assert check_book.check_html(tmp_path) == [
        "_sources/wf/silent.ipynb: download is not executed (0 of 2 code cells without execution "
        "count, 0 with outputs)"
    ]


def test_notebook_gate_outputs_but_one_unrun_cell(tmp_path):
    _notebook(tmp_path, "partly.ipynb", [_code(1, PRINTED), _code(None)])
    assert check_book.check_html(tmp_path) == [
        "_sources/wf/partly.ipynb: download is not executed (1 of 2 code cells without execution "
        "count, 1 with outputs)"
    ]


def test_notebook_gate_passes_an_executed_notebook_and_one_without_code(tmp_path):
    _notebook(tmp_path, "good.ipynb", [_code(1, PRINTED), _code(2)])
    _notebook(tmp_path, "prose.ipynb", [{"cell_type": "markdown", "source": "text"}])
    assert check_book.check_html(tmp_path) == []


def test_notebook_gate_wants_the_build_named_in_every_download(tmp_path):
    _notebook(tmp_path, "anonymous.ipynb", [_code(1, PRINTED)], metadata={})
    _notebook(
        tmp_path, "partial.ipynb", [_code(1, PRINTED)], metadata={"navcore_provenance": {"commit": "0"}}
    )
    _notebook(tmp_path, "prose.ipynb", [{"cell_type": "markdown", "source": "text"}], metadata={})
    assert check_book.check_html(tmp_path) == [
        f"_sources/wf/{name}.ipynb: download does not name the build (navcore_provenance)"
        for name in ("anonymous", "partial", "prose")
    ]


# --- the build comparison ---------------------------------------------------------------------


@pytest.mark.parametrize("extra_in", ["a", "b"])
def test_same_gate_a_file_in_only_one_tree(tmp_path, extra_in):
    for run in ("a", "b"):
        (tmp_path / run / "wf").mkdir(parents=True)
        (tmp_path / run / "index.html").write_text("same")
    (tmp_path / extra_in / "wf" / "extra.html").write_text("only here")
    problems = check_book.same_trees(tmp_path / "a", tmp_path / "b")
    assert problems == [f"only in {tmp_path / extra_in}: {Path('wf/extra.html')}"]


def test_same_gate_pdf_bodies_still_compared(tmp_path):
    for run, body in (("a", b"one"), ("b", b"two")):
        (tmp_path / run).mkdir()
        (tmp_path / run / "book.pdf").write_bytes(b"%PDF /ModDate (D:2026) " + body)
    assert check_book.same_trees(tmp_path / "a", tmp_path / "b") == ["differs: book.pdf"]


# --- the link check ---------------------------------------------------------------------------


def _page(path: Path, body: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"<html><body>{body}</body></html>")


def test_link_check_broken_anchor_on_the_same_page(tmp_path):
    _page(tmp_path / "index.html", '<a href="#here">ok</a><h2 id="here">x</h2><a href="#nope">bad</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: #nope (no such anchor)"]


def test_link_check_anchor_by_name_and_escaped_fragment(tmp_path):
    _page(tmp_path / "index.html", '<a name="old"></a><a href="#old">ok</a><a href="a.html#x%20y">ok</a>')
    _page(tmp_path / "a.html", '<span id="x y"></span>')
    assert check_links.broken_links(tmp_path) == []


def test_link_check_ignores_the_theme_and_sources_folders_and_external_schemes(tmp_path):
    _page(tmp_path / "index.html", '<a href="mailto:x@y">m</a><a href="//cdn.example/x.js">cdn</a>')
    _page(tmp_path / "_static" / "t.html", '<a href="nope.html">theme</a>')
    _page(tmp_path / "_sources" / "s.html", '<a href="nope.html">source</a>')
    assert check_links.broken_links(tmp_path) == []


def test_link_check_command_line(tmp_path, capsys):
    sys_argv = sys.argv
    try:
        sys.argv = ["check_links.py", str(tmp_path)]
        assert check_links.main() == 2  # no book there
        _page(tmp_path / "index.html", '<a href="#nope">bad</a>')
        assert check_links.main() == 1
        out = capsys.readouterr().out
        assert "1 broken internal links in 1 pages:" in out and "index.html: #nope (no such anchor)" in out
        _page(tmp_path / "index.html", "<p>no links</p>")
        assert check_links.main() == 0
        assert "internal links: all resolve (1 pages)" in capsys.readouterr().out
    finally:
        sys.argv = sys_argv


# --- the equation numbering -------------------------------------------------------------------


def _equations(labels: list[str | None]) -> nodes.document:
    doc = new_document("page", get_default_settings(Parser))
    for i, label in enumerate(labels):
        block = nodes.math_block("", f"x_{i}")
        if label is not None:
            block["label"] = label
            block["ids"] = [f"equation-{label}"]
        doc += block
    return doc


def test_derived_equations_after_paper_equations_are_numbered_in_page_order():
    """Paper equations keep their numbers; the book's own (``eq-wf-x-...``, or any other label)
    are N1, N2, N3 in page order, counted among themselves only; an unlabelled equation is not
    numbered at all."""
    doc = _equations(["eq-wf-13", "eq-wf-x-first", "eq-wf-14", None, "eq-wf-x-second", "eq-other"])
    env = SimpleNamespace(docname="wf/01")
    paper_equations._collect(SimpleNamespace(env=env), doc)
    assert env.paper_equation_tags == {
        "wf/01": {
            "equation-eq-wf-13": "13",
            "equation-eq-wf-x-first": "N1",
            "equation-eq-wf-14": "14",
            "equation-eq-wf-x-second": "N2",
            "equation-eq-other": "N3",
        }
    }
    assert [b.get("paper_tag") for b in doc.findall(nodes.math_block)] == ["13", "N1", "14", None, "N2", "N3"]


def test_a_label_without_an_id_is_not_numbered():
    doc = _equations(["eq-wf-x-a", "eq-wf-x-b"])
    next(iter(doc.findall(nodes.math_block)))["ids"] = []
    env = SimpleNamespace(docname="wf/02")
    paper_equations._collect(SimpleNamespace(env=env), doc)
    assert env.paper_equation_tags == {"wf/02": {"equation-eq-wf-x-b": "N1"}}


def test_numbers_replace_sphinxs_and_follow_purge_and_merge():
    env = SimpleNamespace(
        docname="",
        toc_fignumbers={"wf/01": {"displaymath": {"equation-eq-wf-13": (1,), "equation-other": (2,)}}},
        paper_equation_tags={"wf/01": {"equation-eq-wf-13": "13"}, "kzl/01": {"equation-eq-kzl-x-a": "N1"}},
    )
    assert paper_equations._renumber(None, env) == []
    assert env.toc_fignumbers == {
        "wf/01": {"displaymath": {"equation-eq-wf-13": ("13",), "equation-other": (2,)}},
        "kzl/01": {"displaymath": {"equation-eq-kzl-x-a": ("N1",)}},
    }
    paper_equations._purge(None, env, "wf/01")
    assert list(env.paper_equation_tags) == ["kzl/01"]
    paper_equations._purge(None, SimpleNamespace(), "wf/01")  # nothing collected yet: no error
    fresh = SimpleNamespace()
    paper_equations._merge(None, fresh, set(), SimpleNamespace(paper_equation_tags={"a": {"i": "1"}}))
    paper_equations._merge(None, fresh, set(), SimpleNamespace(paper_equation_tags={"b": {"j": "N1"}}))
    assert fresh.paper_equation_tags == {"a": {"i": "1"}, "b": {"j": "N1"}}


@pytest.mark.parametrize(
    ("tag", "nowrap", "expected"),
    [
        ("2.4.2", False, "\\begin{equation}\\tag{2.4.2}\\label{eq:a}x\\end{equation}"),
        ("N1", False, "\\begin{equation}\\tag{N1}\\label{eq:a}x\\end{equation}"),
        (None, False, "\\begin{equation}\\label{eq:a}x\\end{equation}"),
        ("13", True, "\\begin{equation}\\label{eq:a}x\\end{equation}"),
    ],
)
def test_latex_equations_are_tagged_with_their_number(tag, nowrap, expected):
    """Sphinx's LaTeX visitor appends the equation (with its label) and raises SkipNode; the
    patched visitor puts ``\\tag{<number>}`` before the label and re-raises."""

    def original(self, node):
        self.body.append("\\begin{equation}\\label{eq:a}x\\end{equation}")
        raise nodes.SkipNode

    visit = paper_equations._latex_visit_math_block(original)
    node = nodes.math_block("", "x", nowrap=nowrap)
    if tag:
        node["paper_tag"] = tag
    writer = SimpleNamespace(body=["before"])
    with pytest.raises(nodes.SkipNode):
        visit(writer, node)
    assert writer.body == ["before", expected]
