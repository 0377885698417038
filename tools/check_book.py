"""Release gates on a built book: what a reader sees, and that two builds are the same.

Usage::

    python tools/check_book.py pages book              # helpers in shown code cells of the pages
    python tools/check_book.py html _build/html        # helpers in code cells; notebook outputs
    python tools/check_book.py numbers _build/html     # numbers as a program prints them
    python tools/check_book.py latex _build/latex      # overfull boxes; helpers in code listings
    python tools/check_book.py same BUILD_A BUILD_B    # byte-identical trees (PDF: up to its dates)

``pages``: no code cell whose source a reader sees (not ``remove-cell`` or ``remove-input``)
holds a build helper (``HELPERS``); the pages keep them in hidden cells, so that the code
shown is the code the downloaded notebook runs.
``html``: no rendered code cell shows a build helper (``glue(...)``, ``show_figure``,
``book.setup()``, ``%matplotlib``); every downloadable notebook under ``_sources`` is
executed (each code cell has an execution count), carries outputs and names the build that
made it (``navcore_provenance`` in its metadata, with the commit and the lock's hash); and no library
identifier stands in running prose (see ``prose_identifiers``): a dotted ``navcore.`` path,
a snake_case name or a call such as ``name()`` in the text of a paragraph, list item,
definition, table cell, caption or admonition, outside code, links, math, cell outputs and
claim tables, on every page but the API reference and the generated ones.
It also finds developer wording in anything a reader sees or downloads (see
``DEVELOPER_WORDING``): a claim's change history ("Verdict changed from ..."), the regression pin
``expected_status``, or test and oracle bookkeeping, in the text and the embedded data of
every page but the API reference and in the downloadable notebooks' outputs.
It also finds formulas shown as LaTeX source (see ``check_plain_math``): a LaTeX command
(``\\frac``, ``\\mathbf``) or a braced sub- or superscript (``_{n-1}``) outside the math a
reader sees typeset, in the text of every page but the API reference (a quote of the paper in a
claim row or the ledger, a table, a caption), and in the text fields of the ledger's embedded
records, which its JSON and CSV downloads carry (``printed``, ``quantity``, ``note``).
And it finds formulas shown as program text (see ``check_plain_text_math``): the plain-text math
patterns the ledger's own texts are held to (a power ``m^3/s^2``, a flat subscript ``tau_c``, a
Greek letter spelled out, e-notation, ``sqrt(``, literal ``**``), in the text of every page but
the API reference, outside math, code and a cell's printed output (``PLAIN_TEXT_ALLOWED`` lists
the few a page may show, each with its reason).
``numbers``: no number as a program prints it (``1.00e-04``, ``1.6344416666666666``,
``-0.000``, ``60.000000``, a printed dictionary; see ``tools/check_numbers.py``) in the text a
reader sees. Part of ``html`` too.
``latex``: the LaTeX log reports no overfull box wider than ``--max-overfull`` points, and
no code listing shows a build helper.
``same``: every file of the two trees is byte-identical, except that PDFs are compared
without their creation and modification dates and document id.

Exit status 1 and one line per problem when a gate fails.
"""

from __future__ import annotations

import argparse
import html
import json
import re
import sys
from fnmatch import fnmatch
from html.parser import HTMLParser
from pathlib import Path

#: A build helper: bookkeeping a page needs to run on its own but that teaches the reader
#: nothing (glue, a registered figure, the book's setup, the matplotlib magic, glue's import).
#: Pages keep these in hidden cells (``remove-cell``, or ``remove-input`` when they display
#: something); the one pattern for the gates on the pages, the HTML and the LaTeX.
HELPERS = re.compile(
    r"(?m)^\s*(?:(?:\w+\s*=\s*)?(?:book\.)?show_figure\s*\(|glue\s*\(|book\.setup\s*\(|%matplotlib\b"
    r"|from\s+(?:myst_nb|navcore\.book)\s+import\s+glue\b)"
)
#: A code cell of a page (a MyST notebook): its tags and its source.
CODE_CELL = re.compile(
    r"^```\{code-cell\}[^\n]*\n(?::tags:\s*\[([^\]\n]*)\]\n)?(.*?)^```[ \t]*$", re.M | re.S
)
#: Tags that hide a cell's source from the reader (``hide-input`` only folds it: still shown).
HIDDEN_SOURCE = {"remove-cell", "remove-input"}
PROVENANCE_KEY = "navcore_provenance"  # book/_ext/book_downloads.py writes it
CELL_PRE = re.compile(
    r'class="cell_input[^"]*"[^>]*>\s*<div class="highlight-[^"]*"><div class="highlight"><pre>(.*?)</pre>',
    re.S,
)
OVERFULL = re.compile(r"^Overfull \\hbox \((\d+(?:\.\d+)?)pt too wide\)(.*)$", re.M)
VERBATIM = re.compile(r"\\begin\{sphinxVerbatim\}.*?\n(.*?)\\end\{sphinxVerbatim\}", re.S)


