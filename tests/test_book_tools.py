"""The book's build tools: paper equation numbers, the internal link check, link prefixes."""

from __future__ import annotations

import importlib.util
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


paper_equations = _load(ROOT / "book" / "_ext" / "paper_equations.py", "paper_equations")
check_links = _load(ROOT / "tools" / "check_links.py", "check_links")


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


def test_errata_and_ledger_links_use_the_root_prefix():
    from navcore import book, ledger

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

    df = pd.DataFrame({"a": [1.23456, np.nan], "b|c": ["u", "v"]})
    styled = df.style.format(precision=2, na_rep="").hide(axis="index")
    assert book.table(styled)._repr_markdown_() == "| a | b\\|c |\n|---|---|\n| 1.23 | u |\n|   | v |"
    assert "<table" in book.table(df)._repr_html_()
