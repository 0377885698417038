"""Check every internal link of the built HTML book: target file and anchor must exist.

Usage: ``python tools/check_links.py [_build/html]``

Sphinx's nitpicky mode (``-n -W``) already fails the build on a broken cross-reference; this
check covers what it cannot see: raw HTML links, links inside notebook outputs (the ledger
and errata tables link to the pages that discuss each claim), and anchors. External links
(``http:``, ``https:``, ``mailto:``) are not followed (the build machine has no internet).
Exits non-zero and lists the broken links if there are any.
"""

from __future__ import annotations

import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

ROOT = Path(__file__).resolve().parents[1]
SKIP_SCHEMES = ("http", "https", "mailto", "data", "javascript", "ftp")


class _Page(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.ids: set[str] = set()
        self.links: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        for key in ("id", "name"):
            if values.get(key):
                self.ids.add(values[key] or "")
        if tag == "a" and values.get("href"):
            self.links.append(values["href"] or "")


def _parse(path: Path) -> _Page:
    page = _Page()
    page.feed(path.read_text(errors="replace"))
    return page


def broken_links(html_root: Path) -> list[str]:
    """Every internal link of the HTML tree whose file or anchor does not exist."""
    pages = {p.resolve(): _parse(p) for p in html_root.rglob("*.html")}
    broken = []
    for path, page in pages.items():
        if "_static" in path.parts or "_sources" in path.parts:
            continue
        for href in page.links:
            parts = urlsplit(href)
            if parts.scheme in SKIP_SCHEMES or parts.netloc:
                continue
            target = (path.parent / unquote(parts.path)).resolve() if parts.path else path
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                broken.append(f"{path.relative_to(html_root.resolve())}: {href} (no such file)")
                continue
            if parts.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else _parse(target).ids
                if unquote(parts.fragment) not in ids:
                    broken.append(f"{path.relative_to(html_root.resolve())}: {href} (no such anchor)")
    return broken


def main() -> int:
    html_root = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "_build" / "html"
    if not (html_root / "index.html").exists():
        print(f"no HTML book at {html_root}: build it first (nox -s book)")
        return 2
    broken = broken_links(html_root)
    n_pages = sum(1 for _ in html_root.rglob("*.html"))
    if broken:
        print(f"{len(broken)} broken internal links in {n_pages} pages:")
        print("\n".join(f"  {b}" for b in broken))
        return 1
    print(f"internal links: all resolve ({n_pages} pages)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