def _text(fragment: str) -> str:
    return html.unescape(re.sub(r"<[^>]+>", "", fragment))


# --- library identifiers in running prose -------------------------------------------------

IDENTIFIER = re.compile(
    r"\bnavcore(?:\.[A-Za-z_]\w*)+"  # a dotted path into the library
    r"|\b[A-Za-z_][\w.]*\((?:\.\.\.)?\)"  # a call: name() or name(...)
    r"|\b\w*[A-Za-z]_[A-Za-z]\w*"  # snake_case: an underscore between letters
)
# the text of these elements is running prose
PROSE_TAGS = {"p", "li", "dd", "td", "figcaption"}
# nothing inside these is prose: code blocks, links, math, and what a program printed. Inline
# code in a sentence is prose: a library name set in code type still stands in the text
SKIP_TAGS = {"pre", "kbd", "samp", "tt", "var", "a", "script", "style", "svg", "math", "th", "button"}
SKIP_CLASSES = {"math", "cell_output", "output", "output_area", "highlight", "headerlink", "sig"}
VOID_TAGS = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "wbr"}
# pages that are not prose: the API reference (its how-to guides are), generated indexes,
# highlighted sources, search
NOT_PROSE = re.compile(
    r"^(?:reference/(?!howto/)|_modules/|_sources/|_static/|_images/|genindex|py-modindex|search\.html)"
)


class _ProseText(HTMLParser):
    """Collects the running-prose text of a page, one string per outermost prose block."""

    def __init__(self, whole_page: bool):
        super().__init__(convert_charrefs=True)
        self.stack: list[tuple[str, bool, bool]] = []  # (tag, skips, is prose)
        self.in_main = whole_page
        self.main_depth = 0 if whole_page else None
        self.blocks: list[list[str]] = []

    def _skipping(self) -> bool:
        return any(skip for _, skip, _ in self.stack)

    def _in_prose(self) -> bool:
        return any(prose for _, _, prose in self.stack)

    def handle_starttag(self, tag, attrs):
        if tag in VOID_TAGS:
            return
        classes = set((dict(attrs).get("class") or "").split())
        if not self.in_main and tag == "article" and "bd-article" in classes:
            self.in_main, self.main_depth = True, len(self.stack)
        skip = (
            tag in SKIP_TAGS
            or tag.startswith("mjx-")
            or bool(classes & SKIP_CLASSES)
            or any(c.startswith("ledger-") for c in classes)
        )
        prose = self.in_main and (tag in PROSE_TAGS or (tag == "div" and "admonition" in classes))
        if prose and not self._in_prose():
            self.blocks.append([])
        self.stack.append((tag, skip, prose))

    def handle_startendtag(self, tag, attrs):
        pass

    def handle_endtag(self, tag):
        for i in range(len(self.stack) - 1, -1, -1):
            if self.stack[i][0] == tag:
                del self.stack[i:]
                break
        if self.main_depth is not None and len(self.stack) <= self.main_depth and tag == "article":
            self.in_main = False
        if self.blocks and self._in_prose() is False and self.blocks[-1] and self.blocks[-1][-1] != " ":
            self.blocks[-1].append(" ")

    def handle_data(self, data):
        if not (self.in_main and self._in_prose()):
            return
        self.blocks[-1].append(" " if self._skipping() else data)


