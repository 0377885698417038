"""The book's tools run in-process on small synthetic inputs (issue 31, mutation testing).

The gates' own tests mostly run them as subprocesses, which mutation testing cannot see; here
each tool is loaded under its dotted name (``tools.check_links``), the name mutmut's
trampolines recognise (tools/mutation.py), and its functions are called directly:

* ``check_links``: every skipped scheme, ``id`` and ``name`` anchors, a broken and a good
  same-page anchor, quoted paths and fragments, folders, the skipped asset folders, ``main``;
* ``ledger_twice``: the two processes' commands and environments, the comparison of their
  exports and the exit status, with a stand-in for ``subprocess.Popen``;
* ``check_numbers``: each pattern's edges, the reader's text (blocks, skipped tags and
  classes, the article's bounds), the skipped pages and ``main``;
* ``rename_claim_ids``: whole-id matching at each boundary character, the aliases line, the
  map's checks, and ``main`` on a small git repository;
* ``check_layout`` (what needs no Chromium): the allowlist's two one-sided cases per kind and
  width, the counted kinds, the page list, the browser lookup, ``main``.

Oracle in each test: the hand-made input and the result written out by hand.
"""

from __future__ import annotations

import asyncio
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests._tools import help_text, load_tool

ROOT = Path(__file__).resolve().parents[1]


_tool = load_tool


check_links = _tool("check_links")
ledger_twice = _tool("ledger_twice")
check_numbers = _tool("check_numbers")
rename_claim_ids = _tool("rename_claim_ids")
check_layout = _tool("check_layout")


def _write(path: Path, text: str | bytes) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    return path


# --- check_links ------------------------------------------------------------------------------


def _page(path: Path, body: str) -> None:
    _write(path, f"<html><body>{body}</body></html>")


