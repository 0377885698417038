"""Erratum boxes come from the Erratum objects: no page writes one by hand.

A page shows an erratum with the ``{erratum} <id>`` directive (book/_ext/book_presentation.py),
which builds the warning box from the erratum's own fields (:func:`navcore.book.erratum_box`).
These tests read every page of the book: no hand-written erratum admonition is left, and each
box names an erratum that exists and is discussed on that very page (so the errata page's
"Discussed in" link lands on the box). A toy Sphinx build checks the directive itself: the box
carries the erratum's words and math, and an unknown id or a box on the wrong page stops the
build.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

from navcore import book, ledger

ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "book"
# a hand-written box: an admonition (or a colon fence) titled "Erratum ..."
HAND_WRITTEN = re.compile(r"^(?:```+|:::+)\{admonition\}\s*Erratum\b", re.M | re.I)
DIRECTIVE = re.compile(r"^```+\{erratum\}[ \t]*(\S*)[ \t]*$", re.M)


def _pages() -> list[Path]:
    return sorted(p for p in BOOK.rglob("*.md") if "_build" not in p.parts)


def _docname(page: Path) -> str:
    return page.relative_to(BOOK).with_suffix("").as_posix()


def test_no_page_writes_an_erratum_box_by_hand():
    found = [
        f"{_docname(p)}:{p.read_text().count(chr(10), 0, m.start()) + 1}"
        for p in _pages()
        for m in HAND_WRITTEN.finditer(p.read_text(encoding="utf-8"))
    ]
    assert found == [], "hand-written erratum boxes (use ```{erratum} <id>```): " + ", ".join(found)


def test_the_pattern_finds_a_hand_written_box():
    page = "text\n\n```{admonition} Erratum WF-E1-x\n:class: warning\nwords\n```\n"
    assert HAND_WRITTEN.search(page) and not HAND_WRITTEN.search("```{admonition} A caveat\n```\n")
    assert DIRECTIVE.findall("```{erratum} WF-E1-x\n```\n") == ["WF-E1-x"]


def test_every_box_names_an_erratum_discussed_on_its_page():
    known = {e.id: e for e in ledger.errata()}
    boxes = [(_docname(p), i) for p in _pages() for i in DIRECTIVE.findall(p.read_text(encoding="utf-8"))]
    assert boxes, "no page shows an erratum box"
    problems = [
        f"{page}: {i or '(no id)'}: "
        + ("no such erratum" if i not in known else f"discussed in {known[i].discussed_in}")
        for page, i in boxes
        if i not in known or known[i].discussed_in != page
    ]
    assert problems == []
    ids = [i for _, i in boxes]
    assert len(ids) == len(set(ids)), "an erratum shown twice"


def test_erratum_box_is_the_object_s_words():
    e = ledger.errata("ATC10")[0]
    title, paragraphs = book.erratum_box(e.id)
    assert title == f"Erratum {e.id}"
    text = ["".join(f"${t}$" if style == "math" else t for style, t in p) for p in paragraphs]
    assert text == [
        f"Printed ({e.locator}): {e.printed}",
        f"The book finds: {e.finding}",
        f"Evidence: {e.evidence}",
    ]
    assert [p[0][0] for p in paragraphs] == ["label"] * 3
    with pytest.raises(ValueError, match="not in the ledger"):
        book.erratum_box("ATC10-E0-no-such-erratum")
    with pytest.raises(ValueError, match=f"discussed in {e.discussed_in}, not on wf/other"):
        book.erratum_box(e.id, "wf/other")


# --- the directive, in a toy Sphinx build ---------------------------------------------------------


def _build(
    tmp_path: Path, page: str, body: str, builder: str = "html", extensions: tuple[str, ...] = ()
) -> tuple[int, str, Path]:
    from sphinx.cmd.build import build_main

    src = tmp_path / "src"
    (src / Path(page).parent).mkdir(parents=True, exist_ok=True)
    (src / "conf.py").write_text(
        f"import sys\nsys.path.insert(0, {str(BOOK / '_ext')!r})\n"
        f"extensions = {['myst_parser', 'book_presentation', *extensions]!r}\n"
        'myst_enable_extensions = ["dollarmath"]\n'
    )
    (src / "index.md").write_text(f"# Toy\n\n```{{toctree}}\n{page}\n```\n")
    (src / f"{page}.md").write_text(body)
    out = tmp_path / "out"
    errors = tmp_path / "errors.txt"
    with errors.open("w") as err:
        old = sys.stderr
        sys.stderr = err
        try:
            code = build_main(["-q", "-W", "-b", builder, str(src), str(out)])
        finally:
            sys.stderr = old
    return code, errors.read_text(), out


def test_directive_builds_the_box_from_the_object(tmp_path):
    e = next(e for e in ledger.errata("ATC10") if "$" in e.printed)
    code, err, out = _build(tmp_path, e.discussed_in, f"# Page\n\n```{{erratum}} {e.id}\n```\n\nAfter.\n")
    assert code == 0, err
    html = (out / f"{e.discussed_in}.html").read_text()
    box = html[html.index('<div class="warning erratum-box admonition"') :]
    box = box[: box.index("</div>")]
    assert f'id="{e.id.lower()}"' in box  # the errata page's link lands on it
    assert f'<p class="admonition-title">Erratum {e.id}</p>' in box
    assert "<strong>Printed</strong>" in box and "<strong>The book finds:</strong>" in box
    assert "<strong>Evidence:</strong>" in box
    assert box.count('<span class="math notranslate nohighlight">') == sum(
        text.count("$") // 2 for text in (e.locator, e.printed, e.finding, e.evidence)
    )


def test_directive_stops_the_build_on_an_unknown_id_or_the_wrong_page(tmp_path):
    code, err, _ = _build(tmp_path / "a", "wf/01-x", "# P\n\n```{erratum} WF-E0-no-such-erratum\n```\n")
    assert code != 0 and "WF-E0-no-such-erratum" in err and "not in the ledger" in err
    e = ledger.errata("KZL")[0]
    code, err, _ = _build(tmp_path / "b", "wf/01-x", f"# P\n\n```{{erratum}} {e.id}\n```\n")
    assert code != 0 and f"discussed in {e.discussed_in}, not on wf/01-x" in err


def test_directive_box_in_print_is_a_warning_box(tmp_path):
    e = ledger.errata("KZL")[0]
    body = f"# P\n\n```{{erratum}} {e.id}\n```\n"
    code, err, out = _build(tmp_path, e.discussed_in, body, builder="latex", extensions=("pdf_layout",))
    assert code == 0, err
    tex = next(out.glob("*.tex")).read_text()
    box = tex[tex.index("\\begin{sphinxadmonition}{warning}{Erratum KZL\\sphinxhyphen{}") :]
    box = box[: box.index("\\end{sphinxadmonition}")]
    assert "\\sphinxstylestrong{The book finds:}" in box and "\\sphinxstylestrong{Evidence:}" in box
    assert "\\(" in box  # its math is math