def prose_identifiers(page_html: str) -> list[tuple[str, str]]:
    """(identifier, context) for each library identifier in the running prose of a page."""
    parser = _ProseText(whole_page='class="bd-article"' not in page_html)
    parser.feed(page_html)
    parser.close()
    found = []
    for block in parser.blocks:
        text = re.sub(r"\s+", " ", "".join(block)).strip()
        for m in IDENTIFIER.finditer(text):
            start, end = max(0, m.start() - 40), min(len(text), m.end() + 40)
            found.append((m.group(0), text[start:end]))
    return found


def check_prose(root: Path) -> list[str]:
    problems = []
    for page in sorted(root.rglob("*.html")):
        rel = page.relative_to(root).as_posix()
        if NOT_PROSE.match(rel):
            continue
        for ident, context in prose_identifiers(page.read_text(encoding="utf-8", errors="replace")):
            problems.append(f"{rel}: identifier {ident!r} in prose: ...{context}...")
    return problems


# change history, regression pins and test bookkeeping: for developers (git, tests), not readers
DEVELOPER_WORDING = re.compile(
    r"[Vv]erdict changed|\bwas (?:discrepant|inconsistent|consistent|reproduced|not-reproducible)\b"
    r"|expected_status|\bOracle:|caught by the oracle|checked by the library's tests|\(tests?\)"
    r"|\bin the tests\b|\bin the test suite\b|\bthe library's tests\b"
)
_SCRIPT_OR_STYLE = re.compile(r"<(style)\b.*?</\1>", re.S)


def check_wording(root: Path) -> list[str]:
    """Developer wording in what a reader sees: page text, embedded ledger data, notebook outputs."""
    problems = []
    for page in sorted(root.rglob("*.html")):
        rel = page.relative_to(root).as_posix()
        if NOT_PROSE.match(rel):
            continue
        text = _text(_SCRIPT_OR_STYLE.sub(" ", page.read_text(encoding="utf-8", errors="replace")))
        for m in DEVELOPER_WORDING.finditer(text):
            context = re.sub(r"\s+", " ", text[max(0, m.start() - 50) : m.end() + 50])
            problems.append(f"{rel}: developer wording {m.group(0)!r}: ...{context}...")
    for nb_path in sorted((root / "_sources").rglob("*.ipynb")):
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        outputs = json.dumps(
            [o for c in nb.get("cells", []) for o in c.get("outputs", [])], ensure_ascii=False
        )
        for m in DEVELOPER_WORDING.finditer(outputs):
            context = outputs[max(0, m.start() - 50) : m.end() + 50]
            problems.append(
                f"{nb_path.relative_to(root)}: developer wording {m.group(0)!r} in an output: ...{context}..."
            )
    return problems


# --- formulas shown as LaTeX source -------------------------------------------------------

#: LaTeX outside math: a command of two or more letters, or a braced sub- or superscript.
LATEX_SOURCE = re.compile(r"\\[A-Za-z]{2,}(?![A-Za-z])|[_^]\{")
#: What a reader sees typeset: MathJax's delimiters in the page (``\(..\)``, ``\[..\]``) and
#: the ``$...$`` and ``$$...$$`` of texts and tables that MathJax or the ledger's cells typeset.
TYPESET_MATH = re.compile(
    r"\$\$.*?\$\$|(?<![\\$])\$(?=[^\s$])[^$]*?[^\s\\$]\$(?!\$)|\\\(.*?\\\)|\\\[.*?\\\]", re.S
)
#: The text fields of a ledger record a reader sees (and downloads as JSON or CSV).
RECORD_TEXT_FIELDS = ("printed", "quantity", "note")
_LEDGER_DATA = re.compile(r'<script type="application/json" class="ledger-data">(.*?)</script>', re.S)


def latex_outside_math(text: str) -> list[str]:
    """The LaTeX source (commands, braced sub- and superscripts) in ``text`` outside its math.

    Examples
    --------
    >>> latex_outside_math(r"the error \\mathbf{e} and $\\mathbf{p}$ of $$x_{n-1}$$")
    ['\\\\mathbf']
    >>> latex_outside_math(r"a fixed P_{DL} and \\(\\bar{N}\\)")
    ['_{']
    """
    return [m.group(0) for m in LATEX_SOURCE.finditer(TYPESET_MATH.sub(" ", text))]