def test_links_a_broken_same_page_anchor_is_reported_and_a_good_one_is_not(tmp_path):
    """Oracle: one page linking to its own ``#here`` (present) and ``#nope`` (absent)."""
    _page(tmp_path / "index.html", '<h1 id="here">x</h1><a href="#here">a</a><a href="#nope">b</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: #nope (no such anchor)"]


def test_links_a_same_page_anchor_is_looked_up_on_the_page_itself(tmp_path):
    """Oracle: a chapter page (not its folder's index) whose own anchor exists only there, and
    a page whose missing file comes before a missing anchor: both reported."""
    _page(tmp_path / "wf" / "index.html", '<p id="elsewhere">x</p>')
    _page(tmp_path / "wf" / "a.html", '<p id="here">x</p><a href="#here">a</a><a href="#elsewhere">b</a>')
    _page(tmp_path / "wf" / "b.html", '<a href="gone.html">a</a><a href="#nope">b</a>')
    assert sorted(check_links.broken_links(tmp_path)) == [
        "wf/a.html: #elsewhere (no such anchor)",
        "wf/b.html: #nope (no such anchor)",
        "wf/b.html: gone.html (no such file)",
    ]


def test_links_pages_after_an_asset_folder_are_still_checked(tmp_path):
    """Oracle: ten chapter folders beside ``_static`` and ``_sources``, each page with one
    broken link: all ten reported, whichever folder is read first."""
    _page(tmp_path / "_static" / "s.html", '<a href="gone.html">x</a>')
    _page(tmp_path / "_sources" / "s.html", '<a href="gone.html">x</a>')
    for i in range(10):
        _page(tmp_path / f"c{i}" / "p.html", '<a href="#nope">x</a>')
    assert sorted(check_links.broken_links(tmp_path)) == [
        f"c{i}/p.html: #nope (no such anchor)" for i in range(10)
    ]


def test_links_other_schemes_and_hosts_are_not_followed(tmp_path):
    """Oracle: a link of each skipped scheme, and one to another host, none of them a file."""
    hrefs = [
        "http://x/a.html",
        "https://x/a.html",
        "mailto:someone",
        "data:text",
        "javascript:void",
        "ftp://x/y",
        "//example.org/page.html",
    ]
    _page(tmp_path / "index.html", "".join(f'<a href="{h}">x</a>' for h in hrefs))
    assert check_links.broken_links(tmp_path) == []
    _page(tmp_path / "index.html", '<a href="other:thing">x</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: other:thing (no such file)"]
    _page(tmp_path / "index.html", '<a href="https://x/">x</a><a href="#nope">x</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: #nope (no such anchor)"]


def test_links_name_anchors_quoted_paths_folders_and_files_that_are_not_pages(tmp_path):
    """Oracle: a tree where each link resolves only if its kind of target is understood: a
    ``name=`` anchor, a ``%20`` in the path and in the fragment, a folder's index, a PDF with
    a fragment (not parsed), a page outside the tree; then the same links broken."""
    _page(tmp_path / "a b.html", '<a name="n"></a><p id="x y">t</p>')
    _page(tmp_path / "sub" / "index.html", '<p id="s">t</p>')
    _write(tmp_path / "doc.pdf", b"%PDF")
    _page(tmp_path.parent / f"{tmp_path.name}-outside.html", '<p id="o">o</p>')
    good = [
        "a%20b.html#n",
        "a%20b.html#x%20y",
        "sub/#s",
        "sub",
        "doc.pdf#page=2",
        f"../{tmp_path.name}-outside.html#o",
    ]
    _page(tmp_path / "index.html", "".join(f'<a href="{h}">x</a>' for h in good))
    assert check_links.broken_links(tmp_path) == []
    bad = ["a%20b.html#m", f"../{tmp_path.name}-outside.html#p", "sub/#t", "sub/other.html"]
    _page(tmp_path / "index.html", "".join(f'<a href="{h}">x</a><link href="gone.css">' for h in bad))
    assert check_links.broken_links(tmp_path) == [
        "index.html: a%20b.html#m (no such anchor)",
        f"index.html: ../{tmp_path.name}-outside.html#p (no such anchor)",
        "index.html: sub/#t (no such anchor)",
        "index.html: sub/other.html (no such file)",
    ]


def test_links_in_asset_folders_are_not_checked_but_their_anchors_count(tmp_path):
    """Oracle: broken links inside ``_static`` and ``_sources`` pages are left alone; a page
    linking into ``_static`` finds the anchors there; an empty ``id`` is no anchor."""
    _page(tmp_path / "_static" / "s.html", '<a href="gone.html">x</a><p id="k">k</p>')
    _page(tmp_path / "_sources" / "t.html", '<a href="#gone">x</a>')
    _page(tmp_path / "index.html", '<a href="_static/s.html#k">x</a><a href="#">top</a><p id="">e</p>')
    assert check_links.broken_links(tmp_path) == []
    _page(tmp_path / "index.html", '<a href="_static/s.html#q">x</a><a href="">self</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: _static/s.html#q (no such anchor)"]


def test_links_a_page_that_is_not_utf8_is_read(tmp_path):
    """Oracle: a byte that is not UTF-8 in a page's text is replaced, not an error."""
    _write(tmp_path / "index.html", b'<p id="a">\xff\xfe</p><a href="#a">x</a><a href="#b">y</a>')
    _write(tmp_path / "wf" / "p.html", b'<p>\xff</p><a href="../index.html#a">x</a>')
    assert check_links.broken_links(tmp_path) == ["index.html: #b (no such anchor)"]


def test_links_main_reports_a_missing_book_broken_links_and_a_good_book(tmp_path, monkeypatch, capsys):
    """Oracle: the three exit statuses and their messages, written out by hand."""
    monkeypatch.setattr(sys, "argv", ["check_links.py", str(tmp_path)])
    assert check_links.main() == 2
    assert capsys.readouterr().out == f"no HTML book at {tmp_path}: build it first (nox -s book)\n"
    _page(tmp_path / "index.html", '<a href="#x">x</a><a href="y.html">y</a>')
    _page(tmp_path / "_static" / "z.html", "")
    assert check_links.main() == 1
    assert capsys.readouterr().out == (
        "2 broken internal links in 2 pages:\n"
        "  index.html: #x (no such anchor)\n"
        "  index.html: y.html (no such file)\n"
    )
    _page(tmp_path / "index.html", '<a href="#x" id="x">x</a>')
    assert check_links.main() == 0
    assert capsys.readouterr().out == "internal links: all resolve (2 pages)\n"
    # without an argument: the repository's _build/html
    monkeypatch.setattr(sys, "argv", ["check_links.py"])
    monkeypatch.setattr(check_links, "ROOT", tmp_path / "repo")
    for rel in ("index.html", "wf/a.html", "wf/b.html"):
        _page(tmp_path / "repo" / "_build" / "html" / rel, "")
    assert check_links.main() == 0
    assert capsys.readouterr().out == "internal links: all resolve (3 pages)\n"


# --- ledger_twice -------------------------------------------------------------------------------


class _Runs:
    """A stand-in for ``subprocess.Popen``: records each command and writes its ``--json-out``
    with the text and exit code given for its ``--jobs``, once waited for."""

    def __init__(self, texts: dict[str, str], codes: dict[str, int]):
        self.texts, self.codes, self.started, self.waited = texts, codes, [], []

    def __call__(self, command, env=None, stdout=None):
        runs = self

        class Run:
            def wait(self):
                jobs = command[command.index("--jobs") + 1]
                runs.waited.append(jobs)
                out = Path(command[command.index("--json-out") + 1])
                out.write_text(runs.texts[jobs])
                return runs.codes[jobs]

        self.started.append((command, env, stdout))
        assert not self.waited, "both processes start before either is waited for"
        return Run()


def test_ledger_twice_without_arguments_prints_its_usage(capsys):
    """Oracle: the docstring's usage line."""
    assert ledger_twice.main([]) == 2
    err = capsys.readouterr().err
    usage = "Usage: ``python tools/ledger_twice.py OUT.json [LEDGER ARGS ...]``"
    assert err == usage + " (``nox -s ledger -- --twice``).\n"


def test_ledger_twice_runs_one_serial_and_one_parallel_evaluation(tmp_path, monkeypatch, capsys):
    """Oracle: the two commands and environments written out from the docstring; identical
    exports pass."""
    runs = _Runs({"1": "{}", "2": "{}"}, {"1": 0, "2": 0})
    monkeypatch.setattr(ledger_twice.subprocess, "Popen", runs)
    monkeypatch.setenv("NAVCORE_CACHE", "/somewhere")
    monkeypatch.setenv("NAVCORE_CACHE_REFRESH", "0")
    monkeypatch.setenv("NAVCORE_OTHER", "kept")
    out = tmp_path / "new" / "dir" / "ledger.json"
    assert ledger_twice.main([str(out), "--paper", "WF"]) == 0
    second = tmp_path / "new" / "dir" / "ledger.second.json"
    (c1, env1, out1), (c2, env2, out2) = runs.started
    head = [sys.executable, "-m", "navcore", "ledger", "--jobs"]
    assert c1 == [*head, "1", "--json-out", str(out), "--paper", "WF"]
    assert c2 == [*head, "2", "--json-out", str(second), "--paper", "WF"]
    assert env1["NAVCORE_CACHE_REFRESH"] == "1" and "NAVCORE_CACHE" not in env1
    assert env2["NAVCORE_CACHE"] == "off" and "NAVCORE_CACHE_REFRESH" not in env2
    assert env1["NAVCORE_OTHER"] == env2["NAVCORE_OTHER"] == "kept"
    assert {k: v for k, v in env1.items() if k != "NAVCORE_CACHE_REFRESH"} == {
        k: v for k, v in os.environ.items() if not k.startswith("NAVCORE_CACHE")
    }
    assert out1 is None and out2 == subprocess.DEVNULL
    assert runs.waited == ["1", "2"]
    assert capsys.readouterr().out == (
        f"the ledger evaluated in one process and on two workers wrote identical JSON ({out})\n"
    )


def test_ledger_twice_fails_on_exports_that_differ(tmp_path, monkeypatch, capsys):
    """Oracle: two exports differing by one byte."""
    monkeypatch.setattr(ledger_twice.subprocess, "Popen", _Runs({"1": "{}", "2": "{ }"}, {"1": 0, "2": 0}))
    out = tmp_path / "l.json"
    assert ledger_twice.main([str(out)]) == 1
    second = tmp_path / "l.second.json"
    assert capsys.readouterr().err == f"two evaluations of the ledger differ: {out} and {second}\n"


@pytest.mark.parametrize(("codes", "status"), [((1, 0), 1), ((0, 3), 3), ((2, 3), 2)])
def test_ledger_twice_returns_the_first_failing_process_status(tmp_path, monkeypatch, capsys, codes, status):
    """Oracle: a process's own status, the serial one's first; the exports are not compared."""
    runs = _Runs({"1": "{}", "2": "{}"}, {"1": codes[0], "2": codes[1]})
    monkeypatch.setattr(ledger_twice.subprocess, "Popen", runs)
    assert ledger_twice.main([str(tmp_path / "l.json")]) == status
    assert runs.waited == ["1", "2"]
    assert capsys.readouterr().out == ""


# --- check_numbers ------------------------------------------------------------------------------


def _article(body: str) -> str:
    article = f'<article class="bd-article">{body}</article>'
    return f"<html><body><p>1.00e-04 outside</p>{article}<p>-0</p></body></html>"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("a 1.0E+04 b", [("exponent", "1.0E+04")]),
        ("a −2e−7 b", [("exponent", "−2e−7")]),
        ("a 3e5 b", [("exponent", "3e5")]),
        ("x1e5 v1.2e3 1.2e3x", []),
        ("a −0.12345678 b", [("long decimal", "−0.12345678")]),
        ("a 0.1234567 b 1/0.123456789 x.123456789", []),
        ("a −0 b", [("negative zero", "−0")]),
        ("a -0.0 b", [("negative zero", "-0.0")]),
        ("-01 -0.5 -0×10 x-0 1-0", []),
        ("a 20.0000 b", [("padded", "20.0000")]),
        ("a 9.00000 b", [("padded", "9.00000")]),
        ("0.0000 1.0000 10.000 2.00001 v2.0000", []),
        ("a {'x': 1} b", [("mapping", "{'x': 1")]),
        ('a {"x" : (2 b', [("mapping", '{"x" : (2')]),
        ("a {'x':−2 b", [("mapping", "{'x':−2")]),
        ("a { -1.5: 2} b", [("mapping", "{ -1.5: 2")]),
        ("{x: 1} {1: a}", []),
    ],
)
def test_numbers_each_pattern_and_its_edges(text, expected):
    """Oracle: each pattern's documented cases and the near misses beside them, by hand."""
    found = [(name, match) for name, match, _ in check_numbers.hits(_article(f"<p>{text}</p>"))]
    assert found == expected


def test_numbers_reader_text_keeps_the_articles_blocks_and_drops_code_and_math():
    """Oracle: a page with one element of each skipped tag and class, void tags and block
    tags, and the blocks read by hand."""
    skipped = "".join(
        f"<{tag}>9e9</{tag}>" for tag in ("script", "style", "math", "svg", "button", "mjx-c")
    ) + "".join(
        f'<span class="{c} other">9e9</span>'
        for c in ("cell_input", "math", "headerlink", "sig", "highlight-ipython3")
    )
    body = (
        '<div><h1>Title</h1><p>one <b>two</b><br>three</p><img class="math" src="x.png">after img'
        f"{skipped}<ul><li>four</li></ul><table><tr><th>h</th><td>d1</td><td>d2</td></tr></table>"
        "<dl><dt>t</dt><dd>d</dd></dl><pre>p  re</pre><figure><figcaption>cap</figcaption></figure>"
        "<h2>h2</h2><h3>h3</h3><h4>h4</h4><p>open <em>unclosed</p>tail</div>"
        '<span class="ledger-claims">led</span>'
    )
    html = _article(body) + '<article class="bd-article"><p>second</p></article>'
    expected = [
        "Title", "one two", "three", "after img", "four", "h", "d1", "d2", "t", "d", "p re", "cap",
        "h2", "h3", "h4", "open unclosed", "tail",
    ]  # fmt: skip
    assert check_numbers.reader_text(html) == [*expected, "led", "second"]
    assert check_numbers.reader_text(html, skip_ledger=True) == [*expected, "second"]


def test_numbers_reader_text_entities_inline_elements_and_stray_end_tags():
    """Oracle: a character reference is read as its character (``&minus;0`` is a negative
    zero); an inline element closing does not start a block; a stray end tag before anything
    opened, a skipped element closed at the top level, and an unclosed element inside a
    skipped one closed with it."""
    html = (
        '</div><span class="math">9e9</span><article class="bd-article">'
        '<p>a &minus;0 <b>b</b> c</p><p>x <span class="math">m <b>unclosed</span> 1e-9</p></article>'
    )
    assert check_numbers.reader_text(html) == ["a −0 b c", "x 1e-9"]
    assert [(n, m) for n, m, _ in check_numbers.hits(html)] == [("negative zero", "−0"), ("exponent", "1e-9")]


def test_numbers_reader_text_ends_when_the_articles_container_closes():
    """Oracle: malformed HTML whose ``</div>`` closes the article without ``</article>``; the
    text after the container is not the article's. (Sphinx writes well-formed pages, so the
    book is not affected.)"""
    html = '<div><article class="bd-article"><p>in</p></div><p>after 1e-9</p>'
    assert check_numbers.reader_text(html) == ["in"]


def test_numbers_main_help_describes_the_options(capsys):
    """Oracle: the docstring's first line and the options' help, as written in the tool."""
    out = help_text(check_numbers.main, capsys)
    for text in (
        "Number-format gate on a built HTML book: no number as a program prints it.",
        "html the built HTML book (_build/html)",
        "--summary counts per page and pattern",
        "--without-ledger leave out the ledger's own tables and boxes (elements of class ledger-*)",
    ):
        assert text in out


def test_numbers_reader_text_ends_with_the_article_not_a_nested_one():
    """Oracle: an inner element closing does not end the article; text after it is read, and
    text after the article is not; an ``article`` of another class does not start one."""
    html = (
        '<article class="other"><p>0</p></article>'
        '<div><article class="x bd-article"><section><p>in</p></section>tail</article><p>out</p></div>'
    )
    assert check_numbers.reader_text(html) == ["in", "tail"]


def test_numbers_context_is_thirty_characters_either_side():
    """Oracle: the hit's block cut by hand 30 characters before and after the match."""
    before, after = "a" * 40, "b" * 40
    ((name, match, context),) = check_numbers.hits(_article(f"<p>{before} 1e-9 {after}</p>"))
    assert (name, match) == ("exponent", "1e-9")
    assert context == "a" * 29 + " 1e-9 " + "b" * 29
    ((_, _, short),) = check_numbers.hits(_article("<p>x 1e-9</p>"))
    assert short == "x 1e-9"


def _book(tmp_path: Path) -> Path:
    page = _article("<p>gain 1.00e-04 and -0.0</p>")
    for rel in (
        "reference/api.html",
        "_modules/m.html",
        "_sources/s.html",
        "_static/t.html",
        "_images/i.html",
        "genindex.html",
        "py-modindex.html",
        "search.html",
        "wf/reference/a.html",
        "b.html",
    ):
        _write(tmp_path / rel, page)
    _write(tmp_path / "c.html", _article('<p class="ledger-box">x 1e-3</p>'))
    _write(tmp_path / "d.html", b'<article class="bd-article"><p>\xff 1e-2</p></article>')
    _write(tmp_path / "e.txt", page)
    return tmp_path


def test_numbers_check_skips_pages_that_are_not_the_books_text(tmp_path):
    """Oracle: a book where every page carries hits; the skipped pages' names by hand."""
    root = _book(tmp_path)
    found = check_numbers.check(root)
    assert [(page, name, match) for page, name, match, _ in found] == [
        ("b.html", "exponent", "1.00e-04"),
        ("b.html", "negative zero", "-0.0"),
        ("c.html", "exponent", "1e-3"),
        ("d.html", "exponent", "1e-2"),
        ("wf/reference/a.html", "exponent", "1.00e-04"),
        ("wf/reference/a.html", "negative zero", "-0.0"),
    ]
    assert found[0][3] == "gain 1.00e-04 and -0.0"
    assert found[2][3] == "x 1e-3" and found[3][3] == "\ufffd 1e-2"
    assert [p for p, *_ in check_numbers.check(root, skip_ledger=True)].count("c.html") == 0


def test_numbers_main_lists_hits_or_counts_them(tmp_path, capsys):
    """Oracle: the output lines of both modes and the status, written out by hand."""
    root = _book(tmp_path)
    assert check_numbers.main([str(root), "--without-ledger"]) == 1
    out, err = capsys.readouterr()
    assert out.splitlines()[0] == "b.html: exponent '1.00e-04': ...gain 1.00e-04 and -0.0..."
    assert len(out.splitlines()) == 5
    counts = "(exponent 3, negative zero 2)"
    assert err == f"check_numbers: 5 number(s) printed as a program prints them {counts}\n"
    assert check_numbers.main([str(root), "--summary"]) == 1
    out, err = capsys.readouterr()
    assert out == (
        "   1  exponent        b.html\n"
        "   1  negative zero   b.html\n"
        "   1  exponent        c.html\n"
        "   1  exponent        d.html\n"
        "   1  exponent        wf/reference/a.html\n"
        "   1  negative zero   wf/reference/a.html\n"
    )
    clean = tmp_path / "clean"
    _write(clean / "x.html", _article("<p>1.5</p>"))
    assert check_numbers.main([str(clean)]) == 0
    out, err = capsys.readouterr()
    assert out == "" and err == "check_numbers: 0 number(s) printed as a program prints them (none)\n"


# --- rename_claim_ids ---------------------------------------------------------------------------


@pytest.mark.parametrize("before", ["A", "z", "5", ".", "_", "+", "-"])
def test_rename_an_id_continued_on_the_left_is_not_renamed(before):
    """Oracle: every class of id character before an old id (``_ID_CHARS``)."""
    text = f"{before}KZL-c16\n"
    assert rename_claim_ids.rewrite_text(text) == text


@pytest.mark.parametrize("after", ["A", "z", "0", "_", "+", "-x", "-7", ".a", ".5"])
def test_rename_an_id_continued_on_the_right_is_not_renamed(after):
    """Oracle: a letter, digit, ``_`` or ``+``, or a hyphen or a dot then a letter or digit."""
    text = f"(KZL-c17{after})\n"
    assert rename_claim_ids.rewrite_text(text) == text


@pytest.mark.parametrize(("before", "after"), [("(", ")"), ('"', '"'), (" ", "."), ("/", "- "), ("", "-")])
def test_rename_an_id_between_other_characters_is_renamed(before, after):
    """Oracle: the id, delimited by characters that do not continue an id, replaced."""
    assert rename_claim_ids.rewrite_text(f"{before}KZL-c17{after}") == (
        f"{before}KZL-sec3.6-heading-without-init{after}"
    )


def test_rename_pattern_matches_one_whole_id():
    """Oracle: the pattern built for one old id, applied by hand."""
    pattern = rename_claim_ids._pattern("KZL-c1.5")
    assert pattern.sub("X", "KZL-c1.5 KZL-c1x5 KZL-c1.5-a KZL-c1.5.") == "X KZL-c1x5 KZL-c1.5-a X."


def test_rename_files_outside_a_git_repository_fail(tmp_path, monkeypatch):
    """Oracle: ``git ls-files`` fails outside a repository; the failure is not taken for an
    empty list of files."""
    monkeypatch.setenv("GIT_CEILING_DIRECTORIES", str(tmp_path.parent))
    monkeypatch.setattr(rename_claim_ids, "ROOT", tmp_path)
    with pytest.raises(subprocess.CalledProcessError):
        rename_claim_ids._files()


def test_rename_prose_shorthands_and_every_occurrence_on_a_line():
    """Oracle: :data:`PHRASES` and two ids on one line, replaced by hand."""
    text = "see WF-c2/WF-c3 and (WF-c13-*); KZL-c1, KZL-c1\n"
    assert rename_claim_ids.rewrite_text(text) == (
        "see WF-sec3-tip-position-vs-range and WF-sec3-tip-position-vs-ins and "
        "(WF-sec4d-sigma-l-high-resolution, WF-sec4d-sigma-l-medium-resolution); "
        "KZL-sec1-satellite-aircraft-speed-ratio, KZL-sec1-satellite-aircraft-speed-ratio\n"
    )


def test_rename_the_aliases_line_keeps_the_line_ending_and_only_renamed_ids_get_one():
    """Oracle: ``id=`` lines with Windows and no line endings, an unknown id, an ``aliases``
    line with spaces, and the same lines without ``add_aliases``."""
    text = '\tid="WF-c7-ratio",\r\n  id="WF-new-id",\n  aliases = ("WF-c7-ratio",)\n  id="WF-c8-effective",'
    assert rename_claim_ids.rewrite_text(text, add_aliases=True) == (
        '\tid="WF-eq9-velocity-position-ratio",\r\n\taliases=("WF-c7-ratio",),\r\n'
        '  id="WF-new-id",\n  aliases = ("WF-c7-ratio",)\n'
        '  id="WF-eq9-velocity-error-dominates",  aliases=("WF-c8-effective",),\n'
    )
    assert rename_claim_ids.rewrite_text(text) == (
        '\tid="WF-eq9-velocity-position-ratio",\r\n  id="WF-new-id",\n  aliases = ("WF-c7-ratio",)\n'
        '  id="WF-eq9-velocity-error-dominates",'
    )
    # an id line that is not exactly `id="...",` is renamed without an alias
    assert rename_claim_ids.rewrite_text(
        'x id="KZL-c1",\n id="KZL-c1", y\n id="KZL-c1",X\n', add_aliases=True
    ) == (
        'x id="KZL-sec1-satellite-aircraft-speed-ratio",\n id="KZL-sec1-satellite-aircraft-speed-ratio", y\n'
        ' id="KZL-sec1-satellite-aircraft-speed-ratio",X\n'
    )


@pytest.mark.parametrize(
    ("renames", "message"),
    [
        ({"WF-c1": "WF-sec1-a-b", "WF-c2": "WF-sec1-a-b"}, "two old ids map to the same new id"),
        ({"WF-c1": "WF-c2", "WF-c2": "WF-sec1-a-b"}, "a new id is also an old id"),
        ({"WF-c1": "WF-Sec1-a"}, "new ids must be lower-case words joined by hyphens: ['WF-Sec1-a']"),
        ({"WF-c1": "ATC-sec1-a"}, "new ids must be lower-case words joined by hyphens: ['ATC-sec1-a']"),
        ({"WF-c1": "WF-sec1"}, "new ids must be lower-case words joined by hyphens: ['WF-sec1']"),
        ({"WF-c1": "WF-sec1-a-"}, "new ids must be lower-case words joined by hyphens: ['WF-sec1-a-']"),
        ({"WF-c1": "xWF-sec1-a"}, "new ids must be lower-case words joined by hyphens: ['xWF-sec1-a']"),
    ],
)
def test_rename_the_maps_checks(monkeypatch, renames, message):
    """Oracle: each rule of the map broken once."""
    monkeypatch.setattr(rename_claim_ids, "RENAMES", renames)
    with pytest.raises(SystemExit) as exc:
        rename_claim_ids._check_map()
    assert str(exc.value) == message


def test_rename_the_maps_checks_pass_the_committed_map_and_good_ids(monkeypatch):
    """Oracle: the committed map, and ids of both papers with dotted sections."""
    assert rename_claim_ids._check_map() is None
    monkeypatch.setattr(rename_claim_ids, "RENAMES", {"WF-c1": "WF-sec1.2-a", "KZL-c1": "KZL-fig5-b-c9"})
    assert rename_claim_ids._check_map() is None


def _git_repo(root: Path) -> Path:
    files = {
        "navcore/papers/wf.py": '    Claim(\n        id="WF-c7-ratio",\n        note="WF-c8-effective",\n',
        "navcore/other.py": '    id="WF-c7-ratio",\n',
        "navcore/papers/notes.md": 'id="WF-c7-ratio",\n',
        "book/page.md": "see WF-c7-ratio.\n",
        "book/page.ipynb": '{"source": "KZL-c1"}\n',
        "README.txt": "nothing old\n",
        "data.csv": "WF-c7-ratio\n",
        "tools/rename_claim_ids.py": "WF-c7-ratio\n",
        "tests/test_render_claims.py": "WF-c7-ratio\n",
        "gone.md": "WF-c7-ratio\n",
    }
    for rel, text in files.items():
        _write(root / rel, text)
    env = {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_SYSTEM": os.devnull}
    subprocess.run(["git", "init", "-q"], cwd=root, check=True, env=env)
    subprocess.run(["git", "add", "."], cwd=root, check=True, env=env)
    (root / "gone.md").unlink()  # listed by git, deleted from the work tree
    _write(root / "untracked.md", "WF-c7-ratio\n")
    return root


def test_rename_files_are_the_tracked_text_files_less_the_kept_ones(tmp_path, monkeypatch):
    """Oracle: a small git repository; the files listed by hand."""
    root = _git_repo(tmp_path)
    monkeypatch.setattr(rename_claim_ids, "ROOT", root)
    assert sorted(p.relative_to(root).as_posix() for p in rename_claim_ids._files()) == [
        "README.txt",
        "book/page.ipynb",
        "book/page.md",
        "navcore/other.py",
        "navcore/papers/notes.md",
        "navcore/papers/wf.py",
    ]


def test_rename_main_checks_then_rewrites_then_checks_clean(tmp_path, monkeypatch, capsys):
    """Oracle: a small git repository with old ids; ``--check`` lists the files and rewrites
    nothing, a run rewrites them (aliases in the papers' modules only), a second check passes."""
    root = _git_repo(tmp_path)
    monkeypatch.setattr(rename_claim_ids, "ROOT", root)
    before = {p: p.read_text() for p in root.rglob("*") if p.is_file() and ".git" not in p.parts}
    assert rename_claim_ids.main(["--check"]) == 1
    out = capsys.readouterr().out.splitlines()
    referenced = ["book/page.ipynb", "book/page.md", "navcore/other.py", "navcore/papers/notes.md"]
    referenced.append("navcore/papers/wf.py")
    assert sorted(out) == [f"old claim id still referenced: {p}" for p in referenced]
    assert {p: p.read_text() for p in before} == before
    assert rename_claim_ids.main([]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[-1] == "5 files changed" and len(out) == 6
    assert "rewrote navcore/papers/wf.py" in out
    assert (root / "navcore/papers/wf.py").read_text() == (
        '    Claim(\n        id="WF-eq9-velocity-position-ratio",\n        aliases=("WF-c7-ratio",),\n'
        '        note="WF-eq9-velocity-error-dominates",\n'
    )
    assert (root / "navcore/other.py").read_text() == '    id="WF-eq9-velocity-position-ratio",\n'
    assert (root / "navcore/papers/notes.md").read_text() == 'id="WF-eq9-velocity-position-ratio",\n'
    assert (root / "book/page.ipynb").read_text() == '{"source": "KZL-sec1-satellite-aircraft-speed-ratio"}\n'
    for kept in ("data.csv", "tools/rename_claim_ids.py", "tests/test_render_claims.py", "untracked.md"):
        assert (root / kept).read_text() == "WF-c7-ratio\n"
    assert rename_claim_ids.main(["--check"]) == 0
    assert capsys.readouterr().out == ""
    assert rename_claim_ids.main([]) == 0
    assert capsys.readouterr().out == "0 files changed\n"


def test_rename_main_refuses_a_bad_map(tmp_path, monkeypatch):
    """Oracle: a map with a duplicate new id stops the run before any file is read."""
    monkeypatch.setattr(rename_claim_ids, "ROOT", tmp_path)  # not a git repository
    monkeypatch.setattr(rename_claim_ids, "RENAMES", {"WF-c1": "WF-sec1-a-b", "WF-c2": "WF-sec1-a-b"})
    with pytest.raises(SystemExit, match="same new id"):
        rename_claim_ids.main(["--check"])


# --- check_layout -------------------------------------------------------------------------------


def _item(name: str, scroll: int = 500, client: int = 388, text: str = "x") -> tuple[str, dict]:
    return name, {"name": name.split("#")[1], "scroll": scroll, "client": client, "text": text}


@pytest.fixture
def layout(monkeypatch, tmp_path):
    """check_layout with its allowlist in ``tmp_path`` and a stand-in measurement: returns the
    dictionary the stand-in reports (width -> kind -> items) and the calls it received."""
    allow = tmp_path / "allow.json"
    monkeypatch.setattr(check_layout, "ALLOWLIST", allow)
    found: dict = {}
    calls: list = []

    def measure(root, widths, tabs=None):
        calls.append((root, widths, tabs))
        return found

    monkeypatch.setattr(check_layout, "measure", measure)
    return allow, found, calls


@pytest.mark.parametrize("kind", ["math", "table", "cell", "word"])
def test_layout_each_kind_fails_on_an_unlisted_overflow_and_on_a_stale_entry(layout, kind, capsys):
    """Oracle: per kind, one overflow listed, one not, and two listed entries that no longer
    overflow (reported in sorted order); the lines written out by hand."""
    allow, found, calls = layout
    listed = {"a.html#one": "why", "z.html#gone": "why", "b.html#gone": "why"}
    allow.write_text(json.dumps({"420": {kind: listed}}))
    found[420] = {kind: [_item("a.html#one"), _item("c.html#two", 600, 400, "wide")]}
    problems = check_layout.check(Path("book"), (420,), tabs=3)
    assert calls == [(Path("book"), (420,), 3)]
    assert problems == [
        f"420 px: {kind} c.html#two is 600 px in a 400 px box: wide",
        f"420 px: {kind} b.html#gone is in the allowlist but no longer overflows: remove it",
        f"420 px: {kind} z.html#gone is in the allowlist but no longer overflows: remove it",
    ]
    err = capsys.readouterr().err
    assert f"check_layout: 420 px: 2 overflowing {kind} (3 allowed)\n" in err


def test_layout_the_allowlist_is_per_width_and_per_kind(layout, capsys):
    """Oracle: an entry allowed at 420 px for tables does not allow it at 1400 px nor as math;
    a missing allowlist allows nothing; the default widths are measured."""
    allow, found, calls = layout
    found[1400] = {"table": [_item("a.html#t")], "math": []}
    found[420] = {"table": [_item("a.html#t")], "math": [_item("a.html#t")]}
    assert len(check_layout.check(Path("."), (1400, 420))) == 3
    allow.write_text(json.dumps({"420": {"table": {"a.html#t": "why"}}}))
    assert check_layout.check(Path("."), (1400, 420)) == [
        "1400 px: table a.html#t is 500 px in a 388 px box: x",
        "420 px: math a.html#t is 500 px in a 388 px box: x",
    ]
    found.clear()
    found.update({w: {} for w in check_layout.WIDTHS})
    assert check_layout.check(Path(".")) == [
        "420 px: table a.html#t is in the allowlist but no longer overflows: remove it"
    ]
    assert calls[-1] == (Path("."), check_layout.WIDTHS, check_layout.TABS)
    err = capsys.readouterr().err
    assert "check_layout: 1400 px: 0 overflowing math (0 allowed)" in err
    assert "check_layout: 420 px: 0 overflowing table (1 allowed)" in err


def test_layout_smaller_is_counted_and_a_cut_inline_formula_is_a_problem(layout, capsys):
    """Oracle: two equations set smaller (the smallest at 72 %): no problem, one summary line,
    each named only with ``list_all``. A formula cut in a box outside a claim table is a
    problem unless the allowlist names it, like an overflowing display equation."""
    allow, found, _ = layout
    smaller = [("a.html#e1", {"scale": 0.9}), ("b.html#e2", {"scale": 0.72})]
    inline = [_item("c.html#p-inline-math-1", 300, 200)]
    found[420] = {"smaller": smaller, "inline": inline, "math": [_item("a.html#m")]}
    allow.write_text(json.dumps({"420": {"math": {"a.html#m": "why"}}}))
    assert check_layout.check(Path("."), (420,)) == [
        "420 px: inline c.html#p-inline-math-1 is 300 px in a 200 px box: x"
    ]
    out, err = capsys.readouterr()
    assert out == ""
    assert "check_layout: 420 px: 2 display equation(s) set smaller to fit (smallest at 72 %)\n" in err
    assert "check_layout: 420 px: 1 overflowing inline (0 allowed)\n" in err
    allow.write_text(
        json.dumps({"420": {"math": {"a.html#m": "why"}, "inline": {"c.html#p-inline-math-1": "why"}}})
    )
    assert check_layout.check(Path("."), (420,), list_all=True) == []
    out, _ = capsys.readouterr()
    assert out.splitlines() == [
        "420 px: smaller a.html#e1 at 90 %",
        "420 px: smaller b.html#e2 at 72 %",
        "420 px: math a.html#m is 500 px in a 388 px box: x",
        "420 px: inline c.html#p-inline-math-1 is 300 px in a 200 px box: x",
    ]
    found[420] = {}
    assert check_layout.check(Path("."), (420,)) == [
        "420 px: math a.html#m is in the allowlist but no longer overflows: remove it",
        "420 px: inline c.html#p-inline-math-1 is in the allowlist but no longer overflows: remove it",
    ]
    assert "smaller" not in capsys.readouterr().err


def test_layout_pages_leave_out_assets_indexes_and_redirects(tmp_path):
    """Oracle: a tree with one page of each skipped kind; the measured pages by hand. A
    redirect is recognised in a page's first 2000 characters only."""
    for rel in ("_modules/m.html", "_sources/s.html", "_static/t.html", "_images/i.html"):
        _write(tmp_path / rel, "<p>x</p>")
    for rel in ("genindex.html", "py-modindex.html", "search.html", "reference/api.html"):
        _write(tmp_path / rel, "<p>x</p>")
    _write(tmp_path / "index.html", '<meta http-equiv="Refresh" content="0; url=b.html">')
    _write(tmp_path / "late.html", "x" * 1981 + 'http-equiv="Refresh"')  # ends at character 2001
    _write(tmp_path / "odd.html", b"\xff<p>x</p>")
    _write(tmp_path / "b.html", "<p>x</p>")
    _write(tmp_path / "b.txt", "<p>x</p>")
    names = [p.relative_to(tmp_path).as_posix() for p in check_layout.pages(tmp_path)]
    assert names == ["b.html", "late.html", "odd.html", "reference/api.html"]


def test_layout_measure_all_reports_every_kind_by_page_and_width(tmp_path, monkeypatch):
    """Oracle: a stand-in browser reporting one item of each kind per page and width; the
    gathered names by hand, in page order, with every tab closed and one tab per page when
    there are fewer pages than tabs."""
    for name in ("a", "b", "c"):
        _write(tmp_path / "wf" / f"{name}.html", "<p>x</p>")
    log: list = []

    class StandIn:
        def __init__(self, executable):
            log.append(("start", executable))

        async def connect(self):
            log.append("connect")

        async def open_tab(self):
            log.append("tab")
            return "tab"

        async def measure(self, session, url, widths):
            assert session == "tab"
            log.append(url)
            if url.endswith("c.html"):  # a page that reports no kind at all
                return {w: {} for w in widths}
            return {w: {k: [{"name": f"{k}-{w}"}] for k in check_layout.KINDS} for w in widths}

        def close(self):
            log.append("close")

    monkeypatch.setattr(check_layout, "Browser", StandIn)
    monkeypatch.setattr(check_layout, "find_browser", lambda: "/bin/chromium")
    found = check_layout.measure(tmp_path, (1400, 420), tabs=4)
    urls = [(tmp_path / "wf" / f"{p}.html").resolve().as_uri() for p in "abc"]
    assert log[:5] == [("start", "/bin/chromium"), "connect", "tab", "tab", "tab"]
    assert sorted(log[5:-1]) == urls and log[-1] == "close"
    assert set(found) == {1400, 420}
    for w in (1400, 420):
        assert set(found[w]) == set(check_layout.KINDS)
        for kind in check_layout.KINDS:
            assert [n for n, _ in found[w][kind]] == [f"wf/{p}.html#{kind}-{w}" for p in "ab"]
            assert found[w][kind][0][1] == {"name": f"{kind}-{w}"}
    log.clear()
    check_layout.measure(tmp_path, (420,), tabs=0)
    assert log.count("tab") == 1


def test_layout_a_page_not_measured_in_time_fails_the_gate(tmp_path, monkeypatch):
    """Oracle: a stand-in browser that never answers, with the time limit made tiny; the
    browser is still closed."""
    _write(tmp_path / "a.html", "<p>x</p>")
    closed = []

    class Hanging:
        def __init__(self, executable):
            pass

        async def connect(self):
            pass

        async def open_tab(self):
            return "tab"

        async def measure(self, session, url, widths):
            await asyncio.sleep(2)

        def close(self):
            closed.append(True)

    monkeypatch.setattr(check_layout, "Browser", Hanging)
    monkeypatch.setattr(check_layout, "find_browser", lambda: "chromium")
    monkeypatch.setattr(check_layout, "PAGE_TIMEOUT", 0.05)
    with pytest.raises(SystemExit) as exc:
        check_layout.measure(tmp_path, (420,), tabs=1)
    assert str(exc.value) == f"check_layout: {tmp_path / 'a.html'} was not measured within 0.05 s"
    assert closed == [True]


def test_layout_find_browser_takes_the_first_on_the_path(monkeypatch):
    """Oracle: a stand-in ``which`` knowing only some of the names."""
    known = {"chromium-browser": "/usr/bin/chromium-browser", "google-chrome": "/opt/chrome"}
    monkeypatch.setattr(check_layout.shutil, "which", known.get)
    assert check_layout.find_browser() == "/usr/bin/chromium-browser"
    monkeypatch.setattr(check_layout.shutil, "which", {"google-chrome": "/opt/chrome"}.get)
    assert check_layout.find_browser() == "/opt/chrome"


def test_layout_find_browser_without_chromium_names_the_install_command(monkeypatch):
    """Oracle: not root, or no apt-get: the message with the command; nothing is run."""
    ran = []
    monkeypatch.setattr(check_layout.subprocess, "run", lambda *a, **k: ran.append(a))
    monkeypatch.setattr(check_layout.shutil, "which", lambda name: None)
    monkeypatch.setattr(check_layout.os, "geteuid", lambda: 1000)
    message = "check_layout: Chromium is needed; install it with:\n    sudo apt-get install -y "
    message += "--no-install-recommends chromium"
    with pytest.raises(SystemExit) as exc:
        check_layout.find_browser()
    assert str(exc.value) == message
    monkeypatch.setattr(check_layout.os, "geteuid", lambda: 0)
    with pytest.raises(SystemExit) as exc:  # root, but no apt-get
        check_layout.find_browser()
    assert str(exc.value) == message
    assert ran == []


def test_layout_find_browser_as_root_installs_chromium_with_apt(monkeypatch):
    """Oracle: root with apt-get: ``apt-get update`` then the install, non-interactive, then
    Chromium found; if it is still missing, the message."""
    ran = []
    installed = {"apt-get": "/usr/bin/apt-get"}
    monkeypatch.delenv("DEBIAN_FRONTEND", raising=False)

    def run(command, check=False, env=None):
        ran.append((command, check, env["DEBIAN_FRONTEND"], env.get("PATH")))
        if "install" in command:
            installed["chromium"] = "/usr/bin/chromium"

    monkeypatch.setattr(check_layout.subprocess, "run", run)
    monkeypatch.setattr(check_layout.shutil, "which", lambda name: installed.get(name))
    monkeypatch.setattr(check_layout.os, "geteuid", lambda: 0)
    assert check_layout.find_browser() == "/usr/bin/chromium"
    path = os.environ.get("PATH")
    assert ran == [
        (["apt-get", "update", "-qq"], True, "noninteractive", path),
        (["apt-get", "install", "-y", "--no-install-recommends", "chromium"], True, "noninteractive", path),
    ]
    installed.pop("chromium")
    monkeypatch.setattr(check_layout.subprocess, "run", lambda *a, **k: None)
    with pytest.raises(SystemExit, match="Chromium is needed"):
        check_layout.find_browser()


def test_layout_main_passes_its_options_and_prints_the_problems(monkeypatch, capsys):
    """Oracle: a stand-in ``check``; the arguments it receives and the output, by hand."""
    calls = []
    result: list[str] = []

    def check(root, widths, list_all, tabs):
        calls.append((root, widths, list_all, tabs))
        return result

    monkeypatch.setattr(check_layout, "check", check)
    assert check_layout.main(["book"]) == 0
    assert calls[-1] == (Path("book"), (1400, 420), False, 4)
    assert capsys.readouterr() == ("", "check_layout: 0 problem(s)\n")
    result += ["p1", "p2"]
    assert check_layout.main(["b", "--width", "420", "--width", "800", "--list", "--tabs", "1"]) == 1
    assert calls[-1] == (Path("b"), (420, 800), True, 1)
    assert capsys.readouterr() == ("p1\np2\n", "check_layout: 2 problem(s)\n")
    with pytest.raises(SystemExit) as exc:
        check_layout.main(["b", "--tabs", "0"])
    assert exc.value.code == 2
    assert "--tabs must be at least 1, not 0" in capsys.readouterr().err


# --- check_layout's browser, over a stand-in DevTools connection ---------------------------------


class _DevTools:
    """A stand-in for Chromium's DevTools websocket: answers each command as Chromium would
    (a target, a session, a page load's events, a measurement naming the viewport's width)
    and records what was sent."""

    def __init__(self) -> None:
        self.incoming: asyncio.Queue = asyncio.Queue()
        self.sent: list[dict] = []
        self.width = 0
        self.closed = False

    def answer(self, data: dict) -> None:
        self.incoming.put_nowait(json.dumps(data))

    def write_message(self, text: str) -> None:
        msg = json.loads(text)
        self.sent.append(msg)
        ident, method, session = msg["id"], msg["method"], msg.get("sessionId")
        if method == "Target.createTarget":
            self.answer({"id": ident, "result": {"targetId": "T1"}})
        elif method == "Target.attachToTarget":
            self.answer({"id": ident, "result": {"sessionId": "S1"}})
        elif method == "Emulation.setDeviceMetricsOverride":
            self.width = msg["params"]["width"]
            self.answer({"id": ident})
        elif method == "Page.navigate":
            self.answer({"id": ident, "result": {"frameId": "F"}})
            self.answer({"id": 999, "result": {}})  # a reply nobody waits for
            self.answer({"method": "Page.loadEventFired", "sessionId": "other"})  # another tab's
            self.answer({"method": "Page.frameNavigated", "sessionId": session})
            self.answer({"method": "Page.loadEventFired", "sessionId": session})
        elif method == "Runtime.evaluate":
            value = json.dumps({"math": [self.width]}) if self.width != 13 else None
            if self.width == 14:  # an answer without a result
                self.answer({"id": ident})
            else:
                self.answer({"id": ident, "result": {"result": {"value": value}}})
        elif method == "Broken.method":
            self.answer({"id": ident, "error": {"message": "no such method"}})
        else:
            self.answer({"id": ident, "result": {"ok": method}})

    async def read_message(self):
        return await self.incoming.get()

    def close(self) -> None:
        self.closed = True


async def _connected(monkeypatch) -> tuple:
    ws = _DevTools()
    seen = []

    async def websocket_connect(url, max_message_size=None):
        seen.append((url, max_message_size))
        return ws

    monkeypatch.setattr("tornado.websocket.websocket_connect", websocket_connect)
    browser = check_layout.Browser.__new__(check_layout.Browser)
    browser.browser_ws = "ws://127.0.0.1:1/devtools/browser/x"
    browser.ids, browser.pending, browser.events = 0, {}, {}
    await browser.connect()
    assert seen == [("ws://127.0.0.1:1/devtools/browser/x", 1 << 26)]
    return browser, ws


def test_layout_browser_calls_are_matched_to_their_replies(monkeypatch):
    """Oracle: the DevTools protocol's message shapes (an id per command, ``sessionId`` for a
    tab's commands, an ``error`` raised), against the stand-in connection."""

    async def run():
        browser, ws = await _connected(monkeypatch)
        assert await browser.call("Any.thing") == {"ok": "Any.thing"}
        assert await browser.call("Any.other", {"a": 1}, "S9") == {"ok": "Any.other"}
        assert ws.sent == [
            {"id": 1, "method": "Any.thing", "params": {}},
            {"id": 2, "method": "Any.other", "params": {"a": 1}, "sessionId": "S9"},
        ]
        with pytest.raises(RuntimeError) as exc:
            await browser.call("Broken.method")
        assert str(exc.value) == "Broken.method: {'message': 'no such method'}"
        assert await browser.call("Emulation.setDeviceMetricsOverride", {"width": 5}) == {}
        assert browser.pending == {}
        # the connection closed: a command still waiting fails, the reader ends
        pending = asyncio.get_running_loop().create_future()
        browser.pending[50] = pending
        done = asyncio.get_running_loop().create_future()
        done.set_result({})
        browser.pending[51] = done
        ws.incoming.put_nowait(None)
        await browser.reader
        assert str(pending.exception()) == "check_layout: Chromium closed the connection"

    asyncio.run(asyncio.wait_for(run(), 5))  # a mutant that hangs fails in 5 s


def test_layout_browser_opens_a_tab_and_measures_a_page_at_each_width(monkeypatch):
    """Oracle: the commands a measurement sends (the viewport at each width, one navigation,
    one evaluation per width) and the stand-in's answers; a tab's stale events are dropped
    before the navigation, and an evaluation without a value fails."""

    async def run():
        browser, ws = await _connected(monkeypatch)
        session = await browser.open_tab()
        assert session == "S1" and set(browser.events) == {"S1"}
        assert [(m["method"], m["params"], m.get("sessionId")) for m in ws.sent] == [
            ("Target.createTarget", {"url": "about:blank", "newWindow": True}, None),
            ("Target.attachToTarget", {"targetId": "T1", "flatten": True}, None),
            ("Page.enable", {}, "S1"),
        ]
        ws.sent.clear()
        browser.events["S1"].put_nowait({"method": "Page.loadEventFired"})  # the previous page's
        got = await browser.measure("S1", "file:///a.html", (1400, 420))
        assert got == {1400: {"math": [1400]}, 420: {"math": [420]}}
        assert browser.events["S1"].empty()
        methods = [m["method"] for m in ws.sent]
        assert methods == [
            "Emulation.setDeviceMetricsOverride",
            "Page.navigate",
            "Runtime.evaluate",
            "Emulation.setDeviceMetricsOverride",
            "Runtime.evaluate",
        ]
        assert ws.sent[0]["params"] == {
            "width": 1400,
            "height": 1200,
            "deviceScaleFactor": 1,
            "mobile": False,
        }
        assert ws.sent[1]["params"] == {"url": "file:///a.html"}
        assert ws.sent[2]["params"] == {
            "expression": check_layout.MEASURE,
            "awaitPromise": True,
            "returnByValue": True,
            "timeout": 60000,
        }
        assert all(m["sessionId"] == "S1" for m in ws.sent)
        with pytest.raises(RuntimeError, match=r"^file:///b.html at 13 px: measurement failed: "):
            await browser.measure("S1", "file:///b.html", (13,))
        with pytest.raises(RuntimeError, match=r"^file:///c.html at 14 px: measurement failed: \{\}$"):
            await browser.measure("S1", "file:///c.html", (14,))
        browser.reader.cancel()

    asyncio.run(asyncio.wait_for(run(), 5))  # a mutant that hangs fails in 5 s


class _Chromium:
    """A stand-in for the Chromium process: its log announces the DevTools endpoint (or not)."""

    def __init__(self, log: str, hangs: bool = False):
        import io

        self.stderr = io.StringIO(log)
        self.hangs, self.calls = hangs, []

    def terminate(self):
        self.calls.append("terminate")

    def kill(self):
        self.calls.append("kill")

    def wait(self, timeout=None):
        self.calls.append(("wait", timeout))
        if self.hangs and timeout is not None:
            raise subprocess.TimeoutExpired("chromium", timeout)
        return 0


def test_layout_browser_starts_chromium_and_closes_everything(monkeypatch):
    """Oracle: the command line the docstring describes, the endpoint read from Chromium's
    log, and on closing: the socket, then the process (killed if it does not end), then its
    profile folder."""
    started = []
    log = "some line\nDevTools listening on ws://127.0.0.1:9/devtools/browser/abc\nlater line\n"

    def popen(command, stdout=None, stderr=None, text=None):
        started.append((command, stdout, stderr, text))
        return _Chromium(log, hangs=True)

    monkeypatch.setattr(check_layout.subprocess, "Popen", popen)
    browser = check_layout.Browser("/bin/chromium")
    ((command, stdout, stderr, text),) = started
    assert command[0] == "/bin/chromium" and command[-1] == "about:blank"
    for flag in ("--headless", "--no-sandbox", "--hide-scrollbars", "--remote-debugging-port=0"):
        assert flag in command
    assert f"--user-data-dir={browser.profile}" in command
    assert (stdout, stderr, text) == (subprocess.DEVNULL, subprocess.PIPE, True)
    assert browser.browser_ws == "ws://127.0.0.1:9/devtools/browser/abc"
    assert (browser.ids, browser.pending, browser.events) == (0, {}, {})
    assert Path(browser.profile).is_dir() and Path(browser.profile).name.startswith("navcore-layout-")
    # Chromium's log is read to its end in the background, by a thread that does not keep
    # the gate alive
    assert browser._drain.daemon is True
    browser._drain.join(5)
    assert browser.proc.stderr.tell() == len(log)

    class Stream:
        closed = False

        def close(self):
            Stream.closed = True

    ws = _DevTools()
    ws.protocol = type("Protocol", (), {"stream": Stream()})()
    browser.ws = ws

    class Reader:
        cancelled = False

        def cancel(self):
            Reader.cancelled = True

    browser.reader = Reader()
    browser.close()
    assert ws.closed and Stream.closed and Reader.cancelled
    assert browser.proc.calls == ["terminate", ("wait", 10), "kill", ("wait", None)]
    assert browser.proc.stderr.closed
    assert not Path(browser.profile).exists()
    assert not browser._drain.is_alive()


def test_layout_browser_that_announces_no_endpoint_fails(monkeypatch):
    """Oracle: a Chromium whose log never names its DevTools endpoint."""
    monkeypatch.setattr(check_layout.subprocess, "Popen", lambda *a, **k: _Chromium("no endpoint\n"))
    with pytest.raises(SystemExit) as exc:
        check_layout.Browser("chromium")
    assert str(exc.value) == "check_layout: Chromium did not start its DevTools endpoint"


def test_layout_browser_closes_without_a_connection(monkeypatch):
    """Oracle: a browser closed before it connected ends its process, which ends in time; a
    profile folder already gone is no error."""
    log = "DevTools listening on ws://h/x\n"
    monkeypatch.setattr(check_layout.subprocess, "Popen", lambda *a, **k: _Chromium(log))
    browser = check_layout.Browser("chromium")
    import shutil

    shutil.rmtree(browser.profile)
    browser.close()
    assert browser.proc.calls == ["terminate", ("wait", 10)]


@pytest.mark.parametrize("protocol", [None, object()])
def test_layout_browser_closes_a_connection_without_a_socket_to_close(monkeypatch, protocol):
    """Oracle: a connection object without a protocol, or whose protocol has no stream (as
    tornado's after the connection failed), is closed without error."""
    monkeypatch.setattr(
        check_layout.subprocess, "Popen", lambda *a, **k: _Chromium("DevTools listening on ws://h\n")
    )
    browser = check_layout.Browser("chromium")
    browser.ws = _DevTools()
    if protocol is not None:
        browser.ws.protocol = protocol
    browser.reader = type("Reader", (), {"cancel": lambda self: None})()
    browser.close()
    assert browser.ws.closed


def test_layout_main_help_describes_the_options(capsys):
    """Oracle: the docstring's first line and the options' help, as written in the tool."""
    out = help_text(check_layout.main, capsys)
    for text in (
        "Layout gate on a built HTML book, measured in headless Chromium: nothing a reader must",
        "html the built HTML book (_build/html)",
        "--width WIDTH px (default: 1400 and 420)",
        "--list print every overflow, allowed or not",
        "--tabs TABS pages measured at once (default: 4)",
    ):
        assert text in out
