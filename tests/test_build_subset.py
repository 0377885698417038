"""A subset build (``--only``) is strict about its own pages and reads the rest as plain text.

A toy book of two chapters, ``wf`` and ``kzl``, whose KZL page refers to the WF chapter in
every way the book does (a page by name and with words, a Markdown link, a section label, an
equation label, a figure number), to the front matter and to an API object. The oracle is
written out by hand: which references point outside the subset (eight), and that a reference
to nothing (a misspelt label) is broken in every build. Pages are plain Markdown (nothing
executes), so each build costs seconds.
"""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest
from _toybook import ROOT, build_env, make_book

spec = importlib.util.spec_from_file_location("tools.build_book", ROOT / "tools" / "build_book.py")
build_book = importlib.util.module_from_spec(spec)
spec.loader.exec_module(build_book)

pytestmark = pytest.mark.slow

WF_PAGE = """# The WF page

(wf-section)=
## A section of the WF page

$$
x = 1
$$ (eq-wf-1)

```{figure} ../fig.png
:name: fig-wf-1

A figure.
```
"""

KZL_PAGE = """# The KZL page

In the subset: {doc}`index`, {ref}`kzl-section`.

Outside it: {doc}`../wf/01-velocity`, {doc}`the WF page <../wf/01-velocity>`,
[a Markdown link](../wf/01-velocity.md), {ref}`wf-section`, {eq}`eq-wf-1`,
{numref}`fig-wf-1`, {doc}`../intro` and {py:func}`navcore.units.db_from_power_ratio`.

(kzl-section)=
## A section of the KZL page

{cite}`known`
"""

OUTSIDE = 8  # the references to what lies outside the kzl subset, counted by hand above

API_PAGE = """# API

```{eval-rst}
.. py:module:: navcore.units

.. py:function:: db_from_power_ratio(ratio)

   Decibels from a power ratio.
```
"""


def _book(tmp_path: Path, kzl_page: str = KZL_PAGE) -> tuple[Path, Path]:
    book, config = make_book(tmp_path, {"wf": {}, "kzl": {}})
    (book / "fig.png").write_bytes(
        bytes.fromhex(
            "89504e470d0a1a0a0000000d4948445200000001000000010806000000"
            "1f15c4890000000d49444154789c6360000002000001e221bc330000000049454e44ae426082"
        )
    )
    (book / "wf" / "01-velocity.md").write_text(WF_PAGE)
    (book / "kzl" / "01-attitude.md").write_text(kzl_page)
    (book / "reference.md").write_text(API_PAGE)
    (book / "refs.bib").write_text(
        "@book{known, author={A. Author}, title={Known}, year={2000}, publisher={P}}"
    )
    (book / "bibliography.md").write_text("# Bibliography\n\n```{bibliography}\n```\n")
    toc = (book / "_toc.yml").read_text()
    (book / "_toc.yml").write_text(
        toc + "  - caption: Back\n    chapters:\n      - file: reference\n      - file: bibliography\n"
    )
    text = config.read_text().replace("author: tests\n", "author: tests\nbibtex_bibfiles:\n  - refs.bib\n")
    config.write_text(text)
    return book, config


def _build(tmp_path: Path, book: Path, config: Path, only: str | None) -> subprocess.CompletedProcess:
    cmd = [
        sys.executable, str(ROOT / "tools" / "build_book.py"), "--cache", "--book", str(book),
        "--config", str(config), "--out", str(tmp_path / f"out-{only or 'full'}"), "--jobs", "1",
    ]  # fmt: skip
    if only:
        cmd += ["--only", only]
    return subprocess.run(cmd, cwd=ROOT, env=build_env(tmp_path), capture_output=True, text=True, timeout=600)


def _article(page: Path) -> str:
    """The page's text, without the theme's navigation (which links the neighbouring pages)."""
    html = page.read_text()
    return html[html.index("<article") : html.index("</article>")]


def _outside_count(log: str) -> int | None:
    found = re.search(r"subset build: (\d+) references to what lies outside", log)
    return int(found.group(1)) if found else None


def test_subset_toc_roots_a_chapter_at_its_opening_page_without_front_or_back_matter(tmp_path: Path) -> None:
    """The chapter's pages and the bibliography, nothing that reads every paper's claims."""
    import yaml

    toc = yaml.safe_load(build_book.subset_toc("kzl", ROOT / "book"))
    assert toc["root"] == "kzl/index"
    assert toc["parts"][0]["chapters"] == [{"glob": "kzl/[0-9]*"}, {"file": "bibliography"}]
    pages = build_book.toc_pages(_write(tmp_path / "toc.yml", build_book.subset_toc("kzl")), ROOT / "book")
    rel = [p.relative_to(ROOT / "book").as_posix() for p in pages]
    assert rel[0] == "kzl/index.md" and rel[-1] == "bibliography.md"
    assert all(r.startswith("kzl/") for r in rel[:-1])
    assert not {"intro.md", "ledger.md", "errata.md", "about.md"} & set(rel)


def _write(path: Path, text: str) -> Path:
    path.write_text(text)
    return path


def test_a_subset_build_reads_references_outside_it_as_text_and_the_full_build_links_them(
    tmp_path: Path,
) -> None:
    book, config = _book(tmp_path)
    full = _build(tmp_path, book, config, None)
    assert full.returncode == 0, full.stdout[-3000:] + full.stderr[-3000:]
    assert _outside_count(full.stdout) is None  # the full book never loads the extension
    html = _article(tmp_path / "out-full" / "_build" / "html" / "kzl" / "01-attitude.html")
    assert html.count('href="../wf/01-velocity.html') == 6  # every WF reference is a link

    subset = _build(tmp_path, book, config, "kzl")
    assert subset.returncode == 0, subset.stdout[-3000:] + subset.stderr[-3000:]
    assert _outside_count(subset.stdout) == OUTSIDE, subset.stdout
    html = _article(tmp_path / "out-kzl" / "_build" / "html" / "kzl" / "01-attitude.html")
    assert "../wf/01-velocity.html" not in html
    assert html.count('class="xref-outside-subset"') == OUTSIDE
    assert "The WF page" in html  # a page named without words reads as its title


BROKEN = {  # a reference to nothing, in each kind: the target each warning names
    "{ref}`wf-sektion`": "wf-sektion",  # a label no page defines
    "{doc}`../wf/02-missing`": "02-missing",  # a page that does not exist
    "{py:func}`navcore.units.no_such_function`": "no_such_function",  # an API object that does not exist
    "{py:func}`navcore.units._from_db`": "_from_db",  # a private function: not in the API reference
}


def test_a_reference_to_nothing_fails_the_subset_build_and_the_full_build(tmp_path: Path) -> None:
    book, config = _book(tmp_path, KZL_PAGE.replace("{ref}`wf-section`", " ".join(BROKEN)))
    for only in ("kzl", None):
        proc = _build(tmp_path, book, config, only)
        assert proc.returncode != 0, f"the {only or 'full'} build passed with references to nothing"
        assert "sphinx: FAILED" in proc.stdout
        warnings = [line for line in proc.stderr.splitlines() if "WARNING" in line]
        for target in BROKEN.values():
            assert any(target in line for line in warnings), (only, target, proc.stderr[-3000:])
        if only:  # the references outside the subset that do exist still read as text
            assert _outside_count(proc.stdout) == OUTSIDE - 1