def check_plain_math(root: Path) -> list[str]:
    """Formulas shown as LaTeX source in what a reader sees: the text of every page but the API
    reference (``tools/check_numbers.py``'s reader text, with code cells and typeset math left
    out), a quote the ledger could only show as LaTeX source (class ``ledger-latex``), and the
    text fields of the ledger's embedded records (its JSON and CSV downloads)."""
    numbers = _check_numbers()
    problems = []
    for page in sorted(root.rglob("*.html")):
        rel = page.relative_to(root).as_posix()
        if numbers.SKIP_PAGES.match(rel):
            continue
        page_html = page.read_text(encoding="utf-8", errors="replace")
        if 'class="ledger-latex"' in page_html:
            problems.append(f"{rel}: a quote shown as LaTeX source (ledger-latex)")
        for block in numbers.reader_text(page_html):
            found = latex_outside_math(block)
            if found:
                context = block[:120]
                problems.append(f"{rel}: LaTeX outside math {sorted(set(found))}: {context}...")
        for data in _LEDGER_DATA.findall(page_html):
            for record in json.loads(html.unescape(data).replace("<\\/", "</")):
                for field in RECORD_TEXT_FIELDS:
                    found = latex_outside_math(record.get(field) or "")
                    if found:
                        problems.append(
                            f"{rel}: LaTeX outside math in the ledger record {record.get('id')} "
                            f"({field}): {sorted(set(found))}"
                        )
    return problems


# --- formulas shown as program text -------------------------------------------------------

#: Text that reads as plain math to the patterns but is not a formula, removed before the scan:
#: a claim's or an erratum's id (``ATC10-tab4.3-exII-s5-alpha``, ``SP-fig2.1-(peak, omega0)``),
#: an identifier, and the words of navigation and statistics that name a quantity in prose
#: (a delta range, a chi-square quantile, one sigma, the psi-angle model).
NOT_FORMULAS = re.compile(
    r"\b(?:WF|SP|ATC10|KZL)-(?:[\w.\u200b-]|\((?:[\w.\u200b-]|,\s*)+\))+"
    r"|\bdelta[- ](?:(?:pseudo)?ranges?|velocity)\b|\bchi-squared?\b"
    r"|\b(?:\d+|one|two|three|four|five|six)[- ]sigma\b|\bpsi[- ]angle\b",
    re.I,
)

#: Pages whose text lists identifiers, not formulas, with the reason; left out of the scan.
NOT_FORMULA_PAGES = {
    "traceability.html": "it lists the test modules that check each model by their file names",
}

#: (pages, text) of plain-text math the book still shows, each with its reason: a hit inside
#: ``text`` on a page that ``pages`` matches (a glob) passes. Each is for the page's or the
#: registry's owner to fix; keep the list short: an entry that no longer occurs fails the gate.
PLAIN_TEXT_ALLOWED: dict[tuple[str, str], str] = {
    # KZL names its antennas A0, A1, ...: labels, not formulas
    ("kzl/02-error-model.html", "A0"): "KZL's name of its master antenna, a label",
    ("ledger.html", "master antenna (A0)"): "KZL's name of its master antenna in a quote, a label",
}

#: What a program printed or a reader types, which the plain-text math gate leaves out beside
#: math and code cells: code (``<code>``, ``<pre>``, highlighted blocks) and a cell's printed
#: output (plain text, a stream); a cell's HTML output (a table, the ledger's claim rows) is
#: the book's text and is scanned.
PRINTED_TAGS = {"code", "pre", "kbd", "samp", "tt"}
PRINTED_CLASSES = {"text_plain", "stream", "highlight", "output_area", "cell_input"}


def _reader_text_without_printed(page_html: str) -> list[str]:
    """The reader text of a page (``tools/check_numbers.py``'s), without code and printed output."""
    numbers = _check_numbers()

    class _Text(numbers._ReaderText):
        def handle_starttag(self, tag, attrs):
            super().handle_starttag(tag, attrs)
            if tag in numbers.VOID_TAGS:
                return
            classes = set((dict(attrs).get("class") or "").split())
            if tag in PRINTED_TAGS or classes & PRINTED_CLASSES:
                self.stack[-1] = (tag, True)

    parser = _Text()
    parser.feed(page_html)
    parser.close()
    return [re.sub(r"\s+", " ", b).strip() for b in parser.blocks if b.strip()]


