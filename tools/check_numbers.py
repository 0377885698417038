"""Number-format gate on a built HTML book: no number as a program prints it.

Usage::

    python tools/check_numbers.py _build/html            # fails on any hit
    python tools/check_numbers.py _build/html --summary  # counts per page and pattern

The text a reader sees on every page of the book (prose, tables, captions and cell outputs;
not code cells, math, the API reference or highlighted sources) is searched for:

``exponent``
    a number in a program's exponent notation (``1.00e-04``, ``5.8286e-14``), which a
    browser may also break after its minus sign ("1.00e-" / "04");
``long decimal``
    eight or more decimals (``1.6344416666666666``; not a DOI's ``10.1115/1.3662552``);
``negative zero``
    ``-0``, ``-0.0``, ``-0.000`` (a value that rounds to zero has no sign);
``padded``
    an integer padded with four or more zero decimals (``60.000000``); not a 0 or a 1 in a
    column of fixed decimals (``0.0000``, a probability of ``1.0000``);
``mapping``
    a printed dictionary of numbers (``{180.0: 18.02}``).

The book prints numbers with :func:`navcore.formatting.format_number` (re-exported by
``navcore.book``); this gate finds the places that do not. Exit status 1 and one line per hit.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

PATTERNS = {
    "exponent": re.compile(r"(?<![\w.])[-−]?\d+(?:\.\d+)?[eE][-+−]?\d+\b"),
    "long decimal": re.compile(r"(?<![\w./])[-−]?\d+\.\d{8,}"),
    "negative zero": re.compile(r"(?<![\w.\d])[-−]0(?:\.0+)?(?!\d|\.\d|×)"),
    "padded": re.compile(r"(?<![\w.])(?:[2-9]|[1-9]\d+)\.0{4,}(?!\d)"),
    "mapping": re.compile(r"\{\s*(?:'[^']*'|\"[^\"]*\"|[-−]?[\d.]+)\s*:\s*[-−(]?\d"),
}
# pages that are not the book's text for a reader of numbers
SKIP_PAGES = re.compile(
    r"^(?:reference/|_modules/|_sources/|_static/|_images/|genindex|py-modindex|search\.html)"
)
SKIP_TAGS = {"script", "style", "math", "svg", "button"}
SKIP_CLASSES = {"cell_input", "math", "headerlink", "sig", "highlight-ipython3"}
VOID_TAGS = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "wbr"}
BLOCK_TAGS = {"p", "li", "td", "th", "dd", "dt", "pre", "div", "figcaption", "h1", "h2", "h3", "h4", "tr"}


class _ReaderText(HTMLParser):
    """The article's visible text, one string per block, without code cells and math."""

    def __init__(self, skip_ledger: bool = False) -> None:
        super().__init__(convert_charrefs=True)
        self.skip_ledger = skip_ledger
        self.stack: list[tuple[str, bool]] = []
        self.in_article = False
        self.depth = -1
        self.blocks: list[str] = [""]

    def handle_starttag(self, tag, attrs):
        if tag in VOID_TAGS:
            if tag == "br":
                self.blocks.append("")
            return
        classes = set((dict(attrs).get("class") or "").split())
        if tag == "article" and "bd-article" in classes:
            self.in_article, self.depth = True, len(self.stack)
        skip = (
            tag in SKIP_TAGS
            or tag.startswith("mjx-")
            or bool(classes & SKIP_CLASSES)
            or (self.skip_ledger and any(c.startswith("ledger-") for c in classes))
        )
        self.stack.append((tag, skip))
        if tag in BLOCK_TAGS:
            self.blocks.append("")

    def handle_endtag(self, tag):
        for i in range(len(self.stack) - 1, -1, -1):
            if self.stack[i][0] == tag:
                del self.stack[i:]
                break
        # the article ends when its element leaves the stack: by its own end tag, or by the end
        # tag of an element around it (malformed HTML that closes it implicitly)
        if self.in_article and len(self.stack) <= self.depth:
            self.in_article = False
        if tag in BLOCK_TAGS or tag in ("td", "th"):
            self.blocks.append("")

    def handle_data(self, data):
        if self.in_article and not any(skip for _, skip in self.stack):
            self.blocks[-1] += data


def reader_text(page_html: str, skip_ledger: bool = False) -> list[str]:
    parser = _ReaderText(skip_ledger)
    parser.feed(page_html)
    parser.close()
    return [re.sub(r"\s+", " ", b).strip() for b in parser.blocks if b.strip()]


def hits(page_html: str, skip_ledger: bool = False) -> list[tuple[str, str, str]]:
    """(pattern, match, context) for each number printed as a program prints it."""
    found = []
    for block in reader_text(page_html, skip_ledger):
        for name, pattern in PATTERNS.items():
            for m in pattern.finditer(block):
                start, end = max(0, m.start() - 30), min(len(block), m.end() + 30)
                found.append((name, m.group(0), block[start:end]))
    return found


def check(root: Path, skip_ledger: bool = False) -> list[tuple[str, str, str, str]]:
    out = []
    for page in sorted(root.rglob("*.html")):
        rel = page.relative_to(root).as_posix()
        if SKIP_PAGES.match(rel):
            continue
        for name, match, context in hits(page.read_text(encoding="utf-8", errors="replace"), skip_ledger):
            out.append((rel, name, match, context))
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("html", type=Path, help="the built HTML book (_build/html)")
    parser.add_argument("--summary", action="store_true", help="counts per page and pattern")
    parser.add_argument(
        "--without-ledger",
        action="store_true",
        help="leave out the ledger's own tables and boxes (elements of class ledger-*)",
    )
    args = parser.parse_args(argv)
    found = check(args.html, args.without_ledger)
    if args.summary:
        for (page, name), n in sorted(Counter((p, n) for p, n, _, _ in found).items()):
            print(f"{n:4d}  {name:14s}  {page}")
    else:
        for page, name, match, context in found:
            print(f"{page}: {name} {match!r}: ...{context}...")
    by_pattern = Counter(n for _, n, _, _ in found)
    print(
        f"check_numbers: {len(found)} number(s) printed as a program prints them "
        f"({', '.join(f'{k} {v}' for k, v in sorted(by_pattern.items())) or 'none'})",
        file=sys.stderr,
    )
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main())
