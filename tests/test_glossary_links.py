"""The glossary extension: first uses of glossary terms link to their entries (HTML and LaTeX)."""

from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXT = ROOT / "book" / "_ext"

spec = importlib.util.spec_from_file_location("book._ext.glossary_links", EXT / "glossary_links.py")
glossary_links = importlib.util.module_from_spec(spec)
sys.modules["glossary_links"] = glossary_links
spec.loader.exec_module(glossary_links)

GLOSSARY = """# Glossary

% glossary-links ignore: consistent

```{glossary}
CEP
circular error probable
  The radius of the circle, centred on the true position, that holds half of the fixes.

Kalman filter
  The recursive linear estimator.

tightly coupled
  Integration that filters pseudoranges.

coupled
  A word that only the longer term should take.

consistent
  A verdict (never linked automatically).
```
"""

PAGE = """# A CEP page

The CEP of the fix is small, and the CEP stays small; a Kalman filter runs.
Kalman filters are everywhere, but `CEP` in code and $CEP$ in math never link.
The tightly coupled filter is consistent with the data; circular error probable is
the same entry as CEP, so it is not linked again.

```{figure} empty.png
A caption with a Kalman filter.
```

| CEP | coupled |
| --- | ------- |
| tightly coupled | x |

- A [link about the CEP](https://example.org) stays a link.
"""

REFERENCE = """# API

The CEP is not linked in the reference part.
"""

INDEX = """# Book

```{toctree}
page
glossary
reference/api
```
"""


def test_ignored_terms_come_from_the_comment_line():
    assert glossary_links.ignored_terms(GLOSSARY) == {"consistent"}
    assert glossary_links.ignored_terms("% glossary-links ignore: a, b c\n") == {"a", "b c"}


def test_glossary_entries_read_term_lines_and_synonyms():
    entries = glossary_links.glossary_entries(GLOSSARY)
    assert entries == [
        ["CEP", "circular error probable"],
        ["Kalman filter"],
        ["tightly coupled"],
        ["coupled"],
        ["consistent"],
    ]


@pytest.mark.parametrize(
    ("term", "text", "match"),
    [
        ("CEP", "the CEP here", "CEP"),
        ("CEP", "the CEPs here", "CEPs"),
        ("CEP", "the cep here", None),  # acronyms keep their case
        ("CEP", "the CEPTRE", None),  # whole words only
        ("Kalman filter", "a Kalman\nfilter", "Kalman\nfilter"),
        ("Kalman filter", "a kalman filter", None),
        ("tightly coupled", "Tightly coupled filters", "Tightly coupled"),
        ("C/N0", "a C/N0 of 40 dB-Hz", "C/N0"),
        ("C/N0", "a C/N01", None),
        ("coupled", "non-coupled", None),
        ("MEMS", "MEMS-grade", None),  # part of a compound word
    ],
)
def test_term_pattern(term, text, match):
    m = glossary_links.term_pattern(term).search(text)
    assert (m.group(0) if m else None) == match


def _project(tmp_path: Path) -> Path:
    src = tmp_path / "src"
    (src / "reference").mkdir(parents=True)
    (src / "index.md").write_text(INDEX)
    (src / "glossary.md").write_text(GLOSSARY)
    (src / "page.md").write_text(PAGE)
    (src / "reference" / "api.md").write_text(REFERENCE)
    # a one-pixel PNG, so that the figure is real in both builders
    png = bytes.fromhex(
        "89504e470d0a1a0a0000000d4948445200000001000000010806000000"
        "1f15c4890000000d4944415478da63f8ffff3f0005fe02fea7d6a4b00000000049454e44ae426082"
    )
    (src / "empty.png").write_bytes(png)
    (src / "conf.py").write_text(
        "import sys\n"
        f"sys.path.insert(0, {str(EXT)!r})\n"
        "extensions = ['myst_parser', 'glossary_links']\n"
        "myst_enable_extensions = ['dollarmath']\n"
        "project = 't'\n"
        "latex_documents = [('index', 't.tex', 't', 'a', 'manual')]\n"
    )
    return src


def _build(src: Path, out: Path, builder: str) -> None:
    """One strict (-W -n) build; SphinxTestApp undoes its node registrations afterwards."""
    from sphinx.testing.util import SphinxTestApp

    app = SphinxTestApp(
        builder,
        srcdir=src,
        builddir=out,
        freshenv=True,
        confoverrides={"nitpicky": True},
        warningiserror=True,
    )
    try:
        app.build(force_all=True)
    finally:
        app.cleanup()


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("glossary")
    src = _project(tmp)
    _build(src, tmp / "out", "html")
    _build(src, tmp / "out", "latex")
    return tmp / "out"


def _links(html: str) -> list[str]:
    return re.findall(r'<a class="reference internal" href="glossary.html#term-([^"]+)">', html)


def test_html_links_only_the_first_use_of_each_entry(built):
    html = (built / "html" / "page.html").read_text()
    # CEP (first of two, not in the title), Kalman filter, tightly coupled; "consistent" is ignored,
    # "circular error probable" is the CEP entry again, "coupled" is inside "tightly coupled"
    assert _links(html) == ["CEP", "Kalman-filter", "tightly-coupled"]
    body = html[html.index("<p>") :]
    assert body.index('href="glossary.html#term-CEP"') < body.index("stays small")
    assert "<code" in html and "CEP</span></code>" in html  # the literal stays code


def test_html_leaves_headings_captions_header_cells_and_links_alone(built):
    html = (built / "html" / "page.html").read_text()
    title = re.search(r"<h1>(.*?)</h1>", html, re.S).group(1)
    caption = re.search(r'<span class="caption-text">(.*?)</span>', html, re.S).group(1)
    thead = re.search(r"<thead>(.*?)</thead>", html, re.S).group(1)
    for fragment in (title, caption, thead):
        assert "glossary.html" not in fragment
    assert '<a class="reference external" href="https://example.org">link about the CEP</a>' in html


def test_html_skips_the_glossary_and_the_reference(built):
    glossary = (built / "html" / "glossary.html").read_text()
    api = (built / "html" / "reference" / "api.html").read_text()
    assert 'class="xref std std-term glossary-link"' not in glossary
    assert "glossary.html#term" not in api


def test_index_has_an_entry_for_each_linked_use(built):
    genindex = (built / "html" / "genindex.html").read_text()
    assert 'href="page.html#index-0"' in genindex
    assert "Kalman filter" in genindex and "tightly coupled" in genindex


def test_latex_resolves_the_links_and_prints_the_index(built):
    tex = (built / "latex" / "t.tex").read_text()
    assert re.search(r"\\hyperref\[\\detokenize\{glossary:term-CEP\}\]", tex)
    assert r"\index{CEP@\spxentry{CEP}" in tex
    assert r"\printindex" in tex


def test_a_build_without_the_glossary_links_nothing(tmp_path):
    """A subset build (the glossary page excluded) stays strict and unlinked."""
    src = _project(tmp_path)
    (src / "index.md").write_text("# Book\n\n```{toctree}\npage\nreference/api\n```\n")
    with (src / "conf.py").open("a") as conf:
        conf.write("exclude_patterns = ['glossary.md']\n")
    _build(src, tmp_path / "out", "html")
    assert "glossary.html" not in (tmp_path / "out" / "html" / "page.html").read_text()