def plain_text_math(text: str) -> list[tuple[str, str]]:
    r"""The (kind, text) of each formula written as program text in ``text`` outside its math:
    the patterns the ledger's texts are held to (:func:`navcore.formatting.plain_math`:
    e-notation, a flat subscript, a spelled-out Greek letter, a power, ``sqrt(``, ...), one list
    for both. LaTeX source is ``latex_outside_math``'s.

    Examples
    --------
    >>> plain_text_math(r"a unit of m^3/s^2 and $\beta$, \(x_1\) and tau_c")
    [('power', 'm^3'), ('power', 's^2'), ('flat subscript', 'tau_c'), ('Greek name', 'tau_c')]
    """
    from navcore.formatting import plain_math

    shown = TYPESET_MATH.sub(lambda m: m.group(0) if m.group(0).startswith("$") else " ", text)
    shown = NOT_FORMULAS.sub(" ", shown)
    return [(kind, hit) for kind, hit in plain_math(shown) if kind != "LaTeX source"]


def check_plain_text_math(root: Path) -> list[str]:
    """Formulas shown as program text (``m^3/s^2``, ``tau_c``, ``**word**``) in what a reader
    sees: the text of every page but the API reference, outside math, code and printed output
    (:func:`plain_text_math`), unless listed in ``PLAIN_TEXT_ALLOWED`` with its reason; and each
    entry of that list that no longer occurs."""
    numbers = _check_numbers()
    problems, seen = [], set()
    for page in sorted(root.rglob("*.html")):
        rel = page.relative_to(root).as_posix()
        if numbers.SKIP_PAGES.match(rel) or rel in NOT_FORMULA_PAGES:
            continue
        for block in _reader_text_without_printed(page.read_text(encoding="utf-8", errors="replace")):
            for kind, hit in plain_text_math(block):
                allowed = [(g, t) for g, t in PLAIN_TEXT_ALLOWED if fnmatch(rel, g) and hit in t in block]
                if allowed:
                    seen.update(allowed)
                    continue
                at = block.find(hit)
                context = block[max(0, at - 50) : at + len(hit) + 50]
                problems.append(f"{rel}: plain-text math ({kind}) {hit!r}: ...{context}...")
    problems += [
        f"{pages}: allowed plain-text math {text!r} no longer occurs: remove it from PLAIN_TEXT_ALLOWED"
        for pages, text in sorted(set(PLAIN_TEXT_ALLOWED) - seen)
        if any(fnmatch(p.relative_to(root).as_posix(), pages) for p in root.rglob("*.html"))
    ]
    return problems


def check_pages(book: Path) -> list[str]:
    """Build helpers in code cells a reader sees, in the pages' source.

    A cell whose source is shown (not tagged ``remove-cell`` or ``remove-input``; a
    ``hide-input`` cell only folds its source away) must not hold a helper (:data:`HELPERS`):
    the book shows cells as they run, and the downloaded notebook is the page.

    Parameters
    ----------
    book : Path
        The book's folder; every ``*.md`` under it is read.

    Returns
    -------
    list of str
        One line per shown cell with a helper: the page, the line and the helper.
    """
    problems = []
    for page in sorted(book.rglob("*.md")):
        if "_build" in page.parts:
            continue
        text = page.read_text(encoding="utf-8")
        for cell in CODE_CELL.finditer(text):
            tags = {t.strip() for t in (cell.group(1) or "").split(",")}
            if tags & HIDDEN_SOURCE:
                continue
            m = HELPERS.search(cell.group(2))
            if m:
                line = text.count("\n", 0, cell.start(2) + m.start()) + 1
                problems.append(
                    f"{page.relative_to(book)}:{line}: a shown code cell runs {m.group(0).strip()!r}; "
                    "move it to a hidden cell (remove-cell) after it"
                )
    return problems


def check_html(root: Path) -> list[str]:
    problems = []
    for page in sorted(root.rglob("*.html")):
        if "_sources" in page.parts or "_static" in page.parts:
            continue
        for block in CELL_PRE.findall(page.read_text(encoding="utf-8", errors="replace")):
            m = HELPERS.search(_text(block))
            if m:
                problems.append(f"{page.relative_to(root)}: a code cell shows {m.group(0).strip()!r}")
    for nb_path in sorted((root / "_sources").rglob("*.ipynb")):
        nb = json.loads(nb_path.read_text(encoding="utf-8"))
        provenance = nb.get("metadata", {}).get(PROVENANCE_KEY)
        if not isinstance(provenance, dict) or not {"commit", "lock_sha256"} <= set(provenance):
            name = nb_path.relative_to(root)
            problems.append(f"{name}: download does not name the build ({PROVENANCE_KEY})")
        code = [c for c in nb.get("cells", []) if c.get("cell_type") == "code"]
        if not code:
            continue
        unrun = sum(c.get("execution_count") is None for c in code)
        if unrun or not any(c.get("outputs") for c in code):
            problems.append(
                f"{nb_path.relative_to(root)}: download is not executed "
                f"({unrun} of {len(code)} code cells without execution count, "
                f"{sum(bool(c.get('outputs')) for c in code)} with outputs)"
            )
    return (
        problems
        + check_prose(root)
        + check_wording(root)
        + check_number_format(root)
        + check_plain_math(root)
        + check_plain_text_math(root)
    )


def _check_numbers():
    """``tools/check_numbers.py``, loaded beside this file."""
    import importlib.util

    path = Path(__file__).with_name("check_numbers.py")
    spec = importlib.util.spec_from_file_location("check_numbers", path)
    assert spec is not None and spec.loader is not None
    numbers = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(numbers)
    return numbers


def check_number_format(root: Path) -> list[str]:
    """Numbers as a program prints them in what a reader sees (``tools/check_numbers.py``):
    ``1.00e-04``, ``1.6344416666666666``, ``-0.000``, ``60.000000``, ``{180.0: 18.0}``."""
    numbers = _check_numbers()
    return [
        f"{page}: number printed as a program prints it ({name}) {match!r}: ...{context}..."
        for page, name, match, context in numbers.check(root)
    ]


def check_latex(root: Path, max_overfull: float = 3.0) -> list[str]:
    problems = []
    logs = sorted(root.glob("*.log"))
    if not logs:
        problems.append(f"{root}: no LaTeX log")
    for log in logs:
        text = log.read_text(encoding="utf-8", errors="replace")
        for width, where in OVERFULL.findall(text):
            if float(width) > max_overfull:
                problems.append(f"{log.name}: overfull box {width} pt too wide{where}")
    for tex in sorted(root.glob("*.tex")):
        for block in VERBATIM.findall(tex.read_text(encoding="utf-8", errors="replace")):
            m = HELPERS.search(block)
            if m:
                problems.append(f"{tex.name}: a code listing shows {m.group(0).strip()!r}")
    return problems


_PDF_DATES = re.compile(rb"/(?:CreationDate|ModDate)\s*\(D:[^)]*\)|/ID\s*\[<[0-9A-Fa-f]+>\s*<[0-9A-Fa-f]+>\]")


# Sphinx's record for incremental rebuilds, not part of the book: it hashes the configuration,
# which holds the execution cache's folder, so two builds with separate caches always differ
NOT_THE_BOOK = {Path(".buildinfo")}


def same_trees(a: Path, b: Path) -> list[str]:
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.is_file()} - NOT_THE_BOOK
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.is_file()} - NOT_THE_BOOK
    problems = [f"only in {a}: {p}" for p in sorted(files_a - files_b)]
    problems += [f"only in {b}: {p}" for p in sorted(files_b - files_a)]
    for rel in sorted(files_a & files_b):
        x, y = (a / rel).read_bytes(), (b / rel).read_bytes()
        if rel.suffix == ".pdf":
            x, y = _PDF_DATES.sub(b"", x), _PDF_DATES.sub(b"", y)
        if x != y:
            problems.append(f"differs: {rel}")
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("gate", choices=["pages", "html", "numbers", "latex", "same"])
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--max-overfull", type=float, default=3.0, help="points (latex gate)")
    args = parser.parse_args(argv)
    if args.gate == "pages":
        problems = check_pages(args.paths[0])
    elif args.gate == "html":
        problems = check_html(args.paths[0])
    elif args.gate == "numbers":
        problems = check_number_format(args.paths[0])
    elif args.gate == "latex":
        problems = check_latex(args.paths[0], args.max_overfull)
    else:
        if len(args.paths) != 2:
            parser.error("same needs two build folders")
        problems = same_trees(*args.paths)
    for line in problems:
        print(line)
    print(f"check_book {args.gate}: {len(problems)} problem(s)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
